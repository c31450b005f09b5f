"""Checks of the lines of Section sec:partition_of_unity (source lines 1907-2167), moved out of
:mod:`paper_repro.claims.lines.sec4_5` (which registers this module by importing it).

Independent machinery: exact normalizing coefficients by collocation without symmetry
(:func:`paper_repro.core.normalization.solve_full_exact`) or with it (:func:`paper_repro.core.normalization.
coefficients`), univariate constants from the expansion of ``(X^2 + 2 c X Y + Y^2)^n``
(:func:`paper_repro.core.univariate.c_numerator_by_expansion`), the closed forms proven for every alpha
(:mod:`paper_repro.theory.closed_forms`), exact trigonometric polynomials
(:class:`~paper_repro.claims.lines.sec4_5.EP`).
"""

from __future__ import annotations

from functools import cache
from itertools import product
from math import comb

import sympy
from flint import fmpq, fmpq_mat
from sympy.core.function import AppliedUndef

from paper_repro.claims.lines import CHECKS, LineResult, line_check
from paper_repro.claims.lines.sec4_5 import EP, TS, Q, _texts, half_monomial
from paper_repro.core.basis import evaluate
from paper_repro.core.context import ExactContext
from paper_repro.core.domain import rational_alpha, sample_rational_points
from paper_repro.core.labels import BasisLabel, exponents, index_of, united_system
from paper_repro.core.normalization import coefficients, solve_full_exact
from paper_repro.core.univariate import c_numerator_by_expansion
from paper_repro.printed import latex_math as LM
from paper_repro.printed import parsed as P
from paper_repro.printed.latex_math import LatexMathError, Relation
from paper_repro.printed.lines import line, lines_of, verbatim
from paper_repro.printed.lines import sec4_5 as pl


# ---------------------------------------------------------------------------------------------------------------
# Section partition_of_unity
# ---------------------------------------------------------------------------------------------------------------
def read_weight_labels(tex: str, n: int) -> list[str]:
    """The normalizing weights named by the printed list ``r_{2n,n,n}^{\\alpha},\\left\\{ r_{2n,2n-i,j}^{\\alpha}
    \\right\\} _{j=0,i=j}^{n-1,2n-1-j},..`` at order n: the list read by
    :func:`~paper_repro.printed.latex_math.parse_list`, each bounded set enumerated
    (:func:`~paper_repro.printed.parsed.members`); an item that is no weight ``r``, ``g``, ``b`` raises."""
    out = []
    for item in LM.parse_list(tex):
        for w in P.members(item, n=n):
            if not (isinstance(w, AppliedUndef) and w.func.__name__ in ("r", "g", "b") and len(w.args) == 3):
                raise LatexMathError(f"{w} is no normalizing weight r, g, b")
            out.append(f"{w.func.__name__}_{{{','.join(str(P.bound(a)) for a in w.args)}}}")
    return out


@line_check("sec4_5-weights-index")
def check_weights_index(verbatim: str | None = None) -> LineResult:
    """The weights listed by the line (:func:`read_weight_labels`) name each coefficient of T_{2n} once, n <= 12."""
    tex = verbatim if verbatim is not None else _texts({"sec4_5-weights"})["sec4_5-weights"]
    ok = True
    try:
        listed = {n: read_weight_labels(tex, n) for n in range(1, 13)}
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how="the printed index sets read from the transcription, n <= 12", kind="exhaustive",
                          detail={"unread": str(exc)[:200]})
    for n, printed in listed.items():
        ok &= len(printed) == len(set(printed)) == 3 * n * (n + 1) + 1
        ok &= set(printed) == {lab.coefficient for lab in united_system(n)}
    return LineResult(ok, how="the printed index sets (read from the transcription) against the labels of T_{2n} "
                      "(united_system), n <= 12; count 3n(n+1)+1", kind="exhaustive", detail={"n_max": 12})


@cache
def _full(n: int, t: fmpq) -> dict[str, fmpq]:
    sol = solve_full_exact(n, rational_alpha(t))
    return {lab.coefficient: x for lab, x in zip(united_system(n), sol)}


def _coef(n: int, t: fmpq, name: str) -> fmpq:
    return _full(n, t)[united_system(n)[index_of(n)[name]].coefficient]


def _in_omega(rel) -> tuple[str, str, str]:
    """The variables of a parsed membership ``\\left( u,v,w\\right) \\in\\Omega^{\\alpha}`` (the reader drops the
    tag alpha; another superscript is unread); ``LatexMathError`` on anything else."""
    parts = rel.parts if hasattr(rel, "parts") else list(rel.args)
    ops = rel.ops if hasattr(rel, "parts") else ["in"]
    if ops != ["in"] or len(parts) != 2 or parts[1] != sympy.Symbol("Omega") or not (
            isinstance(parts[0], sympy.Tuple) and len(parts[0]) == 3 and
            all(isinstance(x, sympy.Symbol) for x in parts[0])):
        raise LatexMathError(f"not '(u,v,w) in Omega^alpha': {parts} {ops}")
    return tuple(str(x) for x in parts[0])


def read_domain(tex: str) -> tuple[str, tuple[str, str, str]]:
    """``for all $\\left( u,v,w\\right) \\in\\Omega^{\\alpha}$``: the quantifier words (prose) and the variables
    (the one ``$..$`` segment, read by :func:`~paper_repro.printed.latex_math.parse_relation`)."""
    words, segs = LM.prose(tex)
    if len(segs) != 1 or "$$" not in words:
        raise LatexMathError("no '(u,v,w) \\in \\Omega^{\\alpha}' read")
    rel = LM.parse_relation(segs[0])
    if rel.conditions or rel.lead:
        raise LatexMathError("no '(u,v,w) \\in \\Omega^{\\alpha}' read")
    return " ".join(words.split("$$")[0].split()[-2:]), _in_omega(rel)


def partition_terms(expr: sympy.Expr, n: int, args: sympy.Tuple) -> list[str]:
    """The terms of the printed sum L at order n (sums written out): each must be +1 times a coefficient and the
    function of the same colour and indices applied to ``args``; returns the labels (``R_{2,1,0}`` ...)."""
    e = P.expand_sums(expr.subs(sympy.Symbol("n"), n))
    out = []
    for term in sympy.Add.make_args(sympy.expand(e)):
        coef, factors = term.as_coeff_mul()
        if coef != 1 or len(factors) != 2:
            raise LatexMathError(f"term {term} is not +1 * coefficient * function")
        by_kind = {f.func.__name__: f for f in factors if isinstance(f, sympy.core.function.AppliedUndef)}
        low = [k for k in by_kind if k in ("r", "g", "b")]
        if len(low) != 1 or low[0].upper() not in by_kind:
            raise LatexMathError(f"term {term} does not pair a coefficient with its function")
        c, f = by_kind[low[0]], by_kind[low[0].upper()]
        if tuple(f.args[:-1]) != tuple(c.args) or f.args[-1] != args:
            raise LatexMathError(f"term {term}: indices or arguments differ")
        out.append(f"{low[0].upper()}_{{{','.join(str(x) for x in _ints(c.args))}}}")
    return out


@line_check("sec4_5-partition-sum")
def check_partition_sum(text: str | None = None) -> LineResult:
    """The partition of unity parsed from its four lines: the constant and the point of ``1 & =L(u,v,w)``, the
    printed sum L (signs, bounds, coefficients and functions, written out), the domain ``for all (u,v,w) in
    Omega^alpha`` and, in the sentence before, the constant function and the word 'unique'.  With the coefficients
    of the exact collocation solve without symmetry (a square nonsingular system: unique), the printed sum
    evaluated at 6 fresh rational points of Omega^alpha equals the printed constant (n = 1..3, two alpha)."""
    how = ("the four lines parsed (latex_math); coefficients by exact collocation without symmetry (delta_n "
           "unknowns, nonsingular: unique), the printed sum at 6 fresh rational points of Omega^alpha, n = 1..3")
    try:
        one = P.relation(verbatim("sec4_5-L-one"))
        lsum = P.relation(text if text is not None else verbatim("sec4_5-L-sum"))
        quant, dom_vars = read_domain(verbatim("sec4_5-L-domain"))
        prose = verbatim("sec4_5-unique-coefs")
        if one.ops != ["="] or not one.parts[0].is_number or len(one.parts) != 2:
            raise LatexMathError("'K & =L(u,v,w)' not read")
        const = one.parts[0]
        lcall = one.parts[1]
        if not (isinstance(lcall, sympy.core.function.AppliedUndef) and lcall.func.__name__ == "L"):
            raise LatexMathError(f"{lcall} is not L(u,v,w)")
        args = lcall.args[-1]
        if lsum.ops != ["="] or lsum.parts[0] is not None or len(lsum.parts) != 2:
            raise LatexMathError("the row '& =sum' not read")
        if quant != "for all" or tuple(str(x) for x in args) != dom_vars:
            raise LatexMathError(f"domain read as {quant!r} {dom_vars}")
        said = LM.sentence("Since the function system ... that also contains the constant function {one}, it follows "
                           "that there exist {unique:word} coefficients%", prose)
        if said is None or said["unique"] != "unique" or not (number := LM.parse(said["one"])).is_Integer \
                or number != const:
            raise LatexMathError("the constant function or 'unique' of the sentence not read")
        for labels_text in ([verbatim(x) for x in ("sec4_5-L-sum", "sec4_5-L-domain")] if text is None else [text]):
            if P.foreign_tags(labels_text):
                raise LatexMathError(f"superscripts {P.foreign_tags(labels_text)}, the notation labels each with alpha")
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exact-evidence", detail={"unread": str(exc)[:200]})
    ok, rows = True, {}
    for n in (1, 2, 3):
        try:
            named = partition_terms(lsum.parts[1], n, args)
        except LatexMathError as exc:
            return LineResult(False, how=how, kind="exact-evidence", detail={"unread": str(exc)[:200]})
        idx = index_of(n)
        if sorted(named) != sorted(lab.paper for lab in united_system(n)) or len(set(named)) != len(named):
            rows[f"n={n}"] = False
            ok = False
            continue
        for t in TS[:2]:
            alpha = rational_alpha(t)
            pts = sample_rational_points(alpha, 6, seed=23)
            vals = evaluate(n, alpha, pts, ExactContext())
            sums = [sum((_coef(n, t, lab.lower()) * vals[p, idx[lab]] for lab in named), fmpq(0))
                    for p in range(len(pts))]
            rows[f"n={n},t={t}"] = all(s == fmpq(int(const)) for s in sums)
            ok &= rows[f"n={n},t={t}"]
    return LineResult(ok, how=how, kind="exact-evidence", detail=rows)


# -- symmetry conditions symmetry_condition_1..3, parsed -------------------------------------------------------------
SYMMETRY_LINES = ("sec4_5-symmetry-1", "sec4_5-symmetry-2", "sec4_5-symmetry-3")


def corrected_symmetry_text(tex: str) -> str:
    """The correction of erratum sec4_5-symmetry-3: the doubled comma of ``i=j,j+1,,\\ldots`` removed."""
    return tex.replace(",,", ",")


def read_symmetry(tex: str) -> tuple[sympy.Expr, sympy.Expr, tuple, tuple]:
    """One symmetry condition ``X_{..} & =Y_{..},~j=..,~i=..`` parsed: the two coefficients and the listed ranges of
    j and i (sympy, i's bounds may contain j)."""
    k = tex.find(",~")
    if k < 0:
        raise LatexMathError("no ',~' between the equation and its ranges")
    rel = P.relation(tex[:k])
    if rel.ops != ["="] or len(rel.parts) != 2:
        raise LatexMathError(f"not one equation: {rel.ops}")
    _j, jlo, jhi = P.listed_range(tex[k:], "j")
    _i, ilo, ihi = P.listed_range(tex[k:], "i")
    return rel.parts[0], rel.parts[1], (jlo, jhi), (ilo, ihi)


def _name(e: sympy.Expr) -> str:
    if not isinstance(e, sympy.core.function.AppliedUndef) or e.func.__name__ not in ("r", "g", "b"):
        raise LatexMathError(f"{e} is not a normalizing coefficient")
    return f"{e.func.__name__}_{{{','.join(str(x) for x in _ints(e.args))}}}"


def symmetry_pairs(tex: str, n: int) -> list[tuple[str, str]]:
    """The pairs of coefficient names a printed symmetry condition equates at order n (names checked to be
    coefficients of T_{2n})."""
    lhs, rhs, (jlo, jhi), (ilo, ihi) = read_symmetry(tex)
    n_, i_, j_ = sympy.symbols("n i j")
    members = {lab.coefficient for lab in united_system(n)}
    out = []
    for j in range(int(jlo.subs(n_, n)), int(jhi.subs(n_, n)) + 1):
        for i in range(int(ilo.subs({n_: n, j_: j})), int(ihi.subs({n_: n, j_: j})) + 1):
            a, b = (_name(e.subs({n_: n, i_: i, j_: j})) for e in (lhs, rhs))
            if a not in members or b not in members:
                raise LatexMathError(f"{a} = {b}: not coefficients of T_{2 * n}")
            out.append((a, b))
    return out


def _symmetry_texts(which: str | None = None, corrected: bool = False) -> dict[str, str]:
    """The three conditions as read; the erratum line symmetry-3 corrected unless it is the line checked."""
    out = {}
    for lid in SYMMETRY_LINES:
        tex = verbatim(lid)
        if lid != which or corrected:
            tex = corrected_symmetry_text(tex) if line(lid).status == "erratum" else tex
        out[lid] = tex
    return out


def symmetry_partition(n: int, texts: dict[str, str] | None = None) -> list[list[int]]:
    """Classes of the delta_n functions of T_{2n} (internal indices) merged by the printed symmetry conditions
    symmetry_condition_1..3 (parsed from ``texts``, default: the transcriptions, symmetry-3 corrected; union-find on
    the coefficient names)."""
    texts = texts if texts is not None else _symmetry_texts()
    labels = united_system(n)
    idx = index_of(n)
    parent = list(range(len(labels)))

    def find(x: int) -> int:
        while parent[x] != x:
            x = parent[x]
        return x

    for tex in texts.values():
        for a, b in symmetry_pairs(tex, n):
            parent[find(idx[a])] = find(idx[b])
    groups: dict[int, list[int]] = {}
    for k in range(len(labels)):
        groups.setdefault(find(k), []).append(k)
    return sorted(groups.values())


def symmetry_check(lid: str) -> LineResult:
    """A printed symmetry condition (parsed: both coefficients, the ranges of j and i) holds for the coefficients of
    the exact collocation solve without symmetry (n = 1..3, two alpha), and the three conditions together are
    complete: their classes are the orbits of the six permutations of (u, v, w) ((n+1)(n+2)/2 of them, n = 1..6)."""
    how = ("the condition parsed; exact collocation coefficients without symmetry (n = 1..3, tan(alpha/4) in "
           "{1/3, 2/5}); with the other two conditions its classes are the permutation orbits (n = 1..6)")

    def holds(tex_of: dict[str, str]) -> tuple[bool, dict]:
        rows = {}
        for n in (1, 2, 3):
            rows[f"n={n}"] = all(_coef(n, t, a) == _coef(n, t, b) for t in TS[:2]
                                 for a, b in symmetry_pairs(tex_of[lid], n))
        for n in range(1, 7):
            rows[f"complete n={n}"] = symmetry_partition(n, tex_of) == permutation_orbits(n)
        return all(rows.values()), rows

    printed_ok, corrected_ok, rows = False, None, {}
    try:
        printed_ok, rows = holds(_symmetry_texts(lid))
    except (LatexMathError, ValueError, TypeError) as exc:
        rows = {"unread": str(exc)[:200]}
    if line(lid).status == "erratum":
        tex = verbatim(lid)
        corrected_ok = False
        if ",," in tex:  # the slip the erratum records is in the transcription
            try:
                corrected_ok, rows["corrected"] = holds(_symmetry_texts(lid, corrected=True))
            except (LatexMathError, ValueError, TypeError) as exc:
                rows["corrected_unread"] = str(exc)[:200]
    return LineResult(printed_ok, corrected_ok, how=how, kind="exact-evidence", detail=rows)


for _w in SYMMETRY_LINES:
    line_check(_w)(lambda _w=_w: symmetry_check(_w))


def permutation_orbits(n: int) -> list[list[int]]:
    """Orbits of the functions of T_{2n} under the six permutations of (u, v, w) (exponent vectors)."""
    perms = [p for p in product(range(3), repeat=3) if len(set(p)) == 3]
    groups: dict[tuple, list[int]] = {}
    for k, lab in enumerate(united_system(n)):
        e = exponents(lab)
        pairs = ((e[0], e[1]), (e[2], e[3]), (e[4], e[5]))
        groups.setdefault(min(tuple(pairs[p[m]] for m in range(3)) for p in perms), []).append(k)
    return sorted(groups.values())


def unknown_classes(n: int, pairs: list[tuple[int, int]] | None = None,
                    element: sympy.Expr | None = None) -> tuple[int, bool, bool]:
    """Number of classes of the printed symmetry conditions, whether each holds exactly one of the printed unknowns
    ``pairs`` ((i, j) of r_{2n,2n-i,j}; default {j=0..n, i=j..n}), and whether the classes are the permutation
    orbits."""
    part = symmetry_partition(n)
    idx = index_of(n)
    pairs = pairs if pairs is not None else [(i, j) for j in range(n + 1) for i in range(j, n + 1)]
    if element is None:
        names = [f"r_{{{2 * n},{2 * n - i},{j}}}" for i, j in pairs]
    else:
        i_, j_, n_ = sympy.symbols("i j n")
        names = [_name(element.subs({n_: n, i_: i, j_: j})) for i, j in pairs]
    if any(x not in idx for x in names):
        return len(part), False, part == permutation_orbits(n)
    reps = sorted(idx[x] for x in names)
    one_each = all(len(set(g) & set(reps)) == 1 for g in part) and \
        sorted(min(set(g) & set(reps)) for g in part) == reps
    return len(part), one_each, part == permutation_orbits(n)


@cache
def triangular_levels(n: int) -> dict[int, bool]:
    """For each order r = 0..n of system_partition_of_unity (in the class unknowns of the printed symmetry
    conditions, exact, tan(alpha/4) = 1/3, 3n+3 rational x): the order-r equations do not involve the classes of
    level > r, and they determine the classes of level r (full column rank on them) -- the lower triangular
    structure by which the order r gives the level r."""
    t = TS[0]
    al = rational_alpha(t)
    sa, ca = Q(int(al.sin_half.p), int(al.sin_half.q)), Q(int(al.cos_half.p), int(al.cos_half.q))
    part = symmetry_partition(n)
    idx = index_of(n)
    level = []
    for g in part:
        js = [j for j in range(n + 1) for i in range(j, n + 1) if idx.get(f"r_{{{2 * n},{2 * n - i},{j}}}") in g]
        level.append(js[0] if len(js) == 1 else -1)
    xs = [Q(m, 7 * int(t.q)) for m in range(1, 3 * n + 4)]
    out = {}
    for r in range(n + 1):
        rows = []
        for q in xs:
            sx, cx = _angle(q)
            su, cu = sa * cx - ca * sx, ca * cx + sa * sx
            vals = [y_derivative_at_0(exponents(lab), r, su, cu, sx, cx) for lab in united_system(n)]
            rows.append([sum((vals[k] for k in mem), Q(0)) for mem in part])
        above = all(row[c] == 0 for row in rows for c in range(len(part)) if level[c] > r)
        cols = [c for c in range(len(part)) if level[c] == r]
        sub = fmpq_mat([[fmpq(row[c].numerator, row[c].denominator) for c in cols] for row in rows])
        out[r] = above and -1 not in level and sub.rank() == len(cols)
    return out


def check_orders(tex: str, n_max: int = 3) -> tuple[bool, dict]:
    """The orders ``$2\\leq r\\leq n$`` of the line parsed: they are exactly the orders left after Remark
    normalizing_coeff_of_level_0 (level 0) and Proposition prop:level_1_coefficients (level 1), and each order r
    determines the level r (:func:`triangular_levels`, n = 1..n_max)."""
    seg = next((x for x in tex.split("$")[1::2] if "\\leq" in x or "\\geq" in x), None)
    if seg is None:
        raise LatexMathError("no orders 'a \\leq r \\leq b' read")
    rel = P.relation(seg)
    r_, n_ = sympy.symbols("r n")
    if rel.ops != ["<=", "<="] or rel.parts[1] != r_:
        raise LatexMathError(f"orders read as {rel.ops} {rel.parts}")
    rows = {}
    for n in range(2, n_max + 1):
        printed = set(range(int(rel.parts[0].subs(n_, n)), int(rel.parts[2].subs(n_, n)) + 1))
        levels = triangular_levels(n)
        rows[str(n)] = printed == set(range(2, n + 1)) and all(levels.values())
    return all(rows.values()), rows


@line_check("sec4_5-unknowns")
def check_unknowns(override: dict[str, str] | None = None) -> LineResult:
    """The unknowns {r_{2n,2n-i,j}}_{j=0,i=j}^{n,n} of both lines that print them (read from the transcriptions)."""

    rows = {}
    for n in range(1, 11):
        sets = []
        for tex in _texts({"sec4_5-unknowns", "sec4_5-closed-forms-index"}, override).values():
            try:
                (jv, jlo, jhi), (iv, ilo, ihi) = P.index_set(tex)
            except ValueError as exc:
                return LineResult(False, how="the unknowns read from the transcriptions, n <= 10", kind="exhaustive",
                                  detail={"unread": str(exc)})
            sets.append(sorted((i, j) for j in range(P.bound(jlo, n=n), P.bound(jhi, n=n) + 1)
                               for i in range(P.bound(ilo, n=n, j=j), P.bound(ihi, n=n, j=j) + 1)))
        elements = []
        for tex in _texts({"sec4_5-unknowns", "sec4_5-closed-forms-index"}, override).values():
            try:  # the member of the one bounded set of the line's $..$ segments
                fams = [p for seg in LM.inline_math(tex) for p in LM.parse_relation(seg).parts
                        if isinstance(p, AppliedUndef) and p.func == LM.Family]
            except LatexMathError:
                fams = []
            elements.append(P.constants_as_factors(fams[0].args[0]) if len(fams) == 1 else None)
        if None in elements or elements[0] != elements[1]:
            return LineResult(False, how="the unknowns read from the transcriptions, n <= 10", kind="exhaustive",
                              detail={"unread": f"the members {elements}"})
        c, one, orb = unknown_classes(n, sets[0], elements[0])
        rows[n] = (c, one and all(x == sets[0] for x in sets), orb)
    ok = all(c == (n + 1) * (n + 2) // 2 and one and orb for n, (c, one, orb) in rows.items())
    texts = _texts({"sec4_5-unknowns", "sec4_5-closed-forms-index"}, override)
    try:
        orders_ok, orders = check_orders(texts["sec4_5-closed-forms-index"])
        labels = [x for tex in texts.values() for x in P.foreign_tags(tex)]
        if labels:
            raise LatexMathError(f"superscripts other than alpha: {labels}")
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how="the unknowns and orders read from the transcriptions, n <= 10",
                          kind="exhaustive", detail={"unread": str(exc)[:200]})
    ok &= orders_ok
    return LineResult(ok, how="union-find of the delta_n coefficients by symmetry_condition_1..3: (n+1)(n+2)/2 "
                      "classes, one per member of {r_{2n,2n-i,j}}_{j=0,i=j}^{n,n}, equal to the orbits of the six "
                      "permutations of (u, v, w) (n <= 10)", kind="exhaustive",
                      detail={str(n): c for n, (c, _, _) in rows.items()})


@line_check("sec4_5-matrix-sizes")
def check_matrix_sizes() -> LineResult:
    """The three sizes of the remark, parsed from the transcription (``\\delta_{n}=3n(n+1)+1``, then the size after
    symmetry_condition_1..3, then after Remark normalizing_coeff_of_level_0), against: the number of functions of
    T_{2n}; the number of classes of the printed symmetry conditions (parsed, = permutation orbits); those classes
    less the ones holding a coefficient of level 0 (r_{2n,2n-i,0} = c_{2n,i} known), n = 1..10."""
    how = ("the three sizes parsed from the transcription vs |T_{2n}|, the classes of the parsed symmetry conditions "
           "and those without a coefficient of level 0, n = 1..10")
    n_ = sympy.Symbol("n")
    try:
        segs = verbatim("sec4_5-matrix-sizes").split("$")[1::2]
        if len(segs) != 3:
            raise LatexMathError(f"{len(segs)} formulas, three sizes expected")
        first = P.relation(segs[0])
        if first.ops != ["="] or first.parts[0] != sympy.Function("delta")(n_):
            raise LatexMathError(f"not delta_n = ..: {segs[0]!r}")
        sizes = [first.parts[1], P.value(segs[1]), P.value(segs[2])]
        rows, ok = {}, True
        for n in range(1, 11):
            part = symmetry_partition(n)
            idx = index_of(n)
            level0 = {idx[f"r_{{{2 * n},{2 * n - i},0}}"] for i in range(2 * n + 1)}
            truth = [len(united_system(n)), len(part), sum(1 for g in part if not set(g) & level0)]
            got = [s.subs(n_, n) for s in sizes]
            rows[str(n)] = [int(x) for x in truth]
            ok &= got == truth and part == permutation_orbits(n)
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    return LineResult(ok, how=how, kind="exhaustive", detail={"sizes_per_n": rows})


# -- system of equations and derivatives ----------------------------------------------------------------------------
def _d(poly: dict, k: int) -> dict:
    """k-th derivative of sum q S^s C^c (S = sin(t/2), C = cos(t/2))."""
    for _ in range(k):
        out: dict = {}
        for (s, c), q in poly.items():
            if s:
                out[(s - 1, c + 1)] = out.get((s - 1, c + 1), Q(0)) + q * Q(s, 2)
            if c:
                out[(s + 1, c - 1)] = out.get((s + 1, c - 1), Q(0)) - q * Q(c, 2)
        poly = {m: q for m, q in out.items() if q}
    return poly


def y_derivative_at_0(e, r: int, su, cu, sx, cx) -> Q:
    """d^r/dy^r of the monomial ``e`` under u = alpha - x, v = y, w = x - y at y = 0, by the printed chain rule."""
    tot = Q(0)
    base = su ** e[0] * cu ** e[1]
    for k in range(r + 1):
        dv = _d({(e[2], e[3]): Q(1)}, r - k)
        dw = _d({(e[4], e[5]): Q(1)}, k)
        v0 = sum((q for (s, c), q in dv.items() if s == 0), Q(0))
        wx = sum((q * sx ** s * cx ** c for (s, c), q in dw.items()), Q(0))
        tot += comb(r, k) * (-1) ** k * v0 * wx
    return base * tot


def _angle(q: Q) -> tuple[Q, Q]:
    return Q(2 * q, 1 + q * q), Q(1 - q * q, 1 + q * q)


def example_heads() -> dict[int, list[str]]:
    """The coefficient at the head of each chain of Examples normalizing_coefficients_n_1..3 (the first part of the
    lines ``-r-c`` and ``-mid``, parsed), by order."""
    out: dict[int, list[str]] = {}
    for ln in pl.LINES:
        if ln.near.startswith("normalizing_coefficients_n_") and ln.id.endswith(("-r-c", "-mid")):
            head = P.relation(verbatim(ln.id)).parts[0]
            out.setdefault(int(ln.near.rsplit("_", 1)[1]), []).append(_name(head))
    return out


def read_system(tex: str, orders: str) -> dict:
    """system_partition_of_unity parsed by :func:`~paper_repro.printed.latex_math.parse_relation`: the derivative
    ``\\left. \\frac{\\partial^{r}}{\\partial y^{r}}L(u(x,y), v(x,y), w(x,y)) \\right\\vert_{y=0}`` (its order, the
    variable, the point of evaluation, the arguments), the Kronecker delta ``\\delta_{r,0}``, the quantified interval of
    x, and the orders ``\\forall r=..``."""
    rel = LM.parse_relation(tex)
    r_, x_, y_ = sympy.symbols("r x y")
    if rel.ops != ["="] or rel.lead or len(rel.parts) != 2 or not isinstance(rel.parts[0], sympy.Subs):
        raise LatexMathError("d^r/dy^r L(u(x,y), v(x,y), w(x,y)) at y = .. = delta_{r,0}, forall x in .. not read")
    deriv, (pv,), (at,) = rel.parts[0].args
    args = sympy.Tuple(*[sympy.Function(c)(sympy.Tuple(x_, y_)) for c in "uvw"])
    if not (isinstance(deriv, AppliedUndef) and deriv.func.__name__ == "D" and len(deriv.args) == 2) or \
            deriv.args[0] != sympy.Function("L")(args):
        raise LatexMathError(f"{deriv} is not a derivative of L(u(x,y), v(x,y), w(x,y))")
    if deriv.args[1] != sympy.Tuple(y_, r_) or pv != y_:
        raise LatexMathError("the derivative is not d^r/dy^r")
    delta = rel.parts[1]
    if at != 0 or not (isinstance(delta, AppliedUndef) and delta.func.__name__ == "delta") or \
            delta.args != (r_, 0):
        raise LatexMathError("not at y = 0, or not delta_{r,0}")
    if len(rel.conditions) != 1 or rel.conditions[0].quantifier != "forall":
        raise LatexMathError("no quantified clause 'for all x in ..'")
    lo, hi = P.interval(rel, "x")
    if (lo, hi) != (0, sympy.Symbol("alpha")):
        raise LatexMathError(f"x in [{lo}, {hi}], not [0, alpha]")
    quantified = LM.parse_relation(orders)
    if quantified.quantifier != "forall":
        raise LatexMathError("no quantifier 'for all r'")
    return {"orders": P.listed_range(quantified, "r")}


@line_check("sec4_5-system")
def check_system(override: dict[str, str] | None = None) -> LineResult:
    """system_partition_of_unity parsed (:func:`read_system`), with the words 'the unique solution' of the three
    Examples: the system holds with the exact coefficients at the printed orders, and with the symmetry conditions
    (parsed) it determines them (full rank: the unique solution); each Example lists every unknown
    {r_{2n,2n-i,j}}_{j=0,i=j}^{n,n} once (the heads of its chains, parsed)."""
    t = _texts({"sec4_5-system", "sec4_5-system-r-range", "sec4_5-unique-solution-n1", "sec4_5-unique-solution-n2",
                "sec4_5-unique-solution-n3"}, override)
    try:
        _r, r_lo_e, r_hi_e = read_system(t["sec4_5-system"], t["sec4_5-system-r-range"])["orders"]
        for k in (1, 2, 3):
            if LM.sentence("...the unique solution...", t[f"sec4_5-unique-solution-n{k}"]) is None:
                raise LatexMathError(f"'the unique solution' not read in Example n = {k}")
        listed = example_heads()
        for k in (1, 2, 3):  # "the unique solution ... is": each Example lists every unknown once
            want = sorted(f"r_{{{2 * k},{2 * k - i},{j}}}" for j in range(k + 1) for i in range(j, k + 1))
            if sorted(listed.get(k, [])) != want:
                raise LatexMathError(f"Example n = {k} lists {sorted(listed.get(k, []))}, the unknowns are {want}")
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how="the system read from the transcription", detail={"unread": str(exc)[:200]})
    r_lo, r_hi = r_lo_e, r_hi_e
    ok, info = True, {}
    for n in (1, 2, 3):
        t = TS[0]
        al = rational_alpha(t)
        sa, ca = Q(int(al.sin_half.p), int(al.sin_half.q)), Q(int(al.cos_half.p), int(al.cos_half.q))
        coef = {lab.coefficient: _full(n, t)[lab.coefficient] for lab in united_system(n)}
        xs = [Q(m, 7 * int(t.q)) for m in range(1, 3 * n + 4)]  # tan(x/4), x in (0, alpha)
        rows_full, rows_orbit = [], []
        part = symmetry_partition(n)
        for q in xs:
            sx, cx = _angle(q)
            su, cu = sa * cx - ca * sx, ca * cx + sa * sx  # (alpha - x)/2
            for r in range(P.bound(r_lo, n=n), P.bound(r_hi, n=n) + 1):
                vals = [y_derivative_at_0(exponents(lab), r, su, cu, sx, cx) for lab in united_system(n)]
                lhs = sum((Q(int(coef[lab.coefficient].p), int(coef[lab.coefficient].q)) * v
                           for lab, v in zip(united_system(n), vals)), Q(0))
                ok &= lhs == (1 if r == 0 else 0)
                rows_full.append(vals)
                rows_orbit.append([sum((vals[k] for k in mem), Q(0)) for mem in part])

        def rank(rows):
            return fmpq_mat([[fmpq(x.numerator, x.denominator) for x in row] for row in rows]).rank()

        info[str(n)] = {"rank_without_symmetry": rank(rows_full), "delta_n": len(united_system(n)),
                        "rank_with_symmetry": rank(rows_orbit), "unknowns_with_symmetry": len(part)}
        ok &= info[str(n)]["rank_with_symmetry"] == info[str(n)]["unknowns_with_symmetry"]
    return LineResult(ok, how="exact y-derivatives at y = 0 (orders 0..n) of L with the exact coefficients at "
                      f"tan(alpha/4) = {TS[0]} and 3n+3 rational x: delta_{{r,0}}; the system's rank in the orbit "
                      "unknowns (symmetry_condition_1..3 imposed) is full, without them it is not",
                      kind="exact-evidence", detail=info)


def read_parametrization(tex: str) -> dict:
    """The line ``For each order $r=1,2,\\ldots,n$, after evaluating ... with respect to $v\\left( x,y\\right) =y$
    and $w\\left( x,y\\right) =x-y$ at $y=0$`` parsed: the orders (r, lo, hi), v and w as sympy expressions in x, y,
    and the point y."""
    segs = tex.split("$")[1::2]
    out: dict = {}
    xy = sympy.Tuple(*sympy.symbols("x y"))
    for seg in segs:
        rel = LM.parse_relation(seg)
        head = rel.parts[0] if rel.parts else None
        if (isinstance(head, AppliedUndef) and head.func.__name__ in ("u", "v", "w") and head.args == (xy,)
                and rel.ops == ["="] and len(rel.parts) == 2 and not rel.conditions and rel.lead is None):
            if head.func.__name__ in out:
                raise LatexMathError(f"{head.func.__name__}(x, y) printed twice")
            out[head.func.__name__] = P.constants_as_factors(rel.parts[1])
        elif "\\ldots" in seg:
            out["orders"] = P.listed_range(seg, "r")
        elif seg.strip().startswith("y"):
            rel = P.relation(seg)
            if rel.ops != ["="] or rel.parts[0] != sympy.Symbol("y"):
                raise LatexMathError(f"point {seg!r} not read")
            out["y0"] = rel.parts[1]
    if set(out) != {"orders", "v", "w", "y0"}:
        raise LatexMathError(f"read {sorted(out)}, expected the orders, v, w and the point y")
    return out


@line_check("sec4_5-chain-rule")
def check_chain_rule() -> LineResult:
    """The parametrization of the line parsed (v(x,y), w(x,y), u = alpha - v - w; the orders r; the point y): for
    every function f of T_{2n} (n <= 2) and every printed order r <= n, d^r/dy^r f(u, v, w) equals the printed chain
    sum (binomial, sign, orders in v and w read from line sec4_5-chain-sum) as an identity in (x, y) (exact
    exponential expansion); the point y is the chain sum's; and at the printed orders the chain sum of L vanishes
    (check sec4_5-chain-sum, which reads the orders from this line)."""

    how = ("the parametrization and orders parsed; chain rule as identities in (x, y) by exact exponential expansion, "
           "n = 1..2; the printed chain sum vanishes at the printed orders (n = 1..3, exact)")
    x_, y_ = sympy.symbols("x y")
    try:
        par = read_parametrization(verbatim("sec4_5-parametrization-restated"))
        chain = read_chain_sum(verbatim("sec4_5-chain-sum"))
        if chain["y0"] != par["y0"]:
            raise LatexMathError(f"the point y = {par['y0']} is not the chain sum's y = {chain['y0']}")
        lin = {}
        for var in ("v", "w"):
            p = sympy.Poly(par[var], x_, y_)
            if p.total_degree() > 1 or p.coeff_monomial(1) != 0:
                raise LatexMathError(f"{var}(x,y) = {par[var]} is not linear homogeneous")
            lin[var] = (int(p.coeff_monomial(x_)), int(p.coeff_monomial(y_)))
        # u = alpha - v - w (u + v + w = alpha): the constant alpha is a phase, the same on both sides
        to_xy = ((-(lin["v"][0] + lin["w"][0]), -(lin["v"][1] + lin["w"][1])), lin["v"], lin["w"])
        _r, r_lo, r_hi = par["orders"]
        n_ = sympy.Symbol("n")
        ok = True
        for n in (1, 2):
            orders = range(int(r_lo.subs(n_, n)), int(r_hi.subs(n_, n)) + 1)
            for lab in united_system(n):
                f = half_monomial(exponents(lab))
                for r in orders:
                    direct = f.linear(to_xy)
                    for _ in range(r):
                        direct = direct.diff(1)
                    formula = EP(2)
                    for k in range(P.bound(chain["klo"], r=r), P.bound(chain["khi"], r=r) + 1):
                        g = f
                        for _ in range(P.bound(chain["pv"], r=r, k=k)):
                            g = g.diff(1)
                        for _ in range(P.bound(chain["pw"], r=r, k=k)):
                            g = g.diff(2)
                        weight = chain_weight(chain, r, k)
                        formula = formula + g.linear(to_xy) * weight
                    ok &= direct == formula
        vanishes = check_chain_sum().holds_as_printed
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    return LineResult(ok and vanishes, how=how, kind="exhaustive",
                      detail={"chain_rule_identities": ok, "chain_sum_vanishes": vanishes,
                              "v": str(par["v"]), "w": str(par["w"])})


def surviving_degrees(n: int, par: dict | None = None) -> set[int]:
    """Total degrees, in the four half-angle functions of (alpha - x)/2 and x/2, of the terms of the y-derivatives
    (orders 0..n) at y = 0 of the functions of T_{2n} that do not vanish at v = 0 (exponent bookkeeping)."""
    out = set()
    for lab in united_system(n):
        e = exponents(lab)
        for r in range(n + 1):
            for k in range(r + 1):
                dv = {m: q for m, q in _d({(e[2], e[3]): Q(1)}, r - k).items() if m[0] == 0}
                if not dv:
                    continue
                for (s, c), _q in _d({(e[4], e[5]): Q(1)}, k).items():
                    out.add(e[0] + e[1] + s + c)
    return out


@line_check("sec4_5-tan-polynomial")
def check_tan_polynomial() -> LineResult:
    """The line parsed: the variable of the polynomial (tan(x/2)), the four functions whose powers are summed, and
    the sum (2n).  The four functions are the half-angle functions of u = alpha - x and w = x at y = 0 (from the
    parametrization line, parsed), and every term not vanishing at v = 0 has exactly the printed total degree
    (n = 1..6): a form of that degree, linear in sin(x/2), cos(x/2) after expanding (alpha - x)/2, divided by
    cos^{2n}(x/2) is a polynomial in tan(x/2)."""
    how = ("the line parsed (tan(x/2), the four functions, the degree 2n); exponent bookkeeping of the derivatives "
           "of the monomials, n = 1..6")
    n_, x_, a_ = sympy.symbols("n x alpha")
    try:
        segs = [P.value(s) for s in verbatim("sec4_5-tan-polynomial").split("$")[1::2]]
        if len(segs) != 6:
            raise LatexMathError(f"{len(segs)} formulas read, six expected")
        par = read_parametrization(verbatim("sec4_5-parametrization-restated"))
        u0 = (a_ - par["v"] - par["w"]).subs(sympy.Symbol("y"), par["y0"])
        w0 = par["w"].subs(sympy.Symbol("y"), par["y0"])
        funcs = {f(sympy.expand(z / 2)) for f in (sympy.sin, sympy.cos) for z in (u0, w0)}
        variable_ok = segs[0] == sympy.tan(sympy.expand(w0 / 2))
        funcs_ok = set(segs[1:5]) == funcs and len(set(segs[1:5])) == 4
        degree = segs[5]
        per_n = {str(n): surviving_degrees(n) == {int(degree.subs(n_, n))} for n in range(1, 7)}
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    return LineResult(variable_ok and funcs_ok and all(per_n.values()), how=how, kind="exhaustive",
                      detail={"variable": variable_ok, "four_functions": funcs_ok, "degree_per_n": per_n})


def y_range_maps_into_omega(upper) -> tuple[bool, bool]:
    """Parameter triangle x in [0, a], y in [0, upper(a, x)] under u = a - x, v = y, w = x - y: inside, onto."""
    a = Q(3, 2)
    inside = all(min(a - x, y, x - y) >= 0
                 for x in (Q(k, 8) * a for k in range(9)) for y in (Q(m, 8) * upper(a, x) for m in range(9)))
    corners = {(a - x, y, x - y) for x, y in ((Q(0), Q(0)), (a, Q(0)), (a, upper(a, a)))}
    onto = corners == {(a, 0, 0), (0, 0, a), (0, a, 0)}
    return inside, onto


@line_check("sec4_5-y-range-1980")
def check_y_range() -> LineResult:
    """The interval of y parsed from the line (lower and upper end): with the parametrization u = alpha - x,
    v = y, w = x - y the printed triangle leaves Omega^alpha; the correction recorded in the erratum (the upper end
    alpha - x, as printed, replaced by x) maps it onto Omega^alpha."""

    how = "exact images of a grid of the parameter triangle (alpha = 3/2) under parametrization_for_partition_of_unity"
    x_, a_ = sympy.symbols("x alpha")
    try:
        lo, hi = P.interval(verbatim("sec4_5-chain-y-range"), "y")
        if lo.free_symbols - {x_, a_} or hi.free_symbols - {x_, a_}:
            raise LatexMathError("the interval names other variables")
    except (LatexMathError, ValueError) as exc:
        return LineResult(False, False, how=how, kind="proof", detail={"unread": str(exc)[:200]})

    def maps(lo_e, hi_e) -> tuple[bool, bool]:
        def upper(a, x):
            return Q(str(hi_e.subs({a_: sympy.Rational(a.numerator, a.denominator),
                                    x_: sympy.Rational(x.numerator, x.denominator)})))
        low_zero = lo_e == 0
        inside, onto = y_range_maps_into_omega(upper)
        return inside and low_zero, onto and low_zero

    printed = maps(lo, hi)
    recorded = sympy.expand(hi - (a_ - x_)) == 0  # the slip the erratum records is the one printed
    corrected = maps(lo, x_) if recorded else (False, False)
    return LineResult(all(printed), all(corrected), how=how, kind="proof",
                      detail={"printed_inside_onto": list(printed), "corrected_inside_onto": list(corrected),
                              "printed_upper_end": str(hi), "witness": "x = alpha/4, y = alpha/2 gives w = -alpha/4"})


# -- normalizing coefficients of level 0, 1 and the Examples: the printed formulas parsed ----------------------------
S_, C_ = sympy.symbols("S C")  # sin(alpha/2), cos(alpha/2)
_ALPHA = sympy.Symbol("alpha")


def _sc(t: fmpq) -> tuple[fmpq, fmpq]:
    al = rational_alpha(t)
    return al.sin_half, al.cos_half


def c_indep(n: int, t: fmpq):
    s, c = _sc(t)
    polys = c_numerator_by_expansion(n)
    return lambda i: polys[i](c) / s ** (2 * n)


@cache
def _orbit_coefs(n: int, t: fmpq) -> dict:
    return coefficients(n, rational_alpha(t), "exact")


@cache
def _closed_forms(n: int) -> dict:
    from paper_repro.theory.closed_forms import closed_forms_cached

    return closed_forms_cached(n)


@cache
def _closed_forms_proven(n: int) -> bool:
    from paper_repro.theory.closed_forms import proof_cached

    return bool(proof_cached(n)["proved"])


def _poly(p, var) -> sympy.Expr:
    return sum((sympy.Rational(int(a.p), int(a.q)) * var**k for k, a in enumerate(p.coeffs())), sympy.Integer(0))


def _ints(args) -> tuple[int, ...]:
    out = []
    for a in args:
        if not (isinstance(a, sympy.Integer) or (a.is_number and a.is_integer)):
            raise LatexMathError(f"index {a} is not an integer")
        out.append(int(a))
    return tuple(out)


def c_truth(n2: int, i: int) -> sympy.Expr:
    """c_{2n,i}^alpha = P_i(cos(alpha/2)) / sin^{2n}(alpha/2), P_i from the expansion of (X^2 + 2cXY + Y^2)^n
    (:func:`paper_repro.core.univariate.c_numerator_by_expansion`), in the symbols S, C."""
    if n2 < 2 or n2 % 2 or not 0 <= i <= n2:
        raise LatexMathError(f"no univariate constant c_{{{n2},{i}}}")
    return _poly(c_numerator_by_expansion(n2 // 2)[i], C_) / S_**n2


def r_truth(n2: int, k: int, j: int) -> sympy.Expr:
    """r_{2n,k,j}^alpha in closed form P(C)/S^m, proven for every alpha (:mod:`paper_repro.theory.closed_forms`);
    a name that is not a coefficient of T_{2n} is refused."""
    if n2 < 2 or n2 % 2:
        raise LatexMathError(f"r_{{{n2},{k},{j}}}: no order")
    forms = _closed_forms(n2 // 2)
    label = f"r_{{{n2},{k},{j}}}"
    if label not in forms:  # r_{2n,i,j} with i < n: the same orbit as r_{2n,2n-i,j} (symmetry_condition_1)
        mirror = f"r_{{{n2},{n2 - k},{j}}}"
        if label not in {lab.coefficient for lab in united_system(n2 // 2)} or mirror not in forms:
            raise LatexMathError(f"{label} is not a normalizing coefficient")
        label = mirror
    f = forms[label]
    return _poly(f.numerator, C_) / S_**f.sin_power


def in_s_c(expr: sympy.Expr, r_values=None, c_values=None) -> sympy.Expr:
    """A parsed expression with sin(alpha/2) -> S, cos(alpha/2) -> C, the named objects c_{2n,i}, r_{2n,k,j} replaced
    by their independent values (:func:`c_truth`, :func:`r_truth`, or the given functions); anything else (alpha
    left over, an unknown name, a free letter such as a blank ``XXX``) is refused."""
    e = expr.subs({sympy.sin(_ALPHA / 2): S_, sympy.cos(_ALPHA / 2): C_})
    rv, cv = r_values or r_truth, c_values or c_truth
    rep = {}
    for a in e.atoms(sympy.core.function.AppliedUndef):
        name = a.func.__name__
        if name == "c" and len(a.args) == 2:
            rep[a] = cv(*_ints(a.args))
        elif name == "r" and len(a.args) == 3:
            rep[a] = rv(*_ints(a.args))
        else:
            raise LatexMathError(f"unknown object {a}")
    e = e.xreplace(rep)
    if e.free_symbols - {S_, C_}:
        raise LatexMathError(f"unread symbols {sorted(map(str, e.free_symbols - {S_, C_}))}")
    return e


def identically_zero(e: sympy.Expr) -> bool:
    """e (a rational function of S = sin(alpha/2), C = cos(alpha/2)) vanishes for every alpha: its numerator reduced
    modulo S^2 + C^2 - 1 is the zero polynomial."""
    num, _den = sympy.fraction(sympy.together(e))
    rem = sympy.reduced(sympy.expand(num), [S_**2 + C_**2 - 1], S_, C_, order="lex")[1]
    return sympy.expand(rem) == 0


def at_alpha(e: sympy.Expr, t: fmpq) -> sympy.Rational:
    s, c = _sc(t)
    return e.subs({S_: sympy.Rational(int(s.p), int(s.q)), C_: sympy.Rational(int(c.p), int(c.q))})


def _collocation_r(t: fmpq):
    def value(n2: int, k: int, j: int) -> sympy.Expr:
        co = _orbit_coefs(n2 // 2, t)
        label = f"r_{{{n2},{k},{j}}}"
        if label not in co:
            raise LatexMathError(f"{label} is not a normalizing coefficient")
        x = co[label]
        return sympy.Rational(int(x.p), int(x.q))
    return value


def _collocation_c(t: fmpq):
    def value(n2: int, i: int) -> sympy.Expr:
        x = c_indep(n2 // 2, t)(i)
        return sympy.Rational(int(x.p), int(x.q))
    return value


def chain_holds(parts: list, head=None) -> tuple[bool, bool, dict]:
    """Every part of a printed chain ``a = b = ...`` (and the head ``head``, the coefficient the chain is about) is
    the same function of alpha: (1) an identity in alpha with c_{2n,i} by expansion and r_{2n,k,j} in the closed
    form proven for every alpha, (2) at three rational-tangent alpha with r_{2n,k,j} by exact collocation."""
    every = list(parts) + ([head] if head is not None else [])
    if len(every) < 2:
        raise LatexMathError("no chain of equalities")
    if not any(e.atoms(sympy.core.function.AppliedUndef) for e in every):
        raise LatexMathError("the chain names no normalizing coefficient or univariate constant")
    vals = [in_s_c(e) for e in every]
    identity = all(identically_zero(vals[0] - v) for v in vals[1:])
    samples = {}
    for t in TS:
        got = [in_s_c(e, _collocation_r(t), _collocation_c(t)) for e in every]
        got = [at_alpha(g, t) for g in got]
        samples[str(t)] = all(g == got[0] for g in got[1:])
    return identity, all(samples.values()), samples


def _rel(tex: str) -> Relation:
    return P.relation(tex)


def example_check(check_id: str) -> LineResult:
    """One line of Examples normalizing_coefficients_n_1..3, parsed from its transcription: every part of the printed
    chain equals the others and, for a closed form continuing a chain (``-final``), the coefficient named at the
    head of that chain (read from the line ``-mid``).  Univariate constants by expansion, coefficients in the
    closed form proven for every alpha (an identity in alpha: a proof) and by exact collocation at three alpha."""
    how = ("the printed chain parsed (latex_math) and compared part by part: an identity in alpha (numerators modulo "
           "S^2 + C^2 - 1) with c_{2n,i} from (X^2 + 2cXY + Y^2)^n and r_{2n,k,j} in the closed form proven for every "
           "alpha, and exact collocation at tan(alpha/4) in {1/3, 2/5, 1/7}")
    (ln,) = lines_of(check_id)
    try:
        rel = _rel(ln.verbatim)
        if set(rel.ops) != {"="}:
            raise LatexMathError(f"relations {rel.ops}, the Example prints equalities")
        head = None
        if check_id.endswith("-final"):
            head_rel = _rel(verbatim(ln.id.replace("-final", "-mid")))
            head = head_rel.parts[0]
            if not (isinstance(head, sympy.core.function.AppliedUndef) and head.func.__name__ == "r"):
                raise LatexMathError(f"the chain's head {head} is not a coefficient r")
        identity, sampled, samples = chain_holds(rel.parts, head)
    except (LatexMathError, ValueError, TypeError, ZeroDivisionError) as exc:
        return LineResult(False, how=how, kind="proof", detail={"unread": str(exc)[:200]})
    n2 = max(int(a.args[0]) for p in rel.parts + ([head] if head is not None else [])
             for a in p.atoms(sympy.core.function.AppliedUndef))
    proven = _closed_forms_proven(n2 // 2)
    math_ok = identity and sampled
    # the notation: every named object carries the superscript alpha (a "-final" line repeats the combination of
    # its "-mid" line, where a slip is recorded once)
    bare = [] if check_id.endswith("-final") else P.untagged_names(ln.verbatim)
    ok = math_ok and not bare
    correct = (math_ok and bool(bare)) if ln.status == "erratum" else None  # the slip present, the value right
    return LineResult(ok, correct, how=how, kind="proof" if (identity and proven) else "exact-evidence",
                      detail={"identity_in_alpha": identity, "collocation_at_3_alpha": samples,
                              "closed_forms_proven": proven, "without_superscript_alpha": bare})


for _line in pl.LINES:
    if _line.check and _line.check.startswith("sec4_5-ex-") and _line.check not in CHECKS:
        line_check(_line.check)(lambda _c=_line.check: example_check(_c))


def _cases(tex: str) -> tuple[sympy.Expr, str]:
    """A row ``expression, & condition`` of the cases of eq. level_1_coefficients."""
    k = tex.find(", &")
    if k < 0:
        raise LatexMathError("no ', &' between the formula and its condition")
    return P.value(tex[:k]), tex[k + 3:].replace("\\\\", "").strip()


def _condition_values(cond: str, n: int) -> list[int]:
    i, n_ = sympy.Symbol("i"), sympy.Symbol("n")
    if "\\ldots" in cond:
        _v, lo, hi = P.listed_range(cond, "i")
        return list(range(int(lo.subs(n_, n)), int(hi.subs(n_, n)) + 1))
    rel = P.relation(cond.rstrip(".,").strip())
    if rel.ops != ["="] or rel.parts[0] != i or not rel.parts[1].is_number:
        raise LatexMathError(f"condition {cond!r} not read")
    return [int(rel.parts[1])]


@line_check("sec4_5-level-0")
def check_level_0() -> LineResult:
    """Remark normalizing_coeff_of_level_0, both lines parsed: r_{2n,2n-i,0} = c_{2n,2n-i} = c_{2n,i} for the printed
    range of i, every n = 1..8: identities in alpha (closed forms proven for every alpha, expansion of c)."""
    how = "both lines parsed; each part an identity in alpha for every i of the printed range, n = 1..8"
    n_, i_ = sympy.Symbol("n"), sympy.Symbol("i")
    try:
        t1 = verbatim("sec4_5-level0-r-c").replace("\\[", " ")
        t2 = verbatim("sec4_5-level0-c-c")
        k = t2.find(",~\\forall")
        if k < 0:
            raise LatexMathError("no quantifier ',~\\forall' read")
        _v, lo, hi = P.listed_range(t2[k:], "i")
        r1, r2 = P.relation(t1), P.relation(t2[:k])
        if r1.ops != ["="] or r2.ops != ["="] or r1.parts[1] != r2.parts[0]:
            raise LatexMathError("the two lines do not continue one chain")
        rows, ok = {}, True
        for n in range(1, 9):
            good = True
            for i in range(int(lo.subs(n_, n)), int(hi.subs(n_, n)) + 1):
                parts = [p.subs({n_: n, i_: i}) for p in r1.parts + r2.parts[1:]]
                vals = [in_s_c(p) for p in parts]
                good &= all(identically_zero(vals[0] - v) for v in vals[1:])
            rows[str(n)] = good
            ok &= good
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    return LineResult(ok, how=how, kind="exhaustive", detail={"per_n": rows, "i_range": [str(lo), str(hi)]})


@line_check("sec4_5-level-1")
def check_level_1() -> LineResult:
    """Proposition prop:level_1_coefficients parsed (the order bound n >= 2, the set {r_{2n,2n-i,1}}_{i=1}^{n}, the
    two cases of eq. level_1_coefficients with their conditions): for n = bound..7 and every i of the set the case
    whose condition holds is the coefficient (identity in alpha against the closed form proven for every alpha,
    and exact collocation at three alpha for n <= 5); the bound is sharp (the formula fails at n = bound - 1)."""
    how = ("the proposition parsed; n = lower bound..7, every i, identity in alpha with the proven closed forms and "
           "exact collocation at 3 alpha (n <= 5); the formula fails one order below the printed bound")
    n_, i_ = sympy.Symbol("n"), sympy.Symbol("i")
    try:
        rng = verbatim("sec4_5-level1-range")
        dollar = [s for s in rng.split("$")[1::2]]
        bound_rel = P.relation(dollar[0])
        if bound_rel.ops != [">="] or bound_rel.parts[0] != n_ or not bound_rel.parts[1].is_number:
            raise LatexMathError(f"order bound {dollar[0]!r} not read")
        n_lo = int(bound_rel.parts[1])
        fams = [p for seg in dollar[1:] for p in LM.parse_relation(seg).parts
                if isinstance(p, AppliedUndef) and p.func == LM.Family]
        r_ = sympy.Function("r")
        if (len(fams) != 1 or fams[0].args[0] != r_(2 * n_, 2 * n_ - i_, 1) or fams[0].args[1] != sympy.Tuple()
                or len(fams[0].args[2]) != 1 or fams[0].args[2][0][0] != i_
                or any(P.untagged_names(seg) for seg in dollar[1:])):
            raise LatexMathError(f"the set {{r_{{2n,2n-i,1}}}}_{{i=..}}^{{..}} not read: {fams}")
        i_lo, i_hi = fams[0].args[2][0][1:]
        rows = [_cases(verbatim("sec4_5-level1-i1")), _cases(verbatim("sec4_5-level1-i"))]

        def formula(n: int, i: int) -> sympy.Expr:
            hit = [e for e, cond in rows if i in _condition_values(cond, n)]
            if len(hit) != 1:
                raise LatexMathError(f"n = {n}, i = {i}: {len(hit)} cases apply")
            return hit[0].subs({n_: n, i_: i})

        ok, bad = True, []
        for n in range(n_lo, 8):
            for i in range(int(i_lo.subs(n_, n)), int(i_hi.subs(n_, n)) + 1):
                label = sympy.Function("r")(2 * n, 2 * n - i, 1)
                printed = formula(n, i)
                good = identically_zero(in_s_c(printed) - in_s_c(label))
                if n <= 5:
                    good &= chain_holds([printed], label)[1]
                ok &= good
                if not good:
                    bad.append([n, i])
        below = n_lo - 1
        sharp = below < 1 or not all(identically_zero(in_s_c(formula(below, i)) -
                                                      in_s_c(sympy.Function("r")(2 * below, 2 * below - i, 1)))
                                     for i in range(int(i_lo.subs(n_, below)), int(i_hi.subs(n_, below)) + 1))
    except (LatexMathError, ValueError, TypeError, IndexError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    how = how.replace("n = lower bound..7", f"n = {n_lo}..7")
    return LineResult(ok and sharp, how=how, kind="exhaustive",
                      detail={"n_range": [n_lo, 7], "failing": bad, "fails_one_order_below_the_bound": sharp})


def blending_centre_holds(tex: str, n: int) -> bool:
    """The chain ``\\overline{R}_{2n,n,n}(u,v,w) = \\overline{G}_{..} = \\overline{B}_{..} (= r_{2n,n,n} R_{2n,n,n})``
    parsed (the part before ``:`` of a set row): every relation '=', every part the same function at 4 rational
    points of Omega^alpha, X-bar = x X by Definition normalized_united_system (coefficients by exact collocation)."""
    body = tex.split(":")[0].replace("\\cup", " ").replace("\\left\\{", " ")
    rel = P.relation(body)
    if set(rel.ops) != {"="} or len(rel.parts) < 3:
        raise LatexMathError(f"the centre's chain not read: {rel.ops}")
    t = TS[0]
    alpha = rational_alpha(t)
    pts = sample_rational_points(alpha, 4, seed=5)
    vals = evaluate(n, alpha, pts, ExactContext())
    idx = index_of(n)
    n_ = sympy.Symbol("n")

    def value(e: sympy.Expr, p: int):
        out = fmpq(1)
        for f in sympy.Mul.make_args(e.subs(n_, n)):
            if not isinstance(f, sympy.core.function.AppliedUndef):
                raise LatexMathError(f"{f} not read")
            name = f.func.__name__
            if name.endswith("bar"):  # X-bar = x X (the definition rows of normalized_united_system)
                lab = f"{name[0]}_{{{','.join(str(x) for x in _ints(f.args[:-1]))}}}"
                out *= _coef(n, t, lab.lower()) * vals[p, idx[lab]]
            elif name in ("R", "G", "B"):
                out *= vals[p, idx[f"{name}_{{{','.join(str(x) for x in _ints(f.args[:-1]))}}}"]]
            elif name in ("r", "g", "b"):
                out *= _coef(n, t, f"{name}_{{{','.join(str(x) for x in _ints(f.args))}}}")
            else:
                raise LatexMathError(f"{f} not read")
            if name not in ("r", "g", "b") and f.args[-1] != sympy.Tuple(*sympy.symbols("u v w")):
                raise LatexMathError(f"{f}: arguments are not (u, v, w)")
        return out

    return all(len({value(e, p) for e in rel.parts}) == 1 for p in range(len(pts)))


def _weight_of(member, **env: int) -> str:
    """``r_{4,3,0}``: the weight of the parsed normalized function ``Rbar(2n, 2n-i, j, (u, v, w))`` at ``env``."""
    return f"{member.func.__name__[0].lower()}_{{{','.join(str(P.bound(a, **env)) for a in member.args[:-1])}}}"


def _the_set(tex: str):
    """The one set ``\\left\\{ .. : .. \\right\\}`` of a row of Definition normalized_united_system (parsed; the
    row ``\\overline{T}_{2n}^{\\alpha} = \\{..\\}_{..}^{..}`` or ``\\cup\\{..\\}``)."""
    found = [x for part in LM.parse_relation(tex).parts if part is not None
             for x in sympy.preorder_traversal(part) if isinstance(x, AppliedUndef) and x.func == LM.Family]
    if len(found) != 1:
        raise LatexMathError(f"{len(found)} sets in {tex[:50]!r}")
    return found[0]


@line_check("sec4_5-blending-def")
def check_blending_def(override: dict[str, str] | None = None) -> LineResult:
    """The index set of the normalized system (read from the transcription of its first row) names the non-central
    functions of T_{2n}; the centre row names R-bar, G-bar, B-bar_{2n,n,n} (read), one function."""
    from paper_repro.printed.latex_math import index_set

    texts = _texts({"sec4_5-blending-set", "sec4_5-blending-centre-set"}, override)
    try:  # the index set, read by the shared reader
        (jv, jlo_e, jhi_e), (iv, ilo_e, ihi_e) = index_set(texts["sec4_5-blending-set"])
        jv, iv = str(jv), str(iv)
        n_s, j_s = sympy.symbols("n j")

        def bound(e, **env):
            return int(e.subs({n_s: env["n"], j_s: env.get("j", 0)}))

        jlo, jhi, ilo, ihi = jlo_e, jhi_e, ilo_e, ihi_e
    except ValueError as exc:
        return LineResult(False, how="the index set read from the transcription, n <= 8", kind="exhaustive",
                          detail={"unread": str(exc)})
    texts["sec4_5-blending-centre"] = verbatim("sec4_5-blending-centre")
    try:  # the notation (superscripts alpha), the domain of each set, and the centre's chain of equalities
        for key in ("sec4_5-blending-set", "sec4_5-blending-centre-set", "sec4_5-blending-centre"):
            if P.foreign_tags(texts[key]):
                raise LatexMathError(f"{key}: superscripts other than alpha {P.foreign_tags(texts[key])}")
        sets = {key: _the_set(texts[key]) for key in ("sec4_5-blending-set", "sec4_5-blending-centre-set")}
        for key, fam in sets.items():
            if len(fam.args[1]) != 1 or _in_omega(fam.args[1][0]) != ("u", "v", "w"):
                raise LatexMathError(f"{key}: no ': (u,v,w) \\in \\Omega^{{\\alpha}}' read")
        centre_ok = all(blending_centre_holds(texts[key], n) for n in (1, 2, 3)
                        for key in ("sec4_5-blending-centre", "sec4_5-blending-centre-set"))
    except (LatexMathError, ValueError, TypeError) as exc:
        return LineResult(False, how="the normalized system read from the transcriptions", kind="exhaustive",
                          detail={"unread": str(exc)[:200]})
    # the members of each set (parsed): normalized functions X-bar applied to (u, v, w)
    listed = sets["sec4_5-blending-set"].args[0]
    members = list(listed) if isinstance(listed, sympy.Tuple) else [listed]
    centre_members = sorted(sets["sec4_5-blending-centre-set"].args[0].atoms(AppliedUndef), key=str)
    normalized = [m for m in members + centre_members if m.func.__name__ in ("Rbar", "Gbar", "Bbar")
                  and len(m.args) == 4 and m.args[-1] == sympy.Tuple(*sympy.symbols("u v w"))]
    colours = [m.func.__name__[0] for m in members if m in normalized]
    centre_names = [m.func.__name__[0] for m in centre_members if m in normalized]
    ok = (jv, iv) == ("j", "i") and sorted(colours) == ["B", "G", "R"] and sorted(centre_names) == ["B", "G", "R"]
    ok &= len(normalized) == len(members) + len(centre_members) and centre_ok
    for n in range(1, 9) if ok else ():
        named = sorted(_weight_of(m, n=n, i=i, j=j) for m in members
                       for j in range(bound(jlo, n=n), bound(jhi, n=n) + 1)
                       for i in range(bound(ilo, n=n, j=j), bound(ihi, n=n, j=j) + 1))
        ok &= named == sorted(lab.coefficient for lab in united_system(n) if not lab.is_centre)
        # X-bar_{2n,a,b}: the label of T_{2n} with i = 2n - a, j = b (Definition normalized_united_system)
        centre = [exponents(BasisLabel(m.func.__name__[0], n, 2 * n - P.bound(m.args[1], n=n), P.bound(m.args[2], n=n)))
                  for m in centre_members]
        ok &= len(set(centre)) == 1 and all(P.bound(m.args[0], n=n) == 2 * n for m in centre_members)
    return LineResult(ok, how="index set and centre read from the transcriptions vs the labels of T_{2n} (n <= 8); "
                      "R_{2n,n,n}, G_{2n,n,n}, B_{2n,n,n} have the same exponent vector", kind="exhaustive",
                      detail={"n_max": 8})




# -- the printed chain sum and its value 0 (read from the transcription) ---------------------------------------------
def read_chain_sum(tex: str) -> dict:
    """The parts of the printed chain sum ``\\sum_{k=lo}^{hi} w(r, k) \\left. d^r L / dv^{pv} dw^{pw}
    \\right\\vert_{y=y0} = rhs,~\\forall x\\in[..]`` read by :func:`paper_repro.printed.latex_math.parse_relation`
    (sympy): the bounds of k, the weight (binomial and sign: the factors beside the derivative), the orders in v
    and w, the point y, the right-hand side and the range of x."""
    from paper_repro.printed.latex_math import D, parse_relation

    rel = parse_relation(tex)
    if rel.ops != ["="] or len(rel.parts) != 2:
        raise ValueError(f"relations {rel.ops}, not one '='")
    total, rhs = rel.parts
    k_ = sympy.Symbol("k")
    if not isinstance(total, sympy.Sum) or len(total.limits) != 1 or total.limits[0][0] != k_:
        raise ValueError(f"not a sum over k: {total}")
    _k, klo, khi = total.limits[0]
    subs = [f for f in sympy.Mul.make_args(total.function) if isinstance(f, sympy.Subs)]
    if len(subs) != 1:
        raise ValueError("no evaluation bar |_{y=..} in the sum")
    (bar,) = subs
    if bar.variables != (sympy.Symbol("y"),):
        raise ValueError(f"evaluated at {bar.variables}, not at y")
    deriv = bar.expr
    if deriv.func != D or len(deriv.args) != 3 or getattr(deriv.args[0].func, "__name__", "") != "L":
        raise ValueError(f"not a mixed derivative of L: {deriv}")
    (v_, pv), (w_, pw) = deriv.args[1], deriv.args[2]
    if (v_, w_) != sympy.symbols("v w"):
        raise ValueError(f"derivatives in {v_}, {w_}, not in v, w")
    return {"klo": klo, "khi": khi, "weight": total.function / bar, "pv": pv, "pw": pw, "y0": bar.point[0],
            "rhs": rhs, "x_range": P.interval(_forall(rel), "x")}


def _forall(rel: Relation) -> Relation:
    """``rel`` if its clauses are quantified with ``\\forall`` (else ``ValueError``: the check reads 'for all x')."""
    if not rel.conditions or any(c.quantifier != "forall" for c in rel.conditions):
        raise ValueError(f"the clauses {[c.quantifier for c in rel.conditions]} are not 'for all'")
    return rel


def chain_weight(parts: dict, r: int, k: int) -> int:
    """The printed weight of the k-th term at order r (an integer, else ``ValueError``)."""
    w = parts["weight"].subs({sympy.Symbol("r"): r, sympy.Symbol("k"): k})
    if not w.is_Integer:
        raise ValueError(f"the weight {parts['weight']} is not an integer at r = {r}, k = {k}")
    return int(w)


def chain_sum_value(parts: dict, n: int, t: fmpq, r: int, hx: tuple[Q, Q]) -> Q:
    """The printed left-hand side, evaluated exactly: L = sum of the normalized functions of T_{2n} (coefficients by
    the exact collocation solve at tan(alpha/4) = t, no symmetry used) at u = alpha - x, v = y0 = 0, w = x."""

    if parts["y0"] != 0:
        raise ValueError(f"evaluation point y = {parts['y0']} not read as 0")
    al = rational_alpha(t)
    sa, ca = Q(int(al.sin_half.p), int(al.sin_half.q)), Q(int(al.cos_half.p), int(al.cos_half.q))
    sx, cx = hx
    su, cu = sa * cx - ca * sx, ca * cx + sa * sx  # half angles of u = alpha - x
    coef = _full(n, t)
    total = Q(0)
    for k in range(P.bound(parts["klo"], r=r), P.bound(parts["khi"], r=r) + 1):
        weight = chain_weight(parts, r, k)
        pv, pw = P.bound(parts["pv"], r=r, k=k), P.bound(parts["pw"], r=r, k=k)
        for lab in united_system(n):
            e = exponents(lab)
            v0 = sum((q for (s, _c), q in _d({(e[2], e[3]): Q(1)}, pv).items() if s == 0), Q(0))
            if v0 == 0:
                continue
            wx = sum((q * sx ** s * cx ** c for (s, c), q in _d({(e[4], e[5]): Q(1)}, pw).items()), Q(0))
            c = coef[lab.coefficient]
            total += weight * Q(int(c.p), int(c.q)) * su ** e[0] * cu ** e[1] * v0 * wx
    return total


@line_check("sec4_5-chain-sum")
def check_chain_sum(verbatim: str | None = None, orders: str | None = None) -> LineResult:
    """The printed sum_k C(r,k) (-1)^k d^r L / dv^(r-k) dw^k at y = 0 equals the printed right-hand side 0 for every
    order r of the printed range (r = 1..n, line sec4_5-parametrization-restated) at x = 0, alpha (the printed
    ends) and three interior x: everything read from the transcriptions (``verbatim``/``orders`` replace them)."""

    lines = {x.id: x.verbatim for x in pl.LINES}
    how = "the printed chain sum read from the transcription"
    try:
        parts = read_chain_sum(verbatim if verbatim is not None else lines["sec4_5-chain-sum"])
        _r, r_lo, r_hi = P.listed_range(orders if orders is not None else lines["sec4_5-parametrization-restated"], "r")
        if parts["y0"] != 0:
            raise ValueError(f"evaluation point y = {parts['y0']}, the check evaluates at y = 0 only")
    except ValueError as exc:  # an unread or unexpected transcription fails the line, saying why
        return LineResult(False, how=how, kind="exact-evidence", detail={"unread": str(exc)})
    rhs = Q(int(parts["rhs"])) if isinstance(parts["rhs"], sympy.Integer) else None
    bad, cases = [], 0
    for n in (1, 2, 3):
        for t in TS[:2]:
            al = rational_alpha(t)
            ends = {sympy.Integer(0): (Q(0), Q(1)), sympy.Symbol("alpha"): (Q(int(al.sin_half.p), int(al.sin_half.q)),
                                                                      Q(int(al.cos_half.p), int(al.cos_half.q)))}
            xs = [ends.get(parts["x_range"][0]), ends.get(parts["x_range"][1])]
            xs += [_angle(Q(int(t.p), int(t.q)) * Q(m, 4)) for m in (1, 2, 3)]  # tan(x/4) = t m/4: 0 < x < alpha
            for r in range(P.bound(r_lo, n=n), P.bound(r_hi, n=n) + 1):
                for hx in xs:
                    cases += 1
                    value = None if hx is None else chain_sum_value(parts, n, t, r, hx)
                    if rhs is None or value != rhs:
                        bad.append({"n": n, "t": str(t), "r": r, "value": str(value)})
    return LineResult(not bad, how="the printed sum (bounds, binomial, sign, orders, point y = 0, right-hand side, x "
                      "range, and r from the restated parametrization, all read from the transcriptions) evaluated "
                      "exactly with the collocation coefficients at tan(alpha/4) in {1/3, 2/5}, n = 1..3, at the "
                      "ends and three interior x", kind="exact-evidence",
                      detail={"cases": cases, "mismatches": len(bad), "first_mismatches": bad[:2]})


@line_check("sec4_5-cos-nonzero")
def check_cos_nonzero(text: str | None = None) -> LineResult:
    """The line ``$\\cos^{2n}\\frac{x}{2}\\neq0$ ($x\\in\\left[ 0,\\alpha\\right] $)`` parsed: the function, the
    relation and the interval.  Proof: with x in [0, alpha] and alpha in (0, pi), x/2 lies in [0, pi/2), where cos
    is positive; so a power cos^m(x/2) never vanishes there (and sin^m(x/2) would, at x = 0).  The power is the
    one that makes the rewritten equality a polynomial in tan(x/2): the total degree of its terms (2n, by exponent
    bookkeeping, n = 1..6)."""

    how = ("the function, relation and interval parsed; cos(x/2) > 0 on x/2 in [0, alpha/2], alpha < pi (a proof for "
           "every n); the exponent equals the total degree of the terms (bookkeeping n = 1..6)")
    n_, x_, a_ = sympy.symbols("n x alpha")
    tex = text if text is not None else verbatim("sec4_5-cos-nonzero")
    try:
        rel = P.relation(tex.split("$")[1])
        lo, hi = P.interval(tex, "x")
        if rel.ops != ["!="] or rel.parts[1] != 0:
            raise LatexMathError(f"relation {rel.ops} with {rel.parts[1:]}, not '!= 0'")
        f = rel.parts[0]
        base, power = f.as_base_exp()
        if base != sympy.cos(x_ / 2):
            raise LatexMathError(f"{base} is not cos(x/2): it vanishes in [0, alpha] or is not read")
        if lo != 0 or hi != a_:
            raise LatexMathError(f"interval [{lo}, {hi}] is not [0, alpha]: x/2 may reach pi/2")
        degree_ok = all(surviving_degrees(n) == {int(power.subs(n_, n))} for n in range(1, 7))
    except (LatexMathError, ValueError, TypeError, IndexError) as exc:
        return LineResult(False, how=how, kind="exhaustive", detail={"unread": str(exc)[:200]})
    ends_positive = all(rational_alpha(t).cos_half > 0 for t in (fmpq(1, 1000), fmpq(1, 2), fmpq(999, 1000)))
    return LineResult(ends_positive and degree_ok, how=how, kind="exhaustive",
                      detail={"function": str(f), "interval": [str(lo), str(hi)], "power_is_the_degree": degree_ok,
                              "cos_half_alpha_positive": ends_positive})


__all__ = ["y_range_maps_into_omega"]
