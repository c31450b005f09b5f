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
from .render3d import Scene, View


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


#: Opaque, distinguishable colours for the patches of a surface (no transparency: it mixes into mud).
PATCH_COLORS = ["#8fb8de", "#f4a582", "#a6d96a", "#fdd26e", "#c2a5cf", "#80cdc1", "#f1948a", "#bababa",
                "#5e9ccf", "#e08a5a", "#7fbf5a", "#d9b44a", "#9a7fb8", "#4fb3a3", "#d96a6a", "#8c8c8c"]


@figure("third_order_patch", paper_label="fig:third_order_patch", outputs=["third_order_patch.png"],
        caption="Different views (a), (b), (c) of the same third order triangular trigonometric patch with its "
                "37-point control net (alpha = pi/2). Opaque, smoothly shaded surface drawn triangle by triangle far "
                "to near; the net's parts hidden by the patch (tested against its triangles, cut at the silhouette) "
                "are dashed grey.")
def make_third_order(outdir: Path) -> list[Path]:
    net = third_order_net()
    patch = Patch(3, np.pi / 2, net)
    verts, faces = patch.mesh(30)
    colors = [_color(lab) for lab in united_system(3)]
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.6))
    for k, (ax, view) in enumerate(zip(axes, (View(25, -60), View(60, 30), View(8, -100)))):
        sc = Scene(view)
        sc.surface(verts, faces, "#9ecae1")
        sc.net(net, net_edges(3), colors, size=26)
        sc.draw(ax)
        ax.set_title(f"({'abc'[k]}) elevation {view.elev:g}°, azimuth {view.azim:g}°", fontsize=13)
    fig.tight_layout()
    return [save(fig, outdir / "third_order_patch.png")]


@figure("torus", paper_label="fig:torus", outputs=["torus.png"],
        caption="Part of the ring torus (mu = 3, rho = (1+sqrt5)/2 mu, alpha = pi/2) by 12 smoothly joined second "
                "order patches, opaque, one colour each (join gap measured in claim patch_properties); the control "
                "net of the toroidal triangle of Example 6.1 (computed; it differs from the printed one in "
                "b_{4,3,1}.x) in black, its hidden parts dashed.")
def make_torus(outdir: Path) -> list[Path]:
    al = np.pi / 2
    mu = 3.0
    rho = (1 + 5**0.5) / 2 * mu
    pieces = torus_pieces(al, rho, mu, [0.0, al], [0.0, al, 2 * al])
    fig, ax = plt.subplots(figsize=(10, 7))
    sc = Scene(View(32, -35))
    for k, p in enumerate(pieces):
        v, f = p.patch.mesh(16)
        sc.surface(v, f, PATCH_COLORS[k % len(PATCH_COLORS)])
    first = next(p for p in pieces if p.phi == 0 and p.psi == 0 and not p.upper)
    sc.net(first.patch.net, net_edges(2), "black", size=30)
    sc.draw(ax)
    fig.tight_layout()
    return [save(fig, outdir / "torus.png")]


@figure("dupin_03", paper_label="fig:dupin_03", outputs=["dupin_03.png"],
        caption="Ring Dupin cyclide (a = 6, b = 4 sqrt 2, c = 2, mu = 3) by second order rational patches, alpha = "
                "pi/2: (a) the 16 patches of the lower triangles in colour, the other 16 in light grey; (b) all 32 "
                "patches covering the cyclide. Opaque, drawn triangle by triangle far to near.")
def make_dupin(outdir: Path) -> list[Path]:
    al = np.pi / 2
    phases = [k * al for k in range(4)]
    with mpmath.workdps(30):
        params = {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}
    pieces = cyclide_pieces(al, params, phases, phases)
    fig, axes = plt.subplots(1, 2, figsize=(16, 6.4))
    meshes = [p.patch.mesh(12) for p in pieces]
    for col, ax in enumerate(axes):
        sc = Scene(View(35, -50))
        lower = 0
        for p, (v, f) in zip(pieces, meshes):
            if col == 0 and p.upper:
                sc.surface(v, f, "#e6e6e6")
            else:
                sc.surface(v, f, PATCH_COLORS[lower % len(PATCH_COLORS)])
                lower += 1
        sc.draw(ax)
        ax.set_title("(a) the 16 patches of the lower triangles" if col == 0 else "(b) all 32 patches",
                     fontsize=14)
    fig.tight_layout()
    return [save(fig, outdir / "dupin_03.png")]
