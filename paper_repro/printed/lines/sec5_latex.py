"""The reading of the formulas of Section sec:partition_of_unity (source lines 1907-2167) into sympy objects.

:func:`parse` and :func:`parse_relation` read with the project's one reader of the paper's mathematics,
:mod:`paper_repro.printed.latex_math`, adding two rules of Section 5's notation: a parenthesis right after a
constant ``c``, ``r``, ``g``, ``b`` is a factor (``c_{6,4}\\left( 2+..\\right)``: the shared reader appends it as
an argument list), and a row ``& =..`` that continues a chain gets the part None first.  Own readers, where the
shared one does not say what the checks need:

* :func:`listed_range` -- a listed range ``i=j+1,j+2,\\ldots,n-1`` -> ``(var, first, last)`` (sympy), refusing an
  empty item (a doubled comma), a step other than one, or a missing ``\\ldots``;
* :func:`unlabelled` -- the indexed names printed without the superscript ``\\alpha`` of the notation (the shared
  reader drops the tag without a trace), by the small recursive-descent reader of this module (``_Parser``:
  integers, ``+``/``-``, juxtaposition, ``\\frac``, powers, groups, ``\\sin``/``\\cos``/``\\tan``, greek letters,
  indexed names, ``\\overline``, ``\\sum``; anything else raises :class:`LatexMathError`);
* :func:`expand_sums` -- every ``Sum`` written out term by term.

>>> parse(r"\\frac{2\\cos\\frac{\\alpha}{2}}{\\sin ^{2}\\frac{\\alpha}{2}}")
2*cos(alpha/2)/sin(alpha/2)**2
>>> parse_relation(r"r_{2,1,0}^{\\alpha} & =c_{2,1}^{\\alpha}").parts
[r(2, 1, 0), c(2, 1)]
>>> listed_range(r"~i=j+1,j+2,\\ldots,n-1,", "i")
(i, j + 1, n - 1)
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy

GREEK = ("alpha", "beta", "gamma", "delta", "varrho", "mu", "lambda", "tau")
NAMES = ("r", "g", "b", "c", "R", "G", "B", "L")
TRIG = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan}
RELATIONS = {"=": "=", "\\neq": "!=", "\\leq": "<=", "\\geq": ">=", "<": "<", ">": ">"}
_TOKEN = re.compile(r"\\[A-Za-z]+|\d+|[A-Za-z]|[{}()\[\]^_+\-=,<>]|\S")
_IGNORED = ("\\left", "\\right", "\\displaystyle", "\\limits", "\\,", "\\;", "\\!", "\\ ")


class LatexMathError(ValueError):
    """A part of the LaTeX that the reader does not read (named in the message)."""


def _tokens(tex: str) -> list[str]:
    text = tex.replace("\\[", " ").replace("\\]", " ").replace("%", " ").replace("\\\\", " ")
    text = text.replace("&", " ").replace("~", " ")
    for w in ("\\,", "\\;", "\\!", "\\ "):
        text = text.replace(w, " ")
    out = [t for t in _TOKEN.findall(text) if t not in _IGNORED and not t.isspace()]
    return [t for t in out if t not in ("\\left", "\\right")]


@dataclass
class _Parser:
    toks: list[str]
    pos: int = 0
    unlabelled: list[str] = field(default_factory=list)

    def peek(self) -> str | None:
        return self.toks[self.pos] if self.pos < len(self.toks) else None

    def take(self, want: str | None = None) -> str:
        t = self.peek()
        if t is None or (want is not None and t != want):
            raise LatexMathError(f"expected {want or 'more'} at {' '.join(self.toks[self.pos:self.pos + 6])!r}")
        self.pos += 1
        return t

    # expr := [+-] term ([+-] term)*
    def expr(self) -> sympy.Expr:
        sign = 1
        if self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
        out = sign * self.term()
        while self.peek() in ("+", "-"):
            op = self.take()
            t = self.term()
            out = out + t if op == "+" else out - t
        return out

    def term(self) -> sympy.Expr:
        factors = [self.postfix()]
        while self.peek() is not None and self.peek() not in ("+", "-", "}", ")", "]", ",", *RELATIONS):
            factors.append(self.postfix())
        return sympy.Mul(*factors)

    def postfix(self) -> sympy.Expr:
        base = self.atom()
        while self.peek() == "^":
            self.take()
            base = base ** self.group_or_atom()
        return base

    def group(self) -> sympy.Expr:
        self.take("{")
        e = self.expr()
        self.take("}")
        return e

    def group_or_atom(self) -> sympy.Expr:
        return self.group() if self.peek() == "{" else self.atom()

    def index_list(self) -> list[sympy.Expr]:
        if self.peek() != "{":
            return [self.atom()]
        self.take("{")
        out = [self.expr()]
        while self.peek() == ",":
            self.take()
            out.append(self.expr())
        self.take("}")
        return out

    def atom(self) -> sympy.Expr:
        t = self.peek()
        if t is None:
            raise LatexMathError("expression ends early")
        if t.isdigit():
            self.take()
            return sympy.Integer(t)
        if t == "{":
            return self.group()
        if t in ("(", "["):
            self.take()
            e = self.expr()
            self.take(")" if t == "(" else "]")
            return e
        if t in ("\\frac", "\\dfrac", "\\tfrac"):
            self.take()
            num = self.group()
            return num / self.group()
        if t.startswith("\\") and t[1:] in TRIG:
            self.take()
            power = None
            if self.peek() == "^":
                self.take()
                power = self.group_or_atom()
            arg = self.postfix_arg()
            val = TRIG[t[1:]](arg)
            return val ** power if power is not None else val
        if t.startswith("\\") and t[1:] in GREEK:
            self.take()
            if self.peek() == "_":  # an indexed greek name, as \\delta_{n}
                self.take()
                return sympy.Function(t[1:])(*self.index_list())
            return sympy.Symbol(t[1:])
        if t == "\\pi":
            self.take()
            return sympy.pi
        if len(t) == 1 and t.isalpha():
            self.take()
            if self.peek() == "_" and t in NAMES:
                self.take()
                idx = self.index_list()
                if self.peek() == "^" and self.toks[self.pos + 1:self.pos + 4] == ["{", "\\alpha", "}"]:
                    self.pos += 4
                elif self.peek() == "^" and self.toks[self.pos + 1:self.pos + 2] == ["\\alpha"]:
                    self.pos += 2
                else:
                    self.unlabelled.append(f"{t}_{{{','.join(str(x) for x in idx)}}}")
                return sympy.Function(t)(*idx, *self.applied())
            args = self.applied()  # f\\left( x,y\\right): a function of a letter applied to its arguments
            return sympy.Function(t)(*args) if args else sympy.Symbol(t)
        if t == "\\overline":  # \overline{R}_{..}^{\alpha}: the normalized function, named Rbar
            self.take()
            self.take("{")
            letter = self.take()
            self.take("}")
            if letter not in ("R", "G", "B", "T") or self.peek() != "_":
                raise LatexMathError(f"unread \\overline{{{letter}}}")
            self.take()
            idx = self.index_list()
            if self.toks[self.pos:self.pos + 4] == ["^", "{", "\\alpha", "}"]:
                self.pos += 4
            else:
                self.unlabelled.append(f"{letter}bar_{{{','.join(str(x) for x in idx)}}}")
            return sympy.Function(letter + "bar")(*idx, *self.applied())
        if t == "\\sum":  # \sum_{v=lo}^{hi} body: the body is the rest of the product
            self.take()
            self.take("_")
            self.take("{")
            var = sympy.Symbol(self.take())
            self.take("=")
            lo = self.expr()
            self.take("}")
            self.take("^")
            hi = self.group_or_atom()
            return sympy.Sum(self.term(), (var, lo, hi))
        raise LatexMathError(f"unread {t!r} at {' '.join(self.toks[self.pos:self.pos + 6])!r}")

    def applied(self) -> tuple:
        """An argument list ``\\left( u,v,w\\right)`` right after an indexed name, as one final Tuple (a
        parenthesis without a top-level comma is a factor, not arguments)."""
        if self.peek() != "(":
            return ()
        save = self.pos
        self.take()
        items = [self.expr()]
        while self.peek() == ",":
            self.take()
            items.append(self.expr())
        if len(items) < 2 or self.peek() != ")":
            self.pos = save
            return ()
        self.take()
        return (sympy.Tuple(*items),)

    def postfix_arg(self) -> sympy.Expr:
        """The argument of a function: the next atom (a symbol with its numeric coefficient, as ``\\sin 2\\alpha``)."""
        if self.peek() is not None and self.peek().isdigit():
            k = sympy.Integer(self.take())
            return k * self.atom()
        return self.atom()


@dataclass
class Relation:
    parts: list
    ops: list[str]


def _run(tex: str) -> tuple[_Parser, Relation]:
    toks = _tokens(tex)
    while toks and toks[-1] in (".", ","):  # the punctuation of the sentence
        toks.pop()
    p = _Parser(toks)
    # a row of an align that continues a chain (``& =..``) has no left part: None
    parts, ops = [None if p.peek() in RELATIONS else p.expr()], []
    while p.peek() in RELATIONS:
        ops.append(RELATIONS[p.take()])
        parts.append(p.expr())
    if p.peek() is not None:
        raise LatexMathError(f"unread {' '.join(p.toks[p.pos:p.pos + 8])!r}")
    return p, Relation(parts, ops)


_CONSTANTS = ("c", "r", "g", "b")  # constants of the notation: a parenthesis after one is a factor, not arguments


def _factor_not_arguments(e):
    """``c(6, 4, Tuple(x))`` (the shared reader appends a parenthesis after an indexed name as arguments) ->
    ``c(6, 4) * x``: the univariate constants and normalizing coefficients are numbers, not functions."""
    def fix(f):
        if f.func.__name__ in _CONSTANTS and f.args and isinstance(f.args[-1], sympy.Tuple) and len(f.args[-1]) == 1:
            return sympy.Function(f.func.__name__)(*f.args[:-1]) * f.args[-1][0]
        return f

    return e.replace(lambda x: isinstance(x, sympy.core.function.AppliedUndef), fix) if e is not None else None


def _shared():
    from paper_repro.printed import latex_math

    return latex_math


def _lead(tex: str) -> tuple[str | None, str]:
    """A row of an align that continues a chain (``& =..``): its leading relation and the rest."""
    body = tex.replace("%", " ").replace("&", " ").strip()
    for token, op in sorted(RELATIONS.items(), key=lambda kv: -len(kv[0])):
        if body.startswith(token):
            return op, body[len(token):]
    return None, tex


def parse(tex: str) -> sympy.Expr:
    """One expression, read by the shared reader :func:`paper_repro.printed.latex_math.parse` (a parenthesis after
    a constant c, r, g, b is a factor)."""
    lm = _shared()
    try:
        rel = lm.parse_relation(tex)
    except lm.LatexMathError as exc:
        raise LatexMathError(str(exc)) from exc
    if rel.ops or len(rel.parts) != 1 or getattr(rel, "conditions", None):
        raise LatexMathError(f"a relation, not an expression: {tex[:60]!r}")
    return _factor_not_arguments(rel.parts[0])


def parse_relation(tex: str) -> Relation:
    """A chain of relations with every part (``a = b = c`` -> parts [a, b, c], ops ["=", "="]), read by the shared
    reader :func:`paper_repro.printed.latex_math.parse_relation`; a row ``& =b`` continuing a chain has the part
    None first; trailing conditions are refused (the checks split them off and read them themselves)."""
    lm = _shared()
    op, rest = _lead(tex)
    try:
        rel = lm.parse_relation(rest)
    except lm.LatexMathError as exc:
        raise LatexMathError(str(exc)) from exc
    if getattr(rel, "conditions", None):
        raise LatexMathError(f"conditions {rel.conditions} after the relation")
    parts = [_factor_not_arguments(p) for p in rel.parts]
    if op is not None:
        return Relation([None, *parts], [op, *rel.ops])
    return Relation(parts, list(rel.ops))


def expand_sums(e: sympy.Expr) -> sympy.Expr:
    """Every ``Sum`` with integer bounds written out term by term (inner bounds may name outer variables)."""
    def one(s: sympy.Sum) -> sympy.Expr:
        body, limits = s.function, list(s.limits)
        var, lo, hi = limits[-1]
        if not (lo.is_Integer and hi.is_Integer):
            raise LatexMathError(f"bounds {lo}, {hi} of {var} are not numbers")
        rest = sympy.Sum(body, *limits[:-1]) if limits[:-1] else body
        return sympy.Add(*[expand_sums(rest.subs(var, k)) for k in range(int(lo), int(hi) + 1)])

    return e.replace(lambda x: isinstance(x, sympy.Sum), one)


def unlabelled(tex: str) -> list[str]:
    """The indexed names of ``tex`` printed without the superscript ``\\alpha`` of the paper's notation."""
    return _run(tex)[0].unlabelled  # the own reader: the shared one drops the tag ^{\\alpha} without a trace


def listed_range(tex: str, var: str) -> tuple[sympy.Symbol, sympy.Expr, sympy.Expr]:
    """``var=a,a+1,\\ldots,b`` in ``tex`` -> (Symbol(var), a, b): the listed items are read, the step between the
    first two must be one, ``\\ldots`` must come before the last; an empty item (``,,``) is refused."""
    m = re.search(rf"(?<![A-Za-z\\]){re.escape(var)}\s*=", tex)
    if not m:
        raise LatexMathError(f"no listed range of {var!r}")
    rest = tex[m.end():]
    items: list[str] = []
    depth, cur = 0, ""
    for ch in rest:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if depth == 0 and ch == ",":
            items.append(cur)
            cur = ""
            if items and "\\ldots" in items[-1]:
                pass
            continue
        if depth < 0 or ch in "$":
            break
        cur += ch
    items.append(cur)
    items = [x.replace("%", "").strip() for x in items]
    if items and items[-1].endswith("."):
        items[-1] = items[-1][:-1].strip()
    while items and items[-1] in ("", ".", ")"):
        items.pop()
    k = next((n for n, x in enumerate(items) if x == "\\ldots"), None)
    if k is None or k + 1 >= len(items) or k < 1:
        raise LatexMathError(f"no '\\ldots' between listed items of {var!r}: {items}")
    items = items[:k + 2]
    if any(x == "" for x in items):
        raise LatexMathError(f"an empty item in the listed range of {var!r}: {items}")
    vals = [parse(x) for x in items[:k]] + [parse(items[k + 1])]
    for a, b in zip(vals[:k - 1], vals[1:k]):
        if sympy.simplify(b - a) != 1:
            raise LatexMathError(f"the listed range of {var!r} does not step by one: {items}")
    return sympy.Symbol(var), vals[0], vals[-1]


__all__ = ["LatexMathError", "Relation", "parse", "parse_relation", "listed_range", "unlabelled", "expand_sums"]
