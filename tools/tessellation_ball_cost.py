"""Cost of the tessellator's ball route against the float route (docs/tessellation.md, "Rigorous route (ball
arithmetic)"): the torus piece of Section 6 (Example exmp:torus, radii 2 and 1, alpha = pi/2, order 2), elevated
(:func:`~paper_repro.core.elevation.elevate`) to the orders 3..6; for n = 1 a seeded random net (the torus piece
has order 2).

    PYTHONPATH=$PWD python tools/tessellation_ball_cost.py [--orders 1,2,3,4,5,6] [--tols 1e-2,1e-3,1e-4]

Per order and tol: vertices, leaves, depth, the float and ball wall and CPU (process) times (one warm call each,
after a first call that builds the matrices), the ball CPU time per vertex and the CPU ratio ball / float, both
bounds, and whether the two routes give the same triangulation.  Measurements, not data.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

from paper_repro.core.elevation import elevate
from paper_repro.core.labels import delta
from paper_repro.surfaces.models import torus_pieces
from paper_repro.surfaces.tessellation import tessellate


def net_of_order(n: int) -> np.ndarray:
    """The torus piece's net elevated to order n (n >= 2); a seeded random net for n = 1."""
    if n == 1:
        return np.random.default_rng(0).random((delta(1), 3))
    net = np.asarray(torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])[0].patch.net)
    return net if n == 2 else elevate(net, 2, np.pi / 2, to=n)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--orders", default="1,2,3,4,5,6")
    ap.add_argument("--tols", default="1e-2,1e-3,1e-4")
    args = ap.parse_args(argv)
    alpha = np.pi / 2
    print("| n | tol | vertices | leaves, depth | float wall, CPU (s) | ball wall, CPU (s) | ball CPU us/vertex | "
          "ball/float CPU | float bound | ball bound | same mesh |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n in (int(x) for x in args.orders.split(",")):
        net = net_of_order(n)
        tessellate(net, n, alpha, 1e-2)
        tessellate(net, n, alpha, 1e-2, arith="ball")
        for tol in (float(x) for x in args.tols.split(",")):
            t, c = time.perf_counter(), time.process_time()
            flt = tessellate(net, n, alpha, tol)
            tf, cf = time.perf_counter() - t, time.process_time() - c
            t, c = time.perf_counter(), time.process_time()
            ball = tessellate(net, n, alpha, tol, arith="ball")
            tb, cb = time.perf_counter() - t, time.process_time() - c
            same = np.array_equal(flt.triangles, ball.triangles)
            print(f"| {n} | {tol:.0e} | {len(ball.points)} | {ball.leaves}, {ball.depth} | {tf:.3f}, {cf:.3f} | "
                  f"{tb:.2f}, {cb:.2f} | {cb / len(ball.points) * 1e6:.0f} | {cb / max(cf, 1e-3):.0f} | "
                  f"{flt.bound:.7e} | {ball.bound:.7e} | "
                  f"{'yes' if same else 'no'} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
