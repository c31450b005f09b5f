"""Sections sec:coincidence and sec:partition_of_unity (source lines 1414-2167), line by line, verbatim.

``LINES``: every displayed line and inline statement of the part (see :mod:`paper_repro.printed.lines`).  The
constants and functions below are the machine-readable transcriptions of the same printed text that the checks
(:mod:`paper_repro.claims.lines.sec4_5`) compare with independent computations.  The printed example formulas of
Examples normalizing_coefficients_n_1..3 and Proposition prop:level_1_coefficients are transcribed in
:mod:`paper_repro.printed.normalization` (``INTERMEDIATE``, ``FINAL``, ``prop_level_1``; compared with the source
lines 2024-2107 and 1997-2006 for this part).
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

from paper_repro.printed.lines import Line

#: Worked examples after Definition equivalence_relation_definition (n = 3), lines 1493-1502:
#: (first triple, second triple, printed equivalent?).
EXAMPLES_N3 = [((0, 0, 1), (1, 1, 0), True), ((1, 3, 2), (2, 0, 1), True), ((2, 0, 1), (0, 2, 1), True),
               ((1, 3, 2), (0, 2, 1), True), ((1, 0, 0), (0, 1, 0), False)]

#: Arguments of the functions added to V_0 in the printed V_1 (lines 1550-1552): u, v, w.
V1_ARGS = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]

#: The six printed classes of order 2 (lines 1596-1600): {[0u+gv+2w]}_{g=0}^1, {[2u+0v+bw]}_{b=0}^1,
#: {[ru+2v+0w]}_{r=0}^1.
N2_CLASSES = [(0, g, 2) for g in range(2)] + [(2, 0, b) for b in range(2)] + [(r, 2, 0) for r in range(2)]

#: Arguments of the functions added to V_1 in the printed V_2 (lines 1604-1613): 2w, v+2w, 2u, 2u+w, 2v, u+2v.
V2_NEW_ARGS = [(0, 0, 2), (0, 1, 2), (2, 0, 0), (2, 0, 1), (0, 2, 0), (1, 2, 0)]


def prop_representatives(n: int) -> list[tuple[int, int, int]]:
    """Lines 1637-1640: {[0u+gv+nw]}_{g=0}^{n-1} u {[nu+0v+bw]}_{b=0}^{n-1} u {[ru+nv+0w]}_{r=0}^{n-1}."""
    return [(0, g, n) for g in range(n)] + [(n, 0, b) for b in range(n)] + [(r, n, 0) for r in range(n)]


def proof_r_exponents(n: int, i: int, j: int) -> tuple[int, ...]:
    """Lines 1683-1685: R_{2n,2n-i,j} = sin^{2n-i}(u/2) sin^i(w/2) cos^{i-j}(v/2) sin^j(v/2) (j <= i <= n), as
    exponents of (sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2)."""
    return (2 * n - i, 0, j, i - j, i, 0)


def power_reduction(m: int, which: str, ep):
    """Lines 1689-1720, the printed right-hand sides of cos^m(t/2) and sin^m(t/2), built with the trigonometric
    polynomial class ``ep`` (``ep.cos(freq)``, ``ep.sin(freq)``, ``ep.const(1, x)``; frequency of t)."""
    half = Fraction(1, 2)
    if m % 2 == 1:
        out = ep.const(1, 0)
        for k in range((m - 1) // 2 + 1):
            sign = 1 if which == "cos" else (-1) ** ((m - 1) // 2 - k)
            term = ep.cos((half * (m - 2 * k),)) if which == "cos" else ep.sin((half * (m - 2 * k),))
            out = out + term * Fraction(sign * comb(m, k), 2 ** (m - 1))
        return out
    out = ep.const(1, Fraction(comb(m, m // 2), 2**m))
    for k in range(m // 2):
        sign = 1 if which == "cos" else (-1) ** (m // 2 - k)
        out = out + ep.cos((half * (m - 2 * k),)) * (Fraction(sign * comb(m, k) * 2, 2**m))
    return out


#: Eq. possible_products_inclusion: the type of each factor (u part, w part, first v part, second v part) in
#: the four parity cases "i mod 2, j mod 2" (lines 1732-1750).
PRODUCT_TYPES = {"0,0": ("cos", "cos", "cos", "cos"), "1,1": ("sin", "sin", "cos", "sin"),
                 "0,1": ("cos", "cos", "cos", "sin"), "1,0": ("sin", "sin", "cos", "cos")}

#: Lines 1758-1769: the printed upper ends of the four factors of K_{i mod 2, j mod 2} (each {0, 1, ..., B}).
K_UPPER = {
    "0,0": lambda n, i, j: (Fraction(2 * n - i, 2), Fraction(i, 2), Fraction(i - j, 2), Fraction(j, 2)),
    "1,1": lambda n, i, j: (Fraction(2 * n - i - 1, 2), Fraction(i - 1, 2), Fraction(i - j, 2), Fraction(j - 1, 2)),
    "0,1": lambda n, i, j: (Fraction(2 * n - i, 2), Fraction(i, 2), Fraction(i - j - 1, 2), Fraction(j - 1, 2)),
    "1,0": lambda n, i, j: (Fraction(2 * n - i - 1, 2), Fraction(i - 1, 2), Fraction(i - j, 2), Fraction(j, 2)),
}


def weight_labels(n: int) -> list[str]:
    """Eq. normalizing_weights (lines 1914-1916): r_{2n,n,n} and {x_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j}."""
    out = [f"r_{{{2 * n},{n},{n}}}"]
    for x in "rgb":
        out += [f"{x}_{{{2 * n},{2 * n - i},{j}}}" for j in range(n) for i in range(j, 2 * n - j)]
    return out


def partition_sum_labels(n: int) -> list[str]:
    """Lines 1922-1927: the functions of the printed sum L (centre, then the three double sums)."""
    out = [f"R_{{{2 * n},{n},{n}}}"]
    for x in "RGB":
        out += [f"{x}_{{{2 * n},{2 * n - i},{j}}}" for j in range(n) for i in range(j, 2 * n - 1 - j + 1)]
    return out


def blending_labels(n: int) -> list[str]:
    """Eq. normalized_united_system, first row (lines 2128-2131): {R-bar, G-bar, B-bar}_{j=0,i=j}^{n-1,2n-1-j}
    as the coefficient names, sorted."""
    return sorted(f"{x}_{{{2 * n},{2 * n - i},{j}}}" for x in "rgb" for j in range(n) for i in range(j, 2 * n - j))


LINES: list[Line] = [
    Line(id='sec4_5-section-title',
         tex=(1414, 1415),
         near='sec:coincidence',
         kind='prose',
         verbatim=('\\section{\\label{sec:coincidence}Coincidence of vector spaces $\\mathcal{T}% _{2n}^{\\a'
                   'lpha}$ and $\\mathcal{V}_{n}^{\\alpha}$}'),
         says='Section heading: coincidence of T_{2n}^alpha and V_n^alpha.',
         status='excused',
         reason='heading'),
    Line(id='sec4_5-intro-orders',
         tex=(1417, 1417),
         near='sec:coincidence',
         kind='prose',
         verbatim='for the present we could describe these basis transformations only for orders one and two',
         says='The authors could describe the basis transformations only for orders one and two.',
         status='excused',
         reason="prose about the authors' work; nothing to compute"),
    Line(id='sec4_5-def-params',
         tex=(1421, 1422),
         near='equivalence_relation_definition',
         kind='definition',
         verbatim=('Let $n\\geq1$ and $\\left( u,v,w\\right) \\in\\Omega^{\\alpha}$ be fixed parameters and '
                   'consider the set%'),
         says='n >= 1 and (u,v,w) in Omega^alpha are fixed parameters.',
         status='excused',
         reason='introduces the parameters of the definition'),
    Line(id='sec4_5-E-n',
         tex=(1424, 1426),
         near='equivalence_relation_definition',
         kind='index-set',
         verbatim='E_{n}^{\\alpha}=\\left\\{ ru+gv+bw:r,g,b\\in% \\mathbb{N} ,~0\\leq r,g,b\\leq n\\right\\} .',
         says=('E_n = {ru+gv+bw : 0 <= r,g,b <= n}; its classes number 1 + 3n(n+1)/2, i.e. 1 + 2(#classes - '
               '1) = delta_n functions.'),
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-sim-notation',
         tex=(1430, 1432),
         near='equivalence_relation_definition',
         kind='definition',
         verbatim='r_{1}u+g_{1}v+b_{1}w\\sim r_{2}u+g_{2}v+b_{2}w,',
         says='The symbol ~ names the relation defined by the conditions that follow.',
         status='excused',
         reason='introduces a name (the relation itself, with its conditions, is checked by sec4_5-relation)'),
    Line(id='sec4_5-z-range',
         tex=(1433, 1434),
         near='equivalence_relation_definition',
         kind='range',
         verbatim=('there exists an integer $z\\in\\left\\{ -n,-\\left( n-1\\right) ,\\ldots,0,1,\\ldots,2n'
                   '\\right\\} $ for which'),
         says='The common value z of the conditions ranges over {-n,...,2n}.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond1-row1',
         tex=(1439, 1439),
         near='equivalence_conditions_1',
         kind='display',
         verbatim='r_{2}+r_{1} & = & z,',
         says='Condition 1 (sums), row 1: the sums of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond1-row2',
         tex=(1440, 1440),
         near='equivalence_conditions_1',
         kind='display',
         verbatim='g_{2}+g_{1} & = & z,',
         says='Condition 1 (sums), row 2: the sums of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond1-row3',
         tex=(1441, 1441),
         near='equivalence_conditions_1',
         kind='display',
         verbatim='b_{2}+b_{1} & = & z',
         says='Condition 1 (sums), row 3: the sums of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond2-row1',
         tex=(1450, 1450),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='r_{2}-r_{1} & = & z,',
         says='Condition 2 (differences), row 1: the differences of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond2-row2',
         tex=(1451, 1451),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='g_{2}-g_{1} & = & z,',
         says='Condition 2 (differences), row 2: the differences of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cond2-row3',
         tex=(1452, 1452),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='b_{2}-b_{1} & = & z',
         says='Condition 2 (differences), row 3: the differences of corresponding coefficients equal z.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-quotient',
         tex=(1458, 1460),
         near='equivalence_conditions_2',
         kind='definition',
         verbatim=('E_{n}^{\\alpha}/_{\\sim}=\\left\\{ \\left[ ru+gv+bw\\right] :ru+gv+bw\\in E_{n}^{\\alpha'
                   '}\\right\\} \\]'),
         says='E_n/~ is the set of the equivalence classes.',
         status='excused',
         reason='introduces a name'),
    Line(id='sec4_5-z-range-2',
         tex=(1470, 1471),
         near='equivalence_conditions_2',
         kind='range',
         verbatim=('then exists an integer $z\\in\\left\\{ -n,-\\left( n-1\\right) ,\\ldots,0,1,\\ldots,2n\\'
                   'right\\} $ for which one of the equalities'),
         says='For equivalent combinations an integer z in {-n..2n} gives the phase identity.',
         status='checked',
         check='sec4_5-relation'),
    Line(id='sec4_5-cos-step1',
         tex=(1473, 1475),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('\\cos\\left( r_{2}u+g_{2}v+b_{2}w\\right) = & \\cos\\left( \\left( z\\mp r_{1}\\right) u'
                   '+\\left( z\\mp g_{1}\\right) v+\\left( z\\mp b_{1}\\right) w\\right) \\\\'),
         says='cos(r2u+g2v+b2w) = cos((z-+r1)u + (z-+g1)v + (z-+b1)w).',
         status='checked',
         check='sec4_5-phase-cos'),
    Line(id='sec4_5-cos-step2',
         tex=(1476, 1477),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('= & \\cos\\left( z\\left( u+v+w\\right) \\mp\\left( r_{1}u+g_{1}% v+b_{1}w\\right) \\rig'
                   'ht) \\\\'),
         says='... = cos(z(u+v+w) -+ (r1u+g1v+b1w)).',
         status='checked',
         check='sec4_5-phase-cos'),
    Line(id='sec4_5-cos-step3',
         tex=(1478, 1478),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='= & \\cos\\left( z\\alpha\\mp\\left( r_{1}u+g_{1}v+b_{1}w\\right) \\right) \\\\',
         says='... = cos(z alpha -+ (r1u+g1v+b1w)) on Omega^alpha.',
         status='checked',
         check='sec4_5-phase-cos'),
    Line(id='sec4_5-cos-step4-za',
         tex=(1479, 1480),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('= & \\cos\\left( za\\right) \\cdot\\cos\\left( r_{1}u+g_{1}v+b_{1}w\\right) \\pm\\sin\\l'
                   'eft( za\\right) \\cdot\\sin\\left( r_{1}u+g_{1}v+b_{1}w\\right)'),
         says='... = cos(za) cos(X) +- sin(za) sin(X) (printed za for z alpha).',
         status='erratum',
         check='sec4_5-phase-cos-za',
         erratum={'printed': '= cos(za) cos(r1u+g1v+b1w) +- sin(za) sin(r1u+g1v+b1w)',
                  'corrected': '= cos(z alpha) cos(r1u+g1v+b1w) +- sin(z alpha) sin(r1u+g1v+b1w)',
                  'evidence': ('the symbol a is nowhere defined; expanded exactly with a free a the step fa'
                                'ils, with z alpha it holds for every related pair of E_n, n <= 3 (the line '
                                'before has z alpha)'),
                  'severity': 'typo'}),
    Line(id='sec4_5-phase-meaning',
         tex=(1482, 1490),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('i.e., function $\\cos\\left( r_{2}u+g_{2}v+b_{2}w\\right) $ differs from $\\cos\\left( r'
                   '_{1}u+g_{1}v+b_{1}w\\right) $ only in a phase change and it can be expressed as a linear'
                   ' combination of $\\cos\\left( r_{1}u+g_{1}v+b_{1}w\\right) $ and $\\sin\\left( r_{1}u+g_'
                   '{1}v+b_{1}w\\right) $'),
         says=('cos(r2u+g2v+b2w) differs from cos(r1u+g1v+b1w) by a phase: a combination of cos and sin of r'
               '1u+g1v+b1w.'),
         status='checked',
         check='sec4_5-phase-cos'),
    Line(id='sec4_5-examples-n3-1',
         tex=(1493, 1493),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='0\\cdot u+0\\cdot v+1\\cdot w\\sim1\\cdot u+1\\cdot v+0\\cdot w',
         says='For n = 3: w ~ u + v.',
         status='checked',
         check='sec4_5-examples-n3'),
    Line(id='sec4_5-examples-n3-2',
         tex=(1497, 1498),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('1\\cdot u+3\\cdot v+2\\cdot w\\sim2\\cdot u+0\\cdot v+1\\cdot w\\sim0\\cdot u+2\\cdot v+'
                   '1\\cdot w,'),
         says='For n = 3: u+3v+2w ~ 2u+w ~ 2v+w.',
         status='checked',
         check='sec4_5-examples-n3'),
    Line(id='sec4_5-examples-n3-3',
         tex=(1502, 1502),
         near='equivalence_conditions_2',
         kind='display',
         verbatim='1\\cdot u+0\\cdot v+0\\cdot w\\nsim0\\cdot u+1\\cdot v+0\\cdot w.',
         says='For n = 3: u is not equivalent to v.',
         status='checked',
         check='sec4_5-examples-n3'),
    Line(id='sec4_5-sin-step1',
         tex=(1512, 1513),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('\\sin\\left( r_{2}u+g_{2}v+b_{2}w\\right) & =\\sin\\left( z\\alpha\\mp\\left( r_{1}u+g_{'
                   '1}v+b_{1}w\\right) \\right) \\\\'),
         says='sin(r2u+g2v+b2w) = sin(z alpha -+ (r1u+g1v+b1w)).',
         status='checked',
         check='sec4_5-phase-sin'),
    Line(id='sec4_5-sin-step2-za',
         tex=(1514, 1515),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('& =\\sin\\left( za\\right) \\cdot\\cos\\left( r_{1}u+g_{1}v+b_{1}w\\right) \\mp\\cos\\le'
                   'ft( z\\alpha\\right) \\cdot\\sin\\left( r_{1}u+g_{1}v+b_{1}w\\right)'),
         says='... = sin(za) cos(X) -+ cos(z alpha) sin(X) (printed za for z alpha).',
         status='erratum',
         check='sec4_5-phase-sin-za',
         erratum={'printed': '= sin(za) cos(r1u+g1v+b1w) -+ cos(z alpha) sin(r1u+g1v+b1w)',
                  'corrected': '= sin(z alpha) cos(r1u+g1v+b1w) -+ cos(z alpha) sin(r1u+g1v+b1w)',
                  'evidence': ('a is undefined; with a free a the step fails, with z alpha it holds (exact '
                                'expansion, every related pair of E_n, n <= 3)'),
                  'severity': 'typo'}),
    Line(id='sec4_5-E0',
         tex=(1527, 1528),
         near='equivalence_conditions_2',
         kind='definition',
         verbatim=('E_{0}^{\\alpha}=\\left\\{ 0\\cdot u+0\\cdot v+0\\cdot w:\\left( u,v,w\\right) \\in\\Omeg'
                   'a^{\\alpha}\\right\\}'),
         says='E_0 = {0u+0v+0w}.',
         status='excused',
         reason='definition'),
    Line(id='sec4_5-V0',
         tex=(1534, 1534),
         near='equivalence_conditions_2',
         kind='definition',
         verbatim='V_{0}^{\\alpha}=\\left\\{ 1:\\left( u,v,w\\right) \\in\\Omega^{\\alpha}\\right\\} .',
         says='V_0 = {1}.',
         status='excused',
         reason='definition'),
    Line(id='sec4_5-order1-classes',
         tex=(1542, 1545),
         near='equivalence_conditions_2',
         kind='index-set',
         verbatim=('\\left[ ru+gv+bw\\right] \\in E_{1}^{\\alpha}/_{\\sim}\\setminus E_{0}^{\\alpha }/_{\\si'
                   'm}, \\] where at least one of the coefficients $r,g,b$ is equal to $1$.'),
         says='Order 1 adds the classes of E_1 not in E_0, each with a coefficient equal to 1.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-order1-relations',
         tex=(1545, 1547),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('Since $1\\cdot u+1\\cdot v+1\\cdot w\\sim0\\cdot u+0\\cdot v+0\\cdot w\\in\\left[ 0\\rig'
                   'ht] \\in E_{0}^{\\alpha}/_{\\sim}$, $u+v\\sim w$, $u+w\\sim v$ and $v+w\\sim u$'),
         says='u+v+w ~ 0, u+v ~ w, u+w ~ v, v+w ~ u.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-V1',
         tex=(1550, 1552),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('V_{1}^{\\alpha}=V_{0}^{\\alpha}\\cup\\left\\{ \\cos\\left( u\\right) ,\\sin\\left( u\\ri'
                   'ght) ,\\cos\\left( v\\right) ,\\sin\\left( v\\right) ,\\cos\\left( w\\right) ,\\sin\\lef'
                   't( w\\right) :\\left( u,v,w\\right) \\in\\Omega^{\\alpha}\\right\\} .'),
         says='V_1 = V_0 with cos, sin of u, v, w.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-order2-classes',
         tex=(1560, 1563),
         near='equivalence_conditions_2',
         kind='index-set',
         verbatim=('\\left[ ru+gv+bw\\right] \\in E_{2}^{\\alpha}/_{\\sim}\\setminus\\left( E_{0}^{\\alpha}/'
                   '_{\\sim}\\cup E_{1}^{\\alpha}/_{\\sim}\\right) , \\] where at least one of the coefficie'
                   'nts $r,g,b$ is equal to $2$.'),
         says='Order 2 adds the classes of E_2 not in E_0 or E_1, each with a coefficient equal to 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-222',
         tex=(1564, 1566),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('If $r=g=2$, then $\\left[ 2\\cdot u+2\\cdot v+2\\cdot w\\right] =\\left[ 0\\cdot u+0\\cd'
                   'ot v+0\\cdot w\\right] =\\left[ 0\\right] \\in E_{0}^{\\alpha }/_{\\sim}$.'),
         says='b = 2, r = g = 2: [2u+2v+2w] = [0] in E_0/~.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-r1',
         tex=(1566, 1567),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('If $0<r\\leq g\\leq2$, i.e., if $r=1,g\\in\\left\\{ 1,2\\right\\} $, then let $z=\\min\\'
                   'left\\{ r,g\\right\\} =1$'),
         says='0 < r <= g <= 2 means r = 1, g in {1,2}; z = min{r,g} = 1.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-chain',
         tex=(1569, 1574),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('& ru+gv+2w\\\\ = & \\left( r-z\\right) u+\\left( g-z\\right) v+\\left( 2-z\\right) w+z\\'
                   'left( u+v+w\\right) \\\\ = & \\left( r-z\\right) u+\\left( g-z\\right) v+\\left( 2-z\\ri'
                   'ght) w+z\\alpha\\\\ = & \\left( g-z\\right) v+w+z\\alpha,'),
         says='ru+gv+2w = (r-z)u+(g-z)v+(2-z)w+z(u+v+w) = ...+z alpha = (g-z)v+w+z alpha.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-g12',
         tex=(1578, 1584),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('u+gv+2w\\in\\left[ \\left( g-z\\right) v+w\\right] =\\left\\{ \\begin{array} [c]{rc}% \\'
                   'left[ w\\right] \\in E_{1}^{\\alpha}/_{\\sim,} & g=1,\\\\ \\left[ v+w\\right] =\\left[ u'
                   '\\right] \\in E_{1}^{\\alpha}/_{\\sim,} & g=2. \\end{array} \\right.'),
         says='u+gv+2w lies in [w] for g = 1 and in [v+w] = [u] for g = 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-r0',
         tex=(1586, 1588),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('If $r=0$ and $g\\in\\left\\{ 0,1,2\\right\\} $, then $\\left[ gv+2w\\right] \\in E_{2}^{'
                   '\\alpha}/_{\\sim}\\setminus\\left( E_{0}^{\\alpha}/_{\\sim}\\cup E_{1}^{\\alpha}/_{\\sim'
                   '}\\right) $.'),
         says='r = 0, g in {0,1,2}: [gv+2w] is new at order 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-b2-three',
         tex=(1588, 1590),
         near='equivalence_conditions_2',
         kind='count',
         verbatim=('Thus, equality $b=2$ generates only three acceptable equivalence classes, namely $\\left'
                   '\\{ \\left[ gv+2w\\right] \\right\\} _{g=0}^{2}$'),
         says='b = 2 generates only three acceptable classes {[gv+2w]}_{g=0}^2.',
         status='erratum',
         check='sec4_5-b2-three-classes',
         erratum={'printed': ('equality b = 2 generates only three acceptable equivalence classes, namely {'
                               '[gv+2w]}_{g=0}^2 (cases treated: r = g = 2, 0 < r <= g <= 2, r = 0)'),
                  'corrected': ('the triples (r, g, 2) meet five new classes: [2w], [v+2w], [2v+2w] = [2u],'
                                 ' and, from the untreated case 0 = g < r, [u+2w] = [u+2v] and [2u+2w] = [2v'
                                 ']; with r <= g exactly the three printed ones (the final list of six class'
                                 'es is right)'),
                  'evidence': ('class keys of phase equivalence: 5 new classes of E_2 contain a triple with'
                                ' b = 2, 3 when r <= g is added'),
                  'severity': 'statement'}),
    Line(id='sec4_5-n2-2v2w',
         tex=(1590, 1593),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('from which $\\left[ 2v+2w\\right] $ must be ignored, because this equivalence class will'
                   ' reappear as $\\left[ 2u\\right] \\in E_{2}^{\\alpha}/_{\\sim}\\setminus\\left( E_{0}^{'
                   '\\alpha}/_{\\sim}\\cup E_{1}^{\\alpha}/_{\\sim}\\right) $'),
         says='[2v+2w] reappears as [2u], new at order 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-classes-row1',
         tex=(1597, 1597),
         near='equivalence_conditions_2',
         kind='index-set',
         verbatim='\\left\\{ \\left[ 0\\cdot u+g\\cdot v+2\\cdot w\\right] \\right\\} _{g=0}^{1}',
         says='Row 1 of the six new classes of order 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-classes-row2',
         tex=(1598, 1598),
         near='equivalence_conditions_2',
         kind='index-set',
         verbatim='\\left\\{ \\left[ 2\\cdot u+0\\cdot v+b\\cdot w\\right] \\right\\} _{b=0}^{1}',
         says='Row 2 of the six new classes of order 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-classes-row3',
         tex=(1599, 1599),
         near='equivalence_conditions_2',
         kind='index-set',
         verbatim='\\left\\{ \\left[ r\\cdot u+2\\cdot v+0\\cdot w\\right] \\right\\} _{r=0}^{1}',
         says='Row 3 of the six new classes of order 2.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-n2-independent',
         tex=(1601, 1603),
         near='equivalence_conditions_2',
         kind='inline',
         verbatim=('generate new linearly independent constrained trivariate cosine and sine functions over '
                   '$\\Omega^{\\alpha}$, i.e., $\\mathcal{V}_{2}^{\\alpha}=~$span~$V_{2}^{\\alpha}$'),
         says='The six classes of order 2 generate new linearly independent functions; V_2^alpha = span V_2.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-V2-row1',
         tex=(1605, 1607),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('V_{2}^{\\alpha}= & V_{1}^{\\alpha}\\cup\\left\\{ \\cos\\left( 2w\\right) ,\\sin\\left( 2'
                   'w\\right) ,\\cos\\left( v+2w\\right) ,\\sin\\left( v+2w\\right) :\\left( u,v,w\\right) '
                   '\\in\\Omega^{\\alpha}\\right\\} \\\\'),
         says='V_2 row 1: V_1 with cos, sin of 2w and v+2w.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-V2-row2',
         tex=(1608, 1610),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('& \\cup\\left\\{ \\cos\\left( 2u\\right) ,\\sin\\left( 2u\\right) ,\\cos\\left( 2u+w\\ri'
                   'ght) ,\\sin\\left( 2u+w\\right) :\\left( u,v,w\\right) \\in \\Omega^{\\alpha}\\right\\} '
                   '\\\\'),
         says='V_2 row 2: cos, sin of 2u and 2u+w.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-V2-row3',
         tex=(1611, 1613),
         near='equivalence_conditions_2',
         kind='display',
         verbatim=('& \\cup\\left\\{ \\cos\\left( 2v\\right) ,\\sin\\left( 2v\\right) ,\\cos\\left( u+2v\\ri'
                   'ght) ,\\sin\\left( u+2v\\right) :\\left( u,v,w\\right) \\in \\Omega^{\\alpha}\\right\\} '
                   '.'),
         says='V_2 row 3: cos, sin of 2v and u+2v.',
         status='checked',
         check='sec4_5-orders-1-2'),
    Line(id='sec4_5-prop-recurrence',
         tex=(1628, 1632),
         near='iterative_construction_of_trivariate_extension',
         kind='display',
         verbatim=('V_{n}^{\\alpha}=V_{n-1}^{\\alpha}\\cup\\left\\{ \\cos\\left( ru+gv+bw\\right) ,\\sin\\le'
                   'ft( ru+gv+bw\\right) :\\left( u,v,w\\right) \\in\\Omega^{\\alpha },~\\left[ ru+gv+bw\\ri'
                   'ght] \\in E_{n}^{\\alpha}/_{\\sim}\\setminus\\left( \\cup_{i=1}^{n-1}E_{i}^{\\alpha}/_{'
                   '\\sim}\\right) \\right\\} \\]'),
         says='V_n = V_{n-1} with cos, sin of the classes of E_n/~ not in the union of E_i/~, i = 1..n-1.',
         status='erratum',
         check='sec4_5-prop-union',
         erratum={'printed': '[ru+gv+bw] in E_n/~ \\ (cup_{i=1}^{n-1} E_i/~)',
                  'corrected': ('[ru+gv+bw] in E_n/~ \\ (cup_{i=0}^{n-1} E_i/~) (as in the text for n = 1, '
                                 '2: E_1/~ \\ E_0/~, E_2/~ \\ (E_0/~ cup E_1/~))'),
                  'evidence': ('for n = 1 the printed union is empty and E_1/~ has 4 classes including [0] '
                                '(cos 0 = 1, sin 0 = 0 are not new functions); with i from 0 the 3n printed '
                                'representatives are exactly the new classes, n = 1..10'),
                  'severity': 'typo'}),
    Line(id='sec4_5-prop-new-classes',
         tex=(1636, 1641),
         near='iterative_construction_of_trivariate_extension',
         kind='index-set',
         verbatim=('E_{n}^{\\alpha}/_{\\sim}\\setminus\\left( \\cup_{i=1}^{n-1}E_{i}^{\\alpha}/_{\\sim }\\ri'
                   'ght) =\\left\\{ \\left[ 0\\cdot u+g\\cdot v+n\\cdot w\\right] \\right\\} _{g=0}^{n-1}\\c'
                   'up\\left\\{ \\left[ n\\cdot u+0\\cdot v+b\\cdot w\\right] \\right\\} _{b=0}^{n-1}\\cup\\'
                   'left\\{ \\left[ r\\cdot u+n\\cdot v+0\\cdot w\\right] \\right\\} _{r=0}^{n-1}, \\]'),
         says='The new classes at order n are {[gv+nw]}_{g<n}, {[nu+bw]}_{b<n}, {[ru+nv]}_{r<n}.',
         status='erratum',
         check='sec4_5-prop-union',
         erratum={'printed': ('E_n/~ \\ (cup_{i=1}^{n-1} E_i/~) = {[0u+gv+nw]}_{g=0}^{n-1} cup {[nu+0v+bw]}'
                               '_{b=0}^{n-1} cup {[ru+nv+0w]}_{r=0}^{n-1}'),
                  'corrected': 'E_n/~ \\ (cup_{i=0}^{n-1} E_i/~) = ... (same right-hand side)',
                  'evidence': ('n = 1: left side as printed has 4 classes ([0], [u], [v], [w]), right side '
                                '3; with i from 0 equal for n = 1..10 (class keys)'),
                  'severity': 'typo'}),
    Line(id='sec4_5-prop-V0',
         tex=(1642, 1643),
         near='iterative_construction_of_trivariate_extension',
         kind='definition',
         verbatim='$V_{0}^{\\alpha}=\\left\\{ 1:\\left( u,v,w\\right) \\in\\Omega^{\\alpha }\\right\\} $',
         says='V_0 = {1}.',
         status='excused',
         reason='definition (repeated)'),
    Line(id='sec4_5-prop-6n',
         tex=(1643, 1645),
         near='iterative_construction_of_trivariate_extension',
         kind='count',
         verbatim=('if $n\\geq1$ the function system $V_{n}^{\\alpha}$ can be obtained by completing $V_{n-1'
                   '}^{\\alpha}$ with $6n$ new linearly independent'),
         says='V_n is V_{n-1} completed by 6n new linearly independent functions.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-dim-recurrence',
         tex=(1653, 1653),
         near='dimension',
         kind='display',
         verbatim='\\dim\\mathcal{V}_{n}^{\\alpha}=\\dim\\mathcal{V}_{n-1}^{\\alpha}+6n,~n\\geq1',
         says='dim V_n = dim V_{n-1} + 6n, n >= 1.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-dim-initial',
         tex=(1655, 1655),
         near='dimension',
         kind='inline',
         verbatim='$\\dim\\mathcal{V}_{0}^{\\alpha}=1$',
         says='dim V_0 = 1.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-dim-sum',
         tex=(1657, 1657),
         near='dimension',
         kind='display',
         verbatim='\\dim\\mathcal{V}_{n}^{\\alpha}=1+6\\sum_{i=1}^{n}i',
         says='dim V_n = 1 + 6 sum_{i=1}^n i.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-dim-closed',
         tex=(1657, 1658),
         near='dimension',
         kind='display',
         verbatim='1+6\\sum_{i=1}^{n}i=3n\\left( n+1\\right) +1=\\delta_{n}',
         says='1 + 6 sum i = 3n(n+1)+1 = delta_n.',
         status='checked',
         check='sec4_5-dimension'),
    Line(id='sec4_5-dim-T',
         tex=(1658, 1658),
         near='dimension',
         kind='display',
         verbatim='=\\delta_{n} = \\dim\\mathcal{T}_{2n}^{\\alpha}.',
         says='delta_n = dim T_{2n}^alpha.',
         status='checked',
         check='sec4_5-coincidence-rank'),
    Line(id='sec4_5-theorem-statement',
         tex=(1665, 1666),
         near='dimension',
         kind='inline',
         verbatim=('The system $T_{2n}^{\\alpha}$ of constrained trivariate functions forms a basis of the v'
                   'ector space $\\mathcal{V}_{n}^{\\alpha}$'),
         says='T_{2n}^alpha is a basis of V_n^alpha.',
         status='checked',
         check='sec4_5-coincidence-rank'),
    Line(id='sec4_5-theorem',
         tex=(1668, 1672),
         near='dimension',
         kind='display',
         verbatim=('\\mathcal{T}_{2n}^{\\alpha}=% \\operatorname{span}% T_{2n}^{\\alpha}=% \\operatorname{sp'
                   'an}% V_{n}^{\\alpha}=\\mathcal{V}_{n}^{\\alpha}\\text{.}%'),
         says='T_{2n}^alpha = span T_{2n} = span V_n = V_n^alpha.',
         status='checked',
         check='sec4_5-coincidence-rank'),
    Line(id='sec4_5-proof-symmetry-reduction',
         tex=(1678, 1683),
         near='dimension',
         kind='inline',
         verbatim=('First of all, we prove that functions of the system (\\ref{united_system}) are elements '
                   'of $% \\operatorname{span}% V_{n}^{\\alpha}$. Due to symmetry properties of functions ('
                   '\\ref{R_system}), (\\ref{G_system}) and (\\ref{B_system}), it is sufficient to show that'
                   ' for all indices $j=0,1,\\ldots,n$ and $i=j,j+1,\\ldots,n$'),
         says='By the symmetries of R, G, B it suffices to treat R_{2n,2n-i,j}, j = 0..n, i = j..n.',
         status='checked',
         check='sec4_5-proof-reduction'),
    Line(id='sec4_5-proof-R',
         tex=(1683, 1685),
         near='dimension',
         kind='index-set',
         verbatim=('indices $j=0,1,\\ldots,n$ and $i=j,j+1,\\ldots,n$ the function $R_{2n,2n-i,j}% ^{\\alpha'
                   '}\\left( u,v,w\\right) =\\sin^{2n-i}\\frac{u}{2}\\sin^{i}\\frac{w}{2}% \\cos^{i-j}\\frac'
                   '{v}{2}\\sin^{j}\\frac{v}{2}'),
         says=('It suffices to show R_{2n,2n-i,j} = sin^{2n-i}(u/2) sin^i(w/2) cos^{i-j}(v/2) sin^j(v/2) in '
               'span V_n for j = 0..n, i = j..n.'),
         status='checked',
         check='sec4_5-proof-reduction'),
    Line(id='sec4_5-cos-power-odd',
         tex=(1689, 1695),
         near='dimension',
         kind='display',
         verbatim=('\\cos^{m}\\frac{t}{2} & =\\left\\{ \\begin{array} [c]{rl}% \\dfrac{1}{2^{m-1}}% {\\displ'
                   'aystyle\\sum\\limits_{k=0}^{\\frac{m-1}{2}}} \\dbinom{m}{k}\\cos\\left( \\dfrac{1}{2}\\l'
                   'eft( m-2k\\right) t\\right) , & m\\equiv1\\left( \\operatorname{mod}2\\right) ,\\\\'),
         says='cos^m(t/2) = 2^{1-m} sum_{k=0}^{(m-1)/2} C(m,k) cos((m-2k)t/2), m odd.',
         status='checked',
         check='sec4_5-power-reduction'),
    Line(id='sec4_5-cos-power-even',
         tex=(1697, 1700),
         near='dimension',
         kind='display',
         verbatim=('\\dfrac{1}{2^{m}}\\dbinom{m}{\\frac{m}{2}}+\\dfrac{1}{2^{m-1}}% {\\displaystyle\\sum\\li'
                   'mits_{k=0}^{\\frac{m}{2}-1}} \\dbinom{m}{k}\\cos\\left( \\dfrac{1}{2}\\left( m-2k\\right'
                   ') t\\right) , & m\\equiv0\\left( \\operatorname{mod}2\\right) ,'),
         says='cos^m(t/2) = 2^{-m} C(m,m/2) + 2^{1-m} sum_{k=0}^{m/2-1} C(m,k) cos((m-2k)t/2), m even.',
         status='checked',
         check='sec4_5-power-reduction'),
    Line(id='sec4_5-sin-power-odd',
         tex=(1704, 1711),
         near='dimension',
         kind='display',
         verbatim=('\\sin^{m}\\frac{t}{2} & =\\left\\{ \\begin{array} [c]{rl}% \\dfrac{1}{2^{m-1}}% {\\displ'
                   'aystyle\\sum\\limits_{k=0}^{\\frac{m-1}{2}}} \\left( -1\\right) ^{\\frac{m-1}{2}-k}\\dbi'
                   'nom{m}{k}\\sin\\left( \\dfrac{1}% {2}\\left( m-2k\\right) t\\right) , & m\\equiv1\\left('
                   ' \\operatorname{mod}% 2\\right) ,\\\\'),
         says='sin^m(t/2) = 2^{1-m} sum_{k=0}^{(m-1)/2} (-1)^{(m-1)/2-k} C(m,k) sin((m-2k)t/2), m odd.',
         status='checked',
         check='sec4_5-power-reduction'),
    Line(id='sec4_5-sin-power-even',
         tex=(1713, 1717),
         near='dimension',
         kind='display',
         verbatim=('\\dfrac{1}{2^{m}}\\dbinom{m}{\\frac{m}{2}}+\\dfrac{1}{2^{m-1}}% {\\displaystyle\\sum\\li'
                   'mits_{k=0}^{\\frac{m}{2}-1}} \\left( -1\\right) ^{\\frac{m}{2}-k}\\dbinom{m}{k}\\cos\\le'
                   'ft( \\dfrac{1}% {2}\\left( m-2k\\right) t\\right) , & m\\equiv0\\left( \\operatorname{mo'
                   'd}% 2\\right) ,'),
         says=('sin^m(t/2) = 2^{-m} C(m,m/2) + 2^{1-m} sum_{k=0}^{m/2-1} (-1)^{m/2-k} C(m,k) cos((m-2k)t/2),'
               ' m even.'),
         status='checked',
         check='sec4_5-power-reduction'),
    Line(id='sec4_5-power-ranges',
         tex=(1721, 1725),
         near='dimension',
         kind='range',
         verbatim='($m\\in% \\mathbb{N} $, $t\\in% \\mathbb{R} $)',
         says='m in N, t in R.',
         status='checked',
         check='sec4_5-power-reduction'),
    Line(id='sec4_5-parity',
         tex=(1725, 1728),
         near='dimension',
         kind='inline',
         verbatim=('and by the parity of powers $2n-i$, $i$, $i-j$ and $j$, one can easily see that function'
                   ' $R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) $ can be written as the sum of products o'
                   'f the type%'),
         says=('By the parity of 2n-i, i, i-j, j, R_{2n,2n-i,j} is a sum of products of the type (possible_p'
               'roducts_inclusion).'),
         status='checked',
         check='sec4_5-product-types'),
    Line(id='sec4_5-product-type-1',
         tex=(1732, 1735),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\cos\\left( \\frac{2n-i-2k_{1}}{2}u\\right) \\cos\\left( \\frac{i-2k_{2}}% {2}w\\right)'
                   ' \\cos\\left( \\frac{i-j-2k_{3}}{2}v\\right) \\cos\\left( \\frac{j-2k_{4}}{2}v\\right) ,'
                   ' & i\\equiv0\\left( \\operatorname{mod}2\\right) \\text{ and }j\\equiv0\\left( \\operato'
                   'rname{mod}2\\right) ,\\\\'),
         says='Product type 1: cos cos cos cos, i and j even.',
         status='checked',
         check='sec4_5-product-types'),
    Line(id='sec4_5-product-type-2',
         tex=(1737, 1740),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\sin\\left( \\frac{2n-i-2k_{1}}{2}u\\right) \\sin\\left( \\frac{i-2k_{2}}% {2}w\\right)'
                   ' \\cos\\left( \\frac{i-j-2k_{3}}{2}v\\right) \\sin\\left( \\frac{j-2k_{4}}{2}v\\right) ,'
                   ' & i\\equiv1\\left( \\operatorname{mod}2\\right) \\text{ and }j\\equiv1\\left( \\operato'
                   'rname{mod}2\\right) ,\\\\'),
         says='Product type 2: sin sin cos sin, i and j odd.',
         status='checked',
         check='sec4_5-product-types'),
    Line(id='sec4_5-product-type-3',
         tex=(1742, 1745),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\cos\\left( \\frac{2n-i-2k_{1}}{2}u\\right) \\cos\\left( \\frac{i-2k_{2}}% {2}w\\right)'
                   ' \\cos\\left( \\frac{i-j-2k_{3}}{2}v\\right) \\sin\\left( \\frac{j-2k_{4}}{2}v\\right) ,'
                   ' & i\\equiv0\\left( \\operatorname{mod}2\\right) \\text{ and }j\\equiv1\\left( \\operato'
                   'rname{mod}2\\right) ,\\\\'),
         says='Product type 3: cos cos cos sin, i even, j odd.',
         status='checked',
         check='sec4_5-product-types'),
    Line(id='sec4_5-product-type-4',
         tex=(1747, 1750),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\sin\\left( \\frac{2n-i-2k_{1}}{2}u\\right) \\sin\\left( \\frac{i-2k_{2}}% {2}w\\right)'
                   ' \\cos\\left( \\frac{i-j-2k_{3}}{2}v\\right) \\cos\\left( \\frac{j-2k_{4}}{2}v\\right) ,'
                   ' & i\\equiv1\\left( \\operatorname{mod}2\\right) \\text{ and }j\\equiv0\\left( \\operato'
                   'rname{mod}2\\right) ,'),
         says='Product type 4: sin sin cos cos, i odd, j even.',
         status='checked',
         check='sec4_5-product-types'),
    Line(id='sec4_5-K00',
         tex=(1758, 1760),
         near='possible_products_inclusion',
         kind='index-set',
         verbatim=('K_{0,0} & =\\left\\{ 0,1,\\ldots,\\frac{2n-i}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,'
                   '\\frac{i}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,\\frac{i-j}% {2}\\right\\} \\times\\'
                   'left\\{ 0,1,\\ldots,\\frac{j}{2}\\right\\} ,\\\\'),
         says='K_{0,0} = {0..(2n-i)/2} x {0..i/2} x {0..(i-j)/2} x {0..j/2}.',
         status='checked',
         check='sec4_5-K-00'),
    Line(id='sec4_5-K11',
         tex=(1761, 1763),
         near='possible_products_inclusion',
         kind='index-set',
         verbatim=('K_{1,1} & =\\left\\{ 0,1,\\ldots,\\frac{2n-i-1}{2}\\right\\} \\times\\left\\{ 0,1,\\ldot'
                   's,\\frac{i-1}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,\\frac{i-j}% {2}\\right\\} \\tim'
                   'es\\left\\{ 0,1,\\ldots,\\frac{j-1}{2}\\right\\} ,\\\\'),
         says='K_{1,1} = {0..(2n-i-1)/2} x {0..(i-1)/2} x {0..(i-j)/2} x {0..(j-1)/2}.',
         status='checked',
         check='sec4_5-K-11'),
    Line(id='sec4_5-K01',
         tex=(1764, 1766),
         near='possible_products_inclusion',
         kind='index-set',
         verbatim=('K_{0,1} & =\\left\\{ 0,1,\\ldots,\\frac{2n-i}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,'
                   '\\frac{i}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,\\frac{i-j-1}% {2}\\right\\} \\times'
                   '\\left\\{ 0,1,\\ldots,\\frac{j-1}{2}\\right\\} ,\\\\'),
         says='K_{0,1} = {0..(2n-i)/2} x {0..i/2} x {0..(i-j-1)/2} x {0..(j-1)/2}.',
         status='checked',
         check='sec4_5-K-01'),
    Line(id='sec4_5-K10',
         tex=(1767, 1769),
         near='possible_products_inclusion',
         kind='index-set',
         verbatim=('K_{1,0} & =\\left\\{ 0,1,\\ldots,\\frac{2n-i-1}{2}\\right\\} \\times\\left\\{ 0,1,\\ldot'
                   's,\\frac{i-1}{2}\\right\\} \\times\\left\\{ 0,1,\\ldots,\\frac{i-j}% {2}\\right\\} \\tim'
                   'es\\left\\{ 0,1,\\ldots,\\frac{j}{2}\\right\\} .'),
         says='K_{1,0} = {0..(2n-i-1)/2} x {0..(i-1)/2} x {0..(i-j)/2} x {0..j/2}.',
         status='erratum',
         check='sec4_5-K-10',
         erratum={'printed': 'K_{1,0} = {0,...,(2n-i-1)/2} x {0,...,(i-1)/2} x {0,...,(i-j)/2} x {0,...,j/2}',
                  'corrected': ('K_{1,0} = {0,...,(2n-i-1)/2} x {0,...,(i-1)/2} x {0,...,(i-j-1)/2} x {0,..'
                                 '.,j/2}'),
                  'evidence': ('i odd, j even: i-j is odd, so (i-j)/2 is not an integer (n = 2, i = 1, j = '
                                '0: 1/2); the k3 of the expansion of cos^{i-j}(v/2) are 0..(i-j-1)/2 (exact '
                                'expansion, n <= 6), as in K_{0,1}'),
                  'severity': 'typo'}),
    Line(id='sec4_5-in-Vn',
         tex=(1774, 1780),
         near='possible_products_inclusion',
         kind='inline',
         verbatim=('where $\\left[ r_{1},g_{1},b_{1}\\right] ,\\left[ r_{2},g_{2},b_{2}\\right] \\in\\cup_{i'
                   '=1}^{n}E_{i}^{\\alpha}/_{\\sim}$, i.e., \\[ \\cos\\left( r_{1}u+g_{1}v+b_{1}w\\right) ,'
                   '\\sin\\left( r_{2}u+g_{2}% v+b_{2}w\\right) \\in V_{n}^{\\alpha}.'),
         says=('Each product is a combination of cos, sin of combinations whose classes lie in cup_{i=1}^n E'
               '_i/~, i.e. of functions of V_n.'),
         status='checked',
         check='sec4_5-inclusion'),
    Line(id='sec4_5-product-to-sum-1',
         tex=(1785, 1786),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\cos x\\cos y & =\\frac{1}{2}\\left( \\cos\\left( x-y\\right) +\\cos\\left( x+y\\right)'
                   ' \\right) ,\\\\'),
         says='cos x cos y = (cos(x-y)+cos(x+y))/2.',
         status='checked',
         check='sec4_5-product-to-sum'),
    Line(id='sec4_5-product-to-sum-2',
         tex=(1787, 1788),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\sin x\\sin y & =\\frac{1}{2}\\left( \\cos\\left( x-y\\right) -\\cos\\left( x+y\\right)'
                   ' \\right) ,\\\\'),
         says='sin x sin y = (cos(x-y)-cos(x+y))/2.',
         status='checked',
         check='sec4_5-product-to-sum'),
    Line(id='sec4_5-product-to-sum-3',
         tex=(1789, 1790),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\sin x\\cos y & =\\frac{1}{2}\\left( \\sin\\left( x+y\\right) +\\sin\\left( x-y\\right)'
                   ' \\right)'),
         says='sin x cos y = (sin(x+y)+sin(x-y))/2.',
         status='checked',
         check='sec4_5-product-to-sum'),
    Line(id='sec4_5-eight-terms',
         tex=(1794, 1804),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('each of the eight terms of the expansion of the product% \\[ \\sin\\left( \\dfrac{2n-i-2'
                   'k_{1}}{2}u\\right) \\sin\\left( \\dfrac{i-2k_{2}}% {2}w\\right) \\cos\\left( \\dfrac{i-j'
                   '-2k_{3}}{2}v\\right) \\sin\\left( \\dfrac{j-2k_{4}}{2}v\\right) \\] has the form% \\[ \\'
                   'sin\\left( s_{1}\\frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}% {2}+s_{3}\\frac'
                   '{j-2k_{4}}{2}\\right) v+s_{4}\\frac{i-2k_{2}}{2}w\\right) , \\]'),
         says='Each of the eight terms of the odd-odd product is sin(s1 A u + (s2 C + s3 D) v + s4 B w).',
         status='checked',
         check='sec4_5-eight-terms'),
    Line(id='sec4_5-signs',
         tex=(1805, 1806),
         near='possible_products_inclusion',
         kind='range',
         verbatim=('where $s_{1}=1$ and $s_{2},s_{3},s_{4}\\in\\left\\{ -1,+1\\right\\} $, i.e., $s_{r}^{2}='
                   '1$, $r=1,2,3,4$'),
         says='s1 = 1, s2, s3, s4 in {-1,+1}, s_r^2 = 1.',
         status='checked',
         check='sec4_5-eight-terms'),
    Line(id='sec4_5-constraint-prose',
         tex=(1806, 1807),
         near='possible_products_inclusion',
         kind='prose',
         verbatim='Using the constraint $u+v+w=\\alpha$ one can successively write that%',
         says='Using u+v+w = alpha one can successively write.',
         status='excused',
         reason='announces the chain checked by sec4_5-shift-chain'),
    Line(id='sec4_5-shift-step1',
         tex=(1809, 1813),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('& \\sin\\left( s_{1}\\frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}% {2}+s_{3}\\'
                   'frac{j-2k_{4}}{2}\\right) v+s_{4}\\frac{i-2k_{2}}{2}w\\right) \\\\ & =\\sin\\left( s_{1}'
                   '\\frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}% {2}+s_{3}\\frac{j-2k_{4}}{2}\\r'
                   'ight) v+s_{4}\\frac{i-2k_{2}}{2}w-\\frac{\\alpha }{2}+\\frac{\\alpha}{2}\\right) \\\\'),
         says='sin(X) = sin(X - alpha/2 + alpha/2).',
         status='checked',
         check='sec4_5-shift-chain'),
    Line(id='sec4_5-shift-step2',
         tex=(1811, 1819),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('& =\\sin\\left( s_{1}\\frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}% {2}+s_{3}'
                   '\\frac{j-2k_{4}}{2}\\right) v+s_{4}\\frac{i-2k_{2}}{2}w-\\frac{\\alpha }{2}+\\frac{\\alp'
                   'ha}{2}\\right) \\\\ & =\\cos\\frac{\\alpha}{2}\\sin\\left( s_{1}\\frac{2n-i-2k_{1}}{2}u+'
                   '\\left( s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}}{2}\\right) v+s_{4}% \\frac{i-2k'
                   '_{2}}{2}w-\\frac{\\alpha}{2}\\right) \\\\ & +\\sin\\frac{\\alpha}{2}\\cos\\left( s_{1}\\'
                   'frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}}{2}\\right'
                   ') v+s_{4}% \\frac{i-2k_{2}}{2}w-\\frac{\\alpha}{2}\\right) \\\\'),
         says='sin(X - alpha/2 + alpha/2) = cos(alpha/2) sin(X - alpha/2) + sin(alpha/2) cos(X - alpha/2).',
         status='checked',
         check='sec4_5-shift-chain'),
    Line(id='sec4_5-shift-step3',
         tex=(1814, 1825),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('& =\\cos\\frac{\\alpha}{2}\\sin\\left( s_{1}\\frac{2n-i-2k_{1}}{2}u+\\left( s_{2}\\frac{'
                   'i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}}{2}\\right) v+s_{4}% \\frac{i-2k_{2}}{2}w-\\frac{\\a'
                   'lpha}{2}\\right) \\\\ & +\\sin\\frac{\\alpha}{2}\\cos\\left( s_{1}\\frac{2n-i-2k_{1}}{2}'
                   'u+\\left( s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}}{2}\\right) v+s_{4}% \\frac{i-'
                   '2k_{2}}{2}w-\\frac{\\alpha}{2}\\right) \\\\ & =\\cos\\frac{\\alpha}{2}\\sin\\left( s_{1}'
                   '\\frac{2n-i-1-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}-s_{3}}'
                   '{2}\\right) v+s_{4}% \\frac{i-2k_{2}-s_{4}}{2}w\\right) \\\\ & +\\sin\\frac{\\alpha}{2}'
                   '\\cos\\left( s_{1}\\frac{2n-i-1-2k_{1}}{2}u+\\left( s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\fr'
                   'ac{j-2k_{4}-s_{3}}{2}\\right) v+s_{4}% \\frac{i-2k_{2}-s_{4}}{2}w\\right) ,'),
         says='... = cos(alpha/2) sin(P) + sin(alpha/2) cos(P), P = X - (u+v+w)/2 with shifted coefficients.',
         status='checked',
         check='sec4_5-shift-chain'),
    Line(id='sec4_5-integer',
         tex=(1827, 1829),
         near='possible_products_inclusion',
         kind='inline',
         verbatim=('where for all $4$-tuples $\\left( k_{1},k_{2},k_{3},k_{4}\\right) \\in K_{1,1}$ the coef'
                   'ficients of variables $u$, $v$ and $w$ are integer numbers and both of the sine and cosi'
                   'ne functions belong to the equivalence class%'),
         says='For (k1..k4) in K_{1,1} the coefficients of u, v, w are integers, both functions in one class.',
         status='checked',
         check='sec4_5-integer-class'),
    Line(id='sec4_5-class-N',
         tex=(1831, 1838),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\left[ \\underset{\\in% \\mathbb{N} }{\\underbrace{s_{1}\\frac{2n-i-1-2k_{1}}{2}-z}},\\'
                   'underset{\\in% \\mathbb{N} }{\\underbrace{s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4'
                   '}-s_{3}}{2}-z}% },\\underset{\\in% \\mathbb{N} }{\\underbrace{s_{4}\\frac{i-2k_{2}-s_{4}'
                   '}{2}-z}}\\right] ,'),
         says='The class [a - z, b - z, c - z] with entries in N.',
         status='checked',
         check='sec4_5-integer-class'),
    Line(id='sec4_5-z-min',
         tex=(1842, 1843),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('z=\\min\\left\\{ s_{1}\\frac{2n-i-1-2k_{1}}{2},s_{2}\\frac{i-j-2k_{3}}{2}% +s_{3}\\frac{'
                   'j-2k_{4}-s_{3}}{2},s_{4}\\frac{i-2k_{2}-s_{4}}{2}\\right\\} .'),
         says='z = min of the three coefficients.',
         status='checked',
         check='sec4_5-integer-class'),
    Line(id='sec4_5-z-three',
         tex=(1845, 1845),
         near='possible_products_inclusion',
         kind='prose',
         verbatim='Parameter $z$ can take three possible values.',
         says='z can take three values.',
         status='excused',
         reason='prose (the minimum is one of three entries)'),
    Line(id='sec4_5-z-case',
         tex=(1847, 1848),
         near='possible_products_inclusion',
         kind='display',
         verbatim='z=s_{2}\\frac{i-j-2k_{3}}{2}+s_{3}\\frac{j-2k_{4}-s_{3}}{2}% \\]',
         says='Case assumption: z equals the coefficient of v.',
         status='excused',
         reason='case assumption of the proof (the maxima of this case are checked by sec4_5-max-bounds)'),
    Line(id='sec4_5-max1-set',
         tex=(1851, 1854),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('& \\max\\left\\{ s_{1}\\frac{2n-i-1-2k_{1}}{2}-s_{2}\\frac{i-j-2k_{3}}{2}% -s_{3}\\frac{'
                   'j-2k_{4}-s_{3}}{2}:\\left( k_{1},k_{2},k_{3},k_{4}\\right) \\in K_{1,1},~s_{1}=1,s_{2},s'
                   '_{3}\\in\\left\\{ -1,+1\\right\\} \\right\\} \\\\ = & \\frac{2n-i-1}{2}+\\frac{i-j}{2}+'
                   '\\frac{j+1}{2}'),
         says='max{...} = (2n-i-1)/2 + (i-j)/2 + (j+1)/2.',
         status='checked',
         check='sec4_5-max-bounds'),
    Line(id='sec4_5-max1-n',
         tex=(1854, 1855),
         near='possible_products_inclusion',
         kind='display',
         verbatim='\\frac{2n-i-1}{2}+\\frac{i-j}{2}+\\frac{j+1}{2}\\\\ = & n',
         says='(2n-i-1)/2 + (i-j)/2 + (j+1)/2 = n.',
         status='checked',
         check='sec4_5-max-bounds'),
    Line(id='sec4_5-max2-set',
         tex=(1859, 1862),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('& \\max\\left\\{ s_{4}\\frac{i-2k_{2}-s_{4}}{2}-s_{2}\\frac{i-j-2k_{3}}{2}% -s_{3}\\frac'
                   '{j-2k_{4}-s_{3}}{2}:\\left( k_{1},k_{2},k_{3},k_{4}\\right) \\in K_{1,1},~s_{1}=1,s_{2},'
                   's_{3}\\in\\left\\{ -1,+1\\right\\} \\right\\} \\\\ & =\\frac{i-1}{2}+\\frac{i-j}{2}+\\fr'
                   'ac{j+1}{2}'),
         says=('max{s4(i-2k2-s4)/2 - ...} = (i-1)/2 + (i-j)/2 + (j+1)/2 (s4 as defined after the eight-term '
               'form).'),
         status='checked',
         check='sec4_5-max-bounds'),
    Line(id='sec4_5-max2-i',
         tex=(1862, 1863),
         near='possible_products_inclusion',
         kind='display',
         verbatim='=\\frac{i-1}{2}+\\frac{i-j}{2}+\\frac{j+1}{2}\\\\ & =i\\leq n.',
         says='(i-1)/2 + (i-j)/2 + (j+1)/2 = i <= n.',
         status='checked',
         check='sec4_5-max-bounds'),
    Line(id='sec4_5-other-z-cases',
         tex=(1865, 1865),
         near='possible_products_inclusion',
         kind='inline',
         verbatim='The remaining two cases of $z$ can be treated analogously.',
         says='The two other cases of z are treated analogously (the shifted coefficients stay in {0..n}).',
         status='checked',
         check='sec4_5-integer-class'),
    Line(id='sec4_5-inclusion',
         tex=(1867, 1877),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('Performing similar calculations as above, one concludes that all types of products from '
                   '(\\ref{possible_products_inclusion}) can be expanded into linear combinations of sine an'
                   'd cosine functions that belong to some equivalence classes $\\left[ r,g,b\\right] \\in$ '
                   '$\\cup_{i=1}^{n}E_{i}^{\\alpha}/_{\\sim}$. Consequently, \\[% \\operatorname{span}% T_{2'
                   'n}^{\\alpha}\\subseteq% \\operatorname{span}% V_{n}^{\\alpha}\\text{.}% \\]'),
         says='span T_{2n} is contained in span V_n.',
         status='checked',
         check='sec4_5-inclusion'),
    Line(id='sec4_5-sigma-assumption',
         tex=(1879, 1886),
         near='possible_products_inclusion',
         kind='prose',
         verbatim=('Finally, arguing by contradiction, we assume that there exists a constrained trivariate '
                   'function $\\sigma:\\Omega^{\\alpha}\\rightarrow% \\mathbb{R} $ such that $\\sigma\\in% '
                   '\\operatorname{span}% V_{n}^{\\alpha}\\setminus% \\operatorname{span}% T_{2n}^{\\alpha}$'
                   '. Then, using Theorem \\ref{joint_systems_linear_independence}'),
         says='Assume sigma in span V_n minus span T_{2n}.',
         status='excused',
         reason='assumption of a proof by contradiction'),
    Line(id='sec4_5-contradiction',
         tex=(1888, 1896),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('\\[ 1+\\delta_{n}=\\dim% \\operatorname{span}% \\left\\{ \\sigma,% \\operatorname{span}%'
                   ' T_{2n}^{\\alpha}\\right\\} \\leq\\dim% \\operatorname{span}% V_{n}^{\\alpha}=\\delta_{n'
                   '}, \\]'),
         says='1 + delta_n = dim span{sigma, span T_{2n}} <= dim span V_n = delta_n.',
         status='checked',
         check='sec4_5-coincidence-rank'),
    Line(id='sec4_5-conclusion',
         tex=(1897, 1901),
         near='possible_products_inclusion',
         kind='display',
         verbatim=('therefore $\\mathcal{T}_{2n}^{\\alpha}=% \\operatorname{span}% T_{2n}^{\\alpha}=% \\oper'
                   'atorname{span}% V_{n}^{\\alpha}=\\mathcal{V}_{n}^{\\alpha}$'),
         says='Hence T_{2n}^alpha = span T_{2n} = span V_n = V_n^alpha.',
         status='checked',
         check='sec4_5-coincidence-rank'),
    Line(id='sec4_5-section5-title',
         tex=(1907, 1907),
         near='sec:partition_of_unity',
         kind='prose',
         verbatim='\\section{\\label{sec:partition_of_unity}Partition of unity}',
         says='Section heading: partition of unity.',
         status='excused',
         reason='heading'),
    Line(id='sec4_5-unique-coefs',
         tex=(1909, 1912),
         near='sec:partition_of_unity',
         kind='inline',
         verbatim=('Since the function system (\\ref{united_system}) is a basis of the constrained trivariat'
                   'e extension of the vector space (\\ref{truncated_Fourier_vector_space}) that also contai'
                   'ns the constant function $1$, it follows that there exist unique coefficients%'),
         says='T_{2n} is a basis of a space containing 1, so unique coefficients exist.',
         status='checked',
         check='sec4_5-partition-sum'),
    Line(id='sec4_5-weights',
         tex=(1914, 1916),
         near='normalizing_weights',
         kind='index-set',
         verbatim=('r_{2n,n,n}^{\\alpha},\\left\\{ r_{2n,2n-i,j}^{\\alpha}\\right\\} _{j=0,i=j}% ^{n-1,2n-1-'
                   'j},\\left\\{ g_{2n,2n-i,j}^{\\alpha}\\right\\} _{j=0,i=j}% ^{n-1,2n-1-j},\\left\\{ b_{2n'
                   ',2n-i,j}^{\\alpha}\\right\\} _{j=0,i=j}^{n-1,2n-1-j}'),
         says='The coefficients r_{2n,n,n} and {r,g,b}_{2n,2n-i,j}, j = 0..n-1, i = j..2n-1-j.',
         status='checked',
         check='sec4_5-weights-index'),
    Line(id='sec4_5-L-one',
         tex=(1921, 1921),
         near='normalizing_weights',
         kind='display',
         verbatim='1 & =L\\left( u,v,w\\right) \\\\',
         says='1 = L(u,v,w).',
         status='checked',
         check='sec4_5-partition-sum'),
    Line(id='sec4_5-L-sum',
         tex=(1922, 1927),
         near='normalizing_weights',
         kind='display',
         verbatim=('& =r_{2n,n,n}^{\\alpha}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +\\sum _{j=0}^{n-1}\\su'
                   'm_{i=j}^{2n-1-j}r_{2n,2n-i,j}^{\\alpha}R_{2n,2n-i,j}^{\\alpha }\\left( u,v,w\\right) \\'
                   '\\ & +\\sum_{j=0}^{n-1}\\sum_{i=j}^{2n-1-j}g_{2n,2n-i,j}^{\\alpha}G_{2n,2n-i,j}% ^{\\alp'
                   'ha}\\left( u,v,w\\right) +\\sum_{j=0}^{n-1}\\sum_{i=j}^{2n-1-j}% b_{2n,2n-i,j}^{\\alpha}'
                   'B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right)'),
         says='L = r_{2n,n,n} R_{2n,n,n} + the sums over j = 0..n-1, i = j..2n-1-j of r R, g G, b B.',
         status='checked',
         check='sec4_5-partition-sum'),
    Line(id='sec4_5-L-domain',
         tex=(1929, 1929),
         near='normalizing_weights',
         kind='range',
         verbatim='for all $\\left( u,v,w\\right) \\in\\Omega^{\\alpha}$.',
         says='for all (u,v,w) in Omega^alpha.',
         status='checked',
         check='sec4_5-partition-sum'),
    Line(id='sec4_5-symmetry-1',
         tex=(1933, 1934),
         near='symmetry_condition_1',
         kind='display',
         verbatim='r_{2n,2n-i,j}^{\\alpha} & =r_{2n,i,j}^{\\alpha},~j=0,1,\\ldots ,n-1,~i=j+1,j+2,\\ldots,n-1,',
         says='r_{2n,2n-i,j} = r_{2n,i,j}, j = 0..n-1, i = j+1..n-1.',
         status='checked',
         check='sec4_5-symmetry-1'),
    Line(id='sec4_5-symmetry-2',
         tex=(1935, 1936),
         near='symmetry_condition_2',
         kind='display',
         verbatim=('g_{2n,2n-i,j}^{\\alpha} & =r_{2n,2n-i,j}^{\\alpha},~j=0,1,\\ldots ,n-1,~i=j,j+1,\\ldots,'
                   '2n-1-j,'),
         says='g_{2n,2n-i,j} = r_{2n,2n-i,j}, j = 0..n-1, i = j..2n-1-j.',
         status='checked',
         check='sec4_5-symmetry-2'),
    Line(id='sec4_5-symmetry-3',
         tex=(1937, 1938),
         near='symmetry_condition_3',
         kind='display',
         verbatim=('b_{2n,2n-i,j}^{\\alpha} & =r_{2n,2n-i,j}^{\\alpha},~j=0,1,\\ldots ,n-1,~i=j,j+1,,\\ldots'
                   ',2n-1-j,'),
         says='b_{2n,2n-i,j} = r_{2n,2n-i,j}, j = 0..n-1, i = j..2n-1-j (printed with a doubled comma).',
         status='checked',
         check='sec4_5-symmetry-3'),
    Line(id='sec4_5-unknowns',
         tex=(1940, 1941),
         near='symmetry_condition_3',
         kind='index-set',
         verbatim='where constants $\\left\\{ r_{2n,2n-i,j}^{\\alpha}\\right\\} _{j=0,i=j}^{n,n}$',
         says='The unknowns are {r_{2n,2n-i,j}}_{j=0,i=j}^{n,n}.',
         status='checked',
         check='sec4_5-unknowns'),
    Line(id='sec4_5-lower-triangular',
         tex=(1943, 1946),
         near='symmetry_condition_3',
         kind='prose',
         verbatim=('For the present we are not able to give a closed form of normalizing coefficients (\\ref'
                   '{normalizing_weights}) for arbitrary order $n\\geq1$, however we propose an efficient te'
                   'chnique using which one can reduce their determination to the solution of several lower '
                   'triangular linear systems.'),
         says='No closed form for arbitrary n; a reduction to lower triangular systems is proposed.',
         status='excused',
         reason='methodological prose'),
    Line(id='sec4_5-system',
         tex=(1950, 1953),
         near='system_partition_of_unity',
         kind='display',
         verbatim=('\\left. \\frac{\\partial^{r}}{\\partial y^{r}}L\\left( u\\left( x,y\\right) ,v\\left( x,'
                   'y\\right) ,w\\left( x,y\\right) \\right) \\right\\vert _{y=0}% =\\delta_{r,0},~\\forall '
                   'x\\in\\left[ 0,\\alpha\\right]'),
         says='d^r/dy^r L(u(x,y), v(x,y), w(x,y)) at y = 0 equals delta_{r,0} for x in [0, alpha], r = 0..n.',
         status='checked',
         check='sec4_5-system'),
    Line(id='sec4_5-system-y-range',
         tex=(1952, 1953),
         near='system_partition_of_unity',
         kind='range',
         verbatim='\\forall y\\in\\left[ 0,\\alpha-x\\right]',
         says='y in [0, alpha - x].',
         status='erratum',
         check='claim:independence_proof_steps',
         erratum={'printed': 'for all x in [0, alpha], y in [0, alpha - x]',
                  'corrected': 'y in [0, x] (under parametrization_for_partition_of_unity)',
                  'evidence': ('same as erratum parametrization-partition-of-unity-range; the system is onl'
                                'y evaluated at y = 0'),
                  'severity': 'typo'}),
    Line(id='sec4_5-system-r-range',
         tex=(1953, 1953),
         near='system_partition_of_unity',
         kind='range',
         verbatim='\\forall r=0,1,\\ldots,n',
         says='r = 0, 1, ..., n.',
         status='checked',
         check='sec4_5-system'),
    Line(id='sec4_5-param-prose',
         tex=(1955, 1959),
         near='system_partition_of_unity',
         kind='prose',
         verbatim=('under parametrization (\\ref{parametrization_for_partition_of_unity}), where $\\delta_{r'
                   ',0}$ denotes the Kronecker delta. (Naturally, one may solve the system (\\ref{system_par'
                   'tition_of_unity}) by using a different parametrization, however symbolic calculations pr'
                   'oved to be much shorter and easier under parametrization (\\ref{parametrization_for_part'
                   'ition_of_unity}).)'),
         says='delta_{r,0} is the Kronecker delta; another parametrization could be used.',
         status='excused',
         reason='notation and methodological prose'),
    Line(id='sec4_5-level0-r-c',
         tex=(1964, 1965),
         near='normalizing_coeff_of_level_0',
         kind='display',
         verbatim='\\[ r_{2n,2n-i,0}^{\\alpha}=c_{2n,2n-i}^{\\alpha}',
         says='r_{2n,2n-i,0} = c_{2n,2n-i}.',
         status='checked',
         check='sec4_5-level-0'),
    Line(id='sec4_5-level0-c-c',
         tex=(1965, 1966),
         near='normalizing_coeff_of_level_0',
         kind='display',
         verbatim='c_{2n,2n-i}^{\\alpha}=c_{2n,i}^{\\alpha},~\\forall i=0,1,\\ldots,n.',
         says='c_{2n,2n-i} = c_{2n,i}, i = 0..n.',
         status='checked',
         check='sec4_5-level-0'),
    Line(id='sec4_5-parametrization-restated',
         tex=(1971, 1973),
         near='normalizing_coeff_of_level_0',
         kind='parametrization',
         verbatim=('For each order $r=1,2,\\ldots,n$, after evaluating the $r$th order mixed partial derivat'
                   'ives with respect to $v\\left( x,y\\right) =y$ and $w\\left( x,y\\right) =x-y$ at $y=0$'),
         says='r = 1..n; derivatives with respect to v(x,y) = y and w(x,y) = x - y at y = 0.',
         status='checked',
         check='sec4_5-chain-rule'),
    Line(id='sec4_5-cos-nonzero',
         tex=(1974, 1975),
         near='normalizing_coeff_of_level_0',
         kind='bound',
         verbatim='$\\cos^{2n}\\frac{x}{2}\\neq0$ ($x\\in\\left[ 0,\\alpha\\right] $)',
         says='cos^{2n}(x/2) != 0 for x in [0, alpha].',
         status='checked',
         check='sec4_5-tan-polynomial'),
    Line(id='sec4_5-chain-sum',
         tex=(1977, 1980),
         near='normalizing_coeff_of_level_0',
         kind='display',
         verbatim=('\\sum_{k=0}^{r}\\dbinom{r}{k}\\left( -1\\right) ^{k}\\left. \\frac{\\partial^{r}% }{\\pa'
                   'rtial v^{r-k}\\partial w^{k}}L\\left( u\\left( x,y\\right) ,v\\left( x,y\\right) ,w\\lef'
                   't( x,y\\right) \\right) \\right\\vert _{y=0}=0,~\\forall x\\in\\left[ 0,\\alpha\\right]'),
         says='sum_k C(r,k)(-1)^k d^r L/dv^{r-k}dw^k at y = 0 equals 0 for x in [0, alpha].',
         status='checked',
         check='sec4_5-chain-rule'),
    Line(id='sec4_5-chain-y-range',
         tex=(1980, 1980),
         near='normalizing_coeff_of_level_0',
         kind='range',
         verbatim='y\\in\\left[ 0,\\alpha-x\\right]',
         says='y in [0, alpha - x] (restated).',
         status='erratum',
         check='sec4_5-y-range-1980',
         erratum={'printed': ('y in [0, alpha - x] (in the equality after system_partition_of_unity, under '
                               'v = y, w = x - y)'),
                  'corrected': 'y in [0, x]',
                  'evidence': ('with the printed range the parameter triangle is not mapped into Omega^alph'
                                'a (x = alpha/4, y = alpha/2 gives w = -alpha/4); with y in [0, x] it is map'
                                'ped onto Omega^alpha (exact grid, alpha = 3/2); the same slip as erratum sy'
                                'stem-partition-of-unity-range, printed a second time'),
                  'severity': 'typo'}),
    Line(id='sec4_5-tan-polynomial',
         tex=(1982, 1985),
         near='normalizing_coeff_of_level_0',
         kind='inline',
         verbatim=('can be rewritten into a polynomial expression of $\\tan\\frac{x}{2}$, since the sum of p'
                   'owers of trigonometric functions $\\sin\\frac{\\alpha-x}{2}$, $\\cos \\frac{\\alpha-x}{2'
                   '}$, $\\sin\\frac{x}{2}$ and $\\cos\\frac{x}{2}$ appearing as potential factors in the te'
                   'rms of the left hand side always equals $2n$.'),
         says=('The equality is a polynomial in tan(x/2): every term has total power 2n in sin, cos of (alph'
               'a-x)/2 and x/2.'),
         status='checked',
         check='sec4_5-tan-polynomial'),
    Line(id='sec4_5-level1-intro',
         tex=(1987, 1990),
         near='normalizing_coeff_of_level_0',
         kind='prose',
         verbatim=('As an example consider the first order partial derivative of the function system (\\ref{'
                   'united_system}) with respect to $y$, at $y=0$ under parametrization (\\ref{parametrizati'
                   'on_for_partition_of_unity}). Then, we have the next proposition the rather lengthy and t'
                   'echnical proof of which can be found in \\cite{tech_report}.'),
         says='The first order derivative leads to the next proposition, proven in the technical report.',
         status='excused',
         reason='citation of the proof (tech_report)'),
    Line(id='sec4_5-level1-range',
         tex=(1994, 1995),
         near='prop:level_1_coefficients',
         kind='index-set',
         verbatim=('arbitrary order $n\\geq2$, normalizing constants $\\left\\{ r_{2n,2n-i,1}% ^{\\alpha}\\r'
                   'ight\\} _{i=1}^{n}$'),
         says='For n >= 2 the constants {r_{2n,2n-i,1}}_{i=1}^n.',
         status='checked',
         check='sec4_5-level-1'),
    Line(id='sec4_5-level1-i1',
         tex=(2000, 2000),
         near='level_1_coefficients',
         kind='display',
         verbatim='\\dfrac{2}{\\sin\\frac{\\alpha}{2}}c_{2n,2n-2}^{\\alpha}, & i=1,\\\\',
         says='r_{2n,2n-1,1} = 2/sin(alpha/2) c_{2n,2n-2}.',
         status='checked',
         check='sec4_5-level-1'),
    Line(id='sec4_5-level1-i',
         tex=(2002, 2004),
         near='level_1_coefficients',
         kind='display',
         verbatim=('\\dfrac{i}{\\sin\\frac{\\alpha}{2}}c_{2n,2n-i}^{\\alpha}\\cos\\frac{\\alpha}{2}% +\\dfra'
                   'c{i+1}{\\sin\\frac{\\alpha}{2}}c_{2n,2n-\\left( i+1\\right) }^{\\alpha}, & i=2,3,\\ldots'
                   ',n.'),
         says='r_{2n,2n-i,1} = i/s c_{2n,2n-i} cos(alpha/2) + (i+1)/s c_{2n,2n-(i+1)}, i = 2..n.',
         status='checked',
         check='sec4_5-level-1'),
    Line(id='sec4_5-closed-forms-index',
         tex=(2012, 2016),
         near='level_1_coefficients',
         kind='index-set',
         verbatim=('the $r$th order ($2\\leq r\\leq n$) partial derivatives appearing in the system (\\ref{s'
                   'ystem_partition_of_unity}), one is able to calculate the closed form of normalizing cons'
                   'tants $\\left\\{ r_{2n,2n-i,j}^{\\alpha}\\right\\} _{j=0,i=j}% ^{n,n}$'),
         says='r-th order derivatives, 2 <= r <= n, give {r_{2n,2n-i,j}}_{j=0,i=j}^{n,n}.',
         status='checked',
         check='sec4_5-unknowns'),
    Line(id='sec4_5-examples-intro',
         tex=(2016, 2018),
         near='level_1_coefficients',
         kind='prose',
         verbatim=('Examples \\ref{normalizing_coefficients_n_1}--\\ref{normalizing_coefficients_n_3} provid'
                   'e closed formulas of these normalizing coefficients for $n=1,~2$ and $3$, respectively.'),
         says='Examples n = 1, 2, 3 give closed formulas.',
         status='excused',
         reason='pointer to the Examples (each checked line by line)'),
    Line(id='sec4_5-unique-solution-n1',
         tex=(2022, 2023),
         near='normalizing_coefficients_n_1',
         kind='inline',
         verbatim='the unique solution of the system (\\ref{system_partition_of_unity}) is%',
         says=('n = 1: the system (system_partition_of_unity) has a unique solution (in the unknowns left by'
               ' the symmetry conditions).'),
         status='checked',
         check='sec4_5-system'),
    Line(id='sec4_5-ex-r220-r-c',
         tex=(2025, 2025),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim='r_{2,2,0}^{\\alpha} & =c_{2,2}^{\\alpha}',
         says='r_{2,2,0} = c (Remark normalizing_coeff_of_level_0 for n = 1).',
         status='checked',
         check='sec4_5-ex-r220-mid'),
    Line(id='sec4_5-ex-r220-c-value',
         tex=(2025, 2025),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim='c_{2,2}^{\\alpha}=\\frac{1}{\\sin^{2}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{2,2,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r220-c'),
    Line(id='sec4_5-ex-r210-r-c',
         tex=(2026, 2027),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim='r_{2,1,0}^{\\alpha} & =c_{2,1}^{\\alpha}',
         says='r_{2,1,0} = c (Remark normalizing_coeff_of_level_0 for n = 1).',
         status='checked',
         check='sec4_5-ex-r210-mid'),
    Line(id='sec4_5-ex-r210-c-value',
         tex=(2026, 2027),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim='c_{2,1}^{\\alpha}=\\frac{2\\cos\\frac{\\alpha}{2}}{\\sin ^{2}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{2,1,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r210-c'),
    Line(id='sec4_5-ex-r211-mid',
         tex=(2028, 2030),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim=('r_{2,1,1}^{\\alpha} & =\\frac{2}{\\sin\\frac{\\alpha}{2}}c_{2,2}^{\\alpha}% -\\frac{1}{'
                   '\\sin\\frac{\\alpha}{2}}c_{2,1}^{\\alpha}\\cos\\frac{\\alpha}{2}%'),
         says='r_{2,1,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r211-mid'),
    Line(id='sec4_5-ex-r211-final',
         tex=(2028, 2030),
         near='normalizing_coefficients_n_1',
         kind='display',
         verbatim=('\\frac{2}{\\sin\\frac{\\alpha}{2}}c_{2,2}^{\\alpha}% -\\frac{1}{\\sin\\frac{\\alpha}{2}}'
                   'c_{2,1}^{\\alpha}\\cos\\frac{\\alpha}{2}% =\\frac{2\\sin\\frac{\\alpha}{2}}{\\sin^{2}\\f'
                   'rac{\\alpha}{2}}'),
         says='r_{2,1,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r211-final'),
    Line(id='sec4_5-unique-solution-n2',
         tex=(2036, 2036),
         near='normalizing_coefficients_n_2',
         kind='inline',
         verbatim='the system (\\ref{system_partition_of_unity}) admits the unique solution%',
         says=('n = 2: the system (system_partition_of_unity) has a unique solution (in the unknowns left by'
               ' the symmetry conditions).'),
         status='checked',
         check='sec4_5-system'),
    Line(id='sec4_5-ex-r440-r-c',
         tex=(2038, 2038),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='r_{4,4,0}^{\\alpha} & =c_{4,4}^{\\alpha}',
         says='r_{4,4,0} = c (Remark normalizing_coeff_of_level_0 for n = 2).',
         status='checked',
         check='sec4_5-ex-r440-mid'),
    Line(id='sec4_5-ex-r440-c-value',
         tex=(2038, 2038),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='c_{4,4}^{\\alpha}=\\frac{1}{\\sin^{4}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{4,4,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r440-c'),
    Line(id='sec4_5-ex-r430-r-c',
         tex=(2039, 2040),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='r_{4,3,0}^{\\alpha} & =c_{4,3}^{\\alpha}',
         says='r_{4,3,0} = c (Remark normalizing_coeff_of_level_0 for n = 2).',
         status='checked',
         check='sec4_5-ex-r430-mid'),
    Line(id='sec4_5-ex-r430-c-value',
         tex=(2039, 2040),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='c_{4,3}^{\\alpha}=\\frac{4\\cos\\frac{\\alpha}{2}}{\\sin ^{4}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{4,3,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r430-c'),
    Line(id='sec4_5-ex-r420-r-c',
         tex=(2041, 2042),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='r_{4,2,0}^{\\alpha} & =c_{4,2}^{\\alpha}',
         says='r_{4,2,0} = c (Remark normalizing_coeff_of_level_0 for n = 2).',
         status='checked',
         check='sec4_5-ex-r420-mid'),
    Line(id='sec4_5-ex-r420-c-value',
         tex=(2041, 2042),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='c_{4,2}^{\\alpha}=\\frac{2+4\\cos^{2}\\frac{\\alpha}{2}% }{\\sin^{4}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{4,2,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r420-c'),
    Line(id='sec4_5-ex-r431-mid',
         tex=(2043, 2044),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim='r_{4,3,1}^{\\alpha} & =\\dfrac{2}{\\sin\\frac{\\alpha}{2}}c_{4,2}^{\\alpha}%',
         says='r_{4,3,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r431-mid'),
    Line(id='sec4_5-ex-r431-final',
         tex=(2043, 2044),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim=('\\dfrac{2}{\\sin\\frac{\\alpha}{2}}c_{4,2}^{\\alpha}% =\\frac{4+8\\cos^{2}\\frac{\\alpha'
                   '}{2}}{\\sin^{5}\\frac{\\alpha}{2}}'),
         says='r_{4,3,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r431-final'),
    Line(id='sec4_5-ex-r421-mid',
         tex=(2045, 2048),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim=('r_{4,2,1}^{\\alpha} & =\\dfrac{2}{\\sin\\frac{\\alpha}{2}}c_{4,2}^{\\alpha}% \\cos\\frac'
                   '{\\alpha}{2}+\\dfrac{3}{\\sin\\frac{\\alpha}{2}}c_{4,3}^{\\alpha}%'),
         says='r_{4,2,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r421-mid'),
    Line(id='sec4_5-ex-r421-final',
         tex=(2045, 2048),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim=('\\dfrac{2}{\\sin\\frac{\\alpha}{2}}c_{4,2}^{\\alpha}% \\cos\\frac{\\alpha}{2}+\\dfrac{3}'
                   '{\\sin\\frac{\\alpha}{2}}c_{4,3}^{\\alpha}% =\\frac{16\\cos\\frac{\\alpha}{2}+8\\cos^{3}'
                   '\\frac{\\alpha}{2}}{\\sin^{5}\\frac{\\alpha }{2}}'),
         says='r_{4,2,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r421-final'),
    Line(id='sec4_5-ex-r422-mid',
         tex=(2049, 2053),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim=('r_{4,2,2}^{\\alpha} & =-\\frac{6}{\\sin^{2}\\frac{\\alpha}{2}}c_{4,4}^{\\alpha }-\\frac{'
                   '3\\cos\\frac{\\alpha}{2}}{\\sin^{2}\\frac{\\alpha}{2}}c_{4,3}^{\\alpha }+\\left( \\frac{'
                   '6}{\\sin^{2}\\frac{\\alpha}{2}}-\\frac{3\\cos^{2}\\frac{\\alpha}{2}% }{\\sin^{2}\\frac{'
                   '\\alpha}{2}}+2\\right) c_{4,2}^{\\alpha}'),
         says='r_{4,2,2} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r422-mid'),
    Line(id='sec4_5-ex-r422-final',
         tex=(2049, 2053),
         near='normalizing_coefficients_n_2',
         kind='display',
         verbatim=('-\\frac{6}{\\sin^{2}\\frac{\\alpha}{2}}c_{4,4}^{\\alpha }-\\frac{3\\cos\\frac{\\alpha}{2'
                   '}}{\\sin^{2}\\frac{\\alpha}{2}}c_{4,3}^{\\alpha }+\\left( \\frac{6}{\\sin^{2}\\frac{\\al'
                   'pha}{2}}-\\frac{3\\cos^{2}\\frac{\\alpha}{2}% }{\\sin^{2}\\frac{\\alpha}{2}}+2\\right) c'
                   '_{4,2}^{\\alpha}=\\frac{10+20\\cos ^{2}\\frac{\\alpha}{2}}{\\sin^{4}\\frac{\\alpha}{2}}'),
         says='r_{4,2,2} in closed form.',
         status='checked',
         check='sec4_5-ex-r422-final'),
    Line(id='sec4_5-wang-remark',
         tex=(2059, 2062),
         near='normalizing_coefficients_n_2',
         kind='prose',
         verbatim=('Normalizing coefficients provided in Examples \\ref{normalizing_coefficients_n_1} and \\'
                   'ref{normalizing_coefficients_n_2} also appeared (without any explanations) in articles '
                   '\\cite{Wang2010a} and \\cite{Wang2010b}, respectively.'),
         says='The coefficients of Examples n = 1, 2 appeared in Wang2010a, Wang2010b.',
         status='excused',
         reason='citation'),
    Line(id='sec4_5-unique-solution-n3',
         tex=(2066, 2067),
         near='normalizing_coefficients_n_3',
         kind='inline',
         verbatim='the system (\\ref{system_partition_of_unity}) has the unique solution%',
         says=('n = 3: the system (system_partition_of_unity) has a unique solution (in the unknowns left by'
               ' the symmetry conditions).'),
         status='checked',
         check='sec4_5-system'),
    Line(id='sec4_5-ex-r660-r-c',
         tex=(2069, 2069),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='r_{6,6,0}^{\\alpha} & =c_{6,6}^{\\alpha}',
         says='r_{6,6,0} = c (Remark normalizing_coeff_of_level_0 for n = 3).',
         status='checked',
         check='sec4_5-ex-r660-mid'),
    Line(id='sec4_5-ex-r660-c-value',
         tex=(2069, 2069),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='c_{6,6}^{\\alpha}=\\frac{1}{\\sin^{6}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{6,6,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r660-c'),
    Line(id='sec4_5-ex-r650-r-c',
         tex=(2070, 2071),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='r_{6,5,0}^{\\alpha} & =c_{6,5}^{\\alpha}',
         says='r_{6,5,0} = c (Remark normalizing_coeff_of_level_0 for n = 3).',
         status='checked',
         check='sec4_5-ex-r650-mid'),
    Line(id='sec4_5-ex-r650-c-value',
         tex=(2070, 2071),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='c_{6,5}^{\\alpha}=\\frac{6\\cos\\frac{\\alpha}{2}}{\\sin ^{6}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{6,5,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r650-c'),
    Line(id='sec4_5-ex-r640-r-c',
         tex=(2072, 2073),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='r_{6,4,0}^{\\alpha} & =c_{6,4}^{\\alpha}',
         says='r_{6,4,0} = c (Remark normalizing_coeff_of_level_0 for n = 3).',
         status='checked',
         check='sec4_5-ex-r640-mid'),
    Line(id='sec4_5-ex-r640-c-value',
         tex=(2072, 2073),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='c_{6,4}^{\\alpha}=\\frac{12\\cos^{2}\\frac{\\alpha}{2}% +3}{\\sin^{6}\\frac{\\alpha}{2}}',
         says='the univariate constant of r_{6,4,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r640-c'),
    Line(id='sec4_5-ex-r630-r-c',
         tex=(2074, 2075),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='r_{6,3,0}^{\\alpha} & =c_{6,3}^{\\alpha}',
         says='r_{6,3,0} = c (Remark normalizing_coeff_of_level_0 for n = 3).',
         status='checked',
         check='sec4_5-ex-r630-mid'),
    Line(id='sec4_5-ex-r630-c-value',
         tex=(2074, 2075),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('c_{6,3}^{\\alpha}=\\frac{8\\cos^{3}\\frac{\\alpha}% {2}+12\\cos\\frac{\\alpha}{2}}{\\sin'
                   '^{6}\\frac{\\alpha}{2}}'),
         says='the univariate constant of r_{6,3,0} in closed form.',
         status='checked',
         check='sec4_5-ex-r630-c'),
    Line(id='sec4_5-ex-r651-mid',
         tex=(2076, 2077),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim='r_{6,5,1}^{\\alpha} & =\\frac{2}{\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}%',
         says='r_{6,5,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r651-mid'),
    Line(id='sec4_5-ex-r651-final',
         tex=(2076, 2077),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('\\frac{2}{\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}% =\\frac{24\\cos^{2}\\frac{\\alpha}{'
                   '2}+6}{\\sin^{7}\\frac{\\alpha}{2}}'),
         says='r_{6,5,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r651-final'),
    Line(id='sec4_5-ex-r641-mid',
         tex=(2078, 2081),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('r_{6,4,1}^{\\alpha} & =\\frac{3}{\\sin\\frac{\\alpha}{2}}c_{6,3}^{\\alpha}% +\\frac{2\\c'
                   'os\\frac{\\alpha}{2}}{\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}%'),
         says='r_{6,4,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r641-mid'),
    Line(id='sec4_5-ex-r641-final',
         tex=(2078, 2081),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('\\frac{3}{\\sin\\frac{\\alpha}{2}}c_{6,3}^{\\alpha}% +\\frac{2\\cos\\frac{\\alpha}{2}}{'
                   '\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}% =\\frac{48\\cos^{3}\\frac{\\alpha}{2}+42\\cos'
                   '\\frac{\\alpha}{2}}{\\sin^{7}\\frac {\\alpha}{2}}'),
         says='r_{6,4,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r641-final'),
    Line(id='sec4_5-ex-r631-mid',
         tex=(2082, 2085),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('r_{6,3,1}^{\\alpha} & =\\frac{4}{\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}% +\\frac{3\\c'
                   'os\\frac{\\alpha}{2}}{\\sin\\frac{\\alpha}{2}}c_{6,3}^{\\alpha}%'),
         says='r_{6,3,1} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r631-mid'),
    Line(id='sec4_5-ex-r631-final',
         tex=(2082, 2085),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('\\frac{4}{\\sin\\frac{\\alpha}{2}}c_{6,4}^{\\alpha}% +\\frac{3\\cos\\frac{\\alpha}{2}}{'
                   '\\sin\\frac{\\alpha}{2}}c_{6,3}^{\\alpha}% =\\frac{24\\cos^{4}\\frac{\\alpha}{2}+84\\cos'
                   '^{2}\\frac{\\alpha}{2}+12}{\\sin^{7}% \\frac{\\alpha}{2}}'),
         says='r_{6,3,1} in closed form.',
         status='checked',
         check='sec4_5-ex-r631-final'),
    Line(id='sec4_5-ex-r642-mid',
         tex=(2086, 2089),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('r_{6,4,2}^{\\alpha} & =c_{6,4}\\left( 2+\\dfrac{6}{\\sin^{2}\\frac{\\alpha}{2}% }\\right'
                   ') +c_{6,3}^{\\alpha}\\frac{6}{\\sin^{2}\\frac{\\alpha}{2}}\\cos\\frac{\\alpha }{2}'),
         says='r_{6,4,2} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r642-mid'),
    Line(id='sec4_5-ex-r642-final',
         tex=(2086, 2089),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('c_{6,4}\\left( 2+\\dfrac{6}{\\sin^{2}\\frac{\\alpha}{2}% }\\right) +c_{6,3}^{\\alpha}\\f'
                   'rac{6}{\\sin^{2}\\frac{\\alpha}{2}}\\cos\\frac{\\alpha }{2}=\\frac{24\\cos^{4}\\frac{\\a'
                   'lpha}{2}+162\\cos^{2}\\frac{\\alpha}{2}+24}{\\sin ^{8}\\frac{\\alpha}{2}}'),
         says='r_{6,4,2} in closed form.',
         status='checked',
         check='sec4_5-ex-r642-final'),
    Line(id='sec4_5-ex-r632-mid',
         tex=(2090, 2096),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('r_{6,3,2}^{\\alpha} & =-10\\frac{1}{\\sin^{2}\\frac{\\alpha}{2}}c_{6,5}^{\\alpha }+\\lef'
                   't( \\frac{8\\cos^{3}\\frac{\\alpha}{2}}{\\sin^{2}\\frac{\\alpha}{2}}% +8\\cos\\frac{\\al'
                   'pha}{2}\\right) c_{6,4}^{\\alpha}+\\left( \\frac{6\\cos^{2}% \\frac{\\alpha}{2}}{\\sin^{'
                   '2}\\frac{\\alpha}{2}}+\\frac{12}{\\sin^{2}\\frac{\\alpha}% {2}}+3\\right) c_{6,3}^{\\alp'
                   'ha}\\\\ &'),
         says='r_{6,3,2} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r632-mid'),
    Line(id='sec4_5-ex-r632-final',
         tex=(2090, 2096),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('-10\\frac{1}{\\sin^{2}\\frac{\\alpha}{2}}c_{6,5}^{\\alpha }+\\left( \\frac{8\\cos^{3}\\f'
                   'rac{\\alpha}{2}}{\\sin^{2}\\frac{\\alpha}{2}}% +8\\cos\\frac{\\alpha}{2}\\right) c_{6,4}'
                   '^{\\alpha}+\\left( \\frac{6\\cos^{2}% \\frac{\\alpha}{2}}{\\sin^{2}\\frac{\\alpha}{2}}+'
                   '\\frac{12}{\\sin^{2}\\frac{\\alpha}% {2}}+3\\right) c_{6,3}^{\\alpha}\\\\ & =\\frac{24\\'
                   'cos^{5}\\frac{\\alpha}{2}+252\\cos^{3}\\frac{\\alpha}{2}+144\\cos \\frac{\\alpha}{2}}{\\'
                   'sin^{8}\\frac{\\alpha}{2}}'),
         says='r_{6,3,2} in closed form.',
         status='checked',
         check='sec4_5-ex-r632-final'),
    Line(id='sec4_5-ex-r633-mid',
         tex=(2097, 2107),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('r_{6,3,3}^{\\alpha} & =\\frac{20}{\\sin^{3}\\frac{\\alpha}{2}}c_{6,6}^{\\alpha }+\\frac{'
                   '50}{\\sin^{3}\\frac{\\alpha}{2}}\\cos\\frac{\\alpha}{2}c_{6,5}^{\\alpha }-\\left( \\frac'
                   '{56}{\\sin^{3}\\frac{\\alpha}{2}}\\cos^{4}\\frac{\\alpha}{2}% -\\frac{60}{\\sin^{3}\\fra'
                   'c{\\alpha}{2}}\\cos^{2}\\frac{\\alpha}{2}-\\frac{8}% {\\sin\\frac{\\alpha}{2}}+\\frac{56'
                   '}{\\sin\\frac{\\alpha}{2}}\\cos^{2}\\frac{\\alpha}% {2}-\\frac{4}{\\sin^{3}\\frac{\\alph'
                   'a}{2}}\\right) c_{6,4}^{\\alpha}\\\\ & -\\left( \\frac{10}{\\sin^{3}\\frac{\\alpha}{2}}'
                   '\\cos^{3}\\frac{\\alpha}{2}% -\\frac{3}{\\sin\\frac{\\alpha}{2}}\\cos\\frac{\\alpha}{2}+'
                   '\\frac{12}{\\sin^{3}% \\frac{\\alpha}{2}}\\cos\\frac{\\alpha}{2}\\right) c_{6,3}^{\\alph'
                   'a}\\\\ &'),
         says='r_{6,3,3} as a combination of the constants c_{2n,i}.',
         status='checked',
         check='sec4_5-ex-r633-mid'),
    Line(id='sec4_5-ex-r633-final',
         tex=(2097, 2107),
         near='normalizing_coefficients_n_3',
         kind='display',
         verbatim=('\\frac{20}{\\sin^{3}\\frac{\\alpha}{2}}c_{6,6}^{\\alpha }+\\frac{50}{\\sin^{3}\\frac{\\a'
                   'lpha}{2}}\\cos\\frac{\\alpha}{2}c_{6,5}^{\\alpha }-\\left( \\frac{56}{\\sin^{3}\\frac{\\'
                   'alpha}{2}}\\cos^{4}\\frac{\\alpha}{2}% -\\frac{60}{\\sin^{3}\\frac{\\alpha}{2}}\\cos^{2}'
                   '\\frac{\\alpha}{2}-\\frac{8}% {\\sin\\frac{\\alpha}{2}}+\\frac{56}{\\sin\\frac{\\alpha}{'
                   '2}}\\cos^{2}\\frac{\\alpha}% {2}-\\frac{4}{\\sin^{3}\\frac{\\alpha}{2}}\\right) c_{6,4}^'
                   '{\\alpha}\\\\ & -\\left( \\frac{10}{\\sin^{3}\\frac{\\alpha}{2}}\\cos^{3}\\frac{\\alpha}'
                   '{2}% -\\frac{3}{\\sin\\frac{\\alpha}{2}}\\cos\\frac{\\alpha}{2}+\\frac{12}{\\sin^{3}% \\'
                   'frac{\\alpha}{2}}\\cos\\frac{\\alpha}{2}\\right) c_{6,3}^{\\alpha}\\\\ & =\\frac{-104\\c'
                   'os^{6}\\frac{\\alpha}{2}-276\\cos^{4}\\frac{\\alpha}{2}+324\\cos ^{2}\\frac{\\alpha}{2}+'
                   '56}{\\sin^{9}\\frac{\\alpha}{2}}'),
         says='r_{6,3,3} in closed form.',
         status='checked',
         check='sec4_5-ex-r633-final'),
    Line(id='sec4_5-matrix-sizes',
         tex=(2115, 2119),
         near='normalizing_coefficients_n_3',
         kind='count',
         verbatim=('can be reduced from $\\delta_{n}=3n\\left( n+1\\right) +1$ to $\\frac{1}{2}\\left( n+1\\'
                   'right) \\left( n+2\\right) $ that can be further reduced to $\\frac{1}{2}n\\left( n+1\\r'
                   'ight) $'),
         says=('Matrix size delta_n = 3n(n+1)+1, reduced to (n+1)(n+2)/2 by symmetry and to n(n+1)/2 by Rema'
               'rk level 0.'),
         status='checked',
         check='sec4_5-matrix-sizes'),
    Line(id='sec4_5-blending-set',
         tex=(2128, 2131),
         near='normalized_united_system',
         kind='index-set',
         verbatim=('\\overline{T}_{2n}^{\\alpha} & = & \\left\\{ \\overline{R}_{2n,2n-i,j}^{\\alpha }\\left('
                   ' u,v,w\\right) ,\\overline{G}_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,\\overline{B}_'
                   '{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) :\\left( u,v,w\\right) \\in\\Omega^{\\alpha}'
                   '\\right\\} _{j=0,i=j}^{n-1,2n-1-j}\\\\'),
         says='T-bar_{2n} = {R-bar, G-bar, B-bar}_{2n,2n-i,j}, j = 0..n-1, i = j..2n-1-j ...',
         status='checked',
         check='sec4_5-blending-def'),
    Line(id='sec4_5-blending-centre-set',
         tex=(2133, 2136),
         near='normalized_united_system',
         kind='display',
         verbatim=('& & \\cup\\left\\{ \\overline{R}_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) =\\overline{G}_'
                   '{2n,n,n}^{\\alpha}\\left( u,v,w\\right) =\\overline{B}% _{2n,n,n}^{\\alpha}\\left( u,v,w'
                   '\\right) :\\left( u,v,w\\right) \\in \\Omega^{\\alpha}\\right\\}'),
         says='... together with R-bar_{2n,n,n} = G-bar_{2n,n,n} = B-bar_{2n,n,n}.',
         status='checked',
         check='sec4_5-blending-def'),
    Line(id='sec4_5-blending-order',
         tex=(2140, 2141),
         near='normalized_united_system',
         kind='definition',
         verbatim='are called constrained trivariate trigonometric blending functions of order $n\\geq1$',
         says='blending functions of order n >= 1.',
         status='excused',
         reason='introduces a name'),
    Line(id='sec4_5-blending-R',
         tex=(2143, 2144),
         near='normalized_united_system',
         kind='definition',
         verbatim=('\\overline{R}_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) & =r_{2n,2n-i,j}% ^{\\alpha}R_{'
                   '2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,\\\\'),
         says='R-bar = coefficient times R.',
         status='excused',
         reason='definition of the normalized functions'),
    Line(id='sec4_5-blending-G',
         tex=(2145, 2146),
         near='normalized_united_system',
         kind='definition',
         verbatim=('\\overline{G}_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) & =g_{2n,2n-i,j}% ^{\\alpha}G_{'
                   '2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,\\\\'),
         says='G-bar = coefficient times G.',
         status='excused',
         reason='definition of the normalized functions'),
    Line(id='sec4_5-blending-B',
         tex=(2147, 2148),
         near='normalized_united_system',
         kind='definition',
         verbatim='\\overline{B}_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right)',
         says='B-bar = coefficient times B.',
         status='excused',
         reason='definition of the normalized functions'),
    Line(id='sec4_5-blending-centre',
         tex=(2152, 2154),
         near='normalized_united_system',
         kind='display',
         verbatim=('\\overline{R}_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) =\\overline{G}% _{2n,n,n}^{\\alpha'
                   '}\\left( u,v,w\\right) =\\overline{B}_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) =r_{2n,n,n'
                   '}^{\\alpha}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) .'),
         says='R-bar_{2n,n,n} = G-bar_{2n,n,n} = B-bar_{2n,n,n} = r_{2n,n,n} R_{2n,n,n}.',
         status='checked',
         check='sec4_5-blending-def'),
    Line(id='sec4_5-nonnegative',
         tex=(2160, 2160),
         near='normalized_united_system',
         kind='inline',
         verbatim=('Based on Examples \\ref{normalizing_coefficients_n_1}--\\ref{normalizing_coefficients_n_'
                   '3}, in addition to the property of partition of unity, the first, the second and the thi'
                   'rd order cases of the function system (\\ref{normalized_united_system}) are also non-neg'
                   'ative.'),
         says='Orders 1, 2, 3 of the normalized system are non-negative (from the Examples).',
         status='checked',
         check='claim:nonnegativity'),
    Line(id='sec4_5-open-problem',
         tex=(2160, 2160),
         near='normalized_united_system',
         kind='prose',
         verbatim=('The non-negativity, the symmetry and closed formulas of normalizing coefficients of the '
                   'constrained trivariate function system (\\ref{normalized_united_system}) of arbitrary or'
                   'der at the moment constitute one of our open problems'),
         says='Non-negativity, symmetry and closed forms for arbitrary order are open problems.',
         status='excused',
         reason='statement of an open problem (claims nonnegativity_extended and symmetry treat it)'),
    Line(id='sec4_5-subsections-prose',
         tex=(2163, 2166),
         near='normalized_united_system',
         kind='prose',
         verbatim=('Subsections \\ref{sec:triangular_trigonometric_patches} and \\ref{sec:triangular_rationa'
                   'l_trigonometric_patches} introduce the notions of general triangular trigonometric and r'
                   'ational trigonometric patches of order $n$, respectively.'),
         says='Pointer to the next subsections.',
         status='excused',
         reason='prose'),
]
