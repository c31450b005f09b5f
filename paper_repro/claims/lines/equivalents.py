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
