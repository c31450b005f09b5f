"""Normalizing coefficients of T_{2n}^alpha (Section sec:partition_of_unity, eq. normalizing_weights).

The coefficients ``r_{2n,2n-i,j}, g_{...}, b_{...}`` are the unique solution of
``1 = sum_f x_f f(u, v, w)`` on Omega^alpha.  The library evaluates them from the all-n formula
(:mod:`paper_repro.core.normalizing_formula`, proven in docs/question1_for_all_n.md) in every arithmetic, with
no linear solve (:func:`orbit_coefficients`, :func:`scaled_orbit_coefficients`).  This module also keeps the
independent route, used by tests and claims to check the formula -- the collocation solve, which knows nothing
of any closed form:

* Symmetry: the group of the six permutations of (u, v, w) maps T_{2n} onto itself (claim
  ``symmetry``), so by uniqueness the coefficients are constant on its orbits; there are
  (n+1)(n+2)/2 orbits, each named by its R representative ``r_{2n,2n-i,j}`` with ``i = j..n``
  (the reduced system suggested after Example normalizing_coefficients_n_3).  The full system with
  delta_n unknowns (:func:`solve_full_exact`) is used to check this independently.
* Collocation points: the identity is one of trigonometric polynomials on the plane u + v + w = alpha
  (it holds on the triangle, hence everywhere on the plane), so the collocation points may be fixed
  independently of alpha (:func:`fixed_points`; w = alpha - u - v may be negative).  Then every
  coefficient is a rational function of t = tan(alpha/4) of bounded degree (:func:`cramer_degree_bound`),
  which is what makes the closed-form checks of :mod:`paper_repro.theory.closed_forms` proofs.

Arithmetics: exact rationals at rational-tangent alpha (``'exact'``), mpmath (``'mp'``) and float.
"""

from __future__ import annotations

import math
from functools import cache, lru_cache

import mpmath
import numpy as np
from flint import arb, fmpq

from paper_repro.core.alphas import alpha_mp
from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import Collocation, collocate
from paper_repro.core.context import BallContext, Context, ExactContext, FloatContext, LogContext, get_context
from paper_repro.core.domain import RationalAngle, RationalPoints, mp_domain_points
from paper_repro.core.labels import (
    BasisLabel,
    _united_system,
    compose,
    delta,
    delta_unchecked,
    exponent_matrix,
    exponents,
    united_system,
)
from paper_repro.core.normalizing_formula import scaled_table, sin_powers
from paper_repro.util.cache import cached, rational_text
from paper_repro.util.validation import check_alpha, check_n

#: Largest orders for the normalizing coefficients from the all-n formula (n^3 operations; measured on the 2-core
#: machine: exact n = 45 in 0.2 s, n = 100 in 4 s; mp at 30 digits n = 40 in 2.6 s, n = 80 in 18 s (so about 50 s
#: at n = 120); float n = 200 in 0.6 s; logarithms n = 500 in 17 s, n = 1000 in about 105 s).
MAX_N_EXACT = 200
MAX_N_MP = 120
MAX_N_FLOAT = 1000
MAX_N_LOG = 1000
#: Float ``coefficients``/``orbit_coefficients`` up to this n are rounded once from a certified ball evaluation of the
#: formula (:func:`certified_orbit_floats`; measured on the loaded 2-core machine: n = 20 in 0.01 s, 50 in 0.08 s,
#: 100 in 0.5 s, cached per (n, alpha)); beyond, the float64 formula (sums of non-negative terms).
MAX_N_CERTIFIED = 100
#: Kept for the collocation solve (the independent check): (n+1)(n+2)/2 unknowns.
MAX_N_COEFFICIENTS = 60
_LOG_FLOAT_MAX = math.log(np.finfo(np.float64).max)

PERMUTATIONS = ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))


def orbits(n: int) -> tuple[tuple[BasisLabel, tuple[int, ...]], ...]:
    """Orbits of T_{2n} under permutations of (u, v, w): ``(R representative, member indices)``.

    Representatives are ``R_{2n,2n-i,j}`` with ``j = 0..n``, ``i = j..n``, ordered by (j, i).
    """
    return _orbits(check_n(n))


@cache
def _orbits(n: int) -> tuple[tuple[BasisLabel, tuple[int, ...]], ...]:
    """:func:`orbits` for inner code (``n`` already checked)."""
    labels = _united_system(n)
    by_exps = {tuple(e): k for k, e in enumerate(exponent_matrix(n).tolist())}  # = exponents(labels[k])
    out = []
    for j in range(n + 1):
        for i in range(j, n + 1):
            rep = BasisLabel("R", n, i, j)
            members = sorted({by_exps[compose(exponents(rep), s)] for s in PERMUTATIONS})
            out.append((rep, tuple(members)))
    covered = sorted(k for _, m in out for k in m)
    if covered != list(range(len(labels))):
        raise AssertionError(f"orbits of T_{2 * n} do not partition it (n = {n})")
    return tuple(out)


def orbit_matrix(n: int) -> np.ndarray:
    """``(delta_n, m)`` 0/1 matrix: column o sums the functions of orbit o."""
    orb = orbits(n)
    mat = np.zeros((len(united_system(n)), len(orb)), dtype=np.int64)
    for o, (_, members) in enumerate(orb):
        mat[list(members), o] = 1
    return mat


@cache
def fixed_points(n: int, count: int, seed: int = 0) -> tuple[tuple[fmpq, ...], tuple[fmpq, ...]]:
    """``count`` alpha-independent collocation points: quarter tangents (tu, tv) = (a/q, b/q), 0 < a < b < q.

    ``a < b`` matters: the orbit sums are symmetric functions, so the points (u, v, w) and (v, u, w)
    would give equal rows.
    """
    rng = np.random.default_rng(seed + 1000 * n)
    q = max(17, int(2 * np.sqrt(2 * count)) + 3)
    seen: set[tuple[int, int]] = set()
    while len(seen) < count:
        a, b = sorted(int(x) for x in rng.choice(np.arange(1, q), size=2, replace=False))
        seen.add((a, b))
    pairs = sorted(seen, key=lambda ab: (rng.random(), ab))  # seeded shuffle, reproducible
    return tuple(fmpq(a, q) for a, _ in pairs), tuple(fmpq(b, q) for _, b in pairs)


def _plane_points(tu, tv) -> RationalPoints:
    """alpha-independent points of the plane u + v + w = alpha (w may be negative)."""
    return RationalPoints(None, tuple(tu), tuple(tv), check=False)


@cache
def _orbit_columns(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Columns of T_{2n} ordered orbit by orbit, and where each orbit starts (for ``np.add.reduceat``)."""
    perm = [k for _, members in orbits(n) for k in members]
    starts = np.cumsum([0] + [len(m) for _, m in orbits(n)][:-1])
    return np.array(perm), starts


def reduced_matrix(n: int, alpha, pts: RationalPoints, ctx: Context) -> np.ndarray:
    """``(P, m)`` array: the orbit sums of T_{2n} at the points, in the context ``ctx``."""
    vals = evaluate(n, alpha, pts, ctx)
    perm, starts = _orbit_columns(n)
    with ctx.scope():
        sums = np.add.reduceat(vals[:, perm], starts, axis=1)  # at most 6 terms per sum
        return ctx.add(sums, ctx.zeros(sums.shape))  # brings the sums back into the arithmetic (mod p)


def solve_reduced(n: int, alpha, ctx: Context, *, verify: int = 3, seed: int = 0,
                  attempts: int = 5) -> Collocation:
    """Orbit coefficients (in :func:`orbits` order) by :func:`~paper_repro.core.collocation.collocate`.

    The square system at m fixed alpha-independent points (:func:`fixed_points`) is solved in ``ctx``
    and the identity checked at ``verify`` further points; a singular point set is replaced by the
    next one, up to ``attempts`` sets.
    """
    n = check_n(n)
    m = len(orbits(n))

    def system(k: int):
        tu, tv = fixed_points(n, m + verify, seed + k)
        a = reduced_matrix(n, alpha, _plane_points(tu, tv), ctx)
        return a, ctx.ones((a.shape[0], 1))

    return collocate(ctx, system, m, attempts=attempts, what=f"partition of unity (n={n})")


def solve_reduced_exact(n: int, alpha: RationalAngle, *, verify: int = 3, seed: int = 0,
                        attempts: int = 5) -> tuple[list[fmpq], int]:
    """Exact orbit coefficients at rational-tangent alpha: ``(solution, index of the point set used)``."""
    res = solve_reduced(n, alpha, ExactContext(), verify=verify, seed=seed, attempts=attempts)
    return list(res.solution.reshape(-1)), res.point_set


def solve_full_exact(n: int, alpha: RationalAngle, *, seed: int = 0) -> list[fmpq]:
    """Exact coefficients of all delta_n functions (no symmetry assumed), internal order."""
    ctx = ExactContext()
    d = len(united_system(n))

    def system(k: int):
        tu, tv = fixed_points(n, d, seed + 77 + k)
        vals = evaluate(n, alpha, _plane_points(tu, tv), ctx)
        return vals, ctx.ones((d, 1))

    return list(collocate(ctx, system, d, what=f"full partition of unity (n={n})").solution.reshape(-1))


def cramer_degree_bound(n: int) -> int:
    """Degree bound in t = tan(alpha/4) of numerator and denominator of every orbit coefficient.

    Rows are multiplied by (1+t^2)^{2n}: each entry is a polynomial in sin(alpha/2), cos(alpha/2)
    of degree <= 2n (the w-degree of every function is <= 2n and sin(w/2), cos(w/2) are linear in
    them), i.e. of degree <= 4n in t; by Cramer's rule numerator and denominator have degree <= 4n m.
    """
    return 4 * n * len(orbits(n))


def parse_fmpq(text: str) -> fmpq:
    """``'-3/4'`` or ``'5'`` to fmpq."""
    return fmpq(*map(int, text.split("/"))) if "/" in text else fmpq(int(text))


def exact_coefficients_cached(n: int, alpha: RationalAngle) -> tuple[list[fmpq], int]:
    """:func:`solve_reduced_exact` memoised on disk: ``(solution, point set index)``."""

    def compute():
        sol, attempt = solve_reduced_exact(n, alpha)
        return {"solution": [str(x) for x in sol], "point_set": attempt}

    def validate(value) -> str | None:
        sol, m = value["solution"], len(orbits(n))
        if not isinstance(sol, list) or len(sol) != m or not all(rational_text(x) for x in sol):
            return f"solution is not a list of {m} exact rationals"
        return None if type(value["point_set"]) is int else "point_set is not an integer"

    stored = cached("orbit_coefficients", {"n": n, "t": str(alpha.t)}, compute, validate=validate)
    return [parse_fmpq(x) for x in stored["solution"]], stored["point_set"]


def _half_angle(alpha, ctx: Context):
    """``(c, s, s^2)`` of alpha/2 in the context (alpha a RationalAngle, or a real in (0, pi))."""
    if isinstance(alpha, RationalAngle):
        if alpha.t == 0:
            raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
        sh, ch = ctx.from_rational(alpha.sin_half), ctx.from_rational(alpha.cos_half)
    else:
        if ctx.exact:
            raise TypeError(f"alpha must be a RationalAngle (rational tan(alpha/4)) for arith {ctx.name!r}, "
                            f"got {type(alpha).__name__}")
        if not ctx.encloses or not isinstance(alpha, arb):
            check_alpha(alpha)
        sh, ch = ctx.alpha_half(alpha)
    return ch, sh, ctx.mul(sh, sh)


def _float_half_angle(alpha) -> tuple[float, float, float]:
    """``(c, s, s^2)`` in float64, accurate for every alpha in (0, pi) (also below 1e-154, where s^2 underflows:
    then it is 0 to within float64's range, which is what the formula needs).  Inner: ``alpha`` is checked by the
    public callers."""
    a = float(alpha)
    s = math.sin(a / 2)
    return math.cos(a / 2), s, s * s


@lru_cache(maxsize=64)
def _log_scaled_float(n: int, a: float) -> tuple[float, ...]:
    c, _, s2 = _float_half_angle(a)
    ctx = LogContext()
    return tuple(float(x) for x in scaled_table(n, ctx.convert(c), ctx.convert(s2), ctx))


@lru_cache(maxsize=64)
def _scaled_float(n: int, a: float) -> tuple[float, ...] | None:
    c, _, s2 = _float_half_angle(a)
    with np.errstate(over="ignore", invalid="ignore"):
        try:
            vals = scaled_table(n, c, s2, FloatContext())
        except OverflowError:
            return None
    vals = tuple(float(x) for x in vals)
    return vals if all(math.isfinite(x) for x in vals) else None


#: Largest ball precision (bits) tried by :func:`certified_orbit_floats` (128 bits certify 60 bits for every case
#: measured: the formula adds non-negative terms, so the relative radius grows only with the number of operations).
_MAX_CERT_PREC = 4096


@lru_cache(maxsize=256)
def certified_orbit_floats(n: int, alpha, scaled: bool) -> tuple[float, ...]:
    """Orbit coefficients (``scaled``: ``s^{2n+j} r``) rounded once to float64 from a ball evaluation of the all-n
    formula at the exact alpha (a float is an exact binary rational; a :class:`RationalAngle` gives exact half-angle
    values): every value is certified to a relative 2^-60 before rounding, so it is the correctly rounded value
    (or one of the two floats next to it when the true value lies within 2^-60 of a midpoint).  ``ValueError`` when
    a value exceeds float64.

    >>> from paper_repro.core.domain import rational_alpha
    >>> certified_orbit_floats(1, rational_alpha(fmpq(1, 2)), False)  # 25/16, 15/8, 5/2 (Example n = 1)
    (1.5625, 1.875, 2.5)
    """
    prec = 128
    while prec <= _MAX_CERT_PREC:
        ctx = BallContext(prec=prec)
        with ctx.scope():
            a = alpha if isinstance(alpha, RationalAngle) else arb(alpha)
            c, s, s2 = _half_angle(a, ctx)
            vals = scaled_table(n, c, s2, ctx)
            if not scaled:
                vals = [x / s**k for x, k in zip(vals, sin_powers(n))]
            tol = arb(2) ** -60
            if all(x.mid() != 0 and x.rad() <= abs(x.mid()) * tol for x in vals):
                out = tuple(float(x.mid()) for x in vals)
                break
        prec *= 2
    else:  # pragma: no cover - not reached for n <= MAX_N_CERTIFIED (measured)
        raise ArithmeticError(f"normalizing coefficients n = {n}, alpha = {alpha!r}: not certified at "
                              f"{_MAX_CERT_PREC} bits")
    if not all(math.isfinite(x) for x in out):
        k = next(i for i, x in enumerate(out) if not math.isfinite(x))
        size = float(vals[k].mid().log())
        raise ValueError(f"alpha = {float(alpha)!r}: the normalizing coefficient of level {sin_powers(n)[k] - 2 * n} "
                         f"of order n = {n} is about e^{size:.0f} and exceeds float64; use scaled_orbit_coefficients "
                         "(s^(2n+j) r, always finite) or arith='mp'")
    return out


def log_scaled_orbit_coefficients(n: int, alpha) -> list[float]:
    """Natural logarithms of ``s^{2n+j} r_{2n,2n-i,j}`` (orbit order), float64, for every n up to
    :data:`MAX_N_LOG` and every alpha in (0, pi): the logarithm never overflows.

    >>> import math
    >>> [round(math.exp(x), 12) for x in log_scaled_orbit_coefficients(1, 2.0)][:2]
    [1.0, 1.080604611736]
    """
    n = check_n(n)
    if n > MAX_N_LOG:
        raise ValueError(f"n must be at most {MAX_N_LOG} for the logarithmic coefficients (cost grows as n^3: about "
                         f"100 s at n = 1000), got {n}")
    return list(_log_scaled_float(n, float(alpha) if isinstance(alpha, RationalAngle) else check_alpha(alpha)))


def scaled_orbit_coefficients(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> list:
    """``s^{2n+j} r_{2n,2n-i,j}`` for the orbit representatives (order of :func:`orbits`), s = sin(alpha/2).

    Evaluated from the all-n formula (:mod:`paper_repro.core.normalizing_formula`) in the given arithmetic: a sum
    of non-negative terms, so float64 keeps its relative accuracy; bounded as alpha -> 0 (the limit factors of
    Question 7.3), so it stays finite for every alpha in (0, pi).  In float64 it overflows only where the value
    itself exceeds float64 (e.g. n > 200 near alpha = 0): then ``ValueError`` points to
    :func:`log_scaled_orbit_coefficients`.

    >>> from paper_repro.core.domain import rational_alpha
    >>> [str(x) for x in scaled_orbit_coefficients(1, rational_alpha(fmpq(1, 2)), "exact")]
    ['1', '6/5', '32/25']
    """
    n = check_n(n)
    ctx = get_context(arith, dps=mpmath.mp.dps if dps is None else dps)
    limit = MAX_N_FLOAT if isinstance(ctx, FloatContext) else MAX_N_EXACT if ctx.exact else MAX_N_MP
    if n > limit:
        raise ValueError(f"n must be at most {limit} for normalizing coefficients in arith {ctx.name!r} (the cost "
                         f"grows as n^3 operations on numbers of O(n) digits), got {n}")
    if isinstance(ctx, FloatContext):
        a = float(alpha) if isinstance(alpha, RationalAngle) else check_alpha(alpha)
        vals = _scaled_float(n, a)
        if vals is None:
            raise ValueError(f"n = {n}, alpha = {a!r}: s^(2n+j) r exceeds float64 for some coefficient; use "
                             "log_scaled_orbit_coefficients(n, alpha) (natural logarithms) or arith='mp'")
        return list(vals)
    with ctx.scope():
        c, _, s2 = _half_angle(alpha, ctx)
        return scaled_table(n, c, s2, ctx)


def orbit_coefficients(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> list:
    """Orbit coefficients ``r_{2n,2n-i,j}`` (order of :func:`orbits`) in any arithmetic, from the all-n formula
    (no linear solve): ``s^{-(2n+j)}`` times :func:`scaled_orbit_coefficients`.

    Exact arithmetics (``'exact'``, ``'modp'``): alpha must be a :class:`RationalAngle`.  ``'ball'`` gives
    certified enclosures, ``'mp'`` works at ``dps`` digits.  In ``'float'`` a coefficient that exceeds float64
    (small alpha: r grows like alpha^-(2n+j)) raises ``ValueError``; the scaled values never do.

    At tan(alpha/4) = 1/2 (sin(alpha/2) = 4/5, cos(alpha/2) = 3/5) Example normalizing_coefficients_n_1
    gives 1/s^2 = 25/16, 2c/s^2 = 15/8 and 2/s = 5/2:

    >>> from paper_repro.core.domain import rational_alpha
    >>> [str(x) for x in orbit_coefficients(1, rational_alpha(fmpq(1, 2)), "exact")]
    ['25/16', '15/8', '5/2']
    """
    n = check_n(n)
    ctx = get_context(arith, dps=mpmath.mp.dps if dps is None else dps)
    if isinstance(ctx, FloatContext) and n <= MAX_N_CERTIFIED:
        return list(certified_orbit_floats(n, _certifiable_alpha(alpha), False))
    scaled = scaled_orbit_coefficients(n, alpha, ctx, dps=dps)
    powers = sin_powers(n)
    if isinstance(ctx, FloatContext):
        _, s, _ = _float_half_angle(alpha)
        log_s = math.log(s) if s > 0 else math.log(float(alpha) / 2)
        out = []
        for x, k in zip(scaled, powers):
            lx = math.log(x) - k * log_s
            if lx > _LOG_FLOAT_MAX:
                raise ValueError(f"alpha = {float(alpha)!r}: the normalizing coefficient of level {k - 2 * n} of order "
                                 f"n = {n} is about e^{lx:.0f} and exceeds float64; use scaled_orbit_coefficients "
                                 "(s^(2n+j) r, always finite) or arith='mp'")
            out.append(x / s**k if s**k > 0 else math.exp(lx))
        return out
    with ctx.scope():
        _, s, _ = _half_angle(alpha, ctx)
        return [ctx.div(x, _pow(s, k, ctx)) for x, k in zip(scaled, powers)]


def _certifiable_alpha(alpha):
    """alpha for :func:`certified_orbit_floats`: a :class:`RationalAngle` as it is (the exact angle, not float(alpha):
    near pi the float loses 2.3e-11 relative at t = 999999/1000000), else a checked float in (0, pi)."""
    if isinstance(alpha, RationalAngle):
        if alpha.t == 0:
            raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
        return alpha
    return check_alpha(alpha)


def _pow(x, k: int, ctx: Context):
    out = ctx.from_rational(fmpq(1))
    for _ in range(k):
        out = ctx.mul(out, x)
    return out


def orbit_coefficients_collocation(n: int, alpha, arith: str | Context = "exact") -> list:
    """The same coefficients by solving the collocation system (independent of the formula; tests and claims
    compare the two).  Exact at a :class:`RationalAngle`, or in any context that can solve (mp, ball, float)."""
    n = check_n(n)
    ctx = get_context(arith)
    if ctx.exact:
        if not isinstance(alpha, RationalAngle):
            raise TypeError(f"alpha must be a RationalAngle for arith {ctx.name!r}, got {type(alpha).__name__}")
        return [ctx.from_rational(x) for x in exact_coefficients_cached(n, alpha)[0]]
    with ctx.scope():
        return list(solve_reduced(n, alpha, ctx, verify=0, attempts=1).solution.reshape(-1))


def coefficient_vector(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> np.ndarray:
    """Coefficients of all delta_n functions in internal order, as an array of the context."""
    ctx = get_context(arith, dps=mpmath.mp.dps if dps is None else dps)
    orb = orbit_coefficients(n, alpha, ctx)
    out = ctx.zeros((len(united_system(n)),))
    for (_, members), x in zip(orbits(n), orb):
        for k in members:
            out[k] = x
    return out


def coefficients(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None,
                 scaled: bool = False) -> dict[str, object]:
    """Normalizing coefficients (eq. normalizing_weights) keyed by paper label, from the all-n formula.

    Every function of T_{2n} appears once, under its own label (the centre as ``r_{2n,n,n}``).  ``scaled=True``
    gives ``s^{2n+j} r`` instead (s = sin(alpha/2), j the level): finite for every alpha in (0, pi), where the raw
    float64 values overflow for small alpha (then ``ValueError`` says so).

    >>> from paper_repro.core.domain import rational_alpha
    >>> c = coefficients(1, rational_alpha(fmpq(1, 2)), "exact")
    >>> str(c["r_{2,2,0}"]), str(c["g_{2,1,0}"]), str(c["r_{2,1,1}"])
    ('25/16', '15/8', '5/2')
    >>> float(coefficients(2, 1e-200, scaled=True)["r_{4,2,1}"])  # the alpha -> 0 limit factor 5!/(2! 1! 2!) * 4/5
    24.0
    """
    if not isinstance(scaled, bool):
        raise TypeError(f"scaled must be True or False, got {scaled!r}")
    ctx = get_context(arith, dps=mpmath.mp.dps if dps is None else dps)
    if scaled and isinstance(ctx, FloatContext) and check_n(n) <= MAX_N_CERTIFIED:
        orb = certified_orbit_floats(n, _certifiable_alpha(alpha), True)
        vec = np.zeros(len(united_system(n)))
        for (_, members), x in zip(orbits(n), orb):
            vec[list(members)] = x
    else:
        vec = (scaled_coefficient_vector if scaled else coefficient_vector)(n, alpha, ctx, dps=dps)
    return {lab.coefficient: vec[k] for k, lab in enumerate(united_system(n))}


def scaled_coefficient_vector(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> np.ndarray:
    """``s^{2n+j} r`` of all delta_n functions in internal order (finite for every alpha in (0, pi))."""
    ctx = get_context(arith, dps=mpmath.mp.dps if dps is None else dps)
    orb = scaled_orbit_coefficients(n, alpha, ctx, dps=dps)
    return _spread_orbits(n, orb, ctx)


def scaled_float_vector(n: int, alpha: float) -> np.ndarray:
    """:func:`scaled_coefficient_vector` in float64 for inner code whose ``n`` (at most ``MAX_N_FLOAT``) and
    ``alpha`` (a float in (0, pi)) are already checked."""
    vals = _scaled_float(n, float(alpha))
    if vals is None:
        raise ValueError(f"n = {n}, alpha = {float(alpha)!r}: s^(2n+j) r exceeds float64 for some coefficient; use "
                         "log_scaled_orbit_coefficients(n, alpha) (natural logarithms) or arith='mp'")
    return _spread_orbits(n, list(vals), FloatContext())


def _spread_orbits(n: int, orb, ctx: Context) -> np.ndarray:
    """The value of each orbit given to every member of it (internal order)."""
    out = ctx.zeros((delta_unchecked(n),))
    for (_, members), x in zip(_orbits(n), orb):
        for k in members:
            out[k] = x
    return out


def evaluate_normalized(n: int, alpha, points, arith: str | Context = "float", *, dps: int = 50) -> np.ndarray:
    """Values of the blending functions T-bar_{2n}^alpha (eq. normalized_united_system): ``(P, delta_n)``.

    Computed as (s^{2n+j} r) times f / s^{2n+j} (:func:`scaled_coefficient_vector`, ``evaluate(..., scaled=True)``):
    both factors are bounded, so the values are finite and accurate for every alpha in (0, pi), down to 1e-300.

    >>> import numpy as np
    >>> v = evaluate_normalized(2, 1.0, [[0.2, 0.3, 0.5]])
    >>> bool(abs(v.sum() - 1) < 1e-14)
    True
    >>> w = evaluate_normalized(3, 1e-300, [[2e-301, 3e-301, 5e-301]])
    >>> bool(abs(w.sum() - 1) < 1e-14 and np.isfinite(w).all())
    True
    """
    ctx = get_context(arith, dps=dps)
    raw = evaluate(n, alpha, points, ctx, scaled=True)
    vec = scaled_coefficient_vector(n, alpha, ctx, dps=dps)
    with ctx.scope():
        return ctx.mul(raw, vec[None, :])


__all__ = ["orbits", "coefficients", "coefficient_vector", "orbit_coefficients", "evaluate_normalized",
           "scaled_orbit_coefficients", "log_scaled_orbit_coefficients", "orbit_coefficients_collocation",
           "scaled_coefficient_vector",
           "solve_reduced", "solve_reduced_exact", "solve_full_exact", "cramer_degree_bound"]


def collocation_mp(n: int, alpha_text: str, dps: int, seed: int, control: bool = False) -> np.ndarray:
    """Normalized collocation matrix of T_{2n} at delta_n seeded points of Omega^alpha, in mp at ``dps``
    digits (``control``: the last column replaced by the sum of the first two, a rank-deficient control)."""
    with mpmath.workdps(dps):
        alpha = alpha_mp(alpha_text)
        a = evaluate_normalized(n, alpha, mp_domain_points(alpha, delta(n), seed), "mp", dps=dps)
        if control:
            a[:, -1] = a[:, 0] + a[:, 1]
        return a
