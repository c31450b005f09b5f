"""Section 7 (sec:open_problems) and Section 8 (final remarks), source lines 2667-3309: every line that states
something, verbatim.

Generated from the LaTeX source by copying each line range programmatically (never retyped); the tex ranges
are the lines the verbatim occupies.  Rows of the vector equations of Example exmp:from_1_to_2 are one line
each (the verbatim is the row's right-hand side); the vector equations of Example
exmp:degree_elevation_from_1_to_2 are one line per colour (the verbatim is the whole vector equation).
The formulas are read from the verbatim itself by the small LaTeX readers in
:mod:`paper_repro.printed.latex_math`.  Checks: :mod:`paper_repro.claims.lines.sec7`.
"""

from __future__ import annotations

from paper_repro.printed.lines import Line

LINES = [
    Line(id='sec7-harder-than-polynomial', tex=(2668, 2671), near='sec:open_problems', kind='prose',
         verbatim=('Compared to the classical constrained trivariate Bernstein polynomials and\ncorresponding '
                   'triangular patches, in this non-polynomial case, theoretical\nquestions are significantly '
                   'harder to answer even for special values of the\norder $n$. Assuming arbitrary values of '
                   'the order $n$, this section formulates several open questions as follows.'),
         says=('Theoretical questions are harder than for Bernstein polynomials; the section formulates open '
               'questions.'),
         status='excused',
         reason='prose'),
    Line(id='sec7-question-1', tex=(2674, 2674), near='sec:open_problems', kind='prose',
         verbatim=('Are the normalizing coefficients of the constrained trivariate function system '
                   '$T_{2n}^{\\alpha}$ non-negative and symmetric? Can we give closed or at least recursive '
                   'formulas for these coefficients?'),
         says=('Question 1: are the normalizing coefficients of T_{2n} non-negative and symmetric; closed or '
               'recursive formulas?'),
         status='excused',
         reason=('a question; answered for every n and alpha by claim question1_all_n (one formula for every '
                 'coefficient, positive and symmetric: hand proof docs/question1_for_all_n.md), and by claim '
                 'elevation_all_n and pairwise_products_all_n (the recurrence of consecutive orders, through the '
                 'products the paper asks for)')),
    Line(id='sec7-closed-formulas-scope', tex=(2679, 2682), near='sec:open_problems', kind='prose',
         verbatim=('Due to the\ncomplexity of this problem, closed formulas of these coefficients were given\n'
                   'only for levels $0$ and $1$ for arbitrary order, and for all levels\njust for orders $n=1$, '
                   '$2$ and $3$'),
         says=('The paper gives closed formulas of the coefficients for levels 0 and 1 for every n and for all '
               'levels for n = 1, 2, 3.'),
         status='excused',
         reason=("describes the paper's own content (Remark normalizing_coeff_of_level_0, Proposition "
                 'prop:level_1_coefficients, Examples normalizing_coefficients_n_1..3), each checked in its own '
                 'section')),
    Line(id='sec7-unity-product', tex=(2688, 2702), near='sec:open_problems', kind='display',
         verbatim=('1^{n+1} & = & \\left(  \\overline{R}_{2n,n,n}^{\\alpha}+%\n'
                   '{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}}\n'
                   '\\overline{R}_{2n,2n-i,j}^{\\alpha}+%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n'
                   '{\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}}\n\\overline{G}_{2n,2n-i,j}^{\\alpha}+%\n'
                   '{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}}\n'
                   '\\overline{B}_{2n,2n-i,j}^{\\alpha}\\right)  \\\\\n&  & \\\\\n&  & \\cdot\\left(  '
                   '\\overline{R}_{2,1,1}^{\\alpha}+\\overline{R}_{2,2,0}^{\\alpha\n}+\\overline{R}_{2,1,'
                   '0}^{\\alpha}+\\overline{G}_{2,2,0}^{\\alpha}+\\overline\n{G}_{2,1,'
                   '0}^{\\alpha}+\\overline{B}_{2,2,0}^{\\alpha}+\\overline{B}_{2,1,0}%\n^{\\alpha}\\right)'),
         says=('1^{n+1} = (R-bar_{2n,n,n} + sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} (R-bar + G-bar + B-bar)_{2n,2n-i,'
               'j}) * (R-bar_{2,1,1} + R-bar_{2,2,0} + R-bar_{2,1,0} + G-bar_{2,2,0} + G-bar_{2,1,0} + B-bar_{2,'
               '2,0} + B-bar_{2,1,0}): the first factor sums T-bar_{2n}, the second T-bar_2, both equal 1.  '
               '(Second reading: the exponent n+1 is notation -- the first factor is the order-n partition of unity, '
               'not a power of the second -- and 1^k = 1 for every k, so it is not a slip.)'),
         status='checked', check='sec7-unity-product'),
    Line(id='sec7-unity-product-basis', tex=(2705, 2705), near='sec:open_problems', kind='inline',
         verbatim=('into the basis $\\overline{T}_{2\\left(  n+1\\right)}^{\\alpha}$, then this transformation '
                   'would also provide:'),
         says=('The product can be transformed into the basis T-bar_{2(n+1)} (every pairwise product of a '
               'function of T_{2n} and one of T_2 lies in span T_{2(n+1)}).'),
         status='checked', check='claim:pairwise_products_all_n'),
    Line(id='sec7-transformation-consequences', tex=(2707, 2711), near='sec:open_problems', kind='prose',
         verbatim=('\\item a recurrence relation between normalizing coefficients of consecutive orders;\n'
                   '\\item the symmetry and non-negativity of normalizing coefficients;\n\\item the order '
                   'elevation of the constrained trivariate trigonometric\nblending system '
                   '$\\overline{T}_{2n}^{\\alpha}$ (and consequently, the order elevation of triangular '
                   '(rational) trigonometric patches\nfrom arbitrary order $n$ to $n+1$).'),
         says=('Such a transformation would give a recurrence of normalizing coefficients, their symmetry and '
               'non-negativity, and order elevation n -> n+1.'),
         status='checked', check='claim:pairwise_products_all_n'),
    Line(id='sec7-method-comparison', tex=(2714, 2718), near='sec:open_problems', kind='prose',
         verbatim=('In contrast to the technique presented in the proof of\nProposition '
                   '\\ref{prop:level_1_coefficients} (cf. \\cite{tech_report}), the immediate inheritance of\n'
                   'non-negativity and symmetry of normalizing coefficients from lower to higher order\nforms '
                   'the advantage of this alternative method (consider Example \\ref{exmp:from_1_to_2}), while '
                   'its disadvantage lies in\nits complexity and the tedious use of quite involved '
                   'trigonometric identities.'),
         says=('Compared with the proof of Proposition prop:level_1_coefficients, the method inherits '
               'non-negativity and symmetry but needs involved trigonometric identities.'),
         status='excused',
         reason='prose comparing methods (citation of tech_report)'),
    Line(id='sec7-mixed-products-easy', tex=(2722, 2726), near='sec:open_problems', kind='display',
         verbatim=('\\overline{R}_{2n,2n-i,j}^{\\alpha}\\cdot\\overline{R}_{2,1,1}^{\\alpha}%\n,'
                   '~\\overline{R}_{2n,2n-i,j}^{\\alpha}\\cdot\\overline{R}_{2,2,0}^{\\alpha\n},'
                   '~\\overline{R}_{2n,2n-i,j}^{\\alpha}\\cdot\\overline{R}_{2,1,0}^{\\alpha\n},'
                   '~\\overline{R}_{2n,2n-i,j}^{\\alpha}\\cdot\\overline{G}_{2,2,0}^{\\alpha\n}'),
         says=('The mixed products R-bar_{2n,2n-i,j} times R-bar_{2,1,1}, R-bar_{2,2,0}, R-bar_{2,1,0}, '
               'G-bar_{2,2,0} can be transformed into the basis T-bar_{2(n+1)}.'),
         status='checked', check='claim:pairwise_products_all_n'),
    Line(id='sec7-mixed-products-index-set', tex=(2728, 2729), near='sec:open_problems', kind='index-set',
         verbatim='for all indices\n$j=0,1,\\ldots,n-1$ and $i=j,j+1,\\ldots,2n-1-j$',
         says=('... for all indices j = 0, 1, ..., n-1 and i = j, j+1, ..., 2n-1-j (the non-central R functions '
               'of T_{2n}).'),
         status='checked', check='sec7-mixed-products-index-set'),
    Line(id='sec7-mixed-products-hard', tex=(2729, 2736), near='sec:open_problems', kind='display',
         verbatim=('However, in case of pairwise products%\n\\[\n\\overline{R}_{2n,2n-i,'
                   'j}^{\\alpha}\\cdot\\overline{B}_{2,2,0}^{\\alpha},~\n\\overline{R}_{2n,2n-i,'
                   'j}^{\\alpha}\\cdot\\overline{G}_{2,1,0}^{\\alpha}%\n,~\\overline{R}_{2n,2n-i,'
                   'j}^{\\alpha}\\cdot\\overline{B}_{2,1,0}^{\\alpha}%\n\\]\none obtains functions that we '
                   'could not write as the linear combination\nof basis functions of $\\overline{T}_{2\\left(  '
                   'n+1\\right)  }^{\\alpha}$, for the present.'),
         says=('For R-bar_{2n,2n-i,j} times B-bar_{2,2,0}, G-bar_{2,1,0}, B-bar_{2,1,0} the authors could not '
               '(yet) write the product as a combination of T-bar_{2(n+1)}.'),
         status='excused',
         reason=("a statement about the authors' progress, not about the functions; the products are now written "
                 'for every n by claim pairwise_products_all_n (G-bar_{2,1,0} and B-bar_{2,1,0}: one cotangent rule '
                 'applied to the product with the centre; B-bar_{2,2,0}: the cotangent of v applied m - j times, '
                 'the hard case; proof docs/elevation_and_derivative_for_all_n.md).  The claim reads this line: '
                 "its three products and the four 'easy' ones of sec7-mixed-products-easy name each member of T_2 "
                 "once, and the 'easy' ones are exactly those Theorem P writes with at most 2 members of order n + 1 "
                 '(n = 1..5); these three need up to 2n + 2 (G_{2,1,0}, B_{2,1,0}) and 3n + 1 (B_{2,2,0}) members, '
                 'which is consistent with the text')),
    Line(id='sec7-first-order-products', tex=(2736, 2736), near='sec:open_problems', kind='inline',
         verbatim=('For the moment, we are only able (cf. \\cite[Lemma 5.1]{tech_report}) to transform the '
                   'pairwise products of first order blending functions into linear combinations of second '
                   'order blending functions.'),
         says=('Pairwise products of first order blending functions are linear combinations of second order '
               'blending functions (tech_report Lemma 5.1; the tech report is not available here: the lemma number '
               'is not checked, the statement is).'),
         status='checked', check='sec7-products-in-span'),
    Line(id='sec7-square-of-unity', tex=(2742, 2745), near='exmp:from_1_to_2', kind='display',
         verbatim=('1^{2}=\\left(  \\overline{R}_{2,1,1}^{\\alpha}+\\overline{R}_{2,2,0}^{\\alpha\n'
                   '}+\\overline{R}_{2,1,0}^{\\alpha}+\\overline{G}_{2,2,0}^{\\alpha}+\\overline\n{G}_{2,1,'
                   '0}^{\\alpha}+\\overline{B}_{2,2,0}^{\\alpha}+\\overline{B}_{2,1,0}%\n^{\\alpha}\\right)  '
                   '^{2}'),
         says=('1^2 = (R-bar_{2,1,1} + R-bar_{2,2,0} + R-bar_{2,1,0} + G-bar_{2,2,0} + G-bar_{2,1,0} + B-bar_{2,'
               '2,0} + B-bar_{2,1,0})^2: the sum of T-bar_2 squared.'),
         status='checked', check='sec7-square-of-unity'),
    Line(id='sec7-rel-r440', tex=(2759, 2759), near='exmp:from_1_to_2', kind='display',
         verbatim='\\left(  \\Red{r_{2,2,0}^{\\alpha}}\\right)  ^{2}',
         says=('r_{4,4,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,4,0}^alpha).'),
         status='checked', check='sec7-rel-r440'),
    Line(id='sec7-rel-g440', tex=(2760, 2760), near='exmp:from_1_to_2', kind='display',
         verbatim='\\left(  \\Green{g_{2,2,0}^{\\alpha}}\\right)  ^{2}',
         says=('g_{4,4,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,4,0}^alpha).'),
         status='checked', check='sec7-rel-g440'),
    Line(id='sec7-rel-b440', tex=(2761, 2761), near='exmp:from_1_to_2', kind='display',
         verbatim='\\left(  \\Blue{b_{2,2,0}^{\\alpha}}\\right)  ^{2}',
         says=('b_{4,4,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,4,0}^alpha).'),
         status='checked', check='sec7-rel-b440'),
    Line(id='sec7-rel-r430', tex=(2773, 2773), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Red{r_{2,2,0}^{\\alpha}r_{2,1,0}^{\\alpha}}',
         says=('r_{4,3,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,3,0}^alpha).'),
         status='checked', check='sec7-rel-r430'),
    Line(id='sec7-rel-g430', tex=(2774, 2774), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Green{g_{2,2,0}^{\\alpha}g_{2,1,0}^{\\alpha}}',
         says=('g_{4,3,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,3,0}^alpha).'),
         status='checked', check='sec7-rel-g430'),
    Line(id='sec7-rel-b430', tex=(2775, 2775), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Blue{b_{2,2,0}^{\\alpha}b_{2,1,0}^{\\alpha}}',
         says=('b_{4,3,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,3,0}^alpha).'),
         status='checked', check='sec7-rel-b430'),
    Line(id='sec7-rel-r420', tex=(2787, 2788), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Red{r_{2,2,0}^{\\alpha}}\\Green{g_{2,2,0}^{\\alpha}}+\\left(  \\Red{r_{2,1,'
                   '0}^{\\alpha}}\\right)\n^{2}'),
         says=('r_{4,2,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,2,0}^alpha).'),
         status='checked', check='sec7-rel-r420'),
    Line(id='sec7-rel-g420', tex=(2789, 2790), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Green{g_{2,2,0}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}+\\left(  \\Green{g_{2,1,'
                   '0}^{\\alpha}}\\right)\n^{2}'),
         says=('g_{4,2,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,2,0}^alpha).'),
         status='checked', check='sec7-rel-g420'),
    Line(id='sec7-rel-b420', tex=(2791, 2791), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Red{r_{2,2,0}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}+\\left(  \\Blue{b_{2,1,'
                   '0}^{\\alpha}}\\right)  ^{2}'),
         says=('b_{4,2,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,2,0}^alpha).'),
         status='checked', check='sec7-rel-b420'),
    Line(id='sec7-rel-r410', tex=(2804, 2804), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Red{r_{2,1,0}^{\\alpha}}\\Green{g_{2,2,0}^{\\alpha}}',
         says=('r_{4,1,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,1,0}^alpha).'),
         status='checked', check='sec7-rel-r410'),
    Line(id='sec7-rel-g410', tex=(2805, 2805), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Green{g_{2,1,0}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}',
         says=('g_{4,1,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,1,0}^alpha).'),
         status='checked', check='sec7-rel-g410'),
    Line(id='sec7-rel-b410', tex=(2806, 2806), near='exmp:from_1_to_2', kind='display',
         verbatim='2\\Red{r_{2,2,0}^{\\alpha}}\\Blue{b_{2,1,0}^{\\alpha}}',
         says=('b_{4,1,0}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,1,0}^alpha).'),
         status='checked', check='sec7-rel-b410'),
    Line(id='sec7-rel-r431', tex=(2819, 2822), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Red{r_{2,2,0}^{\\alpha}}\\Orange{r_{2,1,1}^{\\alpha}}+\\left(  \\Red{r_{2,2,'
                   '0}^{\\alpha}}\\right)\n^{2}\\Green{g_{2,1,0}^{\\alpha}}\\sin\\alpha+2\\left(  1+\\Red{r_{2,'
                   '2,0}^{\\alpha}}\\cos^{2}%\n\\frac{\\alpha}{2}\\right)  \\Red{r_{2,1,'
                   '0}^{\\alpha}}\\Blue{b_{2,1,0}^{\\alpha}}\\sin\\frac{\\alpha\n}{2}'),
         says=('r_{4,3,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,3,1}^alpha).'),
         status='checked', check='sec7-rel-r431'),
    Line(id='sec7-rel-g431', tex=(2823, 2825), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Orange{r_{2,1,1}^{\\alpha}}\\Green{g_{2,2,0}^{\\alpha}}+2\\Red{r_{2,1,'
                   '0}^{\\alpha}}\\left(\n1+\\Green{g_{2,2,0}^{\\alpha}}\\cos^{2}\\frac{\\alpha}{2}\\right)  '
                   '\\Green{g_{2,1,0}^{\\alpha}}%\n\\sin\\frac{\\alpha}{2}+\\left(  \\Green{g_{2,2,'
                   '0}^{\\alpha}}\\right)  ^{2}\\Blue{b_{2,1,0}^{\\alpha}}\\sin\\alpha'),
         says=('g_{4,3,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,3,1}^alpha).'),
         status='checked', check='sec7-rel-g431'),
    Line(id='sec7-rel-b431', tex=(2826, 2829), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Orange{r_{2,1,1}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}+\\Red{r_{2,1,0}^{\\alpha}}\\left( '
                   ' \\Blue{b_{2,2,0}%\n^{\\alpha}}\\right)  ^{2}\\sin\\alpha+2\\Green{g_{2,1,'
                   '0}^{\\alpha}}\\left(  1+\\Blue{b_{2,2,0}%\n^{\\alpha}}\\cos^{2}\\frac{\\alpha}{2}\\right)  '
                   '\\Blue{b_{2,1,0}^{\\alpha}}\\sin\\frac{\\alpha\n}{2}'),
         says=('b_{4,3,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,3,1}^alpha).'),
         status='checked', check='sec7-rel-b431'),
    Line(id='sec7-rel-r421', tex=(2847, 2852), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Red{r_{2,1,0}^{\\alpha}}\\Orange{r_{2,1,1}^{\\alpha}}+\\Red{r_{2,2,'
                   '0}^{\\alpha}}\\Red{r_{2,1,0}^{\\alpha\n}}\\Green{g_{2,1,'
                   '0}^{\\alpha}}\\tan\\frac{\\alpha}{2}+\\left(  \\Red{r_{2,1,0}^{\\alpha}}\\right)\n'
                   '^{2}\\Green{g_{2,1,0}^{\\alpha}}\\sin\\frac{\\alpha}{2}\\\\\n+\\Red{r_{2,1,'
                   '0}^{\\alpha}}\\left(  \\Blue{b_{2,1,0}^{\\alpha}}\\right)  ^{2}\\sin\\frac{\\alpha}%\n'
                   '{2}+\\Red{r_{2,1,0}^{\\alpha}}\\Green{g_{2,2,0}^{\\alpha}}\\Blue{b_{2,1,'
                   '0}^{\\alpha}}\\tan\\frac{\\alpha}%\n{2}'),
         says=('r_{4,2,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is r_{4,2,1}^alpha).'),
         status='checked', check='sec7-rel-r421'),
    Line(id='sec7-rel-g421', tex=(2854, 2859), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Orange{r_{2,1,1}^{\\alpha}}\\Green{g_{2,1,0}^{\\alpha}}+\\Red{r_{2,1,'
                   '0}^{\\alpha}}\\left(  \\Green{g_{2,1,0}%\n^{\\alpha}}\\right)  '
                   '^{2}\\sin\\frac{\\alpha}{2}+\\Red{r_{2,1,0}^{\\alpha}}\\Green{g_{2,1,0}%\n'
                   '^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}\\tan\\frac{\\alpha}{2}\\\\\n+\\Green{g_{2,2,'
                   '0}^{\\alpha}g_{2,1,0}^{\\alpha}}\\Blue{b_{2,1,0}^{\\alpha}}\\tan\\frac{\\alpha}%\n'
                   '{2}+\\left(  \\Green{g_{2,1,0}^{\\alpha}}\\right)  ^{2}\\Blue{b_{2,1,'
                   '0}^{\\alpha}}\\sin\\frac{\\alpha\n}{2}'),
         says=('g_{4,2,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is g_{4,2,1}^alpha).'),
         status='checked', check='sec7-rel-g421'),
    Line(id='sec7-rel-b421', tex=(2861, 2866), near='exmp:from_1_to_2', kind='display',
         verbatim=('2\\Orange{r_{2,1,1}^{\\alpha}}\\Blue{b_{2,1,0}^{\\alpha}}+\\Red{r_{2,2,'
                   '0}^{\\alpha}}\\Green{g_{2,1,0}^{\\alpha\n}}\\Blue{b_{2,1,'
                   '0}^{\\alpha}}\\tan\\frac{\\alpha}{2}+\\Red{r_{2,1,0}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha\n'
                   '}b_{2,1,0}^{\\alpha}}\\tan\\frac{\\alpha}{2}\\\\\n+\\left(  \\Red{r_{2,1,'
                   '0}^{\\alpha}}\\right)  ^{2}\\Blue{b_{2,1,0}^{\\alpha}}\\sin\\frac{\\alpha}%\n'
                   '{2}+\\Green{g_{2,1,0}^{\\alpha}}\\left(  \\Blue{b_{2,1,0}^{\\alpha}}\\right)  '
                   '^{2}\\sin\\frac{\\alpha\n}{2}'),
         says=('b_{4,2,1}^alpha (second order normalizing coefficient) equals this expression in first order '
               'coefficients (the row of the vector equation whose left-hand side is b_{4,2,1}^alpha).'),
         status='checked', check='sec7-rel-b421'),
    Line(id='sec7-rel-r422', tex=(2869, 2872), near='exmp:from_1_to_2', kind='display',
         verbatim=('\\Orange{r_{4,2,2}^{\\alpha}} &  =\\left(  \\Orange{r_{2,1,1}^{\\alpha}}\\right)  '
                   '^{2}+2\\Red{r_{2,2,0}%\n^{\\alpha}}\\Green{g_{2,2,0}^{\\alpha}}+2\\Red{r_{2,2,'
                   '0}^{\\alpha}}\\Blue{b_{2,2,0}^{\\alpha}}%\n+2\\Green{g_{2,2,0}^{\\alpha}}\\Blue{b_{2,2,'
                   '0}^{\\alpha}}+2\\Red{r_{2,1,0}^{\\alpha}}\\Green{g_{2,1,0}^{\\alpha\n}}+2\\Red{r_{2,1,'
                   '0}^{\\alpha}}\\Blue{b_{2,1,0}^{\\alpha}}+2\\Green{g_{2,1,0}^{\\alpha}}\\Blue{b_{2,1,'
                   '0}^{\\alpha}}'),
         says=('r_{4,2,2} = (r_{2,1,1})^2 + 2 r_{2,2,0} g_{2,2,0} + 2 r_{2,2,0} b_{2,2,0} + 2 g_{2,2,0} b_{2,2,'
               '0} + 2 r_{2,1,0} g_{2,1,0} + 2 r_{2,1,0} b_{2,1,0} + 2 g_{2,1,0} b_{2,1,0}.'),
         status='checked', check='sec7-rel-r422'),
    Line(id='sec7-rel-same-as-example', tex=(2874, 2876), near='exmp:from_1_to_2', kind='inline',
         verbatim=('It is easy to verify that these relations lead to the same second order\nnormalizing '
                   'coefficients that were described in Example\n\\ref{normalizing_coefficients_n_2}'),
         says='The relations give the same second order coefficients as Example normalizing_coefficients_n_2.',
         status='checked', check='sec7-rel-same-as-example'),
    Line(id='sec7-rel-inheritance', tex=(2876, 2878), near='exmp:from_1_to_2', kind='inline',
         verbatim=('Observe that the symmetry and non-negativity\nof normalizing coefficients of order $1$ are '
                   'inherited by those of order\n$2$.'),
         says=('Symmetry and non-negativity of the first order coefficients are inherited by the second order '
               'ones (through the relations).'),
         status='checked', check='sec7-rel-inheritance'),
    Line(id='sec7-elev-product', tex=(2884, 2893), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\mathbf{s}_{1}^{\\alpha}  \\cdot1=  &  \\left(\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\\overline{R}_{2,1,1}^{\\alpha}+\\Red{\\mathbf{r}_{2,2,0}}\\overline\n{R}_{2,2,'
                   '0}^{\\alpha}+\\Red{\\mathbf{r}_{2,1,0}}\\overline{R}_{2,1,0}^{\\alpha\n'
                   '}+\\Green{\\mathbf{g}_{2,2,0}}\\overline{G}_{2,2,0}^{\\alpha}+\\Green{\\mathbf{g}_{2,1,'
                   '0}}%\n\\overline{G}_{2,1,0}^{\\alpha}+\\Blue{\\mathbf{b}_{2,2,0}}\\overline{B}_{2,2,'
                   '0}^{\\alpha\n}+\\Blue{\\mathbf{b}_{2,1,0}}\\overline{B}_{2,1,0}^{\\alpha}\\right) \\\\\n&  '
                   '\\cdot\\left(  \\overline{R}_{2,1,1}^{\\alpha}+\\overline{R}_{2,2,0}^{\\alpha\n'
                   '}+\\overline{R}_{2,1,0}^{\\alpha}+\\overline{G}_{2,2,0}^{\\alpha}+\\overline\n{G}_{2,1,'
                   '0}^{\\alpha}+\\overline{B}_{2,2,0}^{\\alpha}+\\overline{B}_{2,1,0}%\n^{\\alpha}\\right)'),
         says=('s_1 * 1 = (sum of the 7 first order control points times their own blending functions) * (sum '
               'of T-bar_2).'),
         status='checked', check='sec7-elev-product'),
    Line(id='sec7-elev-same-patch', tex=(2895, 2896), near='exmp:degree_elevation_from_1_to_2', kind='inline',
         verbatim=('into the basis $\\overline{T}_{4}^{\\alpha}$ and then collecting the vector\ncoefficients '
                   'of second order blending functions, one obtains the order elevated (i.e., second order) '
                   'representation $\\mathbf{s}_{2}^{\\alpha}$ of the original patch $\\mathbf{s}_{1}^{\\alpha}$'),
         says=('Collecting the coefficients of the second order functions gives the order elevated '
               'representation s_2 of s_1.'),
         status='checked', check='sec7-elev-same-patch'),
    Line(id='sec7-elev-r440', tex=(2898, 2916), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,4,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '4,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,4,0}}\n\\end{array}\n\\right]  =  &  \\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,4,0} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r440'),
    Line(id='sec7-elev-g440', tex=(2898, 2916), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,4,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '4,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,4,0}}\n\\end{array}\n\\right]  =  &  \\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,4,0} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g440'),
    Line(id='sec7-elev-b440', tex=(2898, 2916), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,4,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '4,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,4,0}}\n\\end{array}\n\\right]  =  &  \\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,4,0} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b440'),
    Line(id='sec7-elev-r430', tex=(2917, 2944), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,3,0} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r430'),
    Line(id='sec7-elev-g430', tex=(2917, 2944), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,3,0} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g430'),
    Line(id='sec7-elev-b430', tex=(2917, 2944), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,3,0} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b430'),
    Line(id='sec7-elev-r420', tex=(2945, 2981), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{2\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,2,0} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r420'),
    Line(id='sec7-elev-g420', tex=(2945, 2981), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{2\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,2,0} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g420'),
    Line(id='sec7-elev-b420', tex=(2945, 2981), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{2\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,2,0} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b420'),
    Line(id='sec7-elev-r410', tex=(2982, 3009), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,1,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,1,0} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r410'),
    Line(id='sec7-elev-g410', tex=(2982, 3009), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,1,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,1,0} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g410'),
    Line(id='sec7-elev-b410', tex=(2982, 3009), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,1,0}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1}{2}\\left[\n\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,1,0} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b410'),
    Line(id='sec7-elev-r431', tex=(3010, 3065), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,3,1} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r431'),
    Line(id='sec7-elev-g431', tex=(3010, 3065), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,3,1} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g431'),
    Line(id='sec7-elev-b431', tex=(3010, 3065), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,3,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '3,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,3,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{2+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,3,1} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b431'),
    Line(id='sec7-elev-r421', tex=(3066, 3133), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+\\cos^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point r_{4,2,1} (the first row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-r421'),
    Line(id='sec7-elev-g421', tex=(3066, 3133), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+\\cos^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point g_{4,2,1} (the second row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-g421'),
    Line(id='sec7-elev-b421', tex=(3066, 3133), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\left[\n\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{4,2,1}}\n\\\\%\n\\Green{\\mathbf{g}_{4,'
                   '2,1}}\n\\\\%\n\\Blue{\\mathbf{b}_{4,2,1}}\n\\end{array}\n\\right]  =  &  '
                   '\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+\\cos^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n'
                   '\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{\\sin^{2}\\frac{\\alpha}{2}}{4+2\\cos^{2}\\frac{\\alpha}{2}}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,'
                   '1}}\n\\\\%\n\\Orange{\\mathbf{r}_{2,1,1}}\n\\end{array}\n\\right] \\\\\n&  '
                   '+\\frac{1}{8+4\\cos^{2}\\frac{\\alpha}{2}}\\left[\n\\begin{array}\n[c]{c}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,2,0}}\n\\\\%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\\\%\n\\Blue{\\mathbf{b}_{2,1,0}}\n'
                   '\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n\\end{array}\n\\right]  '
                   '+\\frac{1+2\\cos^{2}\\frac{\\alpha}{2}}{8+4\\cos^{2}\\frac{\\alpha}{2}%\n}\\left[\n'
                   '\\begin{array}\n[c]{c}%\n\\Blue{\\mathbf{b}_{2,1,0}}\n\\\\%\n\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '\\\\%\n\\Green{\\mathbf{g}_{2,1,0}}\n\\end{array}\n\\right]'),
         says=('Elevated control point b_{4,2,1} (the third row of this vector equation) as a combination of '
               'first order control points with these alpha-dependent weights.'),
         status='checked', check='sec7-elev-b421'),
    Line(id='sec7-elev-r422', tex=(3134, 3151), near='exmp:degree_elevation_from_1_to_2', kind='display',
         verbatim=('\\Orange{\\mathbf{r}_{4,2,2}}\n=  &  \\frac{1}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Red{\\mathbf{r}_{2,2,0}}\n'
                   '+\\frac{4\\cos^{2}\\frac{\\alpha}{2}}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Red{\\mathbf{r}_{2,1,0}}\n'
                   '+\\frac{2\\sin^{2}\\frac{\\alpha}{2}}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Orange{\\mathbf{r}_{2,1,1}}\n\\\\\n&  +\\frac{1}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Green{\\mathbf{g}_{2,2,0}}\n'
                   '+\\frac{4\\cos^{2}\\frac{\\alpha}{2}}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Green{\\mathbf{g}_{2,1,0}}\n\\\\\n&  +\\frac{1}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n'
                   '+\\frac{4\\cos^{2}\\frac{\\alpha}{2}}{5+10\\cos^{2}\\frac{\\alpha}{2}}%\n'
                   '\\Blue{\\mathbf{b}_{2,1,0}}\n.'),
         says=('Elevated centre r_{4,2,2} = (r_{2,2,0} + 4c^2 r_{2,1,0} + 2s^2 r_{2,1,1} + g_{2,2,0} + 4c^2 '
               'g_{2,1,0} + b_{2,2,0} + 4c^2 b_{2,1,0}) / (5 + 10c^2), c = cos(alpha/2), s = sin(alpha/2).'),
         status='checked', check='sec7-elev-r422'),
    Line(id='sec7-elev-index-sets', tex=(3155, 3162), near='exmp:degree_elevation_from_1_to_2', kind='index-set',
         verbatim=('\\Orange{\\mathbf{r}_{4,2,2}}\n,~\\left\\{\n\\Red{\\mathbf{r}_{4,4-i,j}}\n\\right\\}  _{j=0,'
                   'i=j}^{1,3-j},~\\left\\{\n\\Green{\\mathbf{g}_{4,4-i,j}}\n\\right\\}  _{j=0,i=j}^{1,3-j},'
                   '~\\left\\{\n\\Blue{\\mathbf{b}_{4,4-i,j}}\n\\right\\}  _{j=0,i=j}^{1,3-j}'),
         says=('The elevated net is r_{4,2,2} and {x_{4,4-i,j}}_{j=0,i=j}^{1,3-j} for x = r, g, b: the 19 '
               'control points of order 2.'),
         status='checked', check='sec7-elev-index-sets'),
    Line(id='sec7-elev-convex', tex=(3164, 3178), near='exmp:degree_elevation_from_1_to_2', kind='inline',
         verbatim=('are in fact convex combinations of different subsets of control points%\n\\[%\n'
                   '\\Orange{\\mathbf{r}_{2,1,1}}\n,~%\n\\Red{\\mathbf{r}_{2,2,0}}\n,~%\n\\Red{\\mathbf{r}_{2,1,'
                   '0}}\n,~%\n\\Green{\\mathbf{g}_{2,2,0}}\n,~%\n\\Green{\\mathbf{g}_{2,1,0}}\n,~%\n'
                   '\\Blue{\\mathbf{b}_{2,2,0}}\n,~%\n\\Blue{\\mathbf{b}_{2,1,0}}'),
         says=('Each elevated control point is a convex combination of a (different) subset of the 7 first '
               'order control points.'),
         status='checked', check='sec7-elev-convex'),
    Line(id='sec7-elev-closer', tex=(3181, 3182), near='exmp:degree_elevation_from_1_to_2', kind='inline',
         verbatim=('Thus, the degree elevated (second order) control net is closer to the given patch\nthan its '
                   'original (first order) one for all values of $\\alpha$.'),
         says='Hence the elevated net is closer to the patch than the original net, for every alpha.',
         status='checked', check='sec7-elev-closer'),
    Line(id='sec7-fig-elev-caption', tex=(3195, 3197), near='fig:degree_elevation_from_1_to_2', kind='caption',
         verbatim=('in cases (\\emph{a}), (\\emph{b}) and (\\emph{c}) the parameter $\\alpha$ fulfills the '
                   'conditions\n$0<\\alpha<\\frac{\\pi}{2}$, $\\alpha=\\frac{\\pi}{2}$ and '
                   '$\\frac{\\pi}{2}<\\alpha\n<\\pi$, respectively.'),
         says='Cases (a), (b), (c) of the figure: 0 < alpha < pi/2, alpha = pi/2, pi/2 < alpha < pi.',
         status='checked', check='sec7-fig-elev-ranges'),
    Line(id='sec7-question-basis-transformation', tex=(3204, 3205), near='que:open_problem_basis_transformation',
         kind='prose',
         verbatim=('What is the general (inverse) transformation between the constrained trivariate bases\n'
                   '$\\overline{T}_{2n}^{\\alpha}$ and $V_{n}^{\\alpha}$?'),
         says='Question: the general (inverse) transformation between T-bar_{2n} and V_n?',
         status='excused',
         reason=('a question; answered for every n and alpha by claim transformation_all_n (hand proof '
                 'docs/transformation_for_all_n.md; closed forms for n <= 4: claim transformation_closed_forms)')),
    Line(id='sec7-question-2-motivation', tex=(3208, 3209), near='que:open_problem_basis_transformation', kind='prose',
         verbatim=('Answering Question \\ref{que:open_problem_basis_transformation} would be important in the '
                   'control point based exact description of triangular patches of (rational) trigonometric '
                   'surfaces the coordinate functions of which are given\nin (the rational counterpart of) '
                   '$\\mathcal{V}_{n}^{\\alpha}$.'),
         says='An answer would give control point based exact descriptions of trigonometric surfaces.',
         status='excused',
         reason='prose'),
    Line(id='sec7-limit-param-u', tex=(3215, 3215), near='que:open_problem_basis_transformation',
         kind='parametrization',
         verbatim='u\\left(x,y\\right) & = & \\alpha x, & x \\in \\left[0, 1\\right]',
         says='u(x, y) = alpha x with x in [0, 1].',
         status='checked', check='sec7-limit-param-map'),
    Line(id='sec7-limit-param-v', tex=(3216, 3216), near='que:open_problem_basis_transformation', kind='range',
         verbatim='v\\left(x,y\\right) & = & \\alpha y, & y \\in \\left[0, x\\right]',
         says='v(x, y) = alpha y with y in [0, x].',
         status='erratum', check='sec7-limit-param-range',
         erratum={
             'printed': ('v(x,y) = alpha y, y in [0, x]  (with u = alpha x, x in [0, 1], w = alpha z, z = 1 - x - '
                       'y)'),
             'corrected': 'y in [0, 1 - x]  (so that z = 1 - x - y >= 0 and (x, y, z) runs over the unit simplex)',
             'evidence': ('on the 1/12-grid of the printed ranges (x in [0, 1], y in [0, x]) 42 images (x, y, '
                        '1-x-y) leave the unit simplex (e.g. x = y = 1 gives z = -1, w = -alpha < 0: not in '
                        'Omega^alpha) and 42 of the 91 simplex grid points are never reached (e.g. (x, y) = (0, '
                        '1), the vertex v = alpha); with y in [0, 1 - x] no image leaves and all 91 are reached '
                        '(exact rationals)'),
             'severity': 'typo',
         }),
    Line(id='sec7-limit-param-w', tex=(3217, 3217), near='que:open_problem_basis_transformation',
         kind='parametrization',
         verbatim='w\\left(x,y\\right) & = & \\alpha z, & z = 1-x-y',
         says='w(x, y) = alpha z with z = 1 - x - y.',
         status='checked', check='sec7-limit-param-map'),
    Line(id='sec7-limit-sin-over-t', tex=(3221, 3221), near='que:open_problem_basis_transformation', kind='inline',
         verbatim='the well-known identity $\\lim_{t\\to 0}\\frac{\\sin\\left(t\\right)}{t}=1$',
         says='The well-known limit lim_{t -> 0} sin(t)/t = 1.',
         status='excused',
         reason='a standard limit, used not stated by the paper'),
    Line(id='sec7-limit-degenerate-bernstein', tex=(3221, 3221), near='que:open_problem_basis_transformation',
         kind='inline',
         verbatim=('it is easy to observe that the first, second and third order normalized constrained '
                   'trivariate trigonometric function systems of type (\\ref{normalized_united_system}) '
                   'degenerate to constrained trivariate Bernstein polynomials defined on the unit simplex '
                   '$x+y+z=1$ as shown in Fig.\\ \\ref{fig:limit_cases_n_1_2_3}.'),
         says=('As alpha -> 0 the first, second and third order normalized systems degenerate to constrained '
               'trivariate Bernstein polynomials on the unit simplex x + y + z = 1.'),
         status='erratum', check='sec7-limit-degenerate-bernstein',
         erratum={
             'printed': ('the first, second and third order normalized systems degenerate to constrained '
                       'trivariate Bernstein polynomials defined on the unit simplex'),
             'corrected': ('they degenerate to non-negative rational multiples L P^{2n+j}_{a,b,c} of constrained '
                         'trivariate Bernstein polynomials (L = 1 on level 0; L < 1 on higher levels for n >= '
                         '2; the centre tends to 0)'),
             'evidence': ('limits of the normalized functions from the proven closed forms (P_f(1) x^a y^b z^c): '
                        'for n = 1 the 6 non-central limits are the Bernstein polynomials P^2; for n = 2 '
                        'R-bar_{4,3,1} -> 12 x^3 y z = 3/5 P^5_{3,1,1} and R-bar_{4,2,1} -> 4/5 P^5_{2,1,2} '
                        '(and their G, B images, 6 functions); for n = 3 all 18 functions of levels 1 and 2 '
                        'tend to multiples 5/7, 6/7, 1/2, 3/4 of P^7, P^8; numerically R-bar_{4,3,1}(alpha x, '
                        'alpha y, alpha z) / (x^3 y z) = 12.0 at alpha = 1e-4 (P^5_{3,1,1} would give 20). The '
                        'factors reappear in the printed conversions (e.g. 3/5 r_{4,3,1} in p_{3,1,1}); the '
                        'missing figure may print them, so this may be loose wording rather than a wrong figure'),
             'severity': 'statement',
         }),
    Line(id='sec7-fig-limit-caption-cases', tex=(3226, 3226), near='fig:limit_cases_n_1_2_3', kind='caption',
         verbatim=('\\caption{Cases (\\emph{a}), (\\emph{b}) and (\\emph{c}) illustrate the limiting case '
                   '$\\alpha\\to 0$ of the first, second and third order constrained trivariate normalized '
                   'trigonometric bases of type (\\ref{normalized_united_system}), respectively.'),
         says='Cases (a), (b), (c): the limit alpha -> 0 of the first, second and third order normalized bases.',
         status='excused',
         reason=('the figure is missing from the source; the limits it shows are checked by '
                 'sec7-limit-degenerate-bernstein and sec7-fig-limit-caption-centre')),
    Line(id='sec7-fig-limit-caption-bernstein', tex=(3226, 3226), near='fig:limit_cases_n_1_2_3', kind='definition',
         verbatim=('($P^{m}_{d,e,f}$ denotes the constrained trivariate Bernstein polynomial '
                   '$\\frac{m!}{d!e!f!}x^d y^e \\left(1-x-y\\right)^f$ of degree $m$'),
         says=('P^m_{d,e,f} = m!/(d! e! f!) x^d y^e (1-x-y)^f is the constrained trivariate Bernstein '
               'polynomial of degree m.'),
         status='checked', check='sec7-bernstein-definition'),
    Line(id='sec7-fig-limit-caption-range', tex=(3226, 3226), near='fig:limit_cases_n_1_2_3', kind='range',
         verbatim='where $x\\in\\left[0,1\\right]$, $y\\in\\left[0,x\\right]$',
         says='... where x in [0, 1], y in [0, x].',
         status='erratum', check='sec7-limit-caption-range',
         erratum={
             'printed': 'x in [0, 1], y in [0, x]  (domain of P^m_{d,e,f}(x, y) = m!/(d!e!f!) x^d y^e (1-x-y)^f)',
             'corrected': 'x in [0, 1], y in [0, 1 - x]  (the unit simplex x + y + z = 1, z = 1 - x - y >= 0)',
             'evidence': ('same range as the parametrization before the figure (line sec7-limit-param-v): on the '
                        '1/12-grid 42 points of x in [0, 1], y in [0, x] have 1 - x - y < 0 (e.g. x = y = 1) '
                        'and 42 of the 91 simplex grid points are missed (e.g. x = 0, y = 1); y in [0, 1 - x] '
                        'gives exactly the simplex'),
             'severity': 'typo',
         }),
    Line(id='sec7-fig-limit-caption-indices', tex=(3226, 3226), near='fig:limit_cases_n_1_2_3', kind='index-set',
         verbatim='$d,e,f\\in\\left\\{0,1,\\ldots,m\\right\\}$ such that $d+e+f=m$',
         says='d, e, f in {0, 1, ..., m} with d + e + f = m.',
         status='checked', check='sec7-bernstein-definition'),
    Line(id='sec7-fig-limit-caption-centre', tex=(3226, 3226), near='fig:limit_cases_n_1_2_3', kind='caption',
         verbatim=('Constrained triavariate normalized trigonometric basis functions associated with the '
                   'innermost node of the graphs above vanish when $\\alpha\\to 0$.'),
         says=('The normalized basis function of the innermost node (the centre R-bar_{2n,n,n}) vanishes as '
               'alpha -> 0.'),
         status='erratum', check='sec7-fig-limit-caption-centre',
         erratum={
             'printed': 'Constrained triavariate normalized trigonometric basis functions ...',
             'corrected': 'Constrained trivariate normalized trigonometric basis functions ...',
             'evidence': ("'triavariate' occurs once in the paper (this caption, tex line 3226); the word is "
                          "'trivariate' in the 62 other occurrences (and in every other transcribed line). The "
                          'mathematics of the line holds: exactly the centre R-bar_{2n,n,n} tends to 0 (limit '
                          'coefficients of the proven closed forms, n = 1..3; limit formula, n = 1..12)'),
             'severity': 'typo',
         }),
    Line(id='sec7-conversion-degrees', tex=(3230, 3230), near='fig:limit_cases_n_1_2_3', kind='inline',
         verbatim=('Moreover, the control nets of the original first, second and third order triangular '
                   'trigonometric patches can be converted to control nets that describe classical polynomial '
                   "quadratic, quintic and octic triangular B\\'ezier patches, respectively, when $\\alpha \\to "
                   '0$.'),
         says=('As alpha -> 0 first, second and third order patches become quadratic, quintic and octic Bezier '
               'triangles.'),
         status='checked', check='sec7-conversion-degrees'),
    Line(id='sec7-conversion-symmetry', tex=(3230, 3230), near='fig:limit_cases_n_1_2_3', kind='inline',
         verbatim="Due to symmetry, we only list for $n=2$ and $3$ the position of B\\'ezier points",
         says=('Due to symmetry only the listed Bezier points of n = 2 and 3 are given (the others follow by '
               'rotating the colours).'),
         status='checked', check='sec7-conversion-symmetry'),
    Line(id='sec7-conv2-p500', tex=(3232, 3232), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim='\\mathbf{p}_{5,0,0}  & =\\Red{\\mathbf{r}_{4,4,0}}',
         says=('Quintic Bezier point p_{5,0,0} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p500'),
    Line(id='sec7-conv2-p401', tex=(3233, 3233), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{4,0,1}  & =\\frac{1}{5}\\Red{\\mathbf{r}_{4,4,'
                   '0}}+\\frac{4}{5}\\Red{\\mathbf{r}_{4,3,0}}'),
         says=('Quintic Bezier point p_{4,0,1} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p401'),
    Line(id='sec7-conv2-p302', tex=(3234, 3234), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{3,0,2}    =\\frac{2}{5}\\Red{\\mathbf{r}_{4,3,'
                   '0}}+\\frac{3}{5}\\Red{\\mathbf{r}_{4,2,0}}'),
         says=('Quintic Bezier point p_{3,0,2} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p302'),
    Line(id='sec7-conv2-p203', tex=(3235, 3235), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{2,0,3}    =\\frac{3}{5}\\Red{\\mathbf{r}_{4,2,'
                   '0}}+\\frac{2}{5}\\Red{\\mathbf{r}_{4,1,0}}'),
         says=('Quintic Bezier point p_{2,0,3} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p203'),
    Line(id='sec7-conv2-p104', tex=(3236, 3236), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{1,0,4}    =\\frac{4}{5}\\Red{\\mathbf{r}_{4,1,'
                   '0}}+\\frac{1}{5}\\Green{\\mathbf{g}_{4,4,0}}'),
         says=('Quintic Bezier point p_{1,0,4} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p104'),
    Line(id='sec7-conv2-p311', tex=(3238, 3238), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{3,1,1}  & =\\frac{1}{5}\\Red{\\mathbf{r}_{4,3,'
                   '0}}+\\frac{3}{5}\\Red{\\mathbf{r}_{4,3,1}}+\\frac{1}{5}\\Blue{\\mathbf{b}_{4,1,0}}'),
         says=('Quintic Bezier point p_{3,1,1} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p311'),
    Line(id='sec7-conv2-p212', tex=(3239, 3239), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{2,1,2}    =\\frac{1}{5}\\Red{\\mathbf{r}_{4,2,'
                   '0}}+\\frac{4}{5}\\Red{\\mathbf{r}_{4,2,1}}'),
         says=('Quintic Bezier point p_{2,1,2} of the limit of an order-2 patch as this convex combination of '
               'its control points.'),
         status='checked', check='sec7-conv2-p212'),
    Line(id='sec7-conv3-p880', tex=(3243, 3243), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim='\\mathbf{p}_{8,8,0}  & =\\Red{\\mathbf{r}_{6,6,0}}',
         says=('Octic Bezier point p_{8,8,0} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='erratum', check='claim:bezier_conversion',
         erratum={
             'printed': 'p_{8,8,0} = 1 r_{6,6,0}',
             'corrected': 'p_{8,0,0} = 1 r_{6,6,0}',
             'evidence': ('p_{8,8,0} is not an index of the degree-8 Bezier net (indices sum to 8); the printed '
                        'weights are those of p_{8,0,0} in the exact general conversion'),
             'severity': 'typo',
         }),
    Line(id='sec7-conv3-p701', tex=(3244, 3244), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{7,0,1}  & =\\frac{1}{4}\\Red{\\mathbf{r}_{6,6,'
                   '0}}+\\frac{3}{4}\\Red{\\mathbf{r}_{6,5,0}}'),
         says=('Octic Bezier point p_{7,0,1} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p701'),
    Line(id='sec7-conv3-p602', tex=(3245, 3245), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{6,0,2}    =\\frac{1}{28}\\Red{\\mathbf{r}_{6,6,'
                   '0}}+\\frac{3}{7}\\Red{\\mathbf{r}_{6,5,0}}+\\frac{15}{28}\\Red{\\mathbf{r}_{6,4,0}}'),
         says=('Octic Bezier point p_{6,0,2} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p602'),
    Line(id='sec7-conv3-p503', tex=(3246, 3246), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{5,0,3}    =\\frac{3}{28}\\Red{\\mathbf{r}_{6,5,'
                   '0}}+\\frac{15}{28}\\Red{\\mathbf{r}_{6,4,0}}+\\frac{5}{14}\\Red{\\mathbf{r}_{6,3,0}}'),
         says=('Octic Bezier point p_{5,0,3} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p503'),
    Line(id='sec7-conv3-p404', tex=(3247, 3247), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{4,0,4}  & =\\frac{3}{14}\\Red{\\mathbf{r}_{6,4,'
                   '0}}+\\frac{4}{7}\\Red{\\mathbf{r}_{6,3,0}}+\\frac{3}{14}\\Red{\\mathbf{r}_{6,2,0}}'),
         says=('Octic Bezier point p_{4,0,4} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p404'),
    Line(id='sec7-conv3-p305', tex=(3248, 3248), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{3,0,5}    =\\frac{5}{14}\\Red{\\mathbf{r}_{6,3,'
                   '0}}+\\frac{15}{28}\\Red{\\mathbf{r}_{6,2,0}}+\\frac{3}{28}\\Red{\\mathbf{r}_{6,1,0}}'),
         says=('Octic Bezier point p_{3,0,5} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p305'),
    Line(id='sec7-conv3-p206', tex=(3249, 3249), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{2,0,6}    =\\frac{15}{28}\\Red{\\mathbf{r}_{6,2,'
                   '0}}+\\frac{3}{7}\\Red{\\mathbf{r}_{6,1,0}}+\\frac{1}{28}\\Green{\\mathbf{g}_{6,6,0}}'),
         says=('Octic Bezier point p_{2,0,6} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p206'),
    Line(id='sec7-conv3-p107', tex=(3250, 3250), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{1,0,7}  & =\\frac{3}{4}\\Red{\\mathbf{r}_{6,1,'
                   '0}}+\\frac{1}{4}\\Green{\\mathbf{g}_{6,6,0}}'),
         says=('Octic Bezier point p_{1,0,7} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p107'),
    Line(id='sec7-conv3-p611', tex=(3252, 3252), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{6,1,1}  & =\\frac{1}{28}\\Red{\\mathbf{r}_{6,6,'
                   '0}}+\\frac{3}{14}\\Red{\\mathbf{r}_{6,5,0}}+\\frac{15}{28}\\Red{\\mathbf{r}_{6,5,'
                   '1}}+\\frac{3}{14}\\Blue{\\mathbf{b}_{6,1,0}}'),
         says=('Octic Bezier point p_{6,1,1} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p611'),
    Line(id='sec7-conv3-p512', tex=(3253, 3255), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{5,1,2}  & =\\frac{1}{14}\\Red{\\mathbf{r}_{6,5,0}}+\\frac{5}{28}%\n'
                   '\\Red{\\mathbf{r}_{6,4,0}}+\\frac{5}{28}\\Red{\\mathbf{r}_{6,5,'
                   '1}}+\\frac{15}{28}\\Red{\\mathbf{r}%\n_{6,4,1}}+\\frac{1}{28}\\Blue{\\mathbf{b}_{6,1,0}}'),
         says=('Octic Bezier point p_{5,1,2} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p512'),
    Line(id='sec7-conv3-p413', tex=(3256, 3258), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{4,1,3}  & =\\frac{3}{28}\\Red{\\mathbf{r}_{6,4,0}}+\\frac{1}{7}%\n'
                   '\\Red{\\mathbf{r}_{6,3,0}}+\\frac{9}{28}\\Red{\\mathbf{r}_{6,4,'
                   '1}}+\\frac{3}{7}\\Red{\\mathbf{r}%\n_{6,3,1}}'),
         says=('Octic Bezier point p_{4,1,3} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p413'),
    Line(id='sec7-conv3-p314', tex=(3259, 3261), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{3,1,4}  & =\\frac{1}{7}\\Red{\\mathbf{r}_{6,3,0}}+\\frac{3}{28}%\n'
                   '\\Red{\\mathbf{r}_{6,2,0}}+\\frac{3}{7}\\Red{\\mathbf{r}_{6,3,'
                   '1}}+\\frac{9}{28}\\Red{\\mathbf{r}%\n_{6,2,1}}'),
         says=('Octic Bezier point p_{3,1,4} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p314'),
    Line(id='sec7-conv3-p215', tex=(3262, 3264), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{2,1,5}  & =\\frac{5}{28}\\Red{\\mathbf{r}_{6,2,0}}+\\frac{1}{14}%\n'
                   '\\Red{\\mathbf{r}_{6,1,0}}+\\frac{15}{28}\\Red{\\mathbf{r}_{6,1,'
                   '1}}+\\frac{1}{28}\\Green{\\mathbf{g}%\n_{6,5,0}}+\\frac{5}{28}\\Green{\\mathbf{g}_{6,5,1}}'),
         says=('Octic Bezier point p_{2,1,5} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='erratum', check='claim:bezier_conversion',
         erratum={
             'printed': ('p_{2,1,5} = 5/28 r_{6,2,0} + 1/14 r_{6,1,0} + 15/28 r_{6,1,1} + 1/28 g_{6,5,0} + 5/28 '
                       'g_{6,5,1}'),
             'corrected': ('p_{2,1,5} = 5/28 r_{6,2,0} + 1/14 r_{6,1,0} + 15/28 r_{6,2,1} + 1/28 g_{6,5,0} + 5/28 '
                         'g_{6,5,1}'),
             'evidence': ('exact general conversion (limit of the normalized basis written in the degree-8 '
                        'Bernstein basis)'),
             'severity': 'statement',
         }),
    Line(id='sec7-conv3-p116', tex=(3265, 3267), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{1,1,6}  & =\\frac{3}{14}\\Red{\\mathbf{r}_{6,1,0}}+\\frac{1}{28}%\n'
                   '\\Green{\\mathbf{g}_{6,6,0}}+\\frac{3}{14}\\Green{\\mathbf{g}_{6,5,'
                   '0}}+\\frac{15}{28}\\Green{\\mathbf{g}%\n_{6,5,1}}'),
         says=('Octic Bezier point p_{1,1,6} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p116'),
    Line(id='sec7-conv3-p422', tex=(3269, 3271), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{4,2,2}  & =\\frac{1}{28}\\Red{\\mathbf{r}_{6,4,0}}+\\frac{3}{14}%\n'
                   '\\Red{\\mathbf{r}_{6,4,1}}+\\frac{1}{28}\\Blue{\\mathbf{b}_{6,2,'
                   '0}}+\\frac{3}{14}\\Blue{\\mathbf{b}%\n_{6,2,1}}+\\frac{1}{2}\\Red{\\mathbf{r}_{6,4,2}}'),
         says=('Octic Bezier point p_{4,2,2} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='checked', check='sec7-conv3-p422'),
    Line(id='sec7-conv3-p323', tex=(3272, 3273), near='fig:limit_cases_n_1_2_3', kind='display',
         verbatim=('\\mathbf{p}_{3,2,3}  & =\\frac{1}{28}\\Red{\\mathbf{r}_{6,2,0}}+\\frac{3}{14}%\n'
                   '\\Red{\\mathbf{r}_{6,3,1}}+\\frac{3}{4}\\Red{\\mathbf{r}_{6,3,2}}'),
         says=('Octic Bezier point p_{3,2,3} of the limit of an order-3 patch as this convex combination of its '
               'control points.'),
         status='erratum', check='claim:bezier_conversion',
         erratum={
             'printed': 'p_{3,2,3} = 1/28 r_{6,2,0} + 3/14 r_{6,3,1} + 3/4 r_{6,3,2}',
             'corrected': 'p_{3,2,3} = 1/28 r_{6,3,0} + 3/14 r_{6,3,1} + 3/4 r_{6,3,2}',
             'evidence': ('exact general conversion (limit of the normalized basis written in the degree-8 '
                        'Bernstein basis)'),
             'severity': 'statement',
         }),
    Line(id='sec7-conversion-convex', tex=(3275, 3275), near='fig:limit_cases_n_1_2_3', kind='inline',
         verbatim=("shows all B\\'ezier points obtained by the evaluation of convex combinations describing "
                   'these conversion processes.'),
         says='All Bezier points are obtained as convex combinations (of the original control points).',
         status='checked', check='sec7-conversion-convex'),
    Line(id='sec7-fig-conversion-caption', tex=(3280, 3280), near='fig:conversion_of_limit_cases_n_1_2_3',
         kind='caption',
         verbatim=('\\caption{Conversion of control nets of original second and third order triangular '
                   'trigonometric patches to that of (\\emph{a}) quintic and (\\emph{b}) octic triangular '
                   "B\\'ezier patches, respectively, when $\\alpha \\to 0$.}"),
         says='Second and third order nets convert to (a) quintic and (b) octic Bezier nets as alpha -> 0.',
         status='checked', check='sec7-conversion-degrees'),
    Line(id='sec7-question-limiting-case', tex=(3286, 3286), near='que:limiting_case', kind='inline',
         verbatim=('Is the limiting case $\\alpha \\to 0$ of the (rational) triangular trigonometric patch of '
                   "order $n$ a (rational) triangular B\\'ezier patch of degree $3n-1$ defined on the unit "
                   'simplex? If so, then how can we convert the control net of the original (rational) '
                   "triangular trigonometric patch to that of the (rational) triangular B\\'ezier patch "
                   'obtained in this limiting case?'),
         says=('Question: is the alpha -> 0 limit of an order-n patch a Bezier triangle of degree 3n-1 on the '
               'unit simplex; how to convert the net?  (The conjectured degree 3n-1 is checked.)'),
         status='checked', check='sec7-question-limiting-case'),
    Line(id='sec7-s8-wang-citation', tex=(3291, 3295), near='que:limiting_case', kind='prose',
         verbatim=('The constrained trivariate counterpart of the univariate normalized\nB-basis\\ '
                   '(\\ref{univariate_basis}) of the vector space\n(\\ref{truncated_Fourier_vector_space}) of '
                   'first and second order\ntrigonometric polynomials were introduced in recent articles '
                   '\\cite{Wang2010a}\nand \\cite{Wang2010b}, respectively.'),
         says=('The trivariate counterparts of the first and second order univariate B-bases were introduced by '
               'Wang et al.'),
         status='excused',
         reason='citation'),
    Line(id='sec7-s8-dimension', tex=(3296, 3298), near='que:limiting_case', kind='count',
         verbatim=('the normalized\nlinearly independent constrained trivariate function system\n'
                   '(\\ref{normalized_united_system}) of dimension $\\delta_{n}=3n\\left(n+1\\right)+1$'),
         says=('The normalized system (normalized_united_system) is linearly independent and has dimension '
               'delta_n = 3n(n+1) + 1.'),
         status='checked', check='sec7-s8-dimension-and-span'),
    Line(id='sec7-s8-spans-fourier', tex=(3298, 3300), near='que:limiting_case', kind='inline',
         verbatim=('that spans the same vector space of functions as the\nconstrained trivariate extension of '
                   'the canonical basis of truncated Fourier\nseries of order $n\\in\\mathbb{N}$.'),
         says=('It spans the same space as the constrained trivariate extension of the truncated Fourier basis '
               'of order n.'),
         status='checked', check='sec7-s8-dimension-and-span'),
    Line(id='sec7-s8-patches-defined', tex=(3300, 3300), near='que:limiting_case', kind='prose',
         verbatim=('The proposed extension was applied to define (rational) triangular trigonometric patches of '
                   'order $n$.'),
         says='The extension was applied to define (rational) triangular trigonometric patches of order n.',
         status='excused',
         reason='prose summary'),
    Line(id='sec7-s8-future-work', tex=(3302, 3304), near='que:limiting_case', kind='prose',
         verbatim=('In Section \\ref{sec:open_problems} we have outlined some theoretical problems that will '
                   'form our forthcoming research directions. We also intend to illustrate the applicability '
                   'of\nthe proposed (rational) triangular trigonometric patches by providing '
                   '$\\alpha$-dependent control point based formulas for order elevation and the exact '
                   'description of triangular patches that lie on trigonometric\n(rational) surfaces.'),
         says=('Future work: the open problems, alpha-dependent order elevation and exact descriptions of '
               'surfaces.'),
         status='excused',
         reason='prose (plans)'),
    Line(id='sec7-s8-acknowledgements', tex=(3307, 3308), near='que:limiting_case', kind='prose',
         verbatim=("\\'{A}. R\\'{o}th partially realized his research in the frames of the highly important "
                   'National Excellence Program -- working out and operating an inland student and researcher '
                   "support, identification number T\\'AMOP 4.2.4.A/2-11-1-2012-0001. The project is realized "
                   'with the help of European Union and Hungary subsidy and co-financing by the European Social '
                   "Fund. \\'{A}. R\\'{o}th and A. Krist\\'{a}ly have also been supported by the Romanian "
                   "national grant CNCS-UEFISCDI/PN-II-RU-TE-2011-3-0047. I. Juh\\'{a}sz carried out his "
                   'research in the framework of the Center of Excellence of Mechatronics and Logistics at the '
                   'University of Miskolc. The authors would like to thank the kind help of W.-Q. Shen who '
                   'translated for them the\narticle \\cite{Wang2010b} from Chinese to English.'),
         says='Acknowledgements.',
         status='excused',
         reason='acknowledgements'),
]
