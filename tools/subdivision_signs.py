"""Where the corner entry of claim subdivision_all_n comes from (issue 38, item 2: the signs of S_k).

For each n given, the exact entry S_u[G_{2n,2n-1,1}, G_{2n,2n-1,0}] of the corner matrix (the sub-net's level-1
point next to the midline, weighted by the parent's point on the opposite edge) is computed at 22 rational-tangent
alpha and interpolated as a rational function of c = cos(alpha/2) of the smallest degree that reproduces every
remaining alpha; it is printed beside the closed form c (c - 1) / (2^{n+1} (1 + c)^n ((n - 1) c + n))
(:func:`paper_repro.claims.subdivision.corner_entry`, negative for every alpha in (0, pi)) and compared exactly at
all 22 alpha.  This is how the closed form was found (evidence); it is now proven for every n and alpha by hand
(Corollary W of docs/subdivision_for_all_n.md, section 9).

Run: ``python tools/subdivision_signs.py 2 3 4`` (n = 5 takes about a minute).
"""

from __future__ import annotations

import sys

import sympy as sp
from flint import fmpq

from paper_repro.claims.subdivision import corner_entry
from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import index_of
from paper_repro.core.subdivision import subdivision_matrix

C = sp.Symbol("c")
TS = ["1/20", "1/9", "1/7", "1/5", "1/4", "1/3", "2/5", "3/7", "1/2", "4/7", "3/5", "2/3", "5/7", "3/4", "4/5",
      "5/6", "6/7", "7/8", "8/9", "9/10", "10/11", "11/12"]


def samples(n: int) -> list[tuple[fmpq, fmpq]]:
    """(c, exact entry) at the 22 alpha of :data:`TS`."""
    idx = index_of(n)
    row, col = idx[f"G_{{{2 * n},{2 * n - 1},1}}"], idx[f"G_{{{2 * n},{2 * n - 1},0}}"]
    out = []
    for t in TS:
        alpha = rational_alpha(fmpq(*map(int, t.split("/"))))
        out.append((alpha.cos_half, subdivision_matrix(n, alpha, "u", "exact")[row, col]))
    return out


def interpolate(points: list[tuple[fmpq, fmpq]]):
    """The rational function of c of the smallest degree through the first 2 deg + 1 points and every other one."""
    pts = [(sp.Rational(int(c.p), int(c.q)), sp.Rational(int(x.p), int(x.q))) for c, x in points]
    for deg in range(1, (len(pts) - 3) // 2 + 1):
        f = sp.polys.polyfuncs.rational_interpolate(pts[:2 * deg + 1], deg, X=C)
        if all(f.subs(C, c) == x for c, x in pts[2 * deg + 1:]):
            return sp.factor(f)
    return None


if __name__ == "__main__":
    for n in [int(x) for x in sys.argv[1:]] or [2, 3, 4]:
        pts = samples(n)
        same = all(x == corner_entry(n, c) for c, x in pts)
        print(f"n = {n}: interpolated {interpolate(pts)}; equals the closed form at all {len(pts)} alpha: {same}",
              flush=True)
