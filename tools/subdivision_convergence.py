"""Measure how fast control nets approach their patch under repeated midpoint subdivision and under repeated order
elevation (docs/tessellation.md §4-§5).

    PYTHONPATH=$PWD python tools/subdivision_convergence.py [--out reports/subdivision_convergence.md] [--quick]

Subdivision: for a seeded random net (3 coordinates, standard normal entries) of order n and parameter alpha, the
4^k sub-nets of depth k (parameter h = alpha / 2^k) and, for every control point Q_f of every sub-net, the distance
|Q_f - s(x_f)| to the patch at the point's position x_f (the node of :func:`paper_repro.core.layout.barycentric`
in the sub-triangle, mapped to Omega^alpha).  Reported: the maximum d_k over all points, over the boundary points
(level j = 0), at the centre and over the other (inner) points, the component normal to the surface over the
inner points and the centre (|(Q_f - s(x_f)) . N(x_f)|: the distance to the surface as a set up to O(h^2)), the
observed order log2(d_{k-1} / d_k), the constant d_k / (h^2 M) of the boundary points with M the proven
second-derivative bound of the whole patch
(:func:`paper_repro.surfaces.tessellation.second_derivative_bound`), and the ratio of the tessellator's bound
over the depth-k leaves to the sampled maximum of the second derivative.

Elevation: the net elevated from order n to m (:func:`paper_repro.core.elevation.elevate`), e_m = max_f |P_f -
s(x_f)| over the positions of order m, and the fitted exponent p of e_m ~ C m^-p over the last half of the range
(also for the component along the surface normal).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from paper_repro.core.elevation import elevate
from paper_repro.core.labels import delta, united_system
from paper_repro.core.layout import barycentric
from paper_repro.core.subdivision import subdivision_matrices
from paper_repro.figures.subdivision_fig import subdivision_levels
from paper_repro.surfaces.patch import Patch
from paper_repro.surfaces.tessellation import second_derivative_bound, second_derivative_nets


def positions(n: int) -> np.ndarray:
    """Barycentric nodes of the members of order n, rows in the net's order."""
    return np.array([barycentric(lab) for lab in united_system(n)])


def subdivision_rates(n: int, alpha: float, depth: int, seed: int = 0) -> list[dict]:
    """One row per depth k = 0..depth (see the module docstring)."""
    net = np.random.default_rng(seed).normal(size=(delta(n), 3))
    patch = Patch(n, alpha, net)
    m_root = float(second_derivative_bound(net, n, alpha)[0])
    # sampled maximum of |D^2 s[e, e]| (for the tightness ratio of the bound)
    rng = np.random.default_rng(seed + 1)
    x = rng.dirichlet([0.5, 0.5, 0.5], 4000) * alpha
    th = rng.uniform(0, 2 * np.pi, 4000)[:, None]
    duu, duv, dvv = (Patch(n, alpha, q[0]) for q in second_derivative_nets(net[None], n, alpha))
    sampled = float(np.linalg.norm(np.cos(th) ** 2 * duu(x) + 2 * np.sin(th) * np.cos(th) * duv(x)
                                   + np.sin(th) ** 2 * dvv(x), axis=1).max())
    bary = positions(n)
    labs = united_system(n)
    edge = np.array([f != 0 and lab.j == 0 for f, lab in enumerate(labs)])  # the boundary points (level j = 0)
    inner = ~edge
    inner[0] = False                                                         # the centre R_{2n,n,n} is row 0
    nets, a, b, sign = net[None], np.zeros(1), np.zeros(1), np.ones(1)
    rows = []
    for k in range(depth + 1):
        h = alpha / 2 ** k
        u = a[:, None] + sign[:, None] * h * bary[None, :, 0]
        v = b[:, None] + sign[:, None] * h * bary[None, :, 1]
        pts = np.stack([u, v, np.maximum(alpha - u - v, 0.0)], axis=-1).reshape(-1, 3)
        diff = nets - patch(pts).reshape(nets.shape)
        dist = np.linalg.norm(diff, axis=2)
        normal = np.abs(np.einsum("nfd,nfd->nf", diff, patch.normals(pts).reshape(nets.shape)))
        m_leaves = float(second_derivative_bound(nets, n, h).max())
        row = {"n": n, "alpha": alpha, "k": k, "h": h, "d": float(dist.max()),
               "d_edge": float(dist[:, edge].max()), "d_centre": float(dist[:, 0].max()),
               "d_inner": float(dist[:, inner].max()) if inner.any() else float("nan"),
               "d_normal": float(normal[:, inner | (np.arange(len(labs)) == 0)].max()),
               "C_edge": float(dist[:, edge].max()) / (h * h * m_root), "bound_ratio": m_leaves / sampled}
        rows.append(row)
        if k == depth:
            break
        mats = subdivision_matrices(n, h)
        nets = np.concatenate([np.einsum("ij,njd->nid", m, nets) for m in mats])
        half = h / 2
        a = np.concatenate([a + sign * half, a, a, a + sign * half])
        b = np.concatenate([b, b + sign * half, b, b + sign * half])
        sign = np.concatenate([sign, sign, sign, -sign])
    for prev, row in zip(rows, rows[1:]):
        row["order"] = math.log2(prev["d"] / row["d"])
        for key in ("edge", "centre", "inner", "normal"):
            row["order_" + key] = math.log2(prev["d_" + key] / row["d_" + key]) if row["d_" + key] > 0 else math.nan
    return rows


def n2_inner_positions() -> np.ndarray:
    """Positions for n = 2 at which every control point approaches like h^2 (found from the measured tangential
    offsets): the six inner members, sine exponents (a, b, c) with a + b + c = 5, at (a + 1, b + 1, c + 1) / 8; the
    others at their layout positions."""
    out = []
    for lab in united_system(2):
        b = barycentric(lab)
        out.append((np.rint(b * 5) + 1) / 8 if lab.j == 1 and not lab.is_centre else b)
    return np.array(out)


def rates_at(positions_: np.ndarray, n: int, alpha: float, depth: int, seed: int = 5) -> list[float]:
    """max_f |Q_f - s(x_f)| per depth with the points placed at ``positions_`` (barycentric, one row per member)."""
    net = np.random.default_rng(seed).normal(size=(delta(n), 3))
    patch = Patch(n, alpha, net)
    out = []
    for lev in subdivision_levels(net, n, alpha, depth):  # the figure's loop: sub-nets with their placements
        h, nets, a, b, sign = lev["h"], lev["nets"], lev["a"], lev["b"], lev["sign"]
        u = a[:, None] + sign[:, None] * h * positions_[None, :, 0]
        v = b[:, None] + sign[:, None] * h * positions_[None, :, 1]
        pts = np.stack([u, v, np.maximum(alpha - u - v, 0.0)], axis=-1).reshape(-1, 3)
        out.append(float(np.linalg.norm(patch(pts).reshape(nets.shape) - nets, axis=2).max()))
    return out


def elevation_rates(n: int, alpha: float, top: int, seed: int = 0) -> dict:
    """e_m for m = n..top and the fitted exponent over the last half."""
    net = np.random.default_rng(seed).normal(size=(delta(n), 3))
    patch = Patch(n, alpha, net)
    cur, out = net, []
    for m in range(n, top + 1):
        if m > n:
            cur = elevate(cur, m - 1, alpha)
        pts = positions(m) * alpha
        diff = cur - patch(pts)
        out.append((m, float(np.linalg.norm(diff, axis=1).max()),
                    float(np.abs(np.einsum("fd,fd->f", diff, patch.normals(pts))).max())))
    ms, es, ns = np.array(out).T
    half = ms >= (n + top) / 2
    slope = np.polyfit(np.log(ms[half]), np.log(es[half]), 1)[0]
    slope_n = np.polyfit(np.log(ms[half]), np.log(ns[half]), 1)[0]
    return {"n": n, "alpha": alpha, "errors": out, "exponent": float(-slope), "exponent_normal": float(-slope_n),
            "m_times_e": [float(m * e) for m, e, _ in out]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="reports/subdivision_convergence.md")
    ap.add_argument("--quick", action="store_true", help="n <= 2, two alpha, depth 4, elevation to 12")
    args = ap.parse_args(argv)
    alphas = [0.5, 1.0, math.pi / 2, 2.5, 3.0] if not args.quick else [1.0, 3.0]
    orders = [1, 2, 3, 4] if not args.quick else [1, 2]
    t0 = time.time()
    lines = ["# Convergence of control nets under subdivision and elevation (measured)", "",
             f"`PYTHONPATH=$PWD python tools/subdivision_convergence.py{' --quick' if args.quick else ''}` "
             "(seeded standard-normal nets, 3 coordinates; definitions: the tool's docstring).", "",
             "## Subdivision: d_k = max |Q_f - s(x_f)| at depth k, h = alpha / 2^k", "",
             "Columns: all points; the boundary points (level j = 0); the centre; the other (inner) points.", "",
             "| n | alpha | k | d_k | order | boundary | order | centre | order | inner | order | normal part, inner "
             "and centre | order | boundary / (h^2 M) | leaf bound / sampled |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    summary = []
    for n in orders:
        depth = (6 if n <= 2 else 5) if not args.quick else 4
        for alpha in alphas:
            rows = subdivision_rates(n, alpha, depth)
            for r in rows:
                nan = float("nan")
                lines.append(f"| {n} | {alpha:.4g} | {r['k']} | {r['d']:.3e} | {r.get('order', nan):.3f} | "
                             f"{r['d_edge']:.3e} | {r.get('order_edge', nan):.3f} | {r['d_centre']:.3e} | "
                             f"{r.get('order_centre', nan):.3f} | {r['d_inner']:.3e} | {r.get('order_inner', nan):.3f} "
                             f"| {r['d_normal']:.3e} | {r.get('order_normal', nan):.3f} "
                             f"| {r['C_edge']:.4f} | {r['bound_ratio']:.4f} |")
            last = rows[-1]
            summary.append((n, alpha, last["order"], last["order_edge"], last["order_centre"], last["order_inner"],
                            last["order_normal"], max(r["C_edge"] for r in rows[1:]), last["bound_ratio"]))
        print(f"subdivision n = {n} done ({time.time() - t0:.0f} s)", file=sys.stderr)
    lines += ["", "Summary (last depth): n, alpha: observed order (all, boundary, centre, inner, normal part of inner "
              "and centre); max over k >= 1 of boundary d_k / (h^2 M); leaf bound / sampled", ""]
    lines += [f"- n = {n}, alpha = {a:.4g}: {o:.3f}, {oe:.3f}, {oc:.3f}, {oi:.3f}, {on:.3f}; {c:.4f}; {br:.4f}"
              for n, a, o, oe, oc, oi, on, c, br in summary]
    lines += ["", "## n = 2 with the inner points at (a + 1, b + 1, c + 1) / 8", "",
              "All points at these positions (the six inner members; sine exponents (a, b, c)), another seed (5):", ""]
    for alpha in alphas:
        d = rates_at(n2_inner_positions(), 2, alpha, 6 if not args.quick else 4)
        ords = [math.log2(d[k - 1] / d[k]) for k in range(1, len(d))]
        lines.append(f"- alpha = {alpha:.4g}: d_k = {', '.join(f'{x:.2e}' for x in d)}; orders of the last three "
                     f"depths {', '.join(f'{o:.3f}' for o in ords[-3:])}")
    lines += ["", "## Elevation: e_m = max |P_f - s(x_f)| after elevating from n to m", "",
              "| n | alpha | fitted p (e ~ m^-p, last half) | m e_m at m = n+1, mid, top | p of the normal part |",
              "|---|---|---|---|---|"]
    top = 24 if not args.quick else 12
    for n in orders[:3]:
        for alpha in alphas:
            r = elevation_rates(n, alpha, top)
            me = r["m_times_e"]
            lines.append(f"| {n} | {alpha:.4g} | {r['exponent']:.3f} | {me[1]:.4f}, {me[len(me) // 2]:.4f}, "
                         f"{me[-1]:.4f} | {r['exponent_normal']:.3f} |")
        print(f"elevation n = {n} done ({time.time() - t0:.0f} s)", file=sys.stderr)
    lines += ["", f"Wall time {time.time() - t0:.0f} s (loaded 2-core machine)."]
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text("\n".join(lines) + "\n")
    print("\n".join(lines[-12:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
