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

from paper_repro.util.io import atomic_path, write_json  # noqa: E402

COLOR_OF = {"R": "#d62728", "G": "#2ca02c", "B": "#1f5fbf", "centre": "#ff9900"}
DPI = 110
#: Width (CSS px) at which the gallery shows a figure: the page's content width.
GALLERY_WIDTH_PX = 1040


def text_sizes(fig, png_width_px: int) -> list[tuple[str, float]]:
    """Every visible text of ``fig`` with its height in CSS px as the gallery shows it (the PNG is scaled
    down to :data:`GALLERY_WIDTH_PX` when wider)."""
    from matplotlib.text import Text

    scale = min(1.0, GALLERY_WIDTH_PX / png_width_px)
    hidden = set()  # tick labels of axes drawn without axes (ax.axis("off")) are not shown
    for ax in fig.axes:
        if not ax.axison:
            for axis in [a for a in (getattr(ax, n, None) for n in ("xaxis", "yaxis", "zaxis")) if a is not None]:
                hidden |= {id(t) for t in axis.get_ticklabels(which="both")}
                hidden.add(id(axis.label))
    out = []
    for t in fig.findobj(Text):
        shown = (t.get_visible() and t.get_text().strip() and id(t) not in hidden
                 and (t.axes is None or t.axes.get_visible()))
        if shown:
            out.append((t.get_text().strip()[:40], round(t.get_fontsize() / 72 * DPI * scale, 2)))
    return out


def save(fig, path: Path) -> Path:
    """Save ``fig`` atomically as PNG and, beside it, SVG (vector), without run-dependent metadata; close it."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=DPI, metadata={"Software": None}, bbox_inches="tight")
        import matplotlib.image as mpimg

        width = mpimg.imread(tmp).shape[1]
    sizes = text_sizes(fig, width)
    write_json(path.with_suffix(".text.json"), {"png_width_px": width, "gallery_width_px": GALLERY_WIDTH_PX,
                                                "min_text_px": min((h for _, h in sizes), default=None),
                                                "smallest": sorted(sizes, key=lambda x: x[1])[:5]})
    with atomic_path(path.with_suffix(".svg")) as tmp:
        fig.savefig(tmp, format="svg", metadata={"Date": None, "Creator": None}, bbox_inches="tight")
    plt.close(fig)
    return path
