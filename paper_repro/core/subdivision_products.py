"""Midpoint subdivision in float64 without a solve: restriction is a ring homomorphism (docs/subdivision_for_all_n.md,
section 9).

Notation of docs/elevation_and_derivative_for_all_n.md: ``m_f = f / s^{2n+j(f)}`` the scaled members of T_{2n}^alpha
(eq. united_system), ``x_f`` their scaled normalizing coefficients (T-bar_f = x_f m_f, eq. normalized_united_system),
``kappa' = cos(alpha/4)``, ``sigma' = sin^2(alpha/4)`` the half-angle values of the parameter alpha/2 of the
sub-patches, and ``x_k`` the map of Omega^{alpha/2} onto the sub-triangle ``k`` (:mod:`paper_repro.core.subdivision`).

The route, for every n (proof: docs/subdivision_for_all_n.md, section 9):

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

Float results are the same bits on every CPU: kappa', sigma' from flint ``arb``, fixed-order sums (no BLAS:
scipy's sparse products sum each row in the order of its entries).

No step subtracts except inside the 7 x 7 matrix R_1 and the signed sums of the level recursion (R_1 has negative
entries), so float64 keeps about 15 digits for every n and alpha measured (reports/subdivision_accuracy.md); the
entrywise running-error bound of :func:`subdivision_matrices_float` (``bound=True``) is computed from the same
recursion in absolute values.

>>> import numpy as np
>>> s = subdivision_matrices_float(2, 1.0)
>>> len(s), s[3].shape, bool(max(abs(m.sum(axis=1) - 1).max() for m in s) < 1e-14)
(4, (19, 19), True)
"""

from __future__ import annotations

from functools import cache, lru_cache

import numpy as np
import scipy.sparse as sp

from paper_repro.core.context import FloatContext
from paper_repro.core.half_angle_matrices import _float_half_angle, evaluate_terms, scaled_coefficients
from paper_repro.core.half_angle_rules import (
    _cotangent_csc,
    _gather,
    _member_parts,
    _member_table,
    cotangent,
    merge,
    order_one_parts,
)
from paper_repro.core.labels import delta_unchecked, exponent_matrix
from paper_repro.core.ordered import ordered_matmul

#: The four sub-triangles (as :data:`paper_repro.core.subdivision.PARTS`).
PARTS = ("u", "v", "w", "middle")
#: Below this alpha the float route computes at ALPHA_TINY: the scaled coefficients of size sigma would underflow;
#: S is an even analytic function of alpha (every quantity of the route is a polynomial in kappa', sigma' or a
#: quotient of such with a non-vanishing limit), so S(alpha) = S(ALPHA_TINY) + O(1e-200), far below float64's
#: rounding.  (The same threshold as :data:`paper_repro.core.half_angle_matrices.ALPHA_TINY`.)
ALPHA_TINY = 1e-100
_F = FloatContext()


# --- step 2: the products with the members of T_2, vectorised ------------------------------------------------------
def _apply_cotangent_terms(big: int, var: np.ndarray, terms: tuple[np.ndarray, ...], steps: np.ndarray
                           ) -> tuple[np.ndarray, ...]:
    """Apply ``L_var`` ``steps[t]`` times to each term ``(col, target, a, b, coef)`` (``var`` per term)."""
    col, target, a, b, coef = terms
    done = [tuple(arr[steps == 0] for arr in terms)]
    col, target, a, b, coef, var, steps = (arr[steps > 0] for arr in (col, target, a, b, coef, var, steps))
    while len(col):
        parts_out = []
        for v in range(3):
            sel = var == v
            if not sel.any():
                continue
            pos, t, aa, bb, cc = _gather(_cotangent_csc(big, v), target[sel])
            idx = np.flatnonzero(sel)[pos]
            parts_out.append((col[idx], t, a[idx] + aa, b[idx] + bb, coef[idx] * cc, var[idx], steps[idx] - 1))
        col, target, a, b, coef, var, steps = (np.concatenate([p[k] for p in parts_out]) for k in range(7))
        fin = steps == 0
        done.append((col[fin], target[fin], a[fin], b[fin], coef[fin]))
        col, target, a, b, coef, var, steps = (arr[~fin] for arr in (col, target, a, b, coef, var, steps))
    return tuple(np.concatenate([d[k] for d in done]) for k in range(5))


@cache
def product_terms_fast(n: int, h: int) -> tuple[np.ndarray, ...]:
    """The terms ``(rows, cols, a, b, coef)`` of :func:`~paper_repro.core.half_angle_rules.product_terms` (the
    product of each member of T_{2n} with the member ``h`` of T_2, written in T_{2(n+1)}: Theorem P of
    docs/elevation_and_derivative_for_all_n.md), built with numpy instead of one dictionary per column; merged
    (:func:`~paper_repro.core.half_angle_rules.merge`).  ``n`` must be checked by the caller.

    >>> from paper_repro.core.half_angle_rules import product_terms
    >>> all(np.array_equal(x, y) for x, y in zip(product_terms_fast(3, 5), merge(product_terms(3, 5))))
    True
    """
    big = n + 1
    table = _member_table(big)
    x, m, y, j = (_member_parts(n)[:, k] for k in range(4))
    z = 3 - x - y
    f = np.arange(delta_unchecked(n))
    one = np.ones_like(f)
    zero = np.zeros_like(f)
    kind, var = order_one_parts()[h]
    if kind in ("centre", "edge"):
        centre = table[x, y, m + 1, j + 1]
        terms = (f, centre, zero, zero, one)
        if kind == "edge":
            terms = _apply_cotangent_terms(big, np.full_like(f, var), terms, one)
        return _merged(terms)
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
    steps = (m - j)[pt[0]]
    out.append(_apply_cotangent_terms(big, y[pt[0]], pt, steps))
    return _merged(tuple(np.concatenate([o[k] for o in out]) for k in range(5)))


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
    T_{2n-2} and the member h of T_2 (exponent vectors add: ``M_X(m; Y, j)`` is ``M_X(m - 1; Y, j - 1)`` times the
    centre ``S_X S_Y S_Z`` if j >= 1, ``M_X(m - 1; Y, j)`` times the edge ``S_X C_Y S_Z`` if j < m, and
    ``S_X^(2n - 2) S_X^2`` at m = 0; the first match in the order of T_2 is taken).

    >>> fp, h = factorization(2)
    >>> bool((exponent_matrix(2) == exponent_matrix(1)[fp] + exponent_matrix(1)[h]).all())
    True
    """
    e, e1, ep = exponent_matrix(n), exponent_matrix(1), exponent_matrix(n - 1)
    index = {tuple(int(v) for v in row): k for k, row in enumerate(ep)}
    fp, hh = [], []
    for row in e:
        for h in range(len(e1)):
            rest = tuple(int(v) for v in row - e1[h])
            if min(rest) >= 0 and rest in index:
                fp.append(index[rest])
                hh.append(h)
                break
        else:  # pragma: no cover - every member factors (docstring)
            raise AssertionError(f"member {row.tolist()} of order {n} does not factor")
    return np.array(fp), np.array(hh)


# --- step 1: order one by substitution and the cotangent rules ------------------------------------------------------
def _cotangent_dense(var: int, kp: float, sg: float) -> np.ndarray:
    """L_var on T_2 as a dense 7 x 7 float matrix at (kappa', sigma') (zero columns where m_g has no S_var)."""
    out = np.zeros((7, 7))
    e = exponent_matrix(1)
    for g in range(7):
        if e[g, 2 * var]:
            for a, b, c, t in cotangent(1, var, g).tolist():
                out[t, g] += c * kp ** a * sg ** b
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
    other quantity is already non-negative), the majorant of the running-error bound.
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
        out[:, h] = vec * (2.0 * kp) ** -float(e[h, 0] + e[h, 2] + e[h, 4])
    return out


# --- the recursion --------------------------------------------------------------------------------------------------
def _product_csr(k: int, h: int, kp: float, sg: float, absolute: bool = False) -> sp.csr_matrix:
    rows, cols, vals = evaluate_terms(product_terms_fast(k, h), kp, sg, _F)
    return sp.csr_matrix((np.abs(vals) if absolute else vals, (rows, cols)),
                         shape=(delta_unchecked(k + 1), delta_unchecked(k)))


def restriction_matrices(n: int, alpha: float, *, absolute: bool = False) -> tuple[np.ndarray, ...]:
    """The four R_n^k (scaled members at alpha -> scaled members at alpha/2), in the order of :data:`PARTS`;
    ``absolute``: the same recursion with every quantity replaced by its absolute value (the majorant of the
    running-error bound).  ``n >= 1`` and ``alpha`` in [ALPHA_TINY, pi) checked by the caller."""
    kp, sg = _float_half_angle(alpha / 2)
    r1 = [order_one_restriction(p, kp, sg, absolute=absolute) for p in PARTS]
    rs = [r.copy() for r in r1]
    for k in range(2, n + 1):
        fp, hh = factorization(k)
        d = delta_unchecked(k)
        base = np.hstack([r[:, fp] for r in rs])  # (delta_{k-1}, 4 delta_k): the four parts side by side
        weights = np.hstack([r[:, hh] for r in r1])  # (7, 4 delta_k)
        out = np.zeros((d, 4 * d))
        for h in range(7):
            w = weights[h]
            if not w.any():
                continue
            out += (_product_csr(k - 1, h, kp, sg, absolute) @ base) * w
        rs = [out[:, i * d:(i + 1) * d] for i in range(4)]
    return tuple(rs)


@lru_cache(maxsize=32)
def _normalizers(n: int, alpha: float) -> tuple[np.ndarray, np.ndarray]:
    k0, s0 = _float_half_angle(alpha)
    k1, s1 = _float_half_angle(alpha / 2)
    return scaled_coefficients(n, k0, s0, _F), scaled_coefficients(n, k1, s1, _F)


def subdivision_matrices_float(n: int, alpha: float, *, bound: bool = False):
    """The four S_k (:func:`paper_repro.core.subdivision.subdivision_matrices`) in float64 by the product route,
    ``n >= 1`` and ``alpha`` in (0, pi) checked by the caller (below :data:`ALPHA_TINY` computed at ALPHA_TINY).
    ``bound=True`` returns ``(matrices, majorants)``: the same recursion in absolute values, normalized likewise,
    for the running-error bound ``|S_float - S| <= gamma_K * majorant + |S| eps_x`` of
    docs/subdivision_for_all_n.md, section 9 (K = :func:`rounding_count`, eps_x the relative error of the scaled
    coefficients)."""
    alpha = max(float(alpha), ALPHA_TINY)
    x0, x1 = _normalizers(n, alpha)
    scale = x0[None, :] / x1[:, None]
    mats = tuple(r * scale for r in restriction_matrices(n, alpha))
    if not bound:
        return mats
    return mats, tuple(r * scale for r in restriction_matrices(n, alpha, absolute=True))


def rounding_count(n: int) -> int:
    """K of the running-error bound: an upper bound of the roundings along any path of the recursion
    (docs/subdivision_for_all_n.md, section 9).  Order one: per variable at most 2 binomial products and 2 Horner
    steps of (a 7-term sum, a product, a sum), times three variables, and the prefactor (2 kappa')^-3: 64.  Per level
    k: the evaluation of a product entry (the powers of kappa', sigma' up to the form's degree, the integer factor,
    the sum of the entry's monomials), the sparse row sum (its length), the weight, the sum over the seven h.  Then
    2 for the normalization x_f / x'_g.

    >>> rounding_count(1), rounding_count(2) > rounding_count(1)
    (66, True)
    """
    k_total = 64
    for k in range(2, n + 1):
        worst = 0
        for h in range(7):
            rows, cols, a, b, _ = product_terms_fast(k - 1, h)
            per_entry = np.unique(rows * (delta_unchecked(k - 1) + 1) + cols, return_counts=True)[1].max()
            per_row = np.unique(rows, return_counts=True)[1].max()
            worst = max(worst, int(a.max() + b.max()) + 2 + int(per_entry) + int(per_row))
        k_total += worst + 1 + 7
    return k_total + 2


__all__ = ["PARTS", "ALPHA_TINY", "product_terms_fast", "factorization", "order_one_restriction",
           "restriction_matrices", "subdivision_matrices_float", "rounding_count"]
