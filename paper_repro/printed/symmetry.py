"""Section sec:RGB as printed, read from the transcriptions (issue 37: no hand copy): the explicit R, G and B
formulas (eqs. R_system_leq_n, R_system_geq_n and the G, B displays after them) as exponent vectors, the printed
second-half relations ``X_{2n,2n-i,j}(u,v,w) = X_{2n,i,j}(sigma)`` and the six symmetry properties of
Fig. oriented_graph(b) (its caption).

Everything is parsed at call time from :func:`paper_repro.printed.lines.verbatim` (so the blank and mutation tests
of the lines reach it) with :mod:`paper_repro.printed.latex_math`;
exponent vectors are in the order of :data:`paper_repro.core.labels.SLOTS` (sin u/2, cos u/2, sin v/2, ...).

>>> printed_g(2, 1, 0)  # G_{4,3,0} = sin^3(w/2) sin(v/2) cos(u/2)
(0, 1, 1, 0, 3, 0)
>>> printed_half()["B"]
(1, 0, 2)
>>> [p[0] for p in six_properties()]
['(w,u)', '(v,w)', '(u,v)', '(v,u)', '(u,w)', '(w,v)']
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import sympy

from paper_repro.printed import latex_math as lm
from paper_repro.printed.latex_math import LatexMathError, prose, sentence
from paper_repro.printed.lines import verbatim

VARS = ("u", "v", "w")


@cache
def parse(tex: str) -> sympy.Expr:
    """One expression, by :func:`paper_repro.printed.latex_math.parse` (cached by the text read)."""
    return lm.parse(tex)


def bound(expr: str | sympy.Expr, **env: int) -> int:
    """Integer value of a printed bound such as ``2n-1-j`` (LaTeX read by :func:`parse`, or already read) with
    ``env`` bound; :class:`LatexMathError` if a name stays unbound or the value is not an integer.

    >>> bound("2n-1-j", n=3, j=1), bound(parse("2n-1-j"), n=3, j=1)
    (4, 4)
    """
    e = parse(expr) if isinstance(expr, str) else sympy.sympify(expr)
    v = e.subs({sympy.Symbol(k): x for k, x in env.items()})
    if not v.is_Integer:
        raise LatexMathError(f"the bound {expr!r} is not an integer at {env}: {v}")
    return int(v)


def half_angle_powers(expr: sympy.Expr, variables=VARS) -> dict[tuple[str, str], sympy.Expr]:
    """The exponents of a parsed product of powers of ``sin(x/2)``, ``cos(x/2)`` (x among ``variables``):
    ``{("sin", "u"): 2n-i, ...}``; :class:`LatexMathError` if ``expr`` is anything else (a sum, another factor,
    another argument).  A factor that occurs twice has its exponents added.

    >>> half_angle_powers(parse(r"\\sin^{i}\\frac{w}{2}\\cos^{j}\\frac{v}{2}\\sin\\frac{w}{2}"))
    {('cos', 'v'): j, ('sin', 'w'): i + 1}
    """
    out: dict[tuple[str, str], sympy.Expr] = {}
    for base, exp in (f.as_base_exp() for f in sympy.Mul.make_args(expr)):
        if isinstance(base, (sympy.sin, sympy.cos)):
            arg = base.args[0]
            x = [v for v in variables if sympy.simplify(arg - sympy.Symbol(v) / 2) == 0]
            if len(x) != 1:
                raise LatexMathError(f"{base} is not a function of one half angle of {variables}")
            key = ("sin" if isinstance(base, sympy.sin) else "cos", x[0])
            out[key] = out.get(key, 0) + exp
        elif base != 1:
            raise LatexMathError(f"factor {base} is not a power of a half-angle sine or cosine")
    return dict(sorted(out.items()))
#: The lines of the explicit formulas: (colour, half) -> line id; "low" is i = j..n, "high" i = n+1..2n-j.
EXPLICIT_LINES = {("R", "low"): "sec1_3-R-leq-n", ("R", "high"): "sec1_3-R-geq-n-explicit",
                  ("G", "low"): "sec1_3-G-leq-explicit", ("G", "high"): "sec1_3-G-geq-explicit",
                  ("B", "low"): "sec1_3-B-leq-explicit", ("B", "high"): "sec1_3-B-geq-explicit"}
#: The lines of the printed second-half relations.
RELATION_LINES = {"R": "sec1_3-R-geq-n-relation", "G": "sec1_3-G-geq-relation", "B": "sec1_3-B-geq-relation"}
CAPTION_LINE = "sec1_3-fig-oriented-graph-caption"
COUNT_LINE = "sec1_3-six-symmetries"

IndexSet = tuple[tuple[str, sympy.Expr, sympy.Expr], tuple[str, sympy.Expr, sympy.Expr]]


def set_builders(tex: str) -> tuple[lm.Relation, list[tuple[sympy.Expr, IndexSet]]]:
    """The display ``tex`` read by :func:`latex_math.parse_relation` (``[lead] part = part ...``), and its parts, each
    a set-builder ``\\left\\{ member \\right\\} _{j=a,i=b}^{c,d}`` (a bounded ``Family`` of the reader): (member,
    ((j, a, c), (i, b, d))); ``LatexMathError`` if a part is anything else or its index set is not a double one.
    """
    rel = lm.parse_relation(tex)
    out = []
    for part in rel.parts:
        if getattr(part, "func", None) is not lm.Family or part.args[1] or len(part.args[2]) != 2:
            raise LatexMathError(f"not a set-builder over a double index set: {part}")
        (ov, olo, ohi), (iv, ilo, ihi) = part.args[2]
        out.append((part.args[0], ((str(ov), olo, ohi), (str(iv), ilo, ihi))))
    return rel, out


def pairs(iset: IndexSet, n: int) -> list[tuple[int, int]]:
    """The (i, j) of a printed index set at order n (outer j, inner i), each once, in printed order."""
    (ov, olo, ohi), (iv, ilo, ihi) = iset
    if (ov, iv) != ("j", "i"):
        raise LatexMathError(f"index set over {(ov, iv)}, not (j, i)")
    return [(i, j) for j in range(bound(olo, n=n), bound(ohi, n=n) + 1)
            for i in range(bound(ilo, n=n, j=j), bound(ihi, n=n, j=j) + 1)]


@cache
def monomial(body: str | sympy.Expr) -> Callable[[int, int, int], tuple[int, ...]]:
    """The exponent vector (n, i, j) -> (sin u, cos u, sin v, ...) of a printed monomial (LaTeX or read)."""
    powers = half_angle_powers(parse(body) if isinstance(body, str) else body, VARS)
    n, i, j = sympy.symbols("n i j")
    extra = set().union(*(sympy.sympify(e).free_symbols for e in powers.values())) - {n, i, j}
    if extra:
        raise LatexMathError(f"exponents name {sorted(map(str, extra))}")
    slots = [sympy.sympify(powers.get((f, x), 0)) for x in VARS for f in ("sin", "cos")]
    fn = sympy.lambdify((n, i, j), slots, "math")
    return lambda nn, ii, jj: tuple(int(q) for q in fn(nn, ii, jj))


def explicit(color: str, half: str) -> tuple[Callable[[int, int, int], tuple[int, ...]], IndexSet]:
    """The printed explicit formula of ``color`` for ``half`` ("low"/"high") as (exponents(n, i, j), index set);
    the display must be ``... = \\left\\{ monomial \\right\\} _{..}^{..}`` (its last set-builder after an ``=``)."""
    rel, found = set_builders(verbatim(EXPLICIT_LINES[color, half]))
    if not found:
        raise LatexMathError(f"no set-builder in {EXPLICIT_LINES[color, half]}")
    body, iset = found[-1]
    if (rel.ops or [rel.lead])[-1] != "=" or len(found) > 2:
        raise LatexMathError(f"{EXPLICIT_LINES[color, half]}: the explicit set does not follow an '='")
    if len(found) == 2:  # the display names its left side: it must be color_{2n,2n-i,j}(u,v,w) on the same set
        lhs, lset = found[0]
        if lset != iset or label_of(lhs) != (color, "2*n - i", "j", (0, 1, 2)):
            raise LatexMathError(f"{EXPLICIT_LINES[color, half]}: left side {lhs} on {lset} is not "
                                 f"{color}_{{2n,2n-i,j}}(u,v,w) on {iset}")
    return monomial(body), iset


def label(tex: str) -> tuple[str, str, str, tuple[int, ...]]:
    """(colour, first index, level, argument permutation) of ``X_{2n,a,b}^{\\alpha}\\left( x,y,z\\right)``."""
    return label_of(parse(tex))


def label_of(e: sympy.Expr) -> tuple[str, str, str, tuple[int, ...]]:
    """:func:`label` of a parsed label."""
    if not isinstance(e, sympy.core.function.AppliedUndef) or len(e.args) != 4:
        raise LatexMathError(f"not a label with arguments: {e}")
    order, first, level, args = e.args
    n = sympy.Symbol("n")
    if sympy.simplify(order - 2 * n) != 0:
        raise LatexMathError(f"order {order} is not 2n")
    names = [str(a) for a in args]
    if sorted(names) != list(VARS):
        raise LatexMathError(f"arguments {names} are not a permutation of (u, v, w)")
    return e.func.__name__, _canon(first), _canon(level), tuple(VARS.index(x) for x in names)


def _canon(e: sympy.Expr) -> str:
    """A printed index in one spelling: ``2n-i`` and ``-i+2n`` both read ``2*n - i``."""
    return {"-i + 2*n": "2*n - i"}.get(str(sympy.expand(e)), str(sympy.expand(e)))


def printed_exponents(color: str, n: int, i: int, j: int) -> tuple[int, ...] | None:
    """Exponent vector of ``color_{2n,2n-i,j}`` from the printed explicit formula whose printed index set holds
    (i, j), or ``None`` if none does (or two do, or a power is negative)."""
    texts = tuple(verbatim(EXPLICIT_LINES[color, half]) for half in ("low", "high"))
    return _table(color, n, texts).get((i, j))


@cache
def _table(color: str, n: int, texts: tuple[str, ...]) -> dict[tuple[int, int], tuple[int, ...] | None]:
    """(i, j) -> exponents of the printed formulas at order n (keyed by the transcriptions read)."""
    out: dict[tuple[int, int], tuple[int, ...] | None] = {}
    seen: dict[tuple[int, int], int] = {}
    for half in ("low", "high"):
        formula, iset = explicit(color, half)
        for i, j in pairs(iset, n):
            seen[i, j] = seen.get((i, j), 0) + 1
            e = formula(n, i, j)
            out[i, j] = None if min(e) < 0 or seen[i, j] > 1 else e
    return out


def printed_g(n: int, i: int, j: int) -> tuple[int, ...] | None:
    """Printed G_{2n,2n-i,j} (read from the G displays)."""
    return printed_exponents("G", n, i, j)


def printed_b(n: int, i: int, j: int) -> tuple[int, ...] | None:
    """Printed B_{2n,2n-i,j} (read from the B displays)."""
    return printed_exponents("B", n, i, j)


def half_relation(color: str) -> tuple[tuple[str, str, str, tuple[int, ...]], tuple[str, str, str, tuple[int, ...]],
                                       IndexSet]:
    """The printed relation ``{X_{2n,a,b}(x,y,z)}_{set} = {X_{2n,c,d}(p,q,r)}_{set}``: the two labels as
    (colour, first index, level, argument permutation) and the index set (both sides must print the same)."""
    lid = RELATION_LINES[color]
    rel, found = set_builders(verbatim(lid))
    if len(found) != 2:
        raise LatexMathError(f"{lid}: {len(found)} set-builders, not 2")
    (lb, lset), (rb, rset) = found
    if rel.ops != ["="] or rel.lead is not None or lset != rset:
        raise LatexMathError(f"{lid}: not an equality of two sets on one index set")
    return label_of(lb), label_of(rb), lset


def printed_half() -> dict[str, tuple[int, int, int]]:
    """The substitution of each printed relation (e.g. R: (w, v, u) -> (2, 1, 0)), for the relations of the form
    X_{2n,2n-i,j}(u,v,w) = X_{2n,i,j}(sigma) (``LatexMathError`` for any other form)."""
    out = {}
    for color in "RGB":
        left, right, _ = half_relation(color)
        if left != (color, "2*n - i", "j", (0, 1, 2)) or right[:3] != (color, "i", "j"):
            raise LatexMathError(f"{RELATION_LINES[color]}: not {color}_{{2n,2n-i,j}}(u,v,w) = {color}_{{2n,i,j}}(..)")
        out[color] = right[3]
    return out


_COLOURS = {"red": "R", "green": "G", "blue": "B"}


def _listed(text: str) -> list[str]:
    """The items of a prose list ``a, b and c`` (or ``a and b``); ``LatexMathError`` for anything else.

    >>> _listed("red, green and blue"), _listed("$$ and $$")
    (['red', 'green', 'blue'], ['$$', '$$'])
    """
    head, sep, last = text.rpartition(" and ")
    items = [*head.split(", "), last] if sep else []
    if len(items) < 2 or not all(items):
        raise LatexMathError(f"unread list {text!r}")
    return items


#: the two sentences of the caption of Fig. oriented_graph(b), word by word (:func:`latex_math.sentence`)
CAPTION_TEMPLATE = ("Functions associated with the {shaded:words} shaded domains are symmetric in variables "
                    "{shaded_pairs:words}, respectively. Functions which correspond to the adjacent domains "
                    "{adjacent:words} are symmetric in variables {adjacent_pairs:words}, respectively.")


def six_properties() -> list[tuple[str, tuple[int, int, int], str, str]]:
    """The symmetry properties of the caption of Fig. oriented_graph(b): (name, substitution, family, image family).
    "Functions associated with the red, green and blue shaded domains are symmetric in (w,u), (v,w), (u,v),
    respectively" maps each family onto itself; "adjacent domains red--green, ..." maps the first onto the second.
    The words are read by :func:`latex_math.sentence`, each pair ``\\left(u,v\\right)`` by :func:`parse`.
    """
    got = sentence(CAPTION_TEMPLATE, verbatim(CAPTION_LINE))
    if got is None:
        raise LatexMathError(f"unread caption {verbatim(CAPTION_LINE)[:60]!r}")
    out = []
    for kind in ("shaded", "adjacent"):
        names = _listed(got[kind])
        marks, segs = prose(got[kind + "_pairs"])
        if _listed(marks) != ["$$"] * len(segs):
            raise LatexMathError(f"not a list of pairs of variables: {got[kind + '_pairs']!r}")
        swaps = [parse(t) for t in segs]
        if len(names) != len(swaps):
            raise LatexMathError(f"{len(names)} domains but {len(swaps)} pairs of variables ({kind})")
        for name, pair in zip(names, swaps):
            if not isinstance(pair, sympy.Tuple) or len(pair) != 2 or any(str(x) not in VARS for x in pair):
                raise LatexMathError(f"{pair} is not a pair of the variables {VARS}")
            a, b = map(str, pair)
            if a == b:
                raise LatexMathError(f"({a},{b}) is not a swap")
            sub = [0, 1, 2]
            sub[VARS.index(a)], sub[VARS.index(b)] = VARS.index(b), VARS.index(a)
            colours = name.split("--")
            if any(c not in _COLOURS for c in colours) or (kind == "shaded") != (len(colours) == 1):
                raise LatexMathError(f"{kind} domains with {name}")
            fam = [_COLOURS[c] for c in colours]
            out.append((f"({a},{b})", tuple(sub), fam[0], fam[-1]))
    return out


def six_count() -> int:
    """The number of symmetry properties the text announces ("six cyclic symmetry properties")."""
    got = sentence("that fulfill {count:count} cyclic symmetry properties in their variables", verbatim(COUNT_LINE))
    if got is None or got["count"] is None:
        raise LatexMathError(f"no count of symmetry properties in {verbatim(COUNT_LINE)!r}")
    return got["count"]


__all__ = ["EXPLICIT_LINES", "RELATION_LINES", "parse", "bound", "half_angle_powers", "set_builders",
           "pairs", "label", "label_of", "monomial", "explicit", "printed_exponents", "printed_g",
           "printed_b", "half_relation", "printed_half", "six_properties", "six_count"]
