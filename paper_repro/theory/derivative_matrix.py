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

The tables (package data ``paper_repro/resources/derivative_tables.json``, n <= :data:`TABLE_MAX_N`, written by
``tools/derivative_tables.py`` from :func:`tables_text`) are read here too, beside the recovery that writes them and
the checks that use them (they were ``paper_repro.core.derivative_tables``, though no library code
reads them since C has a proven closed form, :mod:`paper_repro.core.half_angle_matrices`): :func:`table` gives the
integers, :func:`entries` their float values at ``kappa`` by Horner's rule and :func:`table_derivative_nets` the
nets ``(q_u, q_v)`` of ``2 s d/du`` and ``2 s d/dv`` through them, the independent reference that claim
``derivative_all_n`` (:func:`paper_repro.theory.half_angle_checks.tables_equal`) and the tests compare the closed
form with (n <= 3 recovered again in the fast suite, every n <= 10 in the slow one).

>>> import math
>>> qu, qv = table_derivative_nets(1, math.cos(0.5), np.eye(7)[:, :1])   # the net of m_0 = S_u S_v S_w
>>> np.nonzero(qu[:, 0])[0].tolist(), qu[np.nonzero(qu[:, 0])[0], 0].tolist()
([4, 6], [1.0, -1.0])
"""

from __future__ import annotations

import json
from functools import cache

import numpy as np
from flint import fmpq

from paper_repro.core.basis import monomials
from paper_repro.core.context import ModpContext
from paper_repro.core.derivatives_basis import monomial_derivative
from paper_repro.core.domain import RationalPoints, rational_alpha, scaled_half_angle_values
from paper_repro.core.labels import delta, exponent_matrix, variable_swap
from paper_repro.core.normalization import fixed_points
from paper_repro.theory.modular import _matmul_mod, _nmod_solve, primes_below
from paper_repro.util.io import RESOURCES
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


#: Largest order with a table (the float-accuracy claim's range; each table is exact integers, about 50 KB at n = 10).
TABLE_MAX_N = 10

#: The package data file.
TABLES = RESOURCES / "derivative_tables.json"


def has_table(n: int) -> bool:
    """True when the derivative of order ``n`` goes through C (``1 <= n <= TABLE_MAX_N``)."""
    return 1 <= n <= TABLE_MAX_N


@cache
def _all_tables() -> dict:
    return json.loads(TABLES.read_text(encoding="utf-8"))["tables"]


@cache
def table(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(rows, cols, coefs)`` of C for the direction u: entry ``C[rows[e], cols[e]] = sum_d coefs[e, d] kappa^d``
    (``coefs`` of shape ``(nnz, n + 2)``, integers as float64: exact, at most 2n in size); read-only arrays."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not has_table(int(n)):
        raise ValueError(f"n must be an integer from 1 to {TABLE_MAX_N} for a table of C, got {n!r}")
    n = int(n)
    t = _all_tables()[str(n)]
    out = (np.array(t["rows"], dtype=np.int64), np.array(t["cols"], dtype=np.int64),
           np.array(t["coefs"], dtype=np.float64))
    for a in out:
        a.setflags(write=False)
    return out


def entries(n: int, kappa: float) -> np.ndarray:
    """The float64 values of C's nonzero entries at ``kappa`` (Horner's rule in the order of :func:`table`);
    each within ``(2 (n + 1) + 1) u sum_d |c_d| kappa^d`` of the exact polynomial (u = 2^-53)."""
    coefs = table(n)[2]
    val = coefs[:, -1].copy()
    for d in range(coefs.shape[1] - 2, -1, -1):
        val *= kappa
        val += coefs[:, d]
    return val


def apply(n: int, vals: np.ndarray, net: np.ndarray) -> np.ndarray:
    """``C net`` for a ``(delta_n, m)`` net, with the entry values ``vals`` of :func:`entries`: each output row
    summed in the order of the table (deterministic)."""
    rows, cols, _ = table(n)
    out = np.zeros((delta(n), net.shape[1]))
    np.add.at(out, rows, vals[:, None] * net[cols])
    return out


def table_derivative_nets(n: int, kappa: float, net: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(q_u, q_v)``: the nets of ``2 s d/du`` and ``2 s d/dv`` of the patch ``sum_f net[f] m_f``
    (``net`` of shape ``(delta_n, m)``, on the scaled monomials, :func:`entries` at ``kappa = cos(alpha/2)``)."""
    if not -1.0 <= kappa <= 1.0:
        raise ValueError(f"kappa = cos(alpha/2) must be a number in [-1, 1], got {kappa!r}")
    net = np.asarray(net, dtype=np.float64)
    if net.ndim != 2 or net.shape[0] != delta(n):
        raise ValueError(f"net must be a (delta_n, m) = ({delta(n)}, m) array for n = {n}, got shape {net.shape}")
    vals = entries(n, kappa)
    pi = variable_swap(n, 0, 1)  # m_{pi[f]}(u, v, w) = m_f(v, u, w)
    qu = apply(n, vals, net)
    qv = np.empty_like(qu)
    qv[pi] = apply(n, vals, net[pi])
    return qu, qv
