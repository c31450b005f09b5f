"""The control net's layout (Fig. 1, ``fig:oriented_graph``; Fig. 6, ``fig:associated_control_net``):
which points are connected, and where each sits over the domain.

The expected edges are written by hand from the paper's description, not from ``core/layout.py``: the nodes
sit on n nested triangles (levels j = 0..n-1) around the centre; the three outermost nodes store
sin^{2n}(u/2), sin^{2n}(v/2), sin^{2n}(w/2); every path from an outermost node ends at the centre; and the
net's "faces" are quadrangular (the Remark after Fig. 6).
"""

from __future__ import annotations

import numpy as np
import pytest

import paper_repro as pr
from paper_repro.core.labels import index_of, united_system

# The R colour's edges, read off the drawing (side nodes R_{2n,2n-i,j}, i = j..2n-j, oriented towards the
# middle of the side; inner side nodes connected to the node of the same i one level in).  G and B follow by
# the cyclic rotation of the colours (the symmetry of Fig. 1(b)).
R_EDGES = {
    1: [("R_{2,2,0}", "R_{2,1,0}"), ("R_{2,0,0}", "R_{2,1,0}"),   # level 0, side v = 0
        ("R_{2,1,0}", "R_{2,1,1}")],                               # to the centre
    2: [("R_{4,4,0}", "R_{4,3,0}"), ("R_{4,3,0}", "R_{4,2,0}"),     # level 0, towards the middle R_{4,2,0}
        ("R_{4,0,0}", "R_{4,1,0}"), ("R_{4,1,0}", "R_{4,2,0}"),
        ("R_{4,3,1}", "R_{4,2,1}"), ("R_{4,1,1}", "R_{4,2,1}"),     # level 1
        ("R_{4,3,0}", "R_{4,3,1}"), ("R_{4,2,0}", "R_{4,2,1}"),     # level 0 -> level 1
        ("R_{4,1,0}", "R_{4,1,1}"),
        ("R_{4,2,1}", "R_{4,2,2}")],                                # level 1 -> the centre
}


def expected_edges(n: int) -> set[tuple[int, int]]:
    ix = index_of(n)
    return {(ix[a.replace("R", c)], ix[b.replace("R", c)]) for c in "RGB" for a, b in R_EDGES[n]}


@pytest.mark.parametrize("n", [1, 2])
def test_net_edges_by_hand(n):
    got = pr.net_edges(n)
    assert len(got) == len(set(got))
    assert set(got) == expected_edges(n)


@pytest.mark.parametrize("n", range(1, 7))
def test_net_edges_count_and_quadrangles(n):
    """Per colour and level j: 2n - 2j side edges and 2n - 2j - 1 inward ones, so 6n^2 + 3n edges; with
    delta_n = 3n(n+1) + 1 nodes, Euler's formula on the disc gives 3n^2 faces, and 4 * 3n^2 = 2E - 6n (the 6n
    boundary edges counted once): every face is a quadrilateral."""
    edges = pr.net_edges(n)
    assert len(edges) == 6 * n * n + 3 * n
    faces = len(edges) - pr.delta(n) + 1
    assert faces == 3 * n * n and 4 * faces == 2 * len(edges) - 6 * n
    assert {k for e in edges for k in e} == set(range(pr.delta(n)))  # every control point is on the net


@pytest.mark.parametrize("n", range(1, 6))
def test_every_path_ends_at_the_centre(n):
    """Directed: the centre (row 0) has no outgoing edge, and every node reaches it."""
    out: dict[int, list[int]] = {}
    for a, b in pr.net_edges(n):
        out.setdefault(a, []).append(b)
    assert 0 not in out
    for start in range(pr.delta(n)):
        seen, todo = set(), [start]
        while todo:
            k = todo.pop()
            if k not in seen:
                seen.add(k)
                todo += out.get(k, [])
        assert 0 in seen


@pytest.mark.parametrize("n", range(1, 5))
def test_edges_are_short_and_positions_distinct(n):
    """Over the domain, a side edge joins nodes 1/(2n) of a side apart, and an inward edge is no longer."""
    labels = united_system(n)
    pos = np.array([pr.position(lab) for lab in labels])
    assert len({tuple(p.round(9)) for p in pos}) == pr.delta(n)
    lengths = [np.linalg.norm(pos[a] - pos[b]) for a, b in pr.net_edges(n)]
    assert max(lengths) <= 1 / (2 * n) + 1e-12 and min(lengths) > 0.2 / (2 * n)


def test_corners_and_boundary_rows():
    """Eqs. (R_system_leq_n) ff. at i = j = 0: R_{2n,2n,0} = sin^{2n}(u/2) sits at the corner u = alpha
    (barycentric (1, 0, 0)), G_{2n,2n,0} = sin^{2n}(w/2) at w = alpha, B_{2n,2n,0} = sin^{2n}(v/2) at
    v = alpha; the boundary v = 0 carries the r_{2n,2n-i,0}, i = 0..2n (the list after Definition 6.1)."""
    n = 3
    ix = index_of(n)
    bary = {lab.name: pr.barycentric(lab) for lab in united_system(n)}
    assert bary["R_{6,6,0}"].tolist() == [1.0, 0.0, 0.0]
    assert bary["G_{6,6,0}"].tolist() == [0.0, 0.0, 1.0]
    assert bary["B_{6,6,0}"].tolist() == [0.0, 1.0, 0.0]
    rows = [ix[f"r_{{6,{6 - i},0}}"] for i in range(7)]
    on_v0 = [k for k, lab in enumerate(united_system(n)) if pr.barycentric(lab)[1] == 0]
    assert sorted(rows) == sorted(on_v0)


def test_patch_plot_draws_net_and_surface():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    net = np.random.default_rng(0).normal(size=(pr.delta(3), 3))
    ax = pr.Patch(3, "pi/2", net).plot(labels=True)
    assert len(ax.lines) == len(pr.net_edges(3)) == 63
    assert len(ax.texts) == 37
    ax2 = pr.Patch(3, "pi/2", net).plot(net=False)
    assert len(ax2.lines) == 0 and len(ax2.collections) == 1
    with pytest.raises(ValueError, match="3-D"):
        pr.Patch(1, 1.0, np.zeros((7, 2))).plot()
    plt.close("all")
