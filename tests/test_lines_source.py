"""The transcribed lines of the paper (issue 19): each verbatim text occurs in its source lines, ids are
unique, and every check a line names exists (a registered line check, or a registered claim)."""

import re

import pytest

from paper_repro.app.paper_index import PAPER
from paper_repro.claims.lines import load_checks
from paper_repro.printed.lines import PARTS, STATUSES, all_lines
from paper_repro.util.paper_labels import load_index
from paper_repro.util.registry import CLAIMS, load_all

load_all()


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


def _norm_tight(text: str) -> str:
    return re.sub(r"\s+", "", text)


def test_verbatim_text_occurs_in_its_source_lines():
    if not PAPER.exists():
        pytest.skip(f"the paper's source is not beside this clone ({PAPER}): verbatim transcriptions not compared")
    source = PAPER.read_text(encoding="utf-8").splitlines()
    bad = []
    for line in all_lines():
        first, last = line.tex
        if not 1 <= first <= last <= len(source):
            bad.append(f"{line.id}: source lines {line.tex} outside 1..{len(source)}")
            continue
        span = "\n".join(source[first - 1:last])
        if _norm(line.verbatim) not in _norm(span):
            bad.append(f"{line.id}: verbatim text not in source lines {first}-{last}")
    assert not bad, "\n".join(bad)


def test_the_source_comparison_rejects_a_retyped_line():
    """The normalisation only forgives whitespace: a changed character is caught."""
    assert _norm("a  =\n b") in _norm("x a = b y")
    assert _norm("a = c") not in _norm("x a = b y")


def test_ids_unique_and_prefixed_by_their_part():
    lines = all_lines()
    ids = [x.id for x in lines]
    assert len(ids) == len(set(ids))
    assert all(x.id.split("-", 1)[0] in PARTS for x in lines), [x.id for x in lines if x.id.split("-")[0] not in PARTS]
    assert all(x.status in STATUSES for x in lines)


def test_every_check_resolves():
    checks = load_checks()
    unresolved = []
    for line in all_lines():
        if line.check is None:
            continue
        if line.check.startswith("claim:"):
            if line.check[len("claim:"):] not in CLAIMS:
                unresolved.append(f"{line.id}: {line.check}")
        elif line.check not in checks:
            unresolved.append(f"{line.id}: {line.check}")
    assert not unresolved, unresolved


def test_nearest_labels_are_labels_of_the_paper():
    labels = {r["label"] for r in load_index()}
    assert not [x.id for x in all_lines() if x.near not in labels]
