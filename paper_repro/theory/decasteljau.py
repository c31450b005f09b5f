"""The de Casteljau question: is one order-lowering corner-cutting step possible?

Beyond the paper; docs/subdivision_for_all_n.md, §10.  A de Casteljau step of a Bezier triangle writes the degree-n
basis as the degree-(n - 1) basis times a matrix of degree-1 weights that are >= 0 and sum to 1 along each row.  The
analogue here: find functions W[g, f] of order 1 (in span T_2) with

    T-bar^{(n)}_f(x) = sum_g T-bar^{(n-1)}_g(x) W[g, f](x)    for every member f of T_{2n}, x in Omega^alpha,   (1)
    sum_f W[g, f](x) = 1 (every row; convexity),     W[g, f] >= 0 on Omega^alpha,                           (2)

so that s(x) = sum_g T-bar^{(n-1)}_g(x) P'_g(x) with P'_g(x) = sum_f W[g, f](x) P_f convex combinations of the net
(then recursively down to order 0).  Writing W[g, f] = sum_h w[g, f, h] T-bar^{(1)}_h and using the product matrices
Q_h (T-bar^{(n-1)}_g T-bar^{(1)}_h = sum_f' Q_h[f', g] T-bar^{(n)}_f', :func:`product_matrix`) and the linear
independence of T-bar^{(n)} and T-bar^{(1)}, (1) and the row sums are linear in w:

    K W_f = e_f for every f,   sum_f w[g, f, h] = 1 for every (g, h),                                         (3)

with K the delta_n x 7 delta_{n-1} matrix of columns Q_h[:, g] and W_f the vector w[., f, .].  Variants:

* ``'coefficients'``: w >= 0 (every weight a non-negative combination of the order-1 members; sufficient for (2));
* ``'points'``: W[g, f] >= 0 only at seven unisolvent points of span T_2 (the three corners, the three edge midpoints,
  one interior point); with the Lagrange basis of these points as weight basis, again (3) with v >= 0.  Every
  solution of (1)-(2), with any sign pattern of the coefficients, satisfies it: a relaxation, so its infeasibility
  proves that no order-1 weights at all (non-negative on Omega^alpha) give a convex step;
* ``'cone'``: w >= 0 without the row sums (is T-bar^{(n)}_f a non-negative combination of products?).

**Certificate (Farkas).** (3) with w >= 0 has no solution iff there are Y (delta_n x delta_n) and z (one per (g, h))
with K^T Y + z 1^T >= 0 entrywise and tr Y + sum z < 0: for a solution, 0 <= sum_f W_f^T (K^T Y + z 1^T)[:, f] =
sum_f Y[f, f] + sum_{g,h} z[g, h] (sum_f w[g, f, h]) = tr Y + sum z.  :func:`certificate` finds Y by a float LP
(scipy/HiGHS), rounds it to rationals, takes the smallest admissible z exactly (z[g, h] = max_f -(K^T Y)[(g, h), f])
and checks tr Y + sum z < 0 in exact rational arithmetic: :func:`verify` is the proof of infeasibility at that alpha
(the float LP only proposes Y).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from flint import fmpq, fmpq_mat

from paper_repro.core.context import to_fmpq_mat
from paper_repro.core.domain import RationalAngle, RationalPoints, rational_alpha
from paper_repro.core.half_angle_matrices import product_matrix
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized

VARIANTS = ("coefficients", "points", "cone")


def alpha_from_eighth(t8: fmpq) -> RationalAngle:
    """alpha with tan(alpha/8) = ``t8`` (so that the edge midpoints have rational half-angle data)."""
    return rational_alpha(2 * t8 / (1 - t8 * t8))


def seven_points(alpha: RationalAngle, t8: fmpq) -> RationalPoints:
    """The corners, the edge midpoints and the interior point tan(u/4) = tan(v/4) = tan(alpha/8)/2 of
    Omega^alpha (``t8`` = tan(alpha/8))."""
    t, h = alpha.t, t8
    tu = (t, fmpq(0), fmpq(0), h, h, fmpq(0), h / 2)
    tv = (fmpq(0), t, fmpq(0), h, fmpq(0), h, h / 2)
    return RationalPoints(alpha, tu, tv)


def weight_matrix(n: int, t8: fmpq, variant: str) -> fmpq_mat:
    """K of (3) exactly at tan(alpha/8) = ``t8``: ``delta_n x 7 delta_{n-1}``, column ``g * 7 + h`` (weight basis h:
    T-bar^{(1)}_h, or for ``'points'`` the Lagrange function of the h-th of :func:`seven_points`)."""
    if variant not in VARIANTS:
        raise ValueError(f"variant must be one of {VARIANTS}, got {variant!r}")
    if n < 2:
        raise ValueError(f"n must be >= 2 (order 1 is its own one-step evaluation), got {n!r}")
    alpha = alpha_from_eighth(t8)
    q = [to_fmpq_mat(product_matrix(n - 1, h, alpha, "exact")) for h in range(7)]  # delta_n x delta_{n-1}
    dn, dm = delta(n), delta(n - 1)
    k = fmpq_mat(dn, 7 * dm)
    if variant == "points":
        vals = to_fmpq_mat(evaluate_normalized(1, alpha, seven_points(alpha, t8), "exact"))  # 7 points x 7 members
        if vals.rank() != 7:
            raise ValueError("the seven points are not unisolvent for T_2")
        lag = vals.inv()  # column p: coefficients of the Lagrange function of point p in T-bar^{(1)}
    for g in range(dm):
        for h in range(7):
            for f in range(dn):
                if variant == "points":
                    x = sum((lag[hh, h] * q[hh][f, g] for hh in range(7)), fmpq(0))
                else:
                    x = q[h][f, g]
                k[f, g * 7 + h] = x
    return k


def equalities_consistent(k: fmpq_mat) -> bool:
    """Whether (3) without sign conditions has a solution, proven exactly: K has full row rank delta_n and K 1 = 1
    (then with a right inverse R of K, W_f = R e_f + (1 - R 1)/delta_n solves (3): K W_f = e_f + (K 1 - K R 1)/delta_n
    = e_f and sum_f W_f = R 1 + 1 - R 1 = 1).  K 1 = 1 is the partition of unity of the order-1 and order-n
    systems.  So an infeasibility certificate of a variant is due to its sign conditions, not to the identity."""
    ones = all(sum((k[i, j] for j in range(k.ncols())), fmpq(0)) == 1 for i in range(k.nrows()))
    return ones and k.rank() == k.nrows()


@dataclass(frozen=True)
class Certificate:
    """An exact Farkas certificate: ``y`` (delta_n x delta_n) and ``z`` (7 delta_{n-1}), with the value
    ``tr Y + sum z`` (< 0 proves infeasibility) and the smallest entry of K^T Y + z 1^T (>= 0 required)."""

    y: fmpq_mat
    z: list[fmpq]
    value: fmpq
    min_entry: fmpq


def verify(k: fmpq_mat, y: fmpq_mat, z: list[fmpq] | None) -> tuple[fmpq, fmpq]:
    """``(tr Y + sum z, min of K^T Y + z 1^T)`` in exact arithmetic (``z = None``: the ``'cone'`` variant, z = 0).
    The system (3) with w >= 0 is infeasible if the first is < 0 and the second >= 0."""
    kt = k.transpose() * y
    zz = z if z is not None else [fmpq(0)] * kt.nrows()
    low = min(kt[r, c] + zz[r] for r in range(kt.nrows()) for c in range(kt.ncols()))
    trace = sum((y[i, i] for i in range(y.nrows())), fmpq(0))
    return trace + sum(zz, fmpq(0)), low


def _round(x: float, den: int) -> fmpq:
    return fmpq(int(round(x * den)), den)


def float_lp(k: np.ndarray, row_sums: bool) -> tuple[str, float, np.ndarray]:
    """The dual LP in float64: minimize tr Y + sum z over K^T Y + z 1^T >= 0, -1 <= Y, z <= 1 (for ``row_sums``
    False, z = 0).  Returns (HiGHS status message, optimum, Y)."""
    from scipy.optimize import linprog
    from scipy.sparse import coo_matrix, hstack, identity, kron

    dn, m = k.shape
    # unknowns: vec(Y) column-major by f (Y[:, f] for f = 0..dn-1), then z
    ks = coo_matrix(k.T)
    a_y = kron(identity(dn), ks)  # row (f, j): sum_i K[i, j] Y[i, f]
    if row_sums:
        a_z = kron(np.ones((dn, 1)), identity(m))
        a = hstack([a_y, a_z]).tocsr()
    else:
        a = a_y.tocsr()
    nvar = a.shape[1]
    cost = np.zeros(nvar)
    cost[[f * dn + f for f in range(dn)]] = 1.0
    if row_sums:
        cost[dn * dn:] = 1.0
    res = linprog(cost, A_ub=-a, b_ub=np.zeros(a.shape[0]), bounds=(-1, 1), method="highs")
    y = res.x[: dn * dn].reshape(dn, dn).T if res.x is not None else np.zeros((dn, dn))
    return res.message, float(res.fun) if res.fun is not None else float("nan"), y


def certificate(n: int, t8: fmpq, variant: str, den: int = 10**6) -> tuple[Certificate | None, float, fmpq_mat]:
    """Search a Farkas certificate of the infeasibility of (3) (``variant``) at tan(alpha/8) = ``t8``: the float
    LP's Y rounded to multiples of 1/``den``, then z exactly, then :func:`verify`.  Returns (the certificate if the
    exact check proves infeasibility, else None; the float LP optimum; K)."""
    k = weight_matrix(n, t8, variant)
    kf = np.array([[float(k[i, j]) for j in range(k.ncols())] for i in range(k.nrows())])
    row_sums = variant != "cone"
    _, opt, yf = float_lp(kf, row_sums)
    if not opt < 0:
        return None, opt, k
    y = fmpq_mat(yf.shape[0], yf.shape[1], [_round(x, den) for x in yf.reshape(-1)])
    kt = k.transpose() * y
    if row_sums:
        z = [max(-kt[r, c] for c in range(kt.ncols())) for r in range(kt.nrows())]
    else:
        z = None
    val, low = verify(k, y, z)
    ok = val < 0 and low >= 0
    return (Certificate(y, z if z is not None else [], val, low) if ok else None), opt, k


# --- the strongest variant: order-1 weights of any sign, non-negative at the points of a grid -------------------------
def grid_points(alpha: RationalAngle, size: int) -> RationalPoints:
    """Rational points of Omega^alpha: tan(u/4) = T i/size, tan(v/4) = T j/size (T = tan(alpha/4)), those with
    w >= 0 (tan((u + v)/4) <= T).

    >>> len(grid_points(alpha_from_eighth(fmpq(1, 5)), 8).tu)
    38
    """
    t = alpha.t
    tu, tv = [], []
    for i in range(size + 1):
        for j in range(size + 1):
            a, b = t * i / size, t * j / size
            if a * b < 1 and (a + b) / (1 - a * b) <= t:
                tu.append(a)
                tv.append(b)
    return RationalPoints(alpha, tuple(tu), tuple(tv))


@dataclass(frozen=True)
class GridCertificate:
    """An exact Farkas certificate of the ``'grid'`` system: Y, u >= 0 (one per (f, g, grid point)), z, and the
    value tr Y + sum z (< 0 proves infeasibility); ``min_entry`` >= 0 is the dual feasibility."""

    y: fmpq_mat
    u: fmpq_mat
    z: list[fmpq]
    value: fmpq
    min_entry: fmpq
    points: int


def _lagrange_parts(n: int, t8: fmpq, size: int) -> tuple[fmpq_mat, fmpq_mat, int]:
    """K' (the ``'points'`` weight matrix of :func:`seven_points`) and L (grid points x 7: the values of the seven
    Lagrange functions at the grid points)."""
    alpha = alpha_from_eighth(t8)
    kp = weight_matrix(n, t8, "points")
    seven = to_fmpq_mat(evaluate_normalized(1, alpha, seven_points(alpha, t8), "exact"))
    grid = grid_points(alpha, size)
    vals = to_fmpq_mat(evaluate_normalized(1, alpha, grid, "exact"))
    return kp, vals * seven.inv(), len(grid.tu)


def grid_dual_entries(kp: fmpq_mat, lag: fmpq_mat, y: fmpq_mat, u: fmpq_mat) -> fmpq_mat:
    """(K'^T Y)[(g, q), f] - sum_p u[(f, g), p] L[p, q], as a (7 delta_{n-1}) x delta_n matrix (rows g * 7 + q)."""
    kt = kp.transpose() * y
    ul = u * lag  # rows f * dm + g, columns q
    dn = y.ncols()
    dm = kt.nrows() // 7
    out = fmpq_mat(kt.nrows(), kt.ncols())
    for g in range(dm):
        for q in range(7):
            for f in range(dn):
                out[g * 7 + q, f] = kt[g * 7 + q, f] - ul[f * dm + g, q]
    return out


def grid_certificate(n: int, t8: fmpq, size: int, den: int = 10**7) -> tuple[GridCertificate | None, float]:
    """Search and check exactly a certificate that no order-1 weights W[g, f] (any sign of their coefficients) with
    rows summing to 1 and W >= 0 at the points of :func:`grid_points` give (1): the system with the values v >= 0 at
    the seven points of :func:`seven_points` and slacks s = L v >= 0 at the grid points is in standard form; its
    Farkas certificate is (Y, z, u >= 0) with (K'^T Y)[(g, q), f] + z[(g, q)] - sum_p u[(f, g), p] L[p, q] >= 0 and
    tr Y + sum z < 0.  The float LP proposes Y and u; they are rounded to multiples of 1/``den`` (u clipped at 0), z
    is taken exactly as the smallest admissible, and the value is checked exactly.  Returns (the certificate or None,
    the float optimum)."""
    from scipy.optimize import linprog
    from scipy.sparse import coo_matrix, hstack, identity, kron

    kp, lag, npts = _lagrange_parts(n, t8, size)
    dn, m = kp.nrows(), kp.ncols()
    dm = m // 7
    kf = np.array([[float(kp[i, j]) for j in range(m)] for i in range(dn)])
    lf = np.array([[float(lag[i, j]) for j in range(7)] for i in range(npts)])
    # unknowns: Y column-major by f (dn * dn), z (m), u[(f, g), p] ((dn * dm) * npts)
    # constraint rows (f, (g, q)): sum_i K'[i, (g,q)] Y[i, f] + z[(g,q)] - sum_p u[(f,g), p] L[p, q] >= 0
    a_y = kron(identity(dn), coo_matrix(kf.T))
    a_z = kron(np.ones((dn, 1)), identity(m))
    a_u = kron(identity(dn * dm), coo_matrix(lf.T))  # rows ((f, g), q), columns ((f, g), p)
    a = hstack([a_y, a_z, -a_u]).tocsr()
    nvar = a.shape[1]
    cost = np.zeros(nvar)
    cost[[f * dn + f for f in range(dn)]] = 1.0
    cost[dn * dn: dn * dn + m] = 1.0
    bounds = [(-1, 1)] * (dn * dn + m) + [(0, 10)] * (dn * dm * npts)
    res = linprog(cost, A_ub=-a, b_ub=np.zeros(a.shape[0]), bounds=bounds, method="highs")
    if res.x is None or not res.fun < 0:
        return None, float(res.fun) if res.fun is not None else float("nan")
    yf = res.x[: dn * dn].reshape(dn, dn).T
    uf = res.x[dn * dn + m:].reshape(dn * dm, npts)
    y = fmpq_mat(dn, dn, [_round(x, den) for x in yf.reshape(-1)])
    u = fmpq_mat(dn * dm, npts, [max(_round(x, den), fmpq(0)) for x in uf.reshape(-1)])
    ent = grid_dual_entries(kp, lag, y, u)
    z = [max(-ent[r, c] for c in range(dn)) for r in range(m)]
    low = min(ent[r, c] + z[r] for r in range(m) for c in range(dn))
    value = sum((y[i, i] for i in range(dn)), fmpq(0)) + sum(z, fmpq(0))
    ok = value < 0 and low >= 0
    return (GridCertificate(y, u, z, value, low, npts) if ok else None), float(res.fun)


__all__ = ["VARIANTS", "alpha_from_eighth", "seven_points", "weight_matrix", "equalities_consistent", "Certificate",
           "verify", "float_lp",
           "certificate", "grid_points", "GridCertificate", "grid_dual_entries", "grid_certificate"]
