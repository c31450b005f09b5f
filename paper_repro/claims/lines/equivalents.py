"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

# -- part sec7 (Sections 7-8; helper wt-sec7) ----------------------------------------------------------------------
EQUIVALENT.update({
    "sec7-elev-b430:swap:9f487ddc7e": (
        "r <-> g in [r, g, b]_{4,3,0} = 1/2 [r, g, b]_{2,2,0} + 1/2 [r, g, b]_{2,1,0}: every term has the colours in "
        "the same order, so the swap only exchanges the first two rows of the vector equation; each row is still "
        "a printed row (g_{4,3,0} = 1/2 g_{2,2,0} + 1/2 g_{2,1,0} etc.)"),
    "sec7-elev-b440:swap:e5844da0bc": (
        "r <-> g in [r, g, b]_{4,4,0} = [r, g, b]_{2,2,0}: exchanges the first two rows of the vector equation, "
        "which stay the true rows g_{4,4,0} = g_{2,2,0} and r_{4,4,0} = r_{2,2,0}"),
    "sec7-limit-degenerate-bernstein:swap:2b7b110b57": (
        "x <-> y in the simplex equation x+y+z=1 gives y+x+z=1, the same plane (addition is commutative)"),
    "sec7-square-of-unity:swap:60c7b932f4": (
        "G <-> B in (R_{2,1,1} + R_{2,2,0} + R_{2,1,0} + G_{2,2,0} + G_{2,1,0} + B_{2,2,0} + B_{2,1,0})^2 lists the "
        "same seven functions in another order: the sum, and its square, are unchanged"),
    "sec7-first-order-products:word:f718a70a9e": (
        "'first order products into linear combinations of third order blending functions' is true as well: span "
        "T-bar_4 is contained in span T-bar_6 (order elevation, claim elevation_all_n), so the products of T-bar_2 "
        "lie in span T-bar_6; the check finds this (ranks mod p) and says so"),
})
