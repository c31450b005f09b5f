"""The reader of formulas for the line checks of Sections 1-2 (:mod:`paper_repro.claims.lines.sec1_3`; issue 37: a
check parses the transcription, it never retypes the formula).

:func:`parse` and :func:`relation` call :mod:`paper_repro.printed.latex_math` (the project's grammar of the paper's
notation) and map its names to the ones the checks use (``B_sup`` -> ``B``); :func:`half_angle_powers` reads a
product of half-angle powers.  :func:`own_parse` is the interim recursive-descent reader written before latex_math
landed, kept for the tests that compare the two; it follows the same contract:

* ``\\sin^{k}\\frac{u}{2}`` is ``sin(u/2)**k``; a function's argument is the next atom (``\\frac{..}{..}``,
  ``\\left(..\\right)``, a group, a symbol);
* juxtaposition multiplies (``2n`` is ``2*n``, ``ru`` is ``r*u``); greek letters are Symbols named ``alpha``, ...;
  ``\\pi`` is :data:`sympy.pi`; ``\\binom``/``\\dbinom`` -> :func:`sympy.binomial`; ``\\lfloor..\\rfloor`` ->
  :func:`sympy.floor`; ``\\sum_{i=a}^{b}`` -> :class:`sympy.Sum` over the product that follows;
  ``\\lim_{x\\rightarrow a}`` -> an unevaluated :class:`sympy.Limit`;
* an indexed name ``X_{a,b}^{c}`` -> ``Function(X)(a, b[, c])`` (a superscript ``\\alpha`` is dropped: it names the
  shape parameter, not an index); an argument list ``\\left( u,v,w\\right)`` right after it is appended as a final
  :class:`sympy.Tuple`;
* ``%`` continuations, ``\\left``/``\\right``, spacing, ``&``, ``\\\\``, ``\\label``, ``\\nonumber``, ``\\text{.}``
  are ignored.

Anything else raises :class:`TexError` naming the unread part (latex_math refuses a blank line ``XXX``; the own
reader would parse it to the product ``X*X*X`` of symbols, which a check must refuse: see :func:`names`).

>>> parse(r"\\sin^{2n-i}\\frac{u}{2}\\cos^{j}\\frac{v}{2}")
sin(u/2)**(-i + 2*n)*cos(v/2)**j
>>> relation(r"c_{2n,i}^{\\alpha}=c_{2n,2n-i}^{\\alpha}")
[c(2*n, i), c(2*n, -i + 2*n)]
>>> parse(r"\\sum_{r=0}^{\\left\\lfloor \\frac{i}{2}\\right\\rfloor }\\binom{n}{i-r}")
Sum(binomial(n, i - r), (r, 0, floor(i/2)))
"""

from __future__ import annotations

import re
from functools import cache

import sympy

GREEK = ("alpha", "beta", "gamma", "delta", "varrho", "rho", "mu", "lambda", "tau", "sigma", "omega", "theta")


class TexError(ValueError):
    """A part of the LaTeX the reader does not read."""


_DROP = (r"\\left(?![a-zA-Z])", r"\\right(?![a-zA-Z])", r"\\displaystyle", r"\\limits", r"\\nonumber", r"\\,",
         r"\\!", r"\\;", r"\\quad", r"~", r"&", r"\\\\", r"\\text\{[^{}]*\}", r"\\label\{[^{}]*\}", r"%", r"\\ ")


def clean(tex: str) -> str:
    """The LaTeX without what the reader ignores (see the module docstring)."""
    for pat in _DROP:
        tex = re.sub(pat, " ", tex)
    return tex.replace("\\lbrace", "\\{").replace("\\rbrace", "\\}")


_TOKEN = re.compile(r"\\[a-zA-Z]+|\\[{}|]|\d+|[a-zA-Z]|[-+*/^_=(){}\[\],.<>|:]|\S")


class _Parser:
    def __init__(self, tex: str) -> None:
        self.toks = _TOKEN.findall(clean(tex))
        self.k = 0
        self.src = tex

    # -- tokens
    def peek(self, ahead: int = 0) -> str | None:
        return self.toks[self.k + ahead] if self.k + ahead < len(self.toks) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise TexError(f"expected {want!r} at {' '.join(self.toks[self.k:self.k + 6])!r} in {self.src[:80]!r}")
        self.k += 1
        return tok

    def rest(self) -> str:
        return " ".join(self.toks[self.k:self.k + 8])

    # -- grammar
    def expr(self, stop: tuple[str, ...] = ()) -> sympy.Expr:
        sign = 1
        if self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
        out = sign * self.term(stop)
        while self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
            out = out + sign * self.term(stop)
        return out

    def term(self, stop: tuple[str, ...] = ()) -> sympy.Expr:
        factors = [self.power()]
        while self.peek() is not None and self.peek() not in ("+", "-", "=", ")", "}", "]", ",", "\\rfloor",
                                                              "\\}", ":", "<", ">", "\\in", "\\leq", "\\geq",
                                                              "\\rightarrow", "\\to", "\\neq", "\\cup", ".") + stop:
            factors.append(self.power())
        out = sympy.Integer(1)
        for f in factors:
            out = out * f
        return out

    def power(self) -> sympy.Expr:
        base = self.atom()
        while self.peek() == "^":
            self.take()
            base = base ** self.group_or_token()
        return base

    def group_or_token(self) -> sympy.Expr:
        if self.peek() == "{":
            self.take("{")
            e = self.expr()
            self.take("}")
            return e
        return self.atom()

    def group(self) -> sympy.Expr:
        self.take("{")
        e = self.expr()
        self.take("}")
        return e

    def indices(self) -> list[sympy.Expr]:
        """``{a,b,c}`` or a single token after ``_``/``^``."""
        if self.peek() != "{":
            return [self.atom_plain()]
        self.take("{")
        out = [self.expr()]
        while self.peek() == ",":
            self.take(",")
            out.append(self.expr())
        self.take("}")
        return out

    def atom_plain(self) -> sympy.Expr:
        tok = self.take()
        if tok.isdigit():
            return sympy.Integer(int(tok))
        if re.fullmatch(r"[a-zA-Z]", tok):
            return sympy.Symbol(tok)
        if tok.startswith("\\") and tok[1:] in GREEK:
            return sympy.Symbol(tok[1:])
        raise TexError(f"unread {tok!r} at {self.rest()!r}")

    def fn_argument(self) -> sympy.Expr:
        """The argument of ``\\sin``/``\\cos``: the next atom (with its coefficient, as ``2\\alpha``)."""
        if self.peek() in ("(", "{") or (self.peek() or "").startswith("\\frac"):
            return self.atom()
        out = self.atom()
        while self.peek() is not None and (re.fullmatch(r"[a-zA-Z]|\d+", self.peek())
                                           or self.peek()[1:] in GREEK):
            out = out * self.atom()
        return out

    def atom(self) -> sympy.Expr:
        tok = self.peek()
        if tok is None:
            raise TexError(f"unexpected end of {self.src[:80]!r}")
        if tok == "(":
            self.take()
            e = self.expr()
            self.take(")")
            return e
        if tok == "{":
            return self.group()
        if tok in ("\\frac", "\\dfrac", "\\tfrac"):
            self.take()
            a = self.group()
            b = self.group()
            return a / b
        if tok in ("\\binom", "\\dbinom"):
            self.take()
            a = self.group()
            b = self.group()
            return sympy.binomial(a, b)
        if tok == "\\lfloor":
            self.take()
            e = self.expr()
            self.take("\\rfloor")
            return sympy.floor(e)
        if tok in ("\\sin", "\\cos"):
            self.take()
            exp = None
            if self.peek() == "^":
                self.take()
                exp = self.group_or_token()
            arg = self.fn_argument()
            f = (sympy.sin if tok == "\\sin" else sympy.cos)(arg, evaluate=False)
            return f if exp is None else f ** exp
        if tok == "\\sum":
            self.take()
            self.take("_")
            self.take("{")
            var = self.atom_plain()
            self.take("=")
            lo = self.expr()
            self.take("}")
            self.take("^")
            hi = self.group_or_token()
            body = self.term()
            return sympy.Sum(body, (var, lo, hi))
        if tok == "\\lim":
            self.take()
            self.take("_")
            self.take("{")
            var = self.atom_plain()
            if self.peek() not in ("\\rightarrow", "\\to"):
                raise TexError(f"unread limit at {self.rest()!r}")
            self.take()
            point = self.expr()
            self.take("}")
            body = self.power()
            return sympy.Limit(body, var, point)
        if tok == "\\pi":
            self.take()
            return sympy.pi
        if tok.isdigit():
            self.take()
            return sympy.Integer(int(tok))
        if re.fullmatch(r"[a-zA-Z]", tok) or (tok.startswith("\\") and tok[1:] in GREEK):
            name = self.take()
            name = name[1:] if name.startswith("\\") else name
            if self.peek() != "_":
                return sympy.Symbol(name)
            self.take("_")
            args = self.indices()
            if self.peek() == "^" and self.peek(1) == "{" and self.peek(2) == "\\alpha" and self.peek(3) == "}":
                self.k += 4  # the shape parameter, not an index
            elif self.peek() == "^" and name in ("B",):
                self.take("^")
                args += self.indices()
            if self.peek() == "(":
                self.take("(")
                call = [self.expr()]
                while self.peek() == ",":
                    self.take(",")
                    call.append(self.expr())
                self.take(")")
                args.append(sympy.Tuple(*call))
            return sympy.Function(name)(*args)
        raise TexError(f"unread {tok!r} at {self.rest()!r} in {self.src[:80]!r}")


def _paper_names(e):
    """latex_math's names mapped to this module's: ``B_sup(i, 2n, (s,))`` (B_i^{2n}, the Bernstein polynomial: the
    superscript is an index) is ``B(i, 2n, (s,))``."""
    if not isinstance(e, sympy.Basic):
        raise TexError(f"not an expression: {e!r}")
    return e.replace(lambda x: isinstance(x, sympy.core.function.AppliedUndef) and x.func.__name__ == "B_sup",
                     lambda x: sympy.Function("B")(*x.args))


@cache
def parse(tex: str) -> sympy.Expr:
    """One expression (all of ``tex`` must be read), by :func:`paper_repro.printed.latex_math.parse` (the project's
    reader of the paper's notation); :class:`TexError` on anything it refuses."""
    from paper_repro.printed import latex_math

    try:
        return _paper_names(latex_math.parse(tex))
    except latex_math.LatexMathError as exc:
        raise TexError(str(exc)) from exc


@cache
def relation(tex: str) -> list[sympy.Expr]:
    """The parts of an equality chain ``a = b = c`` (every relation ``=``, no trailing condition), by
    :func:`paper_repro.printed.latex_math.parse_relation`; :class:`TexError` on anything else."""
    from paper_repro.printed import latex_math

    try:
        rel = latex_math.parse_relation(tex)
    except latex_math.LatexMathError as exc:
        raise TexError(str(exc)) from exc
    if any(op != "=" for op in rel.ops) or getattr(rel, "conditions", None):
        raise TexError(f"not an equality chain: {rel.ops} {getattr(rel, 'conditions', '')}")
    return [_paper_names(p) for p in rel.parts]


@cache
def own_parse(tex: str) -> sympy.Expr:
    """This module's own reader (the interim one, kept for comparison with latex_math in the tests)."""
    p = _Parser(tex)
    e = p.expr()
    if p.peek() is not None:
        raise TexError(f"unread tail {p.rest()!r} of {tex[:80]!r}")
    return e


def names(expr: sympy.Basic) -> set[str]:
    """The names of the free symbols and applied functions of ``expr``."""
    out = {s.name for s in expr.free_symbols}
    out |= {f.func.__name__ for f in expr.atoms(sympy.Function) if isinstance(f, sympy.core.function.AppliedUndef)}
    return out


def half_angle_powers(expr: sympy.Expr, variables=("u", "v", "w")) -> dict[tuple[str, str], sympy.Expr]:
    """The exponents of a product of powers of ``sin(x/2)``, ``cos(x/2)`` (x among ``variables``):
    ``{("sin", "u"): 2n-i, ...}``; ``TexError`` if ``expr`` is anything else (a sum, another factor, another
    argument).  A factor that occurs twice has its exponents added.

    >>> half_angle_powers(parse(r"\\sin^{i}\\frac{w}{2}\\cos^{j}\\frac{v}{2}\\sin\\frac{w}{2}"))
    {('cos', 'v'): j, ('sin', 'w'): i + 1}
    """
    out: dict[tuple[str, str], sympy.Expr] = {}
    for base, exp in (f.as_base_exp() for f in sympy.Mul.make_args(expr)):
        if isinstance(base, (sympy.sin, sympy.cos)):
            arg = base.args[0]
            x = [v for v in variables if sympy.simplify(arg - sympy.Symbol(v) / 2) == 0]
            if len(x) != 1:
                raise TexError(f"{base} is not a function of one half angle of {variables}")
            key = ("sin" if isinstance(base, sympy.sin) else "cos", x[0])
            out[key] = out.get(key, 0) + exp
        elif base != 1:
            raise TexError(f"factor {base} is not a power of a half-angle sine or cosine")
    return dict(sorted(out.items()))


__all__ = ["TexError", "clean", "parse", "relation", "names", "half_angle_powers"]
