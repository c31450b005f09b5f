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
