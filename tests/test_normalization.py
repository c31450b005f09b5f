import mpmath
import numpy as np
import pytest
from flint import fmpq, fmpq_poly
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro.claims import normalizing_closed_forms as ncf
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.labels import index_of, united_system
from paper_repro.core.normalization import coefficients, evaluate_normalized, orbits, solve_full_exact
from paper_repro.core.univariate import c_const
from paper_repro.printed import normalization as printed
from paper_repro.theory.closed_forms import ClosedForm, prove, recover, sign_on_unit_interval, sturm_count

from .strategies import alphas, float_points, orders, rational_alphas


def test_api_keys_are_paper_labels():
    co = coefficients(2, 1.0)
    assert list(co) == [lab.coefficient for lab in united_system(2)]
    assert "r_{4,2,2}" in co and "g_{4,3,1}" in co and "b_{4,1,0}" in co


@settings(max_examples=6)
@given(st.integers(1, 3), rational_alphas())
def test_symmetry_conditions_hold_on_the_full_system(n, alpha):
    # eqs. symmetry_condition_1..3 checked on the solution of the full delta_n system, which assumes no
    # symmetry (the reduced solver builds the symmetry in, so its output could not fail this)
    full = dict(zip([lab.coefficient for lab in united_system(n)], solve_full_exact(n, alpha)))
    idx = index_of(n)
    for j in range(n):
        for i in range(j, 2 * n - j):
            r = full[f"r_{{{2 * n},{2 * n - i},{j}}}"]
            g = full[united_system(n)[idx[f"g_{{{2 * n},{2 * n - i},{j}}}"]].coefficient]
            b = full[united_system(n)[idx[f"b_{{{2 * n},{2 * n - i},{j}}}"]].coefficient]
            assert g == r == b
            if j < i < n:
                assert full[united_system(n)[idx[f"r_{{{2 * n},{i},{j}}}"]].coefficient] == r
    assert len(orbits(n)) == (n + 1) * (n + 2) // 2


@given(st.data(), orders, alphas)
def test_partition_of_unity_float(data, n, alpha):
    pts = data.draw(float_points(alpha))
    vals = evaluate_normalized(n, alpha, pts)
    assert np.all(vals >= 0)
    assert np.max(np.abs(vals.sum(axis=1) - 1)) < 1e-12


@given(alphas)
def test_printed_final_forms_at_drawn_alpha(alpha):
    with mpmath.workdps(40):
        a = mpmath.mpf(alpha)
        s, c = mpmath.sin(a / 2), mpmath.cos(a / 2)
        for n in (1, 2, 3):
            co = dict(zip([r.coefficient for r, _ in orbits(n)], __import__(
                "paper_repro.core.normalization", fromlist=["x"]).orbit_coefficients(n, a, "mp", dps=40)))
            for lab, (_, _, _) in printed.FINAL.items():
                if lab.startswith(f"r_{{{2 * n},"):
                    val = printed.final_value(lab, s, c)
                    assert abs(val - co[lab]) <= mpmath.mpf(10) ** -30 * abs(val)
                    inter = printed.INTERMEDIATE[lab][1](s, c, lambda i, n=n: c_const(n, i, a, "mp"))
                    assert abs(inter - co[lab]) <= mpmath.mpf(10) ** -25 * abs(val)


@given(rational_alphas())
def test_exact_matches_full_system(alpha):
    n = 2
    full = solve_full_exact(n, alpha)
    co = coefficients(n, alpha, "exact")
    assert list(co.values()) == full


def test_bad_inputs():
    with pytest.raises(TypeError, match="RationalAngle"):
        coefficients(2, 1.0, "exact")
    with pytest.raises(ValueError, match="alpha"):
        coefficients(2, 3.5)
    with pytest.raises(ValueError, match="n must be"):
        coefficients(0, 1.0)
    with pytest.raises(ValueError, match="arith"):
        coefficients(1, 1.0, "quad")


def test_sturm_counts():
    x = fmpq_poly([0, 1])
    assert sturm_count((x - fmpq(1, 3)) * (x - fmpq(1, 2)) ** 2, fmpq(0), fmpq(1)) == 2
    assert sign_on_unit_interval(x * x + 1) == {"roots_in_open_unit_interval": 0, "sign": 1}
    assert sign_on_unit_interval(x - 1)["roots_in_open_unit_interval"] == 0
    assert sign_on_unit_interval(x - 1)["sign"] == -1
    assert sign_on_unit_interval(x - fmpq(1, 2))["roots_in_open_unit_interval"] == 1


def test_recovered_forms_match_printed_n2():
    forms = recover(2)
    assert forms["r_{4,2,1}"].numerator == fmpq_poly([0, 16, 0, 8]) and forms["r_{4,2,1}"].sin_power == 5
    # printed r_{4,2,2} = (10 + 20c^2)/s^4 = (10 + 20c^2)(1 - c^2)/s^6
    assert forms["r_{4,2,2}"].numerator == fmpq_poly([10, 0, 20]) * fmpq_poly([1, 0, -1])


def test_proof_detects_wrong_form():
    forms = recover(2)
    bad = dict(forms)
    bad["r_{4,3,1}"] = ClosedForm("r_{4,3,1}", 5, forms["r_{4,3,1}"].numerator + 1)
    res = prove(2, bad)
    assert not res["proved"] and res["mismatch"] == "r_{4,3,1}"
    assert prove(2, forms)["proved"]


def test_claim_emits_erratum_for_wrong_transcription(monkeypatch):
    wrong = dict(printed.FINAL)
    wrong["r_{4,3,1}"] = ("normalizing_coefficients_n_2", [4, 0, 9], 5)
    monkeypatch.setattr(ncf, "FINAL", wrong)
    out = ncf.run(ts=["1/2", "1/3", "2/5"], level_n_max=3, proof_n_max=3)
    assert not out.passed
    assert [e["item"] for e in out.errata] == ["r_{4,3,1}"]
    assert "8 c^2 + 4" in out.errata[0]["corrected"]


def test_claim_passes_small():
    out = ncf.run(ts=["1/2", "1/3", "2/5"], level_n_max=4, proof_n_max=3)
    assert out.passed and not out.errata


def test_normalized_values_exact_sum_to_one():
    a = rational_alpha((1, 4))
    from paper_repro.core.domain import sample_rational_points

    pts = sample_rational_points(a, 3, seed=2)
    vals = evaluate_normalized(3, a, pts, "exact")
    assert all(sum(row, fmpq(0)) == 1 for row in vals)


def test_mp_normalized():
    with mpmath.workdps(30):
        raw = sample_points(1.0, 3, seed=1)  # float points; put them exactly on the plane in mp
        pts = np.array([[mpmath.mpf(u), mpmath.mpf(v), 1 - mpmath.mpf(u) - mpmath.mpf(v)] for u, v, _ in raw],
                       dtype=object)
        vals = evaluate_normalized(2, 1.0, pts, "mp", dps=30)
        assert all(abs(sum(r) - 1) < mpmath.mpf(10) ** -25 for r in vals)


def test_symbolic_intermediate_check_can_fail(monkeypatch):
    wrong = dict(printed.INTERMEDIATE)
    ref, expr = wrong["r_{4,3,1}"]
    wrong["r_{4,3,1}"] = (ref, lambda s, c, C: 3 / s * C(2))  # printed: 2 / s * C(2)
    monkeypatch.setattr(ncf, "INTERMEDIATE", wrong)
    out = ncf.run(ts=["1/2", "1/3", "2/5"], level_n_max=2, proof_n_max=2)
    assert not out.passed
    assert out.measured["intermediate_forms_symbolic"]["failed"] == ["r_{4,3,1}"]


def test_ratfunc_identities():
    from paper_repro.theory.ratfunc import RatFunc, half_angle_functions

    s, c = half_angle_functions()
    assert 2 * s * c == 2 * s * c and not (s == c)
    assert (1 - c * c) / s == s and RatFunc.const(1) / (s * s) * s == 1 / s
