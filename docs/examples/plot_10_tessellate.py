"""
Subdivide, join and tessellate the torus
========================================

Beyond the paper.  The torus of Example 6.1 (radii 2 and 1, alpha = pi/2) is covered
by order-2 patches, two per square of its (U, V) plane.  This example subdivides one
piece (``docs/subdivision_for_all_n.md``), checks and rebuilds its C1 join with the
piece across the diagonal, and cuts it into a triangle mesh within a tolerance of the
surface (``docs/tessellation.md``: the bound is proven, and checked here by sampling).
"""

# %%
import matplotlib.pyplot as plt
import numpy as np

import paper_repro as pr
from paper_repro.core.subdivision import to_parent
from paper_repro.surfaces.models import torus_pieces

alpha = np.pi / 2
lower, upper = (p.patch for p in torus_pieces(alpha, 2.0, 1.0, [0.0], [0.0]))
net = np.asarray(lower.net)

# %%
# Subdivide: each of the four sub-nets is the net of the piece on its sub-triangle,
# with parameter alpha/2.
parts = pr.subdivide(net, 2, alpha)
qs = pr.sample_points(alpha / 2, 50, seed=3)
mid = pr.Patch(2, alpha / 2, parts.middle)
gap = abs(mid(qs) - lower(to_parent(qs, alpha, "middle"))).max()
print(f"middle sub-patch against the piece: {gap:.1e}")
assert gap < 1e-12

# %%
# Join: the lower and the upper triangle of the square share the diagonal, the edge
# w = 0 of both, and join C1.  The C1 builder gives back the upper piece's net (its
# boundary row and second row) from the lower piece.
err = pr.join_error(net, upper.net, 2, alpha, "w")
print({k: f"{float(v):.1e}" for k, v in err.items()})
assert err["C0"] < 1e-12 and err["C1"] < 1e-9
rebuilt = pr.join_neighbour(net, 2, alpha, "w", upper.net)
off = abs(rebuilt - upper.net).max()
print(f"rebuilt neighbour against the upper piece: {off:.1e}")
assert off < 1e-9

# %%
# Tessellate to 1e-4: the mesh's deviation from the surface, measured at 28 points in
# every triangle, stays below the proven bound, itself below the tolerance.
mesh = pr.tessellate(net, 2, alpha, 1e-4)
k = 6
bary = np.array([(i / k, j / k, 1 - (i + j) / k)
                 for i in range(k + 1) for j in range(k + 1 - i)])
params = np.einsum("sk,fkd->fsd", bary, mesh.params[mesh.triangles])
flat = np.einsum("sk,fkd->fsd", bary, mesh.points[mesh.triangles])
dev = np.linalg.norm(lower(params.reshape(-1, 3)) - flat.reshape(-1, 3), axis=1).max()
print(f"{len(mesh.points)} vertices, {len(mesh.triangles)} triangles, "
      f"bound {mesh.bound:.2e}, measured deviation {dev:.2e}")
assert dev <= mesh.bound <= 1e-4

# %%
# A coarser mesh (1e-2) is small enough to see its triangles:
coarse = pr.tessellate(net, 2, alpha, 1e-2)
fig = plt.figure(figsize=(7, 6))
ax = fig.add_subplot(projection="3d")
x, y, z = coarse.points.T
ax.plot_trisurf(x, y, z, triangles=coarse.triangles, color="#8fb8de",
                edgecolor="#1f3b5c", linewidth=0.4)
ax.locator_params(nbins=4)
ax.set_title(f"the torus piece within 1e-2: {len(coarse.triangles)} triangles")
plt.show()
