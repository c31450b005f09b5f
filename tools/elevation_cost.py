"""Measured cost model of order elevation (paper_repro.core.elevation): bits lost and time of the certified ball
solve for n = 1..10 at alpha = 1, 1e-3, 1e-9 (ALPHA_FLAT) and pi - 1e-5.

Writes ``reports/elevation_cost.md`` (timings: a report, not data).  Usage::

    .venv/bin/python tools/elevation_cost.py [--n-max 10]

The start precision of :func:`~paper_repro.core.elevation.start_precision` is checked against the bits lost: a
row with "no" means the first solve was not certified and the schedule needed a second one.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time
from pathlib import Path

from paper_repro.core.elevation import certified_solve, start_precision
from paper_repro.core.labels import delta

ALPHAS = (("1", 1.0), ("1e-3", 1e-3), ("1e-9", 1e-9), ("pi - 1e-5", math.pi - 1e-5))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n-max", type=int, default=10)
    ap.add_argument("--out", default="reports/elevation_cost.md")
    args = ap.parse_args()
    rows = []
    for n in range(1, args.n_max + 1):
        for name, a in ALPHAS:
            first, t0 = start_precision(n, a), time.perf_counter()
            _, prec, lost, solves = certified_solve(n, a, child=False)
            dt = time.perf_counter() - t0
            rows.append((n, delta(n + 1), name, first, lost, solves, dt))
            print(f"n = {n:2d}  alpha = {name:9s}  start {first:5d} bits  lost {lost:5d}  solves {solves}  "
                  f"{dt:7.2f} s", flush=True)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = ["# Order elevation: cost of the certified ball solve", "",
             f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, load average "
             f"{load:.2f} at the end; command: `.venv/bin/python tools/elevation_cost.py`.", "",
             "One cold call of `elevation_matrix(n, alpha)` (cache empty): evaluation of both systems at "
             "delta_{n+1} points in ball arithmetic and the preconditioned solve.  'lost' is the start precision "
             "minus the bits certified; 'solves' = 1 means the start precision was enough.", "",
             "| n | delta_{n+1} | alpha | start bits | bits lost | solves | seconds |",
             "| ---: | ---: | --- | ---: | ---: | ---: | ---: |"]
    lines += [f"| {n} | {d} | {name} | {p} | {lost} | {s} | {dt:.1f} |" for n, d, name, p, lost, s, dt in rows]
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(args.out).with_suffix(".tmp")
    tmp.write_text("\n".join(lines) + "\n")
    tmp.replace(args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
