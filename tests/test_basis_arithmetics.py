"""The three arithmetics (float64, mpmath, exact rationals) and the modular image agree."""

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.core.basis import evaluate
from paper_repro.core.context import ModpContext
from paper_repro.core.domain import RationalPoints, rational_alpha, sample_points
from paper_repro.core.labels import delta

from .strategies import alphas, float_points, orders, rational_alphas, rational_points


@given(st.data(), orders, rational_alphas())
def test_exact_mp_float_agree(data, n, alpha):
    pts = data.draw(rational_points(alpha))
    exact = evaluate(n, alpha, pts, "exact")
    mp = evaluate(n, alpha, pts, "mp", dps=60)
    fl = evaluate(n, alpha, pts, "float")
    assert exact.shape == mp.shape == fl.shape == (len(pts), delta(n))
    with mpmath.workdps(60):
        err_mp = max(abs(mpmath.mpf(int(e.p)) / int(e.q) - m) for e, m in zip(exact.ravel(), mp.ravel()))
    # 60 digits, values in [0, 1]: only rounding of at most ~10 products remains.
    assert err_mp < mpmath.mpf(10) ** -55
    ex_float = np.array([float(e) for e in exact.ravel()]).reshape(exact.shape)
    # float64: products of at most 3n <= 18 factors of relative error ~1e-16 each.
    assert np.max(np.abs(ex_float - fl)) < 1e-13


@given(st.data(), orders, rational_alphas())
def test_modp_is_image_of_exact(data, n, alpha):
    pts = data.draw(rational_points(alpha, max_size=3))
    ar = ModpContext()
    exact = evaluate(n, alpha, pts, "exact")
    modp = evaluate(n, alpha, pts, ar)
    assert [ar.from_rational(x) for x in exact.ravel()] == [int(x) for x in modp.ravel()]


@given(orders, alphas, st.data())
def test_values_nonnegative_and_bounded(n, alpha, data):
    pts = data.draw(float_points(alpha))
    vals = evaluate(n, alpha, pts)
    assert np.all(vals >= 0) and np.all(vals <= 1 + 1e-15)


def test_vectorised_many_points():
    pts = sample_points(1.0, 5000, seed=1)
    assert evaluate(3, 1.0, pts).shape == (5000, 37)


@given(st.one_of(st.floats(max_value=0.0), st.floats(min_value=np.pi), st.just(float("nan"))))
def test_alpha_out_of_range_raises(alpha):
    with pytest.raises(ValueError, match="alpha"):
        evaluate(2, alpha, [[0.1, 0.1, 0.1]])


@given(alphas, st.floats(min_value=1e-6, max_value=1.0))
def test_points_off_domain_raise(alpha, off):
    with pytest.raises(ValueError, match="points"):
        evaluate(2, alpha, [[alpha / 3, alpha / 3, alpha / 3 + off * alpha]])
    with pytest.raises(ValueError, match="points"):
        evaluate(2, alpha, [[-off * alpha, alpha / 2, alpha / 2 + off * alpha]])


def test_points_within_tolerance_accepted():
    a = 1.0
    evaluate(2, a, [[a / 3, a / 3, a / 3 + 1e-14]])


def test_bad_shapes_and_rational_inputs():
    with pytest.raises(ValueError, match="points"):
        evaluate(1, 1.0, [[0.5, 0.5]])
    with pytest.raises(TypeError, match="RationalPoints"):
        evaluate(1, 1.0, [[0.5, 0.25, 0.25]], "exact")
    alpha = rational_alpha((1, 3))
    with pytest.raises(ValueError, match="outside"):
        RationalPoints(alpha, ((9, 10),), ((9, 10),))
    with pytest.raises(ValueError, match="alpha"):
        rational_alpha((0, 1))
    with pytest.raises(ValueError, match="arith"):
        evaluate(1, 1.0, [[0.5, 0.25, 0.25]], "quad")


@pytest.mark.parametrize("n", [1, 3, 5])
def test_exact_values_are_the_products_of_the_half_angle_powers(n):
    """The exact and modular evaluators (the sin^a cos^b of each half angle tabulated once) against the plain
    product of the six half-angle powers, function by function."""
    from flint import fmpq

    from paper_repro.core.labels import exponents, united_system

    alpha = rational_alpha(fmpq(2, 5))
    pts = RationalPoints(alpha, (fmpq(1, 7), fmpq(1, 11), fmpq(3, 40)), (fmpq(1, 9), fmpq(2, 13), fmpq(1, 30)))
    trig = pts.half_angle_values()
    exact = evaluate(n, alpha, pts, "exact")
    modp = evaluate(n, alpha, pts, ModpContext())
    for f, lab in enumerate(united_system(n)):
        e = exponents(lab)
        for p in range(len(pts)):
            want = fmpq(1)
            for slot in range(6):
                want *= trig[slot][p] ** e[slot]
            assert exact[p, f] == want
            assert int(modp[p, f]) == ModpContext().from_rational(want)
