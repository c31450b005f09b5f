"""The limit alpha -> 0 (Question que:limiting_case, Fig. limit_cases_n_1_2_3).

With u = alpha x, v = alpha y, w = alpha z (x + y + z = 1) a function of level j of T_{2n} has
sine exponents (a, b, c) for (u, v, w) with a + b + c = 2n + j, and its coefficient is
P(cos(alpha/2)) / sin^{2n+j}(alpha/2) (:mod:`paper_repro.theory.closed_forms`).  Since
sin(alpha x/2) / sin(alpha/2) -> x and cos -> 1::

    lim T-bar_f(alpha x, alpha y, alpha z) = P_f(1) x^a y^b z^c,

a monomial of degree m = 2n + j; the centre vanishes exactly when P(1) = 0.  Multiplying by
(x + y + z)^{N - m} writes every limit in the Bernstein basis P^N_{d,e,f} of degree N = max m with
non-zero limit; :func:`conversion_matrix` gives the resulting control-net conversion.
"""

from __future__ import annotations

import numpy as np
from flint import fmpq

from paper_repro.core.labels import delta, exponents, united_system
from paper_repro.core.nets import check_net
from paper_repro.core.normalization import orbits
from paper_repro.core.ordered import ordered_matmul
from paper_repro.theory.closed_forms import closed_forms_cached
from paper_repro.theory.limit_formula import limit_terms_formula, multinomial
from paper_repro.util.limits import MAX_N_BEZIER_LIMIT, check_int


def limit_terms(n: int) -> list[tuple[fmpq, tuple[int, int, int]]]:
    """For each function of T_{2n} (internal order): (P_f(1), (a, b, c)) -- the limit is P_f(1) x^a y^b z^c."""
    forms = closed_forms_cached(n)
    coef = {}
    for rep, members in orbits(n):
        for k in members:
            coef[k] = forms[rep.coefficient].numerator(fmpq(1))
    out = []
    for k, lab in enumerate(united_system(n)):
        e = exponents(lab)
        out.append((coef[k], (e[0], e[2], e[4])))
    return out


def _terms(n: int, source: str) -> list[tuple[fmpq, tuple[int, int, int]]]:
    if source == "closed_forms":
        return limit_terms(n)
    if source == "formula":
        return limit_terms_formula(n)
    raise ValueError(f"source must be 'closed_forms' or 'formula', got {source!r}")


def limit_degree(n: int, source: str = "closed_forms") -> int:
    """N = the largest degree with a non-zero limit."""
    return max(sum(t) for c, t in _terms(n, source) if c != 0)


def bernstein_index(t: tuple[int, int, int]) -> str:
    return f"P^{sum(t)}_{{{t[0]},{t[1]},{t[2]}}}"


def bezier_indices(N: int) -> list[tuple[int, int, int]]:
    """Indices (d, e, f), d + e + f = N, of the Bezier net, d descending then e ascending."""
    return [(d, e, N - d - e) for d in range(N, -1, -1) for e in range(0, N - d + 1)]


def conversion_matrix(n: int, source: str = "closed_forms") -> tuple[list[tuple[int, int, int]], list[list[fmpq]]]:
    """Exact weights W with Bezier point p_{def} = sum_f W[def][f] (control point f), degree N.

    Each limit L_f x^a y^b z^c (x+y+z)^{N-m} is expanded; its coefficient of x^d y^e z^f divided by
    the multinomial N!/(d!e!f!) is the weight of control point f in p_{def}:
    ``W[r][f] = L_f multinomial(N - m; r - s_f) / multinomial(N; r)``.  ``source="closed_forms"`` takes
    L_f = P_f(1) from the closed forms (proven for every alpha, n <= 30); ``source="formula"`` from the limit
    formula, proven for every n (docs/limit_for_all_n.md).
    """
    terms = _terms(n, source)
    N = max(sum(t) for c, t in terms if c != 0)
    idx = bezier_indices(N)
    pos = {t: k for k, t in enumerate(idx)}
    w = [[fmpq(0)] * delta(n) for _ in idx]
    for f, (c, (a, b, cc)) in enumerate(terms):
        if c == 0:
            continue
        k = N - (a + b + cc)
        for i in range(k + 1):
            for j in range(k - i + 1):
                l_ = k - i - j
                mono = (a + i, b + j, cc + l_)
                coeff = c * multinomial(k, (i, j, l_))
                w[pos[mono]][f] += coeff / multinomial(N, mono)
    return idx, w


def conversion_is_convex(n: int, source: str = "closed_forms") -> bool:
    """Every Bezier point of the limit is a convex combination: weights >= 0, each row summing to 1 (exact)."""
    _, w = conversion_matrix(n, source)
    return all(x >= 0 for row in w for x in row) and all(sum(row) == 1 for row in w)


def bezier_limit(net, n: int) -> tuple[int, dict[tuple[int, int, int], np.ndarray]]:
    """Control net of the Bezier triangle that the order-n patch with ``net`` tends to as alpha -> 0.

    Returns ``(N, {(d, e, f): point})``, ``p_{def}`` in the paper's notation (d for u/x, e for v/y, f for w/z);
    N = 3n - 1 for every n (the weights come from the limit formula, proven for every n: claim
    ``limit_formula``, docs/limit_for_all_n.md).
    """
    n = check_int(n, "n", 1, MAX_N_BEZIER_LIMIT, why="exact conversion weights, O(n^4) rational operations")
    arr = check_net(net, n)
    idx, w = conversion_matrix(n, "formula")
    wf = np.array([[float(x) for x in row] for row in w])
    pts = ordered_matmul(wf, arr)  # the same bits on every CPU (not BLAS)
    return sum(idx[0]), {t: pts[k] for k, t in enumerate(idx)}


def bernstein_eval(N: int, points_xyz: np.ndarray, bez: dict) -> np.ndarray:
    """Evaluate a degree-N Bezier triangle {(d,e,f): point} at barycentric points (x, y, z)."""
    xyz = np.asarray(points_xyz, dtype=np.float64)
    out = 0
    for (d, e, f), p in bez.items():
        b = multinomial(N, (d, e, f)) * xyz[:, 0] ** d * xyz[:, 1] ** e * xyz[:, 2] ** f
        out = out + b[:, None] * np.asarray(p)[None, :]
    return out
