"""Layout of T_{2n} on the triangle (Fig. oriented_graph): node positions and the graph's edges.

A function with half-angle sine exponents (a, b, c) of u, v, w sits at the barycentric point
(a, b, c)/(a + b + c) of the triangle whose corners carry sin^{2n}(u/2), sin^{2n}(v/2), sin^{2n}(w/2).
Edges (a reconstruction; the paper's drawing is not in the source): consecutive functions along a side
of a level triangle, oriented towards the middle, and from level j to level j+1, oriented inwards.
Shared by claims and figures.
"""

from __future__ import annotations

import numpy as np

from paper_repro.core.labels import COLORS, BasisLabel, exponents, index_of

CORNERS = {"u": np.array([0.0, 0.0]), "w": np.array([1.0, 0.0]), "v": np.array([0.5, np.sqrt(3) / 2])}


def barycentric(lab: BasisLabel) -> np.ndarray:
    """The node of a function over the domain, as barycentric ``(x, y, z)`` (the point alpha (x, y, z) of
    Omega^alpha): its half-angle sine exponents (a, b, c) of u, v, w over their sum -- exact ratios, no solve.

    >>> from paper_repro.core.labels import BasisLabel
    >>> barycentric(BasisLabel("R", 2, 1, 0)).tolist()   # R_{4,3,0} = sin^3(u/2) sin(w/2): 3/4 of the way to u
    [0.75, 0.0, 0.25]
    """
    e = exponents(lab)
    a, b, c = int(e[0]), int(e[2]), int(e[4])
    return np.array([a, b, c], dtype=np.float64) / (a + b + c)


def position(lab: BasisLabel) -> np.ndarray:
    """The node of a function in the drawing plane of Fig. 1 (``fig:oriented_graph``): the barycentric point of
    :func:`barycentric` on the triangle whose corners are :data:`CORNERS` -- the corner of
    :math:`\\sin^{2n}(u/2)` at (0, 0), of :math:`\\sin^{2n}(w/2)` at (1, 0), of :math:`\\sin^{2n}(v/2)` at the top.

    >>> from paper_repro.core.labels import BasisLabel
    >>> position(BasisLabel("R", 1, 0, 0)).tolist()   # R_{2,2,0} = sin^2(u/2): the corner u = alpha
    [0.0, 0.0]
    >>> position(BasisLabel("R", 1, 1, 1)).round(4).tolist()   # the centre R_{2,1,1}: the centroid
    [0.5, 0.2887]
    """
    x, y, z = barycentric(lab)
    return x * CORNERS["u"] + y * CORNERS["v"] + z * CORNERS["w"]


def edges(n: int) -> list[tuple[BasisLabel, BasisLabel]]:
    """Directed edges (from, to) of the reconstructed weighted graph of order n."""
    out = []
    for color in COLORS:
        for j in range(n):
            for i in range(j, 2 * n - j):  # side edge between i and i+1, oriented towards i = n
                a, b = BasisLabel(color, n, i, j), BasisLabel(color, n, i + 1, j)
                out.append((a, b) if i < n else (b, a))
            for i in range(j + 1, 2 * n - j):  # inward edge to level j+1: the inner nodes j+1 <= i <= 2n-j-1
                out.append((BasisLabel(color, n, i, j), BasisLabel(color, n, i, j + 1)))
    return out


def net_edges(n: int) -> list[tuple[int, int]]:
    """The edges of the control net of order n (Fig. 1, ``fig:oriented_graph``, and Fig. 6,
    ``fig:associated_control_net``) as directed pairs ``(from, to)`` of row indices of the net (the order of
    :func:`~paper_repro.core.labels.united_system`; a corner or the centre named by two colours is one row).

    Each colour contributes, on every level j = 0..n-1 (the nested triangles), the 2n - 2j edges between
    consecutive nodes of its side, oriented towards the middle of the side, and the 2n - 2j - 1 edges from the
    inner nodes of that side to level j + 1, oriented inwards: :math:`6n^2 + 3n` edges, bounding
    :math:`3n^2` quadrilaterals.

    >>> len(net_edges(1)), len(net_edges(2)), len(net_edges(3))
    (9, 30, 63)
    >>> net_edges(1)[:3]   # r_{2,2,0} -> r_{2,1,0} <- r_{2,0,0}, and r_{2,1,0} -> the centre r_{2,1,1}
    [(1, 2), (3, 2), (2, 0)]
    """
    ix = index_of(n)
    out: list[tuple[int, int]] = []
    for a, b in edges(n):
        pair = (ix[a.name], ix[b.name])
        if pair not in out:
            out.append(pair)
    return out


