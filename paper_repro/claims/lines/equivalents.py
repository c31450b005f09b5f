"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

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
