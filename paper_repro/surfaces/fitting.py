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

import numpy as np
from flint import fmpq

from paper_repro.core.collocation import collocate
from paper_repro.core.context import Context, ExactContext, MpContext, get_context
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    half_angle_values,
    mp_domain_points,
    sample_rational_points,
)
from paper_repro.core.fourier import cos_sin_combination, full_angles
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.util.limits import MAX_DPS, MAX_N_FIT, MAX_N_FIT_EXACT, MIN_DPS, check_int
from paper_repro.util.validation import check_alpha


@dataclass
class ExactTrig:
    """sin/cos of integer combinations of u, v, w at a rational point, exactly (for exact fitting)."""

    full: list[tuple[fmpq, fmpq]]  # (cos, sin) of u, v, w

    def _cs(self, r: int, g: int, b: int) -> tuple[fmpq, fmpq]:
        return cos_sin_combination(self.full, (r, g, b), _EXACT, fmpq(1))

    def cos(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[0]

    def sin(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[1]


_EXACT = ExactContext()


def exact_trig_points(pts: RationalPoints) -> list[ExactTrig]:
    half = half_angle_values(pts, None, _EXACT)
    full = full_angles(half, _EXACT)
    return [ExactTrig([(c[k], s[k]) for c, s in full]) for k in range(len(pts))]


def fit_exact(surface: Callable[[ExactTrig], list[fmpq]], n: int, alpha: RationalAngle, verify: int = 4,
              seed: int = 21) -> list[list[fmpq]]:
    """Exact control net (rows in internal order) of ``surface``, a function of :class:`ExactTrig`.

    ``ValueError`` if the surface is not in the span (the verification points disagree).
    """
    n = check_int(n, "n", 1, MAX_N_FIT_EXACT, why="exact collocation with delta_n unknowns; see the README table")
    if not isinstance(alpha, RationalAngle):
        raise TypeError(f"alpha must be a RationalAngle for exact fitting, got {type(alpha).__name__}")
    d = delta(n)

    def system(k: int):
        pts = sample_rational_points(alpha, d + verify, seed=seed + k)
        basis = evaluate_normalized(n, alpha, pts, _EXACT)
        return basis, _EXACT.asarray([list(surface(t)) for t in exact_trig_points(pts)])

    try:
        net = collocate(_EXACT, system, d, what="fit").solution
    except ArithmeticError as exc:
        raise ValueError(f"surface: its coordinates are not in the span of T_{{{2 * n}}} ({exc})") from None
    return net.tolist()


def fit_mp(surface: Callable, n: int, alpha, dps: int = 40, verify: int = 4, seed: int = 21,
           tol_digits: int | None = None) -> np.ndarray:
    """Control net (object array of mpf) of ``surface(u, v, w) -> sequence`` by collocation in mpmath.

    ``ValueError`` if the surface is not in the span: the residual at the verification points exceeds
    ``10^-(tol_digits)`` relative (default ``dps - 15`` digits).
    """
    n = check_int(n, "n", 1, MAX_N_FIT, why="mp collocation with delta_n unknowns; see the README table")
    check_alpha(alpha)
    dps = check_int(dps, "dps", MIN_DPS, MAX_DPS)
    if tol_digits is not None:
        tol_digits = check_int(tol_digits, "tol_digits", 1, dps - 1,
                               why="the verification tolerance 10^-tol_digits must lie above the working precision")
    d = delta(n)
    ctx = MpContext(dps=dps)

    def system(k: int):
        with ctx.scope():
            a = ctx.convert(alpha)
            pts = mp_domain_points(a, d + verify, seed + k)
            basis = evaluate_normalized(n, a, pts, ctx)
            return basis, np.array([list(surface(*p)) for p in pts], dtype=object)

    try:
        res = collocate(ctx, system, d, what="fit", rtol=10.0 ** (-(tol_digits or dps - 15)))
    except ArithmeticError as exc:
        raise ValueError(f"surface: not in the span of T_{{{2 * n}}} ({exc})") from None
    return res.solution


def fit(surface: Callable, n: int, alpha, arith: str | Context = "mp", **kwargs):
    """Control net of ``surface`` in the normalized basis of order ``n`` (collocation, verified).

    Exact arithmetics: ``alpha`` a :class:`RationalAngle`, ``surface(trig) -> coordinates`` called with an
    :class:`ExactTrig` (exact sin/cos of integer combinations of u, v, w); returns rows of rationals.
    Real arithmetics (mp): ``surface(u, v, w) -> coordinates``; returns an object array of mpf
    (``dps`` keyword, default 40).  ``ValueError`` if the surface is not in the span.

    >>> from flint import fmpq
    >>> from paper_repro.core.domain import rational_alpha
    >>> net = fit(lambda t: [t.cos(1, 0, 0), t.sin(0, 1, 0)], 1, rational_alpha(fmpq(1, 3)), "exact")
    >>> len(net), len(net[0])
    (7, 2)
    """
    if not callable(surface):
        raise TypeError(f"surface must be callable, got {type(surface).__name__}")
    ctx = get_context(arith)
    if ctx.exact:
        return fit_exact(surface, n, alpha, **kwargs)
    return fit_mp(surface, n, alpha, **kwargs)
