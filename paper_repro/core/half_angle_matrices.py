"""Order elevation and the derivative matrix C as explicit constructions (finite compositions of the cotangent rules
of docs/elevation_and_derivative_for_all_n.md; only rule (A) is a closed form), for every n, in every arithmetic.

The integer forms of :mod:`paper_repro.core.half_angle_rules` (proven in docs/elevation_and_derivative_for_all_n.md)
are evaluated here through a context (:mod:`paper_repro.core.context`): the same code gives exact matrices at a
:class:`~paper_repro.core.domain.RationalAngle`, floats, mp numbers, balls or residues mod p.

* :func:`elevation_matrix_ctx`: ``E`` with ``T-bar_n = T-bar_{n+1} E`` (Example exmp:degree_elevation_from_1_to_2,
  Question 1 of sec:open_problems), ``E[g, f] = x_f M[g, f] / x'_g`` with x the scaled normalizing coefficients
  (:mod:`paper_repro.core.normalizing_formula`).  Every entry of M is a polynomial in kappa = cos(alpha/2) and
  sigma = sin^2(alpha/2) with non-negative integer coefficients, so E >= 0 and its rows sum to 1: elevation is a
  convex combination for every n and alpha in (0, pi).
* :func:`derivative_matrix`: C with ``2 s d/du m_f = sum_g C[g, f] m_g`` (u = (1, 0, -1)), the matrix of
  :mod:`paper_repro.theory.derivative_matrix` (the tables recovered modulo primes), now for every n.

Float results are the same bits on every CPU: kappa and sigma are taken from flint ``arb`` (correctly rounded, no
libm), then only elementwise ``+``, ``*`` and ``/`` in a fixed order (no BLAS, no reductions).  Each entry of M is a
sum of positive terms, so it keeps its relative accuracy (about (number of terms) x 2^-53).

At tan(alpha/4) = 1/2 the elevation 1 -> 2 is exact and its rows sum to 1:

>>> from paper_repro.core.domain import rational_alpha
>>> from paper_repro.core.context import get_context
>>> e = elevation_matrix_ctx(1, rational_alpha(fmpq(1, 2)), get_context("exact"))
>>> e.shape, all(sum(row) == 1 for row in e.tolist()), min(min(row) for row in e.tolist()) >= 0
((19, 7), True, True)
"""

from __future__ import annotations

from functools import cache

import numpy as np
from flint import arb, fmpq
from flint import ctx as flint_ctx

from paper_repro.core.context import Context, FloatContext, get_context
from paper_repro.core.domain import RationalAngle
from paper_repro.core.half_angle_rules import _derivative_terms, elevation_terms, merge, product_terms
from paper_repro.core.labels import delta, delta_unchecked, variable_swap
from paper_repro.core.normalization import orbits
from paper_repro.core.normalizing_formula import scaled_table
from paper_repro.util.validation import check_alpha, check_n, parse_alpha


def float_half_angle(alpha: float) -> tuple[float, float]:
    """``(kappa, sigma) = (cos(alpha/2), sin^2(alpha/2))`` correctly rounded to float64 (flint ``arb`` at 128 bits:
    the same bits on every machine, unlike libm).

    >>> float_half_angle(1.0) == (0.8775825618903728, 0.22984884706593015)
    True
    """
    return _float_half_angle(check_alpha(alpha))


def _float_half_angle(a: float) -> tuple[float, float]:
    """:func:`float_half_angle` of an alpha already checked (inner code)."""
    old = flint_ctx.prec
    flint_ctx.prec = 128
    try:
        half = arb(a) / 2  # a float is an exact binary rational
        k, s = half.cos(), half.sin()
        return float(k.mid()), float((s * s).mid())
    finally:
        flint_ctx.prec = old


def half_angle(alpha, ctx: Context) -> tuple:
    """``(kappa, sigma)`` as scalars of ``ctx``: exact at a :class:`RationalAngle`, correctly rounded in float."""
    if isinstance(alpha, RationalAngle):
        if alpha.t == 0:
            raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
        s = alpha.sin_half
        with ctx.scope():  # balls and mp numbers made at the context's precision
            return ctx.from_rational(alpha.cos_half), ctx.from_rational(s * s)
    if isinstance(ctx, FloatContext):
        return float_half_angle(alpha)
    if ctx.exact:
        raise TypeError(f"alpha must be a RationalAngle (rational tan(alpha/4)) for arith {ctx.name!r}, "
                        f"got {type(alpha).__name__}")
    if not isinstance(alpha, arb):
        check_alpha(alpha)
    with ctx.scope():
        s, k = ctx.alpha_half(alpha)
        return k, ctx.mul(s, s)


#: Below this alpha the float closed form is taken at ALPHA_TINY: sin^2(alpha/2) would underflow, and the centre's
#: scaled coefficient, of size sin^2(alpha/2), with it (0/0); E(alpha) = E(0) + O(alpha^2), so the difference is far
#: below float64's rounding (a test compares with the exact E at tan(alpha/4) = 1e-40).
ALPHA_TINY = 1e-100


def below_tiny(build, alpha: float) -> np.ndarray:
    """A float matrix at ``alpha < ALPHA_TINY`` whose entries are ``x_f x_h P / x'_g`` with every factor a polynomial
    in (kappa, sigma) with non-negative coefficients (:func:`product_matrix`), from ``build`` at ALPHA_TINY and
    2 ALPHA_TINY.

    Each such polynomial is sigma^v q with q(1, 0) > 0 (a term free of sigma is positive at kappa = 1), and kappa =
    sqrt(1 - sigma); so every entry is sigma^e G(sigma) with G analytic at 0 and G(0) > 0, and
    Q(alpha) = Q(a) (sigma(alpha) / sigma(a))^e (1 + O(a^2)), sigma(alpha) / sigma(a) = (alpha / a)^2 (1 + O(a^2)).
    The exponent e is read from Q(2a) / Q(a) = 4^e (1 + O(a^2)); an entry that is 0 at a (e >= 2: below 1e-400) stays
    0.  Taking Q(a) itself, as before, left the entries with e >= 1 (all of Q for h = R_{2,1,1}) wrong relative to
    themselves: 2.9e-202 for 2.9e-602 at alpha = 1e-300.  Cost: 2e roundings more per entry.  (Q(a) itself is right
    because :func:`product_matrix` forms x_f / x'_g first: x_f x_h P, of size sigma^2, underflowed at a = 1e-100 and
    gave 0 for entries of size sigma = 2.5e-201.)

    >>> q = below_tiny(lambda a: np.array([1.0, 3 * a * a, 0.0]), 1e-150)
    >>> [f"{x:.3g}" for x in q]
    ['1', '3e-300', '0']
    """
    q1, q2 = build(ALPHA_TINY), build(2 * ALPHA_TINY)
    known = (q1 > 0) & (q2 > 0)
    e = np.zeros(q1.shape, dtype=np.int64)
    e[known] = np.rint(np.log(q2[known] / q1[known]) / np.log(4.0))
    ratio = alpha / ALPHA_TINY
    out = q1.copy()
    for k in range(1, 2 * int(e.max(initial=0)) + 1):
        sel = 2 * e >= k
        out[sel] *= ratio
    return out


@cache
def elevation_form(n: int) -> tuple[np.ndarray, ...]:
    """The integer bivariate form of M: ``(rows, cols, a, b, coef)`` sorted, ``M[g, f] = sum coef kappa^a sigma^b``
    (read-only arrays; every coef > 0)."""
    out = merge(elevation_terms(check_n(n)))
    for arr in out:
        arr.setflags(write=False)
    return out


def derivative_form(n: int) -> tuple[np.ndarray, ...]:
    """The integer bivariate form of C (direction u), as :func:`elevation_form` (signed coefficients)."""
    return _derivative_form(check_n(n))


@cache
def _derivative_form(n: int) -> tuple[np.ndarray, ...]:
    out = merge(_derivative_terms(n))
    for arr in out:
        arr.setflags(write=False)
    return out


@cache
def product_form(n: int, h: int) -> tuple[np.ndarray, ...]:
    """The integer bivariate form of P_h (``m_f m_h = sum_g P_h[g, f] m'_g``, h a member of T_2), as
    :func:`elevation_form` (every coef > 0)."""
    out = merge(product_terms(check_n(n), h))
    for arr in out:
        arr.setflags(write=False)
    return out


#: The absolute part of the float bound of :func:`product_matrix`: entries below the normal range of float64.
PRODUCT_FLOAT_FLOOR = 1e-290


def product_float_bound(n: int) -> float:
    """The relative part of the entrywise bound of the float :func:`product_matrix`: ``|Q_float - Q| <= (2 n + 8) eps
    |Q| + PRODUCT_FLOAT_FLOOR`` for every entry, every h and alpha in (0, pi).  A measured bound: each of x_f, x_h,
    P and x'_g is a sum of non-negative terms (no cancellation), and the largest error measured against mp is
    3.4 eps for n <= 10 (the seven h, alpha from 1e-300 to pi - 1e-12), at most 0.17 of this bound up to n = 30
    (``tools/transformation_accuracy.py`` -> ``reports/transformation_accuracy.md``).

    >>> product_float_bound(10) / 2.0**-52
    28.0
    """
    return (2 * check_n(n) + 8) * 2.0**-52


def product_matrix(n: int, h: int | str, alpha, arith: str | Context = "float") -> np.ndarray:
    """Q, ``(delta_{n+1}, delta_n)``: the products of the normalized members of T-bar_{2n} with the normalized member
    ``h`` of T-bar_2 in T-bar_{2(n+1)}, ``f-bar h-bar = sum_g Q[g, f] g-bar'`` (sec:open_problems, the products the
    paper "could not write": ``h`` = ``'B_{2,2,0}'``, ``'G_{2,1,0}'``, ``'B_{2,1,0}'``, and the four others), for every
    n, in the arithmetic ``arith`` (exact needs a :class:`RationalAngle`).  ``Q[g, f] = x_f x_h P_h[g, f] / x'_g`` with
    P_h in Z_{>=0}[kappa, sigma], so Q >= 0; summed over the seven h, Q is the elevation matrix E.

    In float every entry is within :func:`product_float_bound` (``(2 n + 8) eps`` relative, plus
    :data:`PRODUCT_FLOAT_FLOOR` absolute) at every alpha in (0, pi); below :data:`ALPHA_TINY` through
    :func:`below_tiny`.

    >>> from paper_repro.core.domain import rational_alpha
    >>> q = [product_matrix(1, h, rational_alpha(fmpq(1, 2)), "exact") for h in range(7)]
    >>> (sum(q[1:], q[0]) == elevation_matrix_ctx(1, rational_alpha(fmpq(1, 2)), "exact")).all()
    np.True_
    """
    from paper_repro.core.labels import index_of
    from paper_repro.util.limits import MAX_N_ELEVATION, check_int

    n = check_int(n, "n", 1, MAX_N_ELEVATION, why="the dense Q has delta_{n+1} delta_n entries")
    if isinstance(h, str):
        labels = index_of(1)
        if h not in labels:
            raise ValueError(f"h must be a label of T_2 such as 'B_{{2,2,0}}' or an index in [0, 6], got {h!r}")
        h = labels[h]
    elif isinstance(h, bool) or not isinstance(h, (int, np.integer)) or not 0 <= h < delta(1):
        raise ValueError(f"h must be a label of T_2 such as 'B_{{2,2,0}}' or an index in [0, 6], got {h!r}")
    ctx = get_context(arith)
    alpha = alpha if isinstance(alpha, arb) else parse_alpha(alpha)
    if isinstance(ctx, FloatContext) and not isinstance(alpha, RationalAngle):
        alpha = check_alpha(alpha)
        if alpha < ALPHA_TINY:
            return below_tiny(lambda a: _product_matrix(n, int(h), a, ctx), alpha)
    return _product_matrix(n, int(h), alpha, ctx)


def _product_matrix(n: int, h: int, alpha, ctx: Context) -> np.ndarray:
    """:func:`product_matrix` with ``n``, ``h`` and ``alpha`` checked (inner code)."""
    kappa, sigma = half_angle(alpha, ctx)
    rows, cols, p = evaluate_terms(product_form(n, int(h)), kappa, sigma, ctx)
    x, x1, x2 = (scaled_coefficients(k, kappa, sigma, ctx) for k in (n, 1, n + 1))
    with ctx.scope():  # x_f / x'_g first: the sigma-valuation of the partial products never exceeds the result's
        vals = ctx.mul(ctx.mul(ctx.div(x[cols], x2[rows]), x1[int(h)]), p)  # (no underflow of x_f x_h P before / x'_g)
    return _dense(rows, cols, vals, (delta(n + 1), delta(n)), ctx)


def _layout(rows: np.ndarray, cols: np.ndarray) -> tuple[np.ndarray, ...]:
    """Entries of a sorted form and each monomial's rank within its entry (the fixed order of the sums)."""
    new = np.r_[True, (rows[1:] != rows[:-1]) | (cols[1:] != cols[:-1])]
    entry = np.cumsum(new) - 1
    first = np.flatnonzero(new)
    rank = np.arange(len(rows)) - first[entry]
    return entry, rows[first], cols[first], rank


def evaluate_terms(form: tuple[np.ndarray, ...], kappa, sigma, ctx: Context
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(rows, cols, values)`` of the nonzero entries of a merged form (:func:`~paper_repro.core.half_angle_rules.
    merge`) at ``(kappa, sigma)`` in ``ctx``: each entry the sum of its monomials in the order (a, b) ascending, one
    elementwise addition per rank (so float sums have a fixed order)."""
    rows, cols, a, b, coef = form
    entry, erows, ecols, rank = _layout(rows, cols)
    with ctx.scope():
        kp = [ctx.convert(1)]
        for _ in range(int(a.max()) if len(a) else 0):
            kp.append(ctx.mul(kp[-1], kappa))
        sp = [ctx.convert(1)]
        for _ in range(int(b.max()) if len(b) else 0):
            sp.append(ctx.mul(sp[-1], sigma))
        kpa, spa = ctx.asarray(kp), ctx.asarray(sp)
        coefs = coef.astype(np.float64) if isinstance(ctx, FloatContext) else ctx.asarray([int(c) for c in coef])
        terms = ctx.mul(ctx.mul(coefs, kpa[a]), spa[b])
        vals = ctx.zeros((len(erows),))
        for k in range(int(rank.max()) + 1 if len(rank) else 0):
            sel = rank == k
            vals[entry[sel]] = ctx.add(vals[entry[sel]], terms[sel])
    return erows, ecols, vals


def evaluate_form(form_id: tuple[str, int], kappa, sigma, ctx: Context) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`evaluate_terms` of ``('M', n)`` (:func:`elevation_form`) or ``('C', n)`` (:func:`derivative_form`)."""
    kind, n = form_id
    return evaluate_terms((elevation_form if kind == "M" else _derivative_form)(n), kappa, sigma, ctx)


def scaled_coefficients(n: int, kappa, sigma, ctx: Context) -> np.ndarray:
    """The scaled normalizing coefficients ``s^{2n+j} x_f`` of all members (internal order) at ``(kappa, sigma)``
    (Theorem B's formula, :func:`~paper_repro.core.normalizing_formula.scaled_table`)."""
    with ctx.scope():
        orb = scaled_table(n, kappa, sigma, ctx)
    out = ctx.zeros((delta(n),))
    for (_, members), x in zip(orbits(n), orb):
        out[list(members)] = x
    return out


def _dense(rows, cols, vals, shape, ctx: Context) -> np.ndarray:
    out = ctx.zeros(shape)
    out[rows, cols] = vals
    return out


def elevation_matrix_ctx(n: int, alpha, arith: str | Context = "float") -> np.ndarray:
    """E, ``(delta_{n+1}, delta_n)``, with ``T-bar_n = T-bar_{n+1} E`` in the arithmetic ``arith`` (exact needs a
    :class:`RationalAngle`); from the explicit construction, no linear solve."""
    n = check_n(n)
    ctx = get_context(arith)
    kappa, sigma = half_angle(alpha, ctx)
    return elevation_from_form(elevation_form(n), n, kappa, sigma, ctx)


def elevation_entries(form: tuple[np.ndarray, ...], n: int, kappa, sigma, ctx: Context
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(rows, cols, values)`` of the nonzero entries of E from a merged form of M at ``(kappa, sigma)`` in ``ctx``
    (the checks of :mod:`paper_repro.theory.half_angle_checks` also pass deliberately wrong forms)."""
    rows, cols, m = evaluate_terms(form, kappa, sigma, ctx)
    x, x1 = scaled_coefficients(n, kappa, sigma, ctx), scaled_coefficients(n + 1, kappa, sigma, ctx)
    with ctx.scope():
        vals = ctx.div(ctx.mul(x[cols], m), x1[rows])
    return rows, cols, vals


def elevation_from_form(form: tuple[np.ndarray, ...], n: int, kappa, sigma, ctx: Context) -> np.ndarray:
    """The dense E of :func:`elevation_entries`."""
    return _dense(*elevation_entries(form, n, kappa, sigma, ctx), (delta(n + 1), delta(n)), ctx)


def derivative_matrix(n: int, alpha, arith: str | Context = "float") -> np.ndarray:
    """C, ``(delta_n, delta_n)``, with ``2 s d/du m_f = sum_g C[g, f] m_g`` for the scaled monomials (direction
    u = (1, 0, -1)) in the arithmetic ``arith``, from the explicit construction; the direction v is C conjugated by
    :func:`~paper_repro.core.labels.variable_swap`."""
    n = check_n(n)
    ctx = get_context(arith)
    kappa, sigma = half_angle(alpha, ctx)
    rows, cols, vals = evaluate_form(("C", n), kappa, sigma, ctx)
    return _dense(rows, cols, vals, (delta(n), delta(n)), ctx)


def derivative_nets(n: int, alpha, net: np.ndarray, arith: str | Context = "float") -> tuple[np.ndarray, np.ndarray]:
    """``(q_u, q_v)``: the nets of ``2 s d/du`` and ``2 s d/dv`` of the patch ``sum_f net[f] m_f`` on the scaled
    monomials (``net`` of shape ``(delta_n, d)``), from the explicitly constructed C in the arithmetic ``arith``.  In
    float each output row is summed in the order of the form's entries (``np.add.at``: the same bits on every CPU).

    The direction v is u with the variables u, v exchanged (:func:`~paper_repro.core.labels.variable_swap`).

    >>> import math
    >>> qu, qv = derivative_nets(1, 1.0, np.eye(7)[:, :1])   # the net of m_0 = S_u S_v S_w
    >>> np.nonzero(qu[:, 0])[0].tolist(), qu[np.nonzero(qu[:, 0])[0], 0].tolist()
    ([4, 6], [1.0, -1.0])
    """
    n = check_n(n)
    ctx = get_context(arith)
    net = np.asarray(net, dtype=np.float64 if isinstance(ctx, FloatContext) else object)
    if net.ndim != 2 or net.shape[0] != delta(n):
        raise ValueError(f"net must be a (delta_n, d) = ({delta(n)}, d) array for n = {n}, got shape {net.shape}")
    if not isinstance(alpha, RationalAngle):
        alpha = check_alpha(parse_alpha(alpha))
    return derivative_nets_checked(n, alpha, net, ctx)


def derivative_nets_checked(n: int, alpha, net: np.ndarray, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
    """:func:`derivative_nets` for inner code: ``n``, ``alpha`` (a float in (0, pi) or a RationalAngle) and the
    ``(delta_n, d)`` net of ``ctx``'s kind already checked."""
    kappa, sigma = _float_half_angle(alpha) if isinstance(ctx, FloatContext) and not isinstance(
        alpha, RationalAngle) else half_angle(alpha, ctx)
    rows, cols, vals = evaluate_form(("C", n), kappa, sigma, ctx)
    pi = variable_swap(n, 0, 1)  # m_{pi[f]}(u, v, w) = m_f(v, u, w)

    def apply(x: np.ndarray) -> np.ndarray:
        out = ctx.zeros((delta_unchecked(n), x.shape[1]))
        with ctx.scope():
            if isinstance(ctx, FloatContext):
                np.add.at(out, rows, vals[:, None] * x[cols])
            else:
                for r, c, v in zip(rows, cols, vals):
                    out[r] = ctx.add(out[r], ctx.mul(v, x[c]))
        return out

    qu = apply(net)
    qv = ctx.zeros(qu.shape)
    qv[pi] = apply(net[pi])
    return qu, qv


__all__ = ["PRODUCT_FLOAT_FLOOR", "product_float_bound", "below_tiny",
           "elevation_matrix_ctx", "derivative_matrix", "derivative_nets", "elevation_form", "derivative_form",
           "float_half_angle", "half_angle", "scaled_coefficients", "evaluate_form", "evaluate_terms",
           "elevation_from_form", "elevation_entries"]
_ = fmpq  # doctest name
