"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

# -- Section 3 (sec:linear_independence, source lines >= 462; worktree sec3) ------------------------------------
EQUIVALENT.update({
    'sec1_3-L-R-row:sign:939eec8c60': (
        'the outer bound of a double sum moved from n-1 to n+1: for j >= n the inner range i = j..2n-1-j is '
        'empty, so the sum names the same functions (constants) -- the line states the same'
    ),
    'sec1_3-L-coefficients:sign:fb438eeba0': (
        'the outer bound of a double sum moved from n-1 to n+1: for j >= n the inner range i = j..2n-1-j is '
        'empty, so the sum names the same functions (constants) -- the line states the same'
    ),
    'sec1_3-Lr1-row2:sign:809405929b': (
        'the outer bound of a double sum moved from n-1 to n+1: for j >= n the inner range i = j..2n-1-j is '
        'empty, so the sum names the same functions (constants) -- the line states the same'
    ),
    'sec1_3-Ltilde-row3:sign:3aa7465600': (
        'the outer bound of a double sum moved from n-1 to n+1: for j >= n the inner range i = j..2n-1-j is '
        'empty, so the sum names the same functions (constants) -- the line states the same'
    ),
    'sec1_3-kterm-B-high:constant:baff6fa84f': (
        'outer bound n-1 -> n-2 of sum_{j}^{} sum_{i=n+1}^{2n-1-j}: for j = n-1 the inner range i = n+1..n is '
        'empty, so the row names the same functions with the same factors'
    ),
    'sec1_3-kterm-B-high:swap:05f930bed7': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-kterm-B-low:swap:d8de7f4d52': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-kterm-G-high:swap:cf42850860': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-kterm-G-low:swap:e161212485': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-kterm-R-high:swap:35c927e06e': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-kterm-R-low:swap:eed58fcce4': (
        'i <-> j swapped everywhere in the row: a consistent renaming of the two summation variables (bound '
        'variables), the same sum'
    ),
    'sec1_3-lemma-hypotheses:constant:d372b99a36': (
        "'greater than or equal to $2$': a narrower hypothesis (i, j >= 2) under which the sign rules still "
        'hold (they hold for every i, j >= 1); the line keeps its slip (p >= 2 against the sets p >= 0) and '
        'its correction (drop p from the hypothesis) still holds'
    ),
})

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

# --- part sec6 (Section 6, sec:applications; issue 37, helper of sec6) ---------------------------------------------
# A set {x_{2n,2n-i,j}}_{j=0,i=j}^{J,2n-1-j} has no point with j >= n (i runs j..2n-1-j, empty for j >= n), so an
# upper bound J of n - 1, n or n + 1 names the same points (the same holds for the double sums over l, k of tau).
_SEC6_EMPTY_ROWS = ("the inner range i = j..2n-1-j is empty for j >= n, so j = 0..n+1 names the same points (sums) "
                    "as j = 0..n-1: the mutated line says exactly what the printed one says")
_SEC6_RENAMED = ("i <-> j renames the two bound summation variables consistently (bounds and indices): the same "
                 "double sum")
_SEC6_ORDER_3 = ("order elevation: V_2 is contained in V_3 (every order-2 patch is an order-3 patch), and the check "
                 "computes the exact order-3 fits; the mutated line has the same truth value (and the same correction)")
EQUIVALENT.update({
    "sec6-alpha-range:constant:750c673ac6": "alpha in (1, pi) is a sub-interval of (0, pi): the patch has a free shape "
                                            "parameter there too (a narrower range keeps the statement true)",
    "sec6-control-net-set:swap:579ab4efeb": "r <-> g: the r set has j = 0..n and the g set j = 0..n-1; the row "
                                            "j = n is "
                                            "empty (i = n..n-1), so the swapped union names the same points "
                                            "(equally lacking the centre r_{2n,n,n})",
    "sec6-rational-control-net-set:swap:579ab4efeb": "r <-> g: as in def:surface_patch, the row j = n is empty, so the "
                                                     "swapped union names the same points",
    "sec6-rational-control-net-set:sign:9a7bedb23f": _SEC6_EMPTY_ROWS,
    "sec6-weights-set:sign:a22a495200": _SEC6_EMPTY_ROWS,
    "sec6-tau-row-1:sign:50db01fe54": _SEC6_EMPTY_ROWS,
    "sec6-weights-rank1:swap:9d2cba391c": _SEC6_RENAMED,
    "sec6-corners:swap:5029a23cda": "r <-> g reorders the listed corners r, g, b_{2n,2n,0}: the same set of three "
                                    "corners",
    "sec6-convex-hull-n123:word:cfc23724ab": "first, second and fourth order: the normalizing coefficients of order "
                                             "4 are "
                                             "positive for every alpha in (0, pi) (claim nonnegativity_extended proves "
                                             "n <= 12), so the convex hull property holds for order 4 too",
    "sec6-dupin-phases:constant:f77489e7bb": "[0, 3pi] contains a full period [0, 2pi] of eq. Dupin_in_3d in varphi: "
                                             "every patch position is still reached (a wider range keeps it true)",
    "sec6-dupin-phases:word:d59f6cc1ac": "the operator turns 2\\pi into 22\\pi: [0, 22pi] contains a full period of "
                                         "eq. Dupin_in_3d in varphi (a wider range keeps it true)",
    "sec6-dupin-phases:constant:79acb0afd8": "[0, 3pi] for psi contains a full period [0, 2pi] of eq. Dupin_in_3d in "
                                             "psi: every patch position is still reached",
    "sec6-control-net-set:sign:ecfdf1bd0b": _SEC6_EMPTY_ROWS,
    "sec6-weights-set:sign:b6c0453f60": _SEC6_EMPTY_ROWS,
    "sec6-patch-row-1:sign:7b1d164b63": _SEC6_EMPTY_ROWS,
    "sec6-patch-row-2:sign:55a073e9a7": _SEC6_EMPTY_ROWS,
    "sec6-patch-row-1:swap:132c73c944": _SEC6_RENAMED,
    "sec6-patch-row-2:swap:90cb498d1f": _SEC6_RENAMED,
    "sec6-rational-row-1:swap:bc0b164db7": _SEC6_RENAMED,
    "sec6-rational-row-2:swap:d80a1622d5": _SEC6_RENAMED,
    "sec6-rational-row-3:swap:6213ed5454": _SEC6_RENAMED,
    "sec6-dupin-rational-patches:word:f9e8a0c439": _SEC6_ORDER_3,
    "sec6-torus-joined:constant:ee21dfebbb": _SEC6_ORDER_3,
    "sec6-torus-order2:word:f553a054a6": _SEC6_ORDER_3,
})
