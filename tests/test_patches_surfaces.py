import meshio
import mpmath
import numpy as np
import pytest
from flint import fmpq
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.claims.torus import CORRECTED, exact_torus, printed_net
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.labels import delta, index_of
from paper_repro.printed.torus import torus
from paper_repro.surfaces.fitting import fit_exact, fit_mp
from paper_repro.surfaces.mesh import export_mesh
from paper_repro.surfaces.models import cyclide_parts, cyclide_pieces, join_error
from paper_repro.surfaces.patch import Patch

from .strategies import alphas


def test_fit_exact_torus_matches_mp():
    alpha = rational_alpha((1, 3))
    exact = fit_exact(exact_torus(fmpq(2), fmpq(1)), 2, alpha)
    with mpmath.workdps(40):
        mp = fit_mp(lambda u, v, w: torus(u, v, w, 2, 1), 2, alpha.mp())
        assert max(abs(mpmath.mpf(int(x.p)) / int(x.q) - y) for r1, r2 in zip(exact, mp) for x, y in zip(r1, r2)) \
            < mpmath.mpf(10) ** -30


def test_fit_rejects_surface_outside_space():
    with pytest.raises(ValueError, match="not in the span"):
        fit_mp(lambda u, v, w: (mpmath.exp(u), v, w), 1, 1.0)


@given(alphas)
def test_printed_torus_net_is_exact_except_erratum(alpha):
    with mpmath.workdps(30):
        a = mpmath.mpf(alpha)
        comp = fit_mp(lambda u, v, w: torus(u, v, w, 4, 3), 2, a, dps=30)
        pr = printed_net(a, mpmath.mpf(4), mpmath.mpf(3))
        k = index_of(2)["b_{4,3,1}"]
        diff = np.array([[float(abs(pr[i, j] - comp[i, j])) for j in range(3)] for i in range(19)])
        diff_wo = diff.copy()
        diff_wo[k, 0] = 0
        assert diff_wo.max() < 1e-15
        assert abs(CORRECTED[("b_{4,3,1}", "x")][1](a, 4, 3) - comp[k, 0]) < 1e-20


def test_mesh_export_round_trip(tmp_path):
    patch = Patch(2, 1.0, np.random.default_rng(1).normal(size=(delta(2), 3)))
    v, f = patch.mesh(6)
    assert len(f) == 36 and len(v) == 28
    for ext in ("obj", "ply"):
        path = tmp_path / f"m.{ext}"
        export_mesh(path, v, f)
        back = meshio.read(path)
        assert np.allclose(back.points, v, atol=1e-12) and np.array_equal(back.cells[0].data, f)


def test_cyclide_one_square():
    al = np.pi / 2
    with mpmath.workdps(30):
        params = {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}
    pieces = cyclide_pieces(al, params, [0.0], [0.0])
    assert all(p.patch.weights.min() >= 0 for p in pieces)
    pts = sample_points(al, 20, seed=2)
    for p in pieces:
        parts = (cyclide_parts(U, V, 6, mpmath.sqrt(32), 2, 3) for U, V in p.uv(pts, al))
        ref = [[float(x / W) for x in X] for X, W in parts]
        assert np.abs(p.patch(pts) - np.array(ref)).max() < 1e-12
    assert join_error(pieces, al) < 1e-12


def test_rational_patch_with_equal_weights_is_polynomial():
    net = np.random.default_rng(3).normal(size=(delta(2), 3))
    pts = sample_points(1.2, 50, seed=0)
    assert np.abs(Patch(2, 1.2, net, weights=np.full(delta(2), 2.5))(pts) - Patch(2, 1.2, net)(pts)).max() < 1e-13


@given(st.integers(1, 3))
def test_mesh_resolution_validation(n):
    with pytest.raises(ValueError, match="resolution"):
        Patch(n, 1.0, np.zeros((delta(n), 3))).mesh(0)
