"""Time :func:`paper_repro.surfaces.tessellation.tessellate` on the torus piece of Section 6 (Example exmp:torus,
radii 2 and 1, alpha = pi/2; the lower triangle of the square [0, pi/2]^2) and check each mesh densely.

    PYTHONPATH=$PWD python tools/tessellation_bench.py [--tols 1e-3,1e-4,1e-5,1e-6] [--repeat 3] [--no-check]
        [--check-steps K] [--ball-tol 1e-4]

Per tolerance: vertices, triangles, leaves, depth, fans, the bound, the measured deviation (barycentric grid of 4
steps, 15 points, in every triangle, 3 steps, 10 points, above 1 M triangles unless --check-steps K is given;
skipped with --no-check), the wall and CPU times (all threads) of
``repeat`` warm calls (the first call of the process, which builds the subdivision matrices, is reported
separately), and the wall time per million vertices.  Then one row of the ball route (``arith='ball'``, the bound
proven including every rounding) at ``--ball-tol`` (default 1e-4; 0 skips it).
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

from paper_repro.surfaces.models import torus_pieces
from paper_repro.surfaces.tessellation import tessellate
from paper_repro.util.io import write_text


def deviation(mesh, patch, k: int = 4) -> float:
    """max |s(x) - mesh(x)| over a barycentric grid of k steps in every triangle."""
    bary = np.array([(i / k, j / k, 1 - (i + j) / k) for i in range(k + 1) for j in range(k + 1 - i)])
    worst = 0.0
    for lo in range(0, len(mesh.triangles), 200_000):
        tri = mesh.triangles[lo:lo + 200_000]
        par = np.einsum("sk,fkd->fsd", bary, mesh.params[tri]).reshape(-1, 3)
        lin = np.einsum("sk,fkd->fsd", bary, mesh.points[tri]).reshape(-1, mesh.points.shape[1])
        worst = max(worst, float(np.linalg.norm(patch(par) - lin, axis=1).max()))
    return worst


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tols", default="1e-3,1e-4,1e-5,1e-6")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-check", action="store_true")
    ap.add_argument("--check-steps", type=int, default=None,
                    help="barycentric steps of the deviation check in every triangle, for every tol (4: 15 points)")
    ap.add_argument("--ball-tol", type=float, default=1e-4,
                    help="one row of the ball route (arith='ball': the bound proven with every rounding) at this tol; "
                         "0 skips it (1e-4: 13 041 vertices, about 1 s)")
    ap.add_argument("--out", help="also write the table as markdown to this file (e.g. reports/tessellation_bench.md)")
    args = ap.parse_args(argv)
    rows = []
    piece = torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])[0].patch
    net = np.asarray(piece.net)
    load = os.getloadavg()
    t0 = time.perf_counter()
    tessellate(net, 2, np.pi / 2, 1e-3)
    first = time.perf_counter() - t0
    print(f"first call (subdivision matrices, kernels): {first:.2f} s")
    for tol in (float(x) for x in args.tols.split(",")):
        times, cpu = [], []
        for _ in range(args.repeat):
            t, c = time.perf_counter(), time.process_time()
            mesh = tessellate(net, 2, np.pi / 2, tol)
            times.append(time.perf_counter() - t)
            cpu.append(time.process_time() - c)
        big = len(mesh.triangles) > 1_000_000
        steps = args.check_steps or (3 if big else 4)
        dev = float("nan") if args.no_check else deviation(mesh, piece, k=steps)
        best = min(times)
        print(f"tol {tol:.0e}: {len(mesh.points)} vertices, {len(mesh.triangles)} triangles, {mesh.leaves} leaves, "
              f"depth {mesh.depth}, {mesh.fans} fans, bound {mesh.bound:.3e}, deviation {dev:.3e} "
              f"({(steps + 1) * (steps + 2) // 2} points per triangle), ratio {dev / mesh.bound:.3f}; "
              f"wall {', '.join(f'{x:.2f}' for x in times)} s, CPU {', '.join(f'{x:.2f}' for x in cpu)} s; "
              f"{best / len(mesh.points) * 1e6:.2f} s wall per M vertices")
        rows.append(f"| {tol:.0e} | {len(mesh.points)} | {len(mesh.triangles)} | {mesh.depth} | {mesh.bound:.2e} | "
                    f"{dev:.2e} | {'yes' if dev <= tol else 'NO'} | {best:.2f} | {min(cpu):.2f} |")
    if args.ball_tol > 0:
        tol = args.ball_tol
        tessellate(net, 2, np.pi / 2, 1e-2, arith="ball")
        t, c = time.perf_counter(), time.process_time()
        mesh = tessellate(net, 2, np.pi / 2, tol, arith="ball")
        wall, cpu = time.perf_counter() - t, time.process_time() - c
        dev = float("nan") if args.no_check else deviation(mesh, piece, k=args.check_steps or 4)
        print(f"ball, tol {tol:.0e}: {len(mesh.points)} vertices, {len(mesh.triangles)} triangles, bound "
              f"{mesh.bound:.7e} (proven), deviation {dev:.3e}; wall {wall:.2f} s, CPU {cpu:.2f} s (one warm call)")
        rows.append(f"| {tol:.0e} (ball) | {len(mesh.points)} | {len(mesh.triangles)} | {mesh.depth} | "
                    f"{mesh.bound:.2e} | {dev:.2e} | {'yes' if dev <= tol else 'NO'} | {wall:.2f} | {cpu:.2f} |")
    if args.out:
        write_text(args.out, "\n".join([
            "# Adaptive tessellation of the torus piece (tools/tessellation_bench.py, run by `make bench`)", "",
            "Example exmp:torus (radii 2 and 1), alpha = pi/2, order n = 2; `paper_repro.tessellate(net, 2, pi/2, "
            "tol)`. *deviation*: max |s - mesh| on a barycentric grid in every triangle ("
            + (f"{args.check_steps} steps" if args.check_steps else "3 steps above 1 M triangles, else 4")
            + f"); times: best of {args.repeat} warm calls (wall) and CPU of all threads. Machine: "
            f"{os.cpu_count()} CPUs, load average at start {load[0]:.2f}. The first call of the process (the "
            f"subdivision matrices, the kernels) took {first:.2f} s. A row marked (ball) is `arith='ball'` (the "
            "bound proven including every rounding; one warm call). Measurements, not data.", "",
            "| tol | vertices | triangles | depth | bound | deviation | within tol | wall (s) | CPU (s) |",
            "|---|---|---|---|---|---|---|---|---|", *rows, ""]))
        print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
