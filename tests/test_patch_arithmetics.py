"""Patches in every arithmetic (issue: one formula, every arithmetic).

Exact evaluation at rational points equals mp to the last digit of the mp precision; the float fast
path agrees to 1e-13 relative; ball enclosures contain the exact value; derivatives match mp finite
differences; the fast float kernel equals the generic context path.
"""

import math

import mpmath
import numpy as np
from flint import arb, fmpq
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro import Patch, RationalPoints, basis_derivative, evaluate_normalized, rational_alpha
from paper_repro.core.context import get_context
from paper_repro.core.labels import delta

from .strategies import rational_alphas, rational_points


def _mp_of(q):
    return mpmath.mpf(int(q.p)) / int(q.q)


@settings(max_examples=15)
@given(st.data(), st.integers(1, 3), rational_alphas(), st.booleans())
def test_exact_mp_float_ball_patch_agree(data, n, alpha, rational):
    pts = data.draw(rational_points(alpha, max_size=3))
    rng = np.random.default_rng(n)
    net = rng.integers(-9, 10, size=(delta(n), 3))
    weights = rng.integers(1, 5, size=delta(n)) if rational else None
    p = Patch(n, alpha, net, weights)
    ex = p(pts, arith="exact")
    mp_ = p(pts, arith="mp", dps=50)
    fl = p(pts)
    ball = p(pts, arith="ball", dps=40)
    with mpmath.workdps(50):
        scale = max(1, max(abs(_mp_of(x)) for x in ex.ravel()))
        err = max(abs(_mp_of(e) - m) for e, m in zip(ex.ravel(), mp_.ravel()))
        assert err <= scale * mpmath.mpf(10) ** -45  # mp at 50 digits: the last few digits only
    exf = np.array([float(x) for x in ex.ravel()]).reshape(ex.shape)
    assert np.max(np.abs(exf - fl)) <= 1e-13 * max(1.0, np.max(np.abs(exf)))
    with get_context("ball", prec=400).scope():  # the rational converted at 400 bits lies inside the 133-bit ball
        for e, b in zip(ex.ravel(), ball.ravel()):
            assert b.contains(arb(e)) and b.rad() < 1e-15 * max(1.0, abs(float(e)))  # at least float64 precise


def test_fast_float_kernel_equals_generic_path():
    alpha = 1.3
    pts = np.random.default_rng(3).dirichlet(np.ones(3), size=200) * alpha
    for n in (1, 2, 4):
        net = np.random.default_rng(n).normal(size=(delta(n), 2))
        fast = Patch(n, alpha, net)(pts)
        generic = evaluate_normalized(n, alpha, pts).dot(net)
        assert np.max(np.abs(fast - generic)) < 1e-13


@settings(max_examples=10)
@given(st.integers(1, 4), st.floats(0.05, 3.0), st.sampled_from(["u", "v", "w", (1, -2, 1)]))
def test_basis_derivative_matches_mp_finite_differences(n, alpha, direction):
    ctx = get_context("mp", dps=40)
    with ctx.scope():
        a = mpmath.mpf(alpha)
        pt = np.array([[a * mpmath.mpf("0.3"), a * mpmath.mpf("0.45"), a * mpmath.mpf("0.25")]], dtype=object)
        d = {"u": (1, 0, -1), "v": (0, 1, -1), "w": (0, -1, 1)}.get(direction, direction)
        h = mpmath.mpf(10) ** -12
        step = np.array([[h * d[0], h * d[1], h * d[2]]], dtype=object)
        fd = (evaluate_normalized(n, a, pt + step, ctx) - evaluate_normalized(n, a, pt - step, ctx)) / (2 * h)
        exact = basis_derivative(n, a, pt, direction, ctx)
        err = max(abs(x - y) for x, y in zip(fd.ravel(), exact.ravel()))
        scale = max(1, max(abs(x) for x in exact.ravel()))
        assert err < scale * mpmath.mpf(10) ** -18  # central difference error O(h^2) = 1e-24, rounding 1e-28
    flt = basis_derivative(n, alpha, ctx.to_float(pt), direction)
    assert np.max(np.abs(flt - ctx.to_float(exact))) < 1e-10 * float(scale)


def test_derivatives_of_a_partition_of_unity_sum_to_zero_exactly():
    a = rational_alpha(fmpq(1, 3))
    pts = RationalPoints(a, (fmpq(1, 9),), (fmpq(1, 11),))
    for n in (1, 2, 3):
        d = basis_derivative(n, a, pts, (2, -1, -1), "exact")
        assert sum(d[0]) == 0


def test_patch_derivative_and_normals_float():
    from paper_repro.surfaces.models import torus_pieces

    piece = torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])[0]
    p = piece.patch
    pts = np.random.default_rng(0).dirichlet(np.ones(3), size=20) * float(p.alpha)
    h = 1e-6
    fd = (p(pts + [[h, 0, -h]]) - p(pts - [[h, 0, -h]])) / (2 * h)
    assert np.max(np.abs(p.derivative(pts, "u") - fd)) < 1e-6
    nrm = p.normals(pts)
    assert np.allclose(np.linalg.norm(nrm, axis=1), 1.0)
    assert np.max(np.abs(np.einsum("ij,ij->i", nrm, p.derivative(pts, "v")))) < 1e-12


def test_blocks_cover_every_point_and_errors_name_the_global_index():
    import pytest

    from paper_repro.core.fast import BLOCK

    alpha = 0.9
    pts = np.random.default_rng(5).dirichlet(np.ones(3), size=BLOCK + 7) * alpha
    net = np.random.default_rng(6).normal(size=(delta(2), 3))
    fast = Patch(2, alpha, net)(pts)
    assert np.max(np.abs(fast - evaluate_normalized(2, alpha, pts).dot(net))) < 1e-13
    pts[BLOCK + 3] = [alpha, alpha, 0.0]
    with pytest.raises(ValueError, match=f"point {BLOCK + 3} "):
        Patch(2, alpha, net)(pts)


@settings(max_examples=25)
@given(st.integers(1, 6), st.one_of(st.floats(1e-3, math.pi - 1e-3), st.sampled_from([1e-3, math.pi - 1e-3])),
       st.integers(0, 2**16))
def test_float_path_accuracy_sweep(n, alpha, seed):
    # issue: max relative error <= 1e-13 against the mp path for n <= 6, alpha in [1e-3, pi - 1e-3]
    from paper_repro.claims.float_accuracy import errors

    pou, rel = errors(n, alpha, 4, seed, 30)
    assert pou <= 1e-13 and rel <= 1e-13
