"""Example exmp:torus (Example 6.1): the printed control points of the toroidal triangle, *read* from their
transcriptions (lines ``sec6-torus-point-<label>`` of :mod:`paper_repro.printed.lines.sec6`), never retyped.

Each printed row ``\\mathbf{r}_{4,4,0} = \\left[\\begin{array}[c]{ccc} x & y & z \\end{array}\\right]^{T}`` is
parsed by :func:`read_point` into its label and three sympy expressions in the symbols ``alpha``, ``varrho``,
``mu`` with the reader of :mod:`paper_repro.printed.latex_math` (anything unread raises
:class:`TorusReadError`; a blank line ``XXX`` is refused).

:func:`point_value` evaluates a parsed coordinate exactly (python-flint rationals) at an angle with rational
``tan(alpha/4)`` (then ``cos``, ``sin`` and ``tan`` of every multiple of ``alpha/2`` are rational) and rational
``varrho``, ``mu``; :func:`printed_net_mp` evaluates the whole printed net in mpmath.  The module also keeps the
mpmath form of eq. toroidal_triangle (:func:`torus`), the surface the independent fits interpolate.

>>> lab, xyz = read_point(r"\\mathbf{g}_{4,3,0}% \\normalcolor &  =\\left[ \\begin{array} [c]{ccc}% "
...                       r"\\varrho & \\frac{\\varrho}{2}\\tan\\frac{\\alpha}{2} & \\mu \\end{array} \\right]  ^{T}")
>>> lab, xyz
('g_{4,3,0}', (varrho, varrho*tan(alpha/2)/2, mu))
>>> parse_expression(r"\\cos^{2}\\frac{\\alpha}{2}")
cos(alpha/2)**2
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from paper_repro.printed.latex_math import LatexMathError, clean, parse_relation, strip_comments
from paper_repro.printed.parsed import ALPHA, MU, VARRHO, exact_value, point_label
from paper_repro.printed.parsed import expression as parse_expression

POINT_LINE_PREFIX = "sec6-torus-point-"
TorusReadError = LatexMathError


def read_point(tex: str) -> tuple[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]]:
    """``(label, (x, y, z))`` of one printed control point row ``\\mathbf{r}_{a,b,c} = [x y z]^{T}``, read by
    :func:`paper_repro.printed.latex_math.parse_relation` (``TorusReadError`` if it is not one)."""
    try:
        rel = parse_relation(tex)
        if rel.ops != ["="] or len(rel.parts) != 2 or rel.conditions:
            raise TorusReadError(f"not one equation 'point = column': {rel.ops}")
        point, vector = rel.parts
        label = point_label(point)
    except ValueError as exc:
        raise TorusReadError(f"not a printed control point row: {tex[:50]!r} ({exc})") from None
    if label[0] not in "rgb" or not isinstance(vector, sympy.MatrixBase) or vector.shape != (3, 1) or any(
            not isinstance(x, sympy.Expr) for x in vector):
        raise TorusReadError(f"not a control point and a column of 3 expressions: {point} = {vector}")
    return label, tuple(vector)  # type: ignore[return-value]


def point_line_ids() -> list[str]:
    """The ids of the transcribed lines of the printed torus control points (Example exmp:torus), source order."""
    from paper_repro.printed.lines.sec6 import LINES

    return [x.id for x in LINES if x.id.startswith(POINT_LINE_PREFIX)]


def printed_point(line_id: str) -> tuple[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]]:
    """The printed point of line ``line_id``, read from its transcription now (so the blank and mutation tests,
    :func:`paper_repro.printed.lines.substituted`, are seen)."""
    from paper_repro.printed.lines import verbatim

    return read_point(verbatim(line_id))


def printed_points() -> dict[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]]:
    """``label -> (x, y, z)`` of every printed control point of Example exmp:torus (read now)."""
    out: dict[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]] = {}
    for lid in point_line_ids():
        lab, xyz = printed_point(lid)
        if lab in out:
            raise TorusReadError(f"control point {lab} printed twice")
        out[lab] = xyz
    return out


def corrected_point(line_id: str) -> tuple[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]] | None:
    """The point of ``line_id`` with its erratum's ``fix`` (``(printed, corrected)`` LaTeX pairs) applied to the
    transcription as it stands now; ``None`` if the line has no fix or a printed fragment is not in it."""
    from paper_repro.printed.lines import line

    ln = line(line_id)
    fixes = (ln.erratum or {}).get("fix", [])
    text = ln.verbatim
    for printed, corrected in fixes:
        if printed not in text:
            return None
        text = text.replace(printed, corrected, 1)
    return read_point(text) if fixes else None


def corrected_points() -> dict[str, tuple[str, int, sympy.Expr]]:
    """``"label.axis" -> (line id, axis, corrected expression)`` for every coordinate that an erratum's fix changes
    (``TorusReadError`` if a fix no longer applies to its transcription)."""
    from paper_repro.printed.lines import line

    out = {}
    for lid in point_line_ids():
        if not (line(lid).erratum or {}).get("fix"):
            continue
        fixed = corrected_point(lid)
        if fixed is None:
            raise TorusReadError(f"{lid}: the erratum's fix does not apply to the transcription")
        lab, xyz = printed_point(lid)
        if fixed[0] != lab:
            raise TorusReadError(f"{lid}: the fix changes the label")
        for k, ax in enumerate("xyz"):
            if sympy.simplify(fixed[1][k] - xyz[k]) != 0:
                out[f"{lab}.{ax}"] = (lid, k, fixed[1][k])
    return out


def coordinate_tex(line_id: str, axis: int) -> str:
    """The LaTeX of coordinate ``axis`` (0, 1, 2) of the printed point of ``line_id``, as printed (for errata
    texts): the cell of the row's array, comments out (:func:`~paper_repro.printed.latex_math.strip_comments`); the
    row must be one array row of three cells as the reader cleans it."""
    from paper_repro.printed.lines import verbatim

    arrays: list = []
    clean(verbatim(line_id), arrays)  # the reader's cleaning: one array of one row of three cells
    tex = strip_comments(verbatim(line_id))
    begin, end = tex.find("{ccc}"), tex.find("\\end{array}")
    if len(arrays) != 1 or len(arrays[0]) != 1 or len(arrays[0][0]) != 3 or begin < 0 or end < begin:
        raise TorusReadError(f"not a printed control point row: {line_id}")
    return " ".join(tex[begin + len("{ccc}"):end].split("&")[axis].split())


# -- evaluation ------------------------------------------------------------------------------------------------
def point_value(expr: sympy.Expr, cos_half, sin_half, rho, mu):
    """A parsed coordinate at ``cos(alpha/2) = cos_half``, ``sin(alpha/2) = sin_half`` (exact numbers, e.g. fmpq),
    ``varrho = rho``, ``mu = mu`` (:func:`~paper_repro.printed.lines.parsed.exact_value`)."""
    return exact_value(expr, {VARRHO: rho, MU: mu}, {ALPHA: (2, cos_half, sin_half)}, cos_half * 0)


def mp_function(expr: sympy.Expr) -> Callable:
    """``f(alpha, varrho, mu)`` in mpmath of a parsed coordinate."""
    return sympy.lambdify((ALPHA, VARRHO, MU), expr, modules="mpmath")


def printed_net_mp(a, rho, mu):
    """The printed net (read now) at ``alpha = a`` in mpmath, as an object array in the order of T_4
    (:func:`paper_repro.core.labels.united_system`)."""
    import numpy as np

    from paper_repro.core.labels import united_system

    idx = {lab.control_point: k for k, lab in enumerate(united_system(2))}
    pts = printed_points()
    if sorted(pts) != sorted(idx):
        raise TorusReadError(f"the printed net names {sorted(pts)}, not the 19 points of T_4")
    net = np.empty((len(idx), 3), dtype=object)
    for lab, xyz in pts.items():
        net[idx[lab]] = [mp_function(e)(a, rho, mu) for e in xyz]
    return net


def torus(u, v, w, rho, mu):
    """eq. toroidal_triangle in mpmath, the surface that the independent fits interpolate: t(u, v) = ((rho + mu
    sin u) cos v, (rho + mu sin u) sin v, mu cos u) (``w = alpha - u - v`` unused)."""
    from mpmath import cos as c
    from mpmath import sin as s

    return ((rho + mu * s(u)) * c(v), (rho + mu * s(u)) * s(v), mu * c(u))


__all__ = ["ALPHA", "VARRHO", "MU", "TorusReadError", "parse_expression", "read_point", "point_line_ids",
           "printed_point", "printed_points", "corrected_point", "corrected_points", "coordinate_tex", "point_value",
           "mp_function", "printed_net_mp",
           "torus"]
