"""Derivative and normal speed of the float path relative to a point evaluation (issue 21), one short run:
``Patch(n, pi/2, net)(pts)``, ``.derivative(pts, 'u')`` and ``.normals(pts)`` at the same points, best of
``--repeat`` interleaved runs, with the threads of ``PAPER_REPRO_THREADS`` (set it to 1 for one thread).

    PAPER_REPRO_THREADS=1 python tools/derivative_speed.py [--points 200000] [--repeat 5] [--n 1 3 6 10]

Timings are machine- and load-dependent: they go to stdout, never to data/.
"""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np

from paper_repro.core.labels import delta
from paper_repro.surfaces.patch import Patch


def sample(alpha: float, count: int, seed: int) -> np.ndarray:
    """``count`` uniform points of Omega^alpha (seeded)."""
    rng = np.random.default_rng(seed)
    x, y = rng.random(count), rng.random(count)
    flip = x + y > 1
    x[flip], y[flip] = 1 - x[flip], 1 - y[flip]
    return alpha * np.column_stack([x, y, 1 - x - y])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=200_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--n", type=int, nargs="+", default=[1, 3, 6, 10])
    args = ap.parse_args()
    alpha = math.pi / 2
    pts = sample(alpha, args.points, seed=1)
    threads = os.environ.get("PAPER_REPRO_THREADS", "")
    print(f"points {args.points:,}, best of {args.repeat}, PAPER_REPRO_THREADS={threads!r}")
    print("| n | point (s) | derivative 'u' (s) | normals (s) | derivative / point | normals / point |")
    print("|---|---|---|---|---|---|")
    for n in args.n:
        patch = Patch(n, alpha, np.random.default_rng(n).normal(size=(delta(n), 3)))
        calls = {"point": lambda p=patch: p(pts), "der": lambda p=patch: p.derivative(pts, "u"),
                 "nrm": lambda p=patch: p.normals(pts)}
        for f in calls.values():
            f()
        best = dict.fromkeys(calls, math.inf)
        for _ in range(args.repeat):
            for k, f in calls.items():
                t0 = time.perf_counter()
                f()
                best[k] = min(best[k], time.perf_counter() - t0)
        print(f"| {n} | {best['point']:.4f} | {best['der']:.4f} | {best['nrm']:.4f} | "
              f"{best['der'] / best['point']:.2f} | {best['nrm'] / best['point']:.2f} |", flush=True)


if __name__ == "__main__":
    main()
