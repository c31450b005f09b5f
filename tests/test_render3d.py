"""The 3D drawings of the figures (paper_repro.figures.render3d): nets occluded exactly by the surface, hidden parts
dashed in their own net's tint, smooth shading (no facets).  Visibility is checked against analytic surfaces
(a plane, a hemisphere), not against the renderer's own triangles."""

import numpy as np
import pytest
from matplotlib.collections import LineCollection

from paper_repro.figures import plt
from paper_repro.figures.render3d import GouraudTriangles, Scene, View


def grid_mesh(f, lo=-1.0, hi=1.0, m=40):
    """Vertices and faces of z = f(x, y) (or of the point map f(x, y) -> (x, y, z)) over a square grid."""
    t = np.linspace(lo, hi, m + 1)
    X, Y = np.meshgrid(t, t)
    verts = np.array(f(X.ravel(), Y.ravel())).T if not np.isscalar(f(0.0, 0.0)) else np.c_[X.ravel(), Y.ravel(),
                                                                                            f(X.ravel(), Y.ravel())]
    idx = np.arange((m + 1) ** 2).reshape(m + 1, m + 1)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel()
    return verts, np.r_[np.c_[a, b, d], np.c_[a, d, c]]


def test_points_behind_a_plane_are_hidden_and_beside_it_seen():
    sc = Scene(View(90, -90))  # looking down the z axis
    sc.surface(*grid_mesh(lambda x, y: 0 * x, 0, 1, 10), "#cccccc")
    pts = np.array([[0.5, 0.5, 0.5], [0.5, 0.5, -0.5], [2.0, 0.5, -0.5], [0.5, 0.5, 0.0]])
    assert sc.hidden(pts).tolist() == [False, True, False, False]  # above, below, beside, on it


def test_an_edge_is_cut_exactly_at_the_silhouette():
    """A segment under the plane that runs out from under it: hidden up to x = 1 (t = 1/3), seen after -- the old
    depth buffer left sample-sized gaps (edges stopping short of the silhouette, 'in mid-air')."""
    sc = Scene(View(90, -90))
    sc.surface(*grid_mesh(lambda x, y: 0 * x, 0, 1, 10), "#cccccc")
    pieces = sc.edge_pieces(np.array([0.5, 0.5, -0.5]), np.array([2.0, 0.5, -0.5]))
    assert [h for _, _, h in pieces] == [True, False]
    assert pieces[0][1] == pytest.approx(1 / 3, abs=0.004)  # within the 0.3 % silhouette allowance
    assert pieces[0][0] == 0 and pieces[-1][1] == 1


def test_visibility_matches_a_hemisphere_analytically():
    """A hemisphere x = sqrt(1 - y^2 - z^2) seen along -x: a point is hidden exactly when it is inside the disc
    y^2 + z^2 < 1 on the screen and behind the surface (x < sqrt(1 - y^2 - z^2))."""
    def hemi(u, v):
        r = np.minimum(np.hypot(u, v), 1.0)
        ang = np.arctan2(v, u)
        y, z = r * np.cos(ang), r * np.sin(ang)
        return y * 0 + np.sqrt(np.maximum(1 - y**2 - z**2, 0)), y, z

    def disc(u, v):  # the unit disc from the square by a radial stretch (the mesh covers the disc)
        s = np.maximum(np.abs(u), np.abs(v))
        r = np.hypot(u, v)
        scale = np.where(r > 0, s / np.where(r > 0, r, 1), 0)
        return hemi(u * scale, v * scale)

    sc = Scene(View(0, 0))  # eye on +x
    sc.surface(*grid_mesh(disc, -1, 1, 40), "#cccccc")
    rng = np.random.default_rng(3)
    pts = rng.uniform([-1.5, -1.3, -1.3], [1.5, 1.3, 1.3], size=(2000, 3))
    rho = np.hypot(pts[:, 1], pts[:, 2])
    front = np.sqrt(np.maximum(1 - rho**2, 0))
    truth = (rho < 1) & (pts[:, 0] < front)
    clear = (np.abs(rho - 1) > 0.03) & (np.abs(pts[:, 0] - front) > 0.05)  # away from silhouette and surface
    assert clear.sum() > 1200
    assert (sc.hidden(pts)[clear] == truth[clear]).all()


def test_two_nets_hidden_parts_keep_their_own_colours_and_shading_is_smooth():
    sc = Scene(View(90, -90))
    verts, faces = grid_mesh(lambda x, y: 0.1 * np.sin(3 * x) * np.cos(2 * y), 0, 1, 12)
    sc.surface(verts, faces, "#9ecae1")
    below = np.array([[0.2, 0.2, -1.0], [0.8, 0.3, -1.0], [0.5, 0.8, -1.0]])
    sc.net(below, [(0, 1), (1, 2)], "#d62728", line_color="#d62728")
    sc.net(below + [0.05, 0.05, 0], [(0, 1), (1, 2)], "#1f5fbf", line_color="#1f5fbf")
    fig, ax = plt.subplots()
    sc.draw(ax)
    dashed = [c for c in ax.collections if isinstance(c, LineCollection) and len(c.get_segments())
              and c.get_linestyle()[0][1] is not None]
    colours = {tuple(np.round(c.get_colors()[0][:3], 3)) for c in dashed}
    assert len(dashed) == 2 and len(colours) == 2, colours  # the old renderer drew both in the same grey
    gour = [a for a in ax.get_children() if isinstance(a, GouraudTriangles)]
    assert len(gour) == 1
    # smooth: every vertex has one colour in all the triangles around it (no facets)
    tri_cols = gour[0].colors[..., :3]
    tri2 = gour[0].tris
    seen = {}
    for t in range(len(tri2)):
        for k in range(3):
            key = tuple(np.round(tri2[t, k], 9))
            seen.setdefault(key, []).append(tri_cols[t, k])
    spread = max(np.ptp(np.array(v), axis=0).max() for v in seen.values())
    assert spread < 1e-12
    plt.close(fig)
