"""The adaptive tessellator (paper_repro.surfaces.tessellation; docs/tessellation.md).

* the derivative nets against Patch.derivative; the second-derivative bound against sampled second derivatives;
* the mesh within tol, a posteriori, at a barycentric grid in every triangle (28 points unless said otherwise):
  random patches n = 1..3 (deviation <= bound <= tol and deviation > tol/20), the torus piece (15 points, same
  three checks), a mixed-depth mesh (deviation <= tol), and n = 4 against an independent evaluator built from the
  paper's R/G/B formulas with its own mp normalizing coefficients (tests/independent_patch.py, 15 points);
* the premise of the constant 1/8: every emitted triangle lies in a right-isosceles cell of its leaf's grid;
* the float allowance of M against a 40-digit subdivision chain to depth 14;
* conformity across leaves; bad input refused with the parameter named."""

from __future__ import annotations

import math

import numpy as np
import pytest

from paper_repro.core.labels import delta
from paper_repro.core.subdivision import subdivide_to_depth
from paper_repro.surfaces.patch import Patch
from paper_repro.surfaces.tessellation import (
    MAX_N_TESSELLATE,
    _check_inputs,
    _tree,
    derivative_nets_t,
    rounding_factor,
    second_derivative_bound,
    second_derivative_nets,
    tessellate,
)
from tests import independent_patch


def _deviation(mesh, patch, k: int = 6) -> float:
    """max |s(x) - mesh(x)| over a barycentric grid of k steps ((k + 1)(k + 2)/2 points) in every triangle (x the
    parameter point); ``patch`` maps ``(P, 3)`` parameter points (u, v, w) to surface points."""
    bary = np.array([(i / k, j / k, 1 - (i + j) / k) for i in range(k + 1) for j in range(k + 1 - i)])
    tri = mesh.triangles
    par = np.einsum("sk,fkd->fsd", bary, mesh.params[tri]).reshape(-1, 3)
    lin = np.einsum("sk,fkd->fsd", bary, mesh.points[tri]).reshape(-1, mesh.points.shape[1])
    return float(np.linalg.norm(np.asarray(patch(par), dtype=np.float64) - lin, axis=1).max())


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
    dev = _deviation(mesh, piece, k=4)
    assert 1e-4 / 20 < dev <= mesh.bound <= 1e-4
    _conforming(mesh, np.pi / 2)


def test_order_4_against_an_independent_evaluator():
    """n = 4 (beyond the paper's proven non-negativity, n <= 3): the surface values come from the independent
    evaluator (paper's R/G/B formulas, its own normalizing coefficients solved in mp), not from Patch: the vertices
    agree with it, and the mesh is within its bound and tol at 15 points in every triangle, not absurdly fine."""
    n, alpha, tol = 4, 1.0, 2e-2
    net = np.random.default_rng(44).normal(size=(delta(n), 3))
    coef, residual = independent_patch.coefficients(n, alpha)
    assert residual < 1e-30 and (coef > 0).all()
    mesh = tessellate(net, n, alpha, tol, leaf_resolution=8)
    assert mesh.depth >= 1 and mesh.fans > 0

    def truth(par):
        return independent_patch.evaluate(net, n, alpha, par[:, :2], dtype=np.float64)

    scale = np.abs(mesh.points).max()
    assert np.abs(truth(mesh.params) - mesh.points).max() < 1e-13 * scale
    dev = _deviation(mesh, truth, k=4)
    assert tol / 20 < dev <= mesh.bound <= tol
    _conforming(mesh, alpha)


def test_every_triangle_lies_in_a_right_isosceles_cell():
    """The premise of the constant 1/8 (docs/tessellation.md, Lemma B): every triangle of the mesh, grid cell or fan
    triangle, has its three vertices in the disc of radius l/2 about the hypotenuse midpoint of the grid cell of its
    leaf that contains its centroid (l the cell's hypotenuse).  Checked on a mesh with leaves of several depths,
    both orientations and fans."""
    net = np.zeros((delta(2), 3))
    net[5] = (0.0, 0.0, 3.0)
    alpha, tol, max_depth = 1.5, 1e-3, 10
    mesh = tessellate(net, 2, alpha, tol, leaf_resolution=4, max_depth=max_depth)
    assert mesh.fans > 0 and (mesh.depth >= 2)
    arr, *_ = _check_inputs(net, 2, alpha, tol, 4, max_depth, 4_000_000)
    leaves = _tree(arr, 2, alpha, tol - 1e-13 * float(np.abs(arr).max()), 4, max_depth, 4_000_000)
    unit = alpha / (1 << (max_depth + 1))
    side = ((1 << (max_depth + 1)) >> leaves.level).astype(np.float64)
    assert (leaves.sign == -1).any() and len(set(leaves.level.tolist())) >= 2
    uv = mesh.params[:, :2] / unit
    tri = uv[mesh.triangles]                                  # (F, 3, 2) in units alpha / 2^(max_depth + 1)
    centre = tri.mean(axis=1)
    checked = np.zeros(len(tri), dtype=bool)
    for i in range(len(leaves.level)):
        s, g = float(leaves.sign[i]), side[i] / float(leaves.steps[i])
        p = s * (centre[:, 0] - leaves.a[i]) / g                # local grid coordinates of the centroids
        q = s * (centre[:, 1] - leaves.b[i]) / g
        inside = (p > 0) & (q > 0) & (p + q < leaves.steps[i]) & ~checked
        ci, cj = np.floor(p[inside]), np.floor(q[inside])
        up = (p[inside] - ci) + (q[inside] - cj) < 1
        # hypotenuse midpoint of the cell: (i + 1/2, j + 1/2) for both the up and the down cell
        mid = np.column_stack([leaves.a[i] + s * g * (ci + 0.5), leaves.b[i] + s * g * (cj + 0.5)])
        radius = g * math.sqrt(2) / 2
        dist = np.linalg.norm(tri[inside] - mid[:, None, :], axis=2).max(axis=1)
        assert (dist <= radius * (1 + 1e-9)).all(), (i, float(dist.max() / radius), int(up.sum()))
        checked[np.nonzero(inside)[0]] = True
    assert checked.all()


def test_rounding_allowance_covers_the_measured_error_of_m():
    """M of float64 sub-nets against a 40-digit chain (the middle and the u corner sub-triangle, repeated to depth 14,
    n = 2, alpha = 3): at every depth k the relative error of M is at most 1/100 of the allowance
    rounding_factor(k) - 1 (it grows like 4^k eps, docs/tessellation.md §3).  The margin 100 at n = 2 stands for
    about 30 at n = 6, whose errors the referee measured about 3 times larger (rel / (4^k eps) up to 4.2 against
    1.3 here).  Measured: worst ratio 0.0029 (depth 13); the former constant allowance 1e-6 gives 0.032 at depth 14
    and fails."""
    import mpmath

    from paper_repro.core.half_angle_matrices import derivative_nets
    from paper_repro.core.normalization import scaled_float_vector
    from paper_repro.core.subdivision import subdivision_matrices

    n, alpha, dps = 2, 3.0, 40
    net = np.random.default_rng(1).normal(size=(delta(n), 3))
    worst = []
    with mpmath.workdps(dps):
        for part in (0, 3):
            q_float = net.copy()
            q_mp = np.array([[mpmath.mpf(float(x)) for x in row] for row in net], dtype=object)
            beta = alpha
            for k in range(1, 15):
                q_float = subdivision_matrices(n, beta)[part] @ q_float
                q_mp = subdivision_matrices(n, beta, arith="mp", dps=dps)[part].dot(q_mp)
                beta /= 2
                m_float = float(second_derivative_bound(q_float, n, beta)[0])
                centred = q_mp - np.array([sum(q_mp[:, j]) / len(q_mp) for j in range(3)], dtype=object)
                coef = np.array([mpmath.mpf(x) for x in scaled_float_vector(n, beta)], dtype=object)[:, None]
                scale = 1 / (2 * mpmath.sin(mpmath.mpf(beta) / 2))

                def d(p, coef=coef, scale=scale, beta=beta):
                    qu, qv = derivative_nets(n, beta, coef * p, arith="mp")
                    return qu * scale / coef, qv * scale / coef

                du, dv = d(centred)
                duu, duv = d(du)
                dvv = d(dv)[1]
                m = [max(mpmath.sqrt(sum(x ** 2 for x in row)) for row in x) for x in (duu, duv, dvv)]
                m_mp = float((m[0] + m[2]) / 2 + mpmath.sqrt(((m[0] - m[2]) / 2) ** 2 + m[1] ** 2))
                rel = abs(m_float - m_mp) / m_mp
                worst.append((rel / (rounding_factor(k) - 1), part, k, rel))
    assert max(worst)[0] <= 0.01, max(worst)


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
