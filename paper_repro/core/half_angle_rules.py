"""The half-angle rules: cotangents, derivatives and order elevation of the scaled monomials of T_{2n}, for every n.

Notation (docs/elevation_and_derivative_for_all_n.md, where every rule is proven): ``s = sin(alpha/2)``,
``kappa = cos(alpha/2)``, ``sigma = s^2``, and for x in (u, v, w), u + v + w = alpha: ``S_x = sin(x/2)/s``,
``C_x = cos(x/2)``.  The scaled members of T_{2n} (the monomials of :func:`~paper_repro.core.basis.evaluate` with
``scaled=True``) are, for a permutation (X, Y, Z) of (u, v, w) and ``0 <= j <= m <= n``::

    M_X(m; Y, j) = S_X^(2n-m) S_Y^j C_Y^(m-j) S_Z^m

(``R_{2n,2n-i,j}`` is ``M_u(i; v, j)`` for i <= n and ``M_w(2n-i; v, j)`` for i > n; at m = n, X and Z play the
same part).  Two identities, (I) ``C_x = kappa S_x + S_y C_z + C_y S_z`` and
(II) ``C_y C_z = sigma S_y S_z + kappa C_x + sigma S_x``, give the *cotangent operator* ``L_x: m -> (C_x/S_x) m``
on every member with a factor S_x, as a sum of members with coefficients ``kappa^a sigma^b`` (every coefficient +1):

* rule (A): x in the part X, m < n;  rule (A_n): m = n, x not the cosine variable;
* rule (B): x in the part Z, 1 <= m < n;  x the cosine variable Y: ``(C_Y/S_Y) M_X(m;Y,j) = M_X(m;Y,j-1)``.

From them, with ``D_x(S^a C^b) = a S^(a-1) C^(b+1) - b sigma S^(a+1) C^(b-1)`` (= 2 s d/dx on the variable x):

* the derivative matrix C, ``2 s d/du m_f = (D_u - D_w) m_f = sum_g C[g, f] m_g`` along u = (1, 0, -1):
  ``D_x m = p_x L_x m - q_x sigma (S_x/C_x) m`` (p_x, q_x the exponents of S_x, C_x);
* the elevation matrix M (order n -> N = n + 1), ``m_f = sum_g M[g, f] m'_g``: with x the part X of m_f,
  ``m_f = m_f (sigma S_x^2 + C_x^2) = sigma m'_{P f} + L_x L_x m'_{P f}`` where ``m'_{P f} = S_x^2 m_f`` is a
  member of order N.  No step subtracts: M is in Z_{>=0}[kappa, sigma].

This module holds the rules as integer data (terms ``(row, col, a, b, coef)`` meaning ``coef kappa^a sigma^b`` in
entry (row, col)), built with integer arithmetic only; :mod:`paper_repro.core.half_angle_matrices` evaluates them in
every arithmetic.

>>> rows, cols, a, b, c = elevation_terms(1)
>>> int(c.min()) >= 0, len(set(zip(rows.tolist(), cols.tolist()))) <= 19 * 7
(True, True)
"""

from __future__ import annotations

from functools import cache

import numpy as np

from paper_repro.core.labels import delta, delta_unchecked, exponent_matrix
from paper_repro.util.validation import check_n


def member_table(n: int) -> np.ndarray:
    """``K[X, Y, m, j]``: the internal index (:func:`~paper_repro.core.labels.united_system`) of the member
    ``M_X(m; Y, j)`` of T_{2n} (variables 0, 1, 2 = u, v, w), ``-1`` where X = Y or j > m.

    >>> K = member_table(1)
    >>> int(K[0, 1, 1, 1]), int(K[2, 1, 1, 1]), int(K[1, 0, 1, 1])   # the centre, whatever the parts
    (0, 0, 0)
    """
    return _member_table(check_n(n))


@cache
def _member_table(n: int) -> np.ndarray:
    """:func:`member_table` for inner code (``n`` already checked)."""
    index = {tuple(int(x) for x in row): k for k, row in enumerate(exponent_matrix(n))}
    table = np.full((3, 3, n + 1, n + 1), -1, dtype=np.int64)
    for x in range(3):
        for y in range(3):
            if x == y:
                continue
            z = 3 - x - y
            for m in range(n + 1):
                for j in range(m + 1):
                    e = [0] * 6
                    e[2 * x], e[2 * y], e[2 * y + 1], e[2 * z] = 2 * n - m, j, m - j, m
                    table[x, y, m, j] = index[tuple(e)]
    table.setflags(write=False)
    return table


def member_parts(n: int) -> np.ndarray:
    """``(delta_n, 4)`` array ``(X, m, Y, j)`` of each member: Y the cosine variable (the smaller remaining one when
    there is none), X the variable of the sine exponent 2n - m (for m = n the smaller non-Y variable)."""
    return _member_parts(check_n(n))


@cache
def _member_parts(n: int) -> np.ndarray:
    """:func:`member_parts` for inner code (``n`` already checked)."""
    table = _member_table(n)
    out = np.full((delta_unchecked(n), 4), -1, dtype=np.int64)
    for m in range(n, -1, -1):  # a member with j = m has several names: keep the one found last (smallest X, Y)
        for j in range(m, -1, -1):
            for x in range(2, -1, -1):
                for y in range(2, -1, -1):
                    if x != y:
                        out[table[x, y, m, j]] = (x, m, y, j)
    return out


@cache
def _rule_a_pattern(m: int, j: int) -> tuple[np.ndarray, ...]:
    """Rule (A) for ``(C_X/S_X) M_X(m; Y, j)`` in the parts' coordinates: ``(a, b, part, m', l)`` per term, the
    target being ``M_X(m'; Y, l)`` (part 0) or ``M_X(m'; Z, l)`` (part 1); every coefficient +1."""
    out = [(1, 0, 0, m, j)]
    out += [(ell - j - 1, 0, 0, m, ell) for ell in range(j + 1, m + 1)]
    out.append((0, 0, 0, m + 1, j))
    if j < m:
        out.append((1, 0, 0, m + 1, j + 1))
        out += [(ell - j - 2, 0, 0, m + 1, ell) for ell in range(j + 2, m + 1)]
        out.append((m - j - 1, 1, 0, m + 1, m + 1))
    out.append((m - j, 0, 1, m + 1, m))
    arr = np.array(out, dtype=np.int64)
    return tuple(arr[:, k].copy() for k in range(5))


def _terms(a, b, target) -> np.ndarray:
    """Terms as a ``(k, 4)`` array ``(a, b, coef, target)`` with coef = 1."""
    target = np.atleast_1d(np.asarray(target, dtype=np.int64))
    out = np.ones((len(target), 4), dtype=np.int64)
    out[:, 0], out[:, 1], out[:, 3] = a, b, target
    return out


def _rule_a(n: int, x: int, m: int, y: int, j: int) -> np.ndarray:
    """Rule (A): ``(C_X/S_X) M_X(m; Y, j)`` for 0 <= j <= m < n, as :func:`_terms`."""
    a, b, part, mm, ll = _rule_a_pattern(m, j)
    ys = np.array([y, 3 - x - y])
    return _terms(a, b, _member_table(n)[x][ys[part], mm, ll])


def _shift(terms: np.ndarray, a: int, b: int) -> np.ndarray:
    out = terms.copy()
    out[:, 0] += a
    out[:, 1] += b
    return out


def _rule_an(n: int, x: int, y: int, j: int) -> np.ndarray:
    """Rule (A_n): ``(C_X/S_X) M(n; Y, j)`` at level n (X not the cosine variable Y)."""
    table = _member_table(n)
    z = 3 - x - y
    if j == n:
        return _terms(0, 0, table[y, x, n, n - 1])
    head = _terms(0, 1, [table[x, y, n, j + 1], table[z, y, n - 1, j]])
    return np.concatenate([head, _shift(_rule_a(n, z, n - 1, y, j), 1, 0)])


def _rule_b(n: int, x: int, m: int, y: int, j: int) -> np.ndarray:
    """Rule (B): ``(C_Z/S_Z) M_X(m; Y, j)`` for 1 <= m < n."""
    table = _member_table(n)
    z = 3 - x - y
    if j == m:
        return _terms(0, 0, table[x, z, m, m - 1])
    head = _terms(0, 1, [table[x, y, m, j + 1], table[x, y, m - 1, j]])
    return np.concatenate([head, _shift(_rule_a(n, x, m - 1, y, j), 1, 0)])


@cache
def cotangent(n: int, var: int, g: int) -> np.ndarray:
    """``L_var m_g = (C_var / S_var) m_g`` as a read-only ``(k, 4)`` array of terms ``(a, b, coef, target)``
    (every coef +1), for a member with a factor S_var; ``ValueError`` otherwise."""
    x, m, y, j = (int(v) for v in _member_parts(n)[g])
    e = exponent_matrix(n)[g]
    if e[2 * var] == 0:
        raise ValueError(f"member {g} of order {n} has no factor sin({'uvw'[var]}/2)")
    if e[2 * var + 1] > 0:  # var is the cosine variable Y
        out = _terms(0, 0, _member_table(n)[x, y, m, j - 1])
    elif m == n:  # level n: var is one of the two parts X, Z (or any variable at the centre)
        out = _rule_an(n, var, y if var != y else x, j)
    elif var == x:
        out = _rule_a(n, x, m, y, j)
    elif var == 3 - x - y:
        out = _rule_b(n, x, m, y, j)
    else:
        out = _rule_b(n, x, m, 3 - x - y, j)  # j = m: Y and Z are interchangeable
    out.setflags(write=False)
    return out


def _as_arrays(terms: list[tuple[int, int, int, int, int]]) -> tuple[np.ndarray, ...]:
    arr = np.array(terms, dtype=np.int64).reshape(-1, 5)
    return tuple(arr[:, k].copy() for k in range(5))


def derivative_terms(n: int) -> tuple[np.ndarray, ...]:
    """C (direction u = (1, 0, -1)) as terms ``(rows, cols, a, b, coef)``: ``C[g, f] = sum coef kappa^a sigma^b``
    over the terms with row g and column f (signed integer coefficients; not merged)."""
    return _derivative_terms(check_n(n))


@cache
def _derivative_terms(n: int) -> tuple[np.ndarray, ...]:
    """:func:`derivative_terms` for inner code (``n`` already checked)."""
    e = exponent_matrix(n)
    parts = _member_parts(n)
    table = _member_table(n)
    out = []
    for f in range(delta_unchecked(n)):
        x, m, y, j = (int(v) for v in parts[f])
        for var, sign in ((0, 1), (2, -1)):
            p, q = int(e[f, 2 * var]), int(e[f, 2 * var + 1])
            if p:
                out += [(int(t), f, int(a), int(b), sign * p * int(c)) for a, b, c, t in cotangent(n, var, f)]
            if q:  # var is the cosine variable: (S/C) M_X(m; Y, j) = M_X(m; Y, j + 1)
                out.append((int(table[x, y, m, j + 1]), f, 0, 1, -sign * q))
    return _as_arrays(out)


def elevation_part(n: int) -> np.ndarray:
    """For each column f, the variable x with ``S_x^2 m_f`` a member of order n + 1 (the part X of m_f)."""
    return _member_parts(n)[:, 0]


@cache
def _cotangent_csc(n: int, var: int) -> tuple[np.ndarray, ...]:
    """``L_var`` on every member as compressed columns ``(indptr, target, a, b, coef)`` (empty columns for the
    members without a factor S_var)."""
    e = exponent_matrix(n)
    empty = np.zeros((0, 4), dtype=np.int64)
    cols = [cotangent(n, var, g) if e[g, 2 * var] else empty for g in range(delta_unchecked(n))]
    indptr = np.zeros(delta_unchecked(n) + 1, dtype=np.int64)
    indptr[1:] = np.cumsum([len(c) for c in cols])
    flat = np.concatenate(cols)
    return indptr, flat[:, 3].copy(), flat[:, 0].copy(), flat[:, 1].copy(), flat[:, 2].copy()


def _gather(csc: tuple[np.ndarray, ...], q: np.ndarray) -> tuple[np.ndarray, ...]:
    """The terms of the columns ``q`` of a compressed operator: ``(position in q, target, a, b, coef)``."""
    indptr = csc[0]
    start, counts = indptr[q], indptr[q + 1] - indptr[q]
    pos = np.repeat(np.arange(len(q)), counts)
    first = np.cumsum(counts) - counts
    idx = np.arange(int(counts.sum())) - np.repeat(first, counts) + start[pos]
    return (pos,) + tuple(arr[idx] for arr in csc[1:])


def elevation_terms(n: int) -> tuple[np.ndarray, ...]:
    """M (order n -> n + 1, ``m_f = sum_g M[g, f] m'_g``) as terms ``(rows, cols, a, b, coef)``, coef > 0:
    ``sigma m'_{P f} + L_x L_x m'_{P f}`` for each column (vectorised over the columns with the same part x)."""
    n = check_n(n)
    big = n + 1
    lifted = exponent_matrix(n).copy()
    part = elevation_part(n)
    lifted[np.arange(delta_unchecked(n)), 2 * part] += 2
    key = lambda e: ((((e[:, 0] * 64 + e[:, 1]) * 64 + e[:, 2]) * 64 + e[:, 3]) * 64 + e[:, 4]) * 64 + e[:, 5]
    big_keys = key(exponent_matrix(big))
    order = np.argsort(big_keys)
    loc = np.searchsorted(big_keys[order], key(lifted))
    g = order[loc]
    if not np.array_equal(exponent_matrix(big)[g], lifted):
        raise AssertionError(f"S_x^2 m_f is not a member of order {big}")
    cols = np.arange(delta_unchecked(n))
    out = [(g, cols, np.zeros_like(g), np.ones_like(g), np.ones_like(g))]
    for var in range(3):
        sel = cols[part == var]
        if not len(sel):
            continue
        csc = _cotangent_csc(big, var)
        p1, t1, a1, b1, c1 = _gather(csc, g[sel])
        p2, t2, a2, b2, c2 = _gather(csc, t1)
        out.append((t2, sel[p1[p2]], a1[p2] + a2, b1[p2] + b2, c1[p2] * c2))
    return tuple(np.concatenate([o[k] for o in out]) for k in range(5))


def merge(terms: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    """The same terms with equal ``(row, col, a, b)`` added, zero sums dropped, sorted by (row, col, a, b): the
    integer bivariate form of the matrix."""
    rows, cols, a, b, c = terms
    if not len(rows):
        return terms
    amax, bmax, cmax = int(a.max()) + 1, int(b.max()) + 1, int(cols.max()) + 1
    key = ((rows * cmax + cols) * amax + a) * bmax + b
    order = np.argsort(key, kind="stable")
    key = key[order]
    start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    coef = np.add.reduceat(c[order], start)  # integers: exact in any order
    keep = coef != 0
    u = key[start][keep]
    b_, u = u % bmax, u // bmax
    a_, u = u % amax, u // amax
    return u // cmax, u % cmax, a_, b_, coef[keep]



# --- Pairwise products with the first-order members (the paper's wish list after Question 1, sec:open_problems) ---

@cache
def order_one_parts() -> tuple[tuple[str, int], ...]:
    """Each member h of T_2 (internal order) as ``('centre', -1)`` (``S_u S_v S_w``), ``('edge', y)``
    (``S_x S_z C_y``) or ``('corner', y)`` (``S_y^2``), y in 0, 1, 2 = u, v, w.

    >>> sorted(order_one_parts())[:2]
    [('centre', -1), ('corner', 0)]
    """
    out = []
    for e in exponent_matrix(1).tolist():
        cos = [y for y in range(3) if e[2 * y + 1]]
        if cos:
            out.append(("edge", cos[0]))
        elif max(e[0::2]) == 2:
            out.append(("corner", e[0::2].index(2)))
        else:
            out.append(("centre", -1))
    return tuple(out)


def _apply_cotangent(n: int, var: int, comb: dict) -> dict:
    """``L_var`` on a combination ``{(target, a, b): coef}`` of members of T_{2n}; ``ValueError`` when a member has
    no factor S_var (the lowering lemma of the proof says this never happens on the products' route)."""
    out: dict = {}
    for (g, a0, b0), c0 in comb.items():
        for a, b, c, t in cotangent(n, var, g).tolist():
            key = (t, a0 + a, b0 + b)
            out[key] = out.get(key, 0) + c0 * c
    return out


def product_column(n: int, h: int, f: int) -> dict:
    """``m_f m_h = sum coef kappa^a sigma^b m'_g``: the product of the member f of T_{2n} and the member h of T_2 as
    members g of T_{2(n+1)}, ``{(g, a, b): coef}`` (every coef > 0).  With the parts ``(X, m, Y, j)`` of m_f
    (:func:`member_parts`), Z the third variable and N = n + 1 (docs/elevation_and_derivative_for_all_n.md,
    Theorem P):

    * centre: ``M_X(m + 1; Y, j + 1)``;  edge ``S_x S_z C_y``: ``L_y`` of the centre's product;
    * corner ``S_X^2``: ``M_X(m; Y, j)``;  corner ``S_Z^2`` (or ``S_Y^2`` with j = m, naming the cosine variable Z):
      ``sigma M_X(m + 2; Y, j + 2) + M_X(m + 2; Y, j)`` for m < n, ``M_Z(n; Y, j)`` for m = n;
    * corner ``S_Y^2`` with j < m: ``L_Y^(m - j) p`` with ``p = sigma M_X(m + 2; Z, m + 2) + M_X(m + 2; Z, m)``
      for m < n and ``p = M_Y(n; X, n)`` for m = n.
    """
    big = n + 1
    table = member_table(big)
    x, m, y, j = (int(v) for v in _member_parts(n)[f])
    z = 3 - x - y
    kind, var = order_one_parts()[h]
    centre = {(int(table[x, y, m + 1, j + 1]), 0, 0): 1}
    if kind == "centre":
        return centre
    if kind == "edge":
        return _apply_cotangent(big, var, centre)
    if var == x or (m == n and var == z):  # S_X^2 m_f (at level n, X and Z play the same part)
        return {(int(table[var, y, m, j]), 0, 0): 1}
    if var == z or j == m:  # S_Z^2 m_f, or S_Y^2 m_f with no cosine of Y (rename the cosine variable Z)
        cos, jj = (y, j) if var == z else (z, m)
        if m == n:
            return {(int(table[var, cos, n, jj]), 0, 0): 1}
        return {(int(table[x, cos, m + 2, jj + 2]), 0, 1): 1, (int(table[x, cos, m + 2, jj]), 0, 0): 1}
    # S_Y^2 m_f with j < m: L_Y^(m - j) of a member combination p with the cosines of Y turned into sines
    if m < n:
        p = {(int(table[x, z, m + 2, m + 2]), 0, 1): 1, (int(table[x, z, m + 2, m]), 0, 0): 1}
    else:
        p = {(int(table[y, x, n, n]), 0, 0): 1}
    for _ in range(m - j):
        p = _apply_cotangent(big, y, p)
    return p


@cache
def product_terms(n: int, h: int) -> tuple[np.ndarray, ...]:
    """P_h (``m_f m_h = sum_g P_h[g, f] m'_g``, T_{2n} x T_2 -> T_{2(n+1)}) as terms ``(rows, cols, a, b, coef)``
    (coef > 0) for the member h of T_2 (:func:`order_one_parts`).

    >>> rows, cols, a, b, c = product_terms(1, 0)
    >>> bool(c.min() > 0)
    True
    """
    n = check_n(n)
    if not isinstance(h, (int, np.integer)) or isinstance(h, bool) or not 0 <= h < delta(1):
        raise ValueError(f"h must be the index of a member of T_2, an integer in [0, {delta(1) - 1}], got {h!r}")
    out = [(g, f, a, b, c) for f in range(delta_unchecked(n)) for (g, a, b), c in product_column(n, int(h), f).items()]
    return _as_arrays(out)
