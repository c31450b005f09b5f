"""Lines of Sections 7-8 (paper_repro.printed.lines.sec7): every check meets its expectation, and the comparisons
reject wrong inputs (a perturbed relation, elevation weight, conversion weight, index set or range)."""

from __future__ import annotations

from fractions import Fraction
from functools import cache

import pytest
import sympy

from paper_repro.claims.lines import CHECKS
from paper_repro.claims.lines import sec7 as C
from paper_repro.core.labels import index_of
from paper_repro.printed import parsed as P
from paper_repro.printed.lines.sec7 import LINES
from paper_repro.theory.ratfunc import RatFunc, half_angle_functions

BY_ID = {ln.id: ln for ln in LINES}
OWN = sorted({ln.check for ln in LINES if ln.check and not ln.check.startswith("claim:")})


@cache
def run(check_id: str):
    return CHECKS[check_id]()


def test_part_is_complete():
    assert len([i for i in BY_ID if i.startswith("sec7-rel-") and i[10:].isdigit()]) == 19
    assert len([i for i in BY_ID if i.startswith("sec7-elev-") and i[11:].isdigit()]) == 19
    assert len([i for i in BY_ID if i.startswith(("sec7-conv2-", "sec7-conv3-"))]) == 7 + 16
    assert all(c in CHECKS for c in OWN)
    assert all(ln.tex[0] >= 2667 and ln.tex[1] <= 3309 for ln in LINES)


@pytest.mark.parametrize("line_id", [ln.id for ln in LINES if ln.status != "excused" and
                                     not ln.check.startswith("claim:")])
def test_line_meets_expectation(line_id):
    line = BY_ID[line_id]
    res = run(line.check)
    if line.status == "checked":
        assert res.holds_as_printed, (line_id, res.detail)
    else:
        assert not res.holds_as_printed and res.corrected_holds, (line_id, res.detail)


@pytest.mark.parametrize("line_id,fix", [
    ("sec7-conv3-p215", ("\\Red{\\mathbf{r}_{6,1,1}}", "\\Red{\\mathbf{r}_{6,2,1}}")),
    ("sec7-conv3-p323", ("\\Red{\\mathbf{r}_{6,2,0}}", "\\Red{\\mathbf{r}_{6,3,0}}")),
    ("sec7-conv3-p880", ("\\mathbf{p}_{8,8,0}", "\\mathbf{p}_{8,0,0}")),
])
def test_known_conversion_errata(line_id, fix):
    """The three lines covered by claim bezier_conversion: printed fails, corrected holds (own comparison)."""
    tex = BY_ID[line_id].verbatim
    assert BY_ID[line_id].status == "erratum" and BY_ID[line_id].check == "claim:bezier_conversion"
    assert not C.conversion_holds(3, tex)
    assert C.conversion_holds(3, tex.replace(*fix))


def test_relation_rejects_perturbation():
    tex = BY_ID["sec7-rel-r431"].verbatim
    assert C.relation_holds(tex, "r_{4,3,1}")
    assert not C.relation_holds(tex.replace("\\sin\\alpha", "\\sin\\frac{\\alpha}{2}", 1), "r_{4,3,1}")
    assert not C.relation_holds(BY_ID["sec7-rel-r430"].verbatim, "r_{4,4,0}")  # right formula, wrong coefficient


def test_elevation_rejects_perturbation():
    tex = BY_ID["sec7-elev-r420"].verbatim
    assert C.elevation_row_holds(tex, 0, "1/3")
    wrong = tex.replace("\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}", "\\frac{1}{4+2\\cos^{2}\\frac{\\alpha}{2}}", 1)
    assert wrong != tex and not C.elevation_row_holds(wrong, 0, "1/3")
    # the symbolic identity: the printed matrix passes, a matrix with two weights exchanged fails
    s, c = half_angle_functions()
    mat = C.printed_elevation_matrix(c * c, s * s, RatFunc.const)
    assert all(C.elevation_identity(mat))
    k = index_of(2)["r_{4,2,0}"]  # weights 1/(2+4c^2) r_{2,2,0} + 2c^2/(1+2c^2) r_{2,1,0} + ...
    a, b = index_of(1)["r_{2,2,0}"], index_of(1)["r_{2,1,0}"]
    assert not mat[k][a] == mat[k][b]
    mat[k][a], mat[k][b] = mat[k][b], mat[k][a]
    assert not all(C.elevation_identity(mat))


def test_conversion_rejects_perturbation():
    tex = BY_ID["sec7-conv3-p611"].verbatim
    assert C.conversion_holds(3, tex)
    assert not C.conversion_holds(3, tex.replace("\\frac{15}{28}", "\\frac{13}{28}"))
    assert not C.conversion_holds(3, tex.replace("\\Blue{\\mathbf{b}_{6,1,0}}", "\\Green{\\mathbf{g}_{6,1,0}}"))


def test_index_sets_reject_perturbation():
    tex = BY_ID["sec7-unity-product"].verbatim
    assert C.printed_first_factor(tex, 3) == C._member_names(3)
    assert C.printed_first_factor(tex.replace("^{2n-1-j}", "^{2n-j}", 1), 3) != C._member_names(3)
    assert C.printed_first_factor(tex.replace("_{j=0}^{n-1}", "_{j=1}^{n-1}", 1), 3) != C._member_names(3)
    # a sign is read, not skipped; a superscript other than alpha is refused
    assert "-R_{6,6,0}" in C.printed_first_factor(tex.replace("}+%", "}-%", 1), 3)
    with pytest.raises(ValueError):
        C.unity_product(tex.replace("R}_{2n,n,n}^{\\alpha}", "R}_{2n,n,n}^{\\alpha-1}"))


def test_parametrization_report_distinguishes_ranges():
    good = C.parametrization_report({"x": ("0", "1"), "y": ("0", "1-x")})
    bad = C.parametrization_report({"x": ("0", "1"), "y": ("0", "x")})
    assert good["images_outside_Omega"] == good["simplex_points_not_reached"] == 0
    assert bad["images_outside_Omega"] > 0 and bad["simplex_points_not_reached"] > 0
    assert C.parametrization_rows()["v"][2] == ("in", "y", 0, sympy.Symbol("x"))
    wide = C.parametrization_report({"x": ("0", "2"), "y": ("0", "1-x")})
    assert wide["x_without_y"] > 0  # x in (1, 2] has no y: a printed x range wider than the domain is refused


def test_readers_refuse_unread_latex():
    with pytest.raises(ValueError):  # cot is read, but a relation's value is a sum of products and powers only
        C.relation_value("r_{4,2,2}^{\\alpha}=2\\Red{r_{2,2,0}^{\\alpha}}\\cot\\frac{\\alpha}{2}", Fraction,
                         {"s": 1, "c": 1, "sinA": 1, "tanH": 1}, {"r220": Fraction(1)})
    with pytest.raises(ValueError):
        P.conversion("\\mathbf{p}_{1,0,4} =\\frac{4}{5}\\Red{\\mathbf{r}_{4,1,0}}+\\frac{1}{5}"
                     "\\Green{\\mathbf{x}_{4,4,0}}")
    with pytest.raises(ValueError):
        P.evaluate_at("open('x')")


def test_degree_and_dimension_are_read_from_the_transcriptions():
    """The Question's degree 3n-1 and Section 8's delta_n = 3n(n+1)+1 are read, not retyped (issue 31, item 6)."""
    from paper_repro.claims.lines import sec7 as c7

    q, d = c7.VERBATIM["sec7-question-limiting-case"], c7.VERBATIM["sec7-s8-dimension"]
    assert c7.check_question_limiting_case().holds_as_printed and c7.check_dimension_and_span().holds_as_printed
    assert not c7.check_question_limiting_case(q.replace("$3n-1$", "$3n$")).holds_as_printed
    assert not c7.check_dimension_and_span(d.replace("\\right)+1$", "\\right)+2$")).holds_as_printed


def test_strict_conversion_reads_signs_and_relation():
    tex = BY_ID["sec7-conv2-p401"].verbatim
    idx, terms = P.conversion(tex)
    assert idx == (4, 0, 1) and [w for w, _ in terms] == [Fraction(1, 5), Fraction(4, 5)]
    assert not C.conversion_holds(2, tex.replace("}+\\frac", "}-\\frac"))
    with pytest.raises(ValueError):
        P.conversion(tex.replace("=", "\\neq ", 1))


@pytest.mark.parametrize("line_id,old,new", [
    ("sec7-question-limiting-case", "$\\alpha \\to 0$", "$\\alpha \\to 1$"),
    ("sec7-conversion-degrees", "$\\alpha \\to 0$", "$\\alpha \\to 1$"),
    ("sec7-conversion-degrees", "quadratic, quintic", "quadratic, sextic"),
    ("sec7-conversion-degrees", "first, second", "second, second"),
    ("sec7-fig-conversion-caption", "quintic", "sextic"),
    ("sec7-question-limiting-case", "order $n$", "order $n+1$"),
])
def test_named_weak_checks_read_limit_and_degrees(line_id, old, new):
    """issue 37: sec7-question-limiting-case and sec7-conversion-degrees read 'alpha -> 0' and the degrees."""
    from paper_repro.claims.lines.mutation import verdict, verdict_with

    check = BY_ID[line_id].check
    tex = BY_ID[line_id].verbatim
    assert old in tex
    assert verdict(check) == (True, None)
    assert verdict_with(check, {line_id: tex.replace(old, new, 1)}) != (True, None)


def test_sec7_mutants_of_a_sample_of_lines_are_killed():
    """The mutants of two lines (a conversion, the parametrization) are all killed (the blank test of every sec7 check
    is tests/test_line_mutation.py::test_blank_line_fails_its_check[sec7]; the whole part: make mutate-lines)."""
    from paper_repro.claims.lines.mutation import mutation_test, summary

    recs = mutation_test(["sec7-conv3-p512", "sec7-limit-param-map"])
    assert summary(recs)["rate"] == 1.0, [r["where"] for r in recs if not r["killed"] and not r["equivalent"]]


@pytest.mark.slow
def test_sec7_mutants_of_read_prose_and_definitions_are_killed():
    from paper_repro.claims.lines.mutation import mutation_test, summary

    recs = mutation_test(["sec7-bernstein-definition", "sec7-fig-limit-caption-centre", "sec7-s8-dimension-and-span"])
    assert summary(recs)["rate"] == 1.0, [r["where"] for r in recs if not r["killed"] and not r["equivalent"]]


def test_claim_lines_are_read_by_their_claims():
    """The lines resolved to claims give the claim the parsed printed object: pairwise_products_all_n reads the
    products, index set, target basis and consequences (every mutant of its three lines is refused or fails);
    bezier_conversion reads the printed conversions (blank: refused; each erratum line's correction holds)."""
    from paper_repro.claims.half_angle_all_n import printed_products_agree
    from paper_repro.claims.limits_claims import run_conversion
    from paper_repro.claims.lines.mutation import blank_test, mutants
    from paper_repro.printed.lines import lines_of, substituted, verbatim

    assert printed_products_agree()["ok"]
    for lid in [x.id for x in lines_of("claim:pairwise_products_all_n")]:
        for m in mutants(verbatim(lid), lid) + [type("B", (), {"text": "XXX"})()]:
            with substituted({lid: m.text}):
                try:
                    ok = printed_products_agree()["ok"]
                except ValueError:
                    ok = False
            assert not ok, (lid, m.text)
    out = run_conversion()
    assert out.passed and sorted(out.measured["mismatches"]) == ["p_{2,1,5}", "p_{3,2,3}", "p_{8,8,0}"]
    assert all(r["recorded_correction_holds"] and r["slips"] == 1 for r in out.measured["errata_lines"].values())
    assert blank_test(["claim:bezier_conversion"])[0]["killed"]
    with substituted({"sec7-conv3-p701": verbatim("sec7-conv3-p701").replace("{3}{4}", "{2}{4}")}):
        assert not run_conversion().passed


def test_triavariate_is_a_typo_and_the_corrected_caption_holds():
    """Second reading: 'triavariate' (once in the paper) is a typographical slip of 'trivariate'; the check fails the
    printed caption and passes the corrected one, whose mathematics (the centre vanishes) holds."""
    from paper_repro.claims.lines.mutation import verdict, verdict_with

    tex = BY_ID["sec7-fig-limit-caption-centre"].verbatim
    assert BY_ID["sec7-fig-limit-caption-centre"].status == "erratum" and "triavariate" in tex
    assert verdict("sec7-fig-limit-caption-centre") == (False, True)
    fixed = tex.replace("triavariate", "trivariate")
    assert verdict_with("sec7-fig-limit-caption-centre", {"sec7-fig-limit-caption-centre": fixed}) == (True, True)
    wrong = fixed.replace("innermost", "outermost")  # the mathematics is read too
    assert verdict_with("sec7-fig-limit-caption-centre", {"sec7-fig-limit-caption-centre": wrong})[1] is False
