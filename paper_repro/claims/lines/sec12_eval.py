"""Evaluation of the formulas of Sections 1-2 read from their transcriptions (:mod:`paper_repro.printed.latex_math`) for
the line checks of :mod:`paper_repro.claims.lines.sec1_3`.

The independent objects the parsed formulas are compared with live here too:

* :func:`c_indep` -- c_{2n,i}^alpha as the coefficient of X^{2n-i} Y^i in (X^2 + 2 cos(alpha/2) X Y + Y^2)^n over
  sin^{2n}(alpha/2) (:func:`paper_repro.core.univariate.c_numerator_by_expansion`, not the printed sum);
* :func:`a_value` -- A_{2m,k}^alpha(t) = c_{2m,k} sin^{2m-k}((alpha-t)/2) sin^k(t/2) (the definition of
  eq. univariate_basis, with :func:`c_indep`);
* :func:`bernstein` -- B_k^d(s) = binom(d, k) (1-s)^{d-k} s^k.

:func:`num` evaluates a parsed expression with mpmath (every name must be bound: an unread name raises), so a
check compares values of the printed formula with values of the independent objects.

>>> import mpmath
>>> from paper_repro.printed.latex_math import parse
>>> with mpmath.workdps(30):
...     v = num(parse(r"\\sum_{i=0}^{2n}A_{2n,i}^{\\alpha}\\left( t\\right)"), {"n": 2, "alpha": 1, "t": 0.25})
>>> bool(abs(v - 1) < 1e-25)
True
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from math import comb

import mpmath
import sympy
from flint import fmpq
from sympy.core.function import AppliedUndef

from paper_repro.core.univariate import c_numerator_by_expansion
from paper_repro.printed.latex_math import LatexMathError, prose


@cache
def _c_poly(n: int) -> tuple[tuple, ...]:
    return tuple(tuple((int(fmpq(x).p), int(fmpq(x).q)) for x in p.coeffs()) for p in c_numerator_by_expansion(n))


def c_indep(n: int, i: int, alpha) -> mpmath.mpf:
    """c_{2n,i}^alpha from the expansion of (X^2 + 2 cos(alpha/2) X Y + Y^2)^n (mpmath, current precision);
    ``ValueError`` outside 0 <= i <= 2n."""
    if n < 1 or not 0 <= i <= 2 * n:
        raise ValueError(f"c_{{{2 * n},{i}}} is not a coefficient of order n = {n}")
    c = mpmath.cos(mpmath.mpf(alpha) / 2)
    poly = _c_poly(n)[i]
    value = sum((mpmath.mpf(p) / q * c**k for k, (p, q) in enumerate(poly)), mpmath.mpf(0))
    return value / mpmath.sin(mpmath.mpf(alpha) / 2) ** (2 * n)


def c_exact(n: int, i: int, sin_half: fmpq, cos_half: fmpq) -> fmpq:
    """c_{2n,i}^alpha exactly, from the half-angle sine and cosine of alpha (the expansion, as :func:`c_indep`)."""
    if n < 1 or not 0 <= i <= 2 * n:
        raise ValueError(f"c_{{{2 * n},{i}}} is not a coefficient of order n = {n}")
    poly = c_numerator_by_expansion(n)[i]
    return sum((fmpq(x) * cos_half**k for k, x in enumerate(poly.coeffs())), fmpq(0)) / sin_half ** (2 * n)


def a_value(order, k, t, alpha, scale=1) -> mpmath.mpf:
    """A_{order,k}^alpha(t) (order = 2m) by the definition of eq. univariate_basis with :func:`c_indep`; with
    ``scale`` both sines are multiplied by it (A of order 2m becomes scale^{2m} A: identities between A's of one
    total order then hold as homogeneous polynomials in the two sines, not only as values)."""
    m2, k = _int(order), _int(k)
    if m2 % 2:
        raise ValueError(f"A_{{{m2},{k}}}: the order index must be even")
    m = m2 // 2
    return c_indep(m, k, alpha) * (scale * mpmath.sin((alpha - t) / 2)) ** (m2 - k) * (scale * mpmath.sin(t / 2)) ** k


def bernstein(k, d, s) -> mpmath.mpf:
    """B_k^d(s)."""
    k, d = _int(k), _int(d)
    if not 0 <= k <= d:
        raise ValueError(f"B_{k}^{d} is no Bernstein polynomial")
    return comb(d, k) * (1 - s) ** (d - k) * s**k


def _int(x) -> int:
    v = mpmath.mpf(x) if not isinstance(x, int) else x
    if isinstance(v, int):
        return v
    if v != mpmath.nint(v):
        raise ValueError(f"index {x} is not an integer")
    return int(mpmath.nint(v))


#: Functions of the paper that :func:`num` knows (by name of the parsed applied function).
FUNCS: dict[str, Callable] = {
    "A": lambda env, order, k, args: a_value(order, k, args[0], env["alpha"], env.get("_scale", 1)),
    "B_sup": lambda env, k, d, args: bernstein(k, d, args[0]),  # B_{k}^{d}(s): latex_math keeps the superscript
    "c": lambda env, order, k: c_indep(_half_order(order), _int(k), env["alpha"]),
}


def _half_order(order) -> int:
    o = _int(order)
    if o % 2:
        raise ValueError(f"c_{{{o},..}}: the order index must be even")
    return o // 2


def num(expr: sympy.Basic, env: dict, funcs: dict[str, Callable] | None = None):
    """mpmath value of a parsed expression; ``env`` binds every free symbol (by name), ``funcs`` the applied
    functions (default :data:`FUNCS`).  A name not bound raises :class:`LatexMathError`."""
    funcs = FUNCS if funcs is None else funcs

    def ev(e):
        if isinstance(e, sympy.Integer):
            return int(e)
        if isinstance(e, sympy.Rational):
            return mpmath.mpf(int(e.p)) / int(e.q)
        if isinstance(e, sympy.Float):
            return mpmath.mpf(str(e))
        if e is sympy.pi:
            return mpmath.pi
        if isinstance(e, sympy.Symbol):
            if e.name not in env:
                raise LatexMathError(f"unbound name {e.name!r}")
            return env[e.name]
        if isinstance(e, sympy.Add):
            return sum((ev(a) for a in e.args), 0)
        if isinstance(e, sympy.Mul):
            out = 1
            for a in e.args:
                out = out * ev(a)
            return out
        if isinstance(e, sympy.Pow):
            b, x = ev(e.args[0]), ev(e.args[1])
            if isinstance(x, int) or (isinstance(x, mpmath.mpf) and x == mpmath.nint(x)):
                return b ** int(x)
            return mpmath.power(b, x)
        if isinstance(e, sympy.sin):
            return mpmath.sin(ev(e.args[0]))
        if isinstance(e, sympy.cos):
            return mpmath.cos(ev(e.args[0]))
        if isinstance(e, sympy.binomial):
            return comb(_int(ev(e.args[0])), _int(ev(e.args[1])))
        if isinstance(e, sympy.floor):
            return int(mpmath.floor(ev(e.args[0])))
        if isinstance(e, sympy.Sum):
            body, (var, lo, hi) = e.args[0], e.args[1]
            total = 0
            for x in range(_int(ev(lo)), _int(ev(hi)) + 1):
                total = total + num(body, {**env, var.name: x}, funcs)
            return total
        if isinstance(e, sympy.Tuple):
            return tuple(ev(a) for a in e.args)
        if isinstance(e, AppliedUndef):
            name = e.func.__name__
            if name not in funcs:
                raise LatexMathError(f"unknown function {name!r}")
            return funcs[name](env, *(ev(a) for a in e.args))
        raise LatexMathError(f"cannot evaluate {e}")

    return ev(expr)


def sign_word(tex: str) -> tuple[str, Callable]:
    """The sign the prose claims ("non-negative", "positive", "negative", ...) and its predicate: a word of the
    prose (:func:`~paper_repro.printed.latex_math.prose`, the ``$..$`` formulas set aside), punctuation stripped.

    >>> sign_word("consist of non-negative functions")[0], sign_word("a $x>0$ positive, real")[0]
    ('non-negative', 'positive')
    """
    words = {w.strip(".,;:()%") for w in prose(tex)[0].split()}
    for word, pred in (("non-negative", lambda x: x >= 0), ("nonnegative", lambda x: x >= 0),
                       ("non-positive", lambda x: x <= 0), ("positive", lambda x: x > 0),
                       ("negative", lambda x: x < 0)):
        if word in words:
            return word, pred
    raise LatexMathError(f"no sign word in {tex[:60]!r}")


__all__ = ["c_indep", "c_exact", "a_value", "bernstein", "num", "FUNCS", "sign_word"]
