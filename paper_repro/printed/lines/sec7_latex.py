"""Small readers of the verbatim LaTeX of Section 7 (no formula is retyped: each is read from the ``verbatim`` of
its :class:`~paper_repro.printed.lines.Line`).

* :func:`relation_expression` -- a right-hand side of Example exmp:from_1_to_2 (normalizing coefficients
  ``r_{2,2,0}^{\\alpha}`` ... , ``\\sin\\frac{\\alpha}{2}``, ``\\tan\\frac{\\alpha}{2}``, ``\\sin\\alpha``,
  ``\\cos^{2}\\frac{\\alpha}{2}``) as a Python expression in the names ``r220, g220, b220, r210, g210, b210, r211,
  s, c, sinA, tanH`` and the constructor ``K`` of constants;
* :func:`combination` -- an order-elevation equation of Example exmp:degree_elevation_from_1_to_2: the left-hand
  side labels and the terms ``(weight expression in c2, s2, K; labels)``;
* :func:`conversion` -- a Bezier point ``p_{d,e,f} = sum of \\frac{a}{b} x_{2n,.,.}``: index and weighted labels;
* :func:`overline_labels`, :func:`sum_bounds`, :func:`bracket_ranges` -- labels, summation bounds and interval
  ranges of a display.

Evaluate an expression with :func:`evaluate` (builtins disabled; only the given names exist).
"""

from __future__ import annotations

import functools
import re
from fractions import Fraction

_COEF = re.compile(r"([rgb])_\{(\d),(\d),(\d)\}\s*\^\{\\alpha\s*\}")
_HALF = re.compile(r"\\frac\{\\alpha\s*\}\s*\{2\}")
_TOKEN = re.compile(r"\*\*|\d+|[A-Za-z_]\w*|[-+*/()]")
_POINT = re.compile(r"\\mathbf\{([rgbp])\}\s*_\{(\d+),(\d+),(\d+)\}")


def _implicit_products(text: str) -> str:
    """Tokens of ``text`` joined with ``*`` where LaTeX writes a product by juxtaposition; numbers become K(n)."""
    rest = _TOKEN.sub("", text)
    if rest.strip():
        raise ValueError(f"unread LaTeX left over: {rest.strip()!r}")
    toks = _TOKEN.findall(text)
    out: list[str] = []
    prev_operand = False
    for k, tok in enumerate(toks):
        operand_start = tok[0].isalnum() or tok == "("
        if prev_operand and operand_start:
            out.append("*")
        if tok.isdigit() and not (k and toks[k - 1] == "**"):
            out.append(f"K({tok})")
        else:
            out.append(tok)
        prev_operand = tok[0].isalnum() or tok == ")"
    return "".join(out)


def relation_expression(tex: str) -> str:
    """The right-hand side of one relation of Example exmp:from_1_to_2 as a Python expression."""
    t = tex.split("=", 1)[1] if "=" in tex else tex
    t = t.replace("%", " ")
    t = _COEF.sub(lambda m: f" {m.group(1)}{m.group(2)}{m.group(3)}{m.group(4)} ", t)
    t = _HALF.sub(" H ", t)
    t = re.sub(r"\\sin\s*H", " s ", t)
    t = re.sub(r"\\tan\s*H", " tanH ", t)
    t = re.sub(r"\\cos\^\{2\}\s*H", " c**2 ", t)
    t = re.sub(r"\\sin\s*\\alpha", " sinA ", t)
    t = t.replace("\\left(", "(").replace("\\right)", ")")
    t = re.sub(r"\^\{(\d+)\}", r"**\1", t)
    t = re.sub(r"\\(Red|Green|Blue|Orange)\{", " ", t)
    t = t.replace("{", " ").replace("}", " ").replace("&", " ").replace("\\\\", " ")
    if "\\" in t:
        raise ValueError(f"unread LaTeX command in {t!r}")
    return _implicit_products(t)


def weight_expression(tex: str) -> str:
    """A weight such as ``\\frac{2\\cos^{2}\\frac{\\alpha}{2}}{1+2\\cos^{2}\\frac{\\alpha}{2}}`` in c2, s2, K."""
    t = tex.replace("%", " ")
    t = re.sub(r"\\cos\^\{2\}\s*\\frac\{\\alpha\}\s*\{2\}", " c2 ", t)
    t = re.sub(r"\\sin\^\{2\}\s*\\frac\{\\alpha\}\s*\{2\}", " s2 ", t)
    t = re.sub(r"\\frac\{([^{}]*)\}\s*\{([^{}]*)\}", r" ((\1)/(\2)) ", t)
    t = t.replace("\\\\", " ").replace("&", " ").replace("=", " ").replace(",", " ")
    t = re.sub(r"\\(Red|Green|Blue|Orange)\{\s*\}", " ", t)
    t = t.strip()
    if t.startswith("+"):
        t = t[1:]
    if "\\" in t or "{" in t:
        raise ValueError(f"unread LaTeX in weight {t!r}")
    return _implicit_products(t) if t.strip() else "K(1)"


def _label(m: re.Match) -> str:
    return f"{m.group(1)}_{{{m.group(2)},{m.group(3)},{m.group(4)}}}"


_ARRAY = re.compile(r"\\left\[\s*\\begin\{array\}\s*\[c\]\{c\}%?(.*?)\\end\{array\}\s*\\right\]", re.S)
_COLOURED = re.compile(r"\\(?:Red|Green|Blue|Orange)\{\\mathbf\{([rgb])\}\s*_\{(\d+),(\d+),(\d+)\}\}")


def combination(tex: str) -> tuple[tuple[str, ...], list[tuple[str, tuple[str, ...]]]]:
    """``(left-hand labels, [(weight expression, labels), ...])`` of a printed elevation equation.

    Vector equations (``\\left[\\begin{array}...``) give 3 labels per item, the centre equation 1.
    """
    items = list(_ARRAY.finditer(tex)) if "\\begin{array}" in tex else list(_COLOURED.finditer(tex))
    labels = [tuple(_label(m) for m in _POINT.finditer(it.group(0))) for it in items]
    lhs, terms, end = labels[0], [], items[0].end()
    for it, labs in zip(items[1:], labels[1:]):
        terms.append((weight_expression(tex[end:it.start()]), labs))
        end = it.end()
    if tex[end:].strip(" \n.,\\"):
        raise ValueError(f"unread text after the last term: {tex[end:]!r}")
    return lhs, terms


_CONV = re.compile(r"(?:\\frac\{(\d+)\}\{(\d+)\})?%?\s*"
                   r"\\(?:Red|Green|Blue)\{\\mathbf\{([rgb])\}%?\s*_\{(\d+),(\d+),(\d+)\}\}")


def conversion(tex: str) -> tuple[tuple[int, int, int], list[tuple[Fraction, str]]]:
    """``((d, e, f), [(weight, control point label), ...])`` of a printed Bezier point p_{d,e,f}."""
    m = re.match(r"\\mathbf\{p\}_\{(\d+),(\d+),(\d+)\}", tex)
    if not m:
        raise ValueError(f"not a Bezier point: {tex[:40]!r}")
    idx = (int(m.group(1)), int(m.group(2)), int(m.group(3)))
    body = tex[m.end():]
    terms = [(Fraction(int(a or 1), int(b or 1)), f"{c}_{{{i},{j},{k}}}") for a, b, c, i, j, k in _CONV.findall(body)]
    if body.count("\\frac") != sum(1 for w, _ in terms if w != 1) or len(terms) != body.count("\\mathbf"):
        raise ValueError(f"unread weight or point in {tex!r}")
    return idx, terms


def overline_labels(tex: str) -> list[str]:
    """Labels ``X_{a,b,c}`` of every ``\\overline{X}_{a,b,c}`` with numeric indices, in order."""
    return [f"{m.group(1)}_{{{m.group(2)},{m.group(3)},{m.group(4)}}}" for m in
            re.finditer(r"\\overline\s*\{([RGB])\}_\{(\d+),(\d+),(\d+)\}", tex)]


def paired_points(tex: str) -> list[tuple[str, str]]:
    """``(control point label, function label)`` pairs ``\\mathbf{x}_{...}\\overline{X}_{...}`` of a patch sum."""
    pat = re.compile(r"\\mathbf\{([rgb])\}_\{(\d+),(\d+),(\d+)\}\}%?\s*\\overline\s*\{([RGB])\}_\{(\d+),(\d+),(\d+)\}")
    return [(f"{m.group(1)}_{{{m.group(2)},{m.group(3)},{m.group(4)}}}",
             f"{m.group(5)}_{{{m.group(6)},{m.group(7)},{m.group(8)}}}") for m in pat.finditer(tex)]


def sum_bounds(tex: str) -> list[tuple[str, str, str]]:
    """``(variable, lower, upper)`` of every ``\\sum\\limits_{v=lo}^{hi}`` in order (bounds as printed)."""
    return re.findall(r"\\sum\\limits_\{(\w)=([^{}]+)\}\^\{([^{}]+)\}", tex)


def bracket_ranges(tex: str) -> dict[str, tuple[str, str]]:
    """``{variable: (lower, upper)}`` of every ``v \\in \\left[lo, hi\\right]`` (bounds as printed)."""
    return {v: (lo.strip(), hi.strip()) for v, lo, hi in
            re.findall(r"([a-z])\s*\\in\s*\\left\[\s*([^,\]]+?)\s*,\s*([^\]]+?)\s*\\right\]", tex)}


def bound_value(expr: str, **env: int | Fraction):
    """Value of a printed bound such as ``2n-1-j``, ``1-x`` or ``x`` (juxtaposition is a product)."""
    return evaluate(_implicit_products(expr.replace("\\ldots", "")), K=lambda v: v, **env)


def evaluate(expr: str, **names):
    """Evaluate an expression produced by the readers above with only ``names`` defined."""
    return eval(expr, {"__builtins__": {}}, names)  # noqa: S307 - expressions come from the readers above


def _by_text(func):
    """Memoize a reader on its arguments (the text itself: a changed line is a new key, so the memo never needs
    clearing -- and it has no ``cache_clear``, so :func:`paper_repro.printed.lines.substituted` leaves it alone)."""
    memo: dict = {}

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        key = (args, tuple(sorted(kwargs.items())))
        if key not in memo:
            if len(memo) > 4096:
                memo.clear()
            memo[key] = func(*args, **kwargs)
        return memo[key]

    return wrapper


# ---------------------------------------------------------------- strict readers (issue 37: a changed line is refused)
#
# The readers below read a whole line and refuse (``ValueError``) anything they do not understand: a relation other
# than the printed one, a superscript other than ``\alpha``, an unknown word.  Signs are read, never skipped.

_COLOURS = ("Red", "Green", "Blue", "Orange")


def _group(tex: str, k: int) -> int:
    """Index just after the brace group that opens at ``tex[k] == '{'``."""
    if k >= len(tex) or tex[k] != "{":
        raise ValueError(f"expected '{{' at {tex[k:k + 20]!r}")
    depth = 0
    for m in range(k, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[m], 0)
        if depth == 0:
            return m + 1
    raise ValueError(f"unbalanced braces in {tex!r}")


def unwrap(tex: str, names: tuple[str, ...] = _COLOURS) -> str:
    """``tex`` with every ``\\Name{...}`` of ``names`` replaced by its content (colour macros print nothing)."""
    out, k = [], 0
    pat = re.compile(r"\\(" + "|".join(names) + r")(?![A-Za-z])\s*")
    while True:
        m = pat.search(tex, k)
        if not m:
            out.append(tex[k:])
            return "".join(out)
        out.append(tex[k:m.start()])
        end = _group(tex, m.end())
        out.append(unwrap(tex[m.end() + 1:end - 1], names))
        k = end


def clean(tex: str) -> str:
    """Layout removed: ``%`` line continuations, colour macros, ``\\left``/``\\right``, ``\\displaystyle``,
    ``\\limits``, alignment ``&``, ``~``, ``\\,`` and all white space.  What is left is what the line says."""
    t = re.sub(r"%[^\n]*\n?", "", tex)
    t = unwrap(t)
    t = re.sub(r"\\(?:displaystyle|limits)(?![A-Za-z])", "", t)
    t = re.sub(r"\\left(?![A-Za-z])|\\right(?![A-Za-z])", "", t)
    t = t.replace("\\,", "").replace("~", "").replace("&", "")
    t = re.sub(r"(\\[A-Za-z]+)\s+(?=[A-Za-z])", "\\1\0", t)  # a command keeps one space before a letter
    return re.sub(r"\s+", "", t).replace("\0", " ")


_IDX = r"\{(-?\d+),(-?\d+),(-?\d+)\}"


@_by_text
def to_sympy(tex: str, allowed: tuple[str, ...] = ("x", "y", "z", "n", "m", "d", "e", "f", "alpha", "i", "j")):
    """A simple printed expression (``\\alpha x``, ``1-x-y``, ``\\frac{m!}{d!e!f!}x^d y^e\\left(1-x-y\\right)^f``,
    ``3n-1``) read by the one reader (:func:`paper_repro.printed.latex_math.parse`); ``ValueError`` on anything
    unread or on a name outside ``allowed``."""
    from paper_repro.printed.latex_math import parse

    if not tex.strip():
        raise ValueError("empty expression")
    expr = parse(tex)
    unknown = {str(s) for s in expr.free_symbols} - set(allowed)
    if unknown or not hasattr(expr, "free_symbols"):
        raise ValueError(f"unknown names {sorted(unknown)} in {tex!r}")
    return expr


def strict_conversion(tex: str) -> tuple[tuple[int, int, int], list[tuple[Fraction, str]]]:
    """``((d, e, f), [(signed weight, control point label), ...])`` of ``p_{d,e,f} = w_1 x_1 + w_2 x_2 + ...``: the
    relation must be ``=``, each term an optional ``\\frac{a}{b}`` and a bold control point, joined by ``+`` or
    ``-`` (a ``-`` gives a negative weight); anything else is refused."""
    t = clean(tex).rstrip(",.")
    m = re.fullmatch(r"\\mathbf\{p\}_" + _IDX + r"=(.+)", t)
    if not m:
        raise ValueError(f"not a Bezier point equation: {tex[:60]!r}")
    idx = (int(m.group(1)), int(m.group(2)), int(m.group(3)))
    body, terms, k = m.group(4), [], 0
    term = re.compile(r"([+-]?)(?:\\frac\{(\d+)\}\{(\d+)\})?\\mathbf\{([rgb])\}_" + _IDX)
    while k < len(body):
        mt = term.match(body, k)
        if not mt or (k > 0 and not mt.group(1)):
            raise ValueError(f"unread term at {body[k:k + 30]!r}")
        w = Fraction(int(mt.group(2) or 1), int(mt.group(3) or 1)) * (-1 if mt.group(1) == "-" else 1)
        terms.append((w, f"{mt.group(4)}_{{{mt.group(5)},{mt.group(6)},{mt.group(7)}}}"))
        k = mt.end()
    return idx, terms


def signed_overline_terms(body: str) -> list[tuple[int, str]]:
    """``[(sign, label), ...]`` of a cleaned sum ``\\overline{X}_{a,b,c}^{\\alpha}+...`` with numeric indices; every
    superscript must be ``\\alpha``."""
    out, k = [], 0
    term = re.compile(r"([+-]?)\\overline\{([RGB])\}_" + _IDX + r"\^\{\\alpha\}")
    while k < len(body):
        m = term.match(body, k)
        if not m or (k > 0 and not m.group(1)):
            raise ValueError(f"unread term at {body[k:k + 40]!r}")
        out.append((-1 if m.group(1) == "-" else 1, f"{m.group(2)}_{{{m.group(3)},{m.group(4)},{m.group(5)}}}"))
        k = m.end()
    return out


def square_of_unity(tex: str) -> tuple[tuple[str, str], list[tuple[int, str]], str]:
    """``((base, exponent) of the left side, signed terms of the sum, exponent of the right side)`` of
    ``1^{2}=\\left(sum\\right)^{2}``."""
    m = re.fullmatch(r"(\d+)\^\{(\d+)\}=\((.*)\)\^\{(\d+)\}", clean(tex))
    if not m:
        raise ValueError(f"not 'c^k = (sum)^k': {tex[:60]!r}")
    return (m.group(1), m.group(2)), signed_overline_terms(m.group(3)), m.group(4)


_SUMS = re.compile(r"\\sum_\{(\w)=([^{}]+)\}\^\{([^{}]+)\}\\sum_\{(\w)=([^{}]+)\}\^\{([^{}]+)\}"
                   r"\\overline\{([RGB])\}_\{([^{}]+)\}\^\{\\alpha\}")


def unity_product(tex: str) -> dict:
    """The printed ``1^{n+1} = (first factor) . (second factor)``: ``{"lhs": (base, exponent), "first": [terms],
    "second": [(sign, label)]}``; a first-factor term is ``(sign, colour, subscript)`` for a single function or
    ``(sign, colour, subscript, (outer var, lo, hi), (inner var, lo, hi))`` for a printed double sum."""
    t = re.sub(r"\{(\\sum_\{[^{}]*\}\^\{[^{}]*\})\}", r"\1", clean(tex).replace("\\\\", ""))
    m = re.fullmatch(r"(\d+)\^\{([^{}]+)\}=\((.*)\)\\cdot\((.*)\)", t)
    if not m:
        raise ValueError(f"not 'c^k = (..) . (..)': {tex[:60]!r}")
    first, k, body = [], 0, m.group(3)
    single = re.compile(r"([+-]?)\\overline\{([RGB])\}_\{([^{}]+)\}\^\{\\alpha\}")
    while k < len(body):
        sign = body[k] if body[k] in "+-" else ""
        if k > 0 and not sign:
            raise ValueError(f"unread term at {body[k:k + 40]!r}")
        ms = _SUMS.match(body, k + len(sign))
        if ms:
            first.append((-1 if sign == "-" else 1, ms.group(7), ms.group(8), ms.group(1, 2, 3), ms.group(4, 5, 6)))
            k = ms.end()
            continue
        mo = single.match(body, k)
        if not mo:
            raise ValueError(f"unread term at {body[k:k + 40]!r}")
        first.append((-1 if mo.group(1) == "-" else 1, mo.group(2), mo.group(3)))
        k = mo.end()
    return {"lhs": (m.group(1), m.group(2)), "first": first, "second": signed_overline_terms(m.group(4))}


def patch_product(tex: str) -> dict:
    """The printed ``\\mathbf{s}_{1}^{\\alpha}\\cdot1 = (sum of points times functions) . (sum of functions)``:
    ``{"patch": order, "one": "1", "pairs": [(sign, point, function)], "second": [(sign, label)]}``."""
    t = clean(tex).replace("\\\\", "")
    m = re.fullmatch(r"\\mathbf\{s\}_\{(\d+)\}\^\{\\alpha\}\\cdot(\d+)=\((.*)\)\\cdot\((.*)\)", t)
    if not m:
        raise ValueError(f"not 's^alpha . 1 = (..) . (..)': {tex[:60]!r}")
    pairs, k, body = [], 0, m.group(3)
    term = re.compile(r"([+-]?)\\mathbf\{([rgb])\}_" + _IDX + r"\\overline\{([RGB])\}_" + _IDX + r"\^\{\\alpha\}")
    while k < len(body):
        mt = term.match(body, k)
        if not mt or (k > 0 and not mt.group(1)):
            raise ValueError(f"unread term at {body[k:k + 40]!r}")
        pairs.append((-1 if mt.group(1) == "-" else 1, f"{mt.group(2)}_{{{mt.group(3)},{mt.group(4)},{mt.group(5)}}}",
                      f"{mt.group(6)}_{{{mt.group(7)},{mt.group(8)},{mt.group(9)}}}"))
        k = mt.end()
    return {"patch": int(m.group(1)), "one": m.group(2), "pairs": pairs, "second": signed_overline_terms(m.group(4))}


def parametrization_row(tex: str) -> tuple[str, tuple[str, ...], object, tuple]:
    """One row ``u\\left(x,y\\right) & = & \\alpha x, & x \\in \\left[0, 1\\right]`` (or ``..., & z = 1-x-y``):
    ``(name, arguments, right-hand side (sympy), condition)``; the condition is ``("in", var, lo, hi)`` (bounds as
    printed) or ``("=", var, sympy expression)``.  The relation must be ``=``."""
    t = clean(tex)
    m = re.fullmatch(r"([a-z])\(([a-z](?:,[a-z])*)\)=([^,]+),(.+)", t)
    if not m:
        raise ValueError(f"not a parametrization row 'f(x,y) = expr, condition': {tex!r}")
    rhs = to_sympy(m.group(3))
    cond = m.group(4)
    mi = re.fullmatch(r"([a-z])\\in\[([^,\]]+),([^\]]+)\]", cond)
    me = re.fullmatch(r"([a-z])=([^=]+)", cond)
    if mi:
        return m.group(1), tuple(m.group(2).split(",")), rhs, ("in", mi.group(1), mi.group(2), mi.group(3))
    if me:
        return m.group(1), tuple(m.group(2).split(",")), rhs, ("=", me.group(1), to_sympy(me.group(2)))
    raise ValueError(f"unread condition {cond!r}")


def strict_ranges(tex: str) -> dict[str, tuple[str, str]]:
    """``{variable: (lower, upper)}`` of a text whose every math part is ``v\\in\\left[lo,hi\\right]`` (bounds as
    printed); any other math part (``\\notin``, a relation) is refused."""
    parts = re.findall(r"\$([^$]*)\$", tex)
    if not parts:
        raise ValueError(f"no range in {tex!r}")
    out = {}
    for p in parts:
        m = re.fullmatch(r"([a-z])\\in\[([^,\]]+),([^\]]+)\]", clean(p))
        if not m:
            raise ValueError(f"not 'v in [lo, hi]': {p!r}")
        out[m.group(1)] = (m.group(2), m.group(3))
    return out


def progression(items: list[str], **env) -> list[int]:
    """The values of a printed list ``a, b, \\ldots, c`` (the step is b - a; ``a, \\ldots, c`` has step 1)."""
    if len(items) < 2 or items[-2] != "\\ldots":
        raise ValueError(f"not a list 'a, b, ..., c': {items!r}")
    first, last = bound_value(items[0], **env), bound_value(items[-1], **env)
    step = bound_value(items[1], **env) - first if len(items) == 4 else 1
    if len(items) not in (3, 4) or step <= 0 or last < first:
        raise ValueError(f"unread list {items!r} (an empty list a, ..., c with c < a is refused)")
    return list(range(first, last + 1, step))


def listed_values(tex: str, var: str, **env) -> list[int]:
    """Values of ``$var=a,b,\\ldots,c$`` in ``tex`` (exactly one such part)."""
    found = [clean(p) for p in re.findall(r"\$([^$]*)\$", tex) if clean(p).startswith(var + "=")]
    if len(found) != 1:
        raise ValueError(f"expected one '{var}=a,b,...,c' in {tex!r}")
    return progression(found[0][len(var) + 1:].split(","), **env)


ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6}
DEGREE_WORDS = {"linear": 1, "quadratic": 2, "cubic": 3, "quartic": 4, "quintic": 5, "sextic": 6, "septic": 7,
                "octic": 8, "nonic": 9}


def word_list(text: str, vocabulary: dict[str, int], followed_by: str) -> list[int]:
    """Values of the words of a list ``w1, w2 and w3`` (or ``w1 and w2``) right before ``followed_by``; every word
    must be in ``vocabulary``, and a word listed twice is refused."""
    text = re.sub(r"\s+", " ", text)
    m = re.search(r"((?:[a-z]+, )*[a-z]+ and [a-z]+) " + re.escape(followed_by), text)
    if not m:
        raise ValueError(f"no list before {followed_by!r}")
    words = re.split(r", | and ", m.group(1))
    if any(w not in vocabulary for w in words) or len(set(words)) != len(words):
        raise ValueError(f"unread list {words!r}")
    return [vocabulary[w] for w in words]


def alpha_limit(text: str):
    """The value alpha tends to in ``$\\alpha \\to v$`` (exactly one such part; ``\\rightarrow`` too)."""
    found = re.findall(r"\$\s*\\alpha\s*\\(?:to|rightarrow)\s*([^$]+)\$", text)
    if len(found) != 1:
        raise ValueError(f"expected one '$\\alpha \\to v$' in {text!r}")
    return to_sympy(found[0], allowed=())


# ------------------------------------------------------- through the one reader (paper_repro.printed.latex_math)

@_by_text
def math_expr(tex: str):
    """``tex`` read by :func:`paper_repro.printed.latex_math.parse` (a sympy expression)."""
    from paper_repro.printed.latex_math import parse

    return parse(tex)


@_by_text
def math_relation(tex: str, ops: tuple[str, ...] = ("=",)):
    """The parts of the relation ``tex`` (:func:`paper_repro.printed.latex_math.parse_relation`); its relation
    operators must be ``ops`` (a changed relation, e.g. ``\\neq``, is refused)."""
    from paper_repro.printed.latex_math import parse_relation

    rel = parse_relation(tex)
    if tuple(rel.ops) != tuple(ops):
        raise ValueError(f"relation {rel.ops}, expected {list(ops)}")
    return rel


def evaluate_sympy(expr, K, values: dict, squares: dict | None = None):
    """Value of a parsed expression in the arithmetic of ``K`` (a constructor of constants: ``fmpq``,
    ``RatFunc.const``, an mpoly constant): ``values`` maps sympy atoms (``r(2, 2, 0)``, ``sin(alpha/2)``,
    ``tan(alpha/2)``, ...) to values; ``squares`` maps an atom whose even powers only occur (``cos(alpha/2)``) to the
    value of its square.  Sums, products and integer powers only; anything else raises ``ValueError``."""
    import sympy as sp

    squares = squares or {}

    def ev(e):
        if e in values:
            return values[e]
        if isinstance(e, sp.Integer):
            return K(int(e))
        if isinstance(e, sp.Rational):
            return K(int(e.p)) / K(int(e.q))
        if isinstance(e, sp.Add):
            out = ev(e.args[0])
            for a in e.args[1:]:
                out = out + ev(a)
            return out
        if isinstance(e, sp.Mul):
            out = ev(e.args[0])
            for a in e.args[1:]:
                out = out * ev(a)
            return out
        if isinstance(e, sp.Pow) and isinstance(e.exp, sp.Integer):
            k = int(e.exp)
            if e.base in squares and k % 2 == 0:
                base, k = squares[e.base], k // 2
            else:
                base = ev(e.base)
            if k >= 0:
                out = K(1)
                for _ in range(k):
                    out = out * base
                return out
            out = K(1)
            for _ in range(-k):
                out = out / base
            return out
        raise ValueError(f"cannot evaluate {e!r}")

    return ev(expr)


def linear_terms(expr) -> dict:
    """``{atom: coefficient}`` of an expression linear in applied names (``r_vec(6, 5, 0)``); ``ValueError`` if it is
    not linear in them (a product of two points, a point in a denominator)."""
    import sympy as sp
    from sympy.core.function import AppliedUndef

    e = sp.expand(expr)
    atoms = sorted(e.atoms(AppliedUndef), key=str)
    coefs = {a: sp.expand(e.diff(a)) for a in atoms}
    if any(c.atoms(AppliedUndef) for c in coefs.values()) or sp.expand(e - sum(c * a for a, c in coefs.items())) != 0:
        raise ValueError(f"not a linear combination of points: {expr}")
    return coefs


def point_label(atom) -> str:
    """``r_{6,5,0}`` of the parsed ``r_vec(6, 5, 0)``."""
    name = atom.func.__name__
    if not name.endswith("_vec") or len(atom.args) != 3:
        raise ValueError(f"not a control point: {atom}")
    return f"{name[:-4]}_{{{','.join(str(int(a)) for a in atom.args)}}}"


@_by_text
def math_conversion(tex: str) -> tuple[tuple[int, int, int], dict[str, Fraction]]:
    """``((d, e, f), {control point: weight})`` of a printed Bezier point ``p_{d,e,f} = sum w x``, read by the one
    reader (relation ``=``; weights rational; signs as printed)."""
    import sympy as sp

    lhs, rhs = math_relation(tex).parts
    if getattr(lhs.func, "__name__", "") != "p_vec":
        raise ValueError(f"not a Bezier point: {lhs}")
    out = {}
    for atom, c in linear_terms(rhs).items():
        if not isinstance(c, sp.Rational):
            raise ValueError(f"weight {c} is not a rational number")
        out[point_label(atom)] = Fraction(int(c.p), int(c.q))
    return tuple(int(a) for a in lhs.args), out


@_by_text
def math_elevation(tex: str) -> list[tuple[str, dict]]:
    """``[(order-2 point, {order-1 point: weight expression (sympy)}), ...]`` of a printed elevation equation (a
    vector equation gives its three rows, the centre one), read by the one reader."""
    import sympy as sp

    lhs, rhs = math_relation(tex).parts
    rows = list(zip(lhs, rhs)) if isinstance(lhs, sp.MatrixBase) else [(lhs, rhs)]
    return [(point_label(left), {point_label(a): c for a, c in linear_terms(right).items()}) for left, right in rows]
