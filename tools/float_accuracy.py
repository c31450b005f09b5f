"""Accuracy of the float path against mp at 40 digits: points, derivatives and normals (issue 21).

For n = 1, 3, 6, 10 and alpha from 1e-300 to pi - 1e-3: 16 points (the 3 corners, 3 points on the edges, 10 seeded
interior points), 2 nets.
Points relative to the net's largest coordinate; derivatives (u and v) relative to the largest derivative
component at the points; normals: the largest difference of the unit vectors (where both are defined).
Writes ``reports/float_accuracy.md`` (a report: raw floats, not data).  Usage::

    .venv/bin/python tools/float_accuracy.py
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import numpy as np

from paper_repro.core.domain import sample_points
from paper_repro.core.labels import delta
from paper_repro.surfaces.patch import Patch

NS = (1, 3, 6, 10)
ALPHAS = (1e-300, 1e-9, 1e-3, 1.0, math.pi - 1e-3)
DPS = 40


def _mp_points(pts: np.ndarray, alpha: float) -> np.ndarray:
    """The float points with w recomputed in mp so that u + v + w = alpha exactly."""
    q = np.array([[mpmath.mpf(float(x)) for x in row] for row in pts], dtype=object)
    q[:, 2] = mpmath.mpf(alpha) - q[:, 0] - q[:, 1]
    return q


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=1)[:, None]


def errors(n: int, alpha: float, seed: int) -> tuple[float, float, float]:
    p = Patch(n, alpha, np.random.default_rng(seed).normal(size=(delta(n), 3)))
    bary = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [0.5, 0.5, 0], [0, 0.25, 0.75], [0.6, 0, 0.4]])
    pts = np.vstack([alpha * bary, sample_points(alpha, 10, seed=seed)])  # 3 corners, 3 edge points, 10 inside
    with mpmath.workdps(DPS):
        ref_pts = _mp_points(pts, alpha)
        val = np.array(p(ref_pts, arith="mp", dps=DPS), dtype=float)
        du = np.array(p.derivative(ref_pts, "u", arith="mp", dps=DPS), dtype=float)
        dv = np.array(p.derivative(ref_pts, "v", arith="mp", dps=DPS), dtype=float)
    ev = np.abs(p(pts) - val).max() / np.abs(p.net).max()
    der = max(np.abs(p.derivative(pts, "u") - du).max() / np.abs(du).max(),
              np.abs(p.derivative(pts, "v") - dv).max() / np.abs(dv).max())
    ref_n = _unit(np.cross(du / np.abs(du).max(), dv / np.abs(dv).max()))  # scaled: 1/alpha^2 would overflow
    got_n = p.normals(pts)
    ok = np.all(np.isfinite(got_n), axis=1) & np.all(np.isfinite(ref_n), axis=1)
    nrm = float(np.abs(got_n[ok] - ref_n[ok]).max()) if ok.any() else 0.0
    return float(ev), float(der), nrm


def main() -> None:
    rows = ["# Float path against mp (40 digits): points, derivatives, normals (tools/float_accuracy.py)", "",
            "16 points per case (the 3 corners, 3 points on the edges, 10 seeded interior points), 2 nets (seeds 0, 1); the "
            "largest error over both; normals where both are defined (NaN at a degenerate corner).",
            "", "| n | alpha | points / max net | derivatives / max derivative | normals (unit vectors) |",
            "|---|---|---|---|---|"]
    worst = [0.0, 0.0, 0.0]
    for n in NS:
        for alpha in ALPHAS:
            e = [max(x) for x in zip(*(errors(n, alpha, seed) for seed in (0, 1)))]
            worst = [max(a, b) for a, b in zip(worst, e)]
            rows.append(f"| {n} | {alpha:.6g} | {e[0]:.1e} | {e[1]:.1e} | {e[2]:.1e} |")
            print(rows[-1], flush=True)
    rows += ["", f"Largest: points {worst[0]:.1e}, derivatives {worst[1]:.1e}, normals {worst[2]:.1e}.", ""]
    out = Path("reports/float_accuracy.md")
    out.write_text("\n".join(rows))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
