"""The foundation claims pass, and fail when a transcription is wrong (negative controls)."""

import pytest

from paper_repro.claims import boundary, dimension, symmetry
from paper_repro.claims import univariate as uni
from paper_repro.util.registry import CLAIMS, load_all, run_claim


@pytest.fixture(scope="module", autouse=True)
def _load():
    load_all()


def test_dimension_claim_small():
    res, _, _ = run_claim(CLAIMS["dimension"], {"n_max": 12})
    assert res.status == "pass" and res.kind == "proof"


def test_dimension_detects_wrong_count(monkeypatch):
    monkeypatch.setattr(dimension, "delta", lambda n: 3 * n * (n + 1))
    out = dimension.run(1, 3)
    assert not out.passed and len(out.measured["mismatches"]) == 3


def test_boundary_one_case():
    import mpmath

    with mpmath.workdps(40):
        res = boundary.check_edge(3, mpmath.pi / 3, "v=0", 6, 40)
    assert res["ok"] and res["surviving"] == 7


def test_boundary_detects_wrong_constant(monkeypatch):
    import mpmath

    real = boundary.c_const
    monkeypatch.setattr(boundary, "c_const", lambda n, i, a, ar: real(n, i, a, ar) * (1 + (i == 1)))
    with mpmath.workdps(40):
        assert not boundary.check_edge(2, mpmath.pi / 3, "w=0", 6, 40)["ok"]


def test_symmetry_structural_all_hold():
    for n in range(1, 6):
        assert symmetry.structural_checks(n) == []


def test_symmetry_detects_wrong_printed_formula():
    """The claim reads the printed G formula from its transcription: cos and sin of u/2 exchanged fail."""
    from paper_repro.printed.lines import substituted, verbatim

    text = verbatim("sec1_3-G-leq-explicit")
    wrong = text.replace("\\cos^{i-j}\\frac{u}", "\\sin^{i-j}\\frac{u}").replace("\\sin^{j}\\frac{u}",
                                                                                  "\\cos^{j}\\frac{u}")
    assert wrong != text
    with substituted({"sec1_3-G-leq-explicit": wrong}):
        assert any("printed G" in f for f in symmetry.structural_checks(2))
    assert symmetry.structural_checks(2) == []


def test_symmetry_detects_wrong_six_property():
    """The caption's properties are parsed: red--green exchanged by (v,u) becomes red--blue, which fails."""
    from paper_repro.printed.lines import substituted, verbatim

    text = verbatim("sec1_3-fig-oriented-graph-caption")
    with substituted({"sec1_3-fig-oriented-graph-caption": text.replace("red--green", "red--blue")}):
        assert any("does not map" in f for f in symmetry.structural_checks(2))
    with substituted({"sec1_3-six-symmetries": verbatim("sec1_3-six-symmetries").replace("six", "five")}):
        assert any("announces 5" in f for f in symmetry.structural_checks(2))


def test_univariate_constants_and_detection(monkeypatch):
    assert all(uni.constants_match(n) for n in range(1, 8))
    real = uni.c_numerator
    monkeypatch.setattr(uni, "c_numerator", lambda n, i: [c + (i == 2) for c in real(n, i)])
    assert not uni.constants_match(3)


def test_univariate_claim_small():
    res, _, _ = run_claim(CLAIMS["univariate"], {"n_exact_max": 5, "ns_numeric": [1, 2], "alphas": ["pi/3"]})
    assert res.status == "pass", res.measured
    assert "n = 1..5" in res.statement  # the range it ran with, filled in
    res, _, _ = run_claim(CLAIMS["univariate_limit_order"], {"bernstein_ns": [1, 2]})
    assert res.status == "pass", res.measured
    orders = res.measured["bernstein_observed_order"]
    assert all(abs(o - 2) < 0.05 for o in orders.values())
