"""Section sec:RGB, verbatim: the printed G and B formulas (as exponent vectors), the printed
second-half relations and the six symmetry properties of Fig. oriented_graph(b)."""

from __future__ import annotations


def printed_g(n: int, i: int, j: int) -> tuple[int, ...]:
    """Printed G_{2n,2n-i,j}: i<=n: sin^{2n-i}(w/2) sin^i(v/2) cos^{i-j}(u/2) sin^j(u/2);
    i>n: sin^i(v/2) sin^{2n-i}(w/2) cos^{2n-i-j}(u/2) sin^j(u/2)."""
    if i <= n:
        return (j, i - j, i, 0, 2 * n - i, 0)
    return (j, 2 * n - i - j, i, 0, 2 * n - i, 0)


def printed_b(n: int, i: int, j: int) -> tuple[int, ...]:
    """Printed B_{2n,2n-i,j}: i<=n: sin^{2n-i}(v/2) sin^i(u/2) cos^{i-j}(w/2) sin^j(w/2);
    i>n: sin^i(u/2) sin^{2n-i}(v/2) cos^{2n-i-j}(w/2) sin^j(w/2)."""
    if i <= n:
        return (i, 0, 2 * n - i, 0, j, i - j)
    return (i, 0, 2 * n - i, 0, j, 2 * n - i - j)


# Variable substitutions as the argument tuples fed to a function of (u, v, w).
SWAP_UW, SWAP_VW, SWAP_UV = (2, 1, 0), (0, 2, 1), (1, 0, 2)

#: Printed second-half relations X_{2n,2n-i,j}(u,v,w) = X_{2n,i,j}(sigma) for i > n.
PRINTED_HALF = {"R": SWAP_UW, "G": SWAP_VW, "B": SWAP_UV}

#: Fig. oriented_graph(b): (substitution, family, image family).
SIX_PROPERTIES = [
    ("(w,u)", SWAP_UW, "R", "R"), ("(v,w)", SWAP_VW, "G", "G"), ("(u,v)", SWAP_UV, "B", "B"),
    ("(v,u)", SWAP_UV, "R", "G"), ("(u,w)", SWAP_UW, "G", "B"), ("(w,v)", SWAP_VW, "B", "R"),
]
