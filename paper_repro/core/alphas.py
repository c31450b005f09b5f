"""Shape parameters written as readable strings (``'pi/3'``, ``'2pi/3'``, ``'0.7'``).

Claims record alpha as such strings so that ``data/`` stays readable and exact; this module turns
them into numbers at any precision.
"""

from __future__ import annotations

import re
from fractions import Fraction

import mpmath

from paper_repro.util.validation import check_alpha

_PI_RE = re.compile(r"^\s*(\d*)\s*\*?\s*pi\s*(?:/\s*(\d+))?\s*$")


def alpha_fraction_of_pi(text: str) -> Fraction | None:
    """``'2pi/3'`` -> Fraction(2, 3); ``None`` if ``text`` is not a rational multiple of pi."""
    m = _PI_RE.match(str(text))
    if not m:
        return None
    num, den = int(m.group(1) or 1), int(m.group(2) or 1)
    if den == 0:
        raise ValueError(f"alpha: division by zero in {text!r}; alpha must lie in (0, pi), e.g. 'pi/3' or '1.2'")
    return Fraction(num, den)


def alpha_mp(text: str | float) -> mpmath.mpf:
    """The value of ``text`` at the current mpmath precision; ``ValueError`` outside (0, pi)."""
    frac = alpha_fraction_of_pi(str(text))
    if frac is not None:
        val = mpmath.pi * frac.numerator / frac.denominator
    else:
        try:
            val = mpmath.mpf(str(text))
        except (ValueError, TypeError, ZeroDivisionError):
            raise ValueError(f"alpha must be a number in (0, pi) or a multiple of pi like '2pi/3', "
                             f"got {text!r}") from None
    check_alpha(val)
    return val


def alpha_float(text: str | float) -> float:
    return float(alpha_mp(text))
