"""Heavy check for `make test-all`: every registered claim passes with its default parameters.

The claim cache is bypassed (``PAPER_REPRO_NO_CACHE``): the test re-checks, it never reads old results.
"""

import json

import pytest

from paper_repro.util.registry import CLAIMS, load_all, run_claim

load_all()


def _test_id(cid: str) -> str:
    """The claim id with its paper labels, so a reader goes from a failing test to the paper."""
    return f"{cid} [{', '.join(CLAIMS[cid].paper_ref)}]"


@pytest.mark.slow
@pytest.mark.parametrize("cid", list(CLAIMS), ids=_test_id)
def test_claim_passes(cid, monkeypatch, record_property):
    record_property("claim", cid)
    record_property("paper_labels", ", ".join(CLAIMS[cid].paper_ref))
    monkeypatch.setenv("PAPER_REPRO_NO_CACHE", "1")
    result, _, _ = run_claim(CLAIMS[cid])
    record_property("kind", result.kind)
    record_property("statement", result.statement)
    record_property("parameters", json.dumps(result.parameters, sort_keys=True, default=str))
    record_property("measured", json.dumps(result.measured, sort_keys=True, default=str))
    assert result.status == "pass", result.measured
    assert not result.cached
