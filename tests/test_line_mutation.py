"""Every line check reads its line: blanked, the line must make its check fail (issue: every check reads the paper).

The fast suite runs the blank test per part of the paper; the mutation test (``make mutate-lines``) runs in the slow
suite with its goal.  A survivor names a check that says the same of ``XXX`` as of the paper's line.
"""

from __future__ import annotations

import pytest

from paper_repro.claims.lines.mutation import BLANK, blank_test, check_ids, mutants, summary, verdict_with
from paper_repro.printed.lines import PARTS, lines_of, substituted, verbatim


def _checks_of(part: str) -> list[str]:
    return [c for c in check_ids() if any(x.id.startswith(part + "-") for x in lines_of(c))]


@pytest.mark.parametrize("part", PARTS)
def test_blank_line_fails_its_check(part):
    survivors = [(r["check"], r["verdict"]) for r in blank_test(_checks_of(part)) if not r["killed"]]
    assert survivors == [], f"{len(survivors)} checks of {part} say the same of a blank line: {survivors}"


def test_substituted_restores_and_refuses_unknown_ids():
    lid = lines_of(check_ids()[0])[0].id
    before = verbatim(lid)
    with substituted({lid: BLANK}):
        assert verbatim(lid) == BLANK
    assert verbatim(lid) == before
    with pytest.raises(KeyError):
        with substituted({"no-such-line": "x"}):
            pass
    assert verbatim(lid) == before


def test_a_check_that_reads_nothing_survives(monkeypatch):
    """The harness itself: a check that ignores its line survives the blank test and every mutant."""
    from paper_repro.claims import lines as cl

    cl.load_checks()

    lid = lines_of(check_ids()[0])[0].id
    cid = lines_of(check_ids()[0])[0].check
    monkeypatch.setitem(cl.CHECKS, cid, lambda: cl.LineResult(True, how="nothing read", kind="proof"))
    assert verdict_with(cid, {lid: BLANK}) == (True, None)
    assert not blank_test([cid])[0]["killed"]


def test_mutants_are_deterministic_and_distinct():
    tex = r"\sum_{j=0}^{n-1}\sum_{i=j}^{2n-1-j}\rho_{2n,2n-i,j}R_{2n,2n-i,j}\left(u,v,w\right)=0,~\forall u\geq 0"
    a, b = mutants(tex, "x"), mutants(tex, "x")
    assert [m.text for m in a] == [m.text for m in b]
    assert len({m.text for m in a}) == len(a) and all(m.text != tex for m in a)
    assert {"bound", "sign", "constant", "swap", "relation", "quantifier"} <= {m.op for m in a}
    assert summary([{"op": "sign", "killed": True, "equivalent": None},
                    {"op": "sign", "killed": False, "equivalent": "same"}])["rate"] == 1.0


@pytest.mark.slow
def test_mutation_goal():
    from paper_repro.claims.lines.mutation import mutation_test

    s = summary(mutation_test())
    assert s["rate"] >= 0.95, s
