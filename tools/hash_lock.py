"""Add ``--hash=sha256:...`` to every line of requirements.lock (run by ``make lock``).

The hashes are those of every distribution in the given folders: ``make lock`` downloads the Linux x86_64
wheels of each supported interpreter (CPython 3.11, 3.12, 3.13) and the source distribution of a pinned
version that has no wheel for one of them (bezier on 3.13: built without its compiled speed-up,
``BEZIER_NO_EXTENSION``); ``make`` installs with ``--require-hashes``, so a changed or substituted file is
refused.  Usage: ``python tools/hash_lock.py requirements.lock DIR [DIR ...]``.
"""

import hashlib
import re
import sys
from pathlib import Path


def norm(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def main(lock: str, *wheel_dirs: str) -> int:
    hashes: dict[tuple[str, str], list[str]] = {}
    for f in sorted(f for d in wheel_dirs for f in Path(d).iterdir()):
        m = re.match(r"^(.+?)-(\d[^-]*)(?:-|\.tar\.gz$|\.zip$)", f.name)
        if not m:
            continue
        h = hashlib.sha256(f.read_bytes()).hexdigest()
        known = hashes.setdefault((norm(m.group(1)), m.group(2)), [])
        if h not in known:
            known.append(h)
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
