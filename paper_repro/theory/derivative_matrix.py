"""The derivative of the scaled monomials of T_{2n} as a matrix over Z[cos(alpha/2)], recovered modulo primes.

The span of T_{2n} is closed under differentiation along Omega^alpha (it is the hexagon Fourier span,
:func:`paper_repro.theory.question1.hexagon_check`).  For the direction ``u = (1, 0, -1)``
(:data:`~paper_repro.core.derivatives_basis.DIRECTIONS`) and the scaled monomials ``m_f`` (sines divided by
``s = sin(alpha/2)``, :func:`~paper_repro.core.basis.evaluate` with ``scaled=True``)::

    2 s d/du m_f = sum_g C[g, f](alpha) m_g.

Every entry of C is a polynomial with integer coefficients in ``kappa = cos(alpha/2)`` of degree at most n + 1:
**proven for every n** (docs/elevation_and_derivative_for_all_n.md, Theorem 1; the closed form is
:mod:`paper_repro.core.half_angle_matrices`, claim ``derivative_all_n``).  This module recovers the same polynomials
without the proof, as an independent cross-check of the closed form: at ``n + 2 + verify`` shape parameters
``alpha = 4 atan(1/k)`` (rational half-angle sines and cosines) C is solved exactly over F_p at alpha-independent
collocation points (:func:`~paper_repro.core.normalization.fixed_points`), each entry is interpolated in kappa from
the first n + 2 values and checked at the others, and the coefficients are lifted to the symmetric range; the
recovery is repeated with a second prime and must give the same integers.  What is exact: each modular solve and
check.  What this route alone would leave as evidence: the small integer lifts on which two primes agree (no bound
on their size is used); the degree bound is Theorem 1.  Another independent check: the certified ball solve of
``tools/derivative_matrix.py`` at fixed alpha (tests compare the two).

The other directions follow by symmetry: T_{2n} is invariant under every permutation of (u, v, w)
(:func:`~paper_repro.core.labels.variable_swap`), and ``(0, 1, -1)`` is ``(1, 0, -1)`` with u and v exchanged.

>>> rows, cols, coefs = derivative_polynomials(1)
>>> len(rows), int(abs(coefs).max()), coefs.shape[1] - 1
(20, 2, 2)
"""

from __future__ import annotations

import json

import numpy as np
from flint import fmpq

from paper_repro.core.basis import monomials
from paper_repro.core.context import ModpContext
from paper_repro.core.derivatives_basis import monomial_derivative
from paper_repro.core.domain import RationalPoints, rational_alpha, scaled_half_angle_values
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.normalization import fixed_points
from paper_repro.theory.modular import _matmul_mod, _nmod_solve, primes_below
from paper_repro.util.validation import check_n

#: The direction of the recovered matrix, (du, dv, dw).
DIRECTION_U = (1, 0, -1)


def derivative_matrix_modp(n: int, alpha, p: int, direction=DIRECTION_U, seed: int = 0) -> np.ndarray:
    """C over F_p (``(delta_n, delta_n)`` int64) with ``2 s D m_f = sum_g C[g, f] m_g`` at a rational ``alpha``
    (:func:`~paper_repro.core.domain.rational_alpha`); ``ZeroDivisionError`` if the collocation matrix is singular
    modulo p at these points."""
    ctx = ModpContext(p=p)
    exps = exponent_matrix(n)
    tu, tv = fixed_points(n, delta(n), seed)
    pts = RationalPoints(None, tu, tv, check=False)
    trig = scaled_half_angle_values(pts, alpha, ctx)
    with ctx.scope():
        sa, _ = ctx.alpha_half(alpha)
        vals = monomials(exps, trig, ctx)
        ders = monomial_derivative(exps, trig, direction, ctx, s2=ctx.mul(sa, sa))
    return _nmod_solve(vals, ders, p)


def _recover_modp(n: int, p: int, verify: int, direction) -> np.ndarray | None:
    """``(n + 2, delta_n, delta_n)`` coefficients over F_p, or None if an interpolant fails a check."""
    deg = n + 1
    kappas, mats, k = [], [], 2
    while len(mats) < deg + 1 + verify:
        if k > 4 * (deg + 1 + verify) + 50:
            raise ArithmeticError(f"n = {n}, p = {p}: the collocation points are singular modulo p at every shape "
                                  f"parameter tried (tan(alpha/4) = 1/2 .. 1/{k - 1})")
        alpha = rational_alpha(fmpq(1, k))
        k += 1
        try:
            mats.append(derivative_matrix_modp(n, alpha, p, direction).reshape(-1))
        except ZeroDivisionError:  # singular modulo p at these points: the next parameter
            continue
        kappas.append(ModpContext(p=p).from_rational(alpha.cos_half))
    ks = np.array(kappas, dtype=np.int64)
    vals = np.array(mats, dtype=np.int64)
    vander = np.ones((len(ks), deg + 1), dtype=np.int64)
    for d in range(1, deg + 1):
        vander[:, d] = vander[:, d - 1] * ks % p
    coefs = _nmod_solve(vander[: deg + 1], vals[: deg + 1], p)  # ascending coefficients, (deg + 1, delta_n^2)
    if np.any(_matmul_mod(vander[deg + 1:], coefs, p) != vals[deg + 1:]):
        return None
    m = delta(n)
    return coefs.reshape(deg + 1, m, m)


def derivative_polynomials(n: int, *, primes: int = 2, verify: int = 2, direction=DIRECTION_U
                           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The nonzero entries of C as integer polynomials in kappa: ``(rows, cols, coefs)`` with ``coefs`` of shape
    ``(nnz, n + 2)`` (ascending powers), entries in row-major order.

    ``ArithmeticError`` if an interpolant of degree n + 1 fails at the ``verify`` extra parameters, or if the
    ``primes`` largest primes below 2^31 give different integers (either would contradict Theorem 1 of
    docs/elevation_and_derivative_for_all_n.md).
    """
    n = check_n(n)
    lifts = []
    for p in primes_below(2**31, primes):
        c = _recover_modp(n, p, verify, direction)
        if c is None:
            raise ArithmeticError(f"n = {n}, p = {p}: an entry of C is not a polynomial of degree <= {n + 1} in "
                                  "cos(alpha/2) at the check parameters")
        lifts.append(np.where(c > p // 2, c - p, c))
    if any(not np.array_equal(lifts[0], x) for x in lifts[1:]):
        raise ArithmeticError(f"n = {n}: the integer lifts of C differ between primes")
    coefs = lifts[0]
    rows, cols = np.nonzero(np.any(coefs != 0, axis=0))
    return rows.astype(np.int64), cols.astype(np.int64), coefs[:, rows, cols].T.copy()


def tables_text(nmax: int, progress: bool = False) -> str:
    """The package data ``paper_repro/resources/derivative_tables.json`` for n = 1..nmax: per n the rows, columns
    and integer coefficients of :func:`derivative_polynomials` (one line per n, so a change shows in a diff)."""
    head = {"about": "C with 2 s d/du m_f = sum_g C[g, f] m_g for the scaled monomials m_f of T_{2n} (internal order, "
                     "paper_repro.core.labels.united_system); entry C[rows[e], cols[e]] = sum_d coefs[e][d] kappa^d, "
                     "kappa = cos(alpha/2), s = sin(alpha/2), direction u = (1, 0, -1).  Recovered modulo two primes "
                     "by paper_repro.theory.derivative_matrix (make reproduce); equal to the closed form proven for "
                     "every n in docs/elevation_and_derivative_for_all_n.md (paper_repro.core.half_angle_matrices).",
            "direction": list(DIRECTION_U), "nmax": nmax}
    lines = [json.dumps(head)[:-1] + ', "tables": {']
    for n in range(1, nmax + 1):
        rows, cols, coefs = derivative_polynomials(n)
        t = {"rows": rows.tolist(), "cols": cols.tolist(), "coefs": coefs.tolist()}
        lines.append(f'"{n}": ' + json.dumps(t, separators=(",", ":")) + ("," if n < nmax else ""))
        if progress:
            print(f"  derivative tables: n = {n}, {len(rows)} entries", flush=True)
    lines.append("}}")
    return "\n".join(lines) + "\n"
