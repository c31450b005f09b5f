"""Figures of the alpha -> 0 limit and of order elevation (issue 5)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from paper_repro.core.elevation import elevate
from paper_repro.core.labels import united_system
from paper_repro.core.layout import edges, net_edges, position
from paper_repro.surfaces.patch import Patch
from paper_repro.theory.limit_formula import multinomial
from paper_repro.theory.limits import limit_terms
from paper_repro.util.io import data_dir
from paper_repro.util.registry import figure

from . import COLOR_OF, plt, save


def _color(lab) -> str:
    return COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color]


@figure("limit_cases_n_1_2_3", paper_label="fig:limit_cases_n_1_2_3", outputs=["limit_cases_n_1_2_3.png"],
        caption="Limits alpha -> 0 of the normalized bases of orders 1, 2, 3 (u = alpha x, v = alpha y, "
                "w = alpha z): each node shows q P^m_{d,e,f} with P^m_{d,e,f} = m!/(d!e!f!) x^d y^e z^f; the centre "
                "vanishes. (q = 1 on level 0; q != 1 on higher levels for n >= 2.)")
def make_limit_cases(outdir: Path) -> list[Path]:
    # one panel a row, each as wide as the gallery, so that panel (c) is as legible as (a)
    fig, axes = plt.subplots(3, 1, figsize=(11, 27), gridspec_kw={"height_ratios": [0.6, 1, 1.25]})
    for ax, n in zip(axes, (1, 2, 3)):
        for a, b in edges(n):
            pa, pb = position(a), position(b)
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.85", lw=0.8, zorder=1)
        for lab, (c, t) in zip(united_system(n), limit_terms(n)):
            p = position(lab)
            ax.plot(*p, "o", ms=7, color=_color(lab), zorder=2)
            if c == 0:
                text = "$0$"
            else:
                q = c / multinomial(sum(t), t)
                coef = "" if q == 1 else f"({q.p}/{q.q})\\,"
                text = f"${coef}P^{{{sum(t)}}}_{{{t[0]},{t[1]},{t[2]}}}$"
            ax.text(p[0], p[1] + 0.018, text, fontsize=12, ha="center", va="bottom", color=_color(lab))
        ax.set_title(f"({'abc'[n - 1]}) n = {n}", fontsize=15)
        ax.set_aspect("equal")
        ax.set_xlim(-0.08, 1.08)
        ax.axis("off")
    fig.tight_layout()
    return [save(fig, outdir / "limit_cases_n_1_2_3.png")]


@figure("conversion_of_limit_cases_n_1_2_3", paper_label="fig:conversion_of_limit_cases_n_1_2_3",
        outputs=["conversion_of_limit_cases_n_1_2_3.png"],
        caption="Conversion of the control net of an order-2 (a) and an order-3 (b) patch to the quintic and octic "
                "Bezier nets of the alpha -> 0 limit, by the computed general conversion: each Bezier point "
                "p_{d,e,f} (black square) is a convex combination of control points r, g, b; arrows show, for the "
                "points marked in yellow, which control points enter and with which weight.")
def make_conversion(outdir: Path) -> list[Path]:
    from paper_repro.theory.limits import conversion_matrix

    fig, axes = plt.subplots(2, 1, figsize=(11, 21))
    shown = {2: [(3, 2, 0), (1, 1, 3)], 3: [(2, 1, 5), (5, 2, 1)]}
    for ax, n in zip(axes, (2, 3)):
        labels = united_system(n)
        pos = np.array([position(lab) for lab in labels])
        idx, w = conversion_matrix(n)
        N = sum(idx[0])
        bez = {t: np.array([t[1] * 0.5 + t[2] * 1.0, t[1] * np.sqrt(3) / 2]) / N for t in idx}
        # Bezier points placed on the same triangle as the graph (corner u left, w right, v top)
        for t, p in bez.items():
            special = t in shown[n]
            ax.plot(*p, "s", ms=9 if special else 6, color="#e6b800" if special else "black", zorder=3)
            ax.text(p[0], p[1] - 0.022, f"$p_{{{t[0]},{t[1]},{t[2]}}}$", fontsize=11, ha="center", va="top",
                    zorder=4)
        for lab, p in zip(labels, pos):
            ax.plot(*p, "o", ms=8, color=_color(lab), alpha=0.55, zorder=2)
        for t in shown[n]:
            row = w[idx.index(t)]
            for f, wt in enumerate(row):
                if wt == 0:
                    continue
                ax.annotate("", xy=bez[t], xytext=pos[f], zorder=1,
                            arrowprops=dict(arrowstyle="->", color=_color(labels[f]), lw=0.6 + 3 * float(wt)))
                mid = 0.62 * pos[f] + 0.38 * bez[t]
                ax.text(mid[0], mid[1], f"${wt.p}/{wt.q}$" if wt.q != 1 else f"${wt.p}$", fontsize=11,
                        color=_color(labels[f]), ha="center", va="center",
                        bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.85), zorder=5)
        ax.set_title(f"({'ab'[n - 2]}) order {n} -> Bezier degree {N}: coloured discs = control points "
                     f"(R red, G green, B blue, centre orange)", fontsize=13)
        ax.set_aspect("equal")
        ax.set_xlim(-0.06, 1.06)
        ax.axis("off")
    fig.tight_layout()
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
        ax.set_title(f"({'abc'[k]}) α = {name}", fontsize=14)
        ax.view_init(elev=28, azim=-60)
        ax.set_axis_off()
        ax.set_box_aspect(None, zoom=1.35)  # fill the frame
        if k == 0:
            ax.legend(fontsize=12, loc="upper left")
    return [save(fig, outdir / "degree_elevation_from_1_to_2.png")]


@figure("elevation_convergence", claims=["order_elevation"], outputs=["elevation_convergence.png"],
        caption="New: repeated order elevation 1 -> 6 of a random order-1 net; maximal distance between a control "
                "point and the patch point at its node position, versus the order (from claim order_elevation).")
def make_elevation_convergence(outdir: Path) -> list[Path]:
    claims = {c["id"]: c for c in json.loads((data_dir() / "claims.json").read_text())}
    rec = claims["order_elevation"]["measured"]["repeated_elevation_net_to_patch_distance"]
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    orders = np.arange(1, len(rec["by_order"]) + 1)
    dist = np.array(rec["by_order"], dtype=float)
    ax.loglog(orders, dist, "o-", label="measured")
    slope = np.polyfit(np.log(orders[1:]), np.log(dist[1:]), 1)[0]
    ref = dist[1] * (orders / orders[1]) ** -1.0
    ax.loglog(orders, ref, "--", color="0.45", label="reference slope −1 (1/order)")
    ax.xaxis.set_major_locator(FixedLocator(orders))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.set_xticklabels([str(o) for o in orders])
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("order after elevation", fontsize=12)
    ax.set_ylabel("max distance control point – patch", fontsize=12)
    ax.set_title(f"α = {rec['alpha']}; fitted slope {slope:.2f} (orders 2..{orders[-1]})", fontsize=12)
    ax.tick_params(labelsize=11)
    ax.legend(fontsize=11)
    ax.grid(alpha=0.3, which="both")
    return [save(fig, outdir / "elevation_convergence.png")]
