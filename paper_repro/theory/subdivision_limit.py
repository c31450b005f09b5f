"""The subdivision matrices as exact rational functions of X = cos(alpha/4), and their limit at alpha -> 0
(docs/subdivision_for_all_n.md, section 11, Proposition 11.6 and the paragraph after it).

Beyond the paper.  Proposition 11.6 proves that every entry of the midpoint subdivision matrix S_k (k = u, v, w,
middle) is ``r_{g,f}(cos(alpha/4))`` with ``r_{g,f}`` in Q(X) independent of alpha, and reduces "S is smooth and
even at alpha = 0" to "no r_{g,f} has a pole at X = 1".  This module runs the library's own construction
(:mod:`paper_repro.core.subdivision_products`: Lemma 11.1 for R_1, the integer forms ``coef kappa'^a sigma'^b`` of
Theorem P level by level, :func:`~paper_repro.core.subdivision_products._level_terms`, Theorem 11.3's recursion over
:func:`~paper_repro.core.subdivision_products.factorization`, and the scaled normalizing coefficients of Theorem B)
with X an indeterminate instead of a float, over the integers, with

    kappa' = X,  sigma' = 1 - X^2,  kappa = cos(alpha/2) = 2X^2 - 1,  sigma = sin^2(alpha/2) = 4X^2(1 - X^2).

*The numerators.*  Column h of R_1^k is ``(2X)^{-e(h)}`` times a vector of integer polynomials (Lemma 11.1; e(h) the
total sine degree of the member h), and Theorem 11.3 multiplies columns, so column f of R_n^k is
``(2X)^{-E(f)} N_n^k[:, f]`` with N_n^k an integer polynomial matrix and E(f) = 2n + j(f) the total sine degree of f
(asserted at every level).  Then

    S_k[g, f] = N[g, f](X) xi_f(X) / ((2X)^{E(f)} xi'_g(X)),

xi_f the scaled normalizing coefficient at alpha, xi'_g at alpha/2 (both in Q[X]).

*Where it is computed.*  Every polynomial is kept in the variable t = X - 1 (alpha -> 0 is t -> 0-, t ~ -alpha^2/32),
as the list of its coefficient matrices (flint ``fmpz_mat``), truncated at t^N.  Truncation is a ring homomorphism
Z[t] -> Z[t]/(t^N), so the first N coefficients are exact.  Two modes:

* ``terms=None``: N one more than a degree bound (the degree of R_1's numerators plus that of the product forms,
  level by level), so the polynomials are complete: S_k(X) exactly, evaluated at any X (:func:`exact_matrices_at`,
  compared in the tests with the exact collocation route at rational cos(alpha/4)).
* ``terms=N`` small: enough to decide the pole order at t = 0 and to read the limit.  With o_g = ord_t xi'_g (at most 1
  for n <= 16, counted by :func:`limit_check`), the entry has a pole at X = 1 exactly when
  ``ord_t N[g, f] + ord_t xi_f < o_g``, and its value and derivative at X = 1 need the coefficients up to t^{o_g + 1}:
  N = max o_g + 2 terms decide everything (:func:`limit_check` takes that N).

Every column of every part is computed (no symmetry is used: parts v and w are run with their own R_1), so the check
is exhaustive over the entries.

>>> res = limit_check(1)
>>> res.max_pole, res.entries, res.max_ord_xi_half
(0, 196, 1)
>>> res.limits[3][0, 0]  # the middle's centre row at the centre: -1/2 at every alpha (section 5)
-1/2
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from functools import cache

import numpy as np
import scipy.sparse as sp
from flint import fmpq, fmpq_poly, fmpz, fmpz_mat, fmpz_poly

from paper_repro.core.context import get_context
from paper_repro.core.half_angle_rules import cotangent, merge, product_terms
from paper_repro.core.labels import check_n, delta, exponent_matrix
from paper_repro.core.normalization import orbits
from paper_repro.core.normalizing_formula import scaled_table
from paper_repro.core.subdivision_products import PARTS, _level_terms, factorization
from paper_repro.util.limits import check_int

#: X = cos(alpha/4) and t = X - 1 as integer polynomials.
X_POLY = fmpz_poly([0, 1])
_SHIFT = fmpz_poly([1, 1])  # X = 1 + t


# --- polynomials in t, truncated --------------------------------------------------------------------------------------
def shifted(p, terms: int) -> list:
    """The first ``terms`` coefficients of p(1 + t) for a polynomial p in X (``fmpz_poly``, ``fmpq_poly`` or a
    constant); zeros beyond the degree.

    >>> shifted(fmpz_poly([0, 0, 1]), 4)  # X^2 = 1 + 2t + t^2
    [1, 2, 1, 0]
    """
    q = (fmpq_poly(p) if not isinstance(p, fmpz_poly) else p)(_SHIFT) if not isinstance(p, (int, fmpz, fmpq)) else p
    if isinstance(q, (int, fmpz, fmpq)):
        return [q] + [0] * (terms - 1)
    coeffs = [int(c) if isinstance(c, fmpz) else c for c in q.coeffs()]
    return [coeffs[i] if i < len(coeffs) else 0 for i in range(terms)]


def _mat_mul(a: list, b: list, terms: int) -> list:
    """Truncated product of two polynomial matrices given as coefficient lists of ``fmpz_mat`` (None for zero)."""
    out: list = [None] * terms
    for i, ai in enumerate(a):
        if ai is None:
            continue
        for j, bj in enumerate(b[:terms - i]):
            if bj is None:
                continue
            prod = ai * bj
            out[i + j] = prod if out[i + j] is None else out[i + j] + prod
    return out


def _as_fmpz_mat(arr: np.ndarray) -> fmpz_mat | None:
    """A 2-d integer (int64 or object) array as ``fmpz_mat``; None if it is zero."""
    if not arr.any():
        return None
    flat = arr.ravel().tolist() if arr.dtype == np.int64 else [int(x) for x in arr.ravel().tolist()]
    return fmpz_mat(arr.shape[0], arr.shape[1], flat)


def _as_array(m: fmpz_mat | None, shape: tuple[int, int]) -> np.ndarray:
    out = np.zeros(shape, dtype=object)
    if m is not None:
        out[...] = np.array([int(x) for x in m.entries()], dtype=object).reshape(shape)
    return out


# --- order one: Lemma 11.1 over Z[X] ----------------------------------------------------------------------------------
@cache
def order_one_numerators(part: str) -> tuple[tuple[fmpz_poly, ...], ...]:
    """``N_1[g][h]`` with R_1^part[g, h] = N_1[g][h] / (2X)^{e(h)}: the algorithm of
    :func:`~paper_repro.core.subdivision_products.order_one_restriction` (substitution of the images of
    S_x, C_x times 2X, then each ``S'^(e - t) C'^t`` as L_x^t of the member with S'^e, Horner in L_x) with
    kappa' = X, sigma' = 1 - X^2 as integer polynomials.  Under the translation in x: S_x -> (X S'_x + C'_x)/(2X),
    C_x -> X C'_x - sigma' S'_x, S_y -> S'_y/(2X); under the point reflection S_x -> (C'_x - X S'_x)/(2X),
    C_x -> X C'_x + sigma' S'_x for every x.

    >>> import math
    >>> from paper_repro.core.subdivision_products import order_one_restriction
    >>> kp = math.cos(0.3)
    >>> e = sine_degree(1)
    >>> num = order_one_numerators("middle")
    >>> r1 = np.array([[float(num[g][h](kp)) / (2 * kp) ** int(e[h]) for h in range(7)] for g in range(7)])
    >>> bool(np.abs(r1 - order_one_restriction("middle", kp, 1 - kp * kp)).max() < 1e-14)
    True
    """
    if part not in PARTS:
        raise ValueError(f"part must be one of {PARTS}, got {part!r}")
    e = exponent_matrix(1)
    index = {tuple(int(v) for v in row): k for k, row in enumerate(e)}
    sg = 1 - X_POLY * X_POLY
    lops = []
    for var in range(3):
        op = [[fmpz_poly(0)] * 7 for _ in range(7)]
        for g in range(7):
            if e[g, 2 * var]:
                for a, b, c, t in cotangent(1, var, g).tolist():
                    op[t][g] = op[t][g] + c * X_POLY ** a * sg ** b
        lops.append(op)
    variables = (0, 1, 2) if part == "middle" else ("uvw".index(part),)
    if part == "middle":
        sin_image, cos_image = (-X_POLY, fmpz_poly(1)), (sg, X_POLY)
    else:
        sin_image, cos_image = (X_POLY, fmpz_poly(1)), (-sg, X_POLY)
    cols = []
    for h in range(7):
        base = e[h].copy()
        for v in variables:
            base[2 * v] += base[2 * v + 1]
            base[2 * v + 1] = 0
        vec = [fmpz_poly(0)] * 7
        vec[index[tuple(int(t) for t in base)]] = fmpz_poly(1)
        for v in variables:
            poly = [fmpz_poly(1)]
            for lo, hi in [sin_image] * int(e[h, 2 * v]) + [cos_image] * int(e[h, 2 * v + 1]):
                poly = [lo * poly[0]] + [lo * poly[t] + hi * poly[t - 1] for t in range(1, len(poly))] + [hi * poly[-1]]
            acc = [poly[-1] * x for x in vec]
            for t in range(len(poly) - 2, -1, -1):
                acc = [sum((lops[v][r][c] * acc[c] for c in range(7)), fmpz_poly(0)) + poly[t] * vec[r]
                       for r in range(7)]
            vec = acc
        # every sine, treated or not, carries 1/(2X) (s = 2 s' kappa'): the prefactor (2X)^{-e(h)} is left out
        cols.append(vec)
    return tuple(tuple(cols[h][g] for h in range(7)) for g in range(7))


def sine_degree(n: int) -> np.ndarray:
    """E(f) = a_u + a_v + a_w, the total sine degree of each member of T_{2n} (2n + j(f))."""
    e = exponent_matrix(n)
    return (e[:, 0] + e[:, 2] + e[:, 4]).astype(np.int64)


# --- the level recursion over Z[t]/(t^N) ------------------------------------------------------------------------------
def _level_degree(k: int) -> int:
    """The degree in X of the product forms of level k: max(a + 2b) over the terms coef X^a (1 - X^2)^b."""
    _, _, a, b, _, _ = _level_terms(k)
    return int((a.astype(np.int64) + 2 * b.astype(np.int64)).max())


def degree_bound(n: int, part: str) -> int:
    """An upper bound of the degree of the numerators N_n^part (in X, equally in t): the degree of N_1 plus, per
    level, that of the product forms plus that of N_1."""
    d1 = max(p.degree() for row in order_one_numerators(part) for p in row)
    return d1 + sum(_level_degree(k) + d1 for k in range(2, n + 1))


def _combined_numerator(k: int, n1_shift: list, g: int, terms: int) -> list:
    """Q_g = sum_h N_1[h, g] P_h (delta_k x delta_{k-1}) as ``terms`` coefficient matrices in t: every term
    coef X^a (1 - X^2)^b of :func:`~paper_repro.core.subdivision_products._level_terms` times the numerator of
    R_1[h, g], shifted to t = X - 1 and summed (int64, guarded against overflow)."""
    rows, cols, a, b, coef, hidx = (np.asarray(arr, dtype=np.int64) for arr in _level_terms(k))
    shape = (delta(k), delta(k - 1))
    na, nb = int(a.max()) + 1, int(b.max()) + 1
    # table[a, b, h, i]: [t^i] of X^a (1 - X^2)^b N_1[h, g]
    table = np.zeros((na, nb, 7, terms), dtype=object)
    sg = 1 - X_POLY * X_POLY
    for h in range(7):
        if n1_shift[h][g] is None:
            continue
        for ai in range(na):
            for bi in range(nb):
                table[ai, bi, h] = shifted(X_POLY ** ai * sg ** bi * n1_shift[h][g], terms)
    out = []
    for i in range(terms):
        small = table[:, :, :, i]
        if not small.any():
            out.append(None)
            continue
        big = max(abs(int(w)) for w in small.ravel()) * int(np.abs(coef).max()) * len(coef)
        if big >= 2**62:  # pragma: no cover - small n
            raise OverflowError(f"level {k}: a product coefficient may not fit in int64")
        vals = coef * small.astype(np.int64)[a, b, hidx]
        dense = sp.coo_matrix((vals, (rows, cols)), shape=shape).toarray()
        out.append(_as_fmpz_mat(dense))
    return out


def _plan_all(n: int) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """For levels k = 2..n: the columns of level k grouped by their factor h(f) (``order``, ``bounds``) and the
    position of f'(f) among the columns of level k - 1 (all columns at every level)."""
    out = []
    for k in range(2, n + 1):
        fp, h = factorization(k)
        order = np.argsort(h, kind="stable")
        bounds = np.searchsorted(h[order], np.arange(8))
        out.append((order, bounds, fp[order]))
    return out


def numerators(n: int, part: str, terms: int | None = None) -> tuple[list, int]:
    """``(coeffs, N)``: the numerator N_n^part (delta_n x delta_n) as N coefficient matrices (``fmpz_mat`` or None
    for zero) in t = X - 1, all columns; N = ``terms`` or, for None, one more than :func:`degree_bound` (then the
    polynomials are complete).  Column f of R_n^part is (2X)^{-E(f)} times column f of the numerator."""
    n = _check_n_limit(n)
    if part not in PARTS:
        raise ValueError(f"part must be one of {list(PARTS)}, got {part!r}")
    full = terms is None
    terms = degree_bound(n, part) + 1 if full else check_int(terms, "terms", 1, 64, why="powers of t = X - 1 kept")
    n1 = order_one_numerators(part)
    n1_shift = [[None if n1[h][g] == 0 else n1[h][g] for g in range(7)] for h in range(7)]
    start = np.zeros((terms, 7, 7), dtype=object)
    for g in range(7):
        for h in range(7):
            start[:, g, h] = shifted(n1[g][h], terms)
    cur = [_as_fmpz_mat(start[i]) for i in range(terms)]
    for k, (order, bounds, pos) in zip(range(2, n + 1), _plan_all(n)):
        fp, h = factorization(k)
        if not (sine_degree(k) == sine_degree(1)[h] + sine_degree(k - 1)[fp]).all():  # pragma: no cover
            raise AssertionError(f"level {k}: the denominators (2X)^E(f) do not multiply")
        arrays = [_as_array(c, (delta(k - 1), delta(k - 1))) for c in cur]
        nxt = [np.zeros((delta(k), delta(k)), dtype=object) for _ in range(terms)]
        for g in range(7):
            lo, hi = bounds[g], bounds[g + 1]
            if hi == lo:
                continue
            q = _combined_numerator(k, n1_shift, g, terms)
            rhs = [None if not arr[:, pos[lo:hi]].any() else _as_fmpz_mat(arr[:, pos[lo:hi]]) for arr in arrays]
            prod = _mat_mul(q, rhs, terms)
            for i, m in enumerate(prod):
                if m is not None:
                    nxt[i][:, order[lo:hi]] = _as_array(m, (delta(k), hi - lo))
        cur = [_as_fmpz_mat(arr) for arr in nxt]
    return cur, terms


def level_forms_equal_proof_code(n: int) -> bool:
    """Whether the integer forms of Theorem P that the check uses, ``_level_terms(k)`` for the levels k = 2..n (the
    fast vectorised build: Lemma 11.5's centre embedding plus the new columns), equal term for term, in the same
    order, the forms of the proofs' dictionary construction
    (:func:`~paper_repro.core.half_angle_rules.product_terms` of order k - 1 for the seven h, merged, concatenated by
    h and sorted stably by (row, col)).  True means the pole check of order n runs on the proof code's forms, so it
    does not rest on the fast build (docs/subdivision_for_all_n.md, section 11, "The pole check"; the arrays are
    integers: the comparison is exact).

    >>> level_forms_equal_proof_code(3)
    True
    """
    n = _check_n_limit(n)
    for k in range(2, n + 1):
        forms = [merge(product_terms(k - 1, h)) for h in range(7)]
        cat = [np.concatenate([f[i] for f in forms]) for i in range(5)]
        hidx = np.concatenate([np.full(len(f[0]), h) for h, f in enumerate(forms)])
        order = np.argsort(cat[0].astype(np.int64) * delta(k - 1) + cat[1], kind="stable")
        ref = tuple(arr[order] for arr in cat) + (hidx[order],)
        got = _level_terms(k)
        if len(got) != len(ref) or not all(np.array_equal(x, y) for x, y in zip(got, ref)):
            return False
    return True


# --- the normalizing coefficients -------------------------------------------------------------------------------------
@cache
def scaled_xi(n: int, half: bool) -> tuple[fmpq_poly, ...]:
    """The scaled normalizing coefficients xi_f (``half=False``: at alpha, kappa = 2X^2 - 1, sigma = 4X^2(1 - X^2)) or
    xi'_g (``half=True``: at alpha/2, kappa' = X, sigma' = 1 - X^2) as polynomials in X (Theorem B's formula,
    :func:`~paper_repro.core.normalizing_formula.scaled_table`, with polynomial arguments)."""
    x = fmpq_poly([0, 1])
    kappa, sigma = (x, 1 - x * x) if half else (2 * x * x - 1, 4 * x * x * (1 - x * x))
    orb = scaled_table(n, kappa, sigma, get_context("exact"))
    out: list = [None] * delta(n)
    for (_, members), value in zip(orbits(n), orb):
        for m in members:
            out[m] = fmpq_poly(value)
    return tuple(out)


def _order(coeffs: list) -> int:
    """Index of the first nonzero coefficient (len(coeffs) if none)."""
    return next((i for i, c in enumerate(coeffs) if c != 0), len(coeffs))


def rows_where_xi_half_vanishes(n: int) -> list[int]:
    """The members g with xi'_g(X = 1) = 0 (the rows where "no pole" is not vacuous)."""
    return [g for g, p in enumerate(scaled_xi(n, True)) if p(1) == 0]


# --- exact matrices at a value of X -----------------------------------------------------------------------------------
#: Largest order the exact routines take: measured CPU (tools/subdivision_pole_check.py) 24 s at n = 13 and 92 s at
#: n = 16, growing about like n^5, so n = 20 is about 5 min; beyond that the integer matrices' conversions dominate.
MAX_N_LIMIT = 20


def _check_n_limit(n: object) -> int:
    return check_int(check_n(n), "n", 1, MAX_N_LIMIT, why="exact polynomial route: about 92 s CPU at n = 16, "
                     "growing like n^5")


def _check_x0(x0: object) -> fmpq:
    """``x0`` as an exact rational in (cos(pi/4), 1): an int, ``Fraction`` or ``fmpq`` (a float is refused: it is
    not the exact value it prints)."""
    from fractions import Fraction

    if isinstance(x0, bool) or not isinstance(x0, (int, Fraction, fmpq)):
        raise TypeError(f"x0 must be an exact rational (int, Fraction or fmpq), got {x0!r} of type "
                        f"{type(x0).__name__}")
    q = fmpq(x0.numerator, x0.denominator) if isinstance(x0, Fraction) else fmpq(x0)
    if not (q > 0 and 2 * q * q > 1 and q < 1):
        raise ValueError(f"x0 = cos(alpha/4) must lie in (cos(pi/4), 1) for alpha in (0, pi), got {x0}")
    return q


def exact_matrices_at(n: int, x0) -> tuple[np.ndarray, ...]:
    """The four S_k (object arrays of ``fmpq``, order of :data:`PARTS`) at X = cos(alpha/4) = ``x0`` (rational, in
    (cos(pi/4), 1)), from the complete numerator polynomials (``terms=None``) and xi, xi' evaluated there."""
    n = _check_n_limit(n)
    x0 = _check_x0(x0)
    t0 = x0 - 1
    d = delta(n)
    xi0 = [p(x0) for p in scaled_xi(n, False)]
    xi1 = [p(x0) for p in scaled_xi(n, True)]
    e = sine_degree(n)
    out = []
    for part in PARTS:
        coeffs, terms = numerators(n, part)
        val = np.zeros((d, d), dtype=object)
        power = fmpq(1)
        for c in coeffs:
            if c is not None:
                val = val + _as_array(c, (d, d)) * power
            power *= t0
        mat = np.empty((d, d), dtype=object)
        for g in range(d):
            for f in range(d):
                mat[g, f] = fmpq(val[g, f]) * xi0[f] / ((2 * x0) ** int(e[f]) * xi1[g])
        out.append(mat)
    return tuple(out)


def even_in_x(n: int) -> dict[str, int]:
    """For each part, the number of entries of S_k whose rational function r(X) is *not* even, r(-X) != r(X)
    (exactly, from the complete numerators).  An even r lies in Q(X^2) = Q(cos(alpha/2)) (X^2 = (1 + cos(alpha/2))/2),
    so all-zero counts prove that S_k has entries in Q(cos(alpha/2)) for this n, for every alpha (docs, section 3,
    "Rationality").  xi_f is a polynomial in X^2 (asserted), so r is even iff
    N(X) (-1)^E(f) xi'_g(-X) = N(-X) xi'_g(X).

    >>> even_in_x(1)
    {'u': 0, 'v': 0, 'w': 0, 'middle': 0}
    """
    n = _check_n_limit(n)
    d = delta(n)
    x = fmpq_poly([0, 1])
    back = fmpz_poly([-1, 1])  # t = X - 1
    if any(p(-x) != p for p in scaled_xi(n, False)):  # pragma: no cover - kappa, sigma are polynomials in X^2
        raise AssertionError("a scaled normalizing coefficient at alpha is not even in X")
    half = scaled_xi(n, True)
    half_minus = [p(-x) for p in half]
    e = sine_degree(n)
    out = {}
    for part in PARTS:
        coeffs, terms = numerators(n, part)
        arr = np.stack([_as_array(c, (d, d)) for c in coeffs])
        bad = 0
        for g in range(d):
            for f in range(d):
                num = fmpq_poly(fmpz_poly([int(v) for v in arr[:, g, f]])(back))
                if num == 0:
                    continue
                sign = -1 if int(e[f]) % 2 else 1
                if num * sign * half_minus[g] != num(-x) * half[g]:
                    bad += 1
        out[part] = bad
    return out


# --- the check at X = 1 -----------------------------------------------------------------------------------------------
@dataclass
class LimitResult:
    """The pole check at X = 1 for one n (all four parts).

    ``max_pole``: the largest pole order at X = 1 over all entries of the four S_k (0: none); ``poles``: per part;
    ``entries``: the number of entries checked (4 delta_n^2); ``nonzero``: per part, the entries whose numerator is
    not divisible by t^N; ``max_ord_xi_half``: max ord_{X-1} xi'_g; ``max_ord_xi``: max ord_{X-1} xi_f;
    ``cancelled``: per part, the nonzero entries of the rows with ord xi'_g >= 1 (where the numerator must vanish at
    X = 1 for the check to pass); ``limits`` (meaningful only when ``max_pole`` is 0): S_k(X = 1) exactly (object
    arrays of ``fmpq``, order of :data:`PARTS`); ``slopes``: r'_{g,f}(1) = dS/dX at X = 1 (S(alpha) = S(0+) -
    r'(1) alpha^2/32 + O(alpha^4)); ``terms``: N; ``seconds``: wall time; ``pole_entries``: per part, the entries
    (g, f) with a pole at X = 1 (empty when ``max_pole`` is 0)."""

    n: int
    max_pole: int
    poles: dict
    entries: int
    nonzero: dict
    max_ord_xi_half: int
    max_ord_xi: int
    cancelled: dict
    limits: tuple = field(repr=False)
    slopes: tuple = field(repr=False)
    terms: int
    seconds: float
    pole_entries: dict = field(default_factory=dict, repr=False)


def limit_check(n: int, terms: int | None = None) -> LimitResult:
    """Decide, for every entry of the four S_k of order n, whether its rational function of X = cos(alpha/4) has a
    pole at X = 1, and compute S_k(1) and dS_k/dX(1) exactly (module docstring).  ``terms``: N (default: the
    smallest that decides, max ord xi'_g + 2)."""
    n = _check_n_limit(n)
    start = time.perf_counter()
    d = delta(n)
    xi1 = scaled_xi(n, True)
    xi0 = scaled_xi(n, False)
    o1 = [_order(shifted(p, p.degree() + 1)) for p in xi1]
    o0 = [_order(shifted(p, p.degree() + 1)) for p in xi0]
    need = max(o1) + 2
    terms = need if terms is None else max(check_int(terms, "terms", 1, 64, why="powers of t = X - 1 kept"), need)
    s1 = [shifted(p, terms) for p in xi1]
    s0 = [shifted(p, terms) for p in xi0]
    e = sine_degree(n)
    poles, nonzero, cancelled, limits, slopes, where = {}, {}, {}, [], [], {}
    for part in PARTS:
        coeffs, _ = numerators(n, part, terms)
        arr = np.stack([_as_array(c, (d, d)) for c in coeffs])  # (terms, d, d) of ints
        nz = arr != 0
        ordr = np.where(nz.any(axis=0), nz.argmax(axis=0), terms)  # ord_t N[g, f] (terms: divisible by t^N)
        deficit = np.array(o1)[:, None] - ordr - np.array(o0)[None, :]
        pole = int(max(0, deficit.max()))
        poles[part] = pole
        where[part] = [(int(g), int(f)) for g, f in zip(*np.nonzero(deficit > 0))]
        nonzero[part] = int((ordr < terms).sum())
        cancelled[part] = int(((ordr < terms) & (np.array(o1)[:, None] >= 1)).sum())
        lim = np.full((d, d), fmpq(0), dtype=object)  # the entries divisible by t^N: 0 and slope 0
        slope = np.full((d, d), fmpq(0), dtype=object)
        for g, f in zip(*np.nonzero(ordr < terms)):
            o, ee = o1[g], int(e[f])
            a_co = [sum((arr[i, g, f] * s0[f][k - i] for i in range(k + 1)), fmpq(0)) for k in (o, o + 1)]
            # B = (2 + 2t)^E xi'_g: [t^o] and [t^(o+1)]; xi'_g has no coefficient below t^o
            two = 2 ** ee
            b_co = [two * s1[g][o], two * (ee * s1[g][o] + s1[g][o + 1])]
            lim[g, f] = a_co[0] / b_co[0]
            slope[g, f] = (a_co[1] * b_co[0] - a_co[0] * b_co[1]) / (b_co[0] * b_co[0])
        limits.append(lim)
        slopes.append(slope)
    return LimitResult(n=n, max_pole=max(poles.values()), poles=poles, entries=4 * d * d, nonzero=nonzero,
                       max_ord_xi_half=max(o1), max_ord_xi=max(o0), cancelled=cancelled, limits=tuple(limits),
                       slopes=tuple(slopes), terms=terms, seconds=time.perf_counter() - start,
                       pole_entries=where)


__all__ = ["limit_check", "level_forms_equal_proof_code", "LimitResult", "numerators", "order_one_numerators",
           "exact_matrices_at", "scaled_xi",
           "shifted", "sine_degree", "degree_bound", "rows_where_xi_half_vanishes", "even_in_x"]
