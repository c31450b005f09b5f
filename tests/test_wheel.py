"""The wheel works outside the checkout and never writes into its install location (issue: pip install anywhere).

Builds the wheel from this checkout, installs it into a fresh venv in a temporary folder (dependencies at the
versions of requirements.lock, resolved by pip as a user's ``pip install`` would), then runs there, from
another temporary folder: the README's library example, ``claims --only dimension`` and
``figures --only oriented_graph``; and checks that site-packages holds afterwards exactly what pip put there.

Slow (a venv and a dependency install: 1-3 minutes): run by ``make test-wheel`` (which CI runs) and by
``make test-all``.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
pytestmark = [pytest.mark.slow, pytest.mark.other_env]


def _run(cmd: list[str], cwd: Path, env: dict | None = None, timeout: int = 900) -> subprocess.CompletedProcess:
    proc = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    assert proc.returncode == 0, f"{cmd} failed ({proc.returncode}):\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return proc


def _tree(path: Path) -> dict[str, tuple[int, int]]:
    return {p.relative_to(path).as_posix(): (p.stat().st_size, p.stat().st_mtime_ns)
            for p in path.rglob("*") if p.is_file() and "__pycache__" not in p.parts}


def _readme_example() -> str:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    text = text[text.index("## Using the library"):]  # the example that writes patch.obj (not the quick start's)
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "README.md has no python example"
    return blocks[0]


def test_wheel_installs_and_runs_outside_the_checkout(tmp_path):
    dist = tmp_path / "dist"
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", str(dist), str(ROOT)],
         cwd=tmp_path)
    wheel = next(dist.glob("paper_repro-*.whl"))
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(with_pip=True, clear=True).create(env_dir)
    py = env_dir / "bin" / "python"
    pins = [ln.split()[0] for ln in (ROOT / "requirements.lock").read_text().splitlines() if "==" in ln]
    constraints = tmp_path / "constraints.txt"
    constraints.write_text("\n".join(pins) + "\n")
    _run([str(py), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-c", str(constraints),
          str(wheel)], cwd=tmp_path)
    site = Path(_run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                     cwd=tmp_path).stdout.strip())
    pkg = site / "paper_repro"
    assert (pkg / "resources" / "paper_index.json").is_file() and (pkg / "py.typed").is_file()
    assert (pkg / "resources" / "derivative_tables.json").is_file()  # claim derivative_all_n's independent reference
    before = _tree(site)

    work = tmp_path / "work"
    work.mkdir()
    os.chmod(pkg, 0o555)  # a user who cannot write to the install location must not notice
    env = {k: v for k, v in os.environ.items() if not k.startswith("PAPER_REPRO")}
    env["PAPER_REPRO_CACHE"] = str(tmp_path / "cache")
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    try:
        (work / "example.py").write_text(_readme_example())
        _run([str(py), "example.py"], cwd=work, env=env)
        assert (work / "patch.obj").is_file()
        out = _run([str(py), "-m", "paper_repro", "claims", "--only", "dimension"], cwd=work, env=env).stdout
        assert re.search(r"^dimension .* PASS", out, re.M), out
        _run([str(py), "-m", "paper_repro", "figures", "--only", "oriented_graph"], cwd=work, env=env)
        assert (work / "figures" / "oriented_graph.png").is_file()
        assert (work / "figures" / "index.html").is_file() and (work / "figures" / "manifest.json").is_file()
        other = tmp_path / "elsewhere"
        _run([str(py), "-m", "paper_repro", "figures", "--only", "oriented_graph", "--out", str(other)],
             cwd=work, env=env)
        assert (other / "figures" / "oriented_graph.png").is_file()
        print(_run([str(py), "-m", "paper_repro", "claims", "--list"], cwd=work, env=env).stdout)
        version = _run([str(py), "-c", "import paper_repro; print(paper_repro.__version__)"], cwd=work, env=env)
        assert version.stdout.strip() == re.search(r'__version__ = "(.*)"',
                                                   (ROOT / "paper_repro" / "_version.py").read_text()).group(1)
    finally:
        os.chmod(pkg, 0o755)
    after = _tree(site)
    assert after == before, f"written into site-packages: {sorted(set(after.items()) ^ set(before.items()))[:10]}"
    assert not any((site / name).exists() for name in ("data", "figures", ".cache", "build", "reports"))
    assert any((tmp_path / "cache").rglob("*.json")), "the cache went elsewhere than PAPER_REPRO_CACHE"
