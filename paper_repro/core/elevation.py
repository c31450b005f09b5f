"""Order elevation n -> n+1 (Example exmp:degree_elevation_from_1_to_2, Question 1 of sec:open_problems).

Since span T_{2n} = V_n is contained in V_{n+1} = span T_{2n+2} (claims ``coincidence``), every
blending function of order n is a combination of those of order n+1: ``T-bar_n = T-bar_{n+1} E``
with a ``(delta_{n+1}, delta_n)`` matrix E, and the elevated control net is ``E @ net``.

The library route is the closed form of :mod:`paper_repro.core.half_angle_matrices` (proven for every n in
docs/elevation_and_derivative_for_all_n.md; claim ``elevation_all_n``): exact at a rational-tangent alpha, and in
float the same bits on every CPU, with E >= 0 and rows summing to 1 (a convex combination) for every n and alpha.
No linear solve: n = 10 in milliseconds, any n up to :data:`~paper_repro.util.limits.MAX_N_ELEVATION`.

Two independent routes stay here as cross-checks for tests and tools (they know nothing of the closed form): the
exact collocation solve (:func:`elevation_matrix_exact`) and the certified ball solve (:func:`certified_solve`,
precision raised until every entry is known to 2^-64).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from flint import fmpq

from paper_repro.core.collocation import Collocation, collocate
from paper_repro.core.context import BallContext, Context, ExactContext, FloatContext
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    rational_alpha,
    sample_points,
    sample_rational_points,
)
from paper_repro.core.exact_solve import ModularExactContext
from paper_repro.core.half_angle_matrices import (
    ALPHA_TINY,
    elevation_entries,
    elevation_form,
    elevation_matrix_ctx,
    half_angle,
)
from paper_repro.core.labels import delta
from paper_repro.core.nets import check_net
from paper_repro.core.normalization import evaluate_normalized, fixed_points
from paper_repro.core.ordered import ordered_matmul
from paper_repro.util.limits import MAX_ELEVATION_STEPS, MAX_N_ELEVATION, check_int
from paper_repro.util.sweep import interruptible
from paper_repro.util.validation import check_alpha, check_n, parse_alpha

#: Below this alpha the certified ball solve (a cross-check) needs precision growing like log(1/alpha); E(alpha) -
#: E(0) = O(alpha^2) is below float64's rounding there (measured: max |E(alpha) - E(1e-30)| = 5.6e-10, 5.6e-14, 4e-18
#: at alpha = 1e-4, 1e-6, 1e-8 for n = 1).  The closed form needs no such floor.
ALPHA_FLAT = 1e-9
#: Largest ball precision (bits) tried before giving up (never reached for n <= MAX_N_ELEVATION; measured).
MAX_PREC = 1 << 15


def elevation_system(n: int, alpha, ctx: Context, *, verify: int = 3, seed: int = 4, rows: int | None = None
                     ) -> Collocation:
    """E with T-bar_n(p) = T-bar_{n+1}(p) E by :func:`~paper_repro.core.collocation.collocate` in ``ctx``.

    The exact arithmetics collocate at rational points of Omega^alpha (alpha a :class:`RationalAngle`);
    the real ones at seeded random points.  ``rows`` collocation rows (default delta_{n+1}; more give a
    least-squares solve in float).
    """
    n = check_n(n)
    d1 = delta(n + 1)
    m = rows or d1

    def system(k: int):
        pts: RationalPoints | np.ndarray
        if ctx.exact:
            pts = sample_rational_points(alpha, m + verify, seed=seed + k)
        else:
            pts = sample_points(float(alpha), m + verify, seed=seed + k)
        return evaluate_normalized(n + 1, alpha, pts, ctx), evaluate_normalized(n, alpha, pts, ctx)

    return collocate(ctx, system, m, what=f"elevation {n}->{n + 1}")


@lru_cache(maxsize=64)
def elevation_matrix_exact(n: int, alpha: RationalAngle, verify: int = 3, seed: int = 4) -> list[list[fmpq]]:
    """Exact E with T-bar_n(p) = T-bar_{n+1}(p) E, verified at ``verify`` extra rational points.

    The collocation system is solved by :func:`~paper_repro.core.exact_solve.solve_exact` (modular solves and an
    exact check: the same exact solution as ``fmpq_mat.solve``, 3-6 times faster at n = 6..8)."""
    return elevation_system(n, alpha, ModularExactContext(), verify=verify, seed=seed).solution.tolist()


def _ball_solve(n: int, alpha: float, prec: int) -> tuple[np.ndarray | None, int]:
    """E at ``prec`` bits in ball arithmetic, collocating at alpha-independent points of the plane u + v + w =
    alpha (:func:`~paper_repro.core.normalization.fixed_points`).

    Returns ``(E, bits)``: the float64 midpoints (``None`` if some entry is not certified to 2^-64 or the ball
    matrix is not certified invertible) and the number of bits the largest radius is below 1 (``bits`` > 64 when
    certified; 0 if nothing is known), from which the caller sets the next precision."""
    from flint import arb, arb_mat

    ctx = BallContext(prec=prec)
    m = delta(n + 1)
    tu, tv = fixed_points(n + 1, m, 7)
    pts = RationalPoints(None, tu, tv, check=False)
    with ctx.scope():
        a = arb(alpha)  # a float is an exact binary rational
        big = evaluate_normalized(n + 1, a, pts, ctx)
        small = evaluate_normalized(n, a, pts, ctx)
        try:
            x = arb_mat(big.tolist()).solve(arb_mat(small.tolist()), algorithm="precond")
        except ZeroDivisionError:
            return None, 0
        rad = max((x[i, j].rad() for i in range(x.nrows()) for j in range(x.ncols())), default=arb(0))
        if not rad.is_finite():
            return None, 0
        bits = prec if rad == 0 else max(0, -int(math.floor(float(rad.log() / arb(2).log()))) - 1)
        if bits <= 64:
            return None, bits
        out = np.array([[float(x[i, j].mid()) for j in range(x.ncols())] for i in range(x.nrows())])
    return out, bits


def _ball_solve_task(args: tuple[int, float, int]) -> tuple[np.ndarray | None, int]:
    """:func:`_ball_solve` on one tuple (a picklable task for :func:`~paper_repro.util.sweep.interruptible`)."""
    return _ball_solve(*args)


#: Solves whose work estimate delta_{n+1}^3 x precision exceeds this run in a child process, so that Ctrl-C stops
#: them within a second (flint holds the GIL); measured: 1e9 is about 1.5 s (n = 7 at alpha = 1, 256 bits).
CHILD_WORK = 1e9


def start_precision(n: int, alpha: float) -> int:
    """First ball precision tried, from the bits the preconditioned ball solve loses (measured for n = 1..10 at
    alpha = 1, 1e-3, 1e-9 and pi - 1e-5 by ``tools/elevation_cost.py``: at most 16 (n + 1) at alpha = 1, plus at
    most (4.5 n + 3) log2(1/alpha) as alpha -> 0 -- n = 10 loses 172, 594 and 1432 bits at alpha = 1, 1e-3,
    1e-9 -- and little near pi).  With 96 bits to spare one solve is enough in every case measured."""
    small, near_pi = max(0.0, math.log2(1 / alpha)), max(0.0, math.log2(1 / (math.pi - alpha)))
    lost = 16 * (n + 1) + (4.5 * n + 3) * small + 2 * near_pi
    return 64 * math.ceil((lost + 96) / 64)


def next_precision(prec: int, bits: int) -> int:
    """Precision of the next attempt after a solve at ``prec`` bits certified ``bits`` bits (not enough):
    the bits lost are ``prec - bits``, so ``prec - bits + 64`` would just do; add a margin of 25 %, and
    double if nothing was certified."""
    if bits <= 0:
        return 2 * prec
    return 64 * math.ceil((1.25 * (prec - bits) + 96) / 64)


def certified_solve(n: int, alpha: float, child: bool = True) -> tuple[np.ndarray, int, int, int]:
    """E from the certified ball solve: ``(E, precision, bits lost, solves)``, starting at :func:`start_precision`
    and raising it by :func:`next_precision` until every entry is certified to 64 bits.  With ``child``, solves
    whose work exceeds :data:`CHILD_WORK` run in a child process (Ctrl-C stops them); ``tools/elevation_cost.py``
    measures the same loop in-process."""
    prec, solves = start_precision(n, alpha), 0
    while prec <= MAX_PREC:
        solves += 1
        if child and delta(n + 1) ** 3 * prec > CHILD_WORK:
            e, bits = interruptible(_ball_solve_task, (n, alpha, prec))
        else:
            e, bits = _ball_solve(n, alpha, prec)
        if e is not None:
            return e, prec, prec - bits, solves
        prec = max(prec + 64, next_precision(prec, bits))
    raise ArithmeticError(f"elevation {n}->{n + 1} at alpha = {alpha!r}: not certified at {MAX_PREC} bits")



#: Float matrices up to this order are kept in memory (16 of them, at most 6 MB each); larger ones are recomputed.
CACHE_MAX_N = 15


@lru_cache(maxsize=16)
def _elevation_matrix_float(n: int, alpha: float) -> np.ndarray:
    """E in float64 from the closed form (read-only; the same bits on every CPU)."""
    out = elevation_matrix_ctx(n, alpha, FloatContext())
    out.setflags(write=False)
    return out


def elevation_matrix(n: int, alpha) -> np.ndarray:
    """E as a float64 array, ``(delta_{n+1}, delta_n)``, from the closed form (no solve): exact (then rounded) for a
    :class:`RationalAngle`, for a float alpha every entry a sum of non-negative terms in kappa = cos(alpha/2) and
    sin^2(alpha/2) (taken correctly rounded from flint), so E >= 0 and rows sum to 1 to rounding for every alpha in
    (0, pi), with the same bits on every CPU (Theorem P of docs/elevation_and_derivative_for_all_n.md).

    Parameters
    ----------
    n : int
        The order of the net to elevate, from 1 to :data:`~paper_repro.util.limits.MAX_N_ELEVATION` (time and
        memory of each n: the table of docs/domain_of_validity.md).
    alpha : float, str or RationalAngle
        The shape parameter in (0, pi): a number, text such as ``"pi/2"``, or a
        :class:`~paper_repro.core.domain.RationalAngle` (then the entries are exact before the one rounding).

    Returns
    -------
    numpy.ndarray
        ``E`` with ``delta_{n+1}`` rows and ``delta_n`` columns: ``E @ net`` is the net of order n + 1.

    >>> e = elevation_matrix(2, 1.0)
    >>> e.shape, bool(abs(e.sum(axis=1) - 1).max() < 1e-15), bool(e.min() >= 0)
    ((37, 19), True, True)
    """
    n = check_int(n, "n", 1, MAX_N_ELEVATION, why="the dense E has delta_{n+1} delta_n entries")
    alpha = parse_alpha(alpha)
    if isinstance(alpha, RationalAngle):
        if alpha.t == 0:
            raise ValueError("alpha must lie in the open interval (0, pi): tan(alpha/4) = 0 gives alpha = 0")
        ctx = ExactContext()
        kappa, sigma = half_angle(alpha, ctx)
        rows, cols, vals = elevation_entries(elevation_form(n), n, kappa, sigma, ctx)  # exact, then rounded once
        out = np.zeros((delta(n + 1), delta(n)))
        out[rows, cols] = [float(v) for v in vals]
        return out
    a = max(check_alpha(alpha), ALPHA_TINY)
    if n > CACHE_MAX_N:
        return elevation_matrix_ctx(n, a, FloatContext())
    return _elevation_matrix_float(n, a).copy()


def elevate(net, n: int, alpha, *, to: int | None = None, times: int | None = None) -> np.ndarray:
    """Control net of the same patch written in order ``to`` (or ``n + times``): repeated order elevation.

    ``net`` is a ``(delta_n, d)`` array or ``{label: point}`` of order ``n``; ``alpha`` a float in (0, pi) or a
    :class:`RationalAngle` (then the matrices are exact before rounding).  Give the target order ``to`` (at least
    ``n``) or the number of steps ``times`` (from 0 to :data:`~paper_repro.util.limits.MAX_ELEVATION_STEPS`), both
    keyword-only; neither means one step.  The target order is at most
    :data:`~paper_repro.util.limits.MAX_N_ELEVATION` + 1.

    >>> net = np.zeros((7, 3)); elevate(net, 1, 1.0, to=3).shape, elevate(net, 1, 1.0, times=2).shape
    ((37, 3), (37, 3))
    """
    n = check_int(n, "n", 1, MAX_N_ELEVATION, why="the dense E has delta_{n+1} delta_n entries")
    if to is not None:
        to = check_int(to, "to", n, MAX_N_ELEVATION + 1,
                       why=f"the target order: at least n = {n}, at most {MAX_N_ELEVATION + 1} (the largest "
                           f"elevation matrix)")
        if times is not None and times != to - n:
            raise ValueError(f"give to or times, not both: to = {to} is {to - n} steps from n = {n}, "
                             f"times = {times!r}")
        times = to - n
    times = 1 if times is None else times
    times = check_int(times, "times", 0, min(MAX_ELEVATION_STEPS, MAX_N_ELEVATION + 1 - n),
                      why=f"n + times - 1 must be at most {MAX_N_ELEVATION} (the largest elevation matrix)")
    alpha = parse_alpha(alpha)
    if not isinstance(alpha, RationalAngle):
        check_alpha(alpha)
    arr = check_net(net, n)
    for k in range(times):
        arr = ordered_matmul(elevation_matrix(n + k, alpha), arr)
    return arr


def rational_alpha_near(alpha: float, denominator: int = 1000) -> RationalAngle:
    """A rational-tangent alpha close to ``alpha``: tan(alpha/4) rounded to ``denominator``."""
    from fractions import Fraction

    # math.tan (libm): numpy's tan ufunc is SIMD code chosen per CPU (Intel SVML on AVX512), other last bits
    f = Fraction(math.tan(check_alpha(parse_alpha(alpha)) / 4)).limit_denominator(denominator)
    return rational_alpha(fmpq(f.numerator, f.denominator))
