"""The domain Omega^alpha = {(u, v, w): u + v + w = alpha, u, v, w >= 0} and its points.

Two kinds of points:

* real points ``(u, v, w)`` (float or mpmath), checked to lie on Omega^alpha within
  :data:`~paper_repro.validation.DOMAIN_TOL` (relative to alpha);
* rational points (:class:`RationalPoints`): alpha, u and v are given through the rational
  tangents of their quarter angles, ``t = tan(x/4)``, so that ``sin(x/2) = 2t/(1+t^2)`` and
  ``cos(x/2) = (1-t^2)/(1+t^2)`` are rational; w/2 = alpha/2 - u/2 - v/2 then has rational sine and
  cosine by the angle-difference formulas.  Every basis function is then an exact rational.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np
from flint import fmpq

from .arith import Arith, ModpArith
from .validation import DOMAIN_TOL, check_alpha


def _q(x) -> fmpq:
    if isinstance(x, fmpq):
        return x
    if isinstance(x, tuple):
        return fmpq(*x)
    return fmpq(x)


@dataclass(frozen=True)
class RationalAngle:
    """An angle ``x`` in ``[0, pi)`` given by ``t = tan(x/4)`` rational, ``0 <= t < tan(pi/4) = 1``."""

    t: fmpq

    def __post_init__(self) -> None:
        object.__setattr__(self, "t", _q(self.t))
        if not (0 <= self.t < 1):
            raise ValueError(f"t = tan(x/4) must satisfy 0 <= t < 1 (x in [0, pi)), got {self.t}")

    @property
    def sin_half(self) -> fmpq:
        return 2 * self.t / (1 + self.t**2)

    @property
    def cos_half(self) -> fmpq:
        return (1 - self.t**2) / (1 + self.t**2)

    def mp(self) -> mpmath.mpf:
        """The angle itself, ``4 atan(t)``, at the current mpmath precision."""
        return 4 * mpmath.atan(mpmath.mpf(int(self.t.p)) / int(self.t.q))

    def __float__(self) -> float:
        return 4 * math.atan(int(self.t.p) / int(self.t.q))


def rational_alpha(t) -> RationalAngle:
    """Shape parameter alpha = 4 atan(t) for rational ``0 < t < 1`` (so alpha in (0, pi))."""
    a = RationalAngle(_q(t))
    if a.t == 0:
        raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
    return a


@dataclass(frozen=True)
class RationalPoints:
    """Points of Omega^alpha with rational half-angle sines and cosines.

    ``tu[k]``, ``tv[k]`` are ``tan(u/4)``, ``tan(v/4)`` of the k-th point; w = alpha - u - v must be
    >= 0 (checked exactly: ``sin(w/2) >= 0``).
    """

    alpha: RationalAngle
    tu: tuple[fmpq, ...]
    tv: tuple[fmpq, ...]
    #: ``False`` allows points of the whole plane u + v + w = alpha (used for collocation of identities
    #: that hold on the plane, see :mod:`paper_repro.normalization`).
    check: bool = True

    def __post_init__(self) -> None:
        object.__setattr__(self, "tu", tuple(_q(x) for x in self.tu))
        object.__setattr__(self, "tv", tuple(_q(x) for x in self.tv))
        if len(self.tu) != len(self.tv):
            raise ValueError("points: tu and tv must have the same length")
        if not self.check:
            return
        for x in self.tu + self.tv:
            if not (0 <= x < 1):
                raise ValueError(f"points: quarter-angle tangents must lie in [0, 1), got {x}")
        sw = self.half_angle_values()[4]
        bad = [k for k, s in enumerate(sw) if s < 0]
        if bad:
            raise ValueError(f"points: point(s) {bad[:5]} lie outside Omega^alpha (u + v > alpha)")

    def __len__(self) -> int:
        return len(self.tu)

    def half_angle_values(self) -> list[list[fmpq]]:
        """``[sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2]`` as lists of exact rationals."""
        sh, ch = self.alpha.sin_half, self.alpha.cos_half
        out: list[list[fmpq]] = [[] for _ in range(6)]
        for tu, tv in zip(self.tu, self.tv):
            su, cu = RationalAngle(tu).sin_half, RationalAngle(tu).cos_half
            sv, cv = RationalAngle(tv).sin_half, RationalAngle(tv).cos_half
            c_uv, s_uv = cu * cv - su * sv, su * cv + cu * sv  # cos, sin of (u+v)/2
            sw = sh * c_uv - ch * s_uv  # sin(alpha/2 - (u+v)/2)
            cw = ch * c_uv + sh * s_uv
            for slot, val in enumerate((su, cu, sv, cv, sw, cw)):
                out[slot].append(val)
        return out

    def uvw_mp(self) -> np.ndarray:
        """The points as an ``(P, 3)`` object array of mpf, at the current mpmath precision."""
        a = self.alpha.mp()
        rows = []
        for tu, tv in zip(self.tu, self.tv):
            u, v = RationalAngle(tu).mp(), RationalAngle(tv).mp()
            rows.append([u, v, a - u - v])
        return np.array(rows, dtype=object).reshape(-1, 3)


def check_points(points, alpha, tol: float = DOMAIN_TOL) -> np.ndarray:
    """Return ``points`` as an ``(P, 3)`` array after checking that they lie on Omega^alpha.

    A point is accepted if ``|u + v + w - alpha| <= tol * alpha`` and ``u, v, w >= -tol * alpha``.
    Raises ``ValueError`` naming the first offending point otherwise.
    """
    check_alpha(alpha)
    arr = np.asarray(points, dtype=object if _is_mp(points) else np.float64)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"points must have shape (P, 3) of (u, v, w), got shape {np.shape(points)}")
    fl = arr.astype(np.float64)
    a = float(alpha)
    if not np.all(np.isfinite(fl)):
        raise ValueError("points must be finite")
    slack = tol * a
    bad = np.nonzero((np.abs(fl.sum(axis=1) - a) > slack) | (fl.min(axis=1) < -slack))[0]
    if bad.size:
        k = int(bad[0])
        raise ValueError(
            f"points: point {k} = {tuple(fl[k])} is not on Omega^alpha (u+v+w = alpha = {a}, u,v,w >= 0)"
            f" within tolerance {tol} * alpha")
    return arr


def _is_mp(points) -> bool:
    try:
        first = np.asarray(points, dtype=object).reshape(-1)[0]
    except (IndexError, ValueError):
        return False
    return isinstance(first, mpmath.mpf)


def half_angle_values(points, alpha, arith: Arith) -> list[np.ndarray]:
    """Six arrays ``sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2`` in the given arithmetic.

    ``points`` is an ``(P, 3)`` array of ``(u, v, w)`` for the ``float`` and ``mp`` arithmetics,
    and a :class:`RationalPoints` for ``exact`` and ``modp`` (then ``alpha`` may be ``None`` or
    must equal ``points.alpha``).
    """
    if isinstance(points, RationalPoints):
        if alpha is not None and alpha != points.alpha:
            raise ValueError("alpha does not match the alpha of the rational points")
        vals = points.half_angle_values()
        if arith.name == "exact":
            return [arith.asarray(v) for v in vals]
        if arith.name == "modp":
            assert isinstance(arith, ModpArith)
            return [arith.asarray([arith.from_fmpq(x) for x in v]) for v in vals]
        if arith.name == "mp":
            return half_angle_values(points.uvw_mp(), points.alpha.mp(), arith)
        return half_angle_values(points.uvw_mp().astype(np.float64), float(points.alpha), arith)
    if arith.name in ("exact", "modp"):
        raise ValueError(f"arith {arith.name!r} needs RationalPoints (rational quarter-angle tangents)")
    arr = check_points(points, alpha)
    return plane_half_angle_values(arr, arith)


def plane_half_angle_values(uvw: np.ndarray, arith: Arith) -> list[np.ndarray]:
    """Half-angle sines/cosines of ``(P, 3)`` points of the plane, unchecked (``float`` or ``mp``)."""
    if arith.name == "float":
        half = np.asarray(uvw, dtype=np.float64) / 2
        s, c = np.sin(half), np.cos(half)
    else:
        half = arith.asarray(uvw) / 2
        s, c = np.frompyfunc(mpmath.sin, 1, 1)(half), np.frompyfunc(mpmath.cos, 1, 1)(half)
    return [s[:, 0], c[:, 0], s[:, 1], c[:, 1], s[:, 2], c[:, 2]]


def mp_domain_points(alpha: mpmath.mpf, count: int, seed: int) -> np.ndarray:
    """``count`` seeded interior points of Omega^alpha as mpf, exactly on the plane (w = alpha - u - v)."""
    raw = sample_points(1.0, count, seed=seed)
    pts = np.empty((count, 3), dtype=object)
    for k, (x, y, _) in enumerate(raw):
        u, v = alpha * mpmath.mpf(float(x)), alpha * mpmath.mpf(float(y))
        pts[k] = (u, v, alpha - u - v)
    return pts


def barycentric_to_uvw(alpha, bary) -> np.ndarray:
    """Points ``alpha * (x, y, z)`` for barycentric ``(x, y, z)`` rows (x + y + z = 1)."""
    b = np.asarray(bary, dtype=np.float64)
    return float(alpha) * b


def sample_points(alpha, count: int, seed: int = 0, interior: bool = True) -> np.ndarray:
    """``count`` seeded uniformly random points of Omega^alpha, as an ``(count, 3)`` float array."""
    check_alpha(alpha)
    rng = np.random.default_rng(seed)
    bary = rng.dirichlet(np.ones(3), size=count)
    if interior:
        bary = 0.98 * bary + 0.02 / 3
    return float(alpha) * bary


def sample_rational_points(alpha: RationalAngle, count: int, seed: int = 0,
                           max_denominator: int = 1000) -> RationalPoints:
    """``count`` seeded random interior rational points of Omega^alpha.

    Barycentric coordinates are drawn uniformly (as :func:`sample_points`), and the quarter-angle
    tangents of u and v are rounded to rationals with denominator <= ``max_denominator``; points
    outside the domain after rounding and duplicates are redrawn.  (Points on a common grid line
    u = const would make collocation matrices rank deficient: the restriction of T_{2n} to such a
    line has dimension <= 2n + 1, so generic points are needed.)
    """
    from fractions import Fraction

    rng = np.random.default_rng(seed)
    a = float(alpha)
    seen: set[tuple[fmpq, fmpq]] = set()
    tus: list[fmpq] = []
    tvs: list[fmpq] = []
    attempts = 0
    while len(tus) < count:
        attempts += 1
        if attempts > 100 * count + 1000:
            raise ValueError(f"could not find {count} distinct rational points; raise max_denominator")
        x, y, _ = 0.98 * rng.dirichlet(np.ones(3)) + 0.02 / 3
        fu = Fraction(math.tan(a * x / 4)).limit_denominator(max_denominator)
        fv = Fraction(math.tan(a * y / 4)).limit_denominator(max_denominator)
        key = (fmpq(fu.numerator, fu.denominator), fmpq(fv.numerator, fv.denominator))
        if key in seen or key[0] <= 0 or key[1] <= 0:
            continue
        if 4 * math.atan(float(fu)) + 4 * math.atan(float(fv)) >= a * (1 - 1e-9):
            continue
        seen.add(key)
        tus.append(key[0])
        tvs.append(key[1])
    return RationalPoints(alpha, tuple(tus), tuple(tvs))
