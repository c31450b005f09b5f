"""A small reader of the LaTeX of Section sec:coincidence (source lines 1414-1906) into sympy objects.

Stop-gap until :mod:`paper_repro.printed.latex_math` lands (issue 37, item 1): it reads the notation of the
coincidence section only, and refuses (``TexError``) anything it does not know, naming the unread part, so that a
blank or garbled transcription fails its check instead of being read charitably.

What it reads: numbers, single-letter variables (a run of letters such as ``za`` or ``ru`` is a product of letters,
as in the paper's juxtaposition), letters with a subscript (``r_{1}`` -> ``r1``, ``k_{4}`` -> ``k4``), ``\\alpha``,
``\\frac``/``\\dfrac``, ``\\dbinom``/``\\binom``, ``\\sin``/``\\cos`` with an optional power (``\\sin^{m}\\frac{t}{2}``
is ``sin(t/2)**m``) and argument (a parenthesised group, or the next atom), powers ``^{..}``, ``\\cdot``,
``\\sum\\limits_{k=a}^{b}`` (a sympy ``Sum`` over the following product), ``\\min\\left\\{..\\right\\}``,
``\\underset{..}{\\underbrace{..}}`` (the braced part), and the signs ``\\mp``/``\\pm`` as ``-S``/``+S`` with the
symbol :data:`PM` (``S = 1``: upper sign, ``S = -1``: lower sign).  Ignored: ``%``, ``&``, ``\\left``/``\\right``,
``\\displaystyle``, ``\\limits``, spacing, a trailing ``,``/``.``/``\\\\``.

>>> parse(r"\\sin\\left( z\\mp r_{1}\\right) ")
-sin(S*r1 - z)
>>> parse(r"\\dfrac{1}{2^{m}}\\dbinom{m}{\\frac{m}{2}}")
binomial(m, m/2)/2**m
>>> parse(r"\\sin^{2}\\frac{u}{2}")
sin(u/2)**2
>>> chain(r"a+b & = & z,")
[a + b, z]
"""

from __future__ import annotations

import re

import sympy as sp

PM = sp.Symbol("S")  # the sign of \mp / \pm: +1 for the upper sign, -1 for the lower one
ALPHA = sp.Symbol("alpha")
_GREEK = {"alpha": ALPHA}


class TexError(ValueError):
    """A part of the LaTeX the reader does not know."""


_TOKEN = re.compile(r"\s*(\\[A-Za-z]+|\\[{}\[\]()|,;!]|\d+|[A-Za-z]|[-+*/^_(){}\[\]=<>,:.|&'])")
_DROP = ("\\displaystyle", "\\limits", "\\left", "\\right", "\\text", "\\quad", "\\qquad", "\\,", "\\;", "\\!")


def tokens(tex: str) -> list[str]:
    text = tex.replace("%", " ").replace("~", " ").replace("\\\\", " ")
    out, k = [], 0
    while k < len(text):
        if text[k].isspace():
            k += 1
            continue
        m = _TOKEN.match(text, k)
        if not m:
            raise TexError(f"unread character {text[k:k + 12]!r}")
        tok = m.group(1)
        k = m.end()
        if tok in _DROP:
            continue
        if tok == "&":
            continue
        out.append(tok)
    return _unwrap_sums(out)


def _close(toks: list[str], k: int) -> int:
    """Index of the brace closing the ``{`` at ``k``."""
    depth = 0
    for j in range(k, len(toks)):
        depth += {"{": 1, "}": -1}.get(toks[j], 0)
        if depth == 0:
            return j
    raise TexError("unbalanced braces")


def _unwrap_sums(toks: list[str]) -> list[str]:
    """``{\\sum_{k=a}^{b}} body`` (the paper's ``{\\displaystyle\\sum\\limits..}``) -> ``\\sum_{k=a}^{b} body``."""
    k = 0
    while k < len(toks) - 3:
        if toks[k] == "{" and toks[k + 1] == "\\sum" and toks[k + 2] == "_" and toks[k + 3] == "{":
            end = _close(toks, k)
            lo_end = _close(toks, k + 3)
            if lo_end + 2 < len(toks) and toks[lo_end + 1] == "^" and toks[lo_end + 2] == "{" and \
                    _close(toks, lo_end + 2) == end - 1:
                toks = toks[:k] + toks[k + 1:end] + toks[end + 1:]
        k += 1
    return toks


class _Parser:
    def __init__(self, toks: list[str]):
        self.t = toks
        self.k = 0

    def peek(self, off: int = 0) -> str | None:
        j = self.k + off
        return self.t[j] if j < len(self.t) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise TexError(f"expected {want!r}, found {tok!r} at token {self.k}")
        self.k += 1
        return tok

    # expr := ['+'|'-'|pm] term { ('+'|'-'|pm) term }
    def expr(self) -> sp.Expr:
        total = sp.Integer(0)
        sign: sp.Expr = sp.Integer(1)
        first = True
        while True:
            tok = self.peek()
            if tok in ("+", "-", "\\mp", "\\pm"):
                self.take()
                sign = {"+": 1, "-": -1, "\\mp": -PM, "\\pm": PM}[tok]
            elif not first:
                return total
            if not self.starts_factor():
                if first and tok is None:
                    raise TexError("empty expression")
                raise TexError(f"unread {self.peek()!r} at token {self.k}")
            total += sign * self.term()
            sign = sp.Integer(1)
            first = False

    def starts_factor(self) -> bool:
        tok = self.peek()
        if tok is None:
            return False
        if tok in ("(", "[", "{") or tok.isdigit() or (len(tok) == 1 and tok.isalpha()):
            return True
        return tok in ("\\frac", "\\dfrac", "\\tfrac", "\\binom", "\\dbinom", "\\sin", "\\cos", "\\sum", "\\min",
                       "\\max", "\\underset", "\\underbrace", "\\{", "\\dim", "\\delta") or tok[1:] in _GREEK

    # term := factor { ['\cdot'|'*'|'/'] factor }
    def term(self) -> sp.Expr:
        out = self.power()
        while True:
            tok = self.peek()
            if tok in ("\\cdot", "*"):
                self.take()
                out *= self.power()
            elif tok == "/":
                self.take()
                out /= self.power()
            elif self.starts_factor():
                if tok == "\\sum":
                    out *= self.power()
                    return out
                out *= self.power()
            else:
                return out

    def power(self) -> sp.Expr:
        base = self.atom()
        if self.peek() == "^":
            self.take()
            base = base ** self.group()
        return base

    def group(self) -> sp.Expr:
        """A braced group, or a single digit/letter (``2^m``)."""
        if self.peek() == "{":
            self.take("{")
            e = self.expr()
            self.take("}")
            return e
        tok = self.take()
        if tok.isdigit():
            return sp.Integer(tok[0]) if len(tok) > 1 else sp.Integer(tok)
        if len(tok) == 1 and tok.isalpha():
            return sp.Symbol(tok)
        raise TexError(f"unread group {tok!r}")

    def atom(self) -> sp.Expr:
        tok = self.take()
        if tok.isdigit():
            return sp.Integer(tok)
        if len(tok) == 1 and tok.isalpha():
            name = tok
            if self.peek() == "_" and self.peek(1) == "{":
                self.take("_")
                self.take("{")
                sub = []
                while self.peek() != "}":
                    sub.append(self.take())
                self.take("}")
                if not all(s.isalnum() for s in sub):
                    raise TexError(f"unread subscript {''.join(sub)!r}")
                name += "".join(sub)
            return sp.Symbol(name)
        if tok in ("(", "["):
            e = self.expr()
            self.take(")" if tok == "(" else "]")
            return e
        if tok == "{":
            e = self.expr()
            self.take("}")
            return e
        if tok in ("\\frac", "\\dfrac", "\\tfrac"):
            a = self.group()
            b = self.group()
            return a / b
        if tok in ("\\binom", "\\dbinom"):
            a = self.group()
            b = self.group()
            return sp.binomial(a, b)
        if tok in ("\\sin", "\\cos"):
            f = sp.sin if tok == "\\sin" else sp.cos
            p = None
            if self.peek() == "^":
                self.take()
                p = self.group()
            if self.peek() in ("(", "["):
                arg = self.atom()
            else:  # the next atom with its numeric coefficient: \sin\frac{u}{2}, \cos x, \sin 2x
                arg = self.atom()
                while self.peek() is not None and (len(self.peek()) == 1 and self.peek().isalpha()):
                    arg *= self.atom()
            out = f(arg)
            return out if p is None else out ** p
        if tok == "\\sum":
            self.take("_")
            self.take("{")
            var = sp.Symbol(self.take())
            self.take("=")
            lo = self.expr()
            self.take("}")
            self.take("^")
            hi = self.group()
            body = self.term()
            return sp.Sum(body, (var, lo, hi))
        if tok in ("\\min", "\\max"):
            self.take("\\{")
            items = [self.expr()]
            while self.peek() == ",":
                self.take(",")
                items.append(self.expr())
            self.take("\\}")
            return (sp.Min if tok == "\\min" else sp.Max)(*items)
        if tok == "\\underset":
            self.take("{")
            depth = 1
            while depth:
                t = self.take()
                depth += {"{": 1, "}": -1}.get(t, 0)
            return self.group()
        if tok == "\\underbrace":
            return self.group()
        if tok == "\\dim":  # \dim\mathcal{V}_{n}^{\alpha} -> dim_V(n)
            self.take("\\mathcal")
            self.take("{")
            name = self.take()
            self.take("}")
            self.take("_")
            sub = self.group()
            if self.peek() == "^":
                self.take("^")
                self.take("{")
                self.take("\\alpha")
                self.take("}")
            return sp.Function(f"dim_{name}")(sub)
        if tok == "\\delta":  # \delta_{n} -> delta(n)
            self.take("_")
            return sp.Function("delta")(self.group())
        if tok[1:] in _GREEK:
            return _GREEK[tok[1:]]
        raise TexError(f"unread {tok!r} at token {self.k - 1}")


def _own_parse(tex: str) -> sp.Expr:
    """One expression (the whole ``tex`` must be read, apart from a trailing ``,``/``.``), by this module's reader."""
    p = _Parser(_strip_end(tokens(tex)))
    e = p.expr()
    if p.peek() is not None:
        raise TexError(f"unread tail {' '.join(p.t[p.k:p.k + 6])!r}")
    return e


def _strip_end(toks: list[str]) -> list[str]:
    while toks and toks[-1] in (",", "."):
        toks = toks[:-1]
    if not toks:
        raise TexError("empty")
    return toks


def _own_chain(tex: str, rel: str = "=") -> list[sp.Expr]:
    """The parts of a chain ``a = b = c`` (``rel`` the relation token; the ``&`` of an alignment ignored).
    ``\\dim\\mathcal{V}_{n}^{\\alpha}`` reads as ``dim_V(n)``, ``\\delta_{n}`` as ``delta(n)``.

    >>> _own_chain(r"\\dim\\mathcal{V}_{n}^{\\alpha}=\\dim\\mathcal{V}_{n-1}^{\\alpha}+6n")
    [dim_V(n), 6*n + dim_V(n - 1)]
    """
    toks = _strip_end(tokens(tex))
    parts: list[list[str]] = [[]]
    depth = 0
    for t in toks:
        if t in ("(", "[", "{", "\\{"):
            depth += 1
        elif t in (")", "]", "}", "\\}"):
            depth -= 1
        if t == rel and depth == 0:
            parts.append([])
        else:
            parts[-1].append(t)
    out = []
    for part in parts:
        if not part:
            continue
        p = _Parser(part)
        out.append(p.expr())
        if p.peek() is not None:
            raise TexError(f"unread tail {' '.join(p.t[p.k:p.k + 6])!r}")
    return out


_INDEXED = {"r", "g", "b", "k", "s"}  # r_{1} -> r1, ..., s_{4} -> s4 (names of this section, plain symbols here)


def from_latex_math(e):
    """An expression of :mod:`paper_repro.printed.latex_math` in this module's conventions: ``r(1)`` -> ``r1`` (the
    section's subscripted letters are plain symbols), ``dim(Vcal(n))`` -> ``dim_V(n)``, ``dim(Tcal(2n))`` ->
    ``dim_T(2n)``, the sign ``pm`` -> :data:`PM`."""
    from sympy.core.function import AppliedUndef

    from paper_repro.printed import latex_math as lm

    def conv(f):
        name = f.func.__name__
        if name == "dim" and len(f.args) == 1 and isinstance(f.args[0], AppliedUndef) and \
                f.args[0].func.__name__ in ("Vcal", "Tcal") and len(f.args[0].args) == 1:
            return sp.Function(f"dim_{f.args[0].func.__name__[0]}")(f.args[0].args[0])
        if name in _INDEXED and len(f.args) == 1 and f.args[0].is_Integer:
            return sp.Symbol(f"{name}{f.args[0]}")
        return f

    out = e.replace(lambda x: isinstance(x, AppliedUndef), conv)
    return out.subs(lm.PM, PM)


def parse(tex: str) -> sp.Expr:
    """One expression: read by :func:`paper_repro.printed.latex_math.parse` (the project's reader of the paper's
    notation) and put into this module's conventions (:func:`from_latex_math`); only what that reader refuses and
    this one knows (``\\min``, ``\\underset``/``\\underbrace``, the ``\\dim`` of a prose line) is read by this
    module's own grammar, which refuses the rest (``TexError``)."""
    from paper_repro.printed import latex_math as lm

    try:
        return from_latex_math(lm.parse(tex.strip().rstrip(",.").strip()))
    except lm.LatexMathError as exc:
        if not re.search(r"\\(min|underset|underbrace|max)\b", tex):
            raise TexError(str(exc)) from exc
    return _own_parse(tex)


def chain(tex: str, rel: str = "=") -> list[sp.Expr]:
    """The parts of a chain ``a = b = c`` (the ``&`` of an alignment ignored), read by
    :func:`paper_repro.printed.latex_math.parse_relation` (every relation must be ``=``, no trailing condition);
    ``\\min``/``\\underbrace`` lines by this module's grammar (:func:`_own_chain`).  ``\\dim\\mathcal{V}_{n}^{\\alpha}``
    reads as ``dim_V(n)``, ``\\delta_{n}`` as ``delta(n)``.

    >>> chain(r"\\dim\\mathcal{V}_{n}^{\\alpha}=\\dim\\mathcal{V}_{n-1}^{\\alpha}+6n")
    [dim_V(n), 6*n + dim_V(n - 1)]
    """
    from paper_repro.printed import latex_math as lm

    lead = re.match(r"[\s&%]*(\\neq|\\leq|\\geq|\\ne\b|<|>|\\sim|\\nsim|\\in\b|\\notin)", tex)
    if lead:  # a continued chain starts with its relation: it must be '='
        raise TexError(f"the chain continues with {lead.group(1)}, not '='")
    if rel == "=" and not re.search(r"\\(min|underset|underbrace|max)\b", tex):
        try:
            r = lm.parse_relation(tex)
        except lm.LatexMathError as exc:
            raise TexError(str(exc)) from exc
        if any(op != "=" for op in r.ops) or r.conditions:
            raise TexError(f"not a chain of '=': {r.ops}")
        return [from_latex_math(x) for x in r.parts]
    return _own_chain(tex, rel)


__all__ = ["PM", "ALPHA", "TexError", "tokens", "parse", "chain", "from_latex_math"]
