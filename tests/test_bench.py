"""Speed benchmarks (no wall-clock asserts); run with `make bench`."""

import pytest

from paper_repro.core.basis import evaluate
from paper_repro.core.domain import rational_alpha, sample_points, sample_rational_points

pytestmark = pytest.mark.benchmark


def test_bench_float_n3_10k_points(benchmark):
    pts = sample_points(1.2, 10_000, seed=0)
    out = benchmark(evaluate, 3, 1.2, pts)
    assert out.shape == (10_000, 37)


def test_bench_modp_n10(benchmark):
    alpha = rational_alpha((1, 3))
    pts = sample_rational_points(alpha, 331, seed=0)
    out = benchmark(evaluate, 10, alpha, pts, "modp")
    assert out.shape == (331, 331)


@pytest.mark.parametrize("tol", [1e-5, 1e-6])
def test_bench_tessellate_torus_piece(benchmark, tol):
    """The torus piece of Example exmp:torus (radii 2 and 1, alpha = pi/2) tessellated to tol
    (docs/tessellation.md §3: 1e-6 gives about 1.4 M vertices)."""
    import numpy as np

    from paper_repro.surfaces.models import torus_pieces
    from paper_repro.surfaces.tessellation import tessellate

    net = np.asarray(torus_pieces(np.pi / 2, 2.0, 1.0, [0.0], [0.0])[0].patch.net)
    tessellate(net, 2, np.pi / 2, 1e-3)  # the subdivision matrices and the kernels, outside the timing
    mesh = benchmark(tessellate, net, 2, np.pi / 2, tol)
    assert mesh.bound <= tol
