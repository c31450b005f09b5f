"""Figures of the alpha -> 0 limit and of order elevation (issue 5)."""

from __future__ import annotations

import json
from fractions import Fraction
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
        ax.set_title(f"({'abc'[n - 1]}) n = {n}", fontsize=15, pad=14)
        ax.set_aspect("equal")
        ax.set_xlim(-0.08, 1.08)
        ax.set_ylim(-0.06, np.sqrt(3) / 2 + 0.11)  # room above the top node's label, below the title
        ax.axis("off")
    fig.tight_layout()
    return [save(fig, outdir / "limit_cases_n_1_2_3.png")]


#: The Bezier points whose conversion the figure spells out: those the paper lists with an erratum (n = 3) and
#: two printed ones of n = 2.
CONVERSION_SHOWN = {2: [(3, 1, 1), (2, 1, 2)], 3: [(2, 1, 5), (3, 2, 3)]}


def _frac(w) -> str:
    return f"{w.p}/{w.q}" if w.q != 1 else f"{w.p}"


@figure("conversion_of_limit_cases_n_1_2_3", paper_label="fig:conversion_of_limit_cases_n_1_2_3",
        outputs=["conversion_of_limit_cases_n_1_2_3.png"],
        caption="Conversion of the control net of an order-2 (a) and an order-3 (b) patch to the quintic and octic "
                "Bezier nets of the alpha -> 0 limit, by the computed general conversion. Left: the control points "
                "r, g, b (discs) and the Bezier points p_{d,e,f} (hollow squares) on one triangle; for two Bezier "
                "points (yellow squares) the control points that enter (ringed) are joined to them (line width ~ "
                "weight; a ringed disc inside the yellow square sits at the Bezier point itself). Right: "
                "their weights as a table (p_{2,1,5} and p_{3,2,3} are printed with an erratum).")
def make_conversion(outdir: Path) -> list[Path]:
    fig = conversion_figure()
    return [save(fig, outdir / "conversion_of_limit_cases_n_1_2_3.png")]


#: Where a label may go around its point (offset in points), tried in this order: the first whose box touches no
#: line and no marker of the panel is taken.
LABEL_OFFSETS = [(12, 10), (12, -18), (-40, 10), (-40, -18), (-14, 22), (-14, -30), (20, -4), (-48, -4)] + [
    (int(round(r * np.cos(a))) - 14, int(round(r * np.sin(a))) - 5) for r in (26, 34, 44)
    for a in np.radians(np.arange(0, 360, 22.5))]


def _segments_px(ax) -> list[np.ndarray]:
    """Every line of ``ax`` in display pixels (markers as their own tiny segments)."""
    out = []
    for line in ax.get_lines():
        xy = ax.transData.transform(np.asarray(line.get_xydata(), float))
        if line.get_linestyle() not in ("None", "none", "") and len(xy) >= 2:
            out += [xy[i:i + 2] for i in range(len(xy) - 1)]
        if line.get_marker() not in ("None", "none", "", None):
            r = line.get_markersize() / 72 * ax.figure.dpi / 2
            out += [np.array([p - (r, 0), p + (r, 0)]) for p in xy] + [np.array([p - (0, r), p + (0, r)]) for p in xy]
    return out


def _hits(box, segments: list[np.ndarray], samples: int = 60) -> bool:
    """Whether any segment has a point inside ``box`` (a matplotlib Bbox in pixels, grown by 2 px)."""
    x0, y0, x1, y1 = box.x0 - 2, box.y0 - 2, box.x1 + 2, box.y1 + 2
    t = np.linspace(0, 1, samples)[:, None]
    for seg in segments:
        pts = seg[0] * (1 - t) + seg[1] * t
        if np.any((pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)):
            return True
    return False


def place_labels(fig, requests: list[tuple]) -> list:
    """Boxed labels ``(ax, text, xy)`` each at the first offset of :data:`LABEL_OFFSETS` where its box lies on no
    line, no marker and no label placed before (after the layout is final, so pixels are the saved ones)."""
    renderer = fig.canvas.get_renderer()
    placed, boxes = [], []
    for ax, text, xy in requests:
        segs = _segments_px(ax)
        for off in LABEL_OFFSETS:
            ann = ax.annotate(text, xy, xytext=off, textcoords="offset points", fontsize=14, zorder=6,
                              bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="0.5"))
            # the text's extent grown by the box's padding (0.15 of the font size) and its edge
            box = ann.get_window_extent(renderer).padded(0.15 * 14 / 72 * fig.dpi + 1)
            if not _hits(box, segs) and not any(box.overlaps(b) for b in boxes):
                break
            ann.remove()
        else:
            raise ValueError(f"no free place for the label {text} at {xy}: add an offset to LABEL_OFFSETS")
        placed.append(ann)
        boxes.append(box)
    return placed


def conversion_figure():
    """The figure of :func:`make_conversion` (not saved)."""
    from paper_repro.theory.limits import conversion_matrix

    labels_to_place: list[tuple] = []
    fig, axes = plt.subplots(2, 2, figsize=(15, 15.5), gridspec_kw={"width_ratios": [1.55, 1]})
    for row, n in enumerate((2, 3)):
        ax, tab = axes[row]
        labels = united_system(n)
        pos = np.array([position(lab) for lab in labels])
        idx, w = conversion_matrix(n)
        N = sum(idx[0])
        # Bezier points on the same triangle as the graph (corner u left, w right, v top)
        bez = {t: np.array([t[1] * 0.5 + t[2] * 1.0, t[1] * np.sqrt(3) / 2]) / N for t in idx}
        for a, b in edges(n):
            pa, pb = position(a), position(b)
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.88", lw=0.8, zorder=0)
        for p in bez.values():
            ax.plot(*p, "s", ms=8, mfc="none", mec="0.25", mew=1.0, zorder=2)
        for lab, p in zip(labels, pos):
            ax.plot(*p, "o", ms=7, color=_color(lab), zorder=3)
        rows = []
        for t in CONVERSION_SHOWN[n]:
            weights = [(f, wt) for f, wt in enumerate(w[idx.index(t)]) if wt != 0]
            for f, wt in weights:
                ax.plot(*np.stack([pos[f], bez[t]]).T, color=_color(labels[f]), lw=0.8 + 5 * float(wt), alpha=0.7,
                        zorder=1, solid_capstyle="round")
                ax.plot(*pos[f], "o", ms=11, mfc="none", mec="black", mew=1.2, zorder=5)
            # hollow and under the discs, so that a control point at the same place stays visible
            ax.plot(*bez[t], "s", ms=17, mfc="#fff3b0", mec="#d4a800", mew=2.5, zorder=2.5)
            labels_to_place.append((ax, f"$p_{{{t[0]},{t[1]},{t[2]}}}$", bez[t]))
            rows.append((t, [(labels[f], wt) for f, wt in weights]))
        ax.set_title(f"({'ab'[n - 2]}) order {n} → Bézier degree {N}", fontsize=15)
        ax.set_aspect("equal")
        ax.set_xlim(-0.04, 1.04)
        ax.set_ylim(-0.05, np.sqrt(3) / 2 + 0.05)
        ax.axis("off")
        # the table of weights
        tab.axis("off")
        y = 0.97
        tab.text(0.0, y, "Bézier point = Σ weight × control point", fontsize=14, weight="bold", va="top",
                 transform=tab.transAxes)
        y -= 0.08
        for t, terms in rows:
            tab.text(0.0, y, f"$p_{{{t[0]},{t[1]},{t[2]}}}$ =", fontsize=15, va="top", transform=tab.transAxes)
            y -= 0.065
            for lab, wt in terms:
                tab.text(0.08, y, _frac(wt), fontsize=14, va="top", ha="left", transform=tab.transAxes)
                tab.text(0.30, y, f"${lab.control_point}$", fontsize=14, va="top", color=_color(lab),
                         transform=tab.transAxes)
                y -= 0.055
            y -= 0.04
        tab.text(0.0, y, "discs: control points (R red, G green,\nB blue, centre orange); hollow squares:\n"
                 "Bézier points; yellow: the two spelled out", fontsize=12, va="top", color="0.25",
                 transform=tab.transAxes)
    fig.tight_layout()
    place_labels(fig, labels_to_place)
    return fig


def _demo_net_order_1() -> np.ndarray:
    """A fixed 3D order-1 control net: the graph layout lifted by fixed heights."""
    lift = {"R_{2,1,1}": 1.2, "R_{2,2,0}": 0.0, "R_{2,1,0}": 0.6, "G_{2,2,0}": 0.0, "G_{2,1,0}": 0.9,
            "B_{2,2,0}": 0.0, "B_{2,1,0}": 0.3}
    return np.array([[*position(lab), lift[lab.paper]] for lab in united_system(1)])


@figure("degree_elevation_from_1_to_2", paper_label="fig:degree_elevation_from_1_to_2",
        outputs=["degree_elevation_from_1_to_2.png"],
        caption="Order elevation 1 -> 2 of a first order patch for (a) alpha = pi/4 < pi/2, (b) alpha = pi/2, "
                "(c) alpha = 3pi/4 > pi/2: the order-1 net (blue), the elevated order-2 net (red) and the patch "
                "(grey, opaque, smoothly shaded); net parts hidden by the patch are dashed in a light tint of their "
                "net's colour.")
def make_elevation(outdir: Path) -> list[Path]:
    from .render3d import Scene, View

    fig, axes = plt.subplots(1, 3, figsize=(16, 5.6))
    net1 = _demo_net_order_1()
    for k, (ax, (alpha, name)) in enumerate(zip(axes, ((np.pi / 4, "π/4"), (np.pi / 2, "π/2"),
                                                       (3 * np.pi / 4, "3π/4")))):
        v, f = Patch(1, alpha, net1).mesh(24)
        sc = Scene(View(28, -60))
        sc.surface(v, f, "#cfcfcf")
        sc.net(net1, net_edges(1), "#1f5fbf", line_color="#1f5fbf", size=40)
        sc.net(elevate(net1, 1, alpha), net_edges(2), "#d62728", line_color="#d62728", size=20)
        sc.draw(ax)
        ax.set_title(f"({'abc'[k]}) α = {name}", fontsize=14)
        if k == 0:
            ax.plot([], [], "o-", color="#1f5fbf", label="order 1")
            ax.plot([], [], "o-", color="#d62728", ms=4, label="order 2 (elevated)")
            ax.legend(fontsize=12, loc="upper left")
    fig.tight_layout()
    return [save(fig, outdir / "degree_elevation_from_1_to_2.png")]


@figure("elevation_convergence", claims=["order_elevation", "elevation_all_n"], outputs=["elevation_convergence.png"],
        caption="New: repeated order elevation (a convex combination at every step, proven for every n: claim "
                "elevation_all_n) of random nets of orders n = 1, 2, 3 at three alpha: the largest distance between a "
                "control point and the patch point at its node, versus the number k of elevation steps (from claim "
                "order_elevation). The rate (about 1/k) is observed, not proven; whether elevation factors into "
                "corner-cutting steps is open.")
def make_elevation_convergence(outdir: Path) -> list[Path]:
    claims = {c["id"]: c for c in json.loads((data_dir() / "claims.json").read_text())}
    rec = claims["order_elevation"]["measured"]["repeated_elevation_net_to_patch_distance"]["by_steps"]
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

    alphas = sorted({k.split("alpha=")[1] for k in rec}, key=lambda a: Fraction(a[len("4 atan("):-1]))
    fig, axes = plt.subplots(1, len(alphas), figsize=(13, 4.6), sharey=True)
    colors = {"1": "#1f77b4", "2": "#d62728", "3": "#2ca02c"}
    lo, hi = np.inf, 0.0
    for ax, a in zip(np.atleast_1d(axes), alphas):
        for key, dist in rec.items():
            if not key.endswith(f"alpha={a}"):
                continue
            n0 = key.split(",")[0].split("=")[1]
            d = np.array(dist, dtype=float)
            k = np.arange(len(d)) + 1  # k + 1 on the log axis: the net itself at k = 0
            ax.loglog(k, d, "o-", color=colors.get(n0, "k"), ms=4, label=f"n = {n0}")
            lo, hi = min(lo, d.min()), max(hi, d.max())
            if n0 == "1":
                ax.loglog(k, d[1] * (k / 2.0) ** -1.0, "--", color="0.5", lw=1, label="slope -1 (1/k)")
        ticks = [1, 2, 3, 5, 8, 11]
        ax.xaxis.set_major_locator(FixedLocator(ticks))
        ax.xaxis.set_minor_locator(NullLocator())
        ax.set_xticklabels([str(t - 1) for t in ticks])
        ax.set_xlabel("elevation steps k (log scale of k + 1)", fontsize=11)
        ax.set_title(f"α = {a}", fontsize=12)
        ax.grid(alpha=0.3, which="both")
        ax.tick_params(labelsize=10)
    yt = [m * 10.0**e for e in range(-6, 3) for m in (1, 2, 5) if lo / 1.2 <= m * 10.0**e <= hi * 1.2]
    first = np.atleast_1d(axes)[0]
    first.yaxis.set_major_locator(FixedLocator(yt))
    first.yaxis.set_minor_locator(NullLocator())
    first.set_yticklabels([f"{y:g}" for y in yt])
    first.yaxis.set_minor_formatter(NullFormatter())
    first.set_ylabel("max distance control point – patch", fontsize=11)
    first.legend(fontsize=10)
    fig.tight_layout()
    return [save(fig, outdir / "elevation_convergence.png")]
