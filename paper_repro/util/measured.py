"""Machine-independent measured values: what may reach ``data/``.

``data/`` holds only what every machine computes to the same bytes.  Floating-point results depend on the
machine in their last bits (BLAS threads and kernels, the SIMD code numpy picks per CPU for exp, log, power, tan,
FMA), and a quantity at rounding level (a float64 error of 1e-15, an mpmath residual of 1e-40) is nothing *but*
those bits.  So:

* a quantity at rounding level is published as a **bound** that it must clear, ``"< 1e-12"``
  (:func:`bound`): the bound is the claim's tolerance, far above the value, so every machine writes the same
  text (the raw value goes to ``build/``, see :func:`paper_repro.app.report.run_claims`);
* a quantity whose error is far below its size (a fitted convergence order, a distance between a net and a
  patch, a weight) is published **rounded** to the digits that are meaningful, at most
  :data:`MAX_DIGITS` significant digits (:func:`sig`);
* exact values (integers, rationals as strings, booleans) as they are.

:func:`violations` finds what breaks the rule in a claim's ``measured`` (the runner fails such a claim, and a
test scans the committed ``data/``): a float with more than :data:`MAX_DIGITS` significant digits, a float of
magnitude below :data:`ROUNDING_LEVEL` other than a power of ten (rounding noise: publish a bound), or a string
that is a number in scientific notation below :data:`STRING_ROUNDING_LEVEL` other than a power of ten (e.g.
``mpmath.nstr`` of a residual).

>>> bound(3.2e-15, 1e-12)
'< 1e-12'
>>> sig(2.000137, 3)
2.0
>>> violations({"a": 0.1234567, "b": 3e-15, "c": "5.7e-41", "d": "< 1e-30", "e": "1e-30", "f": 2.0001, "g": 1e-12})
['a', 'b', 'c']
"""

from __future__ import annotations

import math
import re
from typing import Any

#: Largest number of significant digits a published float may carry.
MAX_DIGITS = 6
#: Float magnitudes below this are float64 rounding level (relative to the O(1) quantities published): bounds only.
ROUNDING_LEVEL = 1e-9
#: Numbers written as strings (``mpmath.nstr`` of a 30..60-digit computation) below this are mp rounding level.
STRING_ROUNDING_LEVEL = 1e-25

#: Data files (paths relative to ``data/``) whose floats carry more digits, with the reason they are the same on
#: every machine.  Meshes (``{"__mesh__": ...}``) are exempt too: their vertices are rounded to
#: :data:`MESH_DECIMALS` decimals when written.
DATA_EXEMPT = {
    "dupin/nets.json": "control points and weights of a 30-digit mpmath collocation (accurate to ~25 digits), "
                       "written rounded to 14 decimals",
}
#: Decimals of published mesh vertices (float64 patch points, machine-dependent below ~1e-14 of their size).
MESH_DECIMALS = 8

_SCI = re.compile(r"^-?\d(?:\.(\d+))?e-(\d+)$")


def bound(value: float, tol: float) -> str:
    """``"< tol"`` if ``|value| < tol`` (what ``data/`` holds); otherwise the value with the bound it missed
    (a failing claim, whose text may then depend on the machine)."""
    v, tol = abs(float(value)), float(tol)  # an mpf tol has no format spec before mpmath 1.4
    if v < tol:
        return f"< {tol:g}"
    return f"{v:.3g} (not < {tol:g})"


def bound_holds(text: str) -> bool:
    """Whether a :func:`bound` text says the bound was cleared."""
    return isinstance(text, str) and text.startswith("< ")


def sig(value: float, digits: int = 3) -> float:
    """``value`` rounded to ``digits`` significant digits (``digits <= MAX_DIGITS``)."""
    if not 1 <= digits <= MAX_DIGITS:
        raise ValueError(f"digits must be in 1..{MAX_DIGITS}, got {digits}")
    return float(f"{float(value):.{digits}g}")


def decade_bound(value: float) -> float:
    """The smallest power of ten ``>= |value|`` (0.0 for 0): how a float64 error at rounding level is published
    when its size matters (a figure of errors).  Machine-independent unless the error crosses a power of ten
    between machines -- a change by a factor up to 10 at worst, far beyond a last-bit difference of most errors.

    >>> decade_bound(4.44e-16), decade_bound(1e-15), decade_bound(0.0)
    (1e-15, 1e-15, 0.0)
    """
    v = abs(float(value))
    if v == 0:
        return 0.0
    k = math.ceil(math.log10(v))
    if 10.0 ** (k - 1) >= v:  # log10 rounding at an exact power of ten
        k -= 1
    return float(f"1e{k}")


def _is_power_of_ten(x: float) -> bool:
    return x > 0 and float(f"1e{round(math.log10(x))}") == x


def _float_ok(x: float) -> bool:
    if x == 0 or math.isinf(x) or math.isnan(x) or _is_power_of_ten(abs(x)):  # a tolerance or a decade bound
        return True
    return abs(x) >= ROUNDING_LEVEL and float(f"{x:.{MAX_DIGITS}g}") == x


def _str_ok(s: str) -> bool:
    m = _SCI.match(s.strip())
    if not m:
        return True
    mantissa = s.strip().lstrip("-").split("e")[0]
    exponent = int(m.group(2))
    if float(mantissa) == 1.0:  # a power of ten: a tolerance or a bound, not a measurement
        return True
    return 10.0 ** -exponent >= STRING_ROUNDING_LEVEL


def data_violations(files: dict[str, Any]) -> list[str]:
    """:func:`violations` of the data files a claim publishes (``{path: object}``), but for :data:`DATA_EXEMPT`,
    meshes and text files."""
    out = []
    for rel, obj in files.items():
        if rel in DATA_EXEMPT or isinstance(obj, str) or (isinstance(obj, dict) and "__mesh__" in obj):
            continue
        out += [f"{rel}:{p}" for p in violations(obj)]
    return out


def violations(obj: Any, path: str = "") -> list[str]:
    """Paths (``a/b/0``) in ``obj`` of values that break the rule of this module (empty list: none)."""
    out: list[str] = []
    if isinstance(obj, bool) or obj is None or isinstance(obj, int):
        return out
    if isinstance(obj, float):
        return [] if _float_ok(obj) else [path or "."]
    if isinstance(obj, str):
        return [] if _str_ok(obj) else [path or "."]
    if isinstance(obj, dict):
        for k, v in obj.items():
            out += violations(v, f"{path}/{k}" if path else str(k))
    elif isinstance(obj, (list, tuple)):
        for k, v in enumerate(obj):
            out += violations(v, f"{path}/{k}" if path else str(k))
    return out
