"""Rational functions of one variable over Q (pairs of flint ``fmpq_poly``), for symbolic identities.

With ``t = tan(alpha/4)``, ``sin(alpha/2) = 2t/(1+t^2)`` and ``cos(alpha/2) = (1-t^2)/(1+t^2)``: an
expression built from them with + - * / is a rational function of t, and two such expressions are equal
for every alpha in (0, pi) iff their cross-multiplied numerators are the same polynomial -- a proof, not
a sample.  :class:`RatFunc` supports exactly the operators the printed expressions use.

>>> s, c = half_angle_functions()
>>> s * s + c * c == RatFunc.const(1)
True
>>> (2 / s) * s == RatFunc.const(2)
True
"""

from __future__ import annotations

from fractions import Fraction

from flint import fmpq, fmpq_poly


class RatFunc:
    """``num / den`` with ``den`` non-zero; kept unreduced (equality is by cross-multiplication)."""

    __slots__ = ("num", "den")

    def __init__(self, num: fmpq_poly, den: fmpq_poly | None = None):
        self.num = num
        self.den = den if den is not None else fmpq_poly([1])
        if self.den.is_zero():
            raise ZeroDivisionError("rational function with zero denominator")

    @classmethod
    def const(cls, x) -> RatFunc:
        if isinstance(x, RatFunc):
            return x
        if isinstance(x, Fraction):
            x = fmpq(x.numerator, x.denominator)
        return cls(fmpq_poly([x]))

    def __add__(self, o):
        o = RatFunc.const(o)
        return RatFunc(self.num * o.den + o.num * self.den, self.den * o.den)

    __radd__ = __add__

    def __neg__(self):
        return RatFunc(-self.num, self.den)

    def __sub__(self, o):
        return self + (-RatFunc.const(o))

    def __rsub__(self, o):
        return RatFunc.const(o) - self

    def __mul__(self, o):
        o = RatFunc.const(o)
        return RatFunc(self.num * o.num, self.den * o.den)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = RatFunc.const(o)
        return RatFunc(self.num * o.den, self.den * o.num)

    def __rtruediv__(self, o):
        return RatFunc.const(o) / self

    def __pow__(self, k: int):
        if not isinstance(k, int) or k < 0:
            raise ValueError(f"only non-negative integer powers, got {k!r}")
        return RatFunc(self.num**k, self.den**k)

    def __eq__(self, o) -> bool:
        o = RatFunc.const(o)
        return self.num * o.den == o.num * self.den

    def __hash__(self):  # pragma: no cover - unhashable in spirit (equality is not structural)
        raise TypeError("RatFunc is not hashable")


def half_angle_functions() -> tuple[RatFunc, RatFunc]:
    """``(sin(alpha/2), cos(alpha/2))`` as rational functions of ``t = tan(alpha/4)``."""
    t2p1 = fmpq_poly([1, 0, 1])
    return RatFunc(fmpq_poly([0, 2]), t2p1), RatFunc(fmpq_poly([1, 0, -1]), t2p1)


def poly_at(coeffs, x: RatFunc) -> RatFunc:
    """The polynomial with ascending ``coeffs`` evaluated at the rational function ``x`` (Horner)."""
    acc = RatFunc.const(0)
    for k in reversed(list(coeffs)):
        acc = acc * x + RatFunc.const(fmpq(k) if not isinstance(k, fmpq) else k)
    return acc
