"""Figures of Section sec:applications: control-net layout, a third order patch, the torus, the Dupin cyclide."""

from __future__ import annotations

from pathlib import Path

import mpmath
import numpy as np

from paper_repro.core.labels import united_system
from paper_repro.core.layout import net_edges, position
from paper_repro.surfaces.models import cyclide_pieces, torus_pieces
from paper_repro.surfaces.patch import Patch
from paper_repro.util.registry import figure

from . import COLOR_OF, plt, save


def _color(lab) -> str:
    return COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color]


@figure("associated_control_net", paper_label="fig:associated_control_net", outputs=["associated_control_net.png"],
        caption="Layout of the control points r, g, b of an order-3 patch (37 points), connected along the edges of "
                "the oriented graph (quadrangular faces, not triangulated, as in the paper).")
def make_layout(outdir: Path, n: int = 3) -> list[Path]:
    fig, ax = plt.subplots(figsize=(8, 7.2))
    labels = united_system(n)
    pos = np.array([position(lab) for lab in labels])
    for ka, kb in net_edges(n):
        ax.plot(*pos[[ka, kb]].T, color="0.6", lw=0.8, zorder=1)
    for lab, p in zip(labels, pos):
        ax.plot(*p, "o", ms=6, color=_color(lab), zorder=2)
        ax.text(p[0], p[1] + 0.018, rf"$\mathbf{{{lab.control_point[0]}}}{lab.control_point[1:]}$", fontsize=10,
                ha="center", va="bottom", color=_color(lab))
    ax.set_aspect("equal")
    ax.axis("off")
    return [save(fig, outdir / "associated_control_net.png")]


def third_order_net() -> np.ndarray:
    """A fixed order-3 net: the layout lifted by a smooth height field plus a bump at the centre."""
    pos = np.array([position(lab) for lab in united_system(3)])
    z = 0.6 * np.sin(np.pi * pos[:, 0]) * np.sin(np.pi * pos[:, 1] / 0.866) + 0.25 * pos[:, 0]
    z[0] += 0.5
    return np.c_[pos, z]


def _surface(ax, verts, faces, color, alpha):
    ax.plot_trisurf(verts[:, 0], verts[:, 1], verts[:, 2], triangles=faces, color=color, alpha=alpha, linewidth=0,
                    shade=True)


@figure("third_order_patch", paper_label="fig:third_order_patch", outputs=["third_order_patch.png"],
        caption="Different views of a third order triangular trigonometric patch with its 37-point control net "
                "(alpha = pi/2).")
def make_third_order(outdir: Path) -> list[Path]:
    net = third_order_net()
    patch = Patch(3, np.pi / 2, net)
    verts, faces = patch.mesh(28)
    fig = plt.figure(figsize=(15, 5))
    for k, (elev, azim) in enumerate(((25, -60), (55, 30), (8, -100))):
        ax = fig.add_subplot(1, 3, k + 1, projection="3d")
        _surface(ax, verts, faces, "#9ecae1", 0.8)
        for ka, kb in net_edges(3):
            ax.plot(*net[[ka, kb]].T, color="0.3", lw=0.7)
        ax.scatter(*net.T, c=[_color(lab) for lab in united_system(3)], s=12, depthshade=False)
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_box_aspect(None, zoom=1.4)  # fill the frame
    fig.subplots_adjust(left=0, right=1, bottom=0, top=1, wspace=0)
    return [save(fig, outdir / "third_order_patch.png")]


@figure("torus", paper_label="fig:torus", outputs=["torus.png"],
        caption="Part of the ring torus (mu = 3, rho = (1+sqrt5)/2 mu, alpha = pi/2) by 12 smoothly joined second "
                "order patches (join gap measured in claim patch_properties); the control net of the toroidal "
                "triangle of Example exmp:torus (computed; it differs from the printed one in b_{4,3,1}.x) in black.")
def make_torus(outdir: Path) -> list[Path]:
    al = np.pi / 2
    mu = 3.0
    rho = (1 + 5**0.5) / 2 * mu
    pieces = torus_pieces(al, rho, mu, [0.0, al], [0.0, al, 2 * al])
    fig = plt.figure(figsize=(9, 7))
    ax = fig.add_subplot(projection="3d")
    cmap = plt.get_cmap("tab20")
    for k, p in enumerate(pieces):
        v, f = p.patch.mesh(12)
        _surface(ax, v, f, cmap(k % 20), 0.75)
    first = next(p for p in pieces if p.phi == 0 and p.psi == 0 and not p.upper)
    net = first.patch.net
    for ka, kb in net_edges(2):
        ax.plot(*net[[ka, kb]].T, color="black", lw=1.0)
    ax.scatter(*net.T, color="black", s=14, depthshade=False)
    ax.view_init(elev=30, azim=-35)
    ax.set_box_aspect((1, 1, 0.45), zoom=1.5)  # fill the frame
    ax.set_axis_off()
    fig.subplots_adjust(left=0, right=1, bottom=0, top=1)
    return [save(fig, outdir / "torus.png")]


@figure("dupin_03", paper_label="fig:dupin_03", outputs=["dupin_03.png"],
        caption="Ring Dupin cyclide (a = 6, b = 4 sqrt 2, c = 2, mu = 3) by second order rational patches, alpha = "
                "pi/2: the 16 patches of the lower triangles (left, transparent) and all 32 covering the cyclide "
                "(right, opaque).")
def make_dupin(outdir: Path) -> list[Path]:
    al = np.pi / 2
    phases = [k * al for k in range(4)]
    with mpmath.workdps(30):
        params = {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}
    pieces = cyclide_pieces(al, params, phases, phases)
    fig = plt.figure(figsize=(15, 6.5))
    cmap = plt.get_cmap("tab20")
    for col, (sel, alpha) in enumerate((([p for p in pieces if not p.upper], 0.45), (pieces, 0.95))):
        ax = fig.add_subplot(1, 2, col + 1, projection="3d")
        for k, p in enumerate(sel):
            v, f = p.patch.mesh(10)
            _surface(ax, v, f, cmap(k % 20), alpha)
        ax.view_init(elev=35, azim=-50)
        ax.set_box_aspect((1, 1, 0.55), zoom=1.45)  # fill the frame
        ax.set_axis_off()
    return [save(fig, outdir / "dupin_03.png")]
