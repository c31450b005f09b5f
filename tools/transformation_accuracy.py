"""Float accuracy of the transformation (Question 7.2) and of the product matrices against mp (issue 39, E1).

For each n and alpha: the float64 matrix (the inner route, without the refusal of ``transformation_matrix``) against
mp at ``DPS + 2 log10(1/alpha)`` digits (the cancellation of 'V_to_T' costs about 2 log10(1/alpha) digits), the
largest error relative to the largest entry; and ``(error / eps) alpha^2``, the constant of the bound
:func:`paper_repro.core.transformation.v_to_t_float_bound`.  Writes ``reports/transformation_accuracy.md`` (raw
floats: a report, not data).  Usage::

    .venv/bin/python tools/transformation_accuracy.py [--n 1 2 3 5 8 10]
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import mpmath
import numpy as np

from paper_repro.core.context import FloatContext, get_context
from paper_repro.core.half_angle_matrices import product_matrix
from paper_repro.core.transformation import (
    FLOAT_REL_GOAL,
    half_angle,
    transformation_in_context,
    v_to_t_float_alpha_min,
    v_to_t_float_bound,
)
from paper_repro.util.io import write_text

ALPHAS = (1e-300, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 1.0, 3.0, math.pi - 1e-12)
DPS = 30
EPS = 2.0**-52


def _float(n: int, alpha: float, direction: str) -> np.ndarray:
    ctx = FloatContext()
    s, c = half_angle(alpha, ctx)
    return transformation_in_context(n, s, c, ctx, direction)


def _mp(n: int, alpha: float, direction: str) -> np.ndarray:
    dps = DPS + int(2 * max(0.0, -math.log10(alpha)))
    ctx = get_context("mp", dps=dps)
    with mpmath.workdps(dps):
        s, c = half_angle(mpmath.mpf(alpha), ctx)
        m = transformation_in_context(n, s, c, ctx, direction)
        return np.array([[float(x) for x in row] for row in m])


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.abs(a - b).max() / np.abs(b).max())


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="*", default=[1, 2, 3, 5, 8])
    ap.add_argument("--out", default="reports")
    a = ap.parse_args(argv)
    rows, worst_ratio = [], 0.0
    for n in a.n:
        for alpha in ALPHAS:
            t0 = time.perf_counter()
            cells = []
            for direction in ("V_to_T", "T_to_V"):
                if direction == "V_to_T" and alpha < 1e-6:
                    cells.append("refused" if alpha < v_to_t_float_alpha_min(n) else "?")
                    continue
                with np.errstate(over="ignore", invalid="ignore"):
                    fl = _float(n, alpha, direction)
                if not np.isfinite(fl).all():  # transformation_matrix raises OverflowError here, naming the way out
                    cells.append("overflow: refused")
                    continue
                err = _rel(fl, _mp(n, alpha, direction))
                if direction == "V_to_T":
                    bound = v_to_t_float_bound(n, alpha)
                    worst_ratio = max(worst_ratio, err / bound)
                    state = "refused" if alpha < v_to_t_float_alpha_min(n) else "returned"
                    cells.append(f"{err:.1e} (bound {bound:.1e}, {state})")
                else:
                    cells.append(f"{err:.1e}")
            qf = product_matrix(n, "B_{2,2,0}", alpha)
            with mpmath.workdps(DPS):
                qm = product_matrix(n, "B_{2,2,0}", mpmath.mpf(alpha), "mp")
            cells.append(f"{_rel(qf, np.array([[float(x) for x in r] for r in qm])):.1e}")
            rows.append(f"| {n} | {alpha:.6g} | " + " | ".join(cells) + f" | {time.perf_counter() - t0:.1f} |")
            print(rows[-1], flush=True)
    md = ["# Float accuracy of the transformation and the product matrices (tools/transformation_accuracy.py)", "",
          f"Float64 against mp ({DPS} digits + 2 log10(1/alpha)); the largest error relative to the largest entry. "
          "'V_to_T' is refused in float where its measured bound (12 n + 8) eps (1 + 1/alpha^2) exceeds "
          f"{FLOAT_REL_GOAL:g} (below alpha = {v_to_t_float_alpha_min(1):.2g} at n = 1, "
          f"{v_to_t_float_alpha_min(10):.2g} at n = 10, {v_to_t_float_alpha_min(30):.2g} at n = 30); below 1e-6 "
          "the mp reference is not computed for it. Q is product_matrix(n, 'B_{2,2,0}').", "",
          "| n | alpha | V_to_T | T_to_V | Q | seconds |", "|---|---|---|---|---|---|", *rows, "",
          f"Largest error / bound of V_to_T: {worst_ratio:.2f} (must stay below 1).", ""]
    write_text(Path(a.out) / "transformation_accuracy.md", "\n".join(md))
    return 0 if worst_ratio < 1 else 1


if __name__ == "__main__":
    raise SystemExit(main())
