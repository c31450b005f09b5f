"""Figure scripts (registered in :mod:`paper_repro.util.registry`) and their shared helpers.

Figures are written as PNG and SVG with fixed metadata (no timestamps; a fixed SVG hash salt), so
reruns give identical bytes.  Logarithmic axes take their logarithms from libm (:class:`LibmLogScale`, registered
as matplotlib's ``"log"`` scale), not from numpy's ufuncs, whose SIMD code depends on the CPU (on AVX512
machines numpy's ``log10``/``exp`` are Intel SVML, not the AVX2 or SSE code other machines run: a log-log panel
then differs in a pixel or two, ``make test-bits-numpy-dispatch``).
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "paper_repro"  # deterministic SVG element ids
matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text (small, searchable files)
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.scale import InvertedLogTransform, LogScale, LogTransform, register_scale  # noqa: E402

from paper_repro.util.io import atomic_path, write_json  # noqa: E402


def _elementwise(values, func) -> np.ndarray:
    """``func`` applied to every element of ``values`` as a Python float (same shape; a mask is kept)."""
    arr = np.asarray(values, dtype=np.float64)
    out = np.array([func(x) for x in arr.ravel().tolist()], dtype=np.float64).reshape(arr.shape)
    return np.ma.array(out, mask=np.ma.getmask(values)) if np.ma.isMaskedArray(values) else out


class LibmLogTransform(LogTransform):
    """matplotlib's log transform with the logarithm of libm (``math.log10`` on Python floats) instead of numpy's
    ``log10`` ufunc, whose result depends on the SIMD code numpy dispatches to on the running CPU.

    >>> t = LibmLogTransform(10)
    >>> t.transform_non_affine(np.array([1e-3, 1.0, 0.0, -1.0])).tolist()
    [-3.0, 0.0, -1000.0, -1000.0]
    >>> t.inverted().transform_non_affine(np.array([-3.0, 0.5])).tolist() == [10.0 ** -3.0, 10.0 ** 0.5]
    True
    """

    def _log(self, x: float) -> float:
        if not x > 0:  # zero, negative or nan: numpy's log10 gives -inf or nan, clipped like matplotlib's
            return -1000.0 if self._clip and x <= 0 else (-math.inf if x == 0 else math.nan)
        if self.base == 10:
            return math.log10(x)
        if self.base == 2:
            return math.log2(x)
        return math.log(x) if self.base == math.e else math.log(x) / math.log(self.base)

    def transform_non_affine(self, values):
        return _elementwise(values, self._log)

    def inverted(self):
        return LibmInvertedLogTransform(self.base)


class LibmInvertedLogTransform(InvertedLogTransform):
    """The inverse of :class:`LibmLogTransform`: ``base ** x`` by libm's ``pow`` on Python floats."""

    def _exp(self, x: float) -> float:
        try:
            return math.pow(self.base, x)
        except OverflowError:
            return math.inf

    def transform_non_affine(self, values):
        return _elementwise(values, self._exp)

    def inverted(self):
        return LibmLogTransform(self.base)


class LibmLogScale(LogScale):
    """matplotlib's ``"log"`` scale (``loglog``, ``semilogy``, ``set_yscale("log")``) with :class:`LibmLogTransform`:
    the same pixels on every CPU whatever numpy's SIMD dispatch (registered under the name ``"log"`` when this
    package is imported, so every figure of paper_repro uses it)."""

    name = "log"

    def __init__(self, *, base: float = 10, subs=None, nonpositive: str = "clip") -> None:
        super().__init__(base=base, subs=subs, nonpositive=nonpositive)
        self._transform = LibmLogTransform(base, nonpositive)


register_scale(LibmLogScale)

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
