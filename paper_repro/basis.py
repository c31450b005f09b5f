"""Evaluation of the (un-normalized) joint system T_{2n}^alpha (eq. united_system).

Every function is the monomial whose exponents :mod:`paper_repro.labels` stores; this module
multiplies half-angle values accordingly, in any arithmetic of :mod:`paper_repro.arith`.
"""

from __future__ import annotations

from collections.abc import Sequence

import mpmath
import numpy as np

from .arith import Arith, get_arith, power_table
from .domain import half_angle_values
from .labels import BasisLabel, exponent_matrix, exponents
from .validation import check_n


def monomials(exps: np.ndarray, trig: Sequence[np.ndarray], arith: Arith) -> np.ndarray:
    """Evaluate monomials ``prod_s trig[s] ** exps[f, s]``: returns an ``(P, F)`` array.

    ``exps`` is ``(F, 6)`` (slots as in :data:`paper_repro.labels.SLOTS`), ``trig`` six arrays of
    length P.  Only ``arith.mul`` is used, so this is the single evaluator of every arithmetic.
    """
    exps = np.asarray(exps, dtype=np.int64)
    npts = len(trig[0])
    out = arith.ones((npts, exps.shape[0]))
    kmax = int(exps.max()) if exps.size else 0
    for slot in range(6):
        if not exps[:, slot].any():
            continue
        table = power_table(trig[slot], kmax, arith)  # (kmax+1, P)
        out = arith.mul(out, table[exps[:, slot]].T)
    return out


def evaluate(n: int, alpha, points, arith: str | Arith = "float", *, dps: int = 50,
             labels: Sequence[BasisLabel] | None = None) -> np.ndarray:
    """Values of T_{2n}^alpha (un-normalized) at ``points``: an ``(P, delta_n)`` array.

    Parameters
    ----------
    n : order, a positive integer.
    alpha : shape parameter in (0, pi); for ``exact``/``modp`` the :class:`RationalAngle` of the points.
    points : ``(P, 3)`` array of ``(u, v, w)`` on Omega^alpha (float, mp) or :class:`RationalPoints`.
    arith : ``'float'``, ``'mp'`` (``dps`` digits), ``'exact'``, ``'modp'`` or an :class:`Arith`.
    labels : evaluate these functions instead of T_{2n} (any R, G, B labels of order n).

    Columns follow :func:`paper_repro.labels.united_system` (or ``labels``).
    """
    n = check_n(n)
    ar = get_arith(arith, dps=dps)
    exps = exponent_matrix(n) if labels is None else np.array([exponents(lab) for lab in labels])
    if ar.name == "mp":
        with mpmath.workdps(ar.dps):
            return monomials(exps, half_angle_values(points, alpha, ar), ar)
    return monomials(exps, half_angle_values(points, alpha, ar), ar)
