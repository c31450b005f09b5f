"""Order elevation n -> n+1 (Example exmp:degree_elevation_from_1_to_2, Question 1 of sec:open_problems).

Since span T_{2n} = V_n is contained in V_{n+1} = span T_{2n+2} (claims ``coincidence``), every
blending function of order n is a combination of those of order n+1: ``T-bar_n = T-bar_{n+1} E``
with a ``(delta_{n+1}, delta_n)`` matrix E, and the elevated control net is ``E @ net``.  Rows of E
sum to 1 (both systems are partitions of unity).  E is computed exactly at rational-tangent alpha
(collocation at rational points, verified at further points) and in float for any alpha.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from flint import fmpq

from paper_repro.core.collocation import Collocation, collocate
from paper_repro.core.context import Context, ExactContext, FloatContext
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    rational_alpha,
    sample_points,
    sample_rational_points,
)
from paper_repro.core.labels import delta
from paper_repro.core.nets import check_net
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.util.validation import check_alpha, check_n, parse_alpha


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
    """Exact E with T-bar_n(p) = T-bar_{n+1}(p) E, verified at ``verify`` extra rational points."""
    return elevation_system(n, alpha, ExactContext(), verify=verify, seed=seed).solution.tolist()


@lru_cache(maxsize=64)
def _elevation_matrix_float(n: int, alpha: float) -> np.ndarray:
    """E in float: least squares over 3 delta_{n+1} seeded points (the square systems are ill-conditioned)."""
    return elevation_system(n, alpha, FloatContext(), verify=0, seed=12, rows=3 * delta(n + 1)).solution


def elevation_matrix(n: int, alpha) -> np.ndarray:
    """E as a float array: exact (then rounded) for a :class:`RationalAngle`, least squares otherwise."""
    alpha = parse_alpha(alpha)
    if isinstance(alpha, RationalAngle):
        return np.array([[float(x) for x in row] for row in elevation_matrix_exact(n, alpha)])
    return _elevation_matrix_float(check_n(n), check_alpha(alpha))


def elevate(net, n: int, alpha, times: int = 1) -> np.ndarray:
    """Control net of the same patch written in order ``n + times`` (repeated order elevation).

    ``net`` is a ``(delta_n, d)`` array or ``{label: point}``; ``alpha`` a float in (0, pi) or a
    :class:`RationalAngle` (then the matrices are exact before rounding).
    """
    arr = check_net(net, n)
    alpha = parse_alpha(alpha)
    for k in range(times):
        arr = elevation_matrix(n + k, alpha) @ arr
    return arr


def rational_alpha_near(alpha: float, denominator: int = 1000) -> RationalAngle:
    """A rational-tangent alpha close to ``alpha``: tan(alpha/4) rounded to ``denominator``."""
    from fractions import Fraction

    f = Fraction(np.tan(check_alpha(parse_alpha(alpha)) / 4)).limit_denominator(denominator)
    return rational_alpha(fmpq(f.numerator, f.denominator))
