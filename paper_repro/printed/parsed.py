r"""What the line checks do with the objects the one reader of the paper's mathematics returns.

Every text of the paper is read by :mod:`paper_repro.printed.latex_math` (``parse``, ``parse_relation``,
``index_set``, ``terms``, ``evaluate_sums``); nothing here reads LaTeX with a regular expression.  This module only
*interprets* the parsed sympy objects the way the checks of Sections 5--7 (and the proof of Theorem
joint_systems_linear_independence) need them:

* :func:`expression`, :func:`chain` -- a scalar expression / an (in)equality chain ``c<\mu\leq a``, refusing
  anything else (a relation where an expression is printed, a membership where a chain is);
* :func:`bound` -- the value of a printed bound (``2n-1-j`` at ``n=3, j=1``);
* :func:`listed_range` -- the clause ``i=j+1,j+2,\ldots,n-1`` of a parsed relation as ``(i, j + 1, n - 1)``
  (the step between the listed items must be one, ``\ldots`` must come before the last item);
* :func:`progression` -- the values of a listed range at given n, r (any constant step);
* :func:`interval` -- the clause ``x\in\left[0,\alpha\right]`` as ``(0, alpha)``;
* :func:`constants_as_factors` -- the paper's constants ``c``, ``r``, ``g``, ``b`` are numbers: a parenthesis the
  reader appended to one as an argument list is a factor (``c_{6,4}\left(2+..\right)``);
* :func:`expand_sums` -- every sum written out (bounds must be numbers, empty when they cross, as the paper means);
* :func:`untagged_names` -- the indexed names printed without the tag ``^{\alpha}`` of the notation;
* :func:`linear_terms`, :func:`point_label` -- a linear combination of control points;
* :func:`exact_value`, :func:`evaluate_in`, :func:`relation_holds` -- exact evaluation (python-flint numbers).

>>> expression(r"\frac{1+\sqrt{5}}{2}\mu") == (1 + sympy.sqrt(5)) / 2 * MU
True
>>> chain(r"c<\mu\leq a")
([c, mu, a], ['<', '<='])
>>> listed_range(latex_math.parse_relation(r"\gamma_{2n,2n-i,0}^{\prime}=0,~i=1,2,\ldots,2n."), "i")
(i, 1, 2*n)
>>> bound("2n-1-j", n=3, j=1)
4
"""

from __future__ import annotations

import functools
from fractions import Fraction
from typing import Any

import sympy
from sympy.core.function import AppliedUndef

from paper_repro.printed import latex_math
from paper_repro.printed.latex_math import LDOTS, LatexMathError, Relation

ALPHA, VARRHO, RHO, MU, VARPHI, PSI = sympy.symbols("alpha varrho rho mu varphi psi")
A, B, C, U, V, W = sympy.symbols("a b c u v w")

_TESTS = {"<": lambda x, y: x < y, ">": lambda x, y: x > y, "=": lambda x, y: x == y, "<=": lambda x, y: x <= y,
          ">=": lambda x, y: x >= y, "!=": lambda x, y: x != y}


# -- expressions and chains ------------------------------------------------------------------------------------
def expression(tex: str, allowed: tuple[str, ...] | None = None) -> sympy.Expr:
    """One scalar expression (:func:`latex_math.parse`); ``LatexMathError`` if anything is unread, the text is not
    a scalar expression (a blank line ``XXX`` is refused by the reader) or, with ``allowed``, names a symbol not in
    it."""
    if not tex.strip():
        raise LatexMathError("empty expression")
    out = latex_math.parse(tex)
    if not isinstance(out, sympy.Expr):
        raise LatexMathError(f"not a scalar expression: {tex[:40]!r}")
    return out if allowed is None else within(out, allowed, tex)


def within(expr: sympy.Expr, allowed: tuple[str, ...], tex: str | None = None) -> sympy.Expr:
    """``expr`` (parsed) if it names only symbols in ``allowed`` and no applied name; ``LatexMathError`` otherwise."""
    unknown = sorted({str(x) for x in expr.free_symbols} - set(allowed))
    if unknown or expr.atoms(AppliedUndef):
        raise LatexMathError(f"unknown names {unknown or sorted(map(str, expr.atoms(AppliedUndef)))} in "
                             f"{tex if tex is not None else expr!r}")
    return expr


def chain(tex: str) -> tuple[list[sympy.Expr], list[str]]:
    """A chain ``e0 op1 e1 op2 e2 ...`` with ops ``=``, ``!=``, ``<``, ``<=``, ``>``, ``>=`` and nothing after it
    (:func:`latex_math.parse_relation`): the parts and the ops."""
    rel = latex_math.parse_relation(tex)
    if not rel.ops or rel.conditions or rel.lead:
        raise LatexMathError(f"not a bare relation chain: {tex[:40]!r}")
    if any(op not in _TESTS for op in rel.ops):
        raise LatexMathError(f"relation {rel.ops} is not an (in)equality chain")
    return list(rel.parts), list(rel.ops)


def relation_holds(parts: list, ops: list[str]) -> bool:
    """Whether a chain of numbers satisfies every relation."""
    return all(bool(_TESTS[op](parts[k], parts[k + 1])) for k, op in enumerate(ops))


# -- bounds, listed ranges, intervals --------------------------------------------------------------------------
def _env(env: dict) -> dict:
    return {sympy.Symbol(k) if isinstance(k, str) else k: v for k, v in env.items()}


@functools.lru_cache(maxsize=4096)
def _parsed_bound(text: str):
    return latex_math.parse(text)


@functools.lru_cache(maxsize=4096)
def _compiled(expr, names: tuple[str, ...]):
    """``expr`` as a plain Python function of ``names`` (integer arithmetic), or None if it is not a polynomial
    with integer coefficients in them."""
    syms = [sympy.Symbol(x) for x in names]
    if not expr.free_symbols <= set(syms) or not expr.is_polynomial(*syms):
        return None
    poly = sympy.Poly(expr, *syms) if syms else None
    if poly is not None and not all(c.is_Integer for c in poly.coeffs()):
        return None
    return sympy.lambdify(syms, expr, modules=[])


def bound(expr: Any, **env: int) -> int:
    """The integer value of a printed bound (a text, read by :func:`latex_math.parse`, or a parsed expression) at
    ``env``; ``ValueError`` if it names a variable not in ``env`` or is not an integer there.

    >>> bound(latex_math.parse("2n-(r+1)"), n=4, r=1)
    6
    """
    e = _parsed_bound(expr) if isinstance(expr, str) else sympy.sympify(expr)
    names = tuple(sorted(env))
    f = _compiled(e, names)
    if f is not None:
        v = f(*[env[k] for k in names])
        if isinstance(v, int):
            return v
    v = e.subs(_env(env))
    if not getattr(v, "is_Integer", False):
        raise ValueError(f"bound {expr} is not an integer at {env}: {v}")
    return int(v)


def evaluate_at(expr: Any, **env):
    """The value of a printed expression (a text or a parsed expression) at ``env`` (ints, Fractions), computed in
    Python's arithmetic (``1-x`` at ``x = Fraction(1, 3)`` is ``Fraction(2, 3)``); ``ValueError`` if it names a
    variable not in ``env``.

    >>> from fractions import Fraction
    >>> evaluate_at("1-x", x=Fraction(1, 3))
    Fraction(2, 3)
    """
    e = _parsed_bound(expr) if isinstance(expr, str) else sympy.sympify(expr)
    names = tuple(sorted(env))
    syms = [sympy.Symbol(x) for x in names]
    if not e.free_symbols <= set(syms):
        raise ValueError(f"{expr} names {sorted(map(str, e.free_symbols - set(syms)))}, not in {names}")
    return _function(e, names)(*[env[k] for k in names])


@functools.lru_cache(maxsize=4096)
def _function(expr, names: tuple[str, ...]):
    return sympy.lambdify([sympy.Symbol(x) for x in names], expr, modules=[])


def clauses(src: Relation | str, errors: list | None = None) -> list[Relation]:
    """The relation and its clauses (a parsed :class:`Relation`), or the clauses of a text: each ``$..$`` segment of
    a prose line (or the whole text) read by :func:`latex_math.parse_conditions`; a segment the reader refuses
    gives no clause."""
    if isinstance(src, Relation):
        return [src, *src.conditions]
    out: list[Relation] = []
    for seg in latex_math.inline_math(src) or [src]:
        try:
            out += latex_math.parse_conditions(seg)
        except LatexMathError as exc:
            if errors is not None:
                errors.append(str(exc))
    return out


def _clause(src: Relation | str, var: str, op: str, kind: type) -> Relation:
    """The first clause ``var op X`` with ``X`` of type ``kind`` (``LatexMathError`` if there is none)."""
    sym, errors = sympy.Symbol(var), []
    for c in clauses(src, errors):
        if len(c.parts) == 2 and c.ops == [op] and c.parts[0] == sym and isinstance(c.parts[1], kind):
            return c
    raise LatexMathError(f"no clause '{var} {op} ..' ({kind.__name__}) read" + (f": {errors[0]}" if errors else ""))


def listed(src: Relation | str, var: str) -> list:
    """The items of the (first) listed range ``var=a,b,\\ldots,c`` of a parsed relation or a text (a clause of op
    ``in`` whose right part is a ``Tuple`` with ``ldots`` before its last item)."""
    items = list(_clause(src, var, "in", sympy.Tuple).parts[1])
    if items.count(LDOTS) != 1 or items.index(LDOTS) != len(items) - 2 or len(items) < 3:
        raise LatexMathError(f"no '\\ldots' before the last listed item of {var!r}: {items}")
    return items


def listed_range(src: Relation | str, var: str) -> tuple[sympy.Symbol, sympy.Expr, sympy.Expr]:
    """``(Symbol(var), first, last)`` of the listed range ``var=a,a+1,\\ldots,b`` of a parsed relation or a text:
    the step between consecutive listed items must be one."""
    items = listed(src, var)
    head = items[:-2]
    for a, b in zip(head, head[1:]):
        if sympy.simplify(b - a) != 1:
            raise LatexMathError(f"the listed range of {var!r} does not step by one: {items}")
    return sympy.Symbol(var), head[0], items[-1]


def progression(items: list, **env: int) -> list[int]:
    """The values of listed items ``a, b, \\ldots, c`` at ``env`` (the step is b - a; ``a, \\ldots, c`` has step 1);
    an empty list (c < a) or a non-positive step is refused."""
    items = [LDOTS if x == "\\ldots" else x for x in items]
    if len(items) not in (3, 4) or items[-2] != LDOTS:
        raise ValueError(f"not a list 'a, b, ..., c': {items!r}")
    first, last = bound(items[0], **env), bound(items[-1], **env)
    step = bound(items[1], **env) - first if len(items) == 4 else 1
    if step <= 0 or last < first:
        raise ValueError(f"unread list {items!r} (an empty list a, ..., c with c < a is refused)")
    return list(range(first, last + 1, step))


def index_set(tex: str) -> list[tuple]:
    """The bounds of the last bounded set of ``tex`` (:func:`latex_math.index_set`); in a prose line, of the last
    ``$..$`` segment that has one."""
    segs = latex_math.inline_math(tex) or [tex]
    for seg in reversed(segs):
        try:
            return latex_math.index_set(seg)
        except LatexMathError:
            if len(segs) == 1:
                raise
    raise LatexMathError(f"no index set _{{v=lo,..}}^{{hi,..}} in {tex[:60]!r}")


def interval(src: Relation | str, var: str) -> tuple[sympy.Expr, sympy.Expr]:
    """``(lo, hi)`` of the (first) clause ``var\\in\\left[lo,hi\\right]`` of a parsed relation or a text (a
    closed interval)."""
    right = _clause(src, var, "in", sympy.Interval).parts[1]
    if right.left_open or right.right_open:
        raise LatexMathError(f"{var} is not in a closed interval: {right}")
    return right.start, right.end


# -- the paper's constants, sums, tags ---------------------------------------------------------------------------
CONSTANTS = ("c", "r", "g", "b")  # univariate constants and normalizing coefficients: numbers, not functions


def constants_as_factors(e):
    """``c(6, 4, Tuple(x))`` -> ``c(6, 4) * x``: the reader appends a parenthesis after an indexed name as its
    argument list; after a constant of the notation (``c``, ``r``, ``g``, ``b``) it is a factor."""
    if e is None:
        return None

    def fix(f):
        if f.func.__name__ in CONSTANTS and f.args and isinstance(f.args[-1], sympy.Tuple) and len(f.args[-1]) == 1:
            return sympy.Function(f.func.__name__)(*f.args[:-1]) * f.args[-1][0]
        return f

    return e.replace(lambda x: isinstance(x, AppliedUndef), fix)


def relation(tex: str) -> Relation:
    """A chain of relations with the constants read as numbers (:func:`constants_as_factors`): a row ``& =b`` that
    continues a chain has the part None first (``parts [None, b]``, ``ops ['=']``); trailing clauses are refused
    (the checks read them with :func:`listed_range` and :func:`interval`)."""
    rel = latex_math.parse_relation(tex)
    if rel.conditions:
        raise LatexMathError(f"clauses {rel.conditions} after the relation")
    parts = [constants_as_factors(p) for p in rel.parts]
    if rel.lead is not None:
        return Relation([None, *parts], [rel.lead, *rel.ops])
    return Relation(parts, list(rel.ops))


def value(tex: str):
    """One expression with the constants read as numbers (a relation or a clause is refused)."""
    rel = latex_math.parse_relation(tex)
    if rel.ops or len(rel.parts) != 1 or rel.conditions or rel.lead:
        raise LatexMathError(f"a relation, not an expression: {tex[:60]!r}")
    return constants_as_factors(rel.parts[0])


def expand_sums(e):
    """Every ``Sum`` written out (:func:`latex_math.evaluate_sums`: empty when the bounds cross); ``LatexMathError``
    if a bound is not a number."""
    out = latex_math.evaluate_sums(e)
    if isinstance(out, sympy.Basic) and out.has(sympy.Sum):
        raise LatexMathError(f"a sum whose bounds are not numbers in {out}")
    return out


TAGGED = ("r", "g", "b", "c", "R", "G", "B", "L", "Rbar", "Gbar", "Bbar", "Tbar")  # named objects that carry alpha


def untagged_names(tex: str) -> list[str]:
    """The named objects of the notation (:data:`TAGGED`) printed in ``tex`` without the tag ``^{\\alpha}``, as
    ``c_{6,4}`` (:func:`latex_math.untagged`)."""
    return [f"{f.func.__name__}_{{{','.join(str(a) for a in f.args)}}}" for f in latex_math.untagged(tex)
            if f.func.__name__ in TAGGED]


def _objects(rel: Relation):
    """Every parsed object of a relation: its parts and, recursively, those of its clauses."""
    for p in rel.parts:
        if p is not None:
            yield p
    for c in rel.conditions:
        yield from _objects(c)


def foreign_tags(tex: str) -> list[str]:
    r"""The named objects of ``tex`` (a display line, or every ``$..$`` segment of a prose line) that carry a
    superscript other than the notation's tag ``^{\alpha}`` (the reader drops the tag; any other superscript makes
    ``X_sup(.., s)``, ``^{\prime}`` makes ``X_prime``); a superscript the reader refuses (``\Omega^{\beta}``)
    raises ``LatexMathError``.

    >>> foreign_tags(r"where $\left\{ r_{2n,2n-i,j}^{\alpha}\right\} _{j=0,i=j}^{n,n}$ and $\Omega^{\alpha}$")
    []
    >>> foreign_tags(r"r_{2n,n,n}^{\alpha}R_{2n,n,n}^{\beta}\left( u,v,w\right)")
    ['R_sup(2*n, n, n, beta, (u, v, w))']
    """
    segs = latex_math.inline_math(tex) if "$" in tex else [tex]
    out = []
    for seg in segs:
        for obj in _objects(latex_math.parse_relation(seg)):
            if isinstance(obj, sympy.Basic):
                out += [str(a) for a in obj.atoms(AppliedUndef) if a.func.__name__.endswith(("_sup", "_prime"))]
    return sorted(set(out))


# -- the linear combinations of the proof of Theorem joint_systems_linear_independence ----------------------------
COLOUR_OF = {"rho": "R", "gamma": "G", "beta": "B"}
FUNCTIONS = {"R": "R", "G": "G", "B": "B", "Rbar": "R", "Gbar": "G", "Bbar": "B"}
_N = sympy.Symbol("n")


def _constant_indices(c) -> tuple:
    if len(c.args) != 3 or c.args[0] != 2 * _N:
        raise ValueError(f"the constant {c} is not indexed _{{2n,a,b}}")
    return c.args[1], c.args[2]


def function_terms(tex: str) -> list[tuple[list, str, sympy.Expr, sympy.Expr]]:
    """The terms ``constant_{2n,a,b} X_{2n,a,b}(u,v,w)`` of a printed row (every part of its relation, read by
    :func:`latex_math.parse_relation`; :func:`latex_math.terms`), each with its sums:
    ``[(limits [(var, lo, hi), ...] outermost first, colour, a, b), ...]`` (sympy).  A term whose constant and
    function disagree (colour or indices), a coefficient other than 1, or a term with another name raises
    ``ValueError``; parts without a constant or function (``L(u,v,w)``, ``0``) are skipped."""
    rel = latex_math.parse_relation(tex)
    out = []
    for part in rel.parts:
        for t in latex_math.terms(part):
            consts = [f for f in t.names if f.func.__name__ in COLOUR_OF]
            funcs = [f for f in t.names if f.func.__name__ in FUNCTIONS]
            if not consts and not funcs and t.coefficient.is_number:
                continue
            if len(consts) != 1 or len(funcs) != 1 or len(t.names) != 2 or t.coefficient != 1:
                raise ValueError(f"not a term constant_{{2n,a,b}} X_{{2n,a,b}}: {t}")
            (c,), (f,) = consts, funcs
            fargs = f.args[:-1] if f.args and isinstance(f.args[-1], sympy.Tuple) else f.args
            colour = FUNCTIONS[f.func.__name__]
            if COLOUR_OF[c.func.__name__] != colour or tuple(fargs) != tuple(c.args):
                raise ValueError(f"constant {c} does not match {f}")
            a, b = _constant_indices(c)
            out.append(([tuple(lim) for lim in t.limits], colour, a, b))
    return out


def term_indices(terms, **env: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of every function of :func:`function_terms` (i from the first index 2n - i), the sums
    written out with ``env`` (``n``, ``r``) and the outer sum variables (an empty sum names nothing)."""
    out: list[tuple[str, int, int]] = []

    def walk(limits, colour, first, level, scope):
        if not limits:
            out.append((colour, 2 * scope["n"] - bound(first, **scope), bound(level, **scope)))
            return
        (v, lo, hi), rest = limits[0], limits[1:]
        for x in range(bound(lo, **scope), bound(hi, **scope) + 1):
            walk(rest, colour, first, level, {**scope, str(v): x})

    for limits, colour, first, level in terms:
        walk(limits, colour, first, level, dict(env))
    return out


def constant_sets(tex: str, n: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of the constants named by a printed list of ``$..$`` segments, each a constant
    ``\\rho_{2n,n,n}`` or a bounded set ``\\left\\{ \\rho_{2n,2n-i,j}\\right\\} _{j=0,i=j}^{n-1,2n-1-j}``
    (:func:`latex_math.parse`), at order n; any other segment raises ``ValueError``."""
    out = []
    for seg in latex_math.inline_math(tex) or [tex]:
        e = latex_math.parse(seg)
        if isinstance(e, AppliedUndef) and e.func.__name__ in COLOUR_OF:
            a, b = _constant_indices(e)
            out.append((COLOUR_OF[e.func.__name__], 2 * n - bound(a, n=n), bound(b, n=n)))
            continue
        if not (isinstance(e, AppliedUndef) and e.func == latex_math.Family and len(e.args) == 3
                and isinstance(e.args[0], AppliedUndef) and e.args[0].func.__name__ in COLOUR_OF and not e.args[1]):
            raise ValueError(f"not a constant or a bounded set of constants: {seg[:60]!r}")
        member, _conds, bounds = e.args
        a, b = _constant_indices(member)
        colour = COLOUR_OF[member.func.__name__]
        out += [(colour, 2 * n - bound(a, **env), bound(b, **env))
                for env in _walk_bounds(list(bounds), {"n": n})]
    return out


def _walk_bounds(bounds: list, scope: dict):
    if not bounds:
        yield scope
        return
    (v, lo, hi), rest = bounds[0], bounds[1:]
    for x in range(bound(lo, **scope), bound(hi, **scope) + 1):
        yield from _walk_bounds(rest, {**scope, str(v): x})


def members(item, **env: int) -> list:
    r"""The objects a listed item names at ``env``: a bounded set without condition
    (``\left\{ r_{2n,2n-i,j}^{\alpha}\right\} _{j=0,i=j}^{n-1,2n-1-j}``, parsed) gives its member at every binding
    of its bounds, the first bound outermost, each index evaluated; any other item is itself, evaluated at ``env``.
    A set with a condition is refused (``ValueError``).

    >>> members(latex_math.parse(r"\left\{ r_{2n,2n-i,j}\right\} _{j=0,i=j}^{1,2-j}"), n=1)
    [r(2, 2, 0), r(2, 1, 0), r(2, 0, 0), r(2, 1, 1)]
    """
    def at(e, scope):  # an applied name with integer indices: each index by bound() (compiled, fast)
        if isinstance(e, AppliedUndef) and all(isinstance(a, sympy.Expr) for a in e.args):
            try:
                return e.func(*[sympy.Integer(bound(a, **scope)) for a in e.args])
            except ValueError:
                pass
        return e.subs({sympy.Symbol(k): v for k, v in scope.items()})

    if isinstance(item, AppliedUndef) and item.func == latex_math.Family:
        member, conds, bounds = item.args
        if conds or not bounds:
            raise ValueError(f"not a bounded set without condition: {item}")
        return [at(member, scope) for scope in _walk_bounds(list(bounds), dict(env))]
    return [at(item, env)]


# -- linear combinations of control points -----------------------------------------------------------------------
def linear_terms(expr) -> dict:
    """``{atom: coefficient}`` of an expression linear in applied names (``r_vec(6, 5, 0)``); ``ValueError`` if it is
    not linear in them (a product of two points, a point in a denominator)."""
    e = sympy.expand(expr)
    atoms = sorted(e.atoms(AppliedUndef), key=str)
    coefs = {a: sympy.expand(e.diff(a)) for a in atoms}
    if any(c.atoms(AppliedUndef) for c in coefs.values()) or sympy.expand(e - sum(c * a for a, c in coefs.items())):
        raise ValueError(f"not a linear combination of points: {expr}")
    return coefs


def point_label(atom) -> str:
    """``r_{6,5,0}`` of the parsed ``r_vec(6, 5, 0)``."""
    name = atom.func.__name__
    if not name.endswith("_vec") or len(atom.args) != 3:
        raise ValueError(f"not a control point: {atom}")
    return f"{name[:-4]}_{{{','.join(str(int(a)) for a in atom.args)}}}"


def conversion(tex: str) -> tuple[tuple[int, int, int], list[tuple[Fraction, str]]]:
    """See :func:`_conversion` (memoized on the text: a changed line is another key)."""
    idx, terms = _conversion(tex)
    return idx, list(terms)


@functools.lru_cache(maxsize=512)
def _conversion(tex: str) -> tuple[tuple[int, int, int], tuple[tuple[Fraction, str], ...]]:
    """``((d, e, f), [(weight, control point), ...])`` of a printed Bezier point ``p_{d,e,f} = w_1 x_1 + ...`` in the
    printed order (:func:`latex_math.summands`): the relation must be one ``=``, the left side a point ``p``, each
    term a rational weight (signs as printed) times one control point; anything else raises ``ValueError``."""
    rel = latex_math.parse_relation(tex)
    if rel.ops != ["="] or len(rel.parts) != 2 or rel.conditions or rel.lead:
        raise ValueError(f"relation {rel.ops}, not one '='")
    lhs = rel.parts[0]
    if getattr(lhs.func, "__name__", "") != "p_vec" or len(lhs.args) != 3 or not all(a.is_Integer for a in lhs.args):
        raise ValueError(f"not a Bezier point: {lhs}")
    terms = []
    for t in latex_math.summands(tex)[1]:
        points = [a for a in sympy.Mul.make_args(t) if isinstance(a, AppliedUndef)]
        if len(points) != 1:
            raise ValueError(f"not a weight times one control point: {t}")
        w = sympy.simplify(t / points[0])
        if not isinstance(w, sympy.Rational):
            raise ValueError(f"weight {w} is not a rational number")
        label = point_label(points[0])
        if label[0] not in "rgb":
            raise ValueError(f"{label} is not a control point r, g or b")
        terms.append((Fraction(int(w.p), int(w.q)), label))
    return tuple(int(a) for a in lhs.args), tuple(terms)  # type: ignore[return-value]


def elevation(tex: str) -> list[tuple[str, dict]]:
    """See :func:`_elevation` (memoized on the text: a changed line is another key)."""
    return [(left, dict(row)) for left, row in _elevation(tex)]


@functools.lru_cache(maxsize=512)
def _elevation(tex: str) -> list[tuple[str, dict]]:
    """``[(order-2 point, {order-1 point: weight expression (sympy)}), ...]`` of a printed elevation equation
    (:func:`latex_math.parse_relation`, relation ``=``): a vector equation gives its three rows, the centre one."""
    rel = latex_math.parse_relation(tex)
    if rel.ops != ["="] or len(rel.parts) != 2:
        raise ValueError(f"relation {rel.ops}, expected ['=']")
    lhs, rhs = rel.parts
    rows = list(zip(lhs, rhs)) if isinstance(lhs, sympy.MatrixBase) else [(lhs, rhs)]
    return [(point_label(left), {point_label(a): c for a, c in linear_terms(right).items()}) for left, right in rows]


# -- exact evaluation --------------------------------------------------------------------------------------------
def _linear_angle(arg: sympy.Expr, bases: dict) -> list[tuple[int, sympy.Symbol]]:
    """``arg = sum k_s (s / den_s)`` with integers ``k_s`` over the base angles ``s / den_s`` of ``bases``."""
    arg = sympy.expand(arg)
    out = []
    if not arg.free_symbols <= set(bases):
        raise LatexMathError(f"trigonometric argument {arg} names an unknown angle")
    for s in arg.free_symbols:
        coeff = arg.coeff(s)
        k = sympy.nsimplify(coeff * bases[s][0])
        if not k.is_Integer:
            raise LatexMathError(f"trigonometric argument {arg}: {coeff} {s} is not a multiple of {s}/{bases[s][0]}")
        out.append((int(k), s))
    if sympy.expand(arg - sum(k * s / bases[s][0] for k, s in out)) != 0:
        raise LatexMathError(f"trigonometric argument {arg} has a constant term")
    return out


def exact_value(expr: sympy.Expr, values: dict, bases: dict, zero):
    """``expr`` at ``values`` (symbol -> exact number) with ``bases``: symbol -> ``(den, cos(s/den), sin(s/den))``;
    ``sin``/``cos``/``tan`` of an integer combination of the base angles from ``(cos + i sin)`` products.  ``zero``
    is the zero of the number type (``fmpq(0)``)."""

    def cs(terms: list[tuple[int, sympy.Symbol]]):
        c, s = zero + 1, zero
        for k, sym in terms:
            _, cb, sb = bases[sym]
            for _ in range(abs(k)):
                sb_k = sb if k > 0 else -sb
                c, s = c * cb - s * sb_k, s * cb + c * sb_k
        return c, s

    def ev(e: sympy.Expr):
        if e.is_Integer:
            return zero + int(e)
        if e.is_Rational:
            return (zero + int(e.p)) / int(e.q)
        if e in values:
            return zero + values[e]
        if e.is_Add:
            out = zero
            for a in e.args:
                out = out + ev(a)
            return out
        if e.is_Mul:
            out = zero + 1
            for a in e.args:
                out = out * ev(a)
            return out
        if e.is_Pow and e.exp.is_Integer:
            base = ev(e.base)
            return base ** int(e.exp) if int(e.exp) >= 0 else 1 / base ** (-int(e.exp))
        if isinstance(e, (sympy.sin, sympy.cos, sympy.tan)):
            c, s = cs(_linear_angle(e.args[0], bases))
            return s if isinstance(e, sympy.sin) else c if isinstance(e, sympy.cos) else s / c
        raise LatexMathError(f"cannot evaluate {e} exactly")

    return ev(expr)


def evaluate_in(expr, K, values: dict, squares: dict | None = None):
    """Value of a parsed expression in the arithmetic of ``K`` (a constructor of constants: ``fmpq``,
    ``RatFunc.const``, an mpoly constant): ``values`` maps sympy atoms (``r(2, 2, 0)``, ``sin(alpha/2)``, ...) to
    values; ``squares`` maps an atom whose even powers only occur (``cos(alpha/2)``) to the value of its square.
    Sums, products and integer powers only; anything else raises ``ValueError``."""
    squares = squares or {}

    def power(base, k: int):
        out = K(1)
        for _ in range(abs(k)):
            out = out * base if k >= 0 else out / base
        return out

    def ev(e):
        if e in values:
            return values[e]
        if isinstance(e, sympy.Integer):
            return K(int(e))
        if isinstance(e, sympy.Rational):
            return K(int(e.p)) / K(int(e.q))
        if isinstance(e, (sympy.Add, sympy.Mul)):
            out = ev(e.args[0])
            for a in e.args[1:]:
                out = out + ev(a) if isinstance(e, sympy.Add) else out * ev(a)
            return out
        if isinstance(e, sympy.Pow) and isinstance(e.exp, sympy.Integer):
            k = int(e.exp)
            if e.base in squares and k % 2 == 0:
                return power(squares[e.base], k // 2)
            return power(ev(e.base), k)
        raise ValueError(f"cannot evaluate {e!r}")

    return ev(expr)


__all__ = ["ALPHA", "VARRHO", "RHO", "MU", "VARPHI", "PSI", "A", "B", "C", "U", "V", "W", "expression", "chain",
           "relation_holds", "bound", "index_set", "clauses", "listed", "listed_range", "progression", "interval",
           "CONSTANTS", "constants_as_factors", "relation", "value", "expand_sums", "TAGGED", "untagged_names",
           "linear_terms", "point_label", "exact_value", "evaluate_in", "COLOUR_OF", "FUNCTIONS", "function_terms",
           "term_indices", "constant_sets", "evaluate_at", "conversion", "elevation", "members", "within"]
