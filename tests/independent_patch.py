"""An independent evaluator of the paper's patch (eq. triangular_trig_surface) for the tessellator's tests, copied
from the cold referee's scratch evaluator (/work/wt/reftess/myeval.py, docs/tessellation.md, "Referee report").

The members are written from the paper's definitions of R, G, B (eq. united_system): R_{2n,k,j}(u, v, w) =
sin^k(u/2) sin^(2n-k)(w/2) cos^(min(k, 2n-k)-j)(v/2) sin^j(v/2), G(u, v, w) = R(w, u, v), B(u, v, w) = R(v, w, u).
The normalizing coefficients are not taken from the package: they are solved in mpmath from the partition of unity
(eq. normalized_united_system) by least squares at 2 delta_n + 10 random points.  Only the row order (the labels
of :func:`~paper_repro.core.labels.united_system`) comes from the package.  Evaluation in numpy longdouble.
"""

from __future__ import annotations

import functools
import re

import mpmath
import numpy as np

from paper_repro.core.labels import united_system

_PERM = {"r": (0, 1, 2), "g": (2, 0, 1), "b": (1, 2, 0)}


@functools.lru_cache(None)
def labels(n: int) -> tuple[tuple[str, int, int], ...]:
    """(colour, k, j) of each row of the net, colour in r/g/b, from the control point labels r_{2n,k,j}."""
    out = []
    for lab in united_system(n):
        m = re.match(r"([rgb])_\{(\d+),(\d+),(\d+)\}", lab.control_point)
        assert m, lab.control_point
        out.append((m.group(1), int(m.group(3)), int(m.group(4))))
    return tuple(out)


def _term(col: str, k: int, j: int, n: int, x: tuple, sin, cos):
    a, b, c = _PERM[col]
    u, v, w = x[a], x[b], x[c]
    return sin(u / 2) ** k * sin(w / 2) ** (2 * n - k) * cos(v / 2) ** (min(k, 2 * n - k) - j) * sin(v / 2) ** j


@functools.lru_cache(None)
def coefficients(n: int, alpha: float, dps: int = 40) -> tuple[np.ndarray, float]:
    """The normalizing coefficients (longdouble) and the least-squares residual of the partition of unity."""
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        rng = np.random.default_rng(0)
        rows = []
        for _ in range(2 * len(labels(n)) + 10):
            b = rng.dirichlet([1, 1, 1])
            u, v = a * mpmath.mpf(b[0]), a * mpmath.mpf(b[1])
            rows.append([_term(c, k, j, n, (u, v, a - u - v), mpmath.sin, mpmath.cos) for c, k, j in labels(n)])
        x, res = mpmath.qr_solve(mpmath.matrix(rows), mpmath.matrix([1] * len(rows)))
        return np.array([np.longdouble(mpmath.nstr(t, 25)) for t in x]), float(res)


def evaluate(net, n: int, alpha: float, uv, dtype=np.longdouble) -> np.ndarray:
    """The patch at the parameter points ``uv`` (``(P, 2)``, w = alpha - u - v): ``(P, d)`` in ``dtype``
    (longdouble, or float64 for speed)."""
    coef = coefficients(n, float(alpha))[0].astype(dtype)
    uv = np.asarray(uv, dtype=dtype)
    x = (uv[:, 0], uv[:, 1], np.maximum(dtype(alpha) - uv[:, 0] - uv[:, 1], 0))
    basis = np.stack([_term(c, k, j, n, x, np.sin, np.cos) for c, k, j in labels(n)], axis=1) * coef
    return basis @ np.asarray(net, dtype=dtype)
