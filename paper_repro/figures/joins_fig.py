"""Figure of a G1 join along an edge (issue 38, item 5; beyond the paper): :mod:`paper_repro.surfaces.joins`."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.collections import LineCollection

from paper_repro.core.labels import united_system
from paper_repro.core.layout import net_edges, position
from paper_repro.surfaces.joins import directions, edge_points, edge_rows, join_error, join_neighbour
from paper_repro.surfaces.patch import Patch
from paper_repro.util.registry import figure

from . import plt, save
from .patches_fig import PATCH_COLORS
from .render3d import Scene, View

#: The join drawn: order, alpha, edge, multipliers (G1: d'_{2n-k} = -lam d_k + mu t_k).
N, ALPHA, EDGE, LAM, MU = 2, np.pi / 2, "v", 1.6, 0.4
CROSS_COLOR, NEIGHBOUR_COLOR = "#1f5fbf", "#d35400"


def join_nets() -> tuple[np.ndarray, np.ndarray]:
    """Our net (the layout of Fig. 1 lifted by a height field) and the G1 neighbour across edge v (v = 0, the bottom
    side of the layout): its other rows are the reflected layout lifted by another field; its boundary row and second
    row come from :func:`~paper_repro.surfaces.joins.join_neighbour`."""
    pos = np.array([position(lab) for lab in united_system(N)])
    z = 0.18 * np.sin(np.pi * pos[:, 0]) * (1 + pos[:, 1]) + 0.1 * pos[:, 1]
    net = np.c_[pos, z]
    mirror = np.array([1.0, 0.0]) - pos  # the point reflection through the midpoint (1/2, 0) of the bottom side
    guess = np.c_[mirror, 0.1 * np.sin(np.pi * mirror[:, 0])]
    return net, join_neighbour(net, N, ALPHA, EDGE, guess, lam=LAM, mu=MU)


@figure("join_g1", outputs=["join_g1.png"],
        caption="Beyond the paper (issue 38): two second order patches (alpha = pi/2) joined G1 along the edge v = 0 "
                "with constant multipliers, d'_{2n-k} = -lam d_k + mu t_k, lam = 1.6, mu = 0.4 (docs/"
                "joins_for_all_n.md). (a) The patches with their nets (the shared boundary row; the "
                "neighbour's second row computed by join_neighbour) and the cross-boundary derivatives at seven edge "
                "points: ours into our patch (blue) and the neighbour's into its own (orange), coplanar with the "
                "edge's tangent. (b) The neighbour's cross-boundary derivative along the edge, evaluated by "
                "Patch.derivative (markers), against -lam times ours plus mu times the tangent (lines), per "
                "coordinate; join_error's G1 defect and the fitted lam, mu in the title.",
        claims=["joins_all_n"])
def make_join(outdir: Path) -> list[Path]:
    net, other = join_nets()
    ours, theirs = Patch(N, ALPHA, net), Patch(N, ALPHA, other)
    cross, tangent = directions(EDGE)
    ts = np.linspace(0.08, 0.92, 7) * ALPHA
    pts = edge_points(ALPHA, EDGE, ts)
    mirror = edge_points(ALPHA, EDGE, ALPHA - ts)  # the same points of the edge, in the neighbour's parameter
    base = ours(pts)
    d_ours = ours.derivative(pts, cross)
    d_theirs = theirs.derivative(mirror, cross)
    t_ours = ours.derivative(pts, tangent)
    fig, axes = plt.subplots(1, 2, figsize=(15, 6.2), gridspec_kw={"width_ratios": [1.25, 1]})
    sc = Scene(View(38, -70))
    for patch, colour in ((ours, PATCH_COLORS[0]), (theirs, PATCH_COLORS[1])):
        v, f = patch.mesh(16)
        sc.surface(v, f, colour)
    b, s = edge_rows(N, EDGE)
    colours = ["#444444"] * len(net)
    for k in s:
        colours[k] = CROSS_COLOR
    sc.net(net, net_edges(N), colours, "#1f3f6f", size=22)
    colours = ["#444444"] * len(net)
    for k in s:
        colours[k] = NEIGHBOUR_COLOR
    sc.net(other, net_edges(N), colours, "#8a3a00", size=22)
    ax = axes[0]
    sc.draw(ax)
    scale = 0.22
    for vec, colour in ((d_ours, CROSS_COLOR), (d_theirs, NEIGHBOUR_COLOR)):
        segs = [sc.view.project(np.array([p, p + scale * d]))[0] for p, d in zip(base, vec)]
        ax.add_collection(LineCollection(segs, colors=colour, linewidths=2.4, zorder=5, capstyle="round"))
        tips = np.array([seg[1] for seg in segs])
        ax.scatter(tips[:, 0], tips[:, 1], s=22, c=colour, zorder=6, edgecolors="white", linewidths=0.6)
    ax.set_title("(a) the two patches, their nets and the cross-boundary derivatives", fontsize=13)
    ax = axes[1]
    err = join_error(net, other, N, ALPHA, EDGE)
    want = -LAM * d_ours + MU * t_ours
    fine = np.linspace(0.0, 1.0, 121) * ALPHA
    fine_pts, fine_mirror = edge_points(ALPHA, EDGE, fine), edge_points(ALPHA, EDGE, ALPHA - fine)
    want_fine = -LAM * ours.derivative(fine_pts, cross) + MU * ours.derivative(fine_pts, tangent)
    got_fine = theirs.derivative(fine_mirror, cross)
    for j, (axis, colour) in enumerate(zip("xyz", ("#1b9e77", "#7570b3", "#d95f02"))):
        ax.plot(fine / ALPHA, want_fine[:, j], color=colour, linewidth=1.8,
                label=f"{axis}: -lam d/dcross + mu d/dtangent (ours)")
        ax.plot(ts / ALPHA, d_theirs[:, j], linestyle="none", marker="o", markersize=7, markerfacecolor="white",
                markeredgecolor=colour, label=f"{axis}: d/dcross (neighbour)")
    gap = float(np.abs(got_fine - want_fine).max())
    ax.set_xlabel("t / alpha along the edge v = 0", fontsize=12)
    ax.set_ylabel("derivative (coordinates)", fontsize=12)
    g1 = "< 1e-13" if err["G1"] < 1e-13 else f"= {err['G1']:.1e}"
    ax.set_title(f"(b) G1 defect {g1}, fitted lam = {err['lam']:.6f}, mu = {err['mu']:.6f}\n"
                 f"(sampled gap {'< 1e-13' if gap < 1e-13 else f'{gap:.1e}'}; C0 defect {err['C0']:.0f})",
                 fontsize=12)
    ax.legend(fontsize=10, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    ax.tick_params(labelsize=11)
    ax.grid(alpha=0.3)
    assert float(np.abs(want - d_theirs).max()) < 1e-12 and err["C0"] == 0
    fig.tight_layout()
    return [save(fig, outdir / "join_g1.png")]
