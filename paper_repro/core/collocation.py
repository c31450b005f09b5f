"""The one collocation routine: collocate at points, solve, verify at further points.

Used by the normalizing coefficients (:mod:`paper_repro.core.normalization`), fitting
(:mod:`paper_repro.surfaces.fitting`), order elevation (:mod:`paper_repro.core.elevation`) and the basis
transformation (claim ``basis_transformation``).  The caller supplies ``system(k)``: the matrix ``A``
and right-hand side ``B`` evaluated at point set ``k`` (``m`` collocation rows followed by the
verification rows); the routine solves the first ``m`` rows in the context's arithmetic, checks the
rest (exactly in the exact arithmetics, to the working precision otherwise) and reports which point
set it used.  A singular point set is replaced by the next one.

>>> import numpy as np
>>> from paper_repro.core.context import get_context
>>> ctx = get_context("exact")
>>> def system(k):  # y = 2x + 1 sampled at x = 0, 1 (collocation) and 5 (verification)
...     xs = [0, 1, 5]
...     return ctx.asarray([[x, 1] for x in xs]), ctx.asarray([[2 * x + 1] for x in xs])
>>> res = collocate(ctx, system, m=2)
>>> res.solution.reshape(-1).tolist(), res.point_set, res.verified
([2, 1], 0, 1)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from paper_repro.core.context import Context


@dataclass
class Collocation:
    """Result of :func:`collocate`: the solution (in the context), the point set used, rows verified."""

    solution: np.ndarray
    point_set: int
    verified: int


def has_equal_rows(a: np.ndarray) -> bool:
    """Whether two rows of ``a`` are equal (exact values: int64 or hashable objects such as fmpq).  Such a
    square matrix is singular; for collocation at points this happens when two points are images of each
    other under a symmetry of the functions (e.g. permutations of (u, v, w) for the orbit sums).

    >>> has_equal_rows(np.array([[1, 2], [3, 4], [1, 2]])), has_equal_rows(np.array([[1, 2], [2, 1]]))
    (True, False)
    """
    a = np.asarray(a)
    if a.dtype == object:
        try:
            rows = {tuple(row) for row in a.tolist()}
        except TypeError:  # unhashable entries: no shortcut
            return False
    else:
        rows = {row.tobytes() for row in np.ascontiguousarray(a)}
    return len(rows) < a.shape[0]


def collocate(ctx: Context, system: Callable[[int], tuple[np.ndarray, np.ndarray]], m: int, *,
              attempts: int = 5, what: str = "collocation", rtol: float | None = None) -> Collocation:
    """Solve ``A[:m] X = B[:m]`` for the first non-singular point set and verify ``A[m:] X = B[m:]``.

    ``ArithmeticError`` if the verification rows disagree (the identity sought does not hold) or if
    ``attempts`` point sets are all singular.  ``rtol`` replaces the context's own tolerance of the
    verification residual (relative to the largest right-hand side) in the real arithmetics.
    """
    for k in range(attempts):
        a, b = system(k)
        if ctx.exact and has_equal_rows(a[:m]):
            continue  # singular: the exact solve would raise ZeroDivisionError after a whole elimination
        with ctx.scope():
            try:
                x = ctx.solve(a[:m], b[:m])
            except ZeroDivisionError:
                continue
            extra = a.shape[0] - m
            if extra:
                resid = ctx.sub(ctx.dot(a[m:], x), b[m:])
                if ctx.exact:
                    scale = 1.0
                else:  # size of the terms |A| |x| of the verification rows (and of the right-hand side)
                    ax = np.abs(ctx.to_float(a[m:])) @ np.abs(ctx.to_float(x)).reshape(x.shape[0], -1)
                    scale = max(float(np.max(ax)), float(np.max(np.abs(ctx.to_float(b)))))
                if rtol is not None and not ctx.exact:
                    ok = float(np.max(np.abs(ctx.to_float(resid)))) <= rtol * scale
                else:
                    ok = ctx.residual_ok(resid, scale)
                if not ok:
                    raise ArithmeticError(f"{what}: the solution fails at the {extra} verification point(s) "
                                          f"of point set {k} (arith {ctx.name!r})")
        return Collocation(x, k, extra)
    raise ArithmeticError(f"{what}: the collocation matrix is singular for {attempts} point sets (arith {ctx.name!r})")


def collocate_fmpq(system: Callable[[int], tuple[np.ndarray, np.ndarray]], m: int, *, attempts: int = 10,
                   what: str = "collocation", algorithm: str | None = "fflu") -> Collocation:
    """:func:`collocate` in exact rational arithmetic with flint's ``fmpq_mat`` (``algorithm`` of its solve:
    fraction-free ``"fflu"`` by default, the same exact solution as the default solve and faster on collocation
    systems): ``system(k)`` gives exact arrays ``A``, ``B`` (``m`` collocation rows, then verification rows); the
    solution is an ``fmpq_mat``, verified exactly.  ``ArithmeticError`` if the verification rows disagree or
    ``attempts`` point sets are all singular.

    >>> def system(k):  # y = 2x + 1 sampled at x = 0, 1 (collocation) and 5 (verification)
    ...     return np.array([[x, 1] for x in (0, 1, 5)], dtype=object), np.array([[2 * x + 1] for x in (0, 1, 5)])
    >>> res = collocate_fmpq(system, 2)
    >>> [int(v) for v in res.solution.entries()], res.point_set, res.verified
    ([2, 1], 0, 1)
    """
    from paper_repro.core.context import to_fmpq_mat

    for k in range(attempts):
        a, b = system(k)
        a, b = np.asarray(a, dtype=object), np.asarray(b, dtype=object)
        if has_equal_rows(a[:m]):
            continue
        try:
            x = (to_fmpq_mat(a[:m]).solve(to_fmpq_mat(b[:m]), algorithm=algorithm) if algorithm
                 else to_fmpq_mat(a[:m]).solve(to_fmpq_mat(b[:m])))
        except ZeroDivisionError:
            continue
        extra = a.shape[0] - m
        if extra and to_fmpq_mat(a[m:]) * x != to_fmpq_mat(b[m:]):
            raise ArithmeticError(f"{what}: the solution fails at the {extra} verification point(s) of point set {k} "
                                  "(exact)")
        return Collocation(x, k, extra)
    raise ArithmeticError(f"{what}: the collocation matrix is singular for {attempts} point sets (exact)")
