"""Figure ``float_accuracy``: errors of the float64 path against the mp route versus alpha (from the data
that claim ``float_accuracy`` published)."""

from __future__ import annotations

import json
import math
from pathlib import Path

from paper_repro.util.io import data_dir
from paper_repro.util.registry import figure

from . import plt, save


@figure("float_accuracy", claims=["float_accuracy"], outputs=["float_accuracy.png"],
        caption="New: accuracy of the float64 path against mpmath (30 digits) for n = 1..6 and alpha in "
                "[1e-3, pi - 1e-3]: left, max |sum of the blending values - 1|; right, max error of patch points "
                "relative to the net (random nets); each error drawn as the next power of ten above it (the published, "
                "machine-independent value). Dashed: the 1e-13 bound of claim float_accuracy.")
def make_accuracy(outdir: Path) -> list[Path]:
    rows = json.loads((data_dir() / "accuracy" / "float_vs_mp.json").read_text())["rows"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
    cmap = plt.get_cmap("viridis")
    ns = sorted({r["n"] for r in rows})
    floor = 1e-18
    for ax, key, title in ((axes[0], "partition_of_unity_below", "partition of unity: max |Σ − 1|"),
                           (axes[1], "patch_relative_below", "patch points: max error / max |net|")):
        for k, n in enumerate(ns):
            sel = [r for r in rows if r["n"] == n]
            ax.loglog([r["alpha"] for r in sel], [max(r[key], floor) for r in sel], "o-", ms=3.5, lw=1.3,
                      color=cmap(k / max(1, len(ns) - 1)), label=f"n = {n}")
        ax.axhline(1e-13, color="0.3", ls="--", lw=1)
        ax.set_xlabel("α (log scale)", fontsize=12)
        ax.set_title(title, fontsize=12)
        ax.set_xticks([1e-3, 1e-2, 1e-1, 1, math.pi], ["10⁻³", "10⁻²", "10⁻¹", "1", "π"])
        ax.tick_params(labelsize=11)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel(f"error ≤ (power of ten; 0 drawn at {floor:g})", fontsize=11)
    axes[1].legend(fontsize=11, ncol=2)
    return [save(fig, outdir / "float_accuracy.png")]
