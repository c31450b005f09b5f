"""
The limit alpha -> 0: a Bezier triangle
=======================================

As :math:`\\alpha \\to 0` a patch of order :math:`n` tends to a Bezier triangle of
degree :math:`3n - 1` (Question 7.3, proven for every :math:`n`). With the ``bezier``
package installed it comes as a ``bezier.Triangle``, nodes in ``bezier``'s order.
"""

# %%
import numpy as np

import paper_repro as pr

net = np.random.default_rng(0).normal(size=(pr.delta(2), 3))
N, limit_net = pr.bezier_limit(net, 2)  # {(d, e, f): point}
print("degree", N, "with", len(limit_net), "control points")
try:
    import bezier  # noqa: F401
except ImportError:
    bezier = None
if bezier is not None:
    tri = pr.bezier_triangle(net, 2)
    st = np.asfortranarray([[0.2, 0.3]])
    small = pr.Patch(2, 1e-4, net)
    b = tri.evaluate_cartesian_multi(st).T
    s = small.at_barycentric([[0.5, 0.2, 0.3]])
    print(b, s, sep="\n")
    assert np.allclose(b, s, atol=1e-6)
