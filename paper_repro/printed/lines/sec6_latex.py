"""Readers of the formulas of Section 6 (sec:applications) on top of the paper-wide reader
:mod:`paper_repro.printed.latex_math`: the torus control points of Example exmp:torus, the parametrizations eq.
toroidal_triangle and eq. Dupin_in_3d, the parameter settings of the captions, and chains of relations
(``c<\\mu\\leq a``, ``a^{2}=b^{2}+c^{2}``).  No formula is retyped: each is read from the ``verbatim`` of its
:class:`~paper_repro.printed.lines.Line`.

:func:`parse_expression` and :func:`parse_relation` call :func:`paper_repro.printed.latex_math.parse` and
:func:`~paper_repro.printed.latex_math.parse_relation` (refusing anything unread with ``LatexMathError``; a blank line
``XXX`` is refused) and return plain sympy objects in the symbols below.  :func:`exact_value` evaluates a parsed
expression exactly (python-flint rationals) given exact cosines and sines of base angles (e.g. ``alpha/2`` for a
rational ``tan(alpha/4)``).

>>> parse_expression(r"\\cos^{2}\\frac{\\alpha}{2}")
cos(alpha/2)**2
>>> parse_relation(r"c<\\mu\\leq a")
([c, mu, a], ['<', '<='])
>>> parse_expression(r"\\frac{1+\\sqrt{5}}{2}\\mu") == (1 + sympy.sqrt(5)) / 2 * MU
True
"""

from __future__ import annotations

import re

import sympy

from paper_repro.printed.latex_math import LatexMathError, parse
from paper_repro.printed.latex_math import parse_relation as latex_parse_relation

ALPHA, VARRHO, RHO, MU, VARPHI, PSI = sympy.symbols("alpha varrho rho mu varphi psi")
A, B, C, U, V, W = sympy.symbols("a b c u v w")


LatexReadError = LatexMathError  # what the reader refuses (a ValueError naming the unread part)


def strip_comments(tex: str) -> str:
    """LaTeX comments and ``%`` line continuations removed."""
    return re.sub(r"%[^\n]*\n?", " ", tex)


def parse_expression(tex: str) -> sympy.Expr:
    """One expression, read by :func:`paper_repro.printed.latex_math.parse` (``LatexMathError`` if any part is unread,
    or if it is not a scalar expression)."""
    if not strip_comments(tex).strip():
        raise LatexReadError("empty expression")
    out = parse(tex)
    if not isinstance(out, sympy.Expr):
        raise LatexReadError(f"not a scalar expression: {tex[:40]!r}")
    return out


def parse_relation(tex: str) -> tuple[list[sympy.Expr], list[str]]:
    """A chain ``e0 op1 e1 op2 e2 ...`` (ops ``=``, ``!=``, ``<``, ``<=``, ``>``, ``>=``), read by
    :func:`paper_repro.printed.latex_math.parse_relation`: the parts and the ops."""
    rel = latex_parse_relation(tex)
    if not rel.ops or getattr(rel, "conditions", None):
        raise LatexReadError(f"not a bare relation chain: {tex[:40]!r}")
    if any(op not in _TESTS for op in rel.ops):
        raise LatexReadError(f"relation {rel.ops} is not an (in)equality chain")
    return list(rel.parts), list(rel.ops)


_TESTS = {"<": lambda x, y: x < y, ">": lambda x, y: x > y, "=": lambda x, y: x == y, "<=": lambda x, y: x <= y,
          ">=": lambda x, y: x >= y, "!=": lambda x, y: x != y}


def relation_holds(parts: list, ops: list[str]) -> bool:
    """Whether a chain of numbers satisfies every relation."""
    return all(bool(_TESTS[op](parts[k], parts[k + 1])) for k, op in enumerate(ops))


# -- exact evaluation ------------------------------------------------------------------------------------------
def _linear_angle(arg: sympy.Expr, bases: dict) -> list[tuple[int, sympy.Symbol]]:
    """``arg = sum k_s (s / den_s)`` with integers ``k_s`` over the base angles ``s / den_s`` of ``bases``."""
    arg = sympy.expand(arg)
    out = []
    if not arg.free_symbols <= set(bases):
        raise LatexReadError(f"trigonometric argument {arg} names an unknown angle")
    for s in arg.free_symbols:
        coeff = arg.coeff(s)
        k = sympy.nsimplify(coeff * bases[s][0])
        if not k.is_Integer:
            raise LatexReadError(f"trigonometric argument {arg}: {coeff} {s} is not a multiple of {s}/{bases[s][0]}")
        out.append((int(k), s))
    if sympy.expand(arg - sum(k * s / bases[s][0] for k, s in out)) != 0:
        raise LatexReadError(f"trigonometric argument {arg} has a constant term")
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
        raise LatexReadError(f"cannot evaluate {e} exactly")

    return ev(expr)


__all__ = ["ALPHA", "VARRHO", "RHO", "MU", "VARPHI", "PSI", "A", "B", "C", "U", "V", "W", "LatexReadError",
           "strip_comments", "parse_expression", "parse_relation", "relation_holds", "exact_value"]
