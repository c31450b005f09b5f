"""Surfaces described exactly by joined order-2 patches: the ring torus (Example exmp:torus) and the
ring Dupin cyclide (eq. Dupin_in_3d), over squares [phi, phi + alpha] x [psi, psi + alpha] of their
(U, V) parameter plane, each square split into two triangles:

* lower: U = phi + u, V = psi + v (u + v <= alpha) -- the paper's toroidal triangle for phi = psi = 0;
* upper: U = phi + alpha - u, V = psi + alpha - v.

Each triangle's control net (and, for the rational cyclide, weights) is fitted exactly in the
normalized basis (:mod:`paper_repro.surfaces.fitting`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

from paper_repro.surfaces.fitting import fit_mp
from paper_repro.surfaces.patch import Patch


@dataclass
class Piece:
    """One triangle of a model: its phases ``(phi, psi)``, whether it is the ``upper`` triangle of its square,
    and its :class:`~paper_repro.surfaces.patch.Patch` (evaluate, derivatives, normals, meshes)."""

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
    """The ring torus of Example 6.1 (``exmp:torus``) at ``(U, V)``, in mpmath: ``((rho + mu sin U) cos V,
    (rho + mu sin U) sin V, mu cos U)``."""
    return ((rho + mu * mpmath.sin(U)) * mpmath.cos(V), (rho + mu * mpmath.sin(U)) * mpmath.sin(V), mu * mpmath.cos(U))


def cyclide_parts(U, V, a, b, c, mu):
    """eq. Dupin_in_3d written as (numerator vector, denominator): point = X / W."""
    cu, cv, su, sv = mpmath.cos(U), mpmath.cos(V), mpmath.sin(U), mpmath.sin(V)
    W = a - c * cu * cv
    X = (mu * (c - a * cu * cv) + b**2 * cu, (a - mu * cv) * b * su, (c * cu - mu) * b * sv)
    return X, W


def _real(x, name: str):
    """A finite real number (``TypeError``/``ValueError`` naming ``name``)."""
    from paper_repro.util.limits import real_scalar

    x = real_scalar(x, name)
    try:
        finite = math.isfinite(float(x))
    except OverflowError:
        finite = False
    if not finite:
        raise ValueError(f"{name} must be a finite real number, got {str(x)[:40]}")
    return x


def _phases(values, name: str) -> list:
    """``phis``/``psis``: a non-empty sequence of finite real numbers."""
    if isinstance(values, (str, bytes, dict)) or not hasattr(values, "__iter__"):
        raise TypeError(f"{name} must be a sequence of real numbers (the phases), got {type(values).__name__}")
    out = [_real(x, f"{name} entries") for x in values]
    if not out:
        raise ValueError(f"{name} must hold at least one phase, got an empty sequence")
    return out


def _check_model(alpha, phis, psis, dps) -> tuple[list, list]:
    from paper_repro.util.limits import MAX_DPS, MIN_DPS, check_int
    from paper_repro.util.validation import check_alpha

    check_alpha(alpha)
    check_int(dps, "dps", MIN_DPS, MAX_DPS)
    return _phases(phis, "phis"), _phases(psis, "psis")


def _uv_of(phi, psi, upper, alpha):
    if upper:
        return lambda u, v: (phi + alpha - u, psi + alpha - v)
    return lambda u, v: (phi + u, psi + v)


def torus_pieces(alpha: float, rho: float, mu: float, phis, psis, dps: int = 30) -> list[Piece]:
    """The ring torus (Example 6.1, ``exmp:torus``; radii ``rho > mu > 0``) as order-2 patches, exactly.

    For every phase ``phi`` in ``phis`` and ``psi`` in ``psis`` the square ``[phi, phi + alpha] x [psi, psi + alpha]``
    of the parameter plane gives two pieces (the lower and the upper triangle), each net fitted by collocation
    in ``dps``-digit mpmath and rounded to float64.  With ``alpha = pi/2`` and the four phases ``0, pi/2, pi,
    3pi/2`` in both lists, 32 pieces cover the whole torus.

    Examples
    --------
    >>> import numpy as np
    >>> pieces = torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])
    >>> len(pieces), pieces[0].patch
    (2, <Patch n=2 alpha=1.5708 dim=3>)
    >>> p = pieces[0]                                   # u = U, v = V on the lower triangle
    >>> bool(np.allclose(p.patch([[0.5, 0.25, np.pi / 2 - 0.75]]),
    ...                  [[(2 + np.sin(0.5)) * np.cos(0.25), (2 + np.sin(0.5)) * np.sin(0.25), np.cos(0.5)]]))
    True
    """
    phis, psis = _check_model(alpha, phis, psis, dps)
    rho, mu = _real(rho, "rho"), _real(mu, "mu")
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
    """The ring Dupin cyclide (eq. ``Dupin_in_3d``; ``params`` the numbers ``a``, ``b``, ``c``, ``mu``) as order-2
    rational patches, exactly: per square of phases as in :func:`torus_pieces`, the weights are fitted from the
    denominator W and the weighted points from the numerator X (points = X / weight).  The paper's cyclide is
    ``a=6, b=4 sqrt 2, c=2, mu=3`` with ``alpha = pi/2``; its weights are positive.

    Examples
    --------
    >>> import numpy as np
    >>> pieces = cyclide_pieces(np.pi / 2, {"a": 6, "b": 32 ** 0.5, "c": 2, "mu": 3}, [0.0], [0.0])
    >>> pieces[0].patch, bool(pieces[0].patch.weights.min() > 0)
    (<rational Patch n=2 alpha=1.5708 dim=3>, True)
    >>> model_gap(pieces, np.pi / 2) < 1e-12                # the two triangles meet on the diagonal
    True
    """
    phis, psis = _check_model(alpha, phis, psis, dps)
    if not isinstance(params, dict) or set(params) != {"a", "b", "c", "mu"}:
        got = sorted(map(str, params)) if isinstance(params, dict) else type(params).__name__
        raise TypeError(f"params must be a dict with the keys 'a', 'b', 'c', 'mu' (eq. Dupin_in_3d), got {got}")
    checked = {k: _real(v, f"params[{k!r}]") for k, v in params.items()}
    out = []
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        pr = {k: mpmath.mpf(v) for k, v in checked.items()}
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


def model_gap(pieces: list[Piece], alpha: float, samples: int = 9) -> float:
    """Largest distance between pieces at ``samples`` shared points per edge of their triangles (their C0 joins).

    ``ValueError`` if nothing is measured (no pieces, ``samples`` below 2, or no point shared by two pieces):
    0.0 would read as a perfect join.
    """
    from paper_repro.util.limits import check_int

    if isinstance(pieces, (str, bytes)) or not hasattr(pieces, "__iter__"):
        raise TypeError(f"pieces must be a list of Piece (from torus_pieces or cyclide_pieces), got "
                        f"{type(pieces).__name__}")
    pieces = list(pieces)
    if not pieces or not all(isinstance(p, Piece) for p in pieces):
        raise ValueError("pieces must be a non-empty list of Piece (from torus_pieces or cyclide_pieces)")
    samples = check_int(samples, "samples", 2, 10_000, why="points per edge; one point measures only the corners")
    alpha = _real(alpha, "alpha")
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
    worst, compared = 0.0, 0
    for U, V in pts:
        vals = []
        for p in pieces:
            d = p.domain_point(U, V, alpha)
            if d is not None:
                vals.append(p.patch(d[None, :])[0])
        for k in range(1, len(vals)):
            worst = max(worst, float(np.max(np.abs(vals[k] - vals[0]))))
            compared += 1
    if not compared:
        raise ValueError(f"pieces: no point is shared by two of the {len(pieces)} pieces at alpha={alpha!r}, so no "
                         "join was measured (give pieces of adjacent triangles, made with this alpha)")
    return worst
