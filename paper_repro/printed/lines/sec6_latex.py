"""A small reader of the formulas of Section 6 (sec:applications): the torus control points of Example exmp:torus,
the parametrizations eq. toroidal_triangle and eq. Dupin_in_3d, the parameter settings of the captions, and chains of
relations (``c<\\mu\\leq a``, ``a^{2}=b^{2}+c^{2}``).  No formula is retyped: each is read from the ``verbatim`` of its
:class:`~paper_repro.printed.lines.Line`.

What it reads (:func:`parse_expression`): sums and differences, juxtaposed products, integers, ``\\frac{..}{..}``,
``\\sqrt{..}``, ``\\left( .. \\right)``, groups ``{..}``, powers ``x^{k}`` with an integer ``k``, the symbols
``\\alpha``, ``\\varrho``, ``\\rho``, ``\\mu``, ``\\varphi``, ``\\psi``, ``\\pi`` and the single letters ``a``, ``b``,
``c``, ``u``, ``v``, ``w``, and ``\\sin``/``\\cos``/``\\tan`` (optionally ``^{k}``) applied to the next atom
(``\\sin\\alpha``, ``\\tan\\frac{\\alpha}{2}``, ``\\cos^{2}\\frac{\\alpha}{2}``, ``\\cos\\left( u+\\varphi\\right)``).
What it refuses: everything else (``LatexReadError`` naming the unread part; a blank line ``XXX`` is refused).  The
paper-wide reader ``paper_repro.printed.latex_math`` (being written) is to replace it.

:func:`exact_value` evaluates a parsed expression exactly (python-flint rationals) given exact cosines and sines of
base angles (e.g. ``alpha/2`` for a rational ``tan(alpha/4)``).

>>> parse_expression(r"\\cos^{2}\\frac{\\alpha}{2}")
cos(alpha/2)**2
>>> parse_relation(r"c<\\mu\\leq a")
([c, mu, a], ['<', '<='])
>>> parse_expression(r"\\frac{1+\\sqrt{5}}{2}\\mu")
mu*(1/2 + sqrt(5)/2)
"""

from __future__ import annotations

import re

import sympy

ALPHA, VARRHO, RHO, MU, VARPHI, PSI = sympy.symbols("alpha varrho rho mu varphi psi")
A, B, C, U, V, W = sympy.symbols("a b c u v w")
_SYMBOLS = {"\\alpha": ALPHA, "\\varrho": VARRHO, "\\rho": RHO, "\\mu": MU, "\\varphi": VARPHI, "\\psi": PSI,
            "\\pi": sympy.pi, "a": A, "b": B, "c": C, "u": U, "v": V, "w": W}
_FUNCS = {"\\sin": sympy.sin, "\\cos": sympy.cos, "\\tan": sympy.tan}


class LatexReadError(ValueError):
    """A formula (or a part of one) that the reader does not understand."""


_TOKEN = re.compile(r"\s*(\\left\(|\\right\)|\\[A-Za-z]+|\d+|[a-z](?![a-zA-Z])|\\leq|[-+{}&^()<>=])")


def strip_comments(tex: str) -> str:
    """LaTeX comments and ``%`` line continuations removed."""
    return re.sub(r"%[^\n]*\n?", " ", tex)


def _tokens(tex: str) -> list[str]:
    text = strip_comments(tex)
    out, pos = [], 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m:
            raise LatexReadError(f"unread LaTeX at {text[pos:pos + 30]!r}")
        out.append(m.group(1))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, tex: str):
        self.toks = _tokens(tex)
        self.k = 0

    def peek(self) -> str | None:
        return self.toks[self.k] if self.k < len(self.toks) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise LatexReadError(f"expected {want or 'a token'!r}, found {tok!r} (token {self.k} of {self.toks})")
        self.k += 1
        return tok

    def expr(self) -> sympy.Expr:
        sign = 1
        if self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
        out = sign * self.term()
        while self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
            out += sign * self.term()
        return out

    @staticmethod
    def _starts_atom(tok: str | None) -> bool:
        if tok is None:
            return False
        return tok.isdigit() or tok in ("{", "\\left(", "\\frac", "\\sqrt") or tok in _SYMBOLS or tok in _FUNCS

    def term(self) -> sympy.Expr:
        if not self._starts_atom(self.peek()):
            raise LatexReadError(f"expected a factor, found {self.peek()!r}")
        out = self.factor()
        while self._starts_atom(self.peek()):
            out *= self.factor()
        return out

    def group(self) -> sympy.Expr:
        self.take("{")
        e = self.expr()
        self.take("}")
        return e

    def integer_group(self) -> int:
        self.take("{")
        tok = self.take()
        if not tok.isdigit():
            raise LatexReadError(f"an exponent must be an integer, found {tok!r}")
        self.take("}")
        return int(tok)

    def atom(self) -> sympy.Expr:
        tok = self.take()
        if tok.isdigit():
            out: sympy.Expr = sympy.Integer(int(tok))
        elif tok == "{":
            self.k -= 1
            out = self.group()
        elif tok == "\\left(":
            out = self.expr()
            self.take("\\right)")
        elif tok == "\\frac":
            num = self.group()
            out = num / self.group()
        elif tok == "\\sqrt":
            out = sympy.sqrt(self.group())
        elif tok in _SYMBOLS:
            out = _SYMBOLS[tok]
        else:
            raise LatexReadError(f"unread atom {tok!r}")
        if self.peek() == "^":
            self.take("^")
            out = out ** self.integer_group()
        return out

    def factor(self) -> sympy.Expr:
        tok = self.peek()
        if tok in _FUNCS:
            self.take()
            power = 1
            if self.peek() == "^":
                self.take("^")
                power = self.integer_group()
            arg = self.atom()  # the argument is the next atom
            return _FUNCS[tok](arg) ** power
        return self.atom()


def parse_expression(tex: str) -> sympy.Expr:
    """One expression (``LatexReadError`` if any part is unread)."""
    p = _Parser(tex)
    if p.peek() is None:
        raise LatexReadError("empty expression")
    e = p.expr()
    if p.peek() is not None:
        raise LatexReadError(f"unread tail {p.toks[p.k:]}")
    return e


_REL = {"<": "<", ">": ">", "=": "=", "\\leq": "<=", "\\geq": ">=", "\\neq": "!="}


def parse_relation(tex: str) -> tuple[list[sympy.Expr], list[str]]:
    """A chain ``e0 op1 e1 op2 e2 ...`` with ops among ``<``, ``>``, ``=``, ``\\leq``, ``\\geq``, ``\\neq``: the
    parts and the ops (``=``, ``<``, ``<=``, ...)."""
    text = strip_comments(tex)
    pieces = re.split(r"(\\leq|\\geq|\\neq|<|>|=)", text)
    parts = [parse_expression(x) for x in pieces[0::2]]
    ops = [_REL[x] for x in pieces[1::2]]
    if not ops:
        raise LatexReadError(f"no relation in {tex[:40]!r}")
    return parts, ops


def relation_holds(parts: list, ops: list[str]) -> bool:
    """Whether a chain of numbers satisfies every relation."""
    test = {"<": lambda x, y: x < y, ">": lambda x, y: x > y, "=": lambda x, y: x == y, "<=": lambda x, y: x <= y,
            ">=": lambda x, y: x >= y, "!=": lambda x, y: x != y}
    return all(test[op](parts[k], parts[k + 1]) for k, op in enumerate(ops))


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
