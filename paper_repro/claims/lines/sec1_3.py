"""Checks of the lines of Sections 1-3 (abstract, Introduction, sec:RGB, sec:linear_independence), transcribed in
:mod:`paper_repro.printed.lines.sec1_3`.

The independent computations:

* the functions of T_{2n} as exponent vectors (:mod:`paper_repro.core.labels`): the union R u G u B with equal
  functions merged, boundary restrictions, images under swaps of variables;
* derivatives along the parametrizations of the proof, exactly: a function of T_{2n} is Z(z) O(o) F(f) with
  factors sin^s cos^c of half angles; the r-th derivative along a parametrization is computed from the direction
  vector of the (affine) parametrization -- not from the printed chain rule -- with the factor at 0 from exact
  Taylor series (:func:`paper_repro.theory.derivatives.mixed_derivative`) and the other factors as exact
  trigonometric polynomials evaluated where the half-angle sines and cosines are rational (tan(x/4) rational);
* the elimination of the proof, recomputed from these exact derivatives: the functions whose derivative of the
  step's order does not vanish at the boundary are removed, step by step;
* the printed sums, values and primed coefficients of Section 3 read from the transcriptions
  (:mod:`paper_repro.printed.latex_math`: sums with their bounds, constants, half-angle sines and their
  derivatives, S and M of the Lemma and the Proposition, c and A; the parametrizations and sign functions too),
  compared with the computed sets and, as linear forms in the combining constants, with the computed values.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache
from math import comb

import mpmath
import sympy
from flint import fmpq, fmpz_mpoly_ctx, nmod_mat
from sympy.core.function import AppliedUndef

from paper_repro.claims.lines import LineResult, line_check
from paper_repro.claims.lines.sec12_eval import c_exact, c_indep, num, sign_word
from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import BasisLabel, compose, delta, exponents, full_system, index_of, united_system
from paper_repro.core.univariate import c_const, c_numerator, c_numerator_by_expansion
from paper_repro.printed import latex_math as lm
from paper_repro.printed import parsed
from paper_repro.printed import symmetry as printed_sym
from paper_repro.printed.latex_math import LatexMathError
from paper_repro.printed.lines import line as transcribed_line
from paper_repro.printed.lines import lines_of, verbatim
from paper_repro.theory.derivatives import mixed_derivative, sign, sin_power_derivative

HALF = fmpq(1, 2)
#: alpha = 4 atan(t) for these t, and interior parameters x = 4 atan(t_x) with t_x < t (exact half angles).
ALPHA_TS = (fmpq(1, 2), fmpq(3, 4))
X_FRACTIONS = (fmpq(1, 3), fmpq(5, 7))
N_PROOF = range(1, 7)  # orders n for which the proof's steps are recomputed


# -- reading (paper_repro.printed.latex_math) -------------------------------------------------------------------
@cache
def relation(tex: str) -> list[sympy.Expr]:
    """The parts of an equality chain ``a = b = c`` (every relation ``=``, no trailing clause), by
    :func:`paper_repro.printed.latex_math.parse_relation`; :class:`LatexMathError` on anything else.

    >>> relation(r"c_{2n,i}^{\\alpha}=c_{2n,2n-i}^{\\alpha}")
    [c(2*n, i), c(2*n, -i + 2*n)]
    """
    rel = lm.parse_relation(tex)
    if rel.lead not in (None, "=") or any(op != "=" for op in rel.ops) or rel.conditions:
        raise LatexMathError(f"not an equality chain: {rel.lead} {rel.ops} {len(rel.conditions)} clauses")
    return rel.parts


def equation_over(tex: str, var: str) -> tuple[list[sympy.Expr], sympy.Expr, sympy.Expr]:
    """The parts of an equality chain printed with one trailing listed range ``var=a,a+1,\\ldots,c`` and nothing
    else, and the range's ``(a, c)`` (:func:`listed`), by one :func:`latex_math.parse_relation` of the line.

    >>> equation_over(r"c_{2n,i}^{\\alpha}=c_{2n,2n-i}^{\\alpha},~i=0,1,\\ldots,n.", "i")
    ([c(2*n, i), c(2*n, -i + 2*n)], 0, n)
    """
    rel = lm.parse_relation(tex)
    if rel.lead not in (None, "=") or not rel.ops or any(op != "=" for op in rel.ops) or len(rel.conditions) != 1:
        raise LatexMathError(f"not an equality chain with one listed range: {rel.lead} {rel.ops} "
                             f"{len(rel.conditions)} clauses")
    return rel.parts, *listed(rel, var)


def linear_form(expr: str | sympy.Expr) -> tuple[int, int, int]:
    """Integer coefficients (of alpha, x, y) of a printed linear form such as ``\\alpha-x-y``, ``x-y``, ``y``, ``0``
    (its LaTeX, read by :func:`parse`, or the parsed expression); ``ValueError`` for anything else (another symbol, a
    constant term, a non-integer or non-linear coefficient).

    >>> linear_form(r"\\alpha-x-y")
    (1, -1, -1)
    """
    e = sympy.expand(lm.parse(expr) if isinstance(expr, str) else sympy.sympify(expr))
    alpha, x, y = sympy.symbols("alpha x y")
    if not isinstance(e, sympy.Expr) or not e.free_symbols <= {alpha, x, y}:
        raise LatexMathError(f"not a linear form in alpha, x, y: {expr!r}")
    if e == 0:
        return 0, 0, 0
    coeffs = sympy.Poly(e, alpha, x, y).as_dict()
    if any(sum(m) != 1 for m in coeffs) or any(not c.is_integer for c in coeffs.values()):
        raise LatexMathError(f"not a linear form in alpha, x, y: {expr!r}")
    return tuple(int(coeffs.get(m, 0)) for m in ((1, 0, 0), (0, 1, 0), (0, 0, 1)))


def read_parametrization(tex: str) -> tuple[tuple[tuple[int, int, int], ...], dict[str, tuple]]:
    """The printed parametrization ``\\left\\{ \\begin{array}{rcl} u_{1}\\left( x,y\\right) & = & x,~x\\in\\left[
    0,\\alpha\\right] ,\\\\ ...``: each row read by :func:`paper_repro.printed.latex_math.parse_relation` (the
    three cells of a row are one relation with its clause); the maps of u, v, w (in this order, one subscript, applied
    to (x, y)) as integer linear forms in alpha, x, y, and the printed ranges ``{"x": (lo, hi), "y": (lo, hi)}``
    (closed intervals; the endpoints parsed).

    >>> maps, ranges = read_parametrization(verbatim("sec1_3-param-2"))
    >>> maps, ranges["y"]
    (((0, 1, 0), (1, -1, -1), (0, 0, 1)), (0, alpha - x))
    """
    arrays: list = []
    lm.clean(tex, arrays)
    rows = [r for r in (arrays[0] if len(arrays) == 1 else []) if any(c.strip() for c in r)]
    if len(rows) != 3 or any(len(r) != 3 for r in rows):
        raise LatexMathError(f"not a parametrization of three rows lhs & = & rhs: {tex[:60]!r}")
    xy = sympy.Tuple(*sympy.symbols("x y"))
    maps, ranges, subs = [], {}, set()
    for name, row in zip("uvw", rows):
        rel = lm.parse_relation(" ".join(row))
        lhs = rel.parts[0]
        if rel.ops != ["="] or not isinstance(lhs, AppliedUndef) or lhs.func.__name__ != name or lhs.args[-1] != xy:
            raise LatexMathError(f"row {row[0]!r} is not {name}(x, y) = ..")
        subs.add(lhs.args[:-1])
        maps.append(linear_form(rel.parts[1]))
        for c in rel.conditions:
            var, rng = c.parts[0] if c.parts else None, c.parts[-1] if c.parts else None
            if c.ops != ["in"] or var not in xy or not isinstance(rng, sympy.Interval) or rng.left_open or \
                    rng.right_open or str(var) in ranges:
                raise LatexMathError(f"unread range {c}")
            ranges[str(var)] = (rng.start, rng.end)
    if len(subs) != 1 or set(ranges) != {"x", "y"}:
        raise LatexMathError(f"subscripts {subs} / ranges of {sorted(ranges)}: not one parametrization of x and y")
    return tuple(maps), ranges


# -- exact half-angle arithmetic ------------------------------------------------------------------------------
def _half(t: fmpq) -> tuple[fmpq, fmpq]:
    """(sin(x/2), cos(x/2)) for x = 4 atan(t)."""
    return 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)


def _diff_half(a: tuple[fmpq, fmpq], b: tuple[fmpq, fmpq]) -> tuple[fmpq, fmpq]:
    """Half angles of A - B from those of A and B."""
    return a[0] * b[1] - a[1] * b[0], a[1] * b[1] + a[0] * b[0]


@cache
def _tpoly_derivative(s: int, c: int, k: int) -> tuple[tuple[tuple[int, int], fmpq], ...]:
    """d^k/dt^k sin^s(t/2) cos^c(t/2) as a sum of q sin^a(t/2) cos^b(t/2)."""
    poly = {(s, c): fmpq(1)}
    for _ in range(k):
        out: dict[tuple[int, int], fmpq] = {}
        for (a, b), q in poly.items():
            if a:
                out[(a - 1, b + 1)] = out.get((a - 1, b + 1), fmpq(0)) + q * fmpq(a, 2)
            if b:
                out[(a + 1, b - 1)] = out.get((a + 1, b - 1), fmpq(0)) - q * fmpq(b, 2)
        poly = {key: q for key, q in out.items() if q != 0}
    return tuple(poly.items())


def _factor_derivative(s: int, c: int, k: int, half: tuple[fmpq, fmpq]) -> fmpq:
    """d^k/dt^k sin^s(t/2) cos^c(t/2) at the angle whose half-angle sine and cosine are ``half``."""
    return sum((q * half[0] ** a * half[1] ** b for (a, b), q in _tpoly_derivative(s, c, k)), fmpq(0))


# -- the parametrizations of the proof, read from their transcriptions ------------------------------------------
#: parametrization label -> (its line, the line of its derivative formula, which names the running parameter)
PARAM_LINES = {
    "parametrization_for_partition_of_unity": ("sec1_3-param-partition-of-unity", "sec1_3-chain-rule"),
    "parametrization_1_y_0": ("sec1_3-param-1", "sec1_3-chain-1"),
    "parametrization_2_x_0": ("sec1_3-param-2", "sec1_3-chain-2"),
    "parametrization_3_y_0": ("sec1_3-param-3", "sec1_3-chain-3"),
}


@cache
def _params() -> dict[str, tuple]:
    """label -> (map (alpha, x, y) -> (u, v, w), running parameter, the three printed linear forms, printed ranges):
    the maps and ranges read from the parametrization's transcription, the running parameter from the derivative
    formula that differentiates along it (``\\frac{\\partial^{r}}{\\partial y^{r}}``)."""
    out = {}
    for label, (lid, chain) in PARAM_LINES.items():
        maps, ranges = read_parametrization(_transcribed([lid])[lid])
        try:  # the left side D(L(..), (y, r)) of the chain rule
            lhs = lm.parse_relation(_transcribed([chain])[chain]).parts[0]
        except LatexMathError as exc:
            raise ValueError(f"no running parameter in {chain}: {exc}") from None
        if not (isinstance(lhs, AppliedUndef) and lhs.func.__name__ == "D" and len(lhs.args) == 2) or \
                str(lhs.args[1][0]) not in ("x", "y") or lhs.args[1][1] != sympy.Symbol("r"):
            raise ValueError(f"no running parameter d^r/dx^r or d^r/dy^r in {chain}")
        run = str(lhs.args[1][0])

        def fmap(a, x, y, maps=maps):
            return tuple(p * a + q * x + s * y for p, q, s in maps)
        out[label] = (fmap, run, maps, ranges)
    return out


class _LiveParams(dict):
    """``PARAMS[label]`` = (map, running parameter) read from the transcriptions at every lookup."""

    def __getitem__(self, label: str):
        return _params()[label][:2]

    def __iter__(self):
        return iter(PARAM_LINES)


#: label -> (map (alpha, x, y) -> (u, v, w), running parameter), read live from the transcriptions
PARAMS = _LiveParams()


@cache
def step_geometry(param: str) -> tuple[tuple[int, int, int], int, int, int]:
    """Computed from the printed map: (direction of d/d(running) in (u, v, w), the coordinate that vanishes when the
    running parameter is 0, the coordinate equal to the other parameter there, the remaining coordinate)."""
    fmap, run = PARAMS[param]
    a, p, q = fmpq(7, 5), fmpq(2, 5), fmpq(1, 5)  # any alpha and point; the maps are affine
    base = fmap(a, p, q)
    moved = fmap(a, p + 1, q) if run == "x" else fmap(a, p, q + 1)
    direction = tuple(int(m - b) for m, b in zip(moved, base))
    at0 = fmap(a, fmpq(0), q) if run == "x" else fmap(a, p, fmpq(0))
    other_param = q if run == "x" else p
    zero = [k for k in range(3) if at0[k] == 0]
    fixed = [k for k in range(3) if at0[k] == other_param and at0[k] != 0]
    assert len(zero) == 1 and len(fixed) == 1, (param, at0)
    rest = 3 - zero[0] - fixed[0]
    return direction, zero[0], fixed[0], rest


def elimination_geometry() -> dict[str, tuple[int, int, int]]:
    """The three step parametrizations in the proof's order, each as ``(coordinate set to 0, coordinate running
    with the parameter, the third)`` (:data:`paper_repro.theory.elimination.Geometry`), computed from the printed
    maps (:func:`step_geometry`)."""
    out = {}
    for param in STEP_PARAMS:
        direction, zero, fixed, rest = step_geometry(param)
        if (direction[zero], direction[rest]) != (1, -1):
            raise ValueError(f"{param}: direction {direction} is not d_zero - d_other")
        out[param] = (zero, rest, fixed)
    return out


def _split(e: tuple[int, ...], var: int) -> tuple[int, int]:
    return e[2 * var], e[2 * var + 1]


def boundary_point(alpha_t: fmpq, x_frac: fmpq) -> dict[str, tuple[fmpq, fmpq]]:
    """Half angles of alpha, of the boundary parameter t (tan(t/4) = x_frac tan(alpha/4)) and of alpha - t."""
    ha, ht = _half(alpha_t), _half(alpha_t * x_frac)
    return {"alpha": ha, "t": ht, "alpha-t": _diff_half(ha, ht)}


def mixed_partial(e: tuple[int, ...], param: str, z_order: int, o_order: int, pt) -> fmpq:
    """d^{z_order}/d(zero var) d^{o_order}/d(other var) of the function with exponents e, at the boundary point
    (zero var = 0, fixed var = t, other var = alpha - t)."""
    _, zero, fixed, rest = step_geometry(param)
    zs, zc = _split(e, zero)
    d0 = mixed_derivative(zc, HALF, zs, HALF, z_order)
    if d0 == 0:
        return fmpq(0)
    fs, fc = _split(e, fixed)
    os_, oc = _split(e, rest)
    return d0 * _factor_derivative(os_, oc, o_order, pt["alpha-t"]) * _factor_derivative(fs, fc, 0, pt["t"])


def step_value(e: tuple[int, ...], param: str, r: int, pt) -> fmpq:
    """The r-th derivative along the parametrization at the boundary, from the direction vector."""
    direction, zero, _fixed, rest = step_geometry(param)
    dz, do = direction[zero], direction[rest]
    return sum((comb(r, k) * dz ** (r - k) * do**k * mixed_partial(e, param, r - k, k, pt) for k in range(r + 1)),
               fmpq(0))


def _points():
    return [boundary_point(a, x) for a in ALPHA_TS for x in X_FRACTIONS]


@cache
def survivors(n: int, param: str, r: int, alive: frozenset[int]) -> frozenset[int]:
    """Indices (into T_{2n}) of the alive functions whose r-th derivative along ``param`` does not vanish."""
    labels = united_system(n)
    pts = _points()
    return frozenset(k for k in alive if any(step_value(exponents(labels[k]), param, r, p) != 0 for p in pts))


STEP_PARAMS = ("parametrization_1_y_0", "parametrization_2_x_0", "parametrization_3_y_0")


@cache
def elimination(n: int, orders: int | None = None) -> tuple[tuple[int, str, frozenset[int], frozenset[int]], ...]:
    """The proof's steps recomputed: (order r, parametrization, alive before, removed), orders 0..orders-1."""
    alive = frozenset(range(len(united_system(n))))
    steps = []
    for r in range(n if orders is None else orders):
        for param in STEP_PARAMS:
            gone = survivors(n, param, r, alive)
            steps.append((r, param, alive, gone))
            alive = alive - gone
    return tuple(steps)


def alive_after(n: int, r: int, param_index: int) -> frozenset[int]:
    """Functions left after the step (order r, parametrization 1/2/3 = param_index 0/1/2)."""
    _, _, before, gone = elimination(n)[3 * r + param_index]
    return before - gone


def alive_before(n: int, r: int, param_index: int = 0) -> frozenset[int]:
    return elimination(n)[3 * r + param_index][2]


# -- printed sums as index sets -------------------------------------------------------------------------------
def lab(color: str, n: int, i: int, j: int) -> int:
    """Internal index of the printed label color_{2n,2n-i,j} (aliases resolved by the package's label map)."""
    return index_of(n)[f"{color}_{{{2 * n},{2 * n - i},{j}}}"]


def dsum(color: str, n: int, j_from: int, j_to: int, i_from=lambda j: j, i_to=None) -> set[int]:
    """sum_{j=j_from}^{j_to} sum_{i=i_from(j)}^{i_to(j)} of color_{2n,2n-i,j}; i_to defaults to 2n-1-j."""
    i_to = i_to or (lambda j: 2 * n - 1 - j)
    return {lab(color, n, i, j) for j in range(j_from, j_to + 1) for i in range(i_from(j), i_to(j) + 1)}


def isum(color: str, n: int, j: int, i_from: int, i_to: int) -> set[int]:
    return {lab(color, n, i, j) for i in range(i_from, i_to + 1)}


def centre(n: int) -> set[int]:
    return {lab("R", n, n, n)}


def _names(n: int, idx) -> list[str]:
    """Names of the members ``idx`` of T_{2n}; a string (a printed name that is no member) is kept as it is."""
    labels = united_system(n)
    return sorted(labels[k].paper if isinstance(k, int) else str(k) for k in idx)


def _set_result(printed, computed, how: str, kind: str = "exact-evidence", corrected=None) -> LineResult:
    """Compare printed(n[, r]) with computed(n[, r]) as sets for every n, r given (dicts keyed by (n, r))."""
    bad = {f"n={n},r={r}": {"printed_only": _names(n, printed[(n, r)] - computed[(n, r)]),
                            "computed_only": _names(n, computed[(n, r)] - printed[(n, r)])}
           for (n, r) in printed if printed[(n, r)] != computed[(n, r)]}
    detail = {"cases": len(printed), "mismatches": len(bad), "first_mismatches": dict(list(bad.items())[:2])}
    corr = None
    if corrected is not None:
        corr = all(corrected[key] == computed[key] for key in corrected)
        detail["corrected_mismatches"] = sum(corrected[key] != computed[key] for key in corrected)
    return LineResult(not bad, corr, how=how, kind=kind, detail=detail)


# ==============================================================================================================
# Sections 1-2
# ==============================================================================================================
# -- Sections 1-2: readers of the transcriptions (issue 37) ------------------------------------------------------
def interval_of(x) -> tuple[bool, sympy.Expr, sympy.Expr, bool]:
    """``(lo closed, lo, hi, hi closed)`` of a parsed interval: ``Interval`` (``\\left[ a,b\\right]``, ``(a,b]``, ..)
    or the pair ``Tuple(a, b)`` that ``\\left( a,b\\right)`` after ``\\in`` is read as (the open interval);
    ``LatexMathError`` for anything else (an empty or one-point interval included)."""
    if isinstance(x, sympy.Interval):
        return not x.left_open, x.start, x.end, not x.right_open
    if isinstance(x, sympy.Tuple) and len(x) == 2:
        return False, x[0], x[1], False
    raise LatexMathError(f"{x} is not an interval")


def read_interval(tex: str, var: str) -> tuple[bool, sympy.Expr, sympy.Expr, bool]:
    """``(lo closed, lo, hi, hi closed)`` of the printed ``var \\in \\left( lo,hi \\right)`` (``var`` a name such as
    ``alpha``): the one relation or clause ``var in ..`` of the line's ``$..$`` segments (or of the line), read by
    :func:`latex_math.parse_relation` and :func:`interval_of`."""
    v = sympy.Symbol(var)
    found = []
    for seg in lm.inline_math(tex) or [tex]:
        rel = lm.parse_relation(seg)
        found += [r for r in (rel, *rel.conditions) if r.ops == ["in"] and len(r.parts) == 2 and r.parts[0] == v]
    if len(found) != 1:
        raise LatexMathError(f"{len(found)} intervals for {var} in {tex[:60]!r}")
    return interval_of(found[0].parts[1])


def listed(tex: str | lm.Relation, var: str) -> tuple[sympy.Expr, sympy.Expr]:
    """(first, last) of the printed ``var=a,b,\\ldots,c`` whose step b - a must be 1 (every index between): the
    clause ``var in (a, b, ldots, c)`` of :func:`paper_repro.printed.latex_math.parse_relation` (the relation itself
    or one of its trailing clauses; ``tex`` a text or a parsed relation).

    >>> listed(r"i=0,1,\\ldots,2n", "i")
    (0, 2*n)
    """
    rel = tex if isinstance(tex, lm.Relation) else lm.parse_relation(tex)
    v = sympy.Symbol(var)
    found = [r for r in (rel, *rel.conditions) if r.ops == ["in"] and r.parts[0] == v
             and isinstance(r.parts[1], sympy.Tuple)]
    if len(found) != 1:
        raise LatexMathError(f"no listed range {var}=a,b,...,c")
    items = found[0].parts[1].args
    if len(items) != 4 or items[2] != lm.LDOTS or lm.LDOTS in items[:2] + items[3:]:
        raise LatexMathError(f"the listed range {var}={items} is not a,b,...,c")
    a, b, _, c = items
    if sympy.simplify(b - a - 1) != 0:
        raise LatexMathError(f"the listed range {var}={a},{b},... does not step by 1")
    return a, c


def _unread(how: str, exc: Exception, kind: str = "exact-evidence") -> LineResult:
    kind = "exact-evidence" if kind == "exhaustive" else kind  # nothing was computed over a range
    return LineResult(False, how=how + " (the line was not read)", kind=kind, detail={"unread": str(exc)[:200]})


def _env_int(expr: sympy.Expr, **env: int) -> int:
    """Integer value of a parsed index or bound (every name bound by ``env``)."""
    v = num(expr, env, {})
    if v != int(v):
        raise LatexMathError(f"{expr} is not an integer at {env}")
    return int(v)


_TINY = mpmath.mpf(10) ** -25  # below: zero at the working precision of 40 digits (cos(pi/2) is 6e-41 there)


def _basis_alpha_ok(alpha) -> bool:
    """c_{2n,i}^alpha (from the expansion) finite and positive for n <= 4, and alpha > 0 (so [0, alpha] is an
    interval): where the normalized system (eq. univariate_basis) exists with positive coefficients."""
    if alpha <= 0:
        return False
    try:
        return all(c_indep(n, i, alpha) > _TINY for n in range(1, 5) for i in range(2 * n + 1))
    except ZeroDivisionError:
        return False


@line_check("sec1_3-alpha-range")
def alpha_range() -> LineResult:
    """alpha in (0, pi), read from both lines: the printed interval must be where the coefficients c_{2n,i}^alpha
    (from the expansion of (X^2 + 2cos(alpha/2)XY + Y^2)^n) exist and are positive, and maximal so: every sampled
    interior alpha works (n <= 4, 40 digits), an open end does not (alpha = 0: no interval and sin(alpha/2) = 0;
    alpha = pi: the odd c_{2n,i} vanish), a closed end does and its outside does not.  The polynomial facts behind
    it: the numerators have non-negative coefficients in cos(alpha/2) (n = 1..15) and vanish at cos = 0 exactly
    for odd i."""
    ok_pos = all(min(c_numerator(n, i)) >= 0 and sum(c_numerator(n, i)) > 0
                 for n in range(1, 16) for i in range(2 * n + 1))
    zero_at_pi = all((c_numerator(n, i)[0] == 0) == (i % 2 == 1) for n in range(1, 16) for i in range(2 * n + 1))
    how = ("the printed interval of alpha (read from each line) against where c_{2n,i}^alpha > 0 (n = 1..4, 40 "
           "digits; numerator polynomials n = 1..15)")
    bad = []
    eps = mpmath.mpf("1e-20")
    with mpmath.workdps(40):
        for ln in lines_of("sec1_3-alpha-range"):
            try:
                lo_c, lo, hi, hi_c = read_interval(ln.verbatim, "alpha")
                lo_v, hi_v = num(lo, {}), num(hi, {})
            except (LatexMathError, ValueError) as exc:
                return _unread(how, exc, "exhaustive")
            inside = all(_basis_alpha_ok(lo_v + (hi_v - lo_v) * k / 9) for k in range(1, 9)) and lo_v < hi_v
            ends = all(_basis_alpha_ok(e) if closed else not _basis_alpha_ok(e)
                       for e, closed in ((lo_v, lo_c), (hi_v, hi_c)))
            outside = all(not _basis_alpha_ok(e) for e, closed in ((lo_v - eps, lo_c), (hi_v + eps, hi_c)) if closed)
            near = _basis_alpha_ok(lo_v + eps) and _basis_alpha_ok(hi_v - eps)
            if not (inside and ends and outside and near):
                bad.append(ln.id)
    ok = ok_pos and zero_at_pi and not bad
    return LineResult(ok, how=how, kind="exhaustive",
                      detail={"nonnegative_polynomials": ok_pos, "odd_vanish_at_pi": zero_at_pi, "failing_lines": bad})


def _member_labels(tex: str) -> list[tuple[str, str, str, tuple[int, ...]]]:
    """The labels ``X_{2n,a,b}^{\\alpha}\\left( u,v,w\\right)`` listed before the ``:`` of the last set of a system
    display, as (colour, first index, level, argument permutation): the display read by
    :func:`~paper_repro.printed.latex_math.parse_relation`, the set (a ``Family`` with a double index set) and its
    condition ``(u,v,w) \\in \\Omega^{\\alpha}`` taken from the parsed object."""
    sets = [x for part in lm.parse_relation(tex).parts if part is not None for x in sympy.preorder_traversal(part)
            if isinstance(x, AppliedUndef) and x.func == lm.Family]
    if not sets:
        raise LatexMathError(f"no set-builder in {tex[:60]!r}")
    members, conds, bounds = sets[-1].args
    if len(bounds) != 2:
        raise LatexMathError(f"not a double index set: {bounds}")
    uvw = sympy.Tuple(*sympy.symbols("u v w"))
    if tuple(conds) != (sympy.Function("In")(uvw, sympy.Symbol("Omega")),):
        raise LatexMathError(f"the domain {conds} is not (u,v,w) in Omega^alpha")
    return [printed_sym.label_of(m) for m in (members if isinstance(members, sympy.Tuple) else [members])]


def _require_omega(domain: str) -> None:
    """The domain of a system must read ``(u,v,w) \\in \\Omega^{\\alpha}`` (membership in the printed triangle)."""
    r = lm.parse_relation(domain)
    if r.ops != ["in"] or r.conditions or r.parts != [sympy.Tuple(*sympy.symbols("u v w")), sympy.Symbol("Omega")]:
        raise LatexMathError(f"the domain {domain.strip()[:40]!r} is not (u,v,w) in Omega^alpha")


def _index_value(first: str, level: str, n: int, i: int, j: int) -> tuple[int, int]:
    """(i, j) of the label X_{2n,first,level} at (n, i, j): first = 2n - i'."""
    f, lv = _index_fn(first, level)(n, i, j)
    if f != int(f) or lv != int(lv):
        raise LatexMathError(f"index ({first}, {level}) is not an integer at n={n}, i={i}, j={j}")
    return 2 * n - int(f), int(lv)


@cache
def _index_fn(first: str, level: str):
    n, i, j = sympy.symbols("n i j")
    exprs = [sympy.sympify(first), sympy.sympify(level)]
    if set().union(*(e.free_symbols for e in exprs)) - {n, i, j}:
        raise LatexMathError(f"index ({first}, {level}) names unknown symbols")
    return sympy.lambdify((n, i, j), exprs, "math")


def _centre_members(n: int) -> list[tuple[int, ...] | None]:
    """Exponent vectors of the labels of the printed centre (``R_{2n,n,n} = G_{2n,n,n} = B_{2n,n,n}``, line
    sec1_3-united-centre), ``None`` for a label that is no member of its system."""
    tex = verbatim("sec1_3-united-centre")
    body, _, domain = tex.split("\\cup", 1)[1].partition(":")
    _require_omega(domain.split("\\right\\}")[0])
    parts = relation(body.replace("\\left\\{", " "))
    out = []
    for p in parts:
        color, first, level, perm = printed_sym.label_of(p)
        i, j = _index_value(first, level, n, 0, 0)
        out.append(compose(exponents(BasisLabel(color, n, i, j)), perm)
                   if 0 <= j <= n and j <= i <= 2 * n - j else None)
    return out


@line_check("sec1_3-united-dedupe")
def united_dedupe(verbatim_text: str | None = None) -> LineResult:
    """The members and the index set read from the transcription of eq. united_system (with the centre read from
    the line after it) list each distinct function of R u G u B exactly once (n = 1..20); the functions from the
    printed explicit formulas (:func:`printed_exponents`, parsed), the distinct functions from the package."""
    tex = verbatim_text if verbatim_text is not None else verbatim("sec1_3-united-system")
    how = "the index set and members read from the transcription against the distinct functions of the full " \
          "systems, n = 1..20"
    ok, bad = True, []
    try:
        members = _member_labels(tex)
        if [m[0] for m in members] != list("RGB") or any(m[3] != (0, 1, 2) for m in members):
            raise LatexMathError(f"members {members} are not R, G, B at (u, v, w)")
        for n in range(1, 21):
            pairs = _read_pairs(tex, n)
            centre = _centre_members(n)
            listed = centre[:1] + [printed_exponents(c, n, *_index_value(f, lv, n, i, j))
                                   for c, f, lv, _ in members for i, j in pairs]
            good = None not in listed and len(listed) == len(set(listed)) and set(listed) == distinct_union(n)
            ok &= good
            if not good:
                bad.append(n)
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    return LineResult(ok, how=how, kind="exhaustive", detail={"n_max": 20, "failing_n": bad[:3]})


_LEVELS_WORDS = "weighted oriented\\ graph of $$ levels (numbered from $$ to $$)"


@line_check("sec1_3-levels")
def levels() -> LineResult:
    """"n >= 1 levels (numbered from 0 to n-1)" and "the index j ... as levels ... nested triangles shrinking from
    the boundary to their common centroid", read from the two lines: for n = 1..12 the levels of the non-centre
    functions of T_{2n} (package labels) are exactly the printed numbers; the named index of each function equals
    the order to which it vanishes on the boundary of Omega (its least sine exponent: nested triangles), 0 on the
    boundary and n at the centroid; and the printed least order is the least n with a level."""
    how = "levels and boundary vanishing orders of the labels of T_{2n}, n = 1..12, against the printed numbering"
    try:
        words, segs = lm.prose(verbatim("sec1_3-graph-levels"))
        if words != _LEVELS_WORDS or len(segs) != 3:
            raise LatexMathError("no '$n\\geq k$ levels (numbered from $a$ to $b$)'")
        at_least = lm.parse_relation(segs[0])  # n >= k
        if at_least.ops != [">="] or at_least.parts[0] != sympy.Symbol("n") or not at_least.parts[1].is_Integer or \
                at_least.conditions:
            raise LatexMathError(f"not n >= an integer: {segs[0]!r}")
        least, lo, hi = int(at_least.parts[1]), lm.parse(segs[1]), lm.parse(segs[2])
        said = lm.sentence("We refer to the index {j} of these functions as levels since they correspond to the nested "
                           "triangles shrinking from the {outer:word} to their common {inner:word}",
                           verbatim("sec1_3-levels-j"))
        index = lm.parse(said["j"]) if said else None
        if not isinstance(index, sympy.Symbol):
            raise LatexMathError("the named index or the nesting words are not read")
        named, ends = str(index), (said["outer"], said["inner"])
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    first_n = min(n for n in range(0, 4) if _has_levels(n))
    ok = least == first_n
    for n in range(1, 13):
        labs = united_system(n)
        lv = {lb.j for lb in labs if not lb.is_centre}
        ok &= lv == set(range(_env_int(lo, n=n), _env_int(hi, n=n) + 1)) and len(lv) == n
        for lb in labs:
            e = exponents(lb)
            ok &= getattr(lb, named, None) == min(e[0], e[2], e[4])
        ok &= ends == ("boundary", "centroid") and min(lv) == 0
    return LineResult(ok, how=how, kind="exhaustive", detail={"least_n": least, "index": named})


def _has_levels(n: int) -> bool:
    try:
        return any(not lb.is_centre for lb in united_system(n))
    except ValueError:
        return False


@line_check("sec1_3-corners-centre")
def corners_centre() -> LineResult:
    """The outermost nodes and the centre, read from the two lines: the printed corner functions (as many as the
    number word says) are the functions of T_{2n} that depend on one variable only (the vertices), and the printed
    centre function, and each label of R_{2n,n,n} = G_{2n,n,n} = B_{2n,n,n}, is the function of T_{2n} of the
    highest level (the centroid), n = 1..20 (package labels)."""
    how = "exponent vectors of T_{2n} (package labels) against the functions read from the lines, n = 1..20"
    try:
        tex = verbatim("sec1_3-corners-centre")
        count = lm.sentence("The {k:count} outermost nodes", tex, search=True)
        maths = lm.inline_math(tex)
        if not count or count["k"] is None or len(maths) < 2:
            raise LatexMathError("the corner count or the functions are not read")
        corners_tex, centre_tex = maths[:-1], maths[-1]
        nodes = ("innermost", "outermost", "stored in an inner node", "vertices of the outermost")
        if not all(w in tex for w in nodes):
            raise LatexMathError("the nodes (outermost vertices, inner nodes, innermost centroid) are not read")
        corner_f = [printed_sym.monomial(t) for t in corners_tex]
        centre_f = printed_sym.monomial(centre_tex)
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    ok = len(corners_tex) == count["k"]
    for n in range(1, 21):
        labs = united_system(n)
        ex = {exponents(lb) for lb in labs}
        vertices = {e for e in ex if sum(1 for x in e if x) == 1}
        top = max(lb.j for lb in labs)
        centre = {exponents(lb) for lb in labs if lb.j == top}
        try:
            printed_corners = [f(n, 0, 0) for f in corner_f]
            members = _centre_members(n)
        except (LatexMathError, ValueError) as exc:
            return _unread(how, exc, "exhaustive")
        ok &= sorted(printed_corners) == sorted(vertices) and len(set(printed_corners)) == len(printed_corners)
        ok &= {centre_f(n, 0, 0)} == centre and set(members) == centre and len(members) == 3
    return LineResult(ok, how=how, kind="exhaustive", detail={"corners": len(corners_tex)})


def _omega_points(alpha_t: fmpq) -> list[tuple[tuple[fmpq, fmpq], ...]]:
    """Half angles (sin, cos) of (u, v, w) at interior points of Omega^alpha and at the three vertices (exact)."""
    pts = _domain_points(alpha_t, 6)
    ha, zero = _half(alpha_t), (fmpq(0), fmpq(1))
    return pts + [(ha, zero, zero), (zero, ha, zero), (zero, zero, ha)]


@line_check("sec1_3-nonnegative")
def nonnegative() -> LineResult:
    """"consist of non-negative functions": the sign word read from the line is tested on every function of
    R_{2n}, G_{2n}, B_{2n} as printed (explicit formulas and index sets parsed from their lines), by exact values
    at interior points and the vertices of Omega^alpha, tan(alpha/4) in {1/2, 99/100} (alpha up to 3.12), n = 1..6.
    A word that claims more (positive) or the opposite (negative) fails: the functions vanish at the vertices."""
    how = "exact values of the parsed R, G, B functions at points of Omega^alpha, n = 1..6"
    try:
        word, pred = sign_word(verbatim("sec1_3-nonnegative"))
        if lm.sentence("consist of {sign:word} functions", verbatim("sec1_3-nonnegative"), search=True) is None:
            raise LatexMathError("not a statement about the functions")
        funcs = {(c, h): printed_sym.explicit(c, h) for c in "RGB" for h in ("low", "high")}
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    ok, count = True, 0
    for at in (fmpq(1, 2), fmpq(99, 100)):
        pts = _omega_points(at)
        for n in range(1, 7):
            for (_c, _h), (f, iset) in funcs.items():
                for i, j in printed_sym.pairs(iset, n):
                    e = f(n, i, j)
                    if min(e) < 0:
                        ok = False
                        continue
                    for hu, hv, hw in pts:
                        value = (hu[0] ** e[0] * hu[1] ** e[1] * hv[0] ** e[2] * hv[1] ** e[3] * hw[0] ** e[4]
                                 * hw[1] ** e[5])
                        ok &= bool(pred(value))
                        count += 1
    return LineResult(ok, how=how + f" (the word read: {word!r})", kind="exhaustive",
                      detail={"word": word, "values": count})


def printed_exponents(color: str, n: int, i: int, j: int) -> tuple[int, ...] | None:
    """Exponent vector of color_{2n,2n-i,j} from the printed explicit formulas, parsed from their transcriptions
    (:func:`paper_repro.printed.symmetry.printed_exponents`), or ``None`` (no printed formula holds (i, j), or a
    negative power)."""
    return printed_sym.printed_exponents(color, n, i, j)


@line_check("sec1_3-rgb-index-sets")
def rgb_index_sets(override: dict[str, str] | None = None, n_max: int = 30) -> LineResult:
    """The index sets and member labels read from the transcriptions of eqs. R_system, G_system, B_system,
    R_system_leq_n and R_system_geq_n: for n = 1..n_max, every (i, j) of the three full systems gives non-negative
    powers in the printed explicit formulas (parsed), the full R set is the disjoint union of the two printed
    halves, and R u G u B (equal functions merged) has exactly delta_n = 3n(n+1)+1 members, the exponent vectors of
    T_{2n} (:func:`~paper_repro.core.labels.united_system`).  ``override`` replaces transcriptions (tests)."""
    text = {k: (override or {}).get(k, verbatim(k)) for k in INDEX_SET_LINES}
    how = "index sets read from the transcriptions"
    bad: list[str] = []
    try:
        for color, key in zip("RGB", INDEX_SET_LINES[:3]):
            if _member_labels(text[key]) != [(color, "2*n - i", "j", (0, 1, 2))]:
                raise LatexMathError(f"{key}: the member is not {color}_{{2n,2n-i,j}}(u,v,w)")
        _, leq = printed_sym.set_builders(text["sec1_3-R-leq-n"])
        if not leq or printed_sym.label_of(leq[0][0]) != ("R", "2*n - i", "j", (0, 1, 2)):
            raise LatexMathError("sec1_3-R-leq-n: the left side is not R_{2n,2n-i,j}(u,v,w)")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    for color, key in zip("RGB", INDEX_SET_LINES[:3]):
        try:
            head = lm.clean(text[key].split("\\left\\{", 1)[0]).replace(" ", "")
        except LatexMathError as exc:
            return _unread(how, exc, "exhaustive")
        if head != f"{color}_{{2n}}^{{\\alpha}}=":
            return _unread(how, LatexMathError(f"{key}: not '{color}_{{2n}}^alpha = ..' but {head!r}"), "exhaustive")
    for n in range(1, n_max + 1):
        try:
            sets = {k: _read_pairs(text[k], n) for k in INDEX_SET_LINES}
        except ValueError as exc:
            return _unread(how, exc, "exhaustive")
        for color, key in zip("RGB", INDEX_SET_LINES[:3]):
            if sorted(sets[key]) != sorted((lb.i, lb.j) for lb in full_system(n, color)):
                bad.append(f"n={n}: the printed {color}_{{2n}} is not the graph's (package full system)")
        funcs = set()
        for color, key in zip("RGB", INDEX_SET_LINES[:3]):
            for i, j in sets[key]:
                e = printed_exponents(color, n, i, j)
                if e is None:
                    bad.append(f"n={n}: {color}_{{{2 * n},{2 * n - i},{j}}} has no printed formula or a negative power")
                else:
                    funcs.add(e)
        full, low, high = (set(sets[k]) for k in ("sec1_3-R-system", "sec1_3-R-leq-n", "sec1_3-R-geq-n-relation"))
        if low & high or low | high != full or len(full) != len(sets["sec1_3-R-system"]):
            bad.append(f"n={n}: the R set is not the disjoint union of its printed halves")
        if len(funcs) != 3 * n * (n + 1) + 1 or funcs != {exponents(lb) for lb in united_system(n)}:
            bad.append(f"n={n}: R u G u B has {len(funcs)} distinct functions, not those of T_{{2n}}")
    return LineResult(not bad, how=f"index sets read from the transcriptions, powers of the printed explicit formulas "
                      f"(parsed) and the distinct functions of R u G u B against delta_n and T_{{2n}}, n = 1..{n_max}",
                      kind="exhaustive", detail={"n_max": n_max, "problems": bad[:3]})


@line_check("sec1_3-order-n3")
def order_n3() -> LineResult:
    """"T_{6}^alpha of order 3" and the caption's "of order n=3", read from the lines: the subscript of T must be
    the 2n of eq. united_system (its T_{2n} read from that line) at the printed order, and the caption's n the same
    order; the system of that order has delta_n = 3n(n+1)+1 = 37 distinct functions in n levels and a centre
    (package labels).  The figure itself (an image, empty in the source) cannot be read."""
    how = "the printed subscript and orders against eq. united_system's T_{2n} and the labels of T_{2n}"
    try:
        words, segs = lm.prose(verbatim("sec1_3-T6-order-3"))  # '$T_{6}^{\alpha}$ of order $3$'
        cap_words, cap_segs = lm.prose(verbatim("sec1_3-fig-united-n3-caption"))  # '.. of order $n=3$.'
        united = lm.parse_relation(verbatim("sec1_3-united-system"))  # 'T_{2n}^{\alpha} & = & \left\{..'
        frame = "joint function system (\\ref{united_system}) of order $$"
        if words != "$$ of order $$" or len(segs) != 2 or frame not in cap_words or len(cap_segs) != 1:
            raise LatexMathError("the subscript or the orders are not read")
        t_sub, order_e, cap = lm.parse(segs[0]), lm.parse(segs[1]), lm.parse_relation(cap_segs[0])
        head = united.parts[0] if united.parts else None
        if not (isinstance(t_sub, AppliedUndef) and t_sub.func.__name__ == "T" and len(t_sub.args) == 1
                and t_sub.args[0].is_Integer and order_e.is_Integer and isinstance(head, AppliedUndef)
                and head.func.__name__ == "T" and len(head.args) == 1 and cap.ops == ["="]
                and cap.parts[0] == sympy.Symbol("n") and cap.parts[1].is_Integer and not cap.conditions):
            raise LatexMathError("the subscript or the orders are not read")
        if lm.untagged(segs[0]) or any(f.func.__name__ == "T" for f in lm.untagged(verbatim("sec1_3-united-system"))):
            raise LatexMathError("T printed without its tag alpha")
        sub, order, cap_n = int(t_sub.args[0]), int(order_e), int(cap.parts[1])
        ok = sub == _env_int(head.args[0], n=order) and cap_n == order
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc)
    labs = united_system(order)
    levels_ = {lb.j for lb in labs if not lb.is_centre}
    ok &= len({exponents(lb) for lb in labs}) == len(labs) == 3 * order * (order + 1) + 1 and levels_ == set(
        range(order))
    return LineResult(ok, how=how, detail={"order": order, "functions": len(labs)})


def _edge_points() -> list[tuple[fmpq, tuple[fmpq, fmpq], tuple[fmpq, fmpq]]]:
    """(tan(alpha/4), half angles of alpha, half angles of x) for exact points x in [0, alpha] (ends included)."""
    out = []
    for at in ALPHA_TS:
        for xf in (fmpq(0), fmpq(1, 3), fmpq(5, 7), fmpq(1)):
            out.append((at, _half(at), _half(at * xf)))
    return out


def _boundary(line_id: str) -> LineResult:
    """T_{2n} restricted to {x = 0} (read from the line: the variable, its value, the member A_{2n,a}(y)/c_{2n,b}
    and the index range): the non-vanishing restrictions of the functions of T_{2n} (package labels) are, as a
    multiset of exact functions on the edge (values at 4 points each for two alpha), the printed members with A
    from the definition of eq. univariate_basis and c from the expansion (n = 1..6)."""
    how = "exact values on the edge of the restricted T_{2n} (package labels) and of the printed members, n = 1..6"
    tex = verbatim(line_id)
    try:
        rel = lm.parse_relation(tex)  # Subs(T(2*n), v, 0) = Family(A(2*n, 2*n - i, (u,))/c(..), (In(u, ..),), (..))
        if len(rel.parts) != 2 or rel.ops != ["="] or rel.conditions or not isinstance(rel.parts[0], sympy.Subs):
            raise LatexMathError("no restriction T|_{x=a} = {..}_{i=..}^{..}")
        restricted, fam = rel.parts
        (t_fn,), (var_s,), (value,) = [restricted.expr], restricted.variables, restricted.point
        if not isinstance(t_fn, AppliedUndef) or t_fn.func.__name__ != "T" or len(t_fn.args) != 1 or \
                str(var_s) not in printed_sym.VARS:
            raise LatexMathError(f"not a restriction of T_{{..}}: {restricted}")
        t_order, var = t_fn.args[0], str(var_s)
        if not (isinstance(fam, AppliedUndef) and fam.func == lm.Family) or len(fam.args[1]) != 1 or \
                len(fam.args[2]) != 1:
            raise LatexMathError(f"the restriction is not equated to a set with one condition and one bound: {fam}")
        member, (cond,), ((iv, ilo, ihi),) = fam.args
        dom_var, dom = cond.args if cond.func.__name__ == "In" and len(cond.args) == 2 else (None, None)
        a_terms = [f for f in member.atoms(AppliedUndef) if f.func.__name__ == "A"]
        if len(a_terms) != 1 or not isinstance(dom_var, sympy.Symbol) or len(a_terms[0].args[2]) != 1:
            raise LatexMathError("the member is not one A_{2n,..}(x)/c")
        x = str(a_terms[0].args[2][0])
        if x != str(dom_var) or x == var or dom != sympy.Interval(0, sympy.Symbol("alpha")):
            raise LatexMathError(f"argument {x} on {dom} is not a remaining variable on [0, alpha]")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    rest = [k for k in range(3) if k != printed_sym.VARS.index(var)]
    y = [printed_sym.VARS[k] for k in rest if printed_sym.VARS[k] != x][0]
    ok = True
    for n in range(1, 7):
        if _env_int(t_order, n=n) != 2 * n:
            return LineResult(False, how=how, kind="exhaustive", detail={"order": str(t_order)})
        try:
            zero = _env_int(value, n=n) == 0
            idx = range(_env_int(ilo, n=n), _env_int(ihi, n=n) + 1)
        except (LatexMathError, ValueError) as exc:
            return _unread(how, exc, "exhaustive")
        for _at, ha, hx in _edge_points():
            hy = _diff_half(ha, hx)
            half = {x: hx, y: hy, var: (fmpq(0), fmpq(1))}
            computed = []
            for lb in united_system(n):
                e = exponents(lb)
                if zero and e[2 * printed_sym.VARS.index(var)] > 0:
                    continue  # vanishes on the edge
                computed.append(_mono_value(e, half))
            printed = []
            for i in idx:
                try:
                    printed.append(_edge_value(member, n, i, ha, hx, hy))
                except (LatexMathError, ValueError):
                    printed.append(None)
            ok &= sorted(computed) == sorted(printed) if None not in printed else False
    return LineResult(ok, how=how, kind="exhaustive", detail={"variable": var, "argument": x})


def _mono_value(e: tuple[int, ...], half: dict[str, tuple[fmpq, fmpq]]) -> fmpq:
    out = fmpq(1)
    for k, v in enumerate(printed_sym.VARS):
        out *= half[v][0] ** e[2 * k] * half[v][1] ** e[2 * k + 1]
    return out


def _edge_value(member: sympy.Expr, n: int, i: int, ha, hx, hy) -> fmpq:
    """Exact value of the printed member at order n, index i, where A_{2m,k}(x) = c_{2m,k} sin^{2m-k}((alpha-x)/2)
    sin^k(x/2) (the definition) with the expansion's c, at the point with half angles hx of x, hy of alpha - x."""

    def a_fn(order, k, _args):
        m2, kk = _env_int(order, n=n, i=i), _env_int(k, n=n, i=i)
        if m2 != 2 * n:
            raise LatexMathError("A of another order")
        return c_exact(n, kk, *ha) * hy[0] ** (m2 - kk) * hx[0] ** kk

    def c_fn(order, k):
        m2, kk = _env_int(order, n=n, i=i), _env_int(k, n=n, i=i)
        if m2 % 2:
            raise LatexMathError("c of odd order")
        return c_exact(m2 // 2, kk, *ha)

    out = fmpq(1)
    for factor in sympy.Mul.make_args(member):
        base, ex = factor.as_base_exp()
        if isinstance(base, AppliedUndef) and base.func.__name__ in ("A", "c"):
            v = a_fn(*base.args) if base.func.__name__ == "A" else c_fn(*base.args)
        elif base.is_Integer:
            v = fmpq(int(base))
        else:
            raise LatexMathError(f"factor {base} of the member is not read")
        out *= v ** int(ex)
    return out


@line_check("sec1_3-boundary-v0")
def boundary_v0() -> LineResult:
    return _boundary("sec1_3-boundary-property-1")


@line_check("sec1_3-boundary-u0")
def boundary_u0() -> LineResult:
    return _boundary("sec1_3-boundary-property-2")


@line_check("sec1_3-boundary-w0")
def boundary_w0() -> LineResult:
    return _boundary("sec1_3-boundary-property-3")


def _angle_points() -> list[tuple[fmpq, fmpq, fmpq]]:
    """(tan(alpha/4), sin(alpha/2), cos(alpha/2)) for the sampled alpha."""
    return [(at, *_half(at)) for at in (fmpq(1, 5), *ALPHA_TS, fmpq(19, 20))]


def _trig_exact(expr: sympy.Expr, sin_half: fmpq, cos_half: fmpq) -> fmpq:
    """Exact value of an expression in sin(alpha/2), cos(alpha/2) and numbers (``LatexMathError`` otherwise)."""
    a = sympy.Symbol("alpha")
    s_, c_ = sympy.Symbol("S_"), sympy.Symbol("C_")
    e = expr.xreplace({sympy.sin(a / 2, evaluate=False): s_, sympy.cos(a / 2, evaluate=False): c_})
    e = e.xreplace({sympy.sin(a / 2): s_, sympy.cos(a / 2): c_})
    if e.free_symbols - {s_, c_} or e.atoms(sympy.Function):
        raise LatexMathError(f"{expr} is not a function of the half angle of alpha")
    v = e.subs({s_: sympy.Rational(int(sin_half.p), int(sin_half.q)),
                c_: sympy.Rational(int(cos_half.p), int(cos_half.q))})
    if not v.is_Rational:
        raise LatexMathError(f"{expr} is not rational at a rational half angle")
    return fmpq(int(v.p), int(v.q))


@line_check("sec1_3-c-formula")
def c_formula() -> LineResult:
    """The printed c_{2n,i}^alpha (parsed: the 1/sin^{2n}(alpha/2), the sum over r with its floor bound, the
    binomials and the power of 2cos(alpha/2); its range i = 0, 1, ..., 2n) equal, exactly at four rational-tangent
    alpha for n = 1..6, the coefficients of X^{2n-i} Y^i in (X^2 + 2cos(alpha/2) X Y + Y^2)^n over
    sin^{2n}(alpha/2) (the expansion); the range is all 2n+1 indices of eq. univariate_basis; the printed sign word
    holds of the values and the printed c normalize: sum_i c_{2n,i} sin^{2n-i}((alpha-t)/2) sin^i(t/2) = 1 exactly
    at two points t per alpha."""
    tex = verbatim("sec1_3-c-formula")
    how = "exact values of the parsed formula against the expansion, n = 1..5 at 4 alpha (tan(alpha/4) rational)"
    try:
        word, pred = sign_word(tex.split("\\[", 1)[0])
        if "normalizing" not in lm.prose(tex.split("\\[", 1)[0])[0].split():
            raise LatexMathError("the coefficients are not said to normalize")
        display = tex.split("\\[", 1)[1].split("\\]", 1)[0]
        (lhs, rhs), lo, hi = equation_over(display, "i")
        if not (isinstance(lhs, AppliedUndef) and lhs.func.__name__ == "c" and len(lhs.args) == 2):
            raise LatexMathError(f"left side {lhs} is not c_{{2n,i}}")
        if sympy.simplify(lhs.args[0] - 2 * sympy.Symbol("n")) != 0 or lhs.args[1] != sympy.Symbol("i"):
            raise LatexMathError(f"left side {lhs} is not c_{{2n,i}}")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    ok, bad = True, []
    n_, i_ = sympy.symbols("n i")
    for n in range(1, 6):
        rng = list(range(_env_int(lo, n=n), _env_int(hi, n=n) + 1))
        ok &= rng == list(range(2 * n + 1))
        values: dict[tuple, fmpq] = {}
        for i in rng:
            e = rhs.subs({n_: n, i_: i}).doit()
            for at, sh, ch in _angle_points():
                try:
                    v = values[at, i] = _trig_exact(e, sh, ch)
                except (LatexMathError, ValueError, ZeroDivisionError) as exc:
                    return _unread(how, exc, "exhaustive")
                good = 0 <= i <= 2 * n and v == c_exact(n, i, sh, ch) and pred(v)
                ok &= good
                if not good and len(bad) < 3:
                    bad.append(f"n={n}, i={i}")
        for at, sh, ch in _angle_points():
            for xf in X_FRACTIONS:
                hx = _half(at * xf)
                hy = _diff_half((sh, ch), hx)
                total = sum((values[at, i] * hy[0] ** (2 * n - i) * hx[0] ** i for i in rng if 0 <= i <= 2 * n),
                            fmpq(0))
                ok &= total == 1
    return LineResult(ok, how=how + f"; the word read: {word!r}", kind="exhaustive",
                      detail={"n_max": 5, "mismatches": bad})


@line_check("sec1_3-c-symmetry")
def c_symmetry() -> LineResult:
    """c_{2n,a}^alpha = c_{2n,b}^alpha for i in the printed range (a, b and the range parsed): holds exactly for
    the coefficients from the expansion at four alpha, n = 1..30 (polynomials in cos(alpha/2), n = 1..30, so for
    every alpha); and the printed range with its mirror images i -> 2n-i covers all i = 0..2n (the symmetry of the
    whole sequence)."""
    tex = verbatim("sec1_3-c-symmetry")
    how = "the parsed relation and range against the expansion's coefficients, n = 1..30"
    try:
        (lhs, rhs), lo, hi = equation_over(tex, "i")
        for side in (lhs, rhs):
            if not (isinstance(side, AppliedUndef) and side.func.__name__ == "c" and len(side.args) == 2):
                raise LatexMathError(f"{side} is not a c_{{..,..}}")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")
    ok = True
    for n in range(1, 31):
        polys = c_numerator_by_expansion(n)
        rng = range(_env_int(lo, n=n), _env_int(hi, n=n) + 1)
        covered = set()
        for i in rng:
            (oa, a), (ob, b) = ([_env_int(x, n=n, i=i) for x in side.args] for side in (lhs, rhs))
            if not (oa == ob == 2 * n and 0 <= a <= 2 * n and 0 <= b <= 2 * n and polys[a] == polys[b]):
                ok = False
                break
            covered |= {i, 2 * n - i}
        ok &= covered | {n} == set(range(2 * n + 1))  # i = n is its own mirror: c_{2n,n} = c_{2n,n} says nothing
    return LineResult(ok, how=how, kind="exhaustive", detail={"n_max": 30})


def _fourier_rows(members: list[sympy.Expr], names_: tuple[str, ...], ranges, pts) -> list[list[fmpq]]:
    """Exact collocation rows of the printed Fourier system: each member cos/sin of a linear combination of u, v, w
    with integer coefficients, for every index triple of the printed ranges."""
    out = []
    u, v, w = sympy.symbols("u v w")
    triples = [(a, b, c) for a in range(*ranges[0]) for b in range(*ranges[1]) for c in range(*ranges[2])]
    forms = []
    for (r, g, b) in triples:
        env = dict(zip(names_, (r, g, b)))
        for f in members:
            if not isinstance(f, (sympy.sin, sympy.cos)):
                raise LatexMathError(f"member {f} is not a cosine or sine")
            arg = sympy.expand(f.args[0].subs({sympy.Symbol(k): x for k, x in env.items()}))
            poly = sympy.Poly(arg, u, v, w)
            if poly.total_degree() > 1 or poly.coeff_monomial(1) != 0 or arg.free_symbols - {u, v, w}:
                raise LatexMathError(f"argument {arg} is not a linear form in u, v, w")
            forms.append((isinstance(f, sympy.sin), [int(poly.coeff_monomial(x)) for x in (u, v, w)]))
    for hu, hv, hw in pts:
        e = [_angle(h) for h in (hu, hv, hw)]
        row = []
        for is_sin, coeffs in forms:
            z = (fmpq(1), fmpq(0))
            for base, k in zip(e, coeffs):
                z = _cmul(z, _cpow(base if k >= 0 else (base[0], -base[1]), abs(k)))
            row.append(z[1] if is_sin else z[0])
        out.append(row)
    return out


@line_check("sec1_3-fourier-dimension")
def fourier_dimension() -> LineResult:
    """The system {cos(ru+gv+bw), sin(ru+gv+bw)}_{r,g,b=0}^{n} (members and index ranges parsed from the line) on
    Omega^alpha spans a space of dimension delta_n (the printed 3n(n+1)+1, parsed) equal to span T_{2n}; and the
    abstract's truncated Fourier series of the printed order give the same span (exact collocation ranks modulo a
    61-bit prime at delta_n + 12 points, n = 1..3)."""
    how = "exact collocation ranks modulo 2^61-1 at delta_n + 12 points, tan(alpha/4) = 1/2, n = 1..3"
    try:
        sys_tex = verbatim("sec1_3-fourier-system")
        if "largest linearly independent subset" not in sys_tex:
            raise LatexMathError("V_n is not the largest linearly independent subset")
        rel = lm.parse_relation(sys_tex)  # the display after the words
        fam = rel.parts[0] if len(rel.parts) == 1 and not rel.ops and not rel.conditions else None
        if not (isinstance(fam, sympy.Function) and fam.func == lm.Family) or len(fam.args[2]) != 3:
            raise LatexMathError("no set {..}_{r=..,g=..,b=..}^{..,..,..}")
        member, conds, bounds = fam.args
        names_ = tuple(str(v) for v, _lo, _hi in bounds)
        los, his = [lo for _v, lo, _hi in bounds], [hi for _v, _lo, hi in bounds]
        uvw = sympy.symbols("u v w")
        if [str(c) for c in conds] != ["In((u, v, w), Omega)"]:  # the tag ^{\alpha} dropped, another refused
            raise LatexMathError("the domain is not (u,v,w) in Omega^alpha")
        members = list(member) if isinstance(member, sympy.Tuple) else [member]
        # the trivariate extension of the canonical basis {cos(it), sin(it)}: a cosine and a sine of one argument
        # r u + g v + b w, each index with its own variable
        if not all(isinstance(f, (sympy.sin, sympy.cos)) for f in members):
            raise LatexMathError(f"members {members} are not cosines and sines")
        args = {f.args[0] for f in members}
        kinds = sorted(type(f).__name__ for f in members)
        if len(args) != 1 or kinds != ["cos", "sin"]:
            raise LatexMathError("the members are not the cosine and the sine of one argument")
        coeffs = [sympy.Poly(next(iter(args)), *uvw).coeff_monomial(x) for x in uvw]
        if sorted(str(c) for c in coeffs) != sorted(names_):
            raise LatexMathError(f"the argument {args} does not give each index its own variable")
        dim_words, dim_segs = lm.prose(verbatim("sec1_3-span-coincide-dim"))
        same_words, same_segs = lm.prose(verbatim("sec1_3-abstract-same-span"))
        if dim_words != "along with the determination of the common dimension $$ of these vector spaces" or \
                same_words != ("that spans the same vector space of functions as the constrained trivariate extension "
                               "of the canonical basis of truncated Fourier series of order $$ over") or \
                len(dim_segs) != 1 or len(same_segs) != 1:
            raise LatexMathError("the common dimension or the abstract's order is not read")
        dim = lm.parse_relation(dim_segs[0])
        if dim.ops != ["="] or str(dim.parts[0]) != "delta(n)" or dim.conditions:
            raise LatexMathError(f"not delta_n = ..: {dim_segs[0]!r}")
        delta_printed, order = dim.parts[1], lm.parse(same_segs[0])
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc)
    detail, ok = {}, True
    for n in (1, 2, 3):
        pts = _domain_points(ALPHA_TS[0], delta(n) + 12)
        try:
            ranges = [(_env_int(a, n=n), _env_int(b, n=n) + 1) for a, b in zip(los, his)]
            rows_f = _fourier_rows(members, names_, ranges, pts)
            k = _env_int(order, n=n)
            rows_a = _fourier_rows(members, names_, [(0, k + 1)] * 3, pts)
            d_printed = _env_int(delta_printed, n=n)
        except (LatexMathError, ValueError) as exc:
            return _unread(how, exc)
        rows_t = [[hu[0] ** e[0] * hu[1] ** e[1] * hv[0] ** e[2] * hv[1] ** e[3] * hw[0] ** e[4] * hw[1] ** e[5]
                   for e in (exponents(lb) for lb in united_system(n))] for hu, hv, hw in pts]
        rf, rt, rj = _rank(rows_f), _rank(rows_t), _rank([a + b for a, b in zip(rows_f, rows_t)])
        ra, raj = _rank(rows_a), _rank([a + b for a, b in zip(rows_a, rows_t)])
        detail[str(n)] = {"rank_fourier": rf, "rank_T": rt, "rank_joint": rj, "rank_abstract": ra,
                          "printed_delta": d_printed}
        ok &= rf == rt == rj == ra == raj == d_printed
    return LineResult(ok, how=how, detail=detail)


@line_check("sec1_3-univariate-span")
def univariate_span() -> LineResult:
    """{A_{2n,i}(t)}_{i=0}^{2n} = {c_{2n,i} sin^{2n-i}((alpha-t)/2) sin^i(t/2)}_{i=0}^{2n} (members, argument, domain
    and both index ranges parsed from the line): the printed members, with c from the expansion, are 2n+1 linearly
    independent functions spanning F_{2n}^alpha = span{cos(it), sin(it)}_{i=0}^{n} and sum to 1 (a normalized
    basis), exactly at 2n+6 rational points of [0, alpha], n = 1..5."""
    tex = verbatim("sec1_3-univariate-basis")
    how = "exact collocation ranks (printed members | Fourier) and partition of unity at 2n+6 points, n = 1..5"
    try:
        left, right = _single_sets(tex)
        (lb, (lv, llo, lhi), ldom), (rb, (rv, rlo, rhi), rdom) = left, right
        lhs, member = lb, rb
        if (lv, llo, lhi) != (rv, rlo, rhi) or ldom != rdom or ldom[:2] != ("t", (True, 0, sympy.Symbol("alpha"),
                                                                                   True)):
            raise LatexMathError("the two sides are not on one index set and one domain t in [0, alpha]")
        if not (isinstance(lhs, AppliedUndef) and lhs.func.__name__ == "A" and lhs.args[1] == sympy.Symbol(lv)
                and tuple(lhs.args[2]) == (sympy.Symbol("t"),)):
            raise LatexMathError(f"left member {lhs} is not A_{{2n,{lv}}}(t)")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc)
    detail, ok = {}, True
    n_, t_ = sympy.Symbol("n"), sympy.Symbol("t")
    for n in range(1, 6):
        at = ALPHA_TS[0]
        ha = _half(at)
        try:
            idx = range(_env_int(rlo, n=n), _env_int(rhi, n=n) + 1)
            if _env_int(lhs.args[0], n=n) != 2 * n:
                raise LatexMathError("A of another order")
        except (LatexMathError, ValueError) as exc:
            return _unread(how, exc)
        rows_a, rows_f = [], []
        for k in range(2 * n + 6):
            hx = _half(at * fmpq(k, 2 * n + 5))
            hy = _diff_half(ha, hx)
            row = []
            for i in idx:
                try:
                    row.append(_member_value(member.subs({n_: n, sympy.Symbol(lv): i}), n, ha, hx, hy, t_))
                except (LatexMathError, ValueError):
                    return LineResult(False, how=how, detail={"member": str(member), "i": i})
            rows_a.append(row)
            rows_f.append([q for m in range(n + 1) for q in _cpow(_angle(hx), m)])
        ra, rf, rj = _rank(rows_a), _rank(rows_f), _rank([x + y for x, y in zip(rows_a, rows_f)])
        unity = all(sum(r, fmpq(0)) == 1 for r in rows_a)
        detail[str(n)] = [ra, rf, rj, unity]
        ok &= ra == rj == rf == 2 * n + 1 == len(idx) and unity
    return LineResult(ok, how=how, detail=detail)


def _single_sets(tex: str):
    """The two set-builders ``\\left\\{ body : x\\in\\left[ a,b\\right] \\right\\} _{i=lo}^{hi}`` of an equality
    (:func:`latex_math.parse_relation`: two ``Family`` parts, each with one condition and one bound):
    [(member, (i, lo, hi), (x, interval)), ...], the member and the bounds parsed, ``interval`` as
    :func:`interval_of`."""
    rel = lm.parse_relation(tex)
    if rel.ops != ["="] or rel.conditions:
        raise LatexMathError(f"not one equality of two sets: {rel.ops}")
    out = []
    for fam in rel.parts:
        if not (isinstance(fam, AppliedUndef) and fam.func == lm.Family) or len(fam.args[1]) != 1 or \
                len(fam.args[2]) != 1:
            raise LatexMathError(f"{fam} is not a set with one condition and one bound")
        member, (cond,), ((iv, ilo, ihi),) = fam.args
        if cond.func.__name__ != "In" or len(cond.args) != 2 or not isinstance(cond.args[0], sympy.Symbol):
            raise LatexMathError(f"no domain in {cond}")
        out.append((member, (str(iv), ilo, ihi), (str(cond.args[0]), interval_of(cond.args[1]))))
    if len(out) != 2:
        raise LatexMathError(f"{len(out)} sets, not 2")
    return out


def _member_value(e: sympy.Expr, n: int, ha, hx, hy, t: sympy.Symbol) -> fmpq:
    """Exact value of c_{2n,i} sin^a((alpha-t)/2) sin^b(t/2) (c from the expansion) at half angles hx of t."""
    alpha = sympy.Symbol("alpha")
    out = fmpq(1)
    for factor in sympy.Mul.make_args(e):
        base, ex = factor.as_base_exp()
        if isinstance(base, AppliedUndef) and base.func.__name__ == "c":
            o, k = (int(x) for x in base.args)
            if o != 2 * n:
                raise LatexMathError("c of another order")
            v = c_exact(n, k, *ha)
        elif isinstance(base, sympy.sin) and sympy.simplify(base.args[0] - (alpha - t) / 2) == 0:
            v = hy[0]
        elif isinstance(base, sympy.sin) and sympy.simplify(base.args[0] - t / 2) == 0:
            v = hx[0]
        elif base.is_Integer:
            v = fmpq(int(base))
        else:
            raise LatexMathError(f"factor {base} not read")
        if not ex.is_Integer or ex < 0:
            raise LatexMathError(f"power {ex} is not a non-negative integer")
        out *= v ** int(ex)
    return out


# -- Proposition Bernstein and its proof ------------------------------------------------------------------------
def _display(tex: str, start: str, stop: str) -> str:
    body = tex.split(start, 1)[1] if start in tex else tex
    return body.split(stop, 1)[0] if stop and stop in body else body


def _s_samples(lo, hi) -> list:
    lo, hi = mpmath.mpf(lo), mpmath.mpf(hi)
    return [lo, hi, lo + (hi - lo) / 3, lo + 5 * (hi - lo) / 7]


def _quantified(rel: lm.Relation) -> tuple[str, list]:
    """(quantifier, sample values of s) of the printed clause ``,~\\forall s\\in\\left[ a,b\\right]`` of a parsed
    relation (:func:`latex_math.parse_relation`, the one clause over s with a quantifier); the interval must be the
    one that the reparametrization t = alpha s of Proposition Bernstein maps onto the domain [0, alpha] of t
    (eq. univariate_basis): closed, alpha a = 0 and alpha b = alpha."""
    found = [c for c in rel.conditions if c.quantifier in ("forall", "exists") and c.ops == ["in"]
             and c.parts[0] == sympy.Symbol("s")]
    if len(found) != 1:
        raise LatexMathError("no quantifier over s")
    s_interval(found[0].parts[1])
    return found[0].quantifier, _s_samples(0, 1)


def s_interval(iv) -> None:
    """Refuse an interval of s (parsed) that t = alpha s does not map onto [0, alpha]."""
    if not isinstance(iv, sympy.Interval):
        raise LatexMathError(f"s in {iv}: not an interval")
    alpha = sympy.Symbol("alpha")
    if iv.left_open or iv.right_open or sympy.simplify(alpha * iv.start) != 0 or \
            sympy.simplify(alpha * iv.end - alpha) != 0:
        raise LatexMathError(f"s in {iv}: t = alpha s does not cover [0, alpha]")


_LIMIT_WORDS = ("If one uses the linear reparametrization $$, then basis functions (\\ref{univariate_basis}) of order "
                "$$ converge to the Bernstein polynomials of degree $$ when $$, i.e.,%")


@line_check("sec1_3-bernstein-limit")
def bernstein_limit() -> LineResult:
    """lim_{alpha->0} A_{2n,i}^alpha(alpha s) = B_i^{2n}(s), s in [0,1], i = 0..2n, read from the line (the limit
    point, the argument, which must be the printed reparametrization t(s) = alpha s, the Bernstein indices, the range,
    the interval, the "degree $2n$" and "order $n$" of the prose): A from the definition of eq. univariate_basis
    with the expansion's c, evaluated at alpha = limit point + 1e-15 with 60 digits, is within 1e-20 of B_k^d(s)
    (the error is O(alpha^2)), n = 1..5, four s per interval; the coefficient limit is exact: sin^{2n}(alpha/2)
    c_{2n,i} -> its numerator at cos = 1 = binom(2n, i) (n <= 15)."""
    tex = verbatim("sec1_3-bernstein-limit")
    how = "60-digit values at alpha = 1e-15 of the parsed limit, n = 1..5; exact coefficient limit n <= 15"
    try:
        words, segs = lm.prose(tex.split("\\begin{equation}", 1)[0])
        if words != _LIMIT_WORDS or len(segs) != 4:
            raise LatexMathError("the reparametrization, degree or order is not read")
        rep, lim = lm.parse_relation(segs[0]), lm.parse_relation(segs[3])
        s_ = sympy.Symbol("s")  # t\\left( s\\right) is read as the product t*s (one parenthesised expression)
        if rep.ops != ["="] or rep.parts[0] != sympy.Symbol("t") * s_ or len(rep.conditions) != 1 or \
                rep.conditions[0].ops != ["in"] or rep.conditions[0].parts[0] != s_:
            raise LatexMathError(f"not the reparametrization t(s) = .., s in ..: {segs[0]!r}")
        s_interval(rep.conditions[0].parts[1])
        if lim.ops != ["->"] or lim.parts[0] != sympy.Symbol("alpha") or lim.conditions:
            raise LatexMathError(f"not alpha -> ..: {segs[3]!r}")
        t_of_s, order_n, degree, prose_point = rep.parts[1], lm.parse(segs[1]), lm.parse(segs[2]), lim.parts[1]
        rel = lm.parse_relation(_display(tex, "\\begin{equation}", "\\label"))
        if rel.lead is not None or rel.ops != ["="] or len(rel.conditions) != 2:
            raise LatexMathError("not one equation with the clauses over s and i")
        lhs, rhs = rel.parts
        quant, s_vals = _quantified(rel)
        if quant != "forall":
            raise LatexMathError("the limit is not claimed for all s")
        lo, hi = listed(rel, "i")
        if not isinstance(lhs, sympy.Limit):
            raise LatexMathError("the left side is not a limit")
        body, var, point = lhs.args[0], lhs.args[1], lhs.args[2]
        if var != sympy.Symbol("alpha") or point != prose_point:
            raise LatexMathError("the limit is not alpha -> the prose's point")
        a_term = body
        if not (isinstance(a_term, AppliedUndef) and a_term.func.__name__ == "A"):
            raise LatexMathError("the limit is not of one A")
        if sympy.simplify(a_term.args[2][0] - t_of_s) != 0:
            raise LatexMathError("the argument is not the printed reparametrization")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "numeric-evidence")
    exact = all(sum(c_numerator(n, i)) == comb(2 * n, i) for n in range(1, 16) for i in range(2 * n + 1))
    worst, ok = mpmath.mpf(0), exact
    with mpmath.workdps(60):
        alpha = num(point, {}) + mpmath.mpf("1e-15")
        for n in range(1, 6):
            try:
                rng = range(_env_int(lo, n=n), _env_int(hi, n=n) + 1)
                ok &= list(rng) == list(range(2 * n + 1)) and _env_int(order_n, n=n) == n
                ok &= _env_int(degree, n=n) == _env_int(rhs.args[1], n=n, i=0) and _env_int(a_term.args[0], n=n) \
                    == 2 * _env_int(order_n, n=n)
                for i in rng:
                    for s in s_vals:
                        env = {"n": n, "i": i, "s": s, "alpha": alpha}
                        worst = max(worst, abs(num(body, env) - num(rhs, env)))
            except (LatexMathError, ValueError, ZeroDivisionError) as exc:
                return _unread(how, exc, "numeric-evidence")
    ok = bool(ok and worst < mpmath.mpf("1e-20"))
    return LineResult(ok, how=how, kind="numeric-evidence",
                      detail={"coefficient_limit_exact": exact, "below_1e-20": ok})


def _a_identity(parts: list[sympy.Expr], quant: str, s_vals: list, scale=1) -> bool:
    """Whether the chain ``parts`` (all equal) holds at the sampled s (``forall``: every; ``exists``: some), for
    n = 1..4 at alpha in {0.4, 1.3, 2.9}, 40 digits; with ``scale`` the sines in every A are scaled (the identity
    as homogeneous polynomials in the sines, :func:`~paper_repro.claims.lines.sec12_eval.a_value`)."""
    results = []
    with mpmath.workdps(40):
        for n in range(1, 5):
            for alpha in (mpmath.mpf("0.4"), mpmath.mpf("1.3"), mpmath.mpf("2.9")):
                for s in s_vals:
                    env = {"n": n, "s": s, "alpha": alpha, "_scale": scale}
                    vals = [num(p, env) for p in parts]
                    results.append(all(abs(v - vals[0]) < mpmath.mpf("1e-30") for v in vals))
    return all(results) if quant == "forall" else any(results)


def _read_chain(line_id: str) -> tuple[list[sympy.Expr], str, list]:
    tex = verbatim(line_id)
    rel = lm.parse_relation(_display(tex, "\\[", "\\]"))
    if rel.lead is not None or any(op != "=" for op in rel.ops) or len(rel.conditions) != 1:
        raise LatexMathError(f"not an equality chain with one clause over s: {rel.ops} {len(rel.conditions)} clauses")
    parts = rel.parts
    quant, s_vals = _quantified(rel)
    if len(parts) < 2:
        raise LatexMathError("not an equality")
    return parts, quant, s_vals


def _order_one(e: sympy.Expr, also_argument: bool = False) -> sympy.Expr:
    """The correction of the proof: every A_{2n,k}(x) of ``e`` becomes A_{2,k}(x) (order 1), and with
    ``also_argument`` an argument s becomes alpha s."""
    s, alpha = sympy.Symbol("s"), sympy.Symbol("alpha")

    def fix(f):
        arg = f.args[2]
        if also_argument and tuple(arg) == (s,):
            arg = sympy.Tuple(alpha * s)
        return sympy.Function("A")(2, f.args[1], arg)

    return e.replace(lambda x: isinstance(x, AppliedUndef) and x.func.__name__ == "A", fix)


@line_check("sec1_3-bernstein-identity")
def bernstein_identity() -> LineResult:
    """The printed identity (parsed: its terms, their orders, indices and arguments, the right side, the quantifier
    and the interval of s), evaluated with A from the definition of eq. univariate_basis: false for n >= 2; the
    corrected identity (the same line with every A_{2n,k} of order 1: A_{2,k}) holds (n = 1..4, three alpha, four s,
    40 digits)."""
    how = "40-digit values of the parsed identity and of its order-1 correction, n = 1..4"
    try:
        parts, quant, s_vals = _read_chain("sec1_3-bernstein-identity")
        printed = _a_identity(parts, quant, s_vals)
        corrected = _a_identity([_order_one(p) for p in parts], quant, s_vals)
    except (LatexMathError, ValueError, ZeroDivisionError) as exc:
        return _unread(how, exc, "numeric-evidence")
    return LineResult(printed, corrected, how=how, kind="numeric-evidence", detail={"quantifier": quant})


@line_check("sec1_3-bernstein-power")
def bernstein_power() -> LineResult:
    """The printed chain sum_{i=0}^{2n} A_{2n,i}(alpha s) = (A_{2n,0}(s) + A_{2n,1}(s) + A_{2n,2}(s))^n = 1 (parsed),
    evaluated with A from the definition: the middle part is not the sum for n >= 2; corrected (the power's terms
    A_{2,k}(alpha s): order 1 at the argument alpha s) every part is equal (n = 1..4, three alpha, four s, 40
    digits); and the expansion of (sum_k c_{2,k} X^{2-k} Y^k)^n has the coefficients c_{2n,i} exactly (n <= 5), so
    the terms of the power are the A_{2n,i} at the same argument."""
    how = "40-digit values of the parsed chain and of its correction, n = 1..4; exact expansion n <= 5"
    try:
        parts, quant, s_vals = _read_chain("sec1_3-bernstein-power")
        if len(parts) != 3:
            raise LatexMathError("not a chain of three parts")
        printed = _a_identity(parts, quant, s_vals)
        fixed = [parts[0], _order_one(parts[1], True), parts[2]]
        # the values are all 1; the proof's content is the expansion: the first two parts must agree as homogeneous
        # polynomials in sin((alpha-t)/2), sin(t/2) (a power n-1 would still give the value 1)
        corrected = _a_identity(fixed, quant, s_vals) and _a_identity(fixed[:2], quant, s_vals, scale=mpmath.mpf(1.3))
    except (LatexMathError, ValueError, ZeroDivisionError) as exc:
        return _unread(how, exc, "numeric-evidence")
    a = rational_alpha(ALPHA_TS[0])
    for n in range(1, 6):
        base = [c_const(1, k, a, "exact") for k in range(3)]
        acc = [fmpq(1)]
        for _ in range(n):
            new = [fmpq(0)] * (len(acc) + 2)
            for p, q in enumerate(acc):
                for k, bk in enumerate(base):
                    new[p + k] += q * bk
            acc = new
        corrected &= acc == [c_const(n, i, a, "exact") for i in range(2 * n + 1)]
    return LineResult(printed, corrected, how=how, kind="numeric-evidence", detail={"quantifier": quant})


def _limit_parts(tex: str) -> list[sympy.Expr]:
    """The parts of an aligned chain ``\\lim ... \\\\ = & ... \\\\ = & ...`` (the ``&`` and line breaks dropped)."""
    body = tex.replace("\\begin{align*}", " ").replace("\\end{align*}", " ")
    return relation(body)


def _termwise(lhs: sympy.Limit, rhs: sympy.Expr) -> bool:
    """The proof's step is a termwise limit: lim (t1 + t2 + t3)^n = (r1 + r2 + r3)^n with each t_k -> some r_k (the
    sums themselves are 1 for every alpha, so the values alone cannot tell a wrong limit point): same exponent, and
    the limits of the terms (60 digits at alpha = point + 1e-15, s in {0.1, 0.5, 0.9}) are the right side's terms."""
    body, point = lhs.args[0], lhs.args[2]
    if not (isinstance(body, sympy.Pow) and isinstance(rhs, sympy.Pow)) or body.exp != rhs.exp:
        return False
    left, right = sympy.Add.make_args(body.base), sympy.Add.make_args(rhs.base)
    if len(left) != len(right):
        return False
    with mpmath.workdps(60):
        alpha = num(point, {}) + mpmath.mpf("1e-15")
        ss = (mpmath.mpf("0.1"), mpmath.mpf("0.5"), mpmath.mpf("0.9"))
        try:
            lv = sorted(tuple(mpmath.nstr(num(t, {"s": s, "alpha": alpha}), 15) for s in ss) for t in left)
            rv = sorted(tuple(mpmath.nstr(num(t, {"s": s}), 15) for s in ss) for t in right)
        except (LatexMathError, ValueError, ZeroDivisionError):
            return False
    return lv == rv


@line_check("sec1_3-bernstein-proof-limit")
def bernstein_proof_limit() -> LineResult:
    """The proof's limit (parsed: the lim over alpha of the n-th power of the three terms equals
    ((1-s)^2 + 2(1-s)s + s^2)^n) and the two limits it uses (lim sin(alpha s/2)/sin(alpha/2) = s,
    lim cos(alpha s/2) = 1), evaluated at alpha = the printed limit point + 1e-15 with 60 digits against the right
    sides: within 1e-20 (errors O(alpha^2)), n = 1..4, s in {0, 0.1, 0.5, 0.9, 1}."""
    how = "60-digit values at alpha = 1e-15 of the parsed limits, n = 1..4"
    try:
        parts = _limit_parts(verbatim("sec1_3-bernstein-limit-step1"))
        said = lm.sentence("since {a} and {b}", verbatim("sec1_3-bernstein-limits-used"))
        used = [said["a"], said["b"]] if said else []
        used_parts = [relation(u.rstrip(". ")) for u in used]
        if len(parts) != 2 or len(used_parts) != 2 or any(len(p) != 2 for p in used_parts):
            raise LatexMathError("the limits are not read")
        checks = [parts] + used_parts
        for lhs, _ in checks:
            if not isinstance(lhs, sympy.Limit) or lhs.args[1] != sympy.Symbol("alpha"):
                raise LatexMathError(f"{lhs} is not a limit over alpha")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "numeric-evidence")
    worst = mpmath.mpf(0)
    termwise = _termwise(parts[0], parts[1])
    with mpmath.workdps(60):
        for lhs, rhs in checks:
            alpha = num(lhs.args[2], {}) + mpmath.mpf("1e-15")
            for n in range(1, 5):
                for s in (0, mpmath.mpf("0.1"), mpmath.mpf("0.5"), mpmath.mpf("0.9"), 1):
                    try:
                        env = {"n": n, "s": mpmath.mpf(s), "alpha": alpha}
                        worst = max(worst, abs(num(lhs.args[0], env) - num(rhs, env)))
                    except (LatexMathError, ValueError, ZeroDivisionError) as exc:
                        return _unread(how, exc, "numeric-evidence")
    ok = bool(worst < mpmath.mpf("1e-20")) and termwise
    return LineResult(ok, how=how + "; the limit of each term of the power's base against the right side's terms",
                      kind="numeric-evidence", detail={"below_1e-20": bool(worst < mpmath.mpf("1e-20")),
                                                       "termwise": termwise})


def _one_minus_s(tex: str) -> list[sympy.Expr]:
    """The parts of an equality chain read without simplification (:func:`~paper_repro.printed.latex_math.
    parse_as_printed`), each ``1-s`` in them replaced by the variable x (the change of variable of
    :func:`bernstein_polynomials`, so that ``(1-s)+s`` is not simplified to 1 before the comparison)."""
    rel = lm.parse_as_printed(tex)
    if rel.lead not in (None, "=") or any(op != "=" for op in rel.ops) or rel.conditions:
        raise LatexMathError(f"not an equality chain: {rel.lead} {rel.ops} {len(rel.conditions)} clauses")
    s = sympy.Symbol("s")
    return [p.xreplace({1 - s: sympy.Symbol("x")}) for p in rel.parts]


def _bernstein_xs(f: sympy.Expr, x: sympy.Symbol, s: sympy.Symbol) -> sympy.Expr:
    """B_k^d(s) = binom(d, k) x^{d-k} s^k with x = 1 - s (homogeneous form)."""
    k, d, args = f.args
    if tuple(args) != (s,):
        raise LatexMathError(f"{f} is not a Bernstein polynomial in s")
    return sympy.binomial(d, k) * x ** (d - k) * s**k


@line_check("sec1_3-bernstein-polynomials")
def bernstein_polynomials() -> LineResult:
    """= ((1-s)+s)^{2n} = sum_{i=0}^{2n} B_i^{2n}(s) (parsed from the two lines), as identities of homogeneous
    polynomials in (1-s) =: x and s (so that ((1-s)+s)^k = 1 for every k does not make a wrong exponent true):
    every part equals ((1-s)^2 + 2(1-s)s + s^2)^n, the right side of the step before (read from that line), for
    n = 1..12, with B_k^d(s) = binom(d,k) x^{d-k} s^k."""
    how = "homogeneous polynomial identities in (x, s), x = 1-s, of the parsed parts, n = 1..12"
    s, x = sympy.symbols("s x")
    try:
        parts = [p for lid in ("sec1_3-bernstein-limit-step2", "sec1_3-bernstein-limit-step3")
                 for p in _one_minus_s("0" + verbatim(lid).replace("\\end{align*}", ""))[1:]]
        start = _one_minus_s(verbatim("sec1_3-bernstein-limit-step1").replace("\\begin{align*}", " ")
                             .replace("\\end{align*}", " "))[-1]
        if len(parts) != 3:
            raise LatexMathError(f"{len(parts)} parts, not 3")
    except (LatexMathError, ValueError) as exc:
        return _unread(how, exc, "exhaustive")

    def homog(e, n):
        e = e.subs(sympy.Symbol("n"), n)
        e = e.replace(lambda f: isinstance(f, AppliedUndef) and f.func.__name__ == "B_sup",
                      lambda f: _bernstein_xs(f, x, s))
        return sympy.expand(e.doit())

    ok = True
    for n in range(1, 13):
        try:
            want = homog(start, n)
            got = [homog(p, n) for p in parts]
        except (LatexMathError, ValueError, TypeError) as exc:
            return _unread(how, exc, "exhaustive")
        ok &= all(g == want for g in got) and want.free_symbols <= {x, s}
    return LineResult(ok, how=how, kind="exhaustive", detail={"n_max": 12})


@cache
def distinct_union(n: int) -> frozenset[tuple[int, ...]]:
    """Distinct functions (exponent vectors) of R_{2n} u G_{2n} u B_{2n} (full systems, eqs. R_system..B_system)."""
    return frozenset(exponents(x) for color in "RGB" for x in full_system(n, color))


def _int_at(e: sympy.Expr, env: dict[str, int]) -> int:
    """The integer value of a parsed expression at ``env``, every ``Sum`` (of one or several limits, the first
    innermost as sympy orders them) summed term by term: an empty range (upper < lower) is an empty sum, the paper's
    convention (``LatexMathError`` if a value is not an integer)."""
    if isinstance(e, sympy.Sum):
        return _limits_int(e.function, list(e.limits), env)
    if e.has(sympy.Sum):
        return _env_int(e.func(*[sympy.Integer(_int_at(x, env)) if x.has(sympy.Sum) else x for x in e.args]), **env)
    return _env_int(e, **env)


def _limits_int(f: sympy.Expr, limits: list, env: dict[str, int]) -> int:
    if not limits:
        return _int_at(f, env)
    v, lo, hi = limits[-1]
    return sum(_limits_int(f, limits[:-1], {**env, str(v): x}) for x in range(_int_at(lo, env), _int_at(hi, env) + 1))


def _delta_value(e: sympy.Expr, n: int) -> int | None:
    try:
        return _int_at(e, {"n": n})
    except (LatexMathError, ValueError, ZeroDivisionError, TypeError):
        return None


def read_delta(tex: str) -> list:
    """The printed values of delta_n in ``tex`` (the chain ``\\delta_{n}=a=b..`` of its one ``$..$`` segment or of
    its display, read by :func:`latex_math.parse_relation`), each as a function of n (None where it is not an
    integer): a closed form such as ``3n\\left( n+1\\right) +1`` or ``1+3\\sum_{j=..}^{..}\\sum_{i=..}^{..}1`` (the
    sums evaluated, an empty one 0)."""
    segs = lm.inline_math(tex)
    if len(segs) > 1:
        raise ValueError(f"more than one formula in {tex[:50]!r}")
    try:
        rel = lm.parse_relation(segs[0] if segs else tex)
    except LatexMathError as exc:
        raise ValueError(f"unread value of delta_n: {exc}") from None
    if rel.lead is not None or not rel.ops or any(op != "=" for op in rel.ops) or rel.conditions or \
            rel.parts[0] != sympy.Function("delta")(sympy.Symbol("n")):
        raise ValueError(f"not delta_n = ..: {rel.parts[0]} {rel.ops}")
    return [lambda n, e=part: _delta_value(e, n) for part in rel.parts[1:]]


@line_check("sec1_3-delta-count")
def delta_count(override: dict[str, str] | None = None) -> LineResult:
    """delta_n = 3n(n+1)+1 = 1 + 3 sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} 1: every printed value of its three lines (read
    from the transcriptions) equals the number of distinct functions of R u G u B, for n = 1..40."""
    texts = _transcribed([x.id for x in _lines_of("sec1_3-delta-count")], override)
    try:
        values = {k: read_delta(v) for k, v in sorted(texts.items())}
    except ValueError as exc:
        return LineResult(False, how="the printed values read from the transcriptions, n = 1..40", kind="exhaustive",
                          detail={"unread": str(exc)})
    bad = [(k, n) for n in range(1, 41) for k, fs in values.items()
           if any(f(n) != len(distinct_union(n)) for f in fs)]
    ok = not bad and all(values.values())
    return LineResult(ok, how="count of distinct exponent vectors of R u G u B against every printed value (closed "
                      "form and double sum, read from the transcriptions), n = 1..40", kind="exhaustive",
                      detail={"n_max": 40, "values_per_line": {k: len(v) for k, v in values.items()},
                              "mismatches": bad[:3]})


#: The lines whose index sets :func:`rgb_index_sets` reads (the full systems and the two halves of R).
INDEX_SET_LINES = ("sec1_3-R-system", "sec1_3-G-system", "sec1_3-B-system", "sec1_3-R-leq-n", "sec1_3-R-geq-n-relation")


def _transcribed(ids, override: dict[str, str] | None = None) -> dict[str, str]:
    """The verbatim LaTeX of the lines ``ids`` (``override`` replaces some: the tests' wrong transcriptions)."""
    from paper_repro.printed.lines.sec1_3 import LINES

    text = {x.id: x.verbatim for x in LINES if x.id in ids}
    text.update(override or {})
    return text


def _read_pairs(tex: str, n: int) -> list[tuple[int, int]]:
    """The (i, j) of a printed double index set _{j=a,i=b(j)}^{c,d(j)}, read from ``tex`` at order n."""
    iset = lm.index_set(tex)
    if len(iset) != 2:
        raise ValueError(f"not a double index set: {iset}")
    (ov, olo, ohi), (iv, ilo, ihi) = ((str(v), lo, hi) for v, lo, hi in iset)
    if (ov, iv) != ("j", "i"):
        raise ValueError(f"index set over {(ov, iv)}, not (j, i)")
    return [(i, j) for j in range(bound(olo, n=n), bound(ohi, n=n) + 1)
            for i in range(bound(ilo, n=n, j=j), bound(ihi, n=n, j=j) + 1)]


P = 2**61 - 1


def _modp(q: fmpq) -> int:
    return int(q.p) % P * pow(int(q.q) % P, -1, P) % P


def _rank(rows: list[list[fmpq]]) -> int:
    return nmod_mat(len(rows), len(rows[0]), [_modp(q) for row in rows for q in row], P).rank()


def _angle(half: tuple[fmpq, fmpq]) -> tuple[fmpq, fmpq]:
    """(cos, sin) of the full angle from its half angle."""
    s, c = half
    return c * c - s * s, 2 * s * c


def _cmul(a, b):
    return a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]


def _cpow(a, k):
    out = (fmpq(1), fmpq(0))
    for _ in range(k):
        out = _cmul(out, a)
    return out


def _domain_points(alpha_t: fmpq, count: int) -> list[tuple[tuple[fmpq, fmpq], ...]]:
    """Half angles of (u, v, w) at points of Omega^alpha with rational tan(u/4), tan(v/4) (deterministic)."""
    out = []
    ha = _half(alpha_t)
    k = 0
    while len(out) < count:
        k += 1
        tu, tv = alpha_t * fmpq(k, 2 * k + 5), alpha_t * fmpq(k % 9 + 1, 3 * (k % 9) + k % 4 + 5)
        hu, hv = _half(tu), _half(tv)
        hw = _diff_half(_diff_half(ha, hu), hv)
        if hw[0] > 0 and hw[1] > 0 and (hu, hv) not in [(p[0], p[1]) for p in out]:
            out.append((hu, hv, hw))
    return out


@line_check("sec1_3-independence-rank")
def independence_rank() -> LineResult:
    """T_{2n} is linearly independent (so dim span T_{2n} = delta_n): its exact collocation matrix at delta_n + 5
    rational points of Omega^alpha has rank delta_n (modulo a 61-bit prime: full rank there implies full rank over Q),
    n = 1..5 at tan(alpha/4) = 1/2 and n = 1..4 at tan(alpha/4) = 3/4.  Read from the transcription: the system
    (\\ref{united_system}), the words "is linearly independent", and the space whose dimension is claimed, the span
    of T_{2n}^alpha (its order 2n)."""
    tex = _layout_free(_transcribed(["sec1_3-theorem"])["sec1_3-theorem"])
    words = lm.sentence(r"The function system (\ref{united_system}) is linearly independent and the dimension of the "
                        r"vector space {space}\emph{span}{spanned} is", tex)
    # the formula is split by the text-mode word span: read as one relation with the operator in its place
    rel = _read_segment(words["space"] + r"\operatorname{span}" + words["spanned"]) if words else None
    two_n = 2 * sympy.Symbol("n")
    want = [("Tcal", (two_n,)), ("span", (sympy.Function("T")(two_n),))]
    if rel is None or rel.ops != ["="] or rel.conditions or [(p.func.__name__, p.args) for p in rel.parts] != want:
        return LineResult(False, how="the statement read from the transcription", detail={"unread": tex[:60]})
    detail, ok = {}, True
    for at, n_max in zip(ALPHA_TS, (5, 4)):
        for n in range(1, n_max + 1):
            pts = _domain_points(at, delta(n) + 5)
            rows = [[hu[0] ** e[0] * hu[1] ** e[1] * hv[0] ** e[2] * hv[1] ** e[3] * hw[0] ** e[4] * hw[1] ** e[5]
                     for e in (exponents(lb) for lb in united_system(n))] for hu, hv, hw in pts]
            rank = _rank(rows)
            detail[f"n={n},t={at}"] = rank
            ok &= rank == delta(n)
    return LineResult(ok, how="exact collocation ranks modulo 2^61-1 (full rank mod p proves independence at that "
                      "alpha), n = 1..5 at tan(alpha/4) = 1/2, n = 1..4 at 3/4", detail=detail)


@line_check("sec1_3-sin-power-leading")
def sin_power_leading() -> LineResult:
    """"In particular, $S_{j,\\mu}^{j}\\left( 0\\right) =j!\\mu^{j}$" (read: the indices, the order, the point 0 and
    the right-hand side factorial times power) against exact Taylor coefficients, j = 1..15, mu in {1/2, 1, 3, 7/5}."""
    tex = _transcribed(["sec1_3-sin-leading"])["sec1_3-sin-leading"]
    words, segs = lm.prose(tex)  # the words; the formula, the one $..$ segment, read by the one reader
    j_, mu_ = sympy.Symbol("j"), sympy.Symbol("mu")
    try:
        rel = lm.parse_relation(segs[0]) if len(segs) == 1 and "(In particular, $$)" in words else None
        lhs, rhs = rel.parts if rel is not None and rel.ops == ["="] and not rel.conditions else (None, None)
        if not (isinstance(lhs, AppliedUndef) and lhs.func.__name__ == "S_sup" and len(lhs.args) == 4
                and lhs.args[1] == mu_ and lhs.args[3] == sympy.Tuple(0)
                and (lhs.free_symbols | rhs.free_symbols) <= {j_, mu_}):
            raise LatexMathError(f"not S_{{j,mu}}^{{p}}(0) = f(j, mu): {rel.parts if rel else segs}")
    except LatexMathError as exc:
        return LineResult(False, how="the formula read from the transcription", detail={"unread": str(exc)[:80]})
    names = [str(lhs.args[0]), str(lhs.args[2]), str(rhs)]

    def printed_value(j: int, mu: fmpq):
        v = rhs.subs({j_: j, mu_: sympy.Rational(int(mu.p), int(mu.q))})
        return fmpq(int(v.p), int(v.q)) if v.is_Rational else None

    try:
        ok = all(sin_power_derivative(bound(lhs.args[0], j=j), mu, bound(lhs.args[2], j=j)) == printed_value(j, mu)
                 for j in range(1, 16) for mu in (fmpq(1, 2), fmpq(1), fmpq(3), fmpq(7, 5)))
    except ValueError:  # an index that is not a non-negative integer at j
        ok = False
    return LineResult(ok, how="the printed formula read from the transcription against exact Taylor coefficients, "
                      "j = 1..15", kind="exhaustive", detail={"ok": ok, "read": list(names)})


# -- chain rules and parametrizations ----------------------------------------------------------------------------
def chain_ok(param: str, printed: tuple[int, int]) -> bool:
    """The printed d^r/d(param)^r = sum_k C(r,k) (-1)^k d^{r-k}_a d^k_b holds iff the direction of the (affine)
    parametrization is e_a - e_b; then (d_a - d_b)^r expands binomially (checked as polynomials, r <= 10)."""
    direction = step_geometry(param)[0]
    a, b = printed
    want = [0, 0, 0]
    want[a], want[b] = 1, -1
    ctx = fmpz_mpoly_ctx.get(("a", "b"), "lex")
    da, db = ctx.gens()
    binom_ok = all((da - db) ** r == sum((comb(r, k) * (-1) ** k * da ** (r - k) * db**k for k in range(r + 1)),
                                         ctx.from_dict({})) for r in range(11))
    return tuple(want) == direction and binom_ok


def read_chain(tex: str) -> tuple[int, int]:
    """(a, b) of a printed chain rule sum_k binom (-1)^k d/da^{r-k} d/db^k, read by
    :func:`~paper_repro.printed.latex_math.parse_relation` (variables u, v, w -- also ``v_{1}`` -- as 0, 1, 2): the
    first sum over k whose term has the factor (-1)^k and a derivative of orders (.. - k, k) in two variables; a
    sign other than (-1)^k is unread (``ValueError``)."""
    try:
        rel = lm.parse_relation(tex)
    except LatexMathError as exc:
        raise ValueError(f"chain rule not read: {exc}") from None
    for part in rel.parts:
        for s in (x for x in sympy.preorder_traversal(part) if isinstance(x, sympy.Sum)) if part is not None else ():
            k = s.limits[0][0]
            factors = sympy.Mul.make_args(s.function)
            if sympy.Pow(-1, k) not in factors:
                continue
            for d in sympy.preorder_traversal(s.function):
                if isinstance(d, AppliedUndef) and d.func.__name__ == "D" and len(d.args) == 3:
                    (a, oa), (b, ob) = d.args[1:]
                    if ob == k and sympy.diff(oa, k) == -1:
                        return _uvw_index(a), _uvw_index(b)
    raise ValueError(f"no chain rule sum (-1)^k d^(r-k)/da d^k/db in {tex[:50]!r}")


def _uvw_index(var) -> int:
    """0, 1, 2 of a parsed variable ``u``, ``v``, ``w`` or ``v_{1}`` (``v(1)``)."""
    name = var.name if isinstance(var, sympy.Symbol) else getattr(var.func, "__name__", "")
    if name not in ("u", "v", "w"):
        raise ValueError(f"{var} is not u, v or w")
    return "uvw".index(name)


_CHAIN_HEADS = {("L", ()), ("L", ("r",)), ("Ltilde", ("r",)), ("Lhat", ("r",))}  # L, L_{r}, \widetilde{L}_{r}, ..


def _chain_function(f, coords: tuple) -> str:
    """``L``, ``L_{r}``, ``\\widetilde{L}_{r}`` or ``\\widehat{L}_{r}`` applied to ``coords`` (parsed: ``L(r, (..))``),
    as ``name(index)``; ``ValueError`` otherwise."""
    if not isinstance(f, AppliedUndef) or not f.args or not isinstance(f.args[-1], sympy.Tuple):
        raise ValueError(f"{f} is not a function of the parametrization's coordinates")
    head = (f.func.__name__, tuple(str(x) for x in f.args[:-1]))
    if head not in _CHAIN_HEADS or tuple(f.args[-1]) != coords:
        raise ValueError("the arguments are not the coordinates of the parametrization")
    return f"{head[0]}_{{{','.join(head[1])}}}" if head[1] else head[0]


def read_chain_strict(tex: str, param: str) -> dict:
    """The whole printed chain rule ``\\frac{\\partial^{r}}{\\partial y^{r}}L(..) = \\sum_{k=0}^{r} \\dbinom{r}{k}
    (-1)^k \\frac{\\partial^{r}}{\\partial a^{r-k}\\partial b^{k}} L(..) [|_{y=0}, \\forall x \\in [0,\\alpha]]``
    (or its continuation row ``& = & \\sum ..``), read by :func:`latex_math.parse_relation`: every order equal (of
    the left derivative, the sum's upper bound, the binomial, the derivative under the sum), the sum over k from 0
    of exactly (-1)^k binom(.., k) D(.., (a, .. - k), (b, k)), the variables a, b and the arguments the coordinates
    of ``param`` (its index) at (x, y), the evaluation point the running parameter at 0, the quantifier over the
    other parameter on its printed range (``ValueError`` otherwise)."""
    try:
        rel = lm.parse_relation(tex)
    except LatexMathError as exc:
        raise ValueError(f"chain rule not read: {exc}") from None
    if rel.lead is None and rel.ops == ["="] and len(rel.parts) == 2:
        lhs, rhs = rel.parts
    elif rel.lead == "=" and not rel.ops and len(rel.parts) == 1:
        lhs, rhs = None, rel.parts[0]
    else:
        raise ValueError(f"chain rule not read: {rel.lead} {rel.ops}")
    k = sympy.Symbol("k")
    if not isinstance(rhs, sympy.Sum) or len(rhs.limits) != 1 or rhs.limits[0][:2] != (k, 0):
        raise ValueError(f"not a sum over k from 0: {rhs}")
    order = rhs.limits[0][2]
    factors = sympy.Mul.make_args(rhs.function)
    binoms = [f for f in factors if isinstance(f, sympy.binomial)]
    rest = [f for f in factors if f != sympy.Pow(-1, k) and f not in binoms]
    if len(factors) != 3 or sympy.Pow(-1, k) not in factors or len(binoms) != 1 or binoms[0].args[1] != k or \
            len(rest) != 1:
        raise ValueError(f"the term is not (-1)^k binom(.., k) d/d..: {rhs.function}")
    deriv, bar = rest[0], None
    if isinstance(deriv, sympy.Subs):
        if len(deriv.variables) != 1 or deriv.point != sympy.Tuple(0):
            raise ValueError(f"the evaluation bar is not at 0: {deriv}")
        bar, deriv = str(deriv.variables[0]), deriv.expr
    if not (isinstance(deriv, AppliedUndef) and deriv.func.__name__ == "D" and len(deriv.args) == 3):
        raise ValueError(f"not a derivative in two variables: {deriv}")
    (va, oa), (vb, ob) = deriv.args[1:]
    orders = [order, binoms[0].args[0], oa + k]
    idx = STEP_PARAMS.index(param) + 1 if param in STEP_PARAMS else None
    x_y = sympy.Tuple(*sympy.symbols("x y"))
    coords = tuple(sympy.Function(c)(idx, x_y) if idx else sympy.Function(c)(x_y) for c in "uvw")
    names = {sympy.Function(c)(idx) if idx else sympy.Symbol(c) for c in "uvw"}
    if ob != k or va not in names or vb not in names:
        raise ValueError("the variables are not the coordinates of the parametrization")
    f1 = _chain_function(deriv.args[0], coords)
    run0 = None
    if lhs is not None:
        if not (isinstance(lhs, AppliedUndef) and lhs.func.__name__ == "D" and len(lhs.args) == 2):
            raise ValueError(f"the left side is not a derivative in one variable: {lhs}")
        run0, o0 = str(lhs.args[1][0]), lhs.args[1][1]
        orders.append(o0)
        if _chain_function(lhs.args[0], coords) != f1:
            raise ValueError("the two sides differentiate different functions")
    if any(sympy.expand(o - order) != 0 for o in orders):
        raise ValueError(f"orders {orders}")
    _fmap, run, _maps, ranges = _params()[param]
    if run0 not in (None, run) or bar not in (None, run):
        raise ValueError("not the running parameter of the parametrization")
    if len(rel.conditions) > 1:
        raise ValueError("more than one clause")
    if rel.conditions:
        cond = rel.conditions[0]
        free = "x" if run == "y" else "y"
        iv = cond.parts[1] if cond.ops == ["in"] and len(cond.parts) == 2 else None
        if cond.quantifier != "forall" or str(cond.parts[0]) != free or not isinstance(iv, sympy.Interval) or \
                iv.left_open or iv.right_open or bar is None:
            raise ValueError("the quantifier is not over the other parameter on [0, alpha]")
        lo, hi = _lin(iv.start, 1), _lin(iv.end, 1)

        def at_edge(q) -> tuple[int, int, int]:  # the printed bound with the running parameter at 0
            a, x, y = linear_form(q)
            return (a, 0, y) if run == "x" else (a, x, 0)
        if (lo, hi) != (0, 1) or [at_edge(q) for q in ranges[free]] != [at_edge(iv.start), at_edge(iv.end)]:
            raise ValueError("the quantifier is not over the other parameter on [0, alpha]")
    return {"order": str(order), "a": str(va), "b": str(vb), "function": f1, "run": run0, "bar": bar}


def _chain(param: str, check_id: str, override: dict[str, str] | None = None) -> LineResult:
    """Every line of ``check_id`` (the chain rule and its use at order r+1) read from its transcription: the pair of
    variables it differentiates must be the printed parametrization's direction e_a - e_b."""
    texts = {k: v for k, v in _transcribed([x.id for x in _lines_of(check_id)], override).items()}
    try:
        pairs = {k: read_chain(v) for k, v in sorted(texts.items())}
        for v in texts.values():
            read_chain_strict(v, param)
    except ValueError as exc:
        return LineResult(False, how="the chain rule read from the transcription", detail={"unread": str(exc)})
    ok = bool(pairs) and all(chain_ok(param, pr) for pr in pairs.values())
    return LineResult(ok, how="the differentiated pair of variables read from each transcription against the direction "
                      "vector of the printed affine parametrization; binomial expansion of (d_a - d_b)^r as "
                      "polynomials (r <= 10)", kind="exhaustive",
                      detail={"direction": list(step_geometry(param)[0]),
                              "pairs": {k: list(v) for k, v in pairs.items()}})


def _lines_of(check_id: str):
    from paper_repro.printed.lines.sec1_3 import LINES

    return [x for x in LINES if x.check == check_id]


@line_check("sec1_3-chain-rule-pu")
def chain_pu(override=None) -> LineResult:
    return _chain("parametrization_for_partition_of_unity", "sec1_3-chain-rule-pu", override)


@line_check("sec1_3-chain-rule-1")
def chain_1(override=None) -> LineResult:
    return _chain("parametrization_1_y_0", "sec1_3-chain-rule-1", override)


@line_check("sec1_3-chain-rule-2")
def chain_2(override=None) -> LineResult:
    return _chain("parametrization_2_x_0", "sec1_3-chain-rule-2", override)


@line_check("sec1_3-chain-rule-3")
def chain_3(override=None) -> LineResult:
    return _chain("parametrization_3_y_0", "sec1_3-chain-rule-3", override)


def _lin(expr: str | sympy.Expr, a, x=None):
    """A printed bound (linear form in alpha, x; no y) at alpha = a and x."""

    ca, cx, cy = linear_form(expr)
    if cy or (cx and x is None):
        raise ValueError(f"the bound {expr!r} depends on {'y' if cy else 'x'}")
    return ca * a + (cx * x if cx else 0)


def param_onto(param: str, y_to=None, ranges: dict[str, tuple[str, str]] | None = None) -> bool:
    """The printed map of ``param`` on its printed parameter triangle x in [x_lo, x_hi], y in [y_lo(x), y_hi(x)]
    (read from the transcription; ``ranges`` or ``y_to(alpha, x)`` replace them) is an affine bijection onto
    Omega^alpha: grid points go into Omega^alpha (u + v + w = alpha, u, v, w >= 0, exact) and the parameter
    triangle's vertices onto the three vertices of Omega^alpha."""
    fmap = PARAMS[param][0]
    rng = ranges or _params()[param][3]
    a = fmpq(3, 2)
    x_lo, x_hi = _lin(rng["x"][0], a), _lin(rng["x"][1], a)

    def y_lo(x):
        return fmpq(0) if y_to else _lin(rng["y"][0], a, x)

    def y_hi(x):
        return y_to(a, x) if y_to else _lin(rng["y"][1], a, x)
    if x_hi <= x_lo:
        return False
    xs = [x_lo + fmpq(k, 8) * (x_hi - x_lo) for k in range(9)]
    pts = [(x, y_lo(x) + fmpq(m, 8) * (y_hi(x) - y_lo(x))) for x in xs for m in range(9)]
    grid = all(y_hi(x) >= y_lo(x) for x in xs) and all(sum(fmap(a, x, y)) == a and min(fmap(a, x, y)) >= 0
                                                          for x, y in pts)
    ends = ((x_lo, y_lo(x_lo)), (x_hi, y_lo(x_hi)), (x_lo, y_hi(x_lo)), (x_hi, y_hi(x_hi)))
    corners = {tuple(fmap(a, x, y)) for x, y in ends}  # the parameter triangle's vertices (one listed twice)
    return grid and corners == {(a, 0, 0), (0, a, 0), (0, 0, a)}


def _param(param: str) -> LineResult:
    """The printed parametrization maps its printed triangle onto Omega^alpha, and its direction along the running
    parameter is the pair of variables its derivative formula differentiates (read: d/dy = d_{v_1} - d_{w_1} for
    parametrization_1_y_0), so the map is the one the proof differentiates."""
    try:
        chain_line = PARAM_LINES[param][1]
        ok = param_onto(param) and chain_ok(param, read_chain(_transcribed([chain_line])[chain_line]))
    except ValueError as exc:
        return LineResult(False, how="the parametrization read from the transcription", kind="proof",
                          detail={"unread": str(exc)})
    return LineResult(ok, how="the printed map and ranges read from the transcription; exact images of a grid of the "
                      "parameter triangle and of its vertices (alpha = 3/2; the maps are linear in (alpha, x, y), so "
                      "one alpha > 0 stands for every alpha)", kind="proof",
                      detail={"onto": ok, "map": [list(m) for m in _params()[param][2]]})


@line_check("sec1_3-param-1")
def param_1() -> LineResult:
    return _param("parametrization_1_y_0")


@line_check("sec1_3-param-2")
def param_2() -> LineResult:
    return _param("parametrization_2_x_0")


@line_check("sec1_3-param-3")
def param_3() -> LineResult:
    return _param("parametrization_3_y_0")


@line_check("sec1_3-param-ranges")
def param_ranges() -> LineResult:
    """"for all x in [0, alpha], y in [0, alpha - x] and order r in N" (read): on these ranges each of the three
    printed parametrizations maps onto Omega^alpha."""
    tex = _transcribed(["sec1_3-chain-ranges"])["sec1_3-chain-ranges"]
    try:
        rng = {"x": interval(tex, "x"), "y": interval(tex, "y")}
        words, segs = lm.prose(tex)
        natural = [seg for seg in segs if lm.parse_relation(seg).parts == [sympy.Symbol("r"), sympy.Symbol("N_bb")]
                   and lm.parse_relation(seg).ops == ["in"]]
        if words != "for all $$,$$ and order $$." or len(segs) != 3 or len(natural) != 1:
            raise ValueError("no 'for all ... and order r in N'")
        ok = all(param_onto(p, ranges=rng) for p in STEP_PARAMS)
    except ValueError as exc:
        return LineResult(False, how="the ranges read from the transcription", kind="proof",
                          detail={"unread": str(exc)})
    return LineResult(ok, how="the ranges read from the transcription; the three printed parametrizations on them "
                      "(exact images of the parameter triangle)", kind="proof",
                      detail={"onto": ok, "ranges": {k: [str(a), str(b)] for k, (a, b) in rng.items()}})


def _refs(tex: str) -> list[str]:
    """The labels of the ``\\ref{..}`` cross-references of a line, in order (LaTeX markup, not the paper's words)."""
    out, k = [], tex.find("\\ref{")
    while k >= 0:
        end = tex.find("}", k)
        out.append(tex[k + 5:end].strip())
        k = tex.find("\\ref{", end)
    return out


def _layout_free(tex: str) -> str:
    """The line with its ``%`` line ends and runs of white space as single spaces."""
    return " ".join(tex.replace("%", " ").split())


def _read_segment(seg: str):
    """A ``$..$`` segment read by :func:`~paper_repro.printed.latex_math.parse_relation` (``None`` if unread)."""
    try:
        return lm.parse_relation(seg)
    except LatexMathError:
        return None


def _is_point(rel) -> str | None:
    """``"x"``/``"y"`` when a parsed segment is the point ``x=0``/``y=0``."""
    xy = sympy.symbols("x y")
    if rel is not None and rel.ops == ["="] and not rel.conditions and len(rel.parts) == 2 and \
            rel.parts[1] == 0 and rel.parts[0] in xy:
        return str(rel.parts[0])
    return None


def read_boundary_vars(tex: str) -> list[tuple[str, str]]:
    """(parametrization, variable set to 0) pairs of a line, in order: the ``\\ref{parametrization_..}`` it names and
    the points ``$y=0$``/``$x=0$`` it evaluates at (each ``$..$`` segment parsed; ``ValueError`` if their numbers
    differ or are 0)."""
    params = [r for r in _refs(tex) if r.startswith("parametrization_")]
    points = [v for v in (_is_point(_read_segment(seg)) for seg in lm.prose(tex)[1]) if v]
    if not params or len(params) != len(points):
        raise ValueError(f"{len(params)} parametrizations but {len(points)} points in {tex[:50]!r}")
    return list(zip(params, points))


_RESPECT = ("with respect to $$", "with respect to the variable $$", "with respect to variables $$")


def _resp_vars(tex: str) -> list[list[str]]:
    """The variables of every "with respect to [the variable|variables] $y$[, $x$ and $y$]" of a line (the segments
    parsed: each must be a variable, else it is named as read)."""
    words, segs = lm.prose(_layout_free(tex))
    pieces = words.split("$$")  # pieces[k] is before segment k, pieces[k + 1] after it
    out = []
    for k, seg in enumerate(segs):
        if not (pieces[k] + "$$").endswith(_RESPECT):
            continue
        group = [seg]
        if k + 2 < len(segs) and pieces[k + 1] == ", " and pieces[k + 2] == " and ":
            group += segs[k + 1:k + 3]
        out.append([str(rel.parts[0]) if rel and not rel.ops and not rel.conditions else seg
                    for rel in map(_read_segment, group)])
    return out


def _orders_named(tex: str) -> tuple[list, bool]:
    """The orders of derivatives a line names ("$r=0$", "zeroth order", "$\\left( r+1\\right) $th order"; each segment
    parsed) and whether it speaks of an order at all (the word, or a segment ``r=..``/``r\\neq..``)."""
    words, segs = lm.prose(_layout_free(tex))
    pieces = words.split("$$")
    r = sympy.Symbol("r")
    orders: list = [sympy.Integer(0)] * sum(
        1 for a, b in zip(words.split(), words.split()[1:]) if a == "zeroth" and b == "order")
    speaks = "order" in words
    for k, seg in enumerate(segs):
        rel = _read_segment(seg)
        if rel is None:
            continue
        if rel.ops and rel.parts[0] == r:
            speaks = True
            if rel.ops == ["="] and len(rel.parts) == 2 and not rel.conditions:
                orders.append(rel.parts[1])
        elif not rel.ops and pieces[k + 1].startswith("th order"):
            orders.append(rel.parts[0])
    return orders, speaks


def _step_words_ok(line_id: str, tex: str, pairs: list[tuple[str, str]]) -> bool:
    """The words of a line that names steps of the proof, read: the order of the derivative ("$r=0$", "zeroth
    order": 0 in the order-0 steps, before the induction; "$\\left( r+1\\right) $th order": r + 1 in the step
    r -> r+1), the variables "with respect to" (those of the points), the number of "consecutive steps" (the
    parametrizations named), and what black and coloured dots mean (vanish / do not vanish, substitutions with 0)."""
    t = _layout_free(tex)
    orders, speaks = _orders_named(t)
    if speaks and not orders and "partial derivative formula" not in t and "under parametrizations" not in t:
        raise ValueError(f"{line_id}: an order not read")
    before_induction = transcribed_line(line_id).tex[0] < 912
    if any(o != (0 if before_induction else sympy.Symbol("r") + 1) for o in orders):
        return False
    points = [var for _p, var in pairs]
    for vs in _resp_vars(t):
        if vs != points[:len(vs)] and vs != points[-len(vs):]:
            return False
    m = lm.sentence("illustrate {k:count} consecutive steps", t, search=True)
    if m and m["k"] != len(pairs):
        return False
    if "White dots" in t and lm.sentence("the combining constants of which proved to be $0$ in the previous steps",
                                         t, search=True) is None:
        return False
    if "black dots" in t:
        if lm.sentence("black dots represent functions whose zeroth order partial derivatives vanish when", t,
                       search=True) is None or \
                lm.sentence("partial derivatives of which do not vanish under corresponding parametrizations and "
                            "substitutions with $0$", t, search=True) is None:
            return False
    return True


@line_check("sec1_3-boundary-vars")
def boundary_vars(override: dict[str, str] | None = None) -> LineResult:
    """Each line names parametrizations and the points where they are evaluated (read from the transcription):
    each point must set the running parameter of that printed map to 0, where exactly one of u, v, w vanishes
    (v_1, u_2, w_3: the edges v = 0, u = 0, w = 0 of the three steps)."""
    texts = _transcribed([x.id for x in _lines_of("sec1_3-boundary-vars")], override)
    try:
        pairs = {k: read_boundary_vars(v) for k, v in sorted(texts.items())}
    except ValueError as exc:
        return LineResult(False, how="the parametrizations and points read from the transcriptions",
                          detail={"unread": str(exc)})
    bad = {k: v for k, v in pairs.items() if any(PARAMS[p][1] != var for p, var in v)}
    for k, v in texts.items():  # the orders and the variables the line names
        try:
            if not _step_words_ok(k, v, pairs[k]):
                bad[k] = "words"
        except ValueError as exc:
            bad[k] = str(exc)
    edges = {p: "uvw"[step_geometry(p)[1]] for p in STEP_PARAMS}  # asserts one coordinate vanishes
    return LineResult(not bad, how="the parametrizations and points read from each transcription against the running "
                      "parameter of the printed maps, evaluated at 0", kind="proof",
                      detail={"lines": len(pairs), "wrong": sorted(bad), "vanishing_coordinate": edges})


# ==============================================================================================================
# The proof of Theorem joint_systems_linear_independence
# ==============================================================================================================
#: the combining constant of each colour
_CONST_COLOUR = {"rho": "R", "gamma": "G", "beta": "B"}
_UVW = sympy.Tuple(*sympy.symbols("u v w"))


def combination_terms(expr: sympy.Expr) -> list[tuple[list, str, sympy.Expr, sympy.Expr, sympy.Tuple]]:
    """The terms ``constant_{2n,a,b} X_{2n,a,b}^{alpha}(args)`` of a parsed linear combination
    (:func:`paper_repro.printed.latex_math.terms`): ``[(sums, colour, a, b, args), ...]``, the sums outermost first;
    :class:`LatexMathError` for a term that is anything else (a coefficient, another factor, a constant whose colour
    or indices disagree with its function's, an order other than 2n).

    >>> combination_terms(lm.parse(r"\\rho_{2n,n,n}R_{2n,n,n}^{\\alpha}\\left( u,v,w\\right) "
    ...                         r"+\\sum_{i=1}^{n}\\gamma_{2n,2n-i,1}G_{2n,2n-i,1}^{\\alpha}\\left( x,0,y\\right)"))
    [([], 'R', n, n, (u, v, w)), ([(i, 1, n)], 'G', -i + 2*n, 1, (x, 0, y))]
    """
    out = []
    two_n = 2 * sympy.Symbol("n")
    for t in lm.terms(expr):
        consts = [f for f in t.names if f.func.__name__ in _CONST_COLOUR]
        funcs = [f for f in t.names if f.func.__name__ in ("R", "G", "B")]
        if t.coefficient != 1 or len(t.names) != 2 or len(consts) != 1 or len(funcs) != 1:
            raise LatexMathError(f"the term {t.names} {t.coefficient} is not constant x function")
        (c,), (f,) = consts, funcs
        if _CONST_COLOUR[c.func.__name__] != f.func.__name__ or len(c.args) != 3 or len(f.args) != 4 or \
                tuple(c.args) != tuple(f.args[:3]) or c.args[0] != two_n or not isinstance(f.args[3], sympy.Tuple):
            raise LatexMathError(f"the constant {c} does not match the function {f}")
        out.append((t.limits, f.func.__name__, f.args[1], f.args[2], f.args[3]))
    return out


@cache
def _int_fn(expr: sympy.Expr):
    names = tuple(sorted(s.name for s in expr.free_symbols))
    return names, sympy.lambdify([sympy.Symbol(x) for x in names], expr, "math")


def _int_at(expr: sympy.Expr, scope: dict[str, int]) -> int:
    """Integer value of a parsed bound or index at ``scope`` (every name bound)."""
    names, f = _int_fn(sympy.sympify(expr))
    missing = [x for x in names if x not in scope]
    if missing:
        raise LatexMathError(f"{expr} names {missing}, unbound")
    v = f(*(scope[x] for x in names))
    if v != int(v):
        raise LatexMathError(f"{expr} is not an integer at {scope}")
    return int(v)


def term_indices(terms, **env: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of every function of :func:`combination_terms` (i from the first index 2n - i), the sums
    written out (an empty sum, upper bound below the lower, names nothing) with ``env`` (``n``, ``r``) bound."""
    out: list[tuple[str, int, int]] = []

    def walk(sums, colour, first, level, scope):
        if not sums:
            out.append((colour, 2 * scope["n"] - _int_at(first, scope), _int_at(level, scope)))
            return
        (v, lo, hi), rest = sums[0], sums[1:]
        for x in range(_int_at(lo, scope), _int_at(hi, scope) + 1):
            walk(rest, colour, first, level, {**scope, str(v): x})

    for sums, colour, first, level, _args in terms:
        walk(sums, colour, first, level, dict(env))
    return out


def row_terms(tex: str) -> list[tuple[list, str, sympy.Expr, sympy.Expr, sympy.Tuple]]:
    """The terms (:func:`combination_terms`) of a displayed row of the proof's combinations, read by
    :func:`paper_repro.printed.latex_math.parse_relation`: ``0 = L(u,v,w) = ..``, ``= ..`` or a continued sum; the
    parts before the last are 0 or L, widetilde L, widehat L at (u, v, w); a clause must be ``\\forall (u,v,w) \\in
    \\Omega^{\\alpha}``; every function is applied to (u, v, w)."""
    rel = lm.parse_relation(tex)
    if rel.lead not in (None, "=") or any(op != "=" for op in rel.ops):
        raise LatexMathError(f"the row relates by {rel.lead} {rel.ops}, not '='")
    for p in rel.parts[:-1]:
        if p != 0 and not (isinstance(p, AppliedUndef) and p.func.__name__ in ("L", "Ltilde", "Lhat")
                           and p.args[-1] == _UVW):
            raise LatexMathError(f"the row equates {p}, not 0 or L(u,v,w)")
    for c in rel.conditions:
        if c.quantifier != "forall" or c.ops != ["in"] or c.parts != [_UVW, sympy.Symbol("Omega")]:
            raise LatexMathError(f"the clause {c.parts} {c.ops} is not forall (u,v,w) in Omega^alpha")
    terms = combination_terms(rel.parts[-1])
    if any(args != _UVW for *_, args in terms):
        raise LatexMathError("a function not at (u, v, w)")
    return terms


def constant_sets(tex: str, n: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of the constants named by a printed list such as ``$\\rho_{2n,n,n}$, $\\left\\{
    \\rho_{2n,2n-i,j}\\right\\} _{j=0,i=j}^{n-1,2n-1-j}$, ..`` at order n: each ``$..$`` segment read by
    :func:`paper_repro.printed.latex_math.parse` (a constant, or a family of constants with its index set; i from the
    first index 2n - i)."""
    out: list[tuple[str, int, int]] = []
    two_n = 2 * sympy.Symbol("n")
    for seg in lm.inline_math(tex):
        e = lm.parse(seg)
        if isinstance(e, AppliedUndef) and e.func == lm.Family:
            member, conds, bounds = e.args
            if conds:
                raise LatexMathError(f"a set of constants with conditions {conds}")
            limits = list(bounds)
        else:
            member, limits = e, []
        if not (isinstance(member, AppliedUndef) and member.func.__name__ in _CONST_COLOUR and len(member.args) == 3
                and member.args[0] == two_n):
            raise LatexMathError(f"{member} is not a constant rho, gamma, beta of order 2n")
        out += term_indices([(limits, _CONST_COLOUR[member.func.__name__], member.args[1], member.args[2], None)],
                            n=n)
    return out


def row_combination(tex: str) -> list[tuple[list, str, sympy.Expr, sympy.Expr, sympy.Tuple]]:
    """:func:`combination_terms` of the last part of a printed row (read by
    :func:`paper_repro.printed.latex_math.parse_relation`)."""
    return combination_terms(lm.parse_relation(tex).parts[-1])


@cache
def _row_terms_cached(tex: str):
    return row_terms(tex)


def printed_rows(check_id: str, n: int, r: int = 0, override: dict[str, str] | None = None) -> set:
    """The functions named by the displayed rows of the lines checked by ``check_id``, read from their
    transcriptions (sums, bounds, constants, functions: :func:`row_terms`) at order n and step r: indices into T_{2n}
    by the functions' own names (no alias); a name that is not a member of T_{2n} stays in the set as a string (a
    mismatch).  ``override`` replaces transcriptions (tests)."""
    from paper_repro.printed.lines.sec1_3 import LINES

    rows = {x.id: x.verbatim for x in LINES if x.check == check_id and x.kind == "display"}
    rows.update({k: v for k, v in (override or {}).items() if k in rows})
    strict = {lb.paper: k for k, lb in enumerate(united_system(n))}
    out: set = set()
    for key in sorted(rows):
        for color, i, j in term_indices(_row_terms_cached(rows[key]), n=n, r=r):
            name = f"{color}_{{{2 * n},{2 * n - i},{j}}}"
            out.add(strict.get(name, name))
    return out


def _open_clauses_are_forall(check_id: str, override: dict[str, str] | None = None) -> bool:
    """Every displayed row of the check that ends in an open clause ends in the clause ``\\forall (u, v, w) ..``: the
    combination vanishes identically on Omega^alpha, which is what lets the proof differentiate it (an ``\\exists``
    there would state only a zero somewhere)."""
    from paper_repro.printed.lines.sec1_3 import LINES

    rows = {x.id: x.verbatim for x in LINES if x.check == check_id and x.kind == "display"}
    rows.update({k: v for k, v in (override or {}).items() if k in rows})
    for tex in rows.values():
        rel = lm.parse_relation(tex)
        if rel.unfinished is not None and rel.continues != "forall":
            return False
    return True


def _read_sets(check_id: str, computed_fn, rs=lambda n: [0], ns=N_PROOF, override=None) -> LineResult:
    """:func:`_proof_sets` with the printed sets read from the transcriptions of the check's lines; a row that ends
    in an open quantifier clause must end in ``\\forall`` (:func:`_open_clauses_are_forall`)."""
    try:
        res = _proof_sets(lambda n, r: printed_rows(check_id, n, r, override), computed_fn, rs=rs, ns=ns,
                          how="index sets of the printed sums (read from the transcriptions)")
        forall = _open_clauses_are_forall(check_id, override)
        res.holds_as_printed &= forall
        res.detail["open_clauses_forall"] = forall
        return res
    except (ValueError, LatexMathError) as exc:
        return LineResult(False, how="index sets of the printed sums, read from the transcriptions",
                          detail={"unread": str(exc)})


@line_check("sec1_3-L-set")
def l_set(override: dict[str, str] | None = None) -> LineResult:
    """The rows of eq. linear_combination_union name every function of T_{2n} once; the constants listed after it
    (line sec1_3-L-coefficients, read: rho_{2n,n,n} and the sets of rho and gamma -- the set of beta follows on the
    next, untranscribed, line) are exactly the constants of the R and G terms of the rows (n = 1..12)."""
    res = _read_sets("sec1_3-L-set", lambda n, r: set(range(len(united_system(n)))), ns=range(1, 13),
                     override=override)
    res.how = res.how.replace("against the elimination recomputed from exact derivatives", "against T_{2n}")
    res.kind = "exhaustive"
    t = _transcribed(["sec1_3-L-coefficients", "sec1_3-L-R-row", "sec1_3-L-G-row"], override)
    bad = []
    try:
        sets = lm.sentence(r"where $\rho_{2n,n,n}$, {rho}, {gamma}", t["sec1_3-L-coefficients"].strip())
        if sets is None or any(not isinstance(lm.parse(sets[k]), AppliedUndef) or lm.parse(sets[k]).func != lm.Family
                               for k in ("rho", "gamma")):
            raise ValueError("not 'where rho_{2n,n,n}, {..}'")
        for n in range(1, 13):
            listed = sorted(constant_sets(t["sec1_3-L-coefficients"], n))
            rows = sorted(c for k in ("sec1_3-L-R-row", "sec1_3-L-G-row")
                          for c in term_indices(row_terms(t[k]), n=n))
            if listed != rows:
                bad.append(n)
    except ValueError as exc:
        bad.append(str(exc))
    res.holds_as_printed &= not bad
    res.detail["coefficients_mismatch"] = bad[:3]
    return res


def _proof_sets(printed_fn, computed_fn, rs=lambda n: [0], ns=N_PROOF, corrected_fn=None, kind="exact-evidence",
                how="index sets of the printed sums"):
    printed, computed, corrected = {}, {}, {}
    for n in ns:
        for r in rs(n):
            printed[(n, r)] = printed_fn(n, r)
            computed[(n, r)] = set(computed_fn(n, r))
            if corrected_fn:
                corrected[(n, r)] = corrected_fn(n, r)
    return _set_result(printed, computed, f"{how} against the elimination recomputed from exact derivatives, "
                       f"n = {ns.start}..{ns.stop - 1}", kind=kind, corrected=corrected if corrected_fn else None)


@line_check("sec1_3-Ltilde-set")
def ltilde_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Ltilde-set", lambda n, r: alive_after(n, 0, 0), override=override)


@line_check("sec1_3-Lhat-set")
def lhat_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Lhat-set", lambda n, r: alive_after(n, 0, 1), override=override)


@line_check("sec1_3-L0-set")
def l0_set(override=None) -> LineResult:
    return _read_sets("sec1_3-L0-set", lambda n, r: alive_after(n, 0, 2), override=override)


def listed_ranges(tex: str, var: str) -> list[tuple]:
    """Every listed range ``var=a,\\ldots,c`` or ``var=a,b,\\ldots,c`` of ``tex`` (a display, or the ``$..$``
    segments of a prose line; a segment latex_math does not read lists nothing): the items ``(a, [b,] ldots, c)`` of
    the clauses ``var in (..)`` of :func:`paper_repro.printed.latex_math.parse_relation`."""
    segs = lm.inline_math(tex) or [tex]
    v = sympy.Symbol(var)
    out = []
    for seg in segs:
        try:
            rel = lm.parse_relation(seg)
        except LatexMathError:
            if len(segs) == 1:
                raise
            continue
        for r in (rel, *rel.conditions):
            if r.ops and r.ops[-1] == "in" and r.parts[-2] == v and isinstance(r.parts[-1], sympy.Tuple):
                items = r.parts[-1].args
                if len(items) in (3, 4) and items[-2] == lm.LDOTS and lm.LDOTS not in items[:-2] + items[-1:]:
                    out.append(items)
    return out


def listed_range(tex: str, var: str) -> tuple[sympy.Expr, sympy.Expr]:
    """(first, last) of the first listed range ``var=a,[b,]\\ldots,c`` of ``tex`` (:func:`listed_ranges`)."""
    found = listed_ranges(tex, var)
    if not found:
        raise ValueError(f"no listed range {var}=a,...,b in {tex[:60]!r}")
    return found[0][0], found[0][-1]


def interval(tex: str, var: str) -> tuple[sympy.Expr, sympy.Expr]:
    """(lo, hi) of the closed interval of the clause ``var\\in\\left[ lo,hi\\right]`` of ``tex`` (a display, or the
    ``$..$`` segments of a prose line), read by :func:`paper_repro.printed.latex_math.parse_relation`."""
    v = sympy.Symbol(var)
    for seg in lm.inline_math(tex) or [tex]:
        try:
            rel = lm.parse_relation(seg)
        except LatexMathError:
            continue
        for r in (rel, *rel.conditions):
            rng = r.parts[-1] if r.parts else None
            if r.ops and r.ops[-1] == "in" and r.parts[-2] == v and isinstance(rng, sympy.Interval) and \
                    not rng.left_open and not rng.right_open:
                return rng.start, rng.end
    raise ValueError(f"no interval {var} in [lo, hi] in {tex[:60]!r}")


def listed_orders(tex: str, var: str, **env: int) -> list[range]:
    """Every listed range ``var=a,a+1,\\ldots,b`` of ``tex`` (:func:`listed_ranges`) as a range (``ValueError`` if
    there is none, or if a second listed value is not the first plus one)."""
    out = []
    found = listed_ranges(tex, var)
    if not found:
        raise ValueError(f"no listed range {var}=a,...,b in {tex[:50]!r}")
    for items in found:
        lo = _int_at(items[0], env)
        if len(items) == 4 and _int_at(items[1], env) != lo + 1:
            raise ValueError(f"{var}={items[0]},{items[1]},... does not step by one")
        out.append(range(lo, _int_at(items[-1], env) + 1))
    return out


def _orders(line_id: str, n: int) -> range:
    """The orders r of the listed range ``r=a,a+1,...,b`` read from the transcription of ``line_id``; for the
    hypothesis' orders (line sec1_3-Lr-orders) the line must say "for all orders" and "the coefficients of all
    discarded functions are equal to $0$", and the range must be all orders of the recomputed elimination."""
    tex = _transcribed([line_id])[line_id]
    (rng,) = listed_orders(tex, "r", n=n)
    if line_id == "sec1_3-Lr-orders":
        words = lm.sentence("for all orders {r}, where the coefficients of all discarded functions are equal to $0$.",
                            tex.strip())
        rel = _read_segment(words["r"]) if words else None
        if rel is None or not rel.ops or rel.parts[0] != sympy.Symbol("r"):
            raise ValueError("not 'for all orders r=.., where the coefficients ... are equal to $0$.'")
        if list(rng) != sorted({r for r, _p, _b, _g in elimination(n)}):
            raise ValueError(f"the orders {list(rng)} are not those of the elimination")
    return rng


@line_check("sec1_3-Lr-set")
def lr_set(override=None) -> LineResult:
    """L_r for the orders r of the printed range (line sec1_3-Lr-orders, r = 0..n-1)."""
    return _read_sets("sec1_3-Lr-set", lambda n, r: alive_after(n, r, 2), rs=lambda n: _orders("sec1_3-Lr-orders", n),
                      override=override)


@line_check("sec1_3-Lr1-set")
def lr1_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Lr1-set", lambda n, r: alive_after(n, r + 1, 2), rs=lambda n: range(n - 1),
                      override=override)


_ZEROED_WORDS = ("by evaluating its $$th order partial derivatives under parametrizations "
                 "(\\ref{parametrization_1_y_0})--(\\ref{parametrization_3_y_0}) with proper substitutions of $$, "
                 "where the combining constants $$ of all the omitted functions are equal to $$.")
_ZEROED_NAMES = {"rho": "R", "gamma": "G", "beta": "B"}


def _zeroed_constants(tex: str):
    r"""The parsed ``$..$`` segments of the line "by evaluating its $(r+1)$th order ... the combining constants
    ``\left\{ \rho_{2n,2n-i,r+1},\gamma_{2n,2n-i,r+1},\beta_{2n,2n-i,r+1}\right\} _{i=r+1}^{2n-1-(r+1)}`` ...
    are equal to $0$": ``(order, substituted value, the Family, the value)``, or None when the words differ, a
    segment is unread or the set is not a bounded set over one index of three constants rho, gamma, beta."""
    words, segs = lm.prose(tex)
    if words != _ZEROED_WORDS or len(segs) != 4:
        return None
    try:
        order, subst, family, value = (lm.parse(x) for x in segs)
    except LatexMathError:
        return None
    if not (isinstance(family, sympy.Function) and family.func == lm.Family):
        return None
    member, conds, bounds = family.args
    if conds or len(bounds) != 1 or not isinstance(member, sympy.Tuple) or len(member) != 3 or \
            [getattr(c.func, "__name__", None) for c in member] != list(_ZEROED_NAMES):
        return None
    return order, subst, family, value


@line_check("sec1_3-level-zeroed")
def level_zeroed(verbatim: str | None = None) -> LineResult:
    """The constants {rho, gamma, beta}_{2n,2n-i,r+1}, i = r+1..2n-1-(r+1) (every index, the bounds, the order
    r+1, the substituted 0 and the value 0 read from the transcription by :func:`latex_math.prose` and
    :func:`latex_math.parse`), are those set to 0 by the step r -> r+1."""

    tex = verbatim if verbatim is not None else _transcribed(["sec1_3-step-zeroed"])["sec1_3-step-zeroed"]
    read = _zeroed_constants(tex)
    r_ = sympy.Symbol("r")
    if read is None or sympy.expand(read[0] - (r_ + 1)) != 0 or read[1] != 0 or read[3] != 0:
        return LineResult(False, how="the constants read from the transcription", detail={"unread": tex[:60]})
    family = read[2]

    def printed(n, r):
        strict = {lb.paper: k for k, lb in enumerate(united_system(n))}
        out = set()
        for triple in parsed.members(family, n=n, r=r):
            for c in triple:
                key = f"{_ZEROED_NAMES[c.func.__name__]}_{{{','.join(str(a) for a in c.args)}}}"
                out.add(strict.get(key, key))
        return out
    return _proof_sets(printed, lambda n, r: alive_after(n, r, 2) - alive_after(n, r + 1, 2), rs=lambda n: range(n - 1),
                       how="constants of the printed set (every index, the range and the value parsed from the "
                           "transcription)")


@line_check("sec1_3-Ltilde-r-set")
def ltilde_r_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Ltilde-r-set", lambda n, r: alive_after(n, r + 1, 0), rs=lambda n: range(n - 1),
                      override=override)


@line_check("sec1_3-Lhat-r-set")
def lhat_r_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Lhat-r-set", lambda n, r: alive_after(n, r + 1, 1), rs=lambda n: range(n - 1),
                      override=override)


@line_check("sec1_3-Ln2-set")
def ln2_set(override=None) -> LineResult:
    return _read_sets("sec1_3-Ln2-set", lambda n, r: alive_after(n, n - 2, 2), ns=range(2, N_PROOF.stop),
                      override=override)


def bound_n(expr: str | sympy.Expr, n: int) -> int:

    return bound(expr, n=n)


def _names_set(n: int, idx) -> set[str]:
    return set(_names(n, idx))


@line_check("sec1_3-Ln1-set")
def ln1_set(override=None) -> LineResult:
    """L_{n-1} = rho_{2n,n,n} R_{2n,n,n}, and R_{2n,n,n} is not the zero function (so rho_{2n,n,n} = 0)."""
    res = _read_sets("sec1_3-Ln1-set", lambda n, r: alive_after(n, n - 1, 2), override=override)
    try:  # '0=L_{n-1}\left( u,v,w\right) =..': the order of L read by the one reader
        ln1 = lm.parse_relation(_transcribed(["sec1_3-Ln1"], override)["sec1_3-Ln1"])
        lcall = ln1.parts[1] if len(ln1.parts) > 2 else None
        head = (lcall.args[0] if ln1.ops[:2] == ["=", "="] and ln1.parts[0] == 0 and isinstance(lcall, AppliedUndef)
                and lcall.func.__name__ == "L" and len(lcall.args) == 2
                and lcall.args[1] == sympy.Tuple(*sympy.symbols("u v w")) else None)
    except LatexMathError:
        head = None
    # the equality is L_r for the last order r of the recomputed elimination
    res.holds_as_printed &= head is not None and all(
        bound_n(head, n) == max(r for r, _p, _b, _g in elimination(n)) for n in N_PROOF)
    pt = _domain_points(ALPHA_TS[0], 1)[0]
    nonzero = all(pt[0][0] ** n * pt[1][0] ** n * pt[2][0] ** n != 0 for n in N_PROOF)
    # "equality (..n_minus_1) holds if and only if \\[ \\rho_{2n,n,n}=0, \\]" (the words, then the display read by
    # the one reader): the one constant of L_{n-1}, and the value 0 that R_{2n,n,n} != 0 forces
    tex = _transcribed(["sec1_3-rho-centre-zero"], override)["sec1_3-rho-centre-zero"]
    words = " ".join(tex.split("\\[", 1)[0].replace("%", " ").split())
    try:
        rel = lm.parse_relation(tex) if "\\[" in tex and tex.rstrip().endswith("\\]") else None
        rho = rel.parts[0] if rel is not None and rel.ops == ["="] and not rel.conditions else None
        if not (isinstance(rho, AppliedUndef) and rho.func.__name__ == "rho" and len(rho.args) == 3
                and rho.args[0] == 2 * sympy.Symbol("n") and rel.parts[1].is_Integer):
            rho = None
    except LatexMathError:
        rho = None
    read = rho is not None and words == ("Moreover, equality (\\ref{induction_hypothesis_for_linear_independence_"
                                         "n_minus_1}) holds if and only if")
    names_ok = read and all(
        {f"R_{{{2 * n},{bound_n(rho.args[1], n)},{bound_n(rho.args[2], n)}}}"}
        == _names_set(n, alive_after(n, n - 1, 2)) for n in N_PROOF)
    res.holds_as_printed &= nonzero and names_ok and read and rel.parts[1] == 0
    res.detail["centre_nonzero_at_a_point"] = nonzero
    res.detail["rho_centre_zero_read"] = read and names_ok
    return res


def _orders_prose(t: dict[str, str]) -> None:
    """The words of the lines about the orders of the induction, read (``ValueError`` if one is not as the proof
    does it): the hypothesis is on the "$r$th order" under the three parametrizations "with respect to variables"
    equal to their points, each the running parameter of its printed map; the step goes "from $r$ to $r+1$ for all
    orders"; the conclusion evaluates "the $\\left( r+1\\right) $th order" derivatives with the "zero constants"
    obtained and holds "for all orders"; the figure's caption shows "three consecutive steps" (the three
    parametrizations) whose "first (resp. (n-1)th) order partial derivatives vanish"; the text after it names the
    equalities 0 = L_0 and 0 = L_{n-2} on Omega^alpha under the successive parametrizations."""
    r_ = sympy.Symbol("r")

    def of_r(seg: str | None) -> bool:  # a segment r=.. (its listed range is read by the caller)
        rel = _read_segment(seg) if seg is not None else None
        return rel is not None and bool(rel.ops) and rel.parts[0] == r_

    rng = _layout_free(t["sec1_3-induction-range"])
    pairs = read_boundary_vars(rng)
    words = lm.sentence("an induction hypothesis with respect to the $r$th order ({r}) partial derivative", rng,
                        search=True)
    if words is None or not of_r(words["r"]) or \
            _resp_vars(rng) != [[v for _p, v in pairs]] or any(PARAMS[p][1] != v for p, v in pairs):
        raise ValueError("induction-range: words")
    words = lm.sentence("we prove our hypothesis from $r$ to $r+1$ for all orders {r}",
                        _layout_free(t["sec1_3-step-range"]), search=True)
    if words is None or not of_r(words["r"]):
        raise ValueError("step-range: words")
    words = lm.sentence(
        r"Summarizing all calculations and zero constants obtained above, by evaluating the $\left( r+1\right) $th "
        r"order ({r1}) partial derivatives under successive parametrizations (\ref{parametrization_1_y_0} )--"
        r"(\ref{parametrization_3_y_0}) of the initial equality (\ref{induction_hypothesis_for_linear_independence}), "
        r"we conclude that equality (\ref{induction_hypothesis_nex_step}) is also valid, i.e., the induction "
        r"hypothesis (\ref{induction_hypothesis_for_linear_independence}) is correct for all orders {r2}.",
        _layout_free(t["sec1_3-induction-conclusion"]).strip())
    if words is None or not of_r(words["r1"]) or not of_r(words["r2"]):
        raise ValueError("induction-conclusion: words")
    cap = _layout_free(t["sec1_3-fig-j1-caption-orders"])
    steps = lm.sentence(r"Cases (\emph{a})--(\emph{c}) and (\emph{d})--(\emph{f}) illustrate {k:count} consecutive "
                        "steps", cap, search=True)
    orders = lm.sentence("whose first (resp. {a}th) order partial derivatives vanish when one evaluates the first "
                         "(resp. {b}th) order partial derivatives of", cap, search=True)
    last = sympy.Symbol("n") - 1
    if steps is None or steps["k"] != len(STEP_PARAMS) or orders is None or \
            any(_read_segment(orders[x]) is None or _read_segment(orders[x]).parts != [last] for x in "ab"):
        raise ValueError("fig-j1-caption-orders: words")
    txt = _layout_free(t["sec1_3-fig-j1-text"])
    eqs = _zero_l_orders(txt)
    if len(eqs) != 2 or lm.sentence(r"under successive parametrizations (\ref{parametrization_1_y_0} )--"
                                    r"(\ref{parametrization_3_y_0}), respectively", txt, search=True) is None:
        raise ValueError("fig-j1-text: words")


def _zero_l_orders(tex: str) -> list[sympy.Expr]:
    """The orders k of the displays ``\\[ 0=L_{k}\\left( u,v,w\\right) ,~\\forall\\left( u,v,w\\right)
    \\in\\Omega^{\\alpha} \\]`` of a prose line, each display read by :func:`latex_math.parse_relation`
    (``ValueError`` if a display is another formula)."""
    out = []
    uvw = sympy.Tuple(*sympy.symbols("u v w"))
    for chunk in tex.split("\\[")[1:]:
        rel = lm.parse_relation(chunk.split("\\]")[0])
        lhs, rhs = (rel.parts + [None, None])[:2]
        cond = rel.conditions[0] if len(rel.conditions) == 1 else None
        if rel.ops != ["="] or lhs != 0 or not (isinstance(rhs, AppliedUndef) and rhs.func.__name__ == "L"
                                                 and len(rhs.args) == 2 and rhs.args[1] == uvw) or \
                cond is None or cond.quantifier != "forall" or cond.ops != ["in"] or \
                cond.parts != [uvw, sympy.Symbol("Omega")]:
            raise ValueError(f"not 0 = L_k(u,v,w) for all (u,v,w) in Omega: {chunk[:50]!r}")
        out.append(rhs.args[0])
    return out


def _r_values(tex: str) -> list[sympy.Expr]:
    """The values X of the ``$r=X$`` segments of a prose line (:func:`latex_math.parse_relation`)."""
    r_ = sympy.Symbol("r")
    out = []
    for seg in lm.inline_math(tex):
        try:
            rel = lm.parse_relation(seg)
        except LatexMathError:
            continue
        if rel.ops == ["="] and rel.parts[0] == r_ and not rel.conditions:
            out.append(rel.parts[1])
    return out


@line_check("sec1_3-elimination-orders")
def elimination_orders(override: dict[str, str] | None = None) -> LineResult:
    """The derivative orders the proof uses, read from five of its lines and compared with the elimination
    recomputed from exact derivatives: level j is removed by the order-j steps (parametrizations 1, 2, 3); L_r
    exists, non-empty, for r = 0..n-1 (induction-range); the steps r -> r+1 are r = 0..n-2 (step-range,
    induction-conclusion); the figure shows the first and last of them, r = 0 and r = n-2, with derivatives of
    orders r + 1 of L_r."""
    ids = ("sec1_3-induction-range", "sec1_3-step-range", "sec1_3-induction-conclusion",
           "sec1_3-fig-j1-caption-orders", "sec1_3-fig-j1-text")
    t = _transcribed(ids, override)
    try:
        ranges = {k: listed_range(t[k], "r") for k in ids[:3]}
        for k in ids[:3]:  # every listing of the line steps by one and they agree
            if len({(x.start, x.stop) for x in listed_orders(t[k], "r", n=5)}) != 1:
                raise ValueError(f"{k}: listings differ")
        _orders_prose(t)
        caption_r = _r_values(t["sec1_3-fig-j1-caption-orders"])
        ordinals = lm.sentence("the evaluation of the first and {k}th order partial derivatives",
                               _layout_free(t["sec1_3-fig-j1-text"]), search=True)
        if ordinals is None:
            raise ValueError("fig-j1-text: orders")
        text_orders = [("first", None), ("", lm.parse(ordinals["k"]))]
        text_l = _zero_l_orders(t["sec1_3-fig-j1-text"])
    except ValueError as exc:
        return LineResult(False, how="the orders read from the transcriptions", detail={"unread": str(exc)})
    bad = []
    for n in N_PROOF:
        labels = united_system(n)
        removed_at = sorted({r for r, _p, _b, gone in elimination(n) if gone})
        levels_ok = all(labels[k].j == r and not labels[k].is_centre for r, _p, _b, gone in elimination(n)
                        for k in gone) and alive_after(n, n - 1, 2) == frozenset({0})
        want = {"sec1_3-induction-range": removed_at,  # the orders whose steps remove a level
                "sec1_3-step-range": [r for r in range(n) if r + 1 < n],
                "sec1_3-induction-conclusion": [r for r in range(n) if r + 1 < n]}
        for k, (lo, hi) in ranges.items():
            if list(range(bound(lo, n=n), bound(hi, n=n) + 1)) != want[k]:
                bad.append(f"n={n}: {k}")
        steps = want["sec1_3-step-range"]
        if n >= 2:
            shown = [bound(x, n=n) for x in caption_r]
            orders = [1 if o == "first" else bound(e, n=n) for o, e in text_orders]
            if shown != [steps[0], steps[-1]] or orders != [r + 1 for r in shown] or \
                    [bound(x, n=n) for x in text_l] != shown:
                bad.append(f"n={n}: figure")
        if not levels_ok:
            bad.append(f"n={n}: levels")
    return LineResult(not bad, how="orders read from the five transcriptions against the elimination recomputed from "
                      f"exact derivatives, n = 1..{N_PROOF.stop - 1}", kind="exhaustive",
                      detail={"ranges": {k: [str(x) for x in v] for k, v in ranges.items()}, "mismatches": bad[:3]})


@line_check("sec1_3-induction-orders")
def induction_orders(verbatim_text: str | None = None) -> LineResult:
    """"we argue by mathematical induction on the derivation order $r=0,1,\\ldots,n$" (range read): the orders of the
    derivatives the proof takes are those of the recomputed elimination -- the order-0 steps and the steps of order
    r + 1, r = 0..n-2 -- i.e. 0..n-1 (level j is removed by the order-j steps; after them only the centre is left,
    which the proof removes by R_{2n,n,n} != 0, without a derivative), and the hypothesis it proves is stated for
    r = 0..n-1 (line sec1_3-Lr-orders, read).  Printed: 0..n; corrected: 0..n-1."""
    tex = verbatim_text if verbatim_text is not None else _transcribed(["sec1_3-induction-orders"])[
        "sec1_3-induction-orders"]

    def run(lo: sympy.Expr, hi: sympy.Expr) -> tuple[bool, list]:
        hyp_lo, hyp_hi = listed_range(_transcribed(["sec1_3-Lr-orders"])["sec1_3-Lr-orders"], "r")
        bad = []
        for n in N_PROOF:
            used = sorted({r for r, _p, _b, gone in elimination(n) if gone})
            printed = list(range(bound(lo, n=n), bound(hi, n=n) + 1))
            hyp = list(range(bound(hyp_lo, n=n), bound(hyp_hi, n=n) + 1))
            if printed != used or printed != hyp or alive_after(n, n - 1, 2) != frozenset({0}):
                bad.append({"n": n, "printed": printed, "orders_used": used})
        return not bad, bad
    try:
        words = lm.sentence("In order to prove the statement, we argue by mathematical induction on the derivation "
                            "order {r}.", tex)
        if words is None:
            raise ValueError("not the induction on the derivation order")
        lo, hi = listed_range(words["r"], "r")
        listed_orders(words["r"], "r", n=N_PROOF.stop - 1)  # the listing steps by one (ValueError if not)
        ok, bad = run(lo, hi)
        # the erratum's correction, on the parsed range: the last order n is n - 1
        corr = run(lo, hi - 1)[0] if hi == sympy.Symbol("n") else None
    except ValueError as exc:
        return LineResult(False, how="the range read from the transcription", detail={"unread": str(exc)})
    return LineResult(ok, corr, how="the printed range of orders against the orders of the elimination recomputed from "
                      f"exact derivatives and the range of the hypothesis (read), n = 1..{N_PROOF.stop - 1}",
                      kind="exhaustive", detail={"mismatches": bad[:3]})


# -- value lines: linear forms in the combining constants -----------------------------------------------------
def _computed_form(n: int, param: str, r: int, alive, pt) -> dict[int, fmpq]:
    labels = united_system(n)
    out = {k: step_value(exponents(labels[k]), param, r, pt) for k in alive}
    return {k: v for k, v in out.items() if v != 0}


def _compare_forms(printed_fn, computed_fn, ns=N_PROOF, rs=lambda n: [0], corrected_fn=None) -> LineResult:
    """printed_fn(n, r, pt) / computed_fn(n, r, pt): {function index: value multiplying its constant}."""
    bad, bad_corr, cases = [], [], 0
    for n in ns:
        for r in rs(n):
            for at in ALPHA_TS:
                for x in X_FRACTIONS:
                    pt = boundary_point(at, x)
                    pt["n"], pt["alpha_t"] = n, at
                    comp = computed_fn(n, r, pt)
                    cases += 1
                    pr = {k: v for k, v in printed_fn(n, r, pt).items() if v != 0}
                    if pr != comp:
                        bad.append({"n": n, "r": r, "printed_only": _names(n, set(pr) - set(comp)),
                                    "computed_only": _names(n, set(comp) - set(pr)),
                                    "values_differ": _names(n, {k for k in set(pr) & set(comp) if pr[k] != comp[k]})})
                    if corrected_fn is not None:
                        co = {k: v for k, v in corrected_fn(n, r, pt).items() if v != 0}
                        bad_corr.append(co != comp)
    detail = {"cases": cases, "mismatches": len(bad), "first_mismatches": bad[:2]}
    corr = None
    if corrected_fn is not None:
        corr = not any(bad_corr)
        detail["corrected_mismatches"] = sum(bad_corr)
    return LineResult(not bad, corr, how="printed terms (as coefficients of the combining constants) against exact "
                      f"derivatives along the parametrization, n = {ns.start}..{ns.stop - 1}, tan(alpha/4) in "
                      "{1/2, 3/4}, two boundary points each", detail=detail)


def _sn(pt, var: str, k: int) -> fmpq:
    """sin^k of half the boundary angle: var 't' or 'alpha-t'."""
    return pt[var][0] ** k


def _c(pt, i: int) -> fmpq:
    return c_const(pt["n"], i, rational_alpha(pt["alpha_t"]), "exact")


def _A(pt, k: int) -> fmpq:
    """A_{2n,k}(t) (eq. univariate_basis) at the boundary parameter t."""
    n = pt["n"]
    return _c(pt, k) * _sn(pt, "alpha-t", 2 * n - k) * _sn(pt, "t", k)


# -- Section 3 values read from the transcriptions (paper_repro.printed.latex_math) -----------------------------
@dataclass(frozen=True)
class Factor:
    """One printed factor of a term of the proof, from the parsed expression.  ``kind``: ``trig`` (sin^s cos^c of half
    an argument, ``deriv`` = (order, coordinate) when differentiated), ``bar`` (an evaluation bar at ``args[0]`` = 0),
    ``S``/``M`` (derivatives at 0 of Lemma lem:sign_cos_power_derivative / Proposition derivative_cosine_sine:
    ``(indices, order)``), ``c`` (normalizing constant: ``(k,)``), ``A`` (univariate function: ``(k, variable)``).
    An argument is a coordinate ``("u", 1)`` of a parametrization or a linear form (a sympy expression)."""

    kind: str
    args: tuple
    deriv: tuple | None = None


@dataclass
class Term:
    """A printed term: its sums ``[(var, lo, hi), ...]`` (outermost first), its combining constant (colour, first
    index, level, primed) and its factors."""

    sums: list
    constant: tuple | None
    factors: list = field(default_factory=list)


_TWO_N = 2 * sympy.Symbol("n")
_PRIMED = {"rho_prime": "R", "gamma_prime": "G", "beta_prime": "B"}


def _coordinate(arg: sympy.Expr):
    """``u(1, (x, y))`` -> ``("u", 1)``, ``u((x, y))`` -> ``("u", None)``; anything else is returned as it is (a
    linear form, checked where it is evaluated)."""
    if isinstance(arg, AppliedUndef) and arg.func.__name__ in ("u", "v", "w"):
        idx = arg.args[:-1] if arg.args and isinstance(arg.args[-1], sympy.Tuple) else arg.args
        if len(idx) > 1 or (idx and not idx[0].is_Integer):
            raise LatexMathError(f"the coordinate {arg} is not u_k(x, y)")
        return arg.func.__name__, int(idx[0]) if idx else None
    return arg


def _trig_factors(e: sympy.Expr) -> list[tuple[str, sympy.Expr, object]]:
    """(sin or cos, exponent, half-angle argument) of a product of powers of sin(X/2), cos(X/2)."""
    out = []
    for f in sympy.Mul.make_args(e):
        base, exp = f.as_base_exp()
        if not isinstance(base, (sympy.sin, sympy.cos)):
            raise LatexMathError(f"the factor {f} is not a power of a half-angle sine or cosine")
        out.append(("sin" if isinstance(base, sympy.sin) else "cos", exp, _coordinate(sympy.expand(2 * base.args[0]))))
    return out


def _factors_of(e: sympy.Expr) -> list[Factor]:
    """The factors of the coefficient part of a term (trigonometric powers, derivatives of them, evaluation bars)."""
    out: list[Factor] = []
    for f in sympy.Mul.make_args(e):
        if f == 1:
            continue
        if isinstance(f, sympy.Subs):
            inner, (var,), (val,) = f.args
            if val != 0:
                raise LatexMathError(f"an evaluation bar at {var} = {val}, not 0")
            out += _factors_of(inner)
            out.append(Factor("bar", (str(var),)))
        elif isinstance(f, AppliedUndef) and f.func == lm.D:
            body, *specs = f.args
            if len(specs) != 1:
                raise LatexMathError(f"a derivative in {len(specs)} variables")
            var, order = specs[0]
            trig = _trig_factors(body)
            args = {a for _, _, a in trig}
            if len(args) != 1 or _coordinate(var) != next(iter(args)):
                raise LatexMathError("a derivative of sines and cosines of another argument")
            s = sum((x for k, x, _ in trig if k == "sin"), sympy.Integer(0))
            c = sum((x for k, x, _ in trig if k == "cos"), sympy.Integer(0))
            out.append(Factor("trig", ((s, c), args.pop()), (order, _coordinate(var))))
        else:
            for kind, x, arg in _trig_factors(f):
                out.append(Factor("trig", ((x, sympy.Integer(0)) if kind == "sin" else (sympy.Integer(0), x), arg)))
    return out


def read_products(expr: sympy.Expr) -> list[Term]:
    """The terms of a parsed sum of products of the proof (:func:`paper_repro.printed.latex_math.terms` after the
    products of a parenthesised sum are multiplied out): the sums of each term, its combining constant (rho, gamma,
    beta, possibly primed) and its factors (:class:`Factor`); :class:`LatexMathError` for anything else (a
    coefficient, an unknown name, a second constant)."""
    expr = sympy.expand(expr, deep=False, mul=True, multinomial=False, power_exp=False, power_base=False, log=False)
    out = []
    for t in lm.terms(expr):
        constant, factors = None, []
        named = [f for f in sympy.Mul.make_args(t.coefficient) if isinstance(f, AppliedUndef) and f.func != lm.D]
        rest = sympy.Mul(*[f for f in sympy.Mul.make_args(t.coefficient) if f not in named])
        for f in [*t.names, *named]:
            name = f.func.__name__
            if name in _CONST_COLOUR or name in _PRIMED:
                if constant is not None or len(f.args) != 3 or f.args[0] != _TWO_N:
                    raise LatexMathError(f"the constant {f} (a second constant, or not of order 2n)")
                constant = (_CONST_COLOUR.get(name) or _PRIMED[name], f.args[1], f.args[2], name in _PRIMED)
            elif name == "c" and len(f.args) == 2 and f.args[0] == _TWO_N:
                factors.append(Factor("c", (f.args[1],)))
            elif name == "A" and len(f.args) == 3 and f.args[0] == _TWO_N and len(f.args[2]) == 1:
                factors.append(Factor("A", (f.args[1], f.args[2][0])))
            elif name == "S_sup" and len(f.args) == 4 and f.args[3] == sympy.Tuple(0):
                factors.append(Factor("S", ((f.args[0], f.args[1]), f.args[2])))
            elif name == "M_sup" and len(f.args) == 6 and f.args[5] == sympy.Tuple(0):
                factors.append(Factor("M", (tuple(f.args[:4]), f.args[4])))
            elif f.func == lm.D:
                factors += _factors_of(f)
            else:
                raise LatexMathError(f"the factor {f} is not read")
        factors += _factors_of(rest)
        out.append(Term([(str(v), lo, hi) for v, lo, hi in t.limits], constant, factors))
    if not out:
        raise LatexMathError("no product read")
    return out


def _rate(x) -> Fraction:
    """An angular velocity of S or M (a parsed rational) as a Fraction."""
    x = sympy.sympify(x)
    if not x.is_Rational:
        raise LatexMathError(f"the rate {x} is not a number")
    return Fraction(int(x.p), int(x.q))


def read_prime_definition(tex: str) -> tuple[tuple[str, sympy.Expr], list[tuple]]:
    """A printed definition ``\\rho_{2n,2n-i,L}^{\\prime} = \\left\\{ CONST/c_{2n,K}^{\\alpha}, & i=a,..,b \\\\
    ..``: ((colour, L), [((colour, first index, level) of CONST, K, first i, last i), ...]), every row read by
    :func:`paper_repro.printed.latex_math.parse_relation` (value and clause); a single case ``i=2n-(r+1)`` has
    first = last; a listed range ``a,b,\\ldots,c`` must step by one."""
    rel = lm.parse_relation(tex)
    head = rel.parts[0] if rel.parts else None
    if rel.ops != ["="] or not isinstance(head, AppliedUndef) or head.func.__name__ not in _PRIMED or \
            len(head.args) != 3 or head.args[0] != _TWO_N or sympy.expand(head.args[1] - _TWO_N + sympy.Symbol("i")):
        raise LatexMathError(f"no primed constant X'_{{2n,2n-i,L}} defined in {tex[:60]!r}")
    i = sympy.Symbol("i")
    value = rel.parts[1]
    if isinstance(value, AppliedUndef) and value.func == lm.Cases:  # the rows, each with its clause, re-read
        arrays: list = []
        lm.clean(lm._display_math(tex), arrays)
        rows = [lm.parse_relation(row[0].strip().rstrip(",") + " , " + row[1]) if len(row) == 2 else row
                for row in (arrays[0] if arrays else []) if any(c.strip() for c in row)]
    else:  # one case: X' = CONST/c, i = ..
        rows = [lm.Relation([value], [], conditions=rel.conditions)]
    cases = []
    for r in rows:
        if not isinstance(r, lm.Relation):
            raise LatexMathError(f"a case row with {len(r)} cells")
        num, den = sympy.fraction(r.parts[0]) if len(r.parts) == 1 and not r.ops else (None, None)
        if not (isinstance(num, AppliedUndef) and num.func.__name__ in _CONST_COLOUR and len(num.args) == 3
                and num.args[0] == _TWO_N and isinstance(den, AppliedUndef) and den.func.__name__ == "c"
                and len(den.args) == 2 and den.args[0] == _TWO_N) or len(r.conditions) != 1:
            raise LatexMathError(f"the case {r.parts} is not CONST/c_{{2n,K}}, i = ..")
        cond = r.conditions[0]
        if cond.parts[0] != i or len(cond.parts) != 2:
            raise LatexMathError(f"the case condition {cond} is not on i")
        if cond.ops == ["="]:
            first = last = cond.parts[1]
        elif cond.ops == ["in"] and isinstance(cond.parts[1], sympy.Tuple):
            items = cond.parts[1].args
            if len(items) not in (3, 4) or items[-2] != lm.LDOTS or lm.LDOTS in items[:-2]:
                raise LatexMathError(f"unread range {items}")
            if len(items) == 4 and sympy.expand(items[1] - items[0] - 1) != 0:
                raise LatexMathError(f"the listed range {items} does not step by one")
            first, last = items[0], items[-1]
        else:
            raise LatexMathError(f"unread case condition {cond}")
        cases.append(((_CONST_COLOUR[num.func.__name__], num.args[1], num.args[2]), den.args[1], first, last))
    if not cases:
        raise LatexMathError(f"no case of the definition read in {tex[:60]!r}")
    return (_PRIMED[head.func.__name__], head.args[2]), cases


def _unit(half: tuple[fmpq, fmpq]) -> tuple[fmpq, fmpq]:
    """(cos, sin) of a half angle from (sin, cos): the unit complex number exp(i h)."""
    return half[1], half[0]


def _half_of(pt, p_alpha: int, q_t: int) -> tuple[fmpq, fmpq]:
    """(sin, cos) of half the angle p_alpha * alpha + q_t * t at the boundary point (exact, by angle addition)."""
    ea, et = _unit(pt["alpha"]), _unit(pt["t"])

    def power(e, k):
        e = e if k >= 0 else (e[0], -e[1])
        return _cpow(e, abs(k))
    c, s = _cmul(power(ea, p_alpha), power(et, q_t))
    return s, c


def _arg_half(arg, param_index: int, pt) -> tuple[fmpq, fmpq]:
    """Half angles of a printed argument at the boundary of the step: a coordinate ``u_1`` of the printed
    parametrization (its index must be the step's), or a linear form in alpha, x, y; (x, y) = (t, 0) when the
    running parameter is y, (0, t) when it is x."""

    _fmap, run, maps, _ranges = _params()[STEP_PARAMS[param_index]]
    if isinstance(arg, tuple):  # a coordinate (letter, index) of the parametrization
        letter, idx = arg
        if idx is None:
            raise ValueError(f"an unindexed coordinate {letter} in a step of the proof")
        if idx != param_index + 1:
            raise ValueError(f"{letter}_{idx} in the step of parametrization {param_index + 1}")
        a, x, y = maps["uvw".index(letter)]
    else:
        a, x, y = linear_form(arg)
    return _half_of(pt, a, x if run == "y" else y)


def bound(expr, **env: int) -> int:
    """Integer value of a printed bound such as ``2n-1-j`` (read by :func:`parse`) with ``env`` bound."""
    return _expr(expr, env)


def _expr(expr, env: dict) -> int:
    """Integer value of a parsed index or bound (or of its LaTeX, read by :func:`parse`) at ``env``."""
    return _int_at(lm.parse(expr) if isinstance(expr, str) else expr, {str(k): v for k, v in env.items()})


def _factor_value(f, env: dict, param_index: int, pt, orders=None) -> fmpq:
    """Value of one printed factor (:class:`Factor`) at the boundary point.
    ``orders`` = (z, k) replaces the printed orders of S, M (z) and of a derivative (k) -- the factor structure
    tested at other orders; the printed orders are compared with the step's apart."""
    n = env["n"]
    if f.kind == "bar":
        run = _params()[STEP_PARAMS[param_index]][1]
        if f.args[0] != run:
            raise ValueError(f"evaluated at {f.args[0]} = 0 in a step at {run} = 0")
        return fmpq(1)
    if f.kind == "trig":
        (s, c), arg = f.args
        half = _arg_half(arg, param_index, pt)
        k = 0
        if f.deriv:
            if f.deriv[1] != arg:
                raise ValueError(f"d/d{f.deriv[1]} of a function of {arg}")
            k = orders[1] if orders else _expr(f.deriv[0], env)
        s_v, c_v = _expr(s, env), _expr(c, env)
        if min(s_v, c_v, k) < 0:
            raise ValueError("a negative power or order")
        return _factor_derivative(s_v, c_v, k, half)
    if f.kind in ("S", "M"):
        sub, order = f.args
        z = orders[0] if orders else _expr(order, env)
        if f.kind == "S":
            if len(sub) != 2:
                raise ValueError(f"S with {len(sub)} indices")
            j, mu = _expr(sub[0], env), _rate(sub[1])
            if j < 0 or z < 0:
                raise ValueError("a negative power or order")
            return sin_power_derivative(j, fmpq(mu.numerator, mu.denominator), z)
        if len(sub) != 4:
            raise ValueError(f"M with {len(sub)} indices")
        i, lam, j, mu = _expr(sub[0], env), _rate(sub[1]), _expr(sub[2], env), _rate(sub[3])
        if min(i, j, z) < 0:
            raise ValueError("a negative power or order")
        return mixed_derivative(i, fmpq(lam.numerator, lam.denominator), j, fmpq(mu.numerator, mu.denominator), z)
    if f.kind == "c":
        k = _expr(f.args[0], env)
        if not 0 <= k <= 2 * n:
            raise ValueError(f"c_{{2n,{k}}} does not exist")
        return _c(pt, k)
    if f.kind == "A":
        k = _expr(f.args[0], env)
        if not 0 <= k <= 2 * n:
            raise ValueError(f"A_{{2n,{k}}} does not exist")
        var = _arg_half(f.args[1], param_index, pt)
        rest = _arg_half(sympy.Symbol("alpha") - f.args[1], param_index, pt)
        return _c(pt, k) * rest[0] ** (2 * n - k) * var[0] ** k
    raise ValueError(f"unknown factor {f.kind}")


def _prime_defs(line_ids) -> dict[str, tuple]:
    """{colour of the primed constant: (level expression, cases)} read from the definition lines."""
    out = {}
    for lid in line_ids:
        (color, level), cases = read_prime_definition(_transcribed([lid])[lid])
        out[color] = (level, cases)
    return out


def _constant_key(const, env: dict, pt, primes: dict | None, used: set | None = None) -> tuple[object, fmpq]:
    """(member of T_{2n} the printed constant multiplies -- a string if no member --, factor of its value): a primed
    constant is resolved through its printed definition (the constant it stands for, divided by c)."""
    color, first, level, primed = const
    n = env["n"]
    strict = {lb.paper: k for k, lb in enumerate(united_system(n))}
    first_v, level_v = _expr(first, env), _expr(level, env)
    if not primed:
        name = f"{color}_{{{2 * n},{first_v},{level_v}}}"
        return strict.get(name, name), fmpq(1)
    if not primes or color not in primes:
        raise ValueError(f"a primed {color} constant without its definition")
    def_level, cases = primes[color]
    if _expr(def_level, env) != level_v:
        return f"{color}'_{{{2 * n},{first_v},{level_v}}} (undefined level)", fmpq(1)
    i = 2 * n - first_v
    if used is not None:
        used.add((color, i))
    for (c2, f2, l2), cidx, lo, hi in cases:
        scope = {**env, "i": i}
        if _expr(lo, scope) <= i <= _expr(hi, scope):
            name = f"{c2}_{{{2 * n},{_expr(f2, scope)},{_expr(l2, scope)}}}"
            ck = _expr(cidx, scope)
            if not 0 <= ck <= 2 * n:
                raise ValueError(f"c_{{2n,{ck}}} does not exist")
            return strict.get(name, name), 1 / _c(pt, ck)
    return f"{color}'_{{{2 * n},{first_v},{level_v}}} (undefined i)", fmpq(1)


def evaluate_terms(terms, env: dict, param_index: int, pt, primes: dict | None = None, orders=None,
                   used: set | None = None) -> dict:
    """{member of T_{2n} (or a printed name that is none): the value its constant multiplies} of printed terms."""
    out: dict = {}

    def walk(term, sums, scope):
        if not sums:
            key, scale = _constant_key(term.constant, scope, pt, primes, used)
            val = scale
            for f in term.factors:
                val *= _factor_value(f, scope, param_index, pt, orders)
            out[key] = out.get(key, fmpq(0)) + val
            return
        (v, lo, hi), rest = sums[0], sums[1:]
        for x in range(_expr(lo, scope), _expr(hi, scope) + 1):
            walk(term, rest, {**scope, v: x})

    for term in terms:
        if term.constant is None:
            raise ValueError("a term without a combining constant")
        walk(term, term.sums, dict(env))
    return out


def _pt(n: int, at: fmpq, x: fmpq):
    pt = boundary_point(at, x)
    pt["n"], pt["alpha_t"], pt["alpha"] = n, at, _half(at)
    return pt


def _A_at(pt, k: int, var: str) -> fmpq:
    """A_{2n,k} at the boundary coordinate named var ('t' is the parameter; 'alpha-t' its complement)."""
    n = pt["n"]
    other = "alpha-t" if var == "t" else "t"
    return _c(pt, k) * _sn(pt, other, 2 * n - k) * _sn(pt, var, k)


def _computed_step(param_index: int, order=lambda r: r, alive_fn=None):
    def fn(n, r, pt):
        alive = alive_fn(n, r) if alive_fn else alive_before(n, r, param_index)
        return _computed_form(n, STEP_PARAMS[param_index], order(r), alive, pt)
    return fn


def read_terms_at_edge(line_id: str, param_index: int, verbatim: str | None = None):
    """The printed terms constant x function(point) of an order-0 step, read from the transcription: a function
    ``(n, r, pt) -> {member of T_{2n}: its value at the boundary point}`` of the functions it names (by their own
    names), after checking that the printed point is the step's parametrization at running parameter 0.  A name
    that is no member of T_{2n} is kept as a string (a mismatch)."""
    tex = verbatim if verbatim is not None else _transcribed([line_id])[line_id]
    rel = lm.parse_relation(tex)
    if rel.lead not in (None, "=") or rel.ops or rel.conditions:
        raise LatexMathError(f"not a row '= sum of terms': {rel.lead} {rel.ops} {len(rel.conditions)} clauses")
    terms = combination_terms(rel.parts[-1])
    fmap, run = PARAMS[STEP_PARAMS[param_index]]
    a, q = fmpq(7, 5), fmpq(2, 5)  # the printed point and the map compared at exact values of alpha and the parameter
    at0 = fmap(a, q, fmpq(0)) if run == "y" else fmap(a, fmpq(0), q)
    other = "x" if run == "y" else "y"
    at = {sympy.Symbol("alpha"): sympy.Rational(7, 5), sympy.Symbol(other): sympy.Rational(2, 5)}
    points = {args for *_, args in terms}
    readable = []
    for pt in points:
        vals = [sympy.sympify(c).subs(at) for c in pt]
        if not all(v.is_Rational for v in vals):
            raise LatexMathError(f"unread point {pt}")
        readable.append(tuple(fmpq(int(v.p), int(v.q)) for v in vals))
    if readable != [tuple(at0)] * len(readable) or not readable:
        raise ValueError(f"the printed points {sorted(map(str, points))} are not the parametrization at {run} = 0")

    def fn(n, r, pt):
        strict = {lb.paper: k for k, lb in enumerate(united_system(n))}
        out = {}
        for color, i, j in term_indices(terms, n=n, r=r):
            name = f"{color}_{{{2 * n},{2 * n - i},{j}}}"
            k = strict.get(name, name)
            out[k] = step_value(exponents(united_system(n)[k]), STEP_PARAMS[param_index], 0, pt) \
                if isinstance(k, int) else fmpq(1)
        return out
    return fn


def _terms_check(line_id: str, param_index: int, verbatim: str | None) -> LineResult:
    try:
        printed = read_terms_at_edge(line_id, param_index, verbatim)
    except ValueError as exc:
        return LineResult(False, how="the printed terms read from the transcription", detail={"unread": str(exc)})
    res = _compare_forms(printed, _computed_step(param_index))
    res.how = "terms read from the transcription (sums, constants, functions, point); " + res.how
    return res


@line_check("sec1_3-r0-p1-terms")
def r0p1_terms(verbatim: str | None = None) -> LineResult:
    return _terms_check("sec1_3-r0-p1-terms", 0, verbatim)


_POWER_WORDS = {"at least": lambda e, m: e >= m, "greater than or equal to": lambda e, m: e >= m,
                "greater than": lambda e, m: e > m, "at most": lambda e, m: e <= m, "less than": lambda e, m: e < m,
                "equal to": lambda e, m: e == m}


#: the relations of a power to a number that the omitted functions' sentence may say
_POWER_RELATIONS = ("at least", "greater than or equal to", "greater than", "at most", "less than", "equal to")


def read_omitted(tex: str) -> dict:
    """The sentence "the omitted functions include the factor $\\left. \\sin\\frac{v_{1}(x,y)}{2}\\right\\vert _{y=0}
    =\\left. \\sin\\frac{y}{2}\\right\\vert _{y=0}=0$ raised to a power at least one", read: the coordinate and its
    parametrization index, the argument it equals, the points, the printed value and the power relation."""
    words, segs = lm.prose(tex)
    w = lm.sentence("... include the factor {f} raised to a power {relation:words} {power:count}", tex)
    if not w or w["relation"] not in _POWER_RELATIONS or w["power"] is None or len(segs) != 1:
        raise ValueError(f"the omitted functions' factor not read in {tex[:50]!r}")
    try:
        rel = lm.parse_relation(segs[0])
    except LatexMathError as exc:
        raise ValueError(f"the omitted functions' factor not read: {exc}") from None
    if rel.lead is not None or rel.ops != ["=", "="] or rel.conditions or \
            not all(isinstance(x, sympy.Subs) for x in rel.parts[:2]) or not rel.parts[2].is_Integer:
        raise ValueError(f"not sin(x_k/2)|_.. = sin(../2)|_.. = value: {segs[0]!r}")
    halves = []
    for bar in rel.parts[:2]:  # Subs(sin(X/2), p, 0): X, the point p
        if not isinstance(bar.expr, sympy.sin) or len(bar.variables) != 1 or bar.point != sympy.Tuple(0):
            raise ValueError(f"not a half-angle sine at 0: {bar}")
        halves.append((sympy.expand(2 * bar.expr.args[0]), str(bar.variables[0])))
    (coord, p1), (arg, p2) = halves
    if not (isinstance(coord, AppliedUndef) and coord.func.__name__ in ("u", "v", "w") and len(coord.args) == 2
            and coord.args[0].is_Integer and coord.args[1] == sympy.Tuple(*sympy.symbols("x y"))):
        raise ValueError(f"{coord} is not a coordinate u_k(x,y), v_k(x,y), w_k(x,y)")
    return {"coord": coord.func.__name__, "index": int(coord.args[0]), "points": {p1, p2}, "arg": arg,
            "value": int(rel.parts[2]), "relation": w["relation"], "power": w["power"]}


def omitted_check(line_id: str, before: str, terms_line: str, param_index: int,
                  override: dict[str, str] | None = None) -> LineResult:
    """"The omitted functions include the factor sin(x_k/2)|_{edge} = sin(t/2)|_{edge} = 0 raised to a power at least
    one", read from the transcriptions (:func:`read_omitted`) together with the functions before the step (the rows
    of ``before``) and those kept (the terms of ``terms_line``): the coordinate is the printed parametrization's
    coordinate of the step (its index), equal to the printed argument (both as linear forms), and its half-angle
    sine at the printed point (the step's edge) is the printed value, 0 (exact); every function before the step and
    not kept has that sine to a power in the printed relation ("at least one"), every kept one has not (n = 1..12)."""
    t = _transcribed([line_id, terms_line], override)
    try:
        o = read_omitted(t[line_id])
        _fmap, run, maps, _r = _params()[STEP_PARAMS[param_index]]
        var = "uvw".index(o["coord"])
        same_arg = linear_form(o["arg"]) == maps[var]
        pt = _pt(1, ALPHA_TS[0], X_FRACTIONS[0])
        value = _arg_half((o["coord"], o["index"]), param_index, pt)[0]
    except ValueError as exc:
        return LineResult(False, how="the omitted functions' factor read from the transcription, n = 1..12",
                          kind="exhaustive", detail={"unread": str(exc)})
    rel = _POWER_WORDS[o["relation"]]
    ok = same_arg and o["points"] == {run} and value == o["value"] and var == step_geometry(STEP_PARAMS[param_index])[1]
    for n in range(1, 13):
        strict = {lb.paper: k for k, lb in enumerate(united_system(n))}
        kept = {strict.get(f"{c}_{{{2 * n},{2 * n - i},{j}}}", "?") for c, i, j in
                term_indices(row_combination(t[terms_line]), n=n)}
        alive = printed_rows(before, n, 0, override)
        ok &= "?" not in kept and kept <= alive
        ok &= all(rel(exponents(united_system(n)[k])[2 * var], o["power"]) == (k not in kept)
                  for k in alive if isinstance(k, int))
    return LineResult(ok, how=f"exponent of sin({o['coord']}/2) in the functions before the step (read) against those "
                      "kept (read), the printed relation and power, and the printed value of the sine at the edge "
                      "(exact), n = 1..12", kind="exhaustive",
                      detail={"variable": o["coord"], "relation": f"{o['relation']} {o['power']}", "ok": bool(ok)})


@line_check("sec1_3-r0-p1-omitted")
def r0p1_omitted(override: dict[str, str] | None = None) -> LineResult:
    """All functions of L other than R_{2n,2n-i,0} (i < 2n) and G_{2n,2n,0} contain sin(v/2) to a power >= 1."""
    return omitted_check("sec1_3-r0-p1-omitted", "sec1_3-L-set", "sec1_3-r0-p1-terms", 0, override)


@line_check("sec1_3-r0-p2-terms")
def r0p2_terms(verbatim: str | None = None) -> LineResult:
    return _terms_check("sec1_3-r0-p2-terms", 1, verbatim)


@line_check("sec1_3-r0-p2-omitted")
def r0p2_omitted(override: dict[str, str] | None = None) -> LineResult:
    """The functions of L-tilde discarded at x = 0 all contain sin(u/2) to a power >= 1."""
    return omitted_check("sec1_3-r0-p2-omitted", "sec1_3-Ltilde-set", "sec1_3-r0-p2-terms", 1, override)


@line_check("sec1_3-r0-p3-terms")
def r0p3_terms(verbatim: str | None = None) -> LineResult:
    return _terms_check("sec1_3-r0-p3-terms", 2, verbatim)


def _a_system_rank(n: int, first: int, last: int) -> bool:
    """{A_{2n,2n-i}}_{i=first}^{last} is linearly independent: exact collocation rank."""
    rows = []
    for k in range(last - first + 3):
        pt = boundary_point(ALPHA_TS[0], fmpq(k + 1, last - first + 5))
        pt["n"], pt["alpha_t"] = n, ALPHA_TS[0]
        rows.append([_A_at(pt, 2 * n - i, "t") for i in range(first, last + 1)])
    return _rank(rows) == last - first + 1


#: A-system line -> the display whose sum of A's it makes vanish term by term
A_SYSTEM_OF = {"sec1_3-r0-p1-A-system": "sec1_3-r0-p1-aform", "sec1_3-r0-p2-A-system": "sec1_3-r0-p2-aform",
               "sec1_3-r0-p3-A-system": "sec1_3-r0-p3-aform"}


def read_a_system(tex: str, param_index: int) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """(first, last, index expression k(i)) of a printed system ``\\left\\{ A_{2n,k(i)}^{\\alpha}\\left( x\\right)
    :x\\in\\left[ 0,\\alpha\\right] \\right\\} _{i=a}^{b}`` (the ``$..$`` segment read by
    :func:`~paper_repro.printed.latex_math.parse_relation`), read: the variable must be the free parameter of the
    step's edge and the interval its printed range there; "is"/"are linearly independent" where the line says it.
    The thin-space typo ``0\\,\\alpha`` of one line is erratum sec1_3-r0-p3-interval: its correction (the comma) is
    applied before reading."""
    typo = _transcribed(["sec1_3-r0-p3-interval"])["sec1_3-r0-p3-interval"]
    t = tex.replace(typo, typo.replace("\\,", ",")) if "\\," in typo else tex
    words, segs = lm.prose(t)
    _fmap, run, _maps, ranges = _params()[STEP_PARAMS[param_index]]
    free = sympy.Symbol("x" if run == "y" else "y")
    unread = ValueError(f"no system {{A_{{2n,k}}({free}) : {free} in [0, alpha]}}_{{i=a}}^{{b}} in {tex[:40]!r}")
    if not segs or not words.endswith(("$$", "$$ is linearly independent", "$$ are linearly independent")):
        raise unread
    try:
        fam = lm.parse(segs[-1])
    except LatexMathError:
        raise unread from None
    if not (isinstance(fam, AppliedUndef) and fam.func == lm.Family and len(fam.args[2]) == 1):
        raise unread
    member, conds, ((var, first, last),) = fam.args
    if not (isinstance(member, AppliedUndef) and member.func.__name__ == "A" and len(member.args) == 3
            and member.args[0] == 2 * sympy.Symbol("n") and member.args[2] == sympy.Tuple(free)) or \
            var != sympy.Symbol("i") or len(conds) != 1 or conds[0].func.__name__ != "In" or conds[0].args[0] != free:
        raise unread
    interval = conds[0].args[1]
    if not isinstance(interval, sympy.Interval) or interval.left_open or interval.right_open or \
            (_lin(interval.start, 1), _lin(interval.end, 1)) != (0, 1):
        raise ValueError(f"the interval {interval} is not [0, alpha]")
    if any(w.startswith("dependent") for w in words.replace("independent", "").replace("-", " ").split()):  # prose
        raise ValueError("'dependent'")
    return first, last, member.args[1]


def _display_a_indices(tex: str, param_index: int, n: int, r: int = 0) -> list[int]:
    """The indices k of the A_{2n,k} in a printed display (its sums evaluated), in order."""
    terms, _k = read_value_line(tex, param_index)
    out = []

    def walk(term, sums, scope):
        if not sums:
            out.extend(_expr(f.args[0], scope) for f in term.factors if f.kind == "A")
            return
        (v, lo, hi), rest = sums[0], sums[1:]
        for x in range(_expr(lo, scope), _expr(hi, scope) + 1):
            walk(term, rest, {**scope, v: x})
    for term in terms:
        walk(term, term.sums, {"n": n, "r": r})
    return out


@line_check("sec1_3-A-independent")
def a_independent(override: dict[str, str] | None = None) -> LineResult:
    """The subsystems {A_{2n,2n-i}}_{i=a}^{b} of the order-0 steps (read from the transcriptions: index expression,
    range, variable and interval) are the A's of the sum in the display before each (read too) and linearly
    independent (exact ranks), n = 1..5."""
    texts = _transcribed(list(A_SYSTEM_OF) + list(A_SYSTEM_OF.values()), override)
    ranges, ok = {}, True
    try:
        for k, (line_id, display) in enumerate(A_SYSTEM_OF.items()):
            first_e, last_e, idx = read_a_system(texts[line_id], k)
            ranges[line_id] = [str(first_e), str(last_e), str(idx)]
            for n in range(1, 6):
                first, last = _expr(first_e, {"n": n}), _expr(last_e, {"n": n})
                listed = [_expr(idx, {"n": n, "i": i}) for i in range(first, last + 1)]
                ok &= sorted(listed) == sorted(_display_a_indices(texts[display], k, n))
                ok &= 0 <= first <= last <= 2 * n and _a_system_rank(n, first, last) and listed == \
                    [2 * n - i for i in range(first, last + 1)]
    except ValueError as exc:
        return LineResult(False, how="the systems read from the transcriptions, n = 1..5", detail={"unread": str(exc)})
    return LineResult(ok, how="systems read from the transcriptions, equal to the A's of the sums they are used "
                      "for; exact collocation ranks, n = 1..5", detail={"ranges": ranges})


# -- the step r -> r+1 -------------------------------------------------------------------------------------------
PARAM1 = "parametrization_1_y_0"


def _kterm_computed(n, r, pt, k, param=PARAM1, alive_fn=None):
    """d^{r+1}/d(zero var)^{r+1-k} d(other var)^k of every function of L_r at the boundary (no binomial, no sign)."""
    labels = united_system(n)
    alive = alive_fn(n, r) if alive_fn else alive_before(n, r + 1, 0)
    out = {q: mixed_partial(exponents(labels[q]), param, r + 1 - k, k, pt) for q in alive}
    return {q: v for q, v in out.items() if v != 0}


def _dk(pt, var: str, s: int, c: int, k: int) -> fmpq:
    """d^k/d(var)^k sin^s(var/2) cos^c(var/2) at the boundary point."""
    return _factor_derivative(s, c, k, pt[var])


def _M(i, j, z):
    return mixed_derivative(i, HALF, j, HALF, z)


def _S(j, z):
    return sin_power_derivative(j, HALF, z)


def _zeroed_check(computed_fn, printed_level, corrected_level, i_range, color, alias) -> LineResult:
    """Constants forced to 0 by a step: the printed primed constants of level printed_level(n, r), i in i_range,
    against the computed ones.  A primed constant of level L and index i names color_{2n,2n-i,L} for
    L <= i <= 2n-1-L and, as in the definitions of rho', gamma', alias_{2n,2n-L,L} for i = 2n-L; any other (n, L, i)
    names a constant that does not exist (a mismatch)."""
    bad, bad_c = [], []
    for n in range(2, N_PROOF.stop):
        for r in range(n - 1):
            comp = set(computed_fn(n, r))

            def named(level, n=n, r=r):
                out = set()
                for i in i_range(n, r):
                    if level <= i <= 2 * n - 1 - level:
                        out.add(lab(color, n, i, level))
                    elif alias and i == 2 * n - level:
                        out.add(lab(alias, n, level, level))
                    else:
                        out.add(-1 - i)
                return out
            if named(printed_level(n, r)) != comp:
                bad.append({"n": n, "r": r, "computed": _names(n, comp)})
            if named(corrected_level(n, r)) != comp:
                bad_c.append((n, r))
    return LineResult(not bad, not bad_c, how="constants removed by the recomputed step against the printed ones, "
                      f"n = 2..{N_PROOF.stop - 1}", detail={"mismatches": len(bad), "first_mismatches": bad[:2],
                                                           "corrected_mismatches": len(bad_c)})


def read_zero_line(tex: str, color: str | None = None) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr, sympy.Expr]:
    """(level, first i, last i, right-hand side) of a printed conclusion ``\\rho_{2n,2n-i,L}^{\\prime}=0,~i=a,a+1,
    \\ldots,b``, read by :func:`paper_repro.printed.latex_math.parse_relation`: a primed constant of order 2n and first
    index 2n-i of the step's colour, ``=``, a number, and a listed range of i stepping by one (``ValueError``
    otherwise; the value and the range are compared by the callers)."""
    rel = lm.parse_relation(tex)
    head = rel.parts[0] if rel.parts else None
    i = sympy.Symbol("i")
    if rel.ops != ["="] or len(rel.parts) != 2 or rel.lead is not None or not isinstance(head, AppliedUndef) or \
            head.func.__name__ not in _PRIMED or len(head.args) != 3 or head.args[0] != _TWO_N or \
            sympy.expand(head.args[1] - _TWO_N + i) != 0 or (color and _PRIMED[head.func.__name__] != color) or \
            not rel.parts[1].is_Integer:
        raise ValueError(f"not a conclusion const'_{{2n,2n-i,L}}=0, i=a,..,b of colour {color}: {tex[:40]!r}")
    found = [c.parts[1].args for c in rel.conditions if c.ops == ["in"] and c.parts[0] == i
             and isinstance(c.parts[1], sympy.Tuple)]
    if len(found) != 1 or len(rel.conditions) != 1:
        raise ValueError(f"not one listed range of i after the conclusion: {tex[:40]!r}")
    listed_orders(tex, "i", n=5, r=1)  # the range steps by one
    return head.args[2], found[0][0], found[0][-1], rel.parts[1]


def read_zeroed(line_id: str, verbatim: str | None = None, color: str | None = None):
    """(level, range of i, right-hand side) of a printed ``const'_{2n,2n-i,LEVEL} = 0, i = a, ..., b``, read from its
    transcription (:func:`read_zero_line`), as functions of (n, r)."""
    tex = verbatim if verbatim is not None else _transcribed([line_id])[line_id]
    level_expr, lo, hi, rhs = read_zero_line(tex, color)
    return (lambda n, r: bound(level_expr, n=n, r=r),
            lambda n, r: range(bound(lo, n=n, r=r), bound(hi, n=n, r=r) + 1), str(rhs))


def _zeroed_read(line_id, computed_fn, corrected_level, color, alias, level=None, verbatim=None) -> LineResult:
    """:func:`_zeroed_check` with the printed level, range and right-hand side read from the transcription
    (``level`` overrides the level read: the corrected form in tests)."""
    try:
        read_level, i_range, rhs = read_zeroed(line_id, verbatim, color)
    except ValueError as exc:
        return LineResult(False, how="the printed constants read from the transcription", detail={"unread": str(exc)})
    res = _zeroed_check(computed_fn, level or read_level, corrected_level, i_range, color, alias)
    res.holds_as_printed &= rhs == "0"
    ln = transcribed_line(line_id)
    if ln.status == "erratum" and verbatim is None:  # the erratum describes what is printed: the level read
        lev = read_zero_line(ln.verbatim)[0]
        if f"_{{2n,2n-i,{lev}}}".replace(" ", "") not in ln.erratum["printed"].replace(" ", ""):
            res.corrected_holds = False
            res.detail["erratum_describes_another_level"] = lev
    res.detail["right_hand_side"] = rhs
    res.how = "level, range and right-hand side read from the transcription; " + res.how
    return res


@line_check("sec1_3-r-p1-zeroed")
def rp1_zeroed(level=None, verbatim=None) -> LineResult:
    """Printed rho'_{2n,2n-i,n-1} = 0, i = r+1..2n-(r+1); the step zeroes the level-(r+1) constants (rho' of level r+1,
    its last one being gamma_{2n,2n-(r+1),r+1})."""
    return _zeroed_read("sec1_3-rp1-zeroed", lambda n, r: alive_before(n, r + 1, 0) - alive_after(n, r + 1, 0),
                        lambda n, r: r + 1, "R", "G", level, verbatim)


# parametrization 2 (u = 0 is the zero variable, v = alpha - y the other, w = y = t fixed)
PARAM2 = "parametrization_2_x_0"


def _p2_alive(n, r):
    return alive_before(n, r + 1, 1)


@line_check("sec1_3-r-p2-zeroed")
def rp2_zeroed(level=None, verbatim=None) -> LineResult:
    """Printed gamma'_{2n,2n-i,n-1} = 0, i = r+2..2n-(r+1); the step zeroes gamma' of level r+1."""
    return _zeroed_read("sec1_3-rp2-zeroed", lambda n, r: alive_before(n, r + 1, 1) - alive_after(n, r + 1, 1),
                        lambda n, r: r + 1, "G", "B", level, verbatim)


# parametrization 3 (w = 0, u = alpha - x the other, v = x = t fixed)
PARAM3 = "parametrization_3_y_0"


def _p3_alive(n, r):
    return alive_before(n, r + 1, 2)


@line_check("sec1_3-r-p3-zeroed")
def rp3_zeroed(verbatim=None) -> LineResult:
    """beta'_{2n,2n-i,r+1} = 0, i = r+2..2n-1-(r+1): exactly the constants the step removes."""
    return _zeroed_read("sec1_3-rp3-zeroed", lambda n, r: alive_before(n, r + 1, 2) - alive_after(n, r + 1, 2),
                        lambda n, r: r + 1, "B", None, verbatim=verbatim)


# -- value lines of the proof, read from their transcriptions ----------------------------------------------------
#: check -> (parametrization index 0/1/2, order: 0 for the order-0 steps, None for r + 1, the definition lines of
#: the primed constants it uses)
VALUE_CHECKS = {
    "sec1_3-r0-p1-cform": (0, 0, ("sec1_3-r0-p1-rho-prime",)),
    "sec1_3-r0-p1-aform": (0, 0, ("sec1_3-r0-p1-rho-prime",)),
    "sec1_3-r0-p2-aform": (1, 0, ("sec1_3-r0-p2-gamma-prime",)),
    "sec1_3-r0-p3-aform": (2, 0, ("sec1_3-r0-p3-beta-prime",)),
    "sec1_3-r-p1-k0": (0, None, ()),
    "sec1_3-r-p1-aform": (0, None, ("sec1_3-rp1-rho-prime",)),
    "sec1_3-r-p1-rho-prime": (0, None, ("sec1_3-rp1-rho-prime",)),
    "sec1_3-r-p2-k0": (1, None, ()),
    "sec1_3-r-p2-aform": (1, None, ("sec1_3-rp2-gamma-prime",)),
    "sec1_3-r-p3-aform": (2, None, ("sec1_3-rp3-beta-prime",)),
}


def _is_definition(tex: str) -> bool:
    """A line that defines a primed constant (``X'_{..} = ..``, parsed)."""
    try:
        rel = lm.parse_relation(tex)
    except LatexMathError:
        return False
    return bool(rel.parts) and rel.ops == ["="] and isinstance(rel.parts[0], AppliedUndef) and \
        rel.parts[0].func.__name__ in _PRIMED


def _row_value(tex: str) -> sympy.Expr:
    """The value of a printed row ``[= &] VALUE [\\\\]`` (no relation or clause after it), read by
    :func:`paper_repro.printed.latex_math.parse_relation`."""
    rel = lm.parse_relation(tex)
    if rel.lead not in (None, "=") or rel.ops or rel.conditions or rel.continues:
        raise LatexMathError(f"not a row '= VALUE': {rel.lead} {rel.ops} {len(rel.conditions)} clauses")
    return rel.parts[0]


def _k_range(cond, var: str = "k") -> tuple[sympy.Expr, sympy.Expr]:
    """(lo, hi) of a parsed case condition ``k=K`` (lo = hi) or ``a\\leq k\\leq b`` (a Relation or a sympy boolean)."""
    k = sympy.Symbol(var)
    if isinstance(cond, lm.Relation):
        if cond.ops == ["="] and len(cond.parts) == 2 and cond.parts[0] == k:
            return cond.parts[1], cond.parts[1]
        if cond.ops == ["<=", "<="] and len(cond.parts) == 3 and cond.parts[1] == k:
            return cond.parts[0], cond.parts[2]
        raise LatexMathError(f"unread condition {cond.parts} {cond.ops}")
    if isinstance(cond, sympy.Eq) and k in (cond.lhs, cond.rhs):
        other = cond.rhs if cond.lhs == k else cond.lhs
        return other, other
    if isinstance(cond, sympy.And) and len(cond.args) == 2:
        lo = hi = None
        for a in cond.args:
            if isinstance(a, (sympy.Le, sympy.Ge)) and a.gts == k:
                lo = a.lts
            elif isinstance(a, (sympy.Le, sympy.Ge)) and a.lts == k:
                hi = a.gts
        if lo is not None and hi is not None:
            return lo, hi
    raise LatexMathError(f"unread condition {cond}")


def read_case_row(tex: str) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """(value, lo, hi) of a printed case row ``VALUE , & k=K`` or ``VALUE , & a\\leq k\\leq b``: a bare row, or a
    case display ``= & \\left\\{ \\begin{array}..`` of one row (its value possibly printed over several rows)."""
    rel = lm.parse_relation(tex)
    last = rel.parts[-1] if rel.parts else None
    if isinstance(last, AppliedUndef) and last.func == lm.Cases:
        if len(last.args) != 1 or rel.conditions or rel.parts[:-1] or rel.lead not in (None, "="):
            raise LatexMathError(f"{len(last.args)} case rows")
        value, cond = last.args[0].args
        return (value, *_k_range(cond))
    if rel.ops or len(rel.conditions) != 1 or rel.lead is not None:
        raise LatexMathError(f"not a case row VALUE, & COND: {rel.ops} {len(rel.conditions)} clauses")
    return (rel.parts[0], *_k_range(rel.conditions[0]))


def _quantified_value(rel: lm.Relation, param_index: int) -> sympy.Expr:
    """The value of ``[0=] VALUE ,~\\forall V\\in\\left[ 0,\\alpha\\right]`` (or ``= & VALUE, ..``): the quantifier
    must range over the free variable of the step's edge and its printed range there, [0, alpha] (read)."""
    run = _params()[STEP_PARAMS[param_index]][1]
    free = sympy.Symbol("x" if run == "y" else "y")
    (c,) = rel.conditions
    rng = c.parts[-1] if c.parts else None
    if c.quantifier != "forall" or c.ops != ["in"] or c.parts[0] != free or not isinstance(rng, sympy.Interval) or \
            linear_form(rng.start) != (0, 0, 0) or linear_form(rng.end) != (1, 0, 0):
        raise ValueError(f"the quantifier {c.quantifier} {c.parts} is not over {free} in [0, alpha] on the edge "
                         f"{run} = 0")
    if rel.parts[:-1] not in ([], [0]) or any(op != "=" for op in rel.ops) or rel.lead not in (None, "="):
        raise ValueError("a display that does not start with 0 =")
    return rel.parts[-1]


def read_value_line(tex: str, param_index: int, correct: Callable[[sympy.Expr], sympy.Expr] | None = None):
    """(terms, k) of a printed value: a case row ``VALUE , & k=K`` (k = K), ``[0=] VALUE ,~\\forall x\\in[0,\\alpha]``
    or ``& = VALUE \\\\`` (k None: the whole derivative); ``correct`` (an erratum's correction) is applied to the
    parsed value."""
    rel = lm.parse_relation(tex)
    last = rel.parts[-1] if rel.parts else None
    k = None
    if (isinstance(last, AppliedUndef) and last.func == lm.Cases) or (not rel.ops and rel.lead is None and
                                                                     len(rel.conditions) == 1
                                                                     and rel.conditions[0].quantifier is None):
        body, lo, hi = read_case_row(tex)
        if lo != hi:
            raise ValueError(f"a value for a range of k: {lo}..{hi}")
        k = _expr(lo, {})
    elif rel.conditions:
        body = _quantified_value(rel, param_index)
    else:
        body = _row_value(tex)
    return read_products(correct(body) if correct else body), k


def _alive_for(param_index: int, r: int, order0: bool, n: int):
    return alive_before(n, r if order0 else r + 1, param_index)


def value_lines_check(check_id: str, texts: dict[str, str] | None = None, defs_texts: dict[str, str] | None = None,
                      correct: Callable[[sympy.Expr], sympy.Expr] | None = None) -> LineResult:
    """Every value line of ``check_id`` (and the definitions of its primed constants) read from the transcription
    and evaluated exactly at the boundary (constants resolved by the printed definitions, S, M by exact Taylor
    series, sines by exact half angles): the {member of T_{2n}: coefficient} it prints must equal the one computed
    from the exact derivatives of the step (the k-th term of its chain rule where the line is a case k = K, the
    whole derivative of the step's order otherwise), n = 1..6 (order-0 steps) or n = 2..6, r = 0..n-2.  ``correct``
    (an erratum's correction) is applied to each parsed value of the check's own lines."""
    param_index, order, def_ids = VALUE_CHECKS[check_id]
    param = STEP_PARAMS[param_index]
    own = {x.id: x.verbatim for x in _lines_of(check_id)}
    all_texts = {**own, **_transcribed([d for d in def_ids if d not in own])}
    all_texts.update(texts or {})
    all_texts.update(defs_texts or {})
    detail: dict = {}
    try:
        primes = {}
        for lid in def_ids:
            (color, level), cases = read_prime_definition(all_texts[lid])
            primes[color] = (level, cases)
        values = {lid: read_value_line(t, param_index, correct) for lid, t in sorted(all_texts.items())
                  if lid in own and not _is_definition(t)}
        if check_id == "sec1_3-r-p1-rho-prime":  # the definition checked through the A-form it defines
            aform = _transcribed(["sec1_3-rp1-aform"])["sec1_3-rp1-aform"]
            values = {"sec1_3-rp1-aform": read_value_line(aform, param_index, _p1_corrected)}
        if not values:
            raise ValueError("no value line")
    except (ValueError, KeyError) as exc:
        return LineResult(False, how="the values read from the transcriptions", detail={"unread": str(exc)})
    ns = N_PROOF if order == 0 else range(2, N_PROOF.stop)
    bad, cases = [], 0
    for n in ns:
        for r in ([0] if order == 0 else range(n - 1)):
            for at in ALPHA_TS:
                for xf in X_FRACTIONS:
                    pt = _pt(n, at, xf)
                    alive = _alive_for(param_index, r, order == 0, n)
                    used: set = set()
                    for lid, (terms, k) in values.items():
                        cases += 1
                        try:
                            pr = evaluate_terms(terms, {"n": n, "r": r, "k": k or 0}, param_index, pt, primes,
                                                used=used)
                        except ValueError as exc:
                            bad.append({"line": lid, "n": n, "r": r, "unread": str(exc)})
                            continue
                        pr = {q: v for q, v in pr.items() if v != 0}
                        if order == 0:
                            comp = _computed_form(n, param, 0, alive, pt)
                        elif k is None:
                            comp = _computed_form(n, param, r + 1, alive, pt)
                        else:
                            comp = _kterm_computed(n, r, pt, k, param, lambda n_, r_, a=alive: a)
                        if pr != comp:
                            bad.append({"line": lid, "n": n, "r": r,
                                        "printed_only": _names(n, set(pr) - set(comp)),
                                        "computed_only": _names(n, set(comp) - set(pr)),
                                        "values_differ": _names(n, {q for q in set(pr) & set(comp)
                                                                    if pr[q] != comp[q]})})
                    # each definition of a primed constant covers exactly the i its values use, once
                    for color, (_level, pcases) in primes.items():
                        scope = {"n": n, "r": r}
                        covered = [i for _c, _k, lo, hi in pcases
                                   for i in range(_expr(lo, scope), _expr(hi, scope) + 1)]
                        if sorted(covered) != sorted({i for c, i in used if c == color}):
                            bad.append({"n": n, "r": r, "definition_of": color, "covers": covered,
                                        "used": sorted({i for c, i in used if c == color})})
    detail.update({"cases": cases, "mismatches": len(bad), "first_mismatches": bad[:2]})
    return LineResult(not bad, how="the printed values (terms, constants, primed definitions, factors) read from the "
                      "transcriptions against the exact derivatives along the printed parametrization, "
                      f"n = {ns.start}..{ns.stop - 1}, tan(alpha/4) in {{1/2, 3/4}}, two boundary points each",
                      detail=detail)


def _p1_corrected(e: sympy.Expr) -> sympy.Expr:
    """The erratum's correction of the A-form of parametrization 1, on the parsed object: the upper bound 2n-(r+1)
    instead of 2n-1-(r+1) (``e`` that bound, or an expression whose sums over i end there)."""
    n, r, i = sympy.symbols("n r i")
    printed, corrected = 2 * n - 1 - (r + 1), 2 * n - (r + 1)
    if e == printed:
        return corrected
    return e.replace(lambda x: isinstance(x, sympy.Sum),
                     lambda x: sympy.Sum(x.function, *[(v, lo, corrected if v == i and hi == printed else hi)
                                                      for v, lo, hi in x.limits]))


def _value_erratum(check_id: str, correct) -> LineResult:
    """An erratum value line: as printed (must fail) and with ``correct`` applied to each parsed value (must hold)."""
    res = value_lines_check(check_id)
    corrected = value_lines_check(check_id, correct=correct)
    res.corrected_holds = corrected.holds_as_printed
    res.detail["corrected_mismatches"] = corrected.detail.get("mismatches", corrected.detail.get("unread"))
    return res


def kpos_check(check_id: str, param_index: int) -> LineResult:
    """The rows ``0, & 1\\leq k\\leq r+1`` (read: the value 0 and the range of k): the range is the rest of the
    chain rule's k = 0..r+1 after k = 0, and every mixed partial of the equality's functions with k in it vanishes
    at the boundary (exact), n = 2..6, r = 0..n-2."""
    param = STEP_PARAMS[param_index]
    try:
        rows = {x.id: read_case_row(x.verbatim) for x in _lines_of(check_id)}
        ranges = {lid: (lo, hi) for lid, (value, lo, hi) in rows.items()}
        if not rows or any(value != 0 for value, _, _ in rows.values()):
            raise ValueError("a value other than 0")
    except ValueError as exc:
        return LineResult(False, how="the rows read from the transcriptions", detail={"unread": str(exc)})
    bad, cases = [], 0
    for n in range(2, N_PROOF.stop):
        for r in range(n - 1):
            alive = alive_before(n, r + 1, param_index)
            for lid, (lo, hi) in ranges.items():
                ks = range(_expr(lo, {"n": n, "r": r}), _expr(hi, {"n": n, "r": r}) + 1)
                if list(ks) != list(range(1, r + 2)):
                    bad.append({"line": lid, "n": n, "r": r, "k": [ks.start, ks.stop - 1]})
                    continue
                for at in ALPHA_TS:
                    for xf in X_FRACTIONS:
                        pt = _pt(n, at, xf)
                        for k in ks:
                            cases += 1
                            if _kterm_computed(n, r, pt, k, param, lambda n_, r_, a=alive: a):
                                bad.append({"line": lid, "n": n, "r": r, "k": k})
    return LineResult(not bad, how="the printed value 0 and range of k read from the transcriptions; every mixed "
                      "partial with k in it of every function of the equality, exactly, n = 2..6, r = 0..n-2",
                      detail={"cases": cases, "mismatches": len(bad), "first_mismatches": bad[:3]})


# rows of the printed k-th term of parametrization 1 (lines sec1_3-kterm-*)
KTERM_LINES = ("sec1_3-kterm-centre", "sec1_3-kterm-R-low", "sec1_3-kterm-R-high", "sec1_3-kterm-G-low",
               "sec1_3-kterm-G-high", "sec1_3-kterm-B-low", "sec1_3-kterm-B-high")


def kterm_row_check(line_id: str, texts: dict[str, str] | None = None) -> LineResult:
    """One row of the printed k-th term (read from its transcription): its sums name functions of L_r, and for each
    the printed product of factors equals the exact mixed partial d^z/dv_1^z d^k/dw_1^k of that function at y = 0 --
    at the printed orders (the orders of S, M must read r+1-k and that of the derivative k, the chain rule's k-th
    term) and, to test the factor structure where it does not vanish, at z = 0..n+2, k = 0..2; the seven rows
    together list exactly the functions of L_r, each once (n = 2..6, r = 0..n-2)."""
    t = _transcribed(list(KTERM_LINES), texts)
    try:
        rows = {lid: read_products(_row_value(tx)) for lid, tx in t.items()}
    except ValueError as exc:
        return LineResult(False, how="the rows read from the transcriptions", detail={"unread": str(exc)})
    bad, cases, nonzero = [], 0, 0
    own = rows[line_id]
    orders_ok = all(_expr(f.args[1], {"r": r, "k": k}) == r + 1 - k for term in own for f in term.factors
                    if f.kind in ("S", "M") for r in range(5) for k in range(r + 2)) and \
        all(_expr(f.deriv[0], {"r": r, "k": k}) == k for term in own for f in term.factors if f.deriv
            for r in range(5) for k in range(r + 2))
    if not orders_ok:
        bad.append("printed orders are not r+1-k (S, M) and k (d/dw_1)")
    for n in range(2, N_PROOF.stop):
        labels = united_system(n)
        for r in range(n - 1):
            at = ALPHA_TS[r % 2]
            pt = _pt(n, at, X_FRACTIONS[n % 2])
            try:
                members = {lid: list(evaluate_terms(ts, {"n": n, "r": r, "k": 0}, 0, pt, orders=(0, 0)))
                           for lid, ts in rows.items()}
            except ValueError as exc:
                bad.append({"n": n, "r": r, "unread": str(exc)})
                continue
            flat = [q for v in members.values() for q in v]
            if len(flat) != len(set(flat)) or set(flat) != set(alive_before(n, r + 1, 0)):
                bad.append({"n": n, "r": r, "rows_do_not_list_L_r_once": True})
            for z in range(n + 3):
                for k in range(3):
                    try:
                        vals = evaluate_terms(own, {"n": n, "r": r, "k": k}, 0, pt, orders=(z, k))
                    except ValueError as exc:
                        bad.append({"n": n, "r": r, "unread": str(exc)})
                        continue
                    for q, val in vals.items():
                        cases += 1
                        if not isinstance(q, int):
                            bad.append({"n": n, "r": r, "not_a_member": q})
                            continue
                        exact = mixed_partial(exponents(labels[q]), PARAM1, z, k, pt)
                        nonzero += exact != 0
                        if val != exact:
                            bad.append({"n": n, "r": r, "z": z, "k": k, "function": labels[q].paper})
    return LineResult(not bad, how="the row read from its transcription; each printed factor product against the "
                      "exact mixed partial of its function, n = 2..6, r = 0..n-2, orders z = 0..n+2, k = 0..2 (the "
                      "printed orders r+1-k and k read)", detail={"cases": cases, "nonzero_cases": nonzero,
                                                                  "mismatches": len(bad), "first_mismatches": bad[:3]})


for _row in KTERM_LINES:
    line_check(_row.replace("sec1_3-kterm-", "sec1_3-kterm-p1-"))(lambda _row=_row: kterm_row_check(_row))


@line_check("sec1_3-r0-p1-cform")
def r0p1_cform() -> LineResult:
    return value_lines_check("sec1_3-r0-p1-cform")


@line_check("sec1_3-r0-p1-aform")
def r0p1_aform() -> LineResult:
    return value_lines_check("sec1_3-r0-p1-aform")


@line_check("sec1_3-r0-p2-aform")
def r0p2_aform() -> LineResult:
    return value_lines_check("sec1_3-r0-p2-aform")


@line_check("sec1_3-r0-p3-aform")
def r0p3_aform() -> LineResult:
    return value_lines_check("sec1_3-r0-p3-aform")


@line_check("sec1_3-r-p1-k0")
def rp1_k0() -> LineResult:
    return value_lines_check("sec1_3-r-p1-k0")


@line_check("sec1_3-r-p1-kpos")
def rp1_kpos() -> LineResult:
    return kpos_check("sec1_3-r-p1-kpos", 0)


@line_check("sec1_3-r-p1-aform")
def rp1_aform() -> LineResult:
    """Printed S^{r+1}_{r+1}(0) sum_{i=r+1}^{2n-1-(r+1)} rho' A_{2n,2n-i}(x) misses the term i = 2n-(r+1) (the gamma
    term that rho' defines); with the upper bound 2n-(r+1) (the correction applied to the transcription) it equals the
    computed derivative."""
    return _value_erratum("sec1_3-r-p1-aform", _p1_corrected)


@line_check("sec1_3-r-p1-rho-prime")
def rp1_rho_prime() -> LineResult:
    """With the printed rho' (read) the A-form over the range r+1..2n-(r+1) that rho' is defined on (the corrected
    A-form line) equals the exact k = 0 term; the i = 2n-(r+1) branch divides by c_{2n,2n-(r+1)}."""
    return value_lines_check("sec1_3-r-p1-rho-prime")


def _a_indices(n: int, r: int, param_index: int) -> set[int]:
    """Indices i of the A_{2n,2n-i} in the exact (r+1)-th derivative of the step (matched as S A / c)."""
    pt = _pt(n, ALPHA_TS[0], X_FRACTIONS[0])
    comp = _kterm_computed(n, r, pt, 0, STEP_PARAMS[param_index],
                           lambda n_, r_: alive_before(n, r + 1, param_index))
    s = _S(r + 1, r + 1)
    return {i for val in comp.values() for i in range(2 * n + 1)
            if val == s * _A_at(pt, 2 * n - i, "t") / _c(pt, 2 * n - i)}


def asystem_check(check_id: str, param_index: int, correct=None) -> LineResult:
    """The printed system {A_{2n,2n-i}}_{i=a}^{b} (range read from the transcription) is exactly the set of A's in the
    exact derivative of the step, and linearly independent (exact rank), n = 2..6, r = 0..n-2."""

    def run(tex: str, fix=lambda e: e) -> tuple[bool, list]:
        first_e, last_e, idx = read_a_system(tex, param_index)
        first_e, last_e = fix(first_e), fix(last_e)
        bad = []
        for n in range(2, N_PROOF.stop):
            for r in range(n - 1):
                lo, hi = _expr(first_e, {"n": n, "r": r}), _expr(last_e, {"n": n, "r": r})
                comp = _a_indices(n, r, param_index)
                listed = [_expr(idx, {"n": n, "r": r, "i": i}) for i in range(lo, hi + 1)]
                if set(range(lo, hi + 1)) != comp or not _a_system_rank(n, lo, hi) or \
                        listed != [2 * n - i for i in range(lo, hi + 1)]:
                    bad.append({"n": n, "r": r, "printed": [lo, hi], "computed": sorted(comp)})
        return not bad, bad

    lines = _lines_of(check_id)
    try:
        ok, bad = run(lines[0].verbatim)
        corr = run(lines[0].verbatim, correct)[0] if correct else None
    except ValueError as exc:
        return LineResult(False, how="the system read from the transcription", detail={"unread": str(exc)})
    return LineResult(ok, corr, how="the printed range read from the transcription against the A functions present "
                      "in the exact derivative; exact collocation rank, n = 2..6, r = 0..n-2",
                      detail={"mismatches": len(bad), "first_mismatches": bad[:2]})


@line_check("sec1_3-r-p1-asystem")
def rp1_asystem() -> LineResult:
    """Printed {A_{2n,2n-i}}_{i=r+1}^{2n-1-(r+1)}; the step needs i = r+1..2n-(r+1) (the erratum's correction)."""
    return asystem_check("sec1_3-r-p1-asystem", 0, _p1_corrected)


@line_check("sec1_3-r-p2-k0")
def rp2_k0() -> LineResult:
    return value_lines_check("sec1_3-r-p2-k0")


@line_check("sec1_3-r-p2-kpos")
def rp2_kpos() -> LineResult:
    return kpos_check("sec1_3-r-p2-kpos", 1)


@line_check("sec1_3-r-p2-aform")
def rp2_aform() -> LineResult:
    return value_lines_check("sec1_3-r-p2-aform")


@line_check("sec1_3-r-p2-asystem")
def rp2_asystem() -> LineResult:
    return asystem_check("sec1_3-r-p2-asystem", 1)


@line_check("sec1_3-r-p3-aform")
def rp3_aform() -> LineResult:
    return value_lines_check("sec1_3-r-p3-aform")


@line_check("sec1_3-r-p3-kpos")
def rp3_kpos() -> LineResult:
    return kpos_check("sec1_3-r-p3-kpos", 2)


@line_check("sec1_3-fig-n4-caption")
def fig_n4_caption(order: int | None = None, n: int | None = None) -> LineResult:
    """Fig. derivative_scheme_n_4, read from the caption: the order of the mixed partials ("$4$th order", and the
    orders k = 0..4 of its list), the parametrization and point (\\ref{parametrization_for_partition_of_unity} at
    $y=0$, with v = y and w = x - y as printed there), the gray areas (sin(v/2) "raised to a power greater than" the
    order in v: the first condition of the zero branch of the Proposition, read from its transcription) and the
    other black dots (the second condition).  Computed: for every function of T_{2n} (n of the text, "In the case of
    $n=4$") with sin(v/2) to the power j and cos(v/2) to the power i (i + j != 0) and every order z in v, its partial
    vanishes at v = 0 exactly when gray or the second condition; the gray ones are exactly those with j > z."""
    from paper_repro.printed.derivatives import branch_disjuncts

    tex = _layout_free(_transcribed(["sec1_3-fig-n4-caption"])["sec1_3-fig-n4-caption"])
    try:
        m = lm.sentence(
            r"\caption{(\emph{a})--(\emph{e}) Using the sign function (\ref{derivative_cosine_sine_at_0}), one can "
            r"easily verify that black and non-black dots represent those functions of system (\ref{united_system}) "
            r"the {order}th order mixed partial derivatives of which with respect to {v} and {w} are zero and "
            r"non-zero, respectively, under parametrization (\ref{{label:word}}) at {at}. Observe, that the gray "
            r"shaded areas correspond to functions which comprise the factor "
            r"$\sin \frac{v\left( x,y\right) }{2}=\sin\frac{y}{2}$ raised to a power {gray:words} the corresponding "
            r"order {k1} of the partial derivative with respect to $v\left( x,y\right) =y$. Thus, these partial "
            r"derivatives vanish at $y=0$ due to the {c1:word} condition of the zero branch of the sign function "
            r"(\ref{derivative_cosine_sine_at_0}). Black dots that fall outside of the gray shaded areas correspond "
            r"to constrained trivariate functions that comprise the factor "
            r"$\sin\frac{v\left( x,y\right) }{2}=\sin\frac{y}{2}$ raised to a power which -- together with the order "
            r"{k2} of the partial derivative with respect to $v\left( x,y\right) =y$, at $y=0$ -- fulfills the "
            r"{c2:word} condition of the zero branch of the sign function (\ref{derivative_cosine_sine_at_0}). (For "
            r"interpretation of the references to color in this figure legend, the reader is referred to the web "
            r"version of this paper.)}", tex)
        text_n = lm.sentence("In the case of {n}, we have provided an example",
                             _layout_free(_transcribed(["sec1_3-L-prose"])["sec1_3-L-prose"]), search=True)
        if not (m and text_n):
            raise ValueError("caption not read")
        n_rel, v_rel, w_rel = (_read_segment(text_n["n"]), _read_segment(m["v"]), _read_segment(m["w"]))
        if n_rel is None or v_rel is None or w_rel is None or not (n_rel.ops == v_rel.ops == w_rel.ops == ["="]) or \
                n_rel.parts[0] != sympy.Symbol("n") or \
                [(r.parts[0].func.__name__, r.parts[0].args) for r in (v_rel, w_rel)] != \
                [("v", (sympy.Tuple(*sympy.symbols("x y")),)), ("w", (sympy.Tuple(*sympy.symbols("x y")),))]:
            raise ValueError("caption formulas not read")
        printed_order, text_n_value = int(lm.parse(m["order"])), int(n_rel.parts[1])
        ks = [listed_range(m[k], "k") for k in ("k1", "k2")]
        label, at = m["label"], _is_point(_read_segment(m["at"]))
        fmap, run, maps, _r = _params()[label]
        forms_ok = linear_form(v_rel.parts[1]) == maps[1] and linear_form(w_rel.parts[1]) == maps[2] and at == run
        parts = branch_disjuncts(_transcribed(["sec1_3-proposition-M"])["sec1_3-proposition-M"], 0, ("j", "z"))
        if len(parts) != 2:
            raise ValueError("the zero branch of the Proposition is not two conditions joined by 'or'")
        which = {"first": parts[0], "second": parts[1]}
        gray_cond, black_cond = which[m["c1"]], which[m["c2"]]
        rel = {"greater than": lambda j, z: j > z, "less than": lambda j, z: j < z,
               "at least": lambda j, z: j >= z, "at most": lambda j, z: j <= z}[m["gray"]]
    except (ValueError, KeyError, TypeError) as exc:
        return LineResult(False, how="the caption read from its transcription", detail={"unread": str(exc)})
    order = printed_order if order is None else order
    n = text_n_value if n is None else n
    direction, zero_var, _fixed, _rest = step_geometry(label)
    bad, v_free, gray_bad = 0, 0, 0
    ok_orders = ks == [(0, printed_order), (0, printed_order)]
    for lb in united_system(n):
        e = exponents(lb)
        j, i = e[2 * zero_var], e[2 * zero_var + 1]
        if i + j == 0:
            v_free += 1
            continue
        for k in range(order + 1):
            z = order - k
            vanish = mixed_derivative(i, HALF, j, HALF, z) == 0
            is_gray = gray_cond(z=z, j=j)
            is_black = black_cond(z=z, j=j)
            bad += vanish != (is_gray or is_black)
            gray_bad += bool(is_gray) != rel(j, z)
    ok = bad == 0 and gray_bad == 0 and ok_orders and forms_ok and direction == (0, 1, -1)
    return LineResult(ok, how=f"exact derivatives at v = 0 of every function of T_{{2n}}, n = {n}, orders "
                      f"z = 0..{order} in v, against the caption and the zero branch of the Proposition (read)",
                      kind="exhaustive", detail={"mismatches": bad, "gray_mismatches": gray_bad,
                                                 "v_independent_functions": v_free, "order": printed_order})


@line_check("sec1_3-interval-typo")
def interval_typo() -> LineResult:
    """An interval [a, b] is written with a comma between its endpoints; the printed ``\\left[ 0\\,\\alpha\\right]``
    (read from the transcription) has none (a thin space instead), so it does not parse as an interval; with the comma
    it is [0, alpha], the range of x on the edge y = 0 of parametrization_3_y_0 (read from its transcription)."""

    tex = _transcribed(["sec1_3-r0-p3-interval"])["sec1_3-r0-p3-interval"]
    def holds(text: str) -> bool:  # x in [a, b] (parse_relation), a closed interval with the printed range's ends
        try:
            rel = lm.parse_relation(text)
            if rel.ops != ["in"] or rel.parts[0] != sympy.Symbol("x") or rel.conditions:
                return False
            lo_c, lo, hi, hi_c = interval_of(rel.parts[1])
            return lo_c and hi_c and [linear_form(lo), linear_form(hi)] == \
                [linear_form(q) for q in _params()["parametrization_3_y_0"][3]["x"]]
        except ValueError:  # LatexMathError included: the thin space leaves no interval to read
            return False
    return LineResult(holds(tex), holds(tex.replace("\\,", ",")) if "\\," in tex else None,
                      how="the printed interval read by parse_relation, against the printed range of x of "
                      "parametrization_3_y_0", kind="proof", detail={"printed": tex.strip()})


def _sign_value_sets(text: str) -> list[int]:
    """The lower bounds of p of the Lemma's two sets of values, the last two ``$..$`` segments of ``text``
    (:func:`latex_math.parse`): ``\\left\\{ C_{i,\\lambda}^{p}\\left( 0\\right) \\right\\} _{p\\geq0}`` and
    ``\\left\\{ S_{j,\\mu}^{p}\\left( 0\\right) \\right\\} _{p\\geq0}``, each a set without condition over p from an
    integer on (``ValueError`` otherwise)."""
    segs = lm.inline_math(text)
    p_, zero = sympy.Symbol("p"), sympy.Tuple(0)
    want = [("C_sup", (sympy.Symbol("i"), sympy.Symbol("lambda"), p_, zero)),
            ("S_sup", (sympy.Symbol("j"), sympy.Symbol("mu"), p_, zero))]
    out = []
    for seg, (name, args) in zip(segs[-2:], want):
        fam = lm.parse(seg)
        if not (isinstance(fam, AppliedUndef) and fam.func == lm.Family) or fam.args[1] or len(fam.args[2]) != 1:
            raise ValueError(f"not a set of values over p: {seg!r}")
        member, ((v, lo, hi),) = fam.args[0], fam.args[2]
        if not (isinstance(member, AppliedUndef) and member.func.__name__ == name and member.args == args) or \
                v != p_ or hi != sympy.oo or not lo.is_Integer:
            raise ValueError(f"not the values {name}(..)(0) for p >= an integer: {seg!r}")
        out.append(int(lo))
    if len(out) != 2:
        raise ValueError("two sets of values not read")
    return out


@line_check("sec1_3-lemma-hypotheses")
def lemma_hypotheses(verbatim_text: str | None = None) -> LineResult:
    """The Lemma's hypotheses (read): "Let $i$, $j$ and $p$ be natural numbers greater than or equal to $1$" while its
    sets of signs run over $p\\geq0$.  The hypothesis on p contradicts the sets (p = 0 is both excluded and listed);
    without it (i, j >= 1, p >= 0 as the sets say) the statement is consistent, and the sine rule (read from its
    transcription) holds on the whole range, p = 0 included (exact Taylor coefficients, j = lower bound..8,
    p = 0..16, mu in {1/2, 1, 3})."""
    from paper_repro.printed.derivatives import read_sign_function, sign_of

    tex = verbatim_text if verbatim_text is not None else _transcribed(["sec1_3-lemma-hypotheses"])[
        "sec1_3-lemma-hypotheses"]

    def run(text: str, without: str | None = None) -> tuple[bool, dict]:
        m = lm.sentence("Let {letters:words} be natural numbers greater than or equal to {lo}.", text, search=True)
        sets = _sign_value_sets(text)
        if not m or len(set(sets)) != 1 or "\\lambda,\\mu>0" not in text:
            raise ValueError("hypotheses not read")
        listed = m["letters"].replace(" and ", ", ").split(", ")  # "$i$, $j$ and $p$": each a segment, parsed
        letters = [str(lm.parse(x.strip("$"))) for x in listed if str(lm.parse(x.strip("$"))) != without]
        lo = lm.parse(m["lo"])
        if not all(x.startswith("$") and x.endswith("$") and len(x) > 2 for x in listed) or \
                not all(len(x) == 1 for x in letters) or not lo.is_Integer:
            raise ValueError("hypotheses not read")
        lo = int(lo)
        p_lo = lo if "p" in letters else int(sets[0])
        consistent = p_lo == int(sets[0])
        rule = read_sign_function(_transcribed(["sec1_3-sign-sin"])["sec1_3-sign-sin"])
        j_lo = lo if "j" in letters else 0
        holds = all(sign_of(rule, j=j, p=p) == sign(sin_power_derivative(j, mu, p)) for j in range(j_lo, 9)
                    for p in range(int(sets[0]), 17) for mu in (fmpq(1, 2), fmpq(1), fmpq(3)))
        return consistent and holds, {"hypothesis_letters": letters, "lower_bound": lo, "sets_from_p": int(sets[0]),
                                      "consistent": consistent, "sine_rule_holds": holds}
    try:
        ok, detail = run(tex)
        # the erratum's correction, on the letters read: the hypothesis is on i and j only
        corr = run(tex, without="p")[0] if detail["hypothesis_letters"] == ["i", "j", "p"] else None
    except ValueError as exc:
        return LineResult(False, how="the hypotheses read from the transcription", detail={"unread": str(exc)})
    return LineResult(ok, corr, how="the hypotheses and the index sets read from the transcription; the sine rule "
                      "(read) against exact Taylor coefficients, j = 1..8, p = 0..16", kind="exhaustive",
                      detail=detail)


def r0p1_sines() -> LineResult:
    """Line sec1_3-r0-p1-sines (resolved to claim independence_proof_steps), read: its terms evaluated at y = 0 of
    parametrization_1_y_0 against the exact values of the functions there.  As printed the last term's constant
    gamma_{2n,2n-i,0} stands outside the sum over i (i unbound: unread); with gamma_{2n,2n,0} (the line before, and
    the definition of rho'_{2n,0,0}) it holds."""
    tex = _transcribed(["sec1_3-r0-p1-sines"])["sec1_3-r0-p1-sines"]

    def run(value: sympy.Expr) -> tuple[bool, object]:
        try:
            terms = read_products(value)
        except ValueError as exc:
            return False, str(exc)
        for n in N_PROOF:
            for at in ALPHA_TS:
                for xf in X_FRACTIONS:
                    pt = _pt(n, at, xf)
                    try:
                        pr = evaluate_terms(terms, {"n": n}, 0, pt)
                    except ValueError as exc:
                        return False, str(exc)
                    if {q: v for q, v in pr.items() if v != 0} != _computed_form(
                            n, STEP_PARAMS[0], 0, alive_before(n, 0, 0), pt):
                        return False, f"n={n}: values differ"
        return True, None
    try:
        value = _row_value(tex)
    except ValueError as exc:
        return LineResult(False, how="the terms read from the transcription", detail={"unread": str(exc)})
    ok, why = run(value)
    fixed = _gamma_corner(value)
    corr = run(fixed)[0] if fixed != value else None
    return LineResult(ok, corr, how="the terms read from the transcription against exact values at y = 0, n = 1..6",
                      detail={"unread": why})


def _gamma_corner(value: sympy.Expr) -> sympy.Expr:
    """The erratum's correction of line sec1_3-r0-p1-sines, on the parsed value: in the term outside the sum, the
    constant ``gamma(2n, 2n-i, 0)`` of the factor ``sin(..)**(2n)`` is ``gamma(2n, 2n, 0)``."""
    n, i = sympy.symbols("n i")
    gamma = sympy.Function("gamma")
    printed, corrected = gamma(2 * n, 2 * n - i, 0), gamma(2 * n, 2 * n, 0)
    out = []
    for t in sympy.Add.make_args(value):
        factors = sympy.Mul.make_args(t)
        if printed in factors and any(f.is_Pow and isinstance(f.base, sympy.sin) and f.exp == 2 * n for f in factors):
            t = t.xreplace({printed: corrected})
        out.append(t)
    return sympy.Add(*out)


# -- the conclusions of the order-0 steps: the primed constants vanish (read from the transcription) ---------------
#: line -> (parametrization index 0/1/2, colour of the primed constants of level 0, colour of the one at i = 2n)
ZERO_LINES = {"sec1_3-r0-p1-zero": (0, "R", "G"), "sec1_3-r0-p2-zero": (1, "G", "B"),
              "sec1_3-r0-p3-zero": (2, "B", None)}


def zero_conclusion(line_id: str, verbatim: str | None = None) -> LineResult:
    """The printed conclusion ``rho'/gamma'/beta'_{2n,2n-i,0} = 0, i = a..b`` of an order-0 step, read from its
    transcription (range and right-hand side): the constants it names (by the definitions of the primed
    constants: color_{2n,2n-i,0} for i <= 2n-1, the other colour's corner for i = 2n) are exactly those of the
    functions whose restriction to the step's edge does not vanish (the elimination recomputed from exact values),
    and those restrictions are linearly independent (exact rank at 2n + 4 points of the edge), so a vanishing
    combination has exactly these constants equal to the printed right-hand side 0 (n = 1..6)."""
    param_index, color, alias = ZERO_LINES[line_id]
    tex = verbatim if verbatim is not None else _transcribed([line_id])[line_id]
    try:
        level, lo, hi, rhs = read_zero_line(tex, color)
        if level != 0:
            raise ValueError("not the level-0 constants")
        rhs = str(rhs)
    except ValueError as exc:
        return LineResult(False, how="the conclusion read from the transcription, n = 1..6", kind="exhaustive",
                          detail={"unread": str(exc)})
    bad = []
    for n in N_PROOF:
        named = set()
        for i in range(bound(lo, n=n), bound(hi, n=n) + 1):
            if 0 <= i <= 2 * n - 1:
                named.add(lab(color, n, i, 0))
            elif alias and i == 2 * n:
                named.add(lab(alias, n, 0, 0))
            else:
                named.add(-1 - i)  # a constant that does not exist
        forced = survivors(n, STEP_PARAMS[param_index], 0, alive_before(n, 0, param_index))
        labels = united_system(n)
        pts = [boundary_point(ALPHA_TS[0], fmpq(k, 2 * n + 5)) for k in range(1, 2 * n + 5)]
        rows = [[step_value(exponents(labels[k]), STEP_PARAMS[param_index], 0, pt) for k in sorted(forced)]
                for pt in pts]
        independent = _rank(rows) == len(forced)
        if named != forced or not independent:
            bad.append({"n": n, "printed_only": _names(n, {k for k in named if k >= 0} - forced),
                        "computed_only": _names(n, forced - named), "independent": independent})
    ok = rhs == "0" and not bad
    return LineResult(ok, how="range and right-hand side read from the transcription; the constants of the functions "
                      "not vanishing on the step's edge (exact values) and their exact rank at 2n + 4 points of the "
                      f"edge, n = {N_PROOF.start}..{N_PROOF.stop - 1}", kind="exhaustive",
                      detail={"printed_range": [str(lo), str(hi)], "right_hand_side": rhs, "mismatches": bad[:2]})


@line_check("sec1_3-r0-p1-zero")
def r0p1_zero() -> LineResult:
    return zero_conclusion("sec1_3-r0-p1-zero")


@line_check("sec1_3-r0-p2-zero")
def r0p2_zero() -> LineResult:
    return zero_conclusion("sec1_3-r0-p2-zero")


@line_check("sec1_3-r0-p3-zero")
def r0p3_zero() -> LineResult:
    return zero_conclusion("sec1_3-r0-p3-zero")
