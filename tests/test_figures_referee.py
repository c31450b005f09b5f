"""What a referee looks at in the figures (issue 33, item 5): values readable, keys present, no label on a line, no
Markdown in titles, log axes with several labelled ticks.  Each figure is drawn (not saved) and its artists read."""

import json

import numpy as np
import pytest
from matplotlib.text import Text

from paper_repro.util.io import data_dir
from paper_repro.util.registry import FIGURES, load_all

load_all()


def drawn(fid, monkeypatch, tmp_path):
    """The matplotlib figure(s) that figure ``fid`` draws, caught at ``save``."""
    import importlib

    mod = importlib.import_module(FIGURES[fid].func.__module__)
    caught = []
    monkeypatch.setattr(mod, "save", lambda fig, path: caught.append(fig) or path)
    FIGURES[fid].func(tmp_path)
    assert caught
    return caught


def texts(fig) -> list[str]:
    return [t.get_text() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


def test_float_accuracy_shows_every_published_decade_as_a_number(monkeypatch, tmp_path):
    """A table, not lines: every (n, alpha) value of data/accuracy/float_vs_mp.json is written in a cell, for both
    quantities (the old line plot drew 288 values as overlapping lines; 0 was drawn at 1e-18 off the axis)."""
    (fig,) = drawn("float_accuracy", monkeypatch, tmp_path)
    rows = json.loads((data_dir() / "accuracy" / "float_vs_mp.json").read_text())["rows"]
    want = {}
    for panel, key in enumerate(("partition_of_unity_below", "patch_relative_below")):
        for r in rows:
            v = r[key]
            want[(panel, r["n"], r["alpha"])] = "0" if v == 0 else f"−{-round(np.log10(v))}"
    ns, alphas = sorted({r["n"] for r in rows}), sorted({r["alpha"] for r in rows})
    got = {}
    for panel, ax in enumerate(fig.axes[:2]):
        for t in ax.texts:
            x, y = t.get_position()
            got[(panel, ns[int(y)], alphas[int(x)])] = t.get_text()
    assert got == want
    assert not any(ax.get_lines() for ax in fig.axes)  # no line joins decades


def test_elevation_convergence_log_axis_has_several_labelled_ticks(monkeypatch, tmp_path):
    (fig,) = drawn("elevation_convergence", monkeypatch, tmp_path)
    ax = fig.axes[0]
    lo, hi = ax.get_ylim()
    shown = [t for t in ax.get_yticklabels() if t.get_text() and lo <= t.get_position()[1] <= hi]
    assert len(shown) >= 4, [t.get_text() for t in shown]  # was one (10^0)


def test_no_markdown_in_figure_texts(monkeypatch, tmp_path):
    (fig,) = drawn("oriented_graph", monkeypatch, tmp_path)
    assert not [t for t in texts(fig) if "`" in t]


def test_derivative_scheme_has_a_key_for_dots_and_grey_halos(monkeypatch, tmp_path):
    (fig,) = drawn("derivative_scheme_n_4", monkeypatch, tmp_path)
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    assert len(legends) == 1
    labels = " ".join(t.get_text() for t in legends[0].get_texts())
    assert "grey halo" in labels and "vanishes" in labels and "does not vanish" in labels


def test_conversion_labels_lie_on_no_line_and_no_marker(monkeypatch, tmp_path):
    """Each boxed label p_{d,e,f} of conversion_of_limit_cases_n_1_2_3 touches no drawn line or marker (checked
    with matplotlib's own path/box intersection; the old fixed offset put p_{2,1,5}'s box on a green weight line)."""
    from matplotlib.path import Path

    (fig,) = drawn("conversion_of_limit_cases_n_1_2_3", monkeypatch, tmp_path)
    renderer = fig.canvas.get_renderer()
    n_labels = 0
    for ax in fig.axes:
        for ann in [t for t in ax.texts if t.get_bbox_patch() is not None]:
            n_labels += 1
            box = ann.get_window_extent(renderer).padded(3)
            for line in ax.get_lines():
                xy = ax.transData.transform(np.asarray(line.get_xydata(), float))
                if len(xy) >= 2 and line.get_linestyle() not in ("None", "none", ""):
                    assert not Path(xy).intersects_bbox(box, filled=False), (ann.get_text(), xy)
                if line.get_marker() not in ("None", "none", "", None):
                    r = line.get_markersize() / 72 * fig.dpi / 2
                    for p in xy:
                        assert not (box.x0 - r <= p[0] <= box.x1 + r and box.y0 - r <= p[1] <= box.y1 + r), (
                            ann.get_text(), p)
    assert n_labels == 4


@pytest.mark.slow  # draws both 3D figures (the renderer's logic is tested fast in test_render3d.py)
@pytest.mark.parametrize("fid", ["degree_elevation_from_1_to_2", "third_order_patch"])
def test_3d_figures_shade_smoothly_and_dash_hidden_parts_in_their_nets_colours(fid, monkeypatch, tmp_path):
    from matplotlib.collections import LineCollection
    from matplotlib.colors import to_rgb

    from paper_repro.figures.render3d import GouraudTriangles

    (fig,) = drawn(fid, monkeypatch, tmp_path)
    for ax in fig.axes:
        assert [a for a in ax.get_children() if isinstance(a, GouraudTriangles)]
        solid = [c for c in ax.collections if isinstance(c, LineCollection) and c.get_linestyle()[0][1] is None]
        dashed = [c for c in ax.collections if isinstance(c, LineCollection) and c.get_linestyle()[0][1] is not None]
        assert len(solid) == len(dashed) >= 1
        for s, d in zip(solid, dashed):  # the hidden parts are a light tint of the same net's colour
            a, b = np.array(s.get_colors()[0][:3]), np.array(d.get_colors()[0][:3])
            assert np.allclose(b, a + 0.45 * (1 - a), atol=1e-6) and not np.allclose(a, to_rgb("0.55"))
