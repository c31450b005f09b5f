"""Signs of the corner subdivision matrices for every n (docs/subdivision_for_all_n.md, §9).

Beyond the paper.  Notation of the proof page: S_u is the matrix of the corner sub-triangle u >= alpha/2 of
Omega^alpha (Q = S_u P), theta = alpha/4, c' = cos(theta), s' = sin(theta), T = tan(theta) in (0, 1).

**Theorem G (proof on the page).** The members of the full system G_{2n} (eq. G_system; (n + 1)^2 functions, the
centre among them) are G_{2n,2n-i,j} = sin^j(u/2) cos^{m-j}(u/2) sin^i(v/2) sin^{2n-i}(w/2), m = min(i, 2n - i),
0 <= j <= m.  Under the translation u = u' + alpha/2 the half angle u/2 becomes u'/2 + theta, and

    sin^j(u'/2 + theta) cos^{m-j}(u'/2 + theta) = c'^m sum_p P^m_{p,j}(T) sin^p(u'/2) cos^{m-p}(u'/2),
    P^m_{p,j}(T) = sum_{k + l = p} C(j, k) C(m - j, l) (-1)^l T^{j - k + l}                            (*)

so the column of S_u at G_{2n,2n-i,j} has its only non-zeros in the rows G_{2n,2n-i,p}, p = 0..m:

    S_u[G_{2n,2n-i,p}, G_{2n,2n-i,j}] = g_{2n,2n-i,j}(alpha) c'^m P^m_{p,j}(T) / g_{2n,2n-i,p}(alpha/2),

with every normalizing coefficient g > 0 (Corollary C of docs/question1_for_all_n.md).  So the entry has the sign of
the integer polynomial P^m_{p,j} at T = tan(alpha/4).  This module evaluates (*) exactly, classifies the signs of
P^m_{p,j} on 0 < T < 1 (i.e. for every alpha in (0, pi)) by exact real-root isolation, and computes the explicit
columns at an alpha with rational tan(alpha/8) for comparison with the library's S_u (an independent route: the
library multiplies M_{alpha/2} Rot M_alpha^{-1}).

>>> poly(2, 1, 0)  # the coefficient of sin cos in cos^2(x + theta), divided by c'^2: -2T
[0, -2]
>>> poly(1, 1, 0)  # sin(x) in cos(x + theta) = c' (cos x - T sin x)
[0, -1]
"""

from __future__ import annotations

from functools import cache
from math import comb

import numpy as np
import sympy as sp
from flint import fmpq

from paper_repro.core.domain import RationalAngle, rational_alpha
from paper_repro.core.labels import check_n, exponent_matrix
from paper_repro.core.normalization import coefficient_vector

_T = sp.Symbol("T")


def poly(m: int, p: int, j: int) -> list[int]:
    """The integer coefficients (ascending powers of T) of P^m_{p,j}(T), eq. (*) of the module docstring: the
    coefficient of sin^p(x) cos^{m-p}(x) in sin^j(x + theta) cos^{m-j}(x + theta), divided by cos^m(theta),
    T = tan(theta)."""
    if not (0 <= p <= m and 0 <= j <= m):
        raise ValueError(f"need 0 <= p, j <= m, got m = {m}, p = {p}, j = {j}")
    out = [0] * (m + 1)
    for k in range(max(0, p - (m - j)), min(j, p) + 1):
        ell = p - k
        out[j - k + ell] += comb(j, k) * comb(m - j, ell) * (-1) ** ell
    while len(out) > 1 and out[-1] == 0:
        out.pop()
    return out


def value(coeffs: list[int], t: fmpq) -> fmpq:
    """The polynomial with integer ``coeffs`` (ascending) at the rational ``t`` (Horner, exact)."""
    acc = fmpq(0)
    for a in reversed(coeffs):
        acc = acc * t + a
    return acc


@cache
def sign_class(m: int, p: int, j: int) -> tuple[str, tuple[str, ...]]:
    """The sign of P^m_{p,j} on the open interval 0 < T < 1 (every alpha in (0, pi)), exactly:
    ``('zero', ())``, ``('positive', ())``, ``('negative', ())`` (no real root in (0, 1) at all, the sign taken at
    T = 1/2), ``('changes', roots)`` (a root of odd multiplicity in (0, 1); the roots as exact algebraic numbers in
    T) or ``('touches', roots)`` (roots in (0, 1), all of even multiplicity)."""
    coeffs = poly(m, p, j)
    if all(a == 0 for a in coeffs):
        return "zero", ()
    q = sp.Poly(list(reversed(coeffs)), _T)
    inside = [r for r in q.real_roots() if 0 < r < 1] if q.degree() > 0 else []
    if not inside:
        return ("positive" if value(coeffs, fmpq(1, 2)) > 0 else "negative"), ()
    odd = any(inside.count(r) % 2 for r in set(inside))
    return ("changes" if odd else "touches"), tuple(str(r) for r in sorted(set(inside)))


def block_signs(m: int) -> dict[str, int]:
    """How many of the (m + 1)^2 entries (p, j) of the block of order m fall in each :func:`sign_class`."""
    out = {"zero": 0, "positive": 0, "negative": 0, "changes": 0, "touches": 0}
    for p in range(m + 1):
        for j in range(m + 1):
            out[sign_class(m, p, j)[0]] += 1
    return out


def g_column_signs(n: int) -> dict[str, int]:
    """The sign classes of the entries of S_u in the (n + 1)^2 columns G_{2n,2n-i,j} (Theorem G; the rows outside
    G_{2n,2n-i,*} are 0 there), summed over i = 0..2n: proven for every alpha in (0, pi) for this n."""
    n = check_n(n)
    total = {"zero": 0, "positive": 0, "negative": 0, "changes": 0, "touches": 0}
    for i in range(2 * n + 1):
        for key, count in block_signs(min(i, 2 * n - i)).items():
            total[key] += count
    # entries of S_u in the G columns outside the blocks are zero: delta_n rows, (n + 1)^2 columns
    from paper_repro.core.labels import delta

    total["zero"] += (n + 1) ** 2 * delta(n) - sum((min(i, 2 * n - i) + 1) ** 2 for i in range(2 * n + 1))
    return total


def hand_negative_pairs(m: int) -> list[tuple[int, int]]:
    """The m entries (p, j) of the block of order m that Corollary N proves negative by hand: (p, 0) for p odd
    (P = C(m, p) (-T)^p) and (m, j) for 1 <= j <= m with m - j odd (P = (-T)^{m-j})."""
    return [(p, 0) for p in range(1, m + 1, 2)] + [(m, j) for j in range(1, m + 1) if (m - j) % 2]


def negative_count_at(n: int, t: fmpq) -> int:
    """The number of negative entries of S_u in the G columns at tan(alpha/4) = ``t`` (exact; by Theorem G this is a
    lower bound of the number of negative entries of S_u, equal to it if every other column is non-negative, which
    is what the exact counts show at the sampled alpha, docs §9)."""
    n = check_n(n)
    count = 0
    for i in range(2 * n + 1):
        m = min(i, 2 * n - i)
        count += sum(1 for p in range(m + 1) for j in range(m + 1) if value(poly(m, p, j), t) < 0)
    return count


def g_index(n: int) -> dict[tuple[int, int], int]:
    """``(i, j) -> internal index`` of G_{2n,2n-i,j} (0 <= i <= 2n, 0 <= j <= min(i, 2n - i)), found by its exponent
    vector sin^j cos^{m-j}(u/2) sin^i(v/2) sin^{2n-i}(w/2) among the members of T_{2n} (several labels of the paper
    name one function; the function is what counts)."""
    rows = {tuple(int(x) for x in r): k for k, r in enumerate(exponent_matrix(n))}
    out = {}
    for i in range(2 * n + 1):
        m = min(i, 2 * n - i)
        for j in range(m + 1):
            out[(i, j)] = rows[(j, m - j, i, 0, 2 * n - i, 0)]
    return out


def explicit_g_columns(n: int, t8: fmpq) -> dict[tuple[int, int], dict[int, fmpq]]:
    """The columns of S_u at G_{2n,2n-i,j} from Theorem G, exactly, at tan(alpha/8) = ``t8`` (so that alpha and
    alpha/2 both have rational quarter-angle tangents): ``{internal column index: {internal row index: entry}}``
    (rows not listed are 0).  Uses only the normalizing coefficients (:func:`coefficient_vector`, the all-n formula)
    and eq. (*)."""
    alpha, half = rational_alpha(2 * t8 / (1 - t8 * t8)), rational_alpha(t8)
    return explicit_g_columns_at(n, alpha, half)


def explicit_g_columns_at(n: int, alpha: RationalAngle, half: RationalAngle) -> dict[tuple[int, int], dict[int, fmpq]]:
    """:func:`explicit_g_columns` for given RationalAngles alpha and ``half`` = alpha/2 (checked)."""
    cq = half.cos_half  # cos(alpha/4)
    t = alpha.t  # tan(alpha/4)
    if half.sin_half / cq != t:
        raise ValueError("half must be alpha/2")
    big = coefficient_vector(n, alpha, "exact")
    small = coefficient_vector(n, half, "exact")
    idx = g_index(n)
    out: dict[tuple[int, int], dict[int, fmpq]] = {}
    for (i, j), col in idx.items():
        m = min(i, 2 * n - i)
        entries = {}
        for p in range(m + 1):
            v = value(poly(m, p, j), t)
            if v != 0:
                row = idx[(i, p)]
                entries[row] = big[col] * cq ** m * v / small[row]
        out[(i, j)] = entries
    return out


def witness_entry(n: int, c: fmpq) -> fmpq:
    """The witness of Corollary W: S_u[G_{2n,2n-1,1}, G_{2n,2n-1,0}] = c (c - 1) / (2^{n+1} (1 + c)^n
    ((n - 1) c + n)) for n >= 2 and S_u[R_{2,1,1}, G_{2,1,0}] = -c / (2 (1 + c)) for n = 1, c = cos(alpha/2)."""
    n = check_n(n)
    if n == 1:
        return -c / (2 * (1 + c))
    return c * (c - 1) / (2 ** (n + 1) * (1 + c) ** n * ((n - 1) * c + n))


def as_array(columns: dict[tuple[int, int], dict[int, fmpq]], n: int, size: int) -> np.ndarray:
    """The explicit columns as a ``(size, (n+1)^2)`` object array (columns in the order of :func:`g_index`)."""
    keys = list(g_index(n))
    out = np.empty((size, len(keys)), dtype=object)
    out[:] = fmpq(0)
    for k, key in enumerate(keys):
        for row, v in columns[key].items():
            out[row, k] = v
    return out


__all__ = ["poly", "value", "sign_class", "block_signs", "g_column_signs", "hand_negative_pairs",
           "negative_count_at", "g_index", "explicit_g_columns", "explicit_g_columns_at", "witness_entry", "as_array"]
