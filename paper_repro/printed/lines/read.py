"""Readers of index sets, ranges and right-hand sides in the verbatim LaTeX of a
:class:`~paper_repro.printed.lines.Line`.

A line check reads what it checks from the transcription with these (issue 31: a check that retypes the printed
index set tests its own copy, not the paper), and the checks' tests feed them a deliberately wrong transcription.
Bounds are returned as printed (strings) and evaluated with :func:`bound`.

>>> index_set(r"\\left\\{ R_{2n,2n-i,j} \\right\\} _{j=0,i=j}^{n,2n-j}")
(('j', '0', 'n'), ('i', 'j', '2n-j'))
>>> listed_range(r"\\gamma_{2n,2n-i,0}^{\\prime}=0,~i=1,2,\\ldots,2n.", "i")
('1', '2n')
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


def bound(expr: str, **env: int):
    """Value of a printed bound such as ``2n-1-j`` (juxtaposition is a product)."""
    return bound_value(expr, **env)


__all__ = ["index_set", "listed_range", "interval", "right_hand_side", "bound"]
