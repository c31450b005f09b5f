"""Exact solve of a rational system ``A X = B`` with a small solution: modular solves, rational reconstruction,
an exact check.

The collocation systems of order elevation (:func:`paper_repro.core.elevation.elevation_matrix_exact`) have
entries of several hundred bits (values of the basis at rational points) but a solution of a few dozen bits per
entry, with one denominator per row.  Fraction-free elimination (flint's ``fflu``) carries the large entries
through; here instead:

1. every row of ``[A | B]`` is multiplied by its least common denominator (same solution, integer entries);
2. the system is solved modulo primes p < 2^62 (``nmod_mat``; a prime where the matrix is singular is skipped),
   the residues are combined by the Chinese remainder theorem, and every row of X is reconstructed as rationals
   with one common denominator (Wang's rational reconstruction), until two successive reconstructions agree;
3. the candidate is **checked exactly**: ``A X == B`` in rational arithmetic.

Why the result is exact (a proof, no bound involved; ``A`` square, the moduli primes): the check makes X a solution
of ``A X = B``; and ``A`` is invertible because the row-scaled integer matrix, whose determinant is det(A) times the
non-zero row denominators, was invertible modulo a prime (step 2 used at least one prime: flint's modular solve
raises on a singular matrix) -- so X is *the* solution, the same matrix flint's ``fmpq_mat.solve`` returns. If the
reconstruction does not stabilise and pass the check within :data:`PRIMES` primes, or the matrix is singular modulo
all of them, the routine falls back to ``fmpq_mat.solve(algorithm="fflu")`` (which raises ``ZeroDivisionError`` for
a singular matrix, like ``fmpq_mat.solve``).  Speed only depends on these choices, never the result.

>>> from flint import fmpq_mat
>>> a = fmpq_mat(2, 2, [1, 4, 8, 3]); b = fmpq_mat(2, 3, range(6))
>>> solve_exact(a, b) == a.solve(b)
True
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from flint import fmpq, fmpq_mat, fmpz, fmpz_mat, nmod_mat

from paper_repro.core.context import ExactContext, to_fmpq_mat

#: Number of primes tried before the fraction-free fallback (64 primes: solutions up to about 1900 bits per entry).
PRIMES = 64


@lru_cache(maxsize=1)
def _primes(count: int = PRIMES) -> tuple[int, ...]:
    """The ``count`` largest primes below 2^62 (deterministic)."""
    out, x = [], 2**62 - 1
    while len(out) < count:
        if fmpz(x).is_prime():
            out.append(x)
        x -= 2
    return tuple(out)


def _isqrt_half(m: int) -> int:
    return int(fmpz(m // 2).isqrt())


def wang_pair(a: int, m: int, bound: int) -> tuple[int, int] | None:
    """``(x, y)`` with ``x = a y (mod m)``, ``|x| <= bound`` and ``0 < |y| <= bound`` from the half extended Euclidean
    algorithm of Wang's rational reconstruction, or ``None`` (no such pair is found).

    >>> wang_pair(4, 7, 2)  # 4 = 1/2 modulo 7
    (1, 2)
    >>> wang_pair(3, 7, 1) is None
    True
    """
    r0, r1, s0, s1 = m, a % m, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1 = r1, r0 - q * r1
        s0, s1 = s1, s0 - q * s1
    if s1 == 0 or abs(s1) > bound:
        return None
    return r1, s1


def _reconstruct_row(res: list[int], mod: int, bound: int) -> tuple[list[int], int] | None:
    """Numerators ``y`` and one denominator ``d`` with ``y_i = res_i d (mod mod)`` and |y_i|, d <= ``bound``
    (Wang's rational reconstruction, the common denominator widened entry by entry), or ``None``."""
    half = mod // 2
    d = 1
    out: list[int] = []
    for r in res:
        y = r * d % mod
        if y > half:
            y -= mod
        if -bound <= y <= bound:
            out.append(y)
            continue
        pair = wang_pair(y, mod, bound)
        if pair is None:
            return None
        g = abs(pair[1])
        d *= g
        if d > bound:
            return None
        out = [x * g for x in out]
        y = r * d % mod
        if y > half:
            y -= mod
        if not -bound <= y <= bound:
            return None
        out.append(y)
    return out, d


def _row_scaled(a: fmpq_mat, b: fmpq_mat) -> tuple[list[list[int]], list[list[int]]]:
    """Rows of ``[A | B]`` times the least common denominator of the row: integer rows, same solution."""
    ta, tb = a.table(), b.table()
    outa, outb = [], []
    for ra, rb in zip(ta, tb):
        num, _ = fmpq_mat(1, len(ra) + len(rb), ra + rb).numer_denom()
        ints = [int(v) for v in num.entries()]
        outa.append(ints[: len(ra)])
        outb.append(ints[len(ra):])
    return outa, outb


def solve_exact(a: fmpq_mat, b: fmpq_mat) -> fmpq_mat:
    """The X with ``A X = B`` (A square and invertible; ``ZeroDivisionError`` if singular), exactly: see the module
    docstring.

    >>> from flint import fmpq_mat, fmpq
    >>> a = fmpq_mat(2, 2, [fmpq(1, 3), 2, 5, fmpq(7, 11)]); x = fmpq_mat(2, 1, [fmpq(-2, 9), 4])
    >>> solve_exact(a, a * x) == x
    True
    >>> solve_exact(fmpq_mat(2, 2, [1, 2, 2, 4]), fmpq_mat(2, 1, [1, 2]))
    Traceback (most recent call last):
      ...
    ZeroDivisionError: singular matrix in solve()
    """
    if a.nrows() != a.ncols() or b.nrows() != a.nrows():
        raise ValueError("need a square system and compatible right hand side")
    m, k = a.nrows(), b.ncols()
    ia, ib = _row_scaled(a, b)
    az, bz = fmpz_mat(ia), fmpz_mat(ib)
    mod, res, prev = 1, None, None
    for p in _primes():
        try:
            xm = nmod_mat(az, p).solve(nmod_mat(bz, p))
        except ZeroDivisionError:
            continue
        ent = [int(v) for v in xm.entries()]
        if res is None:
            res, mod = ent, p
        else:
            inv = pow(mod % p, -1, p)
            res = [r + mod * ((x - r) * inv % p) for r, x in zip(res, ent)]
            mod *= p
        bound = _isqrt_half(mod)
        rows = []
        for i in range(m):
            row = _reconstruct_row(res[i * k: (i + 1) * k], mod, bound)
            if row is None:
                break
            rows.append(row)
        if len(rows) < m:
            prev = None
            continue
        if rows != prev:
            prev = rows
            continue
        x = fmpq_mat(m, k, [fmpq(y, d) for ys, d in rows for y in ys])
        if a * x == b:
            return x
    return a.solve(b, algorithm="fflu")


def solve_exact_array(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """:func:`solve_exact` on object arrays of ``fmpq`` (the shape of ``b`` kept, like ``ExactContext.solve``)."""
    a, b = np.asarray(a, dtype=object), np.asarray(b, dtype=object)
    x = solve_exact(to_fmpq_mat(a), to_fmpq_mat(b.reshape(b.shape[0], -1)))
    return np.array(x.table(), dtype=object).reshape((a.shape[1],) + b.shape[1:])


@dataclass(frozen=True)
class ModularExactContext(ExactContext):
    """:class:`~paper_repro.core.context.ExactContext` whose ``solve`` is :func:`solve_exact` (the same exact
    solution, faster when it is small and the matrix entries are large)."""

    def solve(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return solve_exact_array(a, b)
