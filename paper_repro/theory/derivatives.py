"""Derivatives at 0 of powers of cosine and sine (Lemma lem:sign_cos_power_derivative,
Proposition derivative_cosine_sine).

``C^p_{i,lambda}(0)``, ``S^p_{j,mu}(0)`` and ``M^z_{i,lambda,j,mu}(0)`` are computed independently as
``p! [t^p]`` of exact truncated power series (flint ``fmpq_poly``, rational lambda and mu); the
printed sign rules are transcribed verbatim in :mod:`paper_repro.printed.derivatives`.
"""

from __future__ import annotations

from functools import cache
from math import factorial

from flint import fmpq, fmpq_poly


@cache
def _cos_series(lam: fmpq, order: int) -> fmpq_poly:
    return fmpq_poly([(-1) ** (k // 2) * lam**k / factorial(k) if k % 2 == 0 else 0 for k in range(order + 1)])


@cache
def _sin_series(mu: fmpq, order: int) -> fmpq_poly:
    return fmpq_poly([(-1) ** (k // 2) * mu**k / factorial(k) if k % 2 == 1 else 0 for k in range(order + 1)])


def _deriv(series: fmpq_poly, p: int) -> fmpq:
    coeffs = series.coeffs()
    return (coeffs[p] if p < len(coeffs) else fmpq(0)) * factorial(p)


def cos_power_derivative(i: int, lam: fmpq, p: int) -> fmpq:
    """C^p_{i,lambda}(0) = d^p/dt^p cos^i(lambda t) at 0, exactly."""
    return _deriv(_cos_series(lam, p).pow_trunc(i, p + 1), p)


def sin_power_derivative(j: int, mu: fmpq, p: int) -> fmpq:
    """S^p_{j,mu}(0) = d^p/dt^p sin^j(mu t) at 0, exactly."""
    return _deriv(_sin_series(mu, p).pow_trunc(j, p + 1), p)


def mixed_derivative(i: int, lam: fmpq, j: int, mu: fmpq, z: int) -> fmpq:
    """M^z_{i,lambda,j,mu}(0) = d^z/dt^z (cos^i(lambda t) sin^j(mu t)) at 0, exactly."""
    prod = _cos_series(lam, z).pow_trunc(i, z + 1).mul_low(_sin_series(mu, z).pow_trunc(j, z + 1), z + 1)
    return _deriv(prod, z)


def sign(x: fmpq) -> int:
    return (x > 0) - (x < 0)


def corrected_sign_cos(i: int, p: int) -> int:
    """Sign of C^p_{i,lambda}(0) for i >= 1, lambda > 0: 0 for odd p, (-1)^(p/2) for even p.

    (cos^i is even with alternating Taylor series: a product of alternating even series is alternating.)
    """
    return 0 if p % 2 else (-1) ** (p // 2)
