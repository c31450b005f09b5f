"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

# -- Section 5, sec:partition_of_unity (claims/lines/sec5.py; worktree sec5) ----------------------------------------
EQUIVALENT.update({
    "sec4_5-parametrization-restated:bound:c94899d3f0":
        "orders r = 1..n-1 instead of 1..n: the rewritten equality (the chain sum = 0) holds at every order r >= 1, "
        "since L = 1 identically on Omega^alpha and every y-derivative of order >= 1 of L vanishes; a shorter list "
        "of orders states less and stays true",
    "sec4_5-level0-c-c:bound:70e017c361":
        "i = 0..n-1 instead of 0..n: a subset of the printed range; c_{2n,2n-i} = c_{2n,i} holds for every i = 0..2n "
        "(the coefficients of X^{2n-i}Y^i and X^iY^{2n-i} of the symmetric (X^2 + 2cXY + Y^2)^n), so the narrower "
        "statement stays true",
    "sec4_5-symmetry-1:sign:847c54dc71":
        "j = 0..n+1 instead of 0..n-1: for j >= n-1 the range i = j+1..n-1 is empty, so the added j add no "
        "condition; the set of conditions is unchanged",
    "sec4_5-symmetry-1:constant:ea030d2bda":
        "j = 0..n-2 instead of 0..n-1: the dropped j = n-1 has the empty range i = n..n-1; the set of conditions is "
        "unchanged",
    "sec4_5-symmetry-2:sign:447c1f71c1":
        "j = 0..n+1 instead of 0..n-1: for j = n, n+1 the range i = j..2n-1-j is empty; the set of conditions is "
        "unchanged",
    "sec4_5-weights:sign:dd6689803e":
        "the b-set's j bound n+1 instead of n-1: for j = n, n+1 the range i = j..2n-1-j is empty, so the index set "
        "{b_{2n,2n-i,j}} is the same set",
})
