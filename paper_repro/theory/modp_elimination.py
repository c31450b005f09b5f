"""Exact full-rank test over F_p by recursive Gaussian elimination whose matrix products run in float64 BLAS.

The collocation matrices of claim ``linear_independence`` (Theorem joint_systems_linear_independence) are square,
up to 4921 x 4921 (n = 40), with entries modulo ``p = 2^31 - 1``. The python-flint build used here multiplies
``nmod_mat`` without BLAS: its rank at n = 30 (2791 x 2791) costs about 3.4 s, plus 2 s to build the matrix from a
Python list; the same elimination here costs a fraction of that, because its O(N^3) part is ``float64`` matrix
products (``numpy`` / BLAS) that are **exact**:

* every entry is an integer in ``[0, p)``, ``p < 2^31``;
* a product ``L @ U`` (inner dimension ``k <= MAX_INNER = 2^18``) is computed from the 16-bit halves
  ``L = L1 2^16 + L0``, ``U = U1 2^16 + U0`` (``0 <= L0, U0 < 2^16``, ``0 <= L1, U1 < 2^15``) as the three float64
  products ``L1 @ U1``, ``L0 @ U0`` and ``(L1 + L0) @ (U1 + U0)`` (Karatsuba: the cross term ``L1 U0 + L0 U1`` is
  the last minus the first two, in int64).  Each is a sum of ``k`` non-negative integer terms below
  ``(2^15 + 2^16)^2 < 2^34``, so every partial sum -- in whatever order BLAS adds, with or without fused
  multiply-add -- is an integer below ``k 2^34 <= 2^52 < 2^53`` (:data:`EXACT_BOUND`), exactly representable in
  float64: every floating-point operation is exact and each product is the exact integer product (converted to
  int64 exactly), reduced modulo p in int64.  *Assumed*: a classical IEEE binary64 GEMM (OpenBLAS here), whose
  partial sums are sums of the products; a Strassen-type product adds and subtracts blocks, and its intermediates
  could pass 2^53 near ``MAX_INNER`` (the inner dimensions used here are at most about 2500, below 2^12);
* every update reduces modulo p again, so every entry stays an integer in ``[0, p)`` throughout, not only in the
  input;
* everything else (pivot search, multipliers, the small triangular solves) is int64 arithmetic on values below
  ``2^63``.

So the elimination is Gaussian elimination over F_p (recursive LU with row pivoting, as flint's own
``nmod_mat_lu_recursive``) carried out exactly.  It returns ``N`` only when it found N non-zero pivots: then
``P A = L U`` with ``L`` unit lower triangular and ``U`` upper triangular with a non-zero diagonal, so
``det A != 0`` in F_p, and the rank over F_p (a lower bound of the rank over Q) is ``N``.  If a column has no
non-zero pivot the matrix is singular modulo p, and its exact rank is taken from flint
(:meth:`paper_repro.core.context.ModpContext.rank`), which also serves non-square matrices.

>>> import numpy as np
>>> modp_rank_blas(np.array([[1, 2], [3, 4]]), 7), modp_rank_blas(np.array([[1, 2], [2, 4]]), 7)
(2, 1)
"""

from __future__ import annotations

import numpy as np

from paper_repro.core.context import ModpContext
from paper_repro.core.fast import single_threaded_blas

#: Largest inner dimension of one float64 product.
MAX_INNER = 2**18
#: Largest value any partial sum of a float64 product can reach: ``MAX_INNER (2^15 - 1 + 2^16 - 1)^2``, below 2^53.
EXACT_BOUND = MAX_INNER * (2**15 - 1 + 2**16 - 1) ** 2
#: Column blocks of at most this width are factored column by column in int64 (row blocks: by their inverse).
BASE = 32


def _products(left: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(L1 @ U1, L1 @ U0 + L0 @ U1, L0 @ U0)`` as exact int64 arrays (module docstring: three float64 products)."""
    if left.shape[1] > MAX_INNER:
        raise ValueError(f"inner dimension {left.shape[1]} > {MAX_INNER}: the float64 products would not be exact")
    l1, l0 = (left >> 16).astype(np.float64), (left & 0xFFFF).astype(np.float64)
    r1, r0 = (right >> 16).astype(np.float64), (right & 0xFFFF).astype(np.float64)
    high = (l1 @ r1).astype(np.int64)
    low = (l0 @ r0).astype(np.int64)
    l1 += l0
    r1 += r0
    cross = (l1 @ r1).astype(np.int64)
    cross -= high
    cross -= low  # Karatsuba: L1 U0 + L0 U1
    return high, cross, low


def mulmod(left: np.ndarray, right: np.ndarray, p: int) -> np.ndarray:
    """``(left @ right) mod p`` exactly, for int64 arrays with entries in ``[0, p)``, ``p < 2^31`` (module
    docstring: three float64 products of 16-bit halves).

    >>> import numpy as np
    >>> a = np.array([[2**31 - 2, 5], [7, 2**31 - 3]])
    >>> bool((mulmod(a, a, 2**31 - 1) == (a.astype(object).dot(a.astype(object)) % (2**31 - 1))).all())
    True
    """
    high, cross, low = _products(left, right)
    return ((high % p) * (2**32 % p) + (cross % p) * (2**16 % p) + low) % p  # < 2^62 + 2^47 + 2^52 < 2^63


def _subtract_product(target: np.ndarray, left: np.ndarray, right: np.ndarray, p: int) -> None:
    """``target = (target - left @ right) mod p`` in place (``target`` a view of the matrix, entries in [0, p))."""
    high, cross, low = _products(left, right)
    high %= p
    high *= 2**32 % p
    cross %= p
    cross *= 2**16 % p
    high += cross
    high += low  # (L @ U) mod p + a multiple of p, below 2^62 + 2^47 + 2^52 < 2^63
    np.subtract(target, high, out=high)  # > -2^63
    np.remainder(high, p, out=target)


def modp_rank_blas(a: np.ndarray, p: int) -> int:
    """Exact rank over F_p of an integer matrix (entries taken modulo ``p``; ``2 < p < 2^31`` prime).

    A square matrix is eliminated here (module docstring); a non-square or singular one gets its rank from flint.
    """
    ctx = ModpContext(p=p)
    src = np.asarray(a)
    if src.ndim != 2:
        raise ValueError(f"a must be a 2-D integer array, got shape {src.shape}")
    n = src.shape[0]
    if n != src.shape[1] or n == 0:
        return ctx.rank(np.asarray(src, dtype=np.int64) % p)
    work = np.array(src, dtype=np.int64) % p  # a copy: eliminated in place
    with single_threaded_blas():
        if _factor(work, 0, n, p):
            return n
    return ctx.rank(np.asarray(src, dtype=np.int64) % p)


def _factor(a: np.ndarray, k0: int, k1: int, p: int) -> bool:
    """LU with row pivoting of the columns ``k0:k1`` of ``a`` (rows ``k0:``; row exchanges over the full width),
    in place; false as soon as a column has no non-zero pivot."""
    if k1 - k0 <= BASE:
        return _factor_panel(a, k0, k1, p)
    mid = k0 + (k1 - k0) // 2
    if not _factor(a, k0, mid, p):
        return False
    _solve_lower(a, k0, mid, mid, k1, p)
    _subtract_product(a[mid:, mid:k1], a[mid:, k0:mid], a[k0:mid, mid:k1], p)
    return _factor(a, mid, k1, p)


def _factor_panel(a: np.ndarray, k0: int, k1: int, p: int) -> bool:
    """:func:`_factor` of a narrow panel, column by column, on a column-major copy (its columns contiguous); the row
    exchanges are applied to the full rows of ``a`` as they are found."""
    panel = np.asfortranarray(a[k0:, k0:k1])
    for j in range(k1 - k0):
        nz = np.flatnonzero(panel[j:, j])
        if nz.size == 0:
            return False
        piv = j + int(nz[0])
        if piv != j:
            panel[[j, piv]] = panel[[piv, j]]
            a[[k0 + j, k0 + piv]] = a[[k0 + piv, k0 + j]]
        col = panel[j + 1:, j] * pow(int(panel[j, j]), -1, p) % p
        panel[j + 1:, j] = col
        for c in range(j + 1, k1 - k0):
            panel[j + 1:, c] = (panel[j + 1:, c] - col * panel[j, c] % p) % p
    a[k0:, k0:k1] = panel
    return True


def _solve_lower(a: np.ndarray, r0: int, r1: int, c0: int, c1: int, p: int) -> None:
    """``a[r0:r1, c0:c1] = L^-1 a[r0:r1, c0:c1]`` for the unit lower triangular ``L`` stored in ``a[r0:r1, r0:r1]``."""
    if r1 - r0 <= BASE:  # L^-1 by the row operations of the substitution applied to I (small), then one product
        inv = np.eye(r1 - r0, dtype=np.int64)
        for j in range(r1 - r0 - 1):
            inv[j + 1:] = (inv[j + 1:] - a[r0 + j + 1:r1, r0 + j, None] * inv[j] % p) % p
        a[r0:r1, c0:c1] = mulmod(inv, a[r0:r1, c0:c1], p)
        return
    mid = r0 + (r1 - r0) // 2
    _solve_lower(a, r0, mid, c0, c1, p)
    _subtract_product(a[mid:r1, c0:c1], a[mid:r1, r0:mid], a[r0:mid, c0:c1], p)
    _solve_lower(a, mid, r1, c0, c1, p)
