"""Lines of Section sec:partition_of_unity (source lines 1907-2167), checked in :mod:`paper_repro.claims.lines.sec5`:
the comparisons read their transcriptions and reject wrong ones."""

from __future__ import annotations

import pytest

from paper_repro.claims.lines import sec5 as ck
from paper_repro.printed.lines import sec4_5 as pl


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
