"""
Fit a patch to a surface
========================

Least squares with exact corners (a sphere octant), and exact reproduction of a
trigonometric surface (a torus piece, Example 6.1 of the paper).
"""

# %%
# The sphere is not a patch of this kind, so we fit one, passing exactly through the
# three corners (a patch interpolates its corner control points).
import mpmath
import numpy as np

import paper_repro as pr

alpha = np.pi / 2
pts = pr.sample_points(alpha, 400, seed=3)
u, v, w = pts.T
octant = np.stack([np.sin(u), np.sin(v), np.sin(w)], axis=1)
octant /= np.linalg.norm(octant, axis=1)[:, None]  # unit sphere, x, y, z >= 0
corners = np.eye(3)  # the surface at (alpha,0,0), (0,alpha,0), (0,0,alpha)
fitted, rms = pr.fit_least_squares(pts, octant, 2, alpha, corners=corners,
                                   full_output=True)
sphere = pr.Patch(2, alpha, fitted)
print(f"rms distance to the octant: {rms:.2e}")
assert rms < 0.02
assert np.allclose(sphere(alpha * np.eye(3)), corners)  # exact corners
radius = np.linalg.norm(sphere(pr.sample_points(alpha, 1000, seed=4)), axis=1)
print(f"radius between {radius.min():.4f} and {radius.max():.4f}")
sphere.plot().set_title("an order-2 patch fitted to a sphere octant")

# %%
# Boundary curves can be interpolated as well: ``boundary={"v=0": curve}`` with
# ``curve(t)`` the points of the edge for ``t`` in :math:`[0, \alpha]`
# (:func:`paper_repro.fit_least_squares`).
#
# A torus piece is reproduced exactly: its coordinates are trigonometric polynomials
# of the right degree, and :func:`paper_repro.fit` collocates and verifies.
rho, mu = 2.0, 1.0


def torus(u, v, w):
    r = rho + mu * mpmath.sin(u)
    return r * mpmath.cos(v), r * mpmath.sin(v), mu * mpmath.cos(u)


torus_net = pr.fit(torus, 2, alpha, "mp", dps=30).astype(float)
piece = pr.Patch(2, alpha, torus_net)
q = pr.sample_points(alpha, 50, seed=5)
exact = np.array([[float(c) for c in torus(*p)] for p in q])
print(f"max deviation from the torus: {abs(piece(q) - exact).max():.1e}")
assert abs(piece(q) - exact).max() < 1e-12
piece.plot().set_title("a torus piece, exactly (order 2)")
