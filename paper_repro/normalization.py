"""Normalizing coefficients of T_{2n}^alpha (Section sec:partition_of_unity, eq. normalizing_weights).

The coefficients ``r_{2n,2n-i,j}, g_{...}, b_{...}`` are the unique solution of
``1 = sum_f x_f f(u, v, w)`` on Omega^alpha.  They are computed *without* the paper's closed forms:

* Symmetry: the group of the six permutations of (u, v, w) maps T_{2n} onto itself (claim
  ``symmetry``), so by uniqueness the coefficients are constant on its orbits; there are
  (n+1)(n+2)/2 orbits, each named by its R representative ``r_{2n,2n-i,j}`` with ``i = j..n``
  (the reduced system suggested after Example normalizing_coefficients_n_3).  The full system with
  delta_n unknowns (:func:`solve_full_exact`) is used to check this independently.
* Collocation points: the identity is one of trigonometric polynomials on the plane u + v + w = alpha
  (it holds on the triangle, hence everywhere on the plane), so the collocation points may be fixed
  independently of alpha (:func:`fixed_points`; w = alpha - u - v may be negative).  Then every
  coefficient is a rational function of t = tan(alpha/4) of bounded degree (:func:`cramer_degree_bound`),
  which is what makes the closed-form checks of :mod:`paper_repro.closed_forms` proofs.

Arithmetics: exact rationals at rational-tangent alpha (``'exact'``), mpmath (``'mp'``) and float.
"""

from __future__ import annotations

from functools import cache, lru_cache

import mpmath
import numpy as np
from flint import arb, arb_mat, ctx, fmpq, fmpq_mat

from .arith import BallArith, to_fmpq_mat
from .basis import evaluate, monomials
from .cache import cached
from .domain import RationalAngle, RationalPoints
from .labels import BasisLabel, compose, exponent_matrix, exponents, united_system
from .validation import check_alpha, check_n

PERMUTATIONS = ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))


@cache
def orbits(n: int) -> tuple[tuple[BasisLabel, tuple[int, ...]], ...]:
    """Orbits of T_{2n} under permutations of (u, v, w): ``(R representative, member indices)``.

    Representatives are ``R_{2n,2n-i,j}`` with ``j = 0..n``, ``i = j..n``, ordered by (j, i).
    """
    n = check_n(n)
    labels = united_system(n)
    by_exps = {exponents(lab): k for k, lab in enumerate(labels)}
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


def _plane_points(alpha: RationalAngle, tu, tv) -> RationalPoints:
    return RationalPoints(alpha, tuple(tu), tuple(tv), check=False)


def reduced_matrix_exact(n: int, alpha: RationalAngle, pts: RationalPoints) -> np.ndarray:
    """``(P, m)`` object array of fmpq: orbit sums of T_{2n} at the points."""
    vals = evaluate(n, alpha, pts, "exact")
    om = orbit_matrix(n)
    out = np.empty((vals.shape[0], om.shape[1]), dtype=object)
    for o in range(om.shape[1]):
        cols = np.nonzero(om[:, o])[0]
        for p in range(vals.shape[0]):
            acc = fmpq(0)
            for k in cols:
                acc += vals[p, k]
            out[p, o] = acc
    return out


def solve_reduced_exact(n: int, alpha: RationalAngle, *, verify: int = 3, seed: int = 0,
                        attempts: int = 5) -> tuple[list[fmpq], int]:
    """Exact orbit coefficients (in :func:`orbits` order) at rational-tangent alpha.

    Solves the square system at m fixed points and checks the identity exactly at ``verify`` further
    points (``ArithmeticError`` if it fails).  A singular point set is replaced by the next one, up to
    ``attempts`` sets; returns ``(solution, index of the point set used)``.
    """
    n = check_n(n)
    m = len(orbits(n))
    for attempt in range(attempts):
        tu, tv = fixed_points(n, m + verify, seed + attempt)
        mat = reduced_matrix_exact(n, alpha, _plane_points(alpha, tu, tv))
        a = to_fmpq_mat(mat[:m])
        try:
            x = a.solve(fmpq_mat(m, 1, [1] * m))
        except ZeroDivisionError:
            continue
        sol = [x[k, 0] for k in range(m)]
        for p in range(m, m + verify):
            if sum((mat[p, k] * sol[k] for k in range(m)), fmpq(0)) != 1:
                raise ArithmeticError(f"partition of unity fails at a verification point (n={n}, t={alpha.t})")
        return sol, attempt
    raise ArithmeticError(f"collocation matrix singular for {attempts} point sets (n={n}, t={alpha.t})")


def solve_full_exact(n: int, alpha: RationalAngle, *, seed: int = 0) -> list[fmpq]:
    """Exact coefficients of all delta_n functions (no symmetry assumed), internal order."""
    d = len(united_system(n))
    for attempt in range(5):
        tu, tv = fixed_points(n, d, seed + 77 + attempt)
        vals = evaluate(n, alpha, _plane_points(alpha, tu, tv), "exact")
        try:
            x = to_fmpq_mat(vals).solve(fmpq_mat(d, 1, [1] * d))
        except ZeroDivisionError:
            continue
        return [x[k, 0] for k in range(d)]
    raise ArithmeticError(f"full collocation matrix singular for 5 point sets (n={n})")


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

    stored = cached("orbit_coefficients", {"n": n, "t": str(alpha.t)}, compute)
    return [parse_fmpq(x) for x in stored["solution"]], stored["point_set"]


@lru_cache(maxsize=256)
def _ball_orbit_coefficients(n: int, alpha_str: str, digits: int) -> tuple[str, ...]:
    """Orbit coefficients to ``digits`` correct significant digits, as decimal strings.

    Ball arithmetic (flint ``arb``): the fixed collocation points have rational half-angle sines and
    cosines, only sin(alpha/2), cos(alpha/2) are balls; the reduced system is solved with ``arb_mat``
    and the working precision doubled until every coefficient's radius is below ``10^-digits`` of its
    midpoint.  The result is therefore certified (up to the decimal rounding of alpha itself).
    """
    m = len(orbits(n))
    tu, tv = fixed_points(n, m, 0)
    prec = int(3.33 * digits) + 64
    old = ctx.prec
    try:
        for _ in range(8):
            ctx.prec = prec
            half = arb(alpha_str) / 2
            vals = [[] for _ in range(6)]
            sh, ch = half.sin(), half.cos()
            for a, b in zip(tu, tv):
                su, cu = RationalAngle(a).sin_half, RationalAngle(a).cos_half
                sv, cv = RationalAngle(b).sin_half, RationalAngle(b).cos_half
                c_uv, s_uv = cu * cv - su * sv, su * cv + cu * sv
                row = (su, cu, sv, cv, sh * arb(c_uv) - ch * arb(s_uv), ch * arb(c_uv) + sh * arb(s_uv))
                for slot, val in enumerate(row):
                    vals[slot].append(arb(val))
            trig = [np.array(v, dtype=object) for v in vals]
            red = monomials(exponent_matrix(n), trig, BallArith()).dot(orbit_matrix(n).astype(object))
            try:
                x = arb_mat(red.tolist()).solve(arb_mat(m, 1, [1] * m))
            except ZeroDivisionError:
                prec *= 2
                continue
            xs = [x[k, 0] for k in range(m)]
            if all(v.rad() <= abs(v.mid()) * arb(10) ** (-digits) for v in xs):
                return tuple(v.mid().str(digits + 5, radius=False) for v in xs)
            prec *= 2
    finally:
        ctx.prec = old
    raise ArithmeticError(f"normalization: no certified {digits} digits up to {prec // 2} bits (n={n})")


def orbit_coefficients(n: int, alpha, arith: str = "float", *, dps: int | None = None) -> list:
    """Orbit coefficients (order of :func:`orbits`) in ``'float'``, ``'mp'`` or ``'exact'``.

    ``alpha`` is a number in (0, pi) (``'float'``, ``'mp'``; mpf allowed) or a :class:`RationalAngle`
    (``'exact'``).  ``'mp'`` returns ``dps`` (default: the current mpmath precision) certified digits,
    ``'float'`` 20 certified digits rounded to float64 (ball arithmetic, see
    :func:`_ball_orbit_coefficients`).
    """
    n = check_n(n)
    if arith not in ("float", "mp", "exact"):
        raise ValueError(f"arith must be 'float', 'mp' or 'exact', got {arith!r}")
    if arith == "exact":
        if not isinstance(alpha, RationalAngle):
            raise ValueError("alpha must be a RationalAngle (rational tan(alpha/4)) for arith='exact'")
        return exact_coefficients_cached(n, alpha)[0]
    digits = (dps or mpmath.mp.dps) if arith == "mp" else 20
    if isinstance(alpha, RationalAngle):
        with mpmath.workdps(digits + 20):
            alpha = alpha.mp()
    check_alpha(alpha)
    with mpmath.workdps(digits + 20):
        alpha_str = mpmath.nstr(mpmath.mpf(alpha), digits + 15, strip_zeros=False)
    xs = _ball_orbit_coefficients(n, alpha_str, digits)
    if arith == "mp":
        with mpmath.workdps(digits):
            return [mpmath.mpf(v) for v in xs]
    return [float(v) for v in xs]


def coefficient_vector(n: int, alpha, arith: str = "float", *, dps: int | None = None) -> np.ndarray:
    """Coefficients of all delta_n functions in internal order (float array, or object array)."""
    orb = orbit_coefficients(n, alpha, arith, dps=dps)
    out = np.empty(len(united_system(n)), dtype=np.float64 if arith == "float" else object)
    for (_, members), x in zip(orbits(n), orb):
        for k in members:
            out[k] = x
    return out


def coefficients(n: int, alpha, arith: str = "float", *, dps: int | None = None) -> dict[str, object]:
    """Normalizing coefficients keyed by paper label: ``{'r_{4,4,0}': ..., 'g_{4,3,1}': ..., ...}``.

    Every function of T_{2n} appears once, under its own label (the centre as ``r_{2n,n,n}``).
    """
    vec = coefficient_vector(n, alpha, arith, dps=dps)
    return {lab.coefficient: vec[k] for k, lab in enumerate(united_system(n))}


def evaluate_normalized(n: int, alpha, points, arith: str = "float", *, dps: int = 50) -> np.ndarray:
    """Values of the blending functions T-bar_{2n}^alpha (eq. normalized_united_system): ``(P, delta_n)``."""
    raw = evaluate(n, alpha, points, arith, dps=dps)
    vec = coefficient_vector(n, alpha, arith, dps=None if arith != "mp" else dps)
    if arith == "mp":
        with mpmath.workdps(dps):
            return raw * vec[None, :]
    return raw * vec[None, :]


__all__ = ["orbits", "coefficients", "coefficient_vector", "orbit_coefficients", "evaluate_normalized",
           "solve_reduced_exact", "solve_full_exact", "cramer_degree_bound"]
