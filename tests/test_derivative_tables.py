"""The derivative of a patch as a patch of the same order (issue 21): the tables of C and the route through them.

* The shipped tables are what the modular recovery computes (n <= 3 here, every n in the slow test).
* The recovery is repeated independently: other collocation points and shape parameters, another prime, the
  direction v computed directly instead of by the u <-> v exchange.
* The float route through C against the direct route (the monomials' brackets) and against central differences
  of the patch values in mp (independent of the derivative formula of both routes).
* The degree <= n + 1 in cos(alpha/2) (proven for every n: docs/elevation_and_derivative_for_all_n.md, Theorem 1)
  and the observed coefficients <= 2n and 3n + 2 entries per column from n = 2 (not proven) hold on the tables.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from flint import fmpq

from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.fast import FloatKernel, trig_of_rows
from paper_repro.core.labels import delta, exponent_matrix, variable_swap
from paper_repro.surfaces.patch import Patch
from paper_repro.theory import derivative_matrix as dm


def _as_dict(rows, cols, coefs):
    return {(int(i), int(j)): [int(x) for x in c] for i, j, c in zip(rows, cols, coefs)}


@pytest.mark.parametrize("n", [1, 2, 3])
def test_tables_are_the_recovery(n):
    assert _as_dict(*dm.derivative_polynomials(n)) == _as_dict(*dm.table(n))


@pytest.mark.slow
@pytest.mark.parametrize("n", range(4, dm.TABLE_MAX_N + 1))
def test_tables_are_the_recovery_all(n):
    assert _as_dict(*dm.derivative_polynomials(n)) == _as_dict(*dm.table(n))


@pytest.mark.parametrize("n", [1, 2, 3])
def test_recovery_is_independent_of_points_parameters_and_prime(n):
    """C at one rational alpha from other collocation points and another prime (not among the recovery's), against
    the table's polynomials at that alpha's cos(alpha/2) modulo that prime."""
    p = 2**31 - 1 - 10**6
    while not all(p % q for q in range(3, int(p**0.5) + 1, 2)):
        p -= 2
    alpha = rational_alpha(fmpq(2, 7))
    for seed in range(3, 10):  # the first point set that is not singular modulo p
        try:
            c = dm.derivative_matrix_modp(n, alpha, p, seed=seed)
            break
        except ZeroDivisionError:
            continue
    kappa = int(alpha.cos_half.p) * pow(int(alpha.cos_half.q), -1, p) % p
    rows, cols, coefs = dm.table(n)
    want = np.zeros_like(c)
    for i, j, co in zip(rows, cols, coefs.astype(np.int64)):
        want[i, j] = sum(int(x) * pow(kappa, d, p) for d, x in enumerate(co)) % p
    assert np.array_equal(c, want)


@pytest.mark.parametrize("n", [1, 2, 3])
def test_direction_v_is_u_with_u_and_v_exchanged(n):
    direct = _as_dict(*dm.derivative_polynomials(n, direction=(0, 1, -1)))
    pi = variable_swap(n, 0, 1)
    rows, cols, coefs = dm.table(n)
    assert direct == _as_dict(pi[rows], pi[cols], coefs)


def test_found_pattern_on_the_tables():
    for n in range(1, dm.TABLE_MAX_N + 1):
        rows, cols, coefs = dm.table(n)
        assert coefs.shape[1] == n + 2 and np.any(coefs[:, -1] != 0)  # degree n + 1, reached
        assert np.abs(coefs).max() == 2 * n
        per_column = np.bincount(cols, minlength=delta(n))
        assert per_column.max() == (4 if n == 1 else 3 * n + 2)


@pytest.mark.parametrize("n", [1, 3, 6, 10])
@pytest.mark.parametrize("alpha", [1e-3, 1.0, math.pi - 1e-3])
def test_route_through_c_against_the_brackets(n, alpha):
    """2 s D m_f contracted with a net: through C's nets, and through the monomials' brackets
    (:meth:`FloatKernel.contract_derivatives`); both within a few units of rounding of the terms' size."""
    rng = np.random.default_rng(n)
    net = rng.normal(size=(delta(n), 3))
    kern = FloatKernel(exponent_matrix(n))
    pts = sample_points(alpha, 300, seed=n)
    sa = math.sin(alpha / 2)
    s, c = trig_of_rows(np.ascontiguousarray(pts.T), alpha, sa)
    qu, qv = dm.table_derivative_nets(n, math.cos(alpha / 2), net)
    basis = kern.basis_rows(s, c)
    via_c = [qu.T @ basis, qv.T @ basis]
    _, direct = kern.contract_derivatives(s, c, sa * sa, [(1, 0, -1), (0, 1, -1)], kern.split_net(net.T.copy()))
    _, parts = kern.derivatives_rows(s, c, sa * sa, [(1, 0, 0), (0, 1, 0), (0, 0, 1)])
    size = sum(np.abs(net.T) @ np.abs(p) for p in parts)  # sum_f |p_f| (|q_0| + |q_1| + |q_2|): the terms' size
    for a, b in zip(via_c, direct):
        assert np.all(np.abs(a - b) <= 64 * delta(n) * 2.0**-53 * (size + np.abs(qu.T) @ basis + np.abs(qv.T) @ basis))


@pytest.mark.parametrize("n,alpha", [(1, 0.7), (2, 1e-3), (3, 2.9), (4, 1.3)])
def test_patch_derivative_against_central_differences_in_mp(n, alpha):
    """Patch.derivative (float, through C) against central differences of the patch's values in mp: independent
    of the derivative formula (the tables were recovered from it)."""
    p = Patch(n, alpha, np.random.default_rng(7).normal(size=(delta(n), 3)))
    pts = sample_points(alpha, 4, seed=2)
    got = p.derivative(pts, "u")
    with mpmath.workdps(50):
        a = mpmath.mpf(alpha)
        h = mpmath.mpf(10) ** -20
        for k, (u, v, _) in enumerate(pts):
            x = [[mpmath.mpf(u) + h, mpmath.mpf(v), a - mpmath.mpf(u) - mpmath.mpf(v) - h],
                 [mpmath.mpf(u) - h, mpmath.mpf(v), a - mpmath.mpf(u) - mpmath.mpf(v) + h]]
            vals = p(np.array(x, dtype=object), arith="mp", dps=50)
            fd = [(vals[0][i] - vals[1][i]) / (2 * h) for i in range(3)]
            scale = max(1.0, max(abs(float(f)) for f in fd))
            assert max(abs(float(f) - g) for f, g in zip(fd, got[k])) <= 1e-12 * scale


def test_orders_beyond_the_tables_take_the_direct_route():
    n = dm.TABLE_MAX_N + 1
    assert not dm.has_table(n)
    p = Patch(n, 1.0, np.random.default_rng(1).normal(size=(delta(n), 3)))
    pts = sample_points(1.0, 3, seed=1)
    ref = np.array(p.derivative(pts, "v", arith="mp", dps=30), dtype=float)
    assert np.abs(p.derivative(pts, "v") - ref).max() <= 1e-12 * np.abs(ref).max()


@pytest.mark.parametrize("n", [1, 2, 3, 4])
@pytest.mark.parametrize("alpha", [1.0, 0.3])
def test_tables_inside_the_certified_ball_solve(n, alpha):
    """An independent, certified computation at one alpha: C-bar of the normalized functions by a collocation
    solve in ball arithmetic (``tools/derivative_matrix.py``'s solve) against the table's C(cos(alpha/2)) carried
    over to them, ``C-bar[g, f] = C[g, f] c_f / (2 s c_g)`` (c = the scaled coefficients): every entry's balls
    overlap (radii below 2^-100), and every entry not in the table is a ball around 0."""
    from flint import arb, arb_mat

    from paper_repro.core.context import BallContext
    from paper_repro.core.derivatives_basis import basis_derivative
    from paper_repro.core.domain import RationalPoints
    from paper_repro.core.normalization import evaluate_normalized, fixed_points, scaled_coefficient_vector

    ctx = BallContext(prec=256 + 32 * n)
    m = delta(n)
    tu, tv = fixed_points(n, m, 7)
    pts = RationalPoints(None, tu, tv, check=False)
    with ctx.scope():
        a = arb(alpha)
        cbar = arb_mat(evaluate_normalized(n, a, pts, ctx).tolist()).solve(
            arb_mat(basis_derivative(n, a, pts, "u", ctx).tolist()), algorithm="precond")
        coef = scaled_coefficient_vector(n, a, ctx)
        kappa, two_s = (a / 2).cos(), 2 * (a / 2).sin()
        rows, cols, coefs = dm.table(n)
        predicted = {}
        for g, f, co in zip(rows, cols, coefs):
            value = sum(int(x) * kappa ** d for d, x in enumerate(co))
            predicted[int(g), int(f)] = value * coef[f] / (two_s * coef[g])
        tiny = arb(2) ** -100
        for g in range(m):
            for f in range(m):
                x = cbar[g, f]
                want = predicted.get((g, f), arb(0))
                assert x.rad() < tiny and want.rad() < tiny
                assert x.overlaps(want), (g, f, x, want)


def test_directions_are_tangent_in_every_arithmetic():
    """(referee pass) A triple direction is du (1, 0, -1) + dv (0, 1, -1) in every route: a component off the plane
    within the tolerance no longer reaches the mp route (where a net offset by 1e6 turned it into a 1e-7 error),
    and one beyond 1e-12 of the largest component is refused whatever the components' size."""
    n, alpha = 3, 1.0
    net = np.random.default_rng(1).normal(size=(delta(n), 3)) + 1e6
    p = Patch(n, alpha, net)
    pts = sample_points(alpha, 3, seed=4)
    d = (1.0, 0.0, -1.0 + 1e-13)
    with mpmath.workdps(40):  # the points exactly on the plane in mp (w = alpha - u - v)
        q = np.array([[mpmath.mpf(float(x)) for x in row] for row in pts], dtype=object)
        q[:, 2] = mpmath.mpf(alpha) - q[:, 0] - q[:, 1]
        ref = np.array(p.derivative(q, d, arith="mp", dps=40), dtype=float)
    assert np.abs(p.derivative(pts, d) - ref).max() <= 1e-12 * np.abs(ref).max()
    with pytest.raises(ValueError, match="tangent"):
        p.derivative(pts, (1e-13, 0, 1e-13))
    with pytest.raises(ValueError, match="direction"):
        p.derivative(pts, (10**400, 0, -(10**400)))


def test_large_direction_components_do_not_overflow_on_the_way():
    """(referee pass) The direction is brought to unit size by a power of two before the nets are combined:
    (1e306, 0, -1e306) on a net of size 1e-10 gave a false OverflowError through the table route."""
    n, alpha = 3, 1.0
    p = Patch(n, alpha, 1e-10 * np.random.default_rng(1).normal(size=(delta(n), 3)))
    pts = sample_points(alpha, 3, seed=4)
    big = p.derivative(pts, (1e306, 0, -1e306))
    assert np.all(np.isfinite(big))
    assert np.abs(big - 1e306 * p.derivative(pts, "u")).max() <= 1e-15 * np.abs(big).max()


def test_table_arguments_are_checked():
    with pytest.raises(ValueError, match="integer from 1 to"):
        dm.table(2.0)
    with pytest.raises(ValueError, match="delta_n"):
        dm.table_derivative_nets(1, 0.5, np.ones((8, 1)))
    with pytest.raises(ValueError, match="delta_n"):
        dm.table_derivative_nets(1, 0.5, np.ones(7))
    with pytest.raises(ValueError, match="kappa"):
        dm.table_derivative_nets(1, float("nan"), np.ones((7, 1)))


def test_recovery_stops_when_every_parameter_is_singular(monkeypatch):
    def singular(*args, **kwargs):
        raise ZeroDivisionError("singular")

    monkeypatch.setattr(dm, "derivative_matrix_modp", singular)
    with pytest.raises(ArithmeticError, match="singular modulo p at every shape parameter"):
        dm.derivative_polynomials(2)
