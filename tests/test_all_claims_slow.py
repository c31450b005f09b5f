"""Heavy check for `make test-all`: every registered claim passes with its default parameters.

The claim cache is bypassed (``PAPER_REPRO_NO_CACHE``): the test re-checks, it never reads old results.
"""

import pytest

from paper_repro.util.registry import CLAIMS, load_all, run_claim

load_all()


@pytest.mark.slow
@pytest.mark.parametrize("cid", list(CLAIMS))
def test_claim_passes(cid, monkeypatch):
    monkeypatch.setenv("PAPER_REPRO_NO_CACHE", "1")
    result, _, _ = run_claim(CLAIMS[cid])
    assert result.status == "pass", result.measured
    assert not result.cached
