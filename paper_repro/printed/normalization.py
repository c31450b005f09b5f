"""The printed normalizing-coefficient formulas of Section sec:partition_of_unity, read from their transcriptions.

Nothing here is typed in: every value is parsed (:mod:`paper_repro.printed.latex_math`) from the verbatim
LaTeX of the lines of :mod:`paper_repro.printed.lines.sec4_5` at the moment it is asked for (so the blank and
mutation tests of :mod:`paper_repro.claims.lines.mutation` reach every user).  ``s = sin(alpha/2)``,
``c = cos(alpha/2)``, ``C(i) = c_{2n,i}^alpha`` (the univariate constants); the values are computed with the
arithmetic of the arguments (exact ``fmpq``, mpmath, rational functions alike).

* ``FINAL`` -- right-hand closed forms of Examples normalizing_coefficients_n_1..3 (lines ``sec4_5-ex-*-final`` and,
  at level 0, ``sec4_5-ex-*-c-value``): ``(paper_ref, numerator coefficients in c ascending, power of s)``.
* ``INTERMEDIATE`` -- the middle expressions of the same Examples (in terms of c_{2n,i}; at level 0 the constant
  c_{2n,k} the line equates r with): ``(paper_ref, function of (s, c, C))``.
* :func:`remark_level_0` (Remark normalizing_coeff_of_level_0) and :func:`prop_level_1` (Proposition
  prop:level_1_coefficients, eq. level_1_coefficients), for any n, parsed from their lines.
* :func:`from_1_to_2` -- Example exmp:from_1_to_2 (Section 7, not read here: a verbatim Python transcription kept
  for its claim; the lines of Section 7 are checked by :mod:`paper_repro.claims.lines.sec7`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping

import sympy

from paper_repro.printed.latex_math import LatexMathError
from paper_repro.printed.lines import line, verbatim
from paper_repro.printed.parsed import listed_range, relation, value

#: The coefficients of the Examples, in the order printed (their lines are ``sec4_5-ex-<slug>-...``).
LABELS = ("r_{2,2,0}", "r_{2,1,0}", "r_{2,1,1}", "r_{4,4,0}", "r_{4,3,0}", "r_{4,2,0}", "r_{4,3,1}", "r_{4,2,1}",
          "r_{4,2,2}", "r_{6,6,0}", "r_{6,5,0}", "r_{6,4,0}", "r_{6,3,0}", "r_{6,5,1}", "r_{6,4,1}", "r_{6,3,1}",
          "r_{6,4,2}", "r_{6,3,2}", "r_{6,3,3}")
_S, _C = sympy.symbols("S C")
_ALPHA = sympy.Symbol("alpha")


def _slug(label: str) -> str:
    return label.replace("_{", "").replace(",", "").replace("}", "")


def _level0(label: str) -> bool:
    return label.endswith(",0}")


def _in_s_c(e: sympy.Expr) -> sympy.Expr:
    return e.subs({sympy.sin(_ALPHA / 2): _S, sympy.cos(_ALPHA / 2): _C})


def evaluate(e: sympy.Expr, s, c, C: Callable | None = None):
    """The value of a parsed expression in S, C and c_{2n,i} with the arithmetic of ``s``, ``c``, ``C(i)``."""
    if e == _S:
        return s
    if e == _C:
        return c
    if e.is_Integer:
        return int(e)
    if isinstance(e, sympy.Add):
        out = None
        for a in e.args:
            v = evaluate(a, s, c, C)
            out = v if out is None else out + v
        return out
    if isinstance(e, sympy.Mul):
        out = None
        for a in e.args:
            v = evaluate(a, s, c, C)
            out = v if out is None else out * v
        return out
    if isinstance(e, sympy.Pow) and e.exp.is_Integer:
        base = evaluate(e.base, s, c, C)
        k = int(e.exp)
        return base**k if k >= 0 else 1 / base ** (-k)
    if isinstance(e, sympy.core.function.AppliedUndef) and e.func.__name__ == "c" and C is not None:
        return C(int(e.args[1]))
    raise LatexMathError(f"cannot evaluate {e}")


def _parts(line_id: str) -> list[sympy.Expr]:
    rel = relation(verbatim(line_id))
    if set(rel.ops) != {"="}:
        raise LatexMathError(f"{line_id}: relations {rel.ops}")
    return [_in_s_c(p) for p in rel.parts]


def intermediate_expr(label: str) -> sympy.Expr:
    """The printed middle expression of ``label`` (level 0: the constant c_{2n,k} of ``r = c``)."""
    return _parts(f"sec4_5-ex-{_slug(label)}-{'r-c' if _level0(label) else 'mid'}")[-1]


def final_expr(label: str) -> sympy.Expr:
    """The printed closed form of ``label``: the last part of its chain."""
    return _parts(f"sec4_5-ex-{_slug(label)}-{'c-value' if _level0(label) else 'final'}")[-1]


def final_parts(label: str) -> tuple[list[int], int]:
    """The printed closed form as (numerator coefficients in c ascending, power of sin(alpha/2))."""
    num, den = sympy.fraction(sympy.together(final_expr(label)))
    k = sympy.Poly(den, _S, _C)
    if len(k.terms()) != 1 or k.terms()[0][0][1] != 0:
        raise LatexMathError(f"{label}: the denominator {den} is not a power of sin(alpha/2)")
    (ks, _kc), lead = k.terms()[0]
    p = sympy.Poly(num, _C)
    coeffs = [sympy.Rational(x) / lead for x in reversed(p.all_coeffs())]
    if any(not x.is_Integer for x in coeffs) or num.has(_S):
        raise LatexMathError(f"{label}: the numerator {num} is not an integer polynomial in cos(alpha/2)")
    return [int(x) for x in coeffs], int(ks)


def _ref(label: str) -> str:
    return line(f"sec4_5-ex-{_slug(label)}-{'c-value' if _level0(label) else 'final'}").near


class _Final(Mapping):
    """``label -> (paper_ref, numerator coefficients ascending, power of s)``, parsed at every lookup."""

    def __getitem__(self, label: str) -> tuple[str, list[int], int]:
        if label not in LABELS:
            raise KeyError(label)
        return (_ref(label), *final_parts(label))

    def __iter__(self) -> Iterator[str]:
        return iter(LABELS)

    def __len__(self) -> int:
        return len(LABELS)


class _Intermediate(Mapping):
    """``label -> (paper_ref, function (s, c, C) -> value)``, parsed at every lookup."""

    def __getitem__(self, label: str) -> tuple[str, Callable]:
        if label not in LABELS:
            raise KeyError(label)
        e = intermediate_expr(label)
        return (_ref(label), lambda s, c, C, e=e: evaluate(e, s, c, C))

    def __iter__(self) -> Iterator[str]:
        return iter(LABELS)

    def __len__(self) -> int:
        return len(LABELS)


FINAL: Mapping[str, tuple[str, list[int], int]] = _Final()
INTERMEDIATE: Mapping[str, tuple[str, Callable]] = _Intermediate()


def final_value(label: str, s, c):
    """Value of the printed final closed form of ``label`` at ``s = sin(a/2)``, ``c = cos(a/2)``."""
    return evaluate(final_expr(label), s, c)


def remark_level_0(n: int, i: int, C: Callable):
    """Remark normalizing_coeff_of_level_0, parsed: the constant r_{2n,2n-i,0} is equated with, at (n, i)."""
    rel = relation(verbatim("sec4_5-level0-r-c"))
    if rel.ops != ["="]:
        raise LatexMathError(f"relations {rel.ops}")
    e = rel.parts[1].subs({sympy.Symbol("n"): n, sympy.Symbol("i"): i})
    return evaluate(e, None, None, C)


def prop_level_1(n: int, i: int, s, c, C: Callable):
    """Proposition prop:level_1_coefficients (eq. level_1_coefficients), parsed: the case whose printed condition
    holds at i (``i=1`` or ``i=2,3,\\ldots,n``), at order n."""
    for lid in ("sec4_5-level1-i1", "sec4_5-level1-i"):
        tex = verbatim(lid)
        k = tex.find(", &")
        if k < 0:
            raise LatexMathError(f"{lid}: no condition")
        cond = tex[k + 3:].replace("\\\\", "").strip().rstrip(".,")
        n_ = sympy.Symbol("n")
        if "\\ldots" in cond:
            _v, lo, hi = listed_range(cond, "i")
            hit = int(lo.subs(n_, n)) <= i <= int(hi.subs(n_, n))
        else:
            rel = relation(cond)
            hit = rel.ops == ["="] and rel.parts[0] == sympy.Symbol("i") and rel.parts[1] == i
        if hit:
            e = _in_s_c(value(tex[:k])).subs({n_: n, sympy.Symbol("i"): i})
            return evaluate(e, s, c, C)
    raise LatexMathError(f"no printed case of eq. level_1_coefficients for i = {i}")


def from_1_to_2(s, c, r: dict) -> dict:
    """Example exmp:from_1_to_2: second order coefficients from first order ones (verbatim).

    ``r`` maps first-order labels (r_, g_, b_ of {2,2,0}, {2,1,0} and r_{2,1,1}) to values.
    Returns the printed right-hand sides keyed by second-order label.
    """
    r220, r210, r211 = r["r_{2,2,0}"], r["r_{2,1,0}"], r["r_{2,1,1}"]
    g220, g210, b220, b210 = r["g_{2,2,0}"], r["g_{2,1,0}"], r["b_{2,2,0}"], r["b_{2,1,0}"]
    sin_a = 2 * s * c  # sin(alpha)
    tan_h = s / c  # tan(alpha/2)
    return {
        "r_{4,4,0}": r220**2, "g_{4,4,0}": g220**2, "b_{4,4,0}": b220**2,
        "r_{4,3,0}": 2 * r220 * r210, "g_{4,3,0}": 2 * g220 * g210, "b_{4,3,0}": 2 * b220 * b210,
        "r_{4,2,0}": 2 * r220 * g220 + r210**2, "g_{4,2,0}": 2 * g220 * b220 + g210**2,
        "b_{4,2,0}": 2 * r220 * b220 + b210**2,
        "r_{4,1,0}": 2 * r210 * g220, "g_{4,1,0}": 2 * g210 * b220, "b_{4,1,0}": 2 * r220 * b210,
        "r_{4,3,1}": 2 * r220 * r211 + r220**2 * g210 * sin_a + 2 * (1 + r220 * c**2) * r210 * b210 * s,
        "g_{4,3,1}": 2 * r211 * g220 + 2 * r210 * (1 + g220 * c**2) * g210 * s + g220**2 * b210 * sin_a,
        "b_{4,3,1}": 2 * r211 * b220 + r210 * b220**2 * sin_a + 2 * g210 * (1 + b220 * c**2) * b210 * s,
        "r_{4,2,1}": (2 * r210 * r211 + r220 * r210 * g210 * tan_h + r210**2 * g210 * s
                      + r210 * b210**2 * s + r210 * g220 * b210 * tan_h),
        "g_{4,2,1}": (2 * r211 * g210 + r210 * g210**2 * s + r210 * g210 * b220 * tan_h
                      + g220 * g210 * b210 * tan_h + g210**2 * b210 * s),
        "b_{4,2,1}": (2 * r211 * b210 + r220 * g210 * b210 * tan_h + r210 * b220 * b210 * tan_h
                      + r210**2 * b210 * s + g210 * b210**2 * s),
        "r_{4,2,2}": (r211**2 + 2 * r220 * g220 + 2 * r220 * b220 + 2 * g220 * b220 + 2 * r210 * g210
                      + 2 * r210 * b210 + 2 * g210 * b210),
    }
