"""Routes the library's tests never ran (found by a mutation test of the library code): each test here fails on a
mutant that survived before -- the exact elevation route, the child-process certified solve and its counts, the
mesh and point validation at their boundaries, huge exact weights, the mp product matrix at tiny alpha, the rational
derivative in exact and mp arithmetic, the cotangent guard and rational_alpha_near."""

from __future__ import annotations

import numpy as np
import pytest
from flint import fmpq

from paper_repro.core.domain import RationalAngle, rational_alpha
from paper_repro.core.labels import delta


def test_elevation_with_a_rational_angle_is_the_exact_route():
    from paper_repro.core.elevation import elevate, elevation_matrix, elevation_matrix_exact

    alpha = rational_alpha(fmpq(1, 3))
    e = elevation_matrix(2, alpha)
    exact = np.array([[float(x) for x in row] for row in elevation_matrix_exact(2, alpha)])
    assert e.shape == (delta(3), delta(2)) and np.array_equal(e, exact)  # exact, then rounded once
    assert np.abs(e - elevation_matrix(2, float(alpha))).max() < 1e-15
    net = np.random.default_rng(3).normal(size=(delta(2), 3))
    assert np.abs(elevate(net, 2, alpha) - exact @ net).max() < 1e-13
    assert np.abs(elevate(net, 2, alpha, times=2) - elevate(elevate(net, 2, alpha), 3, alpha)).max() == 0


def test_certified_solve_in_a_child_process_gives_the_same_matrix_and_its_counts(monkeypatch):
    from paper_repro.core import elevation as el

    e0, prec0, lost0, solves0 = el.certified_solve(1, 1.0, child=False)
    monkeypatch.setattr(el, "CHILD_WORK", 0)  # every solve goes to a child process
    e1, prec1, lost1, solves1 = el.certified_solve(1, 1.0, child=True)
    assert np.array_equal(e0, e1) and (prec0, lost0, solves0) == (prec1, lost1, solves1)
    assert solves0 >= 1 and prec0 >= el.start_precision(1, 1.0) and 0 <= lost0 <= prec0 - 64
    assert prec0 - lost0 >= 64  # certified to 64 bits at least (a 63-bit result is not certified)


def test_merge_meshes_refuses_a_face_index_equal_to_the_vertex_count():
    from paper_repro.surfaces.patch import merge_meshes

    v = np.eye(3)
    assert merge_meshes([(v, np.array([[0, 1, 2]]))])[1].tolist() == [[0, 1, 2]]
    with pytest.raises(ValueError, match="faces must index its vertices 0..2"):
        merge_meshes([(v, np.array([[0, 1, 3]]))])
    with pytest.raises(ValueError, match="faces must index"):
        merge_meshes([(v, np.array([[-1, 1, 2]]))])


def test_points_validation_at_its_edges():
    from paper_repro.core.domain import check_points

    with pytest.raises(ValueError, match=r"P >= 1, got shape \(0, 3\)"):
        check_points(np.zeros((0, 3)), 1.0)  # documented: at least one point
    with pytest.raises(ValueError):
        check_points(np.zeros((0, 2)), 1.0)
    ok = check_points([[0.5, 0.25, 0.25]], 1.0)
    assert ok.shape == (1, 3)
    with pytest.raises(ValueError):
        check_points([[0.5, 0.25, 0.26]], 1.0)  # u + v + w = 1.01


def test_huge_exact_weights_give_the_exact_rational_patch():
    """A rational patch does not change when every weight is multiplied by one factor (here 10^200): exactly."""
    from paper_repro.core.domain import sample_rational_points
    from paper_repro.surfaces.patch import Patch

    n, d = 1, delta(1)
    alpha = rational_alpha(fmpq(1, 2))
    net = np.array([[fmpq(k), fmpq(k * k)] for k in range(d)], dtype=object)
    w = np.array([fmpq(k % 3 + 1) for k in range(d)], dtype=object)
    pts = sample_rational_points(alpha, 4, seed=2)
    a = Patch(n, alpha, net, weights=w * 10**200, arith="exact")(pts)
    b = Patch(n, alpha, net, weights=w, arith="exact")(pts)
    assert np.asarray(a).tolist() == np.asarray(b).tolist()
    c = Patch(n, alpha, net, weights=np.array([x * 10**200 if k else x for k, x in enumerate(w)], dtype=object),
              arith="exact")(pts)
    assert np.asarray(c).tolist() != np.asarray(b).tolist()  # one huge weight does change the patch


def test_product_matrix_in_mp_is_not_clamped_at_tiny_alpha():
    import mpmath

    from paper_repro.core.half_angle_matrices import ALPHA_TINY, product_matrix

    with mpmath.workdps(260):  # E(alpha) = E(0) + O(alpha^2): entries at 1e-300 and 1e-100 differ near 1e-200
        tiny = product_matrix(1, 1, mpmath.mpf("1e-300"), "mp")
        clamp = product_matrix(1, 1, mpmath.mpf(ALPHA_TINY), "mp")
        diff = max(abs(x - y) for x, y in zip(tiny.ravel(), clamp.ravel()))
    assert mpmath.mpf("1e-240") < diff < mpmath.mpf("1e-150")  # mp is not clamped to ALPHA_TINY


@pytest.mark.parametrize("arith", ["exact", "mp"])
def test_derivative_of_a_rational_patch_in_exact_and_mp(arith):
    import mpmath

    from paper_repro.core.domain import sample_rational_points
    from paper_repro.surfaces.patch import Patch

    n, alpha = 1, rational_alpha(fmpq(1, 3))
    rng = np.random.default_rng(5)
    net = np.array([[fmpq(int(x)) for x in row] for row in rng.integers(-5, 6, size=(delta(n), 3))], dtype=object)
    w = np.array([fmpq(int(x)) for x in rng.integers(1, 4, size=delta(n))], dtype=object)
    pts = sample_rational_points(alpha, 2, seed=1)
    p = Patch(n, alpha, net, weights=w, arith=arith)
    f = Patch(n, float(alpha), np.array(net, dtype=float), weights=np.array(w, dtype=float))
    got = np.array(p.derivative(pts, "u"), dtype=object)
    want = f.derivative(pts.uvw_float(), "u")
    assert np.abs(np.array([[float(x) for x in row] for row in got]) - want).max() < 1e-10
    # the quotient rule is exercised: doubling every weight changes nothing, changing one weight changes the result
    p2 = Patch(n, alpha, net, weights=w * 2, arith=arith)
    assert np.array_equal(np.array(p2.derivative(pts, "u"), dtype=object).astype(str), got.astype(str)) or arith == "mp"
    w3 = w.copy()
    w3[0] = w3[0] + 1
    p3 = Patch(n, alpha, net, weights=w3, arith=arith)
    with mpmath.workdps(30):
        assert np.abs(np.array([[float(x) for x in row] for row in np.array(p3.derivative(pts, "u"), dtype=object)])
                      - want).max() > 1e-6


def test_cotangent_guard_fires_on_a_member_without_the_sine_factor():
    from paper_repro.core.half_angle_rules import cotangent
    from paper_repro.core.labels import exponent_matrix

    n = 2
    e = exponent_matrix(n)
    g = next(k for k in range(delta(n)) if e[k][2] == 0)  # no factor sin(v/2)
    with pytest.raises(ValueError, match="has no factor sin"):
        cotangent(n, 1, g)


def test_rational_alpha_near():
    from paper_repro.core.elevation import rational_alpha_near

    r = rational_alpha_near(1.0, 1000)
    assert isinstance(r, RationalAngle) and abs(float(r) - 1.0) < 4 * 4e-6  # tan(alpha/4) within 1/2000
    assert r.t.q <= 1000
    assert float(rational_alpha_near(1.0, 10**9)) == pytest.approx(1.0, abs=1e-12)
    with pytest.raises(ValueError):
        rational_alpha_near(4.0)
