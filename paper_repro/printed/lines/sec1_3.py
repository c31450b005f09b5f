"""Sections 1-3 of the paper (abstract, Introduction, sec:RGB, sec:linear_independence), line by line.

Verbatim transcriptions (whitespace-normalised LaTeX of source lines ``tex``), checked by
:mod:`paper_repro.claims.lines.sec1_3` or by the claim named in ``check``.
"""

from __future__ import annotations

from paper_repro.printed.lines import Line

LINES = [
    Line('sec1_3-abstract-alpha-range',
         (67, 70),
         'truncated_Fourier_vector_space',
         'range',
         '$\\alpha\\in\\left( 0,\\pi\\right) $',
         'the shape parameter alpha lies in (0, pi)',
         'checked',
         check='sec1_3-alpha-range'),
    Line('sec1_3-abstract-delta',
         (72, 72),
         'truncated_Fourier_vector_space',
         'count',
         '$\\delta_{n}=3n\\left( n+1\\right) +1$',
         'the triangular extension has delta_n = 3n(n+1)+1 functions',
         'checked',
         check='sec1_3-delta-count'),
    Line('sec1_3-abstract-same-span',
         (72, 75),
         'truncated_Fourier_vector_space',
         'inline',
         'that spans the same vector space of functions as the constrained trivariate extensio'
         'n of the canonical basis of truncated Fourier series of order $n$ over',
         'span T_{2n} equals the span of the constrained trivariate extension of the truncated'
         ' Fourier basis of order n',
         'checked',
         check='sec1_3-fourier-dimension'),
    Line('sec1_3-abstract-prose',
         (75, 77),
         'truncated_Fourier_vector_space',
         'prose',
         'Although the explicit general basis transformation is yet unknown, the coincidence o'
         'f these vector spaces is proved by means of an appropriate equivalence relation. As '
         'a possible application of our triangular extension, we introduce the notion of (rati'
         'onal) triangular trigonometric patches of order $n$ and of singularity free parametr'
         'ization that could be used as control point based modeling tools in CAGD.',
         'the basis transformation is unknown; coincidence proved by an equivalence relation; '
         'patches introduced',
         'excused',
         reason='pure prose (outline of results checked where they are stated)'),
    Line('sec1_3-intro-history',
         (104, 113),
         'truncated_Fourier_vector_space',
         'prose',
         'Triangular (rational) polynomial (spline) surfaces like the Coons \\cite{Barnhill1973'
         "}, the Bernstein-B\\'ezier \\cite{deCasteljau1963, Barnhill1985, Farin1986} and the B-"
         'spline \\cite{Dahmen1992} triangular patches (and their rational variants) form an im'
         'portant aspect of CAGD. However, in order to provide control point based exact descr'
         'iption of triangular parts of certain well-known surfaces, the rational form of thes'
         'e triangular patches should be used, which implies an undesired complexity (consider'
         ' for example the evaluation of higher order (partial) derivatives, or the usage of n'
         'on-negative special weights associated with control points that may be unknown for t'
         'he designer) and in most cases provides a parametrization that does not reflect the '
         'variation of certain inner geometric properties (like curvature distribution) along '
         'the surface. One possibility to overcome some of these shortcomings is to consider t'
         'he normalized B-basis of other (non-polynomial) vector spaces of functions that incl'
         'ude the desired surfaces without the need of rational forms. Non-polynomial surfaces'
         ' like the first and second order triangular trigonometric patches and fourth order a'
         'lgebraic trigonometric ones were initiated by W.-Q. Shen, G.-Z. Wang and Y.-W. Wei i'
         'n recent papers \\cite{Wang2010a,Wang2010b} and \\cite{Wei2011}, respectively. These s'
         'pecial cases of triangular patches were obtained by certain constrained trivariate e'
         'xtensions of univariate normalized B-bases of the first and second order trigonometr'
         'ic and of the fourth order algebraic trigonometric vector spaces',
         'history: Coons, Bernstein-Bezier, B-spline patches; Shen, Wang, Wei for orders 1, 2 '
         'and algebraic trigonometric order 4',
         'excused',
         reason='pure prose and citations'),
    Line('sec1_3-intro-F2',
         (115, 118),
         'truncated_Fourier_vector_space',
         'definition',
         '\\mathcal{F}_{2}^{\\alpha} & =% \\operatorname{span}% \\left\\{ 1,\\cos\\left( t\\right) ,\\s'
         'in\\left( t\\right) :t\\in\\left[ 0,\\alpha\\right] \\right\\} ,\\\\',
         'F_2^alpha = span{1, cos t, sin t} on [0, alpha]',
         'excused',
         reason='a definition that only introduces a name (it is eq. truncated_Fourier_vector_space f'
                'or n = 1)'),
    Line('sec1_3-intro-F4',
         (119, 122),
         'truncated_Fourier_vector_space',
         'definition',
         '\\mathcal{F}_{4}^{\\alpha} & =% \\operatorname{span}% \\left\\{ 1,\\cos\\left( t\\right) ,\\s'
         'in\\left( t\\right) ,\\cos\\left( 2t\\right) ,\\sin\\left( 2t\\right) :t\\in\\left[ 0,\\alpha\\r'
         'ight] \\right\\}',
         'F_4^alpha = span{1, cos t, sin t, cos 2t, sin 2t}',
         'excused',
         reason='a definition that only introduces a name (it is eq. truncated_Fourier_vector_space f'
                'or n = 2)'),
    Line('sec1_3-intro-M4',
         (126, 129),
         'truncated_Fourier_vector_space',
         'definition',
         '\\mathcal{M}_{4}^{\\alpha}=% \\operatorname{span}% \\left\\{ 1,t,\\cos\\left( t\\right) ,\\si'
         'n\\left( t\\right) :t\\in\\left[ 0,\\alpha\\right] \\right\\} ,',
         'M_4^alpha = span{1, t, cos t, sin t}',
         'excused',
         reason='a definition that only introduces a name (cited work)'),
    Line('sec1_3-intro-alpha-range',
         (131, 131),
         'truncated_Fourier_vector_space',
         'range',
         'where $\\alpha\\in\\left( 0,\\pi\\right) $',
         'alpha in (0, pi) is a fixed shape parameter',
         'checked',
         check='sec1_3-alpha-range'),
    Line('sec1_3-sanchez-reyes',
         (156, 156),
         'univariate_basis',
         'prose',
         'The normalized B-basis of the vector space (\\ref{truncated_Fourier_vector_space}) wa'
         "s introduced by J. S\\'{a}nchez-Reyes in \\cite{SReyes1998}.",
         'the normalized B-basis of F_{2n}^alpha is due to Sanchez-Reyes',
         'excused',
         reason='citation (Sanchez-Reyes 1998); the basis itself is checked on the next line'),
    Line('sec1_3-truncated-fourier',
         (139, 142),
         'truncated_Fourier_vector_space',
         'definition',
         '\\mathcal{F}_{2n}^{\\alpha}=% \\operatorname{span}% \\left\\{ \\cos\\left( it\\right) ,\\sin\\'
         'left( it\\right) :t\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}^{n} \\label{truncated_Fou'
         'rier_vector_space}%',
         'F_{2n}^alpha = span{cos(it), sin(it)}_{i=0}^n on [0, alpha]',
         'excused',
         reason='a definition that only introduces a name'),
    Line('sec1_3-pena-alpha-pi',
         (149, 154),
         'truncated_Fourier_vector_space',
         'prose',
         'It was shown in \\cite{Pena1997} that vector space (\\ref{truncated_Fourier_vector_spa'
         'ce}) has no normalized totally positive bases when $\\alpha\\geq\\pi$, i.e., in this ca'
         'se it does not provide shape preserving representations using control polygons. Thus'
         ', it is crucial for the shape parameter $\\alpha$ to determine an interval of length '
         'strictly less than $\\pi$.',
         'for alpha >= pi the space has no normalized totally positive basis',
         'excused',
         reason='a cited result (Pena 1997); the degeneration of the printed basis at alpha = pi is s'
                'hown by check sec1_3-alpha-range'),
    Line('sec1_3-univariate-basis',
         (158, 161),
         'univariate_basis',
         'display',
         '\\left\\{ A_{2n,i}^{\\alpha}\\left( t\\right) :t\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}'
         '^{2n}=\\left\\{ c_{2n,i}^{\\alpha}\\sin^{2n-i} \\frac{\\alpha-t}{2} \\sin^{i}\\frac{t}{2}:t\\'
         'in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}^{2n}, \\label{univariate_basis}%',
         'A_{2n,i}(t) = c_{2n,i} sin^{2n-i}((alpha-t)/2) sin^i(t/2), i = 0..2n, a basis of F_{'
         "2n}^alpha (a reparametrization of Sanchez-Reyes' B-basis)",
         'checked',
         check='sec1_3-univariate-span'),
    Line('sec1_3-c-formula',
         (163, 168),
         'univariate_basis',
         'display',
         'where the normalizing non-negative coefficients% \\[ c_{2n,i}^{\\alpha}=\\frac{1}{\\sin^'
         '{2n}\\frac{\\alpha}{2}}\\sum_{r=0}^{\\left\\lfloor \\frac{i}{2}\\right\\rfloor }\\binom{n}{i-'
         'r}\\binom{i-r}{r}\\left( 2\\cos \\frac{\\alpha}{2}\\right) ^{i-2r},~i=0,1,\\ldots,2n \\]',
         'c_{2n,i} = sin^{-2n}(alpha/2) sum_{r=0}^{floor(i/2)} binom(n,i-r) binom(i-r,r) (2cos'
         '(alpha/2))^{i-2r}, non-negative, normalizing',
         'checked',
         check='sec1_3-c-formula'),
    Line('sec1_3-c-symmetry',
         (170, 172),
         'symmetry_of_Sanchez_Reyes_constants',
         'display',
         '\\begin{equation} c_{2n,i}^{\\alpha}=c_{2n,2n-i}^{\\alpha},~i=0,1,\\ldots,n. \\label{symm'
         'etry_of_Sanchez_Reyes_constants}%',
         'c_{2n,i} = c_{2n,2n-i}, i = 0..n',
         'checked',
         check='sec1_3-c-symmetry',
         reason=(
                'read skeptically: the range i = 0..n is enough (i = n+1..2n are the same equations read backwards) '
                'and i = n is trivial (c_{2n,n} = c_{2n,n}), so i = 0..n-1 would say the same; the check requires the'
                ' printed range with its mirror images to cover 0..2n')),
    Line('sec1_3-omega',
         (177, 180),
         'symmetry_of_Sanchez_Reyes_constants',
         'definition',
         '\\[ \\Omega^{\\alpha}=\\left\\{ \\left( u,v,w\\right) \\in\\left[ 0,\\alpha\\right]\\times\\left['
         ' 0,\\alpha\\right]\\times\\left[ 0,\\alpha\\right] :u+v+w=\\alpha\\right\\} , \\]',
         'Omega^alpha = {(u,v,w) in [0,alpha]^3 : u+v+w = alpha}',
         'excused',
         reason='a definition that only introduces a name'),
    Line('sec1_3-V-span',
         (183, 188),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'definition',
         '\\begin{equation} \\mathcal{V}_{n}^{\\alpha}=% \\operatorname{span}% V_{n}^{\\alpha}% \\la'
         'bel{constrained_trivariate_extension_of_truncated_Fourier_series}% \\end{equation}',
         'V_n^alpha spans the constrained trivariate extension',
         'excused',
         reason='a definition that only introduces a name'),
    Line('sec1_3-fourier-system',
         (190, 195),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'index-set',
         'the largest linearly independent subset of the function system% \\[ \\left\\{ \\cos\\left'
         '( ru+gv+bw\\right) ,\\sin\\left( ru+gv+bw\\right) :\\left( u,v,w\\right) \\in\\Omega^{\\alpha'
         '}\\right\\} _{r=0,g=0,b=0}^{n,n,n}.',
         'V_n is the largest linearly independent subset of {cos, sin}(ru+gv+bw), r, g, b = 0.'
         '.n',
         'checked',
         check='sec1_3-fourier-dimension',
         reason=(
                'read skeptically: on Omega^alpha (w = alpha-u-v) the index range is not minimal -- dropping b = n '
                '(or b = 0, or the same for r or g) keeps the span, since those frequencies are the negatives of '
                'others; the line claims only the span and it holds (ranks n = 1..3)')),
    Line('sec1_3-remark-not-b-basis',
         (197, 199),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'prose',
         '\\begin{remark} Note, that we only provide a special constrained trivariate extension'
         ' of the univariate B-basis (\\ref{univariate_basis}) that can be used to describe tri'
         'angular (rational) trigonometric patches with boundary curves defined by linear comb'
         'inations of control points and functions (\\ref{univariate_basis}). We do not suggest'
         ' that the proposed extension is also a B-basis. To the best of our knowledge, the no'
         'tion of multivariate normalized B-basis (or something similar) does not even exist i'
         'n the literature. The present paper describes some aspects of the proposed extension'
         ', but its global nature (e.g., whether its total behavior is similar to that of the '
         'multivariate Bernstein polynomials, or whether the multivariate Bernstein polynomial'
         's form the normalized B-basis of the vector space of multivariate polynomials of fin'
         'ite degree) needs further studies. \\end{remark}',
         'the extension is not claimed to be a B-basis',
         'excused',
         reason='pure prose'),
    Line('sec1_3-constraint-prose',
         (201, 206),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'prose',
         'In CAGD, the expression constrained trivariate function system refers in fact to a b'
         'ivariate one. Due to the constraint $u+v+w=\\alpha$ each variable can be written as t'
         'he linear combination of the remaining two independent ones. However, we do not fix '
         'which is pair assumed to be independent, since in most cases we will work with diffe'
         'rent parametrizations of the triangular domain $\\Omega^{\\alpha}$.',
         'a constrained trivariate system is bivariate',
         'excused',
         reason='pure prose'),
    Line('sec1_3-special-cases',
         (208, 210),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'prose',
         'the special cases $n=1$ and $n=2$ in recent articles \\cite{Wang2010a} and \\cite{Wang'
         '2010b}, respectively.',
         'the literature details n = 1 and n = 2',
         'excused',
         reason='citation (Wang 2010a, 2010b)'),
    Line('sec1_3-eight-sections',
         (211, 212),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'count',
         'we split our paper into eight sections',
         'the paper has eight sections',
         'excused',
         reason="a count of the paper's own sections, not a computation (the source has eight \\sectio"
                'n commands: Introduction .. Final remarks)'),
    Line('sec1_3-graph-levels',
         (214, 216),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'range',
         'weighted oriented\\ graph of $n\\geq1$ levels (numbered from $0$ to $n-1$)',
         'the graph of order n >= 1 has n levels numbered 0..n-1',
         'checked',
         check='sec1_3-levels'),
    Line('sec1_3-six-symmetries',
         (216, 219),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'inline',
         'that fulfill six cyclic symmetry properties in their variables',
         'R, G, B fulfil six cyclic symmetry properties',
         'checked',
         check='claim:symmetry',
         reason=(
                'debatable wording: the six properties are transpositions of two variables (three keep a family, '
                "three exchange adjacent families, caption of Fig. oriented_graph); 'cyclic' describes their "
                'arrangement around the triangle, not the symmetries')),
    Line('sec1_3-outline-sec3',
         (223, 229),
         'constrained_trivariate_extension_of_truncated_Fourier_series',
         'prose',
         'The linear independence of $T_{2n}^{\\alpha}$ will be proved in Section \\ref{sec:line'
         'ar_independence} by exploiting the symmetry properties of the oriented graph. More p'
         'recisely, using three periodically rotating parametrizations of $\\Omega^{\\alpha}$, w'
         'e apply a technique based on a special form of mathematical induction on the order o'
         'f partial derivatives\\ of a vanishing linear combination of constrained trivariate f'
         'unctions $R_{2n}^{\\alpha}$, $G_{2n}^{\\alpha}$ and $B_{2n}^{\\alpha}$.',
         'Section 3 proves linear independence by induction on the order of partial derivative'
         's under three rotating parametrizations',
         'excused',
         reason='outline of Section sec:linear_independence; its lines are transcribed and checked be'
                'low'),
    Line('sec1_3-outline-sec4',
         (231, 239),
         'sec:RGB',
         'prose',
         'Section \\ref{sec:coincidence} introduces an equivalence relation by means of which o'
         'ne can recursively construct the linearly independent function system $V_{n}^{\\alpha'
         '}$ that spans the constrained trivariate extension $\\mathcal{V}_{n}^{\\alpha}$ of the'
         ' univariate vector space $\\mathcal{F}% _{2n}^{\\alpha}$. As expected, vector spaces $'
         '\\mathcal{T}_{2n}^{\\alpha}=% \\operatorname{span}% T_{2n}^{\\alpha}$ and $\\mathcal{V}_{'
         'n}^{\\alpha}=% \\operatorname{span}% V_{n}^{\\alpha}$ coincide. Indeed, using equivalen'
         'ce classes we also prove',
         'Section 4 constructs V_n by an equivalence relation; span T_{2n} = span V_n',
         'excused',
         reason='outline of Section sec:coincidence; checked in that part'),
    Line('sec1_3-span-coincide-dim',
         (239, 241),
         'sec:RGB',
         'count',
         'along with the determination of the common dimension $\\delta_{n}=3n\\left( n+1\\right)'
         ' +1$ of these vector spaces',
         'span T_{2n} = span V_n, common dimension delta_n = 3n(n+1)+1',
         'checked',
         check='sec1_3-fourier-dimension'),
    Line('sec1_3-outline-normalization',
         (243, 248),
         'sec:RGB',
         'prose',
         'Section \\ref{sec:partition_of_unity} offers a procedure to obtain the normalized for'
         'm $\\overline{T}_{2n}^{\\alpha}$ of the function system $T_{2n}^{\\alpha}$. Due to the '
         'complexity of this problem, closed formulas of corresponding non-negative, symmetric'
         ' and unique normalizing coefficients are given only in case of levels $0$ and $1$ fo'
         'r arbitrary order, and for all levels just for orders $n=1$, $2$ and $3$.',
         'closed normalizing coefficients: levels 0 and 1 for every n; all levels for n = 1, 2'
         ', 3',
         'excused',
         reason='outline of Section sec:partition_of_unity; its statements are transcribed and checke'
                'd in that part'),
    Line('sec1_3-outline-rest',
         (250, 266),
         'sec:RGB',
         'prose',
         'Section \\ref{sec:applications} lists possible applications of our constrained triang'
         'ular extension by providing control point based surface modeling tools that may be u'
         'sed in CAGD. Subsection \\ref{sec:triangular_trigonometric_patches} introduces the no'
         'tion of triangular trigonometric patches of order $n$ and presents some of their geo'
         'metric properties. Using non-negative weights of rank $1$ and quotient basis functio'
         'ns, the rational counterpart of $\\overline{T}_{2n}^{\\alpha}$ is formulated in Subsec'
         'tion \\ref{sec:triangular_rational_trigonometric_patches} that defines triangular rat'
         'ional trigonometric patches. Compared to the classical constrained trivariate Bernst'
         'ein polynomials on triangular domains, in this non-polyno\\-mi\\-al case, theoretical '
         'questions are significantly harder to answer even for special values of the order $n'
         '$. Since we cannot answer some theoretical questions in their full generality for th'
         'e present, Section \\ref{sec:open_problems} formulates several open problems like the'
         ' general basis transformation between vector spaces $\\mathcal{T}% _{2n}^{\\alpha}$ an'
         'd $\\mathcal{V}_{n}^{\\alpha}$, the non-negativity, symmetry properties and closed/rec'
         'ursive formulas of normalizing coefficients of arbitrary order, general order elevat'
         'ion, and convergence of (rational) triangular trigonometric patches to (rational) B\\'
         "'ezier triangles when $\\alpha \\to 0$.",
         'outline of Sections 6-7',
         'excused',
         reason='pure prose'),
    Line('sec1_3-remark-technical-report',
         (268, 270),
         'sec:RGB',
         'prose',
         'In order to reduce the length of the paper, technical details of some proofs and reformulations are '
         'left out, that can be found in the technical report \\cite{tech_report}.',
         'Remark 1.2: details of some proofs are in a technical report',
         'excused',
         reason='a pointer to another document; nothing to compute (issue 33: its box showed "not yet checked")'),
    Line('sec1_3-fig-oriented-graph-caption',
         (284, 294),
         'fig:oriented_graph',
         'caption',
         'Functions associated with the red, green and blue shaded domains are symmetric in va'
         'riables $\\left( w,u\\right) $, $\\left( v,w\\right) $ and $\\left( u,v\\right) $, respect'
         'ively. Functions which correspond to the adjacent domains red--green, green--blue and blue--red are '
         'symmetric in variables $\\left( v,u\\right) $, $\\left( u,w\\right) $ and $\\left( w,v\\right) $, '
         'respectively.',
         'red, green, blue functions are symmetric in (w,u), (v,w), (u,v); adjacent red-green,'
         ' green-blue, blue-red in (v,u), (u,w), (w,v)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-corners-centre',
         (298, 307),
         'fig:oriented_graph',
         'inline',
         'The three outermost nodes (i.e., the vertices of the outermost triangle) store the f'
         'unctions $\\sin^{2n}\\frac{u}{2}$, $\\sin^{2n}\\frac{v}{2}$ and $\\sin ^{2n}\\frac{w}{2}$.'
         ' Each directed edge has a weight function that defines a multiplication factor when '
         'one follows a path from a given node to another one. Tracking a given path and multi'
         'plying by weight functions along the edges, determines the function stored in an inn'
         'er node of the graph. Observe that the layout of these multiplicative weight functio'
         'ns ensures that all paths starting from an outermost node and terminating at the inn'
         'ermost one (i.e., the common centroid of triangles) generate the same constrained tr'
         'ivariate function $\\sin^{n}\\frac{u}{2}\\sin^{n}\\frac{v}{2}\\sin^{n}\\frac{w}{2}$.',
         'the outermost nodes store sin^{2n}(u/2), sin^{2n}(v/2), sin^{2n}(w/2); all paths end'
         ' at sin^n(u/2) sin^n(v/2) sin^n(w/2)',
         'checked',
         check='sec1_3-corners-centre'),
    Line('sec1_3-R-system',
         (311, 313),
         'R_system',
         'index-set',
         'R_{2n}^{\\alpha} & =\\left\\{ R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) :\\left( u,v,w\\r'
         'ight) \\in\\Omega^{\\alpha}\\right\\} _{j=0,i=j}^{n,2n-j}% ,\\label{R_system}\\\\',
         'R_{2n} = {R_{2n,2n-i,j}}, j = 0..n, i = j..2n-j',
         'checked',
         check='sec1_3-rgb-index-sets'),
    Line('sec1_3-G-system',
         (314, 316),
         'G_system',
         'index-set',
         'G_{2n}^{\\alpha} & =\\left\\{ G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) :\\left( u,v,w\\r'
         'ight) \\in\\Omega^{\\alpha}\\right\\} _{j=0,i=j}^{n,2n-j}% \\label{G_system}%',
         'G_{2n} = {G_{2n,2n-i,j}}, j = 0..n, i = j..2n-j',
         'checked',
         check='sec1_3-rgb-index-sets'),
    Line('sec1_3-B-system',
         (319, 321),
         'B_system',
         'index-set',
         'B_{2n}^{\\alpha}=\\left\\{ B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) :\\left( u,v,w\\righ'
         't) \\in\\Omega^{\\alpha}\\right\\} _{j=0,i=j}^{n,2n-j}',
         'B_{2n} = {B_{2n,2n-i,j}}, j = 0..n, i = j..2n-j',
         'checked',
         check='sec1_3-rgb-index-sets'),
    Line('sec1_3-R-leq-n',
         (325, 328),
         'R_system_leq_n',
         'display',
         '\\left\\{ R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=j}% ^{n,n} & =\\le'
         'ft\\{ \\sin^{2n-i}\\frac{u}{2}\\sin^{i}\\frac{w}{2}\\cos^{i-j}% \\frac{v}{2}\\sin^{j}\\frac{v'
         '}{2}\\right\\} _{j=0,i=j}^{n,n}% ,\\label{R_system_leq_n}\\\\',
         'R_{2n,2n-i,j} = sin^{2n-i}(u/2) sin^i(w/2) cos^{i-j}(v/2) sin^j(v/2), j = 0..n, i = '
         'j..n (its index range: half of R_system; powers >= 0)',
         'checked',
         check='sec1_3-rgb-index-sets'),
    Line('sec1_3-R-geq-n-relation',
         (330, 332),
         'R_system_geq_n',
         'display',
         '\\left\\{ R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=n+1}% ^{n-1,2n-j}'
         ' & =\\left\\{ R_{2n,i,j}^{\\alpha}\\left( w,v,u\\right) \\right\\} _{j=0,i=n+1}^{n-1,2n-j}\\'
         'label{R_system_geq_n}\\\\',
         'R_{2n,2n-i,j}(u,v,w) = R_{2n,i,j}(w,v,u) for j = 0..n-1, i = n+1..2n-j',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-R-geq-n-explicit',
         (333, 334),
         'R_system_geq_n',
         'display',
         '& =\\left\\{ \\sin^{i}\\frac{w}{2}\\sin^{2n-i}\\frac{u}{2}\\cos^{2n-i-j}\\frac{v}% {2}\\sin^{'
         'j}\\frac{v}{2}\\right\\} _{j=0,i=n+1}^{n-1,2n-j},\\nonumber',
         '= sin^i(w/2) sin^{2n-i}(u/2) cos^{2n-i-j}(v/2) sin^j(v/2)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-G-cyclic',
         (338, 340),
         'R_system_geq_n',
         'definition',
         '\\left\\{ G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=j}% ^{n,n} & =\\le'
         'ft\\{ R_{2n,2n-i,j}^{\\alpha}\\left( w,u,v\\right) \\right\\} _{j=0,i=j}^{n,n}\\\\',
         'G_{2n,2n-i,j}(u,v,w) = R_{2n,2n-i,j}(w,u,v), j = 0..n, i = j..n',
         'excused',
         reason='definition of G by the cyclic substitution; the explicit form on the next row is che'
                'cked against it (claim symmetry)'),
    Line('sec1_3-G-leq-explicit',
         (341, 342),
         'R_system_geq_n',
         'display',
         '& =\\left\\{ \\sin^{2n-i}\\frac{w}{2}\\sin^{i}\\frac{v}{2}\\cos^{i-j}\\frac{u}% {2}\\sin^{j}\\'
         'frac{u}{2}\\right\\} _{j=0,i=j}^{n,n},\\nonumber\\\\',
         'G_{2n,2n-i,j} = sin^{2n-i}(w/2) sin^i(v/2) cos^{i-j}(u/2) sin^j(u/2)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-G-geq-relation',
         (344, 346),
         'R_system_geq_n',
         'display',
         '\\left\\{ G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=n+1}% ^{n-1,2n-j}'
         ' & =\\left\\{ G_{2n,i,j}^{\\alpha}\\left( u,w,v\\right) \\right\\} _{j=0,i=n+1}^{n-1,2n-j}\\'
         '\\',
         'G_{2n,2n-i,j}(u,v,w) = G_{2n,i,j}(u,w,v), i = n+1..2n-j',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-G-geq-explicit',
         (347, 348),
         'R_system_geq_n',
         'display',
         '& =\\left\\{ \\sin^{i}\\frac{v}{2}\\sin^{2n-i}\\frac{w}{2}\\cos^{2n-i-j}\\frac{u}% {2}\\sin^{'
         'j}\\frac{u}{2}\\right\\} _{j=0,i=n+1}^{n-1,2n-j},\\nonumber',
         '= sin^i(v/2) sin^{2n-i}(w/2) cos^{2n-i-j}(u/2) sin^j(u/2)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-B-cyclic',
         (351, 353),
         'R_system_geq_n',
         'definition',
         '\\left\\{ B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=j}% ^{n,n} & =\\le'
         'ft\\{ R_{2n,2n-i,j}^{\\alpha}\\left( v,w,u\\right) \\right\\} _{j=0,i=j}^{n,n}\\\\',
         'B_{2n,2n-i,j}(u,v,w) = R_{2n,2n-i,j}(v,w,u), j = 0..n, i = j..n',
         'excused',
         reason='definition of B by the cyclic substitution; the explicit form on the next row is che'
                'cked against it (claim symmetry)'),
    Line('sec1_3-B-leq-explicit',
         (354, 355),
         'R_system_geq_n',
         'display',
         '& =\\left\\{ \\sin^{2n-i}\\frac{v}{2}\\sin^{i}\\frac{u}{2}\\cos^{i-j}\\frac{w}% {2}\\sin^{j}\\'
         'frac{w}{2}\\right\\} _{j=0,i=j}^{n,n},\\nonumber\\\\',
         'B_{2n,2n-i,j} = sin^{2n-i}(v/2) sin^i(u/2) cos^{i-j}(w/2) sin^j(w/2)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-B-geq-relation',
         (357, 359),
         'united_system',
         'display',
         '\\left\\{ B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\right\\} _{j=0,i=n+1}% ^{n-1,2n-j}'
         ' & =\\left\\{ B_{2n,i,j}^{\\alpha}\\left( v,u,w\\right) \\right\\} _{j=0,i=n+1}^{n-1,2n-j}\\'
         '\\',
         'B_{2n,2n-i,j}(u,v,w) = B_{2n,i,j}(v,u,w), i = n+1..2n-j',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-B-geq-explicit',
         (360, 361),
         'united_system',
         'display',
         '& =\\left\\{ \\sin^{i}\\frac{u}{2}\\sin^{2n-i}\\frac{v}{2}\\cos^{2n-i-j}\\frac{w}% {2}\\sin^{'
         'j}\\frac{w}{2}\\right\\} _{j=0,i=n+1}^{n-1,2n-j}.\\nonumber',
         '= sin^i(u/2) sin^{2n-i}(v/2) cos^{2n-i-j}(w/2) sin^j(w/2)',
         'checked',
         check='claim:symmetry'),
    Line('sec1_3-nonnegative',
         (364, 366),
         'united_system',
         'inline',
         'consist of non-negative functions',
         'R, G, B consist of non-negative functions',
         'checked',
         check='sec1_3-nonnegative'),
    Line('sec1_3-united-system',
         (373, 376),
         'united_system',
         'index-set',
         'T_{2n}^{\\alpha} & = & \\left\\{ R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,G_{2n,2n-i,'
         'j}^{\\alpha}\\left( u,v,w\\right) ,B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) :\\left( u,'
         'v,w\\right) \\in\\Omega^{\\alpha}\\right\\} _{j=0,i=j}^{n-1,2n-1-j}\\\\',
         'T_{2n}: R, G, B with j = 0..n-1, i = j..2n-1-j',
         'checked',
         check='sec1_3-united-dedupe'),
    Line('sec1_3-united-centre',
         (378, 380),
         'united_system',
         'display',
         '& & \\cup\\left\\{ R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) =G_{2n,n,n}% ^{\\alpha}\\left( '
         'u,v,w\\right) =B_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) :\\left( u,v,w\\right) \\in\\Omega^'
         '{\\alpha}\\right\\}',
         'and the centre R_{2n,n,n} = G_{2n,n,n} = B_{2n,n,n}',
         'checked',
         check='sec1_3-corners-centre'),
    Line('sec1_3-levels-j',
         (384, 386),
         'united_system',
         'inline',
         'We refer to the index $j$ of these functions as levels since they correspond to the '
         'nested triangles shrinking from the boundary to their common centroid',
         'the index j is the level (nested triangles shrinking to the centroid)',
         'checked',
         check='sec1_3-levels',
         reason=(
                'debatable: the centre R_{2n,n,n} = G_{2n,n,n} = B_{2n,n,n} of T_{2n} has j = n, yet the graph has n '
                'levels numbered 0..n-1 (line sec1_3-graph-levels): the levels are the nested triangles, the centroid'
                " is not one of them; the check reads 'levels' so (non-centre functions) and checks that j is the "
                'order of vanishing on the boundary for every function, the centre included')),
    Line('sec1_3-T6-order-3',
         (387, 388),
         'united_system',
         'inline',
         '$T_{6}^{\\alpha}$ of order $3$',
         'T_6^alpha is the system of order 3',
         'checked',
         check='sec1_3-order-n3'),
    Line('sec1_3-fig-united-n3-caption',
         (398, 399),
         'fig:united_system_n_3',
         'caption',
         'The layout of the constrained trivariate joint function system (\\ref{united_system})'
         ' of order $n=3$.',
         'the layout of T_{2n} for n = 3',
         'checked',
         check='sec1_3-order-n3'),
    Line('sec1_3-boundary-property-1',
         (408, 410),
         'boundary_property_1',
         'display',
         '\\left. T_{2n}^{\\alpha}\\right\\vert _{v=0} & =\\left\\{ \\frac{1}{c_{2n,2n-i}% ^{\\alpha}}'
         'A_{2n,2n-i}^{\\alpha}\\left( u\\right) :u\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}^{2n}'
         ',\\label{boundary_property_1}\\\\',
         'T_{2n} restricted to v = 0 is {A_{2n,2n-i}(u)/c_{2n,2n-i}}, i = 0..2n',
         'checked',
         check='sec1_3-boundary-v0',
         reason=(
                'debatable wording: the functions of T_{2n} with a factor sin(v/2) restrict to 0 on v = 0; the '
                'display lists only the non-zero restrictions (the check drops the vanishing ones); as sets the order'
                ' of the index i does not matter, and with the labels it matches: R_{2n,2n-i,0}(u,0,w) = '
                'A_{2n,2n-i}(u)/c_{2n,2n-i}')),
    Line('sec1_3-boundary-property-2',
         (411, 413),
         'boundary_property_2',
         'display',
         '\\left. T_{2n}^{\\alpha}\\right\\vert _{u=0} & =\\left\\{ \\frac{1}{c_{2n,2n-i}% ^{\\alpha}}'
         'A_{2n,2n-i}^{\\alpha}\\left( w\\right) :w\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}^{2n}'
         ',\\label{boundary_property_2}\\\\',
         'T_{2n} restricted to u = 0 is {A_{2n,2n-i}(w)/c_{2n,2n-i}}, i = 0..2n',
         'checked',
         check='sec1_3-boundary-u0'),
    Line('sec1_3-boundary-property-3',
         (414, 416),
         'boundary_property_3',
         'display',
         '\\left. T_{2n}^{\\alpha}\\right\\vert _{w=0} & =\\left\\{ \\frac{1}{c_{2n,2n-i}% ^{\\alpha}}'
         'A_{2n,2n-i}^{\\alpha}\\left( v\\right) :v\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=0}^{2n}'
         '.\\label{boundary_property_3}%',
         'T_{2n} restricted to w = 0 is {A_{2n,2n-i}(v)/c_{2n,2n-i}}, i = 0..2n',
         'checked',
         check='sec1_3-boundary-w0'),
    Line('sec1_3-bernstein-limit',
         (420, 425),
         'Bernstein',
         'display',
         'If one uses the linear reparametrization $t\\left( s\\right) =\\alpha s,~s\\in\\left[ 0,1'
         '\\right] $, then basis functions (\\ref{univariate_basis}) of order $n$ converge to th'
         'e Bernstein polynomials of degree $2n$ when $\\alpha\\rightarrow0$, i.e.,% \\begin{equa'
         'tion} \\lim_{\\alpha\\rightarrow0}A_{2n,i}^{\\alpha}\\left( \\alpha s\\right) =B_{i}^{2n}\\l'
         'eft( s\\right) ,\\, \\forall s \\in \\left[0,1\\right],~i=0,1,\\ldots,2n\\text{.} \\label{lim'
         'it_Bernstein}%',
         'with t = alpha s, lim_{alpha->0} A_{2n,i}(alpha s) = B_i^{2n}(s), s in [0,1], i = 0.'
         '.2n',
         'checked',
         check='sec1_3-bernstein-limit'),
    Line('sec1_3-bernstein-identity',
         (433, 436),
         'limit_Bernstein',
         'display',
         '\\[ A_{2n,0}^{\\alpha}\\left( \\alpha s\\right) +A_{2n,1}^{\\alpha}\\left( \\alpha s\\right) '
         '+A_{2n,2}^{\\alpha}\\left( \\alpha s\\right) =1,~\\forall s\\in\\left[ 0,1\\right] \\]',
         'the identity raised to the power n: A_{2n,0}(alpha s) + A_{2n,1}(alpha s) + A_{2n,2}'
         '(alpha s) = 1',
         'erratum',
         check='sec1_3-bernstein-identity',
         erratum={'printed': 'A_{2n,0}^alpha(alpha s) + A_{2n,1}^alpha(alpha s) + A_{2n,2}^alpha(alpha'
                             ' s) = 1 for all s in [0,1]',
                  'corrected': 'A_{2,0}^alpha(alpha s) + A_{2,1}^alpha(alpha s) + A_{2,2}^alpha(alpha s)'
                               ' = 1 (the order-1 basis, whose n-th power gives the order-n basis; the n'
                               'ext display writes it with 1/sin^2(alpha/2), 2cos(alpha/2)/sin^2(alpha/2'
                               '), 1/sin^2(alpha/2), i.e. c_{2,0}, c_{2,1}, c_{2,2})',
                  'evidence': 'exact values: for n = 2, tan(alpha/4) = 1/2, tan(alpha s/4) = 1/6 the pr'
                              'inted sum is 1612936/1874161 != 1 (it fails for every n >= 2 at all 4 sa'
                              'mpled points); with A_{2,k} it is 1 exactly at every sampled point',
                  'severity': 'typo'}),
    Line('sec1_3-bernstein-power',
         (438, 442),
         'limit_Bernstein',
         'display',
         '\\[ \\sum_{i=0}^{2n}A_{2n,i}^{\\alpha}\\left( \\alpha s\\right) =\\left( A_{2n,0}^{\\alpha }'
         '\\left( s\\right) +A_{2n,1}^{\\alpha}\\left( s\\right) +A_{2n,2}^{\\alpha }\\left( s\\right)'
         ' \\right) ^{n}=1,~\\forall s\\in\\left[ 0,1\\right] \\]',
         'sum_{i=0}^{2n} A_{2n,i}(alpha s) = (A_{2n,0}(s) + A_{2n,1}(s) + A_{2n,2}(s))^n = 1',
         'erratum',
         check='sec1_3-bernstein-power',
         erratum={'printed': 'sum_{i=0}^{2n} A_{2n,i}^alpha(alpha s) = (A_{2n,0}^alpha(s) + A_{2n,1}^a'
                             'lpha(s) + A_{2n,2}^alpha(s))^n = 1',
                  'corrected': 'sum_{i=0}^{2n} A_{2n,i}^alpha(alpha s) = (A_{2,0}^alpha(alpha s) + A_{2,'
                               '1}^alpha(alpha s) + A_{2,2}^alpha(alpha s))^n = 1',
                  'evidence': 'exact values: the printed middle term is not 1 for n >= 2 (e.g. n = 2, t'
                              'an(alpha/4) = 1/2); with A_{2,k} both equalities hold at all sampled poi'
                              'nts (n <= 4), and the expansion of (sum_k c_{2,k} X^{2-k} Y^k)^n has the'
                              ' coefficients c_{2n,i} exactly (n <= 5), so the terms of the power are t'
                              'he A_{2n,i} at the same argument (alpha s, not s)',
                  'severity': 'typo'}),
    Line('sec1_3-bernstein-limit-step1',
         (444, 452),
         'sec:linear_independence',
         'display',
         '\\begin{align*} & \\lim_{\\alpha\\rightarrow0}\\left( \\frac{1}{\\sin^{2}\\left( \\frac{\\alph'
         'a}% {2}\\right) }\\sin^{2}\\left( \\frac{\\alpha-\\alpha s}{2}\\right) +\\frac {2\\cos\\left( '
         '\\frac{\\alpha}{2}\\right) }{\\sin^{2}\\left( \\frac{\\alpha}% {2}\\right) }\\sin\\left( \\frac'
         '{\\alpha-\\alpha s}{2}\\right) \\sin\\left( \\frac{\\alpha s}{2}\\right) +\\frac{1}{\\sin^{2}\\'
         'left( \\frac{\\alpha}{2}\\right) }\\sin^{2}\\left( \\frac{\\alpha s}{2}\\right) \\right) ^{n}'
         '\\\\ = & \\left( \\left( 1-s\\right) ^{2}+2\\left( 1-s\\right) s+s^{2}\\right) ^{n}\\\\',
         'the limit of the order-1 sum to the power n is ((1-s)^2 + 2(1-s)s + s^2)^n',
         'checked',
         check='sec1_3-bernstein-proof-limit',
         reason=(
                'debatable (proof gap): the chain shows that the n-th power of the sum of the three terms tends to '
                "((1-s)+s)^{2n}; both ends equal 1 for every alpha, so as values it says nothing -- the Proposition's"
                ' termwise limit needs that the expansion of the power groups into the A_{2n,i}(alpha s) (the erratum'
                ' of sec1_3-bernstein-power) and that each group tends to the matching group of the expansion of '
                '((1-s)+s)^{2n}; the check reads the step as a termwise limit (each of the three terms against the '
                "right side's)")),
    Line('sec1_3-bernstein-limit-step2',
         (453, 454),
         'sec:linear_independence',
         'display',
         '= & \\left( \\left( 1-s\\right) +s\\right) ^{2n}\\\\ = & \\sum_{i=0}^{2n}B_{i}^{2n}\\left( s'
         '\\right)',
         '= ((1-s) + s)^{2n}',
         'checked',
         check='sec1_3-bernstein-polynomials'),
    Line('sec1_3-bernstein-limit-step3',
         (454, 455),
         'sec:linear_independence',
         'display',
         '= & \\sum_{i=0}^{2n}B_{i}^{2n}\\left( s\\right) \\end{align*}',
         '= sum_{i=0}^{2n} B_i^{2n}(s)',
         'checked',
         check='sec1_3-bernstein-polynomials'),
    Line('sec1_3-bernstein-limits-used',
         (457, 459),
         'sec:linear_independence',
         'inline',
         'since $ \\lim\\limits_{\\alpha\\rightarrow0}\\frac{\\sin\\left( \\frac{\\alpha s}{2}\\right) }'
         '% {\\sin\\left( \\frac{\\alpha}{2}\\right) } =s$ and $\\lim\\limits_{\\alpha\\rightarrow0}\\co'
         's\\left( \\frac{\\alpha s}{2}\\right) =1.$',
         'lim sin(alpha s/2)/sin(alpha/2) = s, lim cos(alpha s/2) = 1',
         'checked',
         check='sec1_3-bernstein-proof-limit',
         reason=(
                'debatable: the limit expression of the proof contains cos(alpha/2) and sin((alpha-alpha '
                's)/2)/sin(alpha/2), not cos(alpha s/2); the limits needed are the printed ones at s = 1 and with s '
                'replaced by 1-s, which they imply')),
    Line('sec1_3-CS-definitions',
         (467, 475),
         'sec:linear_independence',
         'definition',
         '\\begin{align*} C_{i,\\lambda}^{p}\\left( t\\right) & =\\frac{\\text{d}^{p}}{\\text{d}t^{p}'
         '}% \\cos^{i}\\left( \\lambda t\\right) ,~t\\in% \\mathbb{R} ,\\\\ S_{j,\\mu}^{p}\\left( t\\righ'
         't) & =\\frac{\\text{d}^{p}}{\\text{d}t^{p}}\\sin ^{j}\\left( \\mu t\\right) ,~t\\in% \\mathbb'
         '{R}% \\end{align*}',
         'C^p_{i,lambda}(t) = d^p/dt^p cos^i(lambda t), S^p_{j,mu}(t) likewise',
         'excused',
         reason='a definition that only introduces a name'),
    Line('sec1_3-M-definition',
         (477, 481),
         'lem:sign_cos_power_derivative',
         'definition',
         '\\[ M_{i,\\lambda,j,\\mu}^{z}\\left( t\\right) =\\frac{\\text{d}^{z}}{\\text{d}t^{z}% }\\left'
         '( \\cos^{i}\\left( \\lambda t\\right) \\sin^{j}\\left( \\mu t\\right) \\right) \\]',
         'M^z_{i,lambda,j,mu}(t) = d^z/dt^z (cos^i(lambda t) sin^j(mu t))',
         'excused',
         reason='a definition that only introduces a name'),
    Line('sec1_3-lemma-hypotheses',
         (487, 490),
         'lem:sign_cos_power_derivative',
         'prose',
         'Let $i$, $j$ and $p$ be natural numbers greater than or equal to $1$. If $\\lambda,\\m'
         'u>0$, then signs of values $\\left\\{ C_{i,\\lambda}^{p}\\left( 0\\right) \\right\\} _{p\\ge'
         'q0}$ and $\\left\\{ S_{j,\\mu}^{p}\\left( 0\\right) \\right\\} _{p\\geq0}$ are%',
         'i, j, p >= 1, lambda, mu > 0; the signs of {C^p(0)}_{p>=0}, {S^p(0)}_{p>=0}',
         'erratum',
         check='sec1_3-lemma-hypotheses',
         erratum={'printed': 'Let i, j and p be natural numbers greater than or equal to 1 ... the signs of {C^p_{i,l'
                             'ambda}(0)}_{p>=0} and {S^p_{j,mu}(0)}_{p>=0}',
                  'corrected': 'Let i and j be natural numbers greater than or equal to 1 (p >= 0, as the sets of '
                               'signs say)',
                  'evidence': 'the hypothesis p >= 1 excludes p = 0, which the two sets of signs the Lemma states '
                              '(indexed p >= 0) and its rules include (e.g. the sine rule gives sign S^0_{j,mu}(0) '
                              '= 0 by its branch p < j, exact: sin^j(0) = 0); the sine rule read from the transcri'
                              'ption holds exactly for j = 1..8, p = 0..16, mu in {1/2, 1, 3} (check sec1_3-lemma-h'
                              'ypotheses); i, j >= 1 is needed (j = 0, p = 2: the rule gives -1, the derivative of '
                              'sin^0 = 1 is 0)',
                  'severity': 'typo'}),
    Line('sec1_3-sign-cos',
         (491, 501),
         'sign_cos_power_derivative',
         'display',
         '\\begin{equation}% \\operatorname{sign}% C_{i,\\lambda}^{p}\\left( 0\\right) =\\left\\{ \\be'
         'gin{array} [c]{rl}% -1, & ~p-i=2r,~r\\equiv1\\left( \\operatorname{mod}2\\right) ,\\\\ 0, '
         '& ~p\\equiv1\\left( \\operatorname{mod}2\\right) ,\\\\ +1, & ~p-i=2r,~r\\equiv0\\left( \\oper'
         'atorname{mod}2\\right) \\end{array} \\right. \\label{sign_cos_power_derivative}% \\end{eq'
         'uation}',
         'the sign rule of C^p_{i,lambda}(0)',
         'erratum',
         check='claim:derivative_signs',
         erratum={'id': 'lemma-sign-cos-power',
                  'printed': '-1 if p-i = 2r with r odd; 0 if p odd; +1 if p-i = 2r with r even',
                  'corrected': '0 if p is odd; (-1)^(p/2) if p is even (for every i >= 1, lambda > 0)',
                  'evidence': ("exact Taylor coefficients: 936 of 1488 cases (i <= 12, p <= 30, lambda in ['1/2', '1"
                              "', '3', '7/5']) disagree with the printed rule read from the transcription (no print"
                              'ed case applies when p is even and i odd; when p and i are both odd the branches 0 ('
                              'p odd) and +-1 (p-i = 2r) both apply, with different values; the sign is wrong when '
                              'i = 2 mod 4), e.g. i = 1, p = 0: no branch, true +1; i = 1, p = 1: branches 0 and +1'
                              ', true 0; i = 2, p = 2: printed +1, true -1; the corrected rule matches all cases. T'
                              'he proof of the theorem uses Proposition derivative_cosine_sine, which is correct.'),
                  'severity': 'statement'}),
    Line('sec1_3-sign-sin',
         (503, 514),
         'sign_sin_power_derivative',
         'display',
         '\\begin{equation}% \\operatorname{sign}% S_{j,\\mu}^{p}\\left( 0\\right) =\\left\\{ \\begin{'
         'array} [c]{rl}% -1, & ~p\\geq j,~p-j=2r,~r\\equiv1\\left( \\operatorname{mod}2\\right) ,\\'
         '\\ 0, & ~\\left( p<j\\right) \\ \\text{or }\\left( p-j\\equiv1\\left( \\operatorname{mod}2\\ri'
         'ght) \\text{ and }p>j\\right) ,\\\\ +1, & ~p\\geq j,~p-j=2r,~r\\equiv0\\left( \\operatorname'
         '{mod}2\\right) , \\end{array} \\right. \\label{sign_sin_power_derivative}% \\end{equation'
         '}',
         'the sign rule of S^p_{j,mu}(0)',
         'checked',
         check='claim:derivative_signs'),
    Line('sec1_3-sin-leading',
         (515, 515),
         'sign_sin_power_derivative',
         'inline',
         'respectively. (In particular, $S_{j,\\mu}^{j}\\left( 0\\right) =j!\\mu^{j}$).',
         'S^j_{j,mu}(0) = j! mu^j',
         'checked',
         check='sec1_3-sin-power-leading'),
    Line('sec1_3-proposition-M',
         (520, 536),
         'derivative_cosine_sine',
         'display',
         'Independently of $i\\in% \\mathbb{N} $ and $\\lambda,\\mu>0$, for all values of $j,z\\in%'
         ' \\mathbb{N} $ such that $i+j\\neq0$ and $z\\geq1$ we have the equality% \\begin{equatio'
         'n}% \\operatorname{sign}% M_{i,\\lambda,j,\\mu}^{z}\\left( 0\\right) =\\left\\{ \\begin{arra'
         'y} [c]{rl}% -1, & ~z-j\\equiv2\\left( \\operatorname{mod}4\\right) \\text{ and }z\\geq j,\\'
         '\\ 0, & ~\\left( z<j\\right) \\text{ or }\\left( z-j\\equiv\\pm1\\left( \\operatorname{mod}4\\'
         'right) \\text{ and }z>j\\right) ,\\\\ +1, & ~z-j\\equiv0\\left( \\operatorname{mod}4\\right)'
         ' \\text{ and }z\\geq j. \\end{array} \\right. \\label{derivative_cosine_sine_at_0}% \\end{'
         'equation}',
         'sign M^z(0): -1 if z-j = 2 mod 4, z >= j; 0 if z < j or z-j = +-1 mod 4, z > j; +1 i'
         'f z-j = 0 mod 4, z >= j (i+j != 0, z >= 1)',
         'checked',
         check='claim:derivative_signs'),
    Line('sec1_3-param-partition-of-unity',
         (541, 550),
         'parametrization_for_partition_of_unity',
         'parametrization',
         '\\begin{equation} \\left\\{ \\begin{array} [c]{rcl}% u\\left( x,y\\right) & = & \\alpha-x,~'
         'x\\in\\left[ 0,\\alpha\\right] ,\\\\ v\\left( x,y\\right) & = & y,~y\\in\\left[ 0,\\alpha-x\\rig'
         'ht] ,\\\\ w\\left( x,y\\right) & = & x-y, \\end{array} \\right. \\label{parametrization_for'
         '_partition_of_unity}% \\end{equation}',
         'u = alpha - x, v = y, w = x - y, x in [0, alpha], y in [0, alpha - x]',
         'erratum',
         check='claim:independence_proof_steps',
         erratum={'id': 'parametrization-partition-of-unity-range',
                  'printed': 'u = alpha - x, v = y, w = x - y with x in [0, alpha], y in [0, alpha - x'
                             ']',
                  'corrected': 'y in [0, x] (v + w = x, so w = x - y >= 0 needs y <= x)',
                  'evidence': 'with the printed range, x = alpha/4, y = alpha/2 gives w = -alpha/4 < 0;'
                              ' with y in [0, x] the parameter triangle maps onto Omega^alpha (checked '
                              'exactly); only y = 0 is used downstream',
                  'severity': 'typo'}),
    Line('sec1_3-chain-rule',
         (555, 561),
         'chain_rule',
         'display',
         '\\begin{equation} \\frac{\\partial^{r}}{\\partial y^{r}}L\\left( u\\left( x,y\\right) ,v\\le'
         'ft( x,y\\right) ,w\\left( x,y\\right) \\right) =\\sum_{k=0}^{r}\\dbinom{r}{k}\\left( -1\\rig'
         'ht) ^{k}\\frac{\\partial^{r}}{\\partial v^{r-k}\\partial w^{k}}L\\left( u\\left( x,y\\right'
         ') ,v\\left( x,y\\right) ,w\\left( x,y\\right) \\right) . \\label{chain_rule}% \\end{equatio'
         'n}',
         'd^r/dy^r L = sum_k binom(r,k) (-1)^k d^r/dv^{r-k} dw^k L',
         'checked',
         check='sec1_3-chain-rule-pu'),
    Line('sec1_3-L-R-row',
         (566, 570),
         'chain_rule',
         'display',
         'L\\left( u,v,w\\right) & = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\'
         'displaystyle\\sum\\limits_{j=0}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_'
         '{2n,2n-i,j}R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L = rho_{2n,n,n} R_{2n,n,n} + sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} rho R',
         'checked',
         check='sec1_3-L-set'),
    Line('sec1_3-L-G-row',
         (571, 574),
         'linear_combination_union',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=0}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-'
         'j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) +%',
         '+ sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} gamma G',
         'checked',
         check='sec1_3-L-set'),
    Line('sec1_3-L-B-row',
         (575, 577),
         'linear_combination_union',
         'display',
         '{\\displaystyle\\sum\\limits_{j=0}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\be'
         'ta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right)',
         '+ sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} beta B',
         'checked',
         check='sec1_3-L-set'),
    Line('sec1_3-L-coefficients',
         (581, 583),
         'linear_combination_union',
         'index-set',
         'where $\\rho_{2n,n,n}$, $\\left\\{ \\rho_{2n,2n-i,j}\\right\\} _{j=0,i=j}% ^{n-1,2n-1-j}$,'
         ' $\\left\\{ \\gamma_{2n,2n-i,j}\\right\\} _{j=0,i=j}^{n-1,2n-1-j}$',
         'the constants rho_{2n,n,n}, {rho, gamma, beta}_{2n,2n-i,j}, j = 0..n-1, i = j..2n-1-'
         'j',
         'checked',
         check='sec1_3-L-set'),
    Line('sec1_3-L-prose',
         (584, 589),
         'linear_combination_union',
         'prose',
         'then, by the help of Proposition \\ref{derivative_cosine_sine}, one can easily determ'
         'ine those functions of system (\\ref{united_system}) the higher order mixed partial d'
         'erivatives ($\\frac{\\partial^{r}}{\\partial v^{r-k}\\partial w^{k}}\\left( \\cdot\\right) '
         '$, $k=0,1,\\ldots,r$) of which vanish when one evaluates the terms of (\\ref{chain_rul'
         'e}) at $y=0$. In the case of $n=4$, we have provided an example in Fig.\\ \\ref{fig:de'
         'rivative_scheme_n_4}.',
         'Proposition derivative_cosine_sine tells which mixed partials vanish at y = 0; examp'
         'le n = 4 in a figure',
         'excused',
         reason='pure prose'),
    Line('sec1_3-fig-n4-caption',
         (599, 619),
         'fig:derivative_scheme_n_4',
         'caption',
         '\\caption{(\\emph{a})--(\\emph{e}) Using the sign function (\\ref{derivative_cosine_sine'
         '_at_0}), one can easily verify that black and non-black dots represent those functio'
         'ns of system (\\ref{united_system}) the $4$th order mixed partial derivatives of whic'
         'h with respect to $v\\left( x,y\\right) =y$ and $w\\left( x,y\\right) =x-y$ are zero and'
         ' non-zero, respectively, under parametrization (\\ref{parametrization_for_partition_o'
         'f_unity}) at $y=0$. Observe, that the gray shaded areas correspond to functions whic'
         'h comprise the factor $\\sin \\frac{v\\left( x,y\\right) }{2}=\\sin\\frac{y}{2}$ raised to'
         ' a power greater than the corresponding order $k=0,1,\\ldots,4$ of the partial deriva'
         'tive with respect to $v\\left( x,y\\right) =y$. Thus, these partial derivatives vanish'
         ' at $y=0$ due to the first condition of the zero branch of the sign function (\\ref{d'
         'erivative_cosine_sine_at_0}). Black dots that fall outside of the gray shaded areas '
         'correspond to constrained trivariate functions that comprise the factor $\\sin\\frac{v'
         '\\left( x,y\\right) }{2}=\\sin\\frac{y}{2}$ raised to a power which -- together with the'
         ' order $k=0,1,\\ldots,4$ of the partial derivative with respect to $v\\left( x,y\\right'
         ') =y$, at $y=0$ -- fulfills the second condition of the zero branch of the sign func'
         'tion (\\ref{derivative_cosine_sine_at_0}). (For interpretation of the references to c'
         'olor in this figure legend, the reader is referred to the web version of this paper.'
         ')}%',
         'n = 4, 4th-order mixed partials in v, w at y = 0: gray = sin(v/2) power above the or'
         'der in v (first zero condition); other black dots: second zero condition',
         'checked',
         check='sec1_3-fig-n4-caption',
         reason='second reading: the caption calls the order of the derivative in v "k = 0, 1, ..., 4", while in '
                'eq. chain_rule k is the order in w and the order in v is r - k; both run over 0..4 here, so the '
                'statement holds (checked), but the letter k means two things -- a notation slip, debatable'),
    Line('sec1_3-theorem',
         (626, 628),
         'joint_systems_linear_independence',
         'inline',
         'The function system (\\ref{united_system}) is linearly independent and the dimension '
         'of the vector space $\\mathcal{T}_{2n}^{\\alpha}=~$\\emph{span}$\\emph{~}T_{2n}^{\\alpha}'
         '$ is',
         'T_{2n} is linearly independent; dim span T_{2n} = delta_n',
         'checked',
         check='sec1_3-independence-rank'),
    Line('sec1_3-theorem-delta',
         (630, 630),
         'joint_systems_linear_independence',
         'count',
         '\\delta_{n}=3n\\left( n+1\\right) +1.',
         'delta_n = 3n(n+1)+1',
         'checked',
         check='sec1_3-delta-count'),
    Line('sec1_3-delta-sum',
         (636, 640),
         'linear_combination_union_null_equality',
         'count',
         'It is easy to verify that the number of functions in system (\\ref{united_system}) is'
         ' exactly% \\[ \\delta_{n}=1+3\\sum_{j=0}^{n-1}\\sum_{i=j}^{2n-1-j}1=1+3n\\left( n+1\\right'
         ') . \\]',
         'delta_n = 1 + 3 sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} 1 = 1 + 3n(n+1)',
         'checked',
         check='sec1_3-delta-count'),
    Line('sec1_3-null-assumption',
         (641, 646),
         'linear_combination_union_null_equality',
         'prose',
         'Consider the linear combination (\\ref{linear_combination_union}) and assume that the'
         ' equality% \\begin{equation} L\\left( u,v,w\\right) =0 \\label{linear_combination_union_'
         'null_equality}% \\end{equation} holds for all $\\left( u,v,w\\right) \\in\\Omega^{\\alpha}'
         '$.',
         'assume L = 0 on Omega^alpha',
         'excused',
         reason='the assumption of the proof by contradiction'),
    Line('sec1_3-param-1',
         (653, 662),
         'parametrization_1_y_0',
         'parametrization',
         '\\begin{equation} \\left\\{ \\begin{array} [c]{rcl}% u_{1}\\left( x,y\\right) & = & x,~x\\i'
         'n\\left[ 0,\\alpha\\right] ,\\\\ v_{1}\\left( x,y\\right) & = & y,~y\\in\\left[ 0,\\alpha-x\\ri'
         'ght] ,\\\\ w_{1}\\left( x,y\\right) & = & \\alpha-x-y, \\end{array} \\right. \\label{paramet'
         'rization_1_y_0}% \\end{equation}%',
         'u_1 = x, v_1 = y, w_1 = alpha - x - y, x in [0, alpha], y in [0, alpha-x]',
         'checked',
         check='sec1_3-param-1'),
    Line('sec1_3-param-2',
         (663, 672),
         'parametrization_2_x_0',
         'parametrization',
         '\\begin{equation} \\left\\{ \\begin{array} [c]{rcl}% u_{2}\\left( x,y\\right) & = & x,~x\\i'
         'n\\left[ 0,\\alpha\\right] ,\\\\ v_{2}\\left( x,y\\right) & = & \\alpha-x-y,\\\\ w_{2}\\left( x'
         ',y\\right) & = & y,~y\\in\\left[ 0,\\alpha-x\\right] , \\end{array} \\right. \\label{paramet'
         'rization_2_x_0}% \\end{equation}',
         'u_2 = x, v_2 = alpha - x - y, w_2 = y',
         'checked',
         check='sec1_3-param-2'),
    Line('sec1_3-param-3',
         (674, 683),
         'parametrization_3_y_0',
         'parametrization',
         '\\begin{equation} \\left\\{ \\begin{array} [c]{rcl}% u_{3}\\left( x,y\\right) & = & \\alpha'
         '-x-y,\\\\ v_{3}\\left( x,y\\right) & = & x,~x\\in\\left[ 0,\\alpha\\right] ,\\\\ w_{3}\\left( x'
         ',y\\right) & = & y,~y\\in\\left[ 0,\\alpha-x\\right] . \\end{array} \\right. \\label{paramet'
         'rization_3_y_0}% \\end{equation}',
         'u_3 = alpha - x - y, v_3 = x, w_3 = y',
         'checked',
         check='sec1_3-param-3'),
    Line('sec1_3-chain-1',
         (686, 691),
         'derivative_formula_parametrization_1',
         'display',
         '\\frac{\\partial^{r}}{\\partial y^{r}}L\\left( u_{1}\\left( x,y\\right) ,v_{1}\\left( x,y\\r'
         'ight) ,w_{1}\\left( x,y\\right) \\right) & =\\sum _{k=0}^{r}\\dbinom{r}{k}\\left( -1\\right'
         ') ^{k}\\frac{\\partial^{r}}{\\partial v_{1}^{r-k}\\partial w_{1}^{k}}L\\left( u_{1}\\left('
         ' x,y\\right) ,v_{1}\\left( x,y\\right) ,w_{1}\\left( x,y\\right) \\right) ,\\label{derivati'
         've_formula_parametrization_1}\\\\',
         'd^r/dy^r L(param 1) = sum_k binom(r,k)(-1)^k d^r/dv_1^{r-k} dw_1^k L',
         'checked',
         check='sec1_3-chain-rule-1'),
    Line('sec1_3-chain-2',
         (693, 698),
         'derivative_formula_parametrization_2',
         'display',
         '\\frac{\\partial^{r}}{\\partial x^{r}}L\\left( u_{2}\\left( x,y\\right) ,v_{2}\\left( x,y\\r'
         'ight) ,w_{2}\\left( x,y\\right) \\right) & =\\sum _{k=0}^{r}\\dbinom{r}{k}\\left( -1\\right'
         ') ^{k}\\frac{\\partial^{r}}{\\partial u_{2}^{r-k}\\partial v_{2}^{k}}L\\left( u_{2}\\left('
         ' x,y\\right) ,v_{2}\\left( x,y\\right) ,w_{2}\\left( x,y\\right) \\right) ,\\label{derivati'
         've_formula_parametrization_2}\\\\',
         'd^r/dx^r L(param 2) = sum_k binom(r,k)(-1)^k d^r/du_2^{r-k} dv_2^k L',
         'checked',
         check='sec1_3-chain-rule-2'),
    Line('sec1_3-chain-3',
         (700, 705),
         'derivative_formula_parametrization_3',
         'display',
         '\\frac{\\partial^{r}}{\\partial y^{r}}L\\left( u_{3}\\left( x,y\\right) ,v_{3}\\left( x,y\\r'
         'ight) ,w_{3}\\left( x,y\\right) \\right) & =\\sum _{k=0}^{r}\\dbinom{r}{k}\\left( -1\\right'
         ') ^{k}\\frac{\\partial^{r}}{\\partial w_{3}^{r-k}\\partial u_{3}^{k}}L\\left( u_{3}\\left('
         ' x,y\\right) ,v_{3}\\left( x,y\\right) ,w_{3}\\left( x,y\\right) \\right) \\label{derivativ'
         'e_formula_parametrization_3}%',
         'd^r/dy^r L(param 3) = sum_k binom(r,k)(-1)^k d^r/dw_3^{r-k} du_3^k L',
         'checked',
         check='sec1_3-chain-rule-3'),
    Line('sec1_3-chain-ranges',
         (707, 710),
         'derivative_formula_parametrization_3',
         'range',
         'for all $x\\in\\left[ 0,\\alpha\\right] $,$\\ y\\in\\left[ 0,\\alpha-x\\right] $ and order $r'
         '\\in% \\mathbb{N} $.',
         'for all x in [0, alpha], y in [0, alpha - x], r in N',
         'checked',
         check='sec1_3-param-ranges'),
    Line('sec1_3-induction-orders',
         (712, 713),
         'derivative_formula_parametrization_3',
         'range',
         'In order to prove the statement, we argue by mathematical induction on the derivatio'
         'n order $r=0,1,\\ldots,n$.',
         'induction on the derivation order r = 0..n',
         'erratum',
         check='sec1_3-induction-orders',
         erratum={'printed': 'we argue by mathematical induction on the derivation order r = 0, 1, ..., n',
                  'corrected': 'we argue by mathematical induction on the derivation order r = 0, 1, ..., n-1',
                  'evidence': 'the proof takes derivatives of the orders 0 (the three order-0 steps) and r+1 for '
                              'r = 0..n-2, i.e. 0..n-1: recomputed from exact derivatives, level j of T_{2n} is '
                              'removed by the order-j steps and after the order-(n-1) steps only the centre is '
                              'left, which the proof removes without a derivative (L_{n-1} = rho_{2n,n,n} '
                              'R_{2n,n,n} = 0 iff rho_{2n,n,n} = 0); the induction hypothesis is stated for '
                              'r = 0..n-1 (eq. induction_hypothesis_for_linear_independence) and proved from r to '
                              'r+1 for r = 0..n-2; no derivative of order n occurs (n = 1..6 checked)',
                  'severity': 'typo'}),
    Line('sec1_3-r0-p1-where',
         (715, 716),
         'derivative_formula_parametrization_3',
         'inline',
         'In the case of $r=0$ and parametrization (\\ref{parametrization_1_y_0}), observe that'
         ' at $y=0$ equality (\\ref{linear_combination_union_null_equality}) becomes%',
         'order 0, parametrization 1, at y = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-r0-p1-start',
         (718, 719),
         'derivative_formula_parametrization_3',
         'display',
         '0 & =\\left. L\\left( u_{1}\\left( x,y\\right) ,v_{1}\\left( x,y\\right) ,w_{1}\\left( x,y\\'
         'right) \\right) \\right\\vert _{y=0}\\\\',
         '0 = L(u_1, v_1, w_1)|_{y=0}',
         'excused',
         reason='the assumption L = 0 restricted to y = 0'),
    Line('sec1_3-r0-p1-terms',
         (720, 722),
         'derivative_formula_parametrization_3',
         'display',
         '& =\\sum_{i=0}^{2n-1}\\rho_{2n,2n-i,0}R_{2n,2n-i,0}^{\\alpha}\\left( x,0,\\alpha-x\\right)'
         ' +\\gamma_{2n,2n,0}G_{2n,2n,0}^{\\alpha}\\left( x,0,\\alpha-x\\right) \\\\',
         '= sum_{i=0}^{2n-1} rho_{2n,2n-i,0} R_{2n,2n-i,0}(x,0,alpha-x) + gamma_{2n,2n,0} G_{2'
         'n,2n,0}(x,0,alpha-x)',
         'checked',
         check='sec1_3-r0-p1-terms'),
    Line('sec1_3-r0-p1-sines',
         (723, 724),
         'derivative_formula_parametrization_3',
         'display',
         '& =\\sum_{i=0}^{2n-1}\\rho_{2n,2n-i,0}\\sin^{2n-i}\\frac{x}{2}\\sin^{i}% \\frac{\\alpha-x}{'
         '2}+\\gamma_{2n,2n-i,0}\\sin^{2n}\\frac{\\alpha-x}{2}\\\\',
         '= sum_{i=0}^{2n-1} rho sin^{2n-i}(x/2) sin^i((alpha-x)/2) + gamma_{2n,2n-i,0} sin^{2'
         'n}((alpha-x)/2)',
         'erratum',
         check='claim:independence_proof_steps',
         erratum={'id': 'independence-proof-gamma-index',
                  'printed': '... + gamma_{2n,2n-i,0} sin^{2n}((alpha - x)/2)   (outside the sum over '
                             'i)',
                  'corrected': '... + gamma_{2n,2n,0} sin^{2n}((alpha - x)/2)   (the line before has G_{'
                               '2n,2n,0}, and G_{2n,2n,0}(x, 0, alpha - x) = sin^{2n}((alpha - x)/2))',
                  'evidence': 'the term stands outside the sum, so i is unbound; the previous line and '
                              "the definition of rho'_{2n,0,0} = gamma_{2n,2n,0}/c_{2n,0} below name ga"
                              'mma_{2n,2n,0} (computed: G_{2n,2n,0} is the only G function not vanishin'
                              'g at v = 0)',
                  'severity': 'typo'}),
    Line('sec1_3-r0-p1-cform',
         (725, 726),
         'derivative_formula_parametrization_3',
         'display',
         '& =\\sum_{i=0}^{2n}\\rho_{2n,2n-i,0}^{\\prime}c_{2n,2n-i}^{\\alpha}\\sin ^{2n-i}\\frac{x}{'
         '2}\\sin^{i}\\frac{\\alpha-x}{2}\\\\',
         "= sum_{i=0}^{2n} rho'_{2n,2n-i,0} c_{2n,2n-i} sin^{2n-i}(x/2) sin^i((alpha-x)/2)",
         'checked',
         check='sec1_3-r0-p1-cform'),
    Line('sec1_3-r0-p1-aform',
         (727, 728),
         'derivative_formula_parametrization_3',
         'display',
         '& =\\sum_{i=0}^{2n}\\rho_{2n,2n-i,0}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left( x\\right) ,~\\fo'
         'rall x\\in\\left[ 0,\\alpha\\right] ,',
         "= sum_{i=0}^{2n} rho'_{2n,2n-i,0} A_{2n,2n-i}(x)",
         'checked',
         check='sec1_3-r0-p1-aform'),
    Line('sec1_3-r0-p1-rho-prime',
         (731, 740),
         'derivative_formula_parametrization_3',
         'definition',
         '\\[ \\rho_{2n,2n-i,0}^{\\prime}=\\left\\{ \\begin{array} [c]{rl}% \\dfrac{\\rho_{2n,2n-i,0}}'
         '{c_{2n,2n-i}^{\\alpha}}, & i=0,1,\\ldots,2n-1,\\\\ & \\\\ \\dfrac{\\gamma_{2n,2n,0}}{c_{2n,0'
         '}^{\\alpha}}, & i=2n \\end{array} \\right. \\]',
         "rho'_{2n,2n-i,0} = rho_{2n,2n-i,0}/c_{2n,2n-i} (i = 0..2n-1), gamma_{2n,2n,0}/c_{2n,"
         '0} (i = 2n)',
         'checked',
         check='sec1_3-r0-p1-cform'),
    Line('sec1_3-r0-p1-omitted',
         (741, 743),
         'linear_combination_union_reduced_null_equality_1',
         'inline',
         'all omitted functions include the factor $\\left. \\sin \\frac{v_{1}\\left( x,y\\right) }'
         '{2}\\right\\vert _{y=0}=\\left. \\sin\\frac{y}% {2}\\right\\vert _{y=0}=0$ raised to a powe'
         'r at least one',
         'all omitted functions contain sin(v_1/2) = sin(y/2) to a power >= 1',
         'checked',
         check='sec1_3-r0-p1-omitted'),
    Line('sec1_3-r0-p1-A-system',
         (743, 745),
         'linear_combination_union_reduced_null_equality_1',
         'index-set',
         'Since the function system $\\left\\{ A_{2n,2n-i}^{\\alpha}\\left( x\\right) :x\\in\\left[ 0'
         ',\\alpha\\right] \\right\\} _{i=0}^{2n}$ is linearly independent',
         '{A_{2n,2n-i}}_{i=0}^{2n} is linearly independent',
         'checked',
         check='sec1_3-A-independent'),
    Line('sec1_3-r0-p1-zero',
         (748, 748),
         'linear_combination_union_reduced_null_equality_1',
         'range',
         '\\rho_{2n,2n-i,0}^{\\prime}=0,~i=0,1,\\ldots,2n.',
         "rho'_{2n,2n-i,0} = 0, i = 0..2n",
         'checked',
         check='sec1_3-r0-p1-zero'),
    Line('sec1_3-Ltilde-row1',
         (756, 759),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n-i'
         ',j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L-tilde = rho_{2n,n,n} R_{2n,n,n} + sum_{j=1}^{n-1} sum_{i=j}^{2n-1-j} rho R',
         'checked',
         check='sec1_3-Ltilde-set'),
    Line('sec1_3-Ltilde-row2',
         (760, 765),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{i=1}^{2n-1}} \\gamma_{2n,2n-i,0}G_{2n,2n-i,0}^{\\alp'
         'ha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limits_{j=1}^{n-1}} {\\displaystyle\\sum\\'
         'limits_{i=j}^{2n-1-j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\'
         '\\',
         '+ sum_{i=1}^{2n-1} gamma_{2n,2n-i,0} G + sum_{j=1}^{n-1} sum gamma G',
         'checked',
         check='sec1_3-Ltilde-set'),
    Line('sec1_3-Ltilde-row3',
         (766, 770),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=0}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-'
         'j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,~\\forall\\left( u,v,w'
         '\\right) \\in\\Omega^{\\alpha}.',
         '+ sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} beta B',
         'checked',
         check='sec1_3-Ltilde-set'),
    Line('sec1_3-r0-p2-where',
         (775, 778),
         'linear_combination_union_reduced_null_equality_1',
         'inline',
         'Now, considering parametrization (\\ref{parametrization_2_x_0}) and the partial deriv'
         'ative of order $r=0$ of equality (\\ref{linear_combination_union_reduced_null_equalit'
         'y_1}) with respect to the variable $x$, at $x=0$, we obtain that%',
         'parametrization 2, order 0 in x, at x = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-r0-p2-start',
         (780, 781),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '0 & =\\left. \\widetilde{L}\\left( u_{2}\\left( x,y\\right) ,v_{2}\\left( x,y\\right) ,w_{2'
         '}\\left( x,y\\right) \\right) \\right\\vert _{x=0}\\\\',
         '0 = L-tilde(u_2, v_2, w_2)|_{x=0}',
         'excused',
         reason='L-tilde = 0 restricted to x = 0'),
    Line('sec1_3-r0-p2-terms',
         (782, 784),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '& =\\sum_{i=1}^{2n-1}\\gamma_{2n,2n-i,0}G_{2n,2n-i,0}^{\\alpha}\\left( 0,\\alpha-y,y\\righ'
         't) +\\beta_{2n,2n,0}B_{2n,2n,0}^{\\alpha}\\left( 0,\\alpha-y,y\\right) \\\\',
         '= sum_{i=1}^{2n-1} gamma G_{2n,2n-i,0}(0,alpha-y,y) + beta_{2n,2n,0} B_{2n,2n,0}(0,a'
         'lpha-y,y)',
         'checked',
         check='sec1_3-r0-p2-terms'),
    Line('sec1_3-r0-p2-aform',
         (785, 786),
         'linear_combination_union_reduced_null_equality_1',
         'display',
         '& =\\sum_{i=1}^{2n}\\gamma_{2n,2n-i,0}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left( y\\right) ,~\\'
         'forall y\\in\\left[ 0,\\alpha\\right] ,',
         "= sum_{i=1}^{2n} gamma'_{2n,2n-i,0} A_{2n,2n-i}(y)",
         'checked',
         check='sec1_3-r0-p2-aform'),
    Line('sec1_3-r0-p2-gamma-prime',
         (789, 798),
         'linear_combination_union_reduced_null_equality_1',
         'definition',
         '\\[ \\gamma_{2n,2n-i,0}^{\\prime}=\\left\\{ \\begin{array} [c]{rl}% \\dfrac{\\gamma_{2n,2n-i'
         ',0}}{c_{2n,2n-i}^{\\alpha}}, & i=1,2,\\ldots,2n-1,\\\\ & \\\\ \\dfrac{\\beta_{2n,2n,0}}{c_{2'
         'n,0}^{\\alpha}}, & i=2n \\end{array} \\right. \\]',
         "gamma'_{2n,2n-i,0} = gamma_{2n,2n-i,0}/c_{2n,2n-i} (i = 1..2n-1), beta_{2n,2n,0}/c_{"
         '2n,0} (i = 2n)',
         'checked',
         check='sec1_3-r0-p2-aform'),
    Line('sec1_3-r0-p2-omitted',
         (799, 801),
         'linear_combination_union_reduced_null_equality_1',
         'inline',
         'discarded functions include the factor $\\left. \\sin \\frac{u_{2}\\left( x,y\\right) }{2'
         '}\\right\\vert _{x=0}=\\left. \\sin\\frac{x}% {2}\\right\\vert _{x=0}=0$ raised to a power '
         'greater than or equal to one',
         'discarded functions contain sin(u_2/2) = sin(x/2) to a power >= 1',
         'checked',
         check='sec1_3-r0-p2-omitted'),
    Line('sec1_3-r0-p2-A-system',
         (802, 804),
         'linear_combination_union_reduced_null_equality_2',
         'index-set',
         'the univariate function system $\\left\\{ A_{2n,2n-i}^{\\alpha}\\left( y\\right) :y\\in\\le'
         'ft[ 0,\\alpha\\right] \\right\\} _{i=1}^{2n}$',
         '{A_{2n,2n-i}(y)}_{i=1}^{2n} is linearly independent',
         'checked',
         check='sec1_3-A-independent'),
    Line('sec1_3-r0-p2-zero',
         (806, 806),
         'linear_combination_union_reduced_null_equality_2',
         'range',
         '\\gamma_{2n,2n-i,0}^{\\prime}=0,~i=1,2,\\ldots,2n.',
         "gamma'_{2n,2n-i,0} = 0, i = 1..2n",
         'checked',
         check='sec1_3-r0-p2-zero'),
    Line('sec1_3-Lhat-row1',
         (815, 818),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n-i'
         ',j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L-hat = rho_{2n,n,n} R_{2n,n,n} + sum_{j=1}^{n-1} sum rho R',
         'checked',
         check='sec1_3-Lhat-set'),
    Line('sec1_3-Lhat-row2',
         (819, 822),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-'
         'j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         '+ sum_{j=1}^{n-1} sum gamma G',
         'checked',
         check='sec1_3-Lhat-set'),
    Line('sec1_3-Lhat-row3',
         (823, 828),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{i=1}^{2n-1}} \\beta_{2n,2n-i,0}B_{2n,2n-i,0}^{\\alph'
         'a}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limits_{j=1}^{n-1}} {\\displaystyle\\sum\\l'
         'imits_{i=j}^{2n-1-j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,~\\'
         'forall\\left(',
         '+ sum_{i=1}^{2n-1} beta_{2n,2n-i,0} B + sum_{j=1}^{n-1} sum beta B',
         'checked',
         check='sec1_3-Lhat-set'),
    Line('sec1_3-r0-p3-where',
         (833, 836),
         'linear_combination_union_reduced_null_equality_2',
         'inline',
         'Performing similar calculations as above, but using parametrization (\\ref{parametriz'
         'ation_3_y_0}) and the zeroth order partial derivative of equality (\\ref{linear_combi'
         'nation_union_reduced_null_equality_2}) with respect to $y$, at $y=0$, we obtain that'
         '%',
         'parametrization 3, order 0 in y, at y = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-r0-p3-start',
         (838, 839),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '0 & =\\left. \\widehat{L}\\left( u_{3}\\left( x,y\\right) ,v_{3}\\left( x,y\\right) ,w_{3}\\'
         'left( x,y\\right) \\right) \\right\\vert _{y=0}\\\\',
         '0 = L-hat(u_3, v_3, w_3)|_{y=0}',
         'excused',
         reason='L-hat = 0 restricted to y = 0'),
    Line('sec1_3-r0-p3-terms',
         (840, 841),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '& =\\sum_{i=1}^{2n-1}\\beta_{2n,2n-i,0}B_{2n,2n-i,0}^{\\alpha}\\left( \\alpha-x,x,0\\right'
         ') \\\\',
         '= sum_{i=1}^{2n-1} beta_{2n,2n-i,0} B_{2n,2n-i,0}(alpha-x,x,0)',
         'checked',
         check='sec1_3-r0-p3-terms'),
    Line('sec1_3-r0-p3-aform',
         (842, 843),
         'linear_combination_union_reduced_null_equality_2',
         'display',
         '& =\\sum_{i=1}^{2n-1}\\beta_{2n,2n-i,0}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left( x\\right) ,~'
         '\\forall x\\in\\left[ 0,\\alpha\\right] ,',
         "= sum_{i=1}^{2n-1} beta'_{2n,2n-i,0} A_{2n,2n-i}(x)",
         'checked',
         check='sec1_3-r0-p3-aform'),
    Line('sec1_3-r0-p3-beta-prime',
         (846, 849),
         'linear_combination_union_reduced_null_equality_3',
         'definition',
         '\\[ \\beta_{2n,2n-i,0}^{\\prime}=\\frac{\\beta_{2n,2n-i,0}}{c_{2n,2n-i}^{\\alpha}% },~i=1,'
         '2,\\ldots,2n-1, \\]',
         "beta'_{2n,2n-i,0} = beta_{2n,2n-i,0}/c_{2n,2n-i}, i = 1..2n-1",
         'checked',
         check='sec1_3-r0-p3-aform'),
    Line('sec1_3-r0-p3-A-system',
         (850, 852),
         'linear_combination_union_reduced_null_equality_3',
         'index-set',
         'the function system $\\left\\{ A_{2n,2n-i}^{\\alpha}\\left( x\\right) :x\\in\\left[ 0\\,\\alp'
         'ha\\right] \\right\\} _{i=1}^{2n-1}$',
         '{A_{2n,2n-i}(x)}_{i=1}^{2n-1} is linearly independent',
         'checked',
         check='sec1_3-A-independent'),
    Line('sec1_3-r0-p3-interval',
         (851, 851),
         'linear_combination_union_reduced_null_equality_3',
         'inline',
         'x\\in\\left[ 0\\,\\alpha\\right]',
         'x in [0, alpha] (printed with a thin space instead of the comma)',
         'erratum',
         check='sec1_3-interval-typo',
         erratum={'printed': 'x in \\left[ 0\\,\\alpha\\right]  (typeset [0 alpha])',
                  'corrected': 'x in \\left[ 0,\\alpha\\right]',
                  'evidence': 'the printed interval has no comma between its endpoints (\\, is a thin sp'
                              "ace): it parses into the single item '0 \\alpha', the corrected one into "
                              'the endpoints 0 and alpha; every other interval of the proof is written '
                              '[0,\\alpha]',
                  'severity': 'typo'}),
    Line('sec1_3-r0-p3-zero',
         (854, 854),
         'linear_combination_union_reduced_null_equality_3',
         'range',
         '\\beta_{2n,2n-i,0}^{\\prime}=0,~i=1,2,\\ldots,2n-1.',
         "beta'_{2n,2n-i,0} = 0, i = 1..2n-1",
         'checked',
         check='sec1_3-r0-p3-zero'),
    Line('sec1_3-L0-row1',
         (861, 863),
         'linear_combination_union_reduced_null_equality_3',
         'display',
         '= & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +\\sum_{j=1}% ^{n-1}\\sum_{i=j'
         '}^{2n-1-j}\\rho_{2n,2n-i,j}R_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\nonumber\\\\',
         'L_0 = rho_{2n,n,n} R_{2n,n,n} + sum_{j=1}^{n-1} sum rho R',
         'checked',
         check='sec1_3-L0-set'),
    Line('sec1_3-L0-row2',
         (864, 867),
         'linear_combination_union_reduced_null_equality_3',
         'display',
         '& +\\sum_{j=1}^{n-1}\\sum_{i=j}^{2n-1-j}\\gamma_{2n,2n-i,j}G_{2n,2n-i,j}% ^{\\alpha}\\lef'
         't( u,v,w\\right) +\\sum_{j=1}^{n-1}\\sum_{i=j}^{2n-1-j}% \\beta_{2n,2n-i,j}B_{2n,2n-i,j}'
         '^{\\alpha}\\left( u,v,w\\right) ,~\\forall\\left( u,v,w\\right) \\in\\Omega^{\\alpha}.\\nonumb'
         'er',
         '+ sum_{j=1}^{n-1} sum gamma G + sum_{j=1}^{n-1} sum beta B',
         'checked',
         check='sec1_3-L0-set'),
    Line('sec1_3-fig-j0-text',
         (870, 877),
         'linear_combination_union_reduced_null_equality_3',
         'prose',
         'Cases (\\emph{a})--(\\emph{c}) of Fig.\\ \\ref{fig:linear_independence_j_0} represent ca'
         'lculations that correspond to the evaluation of the zeroth order partial derivatives'
         ' of equalities (\\ref{linear_combination_union_null_equality}), (\\ref{linear_combinat'
         'ion_union_reduced_null_equality_1}) and (\\ref{linear_combination_union_reduced_null_'
         'equality_2}) detailed above, under successive parametrizations (\\ref{parametrization'
         '_1_y_0}% )--(\\ref{parametrization_3_y_0}).%',
         'cases (a)-(c) of a figure show the order-0 steps',
         'excused',
         reason='the figure itself is missing from the source (captions only)'),
    Line('sec1_3-fig-j0-caption',
         (887, 907),
         'fig:linear_independence_j_0',
         'caption',
         '\\caption{Cases (\\emph{a}), (\\emph{b}) and (\\emph{c}) illustrate three consecutive st'
         'eps performed in order to gradually simplify equality (\\ref{linear_combination_union'
         '_null_equality}) to its final form (\\ref{linear_combination_union_reduced_null_equal'
         'ity_3}) via intermediate equalities (\\ref{linear_combination_union_reduced_null_equa'
         'lity_1}) and (\\ref{linear_combination_union_reduced_null_equality_2}). In each step,'
         ' black dots represent functions whose zeroth order partial derivatives vanish when o'
         'ne evaluates the zeroth order partial derivatives of equalities (\\ref{linear_combina'
         'tion_union_null_equality}), (\\ref{linear_combination_union_reduced_null_equality_1})'
         ' and (\\ref{linear_combination_union_reduced_null_equality_2}) under parametrizations'
         ' (\\ref{parametrization_1_y_0}), (\\ref{parametrization_2_x_0}) and (\\ref{parametrizat'
         'ion_3_y_0}) with respect to variables $y$, $x$ and $y$, at $y=0$, $x=0$ and $y=0$, r'
         'espectively. Red, green and blue colored dots represent functions the zeroth order p'
         'artial derivatives of which do not vanish under corresponding parametrizations and s'
         'ubstitutions with $0$. White dots correspond to functions the combining constants of'
         ' which proved to be $0$ in the previous steps. The gray shaded shrinking areas show '
         'all those functions which are present in the corresponding equalities. (For interpre'
         'tation of the references to color in this figure legend, the reader is referred to t'
         'he web version of this paper.)}%',
         'three steps: parametrizations 1, 2, 3 differentiated in y, x, y at y = 0, x = 0, y ='
         ' 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-induction-range',
         (912, 917),
         'fig:linear_independence_j_0',
         'range',
         'Now, we formulate and prove an induction hypothesis with respect to the $r$th order '
         '($r=0,1,\\ldots,n-1$) partial derivative of the initial equality (\\ref{linear_combina'
         'tion_union_null_equality}) under successive application of parametrizations (\\ref{pa'
         'rametrization_1_y_0}), (\\ref{parametrization_2_x_0}) and (\\ref{parametrization_3_y_0'
         '}) with respect to variables $y$, $x$ and $y$, at $y=0$, $x=0$ and $y=0$, respective'
         'ly.',
         'hypothesis for the order r = 0..n-1 under parametrizations 1, 2, 3 in y, x, y at y ='
         ' 0, x = 0, y = 0',
         'checked',
         check='sec1_3-elimination-orders'),
    Line('sec1_3-Lr-row1',
         (924, 927),
         'induction_hypothesis_for_linear_independence',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=r+1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n'
         '-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L_r = rho_{2n,n,n} R_{2n,n,n} + sum_{j=r+1}^{n-1} sum_{i=j}^{2n-1-j} rho R',
         'checked',
         check='sec1_3-Lr-set'),
    Line('sec1_3-Lr-row2',
         (928, 931),
         'induction_hypothesis_for_linear_independence',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         '+ sum_{j=r+1}^{n-1} sum gamma G',
         'checked',
         check='sec1_3-Lr-set'),
    Line('sec1_3-Lr-row3',
         (932, 936),
         'induction_hypothesis_for_linear_independence',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,\\forall\\left( u,v,'
         'w\\right) \\in\\Omega^{\\alpha}%',
         '+ sum_{j=r+1}^{n-1} sum beta B',
         'checked',
         check='sec1_3-Lr-set'),
    Line('sec1_3-Lr-orders',
         (940, 941),
         'induction_hypothesis_for_linear_independence',
         'range',
         'for all orders $r=0,1,\\ldots,n-1$, where the coefficients of all discarded functions'
         ' are equal to $0$.',
         'for all orders r = 0..n-1, the discarded constants being 0',
         'checked',
         check='sec1_3-Lr-set'),
    Line('sec1_3-step-range',
         (943, 945),
         'induction_hypothesis_for_linear_independence',
         'range',
         'Hereafter, we prove our hypothesis from $r$ to $r+1$ for all orders $r=0,1,\\ldots,n-'
         '2$, i.e., we show that equality (\\ref{induction_hypothesis_for_linear_independence})'
         ' can be reduced to',
         'the step from r to r+1 for r = 0..n-2',
         'checked',
         check='sec1_3-elimination-orders'),
    Line('sec1_3-Lr1-row1',
         (950, 953),
         'induction_hypothesis_nex_step',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n'
         '-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L_{r+1} = rho_{2n,n,n} R_{2n,n,n} + sum_{j=r+2}^{n-1} sum rho R',
         'checked',
         check='sec1_3-Lr1-set'),
    Line('sec1_3-Lr1-row2',
         (954, 957),
         'induction_hypothesis_nex_step',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         '+ sum_{j=r+2}^{n-1} sum gamma G',
         'checked',
         check='sec1_3-Lr1-set'),
    Line('sec1_3-Lr1-row3',
         (958, 962),
         'induction_hypothesis_nex_step',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,\\forall\\left( u,v,'
         'w\\right) \\in\\Omega^{\\alpha},',
         '+ sum_{j=r+2}^{n-1} sum beta B',
         'checked',
         check='sec1_3-Lr1-set'),
    Line('sec1_3-step-zeroed',
         (966, 971),
         'induction_hypothesis_nex_step',
         'index-set',
         'by evaluating its $\\left( r+1\\right) $th order partial derivatives under parametriza'
         'tions (\\ref{parametrization_1_y_0})--(\\ref{parametrization_3_y_0}) with proper subst'
         'itutions of $0$, where the combining constants $\\left\\{ \\rho_{2n,2n-i,r+1},\\gamma_{2'
         'n,2n-i,r+1},\\beta_{2n,2n-i,r+1}\\right\\} _{i=r+1}^{2n-1-\\left( r+1\\right) }$ of all t'
         'he omitted functions are equal to $0$.',
         'the constants {rho, gamma, beta}_{2n,2n-i,r+1}, i = r+1..2n-1-(r+1), are 0',
         'checked',
         check='sec1_3-level-zeroed'),
    Line('sec1_3-rp1-where',
         (973, 975),
         'induction_hypothesis_nex_step',
         'inline',
         'Using parametrization (\\ref{parametrization_1_y_0}) and the partial derivative formu'
         'la (\\ref{derivative_formula_parametrization_1}) with respect to $y$, at $y=0$ one ha'
         's that%',
         'parametrization 1 and its derivative formula in y at y = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-y-derivative-L-r',
         (982, 987),
         'y_derivative_L_r',
         'display',
         '& = & {\\displaystyle\\sum\\limits_{k=0}^{r+1}} \\dbinom{r+1}{k}\\left( -1\\right) ^{k}\\le'
         'ft. \\dfrac{\\partial^{r+1}}{\\partial v_{1}^{r+1-k}\\partial w_{1}^{k}}L_{r}\\left( u_{1'
         '}\\left( x,y\\right) ,v_{1}\\left( x,y\\right) ,w_{1}\\left( x,y\\right) \\right) \\right\\ve'
         'rt _{y=0},~\\forall x\\in\\left[ 0,\\alpha\\right] .',
         'd^{r+1}/dy^{r+1} L_r = sum_{k=0}^{r+1} binom(r+1,k)(-1)^k d^{r+1}/dv_1^{r+1-k} dw_1^'
         'k L_r at y = 0',
         'checked',
         check='sec1_3-chain-rule-1'),
    Line('sec1_3-kterm-centre',
         (999, 1002),
         'y_derivative_L_r',
         'display',
         '= & \\rho_{2n,n,n}\\left. \\sin^{n}\\frac{u_{1}\\left( x,y\\right) }% {2}\\right\\vert _{y=0'
         '}\\cdot S_{n,\\frac{1}{2}}^{r+1-k}\\left( 0\\right) \\cdot\\left. \\frac{\\text{d}^{k}}{\\tex'
         't{d}w_{1}^{k}}\\sin^{n}\\frac{w_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\\\',
         'k-th term, centre: rho_{2n,n,n} sin^n(u_1/2) S^{r+1-k}_{n,1/2}(0) d^k/dw^k sin^n(w_1'
         '/2)',
         'checked',
         check='sec1_3-kterm-p1-centre'),
    Line('sec1_3-kterm-R-low',
         (1004, 1008),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=j}^{n}\\rho_{2n,2n-i,j}\\left. \\sin^{2n-i}% \\frac{u_{1}\\l'
         'eft( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot\\left. \\frac{\\text{d}^{k}}{\\text{d}w_{1}^'
         '{k}}\\sin^{i}\\frac{w_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot M_{i-j,\\frac{1}'
         '{2},j,\\frac{1}{2}}^{r+1-k}\\left( 0\\right) \\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=j}^{n} rho sin^{2n-i}(u_1/2) d^k sin^i(w_1/2) M^{r+1-k}_{'
         'i-j,1/2,j,1/2}(0)',
         'checked',
         check='sec1_3-kterm-p1-R-low'),
    Line('sec1_3-kterm-R-high',
         (1009, 1013),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=n+1}^{2n-1-j}\\rho_{2n,2n-i,j}\\left. \\frac{\\text{d}^{k}}'
         '{\\text{d}w_{1}^{k}}\\sin^{i}\\frac{w_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot\\'
         'left. \\sin^{2n-i}\\frac{u_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot M_{2n-i-j,'
         '\\frac{1}{2},j,\\frac{1}{2}}% ^{r+1-k}\\left( 0\\right) \\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=n+1}^{2n-1-j} rho d^k sin^i(w_1/2) sin^{2n-i}(u_1/2) M^{r'
         '+1-k}_{2n-i-j,1/2,j,1/2}(0)',
         'checked',
         check='sec1_3-kterm-p1-R-high'),
    Line('sec1_3-kterm-G-low',
         (1015, 1019),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=j}^{n}\\gamma_{2n,2n-i,j}\\left. \\frac {\\text{d}^{k}}{\\te'
         'xt{d}w_{1}^{k}}\\sin^{2n-i}\\frac{w_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot S'
         '_{i,\\frac{1}{2}}^{r+1-k}\\left( 0\\right) \\cdot\\left. \\left( \\cos^{i-j}\\frac{u_{1}\\lef'
         't( x,y\\right) }{2}\\sin ^{j}\\frac{u_{1}\\left( x,y\\right) }{2}\\right) \\right\\vert _{y='
         '0}\\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=j}^{n} gamma d^k sin^{2n-i}(w_1/2) S^{r+1-k}_{i,1/2}(0) c'
         'os^{i-j}(u_1/2) sin^j(u_1/2)',
         'checked',
         check='sec1_3-kterm-p1-G-low'),
    Line('sec1_3-kterm-G-high',
         (1020, 1024),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=n+1}^{2n-1-j}\\gamma_{2n,2n-i,j}S_{i,\\frac{1}{2}% }^{r+1'
         '-k}\\left( 0\\right) \\cdot\\left. \\frac{\\text{d}^{k}}{\\text{d}w_{1}^{k}% }\\sin^{2n-i}\\f'
         'rac{w_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot\\left. \\left( \\cos^{2n-i-j}\\fr'
         'ac{u_{1}\\left( x,y\\right) }{2}\\sin^{j}\\frac {u_{1}\\left( x,y\\right) }{2}\\right) \\rig'
         'ht\\vert _{y=0}\\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=n+1}^{2n-1-j} gamma S^{r+1-k}_{i,1/2}(0) d^k sin^{2n-i}(w'
         '_1/2) cos^{2n-i-j}(u_1/2) sin^j(u_1/2)',
         'checked',
         check='sec1_3-kterm-p1-G-high'),
    Line('sec1_3-kterm-B-low',
         (1026, 1030),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=j}^{n}\\beta_{2n,2n-i,j}S_{2n-i,\\frac{1}{2}% }^{r+1-k}\\l'
         'eft( 0\\right) \\cdot\\left. \\sin^{i}\\frac{u_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0'
         '}\\cdot\\left. \\frac{\\text{d}^{k}}{\\text{d}w_{1}^{k}% }\\left( \\cos^{i-j}\\frac{w_{1}\\le'
         'ft( x,y\\right) }{2}\\sin^{j}\\frac {w_{1}\\left( x,y\\right) }{2}\\right) \\right\\vert _{y'
         '=0}\\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=j}^{n} beta S^{r+1-k}_{2n-i,1/2}(0) sin^i(u_1/2) d^k (cos'
         '^{i-j}(w_1/2) sin^j(w_1/2))',
         'checked',
         check='sec1_3-kterm-p1-B-low'),
    Line('sec1_3-kterm-B-high',
         (1031, 1035),
         'y_derivative_L_r',
         'display',
         '& +\\sum_{j=r+1}^{n-1}\\sum_{i=n+1}^{2n-1-j}\\beta_{2n,2n-i,j}\\left. \\sin ^{i}\\frac{u_{'
         '1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}\\cdot S_{2n-i,\\frac {1}{2}}^{r+1-k}\\left( '
         '0\\right) \\cdot\\left. \\frac{\\text{d}^{k}}% {\\text{d}w_{1}^{k}}\\left( \\cos^{2n-i-j}\\fr'
         'ac{w_{1}\\left( x,y\\right) }% {2}\\sin^{j}\\frac{w_{1}\\left( x,y\\right) }{2}\\right) \\ri'
         'ght\\vert _{y=0}\\\\',
         '+ sum_{j=r+1}^{n-1} sum_{i=n+1}^{2n-1-j} beta sin^i(u_1/2) S^{r+1-k}_{2n-i,1/2}(0) d'
         '^k (cos^{2n-i-j}(w_1/2) sin^j(w_1/2))',
         'checked',
         check='sec1_3-kterm-p1-B-high'),
    Line('sec1_3-footnote-tech-report',
         (991, 992),
         'y_derivative_L_r',
         'prose',
         'Observe that in case of the $k$th ($k=0,1,\\ldots,r+1$) term of the summation appeari'
         'ng in equality (\\ref{y_derivative_L_r}) we can successively write\\footnote{Technical'
         ' details can be found in \\cite{tech_report}. From hereon, a number in parenthesis ab'
         'ove the equality sign indicates that we apply the corresponding trigonometric identi'
         'ty.}%',
         'the steps of the k-th term are detailed in the technical report',
         'excused',
         reason='citation (technical report) and notation of the footnote.  Second reading: the footnote says a '
                'number above the equality sign names a trigonometric identity, but the numbers the proof puts '
                'there (lines sec1_3-rp1-k0, sec1_3-rp2-k0: sign_sin_power_derivative over '
                'derivative_cosine_sine_at_0) are the sign rules of the Lemma and the Proposition, not identities '
                '-- a wording slip, debatable, not an erratum (nothing computed depends on it)'),
    Line('sec1_3-rp1-k0',
         (1037, 1056),
         'y_derivative_L_r',
         'display',
         '\\underset{\\text{(\\ref{derivative_cosine_sine_at_0})}}{\\overset {\\text{(\\ref{sign_sin'
         '_power_derivative})}}{=}} & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}'
         '\\left( 0\\right) \\cdot\\left( {\\displaystyle\\sum\\limits_{i=r+1}^{n}} \\rho_{2n,2n-i,r+1'
         '}\\left. \\sin^{2n-i}\\dfrac{u_{1}\\left( x,y\\right) }% {2}\\right\\vert _{y=0}\\cdot\\left.'
         ' \\sin^{i}\\dfrac{w_{1}\\left( x,y\\right) }% {2}\\right\\vert _{y=0}\\right. & \\\\ & \\\\ +% '
         '{\\displaystyle\\sum\\limits_{i=n+1}^{2n-1-\\left( r+1\\right) }} \\rho_{2n,2n-i,r+1}\\left'
         '. \\sin^{i}\\dfrac{w_{1}\\left( x,y\\right) }% {2}\\right\\vert _{y=0}\\cdot\\left. \\sin^{2n'
         '-i}\\dfrac{u_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0} & \\\\ & \\\\ \\left. +\\gamma_{2n'
         ',2n-\\left( r+1\\right) ,r+1}\\left. \\sin^{2n-\\left( r+1\\right) }\\dfrac{w_{1}\\left( x,y'
         '\\right) }{2}\\right\\vert _{y=0}% \\cdot\\left. \\sin^{r+1}\\dfrac{u_{1}\\left( x,y\\right) '
         '}{2}\\right\\vert _{y=0}\\right) , & k=0\\\\',
         '= (k = 0) S^{r+1}_{r+1,1/2}(0) (sum_{i=r+1}^{n} rho sin^{2n-i}(u_1/2) sin^i(w_1/2) +'
         ' sum_{i=n+1}^{2n-1-(r+1)} rho ... + gamma_{2n,2n-(r+1),r+1} sin^{2n-(r+1)}(w_1/2) si'
         'n^{r+1}(u_1/2))',
         'checked',
         check='sec1_3-r-p1-k0'),
    Line('sec1_3-rp1-kpos',
         (1058, 1058),
         'y_derivative_L_r',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p1-kpos'),
    Line('sec1_3-rp1-k0-at-y0',
         (1062, 1075),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '= & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot\\le'
         'ft( {\\displaystyle\\sum\\limits_{i=r+1}^{n}} \\rho_{2n,2n-i,r+1}\\sin^{2n-i}\\dfrac{x}{2}'
         '\\sin^{i}\\dfrac{\\alpha-x}{2}\\right. & \\\\ & \\\\ +% {\\displaystyle\\sum\\limits_{i=n+1}^{2'
         'n-1-\\left( r+1\\right) }} \\rho_{2n,2n-i,r+1}\\sin^{i}\\dfrac{\\alpha-x}{2}\\sin^{2n-i}\\df'
         'rac{x}{2} & \\\\ & \\\\ \\left. +\\gamma_{2n,2n-\\left( r+1\\right) ,r+1}\\sin^{2n-\\left( r+1'
         '\\right) }\\dfrac{\\alpha-x}{2}\\sin^{r+1}\\dfrac{x}{2}\\right) , & k=0,\\\\',
         '= (k = 0) the same with u_1 = x, w_1 = alpha - x',
         'checked',
         check='sec1_3-r-p1-k0'),
    Line('sec1_3-rp1-kpos-at-y0',
         (1077, 1077),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p1-kpos'),
    Line('sec1_3-rp1-aform',
         (1081, 1086),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '= & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {'
         '\\displaystyle\\sum\\limits_{i=r+1}^{2n-1-\\left( r+1\\right) }} \\rho_{2n,2n-i,r+1}^{\\pri'
         'me}A_{2n,2n-i}^{\\alpha}\\left( x\\right) , & k=0,\\\\',
         "= (k = 0) S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-1-(r+1)} rho' A_{2n,2n-i}(x)",
         'erratum',
         check='sec1_3-r-p1-aform',
         erratum={'printed': "S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-1-(r+1)} rho'_{2n,2n-i,r+1} A_{2n,2"
                             'n-i}(x)',
                  'corrected': "S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-(r+1)} rho'_{2n,2n-i,r+1} A_{2n,2n-"
                               "i}(x)  (upper bound 2n-(r+1): the last term, defined by rho'_{2n,r+1,r+1"
                               '} = gamma_{2n,2n-(r+1),r+1}/c_{2n,2n-(r+1)}, carries the gamma term of t'
                               'he line before)',
                  'evidence': 'the exact (r+1)-th y-derivative at y = 0 of L_r contains gamma_{2n,2n-(r'
                              '+1),r+1} times S^{r+1}_{r+1}(0) A_{2n,r+1}(x)/c_{2n,r+1} (e.g. G_{4,3,1}'
                              ' for n = 2, r = 0); the printed bound drops it (60 of 60 cases n = 2..6,'
                              ' r = 0..n-2, 4 points each differ), the corrected bound matches all; the'
                              " definition of rho' and the conclusion rho' = 0 for i up to 2n-(r+1) bel"
                              'ow use the corrected range',
                  'severity': 'typo'}),
    Line('sec1_3-rp1-kpos-aform',
         (1088, 1088),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p1-kpos'),
    Line('sec1_3-rp1-rho-prime',
         (1094, 1105),
         'reduced_y_derivative_L_r_tilde',
         'definition',
         '\\[ \\rho_{2n,2n-i,r+1}^{\\prime}=\\left\\{ \\begin{array} [c]{rl}% \\dfrac{\\rho_{2n,2n-i,r'
         '+1}}{c_{2n,2n-i}^{\\alpha}}, & i=r+1,r+2,\\ldots ,2n-1-\\left( r+1\\right) ,\\\\ & \\\\ \\dfr'
         'ac{\\gamma_{2n,2n-\\left( r+1\\right) ,r+1}}{c_{2n,2n-\\left( r+1\\right) }^{\\alpha}}, & '
         'i=2n-\\left( r+1\\right) . \\end{array} \\right. \\]',
         "rho'_{2n,2n-i,r+1} = rho/c_{2n,2n-i} (i = r+1..2n-1-(r+1)), gamma_{2n,2n-(r+1),r+1}/"
         'c_{2n,2n-(r+1)} (i = 2n-(r+1))',
         'checked',
         check='sec1_3-r-p1-rho-prime'),
    Line('sec1_3-rp1-reduced',
         (1107, 1111),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '\\[ 0=S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {\\displaystyle\\sum\\limits_{i=r+'
         '1}^{2n-1-\\left( r+1\\right) }} \\rho_{2n,2n-i,r+1}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left( '
         'x\\right) ,~\\forall x\\in\\left[ 0,\\alpha\\right] ,',
         "0 = S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-1-(r+1)} rho' A_{2n,2n-i}(x)",
         'erratum',
         check='sec1_3-r-p1-aform',
         erratum={'printed': "0 = S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-1-(r+1)} rho'_{2n,2n-i,r+1} A_{"
                             '2n,2n-i}(x)',
                  'corrected': "0 = S^{r+1}_{r+1,1/2}(0) sum_{i=r+1}^{2n-(r+1)} rho'_{2n,2n-i,r+1} A_{2n"
                               ',2n-i}(x)',
                  'evidence': 'the exact (r+1)-th y-derivative at y = 0 of L_r contains gamma_{2n,2n-(r'
                              '+1),r+1} times S^{r+1}_{r+1}(0) A_{2n,r+1}(x)/c_{2n,r+1} (e.g. G_{4,3,1}'
                              ' for n = 2, r = 0); the printed bound drops it (60 of 60 cases n = 2..6,'
                              ' r = 0..n-2, 4 points each differ), the corrected bound matches all; the'
                              " definition of rho' and the conclusion rho' = 0 for i up to 2n-(r+1) bel"
                              'ow use the corrected range',
                  'severity': 'typo'}),
    Line('sec1_3-rp1-A-system',
         (1113, 1115),
         'reduced_y_derivative_L_r_tilde',
         'index-set',
         'the function system $\\left\\{ A_{2n,2n-i}^{\\alpha}\\left( x\\right) :x\\in\\left[ 0,\\alph'
         'a\\right] \\right\\} _{i=r+1}^{2n-1-\\left( r+1\\right) }$',
         '{A_{2n,2n-i}}_{i=r+1}^{2n-1-(r+1)} is linearly independent',
         'erratum',
         check='sec1_3-r-p1-asystem',
         erratum={'printed': 'linear independence of {A_{2n,2n-i}(x)}_{i=r+1}^{2n-1-(r+1)}',
                  'corrected': 'linear independence of {A_{2n,2n-i}(x)}_{i=r+1}^{2n-(r+1)}',
                  'evidence': 'the exact (r+1)-th y-derivative of L_r at y = 0 is a combination of A_{2'
                              'n,2n-i}, i = r+1..2n-(r+1) (computed for n = 2..6, r = 0..n-2: 15 of 15 '
                              'cases differ from the printed range, 0 from the corrected one); the conc'
                              'lusion on the next line is stated for i up to 2n-(r+1)',
                  'severity': 'typo'}),
    Line('sec1_3-rp1-zeroed',
         (1117, 1117),
         'reduced_y_derivative_L_r_tilde',
         'range',
         '\\rho_{2n,2n-i,n-1}^{\\prime}=0,~i=r+1,r+2,\\ldots,2n-\\left( r+1\\right) ,',
         "rho'_{2n,2n-i,n-1} = 0, i = r+1..2n-(r+1)",
         'erratum',
         check='sec1_3-r-p1-zeroed',
         erratum={'printed': "rho'_{2n,2n-i,n-1} = 0, i = r+1, r+2, ..., 2n-(r+1)",
                  'corrected': "rho'_{2n,2n-i,r+1} = 0, i = r+1, r+2, ..., 2n-(r+1)",
                  'evidence': "the step removes the level-(r+1) constants (rho' is defined for level r+"
                              '1 only), e.g. for n = 3, r = 0: rho_{6,5,1}, rho_{6,4,1}, rho_{6,3,1}, r'
                              'ho_{6,2,1}, gamma_{6,5,1}; the printed level n-1 names other (partly non'
                              '-existent) constants whenever r < n-2 (10 of 15 cases n = 2..6 differ; n'
                              ' = 2 and r = n-2 coincide); the corrected level matches all cases',
                  'severity': 'typo'}),
    Line('sec1_3-Ltilde-r-row1',
         (1125, 1128),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n'
         '-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L-tilde_r = rho_{2n,n,n} R_{2n,n,n} + sum_{j=r+2}^{n-1} sum rho R',
         'checked',
         check='sec1_3-Ltilde-r-set'),
    Line('sec1_3-Ltilde-r-row2',
         (1129, 1134),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{i=r+2}^{2n-1-\\left( r+1\\right) }} \\gamma_{2n,2n-i,'
         'r+1}G_{2n,2n-i,r+1}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limits_{j=r+2}'
         '^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\'
         'alpha}\\left( u,v,w\\right) \\\\',
         '+ sum_{i=r+2}^{2n-1-(r+1)} gamma_{2n,2n-i,r+1} G + sum_{j=r+2}^{n-1} sum gamma G',
         'checked',
         check='sec1_3-Ltilde-r-set'),
    Line('sec1_3-Ltilde-r-row3',
         (1135, 1139),
         'reduced_y_derivative_L_r_tilde',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+1}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,~\\forall\\left( u,v'
         ',w\\right) \\in\\Omega^{\\alpha}.',
         '+ sum_{j=r+1}^{n-1} sum beta B',
         'checked',
         check='sec1_3-Ltilde-r-set'),
    Line('sec1_3-rp2-where',
         (1144, 1146),
         'reduced_y_derivative_L_r_tilde',
         'inline',
         'Switching to parametrization (\\ref{parametrization_2_x_0}) and evaluating the $\\left'
         '( r+1\\right) $th order partial derivative of equality (\\ref{reduced_y_derivative_L_r'
         '_tilde}) with respect to $x$, at $x=0$, we have%',
         'parametrization 2, order r+1 in x, at x = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-x-derivative-L-tilde-r',
         (1153, 1158),
         'x_derivative_L_tilde_r',
         'display',
         '& = & {\\displaystyle\\sum\\limits_{k=0}^{r+1}} \\dbinom{r+1}{k}\\left( -1\\right) ^{k}\\le'
         'ft. \\dfrac{\\partial^{r+1}}{\\partial u_{2}^{r+1-k}\\partial v_{2}^{k}}\\widetilde{L}_{r'
         '}\\left( u_{2}\\left( x,y\\right) ,v_{2}\\left( x,y\\right) ,w_{2}\\left( x,y\\right) \\righ'
         't) \\right\\vert _{x=0},~\\forall y\\in\\left[ 0,\\alpha\\right] ,',
         'd^{r+1}/dx^{r+1} L-tilde_r = sum_k binom(r+1,k)(-1)^k d^{r+1}/du_2^{r+1-k} dv_2^k L-'
         'tilde_r at x = 0',
         'checked',
         check='sec1_3-chain-rule-2'),
    Line('sec1_3-footnote-1162',
         (1162, 1162),
         'x_derivative_L_tilde_r',
         'prose',
         'the $k$th term ($k=0,1,\\ldots,r+1$) of which can be expressed as\\footnote{Technical '
         'details can be found in \\cite{tech_report}.}%',
         'the k-th term, details in the technical report',
         'excused',
         reason='citation (technical report)'),
    Line('sec1_3-rp2-k0',
         (1168, 1187),
         'x_derivative_L_tilde_r',
         'display',
         '\\underset{\\text{(\\ref{derivative_cosine_sine_at_0})}}{\\overset {\\text{(\\ref{sign_sin'
         '_power_derivative})}}{=}} & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}'
         '\\left( 0\\right) \\cdot\\left( {\\displaystyle\\sum\\limits_{i=r+2}^{n}} \\gamma_{2n,2n-i,r'
         '+1}\\left. \\sin^{2n-i}\\dfrac{w_{2}\\left( x,y\\right) }% {2}\\right\\vert _{x=0}\\cdot\\lef'
         't. \\sin^{i}\\dfrac{v_{2}\\left( x,y\\right) }% {2}\\right\\vert _{x=0}\\right. & \\\\ & \\\\ +'
         '% {\\displaystyle\\sum\\limits_{i=n+1}^{2n-1-\\left( r+1\\right) }} \\gamma_{2n,2n-i,r+1}\\'
         'left. \\sin^{i}\\dfrac{v_{2}\\left( x,y\\right) }% {2}\\right\\vert _{x=0}\\cdot\\left. \\sin'
         '^{2n-i}\\dfrac{w_{2}\\left( x,y\\right) }{2}\\right\\vert _{x=0} & \\\\ & \\\\ \\left. +\\beta_'
         '{2n,2n-\\left( r+1\\right) ,r+1}\\left. \\sin^{2n-\\left( r+1\\right) }\\dfrac{v_{2}\\left( '
         'x,y\\right) }{2}\\right\\vert _{x=0}% \\cdot\\left. \\sin^{r+1}\\dfrac{w_{2}\\left( x,y\\righ'
         't) }{2}\\right\\vert _{x=0}\\right) , & k=0,\\\\',
         '(k = 0) S^{r+1}_{r+1,1/2}(0) (sum_{i=r+2}^{n} gamma sin^{2n-i}(w_2/2) sin^i(v_2/2) +'
         ' sum_{i=n+1}^{2n-1-(r+1)} gamma ... + beta_{2n,2n-(r+1),r+1} sin^{2n-(r+1)}(v_2/2) s'
         'in^{r+1}(w_2/2))',
         'checked',
         check='sec1_3-r-p2-k0'),
    Line('sec1_3-rp2-kpos',
         (1189, 1189),
         'x_derivative_L_tilde_r',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p2-kpos'),
    Line('sec1_3-rp2-aform',
         (1193, 1198),
         'x_derivative_L_tilde_r',
         'display',
         '= & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {'
         '\\displaystyle\\sum\\limits_{i=r+2}^{2n-\\left( r+1\\right) }} \\gamma_{2n,2n-i,r+1}^{\\pri'
         'me}A_{2n,2n-i}^{\\alpha}\\left( y\\right) , & k=0,\\\\',
         "= (k = 0) S^{r+1}_{r+1,1/2}(0) sum_{i=r+2}^{2n-(r+1)} gamma' A_{2n,2n-i}(y)",
         'checked',
         check='sec1_3-r-p2-aform'),
    Line('sec1_3-rp2-kpos-aform',
         (1200, 1200),
         'x_derivative_L_tilde_r',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p2-kpos'),
    Line('sec1_3-rp2-gamma-prime',
         (1206, 1217),
         'reduced_x_derivative_L_r_hat',
         'definition',
         '\\[ \\gamma_{2n,2n-i,r+1}^{\\prime}=\\left\\{ \\begin{array} [c]{rl}% \\dfrac{\\gamma_{2n,2n'
         '-i,r+1}}{c_{2n,2n-i}^{\\alpha}}, & i=r+2,r+3,\\ldots ,2n-1-\\left( r+1\\right) ,\\\\ & \\\\ '
         '\\dfrac{\\beta_{2n,2n-\\left( r+1\\right) ,r+1}}{c_{2n,2n-\\left( r+1\\right) }^{\\alpha}},'
         ' & i=2n-\\left( r+1\\right) . \\end{array} \\right. \\]',
         "gamma'_{2n,2n-i,r+1} = gamma/c_{2n,2n-i} (i = r+2..2n-1-(r+1)), beta_{2n,2n-(r+1),r+"
         '1}/c_{2n,2n-(r+1)} (i = 2n-(r+1))',
         'checked',
         check='sec1_3-r-p2-aform'),
    Line('sec1_3-rp2-reduced',
         (1220, 1224),
         'reduced_x_derivative_L_r_hat',
         'display',
         '\\[ 0=S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {\\displaystyle\\sum\\limits_{i=r+'
         '2}^{2n-\\left( r+1\\right) }} \\gamma_{2n,2n-i,r+1}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left( '
         'y\\right) ,~\\forall y\\in\\left[ 0,\\alpha\\right] .',
         "0 = S^{r+1}_{r+1,1/2}(0) sum_{i=r+2}^{2n-(r+1)} gamma' A_{2n,2n-i}(y)",
         'checked',
         check='sec1_3-r-p2-aform'),
    Line('sec1_3-rp2-A-system',
         (1226, 1228),
         'reduced_x_derivative_L_r_hat',
         'index-set',
         'Since functions $\\left\\{ A_{2n,2n-i}^{\\alpha}\\left( y\\right) :y\\in\\left[ 0,\\alpha\\ri'
         'ght] \\right\\} _{i=r+2}^{2n-\\left( r+1\\right) }$ are linearly independent',
         '{A_{2n,2n-i}(y)}_{i=r+2}^{2n-(r+1)} is linearly independent',
         'checked',
         check='sec1_3-r-p2-asystem'),
    Line('sec1_3-rp2-zeroed',
         (1230, 1230),
         'reduced_x_derivative_L_r_hat',
         'range',
         '\\gamma_{2n,2n-i,n-1}^{\\prime}=0,~i=r+2,r+3,\\ldots,2n-\\left( r+1\\right) ,',
         "gamma'_{2n,2n-i,n-1} = 0, i = r+2..2n-(r+1)",
         'erratum',
         check='sec1_3-r-p2-zeroed',
         erratum={'printed': "gamma'_{2n,2n-i,n-1} = 0, i = r+2, r+3, ..., 2n-(r+1)",
                  'corrected': "gamma'_{2n,2n-i,r+1} = 0, i = r+2, r+3, ..., 2n-(r+1)",
                  'evidence': "the step removes gamma' of level r+1 (gamma_{2n,2n-i,r+1}, i = r+2..2n-1"
                              '-(r+1), and beta_{2n,2n-(r+1),r+1}), e.g. for n = 3, r = 0: gamma_{6,4,1'
                              '}, gamma_{6,3,1}, gamma_{6,2,1}, beta_{6,5,1}; the printed level n-1 dif'
                              'fers whenever r < n-2 (10 of 15 cases n = 2..6); the corrected level mat'
                              "ches all; the same slip as rho'_{2n,2n-i,n-1} above",
                  'severity': 'typo'}),
    Line('sec1_3-Lhat-r-row1',
         (1238, 1241),
         'reduced_x_derivative_L_r_hat',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}} \\rho_{2n,2n-i,j}R_{2n,2n'
         '-i,j}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L-hat_r = rho_{2n,n,n} R_{2n,n,n} + sum_{j=r+2}^{n-1} sum rho R',
         'checked',
         check='sec1_3-Lhat-r-set'),
    Line('sec1_3-Lhat-r-row2',
         (1243, 1248),
         'reduced_x_derivative_L_r_hat',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\gamma_{2n,2n-i,j}G_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\'
         'sum\\limits_{i=r+2}^{2n-1-\\left( r+1\\right) }} \\beta_{2n,2n-i,r+1}B_{2n,2n-i,r+1}^{\\a'
         'lpha}\\left( u,v,w\\right) \\\\',
         '+ sum_{j=r+2}^{n-1} sum gamma G + sum_{i=r+2}^{2n-1-(r+1)} beta_{2n,2n-i,r+1} B',
         'checked',
         check='sec1_3-Lhat-r-set'),
    Line('sec1_3-Lhat-r-row3',
         (1250, 1253),
         'reduced_x_derivative_L_r_hat',
         'display',
         '& & +% {\\displaystyle\\sum\\limits_{j=r+2}^{n-1}} {\\displaystyle\\sum\\limits_{i=j}^{2n-'
         '1-j}} \\beta_{2n,2n-i,j}B_{2n,2n-i,j}^{\\alpha}\\left( u,v,w\\right) ,~\\forall\\left(',
         '+ sum_{j=r+2}^{n-1} sum beta B',
         'checked',
         check='sec1_3-Lhat-r-set'),
    Line('sec1_3-rp3-where',
         (1258, 1261),
         'reduced_x_derivative_L_r_hat',
         'inline',
         'Finally, we apply parametrization (\\ref{parametrization_3_y_0}) and evaluate the $\\l'
         'eft( r+1\\right) $th order partial derivative of equality (\\ref{reduced_x_derivative_'
         'L_r_hat}) with respect to $y$, at $y=0$. Using the derivative formula (\\ref{derivati'
         've_formula_parametrization_3}), we have that%',
         'parametrization 3, order r+1 in y, at y = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-y-derivative-L-hat',
         (1268, 1273),
         'y_derivative_L_hat_n_minus_2',
         'display',
         '& = & {\\displaystyle\\sum\\limits_{k=0}^{r+1}} \\dbinom{r+1}{k}\\left( -1\\right) ^{k}\\le'
         'ft. \\dfrac{\\partial^{r+1}}{\\partial w_{3}^{r+1-k}\\partial u_{3}^{k}}\\widehat{L}_{r}\\'
         'left( u_{3}\\left( x,y\\right) ,v_{3}\\left( x,y\\right) ,w_{3}\\left( x,y\\right) \\right)'
         ' \\right\\vert _{y=0},~\\forall x\\in\\left[ 0\\,,\\alpha\\right] ,',
         'd^{r+1}/dy^{r+1} L-hat_r = sum_k binom(r+1,k)(-1)^k d^{r+1}/dw_3^{r+1-k} du_3^k L-ha'
         't_r at y = 0',
         'checked',
         check='sec1_3-chain-rule-3'),
    Line('sec1_3-footnote-1277',
         (1277, 1277),
         'y_derivative_L_hat_n_minus_2',
         'prose',
         'where the $k$th term ($k=0,1,\\ldots,r+1$) takes the form\\footnote{Technical details '
         'can be found in \\cite{tech_report}.}%',
         'the k-th term, details in the technical report',
         'excused',
         reason='citation (technical report)'),
    Line('sec1_3-rp3-aform',
         (1283, 1288),
         'y_derivative_L_hat_n_minus_2',
         'display',
         '= & \\left\\{ \\begin{array} [c]{rl}% S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {'
         '\\displaystyle\\sum\\limits_{i=r+2}^{2n-1-\\left( r+1\\right) }} \\beta_{2n,2n-i,r+1}^{\\pr'
         'ime}A_{2n,2n-i}^{\\alpha}\\left( x\\right) , & k=0,\\\\',
         "(k = 0) S^{r+1}_{r+1,1/2}(0) sum_{i=r+2}^{2n-1-(r+1)} beta' A_{2n,2n-i}(x)",
         'checked',
         check='sec1_3-r-p3-aform'),
    Line('sec1_3-rp3-kpos',
         (1290, 1290),
         'y_derivative_L_hat_n_minus_2',
         'display',
         '0, & 1\\leq k\\leq r+1',
         '= 0 for 1 <= k <= r+1',
         'checked',
         check='sec1_3-r-p3-kpos'),
    Line('sec1_3-rp3-beta-prime',
         (1295, 1298),
         'y_derivative_L_hat_n_minus_2',
         'definition',
         '\\[ \\beta_{2n,2n-i,r+1}^{\\prime}=\\frac{\\beta_{2n,2n-i,r+1}}{c_{2n,2n-i}^{\\alpha}% },~'
         'i=r+2,r+3,\\ldots,2n-1-\\left( r+1\\right) . \\]',
         "beta'_{2n,2n-i,r+1} = beta/c_{2n,2n-i}, i = r+2..2n-1-(r+1)",
         'checked',
         check='sec1_3-r-p3-aform'),
    Line('sec1_3-rp3-reduced',
         (1300, 1305),
         'y_derivative_L_hat_n_minus_2',
         'display',
         '\\[ 0=S_{r+1,\\frac{1}{2}}^{r+1}\\left( 0\\right) \\cdot% {\\displaystyle\\sum\\limits_{i=r+'
         '2}^{2n-1-\\left( r+1\\right) }} \\beta_{2n,2n-i,r+1}^{\\prime}A_{2n,2n-i}^{\\alpha}\\left('
         ' x\\right) ,~\\forall x\\in\\left[ 0,\\alpha\\right] , \\]',
         "0 = S^{r+1}_{r+1,1/2}(0) sum_{i=r+2}^{2n-1-(r+1)} beta' A_{2n,2n-i}(x)",
         'checked',
         check='sec1_3-r-p3-aform'),
    Line('sec1_3-rp3-zeroed',
         (1308, 1308),
         'induction_hypothesis_for_linear_independence_n_minus_2',
         'range',
         '\\beta_{2n,2n-i,r+1}^{\\prime}=0,~i=r+2,r+3,\\ldots,2n-1-\\left( r+1\\right) .',
         "beta'_{2n,2n-i,r+1} = 0, i = r+2..2n-1-(r+1)",
         'checked',
         check='sec1_3-r-p3-zeroed'),
    Line('sec1_3-induction-conclusion',
         (1311, 1318),
         'induction_hypothesis_for_linear_independence_n_minus_2',
         'range',
         'Summarizing all calculations and zero constants obtained above, by evaluating the $\\'
         'left( r+1\\right) $th order ($r=0,1,\\ldots,n-2$) partial derivatives under successive'
         ' parametrizations (\\ref{parametrization_1_y_0}% )--(\\ref{parametrization_3_y_0}) of '
         'the initial equality (\\ref{induction_hypothesis_for_linear_independence}), we conclu'
         'de that equality (\\ref{induction_hypothesis_nex_step}) is also valid, i.e., the indu'
         'ction hypothesis (\\ref{induction_hypothesis_for_linear_independence}) is correct for'
         ' all orders $r=0,1,\\ldots,n-2$.',
         'the step holds for the orders r = 0..n-2',
         'checked',
         check='sec1_3-elimination-orders'),
    Line('sec1_3-Ln2-row1',
         (1325, 1327),
         'induction_hypothesis_for_linear_independence_n_minus_2',
         'display',
         '& = & \\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) +% {\\displaystyle\\sum\\limi'
         'ts_{i=n-1}^{n}} \\rho_{2n,2n-i,n-1}R_{2n,2n-i,n-1}^{\\alpha}\\left( u,v,w\\right) \\\\',
         'L_{n-2} = rho_{2n,n,n} R_{2n,n,n} + sum_{i=n-1}^{n} rho_{2n,2n-i,n-1} R',
         'checked',
         check='sec1_3-Ln2-set'),
    Line('sec1_3-Ln2-row2',
         (1329, 1330),
         'induction_hypothesis_for_linear_independence_n_minus_2',
         'display',
         '{\\displaystyle\\sum\\limits_{i=n-1}^{n}} \\gamma_{2n,2n-i,n-1}G_{2n,2n-i,n-1}^{\\alpha}\\'
         'left( u,v,w\\right) \\\\',
         '+ sum_{i=n-1}^{n} gamma_{2n,2n-i,n-1} G',
         'checked',
         check='sec1_3-Ln2-set'),
    Line('sec1_3-Ln2-row3',
         (1332, 1334),
         'induction_hypothesis_for_linear_independence_n_minus_2',
         'display',
         '{\\displaystyle\\sum\\limits_{i=n-1}^{n}} \\beta_{2n,2n-i,n-1}B_{2n,2n-i,n-1}^{\\alpha}\\l'
         'eft( u,v,w\\right) ,~\\forall\\left( u,v,w\\right) \\in\\Omega^{\\alpha}%',
         '+ sum_{i=n-1}^{n} beta_{2n,2n-i,n-1} B',
         'checked',
         check='sec1_3-Ln2-set'),
    Line('sec1_3-Ln1',
         (1339, 1343),
         'induction_hypothesis_for_linear_independence_n_minus_1',
         'display',
         '\\begin{equation} 0=L_{n-1}\\left( u,v,w\\right) =\\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left'
         '( u,v,w\\right) ,~\\forall\\left( u,v,w\\right) \\in\\Omega^{\\alpha}, \\label{induction_hyp'
         'othesis_for_linear_independence_n_minus_1}% \\end{equation}',
         '0 = L_{n-1} = rho_{2n,n,n} R_{2n,n,n}',
         'checked',
         check='sec1_3-Ln1-set'),
    Line('sec1_3-rho-centre-zero',
         (1345, 1350),
         'induction_hypothesis_for_linear_independence_n_minus_1',
         'inline',
         'Moreover, equality (\\ref{induction_hypothesis_for_linear_independence_n_minus_1}) ho'
         'lds if and only if% \\[ \\rho_{2n,n,n}=0, \\]',
         'L_{n-1} = 0 iff rho_{2n,n,n} = 0',
         'checked',
         check='sec1_3-Ln1-set'),
    Line('sec1_3-fig-j1-caption-orders',
         (1364, 1374),
         'fig:linear_independence_j_1__j_n_minus_1',
         'caption',
         'Cases (\\emph{a})--(\\emph{c}) and (\\emph{d})--(\\emph{f}) illustrate three consecutive'
         ' steps performed in order to gradually simplify equality (\\ref{induction_hypothesis_'
         'for_linear_independence}) to its final form (\\ref{induction_hypothesis_nex_step}) vi'
         'a intermediate equalities (\\ref{reduced_y_derivative_L_r_tilde}) and (\\ref{reduced_x'
         '_derivative_L_r_hat}% ) for $r=0$ and $r=n-2$, respectively. In each step of cases ('
         '\\emph{a}% )--(\\emph{c}) (resp. (\\emph{d})--(\\emph{f})), black dots represent functio'
         'ns whose first (resp. $\\left( n-1\\right) $th) order partial derivatives vanish when '
         'one evaluates the first (resp. $\\left( n-1\\right) $th) order partial derivatives of '
         'equalities',
         'cases (a)-(c): r = 0, first order; (d)-(f): r = n-2, (n-1)th order',
         'checked',
         check='sec1_3-elimination-orders'),
    Line('sec1_3-fig-j1-caption-params',
         (1374, 1378),
         'fig:linear_independence_j_1__j_n_minus_1',
         'caption',
         'under parametrizations (\\ref{parametrization_1_y_0}), (\\ref{parametrization_2_x_0}) '
         'and (\\ref{parametrization_3_y_0}) with respect to variables $y$, $x$ and $y$, at $y='
         '0$, $x=0$ and $y=0$',
         'parametrizations 1, 2, 3 in y, x, y at y = 0, x = 0, y = 0',
         'checked',
         check='sec1_3-boundary-vars'),
    Line('sec1_3-fig-j1-text',
         (1392, 1404),
         'fig:linear_independence_j_1__j_n_minus_1',
         'inline',
         'represent calculations that correspond to the evaluation of the first and $\\left( n-'
         '1\\right) $th order partial derivatives of equalities \\[ 0=L_{0}\\left( u,v,w\\right) ,'
         '~\\forall\\left( u,v,w\\right) \\in\\Omega^{\\alpha}% \\] and% \\[ 0=L_{n-2}\\left( u,v,w\\rig'
         'ht) ,~\\forall\\left( u,v,w\\right) \\in \\Omega^{\\alpha}% \\] under successive parametriz'
         'ations (\\ref{parametrization_1_y_0}% )--(\\ref{parametrization_3_y_0}), respectively.'
         '\\qedhere',
         'first and (n-1)th order derivatives of 0 = L_0 and 0 = L_{n-2}',
         'checked',
         check='sec1_3-elimination-orders'),
    Line('sec1_3-sec3-outro',
         (1407, 1412),
         'sec:coincidence',
         'prose',
         'Next we introduce an equivalence relation by means of which one can recursively cons'
         'truct the linearly independent function system $V_{n}^{\\alpha }$ that generates the '
         'constrained trivariate extension $\\mathcal{V}% _{n}^{\\alpha}$ ($n\\in% \\mathbb{N} $) '
         'of the vector space (\\ref{truncated_Fourier_vector_space}).',
         'next: the equivalence relation',
         'excused',
         reason='pure prose'),
]
