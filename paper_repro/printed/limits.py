"""Verbatim transcription: the printed order elevation 1 -> 2 (Example exmp:degree_elevation_from_1_to_2).

(The printed alpha -> 0 conversions are no longer copied here: claim bezier_conversion reads them from the
transcribed lines ``sec7-conv2-*``, ``sec7-conv3-*`` of :mod:`paper_repro.printed.lines.sec7`.)

Elevation: for each order-2 control point triple ``[r, g, b]_{4,...}``, a list of ``(weight(c2, s2), (R label,
G label, B label))`` with ``c2 = cos^2(alpha/2)``, ``s2 = sin^2(alpha/2)``; the three colours use the three
labels in turn.
"""

from __future__ import annotations

from fractions import Fraction as F

_RGB = lambda a, b: ((f"r_{{2,{a},{b}}}", f"g_{{2,{a},{b}}}", f"b_{{2,{a},{b}}}"))  # noqa: E731
_GBR = lambda a, b: ((f"g_{{2,{a},{b}}}", f"b_{{2,{a},{b}}}", f"r_{{2,{a},{b}}}"))  # noqa: E731
_BRG = lambda a, b: ((f"b_{{2,{a},{b}}}", f"r_{{2,{a},{b}}}", f"g_{{2,{a},{b}}}"))  # noqa: E731
_CENTRE = ("r_{2,1,1}",) * 3

ELEVATION_1_TO_2 = {
    ("4,4,0"): [(lambda c2, s2: 1, _RGB(2, 0))],
    ("4,3,0"): [(lambda c2, s2: F(1, 2), _RGB(2, 0)), (lambda c2, s2: F(1, 2), _RGB(1, 0))],
    ("4,2,0"): [(lambda c2, s2: 1 / (2 + 4 * c2), _RGB(2, 0)), (lambda c2, s2: 2 * c2 / (1 + 2 * c2), _RGB(1, 0)),
                (lambda c2, s2: 1 / (2 + 4 * c2), _GBR(2, 0))],
    ("4,1,0"): [(lambda c2, s2: F(1, 2), _RGB(1, 0)), (lambda c2, s2: F(1, 2), _GBR(2, 0))],
    ("4,3,1"): [(lambda c2, s2: 1 / (2 + 4 * c2), _RGB(2, 0)), (lambda c2, s2: c2 / (1 + 2 * c2), _RGB(1, 0)),
                (lambda c2, s2: s2 / (2 + 4 * c2), _CENTRE), (lambda c2, s2: c2 / (2 + 4 * c2), _GBR(1, 0)),
                (lambda c2, s2: c2 / (1 + 2 * c2), _BRG(1, 0))],
    ("4,2,1"): [(lambda c2, s2: 1 / (8 + 4 * c2), _RGB(2, 0)), (lambda c2, s2: (1 + c2) / (4 + 2 * c2), _RGB(1, 0)),
                (lambda c2, s2: s2 / (4 + 2 * c2), _CENTRE), (lambda c2, s2: 1 / (8 + 4 * c2), _GBR(2, 0)),
                (lambda c2, s2: (1 + 2 * c2) / (8 + 4 * c2), _GBR(1, 0)),
                (lambda c2, s2: (1 + 2 * c2) / (8 + 4 * c2), _BRG(1, 0))],
}

#: r_{4,2,2} (the centre), printed on its own.
ELEVATION_CENTRE = [
    (lambda c2, s2: 1 / (5 + 10 * c2), "r_{2,2,0}"), (lambda c2, s2: 4 * c2 / (5 + 10 * c2), "r_{2,1,0}"),
    (lambda c2, s2: 2 * s2 / (5 + 10 * c2), "r_{2,1,1}"), (lambda c2, s2: 1 / (5 + 10 * c2), "g_{2,2,0}"),
    (lambda c2, s2: 4 * c2 / (5 + 10 * c2), "g_{2,1,0}"), (lambda c2, s2: 1 / (5 + 10 * c2), "b_{2,2,0}"),
    (lambda c2, s2: 4 * c2 / (5 + 10 * c2), "b_{2,1,0}"),
]


def printed_elevation_rows(c2, s2) -> dict[str, list[tuple[object, str]]]:
    """``{order-2 label: [(weight, order-1 label), ...]}`` for every order-2 control point."""
    out: dict[str, list] = {}
    for idx, terms in ELEVATION_1_TO_2.items():
        for colour, letter in enumerate("rgb"):
            out[f"{letter}_{{{idx}}}"] = [(w(c2, s2), labels[colour]) for w, labels in terms]
    out["r_{4,2,2}"] = [(w(c2, s2), lab) for w, lab in ELEVATION_CENTRE]
    return out
