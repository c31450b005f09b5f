"""Every text of every figure is readable at the gallery's display size: the smallest font, converted to CSS
pixels at the width the gallery shows the PNG, is at least 10 px (subscripts are about 0.7 of that)."""

import json

import pytest

from paper_repro.figures import GALLERY_WIDTH_PX, text_sizes
from paper_repro.util.io import FIGURES
from paper_repro.util.registry import FIGURES as REGISTRY
from paper_repro.util.registry import load_all

load_all()
MIN_PX = 10.0


@pytest.mark.parametrize("fid", sorted(REGISTRY))
def test_text_readable_at_gallery_size(fid):
    for png in REGISTRY[fid].outputs:
        side = FIGURES / png.replace(".png", ".text.json")
        rec = json.loads(side.read_text())
        if rec["min_text_px"] is None:
            continue  # a figure without text (3D surfaces)
        assert rec["min_text_px"] >= MIN_PX, (fid, rec["smallest"])


def test_the_measure_can_fail():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(20, 2))
    ax.text(0.5, 0.5, "tiny", fontsize=5)
    sizes = dict(text_sizes(fig, 2200))
    plt.close(fig)
    assert sizes["tiny"] < MIN_PX  # 5 pt at 110 dpi, scaled by 1040/2200
    assert GALLERY_WIDTH_PX == 1040
