"""Float accuracy and cold cost of ``subdivision_matrices`` against 30-digit mp (issue 38, item 1).

Run: ``python tools/subdivision_accuracy.py [n ...]`` (default 2 4 6 8 10; n = 10 takes minutes on a loaded
machine).  Prints, per n and alpha in {1e-3, 1, pi - 1e-3}: the cold float time, the mp time and the largest
|float - mp| over the four matrices.  (Both are certified ball computations; the mp one at 30 digits.)
"""

from __future__ import annotations

import math
import sys
import time

import mpmath

from paper_repro.core.subdivision import _float_matrices, subdivision_matrices


def measure(n: int, alpha: float) -> tuple[float, float, float]:
    _float_matrices.cache_clear()
    t0 = time.perf_counter()
    flo = subdivision_matrices(n, alpha)
    t_float = time.perf_counter() - t0
    with mpmath.workdps(30):
        t0 = time.perf_counter()
        mp = subdivision_matrices(n, mpmath.mpf(alpha), "mp", dps=30)
        t_mp = time.perf_counter() - t0
        err = max(max(abs(mpmath.mpf(float(x)) - y) for x, y in zip(f.reshape(-1), m.reshape(-1)))
                  for f, m in zip(flo, mp))
    return t_float, t_mp, float(err)


if __name__ == "__main__":
    orders = [int(x) for x in sys.argv[1:]] or [2, 4, 6, 8, 10]
    for n in orders:
        for alpha in (1e-3, 1.0, math.pi - 1e-3):
            tf, tm, err = measure(n, alpha)
            print(f"n={n} alpha={alpha:.4g}: float cold {tf:.2f} s, mp30 {tm:.2f} s, max|float - mp| = {err:.2e}",
                  flush=True)
