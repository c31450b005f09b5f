"""Question 7.1 for every n: the formula, the machine-checked lemmas of docs/question1_for_all_n.md, and checks that
each of those checks rejects a wrong input."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from flint import fmpq, fmpq_poly

from paper_repro import coefficients
from paper_repro.claims import question1_all_n as claim
from paper_repro.core import normalizing_formula as nf
from paper_repro.core.context import ModpContext, get_context
from paper_repro.core.domain import RationalPoints, rational_alpha
from paper_repro.core.labels import united_system
from paper_repro.core.normalization import (
    evaluate_normalized,
    log_scaled_orbit_coefficients,
    orbit_coefficients,
    orbit_coefficients_collocation,
    orbits,
    scaled_orbit_coefficients,
    solve_reduced,
)
from paper_repro.theory import question1 as q1

ALPHA = rational_alpha(fmpq(1, 3))


@pytest.mark.parametrize("n", range(1, 7))
@pytest.mark.parametrize("t", [fmpq(1, 3), fmpq(5, 7)])
def test_formula_equals_the_collocation_solve(n, t):
    a = rational_alpha(t)
    assert orbit_coefficients(n, a, "exact") == orbit_coefficients_collocation(n, a, "exact")


@pytest.mark.slow
@pytest.mark.parametrize("n", [40, 60])
def test_formula_equals_the_collocation_solve_mod_p(n):
    ctx = ModpContext(p=2_147_483_629)
    formula = orbit_coefficients(n, ALPHA, ctx)
    solved = solve_reduced(n, ALPHA, ctx, verify=2).solution.reshape(-1)
    assert [int(x) for x in formula] == [int(x) for x in solved]


def test_printed_examples_n_1_2_3_come_out():
    """Examples normalizing_coefficients_n_1..3 at tan(alpha/4) = 1/2 (s = 4/5, c = 3/5), as printed (n = 3,
    r_{6,3,3}: (-104c^6 - 276c^4 + 324c^2 + 56)/s^9)."""
    a = rational_alpha(fmpq(1, 2))
    c, s = fmpq(3, 5), fmpq(4, 5)
    co = coefficients(3, a, "exact")
    assert co["r_{6,3,3}"] == (-104 * c**6 - 276 * c**4 + 324 * c**2 + 56) / s**9
    assert co["r_{6,4,2}"] == (24 * c**4 + 162 * c**2 + 24) / s**8
    assert coefficients(2, a, "exact")["r_{4,2,2}"] == (10 + 20 * c**2) / s**4


def test_multiplicity_and_weights():
    assert [nf.multiplicity(3, i, j) for i, j in ((2, 1), (2, 2), (3, 3), (3, 0))] == [1, 2, 3, 1]
    assert nf.t_weight(2, 0, 3) == 1 and nf.t_weight(2, 2, 3) == 0 and nf.t_weight(2, 1, 2) == fmpq(15, 5)


# --- the lemmas hold, and their checks can fail -------------------------------------------------------------------
@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_lemmas_hold(n):
    assert q1.order_table(n, ALPHA)["ok"]
    assert q1.triangular_block(n, ALPHA)["ok"]
    assert q1.triangular_solution(n, ALPHA)["ok"]
    assert q1.hexagon_check(n)["ok"]
    assert q1.weights_nonnegative(n)["ok"]


def test_restriction_identity_holds_and_can_fail(monkeypatch):
    tus = [fmpq(1, 9), fmpq(1, 5)]
    assert q1.restriction_identity(ALPHA, fmpq(1, 7), tus)["ok"]
    orig = RationalPoints.half_angle_values

    def swapped(self):
        su, cu, sv, cv, sw, cw = orig(self)
        return [su, cw, sv, cv, sw, cu]  # cos(u/2) and cos(w/2) exchanged

    monkeypatch.setattr(RationalPoints, "half_angle_values", swapped)
    assert not q1.restriction_identity(ALPHA, fmpq(1, 7), tus)["ok"]


def test_order_table_rejects_a_wrong_prediction(monkeypatch):
    orig = q1.predicted_profile
    monkeypatch.setattr(q1, "predicted_profile", lambda lab: orig(lab) | {"order": orig(lab)["order"] + 1})
    assert not q1.order_table(2, ALPHA)["ok"]


def test_order_table_rejects_a_wrong_range(monkeypatch):
    orig = q1.predicted_profile
    monkeypatch.setattr(q1, "predicted_profile", lambda lab: orig(lab) | {"hi": orig(lab)["lo"]})
    assert not q1.order_table(3, ALPHA)["ok"]


def test_triangular_block_rejects_a_wrong_orbit_order(monkeypatch):
    real = orbits(3)
    swapped = list(real)
    swapped[1], swapped[2] = (real[1][0], real[2][1]), (real[2][0], real[1][1])  # members of two orbits exchanged
    monkeypatch.setattr(q1, "orbits", lambda n: tuple(swapped) if n == 3 else orbits(n))
    q1._RESTRICTIONS.clear()
    assert not q1.triangular_block(3, ALPHA)["ok"]


def test_triangular_solution_rejects_a_wrong_formula(monkeypatch):
    def wrong(n, c, s2, ctx, max_level=None):
        vals = nf.scaled_table(n, c, s2, ctx, max_level)
        vals[-1] = vals[-1] + 1
        return vals

    monkeypatch.setattr(q1, "scaled_table", wrong)
    assert not q1.triangular_solution(3, ALPHA)["ok"]


def test_hexagon_check_rejects_functions_of_a_higher_order():
    assert not q1.hexagon_check(2, labels=united_system(3))["ok"]
    assert len(q1.hexagon(4)) == 3 * 16 + 12 + 1


def test_weights_check_rejects_a_negative_weight(monkeypatch):
    monkeypatch.setattr(q1, "t_weight", lambda n, f, m: fmpq(-1))
    assert not q1.weights_nonnegative(3)["ok"]


def test_claim_parts_hold_and_can_fail(monkeypatch):
    assert claim.agrees_with_closed_forms(4) == {"proved_closed_forms": True, "mismatches": []}
    orig = claim.closed_forms_cached

    def perturbed(n):
        forms = orig(n)
        lab = next(iter(forms))
        forms[lab].numerator = forms[lab].numerator + fmpq_poly([0, 1])
        return forms

    monkeypatch.setattr(claim, "closed_forms_cached", perturbed)
    assert claim.agrees_with_closed_forms(4)["mismatches"]


def test_sampled_partition_of_unity_can_fail(monkeypatch):
    good = claim.sampled(3, fmpq(1, 3), 2, seed=1)
    assert good["partition_of_unity_exact"] and good["positive"] and good["collocation_mod_p_agrees"]
    orig = claim.scaled_coefficient_vector

    def wrong(n, alpha, arith="float", dps=None):
        vec = orig(n, alpha, arith)
        vec[0] = vec[0] * 2
        return vec

    monkeypatch.setattr(claim, "scaled_coefficient_vector", wrong)
    assert not claim.sampled(3, fmpq(1, 3), 2, seed=1)["partition_of_unity_exact"]


# --- the library: every arithmetic, every alpha, large n -----------------------------------------------------------
@pytest.mark.parametrize("n", [1, 4, 12, 30])
@pytest.mark.parametrize("alpha", [1e-6, 0.3, 1.5, 3.0, math.pi - 1e-6])
def test_float_coefficients_match_mp(n, alpha):
    """Sums of non-negative terms: the float64 values keep their relative accuracy (measured bound 2e-14 here)."""
    f = np.array(scaled_orbit_coefficients(n, alpha))
    with mpmath.workdps(40):
        m = np.array([float(x) for x in scaled_orbit_coefficients(n, mpmath.mpf(alpha), "mp", dps=40)])
    assert np.max(np.abs(f / m - 1)) < 2e-14


def test_ball_encloses_exact_and_logs_agree():
    a = rational_alpha(fmpq(2, 7))
    exact = scaled_orbit_coefficients(5, a, "exact")
    ctx = get_context("ball", dps=30)
    ball = scaled_orbit_coefficients(5, a, ctx)
    with ctx.scope():  # the exact values converted at the ball's precision
        assert all(b.contains(ctx.from_rational(e)) for b, e in zip(ball, exact))
        assert max(float(b.rad()) for b in ball) < 1e-28
    logs = log_scaled_orbit_coefficients(5, float(a))
    assert np.allclose(np.exp(logs), [float(x) for x in exact], rtol=1e-13, atol=0)


def test_scaled_values_stay_finite_for_tiny_alpha_and_raw_values_refuse_to_overflow():
    vals = scaled_orbit_coefficients(6, 1e-300)
    assert all(math.isfinite(x) and x > 0 for x in vals[:-1])
    assert vals[-1] == 0.0  # the centre: s^{3n} r_{2n,n,n} ~ const * s^2 (limit factor 0), here about 1e-600
    with pytest.raises(ValueError, match="exceeds float64"):
        coefficients(6, 1e-30)
    pts = [[2e-301, 3e-301, 5e-301], [1e-300, 0.0, 0.0]]
    v = evaluate_normalized(6, 1e-300, pts)
    assert np.all(np.isfinite(v)) and np.allclose(v.sum(axis=1), 1.0, atol=1e-14)


def test_large_n_in_logarithms():
    logs = log_scaled_orbit_coefficients(250, 1.0)
    assert len(logs) == 251 * 252 // 2 and all(math.isfinite(x) for x in logs)
    with pytest.raises(ValueError, match="exceeds float64"):
        scaled_orbit_coefficients(250, 1e-3)


@pytest.mark.parametrize("arith", ["exact", "float", "modp"])
def test_scaled_table_min_level_is_the_tail_of_the_table(arith):
    ctx = get_context(arith)
    c, s2 = ctx.from_rational(fmpq(3, 5)), ctx.from_rational(fmpq(16, 25))
    for n in (1, 4, 7):
        full = nf.scaled_table(n, c, s2, ctx)
        for lo in range(n + 1):
            tail = full[sum(n + 1 - j for j in range(lo)):]
            assert [str(x) for x in nf.scaled_table(n, c, s2, ctx, min_level=lo)] == [str(x) for x in tail]
        assert [str(x) for x in nf.scaled_table(n, c, s2, ctx, max_level=2, min_level=1)] == [
            str(x) for x in full[n + 1:sum(n + 1 - j for j in range(3))]]
    with pytest.raises(ValueError, match="min_level"):
        nf.scaled_table(2, c, s2, ctx, min_level=-1)


@pytest.mark.parametrize("n", [1, 2, 4, 6])
def test_centre_end_values_from_the_formula_equal_those_of_the_closed_forms(n):
    """The centre alone (scaled_table with min_level = n) against the recovered closed form of the centre."""
    from paper_repro.theory.general_formulas import centre_end_values, centre_end_values_from_formula

    assert centre_end_values_from_formula(n) == centre_end_values(n)
