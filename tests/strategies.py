"""Hypothesis strategies: orders, shape parameters and points of Omega^alpha."""

from fractions import Fraction

from flint import fmpq
from hypothesis import strategies as st

from paper_repro.core.domain import RationalPoints, rational_alpha

orders = st.integers(min_value=1, max_value=6)
alphas = st.floats(min_value=0.05, max_value=3.1, allow_nan=False)


@st.composite
def rational_alphas(draw):
    """alpha = 4 atan(t) with rational t in (0, 1)."""
    q = draw(st.integers(min_value=2, max_value=60))
    p = draw(st.integers(min_value=1, max_value=q - 1))
    return rational_alpha(fmpq(p, q))


@st.composite
def rational_points(draw, alpha, max_size=6):
    """Rational points of Omega^alpha: quarter tangents tu, tv with u + v <= alpha."""
    import math

    a = float(alpha)
    size = draw(st.integers(min_value=1, max_value=max_size))
    tus, tvs = [], []
    for _ in range(size):
        fu = draw(st.fractions(min_value=0, max_value=1, max_denominator=50))
        fv = draw(st.fractions(min_value=0, max_value=1, max_denominator=50))
        # u = fu * alpha', v = fv * (alpha' - u) with alpha' slightly below alpha, rounded to rationals
        u = float(fu) * a * 0.999
        v = float(fv) * (a * 0.999 - u)
        tus.append(fmpq(*Fraction(math.tan(u / 4)).limit_denominator(1000).as_integer_ratio()))
        tvs.append(fmpq(*Fraction(math.tan(v / 4)).limit_denominator(1000).as_integer_ratio()))
    return RationalPoints(alpha, tuple(tus), tuple(tvs))


@st.composite
def float_points(draw, alpha, max_size=8):
    size = draw(st.integers(min_value=1, max_value=max_size))
    rows = []
    for _ in range(size):
        x = draw(st.floats(min_value=0, max_value=1))
        y = draw(st.floats(min_value=0, max_value=1)) * (1 - x)
        rows.append([alpha * x, alpha * y, alpha * (1 - x - y)])
    return rows


# --- issue 22: the whole domain of validity (types, ranges, sizes, layouts) --------------------------------------
import math as _math  # noqa: E402

import mpmath as _mpmath  # noqa: E402
import numpy as _np  # noqa: E402

#: alpha over all of (0, pi) as float64 represents it: log-uniform towards 0 and towards pi, and in between.
full_alphas = st.one_of(
    st.floats(min_value=1e-3, max_value=3.14),
    st.floats(min_value=-300, max_value=-3).map(lambda e: 10.0**e),
    st.floats(min_value=-14, max_value=-3).map(lambda e: _math.pi - 10.0**e),
)


def real_types(x: float):
    """The same real value in every accepted scalar type."""
    return st.sampled_from([float(x), _np.float64(x), _np.float32(x), _np.longdouble(x), _np.array(x),
                            _mpmath.mpf(x), Fraction(x), fmpq(*Fraction(x).as_integer_ratio())])


#: Values every real parameter refuses with TypeError (booleans, strings, complex, containers, None).
#: (Strings are not here: "1.0" and "pi/2" are valid alphas, read by parse_alpha; tests/test_api_extras.py.)
non_reals = st.sampled_from([True, _np.bool_(True), b"1", None, 1j, _np.complex128(1), _mpmath.mpc(1, 0),
                             [1.0], _np.array([1.0]), {1.0}, object()])


@st.composite
def point_layouts(draw, alpha, n_points=4):
    """Points of Omega^alpha in every accepted layout: list, tuple, float64 C/Fortran order, non-contiguous
    views, object arrays of floats or mpf, float32 (rounded: on the domain within its tolerance only if
    re-projected, so float32 is drawn at alpha = 1 with exactly representable points)."""
    rows = draw(float_points(alpha, max_size=n_points))
    base = _np.array(rows, dtype=_np.float64)
    kind = draw(st.sampled_from(["list", "tuple", "C", "F", "strided", "object", "mpf", "reversed"]))
    if kind == "list":
        return rows, base
    if kind == "tuple":
        return tuple(map(tuple, rows)), base
    if kind == "C":
        return base.copy(), base
    if kind == "F":
        return _np.asfortranarray(base), base
    if kind == "strided":
        return _np.repeat(base, 2, axis=0)[::2], base
    if kind == "object":
        return base.astype(object), base
    if kind == "mpf":
        return _np.array([[_mpmath.mpf(x) for x in r] for r in base], dtype=object), base
    return _np.ascontiguousarray(base[::-1])[::-1], base


#: Positive weights over the whole float64 range, as (weights, common scale).
weight_scales = st.sampled_from([1e-300, 1e-150, 1e-20, 1.0, 1e20, 1e150, 1e300])
