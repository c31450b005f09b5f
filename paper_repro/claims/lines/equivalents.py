"""Equivalent mutants of the transcribed lines: changes that keep a line true, so that no check can kill them.

Keys are :attr:`paper_repro.claims.lines.mutation.Mutant.key` (line id, operator, hash of the mutated text); the
value says why the mutated line still holds.  ``make mutate-lines`` lists every survivor that is not here.
"""

from __future__ import annotations

EQUIVALENT: dict[str, str] = {}

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
