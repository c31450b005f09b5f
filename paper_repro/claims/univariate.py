"""Claim ``univariate``: the univariate normalized B-basis (eq. univariate_basis).

* Printed constants ``c_{2n,i}`` (binomial sum) equal the coefficients of ``(X^2 + 2cXY + Y^2)^n``
  (independent: flint polynomial powers), exactly, as polynomials in c = cos(alpha/2) -- and with the
  identity ``sin^2((a-t)/2) + 2cos(a/2) sin((a-t)/2) sin(t/2) + sin^2(t/2) = sin^2(a/2)``, proven as a
  polynomial identity in S = sin(a/2), C = cos(a/2), s = sin(t/2), c = cos(t/2) (expand with
  sin((a-t)/2) = S c - C s, reduce modulo S^2 + C^2 = 1 and s^2 + c^2 = 1: the remainder is the zero
  polynomial, so the identity holds for all real a and t), this proves the partition of unity for every
  alpha and every n in range.
* Symmetry ``c_{2n,i} = c_{2n,2n-i}`` (eq. symmetry_of_Sanchez_Reyes_constants), exact.
* Partition of unity at high precision at many t and alpha (the evaluator itself).
* Proposition Bernstein (eq. limit_Bernstein): ``A_{2n,i}(alpha s) -> B_i^{2n}(s)``, with the measured
  convergence order (expected 2: the error is an even function of alpha).
"""

from __future__ import annotations

from math import comb

import mpmath
import numpy as np
from flint import fmpq_poly, fmpz_mpoly_ctx

from paper_repro.core.alphas import alpha_mp
from paper_repro.core.univariate import A, bernstein, c_numerator, c_numerator_by_expansion
from paper_repro.util.measured import bound
from paper_repro.util.registry import Outcome, claim


def constants_match(n: int) -> bool:
    expansion = c_numerator_by_expansion(n)
    return all(fmpq_poly(c_numerator(n, i)) == expansion[i] for i in range(2 * n + 1))


def constants_symmetric(n: int) -> bool:
    return all(fmpq_poly(c_numerator(n, i)) == fmpq_poly(c_numerator(n, 2 * n - i)) for i in range(2 * n + 1))


def _reduce_pythagorean(p, ctx):
    """``p`` in Z[S, C, s, c] reduced modulo S^2 + C^2 - 1 and s^2 + c^2 - 1 (S^2 -> 1 - C^2, s^2 -> 1 - c^2):
    a combination of the monomials S^{0,1} C^k s^{0,1} c^l, which is zero iff ``p`` vanishes for all angles."""
    S, C, s, c = ctx.gens()
    out = ctx.from_dict({})
    for (a, b, d, e), coef in p.to_dict().items():
        out += coef * S ** (a % 2) * (1 - C**2) ** (a // 2) * C**b * s ** (d % 2) * (1 - c**2) ** (d // 2) * c**e
    return out


def base_identity_residual(middle: int = 2):
    """The reduced polynomial of ``sin^2((a-t)/2) + middle cos(a/2) sin((a-t)/2) sin(t/2) + sin^2(t/2) -
    sin^2(a/2)`` (zero for the printed ``middle = 2``: the identity holds for all a, t; any other value leaves a
    non-zero remainder)."""
    ctx = fmpz_mpoly_ctx.get(("S", "C", "s", "c"), "lex")
    S, C, s, c = ctx.gens()
    x = S * c - C * s  # sin((a - t)/2)
    return _reduce_pythagorean(x * x + middle * C * x * s + s * s - S * S, ctx)


def bernstein_errors(n: int, exponents_k: list[int], samples: int, dps: int) -> list[mpmath.mpf]:
    """max_{i,s} |A_{2n,i}(alpha s) - B_i^{2n}(s)| for alpha = 2^-k."""
    out = []
    with mpmath.workdps(dps):
        s = [mpmath.mpf(k) / (samples - 1) for k in range(samples)]
        b = bernstein(2 * n, s)
        for k in exponents_k:
            alpha = mpmath.mpf(2) ** (-k)
            a = A(n, alpha, [alpha * x for x in s], "mp")
            out.append(max(abs(x) for x in (a - b).reshape(-1)))
    return out


def limit_factor_is_binomial(n: int) -> bool:
    """Proposition Bernstein, exactly: with s = sin(alpha/2) -> 0 and c -> 1,
    A_{2n,i}(alpha x) = [P_i(c) / s^{2n}] sin^{2n-i}(alpha(1-x)/2) sin^i(alpha x/2) -> P_i(1) (1-x)^{2n-i} x^i,
    so the limit is B_i^{2n}(x) iff the printed numerator at c = 1 equals binom(2n, i)."""
    return all(sum(c_numerator(n, i)) == comb(2 * n, i) for i in range(2 * n + 1))


@claim("univariate", paper_ref=["univariate_basis", "symmetry_of_Sanchez_Reyes_constants", "Bernstein",
                                "limit_Bernstein"],
       statement="The univariate basis A_{2n,i} is a partition of unity, c_{2n,i} = c_{2n,2n-i}, and "
                 "A_{2n,i}(alpha s) -> B_i^{2n}(s) as alpha -> 0 (Proposition Bernstein): proven for "
                 "n = 1..{n_exact_max} and every alpha in (0, pi) by exact polynomial identities.",
       kind="proof", n_exact_max=30, ns_numeric=list(range(1, 11)), alphas=["pi/6", "pi/2", "5pi/6", "3.1"], dps=50)
def run(n_exact_max: int, ns_numeric: list[int], alphas: list[str], dps: int) -> Outcome:
    ns = range(1, n_exact_max + 1)
    match = [n for n in ns if not constants_match(n)]
    sym = [n for n in ns if not constants_symmetric(n)]
    limit = [n for n in ns if not limit_factor_is_binomial(n)]
    ident = base_identity_residual().is_zero()
    worst = mpmath.mpf(0)
    with mpmath.workdps(dps):
        for n in ns_numeric:
            for a_text in alphas:
                alpha = alpha_mp(a_text)
                t = [alpha * mpmath.mpf(k) / 20 for k in range(21)]
                sums = A(n, alpha, t, "mp").sum(axis=1)
                worst = max(worst, max(abs(x - 1) for x in sums))
    tol = mpmath.mpf(10) ** (-(dps - 10))
    passed = not match and not sym and not limit and ident and worst <= tol
    return Outcome(passed, {
        "printed_c_equals_expansion": "all n" if not match else match,
        "c_symmetric": "all n" if not sym else sym,
        "bernstein_limit_factor_equals_binomial": "all n" if not limit else limit,
        "base_identity_polynomial_identity_in_sin_cos": ident,
        "partition_of_unity_max_abs_error_mp_check": bound(worst, tol), "tolerance": f"1e-{dps - 10}",
        "proof_scope": f"exact polynomial identities for n = 1..{n_exact_max}, all alpha in (0, pi) (the base "
                       "identity reduced modulo sin^2 + cos^2 = 1 to the zero polynomial); the mp "
                       "partition-of-unity values are a consistency check, not part of the proof; the "
                       "convergence order of the limit is claim univariate_limit_order (numeric evidence)",
    })


@claim("univariate_limit_order", paper_ref=["limit_Bernstein"],
       statement="The convergence A_{2n,i}(alpha s) -> B_i^{2n}(s) is of order alpha^2 (observed order of the "
                 "max error at alpha = 2^-k, k = 3..12, fitted; n in {bernstein_ns}).",
       kind="numeric-evidence", bernstein_ns=[1, 2, 3, 5, 8], bernstein_k=list(range(3, 13)), dps=50)
def run_order(bernstein_ns: list[int], bernstein_k: list[int], dps: int) -> Outcome:
    orders, limit_errors = {}, {}
    for n in bernstein_ns:
        errs = bernstein_errors(n, bernstein_k, 11, dps)
        logs = np.array([float(mpmath.log(e, 2)) for e in errs])
        slope = -np.polyfit(np.array(bernstein_k, dtype=float), logs, 1)[0]
        orders[str(n)] = round(float(slope), 4)
        limit_errors[str(n)] = {f"2^-{k}": mpmath.nstr(e, 3) for k, e in zip(bernstein_k, errs)}
    orders_ok = all(abs(o - 2) < 0.05 for o in orders.values())
    return Outcome(orders_ok, {"bernstein_observed_order": orders, "bernstein_expected_order": 2,
                               "bernstein_max_error": limit_errors})
