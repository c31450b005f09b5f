"""Claim ``every_line`` (the glue of issue 19): judged on a tiny fake part of the paper, so that it is tested
whatever the readers' parts hold."""

import pytest

from paper_repro.claims import every_line
from paper_repro.claims.lines import LineResult
from paper_repro.printed.lines import Line
from paper_repro.util import cache
from paper_repro.util.paper_labels import pdf_name
from paper_repro.util.registry import CLAIMS, load_all, run_claim

load_all()

LINE_KEYS = {"id", "part", "tex", "near", "number", "kind", "verbatim", "says", "status", "check", "how",
             "proof_kind", "holds_as_printed", "corrected_holds", "reason", "erratum"}
COVERAGE_KEYS = {"lines", "checked", "erratum", "excused", "by_kind", "by_part", "by_proof_kind"}
ERR = {"printed": "x = 1", "corrected": "x = 2", "evidence": "exact", "severity": "typo"}


def fake_lines():
    return [
        Line("fake-b", (20, 21), "united_system", "display", r"x = 2", "x is two", "checked", check="ok"),
        Line("fake-a", (10, 10), "dimension", "count", r"\delta_n", "a count", "checked", check="claim:dimension"),
        Line("fake-c", (30, 30), "united_system", "range", r"y\in[0,\alpha-x]", "a range", "erratum", check="bad",
             erratum=dict(ERR)),
        Line("fake-d", (40, 40), "united_system", "prose", "We prove", "prose", "excused", reason="pure prose"),
    ]


def fake_checks(**override):
    checks = {"ok": lambda: LineResult(True, how="exact expansion", kind="proof"),
              "bad": lambda: LineResult(False, True, how="exact count", kind="exact-evidence")}
    checks.update(override)
    return checks


RESULTS = {"dimension": {"status": "pass", "kind": "proof", "errata": []}}


@pytest.fixture
def fake_part(monkeypatch, tmp_path):
    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path)
    state = {"lines": fake_lines(), "checks": fake_checks()}
    monkeypatch.setattr("paper_repro.printed.lines.all_lines", lambda: sorted(state["lines"], key=lambda x: x.tex))
    monkeypatch.setattr("paper_repro.claims.lines.load_checks", lambda: state["checks"])
    monkeypatch.setattr(every_line, "_committed_results", lambda: {})
    return state


def test_fake_part_passes_with_exact_shape(fake_part):
    out = every_line.run(claim_results=RESULTS)
    assert out.passed, out.measured["problems"]
    pl = out.data["paper_lines.json"]
    assert set(pl) == {"coverage", "lines"}
    assert set(pl["coverage"]) == COVERAGE_KEYS
    assert pl["coverage"]["lines"] == 4 and pl["coverage"]["checked"] == 2 and pl["coverage"]["erratum"] == 1
    assert pl["coverage"]["by_part"] == {"fake": {"checked": 2, "erratum": 1, "excused": 1}}
    assert pl["coverage"]["by_kind"]["range"] == {"erratum": 1}
    assert pl["coverage"]["by_proof_kind"] == {"proof": 1, "exhaustive": 1, "exact-evidence": 1}
    assert [r["id"] for r in pl["lines"]] == ["fake-a", "fake-b", "fake-c", "fake-d"]  # sorted by tex
    assert all(set(r) == LINE_KEYS for r in pl["lines"])
    a, b, c, _ = pl["lines"]
    assert a["number"] == pdf_name("dimension") != "dimension"  # the PDF's number of the nearest label
    assert b["number"] == pdf_name("united_system") and b["number"].startswith("Eq. (")
    # a line resolved to a claim of kind proof (settled for the claim's range of n) is exhaustive, not proof
    assert a["holds_as_printed"] is True and a["proof_kind"] == "exhaustive" and "dimension" in a["how"]
    assert b["proof_kind"] == "proof"
    assert c["holds_as_printed"] is False and c["corrected_holds"] is True
    # the erratum of a line with its own check is published, with its source lines
    assert out.errata == [{"id": "fake-c", "paper_ref": "united_system", "item": "a range", "severity": "typo",
                           "printed": "x = 1", "corrected": "x = 2", "evidence": "exact", "source_lines": [30, 30]}]
    assert out.kind == "exact-evidence"  # the weakest kind of its checks


def test_a_line_that_does_not_hold_fails_the_claim(fake_part):
    fake_part["checks"] = fake_checks(ok=lambda: LineResult(False, how="exact expansion"))
    out = every_line.run(claim_results=RESULTS)
    assert not out.passed and any("fake-b: does not hold as printed" in p for p in out.measured["problems"])


def test_an_erratum_whose_printed_form_holds_fails(fake_part):
    fake_part["checks"] = fake_checks(bad=lambda: LineResult(True, True))
    out = every_line.run(claim_results=RESULTS)
    assert not out.passed and any("fake-c: erratum not confirmed" in p for p in out.measured["problems"])


def test_an_erratum_whose_correction_fails_fails(fake_part):
    fake_part["checks"] = fake_checks(bad=lambda: LineResult(False, False))
    assert not every_line.run(claim_results=RESULTS).passed


def test_claim_checks_are_resolved_not_rerun_and_must_exist(fake_part):
    assert not every_line.run(claim_results={}).passed  # claim:dimension has no result
    failing = {"dimension": {"status": "fail", "kind": "proof", "errata": []}}
    assert not every_line.run(claim_results=failing).passed
    # an erratum resolved to a claim must be published by that claim (and is not published twice)
    fake_part["lines"] = [Line("fake-e", (5, 5), "dimension", "count", "n", "n", "erratum", check="claim:dimension",
                               erratum={**ERR, "id": "known-erratum"})]
    assert not every_line.run(claim_results=RESULTS).passed
    ok = {"dimension": {"status": "pass", "kind": "proof", "errata": ["known-erratum"]}}
    out = every_line.run(claim_results=ok)
    assert out.passed and out.errata == []


def test_unregistered_or_crashing_check_fails(fake_part):
    fake_part["checks"] = {"bad": fake_checks()["bad"]}
    out = every_line.run(claim_results=RESULTS)
    assert any("'ok' is not registered" in p for p in out.measured["problems"])

    def boom():
        raise RuntimeError("broken")

    fake_part["checks"] = fake_checks(ok=boom)
    out = every_line.run(claim_results=RESULTS)
    assert not out.passed and any("RuntimeError: broken" in p for p in out.measured["problems"])


def test_each_check_runs_once(fake_part):
    calls = []

    def counted():
        calls.append(1)
        return LineResult(True)

    fake_part["lines"] = fake_lines() + [Line("fake-f", (50, 50), "united_system", "display", "y", "y", "checked",
                                               check="ok")]
    fake_part["checks"] = fake_checks(ok=counted)
    assert every_line.run(claim_results=RESULTS).passed and len(calls) == 1


def test_runner_passes_the_results_of_the_other_claims(fake_part):
    res, out, _ = run_claim(CLAIMS["every_line"], claim_results=RESULTS)
    assert res.status == "pass" and out.data["paper_lines.json"]["coverage"]["lines"] == 4
    res, _, _ = run_claim(CLAIMS["every_line"], claim_results={"dimension": {**RESULTS["dimension"], "status": "fail"}})
    assert res.status == "fail"  # the results are part of the cache key


def test_prepared_checks_give_the_same_lines_and_are_not_rerun(fake_part):
    """The checks run as tasks beside the other claims (Claim.prepare): the claim then only judges, with the same
    records as when it runs them itself; a chunk in which a check crashed is reported, and not cached."""
    inline = every_line.run(claim_results=RESULTS)
    chunks = every_line.check_chunks()
    assert chunks == [("ok", "bad")]  # one task per part (here the one part "fake"), in line order
    prepared = [every_line.run_check_chunk(c) for c in chunks]
    calls = []

    def counted():
        calls.append(1)
        return LineResult(False)

    fake_part["checks"] = fake_checks(ok=counted, bad=counted)
    out = every_line.run(claim_results=RESULTS, prepared=prepared)
    assert calls == [] and out.data == inline.data and out.errata == inline.errata and out.passed
    # a cached chunk is the stored records (same code): the changed checks are not consulted
    assert every_line.run_check_chunk(("ok", "bad")) == prepared[0] and calls == []

    def boom():
        raise RuntimeError("broken")

    fake_part["checks"] = fake_checks(ok=boom)
    crashed = every_line.run_check_chunk(("ok",))
    assert crashed == {"ok": {"error": "RuntimeError: broken"}}
    fake_part["checks"] = fake_checks()
    assert every_line.run_check_chunk(("ok",))["ok"]["holds_as_printed"] is True  # the crash was not stored
    out = every_line.run(claim_results=RESULTS, prepared=[crashed])
    assert not out.passed and any("RuntimeError: broken" in p for p in out.measured["problems"])


def test_the_runner_prepares_every_line_beside_the_other_claims():
    from paper_repro.util.registry import claim

    assert CLAIMS["every_line"].prepare is every_line.prepare_tasks
    with pytest.raises(ValueError, match="prepare is for a claim that uses"):
        claim("x_prepare_without_results", paper_ref=[], statement="s", kind="proof", prepare=list)


def test_line_coverage_block_of_the_readme():
    from paper_repro.app.report import lines_markdown

    cov = {"lines": 4, "checked": 2, "erratum": 1, "excused": 1, "by_kind": {"range": {"erratum": 1}},
           "by_part": {"fake": {"checked": 2, "erratum": 1, "excused": 1}}}
    text = lines_markdown(cov)
    assert "4 lines" in text and "**2 checked**" in text and "| part `fake` | 2 | 1 | 1 | 4 |" in text
    assert "How far" not in text  # an old coverage without kinds
    text = lines_markdown({**cov, "by_proof_kind": {"proof": 1, "exhaustive": 2}})
    assert "**1** proof (the check settles everything the line states), **2** exhaustive (exact and complete for " \
           "the range of n its `how` names, not for every n)." in text


def test_line_kinds_say_how_far_a_proof_goes(fake_part):
    """"proof" only for everything the line states; a claim's proof for a range of n makes its lines exhaustive,
    naming the range (issue 31, item 6)."""
    res = {"dimension": {"status": "pass", "kind": "proof", "errata": [],
                         "statement": "For n = 1..50, the dimension is delta_n."}}
    a = every_line.run(claim_results=res).data["paper_lines.json"]["lines"][0]
    assert a["proof_kind"] == "exhaustive" and "exhaustive for n = 1..50" in a["how"] and "not for every n" in a["how"]
    assert every_line.claim_line_kind("nonnegativity", {"status": "pass", "kind": "proof"})[0] == "proof"
    assert every_line.claim_line_kind("x", {"status": "pass", "kind": "exact-evidence"})[0] == "exact-evidence"
    fake_part["checks"] = fake_checks(ok=lambda: LineResult(True, how="count, n = 1..12", kind="exhaustive"),
                                      bad=lambda: LineResult(False, True, how="exact", kind="proof"))
    out = every_line.run(claim_results=res)
    assert out.passed and out.kind == "proof"  # the claim's kind: "proof" already means "for the stated range"
    with pytest.raises(ValueError, match="names its range"):
        LineResult(True, how="a count", kind="exhaustive")
    with pytest.raises(ValueError, match="kind must be one of"):
        LineResult(True, how="a count", kind="proven")
