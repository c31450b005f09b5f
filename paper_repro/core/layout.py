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
    """The node of a function in the drawing plane of Fig. oriented_graph (corners :data:`CORNERS`)."""
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
            for i in range(j + 1, 2 * n - j):  # inward edge to level j+1
                if j + 1 <= i <= 2 * n - j - 1:
                    out.append((BasisLabel(color, n, i, j), BasisLabel(color, n, i, j + 1)))
    return out


def net_edges(n: int) -> list[tuple[int, int]]:
    """The graph's edges as pairs of internal indices of T_{2n} (aliases resolved, duplicates dropped)."""
    ix = index_of(n)
    out: list[tuple[int, int]] = []
    for a, b in edges(n):
        pair = (ix[a.name], ix[b.name])
        if pair not in out:
            out.append(pair)
    return out


