"""Evaluation of the (un-normalized) joint system T_{2n}^alpha (eq. united_system).

Every function is the monomial whose exponents :mod:`paper_repro.core.labels` stores; this module
multiplies half-angle values accordingly, in any arithmetic of :mod:`paper_repro.core.context`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from paper_repro.core.context import Context, get_context, power_table
from paper_repro.core.domain import half_angle_values, scaled_half_angle_values
from paper_repro.core.labels import BasisLabel, delta, exponent_matrix, exponents
from paper_repro.util.validation import check_n

#: Largest (points x functions) array :func:`evaluate` builds at once (2e8 float64 values = 1.6 GB).
MAX_MATRIX_ENTRIES = 200_000_000


def monomials(exps: np.ndarray, trig: Sequence[np.ndarray], ctx: Context) -> np.ndarray:
    """Evaluate monomials ``prod_s trig[s] ** exps[f, s]``: returns an ``(P, F)`` array.

    ``exps`` is ``(F, 6)`` (slots as in :data:`paper_repro.core.labels.SLOTS`), ``trig`` six arrays of
    length P.  Only ``ctx.mul`` is used, so this is the single evaluator of every arithmetic.
    """
    exps = np.asarray(exps, dtype=np.int64)
    npts = len(trig[0])
    kmax = int(exps.max()) if exps.size else 0
    if ctx.exact and exps.shape[0] > 1:
        return _monomials_by_pairs(exps, trig, kmax, ctx)
    out = ctx.ones((npts, exps.shape[0]))
    for slot in range(6):
        if not exps[:, slot].any():
            continue
        table = power_table(trig[slot], kmax, ctx)  # (kmax+1, P)
        out = ctx.mul(out, table[exps[:, slot]].T)
    return out


def _monomials_by_pairs(exps: np.ndarray, trig: Sequence[np.ndarray], kmax: int, ctx: Context) -> np.ndarray:
    """:func:`monomials` in an exact context: the products ``sin^a cos^b`` of one variable are formed once per
    distinct ``(a, b)`` (526 pairs for the 2791 functions of n = 30), so the ``(P, F)`` array takes three
    multiplications instead of six.  In exact arithmetic the order of the factors does not change a value."""
    out = None
    for s0 in (0, 2, 4):
        sub = exps[:, s0:s0 + 2]
        if not sub.any():
            continue
        keys, inv = np.unique(sub, axis=0, return_inverse=True)
        first, second = power_table(trig[s0], kmax, ctx), power_table(trig[s0 + 1], kmax, ctx)
        cols = ctx.mul(first[keys[:, 0]], second[keys[:, 1]])[inv.reshape(-1)].T  # (P, F)
        out = cols if out is None else ctx.mul(out, cols)
    return ctx.ones((len(trig[0]), exps.shape[0])) if out is None else out


def evaluate(n: int, alpha, points, arith: str | Context = "float", *, dps: int = 50,
             labels: Sequence[BasisLabel] | None = None, scaled: bool = False) -> np.ndarray:
    """Values of T_{2n}^alpha (un-normalized, eq. united_system) at ``points``: an ``(P, delta_n)`` array.

    Parameters
    ----------
    n : order, a positive integer.
    alpha : shape parameter in (0, pi) (a number, or a :class:`RationalAngle` -- required by the exact
        arithmetics).
    points : ``(P, 3)`` array of ``(u, v, w)`` on Omega^alpha (real arithmetics) or :class:`RationalPoints`
        (every arithmetic).
    arith : a context or its name (:func:`paper_repro.core.context.get_context`; ``dps`` for ``'mp'``).
    labels : evaluate these functions instead of T_{2n} (any R, G, B labels of order n).
    scaled : divide every sine factor by sin(alpha/2), i.e. return ``f / s^{2n+j}`` (bounded by 1 on
        Omega^alpha; multiplied by the scaled coefficients ``s^{2n+j} r`` it gives the blending values without
        overflow for any alpha, :func:`paper_repro.core.domain.scaled_half_angle_values`).

    Returns
    -------
    numpy.ndarray
        ``(P, delta_n)`` values; columns follow :func:`paper_repro.core.labels.united_system` (or ``labels``).

    Examples
    --------
    >>> import numpy as np
    >>> v = evaluate(1, 1.0, [[0.5, 0.25, 0.25]])
    >>> v.shape, bool(np.all(v > 0))
    ((1, 7), True)
    """
    n = check_n(n)
    ctx = get_context(arith, dps=dps)
    count = len(points) if hasattr(points, "__len__") else 0
    if count * delta(n) > MAX_MATRIX_ENTRIES:
        raise ValueError(f"points: {count} points x delta_n = {delta(n)} functions is more than {MAX_MATRIX_ENTRIES:,} "
                         "values in one array; evaluate fewer points at a time (Patch evaluates in blocks)")
    if labels is not None:
        labels = list(labels)
        other = [lab for lab in labels if not isinstance(lab, BasisLabel) or lab.n != n]
        if other or not labels:
            raise ValueError(f"labels must be a non-empty list of BasisLabel of order n = {n} "
                             f"(e.g. united_system({n})), got {other[0] if other else 'an empty list'!r}")
    exps = exponent_matrix(n) if labels is None else np.array([exponents(lab) for lab in labels])
    trig = (scaled_half_angle_values if scaled else half_angle_values)(points, alpha, ctx)
    with ctx.scope():
        return monomials(exps, trig, ctx)
