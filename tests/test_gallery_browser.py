"""The gallery in a real browser (headless Chromium): images load, 3D views draw, no console error, no
network request.  Skipped, saying why, where no Chromium can be had (`make check-gallery INSTALL=1` installs it)."""

import pytest

from paper_repro.app import check_gallery
from paper_repro.util.io import FIGURES


def test_gallery_in_headless_chromium(tmp_path):
    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip(check_gallery.HOW_TO_GET)
    res = check_gallery.check(FIGURES / "index.html", tmp_path / "gallery.png")
    assert res["images"] >= 17 and not res["images_not_loaded"], res
    assert set(res["views"]) == {"view-torus", "view-dupin", "view-third", "view-slider"} and not res["views_blank"]
    assert res["views_clipped"] == {}, res["views_clipped"]  # Fig. 7's view was cut off at the bottom
    assert not res["views_caption_names_a_missing_legend"] and not res["views_title_not_shown"], res
    assert not res["console_errors"] and not res["external_requests"], res
    assert (tmp_path / "gallery.png").stat().st_size > 0


def test_blank_detection_can_fail():
    import io

    import matplotlib.pyplot as plt
    import numpy as np

    for data, blank in ((np.ones((20, 20, 3)), True), (np.random.default_rng(0).random((20, 20, 3)), False)):
        buf = io.BytesIO()
        plt.imsave(buf, data, format="png")
        assert check_gallery._blank(buf.getvalue()) is blank


def test_clipped_view_and_missing_legend_are_caught(tmp_path):
    """A view whose camera is too close (data cut off at the frame), a caption naming a legend the view does not
    show, and a title given the way plotly.js no longer shows it: check() reports each."""
    import json

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip(check_gallery.HOW_TO_GET)
    mesh = {"type": "mesh3d", "x": [0, 1, 0, 0], "y": [0, 0, 1, 0], "z": [0, 0, 0, 1], "i": [0, 0, 0, 1],
            "j": [1, 1, 2, 2], "k": [2, 3, 3, 3], "color": "#4c78a8", "name": "net (toggle)"}
    near = {"margin": {"l": 0, "r": 0, "t": 30, "b": 0}, "height": 400, "title": "a plain-string title",
            "scene": {"aspectmode": "data", "camera": {"eye": {"x": 0.4, "y": -0.4, "z": 0.3}},
                      **{f"{a}axis": {"visible": False} for a in "xyz"}}}
    far = {**near, "title": {"text": "shown"}, "showlegend": True,
           "scene": {**near["scene"], "camera": {"eye": {"x": 2.2, "y": -2.2, "z": 1.6}}}}
    vendor = (FIGURES / "vendor" / "plotly.min.js").resolve().as_uri()
    views = "".join(f'<figure><div class="view" id="view-{k}"></div><figcaption>{cap}</figcaption></figure>'
                    f"<script>Plotly.newPlot('view-{k}',{json.dumps([mesh])},{json.dumps(lay)})</script>"
                    for k, lay, cap in (("near", near, "toggle the net from the legend"), ("far", far, "plain")))
    page = tmp_path / "index.html"
    page.write_text(f'<!DOCTYPE html><html><head><script src="{vendor}"></script></head><body>{views}</body></html>')
    res = check_gallery.check(page, tmp_path / "shot.png")
    assert set(res["views_clipped"]) == {"view-near"}, res["views_clipped"]
    assert res["views_caption_names_a_missing_legend"] == ["view-near"]
    assert res["views_title_not_shown"] == ["view-near"]
