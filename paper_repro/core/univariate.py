"""The univariate normalized B-basis of F_{2n}^alpha (eq. univariate_basis).

``A_{2n,i}^alpha(t) = c_{2n,i}^alpha sin^{2n-i}((alpha - t)/2) sin^i(t/2)``, ``t in [0, alpha]``, with
the printed normalizing constants

``c_{2n,i}^alpha = sin^{-2n}(alpha/2) sum_{r=0}^{floor(i/2)} binom(n, i-r) binom(i-r, r) (2 cos(alpha/2))^{i-2r}``.

The constant is written once as :func:`c_numerator` (the polynomial in ``cos(alpha/2)``) and
evaluated in float, mpmath or exact arithmetic.  An independent computation of the same constants
(coefficients of ``(X^2 + 2 cos(alpha/2) X Y + Y^2)^n``) is :func:`c_numerator_by_expansion`.
"""

from __future__ import annotations

from math import comb

import mpmath
import numpy as np
from flint import fmpq_poly

from paper_repro.core.context import Context, get_context, power_table
from paper_repro.util.validation import check_alpha, check_n


def c_numerator(n: int, i: int) -> list[int]:
    """Printed formula (eq. univariate_basis): coefficients of ``sin^{2n}(alpha/2) c_{2n,i}`` as a
    polynomial in ``cos(alpha/2)``, ascending powers (integers)."""
    n = check_n(n)
    if not 0 <= i <= 2 * n:
        raise ValueError(f"i must satisfy 0 <= i <= 2n = {2 * n}, got {i}")
    coeffs = [0] * (i + 1)
    for r in range(i // 2 + 1):
        coeffs[i - 2 * r] += comb(n, i - r) * comb(i - r, r) * 2 ** (i - 2 * r)
    return coeffs


def c_numerator_by_expansion(n: int) -> list[fmpq_poly]:
    """Independent computation: ``[P_0, ..., P_{2n}]`` with ``P_i(c)`` the coefficient of
    ``X^{2n-i} Y^i`` in ``(X^2 + 2 c X Y + Y^2)^n`` (flint polynomial arithmetic in ``c``).

    Source: the proof of Proposition Bernstein, ``sum_i A_{2n,i} = (A_{2,0}+A_{2,1}+A_{2,2})^n``.
    """
    n = check_n(n)
    # Work with polynomials in Y whose coefficients are polynomials in c: list index = power of Y.
    base = [fmpq_poly([1]), fmpq_poly([0, 2]), fmpq_poly([1])]
    acc = [fmpq_poly([1])]
    for _ in range(n):
        new = [fmpq_poly([0])] * (len(acc) + 2)
        for a, pa in enumerate(acc):
            for b, pb in enumerate(base):
                new[a + b] = new[a + b] + pa * pb
        acc = new
    return acc


def _power(ctx: Context, x, k: int):
    out = ctx.convert(1)
    for _ in range(k):
        out = ctx.mul(out, x)
    return out


def c_const(n: int, i: int, alpha, arith: str | Context = "float"):
    """``c_{2n,i}^alpha`` from the printed formula, in any arithmetic (``'mp'``: the current precision).

    For the exact arithmetics pass a :class:`~paper_repro.core.domain.RationalAngle` as ``alpha``.

    >>> import math
    >>> bool(abs(c_const(1, 1, 1.0) - 2 * math.cos(0.5) / math.sin(0.5) ** 2) < 1e-12)
    True
    """
    coeffs = c_numerator(n, i)
    ctx = get_context(arith, dps=mpmath.mp.dps)
    if not hasattr(alpha, "sin_half"):
        check_alpha(alpha)
    with ctx.scope():
        s, c = ctx.alpha_half(alpha)
        acc = ctx.convert(0)
        for k in reversed(coeffs):
            acc = ctx.add(ctx.mul(acc, c), ctx.convert(k))
        return ctx.div(acc, _power(ctx, s, 2 * n))


def A(n: int, alpha, t, arith: str | Context = "float") -> np.ndarray:
    """``A_{2n,i}^alpha(t)`` for ``i = 0..2n`` at the points ``t`` (array): shape ``(len(t), 2n+1)``.

    Real arithmetics (``'mp'``: the current precision; ``t`` may hold mpf); ``t`` must lie in [0, alpha].
    """
    n = check_n(n)
    a_f = check_alpha(alpha)
    ctx = get_context(arith, dps=mpmath.mp.dps)
    tt_f = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if np.any(tt_f < -1e-12 * a_f) or np.any(tt_f > a_f * (1 + 1e-12)):
        raise ValueError(f"t must lie in [0, alpha] = [0, {a_f}]")
    consts = [c_const(n, i, alpha, ctx) for i in range(2 * n + 1)]
    with ctx.scope():
        tt = ctx.asarray(np.atleast_1d(np.asarray(t, dtype=object)))
        a, two = ctx.convert(alpha), ctx.convert(2)
        s1, s2 = ctx.sin(ctx.div(ctx.sub(a, tt), two)), ctx.sin(ctx.div(tt, two))
        cols = [ctx.mul(ctx.mul(consts[i], power_table(s1, 2 * n, ctx)[2 * n - i]), power_table(s2, 2 * n, ctx)[i])
                for i in range(2 * n + 1)]
        return np.stack(cols, axis=1)


def bernstein(m: int, s) -> np.ndarray:
    """Bernstein polynomials ``B_i^m(s)``, ``i = 0..m``, at ``s``: shape ``(len(s), m+1)`` (float or mp)."""
    ss = np.atleast_1d(np.asarray(s, dtype=object))
    out = np.empty((len(ss), m + 1), dtype=object)
    for k, x in enumerate(ss):
        for i in range(m + 1):
            out[k, i] = comb(m, i) * x**i * (1 - x) ** (m - i)
    return out
