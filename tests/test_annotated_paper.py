"""The annotated paper (`make paper`): rendering, badges from the line index (a fake one in tests/fixtures),
numbering as in the PDF, the page without the index, and the page in a real browser."""

import json
import re
from pathlib import Path

import pytest

from paper_repro.app import annotated_paper as ap
from paper_repro.app.paper_index import PAPER, load_index

FAKE = Path(__file__).parent / "fixtures" / "paper_lines_fake.json"
needs_paper = pytest.mark.skipif(not PAPER.exists(), reason=f"the paper's LaTeX source {PAPER} is not beside the clone")

MINI = r"""\documentclass{elsarticle}\newtheorem{lemma}{Lemma}[section]
\begin{document}
\section{\label{sec:a}First}
Text with $x^2$ and \emph{emphasis}, see (\ref{e1}).
\begin{equation}
a = b \label{e1}
\end{equation}
\begin{lemma}\label{lem:x}
A statement.
\end{lemma}
\begin{align}
c &= d \label{e2}\\
e &= f \nonumber
\end{align}
\end{document}
"""
MINI_INDEX = [{"label": "e1", "kind": "equation", "env": "equation", "number": "1", "display": "Eq. (1)",
               "section": "1", "section_title": "First"}]


def _block(page: str, anchor: str) -> str:
    """The HTML of the element with id ``anchor`` up to the next display/statement/figure."""
    start = page.index(f'id="{anchor}"')
    nxt = re.search(r'<(div class="(display|stmt [a-z]+)"|figure )', page[start + 10:])
    return page[start:start + 10 + (nxt.start() if nxt else len(page))]


def test_mini_source_renders_with_badges_and_numbers():
    page, info = ap.build(MINI, MINI_INDEX, [], [], {}, None, [])
    assert info["displays"] == 2 and info["math_fallback"] == 0 and info["math"] >= 3
    assert "<math" in page and "<em>emphasis</em>" in page and '<a class="ref" href="#e1">1</a>' in page
    assert '<span class="eqno">(1)</span>' in page and '<span class="eqno">(2)</span>' in page  # \nonumber row
    assert "Lemma 1.1" in page
    # without the line index every display and statement is "not yet checked"
    assert info["badges"]["not yet checked"] == 3 and info["badges"]["checked"] == 0


def test_colours_stay_in_their_group_and_alignments_align():
    html_ = ap.mathml(r"\begin{align*}a&=\Red{b},\\ c&=\color[rgb]{0,0,1}d\normalcolor\end{align*}", True)
    assert "<mi>&</mi>" not in html_ and html_.count("<mtr>") == 2 and "#d00000" in html_ and "#0000ff" in html_
    assert ap.mathml(r"a\ b", False).count("\\") == 0


def test_unparsable_math_is_shown_as_source_not_dropped():
    page, info = ap.build(MINI.replace("a = b", r"a = \frac{"), MINI_INDEX, [], [], {}, None, [])
    assert info["math_fallback"] == 1 and "a = \\frac{" in page


@needs_paper
def test_fake_line_index_puts_each_badge_in_its_place():
    lines = json.loads(FAKE.read_text())
    page, info = ap.build(PAPER.read_text(encoding="utf-8"), load_index(), [], [{"id": "symmetry", "kind": "proof",
                          "status": "pass"}, {"id": "limit_formula", "kind": "proof", "status": "pass"}], {}, lines, [])
    assert info["unplaced_entries"] == 0
    assert info["badges"]["checked"] == 2 and info["badges"]["erratum"] == 1 and info["badges"]["excused"] == 1
    r_system = _block(page, "R_system")
    assert 'data-status="checked"' in r_system and "#claim-symmetry" in r_system
    assert "test_claim_passes[symmetry]" in r_system  # the test that checks the claim
    sign = _block(page, "sign_cos_power_derivative")
    assert 'data-status="erratum"' in sign and "FAKE-EVIDENCE-576-of-1488" in sign
    assert '<table class="pair"><tr><th>printed</th><th>corrected</th>' in sign and "statement" in sign
    assert "FAKE-REASON nothing to compute" in page
    question = _block(page, "que:limiting_case")
    assert 'data-status="checked"' in question and "docs/limit_for_all_n.md" in question
    # every display still carries a badge; those the fake index does not cover say "not yet checked"
    assert info["badges"]["not yet checked"] >= info["displays"] - 2


@needs_paper
def test_without_the_index_every_display_is_not_yet_checked_and_errata_stand_at_their_labels():
    errata = [{"id": "fake-erratum", "paper_ref": "exmp:torus", "severity": "typo", "printed": "a", "corrected": "b",
               "evidence": "FAKE"}]
    page, info = ap.build(PAPER.read_text(encoding="utf-8"), load_index(), [], [], {}, None, errata)
    assert info["unplaced_errata"] == 0 and info["badges"]["erratum"] == 1
    assert info["badges"]["not yet checked"] >= info["displays"]
    assert 'data-status="erratum"' in _block(page, "exmp:torus")
    # no LaTeX leaks into the formulas: alignment tabs, stray backslashes (control spaces, unknown commands)
    assert "<mi>&</mi>" not in page and not re.search(r"<m[a-z]+>\\", page)


@needs_paper
def test_numbers_agree_with_the_paper_index():
    index = {r["label"]: r for r in load_index()}
    r = ap.Renderer(PAPER.read_text(encoding="utf-8"), load_index(), [], [], {}, None, [])
    r.render()
    checked = 0
    for b in r.blocks:
        for lab in b.labels:
            rec = index.get(lab)
            if not rec or not rec["number"]:
                continue
            if b.kind == "display":
                assert f"({rec['number']})" in b.title, (lab, rec["display"], b.title)
            elif b.kind in ("statement", "figure"):
                assert rec["display"] == b.title, (lab, rec["display"], b.title)
            checked += 1
    assert checked > 80
    assert r.counters["figure"] == 12 and r.stats["math_fallback"] == 0


def test_absent_source_says_so_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "index.html"
    assert ap.write_paper(tmp_path / "missing.tex", out) is None
    assert not out.exists()
    said = capsys.readouterr().out.strip()
    assert said.count(".") >= 1 and "not beside this clone" in said and "\n" not in said


@needs_paper
def test_annotated_paper_in_headless_chromium():
    from paper_repro.app import check_gallery, check_paper

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip("no chromium/chromedriver on this machine: run `make check-gallery` (installs Debian's chromium)")
    ap.write_paper()
    res = check_paper.check()
    assert check_paper.passed(res), res


def test_link_check_can_fail(tmp_path):
    from paper_repro.app.check_paper import resolve

    page = tmp_path / "p" / "index.html"
    page.parent.mkdir()
    (tmp_path / "f.html").write_text('<p id="here"></p>')
    assert resolve(page, "#a", {"a"}) is None and resolve(page, "#b", {"a"})
    assert resolve(page, "../f.html#here", set()) is None and resolve(page, "../f.html#there", set())
    assert resolve(page, "../missing.html", set()) and resolve(page, "https://example.org/", set())


def test_badge_says_what_its_proof_kind_means():
    """An exhaustive line is not shown as a bare "proof" (issue 31, item 6)."""
    entry = {"id": "x", "tex": [1, 1], "status": "checked", "says": "s", "how": "count, n = 1..12",
             "proof_kind": "exhaustive", "check": "c"}
    block = ap.Block("display", 1, 1, "a", "", [])
    block.entries.append(entry)
    html_ = ap.badge_html(block, ap.Linker({}, set(), {}))
    assert "proof kind: exhaustive (exact and complete for the range named in &#x27;how&#x27; only" in html_
    block.entries[0] = {**entry, "proof_kind": "proof"}
    assert "settles everything the line states" in ap.badge_html(block, ap.Linker({}, set(), {}))
