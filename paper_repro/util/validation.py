"""Input validation shared by every public function.

Errors are :class:`ValueError` naming the parameter and the allowed range.
"""

from __future__ import annotations

import math
import numbers

#: Points may miss the domain Omega^alpha by this much (relative to alpha) in float arithmetic.
DOMAIN_TOL = 1e-12


def check_n(n: object, name: str = "n") -> int:
    """Return ``n`` if it is a positive integer, else raise ``ValueError``."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or int(n) < 1:
        raise ValueError(f"{name} must be a positive integer (n >= 1), got {n!r}")
    return int(n)


def check_alpha(alpha: object, name: str = "alpha") -> float:
    """Return ``float(alpha)`` if ``0 < alpha < pi``, else raise ``ValueError``.

    Accepts floats, mpmath numbers and exact rationals (anything ``float()`` accepts).
    """
    try:
        a = float(alpha)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number in the open interval (0, pi), got {alpha!r}") from None
    if not (0.0 < a < math.pi) or math.isnan(a):
        raise ValueError(f"{name} must lie in the open interval (0, pi), got {alpha!r}")
    return a
