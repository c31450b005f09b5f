"""The normalizing coefficients of T_{2n}^alpha for every n, from one formula (Question 1, sec:open_problems).

For n >= 1, 0 < alpha < pi, c = cos(alpha/2), s = sin(alpha/2) and 0 <= j <= i <= n
(docs/question1_for_all_n.md proves it for every n; claim ``question1_all_n`` checks it)::

    s^{2n+j} r_{2n,2n-i,j} = [t^j X^i] (1 + s^2 t^2)^n (1 + 2(c + s^2 t) X + (1 + s^2 t^2) X^2)^n
                                        * (1 - m c t) / (1 - c t)^{2n+1},

where m is the number of minimal entries of the sine-exponent triple (2n - i, j, i): m = 1 for j < i, m = 2 on
the diagonal i = j < n, m = 3 at the centre i = j = n.  The other orbits follow from r_{2n,2n-i,j} = r_{2n,i,j}
and g = b = r (eqs. symmetry_condition_1..3).

Expanded, with C_{a,k}(c) = [X^k] (1 + 2cX + X^2)^a (the numerators of the Sanchez-Reyes constants of
eq. univariate_basis) and the t-weights w_f(m) = binom(2n+f, f) (2n - (m-1) f) / (2n + f) >= 0 (f <= n)::

    s^{2n+j} r_{2n,2n-i,j} = sum_{l=0}^{j} H_m[l] Q[j-l][i],
    H_m[l]   = sum_{2e + f = l} binom(n, e) s^{2e} w_f(m) c^f,
    Q[k][i]  = sum_{b = ceil(k/2)}^{k} binom(n, b) binom(b, k-b) 2^{2b-k} s^{2b} C_{n-b, i-k}(c),

a sum of non-negative terms for every alpha in (0, pi]: no cancellation, so floating point keeps its relative
accuracy, and the same code runs in the log context (:class:`~paper_repro.core.context.LogContext`) where the
values exceed float64.  The formula is written once (:func:`scaled_table`) and evaluated through a context:
``'float'``, ``'mp'``, ``'exact'``, ``'ball'``, ``'modp'`` and ``'log'``.

At tan(alpha/4) = 1/2 (s = 4/5, c = 3/5), Example normalizing_coefficients_n_1 gives r_{2,2,0} = 1/s^2,
r_{2,1,0} = 2c/s^2 and r_{2,1,1} = 2/s, i.e. s^2 r_{2,2,0} = 1, s^2 r_{2,1,0} = 6/5, s^3 r_{2,1,1} = 32/25:

>>> from flint import fmpq
>>> from paper_repro.core.context import get_context
>>> [str(x) for x in scaled_table(1, fmpq(3, 5), fmpq(16, 25), get_context("exact"))]
['1', '6/5', '32/25']
"""

from __future__ import annotations

import numbers
from math import comb

import numpy as np
from flint import fmpq

from paper_repro.core.context import Context


def _scalar(x):
    """A scalar that numpy broadcasts as one element (polynomials and other sequences become 0-d object arrays)."""
    if isinstance(x, np.ndarray):
        if x.ndim or x.dtype != object:
            return x
        x = x.item()
    if isinstance(x, (numbers.Number, np.generic)) or not hasattr(x, "__len__") and not hasattr(x, "__getitem__"):
        return x
    out = np.empty(1, dtype=object)
    out[0] = x  # element assignment: a sequence-like x is not broadcast
    return out.reshape(())


def _item(x):
    return x.item() if isinstance(x, np.ndarray) and x.ndim == 0 else x


def _mul(ctx: Context, a, b):
    return _item(ctx.mul(_scalar(a), _scalar(b)))


def _add(ctx: Context, a, b):
    return _item(ctx.add(_scalar(a), _scalar(b)))


def multiplicity(n: int, i: int, j: int) -> int:
    """m: how many entries of the sine-exponent triple (2n - i, j, i) equal its minimum (0 <= j <= i <= n)."""
    trip = (2 * n - i, j, i)
    return trip.count(min(trip))


def t_weight(n: int, f: int, m: int) -> fmpq:
    """w_f(m) = [t^f] (1 - m t) / (1 - t)^{2n+1} = binom(2n+f, f) (2n - (m-1) f) / (2n + f)."""
    return fmpq(comb(2 * n + f, f) * (2 * n - (m - 1) * f), 2 * n + f)


def sanchez_reyes_numerators(n: int, c, ctx: Context) -> list[np.ndarray]:
    """Rows ``C[a][x] = [X^x] (1 + 2cX + X^2)^a`` for a = 0..n, x = 0..n, by C_{a+1} = (1 + 2cX + X^2) C_a."""
    two_c = _mul(ctx, ctx.from_rational(fmpq(2)), c)
    rows = [ctx.zeros((n + 1,))]
    rows[0][0] = ctx.from_rational(fmpq(1))
    for _ in range(n):
        prev = rows[-1]
        nxt = prev.copy()
        nxt[1:] = _add(ctx, nxt[1:], _mul(ctx, two_c, prev[:-1]))
        nxt[2:] = _add(ctx, nxt[2:], prev[:-2])
        rows.append(nxt)
    return rows


def _powers(x, kmax: int, ctx: Context) -> list:
    out = [ctx.from_rational(fmpq(1))]
    for _ in range(kmax):
        out.append(_mul(ctx, out[-1], x))
    return out


def scaled_table(n: int, c, s2, ctx: Context, max_level: int | None = None, min_level: int = 0) -> list:
    """``s^{2n+j} r_{2n,2n-i,j}`` for the orbit representatives, j = 0..n and i = j..n (the order of
    :func:`paper_repro.core.normalization.orbits`), from ``c = cos(alpha/2)`` and ``s2 = sin^2(alpha/2)`` given as
    scalars of the context ``ctx``.  Only additions and multiplications of non-negative terms.

    ``max_level``: only the levels j <= max_level (in the same order), at a fraction of the cost; ``min_level``: only
    the levels j >= min_level (``min_level=n``: the centre alone, O(n^2) operations instead of O(n^3)).  The context
    may also hold polynomials (``c`` an ``fmpq_poly`` in the exact context): then the values are polynomials.

    >>> from paper_repro.core.context import get_context
    >>> ctx = get_context("exact")
    >>> c, s2 = fmpq(3, 5), fmpq(16, 25)
    >>> scaled_table(4, c, s2, ctx, min_level=3) == scaled_table(4, c, s2, ctx)[-3:]
    True
    """
    q = ctx.from_rational
    c, s2 = _scalar(c), _scalar(s2)
    top = n if max_level is None else min(n, max_level)
    if isinstance(min_level, bool) or not isinstance(min_level, numbers.Integral) or min_level < 0:
        raise ValueError(f"min_level must be an integer >= 0, got {min_level!r}")
    lo = int(min_level)
    big_c = sanchez_reyes_numerators(n, c, ctx)
    s2p = _powers(s2, n, ctx)
    cp = _powers(c, n, ctx)
    # Q[k] as an array over i = 0..n (zero for i < k)
    table_q = []
    for k in range(top + 1):
        row = ctx.zeros((n + 1,))
        start = max(k, lo)  # the entries i >= start (the levels asked for need no other)
        for b in range((k + 1) // 2, k + 1):
            coef = _mul(ctx, q(fmpq(comb(n, b) * comb(b, k - b) * 2 ** (2 * b - k))), s2p[b])
            row[start:] = _add(ctx, row[start:], _mul(ctx, coef, big_c[n - b][start - k: n + 1 - k]))
        table_q.append(row)
    # H_m = (sum_e binom(n, e) s^{2e} t^{2e}) * (sum_f w_f(m) c^f t^f), as arrays over l = 0..n
    a_even = [_mul(ctx, q(fmpq(comb(n, e))), s2p[e]) for e in range(n // 2 + 1)]
    h = {}
    for m in (1, 2, 3):
        weights = ctx.zeros((n + 1,))
        for f in range(n + 1):
            weights[f] = _mul(ctx, q(t_weight(n, f, m)), cp[f])
        hm = ctx.zeros((n + 1,))
        for e, ae in enumerate(a_even):
            hm[2 * e:] = _add(ctx, hm[2 * e:], _mul(ctx, ae, weights[: n + 1 - 2 * e]))
        h[m] = hm
    out = []
    for j in range(lo, top + 1):
        # off the diagonal (i > j) m = 1: one array operation per l for all i > j at once
        acc = ctx.zeros((n + 1,))
        for ell in range(j + 1):
            acc[j + 1:] = _add(ctx, acc[j + 1:], _mul(ctx, h[1][ell], table_q[j - ell][j + 1:]))
        diag = q(fmpq(0))
        hm = h[multiplicity(n, j, j)]
        for ell in range(j + 1):
            diag = _add(ctx, diag, _mul(ctx, hm[ell], table_q[j - ell][j]))
        out.append(_item(diag))
        out += [_item(x) for x in acc[j + 1:]]
    return out


def sin_powers(n: int) -> list[int]:
    """The exponent 2n + j of s in the scaling of each orbit representative (orbit order)."""
    return [2 * n + j for j in range(n + 1) for _ in range(j, n + 1)]


__all__ = ["multiplicity", "t_weight", "sanchez_reyes_numerators", "scaled_table", "sin_powers"]
