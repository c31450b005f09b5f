"""Figure scripts (registered in :mod:`paper_repro.util.registry`) and their shared helpers.

Figures are written as PNG and SVG with fixed metadata (no timestamps; a fixed SVG hash salt), so
reruns give identical bytes.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "paper_repro"  # deterministic SVG element ids
matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text (small, searchable files)
import matplotlib.pyplot as plt  # noqa: E402

from paper_repro.util.io import atomic_path  # noqa: E402

COLOR_OF = {"R": "#d62728", "G": "#2ca02c", "B": "#1f5fbf", "centre": "#ff9900"}
DPI = 110


def save(fig, path: Path) -> Path:
    """Save ``fig`` atomically as PNG and, beside it, SVG (vector), without run-dependent metadata; close it."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=DPI, metadata={"Software": None}, bbox_inches="tight")
    with atomic_path(path.with_suffix(".svg")) as tmp:
        fig.savefig(tmp, format="svg", metadata={"Date": None, "Creator": None}, bbox_inches="tight")
    plt.close(fig)
    return path
