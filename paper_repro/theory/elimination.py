"""The elimination steps of the proof of Theorem joint_systems_linear_independence, computed.

Every function of T_{2n} is a product U(u) V(v) W(w) of powers of half-angle sines and cosines, so its
derivatives along the parametrizations of the proof factor: derivatives at 0 are exact
(:mod:`paper_repro.theory.derivatives`), derivatives at interior points are evaluated with mpmath.
:func:`elimination` follows the proof: for r = 0, 1, ..., n-1 and the parametrizations
parametrization_1_y_0, _2_x_0, _3_y_0 in turn, the functions still alive whose r-th derivative at the
boundary does not vanish are removed (their coefficients are forced to 0); only the centre must remain.
"""

from __future__ import annotations

from math import comb

import mpmath
from flint import fmpq

from paper_repro.core.labels import exponents, united_system
from paper_repro.theory.derivatives import mixed_derivative

HALF = fmpq(1, 2)


def _factor(e: tuple[int, ...], var: int) -> tuple[int, int]:
    """(sin power, cos power) of variable ``var`` (0 = u, 1 = v, 2 = w) in exponent vector ``e``."""
    return e[2 * var], e[2 * var + 1]


def deriv_at_0(e, var: int, z: int) -> fmpq:
    s, c = _factor(e, var)
    return mixed_derivative(c, HALF, s, HALF, z)


def deriv_at(e, var: int, z: int, x: mpmath.mpf) -> mpmath.mpf:
    s, c = _factor(e, var)
    if s == 0 and c == 0:
        return mpmath.mpf(1 if z == 0 else 0)
    return mpmath.diff(lambda t: mpmath.sin(t / 2) ** s * mpmath.cos(t / 2) ** c, x, z)


#: The geometry of a parametrization of the proof, as the callers pass it: ``(the variable set to 0 by the
#: substitution, the variable running with it, the third)`` (0 = u, 1 = v, 2 = w); the r-th derivative at the boundary
#: is sum_k C(r,k) (-1)^k d^{r-k}_first d^k_second.  It is not defined here: the callers compute it from the printed
#: parametrizations (:func:`paper_repro.claims.lines.sec1_3.step_geometry`, read from the transcriptions).
Geometry = tuple[int, int, int]


def nonvanishing(e, geometry: Geometry, r: int, alpha: mpmath.mpf) -> bool:
    """Whether the r-th derivative of the function along the parametrization of ``geometry`` at the boundary is
    non-zero."""
    zero_var, other, fixed = geometry
    with mpmath.workdps(30):
        for x in (alpha / 3, alpha * 5 / 7):
            total = mpmath.mpf(0)
            for k in range(r + 1):
                d0 = deriv_at_0(e, zero_var, r - k)
                if d0 == 0:
                    continue
                total += comb(r, k) * (-1) ** k * mpmath.mpf(int(d0.p)) / int(d0.q) * deriv_at(e, other, k, alpha - x)
            total *= deriv_at(e, fixed, 0, x)
            if abs(total) > mpmath.mpf(10) ** -20:
                return True
    return False


def elimination(n: int, params: dict[str, Geometry], alpha: float = 1.0) -> list[dict]:
    """The steps of the proof: list of {r, param, alive_before, nonvanishing} (indices into T_{2n}); ``params`` are
    the parametrizations in the order the proof takes them, each with its :data:`Geometry`."""
    labels = united_system(n)
    alive = set(range(len(labels)))
    steps = []
    for r in range(n):
        for param, geometry in params.items():
            nz = {k for k in alive if nonvanishing(exponents(labels[k]), geometry, r, mpmath.mpf(alpha))}
            steps.append({"r": r, "param": param, "alive_before": sorted(alive), "nonvanishing": sorted(nz)})
            alive -= nz
    if alive != {0}:
        raise AssertionError(f"elimination for n={n} leaves {[labels[k].paper for k in sorted(alive)]}")
    return steps
