"""The domain Omega^alpha = {(u, v, w): u + v + w = alpha, u, v, w >= 0} and its points.

Two kinds of points:

* real points ``(u, v, w)`` (float or mpmath), checked to lie on Omega^alpha within
  :data:`~paper_repro.util.validation.DOMAIN_TOL` (relative to alpha);
* rational points (:class:`RationalPoints`): alpha, u and v are given through the rational
  tangents of their quarter angles, ``t = tan(x/4)``, so that ``sin(x/2) = 2t/(1+t^2)`` and
  ``cos(x/2) = (1-t^2)/(1+t^2)`` are rational; w/2 = alpha/2 - u/2 - v/2 then has rational sine and
  cosine by the angle-difference formulas.  Every basis function is then an exact rational.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.context import Context, ExactContext, FloatContext
from paper_repro.util.limits import MAX_RATIONAL_POINTS, MAX_SAMPLE_POINTS, check_int, check_real_array
from paper_repro.util.validation import DOMAIN_TOL, check_alpha, parse_alpha


def _q(x, name: str = "t") -> fmpq:
    """An exact rational from fmpq, int, ``Fraction``, a pair ``(p, q)`` of integers, ``'p/q'`` or a float (its
    exact binary value); ``TypeError``/``ValueError`` naming ``name`` otherwise."""
    from fractions import Fraction

    from paper_repro.util.limits import real_scalar

    if isinstance(x, fmpq):
        return x
    if isinstance(x, tuple):
        if len(x) != 2:
            raise TypeError(f"{name} must be a rational: a pair (p, q) of integers, got a tuple of length {len(x)}")
        if any(isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)) for v in x):
            raise TypeError(f"{name} must be a rational: a pair (p, q) of integers, got {x!r}")
        p, q = (int(v) for v in x)
        if q == 0:
            raise ValueError(f"{name} = {p}/0: the denominator q of (p, q) must not be 0")
        return fmpq(p, q)
    if isinstance(x, str):
        try:
            f = Fraction(x.strip())
        except (ValueError, ZeroDivisionError):
            raise ValueError(f"{name} must be a rational like '1/3', got {x!r}") from None
        return fmpq(f.numerator, f.denominator)
    x = real_scalar(x, name)
    if isinstance(x, int):
        return fmpq(x)
    try:
        f = Fraction(x)
    except (TypeError, ValueError, OverflowError):
        raise TypeError(f"{name} must be a finite rational or real number, got {x!r}") from None
    return fmpq(f.numerator, f.denominator)


def _sin_half(t: fmpq) -> fmpq:
    return 2 * t / (1 + t**2)


def _cos_half(t: fmpq) -> fmpq:
    return (1 - t**2) / (1 + t**2)


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
        return _sin_half(self.t)

    @property
    def cos_half(self) -> fmpq:
        return _cos_half(self.t)

    def mp(self) -> mpmath.mpf:
        """The angle itself, ``4 atan(t)``, at the current mpmath precision."""
        return 4 * mpmath.atan(mpmath.mpf(int(self.t.p)) / int(self.t.q))

    def __float__(self) -> float:
        return 4 * math.atan(int(self.t.p) / int(self.t.q))


def open_alpha(alpha):
    """alpha read (:func:`~paper_repro.util.validation.parse_alpha`) and checked to lie in (0, pi): a float or mpf by
    :func:`~paper_repro.util.validation.check_alpha`, a :class:`RationalAngle` by tan(alpha/4) != 0.

    >>> open_alpha(1.0)
    1.0
    """
    alpha = parse_alpha(alpha)
    if isinstance(alpha, RationalAngle):
        if alpha.t == 0:
            raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
        return alpha
    check_alpha(alpha)
    return alpha


def rational_alpha(t) -> RationalAngle:
    """Shape parameter alpha = 4 atan(t) for rational ``0 < t < 1`` (so alpha in (0, pi))."""
    a = RationalAngle(_q(t, "t"))
    if a.t == 0:
        raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
    return a


@dataclass(frozen=True)
class RationalPoints:
    """Points of Omega^alpha with rational half-angle sines and cosines.

    ``tu[k]``, ``tv[k]`` are ``tan(u/4)``, ``tan(v/4)`` of the k-th point; w = alpha - u - v must be
    >= 0 (checked exactly: ``sin(w/2) >= 0``).
    """

    alpha: RationalAngle | None
    tu: tuple[fmpq, ...]
    tv: tuple[fmpq, ...]
    #: ``False`` allows points of the whole plane u + v + w = alpha (used for collocation of identities
    #: that hold on the plane, see :mod:`paper_repro.core.normalization`).
    check: bool = True

    def __post_init__(self) -> None:
        for name in ("tu", "tv"):
            seq = getattr(self, name)
            if isinstance(seq, (str, bytes)) or not hasattr(seq, "__iter__"):
                raise TypeError(f"points: {name} must be a sequence of rationals (one per point), got {seq!r}")
        object.__setattr__(self, "tu", tuple(_q(x) for x in self.tu))
        object.__setattr__(self, "tv", tuple(_q(x) for x in self.tv))
        if len(self.tu) != len(self.tv):
            raise ValueError("points: tu and tv must have the same length")
        if not self.check:
            return
        if not isinstance(self.alpha, RationalAngle):
            raise TypeError(f"points: alpha must be a RationalAngle, got {type(self.alpha).__name__}")
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
        return [list(v) for v in half_angle_values(self, None, ExactContext())]

    def quarter_values(self) -> list[list[fmpq]]:
        """``[sin u/2, cos u/2, sin v/2, cos v/2]`` exactly (no alpha needed)."""
        out: list[list[fmpq]] = [[], [], [], []]
        for tu, tv in zip(self.tu, self.tv):
            vals = (_sin_half(tu), _cos_half(tu), _sin_half(tv), _cos_half(tv))
            for slot, val in enumerate(vals):
                out[slot].append(val)
        return out

    def uvw_float(self) -> np.ndarray:
        """The points as an ``(P, 3)`` float array."""
        a = float(self.alpha)  # type: ignore[arg-type]
        rows = [[float(RationalAngle(tu)), float(RationalAngle(tv))] for tu, tv in zip(self.tu, self.tv)]
        return np.array([[u, v, a - u - v] for u, v in rows], dtype=np.float64).reshape(-1, 3)

    def uvw_mp(self) -> np.ndarray:
        """The points as an ``(P, 3)`` object array of mpf, at the current mpmath precision."""
        a = self.alpha.mp()  # type: ignore[union-attr]
        rows = []
        for tu, tv in zip(self.tu, self.tv):
            u, v = RationalAngle(tu).mp(), RationalAngle(tv).mp()
            rows.append([u, v, a - u - v])
        return np.array(rows, dtype=object).reshape(-1, 3)


def check_points(points, alpha, tol: float = DOMAIN_TOL, offset: int = 0, *, alpha_checked: bool = False
                 ) -> np.ndarray:
    """Return ``points`` as an ``(P, 3)`` array after checking that they lie on Omega^alpha.

    A point is accepted if ``|u + v + w - alpha| <= tol * alpha`` and ``u, v, w >= -tol * alpha``.
    Raises ``ValueError``/``TypeError`` naming ``points`` (and the first offending point) otherwise.
    ``alpha_checked``: inner callers whose ``alpha`` (a float) is already validated.
    """
    a = float(alpha) if alpha_checked else check_alpha(parse_alpha(alpha))
    if isinstance(points, (str, bytes)):
        raise TypeError(f"points must be a (P, 3) array of (u, v, w), got a string {points!r}")
    if isinstance(points, (dict, set, numbers.Number, np.generic)) or points is None:
        raise TypeError(f"points must be a (P, 3) array of real numbers (u, v, w), got {type(points).__name__}")
    check_real_array(points, "points")
    try:
        arr = np.asarray(points, dtype=object if _is_mp(points) else np.float64)
        fl = arr.astype(np.float64)
    except (TypeError, ValueError):
        raise TypeError("points must be a (P, 3) array of real numbers (u, v, w)") from None
    if arr.ndim == 1 and arr.shape[0] == 3:
        arr, fl = arr.reshape(1, 3), fl.reshape(1, 3)
    if arr.ndim != 2 or arr.shape[1] != 3 or arr.shape[0] == 0:
        raise ValueError(f"points must have shape (P, 3) of (u, v, w) with P >= 1, got shape {np.shape(points)}")
    slack = tol * a
    finite: np.ndarray = np.asarray(np.isfinite(fl).all(axis=1))
    with np.errstate(invalid="ignore", over="ignore"):
        bad = np.nonzero(~finite | (np.abs(fl.sum(axis=1) - a) > slack) | (fl.min(axis=1) < -slack))[0]
    if bad.size:  # the first bad point, whichever way it is bad
        k = int(bad[0])
        pt_index = k + offset
        pt = ", ".join(f"{float(x):.6g}" for x in fl[k])
        if not finite[k]:
            raise ValueError(f"points must be finite (no NaN or inf): point {pt_index} = ({pt})")
        raise ValueError(
            f"points: point {pt_index} = ({pt}) is not on Omega^alpha (u + v + w = alpha = {a:.6g}, u, v, w >= 0)"
            f" within tolerance {tol} * alpha")
    return arr


def _is_mp(points) -> bool:
    try:
        first = np.asarray(points, dtype=object).reshape(-1)[0]
    except (IndexError, ValueError):
        return False
    return isinstance(first, mpmath.mpf)


def half_angle_values(points, alpha, ctx: Context) -> list[np.ndarray]:
    """Six arrays ``sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2`` in the context ``ctx``.

    ``points`` is a :class:`RationalPoints` (every context: the rational half-angle values of u and v
    are converted, w follows from :meth:`Context.w_half`; ``alpha`` may be ``None``, then the
    points' own alpha is used, or a number, for alpha-independent collocation points) or a ``(P, 3)``
    array of real ``(u, v, w)`` (the real contexts only).

    >>> from paper_repro.core.context import get_context
    >>> a = rational_alpha(fmpq(1, 2))
    >>> pts = RationalPoints(a, (fmpq(1, 5),), (fmpq(1, 7),))
    >>> sw_exact = half_angle_values(pts, None, get_context("exact"))[4][0]
    >>> sw_float = half_angle_values(pts.uvw_float(), float(a), get_context("float"))[4][0]
    >>> bool(abs(float(sw_exact) - sw_float) < 1e-15)
    True
    """
    if isinstance(points, RationalPoints):
        if alpha is None:
            alpha = points.alpha
            if alpha is None:
                raise ValueError("alpha: these points carry no alpha; pass alpha")
        elif points.alpha is not None and alpha != points.alpha:
            raise ValueError("alpha does not match the alpha of the rational points")
        with ctx.scope():
            su, cu, sv, cv = (ctx.asarray([ctx.from_rational(x) for x in col]) for col in points.quarter_values())
            sa, ca = ctx.alpha_half(alpha)
            sw, cw = ctx.w_half(ctx, sa, ca, su, cu, sv, cv)
        return [su, cu, sv, cv, sw, cw]
    if ctx.exact:
        raise TypeError(f"arith {ctx.name!r} needs RationalPoints (rational quarter-angle tangents), "
                        f"got {type(points).__name__}")
    arr = check_points(points, alpha)
    return plane_half_angle_values(arr, ctx)


#: Below this alpha the float sine ratios sin(x/2)/sin(alpha/2) are taken as x/alpha (relative error < 1e-17).
SMALL_ALPHA = 1e-8


def scaled_half_angle_values(points, alpha, ctx: Context) -> list[np.ndarray]:
    """Like :func:`half_angle_values`, but the three sines divided by ``s = sin(alpha/2)``.

    Every function of T_{2n} of level j has exactly 2n + j sine factors, so ``r f = (s^{2n+j} r) * f / s^{2n+j}``
    is the scaled coefficient times the monomial in these ratios, each in [0, 1] on Omega^alpha: nothing
    overflows or underflows for any alpha in (0, pi).  In float64 the ratios are ``x / alpha`` below
    :data:`SMALL_ALPHA` (where sin(x/2) = x/2 to the last bit) and ``sin(x/2) / sin(alpha/2)`` above.

    >>> from paper_repro.core.context import get_context
    >>> vals = scaled_half_angle_values([[5e-301, 3e-301, 2e-301]], 1e-300, get_context("float"))
    >>> [float(round(v[0], 12)) for v in vals[::2]]
    [0.5, 0.3, 0.2]
    """
    if isinstance(points, RationalPoints) or ctx.exact or not isinstance(ctx, FloatContext):
        vals = half_angle_values(points, alpha, ctx)
        a = alpha if alpha is not None else points.alpha
        with ctx.scope():
            sa, _ = ctx.alpha_half(a)
            for slot in (0, 2, 4):
                vals[slot] = ctx.div(vals[slot], sa)
        return vals
    arr = check_points(points, alpha)
    a = float(alpha)
    vals = plane_half_angle_values(arr, ctx)
    if a < SMALL_ALPHA:
        ratio = np.clip(arr / a, 0.0, None)
        return [ratio[:, 0], vals[1], ratio[:, 1], vals[3], ratio[:, 2], vals[5]]
    sa = math.sin(a / 2)
    return [vals[0] / sa, vals[1], vals[2] / sa, vals[3], vals[4] / sa, vals[5]]


def plane_half_angle_values(uvw: np.ndarray, ctx: Context) -> list[np.ndarray]:
    """Half-angle sines/cosines of ``(P, 3)`` real points of the plane, unchecked."""
    with ctx.scope():
        half = ctx.div(ctx.asarray(uvw), ctx.convert(2))
        s, c = ctx.sin(half), ctx.cos(half)
    return [s[:, 0], c[:, 0], s[:, 1], c[:, 1], s[:, 2], c[:, 2]]


def mp_domain_points(alpha: mpmath.mpf, count: int, seed: int) -> np.ndarray:
    """``count`` seeded interior points of Omega^alpha as mpf, exactly on the plane (w = alpha - u - v)."""
    raw = sample_points(1.0, count, seed=seed)
    pts = np.empty((count, 3), dtype=object)
    for k, (x, y, _) in enumerate(raw):
        u, v = alpha * mpmath.mpf(float(x)), alpha * mpmath.mpf(float(y))
        pts[k] = (u, v, alpha - u - v)
    return pts


#: how far a barycentric row may miss x + y + z = 1 (or dip below 0): rounding of rows computed in float64
BARY_TOL = 1e-12


def check_barycentric(bary, name: str = "bary") -> np.ndarray:
    """Barycentric ``(x, y, z)`` rows as a float array of the given shape (``(3,)`` or ``(m, 3)``): real, finite,
    each row summing to 1 and >= 0 (to :data:`BARY_TOL`); ``ValueError``/``TypeError`` naming the first offending row
    as the user gave it.

    >>> check_barycentric([[0.5, 0.5, 0.5]])
    Traceback (most recent call last):
    ...
    ValueError: bary row 0 = (0.5, 0.5, 0.5) sums to 1.5: barycentric rows (x, y, z) must sum to 1, with x, y, z >= 0
    """
    raw = np.asarray(bary)
    if raw.dtype == object or np.iscomplexobj(raw) or raw.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be real numbers (x, y, z), got an array of {raw.dtype}")
    b = np.atleast_2d(raw.astype(np.float64))
    if b.ndim != 2 or b.shape[1] != 3:
        raise ValueError(f"{name} must be rows (x, y, z): shape (m, 3), got shape {raw.shape}")
    bad = ~np.isfinite(b).all(axis=1) | (np.abs(b.sum(axis=1) - 1) > BARY_TOL) | (b.min(axis=1, initial=0) < -BARY_TOL)
    if bad.any():
        k = int(np.argmax(bad))
        row = "(" + ", ".join(f"{x:g}" for x in b[k]) + ")"
        why = ("is not finite" if not np.isfinite(b[k]).all() else
               f"sums to {b[k].sum():g}" if abs(b[k].sum() - 1) > BARY_TOL else "has a negative entry")
        raise ValueError(f"{name} row {k} = {row} {why}: barycentric rows (x, y, z) must sum to 1, with x, y, z >= 0")
    return b.reshape(raw.shape)


def barycentric_to_uvw(alpha, bary) -> np.ndarray:
    """Points ``alpha * (x, y, z)`` for barycentric ``(x, y, z)`` rows (x + y + z = 1, x, y, z >= 0; checked by
    :func:`check_barycentric`)."""
    return float(alpha) * check_barycentric(bary)


def check_count(count, name: str = "count", limit: int = 10**8, why: str = "") -> int:
    """A number of points: an integer from 0 to ``limit`` (larger requests would not fit in memory)."""
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or not 0 <= count <= limit:
        raise ValueError(f"{name} must be an integer from 0 to {limit}, got {count!r}" + (f" ({why})" if why else ""))
    return int(count)


def sample_points(alpha, count: int, seed: int = 0, interior: bool = True) -> np.ndarray:
    """``count`` seeded uniformly random points of Omega^alpha, as an ``(count, 3)`` float array.

    >>> sample_points(1.0, -1)
    Traceback (most recent call last):
    ...
    ValueError: count must be an integer from 0 to 30000000, got -1 (about 52 bytes per point at the peak: 2 GB budget)
    """
    alpha = parse_alpha(alpha)
    check_count(count, limit=MAX_SAMPLE_POINTS, why="about 52 bytes per point at the peak: 2 GB budget")
    if not isinstance(interior, (bool, np.bool_)):
        raise TypeError(f"interior must be True or False, got {interior!r}")
    rng = np.random.default_rng(check_int(seed, "seed", 0))
    bary = rng.dirichlet(np.ones(3), size=count)
    if interior:
        bary = 0.98 * bary + 0.02 / 3
    return float(alpha) * bary


def sample_rational_points(alpha: RationalAngle, count: int, seed: int = 0,
                           max_denominator: int | None = None) -> RationalPoints:
    """``count`` seeded random interior rational points of Omega^alpha.

    Barycentric coordinates are drawn uniformly (as :func:`sample_points`), and the quarter-angle
    tangents of u and v are rounded to rationals with denominator <= ``max_denominator``; points
    outside the domain after rounding and duplicates are redrawn.  (Points on a common grid line
    u = const would make collocation matrices rank deficient: the restriction of T_{2n} to such a
    line has dimension <= 2n + 1, so generic points are needed.)  ``max_denominator`` defaults to 1000 for
    alpha >= 1/2 and grows like 1/alpha below (small triangles need finer rationals to stay generic).
    """
    from fractions import Fraction

    if not isinstance(alpha, RationalAngle):
        raise TypeError(f"alpha must be a RationalAngle, got {type(alpha).__name__}")
    check_int(count, "count", 0, MAX_RATIONAL_POINTS, why="rational points are drawn one by one")
    rng = np.random.default_rng(check_int(seed, "seed", 0))
    a = float(alpha)
    if max_denominator is None:
        max_denominator = 1000 if a >= 0.5 else int(500 / a)
    else:
        max_denominator = check_int(max_denominator, "max_denominator", 1)
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
