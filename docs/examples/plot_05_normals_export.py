"""
Normals and meshes for meshio and trimesh
=========================================

Unit normals of a patch, a triangle mesh of it, and files in every format meshio
writes a surface to.
"""

# %%
import os
import tempfile

import meshio
import numpy as np

import paper_repro as pr
from paper_repro.surfaces.mesh import formats

alpha = np.pi / 2
pts = pr.sample_points(alpha, 400, seed=3)
octant = np.sin(pts) / np.linalg.norm(np.sin(pts), axis=1)[:, None]
net = pr.fit_least_squares(pts, octant, 2, alpha, corners=np.eye(3))
sphere = pr.Patch(2, alpha, net)
q = pr.sample_points(alpha, 3, seed=1)
print(sphere.normals(q).round(4))  # unit normals (the outward sphere normal, nearly)
print((sphere(q) / np.linalg.norm(sphere(q), axis=1)[:, None]).round(4))

# %%
# The mesh: a barycentric grid (:func:`paper_repro.triangle_grid`) mapped onto the
# patch.
verts, faces, normals = sphere.mesh(24, normals=True)
print(verts.shape, faces.shape, normals.shape)
os.chdir(tempfile.mkdtemp())
pr.export_mesh("sphere_octant.obj", verts, faces, normals)  # OBJ: vn lines
pr.export_mesh("sphere_octant.stl", verts, faces)
pr.export_mesh("sphere_octant.vtu", verts, faces, normals)
print(sorted(os.listdir(".")))
print(sorted(formats()))  # the extensions, and meshio's format names
print(meshio.read("sphere_octant.vtu"))
try:
    import trimesh  # optional
    print(f"area {trimesh.load('sphere_octant.stl').area:.4f} (pi/2 = {np.pi / 2:.4f})")
except ImportError:
    print("trimesh not installed; meshio has the same arrays")
