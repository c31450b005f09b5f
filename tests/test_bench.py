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
