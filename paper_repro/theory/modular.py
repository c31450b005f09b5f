"""Multimodular recovery of the closed forms ``r = P(cos(alpha/2)) / sin^{2n+j}(alpha/2)`` (open Question 1).

The recovery only *finds* candidates; :mod:`paper_repro.theory.identity_proof` proves them.

For a prime p (below 2^31, so that numpy's int64 products do not overflow) and rational shape
parameters ``alpha = 4 atan(1/k)``, the reduced partition-of-unity system
(:func:`paper_repro.core.normalization.solve_reduced`) is solved over F_p (flint ``nmod_mat``).  For
every orbit o, ``y = r_o s^{k_o}`` is a polynomial in ``c`` of degree <= D (D = 2n first, raised if the
check fails), so D + 1 values give it by interpolation over F_p and ``verify`` further values check
it.  The coefficients over Q follow by the Chinese remainder theorem (symmetric integer lift, or rational
reconstruction); primes are added until the lift no longer changes with a new prime.  Every step is exact; what is
not guaranteed is only that the stabilised reconstruction is the true rational (which the proof settles).

>>> forms = recover_modular(2)
>>> [int(x) for x in forms["r_{4,2,2}"].numerator.coeffs()], forms["r_{4,2,2}"].sin_power
([10, 0, 10, 0, -20], 6)
"""

from __future__ import annotations

import sys
from functools import cache

import numpy as np
from flint import fmpq, fmpq_poly, fmpz

from paper_repro.core.context import ModpContext, power_table, to_nmod_mat
from paper_repro.core.domain import rational_alpha
from paper_repro.core.exact_solve import wang_pair
from paper_repro.core.labels import exponent_matrix
from paper_repro.core.normalization import _orbit_columns, _plane_points, fixed_points, orbits
from paper_repro.theory.closed_form import ClosedForm
from paper_repro.util.validation import check_n

#: Largest number of primes tried before giving up (each adds about 31 bits).
MAX_PRIMES = 64


@cache
def primes_below(bound: int = 2**31, count: int = MAX_PRIMES) -> tuple[int, ...]:
    """The ``count`` largest primes below ``bound``, descending (deterministic)."""
    out, x = [], bound - 1
    while len(out) < count:
        if fmpz(x).is_prime():
            out.append(x)
        x -= 1
    return tuple(out)


def shape_parameters(count: int):
    """``alpha = 4 atan(1/k)`` for ``k = 2, 3, ...``: distinct rational tangents (all alpha in (0, pi))."""
    return [rational_alpha(fmpq(1, k)) for k in range(2, 2 + count)]


def _nmod_solve(mat: np.ndarray, rhs: np.ndarray, p: int) -> np.ndarray:
    """``mat^-1 rhs`` over F_p (``ZeroDivisionError`` if ``mat`` is singular; entries in [0, p), p < 2^31).

    A small matrix with many right-hand sides (the interpolation of a whole matrix's entries) is inverted and the
    inverse applied column by column in int64 (each step below 2^62 before its reduction): the same result,
    without converting every entry to and from flint."""
    if rhs.shape[1] > 16 * mat.shape[0] and p < 2**31:
        inv = to_nmod_mat(mat, p).inv()
        ia = np.array([int(v) for v in inv.entries()], dtype=np.int64).reshape(mat.shape[0], mat.shape[0])
        b = np.asarray(rhs, dtype=np.int64)
        out = np.zeros(b.shape, dtype=np.int64)
        for k in range(ia.shape[1]):
            out = (out + ia[:, k: k + 1] * b[k: k + 1, :]) % p
        return out
    a, b = to_nmod_mat(mat, p), to_nmod_mat(rhs, p)
    x = a.solve(b)
    return np.array([int(v) for v in x.entries()], dtype=np.int64).reshape(x.nrows(), x.ncols())


class ReducedSystemModp:
    """The reduced partition-of-unity system of T_{2n} over F_p at the alpha-independent points
    :func:`~paper_repro.core.normalization.fixed_points` (point set ``seed``).

    Every function is ``g(u, v) * sin^e4(w/2) cos^e5(w/2)``; the factor g does not depend on alpha and is
    computed once, so a new alpha costs only the w powers, one product and the orbit sums.  The matrix
    is the one :func:`~paper_repro.core.normalization.reduced_matrix` builds (a test compares them).
    """

    def __init__(self, n: int, p: int, seed: int = 0) -> None:
        self.n, self.p = n, p
        self.ctx = ModpContext(p=p)
        m = len(orbits(n))
        tu, tv = fixed_points(n, m, seed)
        self.points = _plane_points(tu, tv)
        su, cu, sv, cv = (np.array([self.ctx.from_rational(x) for x in col], dtype=np.int64)
                          for col in self.points.quarter_values())
        self.quarter = (su, cu, sv, cv)
        exps = exponent_matrix(n)
        perm, starts = _orbit_columns(n)
        exps = exps[perm]
        kmax = int(exps.max())
        g = np.ones((m, len(perm)), dtype=np.int64)
        for slot, x in enumerate(self.quarter):
            table = power_table(x, kmax, self.ctx)
            g = g * table[exps[:, slot]].T % p
        # columns of one orbit with the same w exponents (e4, e5) share the alpha-dependent factor: sum them once
        ends = list(starts[1:]) + [len(perm)]
        keys = sorted({(int(a), int(b)) for a, b in exps[:, 4:6]})
        key_index = {k: i for i, k in enumerate(keys)}
        cols, key_of, new_starts = [], [], []
        for lo, hi in zip(starts, ends):
            new_starts.append(len(cols))
            groups: dict[tuple[int, int], list[int]] = {}
            for c in range(lo, hi):
                groups.setdefault((int(exps[c, 4]), int(exps[c, 5])), []).append(c)
            for k, members in groups.items():
                cols.append(g[:, members].sum(axis=1) % p)
                key_of.append(key_index[k])
        self.g = np.stack(cols, axis=1)
        self.key_of = np.array(key_of)
        self.key_exps = np.array(keys, dtype=np.int64)
        self.starts = np.array(new_starts)
        self.kmax = kmax

    def matrix(self, alpha) -> np.ndarray:
        ctx, p = self.ctx, self.p
        sa, ca = ctx.alpha_half(alpha)
        sw, cw = ctx.w_half(ctx, sa, ca, *self.quarter)
        w = (power_table(sw, self.kmax, ctx)[self.key_exps[:, 0]]
             * power_table(cw, self.kmax, ctx)[self.key_exps[:, 1]] % p)
        full = self.g * w[self.key_of].T % p
        return np.add.reduceat(full, self.starts, axis=1) % p

    def solve(self, alpha) -> np.ndarray:
        a = self.matrix(alpha)
        return _nmod_solve(a, np.ones((a.shape[0], 1), dtype=np.int64), self.p).reshape(-1)


def values_modp(n: int, p: int, count: int) -> tuple[np.ndarray, list]:
    """``(values, alphas)``: the orbit coefficients modulo p, ``(count, m)``, at ``count`` shape parameters.

    The solution does not depend on the collocation points, so at each alpha the first of up to 4 point sets
    that is non-singular modulo p is used; an alpha where all are singular is skipped for the next one.
    """
    systems: dict[int, ReducedSystemModp] = {}
    rows, used, k = [], [], 2
    while len(rows) < count:
        alpha = rational_alpha(fmpq(1, k))
        k += 1
        if k > 10 * count + 50:
            raise ArithmeticError(f"recovery n={n}: too many shape parameters singular modulo {p}")
        for seed in range(4):
            system = systems.get(seed)
            if system is None:  # built once per point set (not as a setdefault argument, built every call)
                system = systems[seed] = ReducedSystemModp(n, p, seed)
            try:
                rows.append(system.solve(alpha))
            except ZeroDivisionError:
                continue
            used.append(alpha)
            break
    return np.array(rows), used


def numerators_modp(n: int, p: int, degree: int, verify: int) -> np.ndarray | None:
    """Coefficients (ascending) modulo p of every numerator P_o of degree <= ``degree``: ``(m, degree+1)``;
    ``None`` if the interpolants fail at the ``verify`` further shape parameters."""
    orb = orbits(n)
    count = degree + 1 + verify
    vals, alphas = values_modp(n, p, count)
    ctx = ModpContext(p=p)
    cs = np.array([ctx.from_rational(a.cos_half) for a in alphas], dtype=np.int64)
    ss = np.array([ctx.from_rational(a.sin_half) for a in alphas], dtype=np.int64)
    ks = [2 * n + rep.j for rep, _ in orb]
    ys = np.empty_like(vals)
    for o, k in enumerate(ks):
        ys[:, o] = vals[:, o] * np.array([pow(int(s), k, p) for s in ss], dtype=np.int64) % p
    vander = np.ones((count, degree + 1), dtype=np.int64)
    for d in range(1, degree + 1):
        vander[:, d] = vander[:, d - 1] * cs % p
    coeffs = _nmod_solve(vander[: degree + 1], ys[: degree + 1], p)  # (degree+1, m)
    if verify and np.any(_matmul_mod(vander[degree + 1:], coeffs, p) != ys[degree + 1:]):
        return None
    return coeffs.T.copy()


def _matmul_mod(a: np.ndarray, b: np.ndarray, p: int) -> np.ndarray:
    """``a @ b mod p`` (entries in [0, p)) as an int64 array: flint's ``nmod_mat`` product (exact; p < 2^63).

    >>> _matmul_mod(np.array([[1, 2], [3, 4]]), np.array([[5], [-6]]), 7).tolist()
    [[0], [5]]
    """
    a, b = np.asarray(a) % p, np.asarray(b) % p
    r, c = a.shape[0], b.shape[1]
    if r == 0 or c == 0 or a.shape[1] == 0:
        return np.zeros((r, c), dtype=np.int64)
    prod = to_nmod_mat(a, p) * to_nmod_mat(b, p)
    return np.array([int(x) for x in prod.entries()], dtype=np.int64).reshape(r, c)


def rational_reconstruction(a: int, m: int) -> fmpq | None:
    """The fraction x/y with |x|, 0 < y <= sqrt(m/2) and x = a y (mod m), or ``None`` (Wang's algorithm)."""
    pair = wang_pair(a, m, int(fmpz(m // 2).isqrt()))
    if pair is None:
        return None
    r1, s1 = pair
    from math import gcd

    if gcd(r1, abs(s1)) != 1:
        return None
    return fmpq(r1, s1) if s1 > 0 else fmpq(-r1, -s1)


def _crt(res: list[int], mod: int, new: list[int], p: int) -> list[int]:
    inv = pow(mod % p, -1, p)
    return [r + mod * ((x - r) * inv % p) for r, x in zip(res, new)]


def recover_modular(n: int, *, verify: int = 2, max_degree: int | None = None, progress: bool = False) -> dict:
    """Closed forms ``{label: ClosedForm}`` of every orbit representative (see the module docstring).

    ``ArithmeticError`` if no degree <= ``max_degree`` (default 6n + 4) fits or the reconstruction does
    not stabilise within :data:`MAX_PRIMES` primes.
    """
    n = check_n(n)
    orb = orbits(n)
    limit = max_degree if max_degree is not None else 6 * n + 4
    primes = primes_below()
    degree = 2 * n
    first = None
    while degree <= limit:
        first = numerators_modp(n, primes[0], degree, verify)
        if first is not None:
            break
        degree += 2
    if first is None:
        raise ArithmeticError(f"no closed form P(c)/s^(2n+j) with deg P <= {limit} found for n = {n}")
    flat = [int(x) for x in first.reshape(-1)]
    mod, prev_int, prev_rat = primes[0], None, None
    for p in primes[1:]:
        coeffs = numerators_modp(n, p, degree, verify)
        if coeffs is None:
            raise ArithmeticError(f"recovery n={n}: the interpolants fail modulo {p} (degree {degree})")
        flat = _crt(flat, mod, [int(x) for x in coeffs.reshape(-1)], p)
        mod *= p
        # integers first (the symmetric lift needs half the primes of a rational reconstruction), then
        # rationals; either is accepted once one more prime leaves it unchanged
        lifted = [fmpq(x - mod if 2 * x > mod else x) for x in flat]
        rec = [rational_reconstruction(x, mod) for x in flat]
        if progress:
            print(f"recovery n={n}: {len(str(mod))}-digit modulus", file=sys.stderr, flush=True)
        found = lifted if lifted == prev_int else (rec if None not in rec and rec == prev_rat else None)
        if found is not None:
            table = np.array(found, dtype=object).reshape(first.shape)
            out = {}
            for o, (rep, _) in enumerate(orb):
                out[rep.coefficient] = ClosedForm(rep.coefficient, 2 * n + rep.j, fmpq_poly(list(table[o])))
            return out
        prev_int, prev_rat = lifted, rec
    raise ArithmeticError(f"recovery n={n}: the rational reconstruction did not stabilise with {len(primes)} primes")
