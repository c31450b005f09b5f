"""The gallery in a real browser (headless Chromium): images load, 3D views draw, no console error, no
network request.  Skipped, saying why, where no Chromium can be had (`make check-gallery` installs it)."""

import pytest

from paper_repro.app import check_gallery
from paper_repro.util.io import FIGURES


def test_gallery_in_headless_chromium(tmp_path):
    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip("no chromium/chromedriver on this machine: run `make check-gallery` (installs Debian's chromium)")
    res = check_gallery.check(FIGURES / "index.html", tmp_path / "gallery.png")
    assert res["images"] >= 17 and not res["images_not_loaded"], res
    assert set(res["views"]) == {"view-torus", "view-dupin", "view-third", "view-slider"} and not res["views_blank"]
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
