"""Lines of Sections 1-3 (abstract .. end of Section 3): every check meets its line's expectation, and the checks
reject wrong inputs (perturbed index sets, bounds, levels, chain rules, parametrizations)."""

import json

import pytest
import sympy

from paper_repro.claims.lines import CHECKS, LINE_KINDS
from paper_repro.claims.lines import sec1_3 as C
from paper_repro.printed.lines import sec1_3 as P

OWN = sorted({line.check for line in P.LINES if line.check and not line.check.startswith("claim:")})


@pytest.fixture(scope="module")
def results():
    return {cid: CHECKS[cid]() for cid in OWN}


def _floats(obj) -> bool:
    if isinstance(obj, float):
        return True
    if isinstance(obj, dict):
        return any(_floats(v) for v in obj.values())
    if isinstance(obj, list | tuple):
        return any(_floats(v) for v in obj)
    return False


def test_every_line_meets_its_expectation(results):
    bad = []
    for line in P.LINES:
        if line.check is None or line.check.startswith("claim:"):
            continue
        r = results[line.check]
        if line.status == "checked" and r.holds_as_printed is not True:
            bad.append(f"{line.id}: does not hold as printed ({r.detail})")
        if line.status == "erratum" and not (r.holds_as_printed is False and r.corrected_holds is True):
            bad.append(f"{line.id}: erratum not confirmed ({r.detail})")
    assert not bad, "\n".join(bad)


def test_every_registered_check_of_the_part_is_used_and_reports_plain_values(results):
    assert {c for c in CHECKS if c.startswith("sec1_3-")} == set(OWN)
    for cid, r in results.items():
        json.dumps(r.detail)
        assert not _floats(r.detail), cid
        assert r.kind in LINE_KINDS and r.how


def test_errata_lines_name_their_fields():
    errata = [x for x in P.LINES if x.status == "erratum"]
    assert len(errata) == 13  # 11 + sec1_3-lemma-hypotheses, sec1_3-induction-orders (Section 3 part)
    known = {x.erratum.get("id") for x in errata if x.check.startswith("claim:")}
    assert known == {"lemma-sign-cos-power", "parametrization-partition-of-unity-range",
                     "independence-proof-gamma-index"}


# -- the checks reject wrong inputs ----------------------------------------------------------------------------
def test_united_dedupe_reads_the_transcription_and_rejects_the_full_ranges():
    text = {x.id: x.verbatim for x in P.LINES}["sec1_3-united-system"]
    assert C.united_dedupe().holds_as_printed and "_{j=0,i=j}^{n-1,2n-1-j}" in text
    # i = j..2n-j (the range of R_system) lists R_{2n,j,j} = G_{2n,2n-j,j} twice
    assert not C.united_dedupe(text.replace("^{n-1,2n-1-j}", "^{n-1,2n-j}")).holds_as_printed
    assert not C.united_dedupe(text.replace("_{j=0,i=j}", "_{j=0,i=j+1}")).holds_as_printed
    assert not C.united_dedupe(text.replace("^{n-1,2n-1-j}", "^{n-2,2n-1-j}")).holds_as_printed  # a level short


def test_chain_rule_rejects_a_wrong_pair_of_variables():
    assert C.chain_ok("parametrization_2_x_0", (0, 1))
    assert not C.chain_ok("parametrization_2_x_0", (1, 0))
    assert not C.chain_ok("parametrization_3_y_0", (0, 2))
    assert not C.chain_ok("parametrization_1_y_0", (1, 0))


def test_parametrization_check_rejects_the_printed_partition_range():
    assert not C.param_onto("parametrization_for_partition_of_unity")
    assert C.param_onto("parametrization_for_partition_of_unity", y_to=lambda a, x: x)
    assert all(C.param_onto(p) for p in C.STEP_PARAMS)


def test_boundary_vars_reads_the_transcriptions_and_rejects_a_wrong_variable():
    text = {x.id: x.verbatim for x in P.LINES}
    assert C.boundary_vars().holds_as_printed and C.boundary_vars().detail["lines"] == 8
    assert not C.boundary_vars({"sec1_3-r0-p2-where": text["sec1_3-r0-p2-where"].replace("$x=0$", "$y=0$")}
                               ).holds_as_printed
    caption = text["sec1_3-fig-j1-caption-params"]
    assert not C.boundary_vars({"sec1_3-fig-j1-caption-params": caption.replace("$x=0$ and $y=0$", "$y=0$ and $x=0$")}
                               ).holds_as_printed
    assert not C.boundary_vars({"sec1_3-rp3-where": text["sec1_3-rp3-where"].replace("at $y=0$", "at the edge")}
                               ).holds_as_printed  # a point missing


def test_sum_bound_and_levels_distinguish_printed_from_corrected():
    r = C.rp1_aform()
    assert not r.holds_as_printed and r.corrected_holds
    r = C.rp1_asystem()
    assert not r.holds_as_printed and r.corrected_holds
    assert C.rp1_zeroed(level=lambda n, r: r + 1).holds_as_printed
    assert C.rp2_zeroed(level=lambda n, r: r + 1).holds_as_printed
    # the correctly printed beta' line would fail with the level n-1 of the rho', gamma' lines
    assert not C._zeroed_check(lambda n, r: C.alive_before(n, r + 1, 2) - C.alive_after(n, r + 1, 2),
                               lambda n, r: n - 1, lambda n, r: r + 1,
                               lambda n, r: range(r + 2, 2 * n - 1 - (r + 1) + 1), "B", None).holds_as_printed


def test_index_set_comparison_rejects_a_shifted_level():
    wrong = C._proof_sets(lambda n, r: C.centre(n) | C.dsum("R", n, r, n - 1) | C.dsum("G", n, r + 1, n - 1)
                          | C.dsum("B", n, r + 1, n - 1), lambda n, r: C.alive_after(n, r, 2), rs=lambda n: range(n))
    assert not wrong.holds_as_printed and wrong.detail["mismatches"] > 0


def test_kth_term_rejects_a_wrong_exponent():
    from paper_repro.printed.lines import substituted, verbatim

    assert C.kterm_row_check("sec1_3-kterm-R-low").holds_as_printed
    text = verbatim("sec1_3-kterm-R-low")
    with substituted({"sec1_3-kterm-R-low": text.replace("M_{i-j,", "M_{i-j+1,")}):
        assert not C.kterm_row_check("sec1_3-kterm-R-low").holds_as_printed
    text = verbatim("sec1_3-kterm-B-high")  # a row that forgets the last i of its range no longer covers L_r
    with substituted({"sec1_3-kterm-B-high": text.replace("^{2n-1-j}", "^{2n-2-j}")}):
        assert not C.kterm_row_check("sec1_3-kterm-B-high").holds_as_printed


def test_bernstein_checks_accept_the_order_one_identity():
    from paper_repro.printed.lines import substituted, verbatim

    ident = verbatim("sec1_3-bernstein-identity")
    with substituted({"sec1_3-bernstein-identity": ident.replace("A_{2n,", "A_{2,")}):
        assert C.bernstein_identity().holds_as_printed
    power = verbatim("sec1_3-bernstein-power")
    middle = power.replace("\\left( s\\right)", "\\left( \\alpha s\\right)").replace("A_{2n,0}", "A_{2,0}")
    middle = middle.replace("A_{2n,1}", "A_{2,1}").replace("A_{2n,2}", "A_{2,2}")
    with substituted({"sec1_3-bernstein-power": middle}):
        assert C.bernstein_power().holds_as_printed


# -- Sections 1-2: each check reads its line; a wrong transcription fails (issue 37) -------------------------------
SEC12_WRONG = [
    ("alpha_range", "sec1_3-abstract-alpha-range", "\\pi\\right)", "\\pi\\right]"),
    ("alpha_range", "sec1_3-intro-alpha-range", "0,\\pi", "0,\\frac{\\pi}{2}"),
    ("fourier_dimension", "sec1_3-fourier-system", "^{n,n,n}", "^{n,n-1,n-1}"),  # one bound n-1 alone: same span
    ("fourier_dimension", "sec1_3-fourier-system", "ru+gv+bw\\right) ,\\sin", "ru+gv\\right) ,\\sin"),
    ("fourier_dimension", "sec1_3-span-coincide-dim", "+1$", "+2$"),
    ("fourier_dimension", "sec1_3-abstract-same-span", "order $n$", "order $n+1$"),
    ("univariate_span", "sec1_3-univariate-basis", "\\sin^{i}\\frac{t}{2}", "\\sin^{i+1}\\frac{t}{2}"),
    ("univariate_span", "sec1_3-univariate-basis", "_{i=0}^{2n}=", "_{i=0}^{2n-1}="),
    ("c_formula", "sec1_3-c-formula", "\\binom{i-r}{r}", "\\binom{i-r}{r+1}"),
    ("c_formula", "sec1_3-c-formula", "^{i-2r}", "^{i-r}"),
    ("c_formula", "sec1_3-c-formula", "non-negative", "negative"),
    ("c_formula", "sec1_3-c-formula", "\\ldots,2n", "\\ldots,2n-1"),
    ("c_symmetry", "sec1_3-c-symmetry", "c_{2n,2n-i}", "c_{2n,2n-i-1}"),
    ("c_symmetry", "sec1_3-c-symmetry", "i=0,1,", "i=1,2,"),
    ("levels", "sec1_3-graph-levels", "to $n-1$", "to $n$"),
    ("levels", "sec1_3-levels-j", "index $j$", "index $i$"),
    ("corners_centre", "sec1_3-corners-centre", "$\\sin^{2n}\\frac{v}{2}$", "$\\sin^{2n-1}\\frac{v}{2}$"),
    ("corners_centre", "sec1_3-united-centre", "G_{2n,n,n}", "G_{2n,n,n-1}"),
    ("nonnegative", "sec1_3-nonnegative", "non-negative", "positive"),
    ("united_dedupe", "sec1_3-united-system", "G_{2n,2n-i,j}^{\\alpha}", "G_{2n,i,j}^{\\alpha}"),
    ("order_n3", "sec1_3-T6-order-3", "$T_{6}", "$T_{8}"),
    ("order_n3", "sec1_3-fig-united-n3-caption", "$n=3$", "$n=4$"),
    ("boundary_v0", "sec1_3-boundary-property-1", "_{v=0}", "_{u=0}"),
    ("boundary_u0", "sec1_3-boundary-property-2", "A_{2n,2n-i}^{\\alpha}", "A_{2n,2n-i-1}^{\\alpha}"),
    ("boundary_w0", "sec1_3-boundary-property-3", "_{i=0}^{2n}", "_{i=1}^{2n}"),
    ("bernstein_limit", "sec1_3-bernstein-limit", "\\left( \\alpha s\\right) =", "\\left( s\\right) ="),
    ("bernstein_limit", "sec1_3-bernstein-limit", "B_{i}^{2n}", "B_{i}^{2n-1}"),
    ("bernstein_proof_limit", "sec1_3-bernstein-limits-used", "=s$", "=1$"),
    ("bernstein_proof_limit", "sec1_3-bernstein-limit-step1", "2\\left( 1-s\\right) s", "\\left( 1-s\\right) s"),
    ("bernstein_polynomials", "sec1_3-bernstein-limit-step2", "^{2n}", "^{2n-1}"),
    ("bernstein_polynomials", "sec1_3-bernstein-limit-step3", "B_{i}^{2n}", "B_{i+1}^{2n}"),
]


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
@pytest.mark.parametrize("check, line_id, right, wrong", SEC12_WRONG)
def test_sec12_checks_reject_a_wrong_transcription(check, line_id, right, wrong):
    from paper_repro.printed.lines import substituted, verbatim

    text = verbatim(line_id)
    assert right in text, (line_id, right)
    base = getattr(C, check)()
    with substituted({line_id: text.replace(right, wrong, 1)}):
        try:
            changed = getattr(C, check)()
        except Exception:  # a check that refuses a line it cannot read
            return
    assert (changed.holds_as_printed, changed.corrected_holds) != (base.holds_as_printed, base.corrected_holds)


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec1_3-bernstein-identity", "=1,~", "=2,~"),
    ("sec1_3-bernstein-power", "A_{2n,1}^{\\alpha}\\left( s", "A_{2n,0}^{\\alpha}\\left( s"),
])
def test_bernstein_errata_checks_read_the_corrected_part(line_id, right, wrong):
    """An erratum check corrects only what the erratum says: another slip on the line makes the correction fail."""
    from paper_repro.printed.lines import substituted, verbatim

    check = {"sec1_3-bernstein-identity": C.bernstein_identity, "sec1_3-bernstein-power": C.bernstein_power}[line_id]
    assert check().corrected_holds is True
    with substituted({line_id: verbatim(line_id).replace(right, wrong, 1)}):
        assert check().corrected_holds is False


def test_interval_check_accepts_a_comma():
    from paper_repro.printed.lines import substituted

    with substituted({"sec1_3-r0-p3-interval": r"x\in\left[ 0,\alpha\right]"}):
        assert C.interval_typo().holds_as_printed


def test_fig_n4_rule_holds_at_every_order():
    assert all(C.fig_n4_caption(order=z).holds_as_printed for z in range(1, 9))


def test_elimination_is_exact_and_leaves_the_centre():
    for n in range(1, 5):
        assert C.alive_after(n, n - 1, 2) == frozenset({0})
        removed = [k for _r, _p, _b, gone in C.elimination(n) for k in gone]
        assert sorted(removed) == list(range(1, len(removed) + 1))


# -- the checks read their lines from the transcription (issue 31, item 6) --------------------------------------
@pytest.mark.parametrize("line_id, wrong", [
    ("sec1_3-R-system", ("^{n,2n-j}", "^{n,2n-1-j}")),   # one function short per level
    ("sec1_3-B-system", ("^{n,2n-j}", "^{n,2n}")),       # negative cosine powers
    ("sec1_3-B-system", ("_{j=0,i=j}", "_{j=1,i=j}")),   # level 0 missing
    ("sec1_3-G-system", ("_{j=0,i=j}", "_{j=0,i=0}")),   # i < j: negative powers
    ("sec1_3-R-leq-n", ("^{n,n}", "^{n,n+1}")),          # the halves overlap
])
def test_rgb_index_sets_read_the_transcription_and_reject_a_wrong_one(line_id, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert wrong[0] in text
    assert C.rgb_index_sets(n_max=4).holds_as_printed
    assert not C.rgb_index_sets({line_id: text.replace(*wrong)}, n_max=4).holds_as_printed


def test_printed_exponents_are_those_of_the_package():
    from paper_repro.core.labels import BasisLabel, exponents

    for n in range(1, 6):
        for c in "RGB":
            for j in range(n + 1):
                for i in range(j, 2 * n - j + 1):
                    assert C.printed_exponents(c, n, i, j) == exponents(BasisLabel(c, n, i, j))
    assert C.printed_exponents("R", 2, 1, 2) is None  # i < j


@pytest.mark.parametrize("line_id", sorted(C.ZERO_LINES))
def test_zero_conclusions_are_their_own_checks_and_reject_wrong_transcriptions(line_id, monkeypatch):
    """gamma' = 0 (and rho', beta') is checked as the step's conclusion, not through the display before it."""
    line = {x.id: x for x in P.LINES}[line_id]
    assert line.check == line_id
    assert C.zero_conclusion(line_id).holds_as_printed
    assert not C.zero_conclusion(line_id, line.verbatim.replace("=0,", "=1,")).holds_as_printed
    lo = line.verbatim.split("~i=")[1].split(",")[0]
    wrong_lo = line.verbatim.replace(f"~i={lo},", f"~i={int(lo) + 1},")
    assert not C.zero_conclusion(line_id, wrong_lo).holds_as_printed  # one constant left out
    shorter = line.verbatim.replace("\\ldots,2n", "\\ldots,2n-2")
    assert shorter != line.verbatim and not C.zero_conclusion(line_id, shorter).holds_as_printed
    monkeypatch.setattr(C, "_rank", lambda rows: len(rows[0]) - 1)  # dependent restrictions: nothing is forced
    assert not C.zero_conclusion(line_id).holds_as_printed


# -- the sums of L, L-tilde, L-hat, L_0, L_r, ... are read from their rows (issue 31, item 6) ---------------------
@pytest.mark.parametrize("check, line_id, right, wrong", [
    ("l_set", "sec1_3-L-G-row", "\\sum\\limits_{j=0}^{n-1}", "\\sum\\limits_{j=1}^{n-1}"),
    ("ltilde_set", "sec1_3-Ltilde-row2", "\\sum\\limits_{i=1}^{2n-1}", "\\sum\\limits_{i=0}^{2n-1}"),
    ("lhat_set", "sec1_3-Lhat-row3", "\\beta_{2n,2n-i,0}B_{2n,2n-i,0}", "\\beta_{2n,2n-i,1}B_{2n,2n-i,1}"),
    ("l0_set", "sec1_3-L0-row2", "\\gamma_{2n,2n-i,j}G", "\\beta_{2n,2n-i,j}G"),
    ("lr_set", "sec1_3-Lr-row2", "\\sum\\limits_{j=r+1}^{n-1}", "\\sum\\limits_{j=r}^{n-1}"),
    ("lr1_set", "sec1_3-Lr1-row3", "\\sum\\limits_{i=j}^{2n-1-j}", "\\sum\\limits_{i=j}^{2n-j}"),
    ("ltilde_r_set", "sec1_3-Ltilde-r-row2", "\\gamma_{2n,2n-i,r+1}G_{2n,2n-i,r+1}",
     "\\gamma_{2n,2n-i,r}G_{2n,2n-i,r}"),
    ("lhat_r_set", "sec1_3-Lhat-r-row2", "\\sum\\limits_{i=r+2}", "\\sum\\limits_{i=r+3}"),
    ("ln2_set", "sec1_3-Ln2-row3", "\\sum\\limits_{i=n-1}^{n}", "\\sum\\limits_{i=n-1}^{n+1}"),
    ("ln1_set", "sec1_3-Ln1", "\\rho_{2n,n,n}R_{2n,n,n}", "\\rho_{2n,n,n-1}R_{2n,n,n-1}"),
])
def test_sum_sets_read_their_rows_and_reject_a_wrong_transcription(check, line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text
    fn = getattr(C, check)
    assert fn().holds_as_printed
    assert not fn({line_id: text.replace(right, wrong)}).holds_as_printed


def test_a_constant_that_does_not_match_its_function_is_unread():
    text = {x.id: x.verbatim for x in P.LINES}["sec1_3-L-R-row"]
    res = C.l_set({"sec1_3-L-R-row": text.replace("\\rho_{2n,n,n}R", "\\gamma_{2n,n,n}R")})
    assert not res.holds_as_printed and "does not match" in res.detail["unread"]


def test_zeroed_constants_are_read_from_the_transcription():
    text = {x.id: x.verbatim for x in P.LINES}
    rp3 = text["sec1_3-rp3-zeroed"]
    assert C.rp3_zeroed().holds_as_printed
    for right, wrong in (("=0,", "=1,"), ("i=r+2,r+3", "i=r+1,r+2"),
                         ("2n-1-\\left( r+1\\right)", "2n-\\left( r+1\\right)"),
                         ("\\beta_{2n,2n-i,r+1}", "\\beta_{2n,2n-i,r}")):
        assert right in rp3, right
        assert not C.rp3_zeroed(verbatim=rp3.replace(right, wrong)).holds_as_printed, wrong
    rp1 = text["sec1_3-rp1-zeroed"]
    assert C.rp1_zeroed(level=lambda n, r: r + 1).holds_as_printed  # the erratum's level
    assert not C.rp1_zeroed(level=lambda n, r: r + 1, verbatim=rp1.replace("i=r+1,r+2", "i=r+2,r+3")).holds_as_printed


@pytest.mark.parametrize("check, line_id, right, wrong", [
    ("chain_1", "sec1_3-chain-1", "\\partial v_{1}^{r-k}\\partial w_{1}^{k}",
     "\\partial w_{1}^{r-k}\\partial v_{1}^{k}"),
    ("chain_1", "sec1_3-y-derivative-L-r", "\\left( -1\\right) ^{k}", "\\left( 1\\right) ^{k}"),
    ("chain_2", "sec1_3-x-derivative-L-tilde-r", "\\partial u_{2}^{r+1-k}", "\\partial w_{2}^{r+1-k}"),
    ("chain_3", "sec1_3-chain-3", "\\partial w_{3}^{r-k}\\partial u_{3}^{k}",
     "\\partial u_{3}^{r-k}\\partial w_{3}^{k}"),
    ("chain_pu", "sec1_3-chain-rule", "\\partial v^{r-k}\\partial w^{k}", "\\partial v^{r-k}\\partial u^{k}"),
])
def test_chain_rules_read_their_variables_and_reject_a_wrong_transcription(check, line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text and getattr(C, check)().holds_as_printed
    assert not getattr(C, check)({line_id: text.replace(right, wrong)}).holds_as_printed


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec1_3-delta-sum", "^{2n-1-j}", "^{2n-j}"),
    ("sec1_3-delta-sum", "=1+3n", "=1+2n"),
    ("sec1_3-theorem-delta", "+1", "+2"),
    ("sec1_3-abstract-delta", "=3n", "=3"),
])
def test_delta_count_reads_every_printed_value(line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text and C.delta_count().holds_as_printed
    assert C.delta_count().detail["values_per_line"]["sec1_3-delta-sum"] == 2
    assert not C.delta_count({line_id: text.replace(right, wrong, 1)}).holds_as_printed


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec1_3-r0-p1-A-system", "_{i=0}^{2n}", "_{i=1}^{2n}"),      # not the A's of the sum before it
    ("sec1_3-r0-p2-A-system", "_{i=1}^{2n}", "_{i=0}^{2n+1}"),    # no such A
    ("sec1_3-r0-p3-aform", "\\sum_{i=1}^{2n-1}", "\\sum_{i=1}^{2n}"),
])
def test_a_systems_are_read_and_tied_to_their_sums(line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text and C.a_independent().holds_as_printed
    assert not C.a_independent({line_id: text.replace(right, wrong)}).holds_as_printed


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec1_3-induction-range", "\\ldots,n-1$", "\\ldots,n$"),
    ("sec1_3-step-range", "\\ldots,n-2$", "\\ldots,n-1$"),
    ("sec1_3-induction-conclusion", "$r=0,1,", "$r=1,2,"),
    ("sec1_3-fig-j1-caption-orders", "$r=n-2$", "$r=n-1$"),
    ("sec1_3-fig-j1-text", "the first and", "the second and"),
    ("sec1_3-fig-j1-text", "L_{n-2}", "L_{n-1}"),
])
def test_elimination_orders_read_their_six_lines(line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text and C.elimination_orders().holds_as_printed
    assert not C.elimination_orders({line_id: text.replace(right, wrong, 1)}).holds_as_printed


@pytest.mark.parametrize("check, line_id, right, wrong", [
    ("r0p1_terms", "sec1_3-r0-p1-terms", "\\sum_{i=0}^{2n-1}", "\\sum_{i=0}^{2n-2}"),
    ("r0p1_terms", "sec1_3-r0-p1-terms", "\\gamma_{2n,2n,0}G_{2n,2n,0}", "\\gamma_{2n,2n,1}G_{2n,2n,1}"),
    ("r0p2_terms", "sec1_3-r0-p2-terms", "0,\\alpha-y,y", "0,y,\\alpha-y"),     # not the edge of parametrization 2
    ("r0p3_terms", "sec1_3-r0-p3-terms", "\\beta_{2n,2n-i,0}B", "\\beta_{2n,2n-i,0}G"),  # constant and function differ
])
def test_order_0_terms_are_read_from_the_transcription(check, line_id, right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}[line_id]
    assert right in text and getattr(C, check)().holds_as_printed
    assert not getattr(C, check)(text.replace(right, wrong)).holds_as_printed


def test_omitted_functions_are_read_from_the_transcriptions():
    text = {x.id: x.verbatim for x in P.LINES}
    assert C.r0p1_omitted().holds_as_printed and C.r0p2_omitted().holds_as_printed
    assert not C.r0p1_omitted({"sec1_3-r0-p1-omitted": text["sec1_3-r0-p1-omitted"].replace("v_{1}", "w_{1}")}
                              ).holds_as_printed  # not the variable of the edge
    assert not C.r0p2_omitted({"sec1_3-r0-p2-terms": text["sec1_3-r0-p2-terms"].replace("i=1}", "i=2}")}
                              ).holds_as_printed  # a kept function called omitted


@pytest.mark.parametrize("right, wrong", [("\\gamma_{2n,2n-i,r+1}", "\\gamma_{2n,2n-i,r}"), ("_{i=r+1}", "_{i=r}"),
                                          ("equal to $0$", "equal to $1$")])
def test_level_zeroed_reads_the_constants(right, wrong):
    text = {x.id: x.verbatim for x in P.LINES}["sec1_3-step-zeroed"]
    assert right in text and C.level_zeroed().holds_as_printed
    assert not C.level_zeroed(text.replace(right, wrong)).holds_as_printed


# -- the readers of Sections 1-2 (issue 37) ------------------------------------------------------------------------
@pytest.mark.parametrize("line_id", ["sec1_3-R-leq-n", "sec1_3-G-geq-explicit", "sec1_3-B-leq-explicit"])
def test_explicit_formulas_are_read_by_latex_math(line_id):
    """The explicit R, G, B displays are read by printed/latex_math (no reader of their own): the set-builder's
    member is a product of half-angle powers whose exponents use n, i, j only, and a blank body is refused."""
    import sympy

    from paper_repro.printed import symmetry as S
    from paper_repro.printed.latex_math import LatexMathError
    from paper_repro.printed.lines import verbatim

    _, found = S.set_builders(verbatim(line_id))  # the display read by parse_relation: its bounded families
    body = found[-1][0]
    powers = S.half_angle_powers(body)
    assert {x for _, x in powers} <= set(S.VARS) and len(powers) >= 2
    assert set().union(*(sympy.sympify(e).free_symbols for e in powers.values())) <= set(sympy.symbols("n i j"))
    with pytest.raises(LatexMathError):
        S.half_angle_powers(S.parse(r"\sin^{i}\frac{w}{3}"))  # not a half angle
    with pytest.raises(LatexMathError):
        S.parse("XXX")
    assert S.bound("2n-1-j", n=3, j=1) == 4


def test_printed_symmetry_objects_come_from_the_transcriptions():
    from paper_repro.printed import symmetry as S
    from paper_repro.printed.latex_math import LatexMathError as TexError
    from paper_repro.printed.lines import substituted, verbatim

    assert S.printed_half() == {"R": (2, 1, 0), "G": (0, 2, 1), "B": (1, 0, 2)}
    assert len(S.six_properties()) == S.six_count() == 6
    rel = verbatim("sec1_3-B-geq-relation")
    with substituted({"sec1_3-B-geq-relation": rel.replace("\\left( v,u,w\\right) \\right\\}",
                                                           "\\left( w,u,v\\right) \\right\\}")}):
        assert S.printed_half()["B"] == (2, 0, 1)
    with substituted({"sec1_3-G-leq-explicit": "XXX"}):
        with pytest.raises(TexError):
            S.printed_g(2, 1, 0)
    assert S.printed_g(2, 1, 0) == (0, 1, 1, 0, 3, 0)


# ==============================================================================================================
# Section 3 (sec:linear_independence, source lines >= 462): the checks read their lines (issue 37)
# ==============================================================================================================
def test_sec3_reads_products_parametrizations_and_sign_functions_through_latex_math():
    from paper_repro.claims.lines.sec1_3 import (
        LatexMathError,
        _row_value,
        linear_form,
        read_parametrization,
        read_products,
    )
    from paper_repro.printed.derivatives import read_sign_function, sign_of
    from paper_repro.printed.lines import verbatim

    assert linear_form(r"\alpha-x-y") == (1, -1, -1) and linear_form("x-y") == (0, 1, -1)
    with pytest.raises(ValueError):
        linear_form(r"\alpha-1")
    maps, ranges = read_parametrization(verbatim("sec1_3-param-2"))
    alpha, x = sympy.symbols("alpha x")
    assert maps == ((0, 1, 0), (1, -1, -1), (0, 0, 1)) and ranges["y"] == (0, alpha - x)
    (term,) = read_products(_row_value(verbatim("sec1_3-kterm-R-low")))
    n, r, i, j = sympy.symbols("n r i j")
    assert term.sums == [("j", r + 1, n - 1), ("i", j, n)] and term.constant == ("R", 2 * n - i, j, False)
    assert sorted(f.kind for f in term.factors) == ["M", "bar", "bar", "trig", "trig"]
    cos = read_sign_function(verbatim("sec1_3-sign-cos"))
    assert sign_of(cos, i=2, p=2) == 1          # printed +1, the true sign is -1 (erratum lemma-sign-cos-power)
    assert sign_of(cos, i=1, p=2) is None       # no printed branch applies
    assert sign_of(cos, i=1, p=1) is None       # branches 0 (p odd) and +1 (p - i = 0 = 2r, r even) both apply
    with pytest.raises(LatexMathError):
        read_products(_row_value("XXX"))


def test_sec3_blank_lines_fail_their_checks():
    from paper_repro.claims.lines.mutation import blank_test

    recs = blank_test(["sec1_3-kterm-p1-centre", "sec1_3-r-p2-kpos", "sec1_3-param-3", "sec1_3-fig-n4-caption",
                       "sec1_3-interval-typo", "sec1_3-independence-rank", "sec1_3-r0-p3-aform"])
    assert all(r["killed"] for r in recs), [r["check"] for r in recs if not r["killed"]]


@pytest.mark.slow  # every line gets this in make mutate-lines; the fast suite keeps the blank test
@pytest.mark.parametrize("check, line_id, right, wrong", [
    ("sec1_3-r0-p1-aform", "sec1_3-r0-p1-aform", "\\sum_{i=0}^{2n}", "\\sum_{i=0}^{2n-1}"),
    ("sec1_3-r0-p1-cform", "sec1_3-r0-p1-rho-prime", "{c_{2n,0}^{\\alpha}}", "{c_{2n,1}^{\\alpha}}"),
    ("sec1_3-r-p2-k0", "sec1_3-rp2-k0", "S_{r+1,\\frac{1}{2}}^{r+1}", "S_{r+2,\\frac{1}{2}}^{r+1}"),
    ("sec1_3-r-p1-kpos", "sec1_3-rp1-kpos", "1\\leq k", "0\\leq k"),
    ("sec1_3-r-p3-aform", "sec1_3-rp3-reduced", "\\forall x", "\\forall y"),
    ("sec1_3-param-1", "sec1_3-param-1", "& = & y,", "& = & \\alpha-x-y,"),
    ("sec1_3-r0-p1-omitted", "sec1_3-r0-p1-omitted", "at least one", "at most one"),
    ("sec1_3-r0-p2-omitted", "sec1_3-r0-p2-omitted", "=0$", "=1$"),
    ("sec1_3-fig-n4-caption", "sec1_3-fig-n4-caption", "greater than the", "less than the"),
    ("sec1_3-sin-power-leading", "sec1_3-sin-leading", "=j!\\mu^{j}", "=j!\\mu^{j+1}"),
])
def test_sec3_checks_reject_a_changed_line(check, line_id, right, wrong):
    from paper_repro.printed.lines import substituted, verbatim

    text = verbatim(line_id)
    assert right in text and CHECKS[check]().holds_as_printed
    with substituted({line_id: text.replace(right, wrong, 1)}):
        assert not CHECKS[check]().holds_as_printed


def test_sec3_new_errata_fail_as_printed_and_hold_corrected():
    for res in (C.induction_orders(), C.lemma_hypotheses(), C.r0p1_sines(), C.rp1_aform(), C.rp1_asystem()):
        assert res.holds_as_printed is False and res.corrected_holds is True, res.detail
    # the induction range r = 0..n-1 (the hypothesis' own) is accepted
    text = C._transcribed(["sec1_3-induction-orders"])["sec1_3-induction-orders"]
    assert C.induction_orders(text.replace("\\ldots,n$", "\\ldots,n-1$")).holds_as_printed


def test_sec3_printed_objects_are_read_not_retyped():
    from paper_repro.printed import derivatives as D
    from paper_repro.printed import independence as PI
    from paper_repro.printed.lines import substituted, verbatim

    assert D.printed_sign_m(1, 3) == -1 and D.printed_sign_sin(2, 1) == 0
    with substituted({"sec1_3-sign-sin": verbatim("sec1_3-sign-sin").replace("r\\equiv1", "r\\equiv0", 1)}):
        assert D.printed_sign_sin(1, 3) is None  # p - j = 2 = 2r, r = 1: no branch applies any more
    assert PI.hypothesis_n_minus_2(3) == {"R_{6,3,3}", "R_{6,4,2}", "R_{6,3,2}", "G_{6,4,2}", "G_{6,3,2}",
                                          "B_{6,4,2}", "B_{6,3,2}"}
    with substituted({"sec1_3-L-R-row": verbatim("sec1_3-L-R-row").replace("j=0}^{n-1}", "j=1}^{n-1}")}):
        assert "R_{6,6,0}" not in PI.linear_combination_union(3)
    assert C.PARAMS["parametrization_3_y_0"][1] == "y"
    with substituted({"sec1_3-chain-3": verbatim("sec1_3-chain-3").replace("\\partial y^{r}", "\\partial x^{r}")}):
        assert C.PARAMS["parametrization_3_y_0"][1] == "x"
