"""Checks of the lines of Sections 7 and 8 (:mod:`paper_repro.printed.lines.sec7`).

Every printed formula is read from its verbatim LaTeX -- relations, elevation rows, conversions and simple
expressions, sums with bounds, listed ranges and intervals by the one reader :mod:`paper_repro.printed.latex_math`
(interpreted by :mod:`paper_repro.printed.parsed`), which refuses anything unread; a changed relation, sign or
superscript changes what is read; the key words (orders, degrees, 'convex', 'innermost', 'linearly independent',
...) are read from the prose (:func:`~paper_repro.printed.latex_math.sentence`, a list of words by
:func:`listed_words`) -- and compared with an independent computation of the package:

* normalizing coefficients: the closed forms recovered by :mod:`paper_repro.theory.closed_forms` (proven for every
  alpha, ``proof_cached``), as rational functions of t = tan(alpha/4) (:mod:`paper_repro.theory.ratfunc`), and the
  exact collocation solution of :mod:`paper_repro.core.normalization` at rational alpha;
* order elevation: the exact collocation matrix of :mod:`paper_repro.core.elevation` at rational alpha;
* alpha -> 0: :mod:`paper_repro.theory.limits` / :mod:`paper_repro.theory.limit_formula`;
* index sets: the labels of :mod:`paper_repro.core.labels` (compared as exponent vectors);
* spans: exact ranks modulo a prime of collocation matrices at rational points.
"""

from __future__ import annotations

import functools
import math
import operator
from fractions import Fraction
from functools import cache

import mpmath
import numpy as np
import sympy
from flint import fmpq, fmpq_mpoly_ctx, fmpq_poly
from sympy.core.function import AppliedUndef

from paper_repro.claims.lines import LineResult, line_check
from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import collocate
from paper_repro.core.context import ExactContext, ModpContext
from paper_repro.core.domain import rational_alpha, sample_rational_points
from paper_repro.core.elevation import elevation_matrix, elevation_matrix_exact
from paper_repro.core.fourier import evaluate_v, v_labels
from paper_repro.core.labels import delta, exponents, index_of, parse_label, united_system
from paper_repro.core.normalization import coefficients, evaluate_normalized, orbits
from paper_repro.printed import latex_math as LM
from paper_repro.printed import parsed as P
from paper_repro.printed.lines import live_texts
from paper_repro.printed.lines.sec7 import LINES
from paper_repro.printed.normalization import final_value
from paper_repro.theory.closed_forms import closed_forms_cached, proof_cached, sign_on_unit_interval
from paper_repro.theory.limit_formula import limit_checks, limit_factor, multinomial
from paper_repro.theory.limits import conversion_matrix, limit_degree, limit_terms
from paper_repro.theory.ratfunc import RatFunc, half_angle_functions, poly_at

VERBATIM = live_texts()  # read at every lookup (the blank and mutation tests change the transcription)
#: rational tan(alpha/4) of the exact samples (alpha from 0.57 to 2.9)
TS = ("1/7", "1/3", "1/2", "5/7", "9/10")


#: the names a simple printed expression may use (a name outside them is an unread change of the line)
NAMES = ("x", "y", "z", "n", "m", "d", "e", "f", "alpha", "i", "j")
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6}
DEGREE_WORDS = {"linear": 1, "quadratic": 2, "cubic": 3, "quartic": 4, "quintic": 5, "sextic": 6, "septic": 7,
                "octic": 8, "nonic": 9}


def listed_words(words: str, vocabulary: dict[str, int]) -> list[int]:
    """Values of the words of a prose list ``w1, w2 and w3`` (or ``w1 and w2``), as a ``{name:words}`` slot of
    :func:`~paper_repro.printed.latex_math.sentence` returns it; every word must be in ``vocabulary``, and a word
    listed twice is refused.

    >>> listed_words("first, second and third", ORDINALS), listed_words("quadratic and octic", DEGREE_WORDS)
    ([1, 2, 3], [2, 8])
    """
    head, sep, last = words.rpartition(" and ")
    items = [*head.split(", "), last] if sep else []
    if len(items) < 2 or any(w not in vocabulary for w in items) or len(set(items)) != len(items):
        raise ValueError(f"unread list {words!r}")
    return [vocabulary[w] for w in items]


def read_sentence(template: str, tex: str, what: str) -> dict:
    """:func:`~paper_repro.printed.latex_math.sentence` of ``tex`` by ``template``; ``ValueError`` naming ``what``
    when the words differ."""
    got = LM.sentence(template, tex)
    if got is None:
        raise ValueError(f"unread line ({what})")
    return got


def read_expression(tex: str, allowed: tuple[str, ...] = NAMES):
    """A simple printed expression (``\\alpha x``, ``1-x-y``, ``3n-1``) read by the one reader; ``ValueError`` on
    anything unread or a name outside ``allowed``."""
    return P.expression(tex, allowed)


def _relation(tex: str, ops: tuple[str, ...] = ("=",)):
    """The relation ``tex`` read by :func:`paper_repro.printed.latex_math.parse_relation`; its operators must be
    ``ops`` (a changed relation, e.g. ``\\neq``, is refused)."""
    rel = _parsed_relation(tex)
    if tuple(rel.ops) != tuple(ops):
        raise ValueError(f"relation {rel.ops}, expected {list(ops)}")
    return rel


@functools.lru_cache(maxsize=512)
def _parsed_relation(tex: str):
    """:func:`paper_repro.printed.latex_math.parse_relation`, memoized on the text (a changed line is another key;
    the result is only read)."""
    return LM.parse_relation(tex)


def alpha_limit(text: str):
    """The value alpha tends to in the one ``$\\alpha \\to v$`` of ``text`` (every ``$..$`` segment read; exactly
    one is a limit of alpha)."""
    alpha = sympy.Symbol("alpha")
    found = []
    for seg in LM.inline_math(text) or [text]:
        try:
            rel = LM.parse_relation(seg)
        except LM.LatexMathError:
            continue
        if rel.ops == ["->"] and rel.parts[0] == alpha and not rel.conditions:
            found.append(rel.parts[1])
    if len(found) != 1 or found[0].free_symbols:
        raise ValueError(f"expected one '$\\alpha \\to v$' in {text[:60]!r}, read {found}")
    return found[0]


def listed_values(tex: str, var: str, **env) -> list[int]:
    """Values of the one listed range ``$var=a,b,\\ldots,c$`` of ``tex`` at ``env`` (read by the one reader)."""
    found = [c for c in P.clauses(tex) if c.ops == ["in"] and c.parts[0] == sympy.Symbol(var)
             and isinstance(c.parts[1], sympy.Tuple)]
    if len(found) != 1:
        raise ValueError(f"expected one '{var}=a,b,...,c' in {tex[:60]!r}")
    return P.progression(list(found[0].parts[1]), **env)


def _t(text: str) -> fmpq:
    a, b = text.split("/")
    return fmpq(int(a), int(b))


def _q(x) -> fmpq:
    return fmpq(x.numerator, x.denominator) if isinstance(x, Fraction) else fmpq(x)


def _exps(label: str) -> tuple[int, ...]:
    return exponents(parse_label(label))


def _system_exps(n: int) -> list[tuple[int, ...]]:
    return sorted(exponents(lab) for lab in united_system(n))


# ---------------------------------------------------------------- index sets and the product 1^{n+1}

def _member_names(n: int) -> list[str]:
    """The paper's names of the members of T_{2n} (``R_{2n,n,n}`` for the centre; no aliases such as
    ``G_{2n,n,n}`` or ``R_{2n,0,0}``: the paper names and normalizes only the members)."""
    return sorted(lab.paper for lab in united_system(n))


def _point_names(n: int) -> list[str]:
    """The paper's names of the control points of order n (``r_{2n,n,n}`` for the centre)."""
    return sorted(lab.control_point for lab in united_system(n))


def _label(name, **env: int) -> str:
    """``X_{a,b,c}`` of a parsed normalized function ``Xbar(a, b, c)`` with its indices evaluated at n, i, j."""
    fn = name.func.__name__
    if fn not in ("Rbar", "Gbar", "Bbar"):
        raise ValueError(f"not a normalized function: {name}")
    return f"{fn[0]}_{{{','.join(str(P.bound(a, **env)) for a in name.args)}}}"


def _signed_terms(expr) -> list[tuple[int, object, list]]:
    """``[(sign, name, sums)]`` of a printed sum of normalized functions, each term +/- one name (with its sums);
    anything else (a coefficient, a product) raises ``ValueError``."""
    out = []
    for t in LM.terms(expr):
        if len(t.names) != 1 or t.coefficient not in (1, -1) or \
                t.names[0].func.__name__ not in ("Rbar", "Gbar", "Bbar"):
            raise ValueError(f"not a signed normalized function: {t}")
        out.append((int(t.coefficient), t.names[0], [tuple(lim) for lim in t.limits]))
    return out


def _tagged(tex: str) -> None:
    """Every normalized function of ``tex`` carries the superscript alpha (``ValueError`` naming the first that
    does not)."""
    bare = [f for f in LM.untagged(tex) if f.func.__name__ in ("Rbar", "Gbar", "Bbar")]
    if bare:
        raise ValueError(f"{bare[0]} printed without the superscript alpha")


def unity_product(tex: str) -> dict:
    """The printed ``1^{n+1} = (first factor) . (second factor)`` read by the one reader: ``{"lhs": left side,
    "first": [(sign, name, sums)], "second": [(sign, name, sums)]}`` (the first factor is the one in n)."""
    _tagged(tex)
    lhs, rhs = _relation(tex).parts
    factors = sympy.Mul.make_args(rhs)
    if len(factors) != 2 or not all(isinstance(f, sympy.Add) for f in factors):
        raise ValueError(f"not a product of two sums: {rhs}")
    first, second = sorted(factors, key=lambda f: sympy.Symbol("n") not in f.free_symbols)
    return {"lhs": lhs, "first": _signed_terms(first), "second": _signed_terms(second)}


def printed_first_factor(tex: str, n: int) -> list[str]:
    """Names of the functions of the first factor of the printed 1^{n+1} (the single term and the three printed
    double sums, bounds read from the verbatim), each with its sign; a term with a minus sign is kept as ``-X``."""
    out = []
    for sign, name, sums in unity_product(tex)["first"]:
        prefix = "" if sign > 0 else "-"
        if not sums:
            out.append(prefix + _label(name, n=n))
            continue
        if len(sums) != 2 or [str(v) for v, _, _ in sums] != ["j", "i"]:
            raise ValueError(f"summation variables {[v for v, _, _ in sums]}: the subscript is written in i and j")
        (_, jlo, jhi), (_, ilo, ihi) = sums
        for j in range(P.bound(jlo, n=n), P.bound(jhi, n=n) + 1):
            for i in range(P.bound(ilo, n=n, j=j), P.bound(ihi, n=n, j=j) + 1):
                out.append(prefix + _label(name, n=n, i=i, j=j))
    return sorted(out)


def _second_names(terms) -> list[str]:
    if any(sums for _, _, sums in terms):
        raise ValueError("a sum in the second factor")
    return sorted(("" if sign > 0 else "-") + _label(name) for sign, name, _ in terms)


def _unity_at(n: int, t: str, count: int = 4) -> bool:
    alpha = rational_alpha(_t(t))
    vals = evaluate_normalized(n, alpha, sample_rational_points(alpha, count, seed=70 + n), "exact")
    return all(sum(row) == 1 for row in vals)


@line_check("sec7-unity-product")
def check_unity_product() -> LineResult:
    tex = VERBATIM["sec7-unity-product"]
    read = unity_product(tex)
    first = {n: printed_first_factor(tex, n) == _member_names(n) for n in range(1, 11)}
    second = _second_names(read["second"]) == _member_names(1)
    unity = {n: all(_unity_at(n, t) for t in ("1/3", "5/7")) for n in (1, 2, 3)}
    lhs = read["lhs"] == 1
    ok = all(first.values()) and second and all(unity.values()) and lhs
    return LineResult(ok, how="printed terms (signs, superscripts alpha, summation bounds) read and enumerated: the "
                      "first factor names exactly the members of T-bar_{2n} (n = 1..10), the second those of T-bar_2; "
                      "both sums are 1 exactly at rational points (n = 1..3, tan(alpha/4) = 1/3, 5/7), so the product "
                      "is 1 = the printed left side",
                      detail={"first_factor_is_T2n": {str(k): v for k, v in first.items()},
                              "second_factor_is_T2": second, "left_side_is_1": lhs,
                              "partition_of_unity_exact": {str(k): v for k, v in unity.items()}})


@line_check("sec7-square-of-unity")
def check_square_of_unity() -> LineResult:
    tex = VERBATIM["sec7-square-of-unity"]
    _tagged(tex)
    lhs, rhs = _relation(tex).parts
    base, exp = rhs.as_base_exp()
    same = isinstance(base, sympy.Add) and _second_names(_signed_terms(base)) == _member_names(1)
    unity = all(_unity_at(1, t) for t in TS)
    lhs_one = lhs == 1
    return LineResult(same and unity and lhs_one, how="the printed sum read with its signs: exactly the members of "
                      "T-bar_2, each once with +; that sum is 1 exactly at rational points of 5 rational alpha, so "
                      "its power is 1 = the printed left side",
                      detail={"labels_are_T2": same, "sum_is_one": unity, "left_side_is_1": lhs_one,
                              "exponents": [str(exp)]})


def index_set_from_text(n: int) -> list[tuple[int, int]]:
    """(i, j) of the printed lists 'j=0,1,...,n-1 and i=j,j+1,...,2n-1-j' (first, step and last read from the
    verbatim)."""
    tex = VERBATIM["sec7-mixed-products-index-set"]
    got = read_sentence("for all indices {j} and {i}", tex, "no 'for all indices $..$ and $..$'")
    return [(i, j) for j in listed_values(got["j"], "j", n=n) for i in listed_values(got["i"], "i", n=n, j=j)]


def _r_noncentre(n: int) -> list[tuple[int, int]]:
    return sorted((lab.i, lab.j) for lab in united_system(n) if lab.color == "R" and not lab.is_centre)


@line_check("sec7-mixed-products-index-set")
def check_mixed_index_set() -> LineResult:
    per_n = {str(n): sorted(index_set_from_text(n)) == _r_noncentre(n) for n in range(1, 13)}
    counts = {str(n): len(index_set_from_text(n)) for n in (1, 2, 3)}
    ok = all(per_n.values()) and all(c == (delta(int(n)) - 1) // 3 for n, c in counts.items())
    return LineResult(ok, how="printed lists (first, step, last) enumerated and compared with the non-central R "
                      "labels of T_{2n}, n = 1..12", kind="exhaustive", detail={"equal": per_n, "counts": counts})


def product_expansion(n: int, t: str = "1/3") -> dict[tuple[str, str], list[fmpq]]:
    """Every product f * h (f in T_{2n}, h in T_2) written exactly in T_{2(n+1)} at tan(alpha/4) = t (collocation
    at delta_{n+1} rational points, verified at 4 more; ArithmeticError if a product is not in the span)."""
    alpha = rational_alpha(_t(t))
    ctx = ExactContext()
    big, small, one = united_system(n + 1), united_system(n), united_system(1)
    m = len(big)

    def system(k: int):
        pts = sample_rational_points(alpha, m + 4, seed=300 + 7 * n + k)
        a = evaluate(n + 1, alpha, pts, ctx)
        f, h = evaluate(n, alpha, pts, ctx), evaluate(1, alpha, pts, ctx)
        b = np.empty((len(pts), len(small) * len(one)), dtype=object)
        for p in range(len(small)):
            for q in range(len(one)):
                b[:, p * len(one) + q] = f[:, p] * h[:, q]
        return a, b

    sol = collocate(ctx, system, m, what=f"products T_{2 * n} x T_2").solution
    return {(small[p].paper, one[q].paper): [sol[r, p * len(one) + q] for r in range(m)]
            for p in range(len(small)) for q in range(len(one))}


def products_orders(tex: str) -> tuple[int, int]:
    """``(a, b)`` of the printed 'pairwise products of <a> order blending functions into linear combinations of
    <b> order blending functions' (ordinal words)."""
    got = read_sentence("For the moment, we are only able ... to transform the pairwise products of {a:word} order "
                        "blending functions into linear combinations of {b:word} order blending functions.", tex,
                        "orders of the products")
    if got["a"] not in ORDINALS or got["b"] not in ORDINALS:
        raise ValueError("unread orders of the products")
    return ORDINALS[got["a"]], ORDINALS[got["b"]]


def products_in_span_modp(a: int, b: int) -> bool:
    """Every product of two functions of T_{2a} lies in span T_{2b}: rank of [T_{2b} | products] modulo 2^31 - 1
    at rational points (a rank mod p is at most the rank over Q, so a rank above delta_b proves a product outside
    the span; equal ranks are exact evidence)."""
    ctx = ModpContext(p=2**31 - 1)
    alpha = rational_alpha(fmpq(2, 5))
    pts = sample_rational_points(alpha, delta(max(b, 2 * a)) + 8, seed=60 + a + b)
    big, f = evaluate(b, alpha, pts, ctx), evaluate(a, alpha, pts, ctx)
    prods = [f[:, p] * f[:, q] for p in range(f.shape[1]) for q in range(p, f.shape[1])]
    return ctx.rank(np.concatenate([big, np.stack(prods, axis=1)], axis=1)) == ctx.rank(big) == delta(b)


@line_check("sec7-products-in-span")
def check_products_in_span() -> LineResult:
    a, b = products_orders(VERBATIM["sec7-first-order-products"])
    if (a, b) == (1, 2):
        try:
            exp = product_expansion(1)
            holds, kind = all(len(v) == delta(2) for v in exp.values()), "proof"
        except ArithmeticError:
            holds, kind = False, "proof"
    else:
        holds, kind = products_in_span_modp(a, b), "exact-evidence"
    terms = {}
    if holds and (a, b) == (1, 2):
        terms = {h: sum(1 for x in coeffs if x != 0) for (f, h), coeffs in exp.items() if f == "R_{2,2,0}"}
    return LineResult(holds, kind=kind,
                      how=f"orders read from the line (products of order {a} into order {b}); for 1 -> 2 every "
                          "product of two functions of T_2 solved exactly in T_4 at tan(alpha/4) = 1/3 and verified "
                          "at 4 further rational points (a product outside the span raises); other orders by ranks "
                          "modulo 2^31-1. The cited tech_report Lemma 5.1 is not available and not checked",
                      detail={"orders": [a, b], "terms_of_R220_times_h": terms})


# ---------------------------------------------------------------- Example exmp:from_1_to_2

@cache
def _coefficient_ratfuncs(n: int) -> dict[str, RatFunc]:
    """Normalizing coefficient of every label of T_{2n} (and its aliases) as a rational function of tan(alpha/4)."""
    s, c = half_angle_functions()
    forms = closed_forms_cached(n)
    ix = index_of(n)
    out = {}
    for rep, members in orbits(n):
        f = forms[rep.coefficient]
        val = poly_at(f.numerator.coeffs(), c) / s ** f.sin_power
        for lab, k in ix.items():
            if k in members and lab[0].islower():
                out[lab] = val
    return out


def _names(values: dict[str, object]) -> dict[str, object]:
    return {lab[0] + lab[3] + lab[5] + lab[7]: v for lab, v in values.items() if lab.startswith(("r_{2,", "g_{2,",
                                                                                                "b_{2,"))}


def relation_rhs(tex: str):
    """The printed right-hand side of a relation of Example exmp:from_1_to_2, read by the one reader
    (:mod:`paper_repro.printed.latex_math`): a row of a vector equation is the expression itself; the line of
    ``r_{4,2,2}`` is the relation ``r_{4,2,2} = ...`` (relation ``=`` required)."""
    import sympy as sp

    if "=" in tex or "\\neq" in tex:
        lhs, rhs = _relation(tex).parts
        if lhs != sp.Function("r")(4, 2, 2):
            raise ValueError(f"left side {lhs}")
        return rhs
    return _parsed_expression(tex)


@functools.lru_cache(maxsize=512)
def _parsed_expression(tex: str):
    return LM.parse(tex)


def relation_value(tex: str, K, trig: dict, coeffs: dict):
    """The printed right-hand side evaluated in the arithmetic of ``K``: ``trig`` gives s = sin(alpha/2), c =
    cos(alpha/2), sinA = sin(alpha), tanH = tan(alpha/2); ``coeffs`` the order-1 coefficients by short name
    (``r220``)."""
    import sympy as sp

    a = sp.Symbol("alpha")
    values = {sp.sin(a / 2): trig["s"], sp.cos(a / 2): trig["c"], sp.sin(a): trig["sinA"],
              sp.tan(a / 2): trig["tanH"]}
    values.update({sp.Function(k[0])(int(k[1]), int(k[2]), int(k[3])): v for k, v in coeffs.items()})
    return P.evaluate_in(relation_rhs(tex), K, values)


def relation_holds(tex: str, label: str) -> bool:
    """The printed right-hand side equals the order-2 coefficient ``label`` as rational functions of tan(alpha/4)."""
    s, c = half_angle_functions()
    first = _coefficient_ratfuncs(1)
    ns = _names(first)
    val = relation_value(tex, RatFunc.const, {"s": s, "c": c, "sinA": 2 * s * c, "tanH": s / c}, ns)
    return val == _coefficient_ratfuncs(2)[label]


def _relation_at(tex: str, label: str, t: str) -> bool:
    alpha = rational_alpha(_t(t))
    s, c = alpha.sin_half, alpha.cos_half
    c1, c2 = coefficients(1, alpha, "exact"), coefficients(2, alpha, "exact")
    ns = _names(c1)
    val = relation_value(tex, fmpq, {"s": s, "c": c, "sinA": 2 * s * c, "tanH": s / c}, ns)
    return val == c2[label] if label in c2 else val == c2["r_" + label[2:]]


def _register_relation(line_id: str, label: str) -> None:
    @line_check(f"sec7-rel-{line_id}")
    def check() -> LineResult:
        tex = VERBATIM[f"sec7-rel-{line_id}"]
        proven = all(proof_cached(n)["proved"] for n in (1, 2))
        symbolic = relation_holds(tex, label)
        sampled = all(_relation_at(tex, label, t) for t in ("1/3", "5/7"))
        return LineResult(symbolic and sampled and proven, kind="proof",
                          how="printed right-hand side (read from the LaTeX) with the proven closed forms of the "
                              "order-1 coefficients equals the proven closed form of the order-2 coefficient as a "
                              "rational function of tan(alpha/4); also exactly at tan(alpha/4) = 1/3, 5/7 with the "
                              "collocation coefficients",
                          detail={"symbolic_identity": symbolic, "exact_samples": sampled,
                                  "closed_forms_proven_n1_n2": proven})


for _ln in LINES:
    if _ln.id.startswith("sec7-rel-") and _ln.id[9] in "rgb" and _ln.id[10:].isdigit():
        _slug = _ln.id[9:]
        _register_relation(_slug, f"{_slug[0]}_{{{_slug[1]},{_slug[2]},{_slug[3]}}}")

RELATION_IDS = [ln.id for ln in LINES if ln.id.startswith("sec7-rel-") and ln.id[10:].isdigit()]


def relation_orders() -> tuple[int, int]:
    """``(order of the right-hand sides, order of the left-hand sides)`` of the relations of Example
    exmp:from_1_to_2: from the printed coefficient names (``r_{2,..}`` is order 1) of every relation line, and
    from the line ids (the left-hand side of a row), which must all agree."""
    rhs = {int(f.args[0]) // 2 for lid in RELATION_IDS for f in relation_rhs(VERBATIM[lid]).atoms(AppliedUndef)
           if f.func.__name__ in ("r", "g", "b")}
    lhs = {int(lid[10]) // 2 for lid in RELATION_IDS}
    if len(rhs) != 1 or len(lhs) != 1:
        raise ValueError(f"relations of mixed orders: {rhs}, {lhs}")
    return rhs.pop(), lhs.pop()


@line_check("sec7-rel-same-as-example")
def check_same_as_example() -> LineResult:
    """The statement compares two printed things: the relations evaluated at the printed order-1 coefficients of
    Example normalizing_coefficients_n_1 against the printed order-2 ones of Example normalizing_coefficients_n_2
    (the order is read from the line: 'the same <ordinal> order normalizing coefficients ... Example \\ref{..}')."""
    got = read_sentence("It is easy to verify that these relations lead to the same {o:word} order normalizing "
                        "coefficients that were described in Example \\ref{{example:word}}",
                        VERBATIM["sec7-rel-same-as-example"], "order, Example")
    example = got["example"].removeprefix("normalizing_coefficients_n_")
    if got["o"] not in ORDINALS or example == got["example"] or not example.isdigit():
        raise ValueError("unread line")
    said = [ORDINALS[got["o"]], int(example)]  # the ordinal and the order of the Example's label
    low, high = relation_orders()
    s, c = half_angle_functions()
    ns = {f"{col}2{k}": final_value(f"r_{{2,{k[0]},{k[1]}}}", s, c) for col in "rgb" for k in ("20", "10")}
    ns["r211"] = final_value("r_{2,1,1}", s, c)
    rep = {k: r.coefficient for r, members in orbits(2) for k in members}
    bad = []
    for line_id in RELATION_IDS:
        slug = line_id[9:]
        label = f"{slug[0]}_{{{slug[1]},{slug[2]},{slug[3]}}}"
        val = relation_value(VERBATIM[line_id], RatFunc.const, {"s": s, "c": c, "sinA": 2 * s * c, "tanH": s / c},
                             ns)
        if not val == final_value(rep[index_of(2)[label]], s, c):
            bad.append(slug)
    orders = said[0] == said[1] == high == 2 and low == 1
    return LineResult(not bad and orders, kind="proof", how="the order read from the line (and its Example) is the "
                      "order of the relations' left sides; the 19 relations at the printed order-1 closed forms "
                      "equal the printed order-2 closed forms, as rational functions of tan(alpha/4)",
                      detail={"relations": len(RELATION_IDS), "disagreeing": bad,
                              "orders_read": said})


@line_check("sec7-rel-inheritance")
def check_inheritance() -> LineResult:
    got = read_sentence("Observe that the symmetry and non-negativity of normalizing coefficients of order {low} are "
                        "inherited by those of order {high}.", VERBATIM["sec7-rel-inheritance"], "properties, orders")
    said = [read_expression(got[k], ()) for k in ("low", "high")]  # numbers: no name allowed
    if not all(x.is_Integer for x in said):
        raise ValueError(f"unread line (orders {said})")
    said = [int(x) for x in said]
    orders = tuple(said) == relation_orders()
    names = ("r220", "g220", "b220", "r210", "g210", "b210", "r211", "s", "c", "sinA", "tanH")
    ctx = fmpq_mpoly_ctx.get(names, "lex")
    gens = dict(zip(names, ctx.gens()))
    const = lambda v: ctx.from_dict({(0,) * 11: v})  # noqa: E731
    trig = {k: gens[k] for k in ("s", "c", "sinA", "tanH")}
    first = {k: gens[k] for k in names[:7]}
    polys = {lid[9:]: relation_value(VERBATIM[lid], const, trig, first) for lid in RELATION_IDS}
    nonneg = all(coef > 0 for p in polys.values() for coef in p.coeffs())
    # symmetry: with g = b = r on order 1 the three rows of each vector equation coincide
    sym = {"g220": gens["r220"], "b220": gens["r220"], "g210": gens["r210"], "b210": gens["r210"]}
    ident = {k: relation_value(VERBATIM[f"sec7-rel-{k}"], const, trig, {**first, **sym}) for k in polys}
    groups = sorted({k[1:] for k in polys if k[0] in "gb"})
    symmetric = all(ident["r" + g] == ident["g" + g] == ident["b" + g] for g in groups)
    return LineResult(nonneg and symmetric and orders, kind="proof",
                      how="orders read from the line = the orders of the relations; relations expanded as polynomials "
                          "in the order-1 coefficients and s, c, sin(alpha), tan(alpha/2) (all positive on (0, pi)): "
                          "every coefficient is positive; with g = b = r at order 1 the r, g and b rows coincide",
                      detail={"all_coefficients_positive": nonneg, "rows_equal_under_symmetry": symmetric,
                              "orders_read": said})


# ---------------------------------------------------------------- Example exmp:degree_elevation_from_1_to_2

def printed_elevation(tex: str, colour: int, c2, s2, K) -> dict[str, object]:
    """``{order-1 label: weight}`` of one printed row (colour 0, 1, 2 = r, g, b; the centre has one)."""
    import sympy as sp

    rows = P.elevation(tex)
    names = set(_point_names(1)) | set(_point_names(2))
    unknown = [lab for left, row in rows for lab in [left, *row] if lab not in names]
    if unknown:
        raise ValueError(f"not control points of order 1 or 2 (the paper names only members): {unknown}")
    a = sp.Symbol("alpha")
    squares = {sp.cos(a / 2): c2, sp.sin(a / 2): s2}
    lhs, row = rows[colour]
    return lhs, {lab: P.evaluate_in(w, K, {}, squares) for lab, w in row.items()}


def elevation_row_holds(tex: str, colour: int, t: str) -> bool:
    alpha = rational_alpha(_t(t))
    lhs, row = printed_elevation(tex, colour, alpha.cos_half ** 2, alpha.sin_half ** 2, fmpq)
    exact = elevation_matrix_exact(1, alpha)[index_of(2)[lhs]]
    ix1 = index_of(1)
    want = [fmpq(0)] * delta(1)
    for lab, w in row.items():
        want[ix1[lab]] += w
    return list(exact) == want


@cache
def _plane_monomials():
    """Numerators of sin/cos of u/2, v/2, w/2 on the plane u + v + w = alpha as polynomials in a = tan(alpha/4),
    u = tan(u/4), v = tan(v/4) (denominators 1 + u^2, 1 + v^2 and (1 + a^2)(1 + u^2)(1 + v^2) for w)."""
    ctx = fmpq_mpoly_ctx.get(("a", "u", "v"), "lex")
    a, u, v = ctx.gens()
    su, cu, sv, cv, sa, ca = 2 * u, 1 - u ** 2, 2 * v, 1 - v ** 2, 2 * a, 1 - a ** 2
    sw = sa * (cu * cv - su * sv) - ca * (su * cv + cu * sv)
    cw = ca * (cu * cv - su * sv) + sa * (su * cv + cu * sv)
    return ctx, (su, cu, sv, cv, sw, cw), (1 + u ** 2, 1 + v ** 2, 1 + a ** 2)


def elevation_identity(matrix: list[list[RatFunc]]) -> list[bool]:
    """For each f of T_2: ``x_f f == sum_k E[k][f] y_k g_k`` (T-bar_2 = T-bar_4 E) as a polynomial identity in
    tan(alpha/4), tan(u/4), tan(v/4) after clearing denominators -- for every alpha and every point of the plane.
    ``x``, ``y``: the proven closed forms of the normalizing coefficients."""
    ctx, nums, (du, dv, da) = _plane_monomials()
    zero, one = ctx.from_dict({}), ctx.from_dict({(0, 0, 0): 1})
    y1, y2 = _coefficient_ratfuncs(1), _coefficient_ratfuncs(2)
    t1, t2 = united_system(1), united_system(2)
    out = []
    for f in range(delta(1)):
        terms = [(matrix[k][f] * y2[t2[k].coefficient], exponents(t2[k])) for k in range(delta(2))
                 if not matrix[k][f] == 0]
        terms.append((-1 * y1[t1[f].coefficient], exponents(t1[f])))
        parts, lcm = [], fmpq_poly([1])
        for r, e in terms:
            g = r.num.gcd(r.den)
            num, den = r.num / g, r.den / g
            lcm = lcm * den / lcm.gcd(den)
            mono = one
            for base, k in zip(nums, e):
                mono *= base ** k if k else one
            parts.append((num, den, mono, (e[0] + e[1] + e[4] + e[5], e[2] + e[3] + e[4] + e[5], e[4] + e[5])))
        top = [max(p[3][i] for p in parts) for i in range(3)]
        total = zero
        for num, den, mono, deg in parts:
            coef = ctx.from_dict({(k, 0, 0): x for k, x in enumerate((num * (lcm / den)).coeffs()) if x != 0})
            total += coef * mono * du ** (top[0] - deg[0]) * dv ** (top[1] - deg[1]) * da ** (top[2] - deg[2])
        out.append(total == 0)
    return out


@cache
def _printed_elevation_proof() -> tuple[bool, ...]:
    s, c = half_angle_functions()
    return tuple(elevation_identity(printed_elevation_matrix(c * c, s * s, RatFunc.const)))


def _register_elevation(slug: str, colour: int) -> None:
    @line_check(f"sec7-elev-{slug}")
    def check() -> LineResult:
        tex = VERBATIM[f"sec7-elev-{slug}"]
        rows = len(P.elevation(tex))  # the line is the whole vector equation: every row of it is checked
        per_t = {t: all(elevation_row_holds(tex, k, t) for k in range(rows)) for t in TS}
        proof = _printed_elevation_proof()
        proven = all(proof_cached(n)["proved"] for n in (1, 2))
        return LineResult(all(per_t.values()) and all(proof) and proven, kind="proof",
                          how="printed weights (read from the LaTeX; every row of the printed vector equation) equal "
                              "the rows of the exact elevation matrix (collocation, T-bar_2 = T-bar_4 E) at 5 rational "
                              "alpha; and the whole printed matrix "
                              "satisfies T-bar_2 = T-bar_4 E as a polynomial identity in tan(alpha/4), tan(u/4), "
                              "tan(v/4) with the proven closed-form normalizing coefficients (every alpha; T-bar_4 "
                              "is a basis, so each printed row is the unique one)",
                          detail={"tan_alpha_over_4": per_t, "identity_per_column_of_T2": list(proof),
                                  "closed_forms_proven_n1_n2": proven})


for _ln in LINES:
    if _ln.id.startswith("sec7-elev-") and _ln.id[10] in "rgb" and _ln.id[11:].isdigit():
        _register_elevation(_ln.id[10:], "rgb".index(_ln.id[10]) if _ln.id != "sec7-elev-r422" else 0)

ELEVATION_IDS = [ln.id for ln in LINES if ln.id.startswith("sec7-elev-") and ln.id[11:].isdigit()]


def elevation_orders() -> tuple[int, int]:
    """``(original order, elevated order)`` of Example exmp:degree_elevation_from_1_to_2, from the printed control
    point names of its rows (``r_{2,..}`` is order 1, ``r_{4,..}`` order 2)."""
    lhs, rhs = set(), set()
    for lid in ELEVATION_IDS:
        for left, row in P.elevation(VERBATIM[lid]):
            lhs.add(int(left.split("{")[1].split(",")[0]) // 2)
            rhs |= {int(lab.split("{")[1].split(",")[0]) // 2 for lab in row}
    if len(lhs) != 1 or len(rhs) != 1:
        raise ValueError(f"elevation rows of mixed orders: {rhs} -> {lhs}")
    return rhs.pop(), lhs.pop()


def printed_elevation_matrix(c2, s2, K) -> list[list]:
    ix1, ix2 = index_of(1), index_of(2)
    mat = [[K(0)] * delta(1) for _ in range(delta(2))]
    for lid in ELEVATION_IDS:
        colour = 0 if lid == "sec7-elev-r422" else "rgb".index(lid[10])
        lhs, row = printed_elevation(VERBATIM[lid], colour, c2, s2, K)
        for lab, w in row.items():
            mat[ix2[lhs]][ix1[lab]] = mat[ix2[lhs]][ix1[lab]] + w
    return mat


def patch_product(tex: str) -> dict:
    """The printed ``\\mathbf{s}_{1}^{\\alpha}\\cdot1 = (sum of points times functions) . (sum of functions)``
    read by the one reader: ``{"patch": order, "one": the factor of s, "pairs": [(sign, point, function)],
    "second": [(sign, label)]}`` (the first factor is the one with the points)."""
    _tagged(tex)
    lhs, rhs = _relation(tex).parts
    one = [f for f in sympy.Mul.make_args(lhs) if not isinstance(f, AppliedUndef)]
    patch = [f for f in sympy.Mul.make_args(lhs) if isinstance(f, AppliedUndef)]
    if len(patch) != 1 or patch[0].func.__name__ != "s_vec" or len(patch[0].args) != 1:
        raise ValueError(f"the left side {lhs} is not s_n^alpha times a number")
    factors = sympy.Mul.make_args(rhs)
    if len(factors) != 2 or not all(isinstance(f, sympy.Add) for f in factors):
        raise ValueError(f"not a product of two sums: {rhs}")
    first, second = sorted(factors, key=lambda f: not any(a.func.__name__.endswith("_vec")
                                                          for a in f.atoms(AppliedUndef)))
    pairs = []
    for t in LM.terms(first):
        pts = [a for a in t.names if a.func.__name__.endswith("_vec")]
        fns = [a for a in t.names if not a.func.__name__.endswith("_vec")]
        if t.limits or len(pts) != 1 or len(fns) != 1 or t.coefficient not in (1, -1):
            raise ValueError(f"not a signed point times a function: {t}")
        pairs.append((int(t.coefficient), P.point_label(pts[0]), _label(fns[0])))
    second_terms = [(sign, _label(name)) for sign, name, sums in _signed_terms(second) if not sums]
    if len(second_terms) != len(second.args):
        raise ValueError("a sum in the second factor")
    return {"patch": int(patch[0].args[0]), "one": str(sympy.Mul(*one)), "pairs": pairs, "second": second_terms}


@line_check("sec7-elev-product")
def check_elev_product() -> LineResult:
    read = patch_product(VERBATIM["sec7-elev-product"])
    pairs = read["pairs"]
    own = all(sign > 0 and p == f[0].lower() + f[1:] for sign, p, f in pairs)
    labs = sorted(f for _, _, f in pairs) == _member_names(1) and read["patch"] == 1
    second = sorted(("" if sg > 0 else "-") + lab for sg, lab in read["second"]) == _member_names(1)
    unity = second and _unity_at(1, "1/2") and read["one"] == "1"
    return LineResult(own and labs and unity, how="read with signs: each printed control point multiplies its own "
                      "function with +; the 7 functions are the members of T_2 (s_1 is the first order patch); the "
                      "second factor is T-bar_2, whose sum is 1 exactly, = the printed factor 1",
                      detail={"points_with_own_functions": own, "first_factor_is_s1": labs,
                              "second_factor_is_1": unity})


def same_patch_orders(tex: str) -> dict[str, int]:
    """Orders named by the line: the basis ``\\overline{T}_{2m}^{\\alpha}``, the '<ordinal> order blending
    functions', the '(i.e., <ordinal> order)' representation ``\\mathbf{s}_{k}^{\\alpha}`` and the original
    ``\\mathbf{s}_{l}^{\\alpha}``; every superscript must be ``\\alpha``."""
    got = LM.sentence("into the basis {basis} and then collecting the vector coefficients of {blending:word} order "
                      "blending functions, one obtains the order elevated (i.e., {elevated:word} order) representation "
                      "{s_elevated} of the original patch {s_original}", tex)  # the words carry the ordinals
    if got is None or got["blending"] not in ORDINALS or got["elevated"] not in ORDINALS:
        raise ValueError("unread line (orders, superscripts)")
    segs = [got[k] for k in ("basis", "s_elevated", "s_original")]  # read by the one reader
    basis, elevated, original = (LM.parse(seg) for seg in segs)  # every superscript must be the tag alpha:
    if any(LM.untagged(seg) or P.foreign_tags(seg) for seg in segs):  # none missing, none other
        raise ValueError("unread line (orders, superscripts)")
    if not (basis.func.__name__ == "Tbar" and elevated.func.__name__ == original.func.__name__ == "s_vec"
            and all(len(x.args) == 1 and x.args[0].is_Integer for x in (basis, elevated, original))):
        raise ValueError(f"unread line (orders, superscripts): {basis}, {elevated}, {original}")
    k = int(basis.args[0])
    return {"basis": k // 2 if k % 2 == 0 else -1, "blending": ORDINALS[got["blending"]],
            "elevated": ORDINALS[got["elevated"]], "s_elevated": int(elevated.args[0]),
            "s_original": int(original.args[0])}


@line_check("sec7-elev-same-patch")
def check_same_patch() -> LineResult:
    orders = same_patch_orders(VERBATIM["sec7-elev-same-patch"])
    # the elevation of the Example is 1 -> 2 (the order-2 control points of its rows): every order the line names
    low, high = elevation_orders()
    named = orders["basis"] == orders["blending"] == orders["elevated"] == orders["s_elevated"] == high \
        and orders["s_original"] == low
    rng = np.random.default_rng(7)
    per_t = {}
    for t in ("1/3", "5/7"):
        alpha = rational_alpha(_t(t))
        e = printed_elevation_matrix(alpha.cos_half ** 2, alpha.sin_half ** 2, fmpq)
        net1 = [[fmpq(int(v)) for v in row] for row in rng.integers(-9, 10, size=(delta(1), 3))]
        net2 = [[sum((e[k][f] * net1[f][d] for f in range(delta(1))), fmpq(0)) for d in range(3)]
                for k in range(delta(2))]
        pts = sample_rational_points(alpha, 6, seed=91)
        b1, b2 = evaluate_normalized(1, alpha, pts, "exact"), evaluate_normalized(2, alpha, pts, "exact")
        s1 = [[sum((b1[p, f] * net1[f][d] for f in range(delta(1))), fmpq(0)) for d in range(3)] for p in range(6)]
        s2 = [[sum((b2[p, k] * net2[k][d] for k in range(delta(2))), fmpq(0)) for d in range(3)] for p in range(6)]
        per_t[t] = s1 == s2
    return LineResult(all(per_t.values()) and named, how="orders read from the line (T-bar_4, second order, s_2 of "
                      "s_1) = those of the elevation; a seeded integer net elevated with the printed weights gives the "
                      "same patch, exactly at 6 rational points (tan(alpha/4) = 1/3, 5/7)",
                      detail={"same_patch": per_t, "orders_read": orders})


@line_check("sec7-elev-index-sets")
def check_elev_index_sets() -> LineResult:
    """The printed list ``\\mathbf{r}_{4,2,2}, \\left\\{ \\mathbf{r}_{4,4-i,j}\\right\\} _{j=0,i=j}^{1,3-j}, ..``
    read by :func:`~paper_repro.printed.latex_math.parse_list` (a point and three bounded sets of points), each set
    enumerated (:func:`~paper_repro.printed.parsed.members`): the names of the control points of order 2, each
    once."""
    items = LM.parse_list(VERBATIM["sec7-elev-index-sets"])
    sets = [x for x in items if isinstance(x, AppliedUndef) and x.func == LM.Family]
    if not items or items[0] in sets:
        raise ValueError("unread first point")
    labs = [P.point_label(p) for item in items for p in P.members(item)]
    ok = len(sets) == 3 and sorted(labs) == _point_names(2)
    return LineResult(ok, kind="proof", how="printed point and index sets enumerated and compared with the names of "
                      "the control points of order 2 (each once)",
                      detail={"points": len(labs), "delta_2": delta(2)})


def _listed_points(tex: str) -> list[str]:
    """Names of the bold control points listed in ``tex`` (its displayed list, read by
    :func:`~paper_repro.printed.latex_math.parse_list`), in order; ``ValueError`` on an item that is no point."""
    return [P.point_label(p) for p in LM.parse_list(tex)]


@line_check("sec7-elev-convex")
def check_elev_convex() -> LineResult:
    tex = VERBATIM["sec7-elev-convex"]
    words = LM.sentence("are in fact convex combinations of different subsets of control points%...", tex)
    listed = _listed_points(tex)
    if words is None:
        raise ValueError("unread words ('convex combinations of different subsets')")
    listed_ok = sorted(listed) == _point_names(1)
    x = RatFunc(fmpq_poly([0, 1]))  # c2 = cos^2(alpha/2) runs over (0, 1) for alpha in (0, pi)
    mat = printed_elevation_matrix(x, 1 - x, RatFunc.const)
    sums = all(sum(row, RatFunc.const(0)) == 1 for row in mat)
    positive = True
    for row in mat:
        for w in row:
            if w == 0:
                continue
            for p in (w.num, w.den):
                sign = sign_on_unit_interval(p)
                positive &= sign["roots_in_open_unit_interval"] == 0 and sign["sign"] != 0
            positive &= (w.num(fmpq(1, 2)) > 0) == (w.den(fmpq(1, 2)) > 0)
    supports = {tuple(k for k, w in enumerate(row) if not w == 0) for row in mat}
    different = len(supports) == len(mat)
    return LineResult(sums and positive and listed_ok and different, kind="proof",
                      how="the listed points are the 7 control points of order 1; printed weights as rational "
                          "functions of c2 = cos^2(alpha/2): every row sums to 1 identically and every weight is "
                          "positive on 0 < c2 < 1 (Sturm root count of numerator and denominator); the 19 rows have 19 "
                          "different supports", detail={"rows_sum_to_one": sums, "weights_positive": positive,
                                                        "listed_points_are_order_1": listed_ok,
                                                        "distinct_supports": len(supports), "rows": len(mat)})


def _net_to_patch_distance(net: np.ndarray, patch_pts: np.ndarray) -> float:
    d = np.linalg.norm(net[:, None, :] - patch_pts[None, :, :], axis=2)
    return float(d.min(axis=1).max())


@line_check("sec7-elev-closer")
def check_elev_closer() -> LineResult:
    from paper_repro.core.domain import sample_points

    got = read_sentence("Thus, the degree elevated ({elevated:word} order) control net is closer to the given patch "
                        "than its original ({original:word} order) one for all values of $\\alpha$.",
                        VERBATIM["sec7-elev-closer"], "orders, quantifier")
    if got["elevated"] not in ORDINALS or got["original"] not in ORDINALS:
        raise ValueError("unread line (orders, quantifier)")
    orders = (ORDINALS[got["original"]], ORDINALS[got["elevated"]]) == elevation_orders()
    rng = np.random.default_rng(23)
    results = {}
    for alpha in (0.6, math.pi / 2, 2.6):
        e = np.array(printed_elevation_matrix(math.cos(alpha / 2) ** 2, math.sin(alpha / 2) ** 2, float),
                     dtype=float)
        pts = sample_points(alpha, 4000, seed=5, interior=False)
        b1 = evaluate_normalized(1, alpha, pts)
        closer = 0
        for _ in range(10):
            net1 = rng.normal(size=(delta(1), 3))
            surf = b1 @ net1
            closer += _net_to_patch_distance(e @ net1, surf) < _net_to_patch_distance(net1, surf)
        results[f"{alpha:.4f}"] = closer
    ok = all(v == 10 for v in results.values()) and orders
    return LineResult(ok, kind="numeric-evidence",
                      how="orders read from the line (second, first) = those of the Example's elevation; largest "
                          "distance from a control point to the patch (4000 sample points) for 10 seeded "
                          "random nets at alpha = 0.6, pi/2, 2.6: smaller for the elevated net in every case",
                      detail={"nets_closer_after_elevation_of_10": results})


def alpha_condition(tex: str):
    r"""The printed condition on alpha (``0<\alpha<\frac{\pi}{2}``, ``\alpha=\frac{\pi}{2}``: a chain of
    ``<``, ``<=``, ``=``, read by :func:`~paper_repro.printed.latex_math.parse_relation`) as a predicate of alpha/pi
    (a Fraction), evaluated exactly: every part must be a rational multiple of pi once alpha is.

    >>> p = alpha_condition("\\frac{\\pi}{2}<\\alpha <\\pi")
    >>> p(Fraction(1, 2)), p(Fraction(3, 4)), p(Fraction(1))
    (False, True, False)
    """
    ops = {"<": operator.lt, "<=": operator.le, "=": operator.eq, ">": operator.gt, ">=": operator.ge}
    rel = LM.parse_relation(tex)
    alpha = sympy.Symbol("alpha")
    names = set().union(*(x.free_symbols for x in rel.parts))
    if rel.conditions or rel.lead or not rel.ops or any(op not in ops for op in rel.ops) or names != {alpha}:
        raise ValueError(f"unread condition on alpha {tex!r}")

    def holds(a: Fraction) -> bool:
        vals = [sympy.nsimplify(x.subs(alpha, sympy.Rational(a.numerator, a.denominator) * sympy.pi) / sympy.pi)
                for x in rel.parts]
        if not all(v.is_Rational for v in vals):
            raise ValueError(f"condition {tex!r}: not a rational multiple of pi")
        return all(ops[op](Fraction(int(x.p), int(x.q)), Fraction(int(y.p), int(y.q)))
                   for op, x, y in zip(rel.ops, vals, vals[1:]))

    return holds


@line_check("sec7-fig-elev-ranges")
def check_fig_elev_ranges() -> LineResult:
    """The caption's three conditions on alpha (read by :func:`~paper_repro.printed.latex_math.sentence`, each by
    :func:`alpha_condition`) partition (0, pi); the printed weights against the exact elevation in each case."""
    got = read_sentence("in cases (\\emph{{a:word}}), (\\emph{{b:word}}) and (\\emph{{c:word}}) the parameter "
                        "$\\alpha$ fulfills the conditions {ca}, {cb} and {cc}, respectively.",
                        VERBATIM["sec7-fig-elev-caption"], "cases, conditions")
    if (got["a"], got["b"], got["c"]) != ("a", "b", "c"):
        raise ValueError("unread cases (a), (b), (c)")
    preds = [alpha_condition(got[k]) for k in ("ca", "cb", "cc")]
    samples = [Fraction(k, 24) for k in range(1, 24)]  # alpha / pi
    partition = all(sum(p(a) for p in preds) == 1 for a in samples) and not any(p(Fraction(0)) or p(Fraction(1))
                                                                                 for p in preds)
    # the printed weights at a representative alpha of each case
    exact_cases = {t: printed_elevation_matrix(rational_alpha(_t(t)).cos_half ** 2,
                                               rational_alpha(_t(t)).sin_half ** 2, fmpq)
                   == [list(r) for r in elevation_matrix_exact(1, rational_alpha(_t(t)))] for t in ("1/5", "3/5")}
    half = np.array(printed_elevation_matrix(0.5, 0.5, float), dtype=float)
    dev = float(np.max(np.abs(half - elevation_matrix(1, math.pi / 2))))
    ok = len(preds) == 3 and partition and all(exact_cases.values()) and dev < 1e-9
    return LineResult(ok, kind="numeric-evidence",
                      how="the three printed conditions partition (0, pi) (alpha/pi = k/24); printed weights equal the "
                          "exact elevation at tan(alpha/4) = 1/5 (alpha < pi/2) and 3/5 (alpha > pi/2), and the float "
                          "least-squares elevation at alpha = pi/2 (|difference| < 1e-9)",
                      detail={"partition_of_0_pi": partition, "exact": exact_cases, "pi_over_2_below_1e-9": dev < 1e-9})


# ---------------------------------------------------------------- alpha -> 0

def parametrization_report(ranges: dict[str, tuple[str, str]], N: int = 12) -> dict:
    """Map the grid x, y in (1/N)Z of the printed ranges by (x, y) -> (x, y, 1-x-y): how many images leave the unit
    simplex (then w = alpha z < 0, outside Omega^alpha) and how many simplex grid points are never reached."""
    xlo, xhi = ranges.get("x", ("0", "1"))
    ylo, yhi = ranges["y"]
    outside, reached, empty = 0, set(), 0
    for a in range(-2 * N, 3 * N + 1):
        x = Fraction(a, N)
        if not P.evaluate_at(xlo, x=x) <= x <= P.evaluate_at(xhi, x=x):
            continue
        empty += P.evaluate_at(ylo, x=x) > P.evaluate_at(yhi, x=x)  # a printed x with no y: not a point of the domain
        for b in range(-2 * N, 3 * N + 1):
            y = Fraction(b, N)
            if not P.evaluate_at(ylo, x=x) <= y <= P.evaluate_at(yhi, x=x):
                continue
            z = 1 - x - y
            if min(x, y, z) < 0:
                outside += 1
            else:
                reached.add((x, y))
    simplex = {(Fraction(a, N), Fraction(b, N)) for a in range(N + 1) for b in range(N + 1 - a)}
    return {"grid": N, "images_outside_Omega": outside, "simplex_points_not_reached": len(simplex - reached),
            "x_without_y": empty}


def _range_result(ranges: dict[str, tuple[str, str]]) -> LineResult:
    """The printed ranges against the unit simplex; the corrected line is the printed one with the upper bound of y
    replaced by 1 - x (the slip recorded in the erratum; the other printed bounds are kept)."""
    printed = parametrization_report(ranges)
    corrected = parametrization_report({**ranges, "y": (ranges["y"][0], "1-x")})
    holds = printed["images_outside_Omega"] == printed["simplex_points_not_reached"] == printed["x_without_y"] == 0
    fixed = corrected["images_outside_Omega"] == corrected["simplex_points_not_reached"] == corrected["x_without_y"] \
        == 0
    return LineResult(holds, fixed, kind="exact-evidence",
                      how="the (1/12)-grid of the printed (x, y) ranges mapped by (x, y, 1-x-y) (alpha times it is the "
                          "point of Omega^alpha): images outside the simplex, simplex grid points not reached, and "
                          "printed x with an empty y range",
                      detail={"printed": printed, "corrected_y_upper_1-x": corrected})


def parametrization_row(tex: str) -> tuple[str, tuple[str, ...], object, tuple]:
    """One row ``u\\left(x,y\\right) & = & \\alpha x, & x \\in \\left[0, 1\\right]`` (or ``..., & z = 1-x-y``) read
    by the one reader: ``(name, arguments, right-hand side, condition)``; the condition is ``("in", var, lo, hi)``
    or ``("=", var, expression)``.  The relation must be one ``=`` with one clause."""
    rel = _relation(tex)
    lhs, rhs = rel.parts
    if not (isinstance(lhs, AppliedUndef) and len(lhs.args) == 1 and isinstance(lhs.args[0], sympy.Tuple)
            and len(rel.conditions) == 1 and len(rel.conditions[0].parts) == 2):
        raise ValueError(f"not a parametrization row 'f(x,y) = expr, condition': {tex!r}")
    if {str(x) for x in rhs.free_symbols} - set(NAMES) or rhs.atoms(AppliedUndef):
        raise ValueError(f"unknown names in {rhs}")
    cond = rel.conditions[0]
    var, right = cond.parts
    if cond.ops == ["in"] and isinstance(right, sympy.Interval) and not (right.left_open or right.right_open):
        return lhs.func.__name__, tuple(str(a) for a in lhs.args[0]), rhs, ("in", str(var), right.start, right.end)
    if cond.ops == ["="]:
        return lhs.func.__name__, tuple(str(a) for a in lhs.args[0]), rhs, ("=", str(var), right)
    raise ValueError(f"unread condition {cond}")


def strict_ranges(tex: str) -> dict[str, tuple]:
    """``{variable: (lower, upper)}`` of a text whose every ``$..$`` segment is ``v\\in\\left[lo,hi\\right]`` (read
    by the one reader); any other segment (``\\notin``, a relation) is refused."""
    segs = LM.inline_math(tex)
    if not segs:
        raise ValueError(f"no range in {tex!r}")
    out = {}
    for seg in segs:
        rel = LM.parse_relation(seg)
        right = rel.parts[-1]
        if rel.ops != ["in"] or rel.conditions or not isinstance(right, sympy.Interval) or right.left_open \
                or right.right_open:
            raise ValueError(f"not 'v in [lo, hi]': {seg!r}")
        out[str(rel.parts[0])] = (right.start, right.end)
    return out


def parametrization_rows() -> dict[str, tuple]:
    """The three printed rows u, v, w of the parametrization, read strictly (relation ``=``)."""
    rows = {}
    for r in "uvw":
        name, args, rhs, cond = parametrization_row(VERBATIM[f"sec7-limit-param-{r}"])
        rows[name] = (args, rhs, cond)
    if sorted(rows) != ["u", "v", "w"]:
        raise ValueError(f"rows {sorted(rows)}: not u, v, w")
    return rows


def _row_ranges(rows: dict[str, tuple]) -> dict[str, tuple[str, str]]:
    return {c[1]: (c[2], c[3]) for _, _, c in rows.values() if c[0] == "in"}


@line_check("sec7-limit-param-range")
def check_limit_param_range() -> LineResult:
    return _range_result(_row_ranges(parametrization_rows()))


@line_check("sec7-limit-caption-range")
def check_limit_caption_range() -> LineResult:
    return _range_result(strict_ranges(VERBATIM["sec7-fig-limit-caption-range"]))


@line_check("sec7-limit-param-map")
def check_limit_param_map() -> LineResult:
    """The printed rows read as sympy: with the printed z, u + v + w = alpha identically, and (u, v, w) = alpha (x, y,
    z), so u, v, w >= 0 iff (x, y, z) is in the unit simplex; the printed x range [0, 1] with the corrected y range
    reaches every simplex grid point and no point outside (exact, 1/12-grid)."""
    import sympy as sp

    rows = parametrization_rows()
    alpha, x, y, z = sp.symbols("alpha x y z")
    zdef = [c for _, _, c in rows.values() if c[0] == "="]
    args_ok = all(args == ("x", "y") for args, _, _ in rows.values())
    if len(zdef) != 1 or zdef[0][1] != "z":
        raise ValueError("no 'z = ...' condition")
    zval = zdef[0][2]
    total = sp.expand(sum(rhs for _, rhs, _ in rows.values()).subs(z, zval))
    coords = [sp.simplify(rows[r][1] / alpha) for r in "uvw"] == [x, y, z]
    ranges = _row_ranges(rows)
    rep = parametrization_report({**ranges, "y": (ranges["y"][0], "1-x")})
    ok = total == alpha and coords and args_ok \
        and rep["images_outside_Omega"] == rep["simplex_points_not_reached"] == rep["x_without_y"] == 0
    return LineResult(ok, kind="proof", how="rows read as sympy: u + v + w = alpha(x + y + z) = alpha with the printed "
                      "z = 1 - x - y, (u, v, w) = alpha (x, y, z); x in [0, 1] with y in [0, 1-x] reaches every "
                      "simplex grid point and no point outside", detail={"grid": rep, "sum": str(total),
                                                                          "x_range": list(ranges.get("x", ()))})


def bernstein_limits(n: int) -> dict:
    """Limit of each normalized function (closed forms, :func:`paper_repro.theory.limits.limit_terms`) compared with
    the Bernstein polynomial P^m_{a,b,c} of its monomial."""
    out = {"exact_bernstein": 0, "proper_multiple": [], "zero": []}
    for lab, (coef, tri) in zip(united_system(n), limit_terms(n)):
        bern = multinomial(sum(tri), tri)
        if coef == 0:
            out["zero"].append(lab.paper)
        elif coef == bern:
            out["exact_bernstein"] += 1
        else:
            out["proper_multiple"].append(f"{lab.paper} -> {coef / bern} P^{sum(tri)}_{{{tri[0]},{tri[1]},{tri[2]}}}")
    return out


def _numeric_limit(n: int, label: str, xyz=(Fraction(1, 2), Fraction(1, 4), Fraction(1, 4))) -> str:
    """Value of the normalized function at alpha (x, y, z), alpha = 1e-4, divided by x^a y^b z^c (mp, 30 digits)."""
    k = index_of(n)[label]
    with mpmath.workdps(30):
        alpha = mpmath.mpf("1e-4")
        pt = np.array([[alpha * mpmath.mpf(v.numerator) / v.denominator for v in xyz]], dtype=object)
        val = evaluate_normalized(n, alpha, pt, "mp", dps=30)[0, k]
        e = exponents(united_system(n)[k])
        mono = mpmath.mpf(1)
        for v, p in zip(xyz, (e[0], e[2], e[4])):
            mono *= (mpmath.mpf(v.numerator) / v.denominator) ** p
        return mpmath.nstr(val / mono, 6)


def _simplex_equation(tex: str) -> bool:
    """The printed ``x+y+z=1`` (one ``=``, read by the one reader) is the plane that the parametrization's rows make
    of Omega^alpha: with u, v, w = alpha x, alpha y, alpha z and u + v + w = alpha, x + y + z = 1."""
    import sympy as sp

    lhs, rhs = _relation(tex).parts
    alpha = sp.Symbol("alpha")
    rows = parametrization_rows()
    plane = sp.expand(sum(rows[r][1] for r in "uvw") / alpha)  # x + y + z of the parametrization (u+v+w = alpha)
    return sp.expand(lhs - rhs - (plane - 1)) == 0


def _orders_of_figure_cases() -> list[int]:
    """The orders of cases (a), (b), (c) of Fig. fig:limit_cases_n_1_2_3, read from its caption."""
    got = read_sentence("\\caption{Cases (\\emph{{a:word}}), (\\emph{{b:word}}) and (\\emph{{c:word}}) illustrate the "
                        "limiting case $\\alpha\\to 0$ of the {orders:words} order constrained trivariate normalized "
                        "trigonometric bases of type (\\ref{{eq:word}}), respectively.",
                        VERBATIM["sec7-fig-limit-caption-cases"], "the cases' orders")
    if (got["a"], got["b"], got["c"], got["eq"]) != ("a", "b", "c", "normalized_united_system"):
        raise ValueError("unread caption of the cases (a), (b), (c)")
    return listed_words(got["orders"], ORDINALS)


@line_check("sec7-limit-degenerate-bernstein")
def check_degenerate_bernstein() -> LineResult:
    tex = VERBATIM["sec7-limit-degenerate-bernstein"]
    got = read_sentence("it is easy to observe that the {orders:words} order normalized constrained trivariate "
                        "trigonometric function systems of type (\\ref{{eq:word}}) degenerate to constrained "
                        "trivariate Bernstein polynomials defined on the unit simplex {plane} as shown in "
                        "Fig.\\ \\ref{...}.", tex, "systems, 'degenerate to Bernstein polynomials'")
    if got["eq"] != "normalized_united_system":
        raise ValueError("unread line (systems of type (normalized_united_system))")
    ns = listed_words(got["orders"], ORDINALS)
    figure = ns == _orders_of_figure_cases()  # 'as shown in Fig.': the orders are those of the figure's cases
    plane = _simplex_equation(got["plane"])
    per_n = {str(n): bernstein_limits(n) for n in ns}
    printed = all(not r["proper_multiple"] for r in per_n.values())
    corrected = True
    for n in ns:
        for lab, (coef, tri) in zip(united_system(n), limit_terms(n)):
            ratio = coef / multinomial(sum(tri), tri)
            corrected &= (ratio == 0) == lab.is_centre and 0 <= ratio <= 1 and (lab.j > 0 or ratio == 1)
    numeric = _numeric_limit(2, "R_{4,3,1}")
    return LineResult(printed and figure and plane, corrected and figure and plane, kind="proof",
                      how=f"orders read from the line (= the figure's cases: n = {', '.join(map(str, ns))}), the "
                          "simplex x + y + z = 1 read and compared with the parametrization (u + v + w = alpha); "
                          "limits of the normalized functions "
                          "from the proven closed forms (P_f(1) x^a y^b z^c) compared with the Bernstein polynomials "
                          "P^{a+b+c}_{a,b,c}; numerically, R-bar_{4,3,1} at alpha = 1e-4 divided by x^3 y z is ~12, "
                          "not the 20 of P^5_{3,1,1}",
                      detail={"orders": ns, "orders_are_the_figure_cases": figure, "simplex_equation": plane,
                              "per_n": per_n, "R_431_over_x3yz_at_alpha_1e-4": numeric})


def bernstein_definition() -> dict:
    """The caption's definition read: ``P^{m}_{d,e,f}`` (degree symbol, index symbols), the formula (sympy), the
    words 'of degree $m$', and the index set ``d,e,f \\in \\{0,1,\\ldots,m\\}`` 'such that' ``d+e+f=m``, each
    ``$..$`` segment read by :mod:`~paper_repro.printed.latex_math` (a listed subject in a listed set; the
    superscript of ``P^{m}_{d,e,f}`` printed before its subscript)."""
    words, segs = LM.prose(VERBATIM["sec7-fig-limit-caption-bernstein"])
    if words != "($$ denotes the constrained trivariate Bernstein polynomial $$ of degree $$" or len(segs) != 3:
        raise ValueError("unread definition")
    name = LM.parse(segs[0])
    if not (isinstance(name, AppliedUndef) and name.func.__name__ == "P_sup" and len(name.args) == 4
            and all(isinstance(a, sympy.Symbol) for a in name.args)):
        raise ValueError(f"unread P^{{m}}_{{d,e,f}}: {name}")
    words, segs_i = LM.prose(VERBATIM["sec7-fig-limit-caption-indices"])
    if words != "$$ such that $$" or len(segs_i) != 2:
        raise ValueError("unread index set")
    member = LM.parse_relation(segs_i[0])
    listed = member.parts[-1] if len(member.parts) == 2 else None
    if member.ops != ["in"] or member.conditions or not isinstance(member.parts[0], sympy.Tuple) or not (
            isinstance(listed, AppliedUndef) and listed.func == LM.Family and not listed.args[1]
            and not listed.args[2] and isinstance(listed.args[0], sympy.Tuple)):
        raise ValueError("unread index set")
    constraint = _relation(segs_i[1])
    for e in (*member.parts[0], *listed.args[0], *constraint.parts):
        P.within(e, NAMES + ("ldots",))
    return {"degree": str(name.args[3]), "indices": tuple(str(a) for a in name.args[:3]),
            "formula": read_expression(segs[1]), "degree_words": read_expression(segs[2]),
            "set_vars": tuple(str(a) for a in member.parts[0]), "set": list(listed.args[0]),
            "constraint": tuple(constraint.parts)}


@line_check("sec7-bernstein-definition")
def check_bernstein_definition() -> LineResult:
    """For m = 1..8 the printed index set, enumerated, is the exponent set of (x + y + z)^m, and the printed formula
    at each index is that term of the multinomial expansion (fmpq_mpoly) with z = 1 - x - y, of total degree m = the
    printed degree; so the P^m_{d,e,f} sum to 1 on the unit simplex."""
    import sympy as sp

    d = bernstein_definition()
    ctx = fmpq_mpoly_ctx.get(("x", "y", "z"), "lex")
    X_, Y_, Z_ = ctx.gens()
    xs, ys = sp.symbols("x y")
    per_m, ok = {}, d["set_vars"] == d["indices"]
    for m in range(1, 9):
        env = {"m": m}
        values = P.progression(d["set"], **env)
        idx = []
        for a in values:
            for b in values:
                for c in values:
                    lhs, rhs = d["constraint"]
                    if lhs.subs(dict(zip(d["set_vars"], (a, b, c)))).subs(env) == rhs.subs(env):
                        idx.append((a, b, c))
        expansion = (X_ + Y_ + Z_) ** m
        terms = {tuple(e): c for e, c in zip(expansion.monoms(), expansion.coeffs())}
        same_set = sorted(idx) == sorted(terms)
        formula_ok = True
        for (a, b, c) in idx if same_set else []:
            sub = dict(zip(d["indices"], (a, b, c)))
            got = sp.expand(d["formula"].subs({**sub, d["degree"]: m}))
            coef = sp.Rational(int(terms[(a, b, c)].p), int(terms[(a, b, c)].q))
            want = sp.expand(coef * xs ** a * ys ** b * (1 - xs - ys) ** c)
            formula_ok &= got == want
        degree_ok = d["degree_words"].subs(d["degree"], m) == m
        per_m[str(m)] = {"index_set_is_multinomial": same_set, "formula_is_term": formula_ok, "degree": degree_ok}
        ok &= same_set and formula_ok and degree_ok
    return LineResult(ok, kind="exhaustive",
                      how="printed index set (read: list, step, constraint) enumerated and compared with the exponents "
                      "of (x + y + z)^m; the printed formula (read as sympy) at each index equals that multinomial "
                      "term with z = 1 - x - y; the printed degree is m; m = 1..8",
                      detail={"per_m": per_m})


def _paper_spelling() -> str:
    """The paper's spelling of 'trivariate': the most frequent word ``tri...variate`` over every transcribed line."""
    from collections import Counter

    from paper_repro.printed.lines import all_lines

    prose_words = (x.strip(".,;:(){}").lower() for ln in all_lines() for x in LM.prose(ln.verbatim)[0].split())
    words = Counter(w for w in prose_words if w.startswith("tri") and w.endswith("variate") and w.isalpha())
    return words.most_common(1)[0][0]


@line_check("sec7-fig-limit-caption-centre")
def check_caption_centre() -> LineResult:
    """Which node the caption names (innermost = the centre, the node of the highest level j = n; outermost = level
    0), the word 'vanish', and the limit point of alpha, read; compared with the limits of the proven closed forms
    (n = 1..3) and of the limit formula (n = 1..12), or, for a limit point other than 0, with the values there."""
    tex = VERBATIM["sec7-fig-limit-caption-centre"]
    m = read_sentence("Constrained {word:word} normalized trigonometric basis functions associated with the "
                      "{node:word} node of the graphs above vanish when {limit}.", tex, "node, 'vanish when'")
    if m["node"] not in ("innermost", "outermost"):
        raise ValueError("unread caption (node, 'vanish when')")
    spelled = m["word"] == _paper_spelling()  # 'triavariate' is a typographical slip (erratum on the line)
    level = (lambda n: n) if m["node"] == "innermost" else (lambda n: 0)
    limit = alpha_limit(m["limit"])
    named = {str(n): sorted(lab.paper for lab in united_system(n) if lab.j == level(n)) for n in range(1, 13)}
    if limit == 0:
        closed = {str(n): sorted(lab.paper for lab, (c, _) in zip(united_system(n), limit_terms(n)) if c == 0)
                  for n in (1, 2, 3)}
        formula = {str(n): sorted(lab.paper for lab in united_system(n) if limit_factor(n, lab.i, lab.j) == 0)
                   for n in range(1, 13)}
        ok = all(v == named[n] for d in (closed, formula) for n, v in d.items())
        return LineResult(ok and spelled, ok, kind="exhaustive",
                          how="node read from the caption; limit coefficients P_f(1) of the proven closed forms "
                          "(n = 1..3) and the limit formula (n = 1..12): exactly the named node's functions tend to 0",
                          detail={"word": m["word"], "paper_spelling": _paper_spelling(),
                                  "named": {k: v for k, v in named.items() if int(k) <= 3},
                                  "vanishing_closed_forms": closed, "vanishing_formula_n_le_12": len(formula)})
    value = float(limit)
    pts = np.array([[value / 3, value / 3, value / 3]])
    vals = {str(n): float(max(abs(evaluate_normalized(n, value, pts)[0, k]) for k, lab in enumerate(united_system(n))
                              if lab.j == level(n))) for n in (1, 2, 3)}
    vanish = all(v < 1e-12 for v in vals.values())
    return LineResult(vanish and spelled, vanish, kind="numeric-evidence",
                      how=f"the named node's functions at alpha = {value} at the simplex centre, n = 1, 2, 3",
                      detail={"values": vals})


def _degrees_result(got: dict, degrees: list[int]) -> tuple[bool, dict]:
    """The orders (the ordinal words of the slot ``orders``) and the printed ``degrees``, paired in order, against the
    degree of the alpha -> 0 limit from the proven closed forms and from the limit formula; the limit point (the
    segment of the slot ``limit``) read (must be 0)."""
    orders = listed_words(got["orders"], ORDINALS)
    limit = alpha_limit(got["limit"])
    computed = {str(n): (limit_degree(n, "closed_forms"), limit_degree(n, "formula")) for n in orders}
    ok = limit == 0 and len(orders) == len(degrees) and all(
        a == b == d for (a, b), d in zip(computed.values(), degrees))
    return ok, {"orders": orders, "degrees": degrees, "limit_point": str(limit),
                "computed": {k: list(v) for k, v in computed.items()}}


@line_check("sec7-conversion-degrees")
def check_conversion_degrees() -> LineResult:
    """The orders, the degree words and 'when $\\alpha \\to 0$' of the line and of the caption of Fig.
    fig:conversion (each read by :func:`~paper_repro.printed.latex_math.sentence`), paired in order."""
    line = read_sentence("Moreover, the control nets of the original {orders:words} order triangular trigonometric "
                         "patches can be converted to control nets that describe classical polynomial {degrees:words} "
                         "triangular B\\'ezier patches, respectively, when {limit}.",
                         VERBATIM["sec7-conversion-degrees"], "orders, degrees")
    cap = read_sentence("\\caption{Conversion of control nets of original {orders:words} order triangular "
                        "trigonometric patches to that of (\\emph{{a:word}}) {d1:word} and (\\emph{{b:word}}) "
                        "{d2:word} triangular B\\'ezier patches, respectively, when {limit}.}",
                        VERBATIM["sec7-fig-conversion-caption"], "caption degrees")
    if (cap["a"], cap["b"]) != ("a", "b") or any(cap[d] not in DEGREE_WORDS for d in ("d1", "d2")):
        raise ValueError("unread caption degrees")
    ok1, d1 = _degrees_result(line, listed_words(line["degrees"], DEGREE_WORDS))
    ok2, d2 = _degrees_result(cap, [DEGREE_WORDS[cap[d]] for d in ("d1", "d2")])
    return LineResult(ok1 and ok2, kind="proof", how="orders, degree words and alpha -> 0 read from the line and the "
                      "caption, paired in order; degree of the alpha -> 0 limit from the proven closed forms and from "
                      f"the limit formula, n = {', '.join(map(str, d1['orders']))} (the orders the line names)",
                      detail={"line": d1, "caption": d2})


# ---------------------------------------------------------------- conversions

def conversion_order(terms: list[tuple[Fraction, str]]) -> int:
    """The order n of a printed conversion: control points ``x_{2n,.,.}`` (all of one order)."""
    orders = {int(lab.split("{")[1].split(",")[0]) for _, lab in terms}
    if len(orders) != 1 or next(iter(orders)) % 2:
        raise ValueError(f"control points of orders {orders}")
    return orders.pop() // 2


def conversion_holds(n: int, tex: str) -> bool:
    """The printed p_{d,e,f} (read by the one reader: relation ``=``, signs, weights; names of members) equals the
    row of the exact conversion matrix (limit formula and closed forms agree)."""
    idx, terms = P.conversion(tex)
    if conversion_order(terms) != n or any(lab not in _point_names(n) for _, lab in terms):
        return False
    ix = index_of(n)
    vec = [fmpq(0)] * delta(n)
    for w, lab in terms:
        vec[ix[lab]] += _q(w)
    for source in ("formula", "closed_forms"):
        rows, w = conversion_matrix(n, source)
        if idx not in rows or list(w[rows.index(idx)]) != vec:
            return False
    return True


def _register_conversion(line_id: str, n: int) -> None:
    @line_check(line_id)
    def check() -> LineResult:
        holds = conversion_holds(n, VERBATIM[line_id])
        return LineResult(holds, kind="proof", how="printed weights (read from the LaTeX with their signs) equal the "
                          f"row of the exact conversion to the degree-{3 * n - 1} Bernstein basis (alpha-independent; "
                          "from the limit formula and from the proven closed forms)", detail={"equal": holds})


for _ln in LINES:
    if _ln.id.startswith(("sec7-conv2-", "sec7-conv3-")) and _ln.status == "checked":
        _register_conversion(_ln.id, int(_ln.id[9]))

CONVERSION_IDS = [ln.id for ln in LINES if ln.id.startswith(("sec7-conv2-", "sec7-conv3-"))]


def printed_conversions() -> dict[int, list[tuple[tuple[int, int, int], list[tuple[Fraction, str]]]]]:
    """Every printed Bezier point of the conversions (read strictly), by the order of its control points."""
    out: dict[int, list] = {}
    for lid in CONVERSION_IDS:
        idx, terms = P.conversion(VERBATIM[lid])
        out.setdefault(conversion_order(terms), []).append((idx, terms))
    return out


def _rotate(t: tuple[int, int, int]) -> tuple[int, int, int]:
    return (t[2], t[0], t[1])


@line_check("sec7-conversion-symmetry")
def check_conversion_symmetry() -> LineResult:
    words, segs = LM.prose(VERBATIM["sec7-conversion-symmetry"])  # the words, then 'n = 2' and '3' read
    if words != "Due to symmetry, we only list for $$ and $$ the position of B\\'ezier points" or len(segs) != 2:
        raise ValueError("unread line ('Due to symmetry', the orders)")
    first, second = LM.parse_relation(segs[0]), LM.parse(segs[1])
    if (first.ops != ["="] or first.parts[0] != sympy.Symbol("n") or first.conditions or not first.parts[1].is_Integer
            or not second.is_Integer):
        raise ValueError("unread line ('Due to symmetry', the orders)")
    named = [int(first.parts[1]), int(second)]
    printed = printed_conversions()
    detail = {"orders_named": named, "orders_listed": sorted(printed)}
    ok = named == sorted(printed)
    for n in sorted(printed):
        rows, w = conversion_matrix(n, "formula")
        tri = [t for _, t in limit_terms(n)]
        pos = {t: k for k, t in enumerate(tri)}
        equivariant = all(w[rows.index(_rotate(r))][pos[_rotate(tri[f])]] == w[rows.index(r)][f]
                          for r in rows for f in range(len(tri)))
        listed = [idx for idx, _ in printed[n]]
        valid = [t for t in listed if t in rows]
        orbits_ = {frozenset({t, _rotate(t), _rotate(_rotate(t))}) for t in rows}
        met = {o for o in orbits_ if o & set(valid)}
        # the one invalid printed index (p_{8,8,0}) is erratum conversion-p_{8,8,0}; read as p_{8,0,0}
        met_fixed = {o for o in orbits_ if o & (set(valid) | ({(8, 0, 0)} if n == 3 else set()))}
        detail[str(n)] = {"equivariant_under_rotation": equivariant, "listed": len(listed), "orbits": len(orbits_),
                          "orbits_met": len(met), "orbits_met_with_p800": len(met_fixed),
                          "invalid_listed": [list(t) for t in listed if t not in rows]}
        ok &= equivariant and len(met_fixed) == len(orbits_)
    return LineResult(ok, kind="proof", how="the orders named (n = 2 and 3) are those of the listed points; the exact "
                      "conversion matrix is equivariant under the rotation (d,e,f) -> (f,d,e) of indices and "
                      "functions, and the listed points meet every rotation orbit", detail=detail)


@line_check("sec7-conversion-convex")
def check_conversion_convex() -> LineResult:
    read_sentence("shows all B\\'ezier points obtained by the evaluation of convex combinations describing these "
                  "conversion processes.", VERBATIM["sec7-conversion-convex"], "'all ... convex combinations'")
    printed = printed_conversions()
    per_n = {}
    for n in sorted(printed):
        _, w = conversion_matrix(n, "formula")
        per_n[str(n)] = all(x >= 0 for row in w for x in row) and all(sum(row) == 1 for row in w)
    rows = [terms for n in printed for _, terms in printed[n]]
    printed_ok = all(all(w >= 0 for w, _ in r) and sum(w for w, _ in r) == 1 for r in rows)
    return LineResult(all(per_n.values()) and printed_ok, kind="proof",
                      how="every row of the exact conversion matrix (n = 2, 3: the orders of the figure) and every "
                          "printed row has non-negative weights summing to 1",
                      detail={"computed": per_n, "printed_rows": printed_ok})


@line_check("sec7-question-limiting-case")
def check_question_limiting_case(verbatim: str | None = None) -> LineResult:
    """The Question read from the transcription -- the limit point ``$\\alpha \\to 0$``, the order ``$n$`` and the
    degree ``$3n-1$`` of the (rational) Bezier patch on the unit simplex -- against the degree of the limit from
    the limit formula and from the proven closed forms."""
    from paper_repro.printed.parsed import bound

    m = LM.sentence("Is the limiting case {limit} of the (rational) triangular trigonometric patch of order {n} a "
                    "(rational) triangular B\\'ezier patch of degree {degree} defined on the unit simplex?...",
                    VERBATIM["sec7-question-limiting-case"] if verbatim is None else verbatim)
    if m is None:
        return LineResult(False, how="the Question read from the transcription, n = 1..12", kind="exhaustive",
                          detail={"unread": "no 'limiting case $..$ ... of order $..$ ... of degree $..$'"})
    limit = alpha_limit(m["limit"])
    degrees = {str(n): limit_degree(bound(m["n"], n=n), "formula") for n in range(1, 13)}
    lemmas = {str(n): all(v for k, v in limit_checks(n).items() if isinstance(v, bool)) for n in range(1, 6)}
    closed = {str(n): limit_degree(bound(m["n"], n=n), "closed_forms") for n in (1, 2, 3, 4)}
    ok = limit == 0 and all(d == bound(m["degree"], n=int(n)) for n, d in {**degrees, **closed}.items()) \
        and all(lemmas.values())
    return LineResult(ok, kind="exhaustive",
                      how="limit point, order and degree read from the Question; degree of the limit Bezier triangle "
                      "from the limit formula (n = 1..12; its lemmas checked exactly for n = 1..5) and from the proven "
                      "closed forms (n = 1..4) against the printed degree",
                      detail={"limit_point": str(limit), "degree_formula": degrees, "degree_closed_forms": closed,
                              "lemmas": lemmas})


# ---------------------------------------------------------------- Section 8

@line_check("sec7-s8-dimension-and-span")
def check_dimension_and_span(verbatim: str | None = None) -> LineResult:
    """delta_n as printed (read from the transcription: ``\\delta_{n}=3n\\left(n+1\\right)+1``) = |T_{2n}| = |V_n|;
    'linearly independent' read: the exact rank of T_{2n} is delta_n; the order of the truncated Fourier basis read
    ('of order $n\\in\\mathbb{N}$'): the ranks of V_k and of [T_{2n} V_k] equal delta_n (same span)."""
    from paper_repro.printed.parsed import bound

    words, segs = LM.prose(VERBATIM["sec7-s8-dimension"] if verbatim is None else verbatim)
    try:  # the words, then 'delta_n = ..' read by the one reader
        if words != ("the normalized linearly independent constrained trivariate function system "
                     "(\\ref{normalized_united_system}) of dimension $$") or len(segs) != 1:
            raise LM.LatexMathError("no delta_n")
        rel = LM.parse_relation(segs[0])
        if rel.ops != ["="] or rel.parts[0] != sympy.Function("delta")(sympy.Symbol("n")) or rel.conditions:
            raise LM.LatexMathError("no delta_n")
    except LM.LatexMathError:
        return LineResult(False, how="delta_n read from the transcription", detail={"unread": "no delta_n"})
    expr = rel.parts[1]
    span_words, span_segs = LM.prose(VERBATIM["sec7-s8-spans-fourier"])  # 'of order $n\in\mathbb{N}$.'
    order = LM.parse_relation(span_segs[0]) if len(span_segs) == 1 else None
    if (span_words != "that spans the same vector space of functions as the constrained trivariate extension of the "
            "canonical basis of truncated Fourier series of order $$." or order is None or order.ops != ["in"]
            or order.parts[1] != sympy.Symbol("N_bb") or order.conditions):
        raise ValueError("unread order of the Fourier basis")
    k_order = order.parts[0]
    counts = {str(n): (len(united_system(n)), bound(expr, n=n), len(v_labels(bound(k_order, n=n))))
              for n in range(1, 13)}
    ctx = ModpContext(p=2**31 - 1)
    ranks = {}
    for n in (1, 2, 3):
        k = bound(k_order, n=n)
        alpha = rational_alpha(fmpq(2, 5))
        pts = sample_rational_points(alpha, delta(max(n, k)) + 6, seed=40 + n)
        t = evaluate(n, alpha, pts, ctx)
        v = evaluate_v(k, alpha, pts, ctx)
        ranks[str(n)] = [ctx.rank(t), ctx.rank(v), ctx.rank(np.concatenate([t, v], axis=1))]
    ok = all(a == b == c for a, b, c in counts.values()) and all(r == [delta(int(n))] * 3 for n, r in ranks.items())
    return LineResult(ok, how="|T_{2n}| = printed delta_n = |V_n| (n = 1..12); ranks modulo 2^31-1 of T_{2n}, V_n and "
                      "[T_{2n} V_n] at delta_n + 6 rational points of tan(alpha/4) = 2/5 all equal delta_n (n = 1..3): "
                      "T_{2n} linearly independent (a rank mod p is at most the rank over Q) and the spans equal",
                      detail={"counts": {k: list(v) for k, v in counts.items()}, "ranks_T_V_joint": ranks})
