"""Machine-independent measured values: what may reach ``data/``.

``data/`` holds only what every machine computes to the same bytes.  Floating-point results depend on the
machine in their last bits (BLAS threads and kernels, SIMD implementations of sin/cos, FMA), and a quantity at
rounding level (a float64 error of 1e-15, an mpmath residual of 1e-40) is nothing *but* those bits.  So:

* a quantity at rounding level is published as a **bound** that it must clear, ``"< 1e-12"``
  (:func:`bound`): the bound is the claim's tolerance, far above the value, so every machine writes the same
  text (the raw value goes to ``build/``, see :func:`paper_repro.app.report.run_claims`);
* a quantity whose error is far below its size (a fitted convergence order, a distance between a net and a
  patch, a weight) is published **rounded** to the digits that are meaningful, at most
  :data:`MAX_DIGITS` significant digits (:func:`sig`);
* exact values (integers, rationals as strings, booleans) as they are.

:func:`violations` finds what breaks the rule in a claim's ``measured`` (the runner fails such a claim, and a
test scans the committed ``data/``): a float with more than :data:`MAX_DIGITS` significant digits, a float of
magnitude below :data:`ROUNDING_LEVEL` (rounding noise: publish a bound), or a string that is a number in
scientific notation below that level other than a power of ten (e.g. ``mpmath.nstr`` of a residual).

>>> bound(3.2e-15, 1e-12)
'< 1e-12'
>>> sig(2.000137, 3)
2.0
>>> violations({"a": 0.1234567, "b": 1e-15, "c": "5.7e-41", "d": "< 1e-30", "e": "1e-30", "f": 2.0001})
['a', 'b', 'c']
"""

from __future__ import annotations

import math
import re
from typing import Any

#: Largest number of significant digits a published float may carry.
MAX_DIGITS = 6
#: Magnitudes below this are rounding level in every arithmetic the package publishes: bounds only.
ROUNDING_LEVEL = 1e-9

_SCI = re.compile(r"^-?\d(?:\.(\d+))?e-(\d+)$")


def bound(value: float, tol: float) -> str:
    """``"< tol"`` if ``|value| < tol`` (what ``data/`` holds); otherwise the value with the bound it missed
    (a failing claim, whose text may then depend on the machine)."""
    v = abs(float(value))
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


def _float_ok(x: float) -> bool:
    if x == 0 or math.isinf(x) or math.isnan(x):
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
    return 10.0 ** -exponent >= ROUNDING_LEVEL


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
