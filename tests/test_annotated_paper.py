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
        pytest.skip(check_gallery.HOW_TO_GET)
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


# --- issue 33: the page agrees with itself -------------------------------------------------------------------
MINI2 = r"""\documentclass{elsarticle}\newtheorem{proposition}{Proposition}[section]
\begin{document}
\section{\label{sec:a}First}
Text.
\begin{proposition}\label{prop:x}
A statement with a display:
\begin{equation}
a = b \label{e1}
\end{equation}
\end{proposition}
Some text
\[
c = d
\]
and more text.
\end{document}
"""


def _entry(eid, tex, status, **kw):
    return {"id": eid, "tex": list(tex), "status": status, "near": kw.pop("near", None), "kind": "display",
            "number": None, "says": kw.pop("says", eid), "check": kw.pop("check", None), **kw}


def _mini2_lines():
    src = MINI2.split("\n")
    at = {key: next(k + 1 for k, line in enumerate(src) if key in line) for key in ("a = b", "Some text", "c = d",
                                                                                      "section{")}
    return {"coverage": {"lines": 4}, "lines": [
        _entry("in-display", (at["a = b"], at["a = b"]), "checked", check="x"),
        _entry("paragraph", (at["Some text"], at["c = d"] + 2), "checked", check="x"),  # covers the display inside
        _entry("title", (at["section{"], at["section{"]), "excused", reason="a title"),
        _entry("line-err", (at["c = d"], at["c = d"]), "erratum", check="x",
               erratum={"id": "line-err", "printed": "c = d", "corrected": "c = e", "severity": "typo",
                        "evidence": "e.g. [{'printed': None, 'true': 1}]"})]}


def test_statements_and_displays_covered_elsewhere_point_to_the_badge():
    """Issue 33: Proposition 3.1's box said "not yet checked" while its display (21) said checked; a display inside
    a checked paragraph likewise.  Such blocks point to the entry's badge and are not counted twice."""
    page, info = ap.build(MINI2, [], [], [], {}, _mini2_lines(), [])
    assert info["badges"] == {"checked": 2, "erratum": 1, "excused": 1, "not yet checked": 0}
    stmt = _block(page, "prop:x")
    assert 'data-covered="checked"' in stmt and 'href="#e1"' in stmt and "not yet checked" not in stmt


def test_one_tally_for_the_header_the_table_and_the_page():
    """Issue 33: header 32 errata / 80 excused, table 37 / 80, the browser 78 excused (two badges of section titles
    were counted but never placed).  Now every badge counted is on the page, and the table carries the tally."""
    page, info = ap.build(MINI2, [], [], [], {}, _mini2_lines(), [])
    on_page = re.findall(r'data-status="([^"]+)"', page)
    assert {s: on_page.count(s) for s in ap.STATUSES} == info["badges"]
    table = json.loads(re.search(r'data-counts="([^"]+)"', page).group(1).replace("&quot;", '"'))
    assert table == info["badges"]
    assert "a title" in _block(page, "sec:a") if "sec:a" in page else "a title" in page
    assert "1 errata" in page and "1 excused" in page  # the header says what the table says


def test_errata_of_errata_json_are_shown_once_and_by_their_id():
    """Issue 33: torus-b_{4,3,1}-x appeared nowhere (a label match hid it); five errata appeared twice (at their label
    and at their line, under another id).  An erratum the index holds (same id, or same printed and corrected text)
    is named on the index's badge; the others stand at their label."""
    errata = [{"id": "json-name-of-it", "paper_ref": "prop:x", "severity": "typo", "printed": "c = d",
               "corrected": "c = e", "evidence": "E"},
              {"id": "only-in-json", "paper_ref": "prop:x", "severity": "typo", "printed": "p", "corrected": "q",
               "evidence": "E"}]
    page, info = ap.build(MINI2, [], [], [], {}, _mini2_lines(), errata)
    assert info["badges"]["erratum"] == 2 and info["unplaced_errata"] == 0
    assert "json-name-of-it" in page and "only-in-json" in _block(page, "prop:x")
    assert page.count("json-name-of-it") == 1


def test_no_python_none_in_erratum_boxes():
    page, _ = ap.build(MINI2, [], [], [], {}, _mini2_lines(), [])
    assert ">None<" not in page and "no case" in page


def test_text_words_keep_their_spaces_in_mathml():
    """Issue 33: eq. (21) read "≡ 2(mod4)andz ≥ j": \\text and \\operatorname were turned into \\mathrm."""
    out = ap.mathml(r"z-j\equiv2\left(  \operatorname{mod}4\right)  \text{ and }z\geq j", True)
    assert "<mtext>&#x000A0;and&#x000A0;</mtext>" in out and "<mo>mod</mo>" in out


def test_every_transcribed_line_leaves_no_block_unchecked():
    """With the line index as transcribed in paper_repro/printed/lines (its statuses, without running the checks),
    every display, statement and figure of the paper has a badge other than "not yet checked" (issue 33: Remark 1.2
    and the display defining ~ had none), and every erratum of data/errata.json is named on the page."""
    if not PAPER.exists():
        pytest.skip(f"the paper's LaTeX source {PAPER} is not beside the clone")
    from dataclasses import asdict

    from paper_repro.printed.lines import all_lines
    from paper_repro.util.io import DATA

    entries = [{**asdict(x), "tex": list(x.tex)} for x in all_lines()]
    errata = json.loads((DATA / "errata.json").read_text(encoding="utf-8"))
    page, info = ap.build(PAPER.read_text(encoding="utf-8"), load_index(), [], [], {}, {"lines": entries}, errata)
    assert info["badges"]["not yet checked"] == 0, info
    held = ap.held_errata(entries, errata)  # errata.json is rewritten by make reproduce from the same transcriptions
    assert info["badges"]["erratum"] == sum(e["status"] == "erratum" for e in entries) + len(errata) - len(held)
    assert [e["id"] for e in errata if html_escape(e["id"]) not in page] == []
    assert ">None<" not in page


def html_escape(text: str) -> str:
    import html

    return html.escape(text)


def test_check_paper_measures_every_display_box(tmp_path):
    """Issue 33: check-paper said "overflow 0" while 21 displays scrolled inside their boxes (it measured the page
    only).  A display wider than its box is reported; the page's fitting script makes it fit."""
    from paper_repro.app import check_gallery, check_paper

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip("no chromium/chromedriver on this machine")
    wide = " + ".join(f"x_{{{k}}}^{{{k}}}" for k in range(25))
    page, _ = ap.build(MINI2.replace("a = b", "a = " + wide), [], [], [], {}, _mini2_lines(), [])
    fitted = tmp_path / "paper" / "index.html"
    fitted.parent.mkdir()
    fitted.write_text(page, encoding="utf-8")
    res = check_paper.check(fitted, tmp_path / "shots")
    assert res["display_overflow"] == {1920: [], 1024: [], 1280: []} and res["counts_disagree"] is None, res
    assert res["displays_scaled"][1024][0] >= 1
    unfitted = tmp_path / "paper" / "raw.html"
    unfitted.write_text(page.replace(f"<script>{ap.FIT_JS}</script>", ""), encoding="utf-8")
    res = check_paper.check(unfitted, tmp_path / "shots")
    assert all(len(res["display_overflow"][w]) == 1 for w in (1024, 1280, 1920)), res["display_overflow"]
    assert not check_paper.passed(res)


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


def test_every_element_id_once_and_verdicts_in_words():
    """A \\label inside a statement whose box already carries it as its id (prop:x) gave two elements with one id;
    the erratum boxes said True/False: now "as printed: fails", "as corrected: holds"."""
    lines = _mini2_lines()
    lines["lines"][3].update(holds_as_printed=False, corrected_holds=True)
    page, _ = ap.build(MINI2, [], [], [], {}, lines, [])
    ids = re.findall(r'\bid="([^"]*)"', page)
    assert sorted(i for i in set(ids) if ids.count(i) > 1) == [] and "prop:x" in ids
    assert "as printed: fails" in page and "as corrected: holds" in page
    assert not re.search(r">[^<]*\b(True|False)\b[^<]*<", page)


def test_or_keeps_its_space_after_a_parenthesis():
    """Eq. (sign_sin_power_derivative): "(p<j)\\ \\text{or }(..." read "(p<j)or" -- a space on each side now."""
    out = ap.mathml(r"\left(  p<j\right)  \ \text{or }\left(  p-j\right)", False)
    assert "<mspace" in out and "or&#x000A0;" in out
