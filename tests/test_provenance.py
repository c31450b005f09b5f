"""The gallery's provenance row says only what is true: data/ computed by this code or not, from the code
fingerprint the standard run records (a cold `make reproduce-extended` flipped it to "no" though no code changed)."""

from __future__ import annotations

import json

import pytest

from paper_repro.app import gallery
from paper_repro.util.cache import code_fingerprint
from paper_repro.util.io import set_output_root


@pytest.fixture
def out(tmp_path):
    set_output_root(tmp_path)
    (tmp_path / "data").mkdir()
    yield tmp_path
    set_output_root(None)


def test_recorded_fingerprint_of_this_code_says_yes(out, monkeypatch):
    monkeypatch.setattr(gallery, "REPRODUCED", False)  # an extended run, or none at all in this process
    (out / "data" / "provenance.json").write_text(json.dumps({"code_fingerprint": code_fingerprint()}))
    state = gallery.provenance()["data_matches_code"]
    assert state.startswith("yes: data/ was computed by this code") and code_fingerprint() in state


def test_other_fingerprint_says_no_and_names_both(out):
    (out / "data" / "provenance.json").write_text(json.dumps({"code_fingerprint": "0123456789abcdef"}))
    state = gallery.provenance()["data_matches_code"]
    assert state.startswith("no: data/ was computed by other code") and "0123456789abcdef" in state
    assert code_fingerprint() in state


def test_the_committed_provenance_is_the_fingerprint_format():
    from paper_repro.util.io import ROOT

    path = ROOT / "data" / "provenance.json"
    if not path.exists():
        pytest.skip("data/provenance.json is written by make reproduce")
    rec = json.loads(path.read_text())
    assert len(rec["code_fingerprint"]) == 16 and int(rec["code_fingerprint"], 16) >= 0
