"""The de Casteljau LPs of docs/subdivision_for_all_n.md, section 10, with exact Farkas certificates.

For each n and tan(alpha/8) given, each variant of :mod:`paper_repro.theory.decasteljau` is tried: the float LP's
optimum is printed and, where it is negative, the exact certificate's value tr Y + sum z (< 0: infeasible at that
alpha, proven by the exact check) -- or that the rounded certificate failed the exact check (then nothing is claimed).
An optimum 0 means the float LP found no certificate (the system is feasible up to float rounding: evidence).

Run: ``python tools/decasteljau_certificates.py 2 3`` (seconds per LP at n <= 4; ``--grid`` adds the grid variant,
about 2 s at n = 2 and minutes at n = 3).
"""

from __future__ import annotations

import sys
import time

from flint import fmpq

from paper_repro.theory.decasteljau import certificate, grid_certificate

T8 = ["1/20", "1/5", "2/5"]


def main(args: list[str]) -> None:
    grid = "--grid" in args
    for n in [int(x) for x in args if not x.startswith("--")] or [2, 3]:
        for t8s in T8:
            t8 = fmpq(*map(int, t8s.split("/")))
            for variant in ("coefficients", "cone"):
                t0 = time.perf_counter()
                cert, opt, _ = certificate(n, t8, variant)
                verdict = "no certificate" if cert is None else f"exact certificate, value {float(cert.value):.6g}"
                print(f"n = {n}, tan(alpha/8) = {t8s}, {variant}: float optimum {opt:.6g}; {verdict} "
                      f"({time.perf_counter() - t0:.1f} s)", flush=True)
            if grid:
                t0 = time.perf_counter()
                gcert, gopt = grid_certificate(n, t8, 8)
                verdict = ("no certificate" if gcert is None else
                           f"exact certificate, value {float(gcert.value):.6g}, {gcert.points} grid points")
                print(f"n = {n}, tan(alpha/8) = {t8s}, grid: float optimum {gopt:.6g}; {verdict} "
                      f"({time.perf_counter() - t0:.1f} s)", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
