"""Checks of the lines of Sections sec:coincidence and sec:partition_of_unity (source lines 1414-2167).

Section sec:coincidence (lines 1414-1906): every check reads its lines at call time through
:func:`paper_repro.printed.lines.verbatim`, formulas by :mod:`paper_repro.printed.latex_math` (:func:`parse`,
:func:`chain`; prose by :func:`paper_repro.printed.latex_math.sentence` -- or, from :func:`dim_values` on, anchored
regular expressions -- that must match the whole sentence, so that a changed word, index, count or quantifier is
refused), and compares what it read with the computation below;
no formula of the section is retyped.  The printed formulas become exact trigonometric polynomials
(:func:`to_ep`, :func:`compile_ep`).

Independent machinery used here:

* :class:`EP` -- exact trigonometric polynomials written as sums of complex exponentials
  ``sum_f a_f exp(i f . x)`` with rational frequency vectors ``f`` and Gaussian-rational ``a_f``.  An identity
  between trigonometric expressions is proven by expanding both sides (a finite computation, no sampling).
* phase equivalence of integer triples: ``a ~ b`` iff ``a - b`` or ``a + b`` is a multiple of (1, 1, 1) (the
  meaning of Definition equivalence_relation_definition: cos/sin of the combinations differ by a phase z alpha on
  Omega^alpha), with the canonical class key :func:`class_key` -- no use of the printed z range.
* exact normalizing coefficients by collocation *without symmetry* (:func:`paper_repro.core.normalization.
  solve_full_exact`) or with it (:func:`paper_repro.core.normalization.coefficients`), univariate constants from
  the expansion of ``(X^2 + 2 c X Y + Y^2)^n`` (:func:`paper_repro.core.univariate.c_numerator_by_expansion`),
  exact ranks of collocation matrices (python-flint ``fmpq_mat``).
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache
from itertools import product
from math import comb

import sympy as sp
from flint import fmpq, fmpq_mat

from paper_repro.claims.lines import LineResult, items_result, line_check
from paper_repro.core.basis import evaluate
from paper_repro.core.context import ExactContext
from paper_repro.core.domain import rational_alpha, sample_rational_points
from paper_repro.core.fourier import cos_sin_combination, full_angles
from paper_repro.core.labels import exponents, r_exponents, united_system
from paper_repro.printed import latex_math as lm
from paper_repro.printed.latex_math import LatexMathError
from paper_repro.printed.lines import live_texts, verbatim
from paper_repro.printed.lines import sec4_5 as pl

Q = Fraction
PM = lm.PM  # the sign of \mp / \pm (latex_math's ``pm``): +1 for the upper sign, -1 for the lower one
ALPHA = sp.Symbol("alpha")
#: the section's subscripted letters, plain symbols here: ``r_{1}`` (latex_math's ``r(1)``) is ``r1``
_INDEXED = {"r", "g", "b", "k", "s"}


# ---------------------------------------------------------------------------------------------------------------
# reading: paper_repro.printed.latex_math, with the section's names
# ---------------------------------------------------------------------------------------------------------------
def section_names(e):
    """A parsed expression (:mod:`paper_repro.printed.latex_math`) in this section's names: ``r(1)`` -> ``r1`` (the
    section's subscripted letters r, g, b, k, s with one integer index are plain symbols),
    ``dim(Vcal(n))`` -> ``dim_V(n)``, ``dim(Tcal(2n))`` -> ``dim_T(2n)``."""
    from sympy.core.function import AppliedUndef

    def conv(f):
        name = f.func.__name__
        if name == "dim" and len(f.args) == 1 and isinstance(f.args[0], AppliedUndef) and \
                f.args[0].func.__name__ in ("Vcal", "Tcal") and len(f.args[0].args) == 1:
            return sp.Function(f"dim_{f.args[0].func.__name__[0]}")(f.args[0].args[0])
        if name in _INDEXED and len(f.args) == 1 and f.args[0].is_Integer:
            return sp.Symbol(f"{name}{f.args[0]}")
        return f

    return e.replace(lambda x: isinstance(x, AppliedUndef), conv)


def parse(tex: str):
    """One expression, by :func:`paper_repro.printed.latex_math.parse`, in the section's names
    (:func:`section_names`); :class:`LatexMathError` on anything unread.

    >>> parse(r"\\sin\\left( z\\mp r_{1}\\right) ")
    -sin(pm*r1 - z)
    """
    return section_names(lm.parse(tex))


def bound(expr, **env: int) -> int:
    """Integer value of a printed bound such as ``2n-1-j`` (read by :func:`parse`) with ``env`` bound;
    :class:`LatexMathError` if a name stays unbound or the value is not an integer.

    >>> bound("2n-1-j", n=3, j=1)
    4
    """
    names, f = _bound_fn(expr)
    if not set(names) <= set(env):
        raise LatexMathError(f"the bound {expr!r} names {sorted(set(names) - set(env))}, unbound")
    v = f(*(env[x] for x in names))
    if v != int(v):
        raise LatexMathError(f"the bound {expr!r} is not an integer at {env}: {v}")
    return int(v)


@cache
def _bound_fn(expr):
    e = parse(expr) if isinstance(expr, str) else sp.sympify(expr)  # a text, or a bound latex_math already read
    names = tuple(sorted(s.name for s in e.free_symbols))
    return names, sp.lambdify([sp.Symbol(x) for x in names], e, "math")


def chain(tex: str) -> list:
    """The parts of a chain ``a = b = c`` (a continued row ``= & ..`` too), by
    :func:`paper_repro.printed.latex_math.parse_relation`: every relation must be ``=`` and no clause may follow
    (:class:`LatexMathError` otherwise).

    >>> chain(r"\\dim\\mathcal{V}_{n}^{\\alpha}=\\dim\\mathcal{V}_{n-1}^{\\alpha}+6n")
    [dim_V(n), 6*n + dim_V(n - 1)]
    """
    r = lm.parse_relation(tex)
    if r.lead not in (None, "=") or any(op != "=" for op in r.ops) or r.conditions:
        raise LatexMathError(f"not a chain of '=': lead {r.lead}, {r.ops}, {len(r.conditions)} clauses")
    return [section_names(x) for x in r.parts]
TS = (fmpq(1, 3), fmpq(2, 5), fmpq(1, 7))  # tan(alpha/4) of the sampled alpha


# ---------------------------------------------------------------------------------------------------------------
# exact trigonometric polynomials
# ---------------------------------------------------------------------------------------------------------------
class EP:
    """``sum_f a_f exp(i f . x)``: ``terms`` maps a frequency tuple (Fractions) to ``(re, im)`` (Fractions)."""

    __slots__ = ("terms", "nv")

    def __init__(self, nv: int, terms: dict | None = None):
        self.nv = nv
        self.terms = {k: v for k, v in (terms or {}).items() if v != (0, 0)}

    @staticmethod
    def const(nv: int, x) -> EP:
        return EP(nv, {(Q(0),) * nv: (Q(x), Q(0))})

    @staticmethod
    def cos(freq) -> EP:
        f = tuple(Q(x) for x in freq)
        return EP(len(f), {f: (Q(1, 2), Q(0))}) + EP(len(f), {tuple(-x for x in f): (Q(1, 2), Q(0))})

    @staticmethod
    def sin(freq) -> EP:
        f = tuple(Q(x) for x in freq)
        return EP(len(f), {f: (Q(0), Q(-1, 2))}) + EP(len(f), {tuple(-x for x in f): (Q(0), Q(1, 2))})

    def __add__(self, o: EP) -> EP:
        out = dict(self.terms)
        for k, (a, b) in o.terms.items():
            c, d = out.get(k, (Q(0), Q(0)))
            out[k] = (a + c, b + d)
        return EP(self.nv, out)

    def __neg__(self) -> EP:
        return EP(self.nv, {k: (-a, -b) for k, (a, b) in self.terms.items()})

    def __sub__(self, o: EP) -> EP:
        return self + (-o)

    def __mul__(self, o) -> EP:
        if not isinstance(o, EP):
            q = Q(o)
            return EP(self.nv, {k: (a * q, b * q) for k, (a, b) in self.terms.items()})
        out: dict = {}
        for k1, (a, b) in self.terms.items():
            for k2, (c, d) in o.terms.items():
                k = tuple(x + y for x, y in zip(k1, k2))
                e, f = out.get(k, (Q(0), Q(0)))
                out[k] = (e + a * c - b * d, f + a * d + b * c)
        return EP(self.nv, out)

    __rmul__ = __mul__

    def __pow__(self, m: int) -> EP:
        out = EP.const(self.nv, 1)
        for _ in range(m):
            out = out * self
        return out

    def is_zero(self) -> bool:
        return not self.terms

    def __eq__(self, o) -> bool:  # type: ignore[override]
        return isinstance(o, EP) and (self - o).is_zero()

    __hash__ = None  # type: ignore[assignment]

    def linear(self, matrix) -> EP:
        """Substitute the variables linearly: new frequency = f . matrix (matrix: nv rows of new-variable tuples)."""
        nnv = len(matrix[0])
        out = EP(nnv)
        for k, v in self.terms.items():
            f = tuple(sum((k[r] * Q(matrix[r][c]) for r in range(self.nv)), Q(0)) for c in range(nnv))
            out = out + EP(nnv, {f: v})
        return out

    def diff(self, var: int) -> EP:
        """d/dx_var: multiply a_f by i f_var."""
        return EP(self.nv, {k: (-b * k[var], a * k[var]) for k, (a, b) in self.terms.items()})

    def is_sine_series(self) -> bool:
        return all(self.terms.get(tuple(-x for x in k), (Q(0), Q(0))) == (-a, -b) for k, (a, b) in self.terms.items())

    def is_cosine_series(self) -> bool:
        return all(self.terms.get(tuple(-x for x in k), (Q(0), Q(0))) == (a, b) for k, (a, b) in self.terms.items())


def _axis(nv: int, k: int, scale=1) -> tuple:
    return tuple(Q(scale) if m == k else Q(0) for m in range(nv))


def half_monomial(e: tuple[int, ...]) -> EP:
    """sin^e0(u/2) cos^e1(u/2) sin^e2(v/2) cos^e3(v/2) sin^e4(w/2) cos^e5(w/2) over (u, v, w)."""
    out = EP.const(3, 1)
    for var in range(3):
        out = out * EP.sin(_axis(3, var, Q(1, 2))) ** e[2 * var] * EP.cos(_axis(3, var, Q(1, 2))) ** e[2 * var + 1]
    return out


# ---------------------------------------------------------------------------------------------------------------
# printed formulas (read by paper_repro.printed.latex_math) as exact trigonometric polynomials
# ---------------------------------------------------------------------------------------------------------------
def to_ep(expr, variables) -> EP:
    """The sympy expression ``expr`` (sums and products of rationals, integer powers, sin/cos of rational linear
    forms in ``variables``) as an :class:`EP` over ``variables``; ``LatexMathError`` for anything else (an unknown
    symbol left in a printed formula, a non-linear argument)."""
    import sympy as sp

    nv = len(variables)
    if expr.is_Rational:
        return EP.const(nv, Q(int(expr.p), int(expr.q)))
    if expr.is_Add:
        out = EP(nv)
        for a in expr.args:
            out = out + to_ep(a, variables)
        return out
    if expr.is_Mul:
        out = EP.const(nv, 1)
        for a in expr.args:
            out = out * to_ep(a, variables)
        return out
    if expr.is_Pow and expr.exp.is_Integer and expr.exp >= 0:
        return to_ep(expr.base, variables) ** int(expr.exp)
    if isinstance(expr, (sp.sin, sp.cos)):
        arg = sp.expand(expr.args[0])
        poly = sp.Poly(arg, *variables) if arg.free_symbols <= set(variables) else None
        if poly is None or poly.total_degree() > 1 or poly.coeff_monomial(1) != 0:
            raise LatexMathError(f"argument {arg} is not a linear form in {variables}")
        freq = []
        for v in variables:
            c = poly.coeff_monomial(v)
            if not c.is_Rational:
                raise LatexMathError(f"coefficient {c} of {v} is not rational")
            freq.append(Q(int(c.p), int(c.q)))
        return EP.sin(freq) if isinstance(expr, sp.sin) else EP.cos(freq)
    raise LatexMathError(f"cannot expand {expr}")


def compile_ep(expr, variables, params):
    """``expr`` (read from a transcription; sin/cos of forms linear in ``variables`` whose coefficients, like the
    other factors, may depend on ``params``) compiled to a function ``values of params -> EP`` (fast exact
    evaluation at many parameter values); ``LatexMathError`` for a symbol that is neither a variable nor a parameter, or
    an argument that is not linear in the variables."""
    import sympy as sp

    nv = len(variables)
    extra = expr.free_symbols - set(variables) - set(params)
    if extra:
        raise LatexMathError(f"unknown symbols {sorted(map(str, extra))}")

    def scalar(e):
        f = sp.lambdify(params, e, modules=[{"binomial": comb}, "math"])
        return lambda vals: EP.const(nv, Q(f(*vals)))

    def comp(e):
        if not (e.free_symbols & set(variables)) and not e.has(sp.sin, sp.cos):
            return scalar(sp.nsimplify(e) if e.is_Float else e)
        if e.is_Add or e.is_Mul:
            fs = [comp(a) for a in e.args]

            def run(vals, fs=fs, add=e.is_Add):
                out = EP(nv) if add else EP.const(nv, 1)
                for f in fs:
                    out = out + f(vals) if add else out * f(vals)
                return out
            return run
        if e.is_Pow and e.exp.is_Integer and e.exp >= 0:
            f, k = comp(e.base), int(e.exp)
            return lambda vals: f(vals) ** k
        if isinstance(e, (sp.sin, sp.cos)):
            arg = sp.expand(e.args[0])
            poly = sp.Poly(arg, *variables)
            if poly.total_degree() > 1 or poly.coeff_monomial(1) != 0:
                raise LatexMathError(f"argument {arg} is not a linear form in {variables}")
            cf = [sp.lambdify(params, poly.coeff_monomial(v)) for v in variables]
            mk = EP.sin if isinstance(e, sp.sin) else EP.cos
            return lambda vals: mk([Q(c(*vals)) for c in cf])
        raise LatexMathError(f"cannot expand {e}")

    return comp(expr)


def linear_triple(expr, env: dict | None = None) -> tuple[int, int, int]:
    """``(r, g, b)`` of a printed combination ``ru+gv+bw`` (a sympy expression; letters of ``env`` substituted):
    integer coefficients of u, v, w and nothing else."""
    import sympy as sp

    u, v, w = sp.symbols("u v w")
    e = sp.sympify(expr)
    if not isinstance(e, sp.Expr):
        raise LatexMathError(f"{e} is not a combination of u, v, w")
    e = sp.expand(e.subs({sp.Symbol(k): x for k, x in (env or {}).items()}))
    if not e.free_symbols <= {u, v, w} or not e.is_polynomial(u, v, w):
        raise LatexMathError(f"{e} is not a combination of u, v, w")
    poly = sp.Poly(e, u, v, w)
    if poly.total_degree() > 1 or poly.coeff_monomial(1) != 0:
        raise LatexMathError(f"{e} is not a linear combination of u, v, w")
    out = tuple(poly.coeff_monomial(x) for x in (u, v, w))
    if not all(c.is_Integer for c in out):
        raise LatexMathError(f"{e}: coefficients not integers")
    return tuple(int(c) for c in out)  # type: ignore[return-value]


# ---------------------------------------------------------------------------------------------------------------
# phase equivalence (meaning of Definition equivalence_relation_definition)
# ---------------------------------------------------------------------------------------------------------------
def class_key(t) -> tuple[int, ...]:
    """Canonical key of the class of an integer triple under t ~ t + z(1,1,1) and t ~ z(1,1,1) - t."""
    a = tuple(x - min(t) for x in t)
    b = tuple(max(t) - x for x in t)
    return min(a, b)


def phase_equivalent(a, b) -> bool:
    return class_key(a) == class_key(b)


def E(n: int) -> list[tuple[int, int, int]]:
    return list(product(range(n + 1), repeat=3))


def classes_of(n: int) -> set[tuple[int, ...]]:
    return {class_key(t) for t in E(n)}


def new_class_keys(n: int, lowest: int = 0) -> set[tuple[int, ...]]:
    """Classes of E_n not met by E_i, i = lowest..n-1."""
    old = set().union(*(classes_of(i) for i in range(lowest, n))) if n > lowest else set()
    return classes_of(n) - old


COND_LINES = (("sec4_5-cond1-row1", "sec4_5-cond1-row2", "sec4_5-cond1-row3"),
              ("sec4_5-cond2-row1", "sec4_5-cond2-row2", "sec4_5-cond2-row3"))


def read_conditions() -> list[list]:
    """The two printed systems equivalence_conditions_1/2, each three rows ``lhs = z`` read from the transcriptions,
    as functions ``(r1, g1, b1, r2, g2, b2, z) -> lhs - rhs`` (a row holds when it is 0)."""
    import sympy as sp

    names = sp.symbols("r1 g1 b1 r2 g2 b2 z")
    out = []
    for rows in COND_LINES:
        system = []
        for lid in rows:
            parts = chain(verbatim(lid))
            if len(parts) != 2:
                raise LatexMathError(f"{lid}: not one equation")
            e = sp.expand(parts[0] - parts[1])
            if not e.free_symbols <= set(names):
                raise LatexMathError(f"{lid}: unknown symbols in {e}")
            system.append(sp.lambdify(names, e))
        out.append(system)
    return out


def printed_relation(a, b, zs, conditions) -> bool:
    """The printed definition: some z of ``zs`` fulfils every row of one of the two systems."""
    return any(all(row(*a, *b, z) == 0 for row in system) for system in conditions for z in zs)


def relation_matches(n_max: int, zrange, conditions) -> tuple[bool, dict]:
    """The printed relation (conditions and z range as read) against phase equivalence on all pairs of E_n, and the
    least and greatest z that relate two elements of E_n (the range must be exactly what is needed)."""
    ok, used = True, {}
    for n in range(1, n_max + 1):
        zs = zrange(n)
        for a in E(n):
            for b in E(n):
                if printed_relation(a, b, zs, conditions) != phase_equivalent(a, b):
                    ok = False
        needed = {z for a in E(n) for b in E(n) for z in range(-3 * n, 3 * n + 1)
                  if (all(a[k] + b[k] == z for k in range(3)) or all(b[k] - a[k] == z for k in range(3)))}
        used[str(n)] = [min(needed), max(needed)]
    return ok, {"z_needed_min_max": used}


def read_z_range():
    """The printed set of z, ``\\left\\{ -n,-\\left( n-1\\right) ,\\ldots,0,1,\\ldots,2n\\right\\}``, read from
    both lines that print it (they must agree): a function n -> the list of its integers.  Every listed element is
    read; two listed neighbours differ by 1, elements around ``\\ldots`` increase."""

    sets = set()
    for lid in ("sec4_5-z-range", "sec4_5-z-range-2"):
        got = lm.sentence("{lead:word} exists an integer {z} for which ...", verbatim(lid))
        rel = lm.parse_relation(got["z"]) if got else None
        if rel is None or rel.ops != ["in"] or rel.parts[0] != sp.Symbol("z") or rel.conditions:
            raise LatexMathError(f"{lid}: no 'exists an integer z in {{..}}'")
        sets.add(rel.parts[1])
    if len(sets) != 1:
        raise LatexMathError(f"the two lines print different ranges: {sorted(map(str, sets))}")
    zset = sets.pop()
    if not (isinstance(zset, sp.Function) and zset.func == lm.Family and not zset.args[1] and not zset.args[2]
            and isinstance(zset.args[0], sp.Tuple)):
        raise LatexMathError(f"not a listed set: {zset}")
    exprs = [None if x == lm.LDOTS else section_names(x) for x in zset.args[0]]
    if exprs[0] is None or exprs[-1] is None:
        raise LatexMathError("the set starts or ends with an ellipsis")

    def listed(n: int) -> list[int]:
        vals = [None if e is None else e.subs("n", n) for e in exprs]
        for x in vals:
            if x is not None and not x.is_Integer:
                raise LatexMathError(f"element {x} is not an integer")
        for k in range(len(vals) - 1):
            x, y = vals[k], vals[k + 1]
            if x is not None and y is not None and y - x != 1:
                raise LatexMathError(f"listed neighbours {x}, {y} do not step by 1")
            if x is None and (vals[k - 1] is None or y is None or not y >= vals[k - 1]):
                raise LatexMathError("elements around an ellipsis decrease")
        return list(range(int(vals[0]), int(vals[-1]) + 1))

    return listed


@line_check("sec4_5-relation")
def check_relation() -> LineResult:
    """The printed conditions (each row read) with z in the printed set (every element read, from both lines that
    print it) against phase equivalence; the set is exactly the z that relate two elements of E_n."""

    how = ("the two systems of conditions (each row read from the transcriptions) with z in the printed set (read "
           "from both lines) compared with phase equivalence (a - b or a + b in Z(1,1,1)) on all pairs of E_n, "
           "n = 1..3; the printed set equals the set of z that relate two elements of E_n")
    try:
        zrange, conds = read_z_range(), read_conditions()
        ok, det = relation_matches(3, zrange, conds)
    except (LatexMathError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    ext = all(zrange(int(k)) == list(range(v[0], v[1] + 1)) for k, v in det["z_needed_min_max"].items())
    return LineResult(ok and ext, how=how, kind="exhaustive", detail={**det, "n_max": 3, "range_exact": ext})


# -- phase identities (display after the Definition) --------------------------------------------------------------
#: the lines of each phase chain, in order (each line is one or more '=' parts of the chain)
PHASE_LINES = {"cos": ("sec4_5-cos-step1", "sec4_5-cos-step2", "sec4_5-cos-step3"), "sin": ("sec4_5-sin-step1",)}
#: the last step of each chain (printed with 'za': an erratum each)
PHASE_LAST = {"cos": "sec4_5-cos-step4-za", "sin": "sec4_5-sin-step2-za"}


def _related_pairs(n: int):
    """``(a, b, z, S)`` for every pair of E_n related by a common z: b = z(1,1,1) - a (sums, the upper sign S = 1 of
    the printed -+) or b = z(1,1,1) + a (differences, S = -1); z over every integer that occurs."""
    for a in E(n):
        for b in E(n):
            s = {a[k] + b[k] for k in range(3)}
            d = {b[k] - a[k] for k in range(3)}
            if len(s) == 1:
                yield a, b, s.pop(), 1
            if len(d) == 1:
                yield a, b, d.pop(), -1


def phase_chain(kind: str) -> list:
    """The '=' parts of the printed chain of ``kind`` (read from the transcriptions, in order)."""

    return [part for lid in PHASE_LINES[kind] for part in chain(verbatim(lid))]


def _pair_params():
    import sympy as sp

    return (*sp.symbols("r1 g1 b1 r2 g2 b2 z"), PM)


def _compile_on_omega(expr, extra=()):
    """``expr`` with w = alpha - u - v compiled over (u, v, alpha, *extra) with the pair parameters."""
    import sympy as sp

    u, v, w = sp.symbols("u v w")
    return compile_ep(expr.subs(w, ALPHA - u - v), (u, v, ALPHA, *extra), _pair_params())


def phase_steps(kind: str, n_max: int = 2) -> list[bool]:
    """Each '=' step of the printed chain, exactly at every related pair of E_n, n <= n_max (both signs)."""

    parts = phase_chain(kind)
    if len(parts) < 2:
        raise LatexMathError(f"a chain of {len(parts)} parts")
    fs = [_compile_on_omega(x) for x in parts]
    ok = [True] * (len(parts) - 1)
    for n in range(1, n_max + 1):
        for a, b, z, sg in _related_pairs(n):
            eps = [f((*a, *b, z, sg)) for f in fs]
            ok = [o and eps[k] == eps[k + 1] for k, o in enumerate(ok)]
    return ok


def phase_last(kind: str, n_max: int = 2) -> tuple[bool, bool]:
    """The last step (printed, with the symbol a of 'za' a free variable; and with a = alpha) against the previous
    part of the chain, at every related pair of E_n, n <= n_max."""
    import sympy as sp

    prev = phase_chain(kind)[-1]
    last = chain(verbatim(PHASE_LAST[kind]))
    if len(last) != 1:
        raise LatexMathError(f"the last step has {len(last)} parts")
    a = sp.Symbol("a")
    f_prev, f_last = _compile_on_omega(prev, (a,)), _compile_on_omega(last[0], (a,))
    f_corr = _compile_on_omega(last[0].subs(a, ALPHA), (a,))
    printed = corrected = True
    for n in range(1, n_max + 1):
        for a_, b, z, sg in _related_pairs(n):
            vals = (*a_, *b, z, sg)
            lhs = f_prev(vals)
            printed &= lhs == f_last(vals)
            corrected &= lhs == f_corr(vals)
    return printed, corrected


def phase_meaning() -> dict[str, bool]:
    """The prose after the cos chain: cos(r2u+g2v+b2w) differs from cos(r1u+g1v+b1w) by a phase change and is a
    linear combination of cos and sin of r1u+g1v+b1w.  The four functions are read from the transcription; the
    combination cos(z alpha) cos X + S sin(z alpha) sin X is computed here (not read), exactly at every related pair
    of E_n, n <= 2."""
    import sympy as sp

    got = lm.sentence("i.e., function {f0} differs from {f1} only in a {what:words} and it can be expressed as a "
                      "{how:words} of {f2} and {f3}", verbatim("sec4_5-phase-meaning"))
    if got is None:
        raise LatexMathError("sec4_5-phase-meaning: not 'function .. differs from .. only in a .. and it can be "
                             "expressed as a .. of .. and ..'")
    pieces = [parse(got[x]) for x in ("f0", "f1", "f2", "f3")]
    if not all(isinstance(x, (sp.sin, sp.cos)) for x in pieces):
        raise LatexMathError(f"not four functions cos/sin: {pieces}")
    f0, f1, f2, f3 = pieces
    words = {"phase": got["what"] == "phase change", "combination": got["how"] == "linear combination"}
    same_arg = f1.args[0] == f2.args[0] == f3.args[0] and {type(f2), type(f3)} == {sp.sin, sp.cos}
    cos_x, sin_x = (f2, f3) if isinstance(f2, sp.cos) else (f3, f2)
    same_function = type(f0) is type(f1)
    z, sg = sp.Symbol("z"), _pair_params()[-1]
    rhs = sp.cos(z * ALPHA) * cos_x + sg * sp.sin(z * ALPHA) * sin_x if isinstance(f0, sp.cos) else \
        sp.sin(z * ALPHA) * cos_x - sg * sp.cos(z * ALPHA) * sin_x
    f_lhs, f_rhs = _compile_on_omega(f0), _compile_on_omega(rhs)
    combo = all(f_lhs((*a, *b, zz, s)) == f_rhs((*a, *b, zz, s)) for n in (1, 2) for a, b, zz, s in _related_pairs(n))
    return {**words, "same_argument_X": same_arg, "same_function_phase": same_function,
            "combination_of_cos_sin_X": combo}


def _register_phase(kind: str, steps_how: str, za_how: str) -> None:
    """Register the two checks of the phase identity for ``kind`` ("cos" or "sin"): its steps, and its last step
    with the printed 'za' (sec4_5-phase-<kind> and sec4_5-phase-<kind>-za)."""

    @line_check(f"sec4_5-phase-{kind}")
    def check_steps() -> LineResult:
        try:
            steps = phase_steps(kind)
            meaning = phase_meaning() if kind == "cos" else {}
        except LatexMathError as exc:
            return LineResult(False, how="the chain read from the transcriptions, n <= 2", kind="exhaustive",
                              detail={"unread": str(exc)})
        return LineResult(all(steps) and all(meaning.values()), how=steps_how, kind="exhaustive",
                          detail={"steps": steps, **meaning})

    @line_check(f"sec4_5-phase-{kind}-za")
    def check_za() -> LineResult:
        try:
            printed, corrected = phase_last(kind)
        except LatexMathError as exc:
            return LineResult(False, how="the last step read from the transcription, n <= 2", kind="exhaustive",
                              detail={"unread": str(exc)})
        return LineResult(printed, corrected, how=za_how, kind="exhaustive",
                          detail={"printed_za": printed, "with_z_alpha": corrected})


_register_phase("cos", "each '=' step of the chain read from the transcriptions (z, the signs -+ / +- as S = +-1) "
                "expanded exactly over (u, v, alpha) with w = alpha - u - v, at every related pair of E_n, n <= 2, "
                "both signs; the prose after it (its four functions read) against cos(z alpha) cos X + S sin(z "
                "alpha) sin X", "the last step read from the transcription: with the printed 'za' (a a free "
                "variable) and with a = alpha, against the previous part, every related pair of E_n, n <= 2")
_register_phase("sin", "each '=' step of the sin chain read from the transcription, expanded exactly with w = alpha "
                "- u - v at every related pair of E_n, n <= 2, both signs",
                "as sec4_5-phase-cos-za for the sin chain, n <= 2")


# -- readers of the worked examples (triples ru+gv+bw as printed) -------------------------------------------------
def _family(item):
    """``(member, conditions, bounds)`` of a parsed set (latex_math's ``Family``); :class:`LatexMathError` otherwise."""
    if not (isinstance(item, sp.Function) and item.func == lm.Family):
        raise LatexMathError(f"not a set: {item}")
    return item.args


@cache
def _omega_domain() -> tuple:
    """The condition ``\\left( u,v,w\\right) \\in\\Omega^{\\alpha}`` of a set of functions, as the reader reads it."""
    return tuple(_family(lm.parse(r"\left\{ u:\left( u,v,w\right) \in\Omega^{\alpha}\right\}"))[1])


def cos_sin_triples(item) -> list[tuple[int, int, int]]:
    """The triples (r, g, b) of the ``\\cos\\left( ru+gv+bw\\right)`` of a parsed set of functions
    ``\\left\\{ \\cos\\left( .. \\right) ,\\sin\\left( .. \\right) ,..:\\left( u,v,w\\right) \\in\\Omega^{\\alpha}
    \\right\\}``: each cos with its sin, the one condition its domain (u,v,w) in Omega^alpha, no bounds."""
    members, conds, bounds = _family(item)
    funcs = list(members) if isinstance(members, sp.Tuple) else [members]
    if bounds or tuple(conds) != _omega_domain():
        raise LatexMathError(f"the set does not end with its domain (u,v,w) in Omega^alpha: {tuple(conds)}")
    if not all(isinstance(f, (sp.cos, sp.sin)) for f in funcs):
        raise LatexMathError(f"not a set of cos and sin: {funcs}")
    cos = sorted((f.args[0] for f in funcs if isinstance(f, sp.cos)), key=sp.default_sort_key)
    sin = sorted((f.args[0] for f in funcs if isinstance(f, sp.sin)), key=sp.default_sort_key)
    if cos != sin:
        raise LatexMathError(f"cos and sin arguments differ: {cos} vs {sin}")
    return [linear_triple(x) for x in cos]


def class_family(item, env: dict | None = None) -> list[tuple[int, int, int]]:
    """The triples of the classes ``\\left\\{ \\left[ .. \\right] \\right\\} _{g=a}^{b}`` of a parsed family (one
    bound, no condition; the bounds evaluated with ``env``), in the order of the bound."""
    member, conds, bounds = _family(item)
    if conds or len(bounds) != 1 or not (isinstance(member, sp.Function) and member.func.__name__ == "cls"):
        raise LatexMathError(f"not a family of classes over one bound: {item}")
    var, lo, hi = bounds[0]
    env = dict(env or {})
    return [linear_triple(member.args[0], {**env, str(var): x})
            for x in range(bound(lo, **env), bound(hi, **env) + 1)]


def _texts(ids, override=None) -> dict[str, str]:
    out = {x.id: x.verbatim for x in pl.LINES if x.id in ids}
    out.update({k: v for k, v in (override or {}).items() if k in out})
    return out


@line_check("sec4_5-examples-n3")
def check_examples_n3() -> LineResult:
    """Every link of the worked examples (read from their transcriptions: combinations, ~ and the negated relation)
    against phase equivalence; every combination in E_3 (the text's n = 3: coefficients 0..3)."""

    how = "phase equivalence of the printed pairs (read from the transcriptions), every combination in E_3 (n = 3)"
    try:
        got = []
        for lid in ("sec4_5-examples-n3-1", "sec4_5-examples-n3-2", "sec4_5-examples-n3-3"):
            rel = lm.parse_relation(verbatim(lid))
            triples = [linear_triple(section_names(x)) for x in rel.parts]
            in_e3 = all(0 <= c <= 3 for t in triples for c in t)
            got.append(in_e3 and len(rel.parts) >= 2 and relation_chain_holds(rel))
    except (LatexMathError, TypeError) as exc:
        return LineResult(False, how=how, kind="proof", detail={"unread": str(exc)})
    return LineResult(all(got), how=how, kind="proof", detail={"lines_hold": got})


# -- orders 1 and 2 -----------------------------------------------------------------------------------------------
def set_of_classes(x, env: dict | None = None) -> set:
    """The class keys of a parsed set of classes: ``E_{a}^{\\alpha}/_{\\sim}`` (``quot(E(a))``), a difference
    ``\\setminus`` and a union ``\\cup`` of such sets (indices evaluated with ``env``)."""
    name = x.func.__name__
    if name == "quot" and x.args[0].func.__name__ == "E" and len(x.args[0].args) == 1:
        a = section_names(x.args[0].args[0]).subs({sp.Symbol(k): v for k, v in (env or {}).items()})
        if not a.is_Integer:
            raise LatexMathError(f"index {a} is not an integer")
        return classes_of(int(a))
    if name == "setminus":
        return set_of_classes(x.args[0], env) - set_of_classes(x.args[1], env)
    if name == "cup" and len(x.args) == 2:
        return set_of_classes(x.args[0], env) | set_of_classes(x.args[1], env)
    raise LatexMathError(f"not a quotient set: {x}")


def read_item(x, env: dict | None = None):
    """One member of a parsed relation chain: ``("class", key)`` of ``\\left[ ..\\right]`` (``cls``), ``("set",
    keys)`` of a quotient set (:func:`set_of_classes`) or ``("triple", t)`` of a combination ru+gv+bw."""

    if x.func.__name__ == "cls":
        return "class", class_key(linear_triple(section_names(x.args[0]), env))
    if x.func.__name__ in ("quot", "setminus", "cup"):
        return "set", set_of_classes(x, env)
    return "triple", linear_triple(section_names(x), env)


def relation_chain_holds(rel, env: dict | None = None) -> bool:
    """Every link of a printed chain such as ``1\\cdot u+1\\cdot v+1\\cdot w\\sim0\\cdot u+..\\in\\left[ 0\\right]
    \\in E_{0}^{\\alpha}/_{\\sim}`` (a text, read by :func:`latex_math.parse_relation`, or the parsed relation) against
    the class keys (``~``: same class; ``\\in`` a class: same class; ``=`` of classes: same key; ``\\in`` a set:
    member); a link the reader does not know raises."""

    if isinstance(rel, str):
        rel = lm.parse_relation(rel)
    if not isinstance(rel, lm.Relation) or rel.lead or rel.conditions or not rel.ops:
        raise LatexMathError(f"not a chain of relations: {rel}")
    items = [read_item(x, env) for x in rel.parts]
    ok = True
    for (ka, a), rel_op, (kb, b) in zip(items, rel.ops, items[1:]):
        ka_key = class_key(a) if ka == "triple" else a
        if kb == "set":
            if ka == "set":
                raise LatexMathError("a set related to a set")
            if rel_op not in ("in", "notin"):
                raise LatexMathError(f"{rel_op} before a set")
            ok &= (ka_key in b) == (rel_op == "in")
        elif rel_op in ("sim", "nsim", "=", "in"):
            kb_key = class_key(b) if kb == "triple" else b
            if rel_op == "in" and kb != "class":
                raise LatexMathError("\\in before a combination")
            if rel_op == "=" and (ka, kb) != ("class", "class"):
                raise LatexMathError("= between combinations")
            ok &= (ka_key == kb_key) == (rel_op != "nsim")
        else:
            raise LatexMathError(f"unknown link {rel_op}")
    return ok


def read_order_classes(tex: str) -> dict[str, bool]:
    """``\\left[ ru+gv+bw\\right] \\in E_{a}/_{\\sim}\\setminus .., where at least one of the coefficients r,g,b is
    equal to $c$`` (the words by :func:`latex_math.sentence`, the display and c by the reader): every new class of the
    printed difference of quotient sets is met, in E_a, only by triples with a coefficient c (the new classes of
    order a are those of the triples with a coefficient a)."""

    got = lm.sentence(r"{display:words} \] where at least one of the coefficients $r,g,b$ is equal to {c}.", tex)
    if not got:
        raise LatexMathError("no 'classes in E_a/~ \\ .. where at least one of r,g,b is equal to c'")
    rel = lm.parse_relation(got["display"])
    if rel.lead or rel.ops != ["in"] or rel.conditions or rel.parts[0] != sp.Function("cls")(lm.parse("ru+gv+bw")):
        raise LatexMathError(f"not [ru+gv+bw] in a set of classes: {rel.parts}")
    new = set_of_classes(rel.parts[1])
    head = rel.parts[1].args[0] if rel.parts[1].func.__name__ == "setminus" else rel.parts[1]
    order = head.args[0].args[0] if head.func.__name__ == "quot" else None
    c = parse(got["c"])
    if not (order is not None and order.is_Integer and c.is_Integer):
        raise LatexMathError(f"the order {order} or the coefficient {c} is not an integer")
    members = [t for t in E(int(order)) if class_key(t) in new]
    return {"classes_new": bool(new) and new == new_class_keys(int(order)),
            "coefficient_c": all(int(c) in t for t in members)}


def read_if_then(tex: str) -> tuple[list[dict], list[str]]:
    """``If $r=a$ and $g\\in\\left\\{ ..\\right\\} $, then $..$`` (the words by :func:`latex_math.sentence`, each
    condition by :func:`latex_math.parse_relation`): the environments the condition allows and the math of the
    conclusion."""

    got = lm.sentence("If {cond:words}, then {concl:words}", tex)
    if not got:
        raise LatexMathError("no 'If .., then ..'")
    envs: list[dict] = [{}]
    for seg in lm.inline_math(got["cond"]):
        top = lm.parse_relation(seg)
        for rel in (top, *top.conditions):
            if rel.ops == ["in"] and rel.parts[0].is_Symbol:
                members, conds, bounds = _family(rel.parts[1])
                if conds or bounds:
                    raise LatexMathError(f"not a listed set: {rel.parts[1]}")
                vals = [int(x) for x in (members if isinstance(members, sp.Tuple) else (members,))]
                envs = [{**e, str(rel.parts[0]): x} for e in envs for x in vals]
                continue
            parts = rel.parts
            if rel.lead or set(rel.ops) != {"="} or not parts[-1].is_Integer or \
                    not all(p.is_Symbol for p in parts[:-1]):
                raise LatexMathError(f"unread condition {seg!r}")
            envs = [{**e, **{str(p): int(parts[-1]) for p in parts[:-1]}} for e in envs]
    return envs, lm.inline_math(got["concl"])


def read_v_step(rows: tuple[str, ...]) -> tuple[int, int, list[tuple[int, int, int]]]:
    """``V_{a}^{\\alpha}=V_{b}^{\\alpha}\\cup\\left\\{ ..\\right\\}`` and the rows that go on with ``& \\cup\\left\\{
    ..\\right\\}`` (each read by :func:`latex_math.parse_relation`): a, b and the triples of every set's cos
    (:func:`cos_sin_triples`)."""
    first = lm.parse_relation(rows[0])
    if first.lead or first.ops != ["="] or first.conditions:
        raise LatexMathError(f"not V_a = V_b cup {{..}}: {first.ops}")
    lhs, rhs = first.parts
    if not (rhs.func.__name__ == "cup" and len(rhs.args) == 2 and all(
            x.func.__name__ == "V" and len(x.args) == 1 and x.args[0].is_Integer for x in (lhs, rhs.args[0]))):
        raise LatexMathError(f"not V_a = V_b cup {{..}}: {lhs} = {rhs}")
    sets = [rhs.args[1]]
    for row in rows[1:]:
        r = lm.parse_relation(row)
        if r.lead or r.ops or r.conditions or len(r.parts) != 1 or r.parts[0].func.__name__ != "cup" or len(
                r.parts[0].args) != 1:
            raise LatexMathError(f"not a row '\\cup{{..}}': {r.parts}")
        sets.append(r.parts[0].args[0])
    return int(lhs.args[0]), int(rhs.args[0].args[0]), [x for fam in sets for x in cos_sin_triples(fam)]


def _first_class(concl: list[str]):
    """The combination inside the first class ``\\left[ ..\\right]`` of the one formula of a conclusion."""
    first = lm.parse_relation(concl[0]).parts[0] if len(concl) == 1 else None
    if first is None or first.func.__name__ != "cls":
        raise LatexMathError(f"no class first in {concl}")
    return section_names(first.args[0])


def _orders_1_2() -> dict[str, bool]:
    """The worked text of orders 1 and 2, every statement read from its transcription and checked with the class keys
    of phase equivalence."""
    import sympy as sp

    k = class_key
    t = live_texts()
    out: dict[str, bool] = {}
    for lid in ("sec4_5-order1-classes", "sec4_5-order2-classes"):
        out.update({f"{lid}:{x}": v for x, v in read_order_classes(t[lid]).items()})
    got = lm.sentence("Since {a}, {b}, {c} and {d}", t["sec4_5-order1-relations"])
    out["order1_relations"] = got is not None and all(relation_chain_holds(got[x]) for x in "abcd")
    # b = 2 (the case the text assumes), r = g = 2
    envs, concl = read_if_then(t["sec4_5-n2-222"])
    first = _first_class(concl)
    out["222"] = len(envs) == 1 and relation_chain_holds(concl[0]) and linear_triple(first) == (
        envs[0].get("r"), envs[0].get("g"), 2)
    # 0 < r <= g <= 2, i.e. r = 1, g in {1, 2}; z = min{r, g} = 1
    got = lm.sentence("If {ineq}, i.e., if {cond}, then let {z}", t["sec4_5-n2-r1"])
    if got is None:
        raise LatexMathError("sec4_5-n2-r1: not 'If .., i.e., if .., then let ..'")
    ineq = lm.parse_relation(got["ineq"])
    if ineq.lead or ineq.conditions or not set(ineq.ops) <= {"<", "<="}:
        raise LatexMathError(f"sec4_5-n2-r1: not a chain of < and <=: {ineq.ops}")
    terms = [section_names(x) for x in ineq.parts]
    rs, gs = sp.symbols("r g")
    grid = [(r, g) for r in range(3) for g in range(3)]
    sat = {(r, g) for r, g in grid
           if all((x.subs({rs: r, gs: g}) < y.subs({rs: r, gs: g})) if op == "<"
                  else (x.subs({rs: r, gs: g}) <= y.subs({rs: r, gs: g}))
                  for x, op, y in zip(terms, ineq.ops, terms[1:]))}
    envs_r1, _ = read_if_then(f"If ${got['cond']}$, then $x$")
    stated = {(e["r"], e["g"]) for e in envs_r1}
    out["r1_is_the_rest_of_0<r<=g<=2"] = sat - {(2, 2)} == stated  # r = g = 2 was treated in the sentence before
    zparts = chain(got["z"])
    zsym = zparts[0]
    out["z_min_is_1"] = len(zparts) == 3 and zsym == sp.Symbol("z") and all(
        zparts[1].subs({rs: r, gs: g}) == zparts[2] for r, g in stated)
    zval = int(zparts[2])
    # the chain ru+gv+2w = ... (u + v + w = alpha), for the stated (r, g) and z
    ch = chain(t["sec4_5-n2-chain"])
    u, v, w = sp.symbols("u v w")

    ok_chain = len(ch) == 4
    for r, g in stated:
        vals = [sp.expand(x.subs({rs: r, gs: g, zsym: zval}).subs(ALPHA, u + v + w)) for x in ch]
        ok_chain &= all(x == vals[0] for x in vals) and ch[0].subs({rs: r, gs: g}) == r * u + g * v + 2 * w
        ok_chain &= not (ch[-1].free_symbols & {u, rs})  # the last form has no u: z = r
    out["chain"] = ok_chain
    # u+gv+2w in [(g-z)v+w] = {[w] (g = 1), [v+w] = [u] (g = 2)}
    g12 = lm.parse_relation(t["sec4_5-n2-g12"])
    if g12.lead or g12.conditions or g12.ops != ["in", "="] or g12.parts[1].func.__name__ != "cls" or \
            g12.parts[2].func != lm.Cases:
        raise LatexMathError(f"sec4_5-n2-g12: not 'X in [Y] = {{cases}}': {g12.ops}")
    ok_g12, seen = True, set()
    for stmt, cond in g12.parts[2].args:
        gsym = sp.Symbol("g")
        if not (isinstance(cond, sp.Eq) and cond.lhs == gsym and cond.rhs.is_Integer):
            raise LatexMathError(f"sec4_5-n2-g12: unread row condition {cond}")
        env = {"g": int(cond.rhs), "z": zval}
        seen.add(env["g"])
        lhs, cls = linear_triple(g12.parts[0], env), linear_triple(g12.parts[1].args[0], env)
        row = lm.chain_relation(stmt)
        first_cls = row.parts[0].args[0] if row.parts[0].func.__name__ == "cls" else None
        ok_g12 &= k(lhs) == k(cls) and first_cls is not None and k(linear_triple(first_cls, env)) == k(cls)
        ok_g12 &= relation_chain_holds(row, env)
    out["g12"] = ok_g12 and seen == {g for _, g in stated}
    # r = 0, g in {0, 1, 2}: [gv + 2w] new at order 2
    envs, concl = read_if_then(t["sec4_5-n2-r0"])
    ok_r0 = len(concl) == 1 and len(envs) >= 1
    first = _first_class(concl)
    for env in envs:
        ok_r0 &= relation_chain_holds(concl[0], env) and linear_triple(first, env) == (env.get("r"), env.get("g"), 2)
    out["r0"] = ok_r0
    # [2v+2w] reappears as [2u], new at order 2
    got = lm.sentence("from which {a} must be ignored, because this equivalence class will reappear as {b}",
                      t["sec4_5-n2-2v2w"])
    if got is None:
        raise LatexMathError("sec4_5-n2-2v2w: not 'from which .. must be ignored, because .. will reappear as ..'")
    a_cls = read_item(section_names(lm.parse(got["a"])))
    b_cls = read_item(lm.parse_relation(got["b"]).parts[0])
    out["2v2w_is_2u"] = a_cls[0] == b_cls[0] == "class" and a_cls[1] == b_cls[1] and relation_chain_holds(got["b"])
    # the six classes of order 2, V_1 and V_2
    n2 = [c for r in (1, 2, 3) for c in class_family(lm.parse(t[f"sec4_5-n2-classes-row{r}"]))]
    out["six_classes_n2"] = {k(x) for x in n2} == new_class_keys(2) and len(n2) == 6
    order, prev, v1 = read_v_step((t["sec4_5-V1"],))
    out["V1"] = {k(x) for x in v1} == new_class_keys(order) and len(set(v1)) == 3 and prev == order - 1 == 0
    order, prev, v2 = read_v_step(tuple(t[f"sec4_5-V2-row{r}"] for r in (1, 2, 3)))
    out["V2"] = {k(x) for x in v2} == new_class_keys(order) and len(set(v2)) == 6 and prev == order - 1 == 1
    return out


@line_check("sec4_5-orders-1-2")
def check_orders_1_2() -> LineResult:

    how = ("every statement of the worked text of orders 1 and 2 read from its transcription (relations, classes, "
           "quotient sets, conditions, the chain, V_1, the six classes, V_2) against the class keys of phase "
           "equivalence")
    return items_result(_orders_1_2, how, "proof", (LatexMathError, TypeError, KeyError))


def b2_classes(b: int, restrict_r_le_g: bool) -> set:
    """New classes of order 2 met by the triples (r, g, b) (only r <= g if ``restrict_r_le_g``: the cases the text
    treats, r = g = 2, 0 < r <= g <= 2 and r = 0)."""
    new = new_class_keys(2)
    return {class_key((r, g, b)) for r in range(3) for g in range(3)
            if class_key((r, g, b)) in new and (not restrict_r_le_g or r <= g)}


@line_check("sec4_5-b2-three-classes")
def check_b2() -> LineResult:
    """The printed value of b, the count (a word) and the family {[gv+2w]}_{g=0}^{2} are read; printed: they are all
    the new classes of E_2 met by (r, g, b); corrected: those met with r <= g (the cases the text treats)."""
    how = ("new classes of E_2 met by the triples (r, g, b) with the printed b: all of them (printed), those with "
           "r <= g (corrected), against the printed family and count (read from the transcription)")
    got = lm.sentence("Thus, equality {b} generates only {count:count} acceptable equivalence classes, namely {fam}",
                      verbatim("sec4_5-n2-b2-three"))
    try:
        if not got or got["count"] is None:
            raise ValueError("unread line")
        rel = lm.parse_relation(got["b"])
        if rel.ops != ["="] or rel.parts[0] != sp.Symbol("b") or not rel.parts[1].is_Integer or rel.conditions:
            raise ValueError(f"not b = an integer: {got['b']!r}")
        bb, count = int(rel.parts[1]), got["count"]
        fam = class_family(lm.parse(got["fam"]))
        keys = {class_key(t) for t in fam}
    except (ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="proof", detail={"unread": str(exc)})
    shape = len(keys) == len(fam) == count and all(t[2] == bb for t in fam)
    all_b2, ordered = b2_classes(bb, False), b2_classes(bb, True)
    return LineResult(shape and all_b2 == keys, shape and ordered == keys, how=how, kind="proof",
                      detail={"classes_met_by_b": len(all_b2), "printed": count, "with_r_le_g": len(ordered),
                              "missed_triples": ["(1,0,2) in [u+2v]", "(2,0,2) in [2v]"]})


# -- Proposition iterative_construction_of_trivariate_extension ---------------------------------------------------
def _union_items(x) -> list:
    """The sets of a parsed union ``A\\cup B\\cup C`` (read as ``cup(cup(A, B), C)``), in the printed order."""
    return [y for a in x.args for y in _union_items(a)] if x.func.__name__ == "cup" else [x]


def read_prop_families(tex: str, n: int) -> list[tuple[int, int, int]]:
    """The representatives of the printed families ``\\left\\{ \\left[ .. \\right] \\right\\} _{g=0}^{n-1}`` of
    Proposition iterative_construction_of_trivariate_extension at order n, read from the transcription (the right
    side of its equation, by :func:`latex_math.parse_relation`)."""

    rel = lm.parse_relation(tex)
    if rel.ops != ["="] or rel.conditions:
        raise ValueError(f"not one equation: {rel.ops}")
    fams = _union_items(rel.parts[1])
    if len(fams) != 3:
        raise ValueError(f"{len(fams)} families of classes, not 3")
    return [t for fam in fams for t in class_family(fam, {"n": n})]


def _removed_union(x) -> tuple[int, sp.Expr]:
    """``E_{n}^{\\alpha}/_{\\sim}\\setminus\\left( \\cup_{i=a}^{b}E_{i}^{\\alpha}/_{\\sim}\\right)``, parsed: a (an
    integer) and b (an expression in n)."""
    n, i = sp.symbols("n i")
    quot, e_ = sp.Function("quot"), sp.Function("E")
    if not (x.func.__name__ == "setminus" and x.args[0] == quot(e_(n)) and x.args[1].func.__name__ == "bigcup"):
        raise ValueError(f"not E_n/~ minus a union: {x}")
    member, conds, bounds = _family(x.args[1].args[0])
    if member != quot(e_(i)) or conds or len(bounds) != 1 or bounds[0][0] != i or not bounds[0][1].is_Integer:
        raise ValueError(f"not the union of E_i/~ over i = a..b: {x.args[1]}")
    return int(bounds[0][1]), bounds[0][2]


def read_prop() -> tuple[int, sp.Expr]:
    """The union cup_{i=a}^{b} E_i/~ removed from E_n/~ in both lines of the Proposition (they must agree), and the
    recurrence's other parts: V_n = V_{n-1} cup {cos, sin of one combination : (u,v,w) in Omega, [the same] in ..}
    (both lines read by :func:`latex_math.parse_relation`)."""
    rec = lm.parse_relation(verbatim("sec4_5-prop-recurrence"))
    new = lm.parse_relation(verbatim("sec4_5-prop-new-classes"))
    n = sp.Symbol("n")
    v_ = sp.Function("V")
    if rec.lead or rec.ops != ["="] or rec.conditions or new.ops != ["="]:
        raise ValueError("unread recurrence")
    lhs, rhs = rec.parts
    if lhs != v_(n) or rhs.func.__name__ != "cup" or len(rhs.args) != 2 or rhs.args[0] != v_(n - 1):
        raise ValueError(f"unread recurrence: {lhs} = {rhs}")
    members, conds, bounds = _family(rhs.args[1])
    x = lm.parse("ru+gv+bw")
    if bounds or members != sp.Tuple(sp.cos(x), sp.sin(x)) or len(conds) != 2 or (conds[0],) != _omega_domain() \
            or conds[1].func.__name__ != "In" or conds[1].args[0] != sp.Function("cls")(x):
        raise ValueError(f"unread recurrence set: {rhs.args[1]}")
    union = _removed_union(conds[1].args[1])
    if _removed_union(new.parts[0]) != union:
        raise ValueError(f"the unions differ: {conds[1].args[1]} and {new.parts[0]}")
    return union


def prop_sets_agree(n_max: int, lowest: int, top: str) -> dict[int, bool]:
    """E_n/~ minus the union over i = lowest..top(n) against the printed representatives (read): distinct classes,
    exactly the new ones."""

    tex = verbatim("sec4_5-prop-new-classes")
    out = {}
    for n in range(1, n_max + 1):
        reps = read_prop_families(tex, n)
        keys = [class_key(t) for t in reps]
        hi = bound(top, n=n)
        removed = set().union(*(classes_of(i) for i in range(lowest, hi + 1))) if hi >= lowest else set()
        out[n] = len(set(keys)) == len(reps) and set(keys) == classes_of(n) - removed and all(
            0 <= min(t) <= max(t) <= n for t in reps)  # representatives in E_n
    return out


@line_check("sec4_5-prop-union")
def check_prop_union() -> LineResult:
    """The printed union (start and end read: i = 1..n-1), the recurrence and the representatives (read) against the
    class keys; the correction starts the union at i = 0."""
    how = ("class keys: E_n/~ minus the printed union of E_i/~ (its bounds read; the correction starts it at i = 0) "
           "against the printed representatives, n = 1..10")
    try:
        start, top = read_prop()
        printed, corrected = prop_sets_agree(10, start, top), prop_sets_agree(10, 0, top)
    except (ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(printed.values()), all(corrected.values()), how=how, kind="exhaustive",
                      detail={"printed_fails_at_n": [n for n, v in printed.items() if not v],
                              "classes_left_at_n_1_printed": len(new_class_keys(1, 1)),
                              "corrected_holds_n_1_10": all(corrected.values())})


# -- ranks (V_n independent, dimension, coincidence) --------------------------------------------------------------
def own_v_args(n: int) -> list[tuple[int, ...]]:
    """One triple per non-zero class of E_n (class keys), no use of the printed representatives."""
    return sorted(k for k in classes_of(n) if k != (0, 0, 0))


RANK_CASES = ((1, TS[0]), (2, TS[0]), (3, TS[0]), (1, TS[1]), (2, TS[1]))


@cache
def _rank_data(n: int, t: fmpq) -> dict:
    alpha = rational_alpha(t)
    d = 3 * n * (n + 1) + 1
    pts = sample_rational_points(alpha, d + 4, seed=11)
    ctx = ExactContext()
    half = [list(v) for v in pts.half_angle_values()]
    cols = [[fmpq(1)] * len(pts)]
    full = [full_angles([h[p] for h in half], ctx) for p in range(len(pts))]
    for k in own_v_args(n):
        cs = [cos_sin_combination(full[p], k, ctx, fmpq(1)) for p in range(len(pts))]
        cols += [[c for c, _ in cs], [s for _, s in cs]]
    tm = evaluate(n, alpha, pts, ctx)
    T = fmpq_mat([[tm[p, q] for q in range(tm.shape[1])] for p in range(len(pts))])
    V = fmpq_mat([[cols[q][p] for q in range(len(cols))] for p in range(len(pts))])
    TV = fmpq_mat([[tm[p, q] for q in range(tm.shape[1])] + [cols[q][p] for q in range(len(cols))]
                   for p in range(len(pts))])
    return {"delta": d, "columns_V": len(cols), "rank_T": T.rank(), "rank_V": V.rank(), "rank_TV": TV.rank()}


#: ranks of spans at the rational points of one alpha (they do not depend on the transcriptions: a plain dict, kept
#: when the caches of the line checks are cleared)
_SPAN_RANKS: dict = {}


def span_rank(members: tuple[tuple[str, int], ...]) -> int:
    """Exact rank of the union of the systems ``("T", 2m)`` (T_{2m}^alpha, from :mod:`paper_repro.core`),
    ``("V", k)`` (cos/sin of one triple per class of E_k, and 1) and ``("X", (r, g, b))`` (cos and sin of one
    triple) at delta_3 + 4 rational points of Omega^alpha (tan(alpha/4) = 1/3), m, k <= 3."""
    key = tuple(sorted(set(members)))
    if key in _SPAN_RANKS:
        return _SPAN_RANKS[key]
    if "pts" not in _SPAN_RANKS:
        alpha = rational_alpha(TS[0])
        pts = sample_rational_points(alpha, 3 * 3 * 4 + 1 + 4, seed=11)
        ctx = ExactContext()
        half = [list(v) for v in pts.half_angle_values()]
        full = [full_angles([h[p] for h in half], ctx) for p in range(len(pts))]
        _SPAN_RANKS["pts"] = (alpha, pts, ctx, full)
    alpha, pts, ctx, full = _SPAN_RANKS["pts"]
    cols: list[list] = []
    for kind, order in key:
        if kind == "T":
            if order % 2 or not 2 <= order <= 6:
                raise ValueError(f"T_{order} is not computed")
            tm = evaluate(order // 2, alpha, pts, ctx)
            cols += [[tm[p, q] for p in range(len(pts))] for q in range(tm.shape[1])]
        elif kind == "X":  # cos and sin of one triple
            cs = [cos_sin_combination(full[p], order, ctx, fmpq(1)) for p in range(len(pts))]
            cols += [[c for c, _ in cs], [x for _, x in cs]]
        else:
            if not 0 <= order <= 3:
                raise ValueError(f"V_{order} is not computed")
            cols.append([fmpq(1)] * len(pts))
            for k in own_v_args(order):
                cs = [cos_sin_combination(full[p], k, ctx, fmpq(1)) for p in range(len(pts))]
                cols += [[c for c, _ in cs], [x for _, x in cs]]
    r = fmpq_mat([[c[p] for c in cols] for p in range(len(pts))]).rank()
    _SPAN_RANKS[key] = r
    return r


def dim_values(fn_name: str, arg: int) -> int:
    """The value of a printed dimension: ``dim_V(k)`` the rank of V_k, ``dim_T(2m)`` that of T_{2m}, ``delta(n)`` the
    number of functions of T_{2n} (:func:`paper_repro.core.labels.united_system`)."""
    if fn_name == "dim_V":
        return span_rank((("V", arg),))
    if fn_name == "dim_T":
        return span_rank((("T", arg),))
    if fn_name == "delta":
        return len(united_system(arg))
    raise ValueError(f"unknown {fn_name}")


def eval_dims(expr, n: int):
    """A printed expression in n, dimensions and delta evaluated (sums done)."""
    import sympy as sp

    e = expr.subs(sp.Symbol("n"), n).doit()
    for f in sorted(e.atoms(sp.Function), key=str):
        if f.func.__name__ in ("dim_V", "dim_T", "delta"):
            if not f.args[0].is_Integer:
                raise ValueError(f"{f}: argument not an integer")
            e = e.subs(f, dim_values(f.func.__name__, int(f.args[0])))
    if not e.is_Integer:
        raise ValueError(f"{e} is not a number")
    return int(e)


def read_E_n() -> tuple[list, callable]:
    """The printed E_n: ``E_{n}^{\\alpha}=\\left\\{ ru+gv+bw:r,g,b\\in\\mathbb{N} ,~lo\\leq r,g,b\\leq hi\\right\\}``
    -> (the coefficient letters in the order of u, v, w, n -> the set of triples).  Read by
    :func:`~paper_repro.printed.latex_math.parse_relation`: ``E(n) = Family(r*u + g*v + b*w, conditions, ())``, the
    conditions as the reader splits them at the commas: ``r, g, In(b, N_bb), lo <= r, g, b <= hi``."""
    import sympy as sp

    rel = lm.parse_relation(verbatim("sec4_5-E-n"))
    if rel.ops != ["="] or rel.conditions or rel.parts[0] != sp.Function("E")(sp.Symbol("n")) or \
            getattr(rel.parts[1], "func", None) != lm.Family or rel.parts[1].args[2] != sp.Tuple():
        raise LatexMathError("unread E_n: not E_{n} = {X : ..}")
    combo, conds = rel.parts[1].args[0], list(rel.parts[1].args[1])
    if len(conds) != 6 or not all(isinstance(conds[k], sp.Symbol) for k in (0, 1, 4)) or \
            getattr(conds[2], "func", None) != sp.Function("In"):
        raise LatexMathError("unread E_n: the conditions are not 'r,g,b in N, lo <= r,g,b <= hi'")
    letters3, nat = conds[2].args
    lo_rel, hi_rel = conds[3], conds[5]
    if nat != sp.Symbol("N_bb") or not isinstance(lo_rel, sp.LessThan) or not isinstance(hi_rel, sp.LessThan):
        raise LatexMathError("unread E_n: the letters are not natural numbers between two bounds")
    names = [str(conds[0]), str(conds[1]), str(letters3)]
    names2 = [str(lo_rel.rhs), str(conds[4]), str(hi_rel.lhs)]
    if names != names2 or len(set(names)) != 3:
        raise LatexMathError("the letters of the set and of the bounds differ")
    u, v, w = sp.symbols("u v w")
    poly = sp.Poly(section_names(combo), u, v, w)
    letters = [poly.coeff_monomial(x) for x in (u, v, w)]
    if [str(x) for x in letters] != [str(x) for x in sorted(letters, key=lambda s: names.index(str(s)))] or \
            {str(x) for x in letters} != set(names) or poly.coeff_monomial(1) != 0:
        raise LatexMathError("the combination does not use the three letters once each")
    lo_e, hi_e = section_names(lo_rel.lhs), section_names(hi_rel.rhs)

    def members(n: int) -> list:
        a, b = lo_e.subs("n", n), hi_e.subs("n", n)
        return list(product(range(int(a), int(b) + 1), repeat=3))

    return names, members


def _dimension_items() -> dict[str, bool]:
    import sympy as sp

    out: dict[str, bool] = {}
    # E_n and its classes: 1 + 2 (#classes - 1) = delta_n, the classes give independent cos/sin (rank)
    _, members = read_E_n()
    out["E_n_classes_give_delta_n"] = all(
        set(members(n)) == set(E(n)) and 1 + 2 * (len({class_key(t) for t in members(n)}) - 1) == len(united_system(n))
        for n in range(1, 9))
    out["V_n_rank_is_delta_n"] = all(span_rank((("V", n),)) == len(united_system(n)) for n in (1, 2, 3))
    # order 2: new linearly independent functions; V_2 = span V_2
    d = lm.sentence(r"generate new linearly independent constrained trivariate cosine and sine functions over "
                    r"$\Omega^{\alpha}$, i.e., {space}span~{system}", verbatim("sec4_5-n2-independent"))
    # the word "span" between the two segments is the operator: V_2 = span V_2 read as one relation
    eq = lm.parse_relation(d["space"] + r"\operatorname{span}" + d["system"]) if d else None
    vcal, span_v = sp.Function("Vcal"), sp.Function("span")
    out["order_2_independent"] = eq is not None and eq.ops == ["="] and not eq.conditions and \
        eq.parts[0].func == vcal and eq.parts[1].func == span_v and eq.parts[1].args[0].func == sp.Function("V") and \
        eq.parts[0].args == eq.parts[1].args[0].args == (2,) and \
        span_rank((("V", 2),)) == 1 + 2 * (len(classes_of(2)) - 1) and span_rank((("V", 2),)) > span_rank((("V", 1),))
    # V_n = V_{n-1} with 6n new linearly independent functions, n >= 1
    d = lm.sentence(r"if {start} the function system $V_{n}^{\alpha}$ can be obtained by completing "
                    r"$V_{n-1}^{\alpha}$ with {count} new linearly independent", verbatim("sec4_5-prop-6n"))
    if not d:
        raise ValueError("unread prop-6n")
    start = lm.parse_relation(d["start"])
    if start.parts[0] != sp.Symbol("n") or start.ops != [">="] or not start.parts[1].is_Integer:
        raise ValueError("prop-6n: the start is not n >= a number")
    count, n0 = parse(d["count"]), int(start.parts[1])
    out["6n_new"] = n0 >= 1 and all(
        span_rank((("V", n),)) - span_rank((("V", n - 1),)) == count.subs("n", n) for n in range(n0, 4))
    # the recurrence, its start, the sum and the closed form
    rec = lm.parse_relation(verbatim("sec4_5-dim-recurrence"))
    cond = rec.conditions[0] if len(rec.conditions) == 1 else None
    rec_n0 = int(cond.parts[1]) if cond is not None and cond.ops == [">="] and cond.parts[0] == sp.Symbol("n") and \
        cond.parts[1].is_Integer and not cond.conditions else None
    parts = [section_names(x) for x in rec.parts]
    out["recurrence"] = rec_n0 is not None and rec_n0 >= 1 and rec.ops == ["="] and len(parts) == 2 and all(
        eval_dims(parts[0], n) == eval_dims(parts[1], n) for n in range(rec_n0, 4))
    d = lm.sentence("{initial}", verbatim("sec4_5-dim-initial"))
    ini = chain(d["initial"]) if d else []
    out["initial"] = len(ini) == 2 and eval_dims(ini[0], 0) == eval_dims(ini[1], 0) and ini[0].has(
        sp.Function("dim_V"))
    for key, lid, ns in (("sum", "sec4_5-dim-sum", range(1, 4)), ("closed", "sec4_5-dim-closed", range(1, 13))):
        parts = chain(verbatim(lid))
        out[key] = len(parts) >= 2 and all(len({eval_dims(x, n) for x in parts}) == 1 for n in ns)
    return out


@line_check("sec4_5-dimension")
def check_dimension() -> LineResult:
    how = ("every item read from the transcriptions (E_n, the counts 6n, the recurrence with n >= 1, dim V_0, the sum "
           "and the closed form) against exact ranks of cos/sin of one triple per class of E_k at delta_3 + 4 "
           "rational points (k <= 3) and the number of functions of T_{2n}; class counts of E_n, n = 1..8; the "
           "closed form n = 1..12")
    return items_result(_dimension_items, how, "exact-evidence", (ValueError, TypeError, AttributeError))


def _space(x, n: int) -> tuple[str, int]:
    r"""``("T", 2n)`` / ``("V", n)`` of a parsed space at order n: ``Tcal(2n)`` (:math:`\mathcal{T}_{2n}`),
    ``span(T(2n))``, ``span(V(n))``, ``Vcal(n)``; :class:`LatexMathError` for anything else."""
    import sympy as sp

    head = getattr(x, "func", None)
    if head == sp.Function("span") and len(x.args) == 1:
        x, head = x.args[0], getattr(x.args[0], "func", None)
        kind = {sp.Function("T"): "T", sp.Function("V"): "V"}.get(head)
    else:
        kind = {sp.Function("Tcal"): "T", sp.Function("Vcal"): "V"}.get(head)
    if kind is None or len(x.args) != 1:
        raise LatexMathError(f"{x} is not a space T_{{..}}, V_{{..}} or their span")
    idx = x.args[0].subs(sp.Symbol("n"), n)
    if not idx.is_Integer:
        raise LatexMathError(f"the index of {x} is not an integer at n = {n}")
    return kind, int(idx)


def read_spans(tex: str, n: int) -> list[tuple[str, int]]:
    """The spaces ``\\mathcal{T}_{2n}``, ``\\operatorname{span}T_{2n}``, ``\\operatorname{span}V_{n}``,
    ``\\mathcal{V}_{n}`` of a printed chain of '=' (read by :func:`~paper_repro.printed.latex_math.parse_relation`),
    in order, their indices at order n."""
    rel = lm.parse_relation(tex)
    if set(rel.ops) != {"="} or rel.conditions:
        raise LatexMathError("not a chain of '='")
    return [_space(x, n) for x in rel.parts]


def _coincidence_items() -> dict[str, bool]:
    import sympy as sp

    out: dict[str, bool] = {}
    for lid in ("sec4_5-theorem", "sec4_5-conclusion"):
        tex = verbatim(lid)
        if lid == "sec4_5-conclusion":
            d = lm.sentence("therefore {chain}", tex)
            if not d:
                raise LatexMathError(f"{lid}: not 'therefore $..$'")
            tex = d["chain"]
        ok = len(lm.parse_relation(tex).ops) == 3
        for n in (1, 2):
            sp_ = read_spans(tex, n)
            ok &= len(sp_) == 4 and span_rank(tuple(sp_)) == span_rank((sp_[0],)) == span_rank((sp_[-1],))
            ok &= all(span_rank((x,)) == span_rank(tuple(sp_)) for x in sp_)
        out[lid] = ok
    d = lm.sentence("The system {system} of constrained trivariate functions forms a basis of the vector space {space}",
                    verbatim("sec4_5-theorem-statement"))
    ok = bool(d)
    if d:
        system, space = parse(d["system"]), parse(d["space"])
        ok = getattr(system, "func", None) == sp.Function("T") and getattr(space, "func", None) == sp.Function("Vcal")
        for n in (1, 2):
            t_, v_ = _space(sp.Function("span")(system), n), _space(space, n)
            ok &= span_rank((t_,)) == span_rank((t_, v_)) == span_rank((v_,)) == len(united_system(t_[1] // 2))
    out["basis"] = ok
    # 1 + delta_n = dim span{sigma, span T_2n} <= dim span V_n = delta_n
    rel = lm.parse_relation(verbatim("sec4_5-contradiction"))
    dim, span_ = sp.Function("dim"), sp.Function("span")
    ok = rel.ops == ["=", "<=", "="] and not rel.conditions
    if ok:
        left, with_sigma, dim_v, right = (section_names(x) for x in rel.parts)
        inner = with_sigma.args[0] if with_sigma.func == dim and len(with_sigma.args) == 1 else None
        fam = inner.args[0] if getattr(inner, "func", None) == span_ and len(inner.args) == 1 else None
        ok = getattr(fam, "func", None) == lm.Family and fam.args[1:] == (sp.Tuple(), sp.Tuple()) and \
            len(fam.args[0]) == 2 and fam.args[0][0] == sp.Symbol("sigma") and dim_v.func == dim
    if ok:
        for n in (1, 2, 3):
            t_, v_ = _space(fam.args[0][1], n), _space(dim_v.args[0], n)
            # sigma outside span T: the dimension grows by one; sigma and T in span V: at most dim V
            ok &= t_[0] == "T" and v_[0] == "V" and dim_v.args[0].func == span_
            ok &= eval_dims(left, n) == span_rank((t_,)) + 1
            ok &= span_rank((t_, v_)) == span_rank((v_,)) == eval_dims(right, n)
            ok &= eval_dims(left, n) > eval_dims(right, n)  # the contradiction
    out["contradiction"] = ok
    parts = chain(verbatim("sec4_5-dim-T"))
    out["delta_is_dim_T"] = len(parts) == 2 and all(
        eval_dims(parts[0], n) == eval_dims(parts[1], n) == span_rank((("T", 2 * n),)) for n in (1, 2, 3))
    return out


@line_check("sec4_5-coincidence-rank")
def check_coincidence_rank() -> LineResult:
    how = ("the spaces of each line read from the transcriptions (T_{2n}, V_n, their indices, the relations) and "
           "compared by exact ranks of their unions at delta_3 + 4 rational points of Omega^alpha (tan(alpha/4) = "
           "1/3, n <= 3); the inclusion itself is proven by sec4_5-inclusion")
    return items_result(_coincidence_items, how, "exact-evidence", (ValueError, TypeError, AttributeError))


# -- proof of the coincidence theorem -----------------------------------------------------------------------------
def half_angle_exponents(expr) -> tuple[int, ...]:
    """The exponents (sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2) of a printed product of half-angle
    powers (``LatexMathError`` for anything else)."""
    import sympy as sp

    out = [sp.Integer(0)] * 6
    for f in sp.Mul.make_args(expr):
        base, p = (f.base, f.exp) if f.is_Pow else (f, sp.Integer(1))
        if not isinstance(base, (sp.sin, sp.cos)) or p.has(sp.sin, sp.cos) or not p.free_symbols <= set(
                sp.symbols("n i j")):
            raise LatexMathError(f"{f} is not a power of a half-angle function")
        arg = base.args[0]
        var = [k for k, x in enumerate(sp.symbols("u v w")) if arg == x / 2]
        if len(var) != 1:
            raise LatexMathError(f"argument {arg} is not u/2, v/2 or w/2")
        out[2 * var[0] + (1 if isinstance(base, sp.cos) else 0)] += p
    return tuple(out)


def read_proof_r() -> tuple:
    """The ranges j = a..b, i = c..d (read from both lines that print them: they must agree), the second listed item
    of each range, the printed indices of R_{2n,2n-i,j} and its printed product of half-angle powers.  The words by
    :func:`~paper_repro.printed.latex_math.sentence`, the ranges by :func:`paper_repro.printed.parsed.listed`, the
    function by :func:`~paper_repro.printed.latex_math.parse_relation` (the line ends inside its ``$..$``)."""
    import sympy as sp

    from paper_repro.printed.parsed import listed, listed_range

    templates = {"sec4_5-proof-symmetry-reduction": "... it is sufficient to show that for all indices {j} and {i}",
                 "sec4_5-proof-R": "indices {j} and {i} the function ${function:words}"}
    rng, found = set(), {}
    for lid, template in templates.items():
        found[lid] = d = lm.sentence(template, verbatim(lid))
        if not d:
            raise LatexMathError(f"{lid}: no ranges of j and i")
        items = {x: tuple(listed(d[x], x)) for x in ("j", "i")}
        rng.add((listed_range(d["j"], "j")[1:], listed_range(d["i"], "i")[1:], items["j"], items["i"]))
    if len(rng) != 1:
        raise LatexMathError("the two lines print different ranges")
    (jr, ir, jitems, iitems) = rng.pop()
    rel = lm.parse_relation(found["sec4_5-proof-R"]["function"])
    head = rel.parts[0]
    n, u, v, w = sp.symbols("n u v w")
    if rel.ops != ["="] or rel.conditions or getattr(head, "func", None) != sp.Function("R") or len(head.args) != 4 \
            or head.args[0] != 2 * n or head.args[3] != sp.Tuple(u, v, w):
        raise LatexMathError("no R_{2n,..}(u,v,w) = ..")
    second = {"j": jitems[1], "i": iitems[1]}
    return jr, ir, second, head.args[1], head.args[2], rel.parts[1]


def _proof_reduction() -> dict[str, bool]:
    import sympy as sp


    jr, ir, second, first_idx, level_idx, formula = read_proof_r()
    ns, is_, js = sp.symbols("n i j")
    ok_formula, ok_cover, ok_steps = True, True, True
    expo = sp.lambdify((ns, is_, js), half_angle_exponents(formula))
    idx = sp.lambdify((ns, is_, js), (first_idx, level_idx))
    perms = [p for p in product(range(3), repeat=3) if len(set(p)) == 3]
    for n in range(1, 7):
        pairs = []
        j_lo, j_hi = bound(jr[0], n=n), bound(jr[1], n=n)
        for j in range(j_lo, j_hi + 1):
            for i in range(bound(ir[0], n=n, j=j), bound(ir[1], n=n, j=j) + 1):
                pairs.append((i, j))
        for var, item in second.items():  # the second listed element is the first plus one
            lo = bound((jr if var == "j" else ir)[0], n=n, j=j_lo)
            ok_steps &= item.subs({ns: n, is_: lo, js: lo}) == lo + 1
        for i, j in pairs:
            a_, b_ = idx(n, i, j)
            if Q(a_).denominator != 1 or Q(b_).denominator != 1:
                ok_formula = False
                continue
            ii, jj = 2 * n - int(a_), int(b_)
            try:
                truth = r_exponents(n, ii, jj)
            except ValueError:
                ok_formula = False
                continue
            ok_formula &= tuple(expo(n, i, j)) == truth
        reps = {tuple(sorted(((e[0], e[1]), (e[2], e[3]), (e[4], e[5]))))
                for e in (r_exponents(n, i, j) for i, j in pairs if 0 <= j <= n and j <= i <= 2 * n - j)}
        mem = {tuple(sorted(((e[0], e[1]), (e[2], e[3]), (e[4], e[5]))))
               for e in (exponents(lab) for lab in united_system(n))}
        ok_cover &= mem <= reps
        # the reduction is by the symmetries (permutations of u, v, w): each member is a permutation of one of them
        ok_cover &= all(any(tuple(((e[0], e[1]), (e[2], e[3]), (e[4], e[5]))[p[k]] for k in range(3)) in {
            ((x[0], x[1]), (x[2], x[3]), (x[4], x[5])) for x in (r_exponents(n, i, j) for i, j in pairs)}
            for p in perms) for e in (exponents(lab) for lab in united_system(n)))
    d = lm.sentence(r"First of all, we prove that functions of the system (\ref{{system:word}}) are elements of "
                    r"{space}. Due to symmetry properties of functions (\ref{{r:word}}), (\ref{{g:word}}) and "
                    r"(\ref{{b:word}}), it is sufficient to show that for all indices {j} and {i}",
                    verbatim("sec4_5-proof-symmetry-reduction"))
    words = bool(d) and [d[k] for k in ("system", "r", "g", "b")] == [
        "united_system", "R_system", "G_system", "B_system"] and parse(d["space"]) == sp.Function("span")(
        sp.Function("V")(ns))
    return {"formula_is_R": ok_formula, "every_member_a_permutation_of_one": ok_cover, "listed_steps": ok_steps,
            "by_symmetry": words}


@line_check("sec4_5-proof-reduction")
def check_proof_reduction() -> LineResult:

    how = ("the ranges of j and i (read from both lines), the printed indices and product of R_{2n,2n-i,j} (read) "
           "against the exponents of R_system (core.labels.r_exponents); every function of T_{2n} is a permutation "
           "of the variables of one printed R (n <= 6)")
    return items_result(_proof_reduction, how, "exhaustive", (LatexMathError, ValueError, TypeError))


#: the lines of the power-reduction identities: (odd line with the left side, even line)
POWER_LINES = {"cos": ("sec4_5-cos-power-odd", "sec4_5-cos-power-even"),
               "sin": ("sec4_5-sin-power-odd", "sec4_5-sin-power-even")}


def _parities(cond, names: tuple[str, ...]) -> tuple[int, ...]:
    r"""The residues mod 2 of ``names`` for which a parsed condition holds, found by evaluating it at 0..3 for each
    name: ``Eq(Mod(m + 1, 2), 0)`` gives ``(1,)``, ``Eq(Mod(i, 2), 0) & Eq(Mod(j, 2), 0)`` gives ``(0, 0)``; a clause
    ``m\equiv r (mod q)`` (a :class:`Relation` ``m equiv (r, q)``) is first made ``Eq(Mod(m - r, q), 0)``.
    :class:`LatexMathError` if the condition is not one parity class."""
    import sympy as sp

    if isinstance(cond, lm.Relation):
        if cond.ops != ["equiv"] or cond.conditions or not isinstance(cond.parts[1], sp.Tuple) or \
                len(cond.parts[1]) != 2:
            raise LatexMathError(f"{cond.parts} is not a congruence")
        cond = sp.Eq(sp.Mod(cond.parts[0] - cond.parts[1][0], cond.parts[1][1]), 0)
    syms = [sp.Symbol(x) for x in names]
    if not cond.free_symbols <= set(syms):
        raise LatexMathError(f"the condition {cond} names more than {names}")
    truth = {k: bool(cond.subs(dict(zip(syms, k)))) for k in product(range(4), repeat=len(syms))}
    held = {tuple(x % 2 for x in k) for k, v in truth.items() if v}
    if len(held) != 1 or any(truth[k] != (tuple(x % 2 for x in k) in held) for k in truth):
        raise LatexMathError(f"the condition {cond} is not one parity class of {names}")
    return held.pop()


def read_power_reduction(which: str) -> tuple:
    """The printed left side and the two cases ``(right side, parity)`` of the power reduction of ``which``: the odd
    line ``lhs & =\\left\\{ \\begin{array}.. value, & condition,\\\\`` by
    :func:`~paper_repro.printed.latex_math.parse_relation` (``lhs = Cases((value, condition))``), the even line
    (the array's next row) likewise (``value`` with the clause ``m equiv (0, 2)``)."""
    import sympy as sp

    odd, even = (lm.parse_relation(verbatim(x)) for x in POWER_LINES[which])
    if odd.ops != ["="] or len(odd.parts) != 2 or getattr(odd.parts[1], "func", None) != lm.Cases or \
            len(odd.parts[1].args) != 1 or odd.conditions:
        raise LatexMathError(f"{which}: not 'lhs = {{ value, condition' (one row)")
    if even.ops or len(even.parts) != 1 or len(even.conditions) != 1:
        raise LatexMathError(f"{which}: the second row is not 'value, condition'")
    (value, cond), = odd.parts[1].args
    lhs = section_names(odd.parts[0])
    cases = [(section_names(value), _parities(cond, ("m",))[0]),
             (section_names(even.parts[0]), _parities(even.conditions[0], ("m",))[0])]
    if not all(isinstance(c[0], sp.Expr) for c in cases):
        raise LatexMathError(f"{which}: a case is not an expression")
    return lhs, cases


def power_reduction_holds(which: str, m_max: int = 16) -> dict[str, bool]:
    """Each printed case at every m of its parity (0..m_max), both sides expanded exactly in t."""
    import sympy as sp

    lhs, cases = read_power_reduction(which)
    m_, t = sp.symbols("m t")
    out = {}
    if sorted(c[1] for c in cases) != [0, 1]:
        return {"parities": False}
    for rhs, parity in cases:
        ok = True
        for m in range(parity, m_max + 1, 2):
            ok &= to_ep(lhs.subs(m_, m), (t,)) == to_ep(sp.expand(rhs.subs(m_, m).doit()), (t,))
        out[f"{which}_{'odd' if parity else 'even'}"] = ok
    return out


@line_check("sec4_5-power-reduction")
def check_power_reduction() -> LineResult:

    how = ("both printed cases of each identity (left side, right side, sums with their bounds and parity, read from "
           "the transcriptions) expanded exactly in t at every m = 0..16 of the case's parity; m in N, t in R read")
    try:
        out = {**power_reduction_holds("cos"), **power_reduction_holds("sin")}
        out["ranges_m_in_N_t_in_R"] = lm.sentence(r"($m\in\mathbb{N}$, $t\in\mathbb{R}$)",
                                                  verbatim("sec4_5-power-ranges")) is not None
    except (LatexMathError, TypeError, ValueError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(out.values()), how=how, kind="exhaustive", detail=out)


def factor_support(power: int, base: str) -> tuple[str, list[int]]:
    """Type ('cos'/'sin') and the k's of the expansion of base^power(t/2) (frequency (power - 2k)/2 >= 0)."""
    ep = (EP.cos((Q(1, 2),)) if base == "cos" else EP.sin((Q(1, 2),))) ** power
    kind = "cos" if ep.is_cosine_series() else "sin" if ep.is_sine_series() else "mixed"
    ks = sorted(int(Q(power, 2) - f[0]) for f in ep.terms if f[0] >= 0)
    return kind, ks


K_LINES = {"0,0": "sec4_5-K00", "1,1": "sec4_5-K11", "0,1": "sec4_5-K01", "1,0": "sec4_5-K10"}


def listed_values(items: list, env: dict) -> list[int]:
    """The integers of a printed listed set ``{a, b, \\ldots, c}`` (items parsed, ``None`` for ``\\ldots``) at ``env``:
    listed neighbours step by 1, the set is first..last (``{0,1,\\ldots,0}`` is {0}); ``ValueError`` otherwise (a
    bound that is not an integer, such as (i-j)/2 with i - j odd, included)."""
    vals = [None if e is None else e.subs(env) for e in items]
    for x in vals:
        if x is not None and not x.is_Integer:
            raise ValueError(f"element {x} is not an integer")
    if vals[0] is None or vals[-1] is None:
        raise ValueError("an ellipsis at an end")
    for k in range(len(vals) - 1):
        x, y = vals[k], vals[k + 1]
        if x is not None and y is not None and y - x != 1:
            raise ValueError(f"listed neighbours {x}, {y} do not step by 1")
    if vals[-1] < vals[0]:
        raise ValueError("the last element is below the first")
    return list(range(int(vals[0]), int(vals[-1]) + 1))


def read_k_sets(line_id: str) -> tuple[str, list]:
    """``(case, [four listed sets])`` of a printed ``K_{a,b} & =\\left\\{ 0,1,\\ldots,\\frac{..}{..}\\right\\}
    \\times ..``: each set as its parsed items (``None`` for ``\\ldots``).  Read by
    :func:`~paper_repro.printed.latex_math.parse_relation`: ``K(a, b) = Cartesian(Family(Tuple(0, 1, ldots, x)),
    ..)``, the factors in the printed order."""
    import sympy as sp

    rel = lm.parse_relation(verbatim(line_id))
    head = rel.parts[0]
    if rel.ops != ["="] or rel.conditions or getattr(head, "func", None) != sp.Function("K") or len(head.args) != 2 \
            or not all(x.is_Integer for x in head.args):
        raise LatexMathError(f"{line_id}: not K_{{a,b}} = ..")
    prod_ = rel.parts[1]
    factors = prod_.args if getattr(prod_, "func", None) == lm.Cartesian else (prod_,)
    sets = []
    for f in factors:
        if getattr(f, "func", None) != lm.Family or f.args[1:] != (sp.Tuple(), sp.Tuple()):
            raise LatexMathError(f"{line_id}: the factor {f} is not a listed set")
        items = f.args[0] if isinstance(f.args[0], sp.Tuple) else (f.args[0],)
        sets.append([None if x == lm.LDOTS else section_names(x) for x in items])
    return f"{head.args[0]},{head.args[1]}", sets


def true_k_ranges(n: int, i: int, j: int) -> list[list[int]]:
    """The k's with a non-zero term in the exact expansion of sin^{2n-i}(u/2), sin^i(w/2), cos^{i-j}(v/2),
    sin^j(v/2) (the powers of R_{2n,2n-i,j}, core.labels.r_exponents), in the order k1..k4 of
    possible_products_inclusion."""
    e = r_exponents(n, i, j)
    return [factor_support(e[0], "sin")[1], factor_support(e[4], "sin")[1], factor_support(e[3], "cos")[1],
            factor_support(e[2], "sin")[1]]


def k_sets_agree(line_id: str, n_max: int = 6, fix_third: bool = False) -> bool:
    """The printed K_{a,b} (read) equals the true ranges of k for every (i, j) of parity (a, b), n <= n_max;
    ``fix_third``: the third factor's upper end lowered by 1/2 (the correction of K_{1,0})."""
    import sympy as sp

    case, sets = read_k_sets(line_id)
    if len(sets) != 4:
        return False
    if fix_third:
        sets = [*sets[:2], [*sets[2][:-1], sets[2][-1] - sp.Rational(1, 2)], sets[3]]
    a, b = (int(x) for x in case.split(","))
    ns, is_, js = sp.symbols("n i j")
    for n in range(1, n_max + 1):
        for j in range(n + 1):
            for i in range(j, n + 1):
                if (i % 2, j % 2) != (a, b):
                    continue
                try:
                    got = [listed_values(x, {ns: n, is_: i, js: j}) for x in sets]
                except ValueError:
                    return False
                if got != true_k_ranges(n, i, j):
                    return False
    return True


def k_case_check(case: str) -> LineResult:

    line_id = K_LINES[case]
    how = ("the four listed sets of K_{a,b} (every element read from the transcription; each must be a run of "
           "integers) against the k's with a non-zero term in the exact expansion of each factor of R_{2n,2n-i,j}, "
           "every (i, j) of parity (a, b), n <= 6")
    try:
        read_case = read_k_sets(line_id)[0]
        printed = read_case == case and k_sets_agree(line_id)
        corrected = read_case == case and k_sets_agree(line_id, fix_third=True) if case == "1,0" else None
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(printed, corrected if not printed else None, how=how, kind="exhaustive",
                      detail={"case_i_j_mod_2": case, "printed_holds": printed, "corrected_holds": corrected,
                              "example": "n=2, i=1, j=0: third factor cos^1(v/2) has k in {0}; printed bound "
                                         f"(i-j)/2 = {Q(1, 2)}"})


for _case in ("0,0", "1,1", "0,1", "1,0"):
    line_check(f"sec4_5-K-{_case.replace(',', '')}")(lambda _c=_case: k_case_check(_c))


PRODUCT_LINES = ("sec4_5-product-type-1", "sec4_5-product-type-2", "sec4_5-product-type-3", "sec4_5-product-type-4")
_KSYMS = "n i j k1 k2 k3 k4"


def read_product_types() -> dict[tuple[int, int], object]:
    """``{(i mod 2, j mod 2): product}`` of the printed cases of possible_products_inclusion: each row
    ``product, & i\\equiv a\\left(\\operatorname{mod}2\\right) \\text{ and }j\\equiv b..`` read by
    :func:`~paper_repro.printed.latex_math.parse_relation` (the product and its one clause, a sympy boolean), the
    parities by :func:`_parities`."""
    import sympy as sp

    out = {}
    for lid in PRODUCT_LINES:
        rel = lm.parse_relation(verbatim(lid))
        if rel.ops or len(rel.parts) != 1 or len(rel.conditions) != 1 or rel.conditions[0].ops or \
                len(rel.conditions[0].parts) != 1 or not isinstance(rel.conditions[0].parts[0], sp.And):
            raise LatexMathError(f"{lid}: unread condition")
        key = _parities(rel.conditions[0].parts[0], ("i", "j"))
        if key in out:
            raise LatexMathError(f"{lid}: case {key} printed twice")
        out[key] = section_names(rel.parts[0])
    return out


def r_in_span_of(expr, n_max: int = 3, parity=None) -> bool:
    """R_{2n,2n-i,j} (exact expansion of core.labels.r_exponents) lies in the span of the printed product ``expr``
    over the k's of the exact expansions of its factors (:func:`true_k_ranges`), for every (i, j) of the given
    parity, n <= n_max."""
    import sympy as sp

    u, v, w = sp.symbols("u v w")
    f = compile_ep(expr, (u, v, w), sp.symbols(_KSYMS))
    for n in range(1, n_max + 1):
        for j in range(n + 1):
            for i in range(j, n + 1):
                if parity is not None and (i % 2, j % 2) != parity:
                    continue
                target = half_monomial(r_exponents(n, i, j))
                cols = [f((n, i, j, *k)) for k in product(*true_k_ranges(n, i, j))]
                keys = sorted({x for c in [*cols, target] for x in c.terms})

                def column(ep, keys=keys):
                    return [q for x in keys for q in ep.terms.get(x, (Q(0), Q(0)))]

                mat = [column(c) for c in cols]
                tcol = column(target)
                rows = range(len(keys) * 2)
                a = fmpq_mat([[fmpq(c[r].numerator, c[r].denominator) for c in mat] for r in rows])
                b = fmpq_mat([[fmpq(c[r].numerator, c[r].denominator) for c in [*mat, tcol]] for r in rows])
                if a.rank() != b.rank():
                    return False
    return True


@line_check("sec4_5-product-types")
def check_product_types() -> LineResult:
    """Each printed case (product and parity condition read) spans R_{2n,2n-i,j} of its parity; the parity line's
    powers are read."""
    import sympy as sp

    how = ("each printed product (read) over the k's of the factors' expansions spans the exact expansion of "
           "R_{2n,2n-i,j} for every "
           "(i, j) of the printed parity, n <= 3; the four cases are the four parities; the parity line names the "
           "four powers of R (read, against core.labels.r_exponents, n <= 4)")
    try:
        types = read_product_types()
        out = {f"{a},{b}": r_in_span_of(p, 3, (a, b)) for (a, b), p in types.items()}
        out["four_parities"] = sorted(types) == [(0, 0), (0, 1), (1, 0), (1, 1)]
        d = lm.sentence(r"and by the parity of powers {p1}, {p2}, {p3} and {p4}, one can easily see that function "
                        r"$R_{2n,2n-i,j}^{\alpha}\left( u,v,w\right)$ can be written as the sum of products of the "
                        r"type%", verbatim("sec4_5-parity"))
        if not d:
            raise LatexMathError("unread parity line")
        powers = [parse(d[f"p{k}"]) for k in (1, 2, 3, 4)]
        ns, is_, js = sp.symbols("n i j")
        out["powers_of_R"] = all(
            sorted(int(p.subs({ns: n, is_: i, js: j})) for p in powers) == sorted(
                x for k, x in enumerate(r_exponents(n, i, j)) if k in (0, 2, 3, 4))
            for n in range(1, 5) for j in range(n + 1) for i in range(j, n + 1))
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(out.values()), how=how, kind="exhaustive", detail=out)


@line_check("sec4_5-product-to-sum")
def check_product_to_sum() -> LineResult:
    """Each printed identity (both sides read) expanded exactly in the independent variables x, y."""
    import sympy as sp

    how = "both sides of each identity read from the transcriptions, exponential expansion in x, y"
    rows = []
    try:
        for k in (1, 2, 3):
            parts = chain(verbatim(f"sec4_5-product-to-sum-{k}"))
            xy = sp.symbols("x y")
            rows.append(len(parts) == 2 and to_ep(parts[0], xy) == to_ep(parts[1], xy))
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="proof", detail={"unread": str(exc)})
    return LineResult(all(rows), how=how, kind="proof", detail={"rows": rows})


def _odd_cases(n_max: int):
    """``(n, i, j, (k1, k2, k3, k4))`` for every odd i, j (j <= i <= n) and (k1..k4) in the true K_{1,1} (the k's of
    the exact expansion of the factors, :func:`true_k_ranges`), n <= n_max."""
    for n in range(1, n_max + 1):
        for j in range(1, n + 1, 2):
            for i in range(j, n + 1, 2):
                yield from ((n, i, j, k) for k in product(*true_k_ranges(n, i, j)))


def _abcd(n, i, j, k):
    """The frequencies A, B, C, D of the four factors (u, w, cos v, sin v) of the k-th terms, from the powers of
    R_{2n,2n-i,j} (core.labels.r_exponents): (power - 2k)/2."""
    e = r_exponents(n, i, j)
    return Q(e[0] - 2 * k[0], 2), Q(e[4] - 2 * k[1], 2), Q(e[3] - 2 * k[2], 2), Q(e[2] - 2 * k[3], 2)


def _sign_index(x) -> int:
    """k of a parsed sign ``s(k)`` (``s_{k}``), :class:`LatexMathError` for anything else."""
    import sympy as sp

    if getattr(x, "func", None) != sp.Function("s") or len(x.args) != 1 or not x.args[0].is_Integer:
        raise LatexMathError(f"{x} is not a sign s_{{k}}")
    return int(x.args[0])


def read_signs() -> dict:
    """The sign values of ``where $s_{1}=1$ and $s_{2},s_{3},s_{4}\\in\\left\\{ -1,+1\\right\\} $, i.e., $s_{r}^{2}=1$,
    $r=1,2,3,4$`` (each read; s_r^p = c checked for the listed r, the power p and value c read).  The words by
    :func:`~paper_repro.printed.latex_math.sentence`, each segment by
    :func:`~paper_repro.printed.latex_math.parse_relation`: ``s(1) = 1``, ``(s(2), s(3), s(4)) in Family((-1, 1))``,
    ``s_sup(r, 2) = 1``, ``r in (1, 2, 3, 4)``."""
    import sympy as sp

    d = lm.sentence("where {fixed} and {free}, i.e., {square}, {listed}", verbatim("sec4_5-signs"))
    if not d:
        raise LatexMathError("unread signs")
    fixed, free, square, listed = (lm.parse_relation(d[k]) for k in ("fixed", "free", "square", "listed"))
    if any(x.conditions for x in (fixed, free, square, listed)) or fixed.ops != ["="] or free.ops != ["in"] or \
            square.ops != ["="] or listed.ops != ["in"]:
        raise LatexMathError("unread signs: not 's_a = c', 's_b,.. in {..}', 's_r^p = c', 'r = ..'")
    if not fixed.parts[1].is_Integer:
        raise LatexMathError("the fixed sign is not a number")
    vals = {f"s{_sign_index(fixed.parts[0])}": [int(fixed.parts[1])]}
    names, options = free.parts
    if getattr(options, "func", None) != lm.Family or options.args[1:] != (sp.Tuple(), sp.Tuple()):
        raise LatexMathError("the signs' values are not a listed set")
    opts = options.args[0] if isinstance(options.args[0], sp.Tuple) else (options.args[0],)
    if not all(x.is_Integer for x in opts):
        raise LatexMathError("a sign's value is not a number")
    for x in (names if isinstance(names, sp.Tuple) else (names,)):
        vals[f"s{_sign_index(x)}"] = [int(o) for o in opts]
    power, value = square.parts
    var, rs = listed.parts
    if getattr(power, "func", None) != sp.Function("s_sup") or len(power.args) != 2 or power.args[0] != var or \
            not isinstance(var, sp.Symbol) or not power.args[1].is_Integer or not value.is_Integer:
        raise LatexMathError("not s_{r}^{p} = c over the listed r")
    if not isinstance(rs, sp.Tuple) or lm.LDOTS in rs or not all(x.is_Integer for x in rs):
        raise LatexMathError("the indices r are not listed")
    if sorted(vals) != sorted(f"s{r}" for r in rs) or not all(
            sp.Integer(x) ** power.args[1] == value for r in rs for x in vals[f"s{r}"]):
        raise LatexMathError("s_r^2 = 1 fails for the listed r, or the listed r are not the signs")
    return vals


def _sign_assignments(vals: dict):
    names = sorted(vals)
    for combo in product(*(vals[x] for x in names)):
        yield dict(zip(names, combo))


def _freq(arg, variables) -> tuple:
    import sympy as sp

    poly = sp.Poly(sp.expand(arg), *variables)
    return tuple(Q(int(c.p), int(c.q)) for c in (poly.coeff_monomial(x) for x in variables))


@line_check("sec4_5-eight-terms")
def check_eight_terms() -> LineResult:
    """The printed product and form (read) and the signs (read): the formal expansion of the product has the printed
    number of terms, each +- the form at one choice of signs, and the product over K_{1,1} spans R_{2n,2n-i,j}."""
    import sympy as sp

    how = ("the product and the form read from the transcription, the signs read: for every odd (i, j) and (k1..k4) "
           "in K_{1,1}, n <= 3, the 2^(factors-1) formal terms of the product are, up to sign, exactly the form at "
           "the printed signs (a sine for a sine series); the product spans R_{2n,2n-i,j} (n <= 3)")
    try:
        d = lm.sentence(r"each of the {count:count} terms of the expansion of the product% \[ {product:words} \] has "
                        r"the form% \[ {form:words} \]", verbatim("sec4_5-eight-terms"))
        if not d or d["count"] is None:
            raise LatexMathError("unread line")
        count, prod_e, form = d["count"], parse(d["product"]), parse(d["form"])
        signs = read_signs()
        factors = sp.Mul.make_args(prod_e)
        if not all(isinstance(f, (sp.sin, sp.cos)) for f in factors) or not isinstance(form, (sp.sin, sp.cos)):
            raise LatexMathError("not a product of sines and cosines, or the form is not one function")
        uvw = sp.symbols("u v w")
        params = sp.symbols(_KSYMS)
        ep_prod = compile_ep(prod_e, uvw, params)
        ok_count = count == 2 ** (len(factors) - 1)
        ok_terms, ok_type = True, True
        for n, i, j, k in _odd_cases(3):
            env = dict(zip(params, (n, i, j, *k)))
            fr = [_freq(f.args[0].subs(env), uvw) for f in factors]
            formal = {tuple(sum(e * x[c] for e, x in zip(eps, fr)) for c in range(3))
                      for eps in product((-1, 1), repeat=len(fr))}
            formal = {max(f, tuple(-x for x in f)) for f in formal}
            printed = set()
            for sv in _sign_assignments(signs):
                f = _freq(form.args[0].subs(env).subs({sp.Symbol(a): b for a, b in sv.items()}), uvw)
                printed.add(max(f, tuple(-x for x in f)))
            ok_terms &= formal == printed
            ep = ep_prod((n, i, j, *k))
            ok_type &= (ep.is_sine_series() if isinstance(form, sp.sin) else ep.is_cosine_series())
        spans = r_in_span_of(prod_e, 3, (1, 1))
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    out = {"count": ok_count, "terms_are_the_form": ok_terms, "function_type": ok_type, "spans_R_odd_odd": spans}
    return LineResult(all(out.values()), how=how, kind="exhaustive", detail=out)


SHIFT_LINES = ("sec4_5-shift-step1", "sec4_5-shift-step2", "sec4_5-shift-step3")


@line_check("sec4_5-shift-chain")
def check_shift_chain() -> LineResult:
    """Every '=' of the chain (each line read; a line's first part repeats the previous line's last part): the first
    steps as identities in (u, v, w, alpha), the last one on u + v + w = alpha; every odd (i, j), K_{1,1}, the
    printed signs, n <= 3."""
    import sympy as sp

    how = ("each '=' of the three lines read from the transcriptions, expanded exactly over (u, v, w, alpha) (alpha "
           "free where the step does not use the constraint, alpha = u + v + w for the step that does), every odd "
           "(i, j), (k1..k4) in K_{1,1}, the printed signs, n <= 3")
    try:
        parts = [chain(verbatim(x)) for x in SHIFT_LINES]
        signs = read_signs()
        if [len(p) for p in parts] != [2, 2, 2]:
            raise LatexMathError(f"parts per line {[len(p) for p in parts]}")
        uvwa = (*sp.symbols("u v w"), ALPHA)
        params = (*sp.symbols(_KSYMS), *sp.symbols("s1 s2 s3 s4"))
        free = [[compile_ep(x, uvwa, params) for x in p] for p in parts]
        u, v, w = uvwa[:3]
        plane = [[compile_ep(x.subs(ALPHA, u + v + w), (u, v, w), params) for x in p] for p in parts]
        ok = {"step1_free": True, "step2_free": True, "step3_on_plane": True, "step3_not_free": False,
              "repeats": True}
        for n, i, j, k in _odd_cases(3):
            for sv in _sign_assignments(signs):
                vals = (n, i, j, *k, *(sv[f"s{r}"] for r in (1, 2, 3, 4)))
                ep = [[f(vals) for f in p] for p in free]
                ok["step1_free"] &= ep[0][0] == ep[0][1]
                ok["step2_free"] &= ep[1][0] == ep[1][1]
                ok["repeats"] &= ep[1][0] == ep[0][1] and ep[2][0] == ep[1][1]
                pl_ = [f(vals) for f in plane[2]]
                ok["step3_on_plane"] &= pl_[0] == pl_[1]
                ok["step3_not_free"] |= ep[2][0] != ep[2][1]  # the last step uses the constraint
    except (LatexMathError, ValueError, TypeError, KeyError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(ok.values()), how=how, kind="exhaustive", detail=ok)


def read_class_entries():
    """The three entries of the printed class ``\\left[ \\underset{\\in\\mathbb{N}}{\\underbrace{..}},..\\right]``
    (each marked as a natural number) and the arguments of the printed ``z=\\min\\left\\{ ..\\right\\}``."""
    import sympy as sp

    tex = verbatim("sec4_5-class-N")
    cls = lm.parse(tex)
    if getattr(cls, "func", None) != sp.Function("cls") or len(cls.args) != 1 or not isinstance(cls.args[0], sp.Tuple):
        raise LatexMathError("no class [..]")
    entries = list(cls.args[0])
    marks = lm.underset_marks(tex)  # \underset{\in\mathbb{N}}{\underbrace{X}}: the mark parse drops
    if len(marks) != len(entries) or not all(
            m.lead == "in" and m.parts == [sp.Symbol("N_bb")] and not m.ops and not m.conditions and x == e
            for (m, x), e in zip(marks, entries)):
        raise LatexMathError("an entry is not marked natural")
    entries = [section_names(e) for e in entries]
    zparts = chain(verbatim("sec4_5-z-min"))
    if len(zparts) != 2 or zparts[0] != sp.Symbol("z") or not isinstance(zparts[1], sp.Min):
        raise LatexMathError("z-min is not z = min{..}")
    return entries, zparts[1]


def shifted_truth(n, i, j, k, sv) -> tuple:
    """The coefficients of u, v, w in X - (u + v + w)/2 for the term of the odd-odd product with signs sv:
    X = A u + (s2 C + s3 D) v + s4 B w (A, B, C, D from the powers of R, :func:`_abcd`)."""
    A, B, C, D = _abcd(n, i, j, k)
    return (A - Q(1, 2), sv["s2"] * C + sv["s3"] * D - Q(1, 2), sv["s4"] * B - Q(1, 2))


@line_check("sec4_5-integer-class")
def check_integer_class() -> LineResult:
    """The printed claims after the chain (read): integer coefficients for every k of the printed K_{a,b} (the
    printed number of k's), the printed minimum z and the printed class entries (natural, the same class, in E_n),
    and "the remaining two cases": every case of the minimum."""
    import sympy as sp

    how = ("the printed K_{a,b}, tuple length, minimum and class entries read from the transcriptions against the "
           "coefficients of X - (u+v+w)/2 (A, B, C, D from the powers of R, the signs read), every (i, j) of the "
           "printed parity, n <= 4")
    try:
        d = lm.sentence(r"where for all {length}-tuples {tuple} the coefficients of variables $u$, $v$ and $w$ are "
                        r"integer numbers and both of the sine and cosine functions belong to the equivalence class%",
                        verbatim("sec4_5-integer"))
        if not d:
            raise LatexMathError("unread integer line")
        length, member = parse(d["length"]), lm.parse_relation(d["tuple"])
        ks, kset = member.parts if member.ops == ["in"] and not member.conditions else (None, None)
        if not isinstance(ks, sp.Tuple) or getattr(kset, "func", None) != sp.Function("K") or len(kset.args) != 2 \
                or not all(x.is_Integer for x in kset.args) or not length.is_Integer:
            raise LatexMathError("unread integer line: not 'n-tuples (k_1, ..) in K_{a,b}'")
        ks = [k.args[0] if getattr(k, "func", None) == sp.Function("k") and len(k.args) == 1 else None for k in ks]
        parity = (int(kset.args[0]), int(kset.args[1]))
        if max(parity) > 1:
            raise LatexMathError(f"K_{parity} is not a parity case")
        other = lm.sentence("The remaining {count:count} cases of $z$ can be treated analogously.",
                            verbatim("sec4_5-other-z-cases"))
        if not other or other["count"] is None:
            raise LatexMathError("unread remaining cases")
        entries, zmin = read_class_entries()
        signs = read_signs()
        ok = {"tuple": int(length) == len(ks) == 4 and ks == [1, 2, 3, 4],
              "remaining": other["count"] == len(zmin.args) - 1}
        ok_int = ok_min = ok_nat = True
        params = (*sp.symbols(_KSYMS), *sp.symbols("s1 s2 s3 s4"))
        fz = [sp.lambdify(params, a) for a in zmin.args]
        fe = [sp.lambdify((*params, sp.Symbol("z")), e) for e in entries]
        for n in range(1, 5):
            for j in range(n + 1):
                for i in range(j, n + 1):
                    if (i % 2, j % 2) != parity:
                        continue
                    for k in product(*true_k_ranges(n, i, j)):
                        for sv in _sign_assignments(signs):
                            truth = shifted_truth(n, i, j, k, sv)
                            ok_int &= all(x.denominator == 1 for x in truth)
                            vals = (n, i, j, *k, *(sv.get(f"s{r}", 1) for r in (1, 2, 3, 4)))
                            args = sorted(Q(f(*vals)) for f in fz)
                            ok_min &= args == sorted(truth)
                            z = min(truth)
                            ent = tuple(Q(f(*vals, z)) for f in fe)
                            nat = all(x.denominator == 1 and 0 <= x <= n for x in ent)
                            ok_nat &= nat and tuple(x - z for x in truth) == ent
        ok.update({"integer": ok_int, "min_of_the_coefficients": ok_min, "entries_natural_same_class_in_E_n": ok_nat})
    except (LatexMathError, ValueError, TypeError, KeyError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(ok.values()), how=how, kind="exhaustive", detail=ok)


def _quantified(conds) -> tuple[tuple, dict[str, list[int]]]:
    """``(the tuple a membership names, {sign: values})`` of the parsed conditions of a printed set
    ``\\left\\{ X : \\left(k_{1},..\\right)\\in K_{a,b},~s_{1}=1,s_{2},s_{3}\\in\\left\\{ -1,+1\\right\\} \\right\\}``:
    the reader gives them split at the commas, ``In(Tuple(k(1), ..), K(a, b)), Eq(s(1), 1), s(2), In(s(3), Family((-1,
    1)))``; a bare sign before a membership is listed with it (``s_{2},s_{3}\\in``).  :class:`LatexMathError` for any
    other condition."""
    import sympy as sp

    In = sp.Function("In")
    quant: dict[str, list[int]] = {}
    pending: list = []
    member = None
    for c in conds:
        if isinstance(c, sp.Eq) and c.rhs.is_Integer:
            quant[f"s{_sign_index(c.lhs)}"] = [int(c.rhs)]
        elif getattr(c, "func", None) == sp.Function("s"):
            pending.append(c)
        elif getattr(c, "func", None) == In and isinstance(c.args[0], sp.Tuple) and member is None and not pending:
            member = c
        elif getattr(c, "func", None) == In and getattr(c.args[1], "func", None) == lm.Family and \
                c.args[1].args[1:] == (sp.Tuple(), sp.Tuple()):
            opts = c.args[1].args[0] if isinstance(c.args[1].args[0], sp.Tuple) else (c.args[1].args[0],)
            if not all(o.is_Integer for o in opts):
                raise LatexMathError(f"the values {opts} are not numbers")
            for x in (*pending, c.args[0]):
                quant[f"s{_sign_index(x)}"] = [int(o) for o in opts]
            pending = []
        else:
            raise LatexMathError(f"unread quantifier {c}")
    if pending or member is None:
        raise LatexMathError("a listed sign without its set, or no tuple in K")
    return member, quant


def read_max(line_id: str) -> tuple:
    """``(expression, {sign: values} quantified, parity of K, printed value)`` of a printed max{..} = value: the
    row ``& \\max\\left\\{ X : \\left( k_{1},k_{2},k_{3},k_{4}\\right) \\in K_{a,b},~.. \\right\\} \\\\ = & value``
    read by :func:`~paper_repro.printed.latex_math.parse_relation` (``max(Family(X, conditions, ())) = value``), the
    conditions by :func:`_quantified`."""
    import sympy as sp

    rel = lm.parse_relation(verbatim(line_id))
    top = rel.parts[0]
    fam = top.args[0] if getattr(top, "func", None) == lm.FUNCS["max"] and len(top.args) == 1 else None
    if rel.ops != ["="] or rel.lead or rel.conditions or getattr(fam, "func", None) != lm.Family or fam.args[2]:
        raise LatexMathError(f"{line_id}: unread max")
    member, quant = _quantified(fam.args[1])
    kset = member.args[1]
    if member.args[0] != sp.Tuple(*(sp.Function("k")(r) for r in (1, 2, 3, 4))) or \
            getattr(kset, "func", None) != sp.Function("K") or len(kset.args) != 2 or \
            not all(x.is_Integer for x in kset.args):
        raise LatexMathError(f"{line_id}: not (k_1, k_2, k_3, k_4) in K_{{a,b}}")
    if max(kset.args) > 1:
        raise LatexMathError(f"{line_id}: K_{{{kset.args[0]},{kset.args[1]}}} is not a parity case")
    return section_names(fam.args[0]), quant, (int(kset.args[0]), int(kset.args[1])), section_names(rel.parts[1])


def _sign_names(expr) -> list[str]:
    """The names ``s1``..``s9`` of the signs an expression uses (section_names makes ``s_{k}`` the Symbol ``sk``)."""
    return sorted(str(x) for x in expr.free_symbols if len(str(x)) == 2 and str(x)[0] == "s" and str(x)[1].isdigit())


def max_values(line_id: str, quantify_free: bool, n_max: int = 6) -> bool:
    """The printed max over the printed K (true ranges of its parity) and the quantified signs equals the printed
    value for every (i, j) of that parity; a sign in the expression that is not quantified must not change the max
    (``quantify_free``: it is quantified over {-1, +1}, the correction)."""
    import sympy as sp

    expr, quant, parity, value = read_max(line_id)
    signs = _sign_names(expr)
    free = [x for x in signs if x not in quant]
    if quantify_free:
        quant = {**quant, **{x: [-1, 1] for x in free}}
        free = []
    params = (*sp.symbols(_KSYMS), *sp.symbols("s1 s2 s3 s4"))
    f = sp.lambdify(params, expr)
    fv = sp.lambdify(sp.symbols("n i j"), value)
    for n in range(1, n_max + 1):
        for j in range(n + 1):
            for i in range(j, n + 1):
                if (i % 2, j % 2) != parity:
                    continue
                for fixed in _sign_assignments({x: [-1, 1] for x in free}):
                    best = max(Q(f(n, i, j, *k, *({**{s: v[0] for s, v in quant.items()}, **sv, **fixed}.get(
                        f"s{r}", 0) for r in (1, 2, 3, 4))))
                               for k in product(*true_k_ranges(n, i, j)) for sv in _sign_assignments(quant))
                    if best != Q(fv(n, i, j)):
                        return False
    return True


def _chain_le(line_id: str) -> tuple[list, object]:
    """The '=' parts of a printed chain and its final ``\\leq`` bound (None if there is none)."""

    tex = verbatim(line_id)
    head, _, bound_ = tex.partition("\\leq")
    return chain(head), (parse(bound_) if bound_ else None)


@line_check("sec4_5-max-bounds")
def check_max_bounds() -> LineResult:
    """The first max (set, quantifiers and value read) by enumeration; the arithmetic lines (read) equal n and i
    with i <= n (the second max's value: with its sign s4 quantified, see sec4_5-max2-quantifier)."""
    import sympy as sp

    how = ("maxima by enumeration over the printed K (its true k ranges) and the printed signs, every (i, j) of its "
           "parity, n <= 6; the printed values and the chains '= n', '= i <= n' read and evaluated")
    try:
        out = {"max1": max_values("sec4_5-max1-set", False)}
        v1 = read_max("sec4_5-max1-set")[3]
        v2 = read_max("sec4_5-max2-set")[3]
        ns, is_, js = sp.symbols("n i j")
        cases = [(n, i, j) for n in range(1, 7) for j in range(1, n + 1, 2) for i in range(j, n + 1, 2)]
        p1, b1 = _chain_le("sec4_5-max1-n")
        p2, b2 = _chain_le("sec4_5-max2-i")
        out["max1_is_n"] = b1 is None and len(p1) == 2 and p1[0] == v1 and p1[1] == ns and all(
            p1[0].subs({ns: n, is_: i, js: j}) == n for n, i, j in cases)
        out["max2_is_i_le_n"] = b2 is not None and len(p2) == 2 and p2[0] == v2 and p2[1] == is_ and all(
            p2[0].subs({ns: n, is_: i, js: j}) == i <= b2.subs({ns: n, is_: i, js: j}) for n, i, j in cases)
        out["max2_value_with_s4_quantified"] = max_values("sec4_5-max2-set", True)
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(out.values()), how=how, kind="exhaustive", detail=out)


@line_check("sec4_5-max2-quantifier")
def check_max2_quantifier() -> LineResult:
    """The second max as printed: its expression has s4, its quantifiers name s1 = 1, s2, s3 (s4 free): the max is
    (i-1)/2 + (i-j)/2 + (j+1)/2 = i for s4 = +1 only; with s4 in {-1, +1} (the correction) it is i."""

    how = ("the second max read (expression, quantifiers, K, value): by enumeration over K_{1,1} and the quantified "
           "signs, each value of the unquantified s4 separately (printed) and s4 in {-1, +1} (corrected), n <= 6")
    try:
        printed, corrected = max_values("sec4_5-max2-set", False), max_values("sec4_5-max2-set", True)
        expr, quant, _, _ = read_max("sec4_5-max2-set")
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    free = [x for x in _sign_names(expr) if x not in quant]
    return LineResult(printed, corrected, how=how, kind="exhaustive",
                      detail={"quantified": sorted(quant), "unquantified_in_expression": free,
                              "example": "n = 1, i = j = 1, s4 = -1: max = 0, printed value i = 1"})


def frequency_classes(n: int) -> set:
    """Class keys of the frequencies of the exact expansion of every function of T_{2n}, each shifted by a multiple
    of (1/2)(1,1,1) to integers (a phase: u + v + w = alpha); ValueError if some frequency cannot be."""
    out = set()
    for lab in united_system(n):
        for f in half_monomial(exponents(lab)).terms:
            shift = f[0] - int(f[0]) if f[0] >= 0 else f[0] - int(f[0])
            g = tuple(x - shift for x in f)
            if any(x.denominator != 1 for x in g):
                raise ValueError(f"frequency {f} is not an integer triple plus a multiple of (1,1,1)")
            out.add(class_key(tuple(int(x) for x in g)))
    return out


def read_union(union) -> tuple:
    """``(a, b)`` of a parsed ``\\cup_{i=a}^{b}E_{i}^{\\alpha}/_{\\sim}``: ``bigcup(Family(quot(E(i)), (), ((i, a,
    b),)))`` (:func:`~paper_repro.printed.latex_math.parse`)."""
    import sympy as sp

    fam = union.args[0] if getattr(union, "func", None) == sp.Function("bigcup") and len(union.args) == 1 else None
    if getattr(fam, "func", None) != lm.Family or fam.args[1] or len(fam.args[2]) != 1:
        raise LatexMathError(f"{union} is not a union over one bound")
    (var, lo, hi), = fam.args[2]
    if fam.args[0] != sp.Function("quot")(sp.Function("E")(var)):
        raise LatexMathError(f"{fam.args[0]} is not E_{{{var}}}/~ of the bound variable")
    return lo, hi


def union_holds(union, v_idx) -> bool:
    """The classes of every frequency of T_{2n} lie in the printed union cup_{i=a}^{b} E_i/~ (parsed; bounds read),
    which lies in the classes of the printed V (its index ``v_idx`` parsed), n = 1..3."""
    import sympy as sp

    ns = sp.Symbol("n")
    lo, hi = read_union(union)
    good = True
    for n in (1, 2, 3):
        a, b, v = int(lo.subs(ns, n)), int(hi.subs(ns, n)), int(v_idx.subs(ns, n))
        union_ = set().union(*(classes_of(x) for x in range(a, b + 1))) if b >= a else set()
        good &= frequency_classes(n) <= union_ <= classes_of(v)
    return good


def _space_index(x, letter: str) -> tuple[bool, object]:
    """``(printed as a span, index)`` of a parsed ``X_{idx}`` or ``\\operatorname{span}X_{idx}`` with X = ``letter``."""
    import sympy as sp

    spanned = getattr(x, "func", None) == sp.Function("span") and len(x.args) == 1
    inner = x.args[0] if spanned else x
    if getattr(inner, "func", None) != sp.Function(letter) or len(inner.args) != 1:
        raise LatexMathError(f"{x} is not {letter}_{{..}} or its span")
    return spanned, inner.args[0]


@line_check("sec4_5-in-Vn")
def check_in_vn() -> LineResult:
    """``[r1,g1,b1], [r2,g2,b2] in cup_{i=1}^{n} E_i/~, i.e., cos(r1u+g1v+b1w), sin(r2u+g2v+b2w) in V_n``: the union
    and V's index read.  As printed (elements of V_n): cos and sin of every triple of the union are functions of V_n
    -- false, V_n holds one representative per class (cos(u+v) = cos(alpha - w) is not in V_1, sin 0 = 0 is in no
    V_n); corrected (in span V_n): exact ranks of V_n with cos, sin of each triple added, n <= 2."""
    import sympy as sp

    how = ("the union's bounds and V's index read from the transcription; printed: cos/sin of every triple of the "
           "union equal (exact expansion over (u, v, alpha), w = alpha - u - v) to a function of V_n (1 and cos/sin of "
           "one triple per class); corrected: they lie in span V_n (exact ranks at rational points), and the "
           "frequencies of T_{2n} lie in the union, n = 1..2")
    try:
        d = lm.sentence(r"where {classes}, i.e., \[ {functions:words}", verbatim("sec4_5-in-Vn"))
        if not d:
            raise LatexMathError("unread line")
        classes, functions = lm.parse_relation(d["classes"]), lm.parse_relation(d["functions"])
        cls, letters = sp.Function("cls"), [sp.Function(x) for x in "rgb"]
        u, v, w = sp.symbols("u v w")
        # two listed subjects: the reader gives the first as the part and the second with its membership as a clause
        if classes.ops or len(classes.parts) != 1 or len(classes.conditions) != 1 or \
                classes.conditions[0].ops != ["in"] or functions.ops or len(functions.parts) != 1 or \
                len(functions.conditions) != 1 or functions.conditions[0].ops != ["in"]:
            raise LatexMathError("unread line: not '[..], [..] in U, i.e., cos(..), sin(..) in V'")
        first, (second, union) = classes.parts[0], classes.conditions[0].parts
        cos_, (sin_, space) = functions.parts[0], functions.conditions[0].parts
        if [first, second] != [cls(sp.Tuple(*(x(k) for x in letters))) for k in (1, 2)] or \
                [cos_, sin_] != [f(letters[0](k) * u + letters[1](k) * v + letters[2](k) * w)
                                 for f, k in ((sp.cos, 1), (sp.sin, 2))]:
            raise LatexMathError("unread line: the classes or the functions are not [r_k, g_k, b_k], cos/sin of them")
        says_span, v_idx = _space_index(space, "V")
        ns = sp.Symbol("n")
        lo, hi = read_union(union)
        literal, spans = True, union_holds(union, v_idx)
        for n in (1, 2):
            a, b, vi = int(lo.subs(ns, n)), int(hi.subs(ns, n)), int(v_idx.subs(ns, n))
            triples = sorted({t for x in range(a, b + 1) for t in E(x)})

            def ep(f, t):  # f(r u + g v + b w) with w = alpha - u - v, over (u, v, alpha)
                return f((t[0] - t[2], t[1] - t[2], t[2]))

            members = [EP.const(3, 1)] + [ep(f, t) for t in own_v_args(vi) for f in (EP.cos, EP.sin)]
            literal &= all(any(ep(f, t) == m for m in members) for t in triples for f in (EP.cos, EP.sin))
            if vi > 3:
                raise ValueError(f"V_{vi} is not computed")
            base = span_rank((("V", vi),))
            spans &= all(span_rank((("V", vi), ("X", t))) == base for t in triples)
    except (LatexMathError, ValueError, TypeError, sp.SympifyError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    printed = spans if says_span else literal and spans
    return LineResult(printed, spans if not printed else None, how=how, kind="exhaustive",
                      detail={"printed_says_span": says_span, "elements_of_V_n": literal, "in_span_V_n": spans,
                              "example": "n = 1: cos(u+v) = cos(alpha - w) is none of 1, cos u, sin u, cos v, "
                                         "sin v, cos w, sin w"})


@line_check("sec4_5-inclusion")
def check_inclusion() -> LineResult:
    """The printed union of classes and the spaces (read): the classes of every frequency of T_{2n} (exact expansion,
    shifted by a phase) lie in the printed union, which lies in the classes of V_n; span T_{2n} in span V_n by exact
    ranks (n <= 3)."""
    import sympy as sp

    how = ("exact exponential expansion of every function of T_{2n}: each frequency is m(1,1,1)/2 + an integer triple "
           "whose class lies in the printed union of E_i/~ (bounds read), n = 1..3; the printed inclusion of spans "
           "(indices read) by exact ranks of T and V at rational points, n <= 3")
    try:
        ns = sp.Symbol("n")
        d = lm.sentence(r"Performing similar calculations as above, one concludes that all types of products from "
                        r"(\ref{{label:word}}) can be expanded into linear combinations of sine and "
                        r"cosine functions that belong to some equivalence classes {cls} {union}. Consequently, "
                        r"\[ {inclusion:words} \]", verbatim("sec4_5-inclusion"))
        if not d or d["label"] != "possible_products_inclusion":
            raise LatexMathError("unread line")
        # the membership is printed over two segments, $\left[ r,g,b\right] \in$ $\cup..$: read as one relation
        member, incl = lm.parse_relation(d["cls"] + " " + d["union"]), lm.parse_relation(d["inclusion"])
        if member.ops != ["in"] or member.conditions or \
                member.parts[0] != sp.Function("cls")(sp.Tuple(*sp.symbols("r g b"))) or \
                incl.ops != ["subset"] or incl.conditions:
            raise LatexMathError("unread line: not '[r,g,b] in U' and 'span T subset span V'")
        (t_span, t_idx), (v_span, v_idx) = _space_index(incl.parts[0], "T"), _space_index(incl.parts[1], "V")
        ok = {"inclusion": union_holds(member.parts[1], v_idx), "printed_spans": t_span and v_span}
        ok["spans"] = all(span_rank((("T", int(t_idx.subs(ns, n))), ("V", int(v_idx.subs(ns, n))))) == span_rank(
            (("V", int(v_idx.subs(ns, n))),)) for n in (1, 2, 3))
    except (LatexMathError, ValueError, TypeError, sp.SympifyError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)})
    return LineResult(all(ok.values()), how=how, kind="exhaustive", detail=ok)



__all__ = ["EP", "class_key", "phase_equivalent", "printed_relation", "relation_matches", "power_reduction_holds",
           "k_sets_agree", "prop_sets_agree", "b2_classes", "max_values", "frequency_classes"]

