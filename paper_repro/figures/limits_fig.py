"""Figures of the alpha -> 0 limit and of order elevation (issue 5)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from paper_repro.core.elevation import elevate
from paper_repro.core.labels import united_system
from paper_repro.core.layout import edges, net_edges, position
from paper_repro.core.limits import bezier_limit, limit_terms, multinomial
from paper_repro.surfaces.patch import Patch
from paper_repro.util.io import DATA
from paper_repro.util.registry import figure

from . import COLOR_OF, plt, save


def _color(lab) -> str:
    return COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color]


@figure("limit_cases_n_1_2_3", paper_label="fig:limit_cases_n_1_2_3", outputs=["limit_cases_n_1_2_3.png"],
        caption="Limits alpha -> 0 of the normalized bases of orders 1, 2, 3 (u = alpha x, v = alpha y, "
                "w = alpha z): each node shows q P^m_{d,e,f} with P^m_{d,e,f} = m!/(d!e!f!) x^d y^e z^f; the centre "
                "vanishes. (q = 1 on level 0; q != 1 on higher levels for n >= 2.)")
def make_limit_cases(outdir: Path) -> list[Path]:
    fig, axes = plt.subplots(1, 3, figsize=(18, 6.5))
    for ax, n in zip(axes, (1, 2, 3)):
        for a, b in edges(n):
            pa, pb = position(a), position(b)
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.85", lw=0.6, zorder=1)
        for lab, (c, t) in zip(united_system(n), limit_terms(n)):
            p = position(lab)
            ax.plot(*p, "o", ms=5, color=_color(lab), zorder=2)
            if c == 0:
                text = "$0$"
            else:
                q = c / multinomial(sum(t), t)
                coef = "" if q == 1 else f"{q}\\,"
                text = f"${coef}P^{{{sum(t)}}}_{{{t[0]},{t[1]},{t[2]}}}$"
            ax.text(p[0], p[1] + 0.02, text, fontsize=6.5 if n == 3 else 8, ha="center", va="bottom",
                    color=_color(lab))
        ax.set_title(f"({'abc'[n - 1]}) n = {n}", fontsize=10)
        ax.set_aspect("equal")
        ax.axis("off")
    return [save(fig, outdir / "limit_cases_n_1_2_3.png")]


@figure("conversion_of_limit_cases_n_1_2_3", paper_label="fig:conversion_of_limit_cases_n_1_2_3",
        outputs=["conversion_of_limit_cases_n_1_2_3.png"],
        caption="Conversion of order-2 and order-3 control nets (coloured, laid out as the graph) to the quintic and "
                "octic Bezier nets of the alpha -> 0 limit (black squares), by the computed general conversion.")
def make_conversion(outdir: Path) -> list[Path]:
    fig, axes = plt.subplots(1, 2, figsize=(14, 6.5))
    for ax, n in zip(axes, (2, 3)):
        net = np.array([position(lab) for lab in united_system(n)])
        N, bez = bezier_limit(net, n)
        for a, b in edges(n):
            pa, pb = position(a), position(b)
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.8", lw=0.6)
        for lab in united_system(n):
            ax.plot(*position(lab), "o", ms=6, color=_color(lab), alpha=0.7)
        for (d, e, f), p in bez.items():
            ax.plot(*p, "s", ms=4, color="black")
            ax.text(p[0], p[1] - 0.025, f"$p_{{{d},{e},{f}}}$", fontsize=5.5, ha="center", va="top")
        ax.set_title(f"({'ab'[n - 2]}) n = {n} -> Bezier degree {N}", fontsize=10)
        ax.set_aspect("equal")
        ax.axis("off")
    return [save(fig, outdir / "conversion_of_limit_cases_n_1_2_3.png")]


def _demo_net_order_1() -> np.ndarray:
    """A fixed 3D order-1 control net: the graph layout lifted by fixed heights."""
    lift = {"R_{2,1,1}": 1.2, "R_{2,2,0}": 0.0, "R_{2,1,0}": 0.6, "G_{2,2,0}": 0.0, "G_{2,1,0}": 0.9,
            "B_{2,2,0}": 0.0, "B_{2,1,0}": 0.3}
    return np.array([[*position(lab), lift[lab.paper]] for lab in united_system(1)])


def _draw_net(ax, net, n, color, label, ms):
    for ka, kb in net_edges(n):
        ax.plot(*np.stack([net[ka], net[kb]]).T, color=color, lw=0.8)
    ax.scatter(*net.T, color=color, s=ms, label=label, depthshade=False)


@figure("degree_elevation_from_1_to_2", paper_label="fig:degree_elevation_from_1_to_2",
        outputs=["degree_elevation_from_1_to_2.png"],
        caption="Order elevation 1 -> 2 of a first order patch for (a) alpha = pi/4 < pi/2, (b) alpha = pi/2, "
                "(c) alpha = 3pi/4 > pi/2: the order-1 net (blue), the elevated order-2 net (red) and the patch.")
def make_elevation(outdir: Path) -> list[Path]:
    fig = plt.figure(figsize=(16, 5.2))
    net1 = _demo_net_order_1()
    for k, (alpha, name) in enumerate(((np.pi / 4, "π/4"), (np.pi / 2, "π/2"), (3 * np.pi / 4, "3π/4"))):
        ax = fig.add_subplot(1, 3, k + 1, projection="3d")
        g = 24
        bary = np.array([(i / g, j / g, 1 - (i + j) / g) for i in range(g + 1) for j in range(g + 1 - i)])
        surf = Patch(1, alpha, net1).at_barycentric(bary)
        ax.plot_trisurf(surf[:, 0], surf[:, 1], surf[:, 2], color="0.75", alpha=0.55, linewidth=0)
        _draw_net(ax, net1, 1, "#1f5fbf", "order 1", 25)
        _draw_net(ax, elevate(net1, 1, alpha), 2, "#d62728", "order 2 (elevated)", 12)
        ax.set_title(f"({'abc'[k]}) α = {name}", fontsize=10)
        ax.view_init(elev=28, azim=-60)
        ax.set_axis_off()
        if k == 0:
            ax.legend(fontsize=8, loc="upper left")
    return [save(fig, outdir / "degree_elevation_from_1_to_2.png")]


@figure("elevation_convergence", claims=["order_elevation"], outputs=["elevation_convergence.png"],
        caption="New: repeated order elevation 1 -> 6 of a random order-1 net; maximal distance between a control "
                "point and the patch point at its node position, versus the order (from claim order_elevation).")
def make_elevation_convergence(outdir: Path) -> list[Path]:
    claims = {c["id"]: c for c in json.loads((DATA / "claims.json").read_text())}
    rec = claims["order_elevation"]["measured"]["repeated_elevation_net_to_patch_distance"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    orders = np.arange(1, len(rec["by_order"]) + 1)
    ax.loglog(orders, rec["by_order"], "o-")
    ax.set_xlabel("order after elevation")
    ax.set_ylabel("max distance control point - patch")
    ax.set_title(f"α = {rec['alpha']}")
    ax.grid(alpha=0.3, which="both")
    return [save(fig, outdir / "elevation_convergence.png")]
