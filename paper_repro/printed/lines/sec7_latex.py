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
