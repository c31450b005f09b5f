"""Matrix products summed in a fixed order, so that their bits are the same on every CPU (issue 31, item 1).

BLAS (OpenBLAS's DYNAMIC_ARCH kernels) sums a product in an order that depends on the CPU's kernel (Haswell,
SkylakeX, Sandybridge, ...), on the memory layout of the operands and on its threads; numpy's elementwise
multiply and add are single IEEE operations, the same on every CPU.  :func:`ordered_matmul` is used wherever a
result is promised bit-identical across CPUs (README, "Same bits on every CPU"): order elevation, the Bezier
limit, boundary curves and the float context's products.  ``tools/cpu_bits.py`` (``make test-cpus``) checks it
under every OpenBLAS kernel this machine can be forced to.
"""

from __future__ import annotations

import numpy as np


def ordered_matmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a @ b`` for a ``(M, K)`` matrix and a ``(K, d)`` array, summed in the fixed order k = 0, 1, ..., K-1 by
    elementwise products and sums (each one IEEE-rounded; numpy fuses nothing), so the bits do not depend on the
    memory layout of either operand, on BLAS's kernel (the CPU) or on its threads.  For the small products of
    order elevation and basis transformation (``K`` = delta_n), where BLAS would sum in a CPU- and
    layout-dependent order (issue 31: SkylakeX gave other bits for a Fortran-ordered net).

    >>> a = np.array([[0.1, 0.2, 0.7], [1.0, 0.0, 0.0]])
    >>> b = np.asfortranarray(np.arange(6.0).reshape(3, 2))
    >>> ordered_matmul(a, b).tolist() == ordered_matmul(a, np.ascontiguousarray(b)).tolist()
    True
    >>> bool(np.allclose(ordered_matmul(a, b), a @ b))
    True
    """
    a = np.ascontiguousarray(a, dtype=float)
    b = np.ascontiguousarray(b, dtype=float)
    if a.ndim != 2 or b.ndim != 2 or a.shape[1] != b.shape[0]:
        raise ValueError(f"ordered_matmul: shapes {a.shape} and {b.shape} do not chain")
    out = np.zeros((a.shape[0], b.shape[1]))
    col = np.empty_like(out)
    for k in range(a.shape[1]):
        np.multiply(a[:, k: k + 1], b[k: k + 1, :], out=col)
        out += col
    return out
