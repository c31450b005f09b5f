"""Joins of two triangular trigonometric patches along a shared edge (beyond the paper).

Edges are named by the variable that vanishes on them: ``'v'`` is the edge v = 0 of Omega^alpha, parametrized by
t = u from the corner w = alpha (t = 0) to the corner u = alpha (t = alpha); ``'u'`` (u = 0) by t = w and ``'w'``
(w = 0) by t = v -- the parametrizations of the paper's boundary curves (Section sec:applications): along edge
``'v'`` the patch is ``sum_k A_{2n,k}(t) r_{2n,k,0}`` (eq. boundary_property_1).

* **The boundary row**: the 2n + 1 members that do not vanish on the edge (sine exponent 0 in the vanishing
  variable), row k the one restricted to ``A_{2n,k}``; **the second row**: the 2n + 1 members with sine exponent 1
  in it (:func:`edge_rows`).  Every other member vanishes to second order on the edge.
* **Cross-boundary derivative and tangent**: along the edge, the derivative into the patch (direction (0, 1, -1)
  for ``'v'``: v grows, u fixed) and the derivative along the edge (direction (1, 0, -1)) are trigonometric
  polynomials of degree n in t (V_n is closed under differentiation), so ``sum_k A_{2n,k}(t) d_k`` and
  ``sum_k A_{2n,k}(t) t_k`` with d = D P, t = T P linear in the net (:func:`edge_derivatives`, collocation at
  2n + 1 edge points verified at 3 more by :func:`~paper_repro.core.collocation.collocate`).  D involves only the
  boundary and second rows; T only the boundary row.
* **The neighbour on the point-reflected side**: a patch whose domain is the image of Omega^alpha under the point
  reflection through the edge's midpoint (for ``'v'``: (u, v, w) -> (alpha - u, -v, alpha - w); the lower and upper
  pieces of the torus and the cyclide of Section 6 are such neighbours).  Its edge parameter runs backwards, so
  (A_{2n,k}(alpha - t) = A_{2n,2n-k}(t)):

  - C0 holds iff its boundary row is ours reversed: P'_{2n-k} = P_k (the same alpha);
  - C1 (in the common parameter plane) iff moreover d'_{2n-k} = -d_k;
  - G1 with constant multipliers (sufficient): d'_{2n-k} = -lambda d_k + mu t_k, lambda > 0.

:func:`c1_second_row` builds the neighbour's second row for C1 (or G1 with given lambda, mu) from its boundary row
(the second-row block of D is invertible: checked, ``ArithmeticError`` otherwise); :func:`edge_join_error` reports
the C0, C1 and G1 defects.  For whole models (the torus, the cyclide) :func:`paper_repro.surfaces.models.join_error`
measures the C0 gaps at sampled points of every shared edge.

>>> import numpy as np
>>> from paper_repro.core.labels import delta
>>> net = np.random.default_rng(0).normal(size=(delta(1), 3))
>>> other = c1_second_row(net, 1, 1.0, "v", np.zeros_like(net))
>>> err = edge_join_error(net, other, 1, 1.0, "v")
>>> bool(err["C0"] < 1e-12 and err["C1"] < 1e-10)
True
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from paper_repro.core.collocation import collocate
from paper_repro.core.context import FloatContext
from paper_repro.core.derivatives_basis import basis_derivative
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.nets import check_net
from paper_repro.core.univariate import A
from paper_repro.util.limits import check_int
from paper_repro.util.validation import check_alpha, parse_alpha

#: Edges by the variable that vanishes on them.
EDGES = ("u", "v", "w")
#: (parameter variable, vanishing variable, other variable) of each edge: the parametrizations of the paper's
#: boundary curves (R along v = 0 with t = u, G along u = 0 with t = w, B along w = 0 with t = v).
ROLES = {"v": (0, 1, 2), "u": (2, 0, 1), "w": (1, 2, 0)}
#: Largest order accepted (the univariate collocation in float64 loses about 2n bits; measured fine to n = 8).
MAX_N_JOINS = 8


def check_edge(edge: object) -> str:
    """``edge`` if it is one of :data:`EDGES`, else ``TypeError``/``ValueError`` naming ``edge``."""
    if not isinstance(edge, str):
        raise TypeError(f"edge must be one of {list(EDGES)}, got {edge!r} of type {type(edge).__name__}")
    if edge not in EDGES:
        raise ValueError(f"edge must be one of {list(EDGES)} (the variable that vanishes on it), got {edge!r}")
    return edge


def _unit(var: int, sign: int) -> np.ndarray:
    out = np.zeros(3, dtype=np.int64)
    out[var] = sign
    return out


def directions(edge: str) -> tuple[tuple[int, int, int], tuple[int, int, int]]:
    """(cross-boundary direction, tangent direction) of ``edge``: +vanishing - other, +parameter - other.

    >>> directions("v")
    ((0, 1, -1), (1, 0, -1))
    """
    p, z, o = ROLES[check_edge(edge)]
    cross = _unit(z, 1) + _unit(o, -1)
    tangent = _unit(p, 1) + _unit(o, -1)
    return tuple(int(x) for x in cross), tuple(int(x) for x in tangent)  # type: ignore[return-value]


@lru_cache(maxsize=128)
def edge_rows(n: int, edge: str) -> tuple[np.ndarray, np.ndarray]:
    """Internal indices of the boundary row (2n + 1 members, ordered by k = their sine exponent in the parameter
    variable, so that row k restricts to a multiple of A_{2n,k}) and of the second row (the 2n + 1 members with sine
    exponent 1 in the vanishing variable, ordered by their sine exponent in the parameter variable, then in the
    other one)."""
    p, z, o = ROLES[check_edge(edge)]
    exps = exponent_matrix(n)
    first = [f for f in range(len(exps)) if exps[f, 2 * z] == 0]
    second = [f for f in range(len(exps)) if exps[f, 2 * z] == 1]
    first.sort(key=lambda f: exps[f, 2 * p])
    second.sort(key=lambda f: (exps[f, 2 * p], exps[f, 2 * o]))
    if len(first) != 2 * n + 1 or len(second) != 2 * n + 1 or \
            [int(exps[f, 2 * p]) for f in first] != list(range(2 * n + 1)):  # pragma: no cover - labels' layout
        raise AssertionError("the boundary rows of T_{2n} are not as the boundary property says")
    b, s = np.array(first), np.array(second)
    b.setflags(write=False)
    s.setflags(write=False)
    return b, s


def edge_points(alpha: float, edge: str, ts: np.ndarray) -> np.ndarray:
    """The points of ``edge`` at parameters ``ts`` as ``(P, 3)`` (u, v, w)."""
    p, z, o = ROLES[check_edge(edge)]
    pts = np.zeros((len(ts), 3))
    pts[:, p] = ts
    pts[:, o] = alpha - np.asarray(ts)
    return pts


@lru_cache(maxsize=64)
def _edge_derivatives(n: int, alpha: float, edge: str) -> tuple[np.ndarray, np.ndarray]:
    cross, tangent = directions(edge)
    m = 2 * n + 1
    ctx = FloatContext()

    def system(k: int):
        # Chebyshev-like interior parameters (a different set per attempt), then 3 verification points
        count = m + 3
        ts = alpha * (1 - np.cos(np.pi * (np.arange(count) + 0.5 + 0.1 * k) / (count + 0.2 * k))) / 2
        ts = np.r_[ts[::2], ts[1::2]]  # spread the collocation points over the edge, the rest verify
        pts = edge_points(alpha, edge, ts)
        rhs = np.c_[basis_derivative(n, alpha, pts, cross), basis_derivative(n, alpha, pts, tangent)]
        return A(n, alpha, ts), rhs

    sol = collocate(ctx, system, m, what=f"edge derivatives of order {n} along edge {edge!r}").solution
    d, t = sol[:, :delta(n)], sol[:, delta(n):]
    b, s = edge_rows(n, edge)
    keep_d = np.zeros(delta(n), dtype=bool)
    keep_d[np.r_[b, s]] = True
    keep_t = np.zeros(delta(n), dtype=bool)
    keep_t[b] = True
    scale = max(1.0, float(np.abs(sol).max()))
    if np.abs(d[:, ~keep_d]).max(initial=0.0) > 1e-9 * scale or np.abs(t[:, ~keep_t]).max(initial=0.0) > 1e-9 * scale:
        raise ArithmeticError(f"edge {edge!r}: a member beyond the second row has a cross-boundary derivative")
    d[:, ~keep_d] = 0.0  # exact zeros (second-order vanishing on the edge)
    t[:, ~keep_t] = 0.0
    d.setflags(write=False)
    t.setflags(write=False)
    return d, t


def _check(n, alpha, edge) -> tuple[int, float, str]:
    n = check_int(n, "n", 1, MAX_N_JOINS, why="the univariate collocation of the edge coefficients in float64")
    a = check_alpha(parse_alpha(alpha))
    return n, a, check_edge(edge)


def edge_derivatives(n: int, alpha, edge: str = "v") -> tuple[np.ndarray, np.ndarray]:
    """``(D, T)``, each ``(2n + 1, delta_n)``: the cross-boundary derivative of a patch with net P along ``edge`` is
    ``sum_k A_{2n,k}(t) (D P)_k`` and its derivative along the edge ``sum_k A_{2n,k}(t) (T P)_k`` (float64, from the
    collocation of :func:`~paper_repro.core.derivatives_basis.basis_derivative` at 2n + 1 edge points, verified at
    3 more).

    >>> d, t = edge_derivatives(1, 1.0, "v")
    >>> d.shape, bool(abs(t.sum(axis=1)).max() < 1e-12)  # a constant patch has no derivative
    ((3, 7), True)
    """
    n, a, edge = _check(n, alpha, edge)
    d, t = _edge_derivatives(n, a, edge)
    return d.copy(), t.copy()


def _reverse(rows: np.ndarray) -> np.ndarray:
    return rows[::-1]


def c1_second_row(net, n: int, alpha, edge: str = "v", neighbour=None, *, lam: float = 1.0,
                  mu: float = 0.0) -> np.ndarray:
    """The net of the neighbour on the point-reflected side of ``edge``, joined C1 (``lam = 1, mu = 0``) or G1
    (``d'_{2n-k} = -lam d_k + mu t_k``, ``lam > 0``) to the patch of ``net``: a copy of ``neighbour`` (default:
    zeros) with its boundary row set to ours reversed (C0) and its second row solved from the condition (the
    second-row block of D is inverted; ``ArithmeticError`` if it is singular).  For n = 1 and C1 this is the
    parallelogram rule P'_011 = P_200 + P_101 - P_110 (tested).
    """
    n, a, edge = _check(n, alpha, edge)
    arr = check_net(net, n)
    other = np.zeros_like(arr) if neighbour is None else check_net(neighbour, n, "neighbour").copy()
    if other.shape != arr.shape:
        raise ValueError(f"neighbour must have the shape of net {arr.shape}, got {other.shape}")
    lam_f = _positive(lam, "lam")
    mu_f = _real(mu, "mu")
    d_mat, t_mat = _edge_derivatives(n, a, edge)
    b, s = edge_rows(n, edge)
    other[b] = _reverse(arr[b])
    want = _reverse(-lam_f * (d_mat @ arr) + mu_f * (t_mat @ arr))  # d' wanted, in the neighbour's own order
    block = d_mat[:, s]
    if np.linalg.cond(block) > 1e12:
        raise ArithmeticError(f"the second-row block of the edge derivative is singular at n = {n}")
    rest = d_mat[:, b] @ other[b]
    other[s] = np.linalg.solve(block, want - rest)
    return other


def _positive(x, name: str) -> float:
    v = _real(x, name)
    if not v > 0:
        raise ValueError(f"{name} must be a positive real number, got {x!r}")
    return v


def _real(x, name: str) -> float:
    import math

    from paper_repro.util.limits import real_scalar

    v = float(real_scalar(x, name))
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return v


def edge_join_error(net, neighbour, n: int, alpha, edge: str = "v") -> dict[str, float]:
    """Defects of the join of the patch of ``net`` with the patch of ``neighbour`` on the point-reflected side of
    ``edge`` (same n, same alpha): ``'C0'`` = max_k |P_k - P'_{2n-k}| over the boundary rows (the boundary curves
    coincide iff 0), ``'C1'`` = max_k |d_k + d'_{2n-k}|, and ``'G1'`` = the residual of the least-squares fit
    d'_{2n-k} = -lam d_k + mu t_k (with ``'lam'``, ``'mu'``; G1 with constant multipliers holds where ``'G1'`` is 0
    and ``lam > 0``).  Coefficient defects: the A_{2n,k} are a partition of unity, so the sampled gap of the
    curves is at most the coefficient defect.
    """
    n, a, edge = _check(n, alpha, edge)
    arr = check_net(net, n)
    other = check_net(neighbour, n, "neighbour")
    if other.shape != arr.shape:
        raise ValueError(f"neighbour must have the shape of net {arr.shape}, got {other.shape}")
    d_mat, t_mat = _edge_derivatives(n, a, edge)
    b, _ = edge_rows(n, edge)
    c0 = float(np.abs(arr[b] - _reverse(other[b])).max())
    d, t = d_mat @ arr, t_mat @ arr
    d_other = _reverse(d_mat @ other)  # row k: d'_{2n-k}
    c1 = float(np.abs(d + d_other).max())
    design = np.c_[-d.reshape(-1), t.reshape(-1)]
    coef, *_ = np.linalg.lstsq(design, d_other.reshape(-1), rcond=None)
    g1 = float(np.abs(design @ coef - d_other.reshape(-1)).max())
    return {"C0": c0, "C1": c1, "G1": g1, "lam": float(coef[0]), "mu": float(coef[1])}


__all__ = ["EDGES", "ROLES", "check_edge", "directions", "edge_rows", "edge_points", "edge_derivatives",
           "c1_second_row", "edge_join_error"]
