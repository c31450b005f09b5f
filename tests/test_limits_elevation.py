import numpy as np
import pytest
from flint import fmpq
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.claims.limits_claims import run_conversion
from paper_repro.claims.order_elevation import printed_matrix
from paper_repro.core.domain import sample_points
from paper_repro.core.elevation import elevate, elevation_matrix_exact
from paper_repro.core.labels import delta, united_system
from paper_repro.surfaces.patch import Patch, net_from_labels
from paper_repro.theory.limits import bernstein_eval, bezier_limit, conversion_matrix, limit_degree

from .strategies import alphas, rational_alphas


@given(st.integers(1, 5))
def test_conversion_rows_are_affine(n):
    idx, w = conversion_matrix(n)
    assert all(sum(row, fmpq(0)) == 1 for row in w)
    assert limit_degree(n) == 3 * n - 1


@pytest.mark.parametrize("n", [1, 2, 3])
def test_patch_tends_to_bezier_triangle(n):
    rng = np.random.default_rng(n)
    net = rng.normal(size=(delta(n), 3))
    N, bez = bezier_limit(net, n)
    bary = np.random.default_rng(0).dirichlet(np.ones(3), size=50)
    errs = []
    for alpha in (0.04, 0.02):
        errs.append(np.max(np.abs(Patch(n, alpha, net).at_barycentric(bary) - bernstein_eval(N, bary, bez))))
    assert errs[1] < errs[0] / 3.5  # order-2 convergence: halving alpha divides the error by ~4


@given(st.integers(1, 3), alphas, st.integers(0, 2**31 - 1))
def test_elevation_preserves_patch(n, alpha, seed):
    net = np.random.default_rng(seed).normal(size=(delta(n), 3))
    pts = sample_points(alpha, 30, seed=1)
    up = elevate(net, n, alpha)
    assert up.shape == (delta(n + 1), 3)
    assert np.max(np.abs(Patch(n, alpha, net)(pts) - Patch(n + 1, alpha, up)(pts))) < 1e-9 * (1 + np.abs(net).max())


@given(rational_alphas())
def test_printed_elevation_exact(alpha):
    assert printed_matrix(alpha) == elevation_matrix_exact(1, alpha)


def test_conversion_errata_found():
    out = run_conversion()
    assert out.passed
    assert sorted(e["item"] for e in out.errata) == ["p_{2,1,5}", "p_{3,2,3}", "p_{8,8,0}"]
    fixed = {e["item"]: e["corrected"] for e in out.errata}
    assert fixed["p_{8,8,0}"].startswith("p_{8,0,0}")
    assert "r_{6,2,1}" in fixed["p_{2,1,5}"] and "1/28 r_{6,3,0}" in fixed["p_{3,2,3}"]


def test_bad_nets_and_weights():
    with pytest.raises(ValueError, match="shape"):
        Patch(2, 1.0, np.zeros((18, 3)))
    with pytest.raises(ValueError, match="finite"):
        Patch(1, 1.0, np.full((7, 3), np.nan))
    pts = {lab.control_point: [0.0, 0.0, float(k)] for k, lab in enumerate(united_system(1))}
    assert net_from_labels(pts, 1).shape == (7, 3)
    with pytest.raises(ValueError, match="missing"):
        net_from_labels({k: v for k, v in list(pts.items())[1:]}, 1)
    with pytest.raises(ValueError, match="unknown"):
        net_from_labels({**pts, "r_{4,4,0}": [0, 0, 0]}, 1)
    with pytest.raises(ValueError, match="conflicts"):
        net_from_labels({**pts, "r_{2,0,0}": [9.0, 9.0, 9.0]}, 1)
    with pytest.raises(ValueError, match="weights"):
        Patch(1, 1.0, np.zeros((7, 3)), weights=-np.ones(7))
    with pytest.raises(ValueError, match="weights"):
        Patch(1, 1.0, np.zeros((7, 3)), weights=np.zeros(7))


def test_claim_order_elevation_reads_the_printed_rows_from_the_transcription():
    """No retyped copy of Example exmp:degree_elevation_from_1_to_2: a changed transcribed weight changes the printed
    matrix the claim compares with the exact elevation."""
    from flint import fmpq

    from paper_repro.claims.order_elevation import printed_matrix
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.elevation import elevation_matrix_exact
    from paper_repro.printed.lines import substituted, verbatim

    a = rational_alpha(fmpq(1, 3))
    exact = elevation_matrix_exact(1, a)
    assert printed_matrix(a) == [list(r) for r in exact]
    lid = "sec7-elev-r430"
    text = verbatim(lid)
    assert "\\frac{1}{2}" in text
    with substituted({lid: text.replace("\\frac{1}{2}", "\\frac{1}{3}", 1)}):
        assert printed_matrix(a) != [list(r) for r in exact]
