"""Lines of Section sec:partition_of_unity (source lines 1907-2167), checked in :mod:`paper_repro.claims.lines.sec5`:
the comparisons read their transcriptions and reject wrong ones."""

from __future__ import annotations

import pytest

from paper_repro.claims.lines import load_checks
from paper_repro.claims.lines import sec5 as ck
from paper_repro.claims.lines.mutation import blank_test
from paper_repro.printed.latex_math import LatexMathError
from paper_repro.printed.lines import sec4_5 as pl
from paper_repro.printed.lines import substituted, verbatim
from paper_repro.printed.parsed import listed_range, relation, value


def test_y_range_erratum_is_sharp():
    assert ck.y_range_maps_into_omega(lambda a, x: x) == (True, True)
    assert ck.y_range_maps_into_omega(lambda a, x: a - x) != (True, True)


def test_weights_and_partition_sum_are_read_from_their_transcriptions():
    text = {x.id: x.verbatim for x in pl.LINES}
    weights = text["sec4_5-weights"]
    assert ck.check_weights_index().holds_as_printed
    assert not ck.check_weights_index(weights.replace("r_{2n,n,n}^{\\alpha},", "")).holds_as_printed
    assert not ck.check_weights_index(weights.replace("_{j=0,i=j}^{n-1,2n-1-j}", "_{j=0,i=j}^{n-1,2n-j}")
                                      ).holds_as_printed
    lsum = text["sec4_5-L-sum"]
    assert ck.check_partition_sum().holds_as_printed
    assert not ck.check_partition_sum(lsum.replace("\\sum_{i=j}^{2n-1-j}g", "\\sum_{i=j+1}^{2n-1-j}g")
                                      ).holds_as_printed
    assert not ck.check_partition_sum(lsum.replace("b_{2n,2n-i,j}^{\\alpha}B", "b_{2n,2n-i,j}^{\\alpha}G")
                                      ).holds_as_printed


# -- sec4_5-chain-sum tests its own line, "= 0" included (issue 31, item 6) --------------------------------------------
def test_chain_sum_is_checked_with_its_value_and_rejects_wrong_transcriptions():
    line = {x.id: x for x in pl.LINES}["sec4_5-chain-sum"]
    assert line.check == "sec4_5-chain-sum" and ck.check_chain_sum().holds_as_printed
    for right, wrong in (("=0,~", "=1,~"), ("\\left( -1\\right) ^{k}", "\\left( 1\\right) ^{k}"),
                         ("v^{r-k}", "v^{r}"), ("\\dbinom{r}{k}", "\\dbinom{r}{0}"),
                         ("\\sum_{k=0}^{r}", "\\sum_{k=1}^{r}"), ("_{y=0}", "_{y=x}")):
        assert right in line.verbatim
        assert not ck.check_chain_sum(line.verbatim.replace(right, wrong)).holds_as_printed, wrong
    orders = {x.id: x for x in pl.LINES}["sec4_5-parametrization-restated"].verbatim
    assert not ck.check_chain_sum(orders=orders.replace("r=1,2", "r=0,1")).holds_as_printed  # r = 0 gives 1


def test_cos_nonzero_is_its_own_check_and_reads_its_interval():
    line = {x.id: x for x in pl.LINES}["sec4_5-cos-nonzero"]
    assert line.check == "sec4_5-cos-nonzero" and ck.check_cos_nonzero().holds_as_printed
    assert not ck.check_cos_nonzero(line.verbatim.replace("0,\\alpha", "0,2\\alpha")).holds_as_printed
    assert not ck.check_cos_nonzero(line.verbatim.replace("\\neq0", "=0")).holds_as_printed


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec4_5-blending-set", "^{n-1,2n-1-j}", "^{n-1,2n-j}"),
    ("sec4_5-blending-set", "\\overline{B}_{2n,2n-i,j}", "\\overline{G}_{2n,2n-i,j}"),
    ("sec4_5-blending-centre-set", "\\overline{G}_{2n,n,n}", "\\overline{G}_{2n,n,n-1}"),
])
def test_blending_set_is_read_from_the_transcription(line_id, right, wrong):
    text = {x.id: x.verbatim for x in pl.LINES}[line_id]
    assert right in text and ck.check_blending_def().holds_as_printed
    assert not ck.check_blending_def({line_id: text.replace(right, wrong, 1)}).holds_as_printed


def test_unknowns_are_read_from_both_lines():
    text = {x.id: x.verbatim for x in pl.LINES}
    assert ck.check_unknowns().holds_as_printed
    assert not ck.check_unknowns({"sec4_5-unknowns": text["sec4_5-unknowns"].replace("^{n,n}", "^{n,n-1}")}
                                 ).holds_as_printed  # a class without its unknown
    assert not ck.check_unknowns({"sec4_5-closed-forms-index": text["sec4_5-closed-forms-index"].replace(
        "_{j=0,i=j}", "_{j=0,i=0}")}).holds_as_printed  # two unknowns in one class


def test_system_reads_its_orders_and_right_hand_side():
    text = {x.id: x.verbatim for x in pl.LINES}
    assert ck.check_system().holds_as_printed
    assert not ck.check_system({"sec4_5-system-r-range": text["sec4_5-system-r-range"].replace(
        "\\ldots,n", "\\ldots,n-1")}).holds_as_printed  # order n is needed for a unique solution
    assert not ck.check_system({"sec4_5-system": text["sec4_5-system"].replace("\\delta_{r,0}", "1")}
                               ).holds_as_printed


# -- the printed formulas are parsed, and a wrong transcription fails (issue 37) --------------------------------------

SEC5 = sorted({x.check for x in pl.LINES if x.status != "excused" and x.tex[0] >= 1907
               and not x.check.startswith("claim:")})


def _run(check_id: str, texts: dict[str, str] | None = None):
    with substituted(texts or {}):
        return load_checks()[check_id]()


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
def test_every_section5_check_fails_on_a_blank_line():
    assert [r["check"] for r in blank_test(SEC5) if not r["killed"]] == []


def test_parser_reads_the_paper_notation():
    import sympy

    a = sympy.Symbol("alpha")
    half = a / 2
    expected = 2 * sympy.cos(half) / sympy.sin(half) ** 2
    assert value(r"\frac{2\cos\frac{\alpha}{2}}{\sin ^{2}\frac{\alpha}{2}}") == expected
    rel = relation(r"r_{6,4,2}^{\alpha} & =c_{6,4}\left( 2+\dfrac{6}{\sin^{2}\frac{\alpha}{2}}\right)")
    c64 = sympy.Function("c")(6, 4)
    assert rel.ops == ["="] and sympy.simplify(rel.parts[1] - c64 * (2 + 6 / sympy.sin(a / 2) ** 2)) == 0
    assert listed_range(r"~i=j+1,j+2,\ldots,n-1,", "i")[1:] == (sympy.Symbol("j") + 1, sympy.Symbol("n") - 1)
    for bad in (r"~i=j,j+1,,\ldots,n", r"~i=0,2,\ldots,n"):  # an empty item; a step of two
        with pytest.raises(LatexMathError):
            listed_range(bad, "i")


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec4_5-ex-r633-final", "324\\cos", "326\\cos"),  # a closed-form constant
    ("sec4_5-ex-r633-mid", "-\\frac{8}%", "+\\frac{8}%"),  # a sign inside the combination
    ("sec4_5-ex-r422-mid", "+2\\right)", "\\right)"),  # the dropped "+ 2"
    ("sec4_5-ex-r211-final", "}{\\sin^{2}\\frac{\\alpha}{2}}", "}{\\sin^{3}\\frac{\\alpha}{2}}"),
    ("sec4_5-ex-r640-c-value", "+3}", "+4}"),
    ("sec4_5-ex-r430-r-c", "c_{4,3}", "c_{4,2}"),
    ("sec4_5-ex-r651-mid", "r_{6,5,1}", "r_{6,4,1}"),
])
def test_example_lines_are_parsed_and_a_wrong_transcription_fails(line_id, right, wrong):
    text = verbatim(line_id)
    check = pl.LINES[[x.id for x in pl.LINES].index(line_id)].check
    assert right in text and _run(check).holds_as_printed
    assert not _run(check, {line_id: text.replace(right, wrong, 1)}).holds_as_printed


def test_erratum_c64_without_superscript_alpha():
    res = _run("sec4_5-ex-r642-mid")
    assert res.holds_as_printed is False and res.corrected_holds is True
    assert res.detail["without_superscript_alpha"] == ["c_{6,4}"] and res.detail["identity_in_alpha"]
    fixed = verbatim("sec4_5-ex-r642-mid").replace("c_{6,4}\\left(", "c_{6,4}^{\\alpha}\\left(")
    assert _run("sec4_5-ex-r642-mid", {"sec4_5-ex-r642-mid": fixed}).holds_as_printed
    wrong = verbatim("sec4_5-ex-r642-mid").replace("\\frac{6}{\\sin^{2}\\frac{\\alpha}{2}}\\cos", "\\frac{5}{\\sin^{2}"
                                                                                                   "\\frac{\\alpha}{2}}\\cos")
    assert _run("sec4_5-ex-r642-mid", {"sec4_5-ex-r642-mid": wrong}).corrected_holds is False


def test_erratum_doubled_comma_of_symmetry_condition_3():
    res = _run("sec4_5-symmetry-3")
    assert res.holds_as_printed is False and res.corrected_holds is True and "empty item" in res.detail["unread"]
    fixed = verbatim("sec4_5-symmetry-3").replace(",,", ",")
    assert _run("sec4_5-symmetry-3", {"sec4_5-symmetry-3": fixed}).holds_as_printed
    narrower = verbatim("sec4_5-symmetry-3").replace("\\ldots,2n-1-j", "\\ldots,2n-2-j")
    assert _run("sec4_5-symmetry-3", {"sec4_5-symmetry-3": narrower}).corrected_holds is False  # incomplete


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec4_5-symmetry-1", "i=j+1,j+2,\\ldots,n-1", "i=j+2,j+3,\\ldots,n-1"),  # a condition missing: not complete
    ("sec4_5-symmetry-1", "=r_{2n,i,j}", "=r_{2n,i+1,j}"),
    ("sec4_5-symmetry-2", "g_{2n,2n-i,j}", "b_{2n,2n-i,j}"),
])
def test_symmetry_conditions_are_parsed(line_id, right, wrong):
    text = verbatim(line_id)
    assert right in text and _run(line_id).holds_as_printed
    assert not _run(line_id, {line_id: text.replace(right, wrong, 1)}).holds_as_printed


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
@pytest.mark.parametrize("check, line_id, right, wrong", [
    ("sec4_5-level-1", "sec4_5-level1-range", "n\\geq2", "n\\geq1"),  # the formula fails at n = 1
    ("sec4_5-level-1", "sec4_5-level1-i", "\\dfrac{i+1}", "\\dfrac{i+2}"),
    ("sec4_5-level-1", "sec4_5-level1-i1", "c_{2n,2n-2}", "c_{2n,2n-1}"),
    ("sec4_5-level-0", "sec4_5-level0-c-c", "=c_{2n,i}", "=c_{2n,i+1}"),
    ("sec4_5-matrix-sizes", "sec4_5-matrix-sizes", "\\left( n+2\\right)", "\\left( n+3\\right)"),
    ("sec4_5-matrix-sizes", "sec4_5-matrix-sizes", "3n\\left( n+1\\right) +1", "3n\\left( n+1\\right)"),
    ("sec4_5-tan-polynomial", "sec4_5-tan-polynomial", "equals $2n$", "equals $2n+1$"),
    ("sec4_5-tan-polynomial", "sec4_5-tan-polynomial", "$\\sin\\frac{x}{2}$", "$\\sin\\frac{\\alpha}{2}$"),
    ("sec4_5-chain-rule", "sec4_5-parametrization-restated", "=x-y$", "=x+y$"),
    ("sec4_5-unknowns", "sec4_5-closed-forms-index", "$2\\leq r", "$3\\leq r"),
    ("sec4_5-partition-sum", "sec4_5-L-sum", "+\\sum_{j=0}^{n-1}\\sum_{i=j}^{2n-1-j}g", "-\\sum_{j=0}^{n-1}"
                                                                                       "\\sum_{i=j}^{2n-1-j}g"),
    ("sec4_5-partition-sum", "sec4_5-L-one", "1 & =L", "2 & =L"),
    ("sec4_5-system", "sec4_5-system", "_{y=0}", "_{y=1}"),
    ("sec4_5-system", "sec4_5-ex-r631-mid", "r_{6,3,1}^{\\alpha} &", "r_{6,3,2}^{\\alpha} &"),  # listed twice
    ("sec4_5-blending-def", "sec4_5-blending-centre", "=r_{2n,n,n}", "=g_{2n,n,n-1}"),
])
def test_section5_lines_are_read(check, line_id, right, wrong):
    text = verbatim(line_id)
    assert right in text and _run(check).holds_as_printed
    assert not _run(check, {line_id: text.replace(right, wrong, 1)}).holds_as_printed


def test_printed_normalization_is_parsed_not_retyped():
    """printed.normalization's tables come from the transcriptions: they follow a changed line, and they agree
    with the closed forms proven for every alpha (theory), an independent source."""
    from flint import fmpq_poly

    from paper_repro.printed import normalization as pn
    from paper_repro.theory.closed_forms import closed_forms_cached

    for lab, (_ref, num, k) in pn.FINAL.items():
        form = closed_forms_cached(int(lab.split(",")[0][3:]) // 2)[lab]
        # equal as functions of alpha: P(c)/s^k with s^2 = 1 - c^2 (both sides times s^max)
        m = max(k, form.sin_power)
        lhs, rhs = fmpq_poly(num), form.numerator
        one_minus = fmpq_poly([1, 0, -1])
        assert (m - k) % 2 == 0 and (m - form.sin_power) % 2 == 0
        assert lhs * one_minus ** ((m - k) // 2) == rhs * one_minus ** ((m - form.sin_power) // 2), lab
    text = verbatim("sec4_5-ex-r633-final")
    with substituted({"sec4_5-ex-r633-final": text.replace("324\\cos", "326\\cos")}):
        assert pn.FINAL["r_{6,3,3}"][1][2] == 326
    with substituted({"sec4_5-level1-i": verbatim("sec4_5-level1-i").replace("\\dfrac{i+1}", "\\dfrac{i+2}")}):
        from fractions import Fraction as F

        assert pn.prop_level_1(3, 2, F(3, 5), F(4, 5), F) == 2 / F(3, 5) * 4 * F(4, 5) + 4 / F(3, 5) * 3


def test_nonnegativity_claim_reads_its_line():
    from paper_repro.claims.nonnegativity import printed_orders

    assert printed_orders() == ([1, 2, 3], "non-negative")
    text = verbatim("sec4_5-nonnegative")
    with substituted({"sec4_5-nonnegative": text.replace("non-negative", "negative")}):
        assert printed_orders()[1] == "negative"
    with substituted({"sec4_5-nonnegative": "XXX"}):
        assert printed_orders() == ([], "")
