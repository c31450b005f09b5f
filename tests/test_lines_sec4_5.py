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
def test_relation_rejects_a_narrower_z_range():
    assert ck.relation_matches(3)[0]
    assert not ck.relation_matches(3, zrange=lambda n: (-n, n))[0]  # (n,n,n-1) ~ (n-1,n-1,n) needs z = 2n - 1


def test_power_reduction_rejects_a_wrong_formula():
    assert ck.power_reduction_ok(4, "sin")
    assert not ck.power_reduction_ok(4, "sin", printed=lambda m, w, ep: pl.power_reduction(m, "cos", ep))
    wrong_sign = lambda m, w, ep: pl.power_reduction(m, w, ep) * Fraction(-1)  # noqa: E731
    assert not ck.power_reduction_ok(3, "sin", printed=wrong_sign)


def test_k_sets_reject_a_wrong_bound():
    wrong = dict(ck.read_k_upper())
    wrong["0,0"] = lambda n, i, j: (Fraction(2 * n - i, 2), Fraction(i, 2), Fraction(i - j, 2) + 1, Fraction(j, 2))
    assert ck.k_sets_agree(3)[1]["0,0"] and not ck.k_sets_agree(3, wrong)[1]["0,0"]


@pytest.mark.parametrize("case, line_id, right, wrong", [
    ("0,0", "sec4_5-K00", "\\frac{i}{2}", "\\frac{i+2}{2}"),
    ("1,1", "sec4_5-K11", "K_{1,1}", "K_{1,0}"),
])
def test_k_factors_are_read_from_the_transcription(case, line_id, right, wrong):
    text = {x.id: x.verbatim for x in pl.LINES}[line_id]
    assert right in text and ck.k_case_check(case).holds_as_printed
    assert not ck.k_case_check(case, {line_id: text.replace(right, wrong, 1)}).holds_as_printed
    # the erratum K_{1,0}: the printed third factor fails, the corrected one holds
    k10 = ck.k_case_check("1,0")
    assert k10.holds_as_printed is False and k10.corrected_holds is True


def test_max_bounds_need_s4_to_range():
    assert all(ck.max_values(5).values())
    assert not ck.max_values(5, s4_values=(-1,))["second_max_is_i"]


def test_exp_polynomials_reject_a_false_identity():
    x, y, xm, xp = (1, 0), (0, 1), (1, -1), (1, 1)
    assert not ck.EP.cos(x) * ck.EP.cos(y) == (ck.EP.cos(xm) - ck.EP.cos(xp)) * Fraction(1, 2)
    assert not ck.EP.sin((Fraction(1, 2),)) ** 2 == ck.EP.const(1, Fraction(1, 2))


def test_proposition_and_y_range_errata_are_sharp():
    assert ck.prop_sets_agree(5, 0) == {n: True for n in range(1, 6)}
    assert not ck.prop_sets_agree(5, 1)[1] and all(ck.prop_sets_agree(5, 1)[n] for n in range(2, 6))


def test_b2_count():
    assert len(ck.b2_classes(False)) == 5 and len(ck.b2_classes(True)) == 3


def test_inclusion_rejects_a_too_small_E():
    # with E_{n-1} in place of E_n the frequencies of T_{2n} do not fit: max - min reaches n
    lab_max = max(max(f) - min(f) for lab in ck.united_system(2)
                  for f in ck.half_monomial(ck.exponents(lab)).terms)
    assert ck.inclusion_proof(2) and lab_max == 2


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec4_5-examples-n3-1", "1\\cdot u+1\\cdot v+0\\cdot w", "1\\cdot u+0\\cdot v+0\\cdot w"),
    ("sec4_5-examples-n3-2", "2\\cdot u+0\\cdot v+1\\cdot w", "2\\cdot u+1\\cdot v+1\\cdot w"),
    ("sec4_5-examples-n3-3", "\\nsim", "\\sim"),
])
def test_examples_are_read_from_the_transcription(line_id, right, wrong):
    text = {x.id: x.verbatim for x in pl.LINES}[line_id]
    assert right in text and ck.check_examples_n3().holds_as_printed
    assert not ck.check_examples_n3({line_id: text.replace(right, wrong, 1)}).holds_as_printed


@pytest.mark.parametrize("line_id, right, wrong", [
    ("sec4_5-V1", "\\cos\\left( w\\right) ,\\sin\\left( w\\right)", "\\cos\\left( 2w\\right) ,\\sin\\left( 2w\\right)"),
    ("sec4_5-n2-classes-row2", "_{b=0}^{1}", "_{b=0}^{2}"),
    ("sec4_5-V2-row3", "\\cos\\left( u+2v\\right) ,\\sin\\left( u+2v\\right)",
     "\\cos\\left( 2u+2v\\right) ,\\sin\\left( 2u+2v\\right)"),
    ("sec4_5-V2-row1", "\\sin\\left( 2w\\right)", "\\sin\\left( w\\right)"),  # cos and sin disagree: unread
])
def test_orders_1_2_read_v1_the_classes_and_v2(line_id, right, wrong):
    text = {x.id: x.verbatim for x in pl.LINES}[line_id]
    assert right in text and ck.check_orders_1_2().holds_as_printed
    assert not ck.check_orders_1_2({line_id: text.replace(right, wrong, 1)}).holds_as_printed


def test_proposition_weights_and_partition_sum_are_read_from_their_transcriptions():
    text = {x.id: x.verbatim for x in pl.LINES}
    prop = ck.check_prop_union()
    assert prop.holds_as_printed is False and prop.corrected_holds is True  # erratum: the union from i = 1
    new = text["sec4_5-prop-new-classes"]
    fixed = {k: text[k].replace("\\cup_{i=1}^{n-1}", "\\cup_{i=0}^{n-1}")
             for k in ("sec4_5-prop-recurrence", "sec4_5-prop-new-classes")}
    assert ck.check_prop_union(fixed).holds_as_printed  # the corrected start, read, holds
    assert not ck.check_prop_union({"sec4_5-prop-new-classes": new.replace("_{b=0}^{n-1}", "_{b=1}^{n-1}")}
                                   ).corrected_holds  # a representative missing



def test_relation_reads_the_z_range_of_both_lines():
    text = {x.id: x.verbatim for x in pl.LINES}
    assert ck.check_relation().holds_as_printed
    short = {k: text[k].replace("\\ldots,2n", "\\ldots,2n-1") for k in ("sec4_5-z-range", "sec4_5-z-range-2")}
    assert not ck.check_relation(short).holds_as_printed  # 2n is needed
    assert not ck.check_relation({"sec4_5-z-range": short["sec4_5-z-range"]}).holds_as_printed  # the lines disagree
