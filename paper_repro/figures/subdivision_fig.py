"""Beyond the paper: control nets under repeated midpoint subdivision converging to their patch
(docs/tessellation.md §4)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from paper_repro.core.labels import united_system
from paper_repro.core.layout import barycentric, net_edges
from paper_repro.core.subdivision import subdivision_matrices
from paper_repro.surfaces.patch import Patch
from paper_repro.util.registry import figure

from . import plt, save
from .patches_fig import PATCH_COLORS, third_order_net
from .render3d import Scene, View

ALPHA = np.pi / 2
DEPTH = 5


def subdivision_levels(net: np.ndarray, n: int, alpha: float, depth: int) -> list[dict]:
    """Per depth k = 0..depth: the sub-nets ``(4^k, delta_n, d)``, their (u, v) origins and orientations, h."""
    nets, a, b, sign = net[None], np.zeros(1), np.zeros(1), np.ones(1)
    out = []
    for k in range(depth + 1):
        h = alpha / 2**k
        out.append({"k": k, "h": h, "nets": nets, "a": a, "b": b, "sign": sign})
        if k == depth:
            break
        mats = subdivision_matrices(n, h)
        nets = np.concatenate([np.einsum("ij,njd->nid", m, nets) for m in mats])
        a = np.concatenate([a + sign * h / 2, a, a, a + sign * h / 2])
        b = np.concatenate([b, b + sign * h / 2, b, b + sign * h / 2])
        sign = np.concatenate([sign, sign, sign, -sign])
    return out


def distances(patch: Patch, level: dict, n: int, alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """|Q_f - s(x_f)| and its component along the surface normal N(x_f), for every sub-net and control point, x_f
    the point's layout position in its sub-triangle."""
    bary = np.array([barycentric(lab) for lab in united_system(n)])
    h, a, b, s = level["h"], level["a"], level["b"], level["sign"]
    u = a[:, None] + s[:, None] * h * bary[None, :, 0]
    v = b[:, None] + s[:, None] * h * bary[None, :, 1]
    pts = np.stack([u, v, np.maximum(alpha - u - v, 0.0)], axis=-1).reshape(-1, 3)
    nets = level["nets"]
    diff = nets - patch(pts).reshape(nets.shape)
    return np.linalg.norm(diff, axis=2), np.abs(np.einsum("nfd,nfd->nf", diff, patch.normals(pts).reshape(nets.shape)))


@figure("subdivision_convergence", outputs=["subdivision_convergence.png"],
        caption="Beyond the paper: the order-3 patch of Fig. third_order_patch (alpha = pi/2) with its control net "
                "and the 4 and 16 sub-nets of one and two midpoint subdivisions (each sub-net in its own colour), "
                "and (d) the distance of the sub-nets' points to the patch at their positions against h = alpha/2^k "
                "(measured, depth 0 to 5): the boundary points and the centre approach like h^2; the inner points "
                "like h, but their offset is tangential: its component along the surface normal decreases like h^2 "
                "(docs/tessellation.md).")
def make_subdivision_convergence(outdir: Path) -> list[Path]:
    n = 3
    net = third_order_net()
    patch = Patch(n, ALPHA, net)
    levels = subdivision_levels(net, n, ALPHA, DEPTH)
    verts, faces = patch.mesh(24)
    edges = net_edges(n)
    fig = plt.figure(figsize=(15, 4.8))
    view = View(28, -62)
    for k in range(3):
        ax = fig.add_subplot(1, 4, k + 1)
        sc = Scene(view)
        sc.surface(verts, faces, "#d9d9d9")
        for q, sub in enumerate(levels[k]["nets"]):
            colour = PATCH_COLORS[(q + 8) % len(PATCH_COLORS)] if k else "black"
            sc.net(sub, edges, colour, line_color=colour, size=14 if k else 22)
        sc.draw(ax)
        ax.set_title(f"({'abc'[k]}) depth {k}: {4 ** k} net{'s' if k else ''}", fontsize=14)
    ax = fig.add_subplot(1, 4, 4)
    labs = united_system(n)
    edge = np.array([f != 0 and lab.j == 0 for f, lab in enumerate(labs)])
    inner = ~edge
    inner[0] = False
    hs = np.array([lv["h"] for lv in levels])
    d = [distances(patch, lv, n, ALPHA) for lv in levels]
    for mask, name, marker in ((edge, "boundary points", "o"), (np.arange(len(labs)) == 0, "centre", "s"),
                               (inner, "inner points", "^")):
        ax.loglog(hs, [x[0][:, mask].max() for x in d], marker=marker, label=name)
    ax.loglog(hs, [x[1][:, inner].max() for x in d], marker="v", label="inner, normal part")
    ax.loglog(hs, 0.3 * hs**2, "k--", lw=1, label="h²")
    ax.loglog(hs, 0.1 * hs, "k:", lw=1, label="h")
    ax.set_xlabel("h = α / 2^k", fontsize=13)
    ax.set_ylabel("max distance to the patch", fontsize=13)
    ax.set_title("(d) convergence of the sub-nets", fontsize=14)
    ax.legend(fontsize=11, loc="upper left")
    ax.tick_params(labelsize=12)
    fig.tight_layout()
    return [save(fig, outdir / "subdivision_convergence.png")]
