"""General formulas of the normalizing coefficients by level (the open part of Question 1).

Write ``r_{2n,2n-i,j} = P_{n,i,j}(c) / s^{2n+j}`` (c = cos(alpha/2), s = sin(alpha/2)) and
``C_{n,k}(c) = s^{2n} c_{2n,k}``, the coefficient of X^k in (1 + 2cX + X^2)^n (eq. univariate_basis).
The printed levels are ``P_{n,i,0} = C_{n,i}`` (Remark normalizing_coeff_of_level_0) and
``P_{n,i,1} = i c C_{n,i} + (i+1) C_{n,i+1}`` (Proposition prop:level_1_coefficients, i >= 2).

For level j we search (:func:`fit`) for a formula of the same shape,

    P_{n,i,j}(c) = sum_{k=0..j} sum_{e,a,b} q_{k,e,a,b} c^e i^a n^b C_{n,i+k}(c),     e <= j, a + b <= j,

separately for the *interior* j < i <= n and the *diagonal* i = j < n (there a polynomial in n only), by
exact linear algebra over Q on the proven closed forms of small n.  The system has many more equations
than unknowns, so consistency is already a test; the formula is then compared with the closed forms of
every n up to the largest proven one (:func:`check`), most of them outside the fitted range.  Where it
agrees with proven closed forms it is proven for those n; beyond, it is a conjecture.

>>> f = fit(2, "interior", n_fit=8)
>>> [str(x) for x in predict(f, 3, 3).coeffs()]  # r_{6,3,2}: (144c + 252c^3 + 24c^5)/s^8, printed in Example n=3
['0', '144', '0', '252', '0', '24']
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from flint import fmpq, fmpq_mat, fmpq_poly

from paper_repro.core.univariate import c_numerator
from paper_repro.theory.closed_forms import closed_forms_cached

KINDS = ("interior", "diagonal", "all")


@dataclass(frozen=True)
class Formula:
    """``P_{n,i,j} = sum q[(k, e, a, b)] c^e i^a n^b C_{n,i+k}`` for the cases ``kind`` of level ``level``."""

    level: int
    kind: str
    terms: tuple[tuple[tuple[int, int, int, int], fmpq], ...]

    def as_json(self) -> dict:
        return {"level": self.level, "kind": self.kind, "cases": cases_text(self.level, self.kind),
                "terms": [{"shift_k": k, "c_power": e, "i_power": a, "n_power": b, "coefficient": str(q)}
                          for (k, e, a, b), q in self.terms],
                "expression": "P_{n,i,j}(c) = sum over terms of coefficient * c^c_power * i^i_power * n^n_power "
                              "* C_{n,i+shift_k}(c), C_{n,k} = coefficient of X^k in (1 + 2cX + X^2)^n",
                "latex": latex(self), "latex_expanded": latex_expanded(self)}


def cases_text(level: int, kind: str) -> str:
    return {"interior": f"{level} < i <= n", "diagonal": f"i = {level} < n", "all": f"{level} <= i <= n"}[kind]


def C(n: int, k: int) -> fmpq_poly:
    """``C_{n,k}(c)`` (the printed univariate constant times s^{2n}); zero outside 0..2n."""
    return fmpq_poly(c_numerator(n, k)) if 0 <= k <= 2 * n else fmpq_poly([0])


def _unknowns(level: int, kind: str) -> list[tuple[int, int, int, int]]:
    out = []
    for k in range(level + 1):
        for e in range(level + 1):
            for a in range(level + 1 if kind != "diagonal" else 1):
                for b in range(level + 1 - a):
                    out.append((k, e, a, b))
    return out


def _cases(level: int, kind: str, ns) -> list[tuple[int, int]]:
    if kind == "interior":
        return [(n, i) for n in ns for i in range(level + 1, n + 1)]
    if kind == "all":
        return [(n, i) for n in ns for i in range(level, n + 1)]
    return [(n, level) for n in ns if n > level]


def target(n: int, i: int, level: int, forms: dict | None = None) -> fmpq_poly:
    """The closed form's numerator with sine power 2n + j (as recovered); ``forms``: the closed forms of order n
    (:func:`~paper_repro.theory.closed_forms.closed_forms_cached`, read here when not given)."""
    forms = closed_forms_cached(n) if forms is None else forms
    f = forms[f"r_{{{2 * n},{2 * n - i},{level}}}"]
    if f.sin_power != 2 * n + level:
        raise ArithmeticError(f"unexpected sine power {f.sin_power} for level {level}, n = {n}")
    return f.numerator


def _term_poly(u: tuple[int, int, int, int], n: int, i: int) -> fmpq_poly:
    k, e, a, b = u
    return C(n, i + k) * fmpq_poly([0] * e + [1]) * (i**a * n**b)


def fit(level: int, kind: str, n_fit: int) -> Formula | None:
    """Exact fit on the closed forms of n <= ``n_fit``; ``None`` if the system is inconsistent (no formula of
    this shape).  Among the solutions the one with every free unknown zero (reduced row echelon form)."""
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    unknowns = _unknowns(level, kind)
    rows: list[list[fmpq]] = []
    forms = {n: closed_forms_cached(n) for n in range(1, n_fit + 1) if _cases(level, kind, [n])}
    for n, i in _cases(level, kind, range(1, n_fit + 1)):
        tgt = target(n, i, level, forms[n])
        basis = [_term_poly(u, n, i) for u in unknowns]
        for d in range(max([tgt.degree()] + [p.degree() for p in basis]) + 1):
            rows.append([p[d] for p in basis] + [tgt[d]])
    if not rows:
        return None
    aug = fmpq_mat(len(rows), len(unknowns) + 1, [x for r in rows for x in r])
    red, rank = aug.rref()
    terms = []
    for r in range(rank):
        piv = next(c for c in range(len(unknowns) + 1) if red[r, c] != 0)
        if piv == len(unknowns):
            return None  # a row 0 = 1: inconsistent
        terms.append((unknowns[piv], red[r, len(unknowns)]))
    return Formula(level, kind, tuple((u, q) for u, q in sorted(terms) if q != 0))


def predict(f: Formula, n: int, i: int) -> fmpq_poly:
    out = fmpq_poly([0])
    for u, q in f.terms:
        out += _term_poly(u, n, i) * q
    return out


def check(f: Formula, ns) -> dict:
    """Compare the formula with the closed forms for the given n: ``{"agrees_for_n": [...], "fails_for_n": [...]}``."""
    good, bad = [], []
    for n in ns:
        cases = _cases(f.level, f.kind, [n])
        if not cases:
            continue
        forms = closed_forms_cached(n)
        (good if all(predict(f, n, i) == target(n, i, f.level, forms) for _, i in cases) else bad).append(n)
    return {"agrees_for_n": good, "fails_for_n": bad}


def latex_expanded(f: Formula) -> str:
    """The formula in LaTeX as fitted (a polynomial in c, i, n per C_{n,i+k})."""
    parts = []
    for k in range(f.level + 1):
        coeff = []
        for (kk, e, a, b), q in f.terms:
            if kk != k:
                continue
            mono = "".join(x for x in (_pow("c", e), _pow("i", a), _pow("n", b)) if x)
            num, den = int(q.p), int(q.q)
            mag = (f"\\tfrac{{{abs(num)}}}{{{den}}}" if den != 1 else str(abs(num)))
            mag = "" if (mag == "1" and mono) else mag
            coeff.append(("-" if num < 0 else "+", mag + mono))
        if not coeff:
            continue
        body = "".join(f" {sg} {t}" for sg, t in coeff).strip()
        body = body[2:] if body.startswith("+ ") else body
        parts.append(f"\\left({body}\\right) C_{{n,{_index(f, k)}}}")
    return _lhs(f) + " + ".join(parts)


def _ctx():
    from flint import fmpq_mpoly_ctx

    return fmpq_mpoly_ctx.get(("n", "i", "c", "s"), "lex")


def s_form(f: Formula) -> dict[int, dict[tuple[int, int], object]]:
    """``{k: {(e, 2m): polynomial in n, i}}``: the coefficient of C_{n,i+k} as sum c^e s^{2m} (poly), after
    c^2 = 1 - s^2 (e = 0, 1); polynomials are flint ``fmpq_mpoly`` in (n, i, c, s) with c, s absent."""
    n_, i_, c_, s_ = _ctx().gens()
    out = {}
    for k in range(f.level + 1):
        poly = 0 * n_
        for (kk, e, a, b), q in f.terms:
            if kk == k:
                poly += q * c_ ** (e % 2) * (1 - s_**2) ** (e // 2) * i_**a * n_**b
        if poly == 0:
            continue
        groups: dict[tuple[int, int], object] = {}
        for (pn, pi, pc, ps), q in zip(poly.monoms(), poly.coeffs()):
            groups[(pc, ps)] = groups.get((pc, ps), 0 * n_) + q * n_**pn * i_**pi
        out[k] = groups
    return out


def interior_pattern(f: Formula) -> dict[str, bool]:
    """Two regularities of the interior formulas found (levels 2..5), checked exactly per level:
    the s^0 parts of both brackets equal F_j = (i+1) 2n (2n+j-1)! / (j! (2n+1)!) (as polynomials in n, i), and the
    highest power of s in the first bracket is s^{2 floor(j/2)} with coefficient (-1)^{floor(j/2)} binom(i, j)."""
    from math import factorial

    j = f.level
    n_, i_, _, _ = _ctx().gens()
    form = s_form(f)
    f_j = (i_ + 1) * 2 * n_
    for t in range(2, j):
        f_j *= 2 * n_ + t
    f_j = f_j / factorial(j)  # (2n+j-1)!/(2n+1)! = (2n+2)(2n+3)...(2n+j-1)
    binom = 1 + 0 * n_
    for t in range(j):
        binom *= i_ - t
    binom = binom / factorial(j)
    zero = {k: sum((g for (pc, ps), g in groups.items() if ps == 0), 0 * n_) for k, groups in form.items()}
    top = max(ps for (_, ps) in form[0])
    return {"s0_parts_equal_F_j": set(zero) == {0, 1} and zero[0] == f_j and zero[1] == f_j,
            "top_power_binomial": top == 2 * (j // 2) and sum((g for (_, ps), g in form[0].items() if ps == top),
                                                             0 * n_) == (-1) ** (j // 2) * binom}


def latex(f: Formula) -> str:
    """The same formula with c^2 = 1 - s^2: the coefficient of each C_{n,i+k} as a sum of c^e s^{2m} (e = 0, 1)
    times a polynomial in n and i, factored over Q (flint).  Equal to :func:`latex_expanded` on 0 < c < 1.

    >>> print(latex(printed_level_formulas()[1]))
    P_{n,i,1}(c) = \\left(i c\\right) C_{n,i} + \\left(i + 1\\right) C_{n,i+1}
    """
    parts = []
    for k, groups in s_form(f).items():
        body = ""
        for (pc, ps), g in sorted(groups.items(), key=lambda kv: (kv[0][1], kv[0][0])):
            const, factors = g.factor()
            tail = "".join(f" {x}" for x in (_pow("c", pc), _pow("s", ps)) if x)
            text = _factored(abs(const), factors)
            text = tail.strip() if (text == "1" and tail) else text + tail
            body += (" - " if const < 0 else " + ") + text.strip()
        body = body[3:] if body.startswith(" + ") else "-" + body[3:]
        if body.startswith("(") and body.endswith(")") and body.count("(") == 1:
            body = body[1:-1]  # a single factor: no double parentheses
        parts.append(f"\\left({body}\\right) C_{{n,{_index(f, k)}}}")
    return _lhs(f) + " + ".join(parts)


def _factored(const, factors) -> str:
    num, den = int(const.p), int(const.q)
    out = f"\\tfrac{{{num}}}{{{den}}}" if den != 1 else str(num)
    pieces = []
    for fac, mult in factors:
        t = str(fac).replace("*", " ")
        t = "".join(f"^{{{m.group(1)}}}" if m.group(1) else m.group(0) for m in _POW.finditer(t)) if "^" in t else t
        if len(fac) > 1:
            t = f"({t})"
        pieces.append(t + (f"^{{{mult}}}" if mult > 1 else ""))
    if not pieces:
        return out
    return ("" if out == "1" else out + " \\, ") + " ".join(pieces)


_POW = re.compile(r"\^(\d+)|[^^]")


def _index(f: Formula, k: int) -> str:
    if f.kind == "diagonal":
        return str(f.level + k)  # i = level
    return "i" if k == 0 else f"i+{k}"


def _lhs(f: Formula) -> str:
    return f"P_{{n,{f.level if f.kind == 'diagonal' else 'i'},{f.level}}}(c) = "


def _pow(var: str, e: int) -> str:
    return "" if e == 0 else (var if e == 1 else f"{var}^{{{e}}}")


def printed_level_formulas() -> list[Formula]:
    """Levels 0 and 1 as printed, in the same form (so they are checked by the same :func:`check`)."""
    level0 = Formula(0, "all", (((0, 0, 0, 0), fmpq(1)),))
    level1 = Formula(1, "interior", (((0, 1, 1, 0), fmpq(1)), ((1, 0, 0, 0), fmpq(1)), ((1, 0, 1, 0), fmpq(1))))
    level1_diag = Formula(1, "diagonal", (((1, 0, 0, 0), fmpq(2)),))
    return [level0, level1, level1_diag]


#: The centre r_{2n,n,n} = P_n(c)/s^{3n}: no formula of the level shape, but its two end values have closed
#: forms, found by guessing linear recurrences in n with polynomial coefficients on the proven closed forms
#: (an order-1 recurrence for the first: hypergeometric; for the second the Franel recurrence
#: (n+1)^2 a_{n+1} = (7n^2+7n+2) a_n + 8n^2 a_{n-1}).  ``expression`` is evaluated by :func:`eval_expression`.
CENTRE_END_VALUES = (
    {"name": "centre, alpha -> 0", "kind": "centre_alpha_to_0",
     "quantity": "P_n(1) = 0 and Q_n(1), where P_n = (1 - c^2) Q_n; so s^{3n-2} r_{2n,n,n} -> Q_n(1) as alpha -> 0",
     "expression": "2*(4*n-3)*factorial(3*n-3)//(factorial(n-1)**2*factorial(n))",
     "latex": r"Q_n(1) = \frac{2(4n-3)\,(3n-3)!}{(n-1)!^2\,n!}",
     "recurrence": "n (n+1) (4n-3) a_{n+1} = 3 (4n+1)(3n-1)(3n-2) a_n"},
    {"name": "centre, alpha -> pi (Franel numbers)", "kind": "centre_alpha_to_pi",
     "quantity": "P_n(0) = lim_{alpha -> pi} r_{2n,n,n}",
     "expression": "sum(comb(n, k)**3 for k in range(n + 1))",
     "latex": r"P_n(0) = \sum_{k=0}^{n} \binom{n}{k}^3",
     "recurrence": "(n+1)^2 a_{n+1} = (7n^2 + 7n + 2) a_n + 8 n^2 a_{n-1}"},
)


#: Every level at once, at c = 1: ``P_{n,i,j}(1) = L_{n,i,j}``, the alpha -> 0 limit factor, proven for every n
#: (claim ``limit_formula``, docs/limit_for_all_n.md): s^{2n+j} r_{2n,2n-i,j} -> L_{n,i,j}.
ALL_LEVELS_AT_1 = {
    "name": "alpha -> 0 limit of every coefficient", "kind": "all_levels_alpha_to_0",
    "quantity": "lim_{alpha -> 0} s^{2n+j} r_{2n,2n-i,j} (= P_{n,i,j}(1) wherever the closed form is known)",
    "expression": "0 if i == j == n else Fraction(factorial(2*n+j), factorial(2*n-i)*factorial(j)*factorial(i)) "
                  "* (1 if j == 0 else Fraction(2*n-j, 2*n+j) if i == j else Fraction(2*n, 2*n+j))",
    "latex": r"P_{n,i,j}(1) = \frac{(2n+j)!}{(2n-i)!\,j!\,i!}\cdot\frac{2n - (\mu-1)j}{2n+j}",
    "where": "mu = the number of minimal entries of (2n-i, j, i): 1 if j < i, 2 if i = j < n, 3 at the centre"}


def eval_expression(expr: str, n: int, **indices: int):
    """Evaluate a published expression in ``n`` (and ``i``, ``j``); names: comb, factorial, Fraction, sum, range.

    >>> eval_expression(CENTRE_END_VALUES[1]["expression"], 3)
    56
    >>> eval_expression(ALL_LEVELS_AT_1["expression"], 2, i=1, j=1)
    Fraction(12, 1)
    """
    from fractions import Fraction
    from math import comb, factorial

    names = {"__builtins__": {}, "n": n, "comb": comb, "factorial": factorial, "sum": sum, "range": range,
             "Fraction": Fraction, **indices}
    return eval(expr, names)  # noqa: S307 -- our own published expressions, no builtins


def centre_end_values(n: int) -> dict[str, int | bool]:
    """From the closed form of the centre: P_n(1) = 0?, Q_n(1) and P_n(0) (exact)."""
    p = closed_forms_cached(n)[f"r_{{{2 * n},{n},{n}}}"].numerator
    q, rem = divmod(p, fmpq_poly([1, 0, -1]))
    return {"vanishes_at_1": p(fmpq(1)) == 0 and rem == 0, "centre_alpha_to_0": int(q(fmpq(1))),
            "centre_alpha_to_pi": int(p(fmpq(0)))}


@lru_cache(maxsize=8)
def _formula_polys(n: int, max_level: int | None) -> tuple[fmpq_poly, ...]:
    from paper_repro.core.context import ExactContext
    from paper_repro.core.normalizing_formula import scaled_table

    return tuple(scaled_table(n, fmpq_poly([0, 1]), fmpq_poly([1, 0, -1]), ExactContext(), max_level=max_level))


def formula_target(n: int, i: int, level: int, max_level: int | None = None) -> fmpq_poly:
    """s^{2n+j} r_{2n,2n-i,j} from the all-n formula (docs/question1_for_all_n.md) as a polynomial in c."""
    top = n if max_level is None else min(n, max_level)
    k = sum(n + 1 - j for j in range(level)) + (i - level)
    return _formula_polys(n, top)[k]


def check_against_formula(f: Formula, ns, max_level: int) -> dict:
    """Compare a level formula with the all-n formula for the given n (a consequence, checked)."""
    good, bad = [], []
    for n in ns:
        cases = _cases(f.level, f.kind, [n])
        if not cases:
            continue
        ok = all(predict(f, n, i) == formula_target(n, i, f.level, max_level) for _, i in cases)
        (good if ok else bad).append(n)
    return {"agrees_for_n": good, "fails_for_n": bad}


def centre_end_values_from_formula(n: int) -> dict[str, int | bool]:
    """The centre's end values from the all-n formula: P(1) = 0, (P/(1 - c^2))(1) and P(0) (the centre alone is
    computed, :func:`~paper_repro.core.normalizing_formula.scaled_table` with ``min_level=n``)."""
    from paper_repro.core.context import ExactContext
    from paper_repro.core.normalizing_formula import scaled_table

    (p,) = scaled_table(n, fmpq_poly([0, 1]), fmpq_poly([1, 0, -1]), ExactContext(), min_level=n)
    q, rem = divmod(p, fmpq_poly([1, 0, -1]))
    return {"vanishes_at_1": p(fmpq(1)) == 0 and rem == 0, "centre_alpha_to_0": int(q(fmpq(1))),
            "centre_alpha_to_pi": int(p(fmpq(0)))}
