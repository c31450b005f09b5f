"""What a user reads says what things are: no tracker issue numbers in the pages and the API reference, one
notation, messages that point to the command that works."""

from __future__ import annotations

import importlib
import inspect
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
ISSUE = re.compile(r"\bissues? ?#?\d+", re.I)


def user_pages() -> list[Path]:
    return [ROOT / "README.md", *sorted(DOCS.glob("*.md")), *sorted((DOCS / "guide").glob("*")),
            *sorted((DOCS / "examples").glob("*"))]


def test_no_issue_numbers_in_the_pages():
    hits = [f"{p.relative_to(ROOT)}:{k}" for p in user_pages() for k, line in enumerate(
        p.read_text(encoding="utf-8").splitlines(), 1) if ISSUE.search(line)]
    assert hits == []


def test_no_issue_numbers_in_the_api_reference():
    """The docstrings the API reference shows (every module it documents, and the package root's names)."""
    api = (DOCS / "guide" / "api.rst").read_text(encoding="utf-8")
    hits = []
    for name in re.findall(r"automodule:: (\S+)", api):
        mod = importlib.import_module(name)
        objs = [mod] + [getattr(mod, a) for a in dir(mod) if not a.startswith("_")]
        for obj in objs:
            if obj is not mod and name != "paper_repro" and getattr(obj, "__module__", name) != name:
                continue
            hits += [f"{name}.{getattr(obj, '__name__', '?')}" for _ in ISSUE.finditer(inspect.getdoc(obj) or "")]
    assert hits == []


def test_page_titles_carry_no_math():
    """The sidebar shows a page's title as text: $V_n^\\alpha$ there came out as raw \\(V_n^\\alpha\\)."""
    titles = [line for p in sorted(DOCS.glob("*.md")) for line in p.read_text(encoding="utf-8").splitlines()[:1]]
    assert [t for t in titles if "$" in t] == []


def test_no_slash_between_quantities_read_as_a_fraction():
    """"about 20 s / 2 GB" was typeset by the plain-math pass as a formula."""
    assert [p.name for p in DOCS.glob("*.md") if re.search(r"\d+ s / \d+ GB", p.read_text(encoding="utf-8"))] == []


def test_chromium_skip_messages_name_the_command_that_installs():
    """`make check-gallery` installs Chromium only with INSTALL=1."""
    bad = []
    for p in [*ROOT.glob("tests/*.py"), *ROOT.glob("paper_repro/app/*.py")]:
        for k, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            if re.search(r"make check-gallery`?\s*\(?\s*install", line) and "INSTALL=1" not in line:
                bad.append(f"{p.name}:{k}")
    assert bad == []


def test_elevation_matrix_documents_its_parameters():
    from paper_repro.core.elevation import elevation_matrix

    doc = inspect.getdoc(elevation_matrix)
    assert "README" not in doc and "docs/domain_of_validity.md" in doc
    params = doc.split("Parameters")[1].split("Returns")[0]
    assert re.search(r"^n : int", params, re.M) and re.search(r"^alpha : ", params, re.M)


def test_one_notation_for_multiples_of_pi_in_the_gallery():
    pytest.importorskip("latex2mathml")
    from paper_repro.app.gallery import math_html

    assert math_html("alpha in pi/6, 2pi/3, 5pi/6") == "α in π/6, 2π/3, 5π/6"


def test_progress_label_has_one_colon():
    src = (ROOT / "paper_repro" / "app" / "report.py").read_text(encoding="utf-8")
    assert 'desc=f"tasks, round {self.rounds}",' in src


def test_cluster_page_tells_how_to_make_cached_claims_run():
    text = (DOCS / "cluster.md").read_text(encoding="utf-8")
    assert "PAPER_REPRO_NO_CACHE=1" in text and "(cached)" in text


def test_api_reference_writes_math_as_math():
    from paper_repro.core.transformation import transformation_matrix

    api = (DOCS / "guide" / "api.rst").read_text(encoding="utf-8")
    assert "T-bar" not in api and "T-bar" not in inspect.getdoc(transformation_matrix)
