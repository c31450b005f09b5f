"""Closed formula of the alpha -> 0 limit factors (Question que:limiting_case) and what it rests on.

With u = alpha x, v = alpha y, w = alpha z (x + y + z = 1), the normalized function
``R-bar_{2n,2n-i,j}`` tends to ``L x^{2n-i} y^j z^i`` (:mod:`paper_repro.core.limits`; G and B by the
cyclic rule).  The factor found from the proven closed forms (``L = P(1)``) is, for every n checked,

    L_{n,i,j} = (2n+j)! / ((2n-i)! j! i!) * rho,   rho = 1 (j = 0), (2n-j)/(2n+j) (i = j or i = 2n-j, j >= 1),
                                                 2n/(2n+j) (j < i < 2n-j),   and L = 0 for the centre (i = j = n),

:func:`limit_factor`.  Three facts make it a theorem for a given n (:func:`limit_checks`):

(A) T_{2n}^alpha is linearly independent for all small alpha (paper, Theorem joint_systems_linear_independence;
    our rank certificates show it off a finite set of alpha for n <= 40);
(B) ``sum_f L_f x^a y^b z^c = 1`` on the simplex (an exact polynomial identity, homogenised to degree 3n);
(C) the delta_n limit monomials x^a y^b z^c (centre included) are linearly independent on the simplex
    (full rank modulo p of their homogenised coefficient matrix).

Proof for that n, given (A): with scaled coefficients y_f = r_f sin^{2n+j}(alpha/2) the partition of unity
reads sum_f y_f(alpha) [f(alpha x, alpha y, alpha z) / sin^{2n+j}(alpha/2)] = 1, whose collocation matrix at
delta_n points of the simplex tends to that of the limit monomials, non-singular by (C); so y(alpha) tends to
the unique solution of sum_f y_f x^a y^b z^c = 1, which is L by (B).  (B) and (C) are finite computations
per n, much cheaper than the closed forms, and are checked far beyond them; for *all* n they are open.

>>> limit_factor(2, 2, 1), limit_factor(2, 1, 1), limit_factor(2, 2, 2)
(24, 12, 0)
"""

from __future__ import annotations

from collections import defaultdict
from math import comb, factorial

from flint import fmpq, nmod_mat

from paper_repro.core.labels import exponents, united_system
from paper_repro.util.validation import check_n

PRIME = 2**31 - 1


def limit_factor(n: int, i: int, j: int) -> fmpq:
    """L_{n,i,j} of ``R_{2n,2n-i,j}`` (the formula above; any i = j..2n-j)."""
    n = check_n(n)
    if not (0 <= j <= n and j <= i <= 2 * n - j):
        raise ValueError(f"(i, j) = ({i}, {j}) is not an index of R_{{2n}} for n = {n}")
    if i == j == n:
        return fmpq(0)
    multi = fmpq(factorial(2 * n + j), factorial(2 * n - i) * factorial(j) * factorial(i))
    if j == 0:
        return multi
    if i in (j, 2 * n - j):
        return multi * fmpq(2 * n - j, 2 * n + j)
    return multi * fmpq(2 * n, 2 * n + j)


def limit_terms_formula(n: int) -> list[tuple[fmpq, tuple[int, int, int]]]:
    """Like :func:`paper_repro.core.limits.limit_terms` (internal order), from the formula."""
    out = []
    for lab in united_system(n):
        e = exponents(lab)
        out.append((limit_factor(n, lab.i, lab.j), (e[0], e[2], e[4])))
    return out


def _homogenised(n: int) -> list[dict[tuple[int, int], int]]:
    """``x^a y^b z^c (x+y+z)^{3n-a-b-c}`` as {(power of x, power of y): integer coefficient}, per function."""
    top = 3 * n
    out = []
    for _, (a, b, c) in limit_terms_formula(n):
        k = top - a - b - c
        poly: dict[tuple[int, int], int] = {}
        for p in range(k + 1):
            for q in range(k - p + 1):
                poly[(a + p, b + q)] = factorial(k) // (factorial(p) * factorial(q) * factorial(k - p - q))
        out.append(poly)
    return out


def partition_of_unity_holds(n: int) -> bool:
    """(B): sum_f L_f x^a y^b z^c (x+y+z)^{3n-m} == (x+y+z)^{3n}, exactly."""
    total: dict[tuple[int, int], fmpq] = defaultdict(lambda: fmpq(0))
    for (coef, _), poly in zip(limit_terms_formula(n), _homogenised(n)):
        if coef != 0:
            for key, v in poly.items():
                total[key] += coef * v
    top = 3 * n
    target = {(p, q): comb(top, p) * comb(top - p, q) for p in range(top + 1) for q in range(top - p + 1)}
    return all(total.get(key, 0) == v for key, v in target.items()) and all(
        v == 0 for key, v in total.items() if key not in target)


def monomials_rank(n: int) -> int:
    """(C): rank modulo :data:`PRIME` of the delta_n homogenised limit monomials (a lower bound of the rank over Q)."""
    polys = _homogenised(n)
    keys = sorted({k for p in polys for k in p})
    col = {k: c for c, k in enumerate(keys)}
    entries = [0] * (len(polys) * len(keys))
    for r, p in enumerate(polys):
        for k, v in p.items():
            entries[r * len(keys) + col[k]] = v % PRIME
    return nmod_mat(len(polys), len(keys), entries, PRIME).rank()


def limit_checks(n: int) -> dict:
    """(B) and (C) for one n."""
    d = len(united_system(n))
    rank = monomials_rank(n)
    return {"n": n, "partition_of_unity": partition_of_unity_holds(n), "monomials_rank": rank, "delta_n": d,
            "monomials_independent": rank == d, "degree": max(sum(t) for c, t in limit_terms_formula(n) if c != 0)}


def conversion_weights_nonnegative(n: int) -> bool:
    """Every weight of the conversion to the Bernstein basis of degree 3n - 1 is >= 0 (from the formula:
    W = L_f * multinomial(k; p, q, r) / multinomial(3n-1; d, e, f) with L_f >= 0)."""
    return all(c >= 0 for c, _ in limit_terms_formula(n))
