"""Opaque 3D drawings on flat matplotlib axes: depth-sorted, smoothly shaded surfaces and exactly occluded nets.

matplotlib's 3D axes sort whole collections by one depth each (the painter's algorithm at the level of
artists), which produces dark wedges and draws control nets over the surface that hides them.  Here every
triangle of every surface is projected orthographically and drawn far to near (fine meshes, opaque, so the
per-triangle order is right wherever triangles do not intersect), Gouraud-shaded from per-vertex normals (the
mean of the normals of the triangles around a vertex), so no facets show.  The visibility of a control net is
decided exactly against the same triangles: a point of an edge is hidden when a triangle covering it on the
screen is nearer to the eye (:meth:`Scene.hidden`), and the place where an edge passes behind the surface is
found by bisection to 1e-6 of the edge (:meth:`Scene.edge_pieces`), so a visible edge runs up to the silhouette
that hides it and goes on, dashed, behind it.  Hidden parts are dashed in a light tint of their net's own
colour (two nets stay apart behind the surface too).  Output is 2D graphics framed by the projected bounding
box, so nothing is clipped; the shaded surface is rasterized inside the SVG (Gouraud triangles as SVG
gradients would be megabytes), nets and text stay vectors.  PNG and SVG are byte-stable with the pinned
matplotlib.

PyVista/VTK was measured as the alternative (it renders off-screen here through Mesa), but it is a 566 MB
dependency, takes ~9 s for its first frame, writes no SVG, and its pixels depend on the OpenGL driver, which
would break the byte-stable figures.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.artist import Artist, allow_rasterization
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


def vertex_normals(verts: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Unit normals at the vertices: the sum of the (area-weighted) normals of the triangles around each vertex,
    with the orientation of the first triangle kept (two-sided lighting makes the sign irrelevant).

    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], float)
    >>> vertex_normals(v, np.array([[0, 1, 2], [1, 3, 2]])).round(12).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    tri = verts[faces]
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    vn = np.zeros_like(verts, dtype=float)
    for k in range(3):
        np.add.at(vn, faces[:, k], fn)
    return vn / np.maximum(np.sqrt(_dot3(vn, vn))[:, None], 1e-300)


def _shade(normals: np.ndarray, base: np.ndarray, view: View) -> np.ndarray:
    """Lambert shading, two-sided, light from the upper left front of the viewer."""
    right, up, d = view.frame()
    light = -0.35 * right + 0.55 * up + 0.75 * d
    light /= np.sqrt(_dot3(light, light))
    lam = np.abs(_dot3(normals, light))
    return np.clip(base * (0.38 + 0.62 * lam[..., None]), 0, 1)


def mix(color, weight: float, other="white") -> tuple[float, float, float]:
    """``color`` moved by ``weight`` (0..1) towards ``other``.

    >>> mix("black", 0.5)
    (0.5, 0.5, 0.5)
    """
    a, b = np.array(to_rgb(color)), np.array(to_rgb(other))
    return tuple(float(x) for x in (1 - weight) * a + weight * b)


class GouraudTriangles(Artist):
    """Triangles with a colour per vertex, drawn in the given order (matplotlib's renderers interpolate)."""

    def __init__(self, tris: np.ndarray, colors: np.ndarray, zorder: float = 1, rasterized: bool = False):
        super().__init__()
        self.set_zorder(zorder)
        self.set_rasterized(rasterized)
        self.tris = np.asarray(tris, float)
        self.colors = np.concatenate([np.asarray(colors, float), np.ones(colors.shape[:2] + (1,))], axis=2)

    @allow_rasterization
    def draw(self, renderer):
        if not self.get_visible():
            return
        renderer.open_group("gouraud", gid=self.get_gid())
        gc = renderer.new_gc()
        self._set_gc_clip(gc)
        renderer.draw_gouraud_triangles(gc, self.tris, self.colors, self.axes.transData.frozen())
        gc.restore()
        renderer.close_group("gouraud")
        self.stale = False


class Scene:
    """Surfaces and nets seen from one view, drawn on a flat (2D) matplotlib axes."""

    def __init__(self, view: View, samples: int = 160):
        self.view, self.samples = view, samples
        self.surfaces: list[Surface] = []
        self.nets: list[tuple[np.ndarray, list[tuple[int, int]], list[str] | str, str, float]] = []
        self._tri: tuple[np.ndarray, np.ndarray] | None = None
        self._prep: tuple | None = None

    def surface(self, verts: np.ndarray, faces: np.ndarray, color: str) -> None:
        self.surfaces.append(Surface(np.asarray(verts, float), np.asarray(faces), color))
        self._tri = None
        self._prep = None

    def net(self, pts: np.ndarray, edges: list[tuple[int, int]], point_colors, line_color: str = "black",
            size: float = 28) -> None:
        self.nets.append((np.asarray(pts, float), edges, point_colors, line_color, size))

    # --- visibility ------------------------------------------------------------------------------------------
    def _projected(self) -> tuple[np.ndarray, np.ndarray]:
        """Every surface triangle on the screen ``(K, 3, 2)`` and its vertices' depths ``(K, 3)``."""
        if self._tri is None:
            tris = np.concatenate([s.verts[s.faces] for s in self.surfaces]) if self.surfaces else np.zeros((0, 3, 3))
            p2, dep = self.view.project(tris.reshape(-1, 3))
            self._tri = p2.reshape(-1, 3, 2), dep.reshape(-1, 3)
        return self._tri

    def depth_tolerance(self) -> float:
        """How much nearer a surface must be to hide a point: 0.4 % of the scene's depth range (points on the
        surface, such as the corners of a net, stay visible where the flat triangles cut under the curved patch)."""
        _, dep = self._projected()
        return 0.004 * float(np.ptp(dep)) + 1e-12 if dep.size else 0.0

    def hidden(self, pts: np.ndarray) -> np.ndarray:
        """For each 3D point: whether the surface hides it -- a triangle covering it on the screen is nearer to
        the eye by more than :meth:`depth_tolerance`, also at the four screen points 0.3 % of the scene's width
        beside it (a point on the silhouette itself, such as a boundary polygon seen edge-on, is seen)."""
        tri2, _ = self._projected()
        q2, qd = self.view.project(np.atleast_2d(np.asarray(pts, float)))
        if not len(tri2):
            return np.zeros(len(q2), bool)
        step = 0.003 * float(np.ptp(tri2.reshape(-1, 2), axis=0).max())
        out = self._covered_nearer(q2, qd)
        for dx, dy in ((step, 0), (-step, 0), (0, step), (0, -step)):
            if out.any():
                out[out] = self._covered_nearer(q2[out] + (dx, dy), qd[out])
        return out

    def _prepared(self) -> tuple:
        """What :meth:`_covered_nearer` needs of the triangles, computed once per scene: the non-degenerate ones,
        their corners, the denominator of the barycentric coordinates, depths, the screen boxes widened by 1e-12
        and the depth tolerance."""
        if self._prep is None:
            tri2, tdep = self._projected()
            a, b, c = tri2[:, 0], tri2[:, 1], tri2[:, 2]
            den = (b[:, 1] - c[:, 1]) * (a[:, 0] - c[:, 0]) + (c[:, 0] - b[:, 0]) * (a[:, 1] - c[:, 1])
            ok = np.abs(den) > 1e-14 * (np.ptp(tri2.reshape(-1, 2), axis=0).max() ** 2)
            a, b, c, den, zt = a[ok], b[ok], c[ok], den[ok], tdep[ok]
            lo, hi = np.minimum(np.minimum(a, b), c), np.maximum(np.maximum(a, b), c)
            self._prep = (a, b, c, den, zt, lo - 1e-12, hi + 1e-12, self.depth_tolerance())
        return self._prep

    def _covered_nearer(self, q2: np.ndarray, qd: np.ndarray) -> np.ndarray:
        """Whether a triangle covering the screen point ``q2`` is nearer than the depth ``qd`` (by the tolerance).

        Per block of points only the triangles whose (widened) screen box meets the block's box are tested: any
        other triangle fails the box test at every point of the block, so the answer is the same as testing all,
        computed with the same operations."""
        a, b, c, den, zt, lo, hi, tol = self._prepared()
        out = np.zeros(len(q2), bool)
        for s in range(0, len(q2), 512):
            block = q2[s:s + 512]
            near = np.flatnonzero(np.all((hi >= block.min(axis=0)) & (lo <= block.max(axis=0)), axis=1))
            if not len(near):
                continue
            ta, tb, tc, tden, tz, tlo, thi = a[near], b[near], c[near], den[near], zt[near], lo[near], hi[near]
            q, d = block[:, None, :], qd[s:s + 512, None]
            box = np.all((q >= tlo) & (q <= thi), axis=2)
            qx, qy = q[..., 0] - tc[:, 0], q[..., 1] - tc[:, 1]
            l1 = ((tb[:, 1] - tc[:, 1]) * qx + (tc[:, 0] - tb[:, 0]) * qy) / tden
            l2 = ((tc[:, 1] - ta[:, 1]) * qx + (ta[:, 0] - tc[:, 0]) * qy) / tden
            l3 = 1 - l1 - l2
            inside = box & (l1 >= -1e-9) & (l2 >= -1e-9) & (l3 >= -1e-9)
            z = l1 * tz[:, 0] + l2 * tz[:, 1] + l3 * tz[:, 2]
            out[s:s + 512] = np.any(inside & (z > d + tol), axis=1)
        return out

    def edge_pieces(self, p: np.ndarray, q: np.ndarray) -> list[tuple[float, float, bool]]:
        """The segment p..q cut where it passes behind or out from behind the surface: ``(t0, t1, hidden)``
        pieces covering [0, 1] (a change is located by bisection between samples, to 1e-6 of the edge)."""
        t = np.linspace(0.0, 1.0, self.samples + 1)
        hid = self.hidden(p[None] * (1 - t[:, None]) + q[None] * t[:, None])
        cuts = [0.0]
        for k in np.flatnonzero(hid[1:] != hid[:-1]):
            lo_t, hi_t, h_lo = t[k], t[k + 1], hid[k]
            while hi_t - lo_t > 1e-6:
                mid = 0.5 * (lo_t + hi_t)
                if self.hidden((p * (1 - mid) + q * mid)[None])[0] == h_lo:
                    lo_t = mid
                else:
                    hi_t = mid
            cuts.append(0.5 * (lo_t + hi_t))
        cuts.append(1.0)
        return [(cuts[i], cuts[i + 1], bool(hid[0]) != bool(i % 2)) for i in range(len(cuts) - 1)]

    # --- drawing ---------------------------------------------------------------------------------------------
    def draw(self, ax, margin: float = 0.03) -> None:
        tri2, tdep = self._projected()
        shaded = []
        for s in self.surfaces:
            shaded.append(_shade(vertex_normals(s.verts, s.faces)[s.faces], np.array(to_rgb(s.color)), self.view))
        cols = np.concatenate(shaded)
        allpts = [tri2.reshape(-1, 2)] + [self.view.project(n[0])[0] for n in self.nets]
        lo, hi = np.min([a.min(axis=0) for a in allpts], axis=0), np.max([a.max(axis=0) for a in allpts], axis=0)
        order = np.argsort(tdep.mean(axis=1), kind="stable")  # far to near
        # under the smooth shading, each triangle flat in its mean colour with a thin edge of the same colour:
        # it fills the hairlines that anti-aliasing leaves between neighbouring triangles
        flat = cols.mean(axis=1)[order]
        ax.add_collection(PolyCollection(tri2[order], facecolors=flat, edgecolors=flat, linewidths=0.35,
                                         antialiased=True, zorder=1, rasterized=True))
        ax.add_artist(GouraudTriangles(tri2[order], cols[order], zorder=1.1, rasterized=True))
        for pts, edges, pcols, lcol, size in self.nets:
            shown, hidden = [], []
            for a, b in edges:
                for t0, t1, hid in self.edge_pieces(pts[a], pts[b]):
                    seg = self.view.project(np.array([pts[a] * (1 - t0) + pts[b] * t0,
                                                      pts[a] * (1 - t1) + pts[b] * t1]))[0]
                    (hidden if hid else shown).append(seg)
            ax.add_collection(LineCollection(hidden, colors=[mix(lcol, 0.45)], linewidths=0.9,
                                             linestyles=(0, (3, 2.5)), zorder=2))
            ax.add_collection(LineCollection(shown, colors=lcol, linewidths=1.1, zorder=3, capstyle="round"))
            q2 = self.view.project(pts)[0]
            hid = self.hidden(pts)
            colors = [pcols] * len(pts) if isinstance(pcols, str) else list(pcols)
            vis = ~hid
            ax.scatter(q2[vis, 0], q2[vis, 1], s=size, c=[colors[k] for k in np.flatnonzero(vis)],
                       edgecolors="black", linewidths=0.5, zorder=4)
            if hid.any():
                ax.scatter(q2[hid, 0], q2[hid, 1], s=size * 0.6, facecolors="white",
                           edgecolors=[mix(lcol, 0.35)], linewidths=0.8, zorder=2.5)
        pad = margin * float((hi - lo).max())
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        ax.set_aspect("equal")
        ax.axis("off")
