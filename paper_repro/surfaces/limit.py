"""The alpha -> 0 limit of a patch as a Bezier triangle object of the ``bezier`` package.

:func:`paper_repro.theory.limits.bezier_limit` gives the limit control net ``{(d, e, f): point}`` of degree
N = 3n - 1 (Question 7.3 [que:limiting_case]; the weights are proven for every n, claim ``limit_formula``).
Here the same net is put in the node order of ``bezier.Triangle``: column ``k`` runs over
``(d, e, f) = (N - i - j, i, j)`` for ``j = 0..N``, ``i = 0..N - j`` (``bezier``'s order: the first
barycentric weight is ``1 - s - t``, the second ``s``, the third ``t``), so
``triangle.evaluate_cartesian(s, t)`` is the limit patch at the barycentric point
``(x, y, z) = (1 - s - t, s, t)``, i.e. ``(u, v, w) -> alpha (x, y, z)``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from paper_repro.theory.limits import bezier_limit


def bezier_order(N: int) -> list[tuple[int, int, int]]:
    """Exponents ``(d, e, f)`` of the degree-N Bernstein polynomials in ``bezier.Triangle``'s node order.

    >>> bezier_order(1)
    [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
    >>> bezier_order(2)
    [(2, 0, 0), (1, 1, 0), (0, 2, 0), (1, 0, 1), (0, 1, 1), (0, 0, 2)]
    """
    return [(N - i - j, i, j) for j in range(N + 1) for i in range(N + 1 - j)]


def bezier_nodes(net: Any, n: int) -> tuple[int, np.ndarray]:
    """``(N, nodes)``: the degree N = 3n - 1 of the limit and its control points as the ``(dim, (N+1)(N+2)/2)``
    Fortran-ordered array that ``bezier.Triangle(nodes, degree=N)`` takes."""
    N, pts = bezier_limit(net, n)
    return N, np.asfortranarray(np.stack([pts[t] for t in bezier_order(N)], axis=1))


def bezier_triangle(net: Any, n: int) -> Any:
    """The alpha -> 0 limit of the order-``n`` patch with control net ``net`` as a ``bezier.Triangle``.

    Needs the optional ``bezier`` package (``pip install bezier``); ``ImportError`` saying so otherwise.
    """
    try:
        import bezier
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("bezier_triangle needs the 'bezier' package: pip install bezier "
                          "(or use bezier_limit, which returns the control net as a dict)") from exc
    N, nodes = bezier_nodes(net, n)
    return bezier.Triangle(nodes, degree=N, copy=False, verify=True)
