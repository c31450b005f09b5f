"""Heavy check for `make test-all` and `make report`: every registered claim passes with its default parameters.

`make test-all`: the claim cache is bypassed (``PAPER_REPRO_NO_CACHE``): the test re-checks, it never reads old
results.  `make report` (``PAPER_REPRO_REPORT_REUSE=1``): a result cached under the same id, parameters and code
fingerprint (what `make reproduce` left) is reused, and the report says so; the others are re-run.
"""

import json

import pytest

from paper_repro.app.test_report import reuse_certified_results
from paper_repro.util.cache import code_fingerprint
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
    reuse = reuse_certified_results()
    if not reuse:
        monkeypatch.setenv("PAPER_REPRO_NO_CACHE", "1")
    result, _, _ = run_claim(CLAIMS[cid])
    if result.cached:
        record_property("reused", "1")
        record_property("code", code_fingerprint())
    record_property("kind", result.kind)
    record_property("statement", result.statement)
    record_property("parameters", json.dumps(result.parameters, sort_keys=True, default=str))
    record_property("measured", json.dumps(result.measured, sort_keys=True, default=str))
    assert result.status == "pass", result.measured
    assert reuse or not result.cached
