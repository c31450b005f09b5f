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
  which is what makes the closed-form checks of :mod:`paper_repro.theory.closed_forms` proofs.

Arithmetics: exact rationals at rational-tangent alpha (``'exact'``), mpmath (``'mp'``) and float.
"""

from __future__ import annotations

from functools import cache, lru_cache

import mpmath
import numpy as np
from flint import arb, fmpq

from paper_repro.core.alphas import alpha_mp
from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import Collocation, collocate
from paper_repro.core.context import BallContext, Context, ExactContext, get_context
from paper_repro.core.domain import RationalAngle, RationalPoints, mp_domain_points
from paper_repro.core.labels import BasisLabel, compose, delta, exponents, united_system
from paper_repro.util.cache import cached
from paper_repro.util.validation import check_alpha, check_n

#: Largest order whose normalizing coefficients are computed (exact at n = 40 takes minutes).
MAX_N_COEFFICIENTS = 60

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


def reduced_matrix_exact(n: int, alpha: RationalAngle, pts: RationalPoints) -> np.ndarray:
    """``(P, m)`` object array of fmpq: orbit sums of T_{2n} at the points."""
    return reduced_matrix(n, alpha, pts, ExactContext())


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

    stored = cached("orbit_coefficients", {"n": n, "t": str(alpha.t)}, compute)
    return [parse_fmpq(x) for x in stored["solution"]], stored["point_set"]


@lru_cache(maxsize=256)
def _ball_orbit_coefficients(n: int, alpha_str: str, digits: int) -> tuple[str, ...]:
    """Orbit coefficients to ``digits`` correct significant digits, as decimal strings.

    Ball arithmetic (:class:`~paper_repro.core.context.BallContext`): the fixed collocation points have
    rational half-angle sines and cosines, only sin(alpha/2), cos(alpha/2) are balls; the reduced system
    is solved by :func:`solve_reduced` and the precision doubled until every coefficient's radius is
    below ``10^-digits`` of its midpoint.  The result is therefore certified (up to the decimal
    rounding of alpha itself).
    """
    prec = int(3.33 * digits) + 64
    for _ in range(8):
        ctx = BallContext(prec=prec)
        with ctx.scope():
            try:
                xs = list(solve_reduced(n, arb(alpha_str), ctx, verify=0, attempts=1).solution.reshape(-1))
            except ArithmeticError:
                prec *= 2
                continue
            if all(v.rad() <= abs(v.mid()) * arb(10) ** (-digits) for v in xs):
                return tuple(v.mid().str(digits + 5, radius=False) for v in xs)
        prec *= 2
    raise ArithmeticError(f"normalization: no certified {digits} digits up to {prec // 2} bits (n={n})")


def orbit_coefficients(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> list:
    """Orbit coefficients (order of :func:`orbits`) in any arithmetic.

    Exact arithmetics (``'exact'``, ``'modp'``): alpha must be a :class:`RationalAngle`; the exact
    rational solution (cached on disk) is converted.  Real arithmetics: a certified ball solve to the
    context's digits (``'float'``: 20 digits, rounded to float64; ``'mp'``: ``dps`` digits, default the
    current mpmath precision).

    At tan(alpha/4) = 1/2 (sin(alpha/2) = 4/5, cos(alpha/2) = 3/5) Example normalizing_coefficients_n_1
    gives 1/s^2 = 25/16, 2c/s^2 = 15/8 and 2/s = 5/2:

    >>> from paper_repro.core.domain import rational_alpha
    >>> [str(x) for x in orbit_coefficients(1, rational_alpha(fmpq(1, 2)), "exact")]
    ['25/16', '15/8', '5/2']
    """
    n = check_n(n)
    if n > MAX_N_COEFFICIENTS:
        raise ValueError(f"n must be at most {MAX_N_COEFFICIENTS} for normalizing coefficients (the collocation "
                         f"system has (n+1)(n+2)/2 = {(n + 1) * (n + 2) // 2} unknowns and its solve would not end "
                         f"in reasonable time), got {n}")
    ctx = get_context(arith, dps=dps or mpmath.mp.dps)
    if ctx.exact:
        if not isinstance(alpha, RationalAngle):
            raise TypeError(f"alpha must be a RationalAngle (rational tan(alpha/4)) for arith {ctx.name!r}, "
                            f"got {type(alpha).__name__}")
        return [ctx.from_rational(x) for x in exact_coefficients_cached(n, alpha)[0]]
    if ctx.encloses:  # solve in the context itself: the enclosures then contain the true coefficients
        if not isinstance(alpha, RationalAngle):
            check_alpha(alpha)
        with ctx.scope():
            return list(solve_reduced(n, alpha, ctx, verify=0, attempts=1).solution.reshape(-1))
    digits = max(ctx.digits, 20)
    if isinstance(alpha, RationalAngle):
        with mpmath.workdps(digits + 20):
            alpha = alpha.mp()
    check_alpha(alpha)
    with mpmath.workdps(digits + 20):
        alpha_str = mpmath.nstr(mpmath.mpf(alpha), digits + 15, strip_zeros=False)
    xs = _ball_orbit_coefficients(n, alpha_str, digits)
    with ctx.scope():
        return [ctx.convert(v) for v in xs]  # decimal strings: every real context parses them


def coefficient_vector(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> np.ndarray:
    """Coefficients of all delta_n functions in internal order, as an array of the context."""
    ctx = get_context(arith, dps=dps or mpmath.mp.dps)
    orb = orbit_coefficients(n, alpha, ctx)
    out = ctx.zeros((len(united_system(n)),))
    for (_, members), x in zip(orbits(n), orb):
        for k in members:
            out[k] = x
    return out


def coefficients(n: int, alpha, arith: str | Context = "float", *, dps: int | None = None) -> dict[str, object]:
    """Normalizing coefficients (eq. normalizing_weights) keyed by paper label.

    Every function of T_{2n} appears once, under its own label (the centre as ``r_{2n,n,n}``).

    >>> from paper_repro.core.domain import rational_alpha
    >>> c = coefficients(1, rational_alpha(fmpq(1, 2)), "exact")
    >>> str(c["r_{2,2,0}"]), str(c["g_{2,1,0}"]), str(c["r_{2,1,1}"])
    ('25/16', '15/8', '5/2')
    """
    vec = coefficient_vector(n, alpha, arith, dps=dps)
    return {lab.coefficient: vec[k] for k, lab in enumerate(united_system(n))}


def evaluate_normalized(n: int, alpha, points, arith: str | Context = "float", *, dps: int = 50) -> np.ndarray:
    """Values of the blending functions T-bar_{2n}^alpha (eq. normalized_united_system): ``(P, delta_n)``.

    >>> import numpy as np
    >>> v = evaluate_normalized(2, 1.0, [[0.2, 0.3, 0.5]])
    >>> bool(abs(v.sum() - 1) < 1e-14)
    True
    """
    ctx = get_context(arith, dps=dps)
    raw = evaluate(n, alpha, points, ctx)
    vec = coefficient_vector(n, alpha, ctx)
    with ctx.scope():
        return ctx.mul(raw, vec[None, :])


__all__ = ["orbits", "coefficients", "coefficient_vector", "orbit_coefficients", "evaluate_normalized",
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
