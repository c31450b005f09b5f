"""Checks of Section 6 (sec:applications), source lines 2168-2666 (:mod:`paper_repro.printed.lines.sec6`).

Independent computations used here:

* index sets are enumerated from their printed bounds and compared with the labels of T_{2n}
  (:func:`~paper_repro.core.labels.united_system`), with ``delta_n`` and with the exact rank of the basis;
* patches are evaluated exactly (python-flint rationals) at points with rational half-angle sines and
  cosines (:mod:`paper_repro.core.domain`), the normalizing coefficients coming from exact collocation
  (:mod:`paper_repro.core.normalization`), the univariate B-basis from its constants (eq. univariate_basis);
* the torus and the Dupin cyclide are fitted exactly in the normalized basis
  (:func:`~paper_repro.surfaces.fitting.fit_exact`) and the printed control points, parsed from their
  transcriptions (:mod:`paper_repro.printed.torus`), are evaluated exactly and compared with the fit;
* surfaces are tested against their implicit quartics exactly.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from math import comb

import numpy as np
import sympy
from flint import fmpq, fmpq_mat, fmpq_poly

from paper_repro.claims.lines import LineResult, items_result, line_check
from paper_repro.core.basis import evaluate
from paper_repro.core.derivatives_basis import basis_derivative
from paper_repro.core.domain import RationalAngle, RationalPoints, rational_alpha, sample_rational_points
from paper_repro.core.labels import delta, exponents, index_of, united_system
from paper_repro.core.normalization import coefficient_vector, evaluate_normalized
from paper_repro.core.univariate import c_const, c_numerator
from paper_repro.printed.latex_math import sentence
from paper_repro.printed.lines import live_lines
from paper_repro.surfaces.fitting import ExactTrig, fit_exact

NS = tuple(range(1, 13))  # orders for the index-set counts
TS = (fmpq(1, 5), fmpq(1, 3), fmpq(1, 2), fmpq(3, 4))  # tan(alpha/4) of the exact checks
TS_TORUS = TS + (fmpq(1, 9), fmpq(2, 5), fmpq(3, 5), fmpq(7, 8))  # for the 19 torus points
RHO_MU = ((fmpq(1), fmpq(0)), (fmpq(0), fmpq(1)), (fmpq(7, 2), fmpq(5, 3)))  # (varrho, mu) of the torus fits
_LINE = live_lines()  # read at every lookup (the blank and mutation tests change the transcription)


# --- helpers ---------------------------------------------------------------------------------------------
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5}


def enumerate_set(letter: str, n: int, j_max: int, i_max: Callable[[int], int], first=lambda n, i: 2 * n - i,
                  ) -> list[str]:
    """Labels ``{letter_{2n, first(i), j}}_{j=0, i=j}^{j_max, i_max(j)}`` exactly as the printed bounds say."""
    return [f"{letter}_{{{2 * n},{first(n, i)},{j}}}" for j in range(j_max + 1) for i in range(j, i_max(j) + 1)]


def printed_control_net(n: int, r_j_max: int | None = None) -> list[str]:
    """The control net of def:surface_patch / def:rational_patch as printed: r with ``j = 0..n``,
    g and b with ``j = 0..n-1``, all with ``i = j..2n-1-j``."""
    r_j_max = n if r_j_max is None else r_j_max
    out = enumerate_set("r", n, r_j_max, lambda j, n=n: 2 * n - 1 - j)
    for letter in "gb":
        out += enumerate_set(letter, n, n - 1, lambda j, n=n: 2 * n - 1 - j)
    return out


def corrected_control_net(n: int) -> list[str]:
    return [f"r_{{{2 * n},{n},{n}}}"] + printed_control_net(n, r_j_max=n - 1)


def code_labels(n: int) -> list[str]:
    return [lab.control_point for lab in united_system(n)]


def matches_basis(labels: Sequence[str], n: int) -> bool:
    """``labels`` name each function of T_{2n} exactly once (as a multiset, delta_n of them)."""
    return sorted(labels) == sorted(code_labels(n)) and len(labels) == delta(n)


def _rng(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def random_net(n: int, dim: int, seed: int) -> list[list[fmpq]]:
    rng = _rng(seed)
    return [[fmpq(int(rng.integers(-9, 10)), int(rng.integers(1, 5))) for _ in range(dim)] for _ in range(delta(n))]


def combine(values: np.ndarray, net: Sequence[Sequence[fmpq]]) -> list[list[fmpq]]:
    """Rows ``sum_k values[p, k] * net[k]`` (exact)."""
    dim = len(net[0])
    return [[sum((values[p, k] * net[k][d] for k in range(len(net))), fmpq(0)) for d in range(dim)]
            for p in range(values.shape[0])]


def tq(t: fmpq, s: fmpq) -> fmpq:
    """tan((x - y)/4) from t = tan(x/4), s = tan(y/4)."""
    return (t - s) / (1 + t * s)


def trig_of(t: fmpq) -> tuple[fmpq, fmpq]:
    """(cos x, sin x) for t = tan(x/4) (rational)."""
    s, c = 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)
    return c * c - s * s, 2 * s * c


def rank(rows: Sequence[Sequence[fmpq]]) -> int:
    return fmpq_mat([list(r) for r in rows]).rank()


def corrected_text(line_id: str) -> str | None:
    """The line's transcription with its erratum's ``fix`` applied (each ``(printed, corrected)`` LaTeX pair: the
    printed fragment must occur in the transcription as it stands now), or ``None`` when a printed fragment is not
    there (the transcription is not the one the erratum corrects)."""
    ln = _LINE[line_id]
    text = ln.verbatim
    for printed, corrected in (ln.erratum or {}).get("fix", []):
        if printed not in text:
            return None
        text = text.replace(printed, corrected, 1)
    return text


def has_words(text: str, *phrases: str) -> bool:
    """Every phrase occurs in ``text`` (whitespace-normalised): the words that carry a prose line's claim."""
    norm = " ".join(text.replace("%", " ").split())
    return all(" ".join(p.split()) in norm for p in phrases)


# --- Definition def:surface_patch: index sets and counts -------------------------------------------------
# --- the rows of eq. triangular_trig_surface, eq. rational_patch, tau-bar and the weight sum, read by latex_math ------
N_SYM = sympy.Symbol("n")
UVW = sympy.Tuple(*sympy.symbols("u v w"))
_POINT_OF = {"r_vec": "R", "g_vec": "G", "b_vec": "B"}
_WEIGHT_OF = {"rho": "R", "gamma": "G", "beta": "B"}
_FUNC_OF = {"Rbar": "R", "Gbar": "G", "Bbar": "B"}
#: what one term of each kind of row is made of (besides its coefficient 1)
ROW_KINDS = {"patch": ("point", "function"), "rational": ("weight", "point", "function", "tau"),
             "tau": ("weight", "function"), "weights": ("weight",)}


def parse_rows(ids: Sequence[str], override: dict[str, str] | None = None) -> list[tuple]:
    """``(left-hand side or None, right-hand side)`` of each row, read by
    :func:`paper_repro.printed.latex_math.parse_relation` (a continuation row has no left-hand side)."""
    from paper_repro.printed.latex_math import parse_relation

    out = []
    for k in ids:
        tex = (override or {}).get(k, _LINE[k].verbatim)
        rel = parse_relation(tex.strip().rstrip(",."))
        if rel.conditions or rel.ops not in ([], ["="]):
            raise ValueError(f"{k}: not a row of a sum ({rel.ops})")
        out.append((rel.parts[0] if rel.ops else None, rel.parts[-1]))
    return out


def row_labels(expr, n: int, kind: str, strict_arguments: bool = True) -> list[str]:
    """See :func:`_row_labels` (cached by the parsed expression: the same row is written out once per order)."""
    return list(_row_labels(expr, n, kind, strict_arguments))


@functools.lru_cache(maxsize=512)
def _row_labels(expr, n: int, kind: str, strict_arguments: bool = True) -> tuple[str, ...]:
    """The control-point labels of the terms of a parsed row at order n (sums written out the paper's way,
    :func:`paper_repro.printed.latex_math.evaluate_sums`).  Each term must have coefficient 1 and be made of the
    factors of ``kind`` (:data:`ROW_KINDS`) with one colour and one index triple: weight rho/gamma/beta, point
    r/g/b, normalized function R/G/B-bar with the arguments (u,v,w) (unless ``strict_arguments`` is False) and the
    superscript alpha, and the denominator tau-bar_n(u,v,w); ``ValueError`` otherwise."""
    from paper_repro.printed.latex_math import evaluate_sums

    e = sympy.expand(evaluate_sums(expr.subs(N_SYM, n)))
    out = []
    for mono, coeff in e.as_coefficients_dict().items():
        if coeff != 1:
            raise ValueError(f"term {mono} has the coefficient {coeff}")
        parts: dict[str, tuple] = {}
        for f in sympy.Mul.make_args(mono):
            base, exp = f.as_base_exp()
            name = type(base).__name__
            if name in _WEIGHT_OF and exp == 1:
                slot = "weight"
            elif name in _POINT_OF and exp == 1:
                slot = "point"
            elif name in _FUNC_OF and exp == 1:
                slot = "function"
            elif name == "taubar" and exp == -1:
                slot = "tau"
            else:
                raise ValueError(f"factor {f} of term {mono}")
            if slot in parts:
                raise ValueError(f"two factors {slot} in {mono}")
            parts[slot] = (name, tuple(base.args))
        if set(parts) != set(ROW_KINDS[kind]):
            raise ValueError(f"term {mono}: {sorted(parts)} instead of {ROW_KINDS[kind]}")
        colours = {({**_WEIGHT_OF, **_POINT_OF, **_FUNC_OF}).get(nm) for s, (nm, _) in parts.items() if s != "tau"}
        triples = {args[:3] for s, (_, args) in parts.items() if s != "tau"}
        if len(colours) != 1 or len(triples) != 1:
            raise ValueError(f"term {mono}: colours {colours}, indices {triples}")
        if "tau" in parts and parts["tau"][1] != (n, UVW):
            raise ValueError(f"term {mono}: the denominator is not tau-bar_n(u,v,w)")
        if "function" in parts:
            fargs = parts["function"][1]
            if (fargs[3:] != (UVW,)) if strict_arguments else (fargs[3:] not in ((UVW,), ())):
                raise ValueError(f"term {mono}: the function's arguments are {fargs[3:]}, not (u,v,w)")
        for s, (_, args) in parts.items():
            if s in ("weight", "point") and len(args) != 3:
                raise ValueError(f"term {mono}: {s} with arguments {args}")
        (a, b, c), colour = next(iter(triples)), next(iter(colours))
        if a != 2 * n:
            raise ValueError(f"term {mono}: first index {a}, not 2n")
        out.append(f"{colour.lower()}_{{{a},{b},{c}}}")
    return tuple(out)


def rows_labels(ids: Sequence[str], n: int, kind: str, override: dict[str, str] | None = None, lhs=None,
                strict_arguments: bool = True) -> list[str]:
    """Labels of every term of the rows ``ids`` (read) at order n; ``lhs`` (a sympy object) is the left-hand side
    the first row must have."""
    rows = parse_rows(ids, override)
    if lhs is not None and rows[0][0] != lhs:
        raise ValueError(f"left-hand side {rows[0][0]} instead of {lhs}")
    if any(row[0] is not None for row in rows[1:]):
        raise ValueError("a continuation row has a left-hand side")
    return [lab for _, rhs in rows for lab in row_labels(rhs, n, kind, strict_arguments)]


NS_ROWS = tuple(range(1, 9))  # orders at which the parsed rows are written out (sympy; n = 1..8)
PATCH_ROWS = ("sec6-patch-row-1", "sec6-patch-row-2")


def patch_terms_read(n: int, override: dict[str, str] | None = None) -> list[str]:
    """The control points of eq. triangular_trig_surface at order n, read from the transcriptions of its two rows
    (:func:`rows_labels`: every term a point times its normalized function of (u,v,w), coefficient 1)."""
    return rows_labels(PATCH_ROWS, n, "patch", override, lhs=sympy.Function("s_vec")(N_SYM, UVW))


@line_check("sec6-patch-index-sets")
def patch_index_sets(override: dict[str, str] | None = None) -> LineResult:
    """The terms of eq. triangular_trig_surface (its two rows read by printed.latex_math, sums written out) are the
    delta_n functions of T_{2n}, each once, each a point times its normalized function of (u,v,w) with coefficient 1:
    compared with the code's labels (n = 1..8), distinct functions (exponent vectors), full rank (exact collocation
    at delta_n points, n = 1, 2, 3); the printed order range (n >= 1) vs the orders with a patch."""
    try:
        counts_ok = all(matches_basis(patch_terms_read(n, override), n) for n in NS_ROWS)
    except ValueError as exc:
        return LineResult(False, how="the printed sums read from the transcriptions", detail={"unread": str(exc)})
    distinct = all(len({exponents(lab) for lab in united_system(n)}) == delta(n) for n in NS)
    alpha = rational_alpha(fmpq(1, 3))
    ranks = {}
    for n in (1, 2, 3):
        pts = sample_rational_points(alpha, delta(n), seed=60 + n)
        ranks[n] = rank(evaluate(n, alpha, pts, "exact").tolist())
    full = all(ranks[n] == delta(n) for n in ranks)
    order_ok = order_range_ok("sec6-patch-order")
    return LineResult(counts_ok and distinct and full and order_ok, how="the rows read by printed.latex_math, their "
                      "sums written out vs united_system, n = 1..8; exact rank of the basis at delta_n rational "
                      "points, n = 1..3; the printed order range (n >= 1) vs the orders with a patch (n = 0..12)",
                      kind="exact-evidence",
                      detail={"n": [NS_ROWS[0], NS_ROWS[-1]],
                              "terms_n_1_2_3": [len(patch_terms_read(n, override)) for n in (1, 2, 3)],
                              "rank_n_1_2_3": [ranks[n] for n in (1, 2, 3)], "order_range_read": order_ok})


def order_range_ok(line_id: str) -> bool:
    """The printed range of the order (``of order $n\\geq1$``, read from the transcription) is exactly the set of
    orders n = 0..12 that have a patch: 2n >= 2 (n = 0 leaves the constant function 1 alone, no trigonometric
    function) with delta_n independent functions (rank at n = 1, 2 exact)."""
    from paper_repro.printed.parsed import chain, relation_holds

    m = sentence("triangular trigonometric patch of order {n}", _LINE[line_id].verbatim, search=True)
    if not m:
        return False
    parts, ops = chain(m["n"])
    U = sympy.Symbol("n")

    alpha = rational_alpha(fmpq(1, 3))

    def has_patch(n: int) -> bool:
        if n < 1:
            return False
        if n <= 2:
            return rank(evaluate(n, alpha, sample_rational_points(alpha, delta(n), seed=60 + n), "exact").tolist()
                        ) == delta(n)
        return True  # n >= 3: the ranks of sec6-patch-index-sets and the linear independence claim

    return all(relation_holds([x.subs(U, n) for x in parts], ops) == has_patch(n) for n in range(0, 13))


def control_net_counts(n: int, printed: bool = True) -> dict:
    labels = printed_control_net(n) if printed else corrected_control_net(n)
    centre = f"r_{{{2 * n},{n},{n}}}"
    return {"size": len(labels), "delta_n": delta(n), "has_centre": centre in labels,
            "equals_basis": matches_basis(labels, n)}


@line_check("sec6-control-net-set")
def control_net_set(override: dict[str, str] | None = None) -> LineResult:
    """Printed net {r}_{j=0,i=j}^{n,2n-1-j} U {g}^{n-1,..} U {b}^{n-1,..} (def:surface_patch and def:rational_patch,
    each read from its transcription): at j = n the i-range n..n-1 is empty, so the centre is missing."""
    texts = {k: _LINE[k].verbatim for k in ("sec6-control-net-set", "sec6-rational-control-net-set")}
    texts.update(override or {})
    printed = {k: {n: net_from_transcription(n, tex) for n in NS} for k, tex in texts.items()}
    holds = all(matches_basis(net, n) for nets in printed.values() for n, net in nets.items())
    corrected = {n: control_net_counts(n, printed=False) for n in NS}
    # the correction: the printed set (as read) with the centre r_{2n,n,n} added
    corr = all(matches_basis(net + [f"r_{{{2 * n},{n},{n}}}"], n) for nets in printed.values()
               for n, net in nets.items())
    centre = {k: any(f"r_{{{2 * n},{n},{n}}}" in net for n, net in nets.items()) for k, nets in printed.items()}
    return LineResult(holds, corr, how="enumeration of the printed index sets (read from the transcriptions) vs the "
                      "labels of T_{2n}, n = 1..12", kind="exhaustive",
                      detail={"printed_sizes_n_1_2_3": {k: [len(nets[n]) for n in (1, 2, 3)]
                                                        for k, nets in printed.items()},
                              "delta_n_1_2_3": [delta(n) for n in (1, 2, 3)], "printed_has_centre": centre,
                              "corrected_sizes_n_1_2_3": [corrected[n]["size"] for n in (1, 2, 3)]})


@line_check("sec6-delta3")
def delta3(verbatim: str | None = None) -> LineResult:
    """delta_3 = 37 control points (order and count read from the transcription) against the terms of eq.
    triangular_trig_surface (read) and T_6."""
    tex = _LINE["sec6-delta3"].verbatim if verbatim is None else verbatim
    from paper_repro.printed.latex_math import inline_math, parse_relation

    found = []
    for seg in inline_math(tex):  # the count: a segment delta_{n}=count (read by the one reader)
        try:
            rel = parse_relation(seg)
        except ValueError:
            continue
        head = rel.parts[0]
        if rel.ops == ["="] and not rel.conditions and getattr(head.func, "__name__", "") == "delta" and \
                len(head.args) == 1 and head.args[0].is_Integer and rel.parts[1].is_Integer:
            found.append((int(head.args[0]), int(rel.parts[1])))
    if not found:
        return LineResult(False, how="the count read from the transcription", detail={"unread": tex[:60]})
    n, count = found[0]
    order = sentence(r"Fig.\ \ref{fig:third_order_patch} illustrates a {order:word} order triangular trigonometric "
                     "patch defined by {count} control points.", tex)
    said = ORDINALS.get(order["order"]) if order else None
    terms = len(patch_terms_read(n))
    words = order is not None
    return LineResult(said == n and words and
                      terms == count == delta(n) == len(united_system(n)),
                      how="count read from the transcription vs the terms of eq. triangular_trig_surface (read) and "
                      "T_{2n}; the order word ('third') vs the subscript of delta", kind="proof",
                      detail={"n": n, "order_word": said, "printed": count, "terms": terms,
                                                       "united_system": len(united_system(n))})


@line_check("sec6-quadratic-growth")
def quadratic_growth() -> LineResult:
    """"the quadratic growth of the control points" (read) vs the second differences of the number of terms of eq.
    triangular_trig_surface (read); "order higher than three" (read) is the order beyond which the convex hull
    property is open (the orders of sec6-convex-hull-n123, read there)."""
    tex = _LINE["sec6-quadratic-growth"].verbatim
    sizes = [len(patch_terms_read(n)) for n in NS_ROWS]
    second = {c - 2 * b + a for a, b, c in zip(sizes, sizes[1:], sizes[2:])}
    first = sizes[1] - sizes[0]
    m = sentence("considering the quadratic growth of the control points, it is very unlikely that in CAGD patches of "
                 "order higher than {k:count} would be used for modeling.", tex)
    beyond = m["k"] if m else None
    words = m is not None
    proven = max(convex_hull_orders(), default=None)
    return LineResult(words and beyond == proven and second == {6} and first > 0,
                      how="second differences of the number of control points, n = 1..8; the order named vs the "
                      "highest order with the convex hull property (sec6-convex-hull-n123)", kind="exact-evidence",
                      detail={"sizes": sizes[:4], "second_differences": sorted(second), "order_named": beyond})


# --- geometric properties ---------------------------------------------------------------------------------
def _points(alpha: RationalAngle, count: int, seed: int) -> RationalPoints:
    return sample_rational_points(alpha, count, seed=seed)


def read_open_interval(tex: str, var: str) -> tuple[sympy.Expr, sympy.Expr]:
    """``(lo, hi)`` of the clause ``var \\in \\left(lo,hi\\right)`` of ``tex`` (each ``$..$`` segment read by
    :func:`paper_repro.printed.latex_math.parse_conditions`; the reader's pair after ``\\in`` is the open
    interval); ``ValueError`` if there is none."""
    from paper_repro.printed.latex_math import parse
    from paper_repro.printed.parsed import clauses

    sym = parse(var)
    for c in clauses(tex):
        right = c.parts[-1]
        if c.ops == ["in"] and c.parts[0] == sym and isinstance(right, sympy.Tuple) and len(right) == 2 and \
                all(isinstance(x, sympy.Expr) for x in right):
            return right[0], right[1]
    raise ValueError(f"no open interval {var} in (lo, hi) in {tex[:50]!r}")


#: cos(alpha/2) of the sampled alphas (rational, so everything below is exact): alpha = 2 acos(c) from 0.57 to 5.7
ALPHA_HALF_COS = (fmpq(24, 25), fmpq(4, 5), fmpq(3, 5), fmpq(7, 25), fmpq(0), fmpq(-7, 25), fmpq(-3, 5),
                  fmpq(-4, 5), fmpq(-24, 25))


@line_check("sec6-alpha-range")
def alpha_range() -> LineResult:
    """The printed range of alpha (read from the transcription) is where the patch is defined: at every sampled alpha
    in it (cos(alpha/2) rational, alpha from 0.57 to 5.7) the univariate B-basis constants c_{2n,i} of the boundary
    curves are positive (n = 1, 2, 3) and, for alpha < pi, the exact normalized basis of order 2 sums to one with
    positive coefficients; a sampled alpha in the range where a constant is <= 0 makes the printed range fail."""
    import math

    lo, hi = read_open_interval(_LINE["sec6-alpha-range"].verbatim, "\\alpha")
    lo_f, hi_f = float(lo), float(hi)
    ok, tested = lo_f >= 0, []
    for c in ALPHA_HALF_COS:
        a = 2 * math.acos(float(c))
        if not lo_f < a < hi_f:
            continue
        tested.append(str(c))
        ok &= all(sum(k * c**p for p, k in enumerate(c_numerator(n, i))) > 0
                  for n in (1, 2, 3) for i in range(2 * n + 1))
        if c in ALPHA_HALF_SIN:  # alpha < pi: the normalized basis of order 2, tan(alpha/4) = sin / (1 + cos)
            alpha = rational_alpha(ALPHA_HALF_SIN[c] / (1 + c))
            vals = evaluate_normalized(2, alpha, _points(alpha, 3, seed=3), "exact")
            ok &= all(sum(vals[p].tolist(), fmpq(0)) == 1 for p in range(3))
            ok &= all(x > 0 for x in coefficient_vector(2, alpha, "exact"))
    return LineResult(ok and bool(tested), how="the printed interval read from the transcription; exact B-basis "
                      "constants c_{2n,i}, n = 1, 2, 3, and the exact normalized basis of order 2 (alpha < pi) at "
                      "the sampled alpha in it", kind="exact-evidence",
                      detail={"interval": [str(lo), str(hi)], "cos_alpha_half_tested": tested})


#: the rational sin(alpha/2) belonging to the sampled cos(alpha/2) (Pythagorean triples)
ALPHA_HALF_SIN = {fmpq(24, 25): fmpq(7, 25), fmpq(4, 5): fmpq(3, 5), fmpq(3, 5): fmpq(4, 5), fmpq(7, 25): fmpq(24, 25)}


def affine_invariance_holds(n: int, alpha: RationalAngle, A: Sequence[Sequence[fmpq]], b: Sequence[fmpq],
                            seed: int = 5) -> bool:
    """patch(A p_k + b) == A patch(p_k) + b at rational points (exact)."""
    net = random_net(n, 3, seed)
    moved = [[sum((A[r][c] * p[c] for c in range(3)), fmpq(0)) + b[r] for r in range(3)] for p in net]
    vals = evaluate_normalized(n, alpha, _points(alpha, 4, seed=seed), "exact")
    lhs = combine(vals, moved)
    rhs = [[sum((A[r][c] * q[c] for c in range(3)), fmpq(0)) + b[r] for r in range(3)] for q in combine(vals, net)]
    return lhs == rhs


AFFINE = ([[fmpq(2), fmpq(-1), fmpq(1, 3)], [fmpq(0), fmpq(5, 2), fmpq(1)], [fmpq(-3), fmpq(1), fmpq(1)]],
          [fmpq(7), fmpq(-2, 3), fmpq(11, 5)])


@line_check("sec6-affine-invariance")
def affine_invariance() -> LineResult:
    alpha = rational_alpha(fmpq(1, 3))
    ok = all(affine_invariance_holds(n, alpha, *AFFINE) for n in (1, 2, 3))
    unity = all(sum(row.tolist(), fmpq(0)) == 1
                for n in (1, 2, 3) for row in evaluate_normalized(n, alpha, _points(alpha, 3, seed=9), "exact"))
    words = has_words(_LINE["sec6-affine-invariance"].verbatim, "functions that form a partition of the unity",
                      "any patch of the type", "is invariant under the affine transformations of its control points")
    return LineResult(words and ok and unity, how="the claim's words read from the transcription; exact patch of a "
                      "random rational net and of its affine image at rational points, n = 1, 2, 3, tan(alpha/4) = 1/3",
                      kind="exact-evidence",
                      detail={"partition_of_unity": unity, "affine_image_commutes": ok})


def convex_hull_orders() -> list[int]:
    """The orders of "in the special cases of first, second and third order" (read from the transcription)."""
    tex = _LINE["sec6-convex-hull-n123"].verbatim
    m = sentence("in the special cases of {orders:words} order triangular", tex, search=True)
    if not m or " and " not in m["orders"]:
        return []
    words = m["orders"].replace(" and ", ", ").split(", ")
    return [ORDINALS[w] for w in words if w in ORDINALS] if all(w in ORDINALS for w in words) else []


@line_check("sec6-convex-hull-n123")
def convex_hull_n123() -> LineResult:
    """Non-negative normalized system for the orders read from the transcription (first, second, third): the
    functions are products of half-angle sines and cosines (>= 0 on Omega^alpha); so it is non-negative iff the
    normalizing coefficients are; exact at sampled alpha.  The words "convex hull of their control points" and
    "non-negative" are read."""
    tex = _LINE["sec6-convex-hull-n123"].verbatim
    orders = convex_hull_orders()
    words = has_words(tex, "their shape lies in the convex hull of their control points",
                      "normalized function system (\\ref{normalized_united_system}) is also non-negative")
    mins = {}
    for n in orders:
        for t in TS + (fmpq(9, 10),):
            vec = coefficient_vector(n, rational_alpha(t), "exact")
            mins[f"n={n},t={t}"] = min(vec)
    monomials_nonneg = all(min(exponents(lab)) >= 0 for n in orders for lab in united_system(n))
    ok = words and len(orders) == len(set(orders)) > 0 and monomials_nonneg and all(v > 0 for v in mins.values())
    return LineResult(ok, how="exact normalizing coefficients (collocation) for n = 1, 2, 3 at tan(alpha/4) in "
                      "{1/5, 1/3, 1/2, 3/4, 9/10}", kind="exact-evidence",
                      detail={"min_coefficient": {k: str(v) for k, v in mins.items()}})


# boundary curves ------------------------------------------------------------------------------------------
VARS = ("u", "v", "w")


def net_from_transcription(n: int, tex: str | None = None) -> list[str]:
    """The control points of def:surface_patch read from the transcription of its net (line sec6-control-net-set;
    that printed set lacks the centre, erratum sec6-control-net-set, which no boundary curve uses): the row is the
    union ``\\left\\{ \\mathbf{x}_{..}\\right\\}_{j=..,i=..}^{..,..}\\cup..`` that the next row continues after
    ``\\subset``, read by :func:`paper_repro.printed.latex_math.parse` (``cup`` of ``Family``), each set's members
    at n by :func:`paper_repro.printed.parsed.members`.  A row that is not such a union (a blanked line) names no
    point: ``[]``."""
    from paper_repro.printed import latex_math as LM
    from paper_repro.printed.parsed import members, point_label

    tex = (_LINE["sec6-control-net-set"].verbatim if tex is None else tex).rstrip()
    if not tex.endswith("\\subset"):
        return []
    try:
        union = LM.parse(tex[:-len("\\subset")])
    except LM.LatexMathError:
        return []
    sets, todo = [], [union]
    while todo:  # the union's sets, in the printed order
        e = todo.pop(0)
        if isinstance(e, sympy.Function) and e.func.__name__ == "cup":
            todo[:0] = list(e.args)
        else:
            sets.append(e)
    out = []
    for fam in sets:
        if not (isinstance(fam, sympy.Function) and fam.func == LM.Family
                and fam.args[0].func.__name__ in ("r_vec", "g_vec", "b_vec")):
            return []
        try:
            out += [point_label(p) for p in members(fam, n=n)]
        except (ValueError, TypeError):
            return []
    return out


def read_boundary(tex: str) -> tuple[int, int, str, sympy.Expr, sympy.Expr]:
    """(zero variable, argument variable of A, colour, lower and upper bound of i) of a printed boundary curve, read
    by :func:`paper_repro.printed.latex_math.parse_relation`: ``s_n(args) = sum_{i=lo}^{hi} x_{2n,2n-i,0}
    A_{2n,2n-i}(t), t in [0, alpha]`` with ``args`` the edge x_zero = 0 parametrized by t (``ValueError`` otherwise)."""
    from paper_repro.printed.latex_math import parse_relation
    from paper_repro.printed.parsed import ALPHA

    rel = parse_relation(tex.strip().rstrip(",").rstrip("\\").strip().rstrip(","))
    if rel.ops != ["="] or len(rel.conditions) != 1:
        raise ValueError(f"not a boundary curve: {tex[:60]!r}")
    lhs, rhs = rel.parts
    if type(lhs).__name__ != "s_vec" or len(lhs.args) != 2 or lhs.args[0] != N_SYM:
        raise ValueError(f"left-hand side {lhs} is not s_n(u, v, w)")
    args = list(lhs.args[1])
    if not isinstance(rhs, sympy.Sum) or len(rhs.limits) != 1:
        raise ValueError(f"right-hand side {rhs} is not one sum")
    i, lo, hi = rhs.limits[0]
    factors = {type(f).__name__: f for f in sympy.Mul.make_args(rhs.function)}
    points = [k for k in factors if k in _POINT_OF]
    if len(factors) != 2 or len(points) != 1 or "A" not in factors:
        raise ValueError(f"term {rhs.function} is not x_{{2n,2n-i,0}} A_{{2n,2n-i}}(t)")
    point, basis = factors[points[0]], factors["A"]
    if tuple(point.args) != (2 * N_SYM, 2 * N_SYM - i, 0) or tuple(basis.args[:2]) != (2 * N_SYM, 2 * N_SYM - i) \
            or len(basis.args) != 3 or len(basis.args[2]) != 1:
        raise ValueError(f"term {rhs.function}: indices are not (2n, 2n-i, 0) and (2n, 2n-i), one argument")
    t = basis.args[2][0]
    if len(args) != 3 or args.count(0) != 1 or str(t) not in VARS:
        raise ValueError(f"no single zero argument in s({args})")
    zero, arg = args.index(0), VARS.index(str(t))
    other = 3 - zero - arg
    # the edge of Omega^alpha: the argument t of A runs over [0, alpha], the third variable is alpha - t
    if zero == arg or args[arg] != t or sympy.expand(args[other] - (ALPHA - t)) != 0:
        raise ValueError(f"s({args}) is not the edge x_{zero} = 0 parametrized by {t}")
    cond = rel.conditions[0]
    if cond.ops != ["in"] or cond.parts != [t, sympy.Interval(0, ALPHA)]:
        raise ValueError(f"the curve's parameter range is {cond.parts}, not {t} in [0, alpha]")
    return zero, arg, _POINT_OF[points[0]].lower(), lo, hi


def edge_points(alpha: RationalAngle, zero: int, ts: Sequence[fmpq]) -> RationalPoints:
    """Points of the edge ``x_zero = 0`` with rational quarter tangents (w = 0 via tan((alpha - v)/4))."""
    if zero == 0:
        return RationalPoints(alpha, tuple(fmpq(0) for _ in ts), tuple(ts))
    if zero == 1:
        return RationalPoints(alpha, tuple(ts), tuple(fmpq(0) for _ in ts))
    return RationalPoints(alpha, tuple(tq(alpha.t, t) for t in ts), tuple(ts))


def boundary_holds(n: int, alpha: RationalAngle, zero: int, arg: int, names: Sequence[str], seed: int = 3) -> bool:
    """s on the edge x_zero = 0 equals sum_{i=0}^{2n} names[i] A_{2n,2n-i}(x_arg) (exact, a random rational net)."""
    ts = [fmpq(k, 7) * alpha.t for k in range(1, 6)]
    pts = edge_points(alpha, zero, ts)
    net = random_net(n, 2, seed)
    lhs = combine(evaluate_normalized(n, alpha, pts, "exact"), net)
    half = pts.half_angle_values()  # sin u/2, cos u/2, sin v/2, cos v/2, sin w/2, cos w/2
    idx = index_of(n)
    consts = [c_const(n, k, alpha, "exact") for k in range(2 * n + 1)]
    if len(names) != 2 * n + 1:
        return False
    for p in range(len(ts)):
        s_t = half[2 * arg][p]  # sin(t/2), t the argument of A
        other = 3 - zero - arg
        s_rest = half[2 * other][p]  # sin((alpha - t)/2) on this edge
        rhs = [fmpq(0), fmpq(0)]
        for i, name in enumerate(names):
            k = 2 * n - i
            a_val = consts[k] * s_rest ** (2 * n - k) * s_t**k
            point = net[idx[name]]
            rhs = [rhs[d] + a_val * point[d] for d in range(2)]
        if rhs != lhs[p]:
            return False
    return True


def corner_name(n: int, color: str, i: int, net: Sequence[str]) -> str | None:
    """The control point of ``net`` whose function is the printed color_{2n,2n-i,0} (exponent vectors from the
    printed explicit formulas, :func:`paper_repro.claims.lines.sec1_3.printed_exponents`)."""
    from paper_repro.claims.lines.sec1_3 import printed_exponents

    want = printed_exponents(color.upper(), n, i, 0)
    labs, idx = united_system(n), index_of(n)
    hits = [name for name in net if exponents(labs[idx[name]]) == want]
    return hits[0] if len(hits) == 1 else None


def boundary_curve(line_id: str, verbatim: str | None = None) -> LineResult:
    """A printed boundary curve s(..0..) = sum_{i=a}^{b} x_{2n,2n-i,0} A_{2n,2n-i}(t), read from its transcription:
    it holds as printed iff every control point it names is one of the net of def:surface_patch (read from its
    transcription) and the identity holds exactly; the corrected curve names, for a term whose point is not in the
    net, the net's point of the same function (the corner of the next colour)."""
    tex = _LINE[line_id].verbatim if verbatim is None else verbatim
    try:
        zero, arg, color, lo, hi = read_boundary(tex)
    except ValueError as exc:
        return LineResult(False, how="the printed boundary curve read from the transcription", kind="exact-evidence",
                          detail={"unread": str(exc)})
    printed_ok, corrected_ok, renamed = True, True, {}
    for n in (1, 2, 3):
        net = net_from_transcription(n)
        lo_n, hi_n = sympy.sympify(lo).subs(N_SYM, n), sympy.sympify(hi).subs(N_SYM, n)
        if not (lo_n.is_Integer and hi_n.is_Integer):
            return LineResult(False, how="the sum's bounds read", detail={"unread": f"{lo}, {hi}"})
        names = [f"{color}_{{{2 * n},{2 * n - i},0}}" for i in range(int(lo_n), int(hi_n) + 1)]
        fixed = [x if x in net else corner_name(n, color, 2 * n - int(x.split(",")[1]), net) for x in names]
        renamed.update({x: y for x, y in zip(names, fixed) if x != y})
        in_net = all(x in net for x in names)
        good_fixed = all(y is not None for y in fixed)
        for t in (TS[1], TS[3]):
            a = rational_alpha(t)
            printed_ok &= in_net and boundary_holds(n, a, zero, arg, names)
            corrected_ok &= good_fixed and boundary_holds(n, a, zero, arg, fixed)
    return LineResult(printed_ok, None if printed_ok else corrected_ok,
                      how="the curve read from the transcription (zero argument, colour, sum bounds, argument of A) "
                      "and the net from that of def:surface_patch; exact patch of a random rational net on the edge "
                      "vs the sum, 5 edge points, n = 1, 2, 3, tan(alpha/4) in {1/3, 3/4}", kind="exact-evidence",
                      detail={"edge": f"{VARS[zero]} = 0", "colour": color, "not_in_the_net": renamed})


@line_check("sec6-boundary-u0")
def boundary_u0() -> LineResult:
    return boundary_curve("sec6-boundary-u0")


@line_check("sec6-boundary-v0")
def boundary_v0() -> LineResult:
    return boundary_curve("sec6-boundary-v0")


@line_check("sec6-boundary-w0")
def boundary_w0() -> LineResult:
    return boundary_curve("sec6-boundary-w0")


CORNERS = {"r": (0,), "g": (2,), "b": (1,)}  # colour -> the variable equal to alpha at its corner


def corner_points(alpha: RationalAngle) -> dict[str, RationalPoints]:
    z, a = fmpq(0), alpha.t
    return {"(alpha,0,0)": RationalPoints(alpha, (a,), (z,)), "(0,alpha,0)": RationalPoints(alpha, (z,), (a,)),
            "(0,0,alpha)": RationalPoints(alpha, (z,), (z,))}


@line_check("sec6-corners")
def corners() -> LineResult:
    """At each corner of Omega^alpha the normalized basis is a unit vector; the three are r, g, b_{2n,2n,0}."""
    found: dict[str, str] = {}
    ok = True
    for n in (1, 2, 3):
        alpha = rational_alpha(TS[2])
        for name, pts in corner_points(alpha).items():
            row = evaluate_normalized(n, alpha, pts, "exact")[0].tolist()
            nz = [k for k, v in enumerate(row) if v != 0]
            ok &= len(nz) == 1 and row[nz[0]] == 1
            found[f"n={n} {name}"] = united_system(n)[nz[0]].control_point if nz else "none"
    tex = _LINE["sec6-corners"].verbatim
    from paper_repro.printed import latex_math as LM
    from paper_repro.printed.parsed import members, point_label

    words = has_words(tex, "interpolates the three corners", "of its control net")
    try:  # the three corners as printed: each $..$ segment one control point (the one reader)
        read = [LM.parse(seg) for seg in LM.inline_math(tex)]
        printed = {n: {point_label(members(p, n=n)[0]) for p in read} for n in (1, 2, 3)}
    except (LM.LatexMathError, ValueError, TypeError, AttributeError):
        read, printed = [], {n: set() for n in (1, 2, 3)}
    ok &= words and len(read) == 3  # three labels, nothing else in math mode
    ok &= all({v for k, v in found.items() if k.startswith(f"n={n} ")} == printed[n] for n in (1, 2, 3))
    return LineResult(ok, how="the corner labels read from the transcription vs the exact normalized basis at the "
                      "corners (a unit vector there), n = 1, 2, 3", kind="exact-evidence",
                      detail={"corner_points": found, "printed": [p.func.__name__[0] for p in read]})


def a_forms_rank(n: int, alpha: RationalAngle) -> int:
    """Rank of the A_{2n,i} as forms of degree 2n in x = sin(t/2), y = cos(t/2) (y = 1 dehomogenized):
    sin((alpha - t)/2) = sin(alpha/2) y - cos(alpha/2) x."""
    s, c = alpha.sin_half, alpha.cos_half
    rows = []
    for i in range(2 * n + 1):
        poly = fmpq_poly([s, -c]) ** (2 * n - i) * fmpq_poly([0, 1]) ** i
        coeffs = [poly.coeffs()[k] if k < len(poly.coeffs()) else fmpq(0) for k in range(2 * n + 1)]
        rows.append(coeffs)
    return rank(rows)


@line_check("sec6-trig-curves")
def trig_curves() -> LineResult:
    """F_{2n}^alpha = span{cos kt, sin kt}_{k<=n} is the space of degree-2n forms in sin(t/2), cos(t/2)
    (dimension 2n+1); the 2n+1 functions A_{2n,i} are such forms and independent, so the boundary curves
    (combinations of A_{2n,i}) reach every curve of F_{2n}^alpha."""
    words = has_words(_LINE["sec6-trig-curves"].verbatim, "its boundary curves can exactly describe arcs of any "
                      "trigonometric parametric curve the coordinate functions of which are in the vector space "
                      "(\\ref{truncated_Fourier_vector_space})")
    ranks = {f"n={n},t={t}": a_forms_rank(n, rational_alpha(t)) for n in range(1, 7) for t in TS}
    ok = words and all(v == 2 * int(k.split(",")[0][2:]) + 1 for k, v in ranks.items())
    return LineResult(ok, how="the claim's words read; exact rank of the coefficient matrix of A_{2n,i} as binary "
                      "forms, n = 1..6, "
                      "tan(alpha/4) in {1/5, 1/3, 1/2, 3/4}", kind="exact-evidence",
                      detail={"ranks_t_1_3": [ranks[f"n={n},t=1/3"] for n in range(1, 7)]})


def tangent_labels(n: int, corner_var: int) -> set[str]:
    """Functions whose gradient can be non-zero at the corner x_{corner_var} = alpha: the monomials with at
    most one factor sin(y/2), sin(z/2) of the two vanishing variables (others vanish to second order)."""
    others = [v for v in range(3) if v != corner_var]
    return {lab.control_point for lab in united_system(n)
            if sum(exponents(lab)[2 * v] for v in others) <= 1}


def terminal_edge_labels(n: int, corner: str) -> set[str]:
    """From the printed boundary lines: the corner and its neighbours on the two control polygons through it.

    v = 0: r_{2n,2n-i,0} A_{2n,2n-i}(u), corner u = alpha at i = 0; w = 0: b_{2n,2n-i,0} A_{2n,2n-i}(v), corner
    u = alpha (v = 0) at i = 2n; and cyclically.  Names are mapped to T_{2n} through the label aliases."""
    idx, labs = index_of(n), united_system(n)
    m = 2 * n
    ends = {"r": [("r", 0), ("r", 1), ("b", m), ("b", m - 1)],
            "g": [("g", 0), ("g", 1), ("r", m), ("r", m - 1)],
            "b": [("b", 0), ("b", 1), ("g", m), ("g", m - 1)]}[corner]
    return {labs[idx[f"{c}_{{{m},{m - i},0}}"]].control_point for c, i in ends}


@line_check("sec6-tangent-planes")
def tangent_planes() -> LineResult:
    """At each corner only the corner and its two polygon neighbours have non-zero gradient (monomial orders:
    a proof), and the 2x2 matrix of their exact directional derivatives is regular, so the tangent plane is
    spanned by the two terminal edges."""
    ok = True
    det = {}
    alpha = rational_alpha(TS[1])
    for n in (1, 2, 3):
        for corner, var in (("r", 0), ("g", 2), ("b", 1)):
            labels = tangent_labels(n, var)
            ok &= labels == terminal_edge_labels(n, corner)
            pts = corner_points(alpha)[{0: "(alpha,0,0)", 1: "(0,alpha,0)", 2: "(0,0,alpha)"}[var]]
            dirs = [d for d in ((1, -1, 0), (1, 0, -1), (0, 1, -1))]
            ders = [basis_derivative(n, alpha, pts, d, "exact")[0].tolist() for d in dirs]
            names = code_labels(n)
            nz = {names[k] for der in ders for k, v in enumerate(der) if v != 0}
            ok &= nz <= labels
            corner_name = f"{corner}_{{{2 * n},{2 * n},0}}"
            nb = sorted(labels - {corner_name})
            k1, k2 = names.index(nb[0]), names.index(nb[1])
            m = [[ders[0][k1], ders[0][k2]], [ders[1][k1], ders[1][k2]]]
            d = m[0][0] * m[1][1] - m[0][1] * m[1][0]
            ok &= d != 0
            det[f"n={n} {corner}"] = str(d)
    ok &= has_words(_LINE["sec6-tangent-planes"].verbatim, "The tangent planes at these corners are spanned by the "
                    "terminal edges of the control polygons that generate the boundary curves of the given patch.")
    return LineResult(ok, how="the claim's words read; exponents of the monomials at the corners, exact "
                      "derivatives of the normalized basis "
                      "there (n = 1, 2, 3, tan(alpha/4) = 1/3)", kind="exact-evidence",
                      detail={"neighbour_derivative_determinant": det})


@line_check("sec6-bezier-limit")
def bezier_limit() -> LineResult:
    """A_{2n,i}(alpha s) = P_i(cos(alpha/2)) (sin(alpha(1-s)/2)/sin(alpha/2))^{2n-i} (sin(alpha s/2)/sin(alpha/2))^i
    with P_i the printed numerator; as alpha -> 0 the ratios tend to 1-s and s, so the limit is P_i(1)
    (1-s)^{2n-i} s^i: the Bernstein polynomial iff P_i(1) = binom(2n, i)."""
    from paper_repro.printed.parsed import expression

    tex = _LINE["sec6-bezier-limit"].verbatim
    from paper_repro.printed import latex_math as LM

    words, segs = LM.prose(tex)  # the words, then the limit alpha -> 0 and the degree read by the one reader
    try:
        if ("when $$ the boundary curves degenerate to B\\'ezier curves of degree $$" not in words
                or "Proposition \\ref{Bernstein}" not in tex or len(segs) != 2):
            raise LM.LatexMathError("the words of the limit not read")
        lim = LM.parse_relation(segs[0])
        if (lim.ops != ["->"] or lim.parts[0] != sympy.Symbol("alpha") or not lim.parts[1].is_Integer
                or lim.conditions or lim.lead):
            raise LM.LatexMathError(f"not alpha -> an integer: {lim.parts} {lim.ops}")
        limit, degree = int(lim.parts[1]), expression(segs[1].replace("n", "u"))
    except LM.LatexMathError:
        return LineResult(False, how="the limit and the degree read from the transcription",
                          detail={"unread": tex[:60]})
    from paper_repro.printed.parsed import U

    # as alpha -> 0 cos(alpha/2) -> 1: the limit of A_{2n,i} is P_i(1) (1-s)^{2n-i} s^i, the Bernstein polynomial of
    # degree 2n iff P_i(1) = binom(2n, i); a limit alpha -> a > 0 leaves cos(alpha/2) != 1 (not polynomial)
    ok = limit == 0 and all(degree.subs(U, n) == 2 * n for n in range(1, 31))
    ok &= all(sum(c_numerator(n, i)) == comb(2 * n, i) for n in range(1, 31) for i in range(2 * n + 1))
    return LineResult(ok, how="the limit and the degree read from the transcription; printed numerator of c_{2n,i} "
                      "at cos(alpha/2) = 1 vs binom(2n, i), n = 1..30", kind="exact-evidence",
                      detail={"n": [1, 30], "limit": limit, "degree": str(degree)})


def vn_element(n: int, seed: int, extra: tuple[int, int, int] | None = None):
    rng = _rng(seed)
    terms = [(r, g, b, fmpq(int(rng.integers(-5, 6)), int(rng.integers(1, 4))),
              fmpq(int(rng.integers(-5, 6)), int(rng.integers(1, 4))))
             for r in range(n + 1) for g in range(n + 1) for b in range(n + 1)]
    if extra is not None:
        terms.append((*extra, fmpq(1), fmpq(0)))

    def surface(t: ExactTrig):
        return [sum((cc * t.cos(r, g, b) + ss * t.sin(r, g, b) for r, g, b, cc, ss in terms), fmpq(0))]

    return surface


def in_span(surface, n: int, alpha: RationalAngle) -> bool:
    try:
        fit_exact(surface, n, alpha)
    except ValueError:
        return False
    return True


@line_check("sec6-vn-configurations")
def vn_configurations() -> LineResult:
    """A random element of V_n^alpha (all cos, sin(ru+gv+bw), 0 <= r, g, b <= n) has an exact control net."""
    alpha = rational_alpha(TS[1])
    ok = all(in_span(vn_element(n, 40 + n), n, alpha) for n in (1, 2, 3))
    beyond = in_span(vn_element(2, 42, extra=(3, 0, 0)), 2, alpha)  # cos 3u is not in V_2
    ok &= has_words(_LINE["sec6-vn-configurations"].verbatim, "It provides $\\alpha$-dependent control point "
                    "configurations for the exact description of triangular patches of arbitrary trigonometric "
                    "surfaces the coordinate functions of which are given in the vector space "
                    "(\\ref{constrained_trivariate_extension_of_truncated_Fourier_series}) (consider Example "
                    "\\ref{exmp:torus}).")
    return LineResult(ok and not beyond, how="exact fit (collocation, verified at 4 further points) of a random "
                      "element of V_n, n = 1, 2, 3, tan(alpha/4) = 1/3; an element with cos 3u is not fitted by "
                      "order 2", kind="exact-evidence", detail={"n": [1, 2, 3], "order_2_fits_cos_3u": beyond})


# --- Example exmp:torus ------------------------------------------------------------------------------------
def exact_torus(rho: fmpq, mu: fmpq, phi=None, psi=None, upper: bool = False, alpha: RationalAngle | None = None):
    """t(U, V) (eq. toroidal_triangle) on a triangle: U = phi + u, V = psi + v, or (upper) U = phi + alpha - u,
    V = psi + alpha - v; phi, psi given as (cos, sin) pairs."""
    def cs(t: ExactTrig, var: int, ph, up: bool):
        c = t.cos(*[1 if k == var else 0 for k in range(3)])
        s = t.sin(*[1 if k == var else 0 for k in range(3)])
        if up:  # alpha - x
            ca, sa = trig_of(alpha.t)
            c, s = ca * c + sa * s, sa * c - ca * s
        if ph is not None:
            c, s = ph[0] * c - ph[1] * s, ph[1] * c + ph[0] * s
        return c, s

    def surface(t: ExactTrig):
        cu, su = cs(t, 0, phi, upper)
        cv, sv = cs(t, 1, psi, upper)
        return [(rho + mu * su) * cv, (rho + mu * su) * sv, mu * cu]

    return surface


class Angles:
    """Exact cos/sin of alpha, alpha/2 and 3alpha/2 for rational tan(alpha/4)."""

    def __init__(self, alpha: RationalAngle):
        self.sh, self.ch = alpha.sin_half, alpha.cos_half
        self.sa, self.ca = 2 * self.sh * self.ch, self.ch**2 - self.sh**2
        self.th = self.sh / self.ch
        self.s3h, self.c3h = 3 * self.sh - 4 * self.sh**3, 4 * self.ch**3 - 3 * self.ch


_FITS: dict[tuple, list[list[fmpq]]] = {}


def torus_net(t: fmpq, rho: fmpq, mu: fmpq) -> list[list[fmpq]]:
    """The exact control net of eq. toroidal_triangle (order 2) at tan(alpha/4) = t: interpolation in the normalized
    basis (:func:`~paper_repro.surfaces.fitting.fit_exact`), independent of the printed points."""
    key = (t, rho, mu)
    if key not in _FITS:
        _FITS[key] = fit_exact(exact_torus(rho, mu), 2, rational_alpha(t))
    return _FITS[key]


def printed_formula(xyz) -> Callable:
    """``f(Angles, varrho, mu) -> (x, y, z)`` of a printed point parsed from its transcription
    (:func:`paper_repro.printed.torus.read_point`), evaluated exactly."""
    from paper_repro.printed.torus import point_value

    return lambda A, r, m: tuple(point_value(e, A.ch, A.sh, r, m) for e in xyz)


def compare_point(label: str, formula=None) -> dict[str, int]:
    """Number of (alpha, varrho, mu) cases where each coordinate of ``formula`` (default: the printed point
    ``label`` parsed from its transcription) differs from the exact fit."""
    if formula is None:
        from paper_repro.printed.torus import printed_point

        read_label, xyz = printed_point(f"sec6-torus-point-{label}")
        if read_label != label:
            raise ValueError(f"line sec6-torus-point-{label} prints {read_label}")
        formula = printed_formula(xyz)
    k = index_of(2)[label]
    bad = {"x": 0, "y": 0, "z": 0}
    for t in TS_TORUS:
        A = Angles(rational_alpha(t))
        for rho, mu in RHO_MU:
            fitted = torus_net(t, rho, mu)[k]
            printed = [fmpq(x) if isinstance(x, int) else x for x in formula(A, rho, mu)]
            for d, ax in enumerate("xyz"):
                bad[ax] += printed[d] != fitted[d]
    return bad


def point_check(line_id: str) -> LineResult:
    """The printed control point of line ``line_id`` (label and three coordinates parsed from its transcription)
    against the exact fit of eq. toroidal_triangle at that label."""
    from paper_repro.printed.torus import printed_point

    label, xyz = printed_point(line_id)  # raises on anything unread (a blank line)
    if label not in code_labels(2):
        raise ValueError(f"{line_id}: {label} is no control point of order 2")
    bad = compare_point(label, formula=printed_formula(xyz))
    holds = not any(bad.values())
    corrected_ok = None
    if not holds and _LINE[line_id].status == "erratum":  # the erratum's fix applied to the transcription
        from paper_repro.printed.torus import read_point

        fixed = corrected_text(line_id)
        if fixed is None:
            corrected_ok = False
        else:
            fixed_label, fixed_xyz = read_point(fixed)
            corrected_ok = fixed_label == label and not any(compare_point(label, printed_formula(fixed_xyz)).values())
    return LineResult(holds, corrected_ok, how="the printed point parsed from its transcription (paper_repro.printed."
                      "torus) vs the exact fit of eq. toroidal_triangle in the order-2 normalized basis, exact at "
                      "tan(alpha/4) in {1/9, 1/5, 1/3, 2/5, 1/2, 3/5, 3/4, 7/8} and (varrho, mu) in {(1, 0), (0, 1), "
                      "(7/2, 5/3)} (the coordinates are linear in varrho, mu)", kind="exact-evidence",
                      detail={"label": label, "disagreeing_cases": bad, "cases": len(TS_TORUS) * len(RHO_MU)})


def _register_point_checks() -> None:
    from paper_repro.printed.torus import point_line_ids

    for lid in point_line_ids():
        line_check(lid)(lambda lid=lid: point_check(lid))


_register_point_checks()


def torus_quartic(x, y, z, rho, mu):
    """Implicit torus: (x^2 + y^2 + z^2 + varrho^2 - mu^2)^2 - 4 varrho^2 (x^2 + y^2)."""
    return (x * x + y * y + z * z + rho * rho - mu * mu) ** 2 - 4 * rho * rho * (x * x + y * y)


def torus_quartic_gradient(x, y, z, rho, mu):
    p = x * x + y * y + z * z + rho * rho - mu * mu
    return (4 * p * x - 8 * rho * rho * x, 4 * p * y - 8 * rho * rho * y, 4 * p * z)


def _surface_rows(tex: str, lhs_name: str | None) -> tuple:
    """A printed parametrized surface ``X = [x y z]^{T},~u\\in[..],~v\\in[..]`` read by
    :func:`paper_repro.printed.latex_math.parse_relation`: (left side or None, the three coordinates, the u and v
    intervals); ``ValueError`` if it is not one."""
    from paper_repro.printed.latex_math import parse_relation
    from paper_repro.printed.parsed import U, V, interval

    rel = parse_relation(tex)
    if lhs_name is None:
        if rel.ops:
            raise ValueError(f"a relation {rel.ops} where a column is printed")
        vec = rel.parts[0]
        lhs = None
    else:
        if rel.ops != ["="] or len(rel.parts) != 2:
            raise ValueError(f"relations {rel.ops}, not one '='")
        lhs, vec = rel.parts
        if getattr(lhs.func, "__name__", "") != lhs_name or lhs.args[-1] != sympy.Tuple(U, V):
            raise ValueError(f"the left side {lhs} is not {lhs_name}(.., (u, v))")
    if not isinstance(vec, sympy.MatrixBase) or vec.shape != (3, 1):
        raise ValueError(f"not a column of three coordinates: {vec}")
    if [c.parts[0] for c in rel.conditions] != [U, V]:
        raise ValueError(f"the clauses {rel.conditions} are not u in [..], v in [..]")
    return lhs, tuple(vec), interval(rel, "u"), interval(rel, "v")


def read_torus_parametrization() -> dict:
    """eq. toroidal_triangle read from its transcription: ``{"params": subscript symbols, "xyz": (x, y, z) in u, v,
    varrho, mu, "u": (lo, hi), "v": (lo, hi)}`` (sympy; ``ValueError`` if unread)."""
    lhs, xyz, u, v = _surface_rows(_LINE["sec6-torus-parametrization"].verbatim, "t_vec")
    return {"params": tuple(lhs.args[:-1]), "xyz": xyz, "u": u, "v": v}


def torus_parameters() -> set[str]:
    """The parameters of eq. toroidal_triangle (the subscript of t), read from its printed line, as LaTeX names."""
    try:
        return {"\\" + str(p) for p in read_torus_parametrization()["params"]}
    except ValueError:
        return set()


def parsed_torus_point(tu: fmpq, tv: fmpq, rho: fmpq, mu: fmpq) -> list[fmpq]:
    """The printed parametrization (read) at u = 4 atan(tu), v = 4 atan(tv), exactly."""

    return parsed_torus_at(*trig_of(tu), *trig_of(tv), rho, mu)


def parsed_torus_at(cu: fmpq, su: fmpq, cv: fmpq, sv: fmpq, rho: fmpq, mu: fmpq) -> list[fmpq]:
    """The printed parametrization (read) at (cos u, sin u) = (cu, su), (cos v, sin v) = (cv, sv), exactly."""
    from paper_repro.printed.parsed import MU, VARRHO, U, V, exact_value

    xyz = read_torus_parametrization()["xyz"]
    return [exact_value(e, {VARRHO: rho, MU: mu}, {U: (1, cu, su), V: (1, cv, sv)}, fmpq(0)) for e in xyz]


def _in_read_domain(dom: dict, u: fmpq, v: fmpq, alpha: fmpq) -> bool:
    from paper_repro.printed.parsed import ALPHA, U

    def val(e):
        e = sympy.sympify(e).subs({ALPHA: sympy.Rational(int(alpha.p), int(alpha.q)),
                                   U: sympy.Rational(int(u.p), int(u.q))})
        if not e.is_Rational:
            raise ValueError(f"domain bound {e} names an unknown symbol")
        return fmpq(int(e.p), int(e.q))

    return val(dom["u"][0]) <= u <= val(dom["u"][1]) and val(dom["v"][0]) <= v <= val(dom["v"][1])


@line_check("sec6-torus-parametrization")
def torus_parametrization() -> LineResult:
    """eq. toroidal_triangle read from its transcription: (1) its points are those of the package's torus model
    (:func:`paper_repro.surfaces.models.torus_xyz`, 40 digits) and lie on the implicit torus (exact); (2) the
    printed parameter set {u in [lo, hi], v in [lo(u), hi(u)]} is Omega^alpha with w = alpha - u - v: equal on a
    grid of (u, v) with alpha = 1 (the bounds are linear in alpha) inside Omega and just outside it."""
    import mpmath

    from paper_repro.surfaces.models import torus_xyz as model

    how = ("the parametrization and its parameter set read from the transcription; exact points (rational quarter "
           "tangents) on the implicit torus and equal to the package's torus model (40 digits); the parameter set vs "
           "Omega^alpha on a 11 x 11 grid")

    def items() -> dict[str, bool]:
        dom = read_torus_parametrization()
        rho, mu = fmpq(7, 2), fmpq(5, 3)
        on_torus, same = True, True
        with mpmath.workdps(40):
            for tu in (fmpq(0), fmpq(1, 4), fmpq(2, 3), fmpq(-3, 2)):
                for tv in (fmpq(1, 5), fmpq(3, 4), fmpq(-2, 7)):
                    p = parsed_torus_point(tu, tv, rho, mu)
                    on_torus &= torus_quartic(*p, rho, mu) == 0
                    want = model(4 * mpmath.atan(mpmath.mpf(int(tu.p)) / int(tu.q)),
                                 4 * mpmath.atan(mpmath.mpf(int(tv.p)) / int(tv.q)), mpmath.mpf(7) / 2,
                                 mpmath.mpf(5) / 3)
                    same &= all(abs(mpmath.mpf(int(x.p)) / int(x.q) - w) < mpmath.mpf(10) ** -30
                                for x, w in zip(p, want))
        one = fmpq(1)
        grid = [(fmpq(i, 8), fmpq(j, 8)) for i in range(-1, 10) for j in range(-1, 10)]
        domain = all(_in_read_domain(dom, u, v, one) == (u >= 0 and v >= 0 and one - u - v >= 0) for u, v in grid)
        return {"on_torus": bool(on_torus), "equals_model": bool(same), "parameter_set_is_omega": domain}

    return items_result(items, how, "exact-evidence", (ValueError,))


@line_check("sec6-torus-rho")
def torus_rho() -> LineResult:
    """"where $\\varrho>0$ is the distance from the origin to the center of the meridian circle" (read): on the
    printed parametrization (read) the meridian v = const is the circle of radius mu about (varrho cos v, varrho sin v,
    0), at distance varrho from the origin, in the plane through the z axis; and varrho > 0 is what the relation
    read says."""
    from paper_repro.printed.parsed import VARRHO, chain, relation_holds

    tex = _LINE["sec6-torus-rho"].verbatim
    m = sentence("where {rho} is the distance from the origin to the center of the meridian circle", tex)
    if not m:
        return LineResult(False, how="the line read from the transcription", detail={"unread": tex[:60]})
    parts, ops = chain(m["rho"])
    positive = (all(relation_holds([x.subs(VARRHO, r) for x in parts], ops) for r in (fmpq(1, 3), 1, 7))
                and not any(relation_holds([x.subs(VARRHO, r) for x in parts], ops) for r in (0, -1)))
    rho, mu = fmpq(7, 2), fmpq(5, 3)
    ok = True
    for tv in (fmpq(1, 5), fmpq(2, 3), fmpq(-3, 7)):
        cv, sv = trig_of(tv)
        centre = (rho * cv, rho * sv, fmpq(0))
        ok &= sum((c * c for c in centre), fmpq(0)) == rho * rho
        for tu in (fmpq(0), fmpq(1, 4), fmpq(3, 2), fmpq(-5, 2)):
            p = parsed_torus_point(tu, tv, rho, mu)
            ok &= sum(((p[k] - centre[k]) ** 2 for k in range(3)), fmpq(0)) == mu * mu
            ok &= p[0] * sv - p[1] * cv == 0  # in the meridian plane
    return LineResult(ok and positive, how="the relation read from the transcription; exact points of three meridians "
                      "of the printed parametrization", kind="exact-evidence", detail={"meridians": 3,
                                                                                        "varrho_positive": positive})


def horn_torus_singular(rho: fmpq) -> bool:
    """At mu = varrho the meridian u = 3pi/2 hits the axis: t = 0 for every v and the quartic is singular there."""
    pts = {tuple(parsed_torus_at(fmpq(0), fmpq(-1), *trig_of(tv), rho, rho))
           for tv in (fmpq(1, 3), fmpq(2), fmpq(-1, 5))}
    return pts == {(0, 0, 0)} and torus_quartic(0, 0, 0, rho, rho) == 0 and \
        set(torus_quartic_gradient(fmpq(0), fmpq(0), fmpq(0), rho, rho)) == {0}


def ring_torus_regular(rho: fmpq, mu: fmpq) -> bool:
    """0 < mu < varrho: distance to the axis varrho + mu sin u >= varrho - mu > 0 and the origin is off the torus."""
    return 0 < mu < rho and torus_quartic(0, 0, 0, rho, mu) > 0 and rho - mu > 0


def mu_range_is_ring(tex: str | None) -> bool:
    """The range of mu in ``tex`` (the words 'of radius' and one ``$..$`` segment ``\\mu\\in`` an interval, read by
    :func:`~paper_repro.printed.latex_math.parse_relation`: brackets and end points; each symbol must be a parameter
    of eq. toroidal_triangle) is exactly the set of mu giving a ring torus, tested at mu = k/10 varrho, k = 0..14."""
    from paper_repro.printed.latex_math import parse_relation, prose
    from paper_repro.printed.parsed import MU, VARRHO

    words, segs = prose(tex or "")
    if words != "of radius $$" or len(segs) != 1:
        return False
    rel = parse_relation(segs[0])
    right = rel.parts[-1]
    if isinstance(right, sympy.Tuple) and len(right) == 2:  # the reader's pair (a, b): after \in the open interval
        right = sympy.Interval.open(*right)
    if rel.ops != ["in"] or rel.conditions or rel.lead or rel.parts[0] != MU or not isinstance(right, sympy.Interval):
        return False
    lo, hi, left_open, right_open = right.args
    params = {str(p) for p in read_torus_parametrization()["params"]}
    if not {str(s) for s in lo.free_symbols | hi.free_symbols} <= params:
        return False
    rho = fmpq(7, 2)

    def num(e):
        e = e.subs(VARRHO, sympy.Rational(7, 2))
        if not e.is_Rational:
            raise ValueError(f"range end {e} is not a number")
        return fmpq(int(e.p), int(e.q))

    a, b = num(lo), num(hi)
    for k in range(15):
        mu = rho * fmpq(k, 10)
        inside = (a < mu if left_open else a <= mu) and (mu < b if right_open else mu <= b)
        if inside != ring_torus_regular(rho, mu):
            return False
    return True


@line_check("sec6-torus-mu-range")
def torus_mu_range() -> LineResult:
    """"of radius $\\mu\\in\\left(0,\\rho\\right]$" (read) against the ring tori of eq. toroidal_triangle (read):
    \\rho is no parameter of it, and the closed end mu = varrho is the horn torus (singular point, exact); the
    erratum's fix (\\varrho, open) applied to the transcription gives exactly the ring tori."""
    line = _LINE["sec6-torus-mu-range"].verbatim
    printed_holds = mu_range_is_ring(line)
    corrected = mu_range_is_ring(corrected_text("sec6-torus-mu-range"))
    return LineResult(printed_holds, corrected, how="the range read from the transcription (and with the erratum's fix)"
                      " vs ring tori of the printed parametrization at mu = k/10 varrho, k = 0..14; exact horn-torus "
                      "singularity at mu = varrho", kind="exact-evidence",
                      detail={"parametrization_symbols": sorted(torus_parameters()),
                              "mu_equal_varrho_singular": horn_torus_singular(fmpq(7, 2))})


def torus_order_word() -> int | None:
    m = sentence(r"The toroidal triangle (\ref{toroidal_triangle}) can exactly be described by a {n:word} order "
                 "triangular trigonometric patch defined by control points", _LINE["sec6-torus-order2"].verbatim)
    return ORDINALS.get(m["n"]) if m else None


@line_check("sec6-torus-order2")
def torus_order2() -> LineResult:
    """The order read from the transcription ("second") describes the torus exactly: exact fits in that order (verified
    at further points) at four alpha; the order below it does not contain the torus."""
    n = torus_order_word()
    if n is None:
        return LineResult(False, how="the order read from the transcription", detail={"unread": True})
    ok = all(in_span(exact_torus(rho, mu), n, rational_alpha(t)) for t in TS for rho, mu in RHO_MU[2:])
    lower = n > 1 and in_span(exact_torus(fmpq(7, 2), fmpq(5, 3)), n - 1, rational_alpha(TS[1]))
    return LineResult(ok, how="the order read from the transcription; exact fit of the torus in that order's basis "
                      "(verified at further points), tan(alpha/4) in {1/5, 1/3, 1/2, 3/4}", kind="exact-evidence",
                      detail={"order": n, "fits": ok, "order_below_fits": lower})


def reversed_edge_net(net, n: int, color: str) -> list:
    idx = index_of(n)
    return [net[idx[f"{color}_{{{2 * n},{k},0}}"]] for k in range(2 * n, -1, -1)]


def edge_net(net, n: int, color: str) -> list:
    return list(reversed(reversed_edge_net(net, n, color)))


def _values_and_derivatives(net, n: int, alpha: RationalAngle, pts: RationalPoints, dirs, rational: bool):
    """Exact point and directional derivatives (one per direction) of a patch at each point; ``rational``: the net
    is homogeneous (last coordinate the weight) and the point is X/W."""
    vals = evaluate_normalized(n, alpha, pts, "exact")
    ders = [basis_derivative(n, alpha, pts, d, "exact") for d in dirs]
    out = []
    for p in range(len(pts)):
        h = combine(vals[p:p + 1], net)[0]
        dh = [combine(der[p:p + 1], net)[0] for der in ders]
        if rational:
            w, x = h[-1], h[:-1]
            out.append(([c / w for c in x], [[(dd[k] * w - x[k] * dd[-1]) / (w * w) for k in range(len(x))]
                                             for dd in dh]))
        else:
            out.append((h, dh))
    return out


def c1_across(a: tuple, b: tuple, n: int, alpha: RationalAngle, rational: bool = False) -> bool:
    """Two patches ``(net, points, directions)`` agree at the points of their shared edge together with their first
    derivatives along the directions (the same global directions d/dU, d/dV written in each patch's (u, v, w)):
    C0 and C1 in the common parametrization (U, V), hence G1 (exact)."""
    return _values_and_derivatives(a[0], n, alpha, a[1], a[2], rational) == \
        _values_and_derivatives(b[0], n, alpha, b[1], b[2], rational)


def torus_continuity(n: int, alpha: RationalAngle, lower, upper, nxt) -> dict[str, bool]:
    """C1 (in the phase parametrization (U, V)) across the diagonal of a square (lower w = 0 edge = upper w = 0 edge)
    and across the edge U = alpha (upper u = 0 edge = the next square's lower u = 0 edge), at 3 points each."""
    a = alpha.t
    ss = (a / 5, a / 2, a * fmpq(4, 5))
    down, up = ((1, 0, -1), (0, 1, -1)), ((-1, 0, 1), (0, -1, 1))
    diag = c1_across((lower, RationalPoints(alpha, ss, tuple(tq(a, s) for s in ss)), down),
                     (upper, RationalPoints(alpha, tuple(tq(a, s) for s in ss), ss), up), n, alpha)
    side = c1_across((upper, RationalPoints(alpha, (fmpq(0),) * 3, ss), up),
                     (nxt, RationalPoints(alpha, (fmpq(0),) * 3, tuple(tq(a, s) for s in ss)), down), n, alpha)
    return {"diagonal_C1": diag, "square_edge_C1": side}


@line_check("sec6-torus-joined")
def torus_joined() -> LineResult:
    """"several triangular trigonometric patches of order $2$ that are smoothly joined in order to form a part of a
    ring torus" (order read from the transcription): neighbouring toroidal triangles, each fitted exactly in that
    order (so each reproduces the smooth torus), share their boundary control polygons: the diagonal of a square
    (w = 0 edges, reversed) and the edge U = alpha between the upper triangle of one square and the lower triangle of
    the next (u = 0 edges, reversed)."""
    tex = _LINE["sec6-torus-joined"].verbatim
    from paper_repro.printed import latex_math as LM

    words, segs = LM.prose(tex)  # the words; the order, the one $..$ segment, read by the one reader
    try:
        order = LM.parse(segs[0]) if len(segs) == 1 else None
    except LM.LatexMathError:
        order = None
    if (words != "Fig.\\ \\ref{fig:torus} illustrates several triangular trigonometric patches of order $$ that are "
            "smoothly joined in order to form a part of a ring torus." or order is None or not order.is_Integer
            or order < 1):
        return LineResult(False, how="the line read from the transcription", detail={"unread": tex[:60]})
    n = int(order)
    t = TS[1]
    alpha = rational_alpha(t)
    rho, mu = fmpq(7, 2), fmpq(5, 3)
    ph = trig_of(t)  # phase alpha
    try:
        lower = fit_exact(exact_torus(rho, mu), n, alpha)
        upper = fit_exact(exact_torus(rho, mu, upper=True, alpha=alpha), n, alpha)
        nxt = fit_exact(exact_torus(rho, mu, phi=ph), n, alpha)
    except ValueError:
        return LineResult(False, how=f"exact fits of order {n}", detail={"order": n, "fits": False})
    diag = edge_net(lower, n, "b") == reversed_edge_net(upper, n, "b")
    side = edge_net(upper, n, "g") == reversed_edge_net(nxt, n, "g")
    ring = ring_torus_regular(rho, mu)
    smooth = torus_continuity(n, alpha, lower, upper, nxt)
    return LineResult(diag and side and ring and all(smooth.values()), how="the order read from the transcription; "
                      "exact fits of three neighbouring triangles in that order, tan(alpha/4) = 1/3, varrho = 7/2 > mu "
                      "= 5/3 (ring): shared boundary control polygons (C0) and equal first derivatives in the phase "
                      "parametrization (U, V) at 3 points of each shared edge (C1, hence G1)", kind="exact-evidence",
                      detail={"order": n, "diagonal_join": diag, "square_edge_join": side, **smooth,
                              "continuity": "C1 in (U, V), G1" if all(smooth.values()) else "not C1"})


def torus_settings_ring(tex: str | None) -> bool:
    """The caption's settings (parsed, in order) name parameters of eq. toroidal_triangle (read) or alpha, and give a
    ring torus (mu > 0, varrho > mu: exact for the algebraic number) with alpha in the range of sec6-alpha-range
    (read)."""
    from paper_repro.printed.parsed import ALPHA, MU, VARRHO, chain

    m = sentence("with settings {a}, {b} and {c}.", tex or "")
    if not m:
        return False
    params = set(read_torus_parametrization()["params"]) | {ALPHA}
    values: dict = {}
    for part in (m["a"], m["b"], m["c"]):
        (lhs, rhs), ops = chain(part)
        if ops != ["="] or lhs not in params or lhs in values:
            return False
        values[lhs] = sympy.nsimplify(rhs.subs(values))
    if set(values) != {MU, VARRHO, ALPHA} or any(v.free_symbols for v in values.values()):
        return False
    lo, hi = read_open_interval(_LINE["sec6-alpha-range"].verbatim, "\\alpha")
    return bool(values[MU] > 0 and values[VARRHO] > values[MU] and lo < values[ALPHA] < hi)


@line_check("sec6-fig-torus-settings")
def fig_torus_settings() -> LineResult:
    """Caption of Fig. torus: "settings $\\mu=3$, $\\rho = \\frac{1+\\sqrt{5}}{2}\\mu$ and
    $\\alpha=\\frac{\\pi}{2}$" (parsed): \\rho is no parameter of eq. toroidal_triangle; with the erratum's fix
    (\\varrho) the settings give a ring torus (varrho/mu = golden ratio > 1) and alpha in (0, pi)."""
    printed = torus_settings_ring(_LINE["sec6-fig-torus-settings"].verbatim)
    corrected = torus_settings_ring(corrected_text("sec6-fig-torus-settings"))
    return LineResult(printed, corrected, how="the settings parsed from the transcription (and with the erratum's "
                      "fix) vs the parameters of eq. toroidal_triangle (read), ring condition exact",
                      kind="exact-evidence", detail={"parametrization_symbols": sorted(torus_parameters())})


# --- Section 6.2: rational patches ---------------------------------------------------------------------------
@line_check("sec6-weights-set")
def weights_set(verbatim: str | None = None) -> LineResult:
    """The weights rho_{2n,n,n} and the three printed sets of weights (the list read by
    :func:`paper_repro.printed.latex_math.parse_list`: a weight and bounded sets, each set over (j, i) enumerated by
    :func:`~paper_repro.printed.parsed.members`) name each function of T_{2n} once, n = 1..12."""
    from paper_repro.printed.latex_math import Family, parse_list
    from paper_repro.printed.parsed import members

    tex = _LINE["sec6-weights-set"].verbatim if verbatim is None else verbatim
    try:
        items = parse_list(tex)
        for item in items:
            if isinstance(item, sympy.core.function.AppliedUndef) and item.func == Family:
                if [str(b[0]) for b in item.args[2]] != ["j", "i"]:
                    raise ValueError(f"index set over {[str(b[0]) for b in item.args[2]]}")
                item = item.args[0]
            if type(item).__name__ not in _WEIGHT_OF or len(item.args) != 3:
                raise ValueError(f"not a weight: {item}")
    except ValueError as exc:
        return LineResult(False, how="the weights read from the transcription", detail={"unread": str(exc)[:80]})

    def names(n: int) -> list[str]:
        return [f"{_WEIGHT_OF[type(w).__name__].lower()}_{{{','.join(str(a) for a in w.args)}}}"
                for item in items for w in members(item, n=n)]

    got = {n: names(n) for n in NS}
    ok = all(matches_basis(v, n) for n, v in got.items())
    return LineResult(ok, how="the printed weights read from the transcription (printed.latex_math) vs T_{2n}, "
                      "n = 1..12", kind="exhaustive", detail={"sizes_n_1_2_3": [len(got[n]) for n in (1, 2, 3)]})


def tau_values(n: int, alpha: RationalAngle, weights: Sequence[fmpq], pts: RationalPoints) -> list[fmpq]:
    vals = evaluate_normalized(n, alpha, pts, "exact")
    return [sum((weights[k] * vals[p, k] for k in range(delta(n))), fmpq(0)) for p in range(len(pts))]


def rank1_counterexample(n: int = 2) -> dict:
    """Non-negative weights with non-zero sum: rho_{2n,n,n} = rho_{2n,2n,0} = 1, the others 0."""
    alpha = rational_alpha(TS[1])
    idx = index_of(n)
    w = [fmpq(0)] * delta(n)
    w[idx[f"r_{{{2 * n},{n},{n}}}"]] = fmpq(1)
    w[idx[f"r_{{{2 * n},{2 * n},0}}"]] = fmpq(1)
    edge = RationalPoints(alpha, (fmpq(0),) * 3, tuple(alpha.t * fmpq(k, 4) for k in (1, 2, 3)))
    return {"sum": sum(w, fmpq(0)), "min_weight": min(w), "tau_on_edge_u0": tau_values(n, alpha, w, edge)}


def _rank1_relation(tex: str):
    from paper_repro.printed.latex_math import parse_relation

    rel = parse_relation(tex.strip().rstrip(",."))
    if rel.conditions or len(rel.ops) != 1:
        raise ValueError(f"not one relation: {rel.ops}")
    return rel


def rank1_sum(tex: str):
    """The printed sum of the weights (left-hand side of the relation, read by printed.latex_math)."""
    return _rank1_relation(tex).parts[0]


def rank1_relation(tex: str):
    """The relation that closes the printed sum of weights (``\\neq0``, read by printed.latex_math): a test
    ``f(sum) -> bool`` (``None`` if unread)."""
    from paper_repro.printed.parsed import relation_holds

    try:
        rel = _rank1_relation(tex)
    except ValueError:
        return None
    if rel.parts[1].free_symbols:
        return None
    return lambda total: relation_holds([sympy.Rational(int(total.p), int(total.q)), rel.parts[1]], rel.ops)


@line_check("sec6-weights-rank1")
def weights_rank1(override: dict[str, str] | None = None) -> LineResult:
    """The sum's index sets and its relation (``\\neq0``) are read from the transcription.  Printed: non-negative
    weights whose sum satisfies the relation define q on Omega^alpha -- false: rho_{2n,n,n} = rho_{2n,2n,0} = 1
    (sum 2) lets tau vanish on the edge u = 0.  Corrected: positive weights (then tau >= min weight > 0, exact at
    sampled points) -- and every sum of positive weights (2, 1, 1/2) satisfies the relation read."""
    tex = (override or {}).get("sec6-weights-rank1", _LINE["sec6-weights-rank1"].verbatim)
    relation = rank1_relation(tex)
    if relation is None:
        return LineResult(False, how="the relation read from the transcription", detail={"unread": tex[-30:]})
    try:
        total = rank1_sum(tex)
        sets_ok = all(matches_basis(row_labels(total, n, "weights"), n) for n in NS_ROWS)
    except ValueError:
        sets_ok = False
    ce = rank1_counterexample()
    vanishes = relation(ce["sum"]) and ce["min_weight"] >= 0 and any(v == 0 for v in ce["tau_on_edge_u0"])
    printed_holds = sets_ok and not vanishes
    positive = all(relation(total) for total in (fmpq(2), fmpq(1), fmpq(1, 2)))
    for n in (1, 2, 3):
        alpha = rational_alpha(TS[1])
        rng = _rng(70 + n)
        w = [fmpq(int(rng.integers(1, 9)), int(rng.integers(1, 4))) for _ in range(delta(n))]
        pts = sample_rational_points(alpha, 4, seed=n)
        corner = list(corner_points(alpha).values())
        vals = tau_values(n, alpha, w, pts) + [tau_values(n, alpha, w, c)[0] for c in corner]
        positive &= all(v >= min(w) for v in vals)
    return LineResult(printed_holds, sets_ok and positive,
                      how="the sum and its relation read; exact tau for weights rho_{4,2,2} = rho_{4,4,0} = 1 (others "
                      "0) on the edge u = 0; random positive weights, n = 1, 2, 3 (tau >= min weight at interior "
                      "points and corners)", kind="exact-evidence",
                      detail={"weight_sum": str(ce["sum"]), "tau_on_edge_u0": [str(v) for v in ce["tau_on_edge_u0"]]})


def rational_eval(n: int, alpha: RationalAngle, net, weights, pts: RationalPoints) -> list[list[fmpq]]:
    """q = sum_k w_k p_k B_k / sum_k w_k B_k (eq. rational_patch, tau)."""
    vals = evaluate_normalized(n, alpha, pts, "exact")
    out = []
    for p in range(len(pts)):
        tau = sum((weights[k] * vals[p, k] for k in range(delta(n))), fmpq(0))
        out.append([sum((weights[k] * net[k][d] * vals[p, k] for k in range(delta(n))), fmpq(0)) / tau
                    for d in range(len(net[0]))])
    return out


@line_check("sec6-rational-patch")
def rational_patch(override: dict[str, str] | None = None) -> LineResult:
    """The terms of eq. rational_patch (weight, control point and function of each, its three rows read by
    printed.latex_math, sums written out, n = 1..8) are the delta_n functions of T_{2n}, each divided by
    tau-bar_n^alpha(u,v,w) (subscript and arguments read); with equal weights the rational patch is the polynomial
    patch (exact); the order range read from "of order $n\\geq1$" is the orders with a patch."""
    rows = ("sec6-rational-row-1", "sec6-rational-row-2", "sec6-rational-row-3")

    def items() -> dict[str, bool]:
        # each row's terms (weight, point, function over tau-bar_n(u,v,w)) name T_{2n}: the quotients read
        quotients = all(matches_basis(rows_labels(rows, n, "rational", override,
                                                  lhs=sympy.Function("q_vec")(N_SYM, UVW)), n) for n in NS_ROWS)
        order_ok = order_range_ok("sec6-rational-order")
        alpha = rational_alpha(TS[2])
        same = True
        for n in (1, 2):
            net = random_net(n, 3, 11 + n)
            pts = sample_rational_points(alpha, 3, seed=n)
            poly = combine(evaluate_normalized(n, alpha, pts, "exact"), net)
            same &= rational_eval(n, alpha, net, [fmpq(5, 2)] * delta(n), pts) == poly
        return {"quotients_read": quotients, "order_range_read": order_ok,
                "equal_weights_give_polynomial_patch": bool(same)}

    return items_result(items, "the rows read, n = 1..8; the denominators tau-bar_n^alpha(u,v,w) read; exact "
                        "evaluation with equal weights, n = 1, 2", "exact-evidence", (ValueError,))


_TAU_ROWS = ("sec6-tau-row-1", "sec6-tau-row-2")


def _tau_sets(texts: dict[str, str], strict_row_2: bool) -> bool:
    """The two rows of tau-bar (read by printed.latex_math) name T_{2n} once each, n = 1..8 (row 1 always with the
    arguments (u,v,w); row 2 with them only if ``strict_row_2``)."""
    lhs = sympy.Function("taubar")(N_SYM, UVW)
    rows = parse_rows(_TAU_ROWS, texts)
    if rows[0][0] != lhs or rows[1][0] is not None:
        raise ValueError(f"left-hand sides {rows[0][0]}, {rows[1][0]}")
    return all(matches_basis(row_labels(rows[0][1], n, "tau") +
                             row_labels(rows[1][1], n, "tau", strict_arguments=strict_row_2), n) for n in NS_ROWS)


def _tau_unit() -> bool:
    alpha = rational_alpha(TS[0])
    return all(v == 1 for n in (1, 2, 3)
               for v in tau_values(n, alpha, [fmpq(1)] * delta(n), sample_rational_points(alpha, 3, seed=n)))


@line_check("sec6-tau-index-sets")
def tau_index_sets(override: dict[str, str] | None = None) -> LineResult:
    """tau's sums over l = 0..n-1, k = l..2n-1-l (read from the transcriptions of its rows) name T_{2n}; row 1 writes
    tau-bar_n^alpha(u,v,w) and each of its functions with the arguments (u,v,w); with unit weights tau = 1 (exact)."""
    texts = {k: (override or {}).get(k, _LINE[k].verbatim) for k in _TAU_ROWS}
    how = ("the rows read by printed.latex_math, sums written out vs T_{2n}, n = 1..8 (row 1: every function of "
           "(u,v,w)); exact tau with unit weights, n = 1, 2, 3")
    return items_result(lambda: {"rows_name_T_2n": _tau_sets(texts, strict_row_2=False),
                                 "unit_weights_tau_is_1": _tau_unit()}, how, "exact-evidence", (ValueError,))


@line_check("sec6-tau-row-2")
def tau_row_2() -> LineResult:
    """Row 2 of tau-bar (read): its index sets with row 1 name T_{2n} (n = 1..12), but its G-bar term has no
    arguments (u,v,w) while every other function of tau-bar and of eq. rational_patch has them; the erratum's fix
    (the arguments added) applied to the transcription gives a row whose every function has them."""
    texts = {k: _LINE[k].verbatim for k in _TAU_ROWS}
    try:
        sets = _tau_sets(texts, strict_row_2=False)
    except ValueError as exc:
        return LineResult(False, how="the rows read from the transcriptions", detail={"unread": str(exc)})
    try:
        printed = _tau_sets(texts, strict_row_2=True)
    except ValueError:
        printed = False
    corrected = None
    if not printed:
        fixed = corrected_text("sec6-tau-row-2")
        try:
            corrected = fixed is not None and sets and _tau_sets({**texts, "sec6-tau-row-2": fixed}, True) and \
                _tau_unit()
        except ValueError:
            corrected = False
    return LineResult(sets and printed, corrected, how="the rows read by printed.latex_math (and row 2 with the "
                      "erratum's fix): index sets vs T_{2n}, n = 1..8, and the arguments (u,v,w) of every function",
                      kind="exact-evidence", detail={"index_sets": sets})


def quotient_matrix(n: int, alpha: RationalAngle, weights, pts: RationalPoints) -> list[list[fmpq]]:
    vals = evaluate_normalized(n, alpha, pts, "exact")
    rows = []
    for p in range(len(pts)):
        tau = sum((weights[k] * vals[p, k] for k in range(delta(n))), fmpq(0))
        rows.append([weights[k] * vals[p, k] / tau for k in range(delta(n))])
    return rows


def quotient_properties(n: int, weights: Sequence[fmpq], seed: int) -> tuple[bool, bool]:
    """(normalized, linearly independent) of the quotients w_k X_k / tau at delta_n rational points (exact)."""
    alpha = rational_alpha(TS[1])
    rows = quotient_matrix(n, alpha, weights, sample_rational_points(alpha, delta(n), seed=seed))
    return all(sum(r, fmpq(0)) == 1 for r in rows), rank(rows) == delta(n)


@line_check("sec6-q-normalized-independent")
def q_normalized_independent() -> LineResult:
    """"Q-bar_{2n}^alpha is also normalized and linearly independent" (the properties read from the transcription) for
    the weights of Section 6.2 (non-negative, non-zero sum): a zero weight makes its quotient the zero function, so
    the system is dependent (exact rank); with positive weights (the correction) it is normalized and independent
    (exact, n = 1, 2, 3)."""
    tex = _LINE["sec6-q-normalized-independent"].verbatim
    from paper_repro.printed import latex_math as LM

    segs = LM.prose(tex)[1]  # the words are read by the sentence below; the four $..$ segments by the one reader
    m = sentence(r"Quotient functions in (\ref{rational_patch}) determine the constrained trivariate rational "
                 "trigonometric function system {q} of order {n} that inherits advantageous properties of {t}, i.e., "
                 "{q2} is also {normalized:words} and linearly {independent:word}.", tex)
    if m and (m["normalized"] not in ("normalized", "not normalized") or
              m["independent"] not in ("independent", "dependent")):
        m = None
    try:
        q, order, t, q_again = [LM.parse(seg) for seg in segs] if len(segs) == 4 else [None] * 4
        named = (q == q_again == sympy.Function("Qbar")(2 * order) and t == sympy.Function("Tbar")(2 * order)
                 and order == sympy.Symbol("n") and not any(LM.untagged(segs[k]) for k in (0, 2, 3)))
    except (LM.LatexMathError, TypeError):
        named = False
    if not m or not named:
        return LineResult(False, how="the properties read from the transcription", detail={"unread": tex[-60:]})
    want = (m["normalized"] == "normalized", m["independent"] == "independent")
    printed, corrected, ranks = True, True, {}
    for n in (1, 2, 3):
        rng = _rng(80 + n)
        w = [fmpq(int(rng.integers(1, 9)), int(rng.integers(1, 4))) for _ in range(delta(n))]
        zero = list(w)
        zero[index_of(n)[f"r_{{{2 * n},{2 * n},0}}"]] = fmpq(0)  # non-negative, non-zero sum
        printed &= quotient_properties(n, zero, 90 + n) == want and quotient_properties(n, w, 90 + n) == want
        corrected &= quotient_properties(n, w, 90 + n) == want
        ranks[n] = rank(quotient_matrix(n, rational_alpha(TS[1]), zero,
                                        sample_rational_points(rational_alpha(TS[1]), delta(n), seed=90 + n)))
    return LineResult(printed, None if printed else corrected,
                      how="exact quotient functions at delta_n rational points, tan(alpha/4) = 1/3: random positive "
                      "weights, and the same with rho_{2n,2n,0} = 0; row sums and rank, n = 1, 2, 3",
                      kind="exact-evidence", detail={"rank_with_a_zero_weight_n_1_2_3": [ranks[n] for n in (1, 2, 3)],
                                                     "delta_n": [delta(n) for n in (1, 2, 3)]})


PROJECTIVE = [[fmpq(2), fmpq(1, 3), fmpq(0), fmpq(1)], [fmpq(-1), fmpq(1), fmpq(1, 2), fmpq(0)],
              [fmpq(0), fmpq(1, 5), fmpq(3), fmpq(-1)], [fmpq(1, 20), fmpq(-1, 30), fmpq(1, 40), fmpq(1)]]


def projective_holds(M, n: int = 2, seed: int = 12) -> bool:
    """Patch of the projectively mapped net (weights w_k (M p~_k)_4) == M applied to the patch points (exact)."""
    alpha = rational_alpha(TS[2])
    net = random_net(n, 3, seed)
    rng = _rng(seed)
    w = [fmpq(int(rng.integers(1, 9)), int(rng.integers(1, 4))) for _ in range(delta(n))]

    def apply(p):
        h = [sum((M[r][c] * x for c, x in enumerate(list(p) + [fmpq(1)])), fmpq(0)) for r in range(4)]
        return [h[r] / h[3] for r in range(3)], h[3]

    mapped = [apply(p) for p in net]
    new_net, new_w = [m[0] for m in mapped], [w[k] * mapped[k][1] for k in range(delta(n))]
    if min(new_w) <= 0:
        raise ValueError("M: the transformed weights must stay positive")
    pts = sample_rational_points(alpha, 4, seed=seed)
    lhs = rational_eval(n, alpha, new_net, new_w, pts)
    rhs = [apply(q)[0] for q in rational_eval(n, alpha, net, w, pts)]
    return lhs == rhs


@line_check("sec6-projective")
def projective() -> LineResult:
    """"closed for the projective transformation of its control points, i.e., the patch determined by the
    projectively transformed control points coincides with the pointwisely transformed patch" (read) vs exact
    patches (the weights multiplied by the homogeneous coordinate of each image point, positive here)."""
    words = has_words(_LINE["sec6-projective"].verbatim, "Patch (\\ref{rational_patch}) is closed for the projective "
                      "transformation of its control points, i.e., the patch determined by the projectively "
                      "transformed control points coincides with the pointwisely transformed patch.")
    ok = projective_holds(PROJECTIVE, 1) and projective_holds(PROJECTIVE, 2)
    return LineResult(words and ok, how="the claim's words read; exact rational patch of a random net and positive "
                      "weights and of its projective image (4x4 rational matrix, weights multiplied by the homogeneous "
                      "coordinate), n = 1, 2", kind="exact-evidence", detail={"n": [1, 2]})


# --- the ring Dupin cyclide --------------------------------------------------------------------------------
def dupin_quartic(x, y, z, a, b, c, mu):
    """The ring Dupin cyclide's implicit equation (x^2 + y^2 + z^2 - mu^2 + b^2)^2 - 4 (a x - c mu)^2 - 4 b^2 y^2
    (the standard form, with a^2 = b^2 + c^2)."""
    return (x * x + y * y + z * z - mu * mu + b * b) ** 2 - 4 * (a * x - c * mu) ** 2 - 4 * b * b * y * y


def dupin_quartic_gradient(x, y, z, a, b, c, mu):
    p = x * x + y * y + z * z - mu * mu + b * b
    return (4 * p * x - 8 * a * (a * x - c * mu), 4 * p * y - 8 * b * b * y, 4 * p * z)


def read_dupin() -> dict:
    """eq. Dupin_in_3d read from its three transcribed lines (one display: a factor times a column): ``{"xyz":
    (x, y, z) with the printed factor applied, "u": (lo, hi), "v": (lo, hi)}`` (sympy in a, b, c, mu, u, v, varphi,
    psi; ``ValueError`` if unread)."""
    _, xyz, u, v = _surface_rows("".join(_LINE[k].verbatim for k in ("sec6-dupin-x", "sec6-dupin-y", "sec6-dupin-z")),
                                 None)
    return {"xyz": xyz, "u": u, "v": v}


NO_PHASES = ((fmpq(1), fmpq(0)), (fmpq(1), fmpq(0)))  # (cos, sin) of varphi = psi = 0


def dupin_point(xyz, params, tu: fmpq, tv: fmpq, phases=NO_PHASES) -> list[fmpq]:
    """The printed cyclide (read) at u = 4 atan(tu), v = 4 atan(tv), exactly; ``params`` = (a, b, c, mu) rational,
    ``phases`` the (cos, sin) of varphi and psi."""
    from paper_repro.printed.parsed import MU, PSI, VARPHI, U, V, exact_value
    from paper_repro.printed.parsed import A as SA
    from paper_repro.printed.parsed import B as SB
    from paper_repro.printed.parsed import C as SC

    a, b, c, mu = params
    bases = {U: (1, *trig_of(tu)), V: (1, *trig_of(tv)), VARPHI: (1, *phases[0]), PSI: (1, *phases[1])}
    return [exact_value(e, {SA: a, SB: b, SC: c, MU: mu}, bases, fmpq(0)) for e in xyz]


#: (a, b, c, mu) with rational b (a^2 = b^2 + c^2, c < mu < a): exact points
DUPIN_RATIONAL = ((fmpq(5), fmpq(4), fmpq(3), fmpq(4)), (fmpq(13), fmpq(12), fmpq(5), fmpq(7)),
                  (fmpq(10), fmpq(8), fmpq(6), fmpq(15, 2)))


def dupin_on_quartic(xyz, params, phases=NO_PHASES) -> bool:
    ok = True
    for tu in (fmpq(1, 3), fmpq(2), fmpq(-1, 4)):
        for tv in (fmpq(1, 5), fmpq(3, 2), fmpq(-2, 7)):
            ok &= dupin_quartic(*dupin_point(xyz, params, tu, tv, phases), *params) == 0
    return ok


def _in_domain(dom: dict, u: fmpq, v: fmpq) -> bool:
    return _in_read_domain(dom, u, v, fmpq(1))


@line_check("sec6-dupin-surface")
def dupin_surface() -> LineResult:
    """eq. Dupin_in_3d read from its three lines: its points satisfy the ring Dupin cyclide's implicit quartic exactly
    (three rational (a, b, c, mu) with a^2 = b^2 + c^2, c < mu < a; phases 0 and (3/5, 4/5), (-5/13, 12/13)); its
    parameter set {u in [lo, hi], v in [lo(u), hi(u)]} is Omega^alpha (grid, alpha = 1)."""
    try:
        dom = read_dupin()
    except ValueError as exc:
        return LineResult(False, how="eq. Dupin_in_3d read from the transcriptions", detail={"unread": str(exc)})
    phases = ((fmpq(3, 5), fmpq(4, 5)), (fmpq(-5, 13), fmpq(12, 13)))
    ok = all(dupin_on_quartic(dom["xyz"], p) for p in DUPIN_RATIONAL)
    ok &= dupin_on_quartic(dom["xyz"], DUPIN_RATIONAL[0], phases)
    grid = [(fmpq(i, 8), fmpq(j, 8)) for i in range(-1, 10) for j in range(-1, 10)]
    domain = all(_in_domain(dom, u, v) == (u >= 0 and v >= 0 and 1 - u - v >= 0) for u, v in grid)
    return LineResult(ok and domain, how="exact points (rational cos, sin) of eq. Dupin_in_3d (read) in the implicit "
                      "quartic, (a, b, c, mu) = (5, 4, 3, 4), (13, 12, 5, 7), (10, 8, 6, 15/2); the parameter set vs "
                      "Omega^alpha on a 11 x 11 grid", kind="exact-evidence",
                      detail={"on_quartic": ok, "parameter_set_is_omega": domain})


def dupin_homogeneous(a, b2, c, mu, phi, psi, upper: bool = False, alpha: RationalAngle | None = None):
    """(X, Y/b, Z/b, W) of the cyclide (the package's model, as :func:`paper_repro.surfaces.models.cyclide_parts`) at
    U = phi + u, V = psi + v (upper: U = phi + alpha - u, V = psi + alpha - v); phi, psi as (cos, sin)."""
    def cs(t: ExactTrig, var: int, ph):
        c0 = t.cos(*[1 if k == var else 0 for k in range(3)])
        s0 = t.sin(*[1 if k == var else 0 for k in range(3)])
        if upper:  # alpha - x
            ca, sa = trig_of(alpha.t)
            c0, s0 = ca * c0 + sa * s0, sa * c0 - ca * s0
        return ph[0] * c0 - ph[1] * s0, ph[1] * c0 + ph[0] * s0

    def surface(t: ExactTrig):
        cu, su = cs(t, 0, phi)
        cv, sv = cs(t, 1, psi)
        W = a - c * cu * cv
        return [mu * (c - a * cu * cv) + b2 * cu, (a - mu * cv) * su, (c * cu - mu) * sv, W]

    return surface


def dupin_count_holds(tex: str | None) -> tuple[bool, dict]:
    """The count and order of "by means of sixteen smoothly joined second order rational ... patches" (read from
    ``tex``) against the count of triangles needed to triangulate the cyclide: the phase torus (the square of the
    phase intervals read from sec6-dupin-phases) over the area of one triangle (the parameter set of eq. Dupin_in_3d,
    read, at the alpha of the caption of Fig. dupin_03, read); and exact order-n fits of both triangles of phase
    squares."""
    from paper_repro.printed.parsed import ALPHA, U, V

    m = sentence("by means of {count:count} smoothly joined {order:word} order rational triangular trigonometric "
                 "patches,", tex or "")
    if not m or m["count"] is None or m["order"] not in ORDINALS:
        return False, {"unread": (tex or "")[:60]}
    count, n = m["count"], ORDINALS[m["order"]]
    from paper_repro.printed import latex_math as LM

    settings = {}  # the caption's settings: each $..$ segment 'name = value', read by the one reader
    for seg in LM.inline_math(_LINE["sec6-fig-dupin-settings"].verbatim):
        try:
            rel = LM.parse_relation(seg)
        except LM.LatexMathError:
            continue
        if rel.ops == ["="] and len(rel.parts) == 2 and isinstance(rel.parts[0], sympy.Symbol):
            settings[str(rel.parts[0])] = rel.parts[1]
    alpha_value = settings.get("alpha")
    dom = read_dupin()
    (lo_u, hi_u), (lo_v, hi_v) = dom["u"], dom["v"]
    area = sympy.integrate(sympy.integrate(1, (V, lo_v, hi_v)), (U, lo_u, hi_u)).subs(ALPHA, alpha_value)
    phase = phase_intervals()
    torus_area = (phase[0][1] - phase[0][0]) * (phase[1][1] - phase[1][0])
    needed = sympy.nsimplify(torus_area / area)
    a, b2, c, mu = fmpq(6), fmpq(32), fmpq(2), fmpq(3)
    alpha = rational_alpha(TS[1])
    fits, joins = 0, True
    for phi in [(fmpq(1), fmpq(0)), trig_of(fmpq(1, 2))]:
        psi = (fmpq(1), fmpq(0))
        try:
            net = fit_exact(dupin_homogeneous(a, b2, c, mu, phi, psi), n, alpha)
            up = fit_exact(dupin_homogeneous(a, b2, c, mu, phi, psi, upper=True, alpha=alpha), n, alpha)
        except ValueError:
            return False, {"order": n, "fits": False}
        joins &= edge_net(net, n, "b") == reversed_edge_net(up, n, "b")
        a_t = alpha.t
        ss = (a_t / 5, a_t / 2)
        joins &= c1_across((net, RationalPoints(alpha, ss, tuple(tq(a_t, x) for x in ss)), ((1, 0, -1), (0, 1, -1))),
                           (up, RationalPoints(alpha, tuple(tq(a_t, x) for x in ss), ss), ((-1, 0, 1), (0, -1, 1))),
                           n, alpha, rational=True)
        fits += 2
    ok = needed.is_Integer and count == int(needed) and joins and fits == 4
    return ok, {"count": count, "order": n, "triangle_area": str(area), "phase_area": str(torus_area),
                "triangles_needed": str(needed), "diagonal_joins_C1": joins,
                "continuity": "C0 (shared control polygon and weights) and C1 in (U, V), hence G1" if joins else "no"}


@line_check("sec6-dupin-rational-patches")
def dupin_rational_patches() -> LineResult:
    """"sixteen smoothly joined second order rational ... patches" (read): a triangle u in [0, alpha], v in [0, alpha
    - u] (read) at alpha = pi/2 (caption, read) has area pi^2/8, the phase torus [0, 2pi]^2 (read) 4 pi^2, so the
    ring cyclide needs 32 triangles (16 cover half); exact order-2 fits of (X, Y/b, Z/b, W) on both triangles of a
    phase square share their diagonal control polygon and weights (each patch is the smooth cyclide itself).  The
    erratum's fix (thirty-two) applied to the transcription holds."""
    printed, detail = dupin_count_holds(_LINE["sec6-dupin-rational-patches"].verbatim)
    corrected = None if printed else dupin_count_holds(corrected_text("sec6-dupin-rational-patches"))[0]
    return LineResult(printed, corrected, how="count and order read; parameter areas from the intervals read "
                      "(sympy integration); exact order-n fits on both triangles of 2 phase squares, tan(alpha/4) = "
                      "1/3", kind="exact-evidence", detail=detail)


def phase_intervals() -> list[tuple[sympy.Expr, sympy.Expr]]:
    """``[(lo, hi) of varphi, (lo, hi) of psi]`` read from "$\\left(\\varphi,\\psi\\right) \\in [..]\\times[..]$": the
    words by :func:`~paper_repro.printed.latex_math.prose`, the segment by ``parse_relation`` (a ``ProductSet`` of two
    closed intervals)."""
    from paper_repro.printed.latex_math import parse_relation, prose
    from paper_repro.printed.parsed import PSI, VARPHI

    words, segs = prose(_LINE["sec6-dupin-phases"].verbatim)
    unread = ValueError(f"phases not read: {_LINE['sec6-dupin-phases'].verbatim[:60]!r}")
    if words != "while phase changes $$ are free design parameters that can be used to slide the patch on the " \
                "cyclide." or len(segs) != 1:
        raise unread
    rel = parse_relation(segs[0])
    box = rel.parts[-1]
    if rel.ops != ["in"] or rel.conditions or rel.parts[0] != sympy.Tuple(VARPHI, PSI) or \
            not isinstance(box, sympy.ProductSet) or len(box.sets) != 2 or \
            not all(isinstance(x, sympy.Interval) and not x.left_open and not x.right_open for x in box.sets):
        raise unread
    return [(x.start, x.end) for x in box.sets]


@line_check("sec6-dupin-phases")
def dupin_phases() -> LineResult:
    """"phase changes (varphi, psi) in [0, 2pi] x [0, 2pi] are free design parameters that can be used to slide the
    patch on the cyclide" (read): each interval covers a full period 2pi of eq. Dupin_in_3d (read: its points are
    2pi-periodic in varphi and psi, exact at rational cos, sin), so every patch position is reached; at several
    phases the patch stays on the cyclide's quartic (exact)."""
    try:
        (lo1, hi1), (lo2, hi2) = phase_intervals()
        dom = read_dupin()
    except ValueError as exc:
        return LineResult(False, how="the phase intervals read", detail={"unread": str(exc)})
    full = all((hi - lo) >= 2 * sympy.pi and lo.is_number and hi.is_number for lo, hi in ((lo1, hi1), (lo2, hi2)))
    on = all(dupin_on_quartic(dom["xyz"], DUPIN_RATIONAL[0], ph)
             for ph in (((fmpq(3, 5), fmpq(4, 5)), (fmpq(1), fmpq(0))), ((fmpq(-1), fmpq(0)), (fmpq(0), fmpq(-1)))))
    return LineResult(bool(full) and on, how="the phase intervals read vs the period 2pi; exact points of eq. "
                      "Dupin_in_3d (read) at phases (3/5, 4/5), (-1, 0), (0, -1) on the quartic", kind="exact-evidence",
                      detail={"phase_intervals": [[str(lo1), str(hi1)], [str(lo2), str(hi2)]]})


def collapsed_circle(xyz, a, b, c, mu) -> bool:
    """Whether a parameter circle of the printed cyclide (read) collapses to a point (40-digit values): U0 with
    c cos U0 = mu, or V0 with mu cos V0 = a, when such an angle exists."""
    import mpmath

    from paper_repro.printed.parsed import MU, PSI, VARPHI, U, V
    from paper_repro.printed.parsed import A as SA
    from paper_repro.printed.parsed import B as SB
    from paper_repro.printed.parsed import C as SC

    def sym(x):
        return sympy.Rational(int(x.p), int(x.q)) if isinstance(x, fmpq) else sympy.nsimplify(x)

    a, b, c, mu = (sym(x) for x in (a, b, c, mu))
    f = sympy.lambdify((U, V), [e.subs({VARPHI: 0, PSI: 0, SA: a, SB: b, SC: c, MU: mu}) for e in xyz],
                       modules="mpmath")
    with mpmath.workdps(40):
        circles = []
        if abs(mu) <= abs(c) and c != 0:
            u0 = mpmath.acos(mpmath.mpf(sympy.N(mu / c, 50)))
            circles.append([f(u0, v) for v in (mpmath.mpf("0.3"), mpmath.mpf("1.9"), mpmath.mpf("4.1"))])
        if abs(a) <= abs(mu):
            v0 = mpmath.acos(mpmath.mpf(sympy.N(a / mu, 50)))
            circles.append([f(u, v0) for u in (mpmath.mpf("0.3"), mpmath.mpf("1.9"), mpmath.mpf("4.1"))])
        return any(max(abs(p[k] - q[k]) for p, q in zip(pts, pts[1:]) for k in range(3)) < mpmath.mpf(10) ** -25
                   for pts in circles)


def dupin_conditions_hold(tex: str | None) -> tuple[bool, dict]:
    """The two conditions read from ``tex`` (its words, and its ``$..$`` segments by the one reader: the parameters
    a, b, c, mu, then the equation and the chain): the equation holds exactly for the (a, b, c) whose cyclide (eq.
    Dupin_in_3d, read) lies on the quartic (tested on 5 triples); the chain holds exactly for the mu that give a
    ring cyclide -- no parameter circle collapses (tested at 13 mu for two triples)."""
    from paper_repro.printed.latex_math import parse, prose
    from paper_repro.printed.parsed import MU, chain, relation_holds
    from paper_repro.printed.parsed import A as SA
    from paper_repro.printed.parsed import B as SB
    from paper_repro.printed.parsed import C as SC

    words, segs = prose(tex or "")
    if words != "where parameters $$, $$, $$ and $$ have to fulfill the conditions $$ and $$" or \
            [parse(x) for x in segs[:4]] != [SA, SB, SC, MU]:
        return False, {"unread": (tex or "")[:60]}
    eq, chain = chain(segs[4]), chain(segs[5])
    xyz = read_dupin()["xyz"]

    def sub(rel, a, b, c, mu):
        vals = {SA: sympy.Rational(int(a.p), int(a.q)), SB: sympy.Rational(int(b.p), int(b.q)),
                SC: sympy.Rational(int(c.p), int(c.q)), MU: sympy.Rational(int(mu.p), int(mu.q))}
        return relation_holds([x.subs(vals) for x in rel[0]], rel[1])

    triples = [(fmpq(5), fmpq(4), fmpq(3)), (fmpq(13), fmpq(12), fmpq(5)), (fmpq(6), fmpq(4), fmpq(3)),
               (fmpq(5), fmpq(3), fmpq(3)), (fmpq(7), fmpq(5), fmpq(2))]
    eq_ok = all(sub(eq, a, b, c, fmpq(4)) == dupin_on_quartic(xyz, (a, b, c, (a + c) / 2)) for a, b, c in triples)
    chain_ok, bad = True, []
    for a, b, c in triples[:2]:
        for k in range(13):
            mu = (a + 1) * fmpq(k, 12) + fmpq(1, 7)
            ring = not collapsed_circle(xyz, a, b, c, mu)
            if sub(chain, a, b, c, mu) != ring:
                chain_ok = False
                bad.append(str(mu))
        for mu in (a, c):  # the end points, exactly
            if sub(chain, a, b, c, mu) != (not collapsed_circle(xyz, a, b, c, mu)):
                chain_ok = False
                bad.append(f"{mu} (end point)")
    return eq_ok and chain_ok, {"equation_matches_quartic": eq_ok, "chain_fails_at_mu": bad}


@line_check("sec6-dupin-conditions")
def dupin_conditions() -> LineResult:
    """"the conditions $a^{2}=b^{2}+c^{2}$ and $c<\\mu\\leq a$" (read): the equation is the condition for eq.
    Dupin_in_3d to lie on the cyclide quartic; but at mu = a the parameter circle v + psi = 0 collapses to a point (a
    singular point of the quartic: a horn cyclide), so the ring condition is c < mu < a -- the erratum's fix applied
    to the transcription holds."""
    printed, detail = dupin_conditions_hold(_LINE["sec6-dupin-conditions"].verbatim)
    corrected = None if printed else dupin_conditions_hold(corrected_text("sec6-dupin-conditions"))[0]
    xyz = read_dupin()["xyz"]
    a, b, c = DUPIN_RATIONAL[0][:3]
    p = dupin_point(xyz, (a, b, c, a), fmpq(1, 3), fmpq(0))
    singular = dupin_quartic(*p, a, b, c, a) == 0 and set(dupin_quartic_gradient(*p, a, b, c, a)) == {0}
    return LineResult(printed, corrected, how="the conditions read from the transcription (and with the erratum's "
                      "fix) vs the quartic (exact) and collapsed parameter circles (40 digits), (a, b, c) = (5, 4, 3), "
                      "(13, 12, 5)", kind="exact-evidence",
                      detail={**detail, "mu_equal_a_singular_point": singular})


@line_check("sec6-fig-dupin-settings")
def fig_dupin_settings() -> LineResult:
    """Caption of Fig. dupin_03: "settings $a = 6$, $b=4\\sqrt{2}$, $c=2$ and $\\mu=3$ ... $\\alpha=\\frac{\\pi}{2}$"
    (parsed): eq. Dupin_in_3d (read) with them lies on the cyclide quartic (40 digits), no parameter circle collapses
    (a ring cyclide), and alpha is in the range of sec6-alpha-range (read)."""
    import mpmath

    from paper_repro.printed.parsed import MU, PSI, VARPHI, U, V, chain
    from paper_repro.printed.parsed import A as SA
    from paper_repro.printed.parsed import B as SB
    from paper_repro.printed.parsed import C as SC

    tex = _LINE["sec6-fig-dupin-settings"].verbatim
    m = sentence("cyclide (with settings {a}, {b}, {c} and {mu}) which is rendered as a transparent surface except "
                 "the lower right figure. The shape parameter of each second order rational triangular trigonometric "
                 "patch is {alpha}.", tex)
    if not m:
        return LineResult(False, how="the settings read from the transcription", detail={"unread": tex[:60]})
    values = {}
    for part in (m["a"], m["b"], m["c"], m["mu"], m["alpha"]):
        (lhs, rhs), ops = chain(part)
        if ops != ["="] or not lhs.is_Symbol or lhs in values:
            return LineResult(False, how="the settings read", detail={"unread": part})
        values[str(lhs)] = rhs
    if set(values) != {"a", "b", "c", "mu", "alpha"}:
        return LineResult(False, how="the settings read", detail={"names": sorted(values)})
    xyz = read_dupin()["xyz"]
    sub = {SA: values["a"], SB: values["b"], SC: values["c"], MU: values["mu"], VARPHI: 0, PSI: 0}
    f = sympy.lambdify((U, V), [e.subs(sub) for e in xyz], modules="mpmath")
    num = {k: sympy.N(v, 50) for k, v in values.items()}
    on = True
    with mpmath.workdps(40):
        for u, v in ((0.3, 1.1), (2.0, -0.7), (4.4, 2.9)):
            p = f(mpmath.mpf(u), mpmath.mpf(v))
            q = dupin_quartic(*p, *(mpmath.mpf(str(num[k])) for k in ("a", "b", "c", "mu")))
            on &= abs(q) < mpmath.mpf(10) ** -25
    ring = not collapsed_circle(xyz, values["a"], values["b"], values["c"], values["mu"])
    ring &= bool(values["mu"] > 0)
    lo, hi = read_open_interval(_LINE["sec6-alpha-range"].verbatim, "\\alpha")
    alpha_ok = bool(lo < values["alpha"] < hi)
    return LineResult(on and ring and alpha_ok, how="settings parsed; eq. Dupin_in_3d (read) in the quartic (40 "
                      "digits), collapsed circles, alpha range read", kind="exact-evidence",
                      detail={"on_quartic": on, "ring": ring, "alpha_in_range": alpha_ok})
