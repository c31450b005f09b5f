"""Accuracy and cost of the closed form of the edge coefficients (paper_repro.surfaces.joins.edge_derivatives).

    PYTHONPATH=$PWD python tools/joins_accuracy.py [--n-max 40] [--high 50,60,80,100] [--dps 40] [--json out.json]

Accuracy: float64 against mp (``--dps`` digits) for every n up to ``--n-max`` on every edge, and at the orders
``--high`` on edge 'v' (the three edges' matrices are the same expansions with the columns relabelled), alpha in
ALPHAS: max |D_float - D_mp| / max |D_mp| (T likewise); the C1/G1 builders likewise.  Cost: one cold call (caches
cleared) per arithmetic at n in SIZES (exact at tan(alpha/4) = 1/3): the numbers behind joins.MAX_N_JOINS.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from paper_repro.core.domain import rational_alpha
from paper_repro.surfaces import joins

ALPHAS = (1e-3, 0.1, 1.0, 2.0, 3.0, math.pi - 1e-3)
SIZES = (10, 20, 40, 60, 80, 100)


def accuracy(ns, dps: int, edges=joins.EDGES) -> dict:
    out = {}
    for n in ns:
        worst = 0.0
        for alpha in ALPHAS:
            for edge in edges:
                fl = joins.edge_derivatives(n, alpha, edge, "float")
                mp = joins.edge_derivatives(n, alpha, edge, "mp", dps=dps)
                for f, m in zip(fl, mp):
                    m = m.astype(float)
                    worst = max(worst, float(np.abs(f - m).max() / np.abs(m).max()))
        out[n] = worst
        print(f"n = {n:2d}: max relative deviation of float from mp over alpha and edges {worst:.2e}", flush=True)
    return out


def builder_accuracy(ns, dps: int) -> dict:
    """The C1 and G1 (lam, mu) = (1.6, 0.4) neighbours' second rows in float64 against mp at the same float alpha,
    relative to the largest control point, on a seeded random net (edge 'w')."""
    out = {}
    for n in ns:
        net = np.random.default_rng(n).normal(size=(joins.delta(n), 3))
        worst = 0.0
        for alpha in ALPHAS:
            for lam, mu in ((1, 0), (1.6, 0.4)):
                fl = joins.g1_neighbour_row(net, n, alpha, "w", lam=lam, mu=mu)
                mp = joins.g1_neighbour_row(net, n, alpha, "w", lam=lam, mu=mu, arith="mp", dps=dps).astype(float)
                worst = max(worst, float(np.abs(fl - mp).max() / np.abs(mp).max()))
        out[n] = worst
        print(f"n = {n:2d}: builders, max relative deviation of float from mp {worst:.2e}", flush=True)
    return out


def cost(sizes) -> dict:
    out = {}
    for n in sizes:
        row = {}
        for arith, alpha in (("float", 1.0), ("mp", 1.0), ("exact", rational_alpha("1/3"))):
            joins._cached.cache_clear()
            t0 = time.process_time()
            joins.edge_derivatives(n, alpha, "v", arith, dps=50)
            row[arith] = round(time.process_time() - t0, 3)
        out[n] = row
        print(f"n = {n:2d}: cold CPU seconds {row}", flush=True)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n-max", type=int, default=40)
    ap.add_argument("--high", default="50,60,80,100")
    ap.add_argument("--dps", type=int, default=40)
    ap.add_argument("--sizes", default=",".join(map(str, SIZES)))
    ap.add_argument("--json")
    args = ap.parse_args(argv)
    res = {"cost": cost([int(x) for x in args.sizes.split(",")]),
           "accuracy": accuracy(range(1, args.n_max + 1), args.dps),
           "accuracy_high_edge_v": accuracy([int(x) for x in args.high.split(",") if x], args.dps, ("v",)),
           "builders": builder_accuracy([*range(1, 11), 20, 40], args.dps)}
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(res, fh, indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
