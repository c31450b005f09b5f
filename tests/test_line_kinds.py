"""The kind of every line check says how far it settles its line (issue 31, item 6): ``proof`` for everything the line
states, ``exhaustive`` for the finite range its ``how`` names while the line states every n."""

import pytest

from paper_repro.claims.lines import LINE_KINDS, RANGE_WORDS, load_checks

#: Checks of kind proof whose ``how`` names orders because their lines state exactly those orders (1, 2, 3).
FIXED_ORDER_PROOFS = {"sec7-conversion-convex", "sec7-conversion-degrees", "sec7-limit-degenerate-bernstein"}


@pytest.fixture(scope="module")
def results():
    return {cid: f() for cid, f in load_checks().items()}


def test_a_proof_over_a_range_of_n_is_called_exhaustive(results):
    ranged = {cid for cid, r in results.items() if r.kind == "proof" and RANGE_WORDS.search(r.how)}
    assert ranged == FIXED_ORDER_PROOFS


def test_every_exhaustive_result_names_its_range(results):
    assert all(r.kind in LINE_KINDS for r in results.values())
    ex = [cid for cid, r in results.items() if r.kind == "exhaustive"]
    assert len(ex) > 30 and all(RANGE_WORDS.search(results[c].how) for c in ex)


def test_sampled_rank_is_evidence_not_proof(results):
    assert results["sec6-trig-curves"].kind == "exact-evidence"  # ranks at four rational alpha
