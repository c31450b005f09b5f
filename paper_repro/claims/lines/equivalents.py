"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

# -- Section 3 (sec:linear_independence, source lines >= 462; worktree sec3) ------------------------------------
EQUIVALENT.update({
    'sec1_3-delta-sum:swap:d10546374f': (
        'i <-> j swapped everywhere in delta_n = 1+3 sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} 1: a consistent renaming '
        'of the two summation variables (bound variables), the same sum (a former regular expression '
        'demanded the literal names j, i; the parsed sum is evaluated)'
    ),
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

# -- Sections 1-2 (worktree sec1_3, lines before tex line 462) -- equivalent mutants with their reasons ---------
EQUIVALENT['sec1_3-fourier-system:bound:b2b54a22da'] = (  # r=0,g=0,b=0 -> r=0,g=0,b=0+1
    'on Omega^alpha w = alpha-u-v, so (r,g,b) gives cos/sin((r-b)u+(g-b)v+b alpha); the frequencies of '
    '(r,g,0) are the negatives of those of (n-r,n-g,n), and the cosine and sine of opposite frequencies '
    '(any phase) span the same plane, so dropping one extreme value of one index (by the symmetry of the '
    'roles, any one) keeps the span and its dimension delta_n (exact ranks, n = 1..3)')
EQUIVALENT['sec1_3-fourier-system:bound:89e699c24a'] = (  # n,n,n -> n,n,n-1
    'on Omega^alpha w = alpha-u-v, so (r,g,b) gives cos/sin((r-b)u+(g-b)v+b alpha); the frequencies of '
    '(r,g,0) are the negatives of those of (n-r,n-g,n), and the cosine and sine of opposite frequencies '
    '(any phase) span the same plane, so dropping one extreme value of one index (by the symmetry of the '
    'roles, any one) keeps the span and its dimension delta_n (exact ranks, n = 1..3)')
EQUIVALENT['sec1_3-fourier-system:constant:8eea47d186'] = (  # 0 -> 1
    'on Omega^alpha w = alpha-u-v, so (r,g,b) gives cos/sin((r-b)u+(g-b)v+b alpha); the frequencies of '
    '(r,g,0) are the negatives of those of (n-r,n-g,n), and the cosine and sine of opposite frequencies '
    '(any phase) span the same plane, so dropping one extreme value of one index (by the symmetry of the '
    'roles, any one) keeps the span and its dimension delta_n (exact ranks, n = 1..3)')
EQUIVALENT['sec1_3-fourier-system:constant:7de7dbb143'] = (  # 0 -> 1
    'on Omega^alpha w = alpha-u-v, so (r,g,b) gives cos/sin((r-b)u+(g-b)v+b alpha); the frequencies of '
    '(r,g,0) are the negatives of those of (n-r,n-g,n), and the cosine and sine of opposite frequencies '
    '(any phase) span the same plane, so dropping one extreme value of one index (by the symmetry of the '
    'roles, any one) keeps the span and its dimension delta_n (exact ranks, n = 1..3)')
EQUIVALENT['sec1_3-c-symmetry:bound:722b40fcf7'] = (  # n -> n-1
    'i = n adds only c_{2n,n} = c_{2n,n}: the range i = 0..n-1 states the same symmetry')
EQUIVALENT['sec1_3-united-centre:swap:d21cc01296'] = (  # u <-> v
    'all three labels get the same permuted arguments, and R_{2n,n,n} = sin^n(u/2)sin^n(v/2)sin^n(w/2) is'
    ' symmetric in u, v, w: R = G = B at (v,u,w) is the same statement')
EQUIVALENT['sec1_3-united-centre:swap:2d6fbf3fc2'] = (  # v <-> w
    'all three labels get the same permuted arguments, and R_{2n,n,n} = sin^n(u/2)sin^n(v/2)sin^n(w/2) is'
    ' symmetric in u, v, w: R = G = B at (v,u,w) is the same statement')
EQUIVALENT['sec1_3-boundary-property-1:swap:79b2e10d9b'] = (  # u <-> v
    '{A_{2n,2n-i}(x)/c_{2n,2n-i}}_{i=0}^{2n} = {sin^i((alpha-x)/2) sin^{2n-i}(x/2)} is symmetric under x '
    '<-> alpha-x over the full range, so the restriction to u = 0 with argument v is as true (it is eq. '
    'boundary_property_2 up to that symmetry)')
EQUIVALENT['sec1_3-boundary-property-1:word:57a72cff4d'] = (  # boundary -> interior
    'the word operator changed only the name in \\label{boundary_property_k} (not a statement of the line)')
EQUIVALENT['sec1_3-boundary-property-2:swap:ba7ad9be0a'] = (  # u <-> w
    '{A_{2n,2n-i}(x)/c_{2n,2n-i}}_{i=0}^{2n} = {sin^i((alpha-x)/2) sin^{2n-i}(x/2)} is symmetric under x '
    '<-> alpha-x over the full range, so the restriction to w = 0 with argument u is as true')
EQUIVALENT['sec1_3-boundary-property-2:word:fbdae059fa'] = (  # boundary -> interior
    'the word operator changed only the name in \\label{boundary_property_k} (not a statement of the line)')
EQUIVALENT['sec1_3-boundary-property-3:swap:9676fd14f1'] = (  # v <-> w
    '{A_{2n,2n-i}(x)/c_{2n,2n-i}}_{i=0}^{2n} = {sin^i((alpha-x)/2) sin^{2n-i}(x/2)} is symmetric under x '
    '<-> alpha-x over the full range, so the restriction to v = 0 with argument w is as true')
EQUIVALENT['sec1_3-boundary-property-3:word:53aff2ed45'] = (  # boundary -> interior
    'the word operator changed only the name in \\label{boundary_property_k} (not a statement of the line)')
_CORNERS_SYMMETRIC = (
    "the three corner functions sin^{2n}(u/2), sin^{2n}(v/2), sin^{2n}(w/2) form a set invariant under every "
    "permutation of u, v, w, and the centre sin^n(u/2)sin^n(v/2)sin^n(w/2) is symmetric (which corner is drawn where "
    "is the figure's, an image not in the source)")
EQUIVALENT["sec1_3-corners-centre:swap:9300f4bd97"] = _CORNERS_SYMMETRIC  # u <-> v
EQUIVALENT["sec1_3-corners-centre:swap:6ce019135e"] = _CORNERS_SYMMETRIC  # v <-> w
_SAME_RENAMING = (
    "the same exchange of two variables on both sides of an identity over Omega^alpha (a set invariant under every "
    "permutation of u, v, w): X(pi x) = X'(sigma pi x) for all x is the printed X(x) = X'(sigma x) for all x")
for _key in ("sec1_3-R-geq-n-relation:swap:55ddd9a10c", "sec1_3-R-geq-n-relation:swap:232399d0ba",
             "sec1_3-G-geq-relation:swap:84e9e97303", "sec1_3-G-geq-relation:swap:b50a147834",
             "sec1_3-B-geq-relation:swap:bccbd9a055", "sec1_3-B-geq-relation:swap:cc85cea8c4"):
    EQUIVALENT[_key] = _SAME_RENAMING
EQUIVALENT["sec1_3-R-geq-n-explicit:sign:9ad822b6f9"] = (  # j up to n-1 -> n+1
    "j = n and j = n+1 add no index: i runs from n+1 to 2n-j, empty for j >= n, so the index set is the printed one")

# -- Section 4 (sec:coincidence, source lines 1414-1906): helper sec4 (issue 37) ------------------------------------
_SEC4: dict[str, str] = {
    'sec4_5-eight-terms:sign:156fc58e0b': (
        "s_3 ranges over {-1, +1}: s_2 C - s_3 D with s_3 = +-1 is s_2 C + s_3' D with s_3' = -s_3, the same set "
        'of forms'
    ),
    'sec4_5-eight-terms:swap:50fde95129': (
        "v and w exchanged in the product and in the form alike: 'each term of the expansion of this product has "
        "this form' is an identity of trigonometric polynomials, true for any names of the variables"
    ),
    'sec4_5-examples-n3-1:drop:ca5bceb868': (
        'the term +0 v dropped: 0u+1w ~ 1u+1v+0w is the same relation (a zero coefficient)'
    ),
    'sec4_5-examples-n3-1:swap:42226aaab5': (
        'u, v, w relabelled on both sides of 0u+0v+1w ~ 1u+1v+0w: ~ is invariant under the same permutation of '
        'both coefficient triples, the relabelled pair is still related'
    ),
    'sec4_5-examples-n3-1:swap:6f42a1c7bc': (
        'u, v, w relabelled on both sides of 0u+0v+1w ~ 1u+1v+0w: ~ is invariant under the same permutation of '
        'both coefficient triples, the relabelled pair is still related'
    ),
    'sec4_5-examples-n3-2:swap:ed266ec986': (
        'u, v, w relabelled in all three combinations of the chain: ~ is invariant under the same permutation of '
        'all coefficient triples, the chain stays true'
    ),
    'sec4_5-examples-n3-2:swap:fa9b742cb1': (
        'u, v, w relabelled in all three combinations of the chain: ~ is invariant under the same permutation of '
        'all coefficient triples, the chain stays true'
    ),
    'sec4_5-examples-n3-3:constant:18a163f54a': (
        'a coefficient raised by one in u+0v+0w vs v: (1,1,0)/(0,1,0), resp. (1,0,0)/(0,2,0), are not related '
        'either (no common sum or difference); the negated relation remains true'
    ),
    'sec4_5-examples-n3-3:constant:35ed1f37df': (
        'a coefficient raised by one in u+0v+0w vs v: (1,1,0)/(0,1,0), resp. (1,0,0)/(0,2,0), are not related '
        'either (no common sum or difference); the negated relation remains true'
    ),
    'sec4_5-examples-n3-3:drop:276968405f': (
        'a term dropped from one side of the negated relation: (1,0,0) and (0,0,0), resp. (1,0,0) and (0,1,0), '
        'are still not related; the line remains true'
    ),
    'sec4_5-examples-n3-3:drop:60101d96a9': (
        'a term dropped from one side of the negated relation: (1,0,0) and (0,0,0), resp. (1,0,0) and (0,1,0), '
        'are still not related; the line remains true'
    ),
    'sec4_5-examples-n3-3:sign:12a4f5d488': (
        '1u-0v+0w is 1u+0v+0w (a zero coefficient): the same statement'
    ),
    'sec4_5-examples-n3-3:swap:05c2cfdbd3': (
        'u, v, w relabelled on both sides: the relabelled triples are still not related (~ is invariant under the'
        ' same permutation of both triples)'
    ),
    'sec4_5-examples-n3-3:swap:a68210bc9d': (
        'u, v, w relabelled on both sides: the relabelled triples are still not related (~ is invariant under the'
        ' same permutation of both triples)'
    ),
    'sec4_5-max1-n:swap:648fae8aa2': (
        'i and j exchanged in (2n-i-1)/2 + (i-j)/2 + (j+1)/2 = n: (2n-j-1)/2 + (j-i)/2 + (i+1)/2 = n is still an '
        'identity'
    ),
    'sec4_5-max2-set:constant:c297386863': (
        's_1 = 1 -> s_1 = 2 in the quantifiers of the second max: s_1 does not occur in its expression, the set '
        'is unchanged (the erratum is that s_4, which occurs, is not quantified)'
    ),
    'sec4_5-max2-set:sign:dff0307e12': (
        'the sign of the s_2 term flipped: s_2 ranges over {-1, +1}, the set of values (and its max) is the same;'
        ' the line stays an erratum (s_4 unquantified) with the same correction'
    ),
    'sec4_5-n2-222:drop:2b71c34cbe': (
        'the term +0 v dropped from [0u+0v+0w]: the same class [0]'
    ),
    'sec4_5-n2-classes-row2:sign:4f67c395f8': (
        'the family {[2u-0v+bw]}_{b=0}^{1} is {[2u+0v+bw]}_{b=0}^{1} (a zero coefficient): the same classes; the old '
        'regular expression refused the minus sign, the reader reads the combination'
    ),
    'sec4_5-n2-classes-row3:sign:782291672d': (
        'the family {[ru+2v-0w]}_{r=0}^{1} is {[ru+2v+0w]}_{r=0}^{1} (a zero coefficient): the same classes; the old '
        'regular expression refused the minus sign, the reader reads the combination'
    ),
    'sec4_5-n2-222:sign:38424e3f74': (
        '0u-0v+0w is 0u+0v+0w (a zero coefficient): the same class [0]'
    ),
    'sec4_5-n2-222:swap:005e7da8fb': (
        'u, v, w relabelled inside the classes [2u+2v+2w] = [0u+0v+0w]: these coefficient triples are constant, '
        'the classes are the same'
    ),
    'sec4_5-n2-222:swap:059aea82fc': (
        'u, v, w relabelled inside the classes [2u+2v+2w] = [0u+0v+0w]: these coefficient triples are constant, '
        'the classes are the same'
    ),
    'sec4_5-n2-r0:constant:72c9be315e': (
        "one listed value of g changed ({1,1,2} or {0,2,2}): the claim '[gv+2w] is new at order 2' holds for each"
        ' listed g, the weakened line is still true'
    ),
    'sec4_5-n2-r0:constant:ba44915ed6': (
        "one listed value of g changed ({1,1,2} or {0,2,2}): the claim '[gv+2w] is new at order 2' holds for each"
        ' listed g, the weakened line is still true'
    ),
    'sec4_5-order1-relations:swap:a8fa333382': (
        'u, v, w relabelled in every relation of the line: the list u+v+w ~ 0, u+v ~ w, u+w ~ v, v+w ~ u is '
        'permuted into itself (~ is invariant under permutations of the coefficients)'
    ),
    'sec4_5-order1-relations:swap:f648b405fd': (
        'u, v, w relabelled in every relation of the line: the list u+v+w ~ 0, u+v ~ w, u+w ~ v, v+w ~ u is '
        'permuted into itself (~ is invariant under permutations of the coefficients)'
    ),
    'sec4_5-phase-meaning:swap:3135f75438': (
        'a relabelling of two of u, v, w in the whole line: the line is a statement for all related pairs of E_n '
        '(or all (u,v,w) in Omega^alpha), and E_n, the relation ~ and Omega^alpha are invariant under '
        'permutations of the variables, so the relabelled line is the same true statement'
    ),
    'sec4_5-phase-meaning:swap:35b53e2af0': (
        'a relabelling of two of u, v, w in the whole line: the line is a statement for all related pairs of E_n '
        '(or all (u,v,w) in Omega^alpha), and E_n, the relation ~ and Omega^alpha are invariant under '
        'permutations of the variables, so the relabelled line is the same true statement'
    ),
    'sec4_5-product-to-sum-1:swap:b9b7e0cf76': (
        'x and y exchanged: cos y cos x = (cos(y-x) + cos(y+x))/2 is the same identity (cos even)'
    ),
    'sec4_5-product-to-sum-2:swap:6121723678': (
        'x and y exchanged: sin y sin x = (cos(y-x) - cos(y+x))/2 is the same identity (cos even)'
    ),
    'sec4_5-product-to-sum-3:swap:701ba94632': (
        'x and y exchanged: sin y cos x = (sin(y+x) + sin(y-x))/2 is the identity itself for the variables '
        'renamed (true for all real x, y)'
    ),
    'sec4_5-product-type-1:swap:d0a5abb93b': (
        "v and w exchanged: for i, j even the span over the k's of cos((i-j-2k3)/2 t) cos((j-2k4)/2 t) is that of"
        ' cos((i-2m)/2 t), m = 0..i/2 (polynomials of parity i and degree <= i in cos(t/2)), the same as that of '
        'the w factor cos((i-2k2)/2 t), so the relabelled products span the same functions and R_{2n,2n-i,j} is '
        'still a sum of them'
    ),
    'sec4_5-product-type-2:swap:0ed83c00b1': (
        "v and w exchanged: for i, j odd the span over the k's of cos((i-j-2k3)/2 t) sin((j-2k4)/2 t) is that of "
        'sin((i-2m)/2 t), the same as that of the w factor sin((i-2k2)/2 t), so the relabelled products span the '
        'same functions and R_{2n,2n-i,j} is still a sum of them'
    ),
    'sec4_5-prop-new-classes:sign:8dd4d4e6c8': (
        'n u - 0 v + b w is n u + 0 v + b w (a zero coefficient): the same representatives'
    ),
    'sec4_5-prop-new-classes:swap:04fd8a63a5': (
        'two of u, v, w exchanged in the three families: the set E_n/~ minus the older classes is invariant under'
        ' permutations of the coefficients, and the relabelled families are again one representative of each new '
        'class (the check compares them with the class keys of the new classes, n = 1..10)'
    ),
    'sec4_5-prop-new-classes:swap:ade8dd8ec1': (
        'two of u, v, w exchanged in the three families: the set E_n/~ minus the older classes is invariant under'
        ' permutations of the coefficients, and the relabelled families are again one representative of each new '
        'class (the check compares them with the class keys of the new classes, n = 1..10)'
    ),
    'sec4_5-sin-step1:swap:a9ff3779ec': (
        'a relabelling of two of u, v, w in the whole line: the line is a statement for all related pairs of E_n '
        '(or all (u,v,w) in Omega^alpha), and E_n, the relation ~ and Omega^alpha are invariant under '
        'permutations of the variables, so the relabelled line is the same true statement'
    ),
    'sec4_5-sin-step1:swap:d6092bdadd': (
        'a relabelling of two of u, v, w in the whole line: the line is a statement for all related pairs of E_n '
        '(or all (u,v,w) in Omega^alpha), and E_n, the relation ~ and Omega^alpha are invariant under '
        'permutations of the variables, so the relabelled line is the same true statement'
    ),
}
EQUIVALENT.update(_SEC4)

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

# -- sec7-square-of-unity read by latex_math (helper readers_b): the exponents of "1^{2} = (sum)^{2}" ------------------
EQUIVALENT.update({
    "sec7-square-of-unity:bound:7747f939ee": (
        "1^{2} -> 1^{2-1}: 1^1 = 1 = 1^2, and the printed sum of the members of T-bar_2 is 1, so 1^{1} = (sum)^{2} "
        "still holds"),
    "sec7-square-of-unity:bound:2a5635bc29": (
        "(sum)^{2} -> (sum)^{2-1}: the printed sum of the members of T-bar_2 is 1, so (sum)^1 = 1 = 1^{2} still "
        "holds"),
})

# -- the last survivors of the whole run (make mutate-lines, every part) ---------------------------------------------
EQUIVALENT.update({
    "sec4_5-symmetry-1:bound:405957079c": (
        "a range of symmetry_condition_1 shortened by one: the mutated line lists a subset of the printed conditions "
        "r_{2n,2n-i,j} = r_{2n,i,j} (at j = n - 1 the range i = j+1..n-1 is empty anyway), each of which still holds; "
        "the line states something true and weaker, not something false"),
    "sec7-unity-product:bound:e9fc345c2c": (
        "1^{n+1} -> 1^{n}: both are 1, so the identity (the product of the two partitions of unity) reads the same"),
})

#: Survivors that no computation can decide from the source: the check reads the line, but what the mutant changes
#: is not in the paper's LaTeX (a figure that is missing, a citation of a report that is not available).  They are
#: counted as survivors; the report shows the reason.
UNCHECKABLE: dict[str, str] = {
    "sec6-fig-torus-settings:constant:536e0e567d": (
        "mu = 3 -> 4 in the caption of Fig. torus: the figure is missing from the source, and every other statement "
        "about the torus holds for any mu in (0, varrho); nothing in the paper fixes mu = 3"),
    "sec7-first-order-products:constant:e02412c077": (
        "'Lemma 5.1' -> 'Lemma 6.1' of the technical report [tech_report], which is not available"),
    "sec7-first-order-products:constant:1f7351e286": (
        "'Lemma 5.1' -> 'Lemma 5.2' of the technical report [tech_report], which is not available"),
}

# -- Section 3 (readers_a: the Sections 1-4 readers folded into latex_math) ---------------------------------------
EQUIVALENT["sec1_3-L-coefficients:swap:b23a9135d7"] = (  # i <-> j in the whole line
    "renaming the bound variables: {rho_{2n,2n-j,i}}_{i=0,j=i}^{n-1,2n-1-i} is the set {rho_{2n,2n-i,j}}_{j=0,i=j}"
    "^{n-1,2n-1-j} with i and j named the other way round (the same constants for every n); the line names the "
    "same coefficients")
# -- Section 7 (the list of control points read by latex_math.parse_list) ------------------------------
EQUIVALENT["sec7-elev-index-sets:swap:86ed7af3c5"] = (  # i <-> j in the whole line
    "renaming the bound variables: {r_{4,4-j,i}}_{i=0,j=i}^{1,3-i} is the set {r_{4,4-i,j}}_{j=0,i=j}^{1,3-j} with "
    "i and j named the other way round (and likewise for g, b): the line lists the same 19 control points")
EQUIVALENT["sec4_5-weights:swap:8db582f965"] = (  # i <-> j in the whole line
    "renaming the bound variables: {r_{2n,2n-j,i}}_{i=0,j=i}^{n-1,2n-1-i} is the set {r_{2n,2n-i,j}}_{j=0,i=j}"
    "^{n-1,2n-1-j} with i and j named the other way round (and likewise for g, b): the line names the same weights")
# -- Section 6 (the control net read as a union of bounded sets by latex_math.parse) --------------------
for _lid in ("sec6-control-net-set", "sec6-rational-control-net-set"):
    EQUIVALENT[f"{_lid}:swap:1d5b5ec26a"] = (  # i <-> j in the whole line
        "renaming the bound variables: {r_{2n,2n-j,i}}_{i=0,j=i}^{n,2n-1-i} is the set {r_{2n,2n-i,j}}_{j=0,i=j}"
        "^{n,2n-1-j} with i and j named the other way round (and likewise for g, b with upper bound n-1): the line "
        "names the same control points for every n (and still lacks the centre)")
