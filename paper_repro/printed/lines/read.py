"""Readers of index sets, ranges and right-hand sides in the verbatim LaTeX of a
:class:`~paper_repro.printed.lines.Line`.

A line check reads what it checks from the transcription with these (issue 31: a check that retypes the printed
index set tests its own copy, not the paper), and the checks' tests feed them a deliberately wrong transcription.
Bounds are returned as printed (strings) and evaluated with :func:`bound`.

>>> index_set(r"\\left\\{ R_{2n,2n-i,j} \\right\\} _{j=0,i=j}^{n,2n-j}")
(('j', '0', 'n'), ('i', 'j', '2n-j'))
>>> listed_range(r"\\gamma_{2n,2n-i,0}^{\\prime}=0,~i=1,2,\\ldots,2n.", "i")
('1', '2n')
>>> listed_range(r"=0,~i=r+1,r+2,\\ldots,2n-\\left( r+1\\right) ,", "i")
('r+1', '2n-(r+1)')
>>> bound("2n-1-j", n=3, j=1)
4
"""

from __future__ import annotations

import re

from paper_repro.printed.lines.sec7_latex import bound_value

_INDEX_SET = re.compile(r"\\right\\\}\s*_\{\s*(\w)\s*=\s*([^,{}]+?)\s*,\s*(\w)\s*=\s*([^{}]+?)\s*\}\s*%?\s*"
                        r"\^\{\s*([^,{}]+?)\s*,\s*([^{}]+?)\s*\}")


def index_set(tex: str) -> tuple[tuple[str, str, str], tuple[str, str, str]]:
    """``((outer, lo, hi), (inner, lo, hi))`` of the last double index set ``\\right\\} _{j=a,i=b}^{c,d}`` of ``tex``
    (``ValueError`` if there is none)."""
    found = _INDEX_SET.findall(tex)
    if not found:
        raise ValueError(f"no double index set _{{j=..,i=..}}^{{..,..}} in {tex[:60]!r}")
    o, olo, ilo_var, ilo, ohi, ihi = found[-1]
    return (o, olo, ohi), (ilo_var, ilo, ihi)


def listed_range(tex: str, var: str) -> tuple[str, str]:
    """``(first, last)`` of a listed range ``var=a,b,\\ldots,c`` (or ``var=a,\\ldots,c``) in ``tex``."""
    tex = re.sub(r"\s*\\right\)", ")", re.sub(r"\\left\(\s*", "(", tex))
    m = re.search(rf"(?<![\w\\]){var}\s*=\s*([^,=]+?)\s*,(?:\s*[^,=]+?\s*,)?\s*\\ldots\s*,\s*([^,.\s$]+)", tex)
    if not m:
        raise ValueError(f"no listed range {var}=a,...,b in {tex[:60]!r}")
    return m.group(1).strip(), m.group(2).strip()


def interval(tex: str, var: str) -> tuple[str, str]:
    """``(lo, hi)`` of ``var\\in\\left[ lo,hi\\right]`` in ``tex``."""
    m = re.search(rf"{var}\s*\\in\s*\\left\[\s*([^,\]]+?)\s*,\s*([^\]]+?)\s*\\right\]", tex)
    if not m:
        raise ValueError(f"no interval {var} in [lo, hi] in {tex[:60]!r}")
    return m.group(1).strip(), m.group(2).strip()


def right_hand_side(tex: str, before: str = r",~\\forall") -> str:
    """The text after the last ``=`` that precedes ``before`` (e.g. the ``0`` of ``... =0,~\\forall x``)."""
    head = re.split(before, tex)[0]
    if "=" not in head:
        raise ValueError(f"no '=' before {before!r} in {tex[:60]!r}")
    return head.rsplit("=", 1)[1].strip(" %~")


_SUM = re.compile(r"\\sum(?:\\limits)?\s*_\{(\w)=([^{}]+?)\}\s*%?\s*\^\{([^{}]+?)\}")
_TERM = re.compile(r"\\(rho|gamma|beta)_\{2n,([^{}]+?),([^{}]+?)\}\s*%?\s*(?:\\overline\{)?([RGB])\}?"
                   r"_\{2n,([^{}]+?),([^{}]+?)\}")
_RATIONAL_TERM = re.compile(r"\\(rho|gamma|beta)_\{2n,([^{}]+?),([^{}]+?)\}\s*%?\s*\\mathbf\{([rgb])\}"
                            r"_\{2n,([^{}]+?),([^{}]+?)\}\s*\\dfrac\{\\overline\{([RGB])\}_\{2n,([^{}]+?),([^{}]+?)\}")
_CONSTANT_SETS = re.compile(r"\\left\\\{\s*\\(rho|gamma|beta)_\{2n,2n-i,j\}\s*\\right\\\}\s*"
                            r"_\{j=([^,{}]+),i=([^{}]+)\}\s*%?\s*\^\{([^,{}]+),([^{}]+)\}")
_POINT_TERM = re.compile(r"\\mathbf\{([rgb])\}_\{2n,([^{}]+?),([^{}]+?)\}\s*%?\s*"
                         r"\\overline\{([RGB])\}_\{2n,([^{}]+?),([^{}]+?)\}")
_COLOUR_OF = {"rho": "R", "gamma": "G", "beta": "B", "r": "R", "g": "G", "b": "B"}


_BARE_TERM = re.compile(r"\\(rho|gamma|beta)_\{2n,([^{}]+?),([^{}]+?)\}")
_NORMALIZING_TERM = re.compile(r"(?<![\\\w])([rgb])_\{2n,([^{}]+?),([^{}]+?)\}\^\{\\alpha\s*\}\s*%?\s*"
                               r"([RGB])_\{2n,([^{}]+?),([^{}]+?)\}")


def sum_terms(tex: str, points: bool = False, rational: bool = False, bare: bool = False, normalizing: bool = False
              ) -> list[tuple[list[tuple[str, str, str]], str, str, str]]:
    """The terms ``constant_{2n,a,b} X_{2n,a,b}`` of a printed linear combination, each with the sums written
    before it (since the previous term): ``[([(var, lo, hi), ...], colour, first index, level), ...]`` as printed.
    A term whose constant and function disagree (colour or indices) raises ``ValueError``.  With ``points`` the terms
    are ``\\mathbf{x}_{2n,a,b}\\overline{X}_{2n,a,b}`` (control point times normalized function, a patch); with
    ``rational`` ``\\rho_{2n,a,b}\\mathbf{r}_{2n,a,b}\\dfrac{\\overline{R}_{2n,a,b}..`` (weight, point, function).
    ``\\ell`` is read as the variable ``l``.  With ``bare`` the terms are constants alone (a sum of weights); with
    ``normalizing`` ``r_{2n,a,b}^{\\alpha}R_{2n,a,b}`` (normalizing coefficient times function).

    >>> sum_terms(r"\\rho_{2n,n,n}R_{2n,n,n} +\\sum_{j=1}^{n-1}\\sum_{i=j}^{2n-1-j}\\gamma_{2n,2n-i,j}G_{2n,2n-i,j}")
    [([], 'R', 'n', 'n'), ([('j', '1', 'n-1'), ('i', 'j', '2n-1-j')], 'G', '2n-i', 'j')]
    """
    text = tex.replace("\\left(", "(").replace("\\right)", ")").replace("\\ell", "l")
    out, last = [], 0
    pattern = (_BARE_TERM if bare else _RATIONAL_TERM if rational else _POINT_TERM if points
               else _NORMALIZING_TERM if normalizing else _TERM)
    for m in pattern.finditer(text):
        groups = m.groups()
        if bare:
            const, a, b = groups
            sums = [(v, lo.strip(), hi.strip()) for v, lo, hi in _SUM.findall(text[last:m.start()])]
            out.append((sums, _COLOUR_OF[const], a.strip(), b.strip()))
            last = m.end()
            continue
        const, a, b, colour, fa, fb = groups[:6]
        if rational:
            point, (colour, fa, fb), (pa, pb) = colour, groups[6:], groups[4:6]
            if _COLOUR_OF[point] != colour or (pa.strip(), pb.strip()) != (fa.strip(), fb.strip()):
                raise ValueError(f"point {point}_{{2n,{pa},{pb}}} does not match {colour}_{{2n,{fa},{fb}}}")
        if _COLOUR_OF[const] != colour or (a.strip(), b.strip()) != (fa.strip(), fb.strip()):
            raise ValueError(f"constant {const}_{{2n,{a},{b}}} does not match {colour}_{{2n,{fa},{fb}}}")
        sums = [(v, lo.strip(), hi.strip()) for v, lo, hi in _SUM.findall(text[last:m.start()])]
        out.append((sums, colour, a.strip(), b.strip()))
        last = m.end()
    return out


def constant_sets(tex: str, n: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of the constants named by a printed list such as ``\\rho_{2n,n,n},\\left\\{ \\rho_{2n,2n-i,j}
    \\right\\} _{j=0,i=j}^{n-1,2n-1-j},..`` at order n (a lone constant with numeric or n indices included)."""
    text = tex.replace("%", " ")
    out = []
    for const, jlo, ilo, jhi, ihi in _CONSTANT_SETS.findall(text):
        out += [(_COLOUR_OF[const], i, j) for j in range(bound(jlo, n=n), bound(jhi, n=n) + 1)
                for i in range(bound(ilo, n=n, j=j), bound(ihi, n=n, j=j) + 1)]
    rest = _CONSTANT_SETS.sub(" ", text)
    for const, a, b in re.findall(r"\\(rho|gamma|beta)_\{2n,([^{}]+?),([^{}]+?)\}", rest):
        out.append((_COLOUR_OF[const], 2 * n - bound(a, n=n), bound(b, n=n)))
    return out


def term_indices(terms, **env: int) -> list[tuple[str, int, int]]:
    """``(colour, i, j)`` of every function of :func:`sum_terms` (i from the first index 2n - i), bounds evaluated
    with ``env`` (``n``, ``r``) and the outer sum variables."""
    out: list[tuple[str, int, int]] = []

    def walk(sums, colour, first, level, scope):
        if not sums:
            out.append((colour, 2 * scope["n"] - bound(first, **scope), bound(level, **scope)))
            return
        (v, lo, hi), rest = sums[0], sums[1:]
        for x in range(bound(lo, **scope), bound(hi, **scope) + 1):
            walk(rest, colour, first, level, {**scope, v: x})

    for sums, colour, first, level in terms:
        walk(sums, colour, first, level, dict(env))
    return out


def bound(expr: str, **env: int):
    """Value of a printed bound such as ``2n-1-j`` (juxtaposition is a product); ``ValueError`` if it names an
    unknown variable or does not parse."""
    try:
        return bound_value(expr, **env)
    except (NameError, SyntaxError, TypeError) as exc:
        raise ValueError(f"unread bound {expr!r}: {exc}") from exc


__all__ = ["index_set", "listed_range", "interval", "right_hand_side", "sum_terms", "term_indices", "constant_sets",
           "bound"]
