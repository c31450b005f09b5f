"""Surfaces described exactly by joined order-2 patches: the ring torus (Example exmp:torus) and the
ring Dupin cyclide (eq. Dupin_in_3d), over squares [phi, phi + alpha] x [psi, psi + alpha] of their
(U, V) parameter plane, each square split into two triangles:

* lower: U = phi + u, V = psi + v (u + v <= alpha) -- the paper's toroidal triangle for phi = psi = 0;
* upper: U = phi + alpha - u, V = psi + alpha - v.

Each triangle's control net (and, for the rational cyclide, weights) is fitted exactly in the
normalized basis (:mod:`paper_repro.surfaces.fitting`).
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np

from paper_repro.surfaces.fitting import fit_mp
from paper_repro.surfaces.patch import Patch


@dataclass
class Piece:
    phi: float
    psi: float
    upper: bool
    patch: Patch

    def uv(self, pts: np.ndarray, alpha: float) -> np.ndarray:
        """(U, V) of domain points (u, v, w)."""
        u, v = pts[:, 0], pts[:, 1]
        if self.upper:
            return np.c_[self.phi + alpha - u, self.psi + alpha - v]
        return np.c_[self.phi + u, self.psi + v]

    def domain_point(self, U: float, V: float, alpha: float) -> np.ndarray | None:
        """Domain point of (U, V) if it lies in this piece's triangle (within 1e-12), else None."""
        u, v = (self.phi + alpha - U, self.psi + alpha - V) if self.upper else (U - self.phi, V - self.psi)
        eps = 1e-12
        if u < -eps or v < -eps or u + v > alpha + eps:
            return None
        u, v = max(u, 0.0), max(v, 0.0)
        return np.array([u, v, max(alpha - u - v, 0.0)])


def torus_xyz(U, V, rho, mu):
    return ((rho + mu * mpmath.sin(U)) * mpmath.cos(V), (rho + mu * mpmath.sin(U)) * mpmath.sin(V), mu * mpmath.cos(U))


def cyclide_parts(U, V, a, b, c, mu):
    """eq. Dupin_in_3d written as (numerator vector, denominator): point = X / W."""
    cu, cv, su, sv = mpmath.cos(U), mpmath.cos(V), mpmath.sin(U), mpmath.sin(V)
    W = a - c * cu * cv
    X = (mu * (c - a * cu * cv) + b**2 * cu, (a - mu * cv) * b * su, (c * cu - mu) * b * sv)
    return X, W


def _uv_of(phi, psi, upper, alpha):
    if upper:
        return lambda u, v: (phi + alpha - u, psi + alpha - v)
    return lambda u, v: (phi + u, psi + v)


def torus_pieces(alpha: float, rho: float, mu: float, phis, psis, dps: int = 30) -> list[Piece]:
    out = []
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        for phi in phis:
            for psi in psis:
                for upper in (False, True):
                    m = _uv_of(mpmath.mpf(phi), mpmath.mpf(psi), upper, a)
                    net = fit_mp(lambda u, v, w, m=m: torus_xyz(*m(u, v), rho, mu), 2, a, dps=dps)
                    out.append(Piece(phi, psi, upper, Patch(2, alpha, net.astype(np.float64))))
    return out


def cyclide_pieces(alpha: float, params: dict, phis, psis, dps: int = 30) -> list[Piece]:
    """Rational patches: weights fitted from W, weighted points from X (points = X / weight)."""
    out = []
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        pr = {k: mpmath.mpf(v) for k, v in params.items()}
        for phi in phis:
            for psi in psis:
                for upper in (False, True):
                    m = _uv_of(mpmath.mpf(phi), mpmath.mpf(psi), upper, a)

                    def both(u, v, w, m=m):
                        X, W = cyclide_parts(*m(u, v), pr["a"], pr["b"], pr["c"], pr["mu"])
                        return (*X, W)

                    fitted = fit_mp(both, 2, a, dps=dps)
                    weights = fitted[:, 3]
                    points = np.array([[fitted[k, j] / weights[k] for j in range(3)] for k in range(len(weights))],
                                      dtype=object)
                    out.append(Piece(phi, psi, upper,
                                     Patch(2, alpha, points.astype(np.float64), weights=weights.astype(np.float64))))
    return out


def join_error(pieces: list[Piece], alpha: float, samples: int = 9) -> float:
    """Max distance between pieces at shared points of their triangle edges (C0 joins)."""
    grid_u = sorted({p.phi for p in pieces} | {p.phi + alpha for p in pieces})
    grid_v = sorted({p.psi for p in pieces} | {p.psi + alpha for p in pieces})
    pts = []
    t = np.linspace(0, 1, samples)
    for U in grid_u:  # vertical grid lines
        for V0 in grid_v[:-1]:
            pts += [(U, V0 + alpha * s) for s in t]
    for V in grid_v:
        for U0 in grid_u[:-1]:
            pts += [(U0 + alpha * s, V) for s in t]
    for U0 in grid_u[:-1]:  # diagonals of the squares
        for V0 in grid_v[:-1]:
            pts += [(U0 + alpha * s, V0 + alpha * (1 - s)) for s in t]
    worst = 0.0
    for U, V in pts:
        vals = []
        for p in pieces:
            d = p.domain_point(U, V, alpha)
            if d is not None:
                vals.append(p.patch(d[None, :])[0])
        for k in range(1, len(vals)):
            worst = max(worst, float(np.max(np.abs(vals[k] - vals[0]))))
    return worst
