"""Opaque 3D drawings on flat matplotlib axes: per-triangle depth-sorted surfaces and a depth buffer for nets.

matplotlib's 3D axes sort whole collections by one depth each (the painter's algorithm at the level of
artists), which produces dark wedges and draws control nets over the surface that hides them.  Here every
triangle of every surface is projected orthographically and drawn far to near (fine meshes, opaque, so the
per-triangle order is right wherever triangles do not intersect); the visibility of control nets is decided
by a depth buffer (the surface rasterized in numpy): visible parts are drawn solid, hidden parts dashed and
light.  Output is plain 2D vector graphics (byte-stable PNG and SVG with the pinned matplotlib), framed by
the projected bounding box, so nothing is clipped.

PyVista/VTK was measured as the alternative (it renders off-screen here through Mesa), but it is a 566 MB
dependency, takes ~9 s for its first frame, writes no SVG, and its pixels depend on the OpenGL driver, which
would break the byte-stable figures.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import to_rgb


def _dot3(pts: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``pts @ v`` for 3-vectors, summed in a fixed order by elementwise operations: BLAS's order depends on the
    CPU's kernel, and the PNG bytes with it (issue 31: the 3D figures differed under OpenBLAS's Sandybridge kernel)."""
    return pts[..., 0] * v[..., 0] + pts[..., 1] * v[..., 1] + pts[..., 2] * v[..., 2]


@dataclass(frozen=True)
class View:
    """Orthographic view from elevation/azimuth in degrees (matplotlib's convention: azimuth about z)."""
    elev: float
    azim: float

    def frame(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        e, a = np.radians(self.elev), np.radians(self.azim)
        d = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])  # towards the eye
        right = np.array([-np.sin(a), np.cos(a), 0.0])
        up = np.cross(d, right)
        return right, up, d

    def project(self, pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(2D screen coordinates, depth: larger = nearer the eye)."""
        right, up, d = self.frame()
        return np.c_[_dot3(pts, right), _dot3(pts, up)], _dot3(pts, d)


@dataclass
class Surface:
    verts: np.ndarray
    faces: np.ndarray
    color: str


def _shade(tri: np.ndarray, base: np.ndarray, view: View) -> np.ndarray:
    """Lambert shading, two-sided, light from the upper left front of the viewer."""
    right, up, d = view.frame()
    light = -0.35 * right + 0.55 * up + 0.75 * d
    light /= np.sqrt(_dot3(light, light))
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.sqrt(_dot3(n, n))[:, None], 1e-300)
    lam = np.abs(_dot3(n, light))
    return np.clip(base * (0.38 + 0.62 * lam[:, None]), 0, 1)


class Scene:
    """Surfaces and nets seen from one view, drawn on a flat (2D) matplotlib axes."""

    def __init__(self, view: View, raster: int = 700):
        self.view, self.raster = view, raster
        self.surfaces: list[Surface] = []
        self.nets: list[tuple[np.ndarray, list[tuple[int, int]], list[str] | str, str, float]] = []

    def surface(self, verts: np.ndarray, faces: np.ndarray, color: str) -> None:
        self.surfaces.append(Surface(np.asarray(verts, float), np.asarray(faces), color))

    def net(self, pts: np.ndarray, edges: list[tuple[int, int]], point_colors, line_color: str = "black",
            size: float = 28) -> None:
        self.nets.append((np.asarray(pts, float), edges, point_colors, line_color, size))

    def _triangles(self):
        tris, cols = [], []
        for s in self.surfaces:
            t = s.verts[s.faces]
            tris.append(t)
            cols.append(_shade(t, np.array(to_rgb(s.color)), self.view))
        return np.concatenate(tris), np.concatenate(cols)

    def _zbuffer(self, tri2: np.ndarray, depth: np.ndarray, lo: np.ndarray, scale: float, shape: tuple[int, int]):
        """Largest depth (nearest) of the surfaces at each raster cell."""
        zb = np.full(shape, -np.inf)
        pix = (tri2 - lo) * scale
        for p, z in zip(pix, depth):
            x0, y0 = np.floor(p.min(axis=0)).astype(int)
            x1, y1 = np.ceil(p.max(axis=0)).astype(int)
            x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, shape[1] - 1), min(y1, shape[0] - 1)
            if x1 < x0 or y1 < y0:
                continue
            gx, gy = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
            (ax_, ay), (bx, by), (cx, cy) = p
            den = (by - cy) * (ax_ - cx) + (cx - bx) * (ay - cy)
            if abs(den) < 1e-12:
                continue
            l1 = ((by - cy) * (gx - cx) + (cx - bx) * (gy - cy)) / den
            l2 = ((cy - ay) * (gx - cx) + (ax_ - cx) * (gy - cy)) / den
            l3 = 1 - l1 - l2
            inside = (l1 >= -1e-9) & (l2 >= -1e-9) & (l3 >= -1e-9)
            zz = l1 * z[0] + l2 * z[1] + l3 * z[2]
            sub = zb[y0:y1 + 1, x0:x1 + 1]
            np.maximum(sub, np.where(inside, zz, -np.inf), out=sub)
        return zb

    def draw(self, ax, margin: float = 0.03) -> None:
        tris, cols = self._triangles()
        flat = tris.reshape(-1, 3)
        p2, dep = self.view.project(flat)
        tri2, tdep = p2.reshape(-1, 3, 2), dep.reshape(-1, 3)
        allpts = [p2] + [self.view.project(n[0])[0] for n in self.nets]
        lo, hi = np.min([a.min(axis=0) for a in allpts], axis=0), np.max([a.max(axis=0) for a in allpts], axis=0)
        order = np.argsort(tdep.mean(axis=1), kind="stable")  # far to near
        ax.add_collection(PolyCollection(tri2[order], facecolors=cols[order], edgecolors=cols[order],
                                         linewidths=0.35, antialiased=True, zorder=1))
        if self.nets:
            ext = float((hi - lo).max())
            scale = self.raster / ext
            shape = (int(np.ceil((hi - lo)[1] * scale)) + 2, int(np.ceil((hi - lo)[0] * scale)) + 2)
            zb = self._zbuffer(tri2, tdep, lo, scale, shape)
            eps = 0.012 * float(np.ptp(dep)) + 1e-12

            def visible(pts: np.ndarray) -> np.ndarray:
                q2, qd = self.view.project(pts)
                ij = np.clip(((q2 - lo) * scale).astype(int), 0, [shape[1] - 1, shape[0] - 1])
                # the nearest surface depth in a 3x3 neighbourhood (a line on the surface counts as visible)
                near = np.full(len(pts), -np.inf)
                for dy in (-1, 0, 1):
                    for dx in (-1, 0, 1):
                        yy = np.clip(ij[:, 1] + dy, 0, shape[0] - 1)
                        xx = np.clip(ij[:, 0] + dx, 0, shape[1] - 1)
                        near = np.maximum(near, zb[yy, xx])
                return qd >= near - eps

            for pts, edges, pcols, lcol, size in self.nets:
                shown, hidden = [], []
                for a, b in edges:
                    t = np.linspace(0, 1, 41)[:, None]
                    seg = pts[a] * (1 - t) + pts[b] * t
                    vis = visible(seg)
                    s2 = self.view.project(seg)[0]
                    seen = vis[:-1] & vis[1:]  # per piece; consecutive pieces alike make one polyline
                    start = 0
                    for k in range(1, 41):
                        if k == 40 or seen[k] != seen[start]:
                            (shown if seen[start] else hidden).append(s2[start:k + 1])
                            start = k
                ax.add_collection(LineCollection(hidden, colors="0.55", linewidths=0.6, linestyles=(0, (2, 2)),
                                                 zorder=2))
                ax.add_collection(LineCollection(shown, colors=lcol, linewidths=1.0, zorder=3))
                q2 = self.view.project(pts)[0]
                vis = visible(pts)
                colors = [pcols] * len(pts) if isinstance(pcols, str) else list(pcols)
                ax.scatter(q2[vis, 0], q2[vis, 1], s=size, c=[colors[k] for k in np.flatnonzero(vis)],
                           edgecolors="black", linewidths=0.5, zorder=4)
                if (~vis).any():
                    ax.scatter(q2[~vis, 0], q2[~vis, 1], s=size * 0.6, facecolors="white", edgecolors="0.5",
                               linewidths=0.6, zorder=2.5)
        pad = margin * float((hi - lo).max())
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        ax.set_aspect("equal")
        ax.axis("off")
