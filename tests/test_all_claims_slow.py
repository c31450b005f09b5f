"""Heavy check for `make test-all`: every registered claim passes with its default parameters."""

import pytest

from paper_repro.registry import CLAIMS, load_all, run_claim

load_all()


@pytest.mark.slow
@pytest.mark.parametrize("cid", list(CLAIMS))
def test_claim_passes(cid):
    result, _, _ = run_claim(CLAIMS[cid])
    assert result.status == "pass", result.measured
