"""Every float function within its stated bound or refused (issue 39, item 1): the transformation V_n <-> T-bar_{2n}
(Question 7.2), the product matrices, measured against an independent high-precision reference: mpmath at small n,
the double-double evaluation of ``tools/transformation_accuracy.py`` up to n = 30 (itself checked against mp, and by
the residual of the two independent routes, here).  Expected values come from the reference only."""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest

from paper_repro.core.half_angle_matrices import (
    ALPHA_TINY,
    PRODUCT_FLOAT_FLOOR,
    product_float_bound,
    product_matrix,
)
from paper_repro.core.transformation import (
    t_to_v_float_bound,
    transformation_matrix,
    v_to_t_float_alpha_min,
    v_to_t_float_bound,
)

_PATH = Path(__file__).resolve().parents[1] / "tools" / "transformation_accuracy.py"
_SPEC = importlib.util.spec_from_file_location("transformation_accuracy", _PATH)
ta = sys.modules.setdefault("transformation_accuracy", importlib.util.module_from_spec(_SPEC))
if not hasattr(ta, "DD"):
    _SPEC.loader.exec_module(ta)  # registered first: its dataclass looks its module up


def _bound(n: int, alpha: float, direction: str) -> float:
    return v_to_t_float_bound(n, alpha) if direction == "V_to_T" else t_to_v_float_bound(n)


def _check_transformation(n: int, alpha: float, direction: str, reference) -> float:
    """The public function: refused (ValueError / OverflowError) or within its bound against ``reference``."""
    if direction == "V_to_T" and alpha < v_to_t_float_alpha_min(n):
        with pytest.raises(ValueError, match="loses its digits"):
            transformation_matrix(n, alpha, direction)
        return 0.0
    out = transformation_matrix(n, alpha, direction)
    err = ta.rel_error(out, reference(n, alpha, direction))
    assert err <= _bound(n, alpha, direction), (n, alpha, direction, err, _bound(n, alpha, direction))
    return err / _bound(n, alpha, direction)


# --- the reference ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("direction", ["V_to_T", "T_to_V"])
@pytest.mark.parametrize("alpha", [1e-3, 1.0, math.pi - 1e-12])
def test_double_double_reference_agrees_with_mp(direction, alpha):
    dd = ta.dd_matrix(3, alpha, direction)
    mp = ta.mp_matrix(3, alpha, direction)  # hi + lo pairs of the mp value
    diff = np.abs((dd.real - mp.real) + (dd.imag - mp.imag)).max() / np.abs(mp.real).max()
    assert diff < 1e-24, diff  # 32 digits less the 6 that alpha = 1e-3 costs 'V_to_T'
    assert ta.rel_error(dd.real, mp) > 0 or diff == 0  # the comparison sees the low part


def test_double_double_arithmetic_against_exact_rationals():
    from fractions import Fraction

    from flint import fmpq

    dd = ta.DoubleDoubleContext()
    x, y = dd.from_rational(fmpq(1, 3)), dd.from_rational(fmpq(-2, 7))
    exact = {"add": Fraction(1, 3) - Fraction(2, 7), "sub": Fraction(1, 3) + Fraction(2, 7),
             "mul": Fraction(-2, 21), "div": Fraction(-7, 6)}
    for op, want in exact.items():
        got = getattr(dd, op)(np.asarray(x), np.asarray(y))
        value = Fraction(float(got.real)) + Fraction(float(got.imag))
        assert abs(value - want) <= abs(want) * Fraction(1, 10**31), op


def test_the_two_routes_agree_in_double_double():
    """The residual of A = T_to_V (binomial expansion) and X = V_to_T (generating function): the reference is right
    to about 30 digits, and a wrong entry in one route is seen."""
    a, x = ta.dd_matrix(4, 0.7, "T_to_V"), ta.dd_matrix(4, 0.7, "V_to_T")
    assert ta.route_residual(a, x) < 1e-28
    x[3, 5] += 1e-20j  # in the low part (the high part would round it away)
    assert ta.route_residual(a, x) > 1e-27


# --- the transformation ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n", [1, 2, 3])
def test_transformation_float_within_its_bound_or_refused_small_n(n):
    for alpha in (1e-300, 1e-6, 0.5 * v_to_t_float_alpha_min(n), 1.01 * v_to_t_float_alpha_min(n), 0.01, 1.0, 3.0,
                  math.pi - 1e-12):
        _check_transformation(n, alpha, "V_to_T", ta.mp_matrix)
    for alpha in (1e-9, 1e-3, 1.0, 3.0, math.pi - 1e-12):
        _check_transformation(n, alpha, "T_to_V", ta.mp_matrix)
    with pytest.raises(OverflowError, match="exceeds float64"):
        transformation_matrix(n, 1e-300, "T_to_V")


def test_v_to_t_float_bound_at_tiny_alpha():
    """alpha^2 underflowed to 0 below alpha = 1.5e-162: ZeroDivisionError instead of an infinite bound."""
    assert v_to_t_float_bound(3, 1e-300) == math.inf
    assert v_to_t_float_bound(3, 1e-150) == pytest.approx(44 * 2.0**-52 * 1e300)


@pytest.mark.slow
@pytest.mark.parametrize("n", [15, 20, 30])
def test_transformation_float_within_its_bound_or_refused_up_to_n_30(n):
    """Against the double-double reference (20-30 s per matrix at n = 30); 1.01 alpha_min is the smallest alpha
    'V_to_T' returns, 3.0 where the bound of n <= 10 failed at n = 15 (2.4 times over)."""
    for alpha in (1.01 * v_to_t_float_alpha_min(n), 3.0) if n < 30 else (3.0,):
        _check_transformation(n, alpha, "V_to_T", ta.dd_matrix)
    _check_transformation(n, 0.5 * v_to_t_float_alpha_min(n), "V_to_T", ta.dd_matrix)  # refused
    _check_transformation(n, 0.01, "T_to_V", ta.dd_matrix)


# --- the product matrices -----------------------------------------------------------------------------------------
def _product_ratio(n: int, h: int, alpha: float) -> float:
    """The largest |Q_float - Q| / ((2 n + 8) eps |Q| + floor); Q in mp (30 digits), in double-double from n = 10 at
    alpha >= 1e-60 (the same formulas; checked against mp in test_product_reference_double_double_agrees_with_mp)."""
    q = product_matrix(n, h, alpha)
    if n >= 10 and alpha >= 1e-60:
        ref = product_matrix(n, h, alpha, ta.DD)
    else:
        with mpmath.workdps(30):
            m = product_matrix(n, h, mpmath.mpf(alpha), "mp")
            ref = np.array([[ta.DD.convert(x) for x in row] for row in m], dtype=np.complex128)
    diff = np.abs((q - ref.real) - ref.imag)
    return float((diff / (product_float_bound(n) * np.abs(ref.real) + PRODUCT_FLOAT_FLOOR)).max())


def test_product_reference_double_double_agrees_with_mp():
    for h, alpha in ((0, 1e-3), (5, 3.0), (6, 1e-60)):
        dd = product_matrix(4, h, alpha, ta.DD)
        with mpmath.workdps(40):
            m = product_matrix(4, h, mpmath.mpf(alpha), "mp")
            ref = np.array([[ta.DD.convert(x) for x in row] for row in m], dtype=np.complex128)
        assert ta.dd_distance(dd, ref) < 1e-30, (h, alpha)


@pytest.mark.parametrize("n", [1, 2, 4])
def test_product_matrix_float_within_its_bound(n):
    for h in range(7):
        for alpha in (1e-3, 1.0, math.pi - 1e-12):
            assert _product_ratio(n, h, alpha) <= 1, (n, h, alpha)


@pytest.mark.parametrize("alpha", [1e-300, 1e-150, 0.5 * ALPHA_TINY, ALPHA_TINY, 1e-90])
def test_product_matrix_below_alpha_tiny_within_its_bound(alpha):
    """Below ALPHA_TINY the float Q was Q(ALPHA_TINY): every entry of size sigma^e, e >= 1, was wrong relative to
    itself (all of Q for h = R_{2,1,1}: 2.9e-202 for 2.9e-602 at alpha = 1e-300); and from 1e-100 to about 1e-77
    x_f x_h P, of size sigma^2, underflowed before the division by x'_g (0 for entries of size sigma)."""
    for n in (1, 3):
        for h in range(7):
            assert _product_ratio(n, h, alpha) <= 1, (n, h, alpha)


@pytest.mark.slow
@pytest.mark.parametrize("n", [20, 30])
def test_product_matrix_float_within_its_bound_up_to_n_30(n):
    assert _product_ratio(n, 0, 1e-300) <= 1  # the centre R_{2,1,1}: all of Q of size sigma (mp, cheap for this h)
    for h in (0, 5):
        for alpha in (1e-3, 3.0):
            assert _product_ratio(n, h, alpha) <= 1, (n, h, alpha)
