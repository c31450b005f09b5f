"""Midpoint subdivision in float64 without a solve: restriction is a ring homomorphism (docs/subdivision_for_all_n.md,
section 11).

Notation of docs/elevation_and_derivative_for_all_n.md: ``m_f = f / s^{2n+j(f)}`` the scaled members of T_{2n}^alpha
(eq. united_system), ``x_f`` their scaled normalizing coefficients (T-bar_f = x_f m_f, eq. normalized_united_system),
``kappa' = cos(alpha/4)``, ``sigma' = sin^2(alpha/4)`` the half-angle values of the parameter alpha/2 of the
sub-patches, and ``x_k`` the map of Omega^{alpha/2} onto the sub-triangle ``k`` (:mod:`paper_repro.core.subdivision`).

The route, for every n (proof: docs/subdivision_for_all_n.md, section 11):

1. *Order one.*  ``m_h o x_k = sum_g R_1^k[g, h] m'_g`` for the seven members h of T_2, by substituting
   ``sin(u/2) = s'(kappa' S'_u + C'_u)`` (translation) or ``s'(C'_u - kappa' S'_u)`` (point reflection) and the
   cosines likewise, and re-expressing each monomial ``S'^a C'^b ...`` with the cotangent rules
   (:func:`~paper_repro.core.half_angle_rules.cotangent`, proven for every n) -- a 7 x 7 matrix.
2. *Products.*  Every member of T_{2n} is a member of T_{2n-2} times a member of T_2 (:func:`factorization`), and
   restriction to a sub-triangle is multiplicative: ``(m_f' m_h) o x_k = (m_f' o x_k)(m_h o x_k)``.  The product of
   a member of T_{2n-2} with a member of T_2 is written in T_{2n} by Theorem P of
   docs/elevation_and_derivative_for_all_n.md (:func:`~paper_repro.core.half_angle_rules.product_column`, every
   coefficient a polynomial in kappa', sigma' with non-negative integer coefficients; here vectorised,
   :func:`product_terms_fast`).  So R_n^k[:, f] = sum_h R_1^k[h, h(f)] P_h R_{n-1}^k[:, f'(f)], level by level.
3. *Normalization.*  ``S_k[g, f] = R_n^k[g, f] x_f / x'_g``.

Speed (section 11, Lemmas 11.4 and 11.5): only one column per orbit of the exchanges of variables commuting with the
part's map is computed at the last level (``R[pi g, pi f] = R[g, f]``, :func:`symmetry_permutations`; v <-> w for
the corners, all six for the middle), and at each lower level only the factors those columns need (:func:`_plan`);
the other columns and the corners v, w are written from them (:func:`assemble`).  The integer forms of order n are
those of order n - 1 embedded by the centre S_u S_v S_w (:func:`centre_embedding`) plus the 6n new columns; the
terms of a level stay sorted through the embedding (it is increasing) and the new columns' terms are merged in by
position (:func:`_level_build`), so no level is sorted whole.

Float results are the same bits wherever numpy's and scipy's loops do unfused IEEE double operations (x86-64; tested
with numpy's SIMD dispatch limited below AVX512, tests/test_subdivision_bits.py): kappa', sigma' from flint ``arb``,
every power by repeated multiplication (:func:`power_table`; never numpy's ``power``, which dispatches to SVML under
AVX512, nor libm's ``pow``), fixed-order sums (no BLAS: scipy's sparse products sum each row in the order of its
entries).  An aarch64 build that contracts a*b + c into FMA in scipy's ``csr_matvecs`` is an unverified risk.

No step subtracts except inside the 7 x 7 matrix R_1 and the signed sums of the level recursion (R_1 has negative
entries), so float64 keeps about 15 digits for every n and alpha measured (reports/subdivision_accuracy.md); the
entrywise error estimate of :func:`subdivision_matrices_float` (``bound=True``; first order, a heuristic
a-posteriori estimate, not a certificate) is computed from the same recursion in absolute values.

>>> import numpy as np
>>> s = subdivision_matrices_float(2, 1.0)
>>> len(s), s[3].shape, bool(max(abs(m.sum(axis=1) - 1).max() for m in s) < 1e-14)
(4, (19, 19), True)
"""

from __future__ import annotations

import itertools
import math
from functools import cache, lru_cache

import numpy as np
import scipy.sparse as sp

from paper_repro.core.context import FloatContext
from paper_repro.core.context import power_table as context_power_table
from paper_repro.core.half_angle_matrices import _float_half_angle, scaled_coefficients
from paper_repro.core.half_angle_rules import (
    _gather,
    _rule_a_pattern,
    cotangent,
    merge,
    order_one_parts,
)
from paper_repro.core.labels import delta_unchecked, exponent_matrix
from paper_repro.core.ordered import ordered_matmul

#: The four sub-triangles (as :data:`paper_repro.core.subdivision.PARTS`).
PARTS = ("u", "v", "w", "middle")
#: Below this alpha the float route computes at ALPHA_TINY: the scaled coefficients of size sigma would underflow
#: (0/0 in x_f / x'_g).  Measured S(alpha) - S(ALPHA_TINY) ~ alpha^2/32 (n = 2, 6, 10); S even and analytic at 0,
#: S(alpha) = S(0+) - dS/dX(1) alpha^2/32 + O(alpha^4) with max |dS/dX(1)| = 1, X = cos(alpha/4) (proven for
#: n <= 16 by the exact pole check of :mod:`paper_repro.theory.subdivision_limit`, docs/subdivision_for_all_n.md
#: section 11; evidence beyond): the difference below ALPHA_TINY is at most about 3e-202.
ALPHA_TINY = 1e-100
#: Roundings along any path of the order-one computation (:func:`order_one_restriction`; derived in
#: docs/subdivision_for_all_n.md section 11, "Error estimate"), each occurrence of the correctly rounded inputs kappa',
#: sigma' counted as one: an entry of L_x at most 4, a binomial coefficient at most 4, a Horner start 5 and a Horner
#: step 12 over its input, so at most 29 per variable; three variables (the middle) 87; the prefactor
#: 1/(2 kappa')^e (e <= 3: the input, two products, a quotient) 6.
ORDER_ONE_ROUNDINGS = 3 * 29 + 6
_F = FloatContext()


# --- the member names, vectorised ---------------------------------------------------------------------------------
@cache
def member_table_fast(n: int) -> np.ndarray:
    """:func:`~paper_repro.core.half_angle_rules.member_table` (``K[X, Y, m, j]``, the index of ``M_X(m; Y, j)``,
    -1 where X = Y or j > m) by a sorted-key lookup instead of a dictionary (tested equal)."""
    e = exponent_matrix(n).astype(np.int64)
    weights = 64 ** np.arange(6, dtype=np.int64)
    keys = e @ weights
    order = np.argsort(keys)
    x, y, m, j = np.meshgrid(np.arange(3), np.arange(3), np.arange(n + 1), np.arange(n + 1), indexing="ij")
    valid = (x != y) & (j <= m)
    z = 3 - x - y
    vec = np.zeros(x.shape + (6,), dtype=np.int64)
    for v in range(3):
        vec[..., 2 * v] = np.where(x == v, 2 * n - m, 0) + np.where(y == v, j, 0) + np.where(z == v, m, 0)
        vec[..., 2 * v + 1] = np.where(y == v, m - j, 0)
    want = vec @ weights
    loc = np.clip(np.searchsorted(keys[order], want), 0, len(keys) - 1)
    found = order[loc]
    if not (keys[found] == want)[valid].all():  # pragma: no cover - every name is a member
        raise AssertionError(f"a name M_X(m; Y, j) of order {n} is not a member")
    table = np.where(valid, found, -1)
    table.setflags(write=False)
    return table


@cache
def member_parts_fast(n: int) -> np.ndarray:
    """:func:`~paper_repro.core.half_angle_rules.member_parts` (``(X, m, Y, j)`` of each member: of its names, the
    one with the smallest (m, j, X, Y)) without the Python loops (tested equal)."""
    table = member_table_fast(n)
    x, y, m, j = np.meshgrid(np.arange(3), np.arange(3), np.arange(n + 1), np.arange(n + 1), indexing="ij")
    ok = table >= 0
    member, x, y, m, j = table[ok], x[ok], y[ok], m[ok], j[ok]
    order = np.lexsort((y, x, j, m, member))
    first = order[np.r_[True, member[order][1:] != member[order][:-1]]]
    out = np.empty((delta_unchecked(n), 4), dtype=np.int64)
    out[member[first]] = np.stack([x[first], m[first], y[first], j[first]], axis=1)
    out.setflags(write=False)
    return out


# --- the cotangent rules, vectorised over the members -----------------------------------------------------------
@cache
def cotangent_csc_fast(n: int, var: int) -> tuple[np.ndarray, ...]:
    """``L_var`` on every member of T_{2n} as compressed columns ``(indptr, target, a, b, coef)``: the terms of
    :func:`~paper_repro.core.half_angle_rules.cotangent` (rules (A), (A_n), (B) and the cosine variable of
    docs/elevation_and_derivative_for_all_n.md), built for all members at once (one group per (ring, level) of
    rule (A)) instead of one call per member; within a column the terms may come in another order (tested equal
    as sets to ``_cotangent_csc``).  Empty columns for the members without a factor S_var.

    >>> from paper_repro.core.half_angle_rules import _cotangent_csc
    >>> fast, slow = cotangent_csc_fast(3, 1), _cotangent_csc(3, 1)
    >>> bool(np.array_equal(fast[0], slow[0]))
    True
    """
    table = member_table_fast(n)
    parts = member_parts_fast(n)
    e = exponent_matrix(n)
    g = np.flatnonzero(e[:, 2 * var] > 0)
    x, m, y, j = (parts[g, k] for k in range(4))
    z = 3 - x - y
    direct: list[tuple[np.ndarray, ...]] = []  # (col, target, a, b)
    calls: list[tuple[np.ndarray, ...]] = []  # rule (A) calls (col, X, m, Y, j, a shift)

    def add_direct(sel, target, a, b):
        direct.append((g[sel], target, np.full(int(sel.sum()), a), np.full(int(sel.sum()), b)))

    cosv = e[g, 2 * var + 1] > 0
    add_direct(cosv, table[x[cosv], y[cosv], m[cosv], j[cosv] - 1], 0, 0)
    rest = ~cosv
    # rule (A_n): level n, X := var, Y := y (or x if var is y), Z the third
    an = rest & (m == n)
    ax = np.full_like(x, var)
    ay = np.where(y != var, y, x)
    az = 3 - ax - ay
    sel = an & (j == n)
    add_direct(sel, table[ay[sel], ax[sel], n, n - 1], 0, 0)
    sel = an & (j < n)
    add_direct(sel, table[ax[sel], ay[sel], n, j[sel] + 1], 0, 1)
    add_direct(sel, table[az[sel], ay[sel], n - 1, j[sel]], 0, 1)
    calls.append((g[sel], az[sel], np.full(int(sel.sum()), n - 1), ay[sel], j[sel], np.ones(int(sel.sum()), int)))
    # rule (A): var is the part X, m < n
    sel = rest & (m < n) & (var == x)
    calls.append((g[sel], x[sel], m[sel], y[sel], j[sel], np.zeros(int(sel.sum()), int)))
    # rule (B): var is Z (or Y with j = m, Y and Z exchanged), 1 <= m < n
    sel = rest & (m < n) & (var != x)
    bx, bm, bj = x[sel], m[sel], j[sel]
    by = np.where(var == z[sel], y[sel], z[sel])
    bz = 3 - bx - by
    eq = bj == bm
    direct.append((g[sel][eq], table[bx[eq], bz[eq], bm[eq], bm[eq] - 1], np.zeros(int(eq.sum()), int),
                   np.zeros(int(eq.sum()), int)))
    ne = ~eq
    for target in (table[bx[ne], by[ne], bm[ne], bj[ne] + 1], table[bx[ne], by[ne], bm[ne] - 1, bj[ne]]):
        direct.append((g[sel][ne], target, np.zeros(int(ne.sum()), int), np.ones(int(ne.sum()), int)))
    calls.append((g[sel][ne], bx[ne], bm[ne] - 1, by[ne], bj[ne], np.ones(int(ne.sum()), int)))
    # the rule (A) calls, all at once: the patterns of rule (A) for every (m, j), padded to one length
    col, cx, cm, cy, cj, shift = (np.concatenate([c[k] for c in calls]) for k in range(6))
    out = [tuple(d) for d in direct]
    pa, pb, part, pm, pl, ok = _padded_rule_a(n)
    pid = cm * (n + 1) + cj
    ys = np.stack([cy, 3 - cx - cy], axis=1)  # (calls, 2): Y, Z
    sel_part = part[pid]  # (calls, L)
    ysel = np.take_along_axis(ys, sel_part, axis=1)
    target = table[cx[:, None], ysel, pm[pid], pl[pid]]
    mask = ok[pid]
    out.append((np.broadcast_to(col[:, None], mask.shape)[mask], target[mask],
                (pa[pid] + shift[:, None])[mask], pb[pid][mask]))
    cols, targets, a, b = (np.concatenate([o[k] for o in out]) for k in range(4))
    order = np.argsort(cols, kind="stable")
    indptr = np.zeros(delta_unchecked(n) + 1, dtype=np.int64)
    indptr[1:] = np.bincount(cols, minlength=delta_unchecked(n))
    res = (np.cumsum(indptr), targets[order], a[order], b[order], np.ones(len(order), dtype=np.int64))
    for arr in res:
        arr.setflags(write=False)
    return res


@cache
def _padded_rule_a(n: int) -> tuple[np.ndarray, ...]:
    """The patterns of rule (A) (:func:`~paper_repro.core.half_angle_rules._rule_a_pattern`) for every
    0 <= j <= m < n as ``((n + 1)^2, L)`` arrays ``(a, b, part, m', l, valid)`` indexed by m (n + 1) + j."""
    pats = {(m, j): _rule_a_pattern(m, j) for m in range(n) for j in range(m + 1)}
    width = max((len(p[0]) for p in pats.values()), default=1)
    out = [np.zeros(((n + 1) ** 2, width), dtype=np.int64) for _ in range(5)]
    ok = np.zeros(((n + 1) ** 2, width), dtype=bool)
    for (m, j), p in pats.items():
        row = m * (n + 1) + j
        for k in range(5):
            out[k][row, :len(p[k])] = p[k]
        ok[row, :len(p[0])] = True
    res = tuple(out) + (ok,)
    for arr in res:
        arr.setflags(write=False)
    return res


# --- step 2: the products with the members of T_2, vectorised ------------------------------------------------------
def _apply_cotangent_terms(big: int, var: np.ndarray, terms: tuple[np.ndarray, ...], steps: np.ndarray
                           ) -> tuple[np.ndarray, ...]:
    """Apply ``L_var`` ``steps[t]`` times to each term ``(col, target, a, b, coef)`` (``var`` per term).  The terms
    come out in some order, equal terms not yet added: the caller merges (integer sums, exact in any order)."""
    op = _cotangent_all(big)
    d = delta_unchecked(big)
    col, target, a, b, coef = terms
    done = [tuple(arr[steps == 0] for arr in terms)]
    col, target, a, b, coef, var, steps = (arr[steps > 0] for arr in (col, target, a, b, coef, var, steps))
    while len(col):
        pos, target, aa, bb, cc = _gather(op, var * d + target)  # L_var of each term's member, all variables at once
        col, a, b, coef, var, steps = col[pos], a[pos] + aa, b[pos] + bb, coef[pos] * cc, var[pos], steps[pos] - 1
        fin = steps == 0
        done.append((col[fin], target[fin], a[fin], b[fin], coef[fin]))
        col, target, a, b, coef, var, steps = (arr[~fin] for arr in (col, target, a, b, coef, var, steps))
        if len(col):  # add the terms equal in (col, target, a, b) (var and steps are functions of col): exact
            key = ((col * (int(target.max()) + 1) + target) * (int(a.max()) + 1) + a) * (int(b.max()) + 1) + b
            order = np.argsort(key, kind="stable")  # the keys come in long sorted runs
            key = key[order]
            start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
            first = order[start]
            coef = np.add.reduceat(coef[order], start)
            col, target, a, b, var, steps = (arr[first] for arr in (col, target, a, b, var, steps))
    return tuple(np.concatenate([d[k] for d in done]) for k in range(5))


@cache
def _cotangent_all(n: int) -> tuple[np.ndarray, ...]:
    """The three :func:`cotangent_csc_fast` ``(n, var)`` side by side: column ``var delta_n + g`` is ``L_var`` of
    the member g."""
    ops = [cotangent_csc_fast(n, v) for v in range(3)]
    nnz = np.cumsum([0] + [len(op[1]) for op in ops])
    indptr = np.concatenate([op[0][:-1] + nnz[v] for v, op in enumerate(ops)] + [nnz[-1:]])
    out = (indptr,) + tuple(np.concatenate([op[k] for op in ops]) for k in range(1, 5))
    for arr in out:
        arr.setflags(write=False)
    return out


@cache
def product_terms_fast(n: int, h: int) -> tuple[np.ndarray, ...]:
    """The terms ``(rows, cols, a, b, coef)`` of :func:`~paper_repro.core.half_angle_rules.product_terms` (the
    product of each member of T_{2n} with the member ``h`` of T_2, written in T_{2(n+1)}: Theorem P of
    docs/elevation_and_derivative_for_all_n.md), merged and sorted as
    :func:`~paper_repro.core.half_angle_rules.merge` (:func:`_product_terms_unsorted` sorted).  ``n`` must be
    checked by the caller.

    >>> from paper_repro.core.half_angle_rules import product_terms
    >>> all(np.array_equal(x, y) for x, y in zip(product_terms_fast(3, 5), merge(product_terms(3, 5))))
    True
    """
    rows, cols, a, b, coef = _product_terms_unsorted(n, h)
    order = np.lexsort((b, a, cols, rows))
    out = tuple(arr[order] for arr in (rows, cols, a, b, coef))
    for arr in out:
        arr.setflags(write=False)
    return out


@cache
def centre_embedding(n: int) -> np.ndarray:
    """For n >= 1 the index in T_{2n} of ``S_u S_v S_w m_f`` for each member f of T_{2n-2} (``M_X(m; Y, j)`` times the
    centre is ``M_X(m + 1; Y, j + 1)``, a member); its image is the members with j >= 1.

    >>> e = exponent_matrix(3)[centre_embedding(3)] - exponent_matrix(2)
    >>> bool((e == [1, 0, 1, 0, 1, 0]).all())
    True
    """
    if n == 1:
        out = np.array([int(np.flatnonzero((exponent_matrix(1) == [1, 0, 1, 0, 1, 0]).all(axis=1))[0])])
    else:
        x, m, y, j = (member_parts_fast(n - 1)[:, k] for k in range(4))
        out = member_table_fast(n)[x, y, m + 1, j + 1]
    out.setflags(write=False)
    return out


@cache
def _outer_columns(n: int) -> list[tuple[np.ndarray, ...]]:
    """:func:`_product_columns` of the 6n members with j = 0 (not a multiple of the centre; n = 1: all seven)."""
    f = np.arange(delta_unchecked(1)) if n == 1 else np.flatnonzero(member_parts_fast(n)[:, 3] == 0)
    return _product_columns_all(n, f)


@cache
def _product_terms_unsorted(n: int, h: int) -> tuple[np.ndarray, ...]:
    """:func:`product_terms_fast` unsorted (merged: no two terms with the same (row, col, a, b)).  For n >= 2 the
    columns of the members ``S_u S_v S_w m_g`` (g in T_{2n-2}, :func:`centre_embedding`) are those of order n - 1
    with rows and columns embedded: ``(S_u S_v S_w m_g) m_h = S_u S_v S_w sum_i P[i, g] m_i = sum_i P[i, g]
    m_{centre i}`` (the same coefficient polynomials); only the 6n other columns (j = 0) are built by
    :func:`_product_columns`."""
    if n == 1:
        return _outer_columns(1)[h]
    rows, cols, a, b, coef = _product_terms_unsorted(n - 1, h)
    new = _outer_columns(n)[h]
    up_rows, up_cols = centre_embedding(n + 1), centre_embedding(n)
    out = (np.concatenate([up_rows[rows], new[0]]), np.concatenate([up_cols[cols], new[1]]),
           np.concatenate([a, new[2]]), np.concatenate([b, new[3]]), np.concatenate([coef, new[4]]))
    for arr in out:
        arr.setflags(write=False)
    return out


def _product_columns(n: int, h: int, f: np.ndarray) -> tuple[np.ndarray, ...]:
    """The terms of :func:`~paper_repro.core.half_angle_rules.product_terms` (Theorem P of
    docs/elevation_and_derivative_for_all_n.md) of the columns ``f`` (members of T_{2n}) only, built with numpy
    instead of one dictionary per column; merged (:func:`~paper_repro.core.half_angle_rules.merge`)."""
    return _product_columns_all(n, f)[h]


def _product_columns_all(n: int, f: np.ndarray) -> list[tuple[np.ndarray, ...]]:
    """:func:`_product_columns` for the seven h at once (one pass of the cotangent powers for all of them: the
    column index carries h, ``h delta_n + f``)."""
    d = delta_unchecked(n)
    direct, pending = [], []
    for h in range(7):
        done, pend = _product_seed(n, h, f)
        direct += [(t[0] + h * d,) + t[1:] for t in done]
        if pend is not None:
            terms, var, steps = pend
            pending.append(((terms[0] + h * d,) + terms[1:], var, steps))
    if pending:
        terms = tuple(np.concatenate([p[0][k] for p in pending]) for k in range(5))
        var, steps = (np.concatenate([p[k] for p in pending]) for k in (1, 2))
        direct.append(_apply_cotangent_terms(n + 1, var, terms, steps))
    rows, cols, a, b, coef = _merged(tuple(np.concatenate([t[k] for t in direct]) for k in range(5)))
    which = cols // d
    out = []
    for h in range(7):
        sel = which == h
        part = (rows[sel], cols[sel] - h * d, a[sel], b[sel], coef[sel])
        for arr in part:
            arr.setflags(write=False)
        out.append(part)
    return out


def _product_seed(n: int, h: int, f: np.ndarray) -> tuple[list, tuple | None]:
    """The terms of the columns ``f`` of the product with h that need no cotangent power, and the terms
    ``((col, target, a, b, coef), var, steps)`` still to be raised by ``L_var^steps`` (Theorem P's cases)."""
    big = n + 1
    table = member_table_fast(big)
    parts = member_parts_fast(n)
    x, m, y, j = (parts[f, k] for k in range(4))
    z = 3 - x - y
    one = np.ones_like(f)
    zero = np.zeros_like(f)
    kind, var = order_one_parts()[h]
    if kind in ("centre", "edge"):
        centre = table[x, y, m + 1, j + 1]
        terms = (f, centre, zero, zero, one)
        if kind == "edge":
            return [], (terms, np.full_like(f, var), one)
        return [terms], None
    out = []
    case1 = (var == x) | ((m == n) & (var == z))
    sel = case1
    out.append((f[sel], table[var, y[sel], m[sel], j[sel]], zero[sel], zero[sel], one[sel]))
    case2 = ~case1 & ((var == z) | (j == m))
    cos = np.where(var == z, y, z)
    jj = np.where(var == z, j, m)
    sel = case2 & (m == n)
    out.append((f[sel], table[var, cos[sel], n, jj[sel]], zero[sel], zero[sel], one[sel]))
    sel = case2 & (m < n)
    out.append((f[sel], table[x[sel], cos[sel], m[sel] + 2, jj[sel] + 2], zero[sel], one[sel], one[sel]))
    out.append((f[sel], table[x[sel], cos[sel], m[sel] + 2, jj[sel]], zero[sel], zero[sel], one[sel]))
    case3 = ~case1 & ~case2  # S_Y^2 m_f with j < m: L_Y^(m - j) of p
    sel = case3 & (m < n)
    p = [(f[sel], table[x[sel], z[sel], m[sel] + 2, m[sel] + 2], zero[sel], one[sel], one[sel]),
         (f[sel], table[x[sel], z[sel], m[sel] + 2, m[sel]], zero[sel], zero[sel], one[sel])]
    sel = case3 & (m == n)
    p.append((f[sel], table[y[sel], x[sel], n, n], zero[sel], zero[sel], one[sel]))
    pt = tuple(np.concatenate([q[k] for q in p]) for k in range(5))
    steps = (parts[:, 1] - parts[:, 3])[pt[0]]
    return out, (pt, parts[pt[0], 2], steps)


def _merged(terms: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    """Terms ``(col, target, a, b, coef)`` as the merged form ``(rows, cols, a, b, coef)``."""
    col, target, a, b, coef = terms
    out = merge((target, col, a, b, coef))
    for arr in out:
        arr.setflags(write=False)
    return out


@cache
def factorization(n: int) -> tuple[np.ndarray, np.ndarray]:
    """``(f', h)`` for every member f of T_{2n}, n >= 2: the scaled member m_f is the product of the member f' of
    T_{2n-2} and the member h of T_2 (exponent vectors add).  With the parts ``M_X(m; Y, j)`` of m_f: the centre
    ``S_X S_Y S_Z`` times ``M_X(m - 1; Y, j - 1)`` if j >= 1; the edge ``S_X C_Y S_Z`` times ``M_X(m - 1; Y, j)`` if
    j = 0 < m; the corner ``S_X^2`` times ``M_X(0; Y, 0) = S_X^(2n - 2)`` if m = 0.

    >>> fp, h = factorization(2)
    >>> bool((exponent_matrix(2) == exponent_matrix(1)[fp] + exponent_matrix(1)[h]).all())
    True
    """
    x, m, y, j = (member_parts_fast(n)[:, k] for k in range(4))
    small = member_table_fast(n - 1)
    kinds = order_one_parts()
    centre = kinds.index(("centre", -1))
    edge = np.array([kinds.index(("edge", v)) for v in range(3)])
    corner = np.array([kinds.index(("corner", v)) for v in range(3)])
    fp = np.where(j >= 1, small[x, y, np.maximum(m - 1, 0), np.maximum(j - 1, 0)],
                  np.where(m >= 1, small[x, y, np.maximum(m - 1, 0), 0], small[x, y, 0, 0]))
    h = np.where(j >= 1, centre, np.where(m >= 1, edge[y], corner[x]))
    if not (exponent_matrix(n) == exponent_matrix(n - 1)[fp] + exponent_matrix(1)[h]).all():  # pragma: no cover
        raise AssertionError(f"the factorization of T_{2 * n} failed")
    fp.setflags(write=False)
    h.setflags(write=False)
    return fp, h


# --- step 1: order one by substitution and the cotangent rules ------------------------------------------------------
def _power(x: float, k: int) -> float:
    """``x^k`` (k >= 0) by k - 1 multiplications from the left, ``((x x) x) ...``: no ``pow`` (libm's is only
    faithfully rounded and may differ between builds), so the same bits wherever IEEE double arithmetic is used.

    >>> _power(0.1, 3) == (0.1 * 0.1) * 0.1, _power(0.7, 0)
    (True, 1.0)
    """
    out = 1.0
    for _ in range(k):
        out = out * x
    return out


def power_table(x: float, k: int) -> np.ndarray:
    """``[x^0, x^1, ..., x^k]`` as float64, each by one multiplication from the previous (:func:`_power`'s values):
    not numpy's ``power``, whose SIMD loops (SVML under AVX512) are not correctly rounded and differ with the CPU
    features numpy dispatches to (docs/subdivision_for_all_n.md, section 11, the referee's point 2).

    >>> t = power_table(0.3, 4)
    >>> [float(v) == _power(0.3, i) for i, v in enumerate(t)]
    [True, True, True, True, True]
    """
    return context_power_table(np.float64(x), k, _F)  # the contexts' table: one ctx.mul per power, in order


def _cotangent_dense(var: int, kp: float, sg: float) -> np.ndarray:
    """L_var on T_2 as a dense 7 x 7 float matrix at (kappa', sigma') (zero columns where m_g has no S_var)."""
    out = np.zeros((7, 7))
    e = exponent_matrix(1)
    for g in range(7):
        if e[g, 2 * var]:
            for a, b, c, t in cotangent(1, var, g).tolist():
                out[t, g] += c * _power(kp, a) * _power(sg, b)
    return out


def _binomial_factor(s: int, c: int, sin_image: tuple[float, float], cos_image: tuple[float, float]) -> np.ndarray:
    """Coefficients of C^t (t = 0..s + c) in ``(p S + q C)^s (r S + w C)^c`` with ``sin_image = (p, q)``,
    ``cos_image = (r, w)`` (then S^(s+c-t) C^t is L^t of S^(s+c))."""
    out = [1.0]
    for lo, hi in [sin_image] * s + [cos_image] * c:  # multiply by (lo + hi C), in a fixed order (no BLAS)
        out = [lo * out[0]] + [lo * out[t] + hi * out[t - 1] for t in range(1, len(out))] + [hi * out[-1]]
    return np.array(out)


def order_one_restriction(part: str, kp: float, sg: float, *, absolute: bool = False) -> np.ndarray:
    """R_1 (7 x 7): ``m_h o x_part = sum_g R_1[g, h] m'_g`` for the scaled members of T_2 at alpha (left) and
    alpha/2 (right), ``kp, sg = cos(alpha/4), sin^2(alpha/4)``.  With s = sin(alpha/2) = 2 s' kappa':

    * translation in the variable x (part 'u', 'v', 'w'): S_x -> (kappa' S'_x + C'_x)/(2 kappa'),
      C_x -> kappa' C'_x - sigma' S'_x, the other two S_y -> S'_y/(2 kappa'), C_y -> C'_y;
    * point reflection ('middle'): every S_x -> (C'_x - kappa' S'_x)/(2 kappa'), C_x -> kappa' C'_x + sigma' S'_x;

    and each monomial S'^(e - t) C'^t (times the rest) is L^t of the member with S'^e (the cotangent rules;
    a function divisible by S'_x has no member without S'_x in its expansion, so L applies term by term).
    ``absolute``: the same computation with the images' coefficients replaced by their absolute values (every
    other quantity is already non-negative), the majorant of the error estimate.
    """
    e = exponent_matrix(1)
    index = {tuple(int(v) for v in row): k for k, row in enumerate(e)}
    lops = [_cotangent_dense(v, kp, sg) for v in range(3)]
    variables = (0, 1, 2) if part == "middle" else ("uvw".index(part),)
    if part == "middle":
        sin_image, cos_image = (-kp, 1.0), (sg, kp)
    else:
        sin_image, cos_image = (kp, 1.0), (-sg, kp)
    if absolute:
        sin_image, cos_image = (abs(sin_image[0]), 1.0), (abs(cos_image[0]), kp)
    out = np.zeros((7, 7))
    for h in range(7):
        base = e[h].copy()
        for v in variables:
            base[2 * v] += base[2 * v + 1]
            base[2 * v + 1] = 0
        vec = np.zeros(7)
        vec[index[tuple(int(t) for t in base)]] = 1.0
        for v in variables:
            poly = _binomial_factor(int(e[h, 2 * v]), int(e[h, 2 * v + 1]), sin_image, cos_image)
            acc = poly[-1] * vec  # Horner in L_v
            for t in range(len(poly) - 2, -1, -1):
                acc = ordered_matmul(lops[v], acc[:, None])[:, 0] + poly[t] * vec
            vec = acc
        out[:, h] = vec / _power(2.0 * kp, int(e[h, 0] + e[h, 2] + e[h, 4]))
    return out


# --- the recursion --------------------------------------------------------------------------------------------------
def _level_terms(k: int) -> tuple[np.ndarray, ...]:
    """The seven product forms of order k - 1 (:func:`product_terms_fast`) concatenated: ``(rows, cols, a, b, coef,
    h)``, sorted by (rows, cols, h, a, b): :func:`_level_build`."""
    return _level_build(k)[0]


@cache
def _level_build(k: int) -> tuple[tuple[np.ndarray, ...], np.ndarray]:
    """:func:`_level_terms` and the key ``rows delta_{k-1} + cols`` of each term.  Built level by level (Lemma 8
    of docs/subdivision_for_all_n.md, section 11): the terms of level k - 1 with rows and columns embedded by the
    centre (:func:`centre_embedding`, increasing, so their order is kept) merged with the terms of the 6(k - 1) new
    columns (:func:`_outer_columns`; their (row, col) are none of the embedded ones) -- no sort of the whole level.
    The same arrays as the seven :func:`_product_terms_unsorted` concatenated and sorted stably by (rows, cols)
    (tested equal, ``tests/test_subdivision_speed.py``)."""
    new = _outer_columns(k - 1)
    width = delta_unchecked(k - 1)
    kdt = np.int32 if delta_unchecked(k) * width < 2**31 else np.int64
    idt = np.int32 if delta_unchecked(k) < 2**31 else np.int64
    # compact integer types (the values are those of the forms: rows, cols < delta_k; a, b <= 2k; h < 7)
    dtypes = (idt, idt, np.int16, np.int16, np.int64, np.int16, kdt)
    cat = [np.concatenate([f[i] for f in new]) for i in range(5)]
    if max(int(cat[2].max()), int(cat[3].max())) >= 2**15:  # pragma: no cover - a, b <= 2k
        raise OverflowError("exponents of kappa', sigma' beyond int16")
    hidx = np.concatenate([np.full(len(f[0]), h, dtype=np.int64) for h, f in enumerate(new)])
    key = cat[0] * width + cat[1]
    order = np.argsort(key, kind="stable")  # by (row, column), then h, then (a, b) (each form is sorted)
    fresh = [arr[order].astype(dt) for arr, dt in zip(cat + [hidx, key], dtypes)]
    if k == 2:
        out = fresh
    else:
        prev, prev_key = _level_build(k - 1)
        rows, cols = _centre_index(k, idt)[prev[0]], _centre_index(k - 1, idt)[prev[1]]
        old = [rows, cols] + list(prev[2:]) + [rows.astype(kdt) * width + cols]
        n_old, n_new = len(rows), len(order)
        ins = np.searchsorted(old[-1], fresh[-1])  # the new terms go before these old ones
        at = ins + np.arange(n_new)
        free = np.ones(n_old + n_new, dtype=bool)
        free[at] = False
        old_at = np.flatnonzero(free)
        out = []
        for o, f, dt in zip(old, fresh, dtypes):
            arr = np.empty(n_old + n_new, dtype=dt)
            arr[old_at] = o
            arr[at] = f
            out.append(arr)
    for arr in out:
        arr.setflags(write=False)
    return tuple(out[:6]), out[6]


@cache
def _centre_index(n: int, dtype: type) -> np.ndarray:
    """:func:`centre_embedding` as ``dtype`` (the compact index type of :func:`_level_build`)."""
    out = centre_embedding(n).astype(dtype)
    out.setflags(write=False)
    return out


@cache
def _pattern(k: int, used: tuple[int, ...]) -> tuple[np.ndarray, ...]:
    """For the members h in ``used``: the positions of their terms in :func:`_level_terms`, the start of each
    (row, col) run among them, the CSR ``indptr``, ``indices`` of the distinct (row, col) and the h of each term."""
    (rows, cols, _, _, _, hidx), key = _level_build(k)
    keep = np.zeros(7, dtype=bool)
    keep[list(used)] = True
    pos = np.arange(len(hidx)) if keep.all() else np.flatnonzero(keep[hidx])
    key = key[pos]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    first = pos[starts]
    indptr = np.searchsorted(rows[first], np.arange(delta_unchecked(k) + 1)).astype(np.int32)
    out = (pos, starts, indptr, cols[first].astype(np.int32), hidx[pos])
    for arr in out:
        arr.setflags(write=False)
    return out


def _level_values(k: int, kp: float, sg: float, absolute: bool) -> np.ndarray:
    """The value of every term of :func:`_level_terms` at (kappa', sigma'): coef kappa'^a sigma'^b (coef >= 0)."""
    _, _, a, b, coef, _ = _level_terms(k)
    kpow = power_table(kp, int(a.max()))
    spow = power_table(sg, int(b.max()))
    vals = coef.astype(np.float64) * kpow[a] * spow[b]
    return np.abs(vals) if absolute else vals


def _combined(k: int, weights: np.ndarray, vals: np.ndarray) -> sp.csr_matrix:
    """Q = sum_h weights[h] P_h (order k - 1 -> k) as CSR, each entry summed in a fixed order."""
    used = tuple(int(h) for h in np.flatnonzero(weights))
    pos, starts, indptr, indices, hpos = _pattern(k, used)
    data = np.add.reduceat(vals[pos] * weights[hpos], starts) if len(pos) else np.zeros(0)
    return sp.csr_matrix((data, indices, indptr), shape=(delta_unchecked(k), delta_unchecked(k - 1)))


def restriction_matrices(n: int, alpha: float, *, absolute: bool = False, first: list | None = None
                         ) -> tuple[np.ndarray, ...]:
    """The four R_n^k (scaled members at alpha -> scaled members at alpha/2), in the order of :data:`PARTS`;
    ``absolute``: the product matrices in absolute values (they are non-negative: only the sums' bits change);
    ``first``: the two 7 x 7 matrices R_1 of parts 'u' and 'middle' to start from (default: computed).  ``n >= 1``
    and ``alpha`` in [ALPHA_TINY, pi) checked by the caller.  :func:`restriction_blocks` assembled
    (:func:`assemble`, no normalization)."""
    kp, sg = _float_half_angle(alpha / 2)
    r1 = first if first is not None else [order_one_restriction(p, kp, sg) for p in ("u", "middle")]
    ones = np.ones(delta_unchecked(n))
    return assemble(n, restriction_blocks(n, kp, sg, r1, absolute=absolute), ones, ones)


def restriction_blocks(n: int, kp: float, sg: float, first: list, *, absolute: bool = False,
                       families: tuple[str, ...] = ("u", "middle")) -> list[np.ndarray | None]:
    """The columns ``_plan(n, part)[-1][0]`` (one per symmetry orbit) of R_n^u and R_n^middle, from the two 7 x 7
    matrices R_1 ``first`` (parts 'u', 'middle') at ``kp, sg = cos(alpha/4), sin^2(alpha/4)``: level k computes
    only the columns of its plan, column f as ``Q_{h(f)} R_{k-1}[:, f'(f)]`` with ``Q_g = sum_h R_1[h, g] P_h``
    (the Theorem of docs/subdivision_for_all_n.md, section 11).  Only the ``families`` asked for ('u': the three
    corners, 'middle'); None for the other."""
    fams = [f for f in ("u", "middle") if f in families]
    plans = {f: _plan(n, f) for f in fams}
    r1 = {"u": first[0], "middle": first[1]}
    blocks = {f: r1[f][:, plans[f][0][0]] for f in fams}
    # two buffers per family, used in turn by the levels (fresh memory for every level costs page faults)
    size = {f: max(delta_unchecked(k + 1) * len(plans[f][k][0]) for k in range(n)) for f in fams}
    buffers = {f: (np.empty(size[f]), np.empty(size[f])) for f in fams}
    for k in range(2, n + 1):
        vals = _level_values(k, kp, sg, absolute)
        for f in fams:
            cols, bounds, pos = plans[f][k - 1]
            out = buffers[f][k % 2][:delta_unchecked(k) * len(cols)].reshape(delta_unchecked(k), len(cols))
            for g in range(7):
                lo, hi = bounds[g], bounds[g + 1]
                if hi > lo:  # np.take: a C-contiguous copy, which scipy's product uses as it is
                    out[:, lo:hi] = _combined(k, r1[f][:, g], vals) @ np.take(blocks[f], pos[lo:hi], axis=1)
            blocks[f] = out
    return [blocks.get("u"), blocks.get("middle")]


def assemble(n: int, blocks: list[np.ndarray | None], x0: np.ndarray, x1: np.ndarray,
             parts: tuple[str, ...] = PARTS) -> tuple[np.ndarray, ...]:
    """The ``S_k[g, f] = R_k[g, f] x0_f / x1_g`` of ``parts`` (in that order) from the two blocks of
    :func:`restriction_blocks`: every column is the image of a computed one under :func:`symmetry_permutations`
    (``R[pi g, pi f] = R[g, f]``, and the normalizing coefficients are symmetric, Theorem B), and the corners v, w
    are corner u with u and v (u and w) exchanged, ``R^v[pi g, pi f] = R^u[g, f]`` (T_{2n} is invariant under the
    permutations of (u, v, w); the translation in v is the translation in u conjugated by the exchange).  One
    normalization per computed entry; then each computed column whose member is fixed by a nontrivial pi is made
    constant on the orbits of its stabilizer (:func:`_stabilizer_rows`: every entry takes the value of the smallest
    row of its orbit, which the exact column has there, Lemma 11.4), so that the copies written to the same place
    agree bit for bit and the output is exactly invariant (``S[pi g, pi f] == S[g, f]`` bitwise; corners v, w
    bitwise conjugates of u); then every entry written once per orbit element.  For the estimate B (the same call
    on the bound's blocks) the moved entry takes the estimate of the entry it was moved from.

    >>> import numpy as np
    >>> s_u, s_mid = subdivision_matrices_float(5, 1.1, parts=("u", "middle"))
    >>> all(np.array_equal(s_u[np.ix_(p, p)], s_u) for p in symmetry_permutations(5, "u"))
    True
    >>> all(np.array_equal(s_mid[np.ix_(p, p)], s_mid) for p in symmetry_permutations(5, "middle"))
    True
    """
    d = delta_unchecked(n)
    out = []
    for part in parts:
        family = "middle" if part == "middle" else "u"
        cols = _plan(n, family)[-1][0]
        block = blocks[family == "middle"] * (x0[cols][None, :] / x1[:, None])
        fixed, rows = _stabilizer_rows(n, family)
        if len(fixed):
            block[:, fixed] = np.take_along_axis(block[:, fixed], rows, axis=0)
        swap = None if part in ("u", "middle") else swap_permutation(n, "uvw".index(part))
        full = np.empty((d, d))
        for pi in symmetry_permutations(n, family):
            p = pi if swap is None else swap[pi]
            full[np.ix_(p, p[cols])] = block
        out.append(full)
    return tuple(out)


@cache
def _stabilizer_rows(n: int, part: str) -> tuple[np.ndarray, np.ndarray]:
    """For the computed columns of :func:`_plan` (``_plan(n, part)[-1][0]``) whose member f is fixed by a nontrivial
    pi of :func:`symmetry_permutations`: their positions ``fixed`` among the computed columns, and ``rows``
    (delta_n x len(fixed)), ``rows[g, i]`` the smallest member of the orbit of g under the stabilizer of f (the
    group of the pi with pi f = f).  The exact column is constant on these orbits (Lemma 11.4: R[pi g, f] =
    R[pi g, pi f] = R[g, f]); the computed one only up to rounding, which :func:`assemble` removes.

    >>> fixed, rows = _stabilizer_rows(2, "u")
    >>> bool(len(fixed) > 0 and (rows <= np.arange(19)[:, None]).all())
    True
    """
    d = delta_unchecked(n)
    perms = [pi for pi in symmetry_permutations(n, part) if not np.array_equal(pi, np.arange(d))]
    cols = _plan(n, part)[-1][0]
    stab = np.array([pi[cols] == cols for pi in perms]).reshape(len(perms), len(cols))  # pi fixes the column's f
    fixed = np.flatnonzero(stab.any(axis=0))
    rows = np.repeat(np.arange(d)[:, None], len(fixed), axis=1)
    for pi, fixes in zip(perms, stab[:, fixed]):
        rows[:, fixes] = np.minimum(rows[:, fixes], pi[:, None])
    for arr in (fixed, rows):
        arr.setflags(write=False)
    return fixed, rows


@cache
def _plan(n: int, part: str) -> tuple[tuple[np.ndarray, ...], ...]:
    """The columns of R_k computed at each level k = 1..n: at level n one member of each orbit of
    :func:`symmetry_permutations` (the smallest index; the other columns are their images), at level k - 1 the
    factors f'(f) (:func:`factorization`) of the columns of level k.  Entry k - 1: ``(cols, bounds, pos)`` with
    ``cols`` ordered by the factor h(f) (k >= 2), ``bounds`` the start of each h's run (8 bounds) and ``pos`` the
    position of f'(f) among the columns of level k - 1."""
    perms = np.stack(symmetry_permutations(n, part))
    cols = np.flatnonzero(perms.min(axis=0) == np.arange(delta_unchecked(n)))
    out = []
    if n >= 2:
        cols = cols[np.argsort(factorization(n)[1][cols], kind="stable")]
    for k in range(n, 1, -1):
        fp, h = factorization(k)
        bounds = np.searchsorted(h[cols], np.arange(8))
        prev = np.unique(fp[cols])
        if k > 2:
            prev = prev[np.argsort(factorization(k - 1)[1][prev], kind="stable")]
        where = np.empty(delta_unchecked(k - 1), dtype=np.int64)
        where[prev] = np.arange(len(prev))
        out.append((cols, bounds, where[fp[cols]]))
        cols = prev
    out.append((cols, np.zeros(8, dtype=np.int64), np.zeros(0, dtype=np.int64)))
    out.reverse()
    for entry in out:
        for arr in entry:
            arr.setflags(write=False)
    return tuple(out)


@cache
def symmetry_permutations(n: int, part: str) -> tuple[np.ndarray, ...]:
    """The member permutations ``pi`` (``m_{pi f}(u, v, w) = m_f`` at the permuted variables) of the exchanges of
    variables that commute with the map of ``part``: for the corner ``'u'`` the identity and v <-> w; for
    ``'middle'`` (the point reflection commutes with every permutation of (u, v, w)) all six.  Then
    ``R[pi g, pi f] = R[g, f]``: with tau the exchange, ``m_{pi f} o x_k = m_f o tau o x_k = m_f o x_k o tau =
    sum_g R[g, f] m'_g o tau = sum_g R[g, f] m'_{pi g}`` (docs/subdivision_for_all_n.md, section 11)."""
    e = exponent_matrix(n).astype(np.int64)
    weights = 64 ** np.arange(6, dtype=np.int64)
    keys = e @ weights
    order = np.argsort(keys)
    sigmas = [(0, 1, 2), (0, 2, 1)] if part == "u" else list(itertools.permutations(range(3)))
    out = []
    for sigma in sigmas:
        cols = [2 * sigma[c // 2] + c % 2 for c in range(6)]
        want = e[:, cols] @ weights
        pi = order[np.searchsorted(keys[order], want)]
        if not np.array_equal(keys[pi], want):  # pragma: no cover - T_2n is invariant under the permutations
            raise AssertionError(f"T_{2 * n} is not invariant under the permutation {sigma}")
        pi.setflags(write=False)
        out.append(pi)
    return tuple(out)


@cache
def swap_permutation(n: int, var: int) -> np.ndarray:
    """``variable_swap(n, 0, var)``: the index of each member with the variables u and ``var`` exchanged."""
    e = exponent_matrix(n).astype(np.int64)
    weights = 64 ** np.arange(6, dtype=np.int64)
    cols = list(range(6))
    cols[0:2], cols[2 * var:2 * var + 2] = cols[2 * var:2 * var + 2], cols[0:2]
    keys = e @ weights
    order = np.argsort(keys)
    want = e[:, cols] @ weights
    pi = order[np.searchsorted(keys[order], want)]
    if not np.array_equal(keys[pi], want):  # pragma: no cover - T_2n is invariant under the exchange
        raise AssertionError(f"T_{2 * n} is not invariant under exchanging u and {'uvw'[var]}")
    pi.setflags(write=False)
    return pi


@lru_cache(maxsize=32)
def _normalizers(n: int, alpha: float) -> tuple[np.ndarray, np.ndarray]:
    k0, s0 = _float_half_angle(alpha)
    k1, s1 = _float_half_angle(alpha / 2)
    return scaled_coefficients(n, k0, s0, _F), scaled_coefficients(n, k1, s1, _F)


def _gamma(m: int) -> float:
    u = math.ldexp(1.0, -53)
    return m * u / (1 - m * u)


def subdivision_matrices_float(n: int, alpha: float, *, bound: bool = False, parts: tuple[str, ...] = PARTS):
    """The S_k of ``parts`` (default the four, :func:`paper_repro.core.subdivision.subdivision_matrices`) in
    float64 by the product route, ``n >= 1`` and ``alpha`` in (0, pi) checked by the caller (below
    :data:`ALPHA_TINY` computed at ALPHA_TINY).  Only the recursions the parts need are run (the corners share one).

    ``bound=True`` returns ``(matrices, bounds)`` with the rounding part B of the error estimate of
    docs/subdivision_for_all_n.md, section 11: ``|S_float - S| <= B + (2 eps_x + 3u)(|S_float| + B)`` to first order
    in u, eps_x the relative error of the float scaled coefficients (not computed here: measured by the tests).
    With F the level recursion (each column a homogeneous polynomial of degree n in the entries of R_1 with
    non-negative coefficients, so ``|F(A + E) - F(A)| <= F(|A| + |E|) - F(|A|)`` and ``A -> F(A + e) - F(A)`` is
    monotone on A >= 0), Q_1 the computed R_1, e_1 = gamma_{2 K_1} times the majorant of R_1's computation
    (K_1 = :data:`ORDER_ONE_ROUNDINGS`) and K_L the roundings of the levels (:func:`level_roundings` summed):
    ``B = D (F(|Q_1| + 2 e_1) - F(|Q_1|) + gamma_{2 K_L} F(|Q_1| + 2 e_1)) D`` with D the normalization.  First
    order in u and eps_x not bounded: a heuristic a-posteriori estimate, not a certificate."""
    alpha = max(float(alpha), ALPHA_TINY)
    x0, x1 = _normalizers(n, alpha)
    kp, sg = _float_half_angle(alpha / 2)
    families = tuple({"middle" if p == "middle" else "u" for p in parts})
    r1 = [order_one_restriction(p, kp, sg) for p in ("u", "middle")]
    mats = assemble(n, restriction_blocks(n, kp, sg, r1, families=families), x0, x1, parts)
    if not bound:
        return mats
    e1 = [_gamma(2 * ORDER_ONE_ROUNDINGS) * order_one_restriction(p, kp, sg, absolute=True) for p in ("u", "middle")]
    low = restriction_blocks(n, kp, sg, [abs(r) for r in r1], absolute=True, families=families)
    high = restriction_blocks(n, kp, sg, [abs(r) + 2 * e for r, e in zip(r1, e1)], absolute=True,
                              families=families)
    g = _gamma(2 * (rounding_count(n) - ORDER_ONE_ROUNDINGS - 2))
    comb = [None if h is None else (h - lo) + g * h for h, lo in zip(high, low)]
    return mats, assemble(n, comb, x0, x1, parts)


def level_roundings(k: int) -> int:
    """Roundings that level k (order k - 1 -> k) adds along any path, the factor R_{k-1} excepted
    (docs/subdivision_for_all_n.md section 11, "Error estimate"): a term ``coef kappa'^a sigma'^b`` of a product form
    (the a + b occurrences of the correctly rounded inputs; powers by repeated multiplication, :func:`power_table`:
    a - 1 and b - 1 products, then two products; the integer coef exact) at most 2 max(a + b) over the terms; times
    the weight R_1[h, g]: 1; the fixed-order sum of a (row, column) run of :func:`_combined` over the seven h: its
    length - 1; the sparse product: 1 product and the row's length - 1 additions (the first addition to 0 is exact,
    not counted: the count is an upper bound either way).

    >>> level_roundings(2) > 0
    True
    """
    rows, cols, a, b, coef, _ = _level_terms(k)
    if int(np.abs(coef).max()) >= 2**53:  # pragma: no cover - the integer coefficients are small
        raise AssertionError("an integer coefficient is not exact in float64")
    _, starts, indptr, _, _ = _pattern(k, tuple(range(7)))
    run = int(np.diff(np.r_[starts, len(rows)]).max())
    row = int(np.diff(indptr).max())
    return 2 * int((a + b).max()) + 1 + (run - 1) + 1 + (row - 1)


def rounding_count(n: int) -> int:
    """K of the running-error estimate: an upper bound of the roundings along any path of the recursion
    (docs/subdivision_for_all_n.md, section 11, where the counts are derived): :data:`ORDER_ONE_ROUNDINGS` for R_1,
    :func:`level_roundings` per level k = 2..n (a product's roundings add along a path), and 2 for the
    normalization ``x_f / x'_g`` (a quotient, then a product).

    >>> rounding_count(1), rounding_count(2) - rounding_count(1) == level_roundings(2)
    (95, True)
    """
    return ORDER_ONE_ROUNDINGS + sum(level_roundings(k) for k in range(2, n + 1)) + 2


__all__ = ["PARTS", "ALPHA_TINY", "product_terms_fast", "factorization", "order_one_restriction",
           "restriction_matrices", "restriction_blocks", "assemble", "symmetry_permutations", "centre_embedding",
           "subdivision_matrices_float", "rounding_count",
           "level_roundings", "power_table", "ORDER_ONE_ROUNDINGS"]
