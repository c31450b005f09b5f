"""Figure scripts (registered in :mod:`paper_repro.util.registry`) and their shared helpers.

Figures are written as PNG with fixed metadata (no timestamps), so reruns give identical bytes.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from paper_repro.util.io import atomic_path  # noqa: E402

COLOR_OF = {"R": "#d62728", "G": "#2ca02c", "B": "#1f5fbf", "centre": "#ff9900"}
DPI = 110


def save(fig, path: Path) -> Path:
    """Save ``fig`` atomically as PNG without run-dependent metadata, then close it."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=DPI, metadata={"Software": None}, bbox_inches="tight")
    plt.close(fig)
    return path
