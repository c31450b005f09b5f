"""Fig. oriented_graph and Fig. united_system_n_3: the graph of T_{2n}, computed from the formulas.

Layout: a function with half-angle sine exponents (a, b, c) of u, v, w sits at the barycentric point
(a, b, c)/(a + b + c) of the triangle whose corners carry sin^{2n}(u/2), sin^{2n}(v/2), sin^{2n}(w/2).
Levels j are then the nested triangles of the paper and the centre R_{2n,n,n} is the centroid.

Edges (our reconstruction; the paper's drawing is not in the source): consecutive functions along a
side of a level triangle, oriented from the corners towards the middle, and from level j to level
j+1 (same colour and i), oriented inwards.  Each weight is the *computed* ratio of the two monomials,
so every path multiplies out to the function at its end (e.g. corner -> centre gives
sin^n(u/2) sin^n(v/2) sin^n(w/2)).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scipy.spatial import ConvexHull

from paper_repro.core.labels import COLORS, BasisLabel, exponents, full_system, united_system
from paper_repro.core.layout import CORNERS, edges, net_edges, position  # noqa: F401 (re-exported)
from paper_repro.util.registry import figure

from . import COLOR_OF, plt, save

SHORT = ("s_u", "c_u", "s_v", "c_v", "s_w", "c_w")


def ratio_text(num: BasisLabel, den: BasisLabel) -> str:
    """The weight ``num/den`` as mathtext, e.g. ``s_w c_v / s_u`` (s_x = sin(x/2), c_x = cos(x/2))."""
    d = np.subtract(exponents(num), exponents(den))
    top = " ".join(SHORT[k] + (f"^{d[k]}" if d[k] > 1 else "") for k in range(6) if d[k] > 0) or "1"
    bot = " ".join(SHORT[k] + (f"^{-d[k]}" if d[k] < -1 else "") for k in range(6) if d[k] < 0)
    return f"${top}$" if not bot else f"${top}\\,/\\,{bot}$"


def _node_color(lab: BasisLabel) -> str:
    return COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color]


def draw_weighted_graph(ax, n: int) -> None:
    for a, b in edges(n):
        pa, pb = position(a), position(b)
        ax.annotate("", xy=pb, xytext=pa, arrowprops=dict(arrowstyle="-|>", color="0.45", lw=0.8,
                                                          shrinkA=7, shrinkB=7))
        mid = (pa + pb) / 2
        ax.text(mid[0], mid[1], ratio_text(b, a), fontsize=11, ha="center", va="center",
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.85))
    for lab in united_system(n):
        p = position(lab)
        ax.plot(*p, "o", ms=7, color=_node_color(lab), zorder=3)
    for name in ("u", "v", "w"):
        p = CORNERS[name]
        dx = {"u": -0.06, "v": 0.1, "w": 0.06}[name]
        ax.text(p[0] + dx, p[1] - 0.06 if name != "v" else p[1], rf"$\sin^{{{2 * n}}}\frac{{{name}}}{{2}}$",
                ha="center", fontsize=13)
    ax.set_title(f"(a) weighted oriented graph, n = {n}\n"
                 r"weights: ratios of the monomials, $s_x=\sin(x/2)$, $c_x=\cos(x/2)$", fontsize=14)


def draw_domains(ax, n: int) -> None:
    for color in COLORS:
        pts = np.array([position(lab) for lab in full_system(n, color)])  # the full family R_{2n} etc.
        hull = ConvexHull(pts)
        ax.fill(*pts[hull.vertices].T, color=COLOR_OF[color], alpha=0.18, lw=0)
    for lab in united_system(n):
        ax.plot(*position(lab), "o", ms=5, color=_node_color(lab), zorder=3)
    centroid = position(BasisLabel("R", n, n, n))
    inside = {"R": "(w,u)", "G": "(v,w)", "B": "(u,v)"}
    mids = {"R": (CORNERS["u"] + CORNERS["w"]) / 2, "G": (CORNERS["w"] + CORNERS["v"]) / 2,
            "B": (CORNERS["v"] + CORNERS["u"]) / 2}
    for color, pair in inside.items():
        p = 0.75 * mids[color] + 0.25 * centroid
        ax.text(*p, f"{color}: symmetric in {pair}", color=COLOR_OF[color], ha="center", fontsize=13,
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
    borders = {"(v,u)": CORNERS["w"], "(u,w)": CORNERS["v"], "(w,v)": CORNERS["u"]}
    for pair, corner in borders.items():
        p = 0.45 * corner + 0.55 * centroid
        ax.text(*p, f"{pair}", color="0.2", ha="center", fontsize=13, style="italic",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
    ax.set_title(f"(b) symmetry domains, n = {n}: R, G, B families and the swaps\n"
                 "exchanging adjacent domains (italic), as checked by claim “symmetry”", fontsize=14)


def _axes_clean(ax) -> None:
    ax.set_aspect("equal")
    ax.axis("off")


@figure("oriented_graph", paper_label="fig:oriented_graph", outputs=["oriented_graph.png"],
        caption="(a) The multiplicatively weighted oriented graph of order 2 with weights computed as ratios of the "
                "stored functions; (b) the red, green and blue symmetry domains of order 3.")
def make_oriented_graph(outdir: Path) -> list[Path]:
    fig, axes = plt.subplots(2, 1, figsize=(10.5, 20))
    draw_weighted_graph(axes[0], 2)
    draw_domains(axes[1], 3)
    for ax in axes:
        _axes_clean(ax)
    return [save(fig, outdir / "oriented_graph.png")]


@figure("united_system_n_3", paper_label="fig:united_system_n_3", outputs=["united_system_n_3.png"],
        caption="Layout of the joint system T_6 (n = 3, 37 functions) with paper labels; the centre R_{6,3,3} "
                "in orange.")
def make_united_system_n_3(outdir: Path) -> list[Path]:
    n = 3
    fig, ax = plt.subplots(figsize=(8, 7.2))
    for a, b in edges(n):
        pa, pb = position(a), position(b)
        ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.8", lw=0.7, zorder=1)
    for lab in united_system(n):
        p = position(lab)
        ax.plot(*p, "o", ms=6, color=_node_color(lab), zorder=3)
        ax.text(p[0], p[1] + 0.018, f"${lab.paper}$", color=_node_color(lab), fontsize=10, ha="center",
                va="bottom", zorder=4)
    ax.set_title(rf"$T_{{{2 * n}}}^\alpha$: {len(united_system(n))} functions, levels j = 0..{n}", fontsize=10)
    _axes_clean(ax)
    return [save(fig, outdir / f"united_system_n_{n}.png")]
