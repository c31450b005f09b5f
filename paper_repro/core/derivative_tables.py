"""The derivative of a patch as a patch of the same order: the tables of C (package data) and their float use.

For the scaled monomials ``m_f`` of T_{2n} (sines divided by ``s = sin(alpha/2)``) and the in-plane direction
``u = (1, 0, -1)``::

    2 s d/du m_f = sum_g C[g, f](kappa) m_g,    kappa = cos(alpha/2),

where every entry of C is a polynomial in kappa with integer coefficients (degree <= n + 1).  The tables
``paper_repro/resources/derivative_tables.json`` hold these integers for n <= :data:`TABLE_MAX_N`; they are
recovered exactly modulo two primes by :mod:`paper_repro.theory.derivative_matrix`, written by
``tools/derivative_tables.py`` and recomputed by the tests (n <= 3 in the fast suite, every n <= 10 in the slow one).
Since C has a proven closed form for every n, the library no longer reads them: they are the independent reference
that claim ``derivative_all_n`` compares the closed form with, and ``make reproduce`` no longer recovers them.  That
they hold for *every* alpha, and the closed form for every n, is proven (docs/elevation_and_derivative_for_all_n.md,
Theorem 1; evaluated in every arithmetic by :func:`paper_repro.core.half_angle_matrices.derivative_nets`, which a test
compares with these tables).

The direction ``v = (0, 1, -1)`` is u with the variables u and v exchanged (T_{2n} is symmetric:
:func:`~paper_repro.core.labels.variable_swap`), and any in-plane direction ``(du, dv, dw)`` is
``du * u + dv * v``.  So the derivative of a patch with the (scaled) net ``p`` along u is the patch of the
same order with the net ``C p``: a patch's derivatives and normals cost one point evaluation with 3 or 6 coordinates
(:meth:`paper_repro.surfaces.patch.Patch.derivative`).

>>> import math, numpy as np
>>> qu, qv = derivative_nets(1, math.cos(0.5), np.eye(7)[:, :1])   # the net of m_0 = S_u S_v S_w
>>> np.nonzero(qu[:, 0])[0].tolist(), qu[np.nonzero(qu[:, 0])[0], 0].tolist()
([4, 6], [1.0, -1.0])
"""

from __future__ import annotations

import json
from functools import cache

import numpy as np

from paper_repro.core.labels import delta, variable_swap
from paper_repro.util.io import RESOURCES

#: Largest order with a table (the float-accuracy claim's range; each table is exact integers, about 50 KB at n = 10).
TABLE_MAX_N = 10

#: The package data file.
TABLES = RESOURCES / "derivative_tables.json"


def has_table(n: int) -> bool:
    """True when the derivative of order ``n`` goes through C (``1 <= n <= TABLE_MAX_N``)."""
    return 1 <= n <= TABLE_MAX_N


@cache
def _all_tables() -> dict:
    return json.loads(TABLES.read_text(encoding="utf-8"))["tables"]


@cache
def table(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(rows, cols, coefs)`` of C for the direction u: entry ``C[rows[e], cols[e]] = sum_d coefs[e, d] kappa^d``
    (``coefs`` of shape ``(nnz, n + 2)``, integers as float64: exact, at most 2n in size); read-only arrays."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not has_table(int(n)):
        raise ValueError(f"n must be an integer from 1 to {TABLE_MAX_N} for a table of C, got {n!r}")
    n = int(n)
    t = _all_tables()[str(n)]
    out = (np.array(t["rows"], dtype=np.int64), np.array(t["cols"], dtype=np.int64),
           np.array(t["coefs"], dtype=np.float64))
    for a in out:
        a.setflags(write=False)
    return out


def entries(n: int, kappa: float) -> np.ndarray:
    """The float64 values of C's nonzero entries at ``kappa`` (Horner's rule in the order of :func:`table`);
    each within ``(2 (n + 1) + 1) u sum_d |c_d| kappa^d`` of the exact polynomial (u = 2^-53)."""
    coefs = table(n)[2]
    val = coefs[:, -1].copy()
    for d in range(coefs.shape[1] - 2, -1, -1):
        val *= kappa
        val += coefs[:, d]
    return val


def apply(n: int, vals: np.ndarray, net: np.ndarray) -> np.ndarray:
    """``C net`` for a ``(delta_n, m)`` net, with the entry values ``vals`` of :func:`entries`: each output row
    summed in the order of the table (deterministic)."""
    rows, cols, _ = table(n)
    out = np.zeros((delta(n), net.shape[1]))
    np.add.at(out, rows, vals[:, None] * net[cols])
    return out


def derivative_nets(n: int, kappa: float, net: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(q_u, q_v)``: the nets of ``2 s d/du`` and ``2 s d/dv`` of the patch ``sum_f net[f] m_f``
    (``net`` of shape ``(delta_n, m)``, on the scaled monomials, :func:`entries` at ``kappa = cos(alpha/2)``)."""
    if not -1.0 <= kappa <= 1.0:
        raise ValueError(f"kappa = cos(alpha/2) must be a number in [-1, 1], got {kappa!r}")
    net = np.asarray(net, dtype=np.float64)
    if net.ndim != 2 or net.shape[0] != delta(n):
        raise ValueError(f"net must be a (delta_n, m) = ({delta(n)}, m) array for n = {n}, got shape {net.shape}")
    vals = entries(n, kappa)
    pi = variable_swap(n, 0, 1)  # m_{pi[f]}(u, v, w) = m_f(v, u, w)
    qu = apply(n, vals, net)
    qv = np.empty_like(qu)
    qv[pi] = apply(n, vals, net[pi])
    return qu, qv
