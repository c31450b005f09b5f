"""Add ``--hash=sha256:...`` to every line of requirements.lock (run by ``make lock``).

The hashes are those of the distributions pip downloads for this machine (Linux x86_64, CPython 3.11:
the project's machine kind); ``make`` installs with ``--require-hashes``, so a changed or substituted
file is refused.  Usage: ``python tools/hash_lock.py requirements.lock WHEEL_DIR``.
"""

import hashlib
import re
import sys
from pathlib import Path


def norm(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def main(lock: str, wheel_dir: str) -> int:
    hashes: dict[tuple[str, str], list[str]] = {}
    for f in sorted(Path(wheel_dir).iterdir()):
        m = re.match(r"^(.+?)-(\d[^-]*)(?:-|\.tar\.gz$|\.zip$)", f.name)
        if not m:
            continue
        hashes.setdefault((norm(m.group(1)), m.group(2)), []).append(hashlib.sha256(f.read_bytes()).hexdigest())
    out, missing = [], []
    for line in Path(lock).read_text().splitlines():
        spec = line.split()[0] if line.strip() else ""
        if "==" not in spec:
            continue
        name, ver = spec.split("==")
        hs = hashes.get((norm(name), ver))
        if not hs:
            missing.append(spec)
            continue
        out.append(f"{name}=={ver} " + " ".join(f"--hash=sha256:{h}" for h in hs))
    if missing:
        print(f"no downloaded distribution for: {missing}", file=sys.stderr)
        return 1
    Path(lock).write_text("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(*sys.argv[1:]))
