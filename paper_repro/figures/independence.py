"""Figures of Section sec:linear_independence, computed from the actual derivatives.

Every function of T_{2n} is a product U(u) V(v) W(w) of powers of half-angle sines and cosines, so
its derivatives along the parametrizations of the proof factor: derivatives at 0 are exact
(:mod:`paper_repro.theory.derivatives`), derivatives at a generic interior point are evaluated with mpmath.

* ``derivative_scheme_n_4``: for k = 0..4, which functions have a vanishing 4th order mixed partial
  d^4/dv^{4-k} dw^k at y = 0 under parametrization_for_partition_of_unity (black) or not (coloured);
  grey: functions whose sin(v/2) power exceeds 4 - k.
* ``linear_independence_j_0`` and ``linear_independence_j_1__j_n_minus_1``: the successive elimination
  steps of the proof (parametrizations parametrization_1_y_0, _2_x_0, _3_y_0 in turn, derivative
  order r = 0, 1, ..., n-1): coloured = non-vanishing (their coefficients are forced to 0), black =
  vanishing, white = eliminated before.  The script checks that only the centre survives.
* ``singular_values``: new -- singular value spectra of the normalized collocation matrices.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from paper_repro.core.labels import exponents, united_system
from paper_repro.core.layout import position
from paper_repro.theory import elimination as _elimination
from paper_repro.theory.elimination import deriv_at_0
from paper_repro.util.registry import figure

from . import COLOR_OF, plt, save


def shaded_area(points: np.ndarray, radius: float, m: int = 24) -> np.ndarray:
    """The convex hull of ``points`` grown by ``radius`` (rounded corners): the grey area around the functions
    present in an equality (caption of Figs. 4 and 5)."""
    from scipy.spatial import ConvexHull

    ang = np.linspace(0, 2 * np.pi, m, endpoint=False)
    ring = radius * np.c_[np.cos(ang), np.sin(ang)]
    cloud = (points[:, None, :] + ring[None, :, :]).reshape(-1, 2)
    hull = ConvexHull(cloud)
    return cloud[hull.vertices]


def _draw_step(ax, n: int, step: dict, title: str) -> None:
    labels = united_system(n)
    alive = np.array([position(labels[k]) for k in sorted(step["alive_before"])])
    ax.fill(*shaded_area(alive, 0.045).T, color="0.88", zorder=0, lw=0)
    for k, lab in enumerate(labels):
        p = position(lab)
        if k not in step["alive_before"]:
            ax.plot(*p, "o", ms=7, mfc="white", mec="0.6")
        elif k in step["nonvanishing"]:
            ax.plot(*p, "o", ms=7, color=COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color])
        else:
            ax.plot(*p, "o", ms=7, color="black")
    ax.set_title(title, fontsize=11)
    ax.set_aspect("equal")
    ax.axis("off")


def elimination(n: int) -> list[dict]:
    """The steps of the proof (:func:`paper_repro.theory.elimination.elimination`) along the printed
    parametrizations: their geometry is computed from the transcriptions
    (:func:`paper_repro.claims.lines.sec1_3.elimination_geometry`, the one definition)."""
    from paper_repro.claims.lines.sec1_3 import elimination_geometry

    return _elimination.elimination(n, elimination_geometry())


def _steps_figure(n: int, rows: list[int], path: Path) -> Path:
    steps = elimination(n)
    from paper_repro.util.paper_labels import pdf_name

    fig, axes = plt.subplots(len(rows), 3, figsize=(11, 4.1 * len(rows)), squeeze=False)
    letters = "abcdefghi"
    for a, order in enumerate(rows):
        for b, st in enumerate(s for s in steps if s["r"] == order):
            # the paper's induction index r counts from 0: step r takes derivatives of order r + 1
            what = "values (order 0)" if order == 0 else f"r = {order - 1}: order-{order} derivatives"
            _draw_step(axes[a, b], n, st, f"({letters[3 * a + b]}) {what}\nunder {pdf_name(st['param'])}")
    fig.suptitle(f"n = {n}: coloured = non-vanishing (coefficient forced to 0), black = vanishing,\n"
                 "white = eliminated in an earlier step; grey area = the functions present in the equality",
                 fontsize=12)
    return save(fig, path)


@figure("linear_independence_j_0", paper_label="fig:linear_independence_j_0",
        outputs=["linear_independence_j_0.png"],
        caption="Zeroth order step of the proof for n = 4 under the three parametrizations, computed from the "
                "functions' values on the boundary; the grey shrinking areas hold the functions present in each "
                "equality.")
def make_j0(outdir: Path) -> list[Path]:
    return [_steps_figure(4, [0], outdir / "linear_independence_j_0.png")]


@figure("linear_independence_j_1__j_n_minus_1", paper_label="fig:linear_independence_j_1__j_n_minus_1",
        outputs=["linear_independence_j_1__j_n_minus_1.png"],
        caption="The induction steps r = 0 (first-order derivatives) and r = n - 2 (order n - 1 derivatives) of the "
                "proof for n = 4, computed from the actual derivatives; after the last step only the centre "
                "R_{8,4,4} survives; the grey shrinking areas hold the functions present in each equality.")
def make_j1(outdir: Path) -> list[Path]:
    return [_steps_figure(4, [1, 3], outdir / "linear_independence_j_1__j_n_minus_1.png")]


@figure("derivative_scheme_n_4", paper_label="fig:derivative_scheme_n_4", outputs=["derivative_scheme_n_4.png"],
        caption="n = 4: black = the 4th order mixed partial d^4/dv^(4-k) dw^k vanishes at y = 0 under "
                "parametrization_for_partition_of_unity, coloured = it does not; grey discs: sin(v/2) power > 4-k.")
def make_scheme(outdir: Path, n: int = 4) -> list[Path]:
    labels = united_system(n)
    fig, axes = plt.subplots(2, 3, figsize=(13, 9))
    axes = axes.ravel()
    axes[5].axis("off")
    for k, ax in enumerate(axes[:5]):
        for lab in labels:
            e = exponents(lab)
            p = position(lab)
            v_zero = deriv_at_0(e, 1, 4 - k) == 0
            w_const = k > 0 and e[4] == 0 and e[5] == 0
            if e[2] > 4 - k:
                ax.plot(*p, "o", ms=13, color="0.85", zorder=1)
            color = "black" if (v_zero or w_const) else (COLOR_OF["centre"] if lab.is_centre else COLOR_OF[lab.color])
            ax.plot(*p, "o", ms=6, color=color, zorder=2)
        ax.set_title(rf"({'abcde'[k]}) $\partial^4/\partial v^{{{4 - k}}}\partial w^{{{k}}}$", fontsize=14)
        ax.set_aspect("equal")
        ax.axis("off")
    _scheme_key(axes[5])
    return [save(fig, outdir / "derivative_scheme_n_4.png")]


def _scheme_key(ax) -> None:
    """The key of derivative_scheme_n_4 in its empty sixth panel: dots and the grey halo."""
    from matplotlib.legend_handler import HandlerTuple
    from matplotlib.lines import Line2D

    def dot(color, ms=6):
        return Line2D([], [], ls="none", marker="o", ms=ms, color=color)

    halo = (dot("0.85", 13), dot("black"))  # drawn one over the other, as in the panels
    handles = [dot("black"), (dot(COLOR_OF["R"]), dot(COLOR_OF["G"]), dot(COLOR_OF["B"]), dot(COLOR_OF["centre"])),
               halo]
    labels = ["the 4th order derivative\nvanishes at y = 0",
              "it does not vanish\n(colour of the function's family)",
              "grey halo: the function has the\nfactor sin(v/2) to a power > 4 − k,\n"
              "the order of the derivative in v\n(so the derivative vanishes at y = 0)"]
    ax.legend(handles, labels, handler_map={halo: HandlerTuple(ndivide=1), tuple: HandlerTuple(ndivide=None, pad=0.6)},
              loc="center left", fontsize=11.5, frameon=False, handlelength=3.2, labelspacing=1.4,
              title="key (panels (a)-(e): k = 0, ..., 4)",
              title_fontsize=12, alignment="left")


def _pretty_alpha(text: str) -> str:
    """'5pi/6' -> '5π/6' (the figures write π, as the paper does)."""
    return text.replace("pi", "π").replace("*", "")


@figure("singular_values", claims=["linear_independence"], outputs=["singular_values.png"],
        caption="New: singular values of the normalized collocation matrices (mpmath, 50 digits) for n = 1..4 at "
                "alpha = pi/6 and 5pi/6 (left); condition number versus n for the five alpha of claim "
                "linear_independence (right, from data/claims.json).")
def make_singular_values(outdir: Path) -> list[Path]:
    import json

    from paper_repro.core.alphas import alpha_float
    from paper_repro.theory.rank import collocation_singular_values
    from paper_repro.util.io import data_dir

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 11))
    for a_text, ls in (("pi/6", "-"), ("5pi/6", "--")):
        for n in (1, 2, 3, 4):
            sv = collocation_singular_values(n, a_text, 50, 5)  # computed by claim linear_independence
            ax1.semilogy(np.arange(1, len(sv) + 1), [float(s) for s in sv], ls,
                         label=f"n = {n}, α = {_pretty_alpha(a_text)}")
    ax1.set_xlabel("index")
    ax1.set_ylabel("singular value")
    ax1.legend(fontsize=11, ncol=2)
    ax1.xaxis.label.set_fontsize(12)
    ax1.yaxis.label.set_fontsize(12)
    ax1.grid(alpha=0.3)
    claims = {c["id"]: c for c in json.loads((data_dir() / "claims.json").read_text())}
    rows = claims["linear_independence"]["measured"]["numeric"]
    for a_text in sorted({r["alpha"] for r in rows}, key=alpha_float):
        sel = [r for r in rows if r["alpha"] == a_text]
        ax2.semilogy([r["n"] for r in sel], [float(r["condition"]) for r in sel], "o-",
                     label=f"α = {_pretty_alpha(a_text)}")
    ax2.set_xlabel("order n")
    ax2.set_ylabel("condition number (n > 4: certified upper bound)")
    ax2.legend(fontsize=11)
    ax2.xaxis.label.set_fontsize(12)
    ax2.yaxis.label.set_fontsize(12)
    ax2.grid(alpha=0.3)
    return [save(fig, outdir / "singular_values.png")]
