"""Lines of Section sec:coincidence (source lines 1414-1906; Section 5: tests/test_lines_sec5.py): every check meets its
expectation, and the comparisons reject wrong input."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest

from paper_repro.claims.lines import LINE_KINDS, load_checks
from paper_repro.claims.lines import sec4_5 as ck
from paper_repro.printed.lines import sec4_5 as pl

CHECKS = load_checks()
OWN = sorted({line.check for line in pl.LINES if line.check and not line.check.startswith("claim:")})
EXPECT = {}
for _line in pl.LINES:
    if _line.check and not _line.check.startswith("claim:"):
        EXPECT.setdefault(_line.check, set()).add(_line.status)


def _floats(x) -> bool:
    if isinstance(x, float):
        return True
    if isinstance(x, dict):
        return any(_floats(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return any(_floats(v) for v in x)
    return False


@pytest.mark.parametrize("check_id", OWN)
def test_check_meets_expectation(check_id):
    statuses = EXPECT[check_id]
    assert len(statuses) == 1, f"{check_id} is used by lines of different status {statuses}"
    res = CHECKS[check_id]()
    if statuses == {"checked"}:
        assert res.holds_as_printed is True
    else:
        assert res.holds_as_printed is False and res.corrected_holds is True
    assert res.kind in LINE_KINDS and res.how
    json.dumps(res.detail)
    assert not _floats(res.detail)


def test_every_registered_check_of_the_part_is_used():
    mine = {k for k in CHECKS if k.startswith("sec4_5-")}
    assert mine == set(OWN)


def test_ids_and_ranges():
    ids = [line.id for line in pl.LINES]
    assert len(ids) == len(set(ids)) and all(i.startswith("sec4_5-") for i in ids)
    assert all(1414 <= line.tex[0] <= line.tex[1] <= 2167 for line in pl.LINES)


# -- the comparisons reject wrong input ----------------------------------------------------------------------------
def test_exp_polynomials_reject_a_false_identity():
    x, y, xm, xp = (1, 0), (0, 1), (1, -1), (1, 1)
    assert not ck.EP.cos(x) * ck.EP.cos(y) == (ck.EP.cos(xm) - ck.EP.cos(xp)) * Fraction(1, 2)
    assert not ck.EP.sin((Fraction(1, 2),)) ** 2 == ck.EP.const(1, Fraction(1, 2))





# ======================================================================================================================
# Section 4 (sec:coincidence, source lines 1414-1906): every check reads its lines (issue 37).  Helper sec4's block.
# ======================================================================================================================
SEC4_CHECKS = sorted({x.check for x in pl.LINES if x.tex[0] < 1907 and x.status != "excused"})


def _verdict(check_id: str, texts: dict[str, str]):
    from paper_repro.claims.lines.mutation import verdict_with

    return verdict_with(check_id, texts)


def test_sec4_no_retyped_copies_left():
    for name in ("proof_r_exponents", "power_reduction", "PRODUCT_TYPES"):
        assert not hasattr(pl, name), name


def test_sec4_reader_reads_the_notation_and_refuses_the_rest():
    import sympy as sp

    from paper_repro.claims.lines.sec4_5 import PM, chain, parse
    from paper_repro.printed.latex_math import LatexMathError as TexError

    u, t, m = sp.symbols("u t m")
    assert parse(r"\sin^{m}\frac{t}{2}") == sp.sin(t / 2) ** m
    assert parse(r"\cos\left( z\mp r_{1}\right)") == sp.cos(sp.Symbol("z") - PM * sp.Symbol("r1"))
    assert parse(r"za") == sp.Symbol("z") * sp.Symbol("a")  # juxtaposition: the printed 'za' is z times a
    assert chain(r"{\displaystyle\sum\limits_{k=0}^{2}} k = 3")[0].doit() == 3
    assert chain(r"z=\min\left\{ r_{1},g_{1}+1\right\} .") == [sp.Symbol("z"), sp.Min(sp.Symbol("r1"),
                                                                                      sp.Symbol("g1") + 1)]
    for bad in (r"a=b,~\forall x", r"\leq & b", r"a\leq b"):  # a chain of '=' only
        with pytest.raises(TexError):
            chain(bad)
    for bad in ("", r"\foo{x}", r"\sin\left( u"):
        with pytest.raises(TexError):
            parse(bad)
    assert ck.to_ep(parse(r"\sin x\cos y"), sp.symbols("x y")) == ck.EP.sin((1, 0)) * ck.EP.cos((0, 1))
    with pytest.raises(TexError):
        ck.to_ep(parse(r"\sin\left( xy\right)"), sp.symbols("x y"))


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
@pytest.mark.parametrize("check_id", SEC4_CHECKS)
def test_sec4_blank_line_fails_its_check(check_id):
    from paper_repro.claims.lines.mutation import blank_test

    (rec,) = blank_test([check_id])
    assert rec["killed"], rec


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
@pytest.mark.parametrize("check_id, line_id, right, wrong", [
    ("sec4_5-relation", "sec4_5-cond2-row2", "g_{2}-g_{1}", "g_{2}+g_{1}"),
    ("sec4_5-relation", "sec4_5-z-range", ",0,1,\\ldots,2n", ",0,2,\\ldots,2n"),
    ("sec4_5-phase-cos", "sec4_5-cos-step2", "\\mp\\left(", "\\pm\\left("),
    ("sec4_5-phase-cos", "sec4_5-phase-meaning", "only in a phase change", "only in amplitude"),
    ("sec4_5-phase-sin", "sec4_5-sin-step1", "z\\alpha\\mp", "z\\alpha\\pm"),
    ("sec4_5-examples-n3", "sec4_5-examples-n3-2", "1\\cdot u+3\\cdot v", "1\\cdot u+4\\cdot v"),  # not in E_3
    ("sec4_5-orders-1-2", "sec4_5-order2-classes", "equal to $2$", "equal to $1$"),
    ("sec4_5-orders-1-2", "sec4_5-n2-chain", "\\left( 2-z\\right) w+z\\alpha\\\\", "\\left( 2-z\\right) w\\\\"),
    ("sec4_5-orders-1-2", "sec4_5-V2-row3", "\\in \\Omega", "\\notin \\Omega"),
    ("sec4_5-dimension", "sec4_5-dim-recurrence", "+6n", "+6n+1"),
    ("sec4_5-dimension", "sec4_5-prop-6n", "$6n$", "$3n$"),
    ("sec4_5-dimension", "sec4_5-E-n", "\\leq n", "\\leq n+1"),
    ("sec4_5-coincidence-rank", "sec4_5-theorem", "V_{n}^{\\alpha}=\\mathcal", "V_{n-1}^{\\alpha}=\\mathcal"),
    ("sec4_5-coincidence-rank", "sec4_5-contradiction", "1+\\delta_{n}", "\\delta_{n}"),
    ("sec4_5-proof-reduction", "sec4_5-proof-R", "\\sin^{i}\\frac{w}{2}", "\\sin^{i}\\frac{v}{2}"),
    ("sec4_5-proof-reduction", "sec4_5-proof-symmetry-reduction", "i=j,j+1,\\ldots,n", "i=j,j+1,\\ldots,n-1"),
    ("sec4_5-power-reduction", "sec4_5-sin-power-even", "\\left( -1\\right) ^{\\frac{m}{2}-k}",
     "\\left( -1\\right) ^{k}"),
    ("sec4_5-power-reduction", "sec4_5-cos-power-odd", "k=0}^{\\frac{m-1}{2}}", "k=1}^{\\frac{m-1}{2}}"),
    ("sec4_5-product-types", "sec4_5-product-type-3", "j\\equiv1", "j\\equiv0"),
    ("sec4_5-product-types", "sec4_5-product-type-2", "\\frac{2n-i-2k_{1}}{2}u", "\\frac{2n-i+2k_{1}}{2}u"),
    ("sec4_5-K-00", "sec4_5-K00", "\\frac{i}{2}", "\\frac{i+2}{2}"),
    ("sec4_5-K-11", "sec4_5-K11", "0,1,\\ldots,\\frac{i-1}{2}", "0,2,\\ldots,\\frac{i-1}{2}"),
    ("sec4_5-product-to-sum", "sec4_5-product-to-sum-2", "-\\cos", "+\\cos"),
    ("sec4_5-eight-terms", "sec4_5-eight-terms", "eight", "four"),
    ("sec4_5-eight-terms", "sec4_5-signs", "s_{2},s_{3},s_{4}\\in", "s_{2},s_{3}\\in"),
    ("sec4_5-shift-chain", "sec4_5-shift-step3", "\\frac{j-2k_{4}-s_{3}}{2}\\right) v+s_{4}% \\frac{i-2k_{2}-s_{4}}",
     "\\frac{j-2k_{4}}{2}\\right) v+s_{4}% \\frac{i-2k_{2}-s_{4}}"),
    ("sec4_5-integer-class", "sec4_5-z-min", "\\min", "\\max"),
    ("sec4_5-integer-class", "sec4_5-integer", "K_{1,1}", "K_{0,0}"),
    ("sec4_5-max-bounds", "sec4_5-max2-i", "i\\leq n", "i\\leq n-1"),
    ("sec4_5-inclusion", "sec4_5-inclusion", "\\cup_{i=1}^{n}", "\\cup_{i=1}^{n-1}"),
    ("sec4_5-in-Vn", "sec4_5-in-Vn", "\\in V_{n}", "\\in V_{n-1}"),
])
def test_sec4_checks_reject_a_wrong_transcription(check_id, line_id, right, wrong):
    text = pl.LINES[[x.id for x in pl.LINES].index(line_id)].verbatim
    assert right in text, (line_id, right)
    assert _verdict(check_id, {}) != _verdict(check_id, {line_id: text.replace(right, wrong, 1)})


@pytest.mark.parametrize("check_id, fixes", [
    ("sec4_5-phase-cos-za", {"sec4_5-cos-step4-za": ("za\\right)", "z\\alpha\\right)")}),
    ("sec4_5-phase-sin-za", {"sec4_5-sin-step2-za": ("za\\right)", "z\\alpha\\right)")}),
    ("sec4_5-prop-union", {"sec4_5-prop-recurrence": ("\\cup_{i=1}", "\\cup_{i=0}"),
                           "sec4_5-prop-new-classes": ("\\cup_{i=1}", "\\cup_{i=0}")}),
    ("sec4_5-K-10", {"sec4_5-K10": ("\\frac{i-j}% {2}", "\\frac{i-j-1}% {2}")}),
    ("sec4_5-max2-quantifier", {"sec4_5-max2-set": ("s_{1}=1,s_{2},s_{3}\\in", "s_{2},s_{3},s_{4}\\in")}),
    ("sec4_5-in-Vn", {"sec4_5-in-Vn": ("\\in V_{n}", "\\in\\operatorname{span}V_{n}")}),
])
def test_sec4_errata_printed_fails_corrected_text_holds(check_id, fixes):
    """Each erratum: the printed line fails, the corrected line (the printed text with the correction applied) holds
    as printed."""
    assert _verdict(check_id, {}) == (False, True)
    texts = {}
    for line_id, (right, wrong) in fixes.items():
        text = pl.LINES[[x.id for x in pl.LINES].index(line_id)].verbatim
        assert right in text
        texts[line_id] = text.replace(right, wrong)
    assert _verdict(check_id, texts)[0] is True


def test_sec4_max2_erratum_evidence():
    """With s4 = -1 the second max is (i-1)/2, not i (n = 1, i = j = 1: 0)."""
    assert not ck.max_values("sec4_5-max2-set", False, n_max=1)
    assert ck.max_values("sec4_5-max2-set", True, n_max=1)


def test_sec4_b2_erratum_counts():
    assert len(ck.b2_classes(2, False)) == 5 and len(ck.b2_classes(2, True)) == 3


def test_sec4_equivalent_mutants_exist_and_survive():
    """Every mutant recorded as equivalent for Section 4 is a mutant of its line, and its check says of it what it says
    of the paper (an equivalent mutant keeps the line true)."""
    from paper_repro.claims.lines.equivalents import EQUIVALENT
    from paper_repro.claims.lines.mutation import mutants, verdict

    sec4 = {x.id: x for x in pl.LINES if x.tex[0] < 1907}
    keys = [k for k in EQUIVALENT if k.split(":")[0] in sec4]
    assert keys
    for k in keys[::7]:  # a sample, to keep the fast suite fast
        line = sec4[k.split(":")[0]]
        (m,) = [m for m in mutants(line.verbatim, line.id) if m.key == k]
        assert _verdict(line.check, {line.id: m.text}) == verdict(line.check)


def test_sec4_readers_of_parsed_objects():
    """The helpers that replaced the regular expressions read the parsed objects, checked on hand-written LaTeX:
    the parity class of a condition (m odd; i even and j odd; a mod-4 condition is no parity class), the quantified
    signs of a set builder (s_2 listed with s_3's membership), the bounds of a union of quotient sets (refused when
    the member is not E of the bound variable) and the ordered factors of K_{a,b}."""
    import sympy as sp

    from paper_repro.printed import latex_math as lm

    m, i, j, n = sp.symbols("m i j n")
    assert ck._parities(lm.parse_cases(r"\left\{ \begin{array}[c]{rl} 1, & m\equiv1\left( \operatorname{mod}2\right)"
                                       r"\end{array}\right.")[0][1], ("m",)) == (1,)
    assert ck._parities(lm.parse_conditions(r"m\equiv0\left( \operatorname{mod}2\right)")[0], ("m",)) == (0,)
    cond = lm.parse_relation(r"x, & i\equiv0\left( \operatorname{mod}2\right) \text{ and }j\equiv1\left( "
                             r"\operatorname{mod}2\right)").conditions[0].parts[0]
    assert ck._parities(cond, ("i", "j")) == (0, 1)
    with pytest.raises(ck.LatexMathError):
        ck._parities(sp.Eq(sp.Mod(m, 4), 0), ("m",))
    rel = lm.parse_relation(r"\max\left\{ x:\left( k_{1},k_{2},k_{3},k_{4}\right) \in K_{1,1},~s_{1}=1,s_{2},"
                            r"s_{3}\in\left\{ -1,+1\right\} \right\} =1")
    member, quant = ck._quantified(rel.parts[0].args[0].args[1])
    assert quant == {"s1": [1], "s2": [-1, 1], "s3": [-1, 1]} and member.args[1] == sp.Function("K")(1, 1)
    assert ck.read_union(lm.parse(r"\cup_{i=2}^{n-1}E_{i}^{\alpha}/_{\sim}")) == (2, n - 1)
    with pytest.raises(ck.LatexMathError):
        ck.read_union(lm.parse(r"\cup_{i=1}^{n}E_{j}^{\alpha}/_{\sim}"))
    from paper_repro.printed.lines import substituted

    with substituted({"sec4_5-K00": r"K_{0,0} & =\left\{ 0,1,\ldots,j\right\} \times\left\{ 5\right\} ,\\"}):
        assert ck.read_k_sets("sec4_5-K00") == ("0,0", [[0, 1, None, j], [5]])
