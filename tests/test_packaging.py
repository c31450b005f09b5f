"""Packaging facts a reader depends on: LICENSE, CITATION.cff, the lock file, the Python check."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def test_citation_cff_fields():
    text = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    for key in ("cff-version: 1.2.0", "message:", "title:", "authors:", "preferred-citation:", "type: article",
                "arXiv:1309.4747", "https://arxiv.org/abs/1309.4747"):
        assert key in text, key
    assert not re.search(r"\t", text)  # YAML forbids tabs for indentation
    assert (ROOT / "LICENSE").read_text().startswith("MIT License")


def test_lock_pins_every_dependency_exactly():
    lines = [ln for ln in (ROOT / "requirements.lock").read_text().splitlines() if ln and not ln.startswith("#")]
    pattern = r"[A-Za-z0-9_.\-]+==[A-Za-z0-9_.+\-]+( --hash=sha256:[0-9a-f]{64})+"
    assert lines and all(re.fullmatch(pattern, ln) for ln in lines), lines
    names = {ln.split("==")[0].lower().replace("_", "-") for ln in lines}
    for dep in ("numpy", "scipy", "mpmath", "python-flint", "matplotlib", "pytest", "hypothesis", "bezier", "dask",
                "distributed"):
        assert dep in names, dep


def test_lock_holds_every_requirement_of_the_dask_extra():
    """dask and distributed are locked with their whole dependency tree (installed with --require-hashes)."""
    from importlib.metadata import requires

    from packaging.requirements import Requirement

    lines = [ln for ln in (ROOT / "requirements.lock").read_text().splitlines() if ln and not ln.startswith("#")]
    names = {re.sub(r"[-_.]+", "-", ln.split("==")[0]).lower() for ln in lines}
    todo, seen = ["dask", "distributed"], set()
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        for text in requires(name) or []:
            req = Requirement(text)
            if req.marker is None or req.marker.evaluate({"extra": ""}):
                dep = re.sub(r"[-_.]+", "-", req.name).lower()
                assert dep in names, f"{dep} (needed by {name}) is not in requirements.lock"
                todo.append(dep)
    assert len(seen) > 10


def test_makefile_stops_on_an_old_python(tmp_path):
    fake = tmp_path / "python3"
    fake.write_text("#!/bin/sh\nif [ \"$1\" = -V ]; then echo 'Python 3.10.12'; exit 0; fi\nexit 1\n")
    fake.chmod(0o755)
    proc = subprocess.run(["make", "-s", "-C", str(ROOT), "-n" if False else "venv", f"PYTHON={fake}",
                           f"VENV={tmp_path / 'venv'}"], capture_output=True, text=True)
    assert proc.returncode != 0
    assert "needs Python >= 3.11" in proc.stderr and "3.10.12" in proc.stderr
    assert not (tmp_path / "venv").exists()
    assert sys.version_info >= (3, 11)


@pytest.mark.parametrize("target, var", [("test", "PYTHON"), ("test-pythons", "PYTHON"),
                                         ("test-pythons", "PYTHONS"), ("reproduce", "PYTHON")])
def test_makefile_stops_on_a_python_that_does_not_run(target, var):
    """`make test PYTHON=python3.99` stopped nothing: an empty version chose the 3.11 .venv and tested that."""
    proc = subprocess.run(["make", "--no-print-directory", "-n", "-C", str(ROOT), target, f"{var}=python3.99"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode != 0, proc.stdout
    assert "python3.99 does not run" in proc.stderr, proc.stderr
    assert "pytest" not in proc.stdout and "paper_repro" not in proc.stdout, proc.stdout


@pytest.mark.parametrize("value", ["", "  "])
def test_makefile_says_one_sentence_for_an_empty_python(value):
    """`make test PYTHON=` printed `/bin/sh: 0: Illegal option -` three times before the sentence."""
    proc = subprocess.run(["make", "--no-print-directory", "-n", "-C", str(ROOT), "test", f"PYTHON={value}"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode != 0, proc.stdout
    assert proc.stderr.strip().count("\n") == 0 and "PYTHON is empty" in proc.stderr, proc.stderr
    assert "Illegal option" not in proc.stderr
