"""The fast suite on the other supported interpreters (issue 20: Python 3.11-3.13), where they are installed.

Slow (each interpreter: a venv from requirements.lock and the fast suite, about 5-8 min): ``make test-all`` or
``make test-pythons`` directly.
"""

from __future__ import annotations

import glob
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _runs(exe: str) -> bool:
    try:  # a pyenv shim of a version that is not active is on PATH but does not run
        return subprocess.run([exe, "-c", "pass"], capture_output=True, timeout=30).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


def other_pythons() -> list[str]:
    """python3.12 and python3.13 that run: from PATH, else pyenv's versions."""
    found = []
    for v in ("3.12", "3.13"):
        candidates = [shutil.which(f"python{v}"),
                      *sorted(glob.glob(os.path.expanduser(f"~/.pyenv/versions/{v}*/bin/python{v}")))]
        exe = next((c for c in candidates if c and _runs(c)), None)
        if exe:
            found.append(exe)
    return found


@pytest.mark.slow
@pytest.mark.other_env
def test_fast_suite_on_the_other_interpreters():
    pythons = other_pythons()
    if not pythons:
        pytest.skip("no python3.12 or python3.13 on this machine")
    out = subprocess.run(["make", "--no-print-directory", "test-pythons", f"PYTHONS={' '.join(pythons)}"],
                         cwd=ROOT, capture_output=True, text=True, timeout=3600)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
