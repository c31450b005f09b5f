r"""Lemma lem:sign_cos_power_derivative and Proposition derivative_cosine_sine as printed: the sign rules of the
derivatives at 0, read from the transcriptions of eqs. sign_cos_power_derivative, sign_sin_power_derivative and
derivative_cosine_sine_at_0 by :func:`paper_repro.printed.latex_math.parse_relation` (the left side
``\operatorname{sign} X(0)``, the case display on the right: each branch's value and condition), never retyped.
``None`` where the printed case analysis gives no single value (no branch applies, or branches that apply
disagree).

A condition is the sympy boolean latex_math reads; :class:`Condition` evaluates it at integers.  A name of a
condition that is not an argument of the function (the ``r`` of ``p-i=2r``) is bound by the equation that names it
(``r = (p-i)/2``, which must be an integer); the sign Symbol ``pm`` of ``\equiv\pm1`` stands for either sign.

>>> rule = read_sign_function(verbatim("sec1_3-sign-sin"))
>>> [v for v, _ in rule], sign_of(rule, j=1, p=3), sign_of(rule, j=2, p=1)
([-1, 0, 1], -1, 0)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy

from paper_repro.printed import latex_math as lm
from paper_repro.printed.latex_math import LatexMathError
from paper_repro.printed.lines import verbatim

Env = dict[str, int]


class Condition:
    """A parsed case condition (``expr``, a sympy boolean) compiled once for fast evaluation at integer values of
    ``params`` (names); ``cond(i=1, p=2)`` is a bool.

    >>> c = Condition(lm.parse_cases(verbatim("sec1_3-sign-cos"))[0][1], ("i", "p"))
    >>> c(i=2, p=4), c(i=2, p=6), c(i=1, p=4)
    (True, False, False)
    """

    def __init__(self, expr: Any, params: tuple[str, ...]) -> None:
        if isinstance(expr, str):
            raise LatexMathError(f"unread condition {expr!r}")
        self.expr = expr
        self.params = tuple(params)
        self._fn = _compile(expr, set(params))

    def __call__(self, **env: int) -> bool:
        return self._fn(env)

    def __repr__(self) -> str:
        return f"Condition({self.expr})"


def _compile(c: Any, known: set[str]) -> Callable[[Env], bool]:
    if c is sympy.true or c is sympy.false:
        value = bool(c)
        return lambda env: value
    if lm.PM.name not in known and lm.PM in getattr(c, "free_symbols", ()):  # \pm: either sign
        f = _compile(c, known | {lm.PM.name})
        return lambda env: f({**env, "pm": 1}) or f({**env, "pm": -1})
    if isinstance(c, sympy.Or):
        fs = [_compile(a, known) for a in c.args]
        return lambda env: any(f(env) for f in fs)
    if isinstance(c, sympy.And):
        unknown = sorted((s for s in c.free_symbols if s.name not in known), key=str)
        if not unknown:
            fs = [_compile(a, known) for a in c.args]
            return lambda env: all(f(env) for f in fs)
        s = unknown[0]
        binders = [a for a in c.args if isinstance(a, sympy.Eq) and s in a.free_symbols
                   and (a.lhs - a.rhs).is_polynomial(s) and sympy.degree(a.lhs - a.rhs, s) == 1]
        if not binders:
            raise LatexMathError(f"the name {s} of {c} is bound by no equation")
        (sol,) = sympy.solve(binders[0], s)
        num, den = sympy.fraction(sympy.together(sol))
        if not den.is_Integer or not num.free_symbols <= {sympy.Symbol(k) for k in known}:
            raise LatexMathError(f"{s} = {sol} is not an integer form of {sorted(known)}")
        fnum = _lambda(num, known)
        d = int(den)
        rest = _compile(sympy.And(*[a for a in c.args if a is not binders[0]]), known | {s.name})

        def bound(env: Env, fnum=fnum, d=d, name=s.name, rest=rest) -> bool:
            v = fnum(env)
            return v % d == 0 and rest({**env, name: v // d})
        return bound
    if isinstance(c, sympy.core.relational.Relational):
        return _lambda(c, known)
    raise LatexMathError(f"not a condition: {c}")


def _lambda(e: Any, known: set[str]) -> Callable[[Env], Any]:
    names = sorted(s.name for s in e.free_symbols)
    if not set(names) <= known:
        raise LatexMathError(f"{e} names {sorted(set(names) - known)}, not among {sorted(known)}")
    f = sympy.lambdify([sympy.Symbol(x) for x in names], e, "math")
    return lambda env: bool(f(*(env[x] for x in names))) if isinstance(e, sympy.core.relational.Relational) \
        else f(*(env[x] for x in names))


def read_sign_function(tex: str) -> list[tuple[int, Condition]]:
    r"""The branches of a printed sign function ``\operatorname{sign} X(0) = \left\{ \begin{array}[c]{rl} -1, &
    COND,\\ 0, & COND,\\ +1, & COND \end{array}\right.``: ``[(value, Condition), ...]`` in printed order; the
    conditions are evaluated in the names of X's indices (an index of X is a parameter, any other name must be
    bound by an equation)."""
    rel = lm.parse_relation(tex)
    if rel.ops != ["="] or len(rel.parts) != 2 or not isinstance(rel.parts[0], sympy.sign) or \
            not isinstance(rel.parts[1], sympy.Function) or rel.parts[1].func != lm.Cases:
        raise LatexMathError(f"not sign X = {{cases}}: {rel.parts} {rel.ops}")
    params = tuple(sorted(s.name for s in rel.parts[0].free_symbols))
    out = []
    for value, cond in (row.args for row in rel.parts[1].args):
        if not value.is_Integer:
            raise LatexMathError(f"the branch value {value} is not an integer")
        out.append((int(value), Condition(cond, params)))
    return out


def sign_function_argument(tex: str) -> Any:
    r"""X of the printed ``\operatorname{sign} X = ..`` (e.g. ``C_sup(i, lambda, p, (0,))``)."""
    rel = lm.parse_relation(tex)
    if not rel.parts or not isinstance(rel.parts[0], sympy.sign):
        raise LatexMathError("no \\operatorname{sign} on the left")
    return rel.parts[0].args[0]


def sign_of(branches: list[tuple[int, Condition]], **env: int) -> int | None:
    """The value the printed branches give at ``env``: the one value of the branches whose condition holds; None if
    none holds or holding branches disagree (the printed case analysis gives no single value)."""
    vals = {v for v, c in branches if c(**env)}
    return vals.pop() if len(vals) == 1 else None


def branch_disjuncts(tex: str, value: int, params: tuple[str, ...]) -> list[Condition]:
    r"""The conditions joined by ``\text{or }`` in the branch of value ``value`` of the printed case display, in
    printed order (a sympy ``Or`` sorts its arguments)."""
    arrays: list = []
    lm.clean(lm._display_math(tex), arrays)
    if not arrays:
        raise LatexMathError("no case display")
    rows = [r for r in arrays[0] if len(r) == 2 and r[0].strip().rstrip(",").strip()
            and lm.parse(r[0].strip().rstrip(",")) == value]
    if len(rows) != 1:
        raise LatexMathError(f"{len(rows)} branches of value {value}")
    pieces = lm._split_top_word(rows[0][1].strip().rstrip(",.").strip(), "\\OR")
    return [Condition(lm.parse_condition_clean(p), params) for p in pieces]


def printed_sign_cos(i: int, p: int) -> int | None:
    """eq. sign_cos_power_derivative at (i, p), as printed."""
    return sign_of(read_sign_function(verbatim("sec1_3-sign-cos")), i=i, p=p)


def printed_sign_sin(j: int, p: int) -> int | None:
    """eq. sign_sin_power_derivative at (j, p), as printed."""
    return sign_of(read_sign_function(verbatim("sec1_3-sign-sin")), j=j, p=p)


def printed_sign_m(j: int, z: int, i: int = 1) -> int | None:
    """eq. derivative_cosine_sine_at_0 at (j, z), as printed (its branches do not name i)."""
    return sign_of(read_sign_function(verbatim("sec1_3-proposition-M")), i=i, j=j, z=z)


__all__ = ["Condition", "read_sign_function", "sign_function_argument", "sign_of", "branch_disjuncts",
           "printed_sign_cos", "printed_sign_sin", "printed_sign_m"]
