"""Input validation shared by every public function.

Errors are :class:`ValueError` naming the parameter and the allowed range.
"""

from __future__ import annotations

import math
import numbers

from paper_repro.util.limits import real_scalar

#: Points may miss the domain Omega^alpha by this much (relative to alpha) in float arithmetic.
DOMAIN_TOL = 1e-12
#: Largest order accepted (delta_n = 3n(n+1)+1 functions; beyond this nothing fits in memory or time).
MAX_N = 1000


def check_n(n: object, name: str = "n") -> int:
    """Return ``n`` if it is a positive integer, else raise ``ValueError``."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name} must be a positive integer (n >= 1), got {_plain(n)} of type {type(n).__name__}")
    if not 1 <= int(n) <= MAX_N:
        raise ValueError(f"{name} must be a positive integer from 1 to {MAX_N}, got {int(n)}")
    return int(n)


def _plain(x: object) -> str:
    """A value as a reader writes it: ``0.0`` rather than ``mpf('0.0')`` or ``np.float64(0.0)``."""
    if isinstance(x, bool):
        return repr(x)
    try:
        if isinstance(x, (numbers.Real,)) or type(x).__name__ in ("mpf", "fmpq", "arb"):
            return str(x) if type(x).__name__ in ("fmpq", "arb") else repr(float(x))
    except (TypeError, ValueError, OverflowError):
        pass
    text = repr(x)
    return text if len(text) <= 40 else text[:37] + "..."


def check_alpha(alpha: object, name: str = "alpha") -> float:
    """Return ``float(alpha)`` if ``0 < alpha < pi``, else raise ``ValueError``.

    Accepts ints, floats, numpy real scalars and 0-d arrays, ``Fraction``, mpmath ``mpf`` and flint ``fmpq``;
    ``TypeError`` for booleans, strings, complex numbers and arrays (:func:`paper_repro.util.limits.real_scalar`).
    """
    if isinstance(alpha, (bool, str, bytes)) or alpha is None:
        raise TypeError(f"{name} must be a real number in the open interval (0, pi), got {_plain(alpha)}")
    alpha = real_scalar(alpha, name)
    try:
        a = float(alpha)  # type: ignore[arg-type]
    except (TypeError, ValueError, OverflowError):
        raise TypeError(f"{name} must be a real number in the open interval (0, pi), got {_plain(alpha)}") from None
    if not (0.0 < a < math.pi) or math.isnan(a):
        raise ValueError(f"{name} must lie in the open interval (0, pi), got {_plain(alpha)}")
    return a
