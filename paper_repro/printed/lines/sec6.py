"""Section 6 (sec:applications), source lines 2168-2666: every line that states something, verbatim.

Generated from the LaTeX source by copying each line range programmatically (never retyped).  Checks:
:mod:`paper_repro.claims.lines.sec6`.
"""

from __future__ import annotations

from paper_repro.printed.lines import Line

LINES = [
    Line(id='sec6-control-net-graph', tex=(2170, 2173),
         near='sec:applications', kind='prose',
         verbatim=('One can easily associate control nets with the oriented graph (that induced\nthe const'
                   'rained trivariate trigonometric function systems $\\overline{R}%\n_{2n}^{\\alpha}$, $'
                   '\\overline{G}_{2n}^{\\alpha}$ and $\\overline{B}_{2n}^{\\alpha}%\n$) as shown in Fig.'
                   '\\ \\ref{fig:associated_control_net}'),
         says=('Control nets can be associated with the oriented graph that induced the systems R, G, '
               'B (Fig. associated_control_net).'),
         status='excused',
         reason='prose pointing to a figure; the layout itself is counted by sec6-patch-index-sets'),
    Line(id='sec6-fig-layout-caption', tex=(2181, 2181),
         near='fig:associated_control_net', kind='caption',
         verbatim='\\caption{Layout of control points.}',
         says='Caption: layout of control points.',
         status='excused',
         reason='the figure is missing from the source; the caption states nothing checkable'),
    Line(id='sec6-remark-quad-faces', tex=(2187, 2187),
         near='fig:associated_control_net', kind='prose',
         verbatim=('Naturally, one may triangulate the quadrangular "faces" of the control net shown in Fi'
                   'g.\\ \\ref{fig:associated_control_net}. However, the reason for not doing so is that o'
                   'ur intention was to preserve the relations between constrained trivariate trigonometri'
                   'c functions induced by the oriented and multiplicatively weighted graph shown in Fig.'
                   '\\ \\ref{fig:oriented_graph}, i.e., in this way the edges of the control net have a we'
                   'll-defined meaning. Probably, a deeper understanding of the graph may lead to addition'
                   'al edges needed for a possible triangulation.'),
         says=("Remark: the quadrangular faces of the net are not triangulated to keep the edges' mean"
               'ing.'),
         status='excused',
         reason='design remark, nothing to compute'),
    Line(id='sec6-def-intro', tex=(2192, 2193),
         near='sec:triangular_trigonometric_patches', kind='prose',
         verbatim=('By means of linear combinations of control points and blending functions\n(\\ref{norma'
                   'lized_united_system}) one can define a new surface modeling tool.'),
         says=('Linear combinations of control points and the blending functions define a surface tool'
               '.'),
         status='excused',
         reason='prose'),
    Line(id='sec6-patch-row-1', tex=(2203, 2207),
         near='triangular_trig_surface', kind='display',
         verbatim=('\\mathbf{s}_{n}^{\\alpha}\\left(  u,v,w\\right)  & = & \\mathbf{r}_{2n,n,n}%\n\\overli'
                   'ne{R}_{2n,n,n}^{\\alpha}\\left(  u,v,w\\right)  +%\n{\\displaystyle\\sum\\limits_{j=0}'
                   '^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}}\n\\mathbf{r}_{2n,2n-i,j}\\overli'
                   'ne{R}_{2n,2n-i,j}^{\\alpha}\\left(  u,v,w\\right) \\\\'),
         says=('s_n^alpha = r_{2n,n,n} R-bar_{2n,n,n} + sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} r_{2n,2n-i,'
               'j} R-bar_{2n,2n-i,j}: the centre plus the R functions of levels 0..n-1.'),
         status='checked',
         check='sec6-patch-index-sets'),
    Line(id='sec6-patch-row-2', tex=(2208, 2214),
         near='triangular_trig_surface', kind='display',
         verbatim=('&  & +%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}'
                   '^{2n-1-j}}\n\\mathbf{g}_{2n,2n-i,j}\\overline{G}_{2n,2n-i,j}^{\\alpha}\\left(  u,v,w\\'
                   'right)  +%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i'
                   '=j}^{2n-1-j}}\n\\mathbf{b}_{2n,2n-i,j}\\overline{B}_{2n,2n-i,j}^{\\alpha}\\left(  u,v,'
                   'w\\right)'),
         says='+ the same double sums over the G and B functions (j = 0..n-1, i = j..2n-1-j).',
         status='checked',
         check='sec6-patch-index-sets'),
    Line(id='sec6-patch-order', tex=(2218, 2218),
         near='def:surface_patch', kind='range',
         verbatim='is called triangular trigonometric patch of order $n\\geq1$',
         says='The order is n >= 1.',
         status='checked',
         check='sec6-patch-index-sets'),
    Line(id='sec6-control-net-set', tex=(2220, 2222),
         near='def:surface_patch', kind='index-set',
         verbatim=('\\left\\{  \\mathbf{r}_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n,2n-1-j}\\cup\\left\\{\n\\m'
                   'athbf{g}_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}\\cup\\left\\{\n\\mathbf{b}_{2n'
                   ',2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}\\subset'),
         says=('The control net is {r_{2n,2n-i,j}}_{j=0,i=j}^{n,2n-1-j} U {g ...}_{j=0,i=j}^{n-1,2n-1-'
               'j} U {b ...}_{j=0,i=j}^{n-1,2n-1-j}.'),
         status='erratum',
         check='sec6-control-net-set',
         erratum={
             'printed': ('{r_{2n,2n-i,j}}_{j=0,i=j}^{n,2n-1-j} U {g_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j} U {b_{2n'
                          ',2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j}'),
             'corrected': ('{r_{2n,n,n}} U {r_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j} U {g_{2n,2n-i,j}}_{j=0,i=j}^{n-1'
                            ',2n-1-j} U {b_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j}'),
             'evidence': ('for j = n the range i = n..n-1 is empty, so the printed set has 3n(n+1) = delta_n - 1 '
                           'points (6, 18, 36 for n = 1, 2, 3) and lacks the centre r_{2n,n,n} that eq. triangular'
                           '_trig_surface multiplies by R-bar_{2n,n,n}; the corrected set has delta_n points and e'
                           'quals the labels of T_{2n} (united_system), n = 1..12'),
             'severity': 'typo',
         }),
    Line(id='sec6-delta3', tex=(2229, 2229),
         near='def:surface_patch', kind='count',
         verbatim=('Fig.\\ \\ref{fig:third_order_patch} illustrates a third order triangular trigonometric'
                   ' patch defined by $\\delta_{3}=37$ control points.'),
         says='A third order patch has delta_3 = 37 control points.',
         status='checked',
         check='sec6-delta3'),
    Line(id='sec6-fig-third-order-caption', tex=(2241, 2242),
         near='fig:third_order_patch', kind='caption',
         verbatim=('Different views of the same third order triangular trigonometric patch\nalong with its'
                   ' control net ($\\alpha=\\frac{\\pi}{2}$).'),
         says='Caption: views of a third order patch with its control net, alpha = pi/2.',
         status='excused',
         reason=('the figure (and its control net) is missing from the source; alpha = pi/2 lies in (0, '
                 'pi)')),
    Line(id='sec6-alpha-range', tex=(2251, 2251),
         near='fig:third_order_patch', kind='range',
         verbatim='has a global free shape parameter $\\alpha \\in \\left(0,\\pi\\right).$',
         says='The patch has a global shape parameter alpha in (0, pi).',
         status='checked',
         check='sec6-alpha-range'),
    Line(id='sec6-affine-invariance', tex=(2253, 2256),
         near='fig:third_order_patch', kind='inline',
         verbatim=('Since the basis (\\ref{normalized_united_system}) consists of\nfunctions that form a p'
                   'artition of the unity, any patch of the type\n(\\ref{triangular_trig_surface}) is inva'
                   'riant under the affine transformations\nof its control points.'),
         says='Partition of unity makes the patch invariant under affine maps of its control points.',
         status='checked',
         check='sec6-affine-invariance'),
    Line(id='sec6-convex-hull-n123', tex=(2256, 2256),
         near='fig:third_order_patch', kind='inline',
         verbatim=('Moreover, in the special cases of first, second and third order triangular trigonometr'
                   'ic patches we have already proved that their shape lies in the convex hull of their co'
                   'ntrol points, since in these cases the normalized function system (\\ref{normalized_un'
                   'ited_system}) is also non-negative.'),
         says='For n = 1, 2, 3 the normalized system is non-negative, hence the convex hull property.',
         status='checked',
         check='sec6-convex-hull-n123'),
    Line(id='sec6-convex-hull-open', tex=(2256, 2256),
         near='fig:third_order_patch', kind='prose',
         verbatim=('At the moment, the convex hull property of the patch (\\ref{triangular_trig_surface}) '
                   'of arbitrary order -- that is equivalent to the non-negativity of the normalizing coef'
                   'ficients of the basis (\\ref{united_system}) -- is an open problem.'),
         says=('For arbitrary order the convex hull property (equivalent to non-negative normalizing c'
               'oefficients) is open.'),
         status='excused',
         reason=('states an open problem; the non-negativity for sampled n and alpha is the subject of t'
                 'he nonnegativity claim')),
    Line(id='sec6-quadratic-growth', tex=(2256, 2256),
         near='fig:third_order_patch', kind='count',
         verbatim=('considering the quadratic growth of the control points, it is very unlikely that in CA'
                   'GD patches of order higher than three would be used for modeling.'),
         says='The number of control points grows quadratically in n.',
         status='checked',
         check='sec6-quadratic-growth'),
    Line(id='sec6-boundary-u0', tex=(2263, 2265),
         near='fig:third_order_patch', kind='display',
         verbatim=('\\mathbf{s}_{n}^{\\alpha}\\left(  0,\\alpha-w,w\\right)   &  =\\sum_{i=0}%\n^{2n}\\mat'
                   'hbf{g}_{2n,2n-i,0}A_{2n,2n-i}^{\\alpha}\\left(  w\\right)  ,~w\\in\\left[\n0,\\alpha\\'
                   'right]  ,\\\\'),
         says=('On u = 0: s(0, alpha-w, w) = sum_{i=0}^{2n} g_{2n,2n-i,0} A_{2n,2n-i}(w), w in [0, alp'
               'ha].'),
         status='erratum',
         check='sec6-boundary-u0',
         erratum={'id': 'boundary-curve-u0-corner-name',
                  'printed': ('s(0, alpha-w, w) = sum_{i=0}^{2n} g_{2n,2n-i,0} A_{2n,2n-i}(w): its i = 2n '
                              'term names g_{2n,0,0}'),
                  'corrected': ('s(0, alpha-w, w) = sum_{i=0}^{2n-1} g_{2n,2n-i,0} A_{2n,2n-i}(w) + '
                                'b_{2n,2n,0} A_{2n,0}(w)'),
                  'evidence': ('g_{2n,0,0} is not a control point: the net of def:surface_patch (and the sums '
                               'of eq. triangular_trig_surface) has g_{2n,2n-i,j} for i <= 2n-1-j only; the '
                               'function G_{2n,0,0} of the full system equals B_{2n,2n,0} = sin^{2n}(v/2), whose '
                               'control point is the corner b_{2n,2n,0}; with that name the curve equals the patch '
                               'on the edge u = 0 exactly (random rational nets, n = 1, 2, 3, tan(alpha/4) in '
                               '{1/3, 3/4}). The proof of Theorem joint_systems_linear_independence writes the '
                               'same i = 2n term with the other colour\'s corner (definitions of rho\', gamma\': '
                               'gamma_{2n,2n,0}, beta_{2n,2n,0})'),
                  'severity': 'typo'}),
    Line(id='sec6-boundary-v0', tex=(2266, 2268),
         near='fig:third_order_patch', kind='display',
         verbatim=('\\mathbf{s}_{n}^{\\alpha}\\left(  u,0,\\alpha-u\\right)   &  =\\sum_{i=0}%\n^{2n}\\mat'
                   'hbf{r}_{2n,2n-i,0}A_{2n,2n-i}^{\\alpha}\\left(  u\\right)  ,~u\\in\\left[\n0,\\alpha\\'
                   'right]  ,\\\\'),
         says=('On v = 0: s(u, 0, alpha-u) = sum_{i=0}^{2n} r_{2n,2n-i,0} A_{2n,2n-i}(u), u in [0, alp'
               'ha].'),
         status='erratum',
         check='sec6-boundary-v0',
         erratum={'id': 'boundary-curve-v0-corner-name',
                  'printed': ('s(u, 0, alpha-u) = sum_{i=0}^{2n} r_{2n,2n-i,0} A_{2n,2n-i}(u): its i = 2n '
                              'term names r_{2n,0,0}'),
                  'corrected': ('s(u, 0, alpha-u) = sum_{i=0}^{2n-1} r_{2n,2n-i,0} A_{2n,2n-i}(u) + '
                                'g_{2n,2n,0} A_{2n,0}(u)'),
                  'evidence': ('r_{2n,0,0} is not a control point: the net of def:surface_patch (and the sums '
                               'of eq. triangular_trig_surface) has r_{2n,2n-i,j} for i <= 2n-1-j only; the '
                               'function R_{2n,0,0} of the full system equals G_{2n,2n,0} = sin^{2n}(w/2), whose '
                               'control point is the corner g_{2n,2n,0}; with that name the curve equals the patch '
                               'on the edge v = 0 exactly (random rational nets, n = 1, 2, 3, tan(alpha/4) in '
                               '{1/3, 3/4}). The proof of Theorem joint_systems_linear_independence writes the '
                               'same i = 2n term with the other colour\'s corner (definitions of rho\', gamma\': '
                               'gamma_{2n,2n,0}, beta_{2n,2n,0})'),
                  'severity': 'typo'}),
    Line(id='sec6-boundary-w0', tex=(2269, 2271),
         near='fig:third_order_patch', kind='display',
         verbatim=('\\mathbf{s}_{n}^{\\alpha}\\left(  \\alpha-v,v,0\\right)   &  =\\sum_{i=0}%\n^{2n}\\mat'
                   'hbf{b}_{2n,2n-i,0}A_{2n,2n-i}^{\\alpha}\\left(  v\\right)  ,~v\\in\\left[\n0,\\alpha\\'
                   'right]  ,'),
         says=('On w = 0: s(alpha-v, v, 0) = sum_{i=0}^{2n} b_{2n,2n-i,0} A_{2n,2n-i}(v), v in [0, alp'
               'ha].'),
         status='erratum',
         check='sec6-boundary-w0',
         erratum={'id': 'boundary-curve-w0-corner-name',
                  'printed': ('s(alpha-v, v, 0) = sum_{i=0}^{2n} b_{2n,2n-i,0} A_{2n,2n-i}(v): its i = 2n '
                              'term names b_{2n,0,0}'),
                  'corrected': ('s(alpha-v, v, 0) = sum_{i=0}^{2n-1} b_{2n,2n-i,0} A_{2n,2n-i}(v) + '
                                'r_{2n,2n,0} A_{2n,0}(v)'),
                  'evidence': ('b_{2n,0,0} is not a control point: the net of def:surface_patch (and the sums '
                               'of eq. triangular_trig_surface) has b_{2n,2n-i,j} for i <= 2n-1-j only; the '
                               'function B_{2n,0,0} of the full system equals R_{2n,2n,0} = sin^{2n}(u/2), whose '
                               'control point is the corner r_{2n,2n,0}; with that name the curve equals the patch '
                               'on the edge w = 0 exactly (random rational nets, n = 1, 2, 3, tan(alpha/4) in '
                               '{1/3, 3/4}). The proof of Theorem joint_systems_linear_independence writes the '
                               'same i = 2n term with the other colour\'s corner (definitions of rho\', gamma\': '
                               'gamma_{2n,2n,0}, beta_{2n,2n,0})'),
                  'severity': 'typo'}),
    Line(id='sec6-corners', tex=(2273, 2275),
         near='fig:third_order_patch', kind='inline',
         verbatim=('interpolates the three\ncorners $\\mathbf{r}_{2n,2n,0}$, $\\mathbf{g}_{2n,2n,0}$ and $'
                   '\\mathbf{b}%\n_{2n,2n,0}$ of its control net'),
         says='The patch interpolates the corners r_{2n,2n,0}, g_{2n,2n,0}, b_{2n,2n,0}.',
         status='checked',
         check='sec6-corners'),
    Line(id='sec6-trig-curves', tex=(2275, 2277),
         near='fig:third_order_patch', kind='inline',
         verbatim=('its boundary curves can\nexactly describe arcs of any trigonometric parametric curve t'
                   'he coordinate\nfunctions of which are in the vector space (\\ref{truncated_Fourier_vec'
                   'tor_space}).'),
         says=('The boundary curves can describe exactly any arc whose coordinates lie in F_{2n}^alpha'
               '.'),
         status='checked',
         check='sec6-trig-curves'),
    Line(id='sec6-tangent-planes', tex=(2277, 2277),
         near='fig:third_order_patch', kind='inline',
         verbatim=('The tangent planes at these corners are spanned by the terminal edges of the control p'
                   'olygons that generate the boundary curves of the given patch.'),
         says=('The tangent plane at each corner is spanned by the terminal edges of the two boundary '
               'control polygons.'),
         status='checked',
         check='sec6-tangent-planes'),
    Line(id='sec6-bezier-limit', tex=(2277, 2277),
         near='fig:third_order_patch', kind='inline',
         verbatim=('Moreover, on account of Proposition \\ref{Bernstein}, when $\\alpha \\to 0$ the bounda'
                   "ry curves degenerate to B\\'ezier curves of degree $2n$."),
         says='As alpha -> 0 the boundary curves become Bezier curves of degree 2n.',
         status='checked',
         check='sec6-bezier-limit'),
    Line(id='sec6-vn-configurations', tex=(2279, 2282),
         near='fig:third_order_patch', kind='inline',
         verbatim=('It provides $\\alpha$-dependent control point configurations for the exact description'
                   ' of\ntriangular patches of arbitrary trigonometric surfaces the coordinate\nfunctions '
                   'of which are given in the vector space\n(\\ref{constrained_trivariate_extension_of_tru'
                   'ncated_Fourier_series}) (consider Example \\ref{exmp:torus}).'),
         says='Surfaces with coordinates in V_n^alpha have exact alpha-dependent control nets.',
         status='checked',
         check='sec6-vn-configurations'),
    Line(id='sec6-torus-parametrization', tex=(2289, 2295),
         near='toroidal_triangle', kind='parametrization',
         verbatim=('\\mathbf{t}_{\\varrho,\\mu}\\left(  u,v\\right)  =\\left[\n\\begin{array}\n[c]{ccc}%\n'
                   '\\left(  \\varrho+\\mu\\sin u\\right)  \\cos v & \\left(  \\varrho+\\mu\\sin u\\right)'
                   '\n\\sin v & \\mu\\cos u\n\\end{array}\n\\right]  ^{T},~u\\in\\left[  0,\\alpha\\right]'
                   '  ,~v\\in\\left[  0,\\alpha-u\\right]'),
         says=('t(u, v) = ((rho + mu sin u) cos v, (rho + mu sin u) sin v, mu cos u), u in [0, alpha],'
               ' v in [0, alpha - u].'),
         status='checked',
         check='sec6-torus-parametrization'),
    Line(id='sec6-torus-rho', tex=(2298, 2299),
         near='toroidal_triangle', kind='inline',
         verbatim=('where $\\varrho>0$ is the distance\nfrom the origin to the center of the meridian circ'
                   'le'),
         says=('varrho > 0 is the distance from the origin to the centre of the meridian circle (of ra'
               'dius mu).'),
         status='checked',
         check='sec6-torus-rho'),
    Line(id='sec6-torus-mu-range', tex=(2299, 2300),
         near='toroidal_triangle', kind='range',
         verbatim='of radius $\\mu\\in\\left(\n0,\\rho\\right]$',
         says='The meridian radius satisfies mu in (0, rho] (for a ring torus).',
         status='erratum',
         check='sec6-torus-mu-range',
         erratum={
             'printed': 'mu in (0, \\rho]  (ring torus)',
             'corrected': 'mu in (0, \\varrho)  (ring torus)',
             'evidence': ('the parametrization eq. toroidal_triangle has parameters \\varrho and \\mu; \\rho is n'
                           'ot one of them (it names the weights of Section 6.2); and at mu = varrho the surface i'
                           's a horn torus, not a ring torus: the meridian u = 3pi/2 meets the axis, t(3pi/2, v) ='
                           ' (0, 0, 0) for every v and the implicit equation (x^2+y^2+z^2+varrho^2-mu^2)^2 - 4 var'
                           'rho^2 (x^2+y^2) has zero gradient there (exact); for 0 < mu < varrho the distance to t'
                           'he axis is >= varrho - mu > 0 (no singular point)'),
             'severity': 'statement',
             'fix': [('\\rho\\right]', '\\varrho\\right)')],
         }),
    Line(id='sec6-torus-order2', tex=(2300, 2302),
         near='toroidal_triangle', kind='inline',
         verbatim=('The toroidal triangle\n(\\ref{toroidal_triangle}) can exactly be described by a second'
                   ' order triangular\ntrigonometric patch defined by control points'),
         says='The toroidal triangle is described exactly by a second order patch.',
         status='checked',
         check='sec6-torus-order2'),
    Line(id='sec6-torus-point-r_{4,4,0}', tex=(2305, 2312),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,4,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\mu\\sin\\alpha & 0 & \\mu\\cos\\alpha\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point r_{4,4,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,4,0}'),
    Line(id='sec6-torus-point-r_{4,3,0}', tex=(2314, 2322),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,3,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{\\mu}{2}\\left(  \\tan\\frac{\\alpha}{2}+\\sin\\alpha\\right)  & 0 &\n\\frac{\\'
                   'mu}{2}\\left(  1+\\cos\\alpha\\right)\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point r_{4,3,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,3,0}'),
    Line(id='sec6-torus-point-r_{4,2,0}', tex=(2324, 2332),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,2,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{3\\mu\\sin\\alpha}{4+2\\cos\\alpha} & 0 & \\frac{3\\mu\\left(\n1+\\cos\\alpha\\'
                   'right)  }{4+2\\cos\\alpha}%\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point r_{4,2,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,2,0}'),
    Line(id='sec6-torus-point-r_{4,1,0}', tex=(2334, 2341),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,1,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{\\mu}{2}\\tan\\frac{\\alpha}{2} & 0 & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point r_{4,1,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,1,0}'),
    Line(id='sec6-torus-point-r_{4,3,1}', tex=(2344, 2353),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,3,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{3\\mu\\sin\\alpha}{4+2\\cos\\alpha} & \\frac{3\\varrho\\sin\\alpha\n+\\mu\\left'
                   '(  3+\\cos\\alpha\\right)  \\left(  1-\\cos\\alpha\\right)  }{8+4\\cos\\alpha}\n& \\fr'
                   'ac{3\\mu\\left(  1+\\cos\\alpha\\right)  }{4+2\\cos\\alpha}%\n\\end{array}\n\\right]  '
                   '^{T}'),
         says=('Control point r_{4,3,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,3,1}'),
    Line(id='sec6-torus-point-r_{4,2,1}', tex=(2355, 2365),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,2,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{3\\mu\\left(  2+\\cos\\alpha\\right)  \\sin\\alpha}{\\left(\n1+\\cos\\alpha\\ri'
                   'ght)  \\left(  10+2\\cos\\alpha\\right)  } & \\frac{2\\varrho\\left(\n\\sin\\alpha+\\t'
                   'an\\frac{\\alpha}{2}\\right)  +3\\mu\\left(  1-\\cos\\alpha\\right)\n}{10+2\\cos\\alph'
                   'a} & \\frac{3\\mu\\left(  3+\\cos\\alpha\\right)  }{10+2\\cos\\alpha}%\n\\end{array}\n'
                   '\\right]  ^{T}'),
         says=('Control point r_{4,2,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,2,1}'),
    Line(id='sec6-torus-point-r_{4,2,2}', tex=(2368, 2378),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{r}_{4,2,2}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{6'
                   '\\varrho\\left(  3+2\\cos\\alpha\\right)  +\\mu\\left(  9+\\cos\\alpha\\right)\n\\sin'
                   '\\alpha}{20+10\\cos\\alpha} & \\frac{10\\varrho\\sin\\alpha+\\mu\\left(\n7+\\cos\\alph'
                   'a\\right)  \\left(  1-\\cos\\alpha\\right)  }{20+10\\cos\\alpha} &\n\\frac{3\\mu\\left'
                   '(  3+2\\cos\\alpha\\right)  }{10+5\\cos\\alpha}%\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point r_{4,2,2} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-r_{4,2,2}'),
    Line(id='sec6-torus-point-g_{4,4,0}', tex=(2381, 2388),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,4,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho '
                   '& 0 & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,4,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,4,0}'),
    Line(id='sec6-torus-point-g_{4,3,0}', tex=(2390, 2397),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,3,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho '
                   '& \\frac{\\varrho}{2}\\tan\\frac{\\alpha}{2} & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,3,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,3,0}'),
    Line(id='sec6-torus-point-g_{4,2,0}', tex=(2399, 2407),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,2,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{3'
                   '\\varrho\\left(  1+\\cos\\alpha\\right)  }{4+2\\cos\\alpha} & \\frac\n{3\\varrho\\sin'
                   '\\alpha}{4+2\\cos\\alpha} & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,2,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,2,0}'),
    Line(id='sec6-torus-point-g_{4,1,0}', tex=(2409, 2417),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,1,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{\\'
                   'varrho}{2}\\left(  1+\\cos\\alpha\\right)  & \\frac{\\varrho}{2}\\left(\n\\tan\\frac{'
                   '\\alpha}{2}+\\sin\\alpha\\right)  & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,1,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,1,0}'),
    Line(id='sec6-torus-point-g_{4,3,1}', tex=(2420, 2428),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,3,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{3\\mu\\sin\\alpha}{8+4\\cos\\alpha} & \\frac{3\\varrho\\sin\\alpha\n+2\\mu\\lef'
                   't(  1-\\cos\\alpha\\right)  }{8+4\\cos\\alpha} & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,3,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,3,1}'),
    Line(id='sec6-torus-point-g_{4,2,1}', tex=(2430, 2440),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{g}_{4,2,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{3'
                   '\\varrho\\left(  3+\\cos\\alpha\\right)  +3\\mu\\sin\\alpha}{10+2\\cos\\alpha} &\n\\fr'
                   'ac{3\\varrho\\left(  3\\sin\\frac{\\alpha}{2}+\\sin\\frac{3\\alpha}{2}\\right)\n+3\\mu'
                   '\\left(  \\cos\\frac{\\alpha}{2}-\\cos\\frac{3\\alpha}{2}\\right)  }{\\left(\n20+4\\co'
                   's\\alpha\\right)  \\cos\\frac{\\alpha}{2}} & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point g_{4,2,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-g_{4,2,1}'),
    Line(id='sec6-torus-point-b_{4,4,0}', tex=(2443, 2450),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,4,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho'
                   '\\cos\\alpha & \\varrho\\sin\\alpha & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point b_{4,4,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-b_{4,4,0}'),
    Line(id='sec6-torus-point-b_{4,3,0}', tex=(2452, 2461),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,3,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{\\'
                   'varrho}{2}\\left(  1+\\cos\\alpha\\right)  +\\frac{\\mu}{2}\\tan\\frac{\\alpha\n}{2}\\'
                   'cos\\alpha & \\frac{\\varrho}{2}\\left(  \\tan\\frac{\\alpha}{2}+\\sin\n\\alpha\\right'
                   ')  +\\frac{\\mu}{2}\\left(  1-\\cos\\alpha\\right)  & \\mu\n\\end{array}\n\\right]  ^{'
                   'T}'),
         says=('Control point b_{4,3,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-b_{4,3,0}'),
    Line(id='sec6-torus-point-b_{4,2,0}', tex=(2463, 2473),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,2,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{3'
                   '\\varrho\\left(  1+\\cos\\alpha\\right)  }{4+2\\cos\\alpha}+\\frac{\\mu}{2}%\n\\sin\\a'
                   'lpha & \\frac{3\\varrho\\sin\\alpha+\\mu\\left(  3+\\cos\\alpha\\right)  \\left(\n1-\\'
                   'cos\\alpha\\right)  }{4+2\\cos\\alpha} & \\frac{3\\mu\\left(  1+\\cos\\alpha\\right)\n'
                   '}{4+2\\cos\\alpha}%\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point b_{4,2,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-b_{4,2,0}'),
    Line(id='sec6-torus-point-b_{4,1,0}', tex=(2475, 2484),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,1,0}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\varrho+'
                   '\\frac{\\mu}{2}\\left(  \\tan\\frac{\\alpha}{2}+\\sin\\alpha\\right)  &\n\\frac{\\varr'
                   'ho}{2}\\tan\\frac{\\alpha}{2}+\\frac{\\mu}{2}\\left(  1-\\cos\\alpha\\right)\n& \\frac'
                   '{\\mu}{2}\\left(  1+\\cos\\alpha\\right)\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point b_{4,1,0} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-b_{4,1,0}'),
    Line(id='sec6-torus-point-b_{4,3,1}', tex=(2487, 2497),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,3,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{\\'
                   'varrho\\left(  7-2\\cos^{2}\\frac{\\alpha}{2}+\\cos\\frac{\\alpha}{2}\\right)\n\\cos^{'
                   '2}\\frac{\\alpha}{2}}{4+2\\cos\\alpha}+\\frac{\\mu}{4}\\sin\\alpha &\n\\frac{6\\varrho'
                   '\\sin\\alpha+\\mu\\left(  1-\\cos\\alpha\\right)  \\left(  3+\\cos\n\\alpha\\right)  }'
                   '{8+4\\cos\\alpha} & \\mu\n\\end{array}\n\\right]  ^{T}'),
         says=('Control point b_{4,3,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='erratum',
         check='claim:torus_exact',
         erratum={
             'id': 'torus-b_{4,3,1}-x',
             'item': 'b_{4,3,1}, x coordinate',
             'printed': 'rho (7 - 2 cos^2(a/2) + cos(a/2)) cos^2(a/2) / (4 + 2 cos a) + mu/4 sin a',
             'corrected': '3 rho (1 + cos a) / (4 + 2 cos a) + mu/4 sin a',
             'evidence': ('data/errata.json torus-{b_{4,3,1}}-x (claim torus_exact); the check sec6-torus-point-b'
                           '_{4,3,1} confirms it exactly: the x coordinate differs from the exact fit of eq. toroi'
                           'dal_triangle at every sampled rational-tangent alpha and rational (varrho, mu), y and '
                           'z agree, the corrected x agrees'),
             'severity': 'statement',
             'fix': [('\\frac{\\varrho\\left(  7-2\\cos^{2}\\frac{\\alpha}{2}+\\cos\\frac{\\alpha}{2}\\right)\n'
                      '\\cos^{2}\\frac{\\alpha}{2}}{4+2\\cos\\alpha}',
                      '\\frac{3\\varrho\\left(1+\\cos\\alpha\\right)}{4+2\\cos\\alpha}')],
         }),
    Line(id='sec6-torus-point-b_{4,2,1}', tex=(2499, 2511),
         near='exmp:torus', kind='display',
         verbatim=('\\mathbf{b}_{4,2,1}%\n\\normalcolor\n&  =\\left[\n\\begin{array}\n[c]{ccc}%\n\\frac{3'
                   '\\varrho\\left(  3+\\cos\\alpha\\right)  \\cos\\frac{\\alpha}{2}+\\mu\\left(\n3\\sin\\'
                   'frac{\\alpha}{2}+2\\sin\\frac{3\\alpha}{2}\\right)  }{\\left(  10+2\\cos\n\\alpha\\rig'
                   'ht)  \\cos\\frac{\\alpha}{2}} & \\frac{3\\varrho\\left(  3\\sin\\frac\n{\\alpha}{2}+\\'
                   'sin\\frac{3\\alpha}{2}\\right)  +4\\mu\\left(  \\cos\\frac{\\alpha}%\n{2}-\\cos\\frac{'
                   '3\\alpha}{2}\\right)  }{\\left(  20+4\\cos\\alpha\\right)  \\cos\n\\frac{\\alpha}{2}} '
                   '& \\frac{3\\mu\\left(  3+\\cos\\alpha\\right)  }{10+2\\cos\\alpha}%\n\\end{array}\n\\r'
                   'ight]  ^{T}'),
         says=('Control point b_{4,2,1} of the toroidal triangle (order 2), three coordinates in alpha'
               ', varrho, mu.'),
         status='checked',
         check='sec6-torus-point-b_{4,2,1}'),
    Line(id='sec6-torus-joined', tex=(2514, 2515),
         near='exmp:torus', kind='inline',
         verbatim=('Fig.\\ \\ref{fig:torus} illustrates several triangular trigonometric\npatches of order'
                   ' $2$ that are smoothly joined in order to form a part of a ring torus.'),
         says='Several order-2 patches join smoothly into a part of a ring torus.',
         status='checked',
         check='sec6-torus-joined',
         reason=('continuity computed by the check (issue 38): neighbouring pieces share their boundary control '
                 'polygons (C0) and have equal first derivatives in the phase parametrization (U, V) at the points '
                 'of the shared edges (exact): C1 in (U, V), hence G1 -- each piece is the exact restriction of the '
                 'one analytic parametrization')),
    Line(id='sec6-fig-torus-settings', tex=(2531, 2531),
         near='fig:torus', kind='caption',
         verbatim=('with settings $\\mu=3$, $\\rho = \\frac{1+\\sqrt{5}}{2}\\mu$ and $\\alpha=\\frac{\\pi}'
                   '{2}$.'),
         says=('The displayed net is that of the toroidal triangle with mu = 3, rho = (1+sqrt 5)/2 mu,'
               ' alpha = pi/2.'),
         status='erratum',
         check='sec6-fig-torus-settings',
         erratum={
             'printed': '\\mu = 3, \\rho = (1+sqrt 5)/2 \\mu, \\alpha = pi/2',
             'corrected': '\\mu = 3, \\varrho = (1+sqrt 5)/2 \\mu, \\alpha = pi/2',
             'evidence': ('\\rho is not a parameter of eq. toroidal_triangle (\\varrho, \\mu); read as \\varrho t'
                           'he settings give a ring torus (varrho/mu = (1+sqrt 5)/2 > 1: (varrho/mu)^2 = varrho/mu'
                           ' + 1 with varrho/mu > 1) and alpha = pi/2 in (0, pi)'),
             'severity': 'typo',
             'fix': [('$\\rho =', '$\\varrho =')],
         }),
    Line(id='sec6-fig-torus-prose', tex=(2531, 2531),
         near='fig:torus', kind='prose',
         verbatim=("A triangular part of a ring torus can also be described by polynomial rational B\\'ezi"
                   'er or B-spline triangles. In contrast to existing polynomial triangular patches, our t'
                   'rigonometric modeling tool does not require additional weights that have to be associa'
                   'ted with control points. Moreover, our approach can be used to exactly describe triang'
                   'ular parts of other non-rational trigonometric surfaces that can only be approximated '
                   'by means of classical (rational) polynomial patches.'),
         says='Comparison with rational Bezier/B-spline triangles; no weights needed.',
         status='excused',
         reason=('comparison with the literature; that no weights are needed is the torus net itself (se'
                 'c6-torus-point-*)')),
    Line(id='sec6-rational-intro', tex=(2536, 2538),
         near='fig:torus', kind='prose',
         verbatim=('The next subsection introduces the rational counterpart both of the basis\n(\\ref{norm'
                   'alized_united_system}) and triangular trigonometric patch\n(\\ref{triangular_trig_surf'
                   'ace}).'),
         says='Announces the rational counterpart.',
         status='excused',
         reason='prose'),
    Line(id='sec6-weights-set', tex=(2545, 2547),
         near='sec:triangular_rational_trigonometric_patches', kind='index-set',
         verbatim=('\\rho_{2n,n,n},\\left\\{  \\rho_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}%\n,\\le'
                   'ft\\{  \\gamma_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j},\\left\\{\n\\beta_{2n,2n'
                   '-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}%'),
         says=('Weights rho_{2n,n,n}, {rho_{2n,2n-i,j}}, {gamma_{2n,2n-i,j}}, {beta_{2n,2n-i,j}} with '
               'j = 0..n-1, i = j..2n-1-j: one per function of T_{2n}.'),
         status='checked',
         check='sec6-weights-set'),
    Line(id='sec6-weights-rank1', tex=(2551, 2553),
         near='sec:triangular_rational_trigonometric_patches', kind='display',
         verbatim=('\\rho_{2n,n,n}+\\sum_{j=0}^{n-1}\\sum_{i=j}^{2n-1-j}\\rho_{2n,2n-i,j}+\\sum\n_{j=0}^{n'
                   '-1}\\sum_{i=j}^{2n-1-j}\\gamma_{2n,2n-i,j}+\\sum_{j=0}^{n-1}\\sum\n_{i=j}^{2n-1-j}\\be'
                   'ta_{2n,2n-i,j}\\neq0,'),
         says=('Non-negative weights of rank 1, i.e. with non-zero sum, define rational patches (q_n^a'
               'lpha on all of Omega^alpha).'),
         status='erratum',
         check='sec6-weights-rank1',
         erratum={
             'printed': ('non-negative weights of rank 1, i.e. rho_{2n,n,n} + sum rho + sum gamma + sum beta != '
                          '0, define q_n^alpha : Omega^alpha -> R^3'),
             'corrected': ('non-negative weights with tau_n^alpha > 0 on Omega^alpha (e.g. all weights positive, n'
                            ' <= 3 where the basis is non-negative) define q_n^alpha : Omega^alpha -> R^3'),
             'evidence': ("the sum's index sets hold (delta_n terms); but non-zero sum does not keep the denomina"
                           'tor off zero: n = 2, alpha = 4 atan(1/3), weights rho_{4,n,n} = rho_{4,4,0} = 1, all o'
                           'thers 0: tau vanishes at the corner (0, alpha, 0) of Omega^alpha and the quotient has '
                           'different limits along the edges u = 0 and w = 0 there (exact), so q is not defined on'
                           ' all of Omega^alpha; with all weights positive tau >= min weight > 0 (n = 1, 2, 3, exa'
                           'ct at sampled points)'),
             'severity': 'statement',
         }),
    Line(id='sec6-rational-row-1', tex=(2566, 2572),
         near='rational_patch', kind='display',
         verbatim=('\\mathbf{q}_{n}^{\\alpha}\\left(  u,v,w\\right)  & = & \\rho_{2n,n,n}%\n\\mathbf{r}_{2'
                   'n,n,n}\\dfrac{\\overline{R}_{2n,n,n}^{\\alpha}\\left(  u,v,w\\right)\n}{\\overline{\\t'
                   'au}_{n}^{\\alpha}\\left(  u,v,w\\right)  }+%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}'
                   '}\n{\\displaystyle\\sum\\limits_{i=j}^{2n-1-j}}\n\\rho_{2n,2n-i,j}\\mathbf{r}_{2n,2n-i'
                   ',j}\\dfrac{\\overline{R}_{2n,2n-i,j}^{\\alpha\n}\\left(  u,v,w\\right)  }{\\overline{'
                   '\\tau}_{n}^{\\alpha}\\left(  u,v,w\\right)  }\\\\'),
         says=('q = rho_{2n,n,n} r_{2n,n,n} R-bar_{2n,n,n}/tau + sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} rh'
               'o r R-bar/tau.'),
         status='checked',
         check='sec6-rational-patch'),
    Line(id='sec6-rational-row-2', tex=(2573, 2578),
         near='rational_patch', kind='display',
         verbatim=('&  & +%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}'
                   '^{2n-1-j}}\n\\gamma_{2n,2n-i,j}\\mathbf{g}_{2n,2n-i,j}\\dfrac{\\overline{G}_{2n,2n-i,j'
                   '}%\n^{\\alpha}\\left(  u,v,w\\right)  }{\\overline{\\tau}_{n}^{\\alpha}\\left(\nu,v,w'
                   '\\right)  }\\\\'),
         says='+ sum gamma g G-bar/tau over the same index set.',
         status='checked',
         check='sec6-rational-patch'),
    Line(id='sec6-rational-row-3', tex=(2579, 2584),
         near='rational_patch', kind='display',
         verbatim=('&  & +%\n{\\displaystyle\\sum\\limits_{j=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{i=j}'
                   '^{2n-1-j}}\n\\beta_{2n,2n-i,j}\\mathbf{b}_{2n,2n-i,j}\\dfrac{\\overline{B}_{2n,2n-i,j}'
                   '%\n^{\\alpha}\\left(  u,v,w\\right)  }{\\overline{\\tau}_{n}^{\\alpha}\\left(\nu,v,w\\'
                   'right)  }%'),
         says='+ sum beta b B-bar/tau over the same index set.',
         status='checked',
         check='sec6-rational-patch'),
    Line(id='sec6-rational-order', tex=(2588, 2588),
         near='def:rational_patch', kind='range',
         verbatim='as rational triangular trigonometric patch of order $n\\geq1$',
         says='The order is n >= 1.',
         status='checked',
         check='sec6-rational-patch'),
    Line(id='sec6-rational-control-net-set', tex=(2590, 2592),
         near='def:rational_patch', kind='index-set',
         verbatim=('\\left\\{  \\mathbf{r}_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n,2n-1-j}\\cup\\left\\{\n\\m'
                   'athbf{g}_{2n,2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}\\cup\\left\\{\n\\mathbf{b}_{2n'
                   ',2n-i,j}\\right\\}  _{j=0,i=j}^{n-1,2n-1-j}\\subset'),
         says=('The control net of the rational patch: the same printed index sets as in def:surface_p'
               'atch.'),
         status='erratum',
         check='sec6-control-net-set',
         erratum={
             'printed': ('{r_{2n,2n-i,j}}_{j=0,i=j}^{n,2n-1-j} U {g_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j} U {b_{2n'
                          ',2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j}  (def:rational_patch)'),
             'corrected': ('{r_{2n,n,n}} U {r_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j} U {g_{2n,2n-i,j}}_{j=0,i=j}^{n-1'
                            ',2n-1-j} U {b_{2n,2n-i,j}}_{j=0,i=j}^{n-1,2n-1-j}'),
             'evidence': ('the same index sets as in def:surface_patch: for j = n the range i = n..n-1 is empty, '
                           'so the set has delta_n - 1 points and lacks r_{2n,n,n}, which eq. rational_patch uses '
                           '(rho_{2n,n,n} r_{2n,n,n} R-bar_{2n,n,n}/tau)'),
             'severity': 'typo',
         }),
    Line(id='sec6-tau-row-1', tex=(2600, 2604),
         near='def:rational_patch', kind='display',
         verbatim=('\\overline{\\tau}_{n}^{\\alpha}\\left(  u,v,w\\right)  & = & \\rho_{2n,n,n}%\n\\overli'
                   'ne{R}_{2n,n,n}^{\\alpha}\\left(  u,v,w\\right)  +%\n{\\displaystyle\\sum\\limits_{\\el'
                   'l=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{k=\\ell}^{2n-1-\\ell}}\n\\rho_{2n,2n-k,\\el'
                   'l}\\overline{R}_{2n,2n-k,\\ell}^{\\alpha}\\left(  u,v,w\\right) \\\\'),
         says=('tau = rho_{2n,n,n} R-bar_{2n,n,n} + sum_{l=0}^{n-1} sum_{k=l}^{2n-1-l} rho_{2n,2n-k,l}'
               ' R-bar_{2n,2n-k,l}.'),
         status='checked',
         check='sec6-tau-index-sets'),
    Line(id='sec6-tau-row-2', tex=(2605, 2612),
         near='def:rational_patch', kind='display',
         verbatim=('&  & +%\n{\\displaystyle\\sum\\limits_{\\ell=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{'
                   'k=\\ell}^{2n-1-\\ell}}\n\\gamma_{2n,2n-k,\\ell}\\overline{G}_{2n,2n-k,\\ell}^{\\alpha}'
                   '+%\n{\\displaystyle\\sum\\limits_{\\ell=0}^{n-1}}\n{\\displaystyle\\sum\\limits_{k=\\e'
                   'll}^{2n-1-\\ell}}\n\\beta_{2n,2n-k,\\ell}\\overline{B}_{2n,2n-k,\\ell}^{\\alpha}\\left'
                   '(  u,v,w\\right)\n.'),
         says=('+ sum gamma G-bar + sum beta B-bar over l = 0..n-1, k = l..2n-1-l (the G-bar term prin'
               'ts no arguments).'),
         status='erratum',
         check='sec6-tau-row-2',
         erratum={
             'id': 'tau-row-2-G-arguments',
             'printed': ('... + sum_{l=0}^{n-1} sum_{k=l}^{2n-1-l} gamma_{2n,2n-k,l} G-bar_{2n,2n-k,l}^alpha + ...  '
                         '(no argument)'),
             'corrected': ('... + sum_{l=0}^{n-1} sum_{k=l}^{2n-1-l} gamma_{2n,2n-k,l} G-bar_{2n,2n-k,l}^alpha(u,v,w) '
                           '+ ...'),
             'evidence': ('in the definition of tau-bar_n^alpha(u,v,w) (def:rational_patch) every other term -- '
                          'R-bar_{2n,n,n}, R-bar_{2n,2n-k,l}, B-bar_{2n,2n-k,l} -- and every term of eq. '
                          'rational_patch '
                          'is written as a function of (u,v,w); the G-bar term alone is printed without its argument, '
                          'so the right-hand side mixes functions and function symbols. The index sets of the row hold '
                          '(with row 1 they name T_{2n} once each, n = 1..12)'),
             'severity': 'typo',
             'fix': [('\\overline{G}_{2n,2n-k,\\ell}^{\\alpha}+', '\\overline{G}_{2n,2n-k,\\ell}^{\\alpha}'
                      '\\left(u,v,w\\right)+')],
         }),
    Line(id='sec6-q-normalized-independent', tex=(2615, 2619),
         near='def:rational_patch', kind='inline',
         verbatim=('Quotient functions in (\\ref{rational_patch}) determine the constrained\ntrivariate ra'
                   'tional trigonometric function system $\\overline{Q}_{2n}^{\\alpha}$\nof order $n$ that'
                   ' inherits advantageous properties of $\\overline{T}%\n_{2n}^{\\alpha}$, i.e., $\\overl'
                   'ine{Q}_{2n}^{\\alpha}$ is also\nnormalized and linearly independent.'),
         says=('The quotients form a system Q-bar_{2n}^alpha that is normalized and linearly independe'
               'nt.'),
         status='erratum',
         check='sec6-q-normalized-independent',
         erratum={
             'id': 'rational-system-zero-weight',
             'printed': ('Q-bar_{2n}^alpha (quotients of eq. rational_patch, with the non-negative weights of rank 1 '
                         'introduced above) is normalized and linearly independent'),
             'corrected': ('Q-bar_{2n}^alpha is normalized and linearly independent for positive weights (a zero '
                           'weight makes its quotient the zero function)'),
             'evidence': ('the weights are only required to be non-negative with a non-zero sum; with one weight 0 '
                          '(here rho_{2n,2n,0} = 0, the others positive) its quotient rho B-bar/tau is identically '
                          'zero, so the delta_n quotients have rank delta_n - 1 at delta_n rational points (exact, '
                          'n = 1, 2, 3): linearly dependent; with all weights positive they sum to 1 and have rank '
                          'delta_n (exact, n = 1, 2, 3)'),
             'severity': 'statement',
         }),
    Line(id='sec6-projective', tex=(2622, 2625),
         near='def:rational_patch', kind='inline',
         verbatim=('Patch (\\ref{rational_patch}) is closed for the projective\ntransformation of its cont'
                   'rol points, i.e., the patch determined by the\nprojectively transformed control points'
                   ' coincides with the pointwisely\ntransformed patch.'),
         says=('Projectively transforming the control points (weights adjusted) transforms the patch p'
               'ointwise.'),
         status='checked',
         check='sec6-projective',
         reason=('read as in rational Bezier theory: the control points are transformed as homogeneous points, so '
                 'each weight is multiplied by the homogeneous coordinate of its image (with the weights kept the '
                 'patch of the mapped points is not the mapped patch: exact counterexample in the tests); debatable '
                 'that the sentence leaves this implicit, and that a map sending a control point across the plane at '
                 'infinity makes a weight negative, outside the non-negative weights of Section 6.2')),
    Line(id='sec6-dupin-x', tex=(2629, 2633),
         near='Dupin_in_3d', kind='parametrization',
         verbatim=('\\frac{1}{a-c\\cos\\left(  u+\\varphi\\right)  \\cos\\left(  v+\\psi\\right)  }\\left['
                   '\n\\begin{array}\n[c]{l}%\n\\mu\\left(  c-a\\cos\\left(  u+\\varphi\\right)  \\cos\\le'
                   'ft(  v+\\psi\\right)\n\\right)  +b^{2}\\cos\\left(  u+\\varphi\\right) \\\\'),
         says=('x = (mu (c - a cos U cos V) + b^2 cos U) / (a - c cos U cos V), U = u + phi, V = v + p'
               'si.'),
         status='checked',
         check='sec6-dupin-surface'),
    Line(id='sec6-dupin-y', tex=(2634, 2635),
         near='Dupin_in_3d', kind='parametrization',
         verbatim=('\\left(  a-\\mu\\cos\\left(  v+\\psi\\right)  \\right)  b\\sin\\left(  u+\\varphi\\rig'
                   'ht)\n\\\\'),
         says='y = (a - mu cos V) b sin U / (a - c cos U cos V).',
         status='checked',
         check='sec6-dupin-surface'),
    Line(id='sec6-dupin-z', tex=(2636, 2639),
         near='Dupin_in_3d', kind='parametrization',
         verbatim=('\\left(  c\\cos\\left(  u+\\varphi\\right)  -\\mu\\right)  b\\sin\\left(\nv+\\psi\\rig'
                   'ht)\n\\end{array}\n\\right]  ,~u\\in\\left[  0,\\alpha\\right]  ,~v\\in\\left[  0,\\al'
                   'pha-u\\right]  ,'),
         says=('z = (c cos U - mu) b sin V / (a - c cos U cos V), u in [0, alpha], v in [0, alpha - u]'
               '.'),
         status='checked',
         check='sec6-dupin-surface'),
    Line(id='sec6-dupin-rational-patches', tex=(2642, 2642),
         near='Dupin_in_3d', kind='count',
         verbatim=('by means of sixteen smoothly joined second order rational triangular trigonometric pat'
                   'ches,'),
         says=('The ring Dupin cyclide is described exactly by sixteen smoothly joined second order ra'
               'tional patches.'),
         status='erratum',
         check='sec6-dupin-rational-patches',
         reason=('debatable: if Fig. dupin_03 shows only a part of the cyclide, "the ring Dupin cyclide" is loose '
                 'wording rather than a wrong count; the caption calls it a triangulization of a ring Dupin cyclide. '
                 'Continuity computed by the check (issue 38): the two rational patches of a phase square share '
                 'their diagonal control polygon and weights (C0) and have equal first derivatives in (U, V) there '
                 '(exact): C1 in (U, V), hence G1 ("smoothly joined" holds)'),
         erratum={
             'id': 'dupin-sixteen-patches',
             'printed': ('Fig. dupin_03 shows the exact description of the ring Dupin cyclide by sixteen second order '
                         'rational patches (alpha = pi/2, domain u in [0, alpha], v in [0, alpha - u])'),
             'corrected': ('thirty-two patches describe the whole ring Dupin cyclide at alpha = pi/2; sixteen describe '
                           'half of it'),
             'evidence': ('each patch is eq. Dupin_in_3d on a triangle u in [0, alpha], v in [0, alpha - u] of the '
                          'phase plane, of area alpha^2/2 = pi^2/8 at alpha = pi/2 (caption of Fig. dupin_03); the '
                          'cyclide is the image of the phase torus [0, 2pi] x [0, 2pi] of area 4 pi^2, one-to-one '
                          'for a '
                          'ring cyclide, so its triangulation by such patches needs 4 pi^2 / (pi^2/8) = 32 of them '
                          '(16 cover a part of area 2 pi^2); each of the 32 is an exact order-2 rational fit (exact, '
                          'tan(alpha/4) = 1/3 for the fits)'),
             'severity': 'statement',
             'fix': [('sixteen', 'thirty-two')],
         }),
    Line(id='sec6-dupin-conditions', tex=(2642, 2642),
         near='Dupin_in_3d', kind='range',
         verbatim=('where parameters $a$, $b$, $c$ and $\\mu$ have to fulfill the conditions $a^{2}=b^{2}+'
                   'c^{2}$ and $c<\\mu\\leq a$'),
         says='For a ring Dupin cyclide: a^2 = b^2 + c^2 and c < mu <= a.',
         status='erratum',
         check='sec6-dupin-conditions',
         erratum={
             'printed': 'a^2 = b^2 + c^2 and c < mu <= a  (ring Dupin cyclide)',
             'corrected': 'a^2 = b^2 + c^2 and c < mu < a  (ring Dupin cyclide; mu = a gives a horn cyclide)',
             'evidence': ('with a^2 = b^2 + c^2 the formula satisfies the cyclide quartic (x^2+y^2+z^2-mu^2+b^2)^'
                           '2 - 4(ax-c mu)^2 - 4b^2y^2 = 0 (exact); at mu = a the circle v + psi = 0 collapses to '
                           "the point (c, 0, 0) where the quartic's gradient vanishes (a singular point: horn cycl"
                           'ide; for c = 0 this is the horn torus), while for c < mu < a both factors a - mu cos V'
                           ' >= a - mu > 0 and mu - c cos U >= mu - c > 0 (no collapsed circle); the same non-stri'
                           'ct bound is common in the literature'),
             'severity': 'statement',
             'fix': [('c<\\mu\\leq a', 'c<\\mu<a')],
         }),
    Line(id='sec6-dupin-phases', tex=(2642, 2643),
         near='Dupin_in_3d', kind='range',
         verbatim=('while phase changes $\\left(  \\varphi,\\psi\\right)  \\in\\left[  0,2\\pi\\right]\\ti'
                   'mes\\left[  0,2\\pi\\right] $ are free design parameters that can be used to\nslide th'
                   'e patch on the cyclide.'),
         says='Phases (phi, psi) in [0, 2pi] x [0, 2pi] are free and slide the patch on the cyclide.',
         status='checked',
         check='sec6-dupin-phases'),
    Line(id='sec6-fig-dupin-settings', tex=(2656, 2658),
         near='fig:dupin_03', kind='caption',
         verbatim=('cyclide (with settings $a = 6$, $b=4\\sqrt{2}$, $c=2$ and $\\mu=3$) which is rendered '
                   'as a\ntransparent surface except the lower right figure. The shape parameter of each\n'
                   'second order rational triangular trigonometric patch is $\\alpha=\\frac{\\pi}{2}$.'),
         says='Caption: a = 6, b = 4 sqrt 2, c = 2, mu = 3, alpha = pi/2.',
         status='checked',
         check='sec6-fig-dupin-settings'),
    Line(id='sec6-fig-dupin-prose', tex=(2655, 2660),
         near='fig:dupin_03', kind='caption',
         verbatim=('\\caption{A possible control point based exact triangulization of a ring Dupin\ncyclid'
                   'e (with settings $a = 6$, $b=4\\sqrt{2}$, $c=2$ and $\\mu=3$) which is rendered as a\n'
                   'transparent surface except the lower right figure. The shape parameter of each\nsecond'
                   ' order rational triangular trigonometric patch is $\\alpha=\\frac{\\pi}{2}$. (For inte'
                   'rpretation\nof the references to color in this figure legend, the reader is referred t'
                   'o\nthe web version of this paper.)}'),
         says='Caption prose (rendering, colours).',
         status='excused',
         reason='rendering remarks of a missing figure'),
    Line(id='sec6-next-section', tex=(2665, 2665),
         near='fig:dupin_03', kind='prose',
         verbatim=('In the next section we list several open problems that we could not solve for the time'
                   ' being.'),
         says='Announces the open problems.',
         status='excused',
         reason='prose'),
]
