"""The claim registry: unknown parameters are rejected, crashes are reported and never cached."""

import pytest

from paper_repro.util import cache
from paper_repro.util.registry import CLAIMS, Claim, Outcome, cli_overrides, load_all, run_claim

load_all()


def test_unknown_override_rejected_with_accepted_list():
    with pytest.raises(ValueError, match=r"takes no parameter\(s\) \['bogus'\]; it takes \['n_max', 'n_min'\]"):
        run_claim(CLAIMS["dimension"], {"bogus": 1})


def test_crash_is_a_failure_and_not_cached(tmp_path, monkeypatch):
    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path)
    calls = []

    def boom(x):
        calls.append(x)
        if len(calls) == 1:
            raise RuntimeError("transient")
        return Outcome(True, {"x": x})

    c = Claim("boom", ["x"], "s", "proof", boom, {"x": 1})
    res, _, _ = run_claim(c)
    assert res.status == "fail" and "RuntimeError: transient" in res.measured["error"]
    assert not list(tmp_path.rglob("*.json"))  # nothing stored for the crash
    res2, _, _ = run_claim(c)
    assert res2.status == "pass" and len(calls) == 2  # recomputed, then cached
    res3, _, _ = run_claim(c)
    assert res3.status == "pass" and len(calls) == 2 and res3.cached


def test_cli_overrides_only_for_claims_that_take_them():
    assert cli_overrides(CLAIMS["dimension"], 5, None) == {"n_min": 5, "n_max": 5}
    assert cli_overrides(CLAIMS["dimension"], None, "pi/3") is None


def test_every_published_erratum_has_a_severity():
    import json

    from paper_repro.util.io import DATA

    errata = json.loads((DATA / "errata.json").read_text())
    assert errata and all(e.get("severity") in ("typo", "statement", "result") for e in errata), errata
