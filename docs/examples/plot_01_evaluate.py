"""
Evaluate a patch
================

A patch of order :math:`n` has :math:`\\delta_n = 3n(n+1)+1` control points
:math:`\\mathbf{p}_k` and is

.. math::

   \\mathbf{s}(u, v, w) = \\sum_k \\mathbf{p}_k \\, \\bar T_k(u, v, w),
   \\qquad (u, v, w) \\in \\Omega^\\alpha, \\quad u + v + w = \\alpha,

where the :math:`\\bar T_k` are the normalized functions of :math:`T_{2n}^\\alpha`
(non-negative, summing to 1).
"""

# %%
# An order-2 patch with a random net: 19 control points, rows in the package's order.
import numpy as np

import paper_repro as pr

print(pr.__version__)
net = np.random.default_rng(0).normal(size=(pr.delta(2), 3))
patch = pr.Patch(2, "pi/2", net)  # alpha as a number or as text
pts = pr.sample_points("pi/2", 5, seed=1)  # points (u, v, w) of the domain
print(pts.round(3))
print(patch(pts).round(3))

# %%
# A control point by its paper label, and the same row by index:
print(patch.net["r_{4,3,1}"])
row = patch.net.labels().index("r_{4,3,1}")
assert np.allclose(patch.net["r_{4,3,1}"], patch.net[row])

# %%
# Barycentric coordinates ``(x, y, z)``, summing to 1, name the point
# ``alpha * (x, y, z)`` of the domain; the corners interpolate their control point.
print(patch.at_barycentric([[1, 0, 0], [1 / 3, 1 / 3, 1 / 3]]).round(3))
assert np.allclose(patch.at_barycentric([[1, 0, 0]]), patch.net["r_{4,4,0}"])

# %%
# Weights make a rational patch (Definition 6.2, ``def:rational_patch``):
weights = np.linspace(1.0, 2.0, pr.delta(2))
rational = pr.Patch(2, "pi/2", net, weights=weights)
print(rational(pts[:2]).round(3))

# %%
# The patch and its net, drawn as Fig. 7 of the paper does:
ax = patch.plot()
ax.set_title("order 2, alpha = pi/2")
