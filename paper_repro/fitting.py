"""Control nets of surfaces whose coordinates lie in V_n (exact description by a patch).

``fit(surface, n, alpha)``: the coordinates of ``surface(u, v, w)`` (a callable on Omega^alpha, or on
the plane u + v + w = alpha) are interpolated in the normalized basis T-bar_{2n}^alpha at delta_n
points; if they lie in the space the interpolant *is* the surface, which is checked at further
points (``ValueError`` otherwise).  Arithmetics: mpmath (any alpha) or exact rationals (rational-tangent
alpha and a surface that maps rational points to rationals, e.g. trigonometric polynomials with
rational coefficients, evaluated through :class:`ExactTrig`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import numpy as np
from flint import fmpq

from .arith import to_fmpq_mat
from .domain import RationalAngle, RationalPoints, mp_domain_points, sample_rational_points
from .labels import delta
from .normalization import evaluate_normalized


@dataclass
class ExactTrig:
    """sin/cos of integer combinations of u, v, w at a rational point, exactly (for exact fitting)."""

    cu: fmpq
    su: fmpq
    cv: fmpq
    sv: fmpq
    cw: fmpq
    sw: fmpq

    def _cs(self, r: int, g: int, b: int) -> tuple[fmpq, fmpq]:
        re, im = fmpq(1), fmpq(0)
        for (c, s), k in (((self.cu, self.su), r), ((self.cv, self.sv), g), ((self.cw, self.sw), b)):
            if k < 0:
                s, k = -s, -k
            for _ in range(k):
                re, im = re * c - im * s, re * s + im * c
        return re, im

    def cos(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[0]

    def sin(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[1]


def exact_trig_points(pts: RationalPoints) -> list[ExactTrig]:
    su, cu, sv, cv, sw, cw = pts.half_angle_values()
    out = []
    for k in range(len(pts)):
        out.append(ExactTrig(cu[k] ** 2 - su[k] ** 2, 2 * su[k] * cu[k], cv[k] ** 2 - sv[k] ** 2, 2 * sv[k] * cv[k],
                             cw[k] ** 2 - sw[k] ** 2, 2 * sw[k] * cw[k]))
    return out


def fit_exact(surface: Callable[[ExactTrig], list[fmpq]], n: int, alpha: RationalAngle, verify: int = 4,
              seed: int = 21) -> list[list[fmpq]]:
    """Exact control net (rows in internal order) of ``surface``, a function of :class:`ExactTrig`."""
    d = delta(n)
    pts = sample_rational_points(alpha, d + verify, seed=seed)
    basis = evaluate_normalized(n, alpha, pts, "exact")
    vals = np.array([surface(t) for t in exact_trig_points(pts)], dtype=object)
    net = to_fmpq_mat(basis[:d]).solve(to_fmpq_mat(vals[:d]))
    if to_fmpq_mat(basis[d:]) * net != to_fmpq_mat(vals[d:]):
        raise ValueError("surface: its coordinates are not in the span of T_{2n} (verification points disagree)")
    return [[net[i, j] for j in range(net.ncols())] for i in range(net.nrows())]


def fit_mp(surface: Callable, n: int, alpha, dps: int = 40, verify: int = 4, seed: int = 21,
           tol_digits: int | None = None) -> np.ndarray:
    """Control net (object array of mpf) of ``surface(u, v, w) -> sequence`` by collocation in mpmath."""
    d = delta(n)
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        pts = mp_domain_points(a, d + verify, seed)
        basis = evaluate_normalized(n, a, pts, "mp", dps=dps)
        vals = np.array([list(surface(*p)) for p in pts], dtype=object)
        mat = mpmath.matrix(basis[:d].tolist())
        cols = [mpmath.lu_solve(mat, mpmath.matrix(list(vals[:d, j]))) for j in range(vals.shape[1])]
        net = np.array([[col[i] for col in cols] for i in range(d)], dtype=object)
        resid = max(abs(x) for x in (basis[d:].dot(net) - vals[d:]).reshape(-1))
        scale = max(1, max(abs(x) for x in vals.reshape(-1)))
        if resid > scale * mpmath.mpf(10) ** (-(tol_digits or dps - 15)):
            raise ValueError(f"surface: not in the span of T_{2 * n} (residual {mpmath.nstr(resid, 3)})")
        return net
