"""Closed formula of the alpha -> 0 limit factors (Question que:limiting_case), proven for every n.

With u = alpha x, v = alpha y, w = alpha z (x + y + z = 1), the normalized function
``R-bar_{2n,2n-i,j}`` tends to ``L x^{2n-i} y^j z^i`` (:mod:`paper_repro.theory.limits`; G and B by the
cyclic rule), with

    L_{n,i,j} = (2n+j)! / ((2n-i)! j! i!) * rho,   rho = 1 (j = 0), (2n-j)/(2n+j) (i = j or i = 2n-j, j >= 1),
                                                 2n/(2n+j) (j < i < 2n-j),   and L = 0 for the centre (i = j = n),

:func:`limit_factor`.  The written proof for every n is ``docs/limit_for_all_n.md``; its four lemmas are
finite statements per n, checked exactly here (:func:`limit_checks`):

1. the sine-exponent triples s of T_{2n} are distinct and are exactly the s in N^3 whose two largest entries
   sum to 2n (:func:`exponent_set_characterised`);
2. uniformly, ``L_s = multinomial(s) - sum_{k: s_k = min s} multinomial(s - e_k)`` (:func:`uniform_factor`);
3. the telescoping identity ``Q_j (x+y+z) = P_{j+1} - B_{j+1}`` of Pascal's rule (:func:`telescoping_holds`),
   from which (B) ``sum_f L_f x^a y^b z^c = 1`` on the simplex follows (also checked directly,
   :func:`partition_of_unity_holds`);
4. (C) the delta_n limit monomials (centre included) are linearly independent on the simplex (written proof by
   peeling the edges; checked as the full rank modulo p of their homogenised coefficient matrix,
   :func:`monomials_rank`).

The theorem then follows by continuity and needs neither the paper's independence theorem nor the closed
forms: the scaled collocation matrix of T_{2n}^alpha tends to the non-singular one of the limit monomials.

>>> limit_factor(2, 2, 1), limit_factor(2, 1, 1), limit_factor(2, 2, 2)
(24, 12, 0)
>>> uniform_factor((3, 1, 1)) == limit_factor(2, 1, 1)
True
"""

from __future__ import annotations

from collections import defaultdict
from math import comb, factorial

from flint import fmpq, fmpq_mpoly_ctx, nmod_mat

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
    """Like :func:`paper_repro.theory.limits.limit_terms` (internal order), from the formula."""
    out = []
    for lab in united_system(n):
        e = exponents(lab)
        out.append((limit_factor(n, lab.i, lab.j), (e[0], e[2], e[4])))
    return out


def multinomial(m: int, t: tuple[int, int, int]) -> int:
    """The multinomial coefficient m! / (t0! t1! t2!)."""
    return factorial(m) // (factorial(t[0]) * factorial(t[1]) * factorial(t[2]))


def _multinomial(s: tuple[int, int, int]) -> int:
    """:func:`multinomial` of ``s``, and 0 when an entry is negative."""
    return 0 if min(s) < 0 else multinomial(sum(s), s)


def uniform_factor(s: tuple[int, int, int]) -> fmpq:
    """Lemma 2: ``L_s = multinomial(s) - sum over the minimal entries k of multinomial(s - e_k)``
    (= multinomial(s) (|s| - t m) / |s| with m = min s attained t times)."""
    m = min(s)
    total = _multinomial(s)
    for k in range(3):
        if s[k] == m:
            total -= _multinomial(tuple(v - (q == k) for q, v in enumerate(s)))
    return fmpq(total)


def exponent_set_characterised(n: int) -> bool:
    """Lemma 1: the exponent triples of T_{2n} (from the paper's formulas, :mod:`paper_repro.core.labels`) are
    distinct and are exactly {s in N^3 : the two largest entries of s sum to 2n}."""
    got = [t for _, t in limit_terms_formula(n)]
    want = {(a, b, c) for a in range(2 * n + 1) for b in range(2 * n + 1) for c in range(2 * n + 1)
            if a + b + c - min(a, b, c) == 2 * n}
    return len(set(got)) == len(got) and set(got) == want


def uniform_factor_agrees(n: int) -> bool:
    """Lemma 2 for one n: the case-wise :func:`limit_factor` equals :func:`uniform_factor` on every function."""
    return all(c == uniform_factor(t) for c, t in limit_terms_formula(n))


def _poly_sum(terms) -> dict[tuple[int, int, int], int]:
    out: dict[tuple[int, int, int], int] = defaultdict(int)
    for key, v in terms:
        out[key] += v
    return {k: v for k, v in out.items() if v != 0}


def _layers(n: int, j: int) -> dict[str, dict[tuple[int, int, int], int]]:
    """The homogeneous polynomials of degree 2n + j of the proof of Lemma 3 (as {exponent: coefficient}):
    P_j (min s >= j), Q_j (min s >= j + 1), B_j (min s = j, each minimal entry k contributes multinomial(s - e_k))."""
    d = 2 * n + j
    triples = [(a, b, d - a - b) for a in range(d + 1) for b in range(d + 1 - a)]
    p = _poly_sum((s, _multinomial(s)) for s in triples if min(s) >= j)
    q = _poly_sum((s, _multinomial(s)) for s in triples if min(s) >= j + 1)
    b = _poly_sum((s, _multinomial(tuple(v - (t == k) for t, v in enumerate(s))))
                  for s in triples if min(s) == j for k in range(3) if s[k] == j)
    return {"P": p, "Q": q, "B": b}


def telescoping_holds(n: int) -> bool:
    """Lemma 3 for one n: ``Q_j (x+y+z) = P_{j+1} - B_{j+1}`` exactly for j = 0..n, and the ends
    ``P_0 = (x+y+z)^{2n}``, ``B_0 = 0``, ``P_{n+1} = B_{n+1} = 0``."""
    layers = [_layers(n, j) for j in range(n + 2)]
    for j in range(n + 1):
        lhs = _poly_sum(((s[0] + (k == 0), s[1] + (k == 1), s[2] + (k == 2)), v)
                        for s, v in layers[j]["Q"].items() for k in range(3))
        rhs = _poly_sum(list(layers[j + 1]["P"].items()) + [(s, -v) for s, v in layers[j + 1]["B"].items()])
        if lhs != rhs:
            return False
    d = 2 * n
    sigma = {(a, b, d - a - b): _multinomial((a, b, d - a - b)) for a in range(d + 1) for b in range(d + 1 - a)}
    return (layers[0]["P"] == sigma and not layers[0]["B"] and not layers[n + 1]["P"] and not layers[n + 1]["B"])


def _homogenised_poly(s: tuple[int, int, int], top: int) -> dict[tuple[int, int], int]:
    """``x^a y^b z^c (x+y+z)^{top-a-b-c}`` as {(power of x, power of y): integer coefficient}."""
    a, b, c = s
    k = top - a - b - c
    poly: dict[tuple[int, int], int] = {}
    for p in range(k + 1):
        for q in range(k - p + 1):
            poly[(a + p, b + q)] = factorial(k) // (factorial(p) * factorial(q) * factorial(k - p - q))
    return poly


def _homogenised(n: int) -> list[dict[tuple[int, int], int]]:
    """``x^a y^b z^c (x+y+z)^{3n-a-b-c}`` as {(power of x, power of y): integer coefficient}, per function."""
    return [_homogenised_poly(t, 3 * n) for _, t in limit_terms_formula(n)]


def partition_of_unity_holds(n: int) -> bool:
    """(B): sum_f L_f x^a y^b z^c (x+y+z)^{3n-m} == (x+y+z)^{3n} (m = a + b + c), exactly (flint polynomials in
    x, y, z; the functions of one degree m are summed before the multiplication by the power of x + y + z)."""
    top = 3 * n
    ctx = fmpq_mpoly_ctx.get(("x", "y", "z"))
    sigma = sum(ctx.gens(), ctx.from_dict({}))
    by_power: dict[int, dict[tuple[int, int, int], fmpq]] = defaultdict(dict)
    for coef, s in limit_terms_formula(n):
        if coef != 0:
            if sum(s) > top:
                return False
            part = by_power[top - sum(s)]
            part[s] = part.get(s, fmpq(0)) + coef
    total = sum((sigma ** k * ctx.from_dict(part) for k, part in by_power.items()), ctx.from_dict({}))
    return total == sigma ** top


def _full_rank(exps: list[tuple[int, int, int]], top: int) -> int:
    """Rank modulo :data:`PRIME` of the coefficient matrix of ``x^s (x+y+z)^{top-|s|}``, s in ``exps`` (one
    Gaussian elimination of the whole matrix)."""
    polys = [_homogenised_poly(s, top) for s in exps]
    keys = sorted({k for p in polys for k in p})
    if not polys or not keys:
        return 0
    col = {k: c for c, k in enumerate(keys)}
    entries = [0] * (len(polys) * len(keys))
    for r, p in enumerate(polys):
        for k, v in p.items():
            entries[r * len(keys) + col[k]] = v % PRIME
    return nmod_mat(len(polys), len(keys), entries, PRIME).rank()


def _boundary_rank(exps: list[tuple[int, int, int]], top: int) -> int:
    """Rank modulo :data:`PRIME` of the rows ``x^s (x+y+z)^{top-|s|}`` restricted to the boundary columns (the
    monomials of degree ``top`` with an exponent 0)."""
    keys = [(a, b) for a in range(top + 1) for b in range(top + 1 - a) if min(a, b, top - a - b) == 0]
    col = {k: c for c, k in enumerate(keys)}
    entries = [0] * (len(exps) * len(keys))
    for r, s in enumerate(exps):
        k = top - sum(s)
        for i in range(3):
            if s[i] == 0:  # the monomials of x^s (x+y+z)^k free of variable i: (x_{i+1} + x_{i+2})^k x^s
                for p in range(k + 1):
                    e = list(s)
                    e[(i + 1) % 3] += p
                    e[(i + 2) % 3] += k - p
                    entries[r * len(keys) + col[(e[0], e[1])]] = comb(k, p) % PRIME
    return nmod_mat(len(exps), len(keys), entries, PRIME).rank()


def peeled_rank(exps: list[tuple[int, int, int]], top: int) -> int:
    """Rank modulo :data:`PRIME` of the coefficient matrix of ``x^s (x+y+z)^{top-|s|}`` (s in ``exps``, all
    |s| <= ``top``) in the monomials of degree ``top``: the same number as one elimination of the whole matrix
    (:func:`_full_rank`), computed by peeling the boundary as the proof of Lemma 4 does.

    Exact linear algebra over F_p: let A be the rows with min s = 0 and B the others.  Every row of B is divisible
    by xyz, i.e. lies in the span W of the interior monomials (all exponents >= 1), and the quotient by W keeps
    exactly the boundary columns.  If A restricted to the boundary columns has full row rank |A| (one small
    |A| x 3top elimination), a relation among all rows projects to a relation among A modulo W, so its A-part is 0:
    rank(A + B) = |A| + rank(B).  Dividing B by xyz maps monomials to monomials injectively, so rank(B) is the rank
    of the rows s - (1, 1, 1) at degree top - 3; recurse.  When a boundary block is not of full row rank the
    remaining matrix is eliminated whole, so the result is always the rank of the full matrix modulo p.
    For the delta_n limit monomials the blocks at top = 3k have 6k rows (Lemma 1), so the cost is O(n^4) instead of
    the O(n^6) of the whole elimination.

    >>> exps = [t for _, t in limit_terms_formula(3)]
    >>> peeled_rank(exps, 9) == _full_rank(exps, 9) == 37
    True
    >>> peeled_rank([(1, 0, 0), (1, 0, 0), (0, 1, 1)], 3), _full_rank([(1, 0, 0), (1, 0, 0), (0, 1, 1)], 3)
    (2, 2)
    """
    if any(min(s) < 0 or sum(s) > top for s in exps):
        raise ValueError(f"exps: every exponent triple must be >= 0 with sum <= top = {top}")
    done = 0
    while exps:
        a = [s for s in exps if min(s) == 0]
        b = [(s[0] - 1, s[1] - 1, s[2] - 1) for s in exps if min(s) > 0]
        if a and _boundary_rank(a, top) != len(a):
            return done + _full_rank(exps, top)
        done += len(a)
        exps, top = b, top - 3
    return done


def monomials_rank(n: int) -> int:
    """(C): rank modulo :data:`PRIME` of the delta_n homogenised limit monomials (a lower bound of the rank over Q),
    computed by :func:`peeled_rank`."""
    return peeled_rank([t for _, t in limit_terms_formula(n)], 3 * n)


def limit_checks(n: int) -> dict:
    """Lemmas 1-3, (B) and (C) for one n."""
    d = len(united_system(n))
    rank = monomials_rank(n)
    return {"n": n, "exponent_set": exponent_set_characterised(n), "uniform_factor": uniform_factor_agrees(n),
            "telescoping": telescoping_holds(n),
            "partition_of_unity": partition_of_unity_holds(n), "monomials_rank": rank, "delta_n": d,
            "monomials_independent": rank == d, "degree": max(sum(t) for c, t in limit_terms_formula(n) if c != 0)}


def conversion_weights_nonnegative(n: int) -> bool:
    """Every weight of the conversion to the Bernstein basis of degree 3n - 1 is >= 0 (from the formula:
    W = L_f * multinomial(k; p, q, r) / multinomial(3n-1; d, e, f) with L_f >= 0)."""
    return all(c >= 0 for c, _ in limit_terms_formula(n))
