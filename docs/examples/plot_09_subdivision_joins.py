"""
Subdivision and joins
=====================

Midpoint subdivision (beyond the paper; the proof is ``docs/subdivision_for_all_n.md``):
a patch restricted to each of the four midpoint sub-triangles of its domain is again a
patch of the same order, with parameter alpha/2.  The corner sub-patch ``u`` and the
middle one are point-reflected neighbours across their common edge, and join C1, as
pieces of one patch must.
"""

# %%
import matplotlib.pyplot as plt
import mpmath
import numpy as np

import paper_repro as pr
from paper_repro.core.subdivision import to_parent

alpha, rho, mu = np.pi / 2, 2.0, 1.0


def torus(u, v, w):
    r = rho + mu * mpmath.sin(u)
    return r * mpmath.cos(v), r * mpmath.sin(v), mu * mpmath.cos(u)


torus_net = pr.fit(torus, 2, alpha, "mp", dps=30).astype(float)  # a torus piece
piece = pr.Patch(2, alpha, torus_net)
parts = pr.subdivide(torus_net, 2, alpha)  # SubNets(u, v, w, middle), parameter alpha/2
corner = pr.Patch(2, alpha / 2, parts.u)
qs = pr.sample_points(alpha / 2, 20, seed=6)
gap = abs(corner(qs) - piece(to_parent(qs, alpha, "u"))).max()
print(f"corner sub-patch against the patch on its sub-triangle: {gap:.1e}")
assert gap < 1e-12

# %%
# The corner and the middle sub-patch share the edge u = 0 and join C1:
err = pr.join_error(parts.u, parts.middle, 2, alpha / 2, "u")
print({k: f"{v:.1e}" for k, v in err.items()})
assert err["C0"] < 1e-12 and err["C1"] < 1e-9

# %%
# The four sub-nets, drawn with their sub-patches:
fig = plt.figure(figsize=(7, 6))
ax = fig.add_subplot(projection="3d")
colours = {"u": "tab:red", "v": "tab:green", "w": "tab:blue", "middle": "tab:orange"}
for name, colour in colours.items():
    sub = pr.Patch(2, alpha / 2, getattr(parts, name))
    sub.plot(ax=ax, resolution=8, net_color=colour)
ax.locator_params(nbins=4)  # fewer ticks: the labels do not overlap
ax.set_title("a torus piece subdivided once: the four sub-nets")
plt.show()
