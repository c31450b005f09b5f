"""Directional derivatives of the blending functions along Omega^alpha, in every arithmetic.

With ``s = sin(x/2)``, ``c = cos(x/2)``: ``d/dx (s^a c^b) = (a/2) s^(a-1) c^(b+1) - (b/2) s^(a+1) c^(b-1)``,
so the derivative of every monomial of T_{2n} is a combination of monomials with shifted exponents:
one formula, evaluated by :func:`paper_repro.core.basis.monomials` in any context.  A direction
``(du, dv, dw)`` tangent to Omega^alpha has ``du + dv + dw = 0``.

>>> import numpy as np
>>> pts = np.array([[0.3, 0.3, 0.4]])
>>> h = 1e-6
>>> fd = (evaluate_normalized(2, 1.0, pts + [[h, 0, -h]]) - evaluate_normalized(2, 1.0, pts - [[h, 0, -h]])) / (2 * h)
>>> bool(np.allclose(basis_derivative(2, 1.0, pts, "u"), fd, atol=1e-7))
True
"""

from __future__ import annotations

import numpy as np

from paper_repro.core.basis import monomials
from paper_repro.core.context import Context, get_context
from paper_repro.core.domain import half_angle_values
from paper_repro.core.labels import exponent_matrix
from paper_repro.core.normalization import coefficient_vector, evaluate_normalized  # noqa: F401 (doctest)
from paper_repro.util.validation import check_n

#: Named directions: ``'u'`` = d/du with v fixed (w = alpha - u - v), ``'v'`` = d/dv with u fixed,
#: ``'w'`` = d/dw with u fixed.
DIRECTIONS = {"u": (1, 0, -1), "v": (0, 1, -1), "w": (0, -1, 1)}


def check_direction(direction) -> tuple:
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
    try:
        fl = [float(x) for x in d]
    except (TypeError, ValueError):
        raise TypeError("direction components must be real numbers") from None
    if not all(np.isfinite(fl)) or abs(sum(fl)) > 1e-12 * max(1.0, max(abs(x) for x in fl)):
        raise ValueError(f"direction must be finite with du + dv + dw = 0 (tangent to Omega^alpha), got {d}")
    return d


def monomial_derivative(exps: np.ndarray, trig, direction, ctx: Context) -> np.ndarray:
    """``(P, F)`` directional derivatives of the monomials with exponent rows ``exps``."""
    exps = np.asarray(exps, dtype=np.int64)
    npts = len(trig[0])
    total = ctx.zeros((npts, exps.shape[0]))
    half = ctx.div(ctx.convert(1), ctx.convert(2))
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
            factor = ctx.asarray([ctx.mul(ctx.mul(ctx.convert(int(sign * v)), half), ctx.convert(dx)) for v in k])
            total = ctx.add(total, ctx.mul(monomials(shifted, trig, ctx), factor[None, :]))
    return total


def basis_derivative(n: int, alpha, points, direction="u", arith: str | Context = "float", *,
                     dps: int = 50) -> np.ndarray:
    """Directional derivative of the blending functions T-bar_{2n}^alpha at the points: ``(P, delta_n)``."""
    n = check_n(n)
    d = check_direction(direction)
    ctx = get_context(arith, dps=dps)
    trig = half_angle_values(points, alpha, ctx)
    vec = coefficient_vector(n, alpha, ctx)
    with ctx.scope():
        return ctx.mul(monomial_derivative(exponent_matrix(n), trig, d, ctx), vec[None, :])

