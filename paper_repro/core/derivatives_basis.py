"""Directional derivatives of the blending functions along Omega^alpha, in every arithmetic.

With ``s = sin(x/2)``, ``c = cos(x/2)``: ``d/dx (s^a c^b) = (a/2) s^(a-1) c^(b+1) - (b/2) s^(a+1) c^(b-1)``,
so the derivative of every monomial of T_{2n} is a combination of monomials with shifted exponents:
one formula, evaluated by :func:`paper_repro.core.basis.monomials` in any context.  A direction
``(du, dv, dw)`` tangent to Omega^alpha has ``du + dv + dw = 0``.

The blending functions are evaluated in the scaled form of :func:`paper_repro.core.normalization.evaluate_normalized`
(sine ratios ``S = sin(x/2)/s``, ``s = sin(alpha/2)``, and scaled coefficients ``s^{2n+j} r``):
``d/dx (S^a c^b) = (a S^(a-1) c^(b+1) - b s^2 S^(a+1) c^(b-1)) / (2s)``.  Every factor of the bracket is
bounded; the factor ``1/(2s)`` is applied once, at the end, so the derivatives are finite and accurate for
every alpha in (0, pi) (down to 1e-300; the values are then of size 1/alpha).

>>> import numpy as np
>>> pts = np.array([[0.3, 0.3, 0.4]])
>>> h = 1e-6
>>> fd = (evaluate_normalized(2, 1.0, pts + [[h, 0, -h]]) - evaluate_normalized(2, 1.0, pts - [[h, 0, -h]])) / (2 * h)
>>> bool(np.allclose(basis_derivative(2, 1.0, pts, "u"), fd, atol=1e-7))
True
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from paper_repro.core.basis import monomials
from paper_repro.core.context import Context, FloatContext, _to_fraction, get_context
from paper_repro.core.domain import scaled_half_angle_values
from paper_repro.core.labels import exponent_matrix
from paper_repro.core.normalization import evaluate_normalized, scaled_coefficient_vector  # noqa: F401 (doctest)
from paper_repro.util.validation import check_n

#: Named directions: ``'u'`` = d/du with v fixed (w = alpha - u - v), ``'v'`` = d/dv with u fixed,
#: ``'w'`` = d/dw with u fixed.
DIRECTIONS = {"u": (1, 0, -1), "v": (0, 1, -1), "w": (0, -1, 1)}


def check_direction(direction) -> tuple:
    """A direction as ``(du, dv, dw)``: a name of :data:`DIRECTIONS` (its integer triple), or a triple of real numbers
    with ``|du + dv + dw| <= 1e-12 max(|du|, |dv|, |dw|)``, returned as exact fractions with ``dw = -du - dv``: every
    arithmetic then differentiates along the same tangent direction ``du (1, 0, -1) + dv (0, 1, -1)``.

    >>> check_direction((0.5, 0.25, -0.75)), check_direction("w")
    ((Fraction(1, 2), Fraction(1, 4), Fraction(-3, 4)), (0, -1, 1))
    """
    if isinstance(direction, str):
        if direction not in DIRECTIONS:
            raise ValueError(f"direction must be one of {sorted(DIRECTIONS)} or a triple (du, dv, dw) with sum 0, "
                             f"got {direction!r}")
        return DIRECTIONS[direction]
    try:
        d = tuple(direction)
    except TypeError:
        raise TypeError(f"direction must be a name or a triple (du, dv, dw), got {direction!r}") from None
    if len(d) != 3:
        raise ValueError(f"direction must have 3 components (du, dv, dw), got {len(d)}")
    from paper_repro.util.limits import real_scalar

    try:
        fl = [float(real_scalar(x, "direction components")) for x in d]  # no booleans, strings, complex numbers
    except (TypeError, ValueError):
        raise TypeError(f"direction components must be real numbers (not booleans or strings), got {d!r}") from None
    except OverflowError:
        raise ValueError("direction components must be finite floats (at most about 1.8e308 in size)") from None
    if not all(np.isfinite(fl)) or abs(sum(fl)) > 1e-12 * max(abs(x) for x in fl):
        raise ValueError(f"direction must be finite with du + dv + dw = 0 (tangent to Omega^alpha; |sum| <= 1e-12 "
                         f"of the largest component), got {d}")
    du, dv = (_exact(x) for x in d[:2])
    return du, dv, -du - dv


def _exact(x) -> Fraction:
    """The exact value of a direction component (a float as its binary value)."""
    if isinstance(x, (bool, np.bool_)):
        return Fraction(int(x))
    try:
        return _to_fraction(x)
    except TypeError:
        return Fraction(float(x))


def monomial_derivative(exps: np.ndarray, trig, direction, ctx: Context, *, s2=None) -> np.ndarray:
    """``(P, F)`` directional derivatives of the monomials with exponent rows ``exps``.

    With ``s2`` (= sin^2(alpha/2)), ``trig`` holds the sine ratios ``sin(x/2)/sin(alpha/2)`` and the result is
    ``2 sin(alpha/2)`` times the derivatives of the scaled monomials (the bounded bracket of the module doc).
    """
    exps = np.asarray(exps, dtype=np.int64)
    npts = len(trig[0])
    total = ctx.zeros((npts, exps.shape[0]))
    half = ctx.div(ctx.convert(1), ctx.convert(2))
    unit = ctx.convert(1)
    for var, dx in enumerate(direction):
        if dx == 0:
            continue
        sx, cx = 2 * var, 2 * var + 1
        for slot, sign in ((sx, 1), (cx, -1)):
            k = exps[:, slot]
            if not k.any():
                continue
            shifted = exps.copy()
            shifted[:, slot] = np.maximum(k - 1, 0)
            other = cx if slot == sx else sx
            shifted[:, other] += 1
            scale = half if s2 is None else (unit if slot == sx else s2)
            factor = ctx.asarray([ctx.mul(ctx.mul(ctx.convert(int(sign * v)), scale), ctx.convert(dx)) for v in k])
            total = ctx.add(total, ctx.mul(monomials(shifted, trig, ctx), factor[None, :]))
    return total


def basis_derivative(n: int, alpha, points, direction="u", arith: str | Context = "float", *,
                     dps: int = 50) -> np.ndarray:
    """Directional derivative of the blending functions T-bar_{2n}^alpha at the points: ``(P, delta_n)``."""
    n = check_n(n)
    d = check_direction(direction)
    ctx = get_context(arith, dps=dps)
    trig = scaled_half_angle_values(points, alpha, ctx)
    a = alpha if alpha is not None else points.alpha
    vec = scaled_coefficient_vector(n, a, ctx)
    with ctx.scope():
        sa, _ = ctx.alpha_half(a)
        bracket = monomial_derivative(exponent_matrix(n), trig, d, ctx, s2=ctx.mul(sa, sa))
        with np.errstate(over="ignore"):
            out = ctx.div(ctx.mul(bracket, vec[None, :]), ctx.mul(ctx.convert(2), sa))
    if isinstance(ctx, FloatContext) and not np.all(np.isfinite(out)):
        raise OverflowError(f"alpha: the derivatives are of size 1/alpha and exceed float64's range at alpha = "
                            f"{float(a):.3g}; use arith='mp'")
    return out

