"""Input validation shared by every public function.

Errors are :class:`ValueError` naming the parameter and the allowed range.
"""

from __future__ import annotations

import math
import numbers
import re
import sys
from collections.abc import Callable
from typing import Any, TypeVar

from paper_repro.util.limits import real_scalar

F = TypeVar("F", bound=Callable[..., Any])

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
            return str(x) if type(x).__name__ in ("fmpq", "arb") else repr(float(x))  # type: ignore[arg-type]
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
    except OverflowError:  # a real number too large for a float: the right kind, out of range
        raise ValueError(f"{name} must lie in the open interval (0, pi), got {_plain(alpha)}") from None
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a real number in the open interval (0, pi), got {_plain(alpha)}") from None
    if not (0.0 < a < math.pi) or math.isnan(a):
        raise ValueError(f"{name} must lie in the open interval (0, pi), got {_plain(alpha)}")
    if a < sys.float_info.min:
        raise ValueError(f"{name} must lie in (0, pi) and be at least {sys.float_info.min!r} (the smallest normal "
                         f"float64; below it alpha/2 and the sine ratios lose their precision), got {_plain(alpha)}")
    return a


_ALPHA_TEXT = re.compile(
    r"^\s*(?:(?P<num>\d+(?:\.\d*)?|\.\d+)\s*\*?\s*)?(?:pi|π)\s*(?:/\s*(?P<den>\d+(?:\.\d*)?))?\s*$")
_NUMBER_TEXT = re.compile(r"^\s*(?P<num>[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)\s*(?:/\s*(?P<den>\d+))?\s*$")


def _nearest_float(num: str, den: str, times_pi: bool) -> float | None:
    """``num * (pi if times_pi) / den`` (decimal texts) rounded once to the nearest float64 (``None`` if
    ``den`` is zero): computed at 60 significant digits, then read by ``float`` (correctly rounded).

    >>> _nearest_float("1", "3", True), _nearest_float("1.1", "3", False)
    (1.0471975511965979, 0.36666666666666664)
    """
    from decimal import Decimal, localcontext

    import mpmath

    ctx = mpmath.MPContext()  # a private context: the caller's mpmath.mp.dps is left alone
    ctx.dps = 60
    with localcontext() as dc:  # texts of any length, rounded to 80 digits first (mpmath < 1.4 reads a long text
        dc.prec = 80            # through int(), which Python refuses beyond 4300 digits)
        num, den = str(+Decimal(num)), str(+Decimal(den))
    d = ctx.mpf(den)
    if d == 0:
        return None
    x = ctx.mpf(num) * (ctx.pi if times_pi else 1) / d
    return float(ctx.nstr(x, 60))


def parse_alpha(alpha: object, name: str = "alpha") -> Any:
    """The shape parameter as the package's functions take it; the one reader of alpha for the API and the CLI.

    A string is read as a number (``'1.2'``, ``'3/2'``) or a multiple of pi (``'pi/2'``, ``'2pi/3'``,
    ``'2*pi/3'``, ``'0.5 pi'``, ``'π/3'``) and returned as the float nearest to the exact value (computed
    at 60 digits, so ``'2pi/3'`` is 2.0943951023931957, not ``2 * math.pi / 3``); any other value (a float, an
    int, an mpmath number, a flint ``fmpq``, a
    :class:`~paper_repro.core.domain.RationalAngle`) is checked and returned unchanged, so exact and
    high-precision arithmetic keep their input.  Raises ``ValueError``/``TypeError`` naming ``name`` and the
    allowed range (0, pi) otherwise.

    >>> parse_alpha("pi/2") == math.pi / 2, parse_alpha("2*pi/3"), parse_alpha(" 1.5 ")
    (True, 2.0943951023931957, 1.5)
    >>> parse_alpha("pi")
    Traceback (most recent call last):
    ...
    ValueError: alpha must lie in the open interval (0, pi), got 'pi' (= 3.141592653589793)
    """
    if isinstance(alpha, str):
        shown = _plain(alpha)  # the text, truncated: a 5000-digit input is not echoed whole
        m = _ALPHA_TEXT.match(alpha)
        if not m:
            m = _NUMBER_TEXT.match(alpha)
            if not m:
                raise ValueError(f"{name} must be a number in (0, pi) or a multiple of pi such as 'pi/2' or "
                                 f"'2pi/3', got {shown}")
        value = _nearest_float(m.group("num") or "1", m.group("den") or "1", "pi" in alpha or "π" in alpha)
        if value is None:
            raise ValueError(f"{name}: division by zero in {shown}; give a number in (0, pi) such as 'pi/2'")
        if not 0.0 < value < math.pi:
            raise ValueError(f"{name} must lie in the open interval (0, pi), got {shown} (= {value!r})")
        if value < sys.float_info.min:
            raise ValueError(f"{name} must lie in (0, pi) and be at least {sys.float_info.min!r} (the smallest "
                             f"normal float64), got {shown} (= {value!r})")
        return value
    if hasattr(alpha, "sin_half") and hasattr(alpha, "cos_half"):  # a RationalAngle: valid by construction
        return alpha
    check_alpha(alpha, name)
    return alpha


def accepts_alpha_text(func: F) -> F:
    """Decorate an API function whose parameter ``alpha`` may be given as text (``"pi/2"``): the text is read
    by :func:`parse_alpha` before the call; other values pass through unchanged."""
    import functools
    import inspect

    sig = inspect.signature(func)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        bound = sig.bind_partial(*args, **kwargs)
        if isinstance(bound.arguments.get("alpha"), str):
            bound.arguments["alpha"] = parse_alpha(bound.arguments["alpha"])
        return func(*bound.args, **bound.kwargs)

    return wrapper  # type: ignore[return-value]
