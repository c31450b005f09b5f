"""Order elevation and the derivative matrix C in closed form for every n (issue 30): the rules, the library route,
the claims' checks, and that each check rejects a deliberately wrong variant."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from flint import fmpq

from paper_repro.core import half_angle_rules as hr
from paper_repro.core.context import FloatContext, get_context
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.elevation import elevate, elevation_matrix, elevation_matrix_exact
from paper_repro.core.half_angle_matrices import (
    derivative_form,
    derivative_matrix,
    derivative_nets,
    elevation_form,
    elevation_matrix_ctx,
    float_half_angle,
    scaled_coefficients,
)
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.theory import derivative_matrix as dt
from paper_repro.theory import half_angle_checks as hc
from paper_repro.util.limits import MAX_N_ELEVATION

TS = [fmpq(1, 1000), fmpq(1, 7), fmpq(1, 2), fmpq(5, 7), fmpq(99, 100)]
ALPHA = rational_alpha(fmpq(1, 3))


# --- the identities and the rules, against an independent evaluation ------------------------------------------------

def test_identities_I_II_hold_and_a_wrong_one_fails():
    assert hc.identities_hold()
    p = hc.half_angle_point(*hc.POINTS[0])
    k, s2, S, C = p["kappa"], p["sigma"], p["S"], p["C"]
    assert C[0] * C[1] != s2 * S[0] * S[1] + k * C[2] - s2 * S[2]  # (II) with the last sign flipped


@pytest.mark.parametrize("n", range(1, 5))
def test_every_cotangent_rule_holds_exactly(n):
    assert hc.rules_hold(n)["ok"]


def test_rules_check_fails_on_a_wrong_rule(monkeypatch):
    """Rule (A) with kappa^{m-j} on M_X(m+1; Z, m) replaced by kappa^{m-j+1}: the check reports it."""
    right = hr._rule_a_pattern.__wrapped__

    def wrong(m, j):
        a, b, part, mm, ll = (x.copy() for x in right(m, j))
        a[-1] += 1
        return a, b, part, mm, ll

    monkeypatch.setattr(hr, "_rule_a_pattern", wrong)
    hr.cotangent.cache_clear()
    try:
        assert not hc.rules_hold(2)["ok"]
    finally:
        hr.cotangent.cache_clear()


def test_level_n_members_give_the_same_column_with_either_part():
    """At level n, m_f = sigma m'_{Pf} + L_x L_x m'_{Pf} for either part x (X or Z): the same column (uniqueness,
    Theorem A), a check of rule (A_N) against rule (A)."""
    for n in (1, 2, 3):
        big = n + 1
        parts = hr.member_parts(n)
        e = hr.exponent_matrix(n)
        index = {tuple(int(v) for v in row): k for k, row in enumerate(hr.exponent_matrix(big))}
        form = elevation_form(n)
        for f in range(delta(n)):
            x, m, y, j = (int(v) for v in parts[f])
            if m != n or j == n:
                continue
            other = 3 - x - y
            lifted = [int(v) for v in e[f]]
            lifted[2 * other] += 2
            g = index[tuple(lifted)]
            terms = [(g, f, 0, 1, 1)]
            for a1, b1, c1, t1 in hr.cotangent(big, other, g):
                terms += [(int(t2), f, int(a1 + a2), int(b1 + b2), int(c1 * c2))
                          for a2, b2, c2, t2 in hr.cotangent(big, other, int(t1))]
            arr = np.array(terms, dtype=np.int64)
            mine = hc.kappa_polynomials(hr.merge(tuple(arr[:, k] for k in range(5))))
            sel = form[1] == f
            theirs = hc.kappa_polynomials(tuple(np.asarray(x)[sel] for x in form))
            assert mine == theirs, (n, f)


# --- C --------------------------------------------------------------------------------------------------------------

def test_C_equals_the_recovered_tables_for_n_up_to_10_and_a_wrong_C_fails():
    for n in range(1, dt.TABLE_MAX_N + 1):
        assert hc.tables_equal(n, derivative_form(n)), n
    assert not hc.tables_equal(3, hc.perturbed(derivative_form(3), 5))


def test_C_has_degree_at_most_n_plus_1_in_kappa_reached():
    """Theorem 1's degree bound (a + 2b <= n + 1 for every term kappa^a sigma^b), reached for n <= 15."""
    for n in range(1, 16):
        _, _, a, b, _ = derivative_form(n)
        assert int((a + 2 * b).max()) == n + 1


def test_C_has_at_most_four_rule_terms_per_column():
    for n in (1, 4, 7):
        e = hr.exponent_matrix(n)
        for f in range(delta(n)):
            blocks = sum(bool(e[f, 2 * v]) + bool(e[f, 2 * v + 1]) for v in (0, 2))
            assert blocks <= 4


@pytest.mark.parametrize("n", [1, 3, 6, 10])
def test_derivative_matrix_agrees_with_the_table_route(n):
    a = 1.0
    kappa = math.cos(a / 2)
    rows, cols, _ = dt.table(n)
    ref = np.zeros((delta(n), delta(n)))
    ref[rows, cols] = dt.entries(n, kappa)
    c = derivative_matrix(n, a)
    assert np.abs(c - ref).max() <= 1e-13 * max(1.0, np.abs(ref).max())
    net = np.random.default_rng(n).normal(size=(delta(n), 3))
    qu, qv = derivative_nets(n, a, net)
    ru, rv = dt.table_derivative_nets(n, kappa, net)
    assert np.abs(qu - ru).max() < 1e-11 and np.abs(qv - rv).max() < 1e-11


def test_derivative_matrix_exact_equals_the_table_polynomials():
    for n in (1, 2, 5):
        c = derivative_matrix(n, ALPHA, "exact")
        rows, cols, coefs = dt.table(n)
        k = ALPHA.cos_half
        ref = get_context("exact").zeros((delta(n), delta(n)))
        for r, cc, co in zip(rows, cols, coefs):
            ref[r, cc] = sum((int(v) * k**d for d, v in enumerate(co)), fmpq(0))
        assert c.tolist() == ref.tolist()


def test_derivative_nets_give_the_derivative_of_the_patch():
    n, a = 3, 1.1
    net = np.random.default_rng(3).normal(size=(delta(n), 2))
    from paper_repro.core.basis import evaluate
    pts = sample_points(a, 5, seed=1)
    h = 1e-6
    qu, _ = derivative_nets(n, a, net)
    fd = (evaluate(n, a, pts + [[h, 0, -h]], scaled=True) - evaluate(n, a, pts - [[h, 0, -h]], scaled=True)) / (2 * h)
    s = math.sin(a / 2)
    assert np.abs(2 * s * fd @ net - evaluate(n, a, pts, scaled=True) @ qu).max() < 1e-7


# --- M and E --------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["M", "C"])
@pytest.mark.parametrize("n", [1, 2, 3])
def test_identity_exact_over_Q(kind, n):
    form = (elevation_form if kind == "M" else derivative_form)(n)
    for t in (TS[0], TS[-1]):
        assert hc.identity_check(kind, n, rational_alpha(t), form)["ok"]


@pytest.mark.parametrize("kind", ["M", "C"])
def test_identity_mod_p_to_n_6_and_a_wrong_form_fails(kind):
    get = elevation_form if kind == "M" else derivative_form
    for n in range(4, 7):
        assert hc.identity_check(kind, n, ALPHA, get(n), arith="modp")["ok"]
    for arith in ("modp", "exact"):
        assert not hc.identity_check(kind, 2, ALPHA, hc.perturbed(get(2), 3), arith=arith)["ok"]


def test_E_equals_the_literal_exact_collocation_and_a_wrong_form_fails():
    for n in (1, 2):
        for t in TS:
            assert hc.collocation_equal(n, rational_alpha(t), elevation_form(n))
    assert not hc.collocation_equal(2, ALPHA, hc.perturbed(elevation_form(2), 10))


def test_bivariate_form_is_positive_to_n_15_and_a_negative_coefficient_is_caught():
    for n in range(1, 16):
        assert hc.nonnegative(elevation_form(n))["ok"], n
    assert not hc.nonnegative(hc.perturbed(elevation_form(3), 4, by=-5))["ok"]


def test_rows_have_at_most_9n_minus_2_nonzeros():
    for n in range(1, 9):
        rows = elevation_form(n)[0]
        cols = elevation_form(n)[1]
        per_row = np.bincount(rows[np.r_[True, (rows[1:] != rows[:-1]) | (cols[1:] != cols[:-1])]])
        assert per_row.max() == 9 * n - 2


def test_exact_row_sums_and_a_wrong_form_fails():
    for n in range(1, 6):
        for t in TS:
            assert hc.row_sums_exact(n, rational_alpha(t), elevation_form(n))
    assert not hc.row_sums_exact(2, ALPHA, hc.perturbed(elevation_form(2), 0))


def test_every_check_of_the_claims_passes_and_the_claims_are_registered():
    from paper_repro.util.registry import CLAIMS, load_all

    load_all()
    for cid in ("elevation_all_n", "derivative_all_n"):
        assert CLAIMS[cid].kind == "proof"
    out = CLAIMS["derivative_all_n"].func(ts=["1/2"], n_tables=4, n_recovered=[], n_exact=2, n_modp=3)
    assert out.passed


def test_float_E_is_the_fixed_order_sum_in_python_floats():
    """The float E equals, bit for bit, the same sums done one by one in Python floats (so numpy's kernels, BLAS and
    the CPU do not enter)."""
    n, a = 3, 1.3
    kappa, sigma = float_half_angle(a)
    rows, cols, ea, eb, coef = elevation_form(n)
    m: dict = {}
    for r, c, x, y, k in zip(rows.tolist(), cols.tolist(), ea.tolist(), eb.tolist(), coef.tolist()):
        kp = 1.0
        for _ in range(x):
            kp *= kappa
        sp = 1.0
        for _ in range(y):
            sp *= sigma
        term = float(k) * kp * sp
        m[(r, c)] = m[(r, c)] + term if (r, c) in m else 0.0 + term
    x = scaled_coefficients(n, kappa, sigma, FloatContext())
    x1 = scaled_coefficients(n + 1, kappa, sigma, FloatContext())
    ref = np.zeros((delta(n + 1), delta(n)))
    for (r, c), v in m.items():
        ref[r, c] = x[c] * v / x1[r]
    assert elevation_matrix(n, a).tobytes() == ref.tobytes()


def test_kappa_and_sigma_are_correctly_rounded():
    for a in (1e-7, 0.3, 1.0, 2.5, math.pi - 1e-9):
        k, s2 = float_half_angle(a)
        with mpmath.workdps(60):
            half = mpmath.mpf(a) / 2
            assert k == float(mpmath.cos(half)) and s2 == float(mpmath.sin(half) ** 2)


@pytest.mark.parametrize("n", [1, 4, 8])
def test_float_E_matches_the_exact_E_at_a_rational_alpha(n):
    for t in (TS[0], fmpq(1, 3), TS[-1]):
        a = rational_alpha(t)
        ex = np.array([[float(v) for v in row] for row in elevation_matrix_ctx(n, a, "exact").tolist()])
        fl = elevation_matrix(n, float(a))
        assert np.abs(fl - ex).max() <= 1e-14
        assert np.abs(fl.sum(axis=1) - 1).max() <= 1e-15 * (n + 2) and fl.min() >= 0


def test_large_n_elevation_is_convex_and_reproduces_the_patch():
    n, a = 12, 2.0
    e = elevation_matrix(n, a)
    assert e.shape == (delta(n + 1), delta(n)) and e.min() >= 0
    assert np.abs(e.sum(axis=1) - 1).max() < 1e-14
    net = np.random.default_rng(0).normal(size=(delta(n), 3))
    pts = sample_points(a, 20, seed=2)
    up = elevate(net, n, a)
    assert np.abs(evaluate_normalized(n, a, pts) @ net - evaluate_normalized(n + 1, a, pts) @ up).max() < 1e-11


def test_the_order_limit_is_40():
    assert MAX_N_ELEVATION == 40
    with pytest.raises(ValueError, match="n must"):
        elevation_matrix(41, 1.0)


def test_elevation_matrix_tiny_alpha_is_finite_and_convex():
    for a in (1e-300, 1e-120, 1e-80):
        e = elevation_matrix(3, a)
        assert np.isfinite(e).all() and e.min() >= 0 and np.abs(e.sum(axis=1) - 1).max() < 1e-15


def test_mp_and_ball_give_the_same_E():
    mp = elevation_matrix_ctx(2, 0.7, get_context("mp", dps=40))
    fl = elevation_matrix(2, 0.7)
    assert np.abs(mp.astype(float) - fl).max() < 1e-15
    ctx = get_context("ball", dps=40)
    ball = elevation_matrix_ctx(2, ALPHA, ctx)
    ex = elevation_matrix_ctx(2, ALPHA, "exact")
    with ctx.scope():
        pairs = zip(ball.reshape(-1), ex.reshape(-1))
        assert all(b.contains(ctx.from_rational(e)) and b.rad() < 1e-35 for b, e in pairs)


# --- heavier ranges -------------------------------------------------------------------------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("kind", ["M", "C"])
@pytest.mark.parametrize("n", range(1, 9))
def test_identity_exact_over_Q_to_n_8_at_5_alphas(kind, n):
    form = (elevation_form if kind == "M" else derivative_form)(n)
    for t in TS:
        assert hc.identity_check(kind, n, rational_alpha(t), form)["ok"]


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 6))
def test_E_equals_the_literal_exact_collocation_to_n_5(n):
    for t in TS:
        assert hc.collocation_equal(n, rational_alpha(t), elevation_form(n))


@pytest.mark.slow
@pytest.mark.parametrize("n", [11, 12])
def test_C_equals_a_fresh_modular_recovery(n):
    from paper_repro.theory.derivative_matrix import derivative_polynomials

    assert hc.tables_equal(n, derivative_form(n), derivative_polynomials(n))


@pytest.mark.slow
def test_rules_hold_to_n_8():
    for n in range(5, 9):
        assert hc.rules_hold(n)["ok"]


@pytest.mark.slow
def test_elevation_at_n_30_is_convex():
    e = elevation_matrix(30, 1.0)
    assert e.min() >= 0 and np.abs(e.sum(axis=1) - 1).max() < 1e-14
    _ = elevation_matrix_exact  # the literal solve is exercised above
