"""`make report`: the claim summary shows statements, kinds, ranges and measured values, linked to the paper."""

from types import SimpleNamespace

from paper_repro.app.test_report import properties_of, summary_html


def _report(props, passed=True):
    return SimpleNamespace(user_properties=list(props.items()), passed=passed)


def test_claim_properties_become_a_row_with_links():
    rec = properties_of(_report({"claim": "dimension", "paper_labels": "united_system, dimension",
                                 "statement": "T_{2n} has delta_n = 3n(n+1)+1 functions", "kind": "proof",
                                 "parameters": '{"n_max": 7}', "measured": '{"n_checked": 7, "mismatches": []}'}))
    assert rec["status"] == "pass" and rec["measured"]["n_checked"] == 7 and rec["paper_ref"] == ["united_system",
                                                                                                  "dimension"]
    page = summary_html({"dimension": rec})
    assert "../figures/index.html#claim-dimension" in page and "../paper/index.html#united_system" in page
    assert "n_checked" in page and "&quot;n_max&quot;: 7" in page and "this run" in page and "<math" in page


def test_failed_claim_is_marked_and_other_tests_are_ignored():
    assert properties_of(_report({"other": "x"})) is None
    rec = properties_of(_report({"claim": "dimension", "measured": "not json"}, passed=False))
    assert rec["status"] == "fail" and rec["measured"] == "not json"
