"""Figure ``float_accuracy``: errors of the float64 path against the mp route versus alpha (from the data
that claim ``float_accuracy`` published).

The published values are decades (the smallest power of ten at or above each error), so the figure is a table:
one cell per order n and alpha, its exponent written in it and its colour keyed by decade.  Lines through such
values read as noise, and series of equal values hide each other.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from paper_repro.util.io import data_dir
from paper_repro.util.registry import figure

from . import plt, save

#: The cell colour of each published decade (exponent k of 10^k; None: an error of exactly 0).
DECADE_COLORS = {None: "#ffffff", -17: "#e5f5e0", -16: "#c7e9c0", -15: "#fdd49e", -14: "#fc8d59", -13: "#d7301f"}


def exponent(value: float) -> int | None:
    """The k of a published decade 10^k (None for 0).

    >>> exponent(1e-15), exponent(0.0)
    (-15, None)
    """
    if value == 0:
        return None
    k = round(math.log10(value))
    if float(f"1e{k}") != value:
        raise ValueError(f"value {value!r} is not a power of ten (the data publishes decades)")
    return k


def alpha_text(alpha: float) -> str:
    """alpha as a column label: 3 significant digits, pi - x near pi.

    >>> alpha_text(0.001), alpha_text(1.5), alpha_text(3.140592653589793)
    ('0.001', '1.5', 'π−0.001')
    """
    if alpha > 3.0:
        return f"π−{math.pi - alpha:.2g}"
    return f"{alpha:.3g}"


@figure("float_accuracy", claims=["float_accuracy"], outputs=["float_accuracy.png"],
        caption="New: accuracy of the float64 path against mpmath (30 digits) for n = 1..6 and 24 values of alpha in "
                "[1e-3, pi - 1e-3], as a table: (a) max |sum of the blending values - 1|; (b) max error of patch "
                "points relative to the net (random nets). Each cell holds the exponent k of the published decade "
                "10^k, the smallest power of ten at or above the error (a machine-independent value); the colour "
                "keys the decade. The claim's bound is 1e-13 (k = -13).")
def make_accuracy(outdir: Path) -> list[Path]:
    rows = json.loads((data_dir() / "accuracy" / "float_vs_mp.json").read_text())["rows"]
    ns = sorted({r["n"] for r in rows})
    alphas = sorted({r["alpha"] for r in rows})
    fig, axes = plt.subplots(2, 1, figsize=(13, 7.6))
    used: set = set()
    for ax, key, title in ((axes[0], "partition_of_unity_below", "(a) partition of unity: max |Σ − 1| ≤ $10^k$"),
                           (axes[1], "patch_relative_below", "(b) patch points: max error / max |net| ≤ $10^k$")):
        cell = {(r["n"], r["alpha"]): exponent(r[key]) for r in rows}
        if len(cell) != len(ns) * len(alphas):
            raise ValueError(f"float_accuracy data: {len(cell)} cells, expected every n times every alpha")
        for i, n in enumerate(ns):
            for j, a in enumerate(alphas):
                k = cell[(n, a)]
                if k not in DECADE_COLORS:
                    raise ValueError(f"float_accuracy figure: no colour for the decade 1e{k} (n = {n}, alpha = {a})")
                used.add(k)
                ax.add_patch(plt.Rectangle((j, i), 1, 1, facecolor=DECADE_COLORS[k], edgecolor="white", lw=1.5))
                ax.text(j + 0.5, i + 0.5, "0" if k is None else f"−{-k}", ha="center", va="center", fontsize=11)
        ax.set_xlim(0, len(alphas))
        ax.set_ylim(len(ns), 0)
        ax.set_yticks(np.arange(len(ns)) + 0.5, [f"n = {n}" for n in ns])
        ax.set_xticks(np.arange(len(alphas)) + 0.5, [alpha_text(a) for a in alphas], rotation=60, ha="right",
                      rotation_mode="anchor")
        ax.tick_params(length=0, labelsize=10.5)
        ax.tick_params(axis="y", labelsize=11.5)
        for side in ax.spines.values():
            side.set_visible(False)
        ax.set_title(title, fontsize=13, loc="left")
    axes[1].set_xlabel("α (columns: the 24 values of the claim's grid, dense near 0 and π)", fontsize=12)
    handles = [plt.Rectangle((0, 0), 1, 1, facecolor=DECADE_COLORS[k], edgecolor="0.6")
               for k in sorted(used, key=lambda k: -99 if k is None else k)]
    labels = ["0 (exact)" if k is None else f"k = −{-k}: error ≤ 1e{k}" for k in sorted(used, key=lambda k: -99
                                                                                         if k is None else k)]
    fig.legend(handles, labels, loc="upper right", ncol=len(handles), fontsize=11.5, frameon=False,
               title="cell colour (bound of claim float_accuracy: 1e-13)", title_fontsize=11.5,
               bbox_to_anchor=(0.99, 1.02))
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return [save(fig, outdir / "float_accuracy.png")]
