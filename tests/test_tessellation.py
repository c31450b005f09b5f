"""The adaptive tessellator (paper_repro.surfaces.tessellation; docs/tessellation.md): the derivative nets against
Patch.derivative, the second-derivative bound against sampled second derivatives, the mesh within tol of the surface
(dense sampling, a posteriori), conformity across leaves, and bad input refused with the parameter named."""

from __future__ import annotations

import math

import numpy as np
import pytest

from paper_repro.core.labels import delta
from paper_repro.core.subdivision import subdivide_to_depth
from paper_repro.surfaces.patch import Patch
from paper_repro.surfaces.tessellation import (
    MAX_N_TESSELLATE,
    derivative_nets_t,
    second_derivative_bound,
    second_derivative_nets,
    tessellate,
)


def _deviation(mesh, patch: Patch, k: int = 6) -> float:
    """max |s(x) - mesh(x)| over a barycentric grid of k steps in every triangle (x the parameter point)."""
    bary = np.array([(i / k, j / k, 1 - (i + j) / k) for i in range(k + 1) for j in range(k + 1 - i)])
    tri = mesh.triangles
    par = np.einsum("sk,fkd->fsd", bary, mesh.params[tri]).reshape(-1, 3)
    lin = np.einsum("sk,fkd->fsd", bary, mesh.points[tri]).reshape(-1, mesh.points.shape[1])
    return float(np.linalg.norm(patch(par) - lin, axis=1).max())


def _conforming(mesh, alpha: float) -> None:
    """Every edge in at most two triangles; an edge in one triangle lies on the boundary of Omega^alpha; all
    triangles non-degenerate with one orientation in the (u, v) plane."""
    tri, uv = mesh.triangles, mesh.params[:, :2]
    e1, e2 = uv[tri[:, 1]] - uv[tri[:, 0]], uv[tri[:, 2]] - uv[tri[:, 0]]
    area = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    assert (np.sign(area) == np.sign(area[0])).all() and np.abs(area).min() > 0
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    keys, count = np.unique(edges[:, 0] * len(uv) + edges[:, 1], return_counts=True)
    assert count.max() == 2
    single = np.column_stack(np.divmod(keys[count == 1], len(uv)))
    p = mesh.params
    eps = 1e-12 * alpha
    on_side = ((np.abs(p[single[:, 0]]) < eps) & (np.abs(p[single[:, 1]]) < eps)).any(axis=1)
    assert on_side.all(), f"{int((~on_side).sum())} open edges inside the domain (cracks)"
    # the boundary edges cover the three sides exactly once: total length 2 alpha + sqrt(2) alpha in (u, v)
    length = np.linalg.norm(uv[single[:, 0]] - uv[single[:, 1]], axis=1).sum()
    assert abs(length - (2 + math.sqrt(2)) * alpha) < 1e-9 * alpha


def test_derivative_nets_match_patch_derivative():
    rng = np.random.default_rng(3)
    for n in (1, 2, 3):
        net = rng.normal(size=(delta(n), 3))
        beta = 0.7
        du, dv = derivative_nets_t(net[None], n, beta)
        patch = Patch(n, beta, net)
        x = rng.dirichlet([1, 1, 1], 40) * beta
        scale = np.abs(patch.derivative(x, "u")).max()
        assert np.abs(Patch(n, beta, du[0])(x) - patch.derivative(x, "u")).max() < 1e-12 * scale
        assert np.abs(Patch(n, beta, dv[0])(x) - patch.derivative(x, "v")).max() < 1e-12 * scale


@pytest.mark.parametrize("n, alpha", [(1, 1.0), (2, 2.5), (3, 0.6)])
def test_second_derivative_bound_holds_and_tightens(n, alpha):
    """M bounds every sampled |D^2 s[e, e]| (e unit in (u, v)); on the sub-nets of depth 3 the bound over the
    leaves is within a factor 1.6 of the sampled maximum (measured: the derivative nets converge)."""
    rng = np.random.default_rng(n)
    net = rng.normal(size=(delta(n), 3))
    duu, duv, dvv = (Patch(n, alpha, x[0]) for x in second_derivative_nets(net[None], n, alpha))
    x = rng.dirichlet([0.5, 0.5, 0.5], 400) * alpha
    theta = rng.uniform(0, 2 * np.pi, 400)[:, None]
    second = np.cos(theta) ** 2 * duu(x) + 2 * np.sin(theta) * np.cos(theta) * duv(x) + np.sin(theta) ** 2 * dvv(x)
    true = np.linalg.norm(second, axis=1).max()
    m_root = float(second_derivative_bound(net, n, alpha)[0])
    assert true <= m_root
    leaves = subdivide_to_depth(net, n, alpha, 3)
    m_leaves = second_derivative_bound(np.array(list(leaves.values())), n, alpha / 8).max()
    assert true <= m_leaves * (1 + 1e-9) and m_leaves < 1.6 * true


@pytest.mark.parametrize("n, alpha, tol", [(1, 1.0, 1e-3), (2, 3.0, 1e-3), (3, 2.0, 1e-3), (2, 0.05, 1e-3)])
def test_random_patch_within_tol(n, alpha, tol):
    net = np.random.default_rng(10 * n).normal(size=(delta(n), 3))
    mesh = tessellate(net, n, alpha, tol, leaf_resolution=8)
    dev = _deviation(mesh, Patch(n, alpha, net))
    assert dev <= mesh.bound <= tol
    assert dev > tol / 20  # not absurdly fine: the bound is within a factor 20 of the measured deviation
    _conforming(mesh, alpha)


def test_mixed_depths_are_crack_free():
    """A net with one far point: leaves of several depths and steps meet; fans close the T-junctions."""
    net = np.zeros((delta(2), 3))
    net[5] = (0.0, 0.0, 3.0)
    mesh = tessellate(net, 2, 1.5, 1e-3, leaf_resolution=4)
    assert mesh.fans > 0 and mesh.depth >= 2
    _conforming(mesh, 1.5)
    assert _deviation(mesh, Patch(2, 1.5, net)) <= 1e-3


def test_torus_piece():
    """Section 6's torus (Example exmp:torus, radii 2 and 1, alpha = pi/2): within tol, checked densely."""
    from paper_repro.surfaces.models import torus_pieces

    piece = torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])[0].patch
    mesh = tessellate(piece.net, 2, np.pi / 2, 1e-4)
    assert _deviation(mesh, piece, k=4) <= mesh.bound <= 1e-4
    _conforming(mesh, np.pi / 2)


@pytest.mark.parametrize("kwargs, name", [
    ({"n": 0}, "n"), ({"n": MAX_N_TESSELLATE + 1}, "n"), ({"n": "2"}, "n"), ({"n": 2.0}, "n"),
    ({"alpha": 0.0}, "alpha"), ({"alpha": 4.0}, "alpha"), ({"alpha": float("nan")}, "alpha"), ({"alpha": 1j}, "alpha"),
    ({"tol": 0.0}, "tol"), ({"tol": -1e-3}, "tol"), ({"tol": float("nan")}, "tol"), ({"tol": float("inf")}, "tol"),
    ({"tol": "1e-3"}, "tol"), ({"tol": 1e-20}, "tol"), ({"tol": [1e-3]}, "tol"),
    ({"net": np.zeros((7, 3))}, "net"), ({"net": np.full((19, 3), np.nan)}, "net"), ({"net": "net"}, "net"),
    ({"leaf_resolution": 0}, "leaf_resolution"), ({"max_depth": -1}, "max_depth"), ({"max_depth": 99}, "max_depth"),
    ({"max_vertices": 10, "tol": 1e-6}, "max_vertices"),
])
def test_bad_input_refused(kwargs, name):
    args = {"net": np.random.default_rng(0).normal(size=(19, 3)), "n": 2, "alpha": 1.0, "tol": 1e-3}
    args.update(kwargs)
    with pytest.raises((ValueError, TypeError)) as exc:
        tessellate(**args)
    assert name in str(exc.value)


def test_max_depth_range_is_0_to_14():
    """docs/tessellation.md: max_depth outside 0..14 is refused; both ends of the range are accepted."""
    net = np.random.default_rng(0).normal(size=(19, 3))
    with pytest.raises(ValueError, match="max_depth"):
        tessellate(net, 2, 1.0, 1e-3, max_depth=15)
    for depth in (0, 14):  # a coarse tol: the tree stops long before the largest depth
        mesh = tessellate(net, 2, 1.0, 10.0, max_depth=depth)
        assert mesh.bound <= 10.0
