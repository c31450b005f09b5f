"""Tests that kill the mutants of the library code that survived ``tools/mutate_code.py`` (issue 39, item 6).

Each test asserts a value computed independently of the code under test (by hand, by another route, or by a
definition of the paper) at small n, so the fast suite stays fast.
"""

from __future__ import annotations

import numpy as np
import pytest
from flint import fmpq

from paper_repro.core.domain import RationalAngle, rational_alpha
from paper_repro.core.labels import delta

# --- core/labels.py --------------------------------------------------------------------------------------------


def test_parse_label_reads_every_even_first_index_and_refuses_odd_ones():
    from paper_repro.core.labels import BasisLabel, parse_label

    # R_{2n, 2n - i, j}: the first index is 2n (the order n), by the paper's naming of the systems
    for two_n in (2, 4, 6, 8):
        lab = parse_label(f"R_{{{two_n},{two_n},0}}")  # i = 0, j = 0: the corner function
        assert lab == BasisLabel("R", two_n // 2, 0, 0)
    for bad in ("R_{3,3,0}", "R_{5,4,1}", "R_{0,0,0}"):
        with pytest.raises(ValueError, match="first index must be 2n"):
            parse_label(bad)


def test_names_of_the_normalizing_coefficient_and_control_point():
    from paper_repro.core.labels import BasisLabel

    lab = BasisLabel("G", 2, 1, 1)  # G_{4,3,1}: its coefficient is g_{4,3,1} (paper, Section 4)
    assert lab.paper == "G_{4,3,1}" and lab.coefficient == "g_{4,3,1}" and lab.control_point == "g_{4,3,1}"
    centre = BasisLabel("B", 2, 2, 2)  # the centre is always written R_{2n,n,n}
    assert centre.coefficient == "r_{4,2,2}"


def test_parse_label_refuses_a_non_string():
    from paper_repro.core.labels import parse_label

    with pytest.raises(TypeError, match="label must be a string"):
        parse_label(431)


def test_exponent_matrix_is_the_united_system_and_read_only():
    from paper_repro.core.labels import delta, exponent_matrix, exponents, united_system

    e = exponent_matrix(2)
    assert e.shape == (delta(2), 6) and e.tolist() == [list(exponents(lab)) for lab in united_system(2)]
    with pytest.raises(ValueError):  # a cached array: a caller must not be able to change it
        e[0, 0] = 7


def test_variable_swap_for_every_pair_of_variables_by_values():
    from paper_repro.core.labels import exponent_matrix, variable_swap

    def values(n, x):  # f_k(x) = prod over SLOTS (sin u/2, cos u/2, sin v/2, ...) of trig^exponent
        trig = np.array([f(t / 2) for t in x for f in (np.sin, np.cos)])
        return np.prod(trig[None, :] ** exponent_matrix(n), axis=1)

    x = np.array([0.3, 0.5, 0.2])
    for n in (1, 2):
        for a in range(3):
            for b in range(3):
                if a == b:
                    with pytest.raises(ValueError, match="two different variables"):
                        variable_swap(n, a, b)
                    continue
                y = x.copy()
                y[[a, b]] = x[[b, a]]
                pi = variable_swap(n, a, b)
                assert sorted(pi.tolist()) == list(range(len(pi)))
                assert np.allclose(values(n, x)[pi], values(n, y), rtol=1e-14, atol=0)
    for bad in ((0, 3), (-1, 1)):
        with pytest.raises(ValueError):
            variable_swap(1, *bad)


# --- core/alphas.py --------------------------------------------------------------------------------------------


def test_alpha_strings_as_fractions_of_pi_and_numbers():
    import math
    from fractions import Fraction

    import mpmath

    from paper_repro.core.alphas import alpha_float, alpha_fraction_of_pi, alpha_mp

    assert alpha_fraction_of_pi("2pi/3") == Fraction(2, 3)
    assert alpha_fraction_of_pi(" pi / 4 ") == Fraction(1, 4)
    assert alpha_fraction_of_pi("pi") == Fraction(1, 1)
    assert alpha_fraction_of_pi("3*pi/5") == Fraction(3, 5)
    assert alpha_fraction_of_pi("0.7") is None
    with pytest.raises(ValueError, match="division by zero"):
        alpha_fraction_of_pi("pi/0")
    with mpmath.workdps(40):
        assert alpha_mp("2pi/3") == 2 * mpmath.pi / 3 and alpha_mp("0.7") == mpmath.mpf("0.7")
    assert alpha_float("pi/2") == math.pi / 2 and alpha_float(1.25) == 1.25
    for bad in ("pi", "4pi/3", "0", "-0.5", "one"):  # alpha must lie in (0, pi)
        with pytest.raises(ValueError):
            alpha_mp(bad)


# --- core/ordered.py -------------------------------------------------------------------------------------------


def test_ordered_matmul_is_the_exact_product_for_small_integers_and_refuses_other_shapes():
    from paper_repro.core.ordered import ordered_matmul

    rng = np.random.default_rng(5)
    a = rng.integers(-9, 10, size=(4, 5)).astype(float)
    b = rng.integers(-9, 10, size=(5, 3)).astype(float)
    exact = [[sum(int(a[i, k]) * int(b[k, j]) for k in range(5)) for j in range(3)] for i in range(4)]
    assert ordered_matmul(a, b).tolist() == exact  # small integers: every float operation is exact
    assert ordered_matmul(a[:, :1], b[:1]).tolist() == [[a[i, 0] * b[0, j] for j in range(3)] for i in range(4)]
    for x, y in ((a, b.T), (a[0], b), (a, b[:, 0])):
        with pytest.raises(ValueError, match="do not chain"):
            ordered_matmul(x, y)


# --- surfaces/limit.py -----------------------------------------------------------------------------------------


def test_bezier_order_is_bezier_packages_node_order():
    from math import comb

    from paper_repro.surfaces.limit import bezier_order

    for N in range(1, 6):
        order = bezier_order(N)
        assert len(order) == comb(N + 2, 2) and len(set(order)) == len(order)
        assert all(min(t) >= 0 and sum(t) == N for t in order)
        # bezier.Triangle's nodes: j (the power of t) outermost, then i (the power of s) increasing
        assert order[0] == (N, 0, 0) and order[N] == (0, N, 0) and order[-1] == (0, 0, N)
        assert order[N + 1] == (N - 1, 0, 1)


def test_bezier_triangle_evaluates_the_limit_net_as_a_bernstein_polynomial():
    pytest.importorskip("bezier")
    from math import factorial

    from paper_repro.surfaces.limit import bezier_nodes, bezier_triangle
    from paper_repro.theory.limits import bezier_limit

    n = 2
    net = np.random.default_rng(11).normal(size=(19, 3))
    N, bez = bezier_limit(net, n)
    assert N == 3 * n - 1
    tri = bezier_triangle(net, n)
    N2, nodes = bezier_nodes(net, n)
    assert N2 == N and nodes.shape == (3, (N + 1) * (N + 2) // 2) and nodes.flags.f_contiguous
    for s, t in ((0.2, 0.3), (0.0, 0.0), (0.6, 0.1), (0.0, 1.0)):
        x, y, z = 1 - s - t, s, t  # bezier's barycentric weights
        direct = sum(factorial(N) / (factorial(d) * factorial(e) * factorial(f)) * x**d * y**e * z**f * p
                     for (d, e, f), p in bez.items())
        assert np.allclose(tri.evaluate_cartesian(s, t)[:, 0], direct, atol=1e-12)


# --- core/collocation.py ---------------------------------------------------------------------------------------


def _line_system(ctx, xs_by_set, last=None):
    """y = 2x + 1 at the points of set k (the last one a verification row); ``last`` replaces its right-hand side."""
    def system(k):
        xs = xs_by_set[k]
        rhs = [2 * x + 1 for x in xs]
        if last is not None:
            rhs[-1] = last
        return ctx.asarray([[x, 1] for x in xs]), ctx.asarray([[y] for y in rhs])
    return system


def test_collocate_in_float_verifies_to_the_context_tolerance_or_to_rtol():
    from paper_repro.core.collocation import collocate
    from paper_repro.core.context import get_context

    ctx = get_context("float")
    sets = {0: [0.0, 1.0, 5.0]}
    res = collocate(ctx, _line_system(ctx, sets), m=2)
    assert np.allclose(res.solution.reshape(-1), [2.0, 1.0], rtol=0, atol=1e-15)
    assert (res.point_set, res.verified) == (0, 1)
    # the verification row y(5) = 11: off by 11e-12 (relative 1e-12) passes float's own check (|r| <= |A||x| 10^-9.6),
    # off by 11e-6 fails it; rtol replaces that tolerance in both directions
    near, far = 11 * (1 + 1e-12), 11 * (1 + 1e-6)
    assert collocate(ctx, _line_system(ctx, sets, near), m=2).verified == 1
    with pytest.raises(ArithmeticError, match=r"fails at the 1 verification point\(s\) of point set 0"):
        collocate(ctx, _line_system(ctx, sets, far), m=2)
    assert collocate(ctx, _line_system(ctx, sets, far), m=2, rtol=1e-5).verified == 1  # 11e-6 <= 1e-5 * 11
    with pytest.raises(ArithmeticError):
        collocate(ctx, _line_system(ctx, sets, far), m=2, rtol=1e-7)  # 11e-6 > 1e-7 * 11
    with pytest.raises(ArithmeticError):
        collocate(ctx, _line_system(ctx, sets, near), m=2, rtol=1e-14)
    # the scale is |A| |x| (or the right-hand side): a residual of 1e-5 * 11 with rtol 1e-5 x (|A||x| = 11) passes,
    # one of 2e-5 * 11 does not
    assert collocate(ctx, _line_system(ctx, sets, 11 * (1 + 0.9e-5)), m=2, rtol=1e-5).verified == 1
    with pytest.raises(ArithmeticError):
        collocate(ctx, _line_system(ctx, sets, 11 * (1 + 2e-5)), m=2, rtol=1e-5)


def test_collocate_exact_ignores_rtol_and_counts_singular_point_sets():
    from flint import fmpq

    from paper_repro.core.collocation import collocate, has_equal_rows
    from paper_repro.core.context import get_context

    ctx = get_context("exact")
    sets = {0: [0, 1, 5]}
    with pytest.raises(ArithmeticError, match="verification"):  # exact: any residual, whatever rtol says
        collocate(ctx, _line_system(ctx, sets, fmpq(11) + fmpq(1, 10**30)), m=2, rtol=1.0)
    calls = []

    def singular(k):  # two equal collocation rows in every point set
        calls.append(k)
        return ctx.asarray([[1, 1], [1, 1], [2, 1]]), ctx.asarray([[1], [1], [3]])

    with pytest.raises(ArithmeticError, match="singular for 3 point sets"):
        collocate(ctx, singular, m=2, attempts=3)
    assert calls == [0, 1, 2]
    calls.clear()
    with pytest.raises(ArithmeticError, match="singular for 5 point sets"):  # the documented default: 5 sets
        collocate(ctx, singular, m=2)
    assert calls == [0, 1, 2, 3, 4]
    fctx = get_context("float")
    calls.clear()
    with pytest.raises(ArithmeticError, match="singular for 2 point sets"):  # float: the solve itself says so
        collocate(fctx, singular, m=2, attempts=2)
    assert calls == [0, 1]
    unhashable = np.empty((2, 1), dtype=object)
    unhashable[0, 0], unhashable[1, 0] = [1], [1]  # equal rows, but lists cannot be hashed: no shortcut
    assert has_equal_rows(unhashable) is False
    assert has_equal_rows(np.array([[1, 2], [3, 4]])) is False


# --- core/basis.py ---------------------------------------------------------------------------------------------


def test_monomials_with_every_exponent_zero_are_ones_in_every_arithmetic():
    from flint import fmpq

    from paper_repro.core.basis import monomials
    from paper_repro.core.context import get_context

    for arith in ("exact", "float", "mp"):
        ctx = get_context(arith)
        trig = [ctx.asarray([fmpq(1, k + 2), fmpq(1, 3)]) for k in range(6)]  # slot k: 1/(k+2) and 1/3 (P = 2)
        with ctx.scope():
            out = monomials(np.zeros((3, 6), dtype=np.int64), trig, ctx)  # F = 3 constant functions
            assert out.shape == (2, 3) and all(float(x) == 1.0 for x in out.reshape(-1))
            one = monomials(np.array([[1, 0, 0, 2, 0, 0]]), trig, ctx)  # slot 0 times slot 3 squared
            assert one.shape == (2, 1) and np.allclose([float(x) for x in one[:, 0]], [1 / 50, 1 / 27], rtol=1e-15)


# --- surfaces/patch.py -----------------------------------------------------------------------------------------


def _points_on(alpha, count, seed=0):
    rng = np.random.default_rng(seed)
    bary = rng.dirichlet([1.0, 1.0, 1.0], size=count)
    return alpha * bary


@pytest.mark.parametrize("jit", [True, False], ids=["compiled", "numpy"])
@pytest.mark.parametrize("rational", [False, True], ids=["polynomial", "rational"])
def test_patch_float_routes_against_mp(jit, rational, monkeypatch):
    """Values, derivatives and normals of the float path (compiled kernel or numpy blocks) against the mp route
    (evaluate_normalized and basis_derivative, the quotient rule written out), on a net far from unit scale."""
    import paper_repro.surfaces.patch as pm

    if not jit:
        monkeypatch.setattr(pm, "jit_available", lambda: False)
    n, alpha = 2, 1.1
    rng = np.random.default_rng(7)
    net = rng.normal(size=(19, 3)) * 1e3 + 5e3  # off-centre and large: the power-of-two scalings matter
    weights = rng.uniform(0.5, 2.0, size=19) * 1e-200 if rational else None
    p = pm.Patch(n, alpha, net, weights=weights)
    pts = _points_on(alpha, 4)
    assert p.dimension == 3
    ref = np.array(p(pts, arith="mp", dps=30), dtype=float)
    assert np.allclose(p(pts), ref, rtol=1e-12, atol=1e-12 * 5e3)
    for d in ("u", "v", "w", (1.0, -3.0, 2.0), (0.0, 0.0, 0.0)):
        dref = np.array(p.derivative(pts, d, arith="mp", dps=30), dtype=float)
        assert np.allclose(p.derivative(pts, d), dref, rtol=1e-9, atol=1e-9 * np.abs(dref).max(initial=1.0)), d
    du = np.array(p.derivative(pts, "u", arith="mp", dps=30), dtype=float)
    dv = np.array(p.derivative(pts, "v", arith="mp", dps=30), dtype=float)
    cross = np.cross(du, dv)
    assert np.allclose(p.normals(pts), cross / np.linalg.norm(cross, axis=1)[:, None], rtol=0, atol=1e-9)
    # the mp derivative itself against a central difference of mp values along u (v fixed, w = alpha - u - v)
    h = 1e-12
    import mpmath

    with mpmath.workdps(40):
        q = np.array([[mpmath.mpf(float(x)) for x in row] for row in pts[:2]], dtype=object)
        qp, qm = q.copy(), q.copy()
        qp[:, 0] += h
        qp[:, 2] -= h
        qm[:, 0] -= h
        qm[:, 2] += h
        fd = (p(qp, arith="mp", dps=40) - p(qm, arith="mp", dps=40)) / (2 * h)
        assert np.allclose(np.array(fd, dtype=float), du[:2], rtol=1e-8)


def test_patch_boundary_curves_are_the_patch_on_its_edges():
    from paper_repro.surfaces.patch import Patch

    n, alpha = 2, 1.3
    net = np.random.default_rng(2).normal(size=(19, 2))
    p = Patch(n, alpha, net)
    t = np.array([0.0, 0.4, alpha])
    on_edge = {"v=0": np.column_stack([t, 0 * t, alpha - t]),  # t is u on v = 0
               "w=0": np.column_stack([alpha - t, t, 0 * t]),  # t is v on w = 0
               "u=0": np.column_stack([0 * t, alpha - t, t])}  # t is w on u = 0
    for edge, pts in on_edge.items():
        assert p.boundary_net(edge).shape == (2 * n + 1, 2)
        assert np.allclose(p.boundary_curve(edge, t), p(pts), rtol=0, atol=1e-13), edge
    with pytest.raises(ValueError, match="edge must be one of"):
        p.boundary_net("x=0")
    with pytest.raises(ValueError, match=r"t must lie in \[0, alpha\]"):
        p.boundary_curve("v=0", [alpha * 1.01])
    with pytest.raises(ValueError, match="t must be finite"):
        p.boundary_curve("v=0", [float("nan")])
    assert repr(p) == "<Patch n=2 alpha=1.3 dim=2>"
    assert repr(Patch(1, 1.0, np.zeros((7, 3)), weights=np.ones(7))) == "<rational Patch n=1 alpha=1 dim=3>"
    with pytest.raises(ValueError, match="normals need a 3-D control net"):
        p.normals([[0.5, 0.4, 0.4]])


# --- core/elevation.py -----------------------------------------------------------------------------------------


def test_precision_schedule_of_the_certified_solve():
    from paper_repro.core.elevation import certified_solve, next_precision, start_precision

    # documented: a solve that certified nothing doubles the precision; otherwise the bits lost (prec - bits)
    # plus 64 would just do, and 25 % more are taken, rounded up to whole 64-bit words
    assert next_precision(256, 0) == 512 and next_precision(128, -3) == 256
    for prec, bits in ((256, 40), (512, 10), (1024, 60), (192, 63)):
        nxt = next_precision(prec, bits)
        assert nxt % 64 == 0 and nxt >= prec - bits + 64 + 0.25 * (prec - bits)
        assert nxt < 1.25 * (prec - bits) + 96 + 64
    # the start: whole words, at least 96 bits above what a solve loses at alpha = 1 (<= 16 (n + 1), measured),
    # growing as alpha -> 0 and near pi
    for n in (1, 3, 10):
        s = start_precision(n, 1.0)
        assert s % 64 == 0 and s >= 16 * (n + 1) + 96
        assert start_precision(n, 1e-9) > start_precision(n, 1e-3) > s
        assert start_precision(n, np.pi - 1e-9) > s
    # one solve is enough at n = 1, alpha = 1 (docstring: "with 96 bits to spare one solve is enough")
    e, prec, lost, solves = certified_solve(1, 1.0, child=False)
    assert solves == 1 and prec == start_precision(1, 1.0) and 0 <= lost <= prec - 65
    assert np.allclose(e.sum(axis=1), 1.0, atol=1e-15) and e.min() >= -1e-18


def test_elevation_matrix_at_its_edges():
    from paper_repro.core.elevation import CACHE_MAX_N, elevation_matrix, elevation_matrix_exact
    from paper_repro.core.half_angle_matrices import ALPHA_TINY

    with pytest.raises(ValueError):
        elevation_matrix(1, rational_alpha(fmpq(0)))  # tan(alpha/4) = 0 is alpha = 0
    with pytest.raises(ValueError, match="open interval"):  # the same, past rational_alpha's own check
        elevation_matrix(1, RationalAngle(fmpq(0)))
    # below ALPHA_TINY the float closed form is taken at ALPHA_TINY: E(alpha) = E(0) + O(alpha^2)
    tiny = elevation_matrix(1, 1e-300)
    exact_small = elevation_matrix_exact(1, rational_alpha(fmpq(1, 10**40)))
    assert np.abs(tiny - np.array([[float(x) for x in row] for row in exact_small])).max() < 1e-15
    assert np.array_equal(tiny, elevation_matrix(1, ALPHA_TINY))
    # the returned array is the caller's: changing it does not change the next result (cache copy)
    e = elevation_matrix(2, 0.9)
    e[:] = 0
    assert elevation_matrix(2, 0.9).sum() == pytest.approx(delta(3))
    # beyond the cached orders the same closed form, rows summing to 1
    big = elevation_matrix(CACHE_MAX_N + 1, 1.0)
    assert big.shape == (delta(CACHE_MAX_N + 2), delta(CACHE_MAX_N + 1))
    assert np.abs(big.sum(axis=1) - 1).max() < 1e-13 and big.min() >= 0


def test_elevate_to_and_times():
    from paper_repro.core.elevation import elevate, elevation_matrix

    net = np.random.default_rng(1).normal(size=(delta(1), 2))
    assert np.array_equal(elevate(net, 1, 1.0, times=0), net) and np.array_equal(elevate(net, 1, 1.0, to=1), net)
    one = elevation_matrix(1, 1.0) @ net
    assert np.allclose(elevate(net, 1, 1.0), one, rtol=0, atol=1e-15)
    two = elevation_matrix(2, 1.0) @ one
    assert np.allclose(elevate(net, 1, 1.0, to=3), two, rtol=0, atol=1e-14)
    assert np.array_equal(elevate(net, 1, 1.0, to=3, times=2), elevate(net, 1, 1.0, times=2))
    with pytest.raises(ValueError, match="give to or times, not both"):
        elevate(net, 1, 1.0, to=3, times=1)
    with pytest.raises(ValueError):
        elevate(net, 1, 1.0, to=0)
    with pytest.raises(ValueError):
        elevate(net, 1, 4.0)
    # the same patch: values of the elevated net in order 3 equal the order-1 values
    from paper_repro.surfaces.patch import Patch

    pts = _points_on(1.0, 5, seed=3)
    assert np.allclose(Patch(3, 1.0, two)(pts), Patch(1, 1.0, net)(pts), rtol=0, atol=1e-13)


# --- core/domain.py --------------------------------------------------------------------------------------------


def test_rationals_angles_and_rational_points():
    import math
    from fractions import Fraction

    import mpmath

    from paper_repro.core.domain import RationalAngle, RationalPoints, _q

    for x, want in ((fmpq(2, 7), fmpq(2, 7)), (3, fmpq(3)), (Fraction(5, 9), fmpq(5, 9)), ((4, -6), fmpq(-2, 3)),
                    (" 1/3 ", fmpq(1, 3)), (0.375, fmpq(3, 8)), (np.int64(2), fmpq(2))):
        assert _q(x) == want
    with pytest.raises(ValueError, match=r"t = 1/0"):
        _q((1, 0))
    with pytest.raises(TypeError, match="tuple of length 3"):
        _q((1, 2, 3))
    with pytest.raises(TypeError, match="pair"):
        _q((1.5, 2))
    with pytest.raises(TypeError, match="pair"):
        _q((True, 2))
    with pytest.raises(ValueError, match="rational like"):
        _q("1/0")
    # tan(x/4) = t: sin(x/2) = 2t/(1+t^2), cos(x/2) = (1-t^2)/(1+t^2) (double-angle formulas)
    a = RationalAngle(fmpq(1, 3))
    assert a.sin_half == fmpq(3, 5) and a.cos_half == fmpq(4, 5)
    assert float(a) == pytest.approx(4 * math.atan(1 / 3), rel=1e-15)
    with mpmath.workdps(50):
        assert abs(a.mp() - 4 * mpmath.atan(mpmath.mpf(1) / 3)) < mpmath.mpf(10) ** -48
    assert RationalAngle(0).t == 0  # [0, pi): 0 is an angle (not a shape parameter: rational_alpha refuses it)
    for bad in (1, fmpq(-1, 5), fmpq(3, 2)):
        with pytest.raises(ValueError, match="0 <= t < 1"):
            RationalAngle(bad)
    with pytest.raises(ValueError, match="open interval"):
        rational_alpha(0)
    alpha = rational_alpha(fmpq(1, 2))
    pts = RationalPoints(alpha, (fmpq(1, 5), fmpq(1, 9)), (fmpq(1, 7), 0))
    assert len(pts) == 2
    quarter = pts.quarter_values()
    assert quarter[0] == [fmpq(5, 13), fmpq(9, 41)] and quarter[3] == [fmpq(24, 25), fmpq(1)]
    full = pts.half_angle_values()
    assert full[:4] == quarter
    for k in range(2):  # sin^2 + cos^2 = 1 for w too, and w = alpha - u - v
        assert full[4][k] ** 2 + full[5][k] ** 2 == 1
    uvw = pts.uvw_float()
    assert uvw.shape == (2, 3) and np.allclose(uvw.sum(axis=1), float(alpha), rtol=1e-15)
    assert uvw[0, 0] == pytest.approx(4 * math.atan(1 / 5), rel=1e-15) and uvw[1, 1] == 0.0
    assert np.allclose(np.sin(uvw[:, 2] / 2), [float(x) for x in full[4]], rtol=1e-14)
    with mpmath.workdps(30):
        assert np.allclose(np.array(pts.uvw_mp(), dtype=float), uvw, rtol=1e-15)
    with pytest.raises(ValueError, match="outside Omega"):
        RationalPoints(alpha, (fmpq(1, 3),), (fmpq(1, 3),))  # u + v > alpha
    with pytest.raises(ValueError, match="same length"):
        RationalPoints(alpha, (fmpq(1, 5),), ())
    with pytest.raises(ValueError, match=r"must lie in \[0, 1\)"):
        RationalPoints(alpha, (fmpq(1, 1),), (fmpq(0),))
    with pytest.raises(TypeError, match="must be a RationalAngle"):
        RationalPoints(1.0, (fmpq(1, 5),), (fmpq(1, 7),))
    with pytest.raises(TypeError, match="sequence of rationals"):
        RationalPoints(alpha, "1/5", (fmpq(1, 7),))
    assert len(RationalPoints(None, (fmpq(7, 8),), (fmpq(7, 8),), check=False)) == 1  # the plane: no check


def test_check_points_and_barycentric_edges():
    from paper_repro.core.domain import barycentric_to_uvw, check_barycentric, check_points

    a = 1.0
    assert check_points([0.5, 0.25, 0.25], a).shape == (1, 3)  # one point as a flat triple
    assert check_points([[1.0, 0.0, 0.0]], a).tolist() == [[1.0, 0.0, 0.0]]  # a corner is on the domain
    with pytest.raises(ValueError, match="point 3 = "):
        check_points([[0.5, 0.5, 0.1]], a, offset=3)  # offset: the index as the caller counts
    with pytest.raises(ValueError, match="finite"):
        check_points([[np.nan, 0.5, 0.5]], a)
    with pytest.raises(ValueError, match="not on Omega"):
        check_points([[-0.01, 0.51, 0.5]], a)  # negative coordinate
    assert check_points([[-1e-14, 0.5, 0.5 + 1e-14]], a).shape == (1, 3)  # within the tolerance
    assert check_points([[0.5, 0.5, 0.1]], a, tol=0.2).shape == (1, 3)
    for bad in ("points", {1: 2}, 3.0, None):
        with pytest.raises(TypeError):
            check_points(bad, a)
    assert check_barycentric([0.2, 0.3, 0.5]).shape == (3,)
    with pytest.raises(ValueError, match="has a negative entry"):
        check_barycentric([[1.5, -0.5, 0.0]])
    with pytest.raises(ValueError, match="is not finite"):
        check_barycentric([[np.inf, 0.0, 0.0]])
    with pytest.raises(ValueError, match=r"shape \(m, 3\)"):
        check_barycentric([[0.5, 0.5]])
    with pytest.raises(TypeError):
        check_barycentric([["a", "b", "c"]])
    assert np.allclose(barycentric_to_uvw(2.0, [[0.25, 0.25, 0.5]]), [[0.5, 0.5, 1.0]])


def test_sampled_points_lie_inside_and_are_seeded():
    from paper_repro.core.context import get_context
    from paper_repro.core.domain import sample_points, sample_rational_points, scaled_half_angle_values

    p = sample_points(2.0, 50, seed=4)
    assert p.shape == (50, 3) and np.allclose(p.sum(axis=1), 2.0) and p.min() >= 2.0 * 0.02 / 3 * 0.999
    assert np.array_equal(p, sample_points(2.0, 50, seed=4)) and not np.array_equal(p, sample_points(2.0, 50, seed=5))
    q = sample_points(2.0, 200, seed=4, interior=False)
    assert q.min() < 2.0 * 0.02 / 3  # the whole triangle
    with pytest.raises(TypeError):
        sample_points(1.0, 3, interior=1)
    alpha = rational_alpha(fmpq(1, 2))
    r = sample_rational_points(alpha, 6, seed=1)
    assert len(r) == 6 and len(set(zip(r.tu, r.tv))) == 6 and all(d.q <= 1000 for d in r.tu + r.tv)
    assert all(d.q <= 10 for d in sample_rational_points(alpha, 3, seed=1, max_denominator=10).tu)
    with pytest.raises(TypeError):
        sample_rational_points(1.0, 3)
    # the scaled sines: sin(x/2)/sin(alpha/2) in float (alpha >= 1e-8) and x/alpha below
    ctx = get_context("float")
    pts = np.array([[0.5, 0.3, 0.2]])
    vals = scaled_half_angle_values(pts, 1.0, ctx)
    assert np.allclose([v[0] for v in vals[::2]], np.sin(pts[0] / 2) / np.sin(0.5), rtol=1e-15)
    assert np.allclose([v[0] for v in vals[1::2]], np.cos(pts[0] / 2), rtol=1e-15)
    tiny = scaled_half_angle_values(pts * 1e-9, 1e-9, ctx)
    assert np.allclose([v[0] for v in tiny[::2]], [0.5, 0.3, 0.2], rtol=1e-15)
    mp_vals = scaled_half_angle_values(pts, 1.0, get_context("mp"))
    assert np.allclose([float(v[0]) for v in mp_vals[::2]], np.sin(pts[0] / 2) / np.sin(0.5), rtol=1e-15)


# --- core/context.py -------------------------------------------------------------------------------------------


def _close(ctx, got, want, digits=12):
    """Scalars or arrays of ``ctx`` against exact Fractions: equal (exact, modp images) or within 10^-digits."""
    from fractions import Fraction

    from paper_repro.core.context import ModpContext

    got_flat = np.asarray(got, dtype=object).reshape(-1)
    want_flat = np.asarray(want, dtype=object).reshape(-1)
    assert got_flat.size == want_flat.size
    for g, w in zip(got_flat, want_flat):
        w = Fraction(w)
        if isinstance(ctx, ModpContext):
            assert int(g) == w.numerator * pow(w.denominator, -1, ctx.p) % ctx.p
        elif ctx.exact:
            assert g == fmpq(w.numerator, w.denominator)
        else:
            gv = float(g.mid()) if hasattr(g, "mid") else float(g)
            assert abs(gv - float(w)) <= 10.0**-digits * max(1.0, abs(float(w))), (g, w)


@pytest.mark.parametrize("arith", ["float", "mp", "exact", "ball", "modp"])
def test_every_context_computes_the_same_rational_results(arith):
    from fractions import Fraction as F

    from paper_repro.core.context import get_context, power_table

    ctx = get_context(arith, dps=30)
    with ctx.scope():
        a = ctx.asarray([[fmpq(2), fmpq(1)], [fmpq(1), fmpq(3)]])
        b = ctx.asarray([[fmpq(1), fmpq(2)], [fmpq(4), fmpq(-1)]])
        _close(ctx, ctx.add(a, b), [[3, 3], [5, 2]])
        _close(ctx, ctx.sub(a, b), [[1, -1], [-3, 4]])
        _close(ctx, ctx.mul(a, b), [[2, 2], [4, -3]])
        _close(ctx, ctx.div(a, ctx.asarray([[fmpq(4), fmpq(2)], [fmpq(3), fmpq(5)]])),
               [[F(1, 2), F(1, 2)], [F(1, 3), F(3, 5)]])
        _close(ctx, ctx.dot(a, b), [[6, 3], [13, -1]])
        # A x = B with A = [[2, 1], [1, 3]] (det 5): x = A^-1 B, A^-1 = [[3, -1], [-1, 2]] / 5
        _close(ctx, ctx.solve(a, b), [[F(-1, 5), F(7, 5)], [F(7, 5), F(-4, 5)]])
        x1 = ctx.solve(a, ctx.asarray([fmpq(3), fmpq(4)]))  # a 1-D right-hand side keeps its shape
        assert np.shape(x1) == (2,)
        _close(ctx, x1, [1, 1])
        _close(ctx, ctx.from_rational(fmpq(3, 4)), [F(3, 4)])
        _close(ctx, ctx.convert(F(5, 8)), [F(5, 8)])
        _close(ctx, ctx.ones((2, 1)), [1, 1])
        _close(ctx, ctx.zeros((1, 2)), [0, 0])
        assert ctx.ones((2, 3)).shape == (2, 3) and ctx.zeros((3, 1)).shape == (3, 1)
        _close(ctx, power_table(ctx.asarray([fmpq(2), fmpq(1, 2)]), 3, ctx),
               [[1, 1], [2, F(1, 2)], [4, F(1, 4)], [8, F(1, 8)]])
        if arith != "ball":
            singular = ctx.asarray([[fmpq(1), fmpq(2)], [fmpq(2), fmpq(4)]])
            assert ctx.rank(singular) == 1 and ctx.rank(a) == 2
            with pytest.raises(ZeroDivisionError):
                ctx.solve(singular, b)
        else:
            assert ctx.rank(a) == 2
            with pytest.raises(ValueError, match="certifies full rank"):
                ctx.rank(ctx.asarray([[fmpq(1), fmpq(2)], [fmpq(2), fmpq(4)]]))
        # alpha = 4 atan(1/3): sin(alpha/2) = 3/5, cos(alpha/2) = 4/5, in every context
        alpha = rational_alpha(fmpq(1, 3))
        sa, ca = ctx.alpha_half(alpha)
        _close(ctx, [sa, ca], [F(3, 5), F(4, 5)])
        # w = alpha - u - v from the angle-difference formulas: u = v = 4 atan(1/7), both exact
        s7, c7 = ctx.from_rational(fmpq(7, 25)), ctx.from_rational(fmpq(24, 25))  # t = 1/7: 2t/(1+t^2), ...
        sw, cw = ctx.w_half(ctx, sa, ca, s7, c7, s7, c7)
        # (u+v)/2: sin = 2 s c = 336/625, cos = c^2 - s^2 = 527/625; w/2 = alpha/2 - (u+v)/2
        _close(ctx, [sw, cw], [F(3, 5) * F(527, 625) - F(4, 5) * F(336, 625),
                               F(4, 5) * F(527, 625) + F(3, 5) * F(336, 625)])
        if not ctx.exact:
            sa_f, ca_f = ctx.alpha_half(1.0)
            assert abs(float(sa_f.mid() if arith == "ball" else sa_f) - np.sin(0.5)) < 1e-15
            assert abs(float(ca_f.mid() if arith == "ball" else ca_f) - np.cos(0.5)) < 1e-15
            assert np.allclose(ctx.to_float(ctx.sin(ctx.asarray([0.5, 1.0]))), np.sin([0.5, 1.0]), rtol=1e-15)
            assert np.allclose(ctx.to_float(ctx.cos(ctx.asarray([0.5, 1.0]))), np.cos([0.5, 1.0]), rtol=1e-15)
            assert ctx.to_float(a).tolist() == [[2.0, 1.0], [1.0, 3.0]]
            assert ctx.digits >= 15
        else:
            assert ctx.digits == 0
            with pytest.raises(TypeError):
                ctx.alpha_half(1.0)
            with pytest.raises(TypeError):
                ctx.sin(a)


def test_context_specifics():
    import math
    from fractions import Fraction

    import mpmath

    from paper_repro.core.context import (
        BallContext,
        LogContext,
        ModpContext,
        MpContext,
        _to_fraction,
        _unwrap,
        get_context,
    )

    assert _to_fraction(fmpq(3, 7)) == Fraction(3, 7) and _to_fraction("2/6") == Fraction(1, 3)
    assert _to_fraction(0.5) == Fraction(1, 2) and _to_fraction(np.float32(0.25)) == Fraction(1, 4)
    assert _to_fraction(mpmath.mpf(0.75)) == Fraction(3, 4) and _to_fraction(np.int64(4)) == Fraction(4)
    for bad in (True, np.bool_(False), "x", object(), math.inf, mpmath.inf):
        with pytest.raises((TypeError, ValueError)):
            _to_fraction(bad)
    assert _unwrap(np.array(2.5)) == 2.5 and type(_unwrap(np.float32(2.5))) is float
    assert type(_unwrap(np.int64(3))) is int and type(_unwrap(np.longdouble(1.5))) is float
    # contexts by name, with their precisions
    assert get_context("mp", dps=40).digits == 40 and get_context("ball", dps=30).prec == int(3.33 * 30) + 20
    assert get_context("ball", prec=128).prec == 128 and get_context("modp", p=101).p == 101
    ctx = BallContext(prec=100)
    assert get_context(ctx) is ctx and BallContext(prec=333).digits == 100
    for bad in ("fast", 3, None):
        with pytest.raises(ValueError, match="arith must be one of"):
            get_context(bad)
    for bad in (4, 0, 10_001, True):
        with pytest.raises(ValueError, match="dps"):
            MpContext(dps=bad)
    for bad in (19, True, 2.5):
        with pytest.raises(ValueError, match="prec"):
            BallContext(prec=bad)
    for bad in (2, 91, 2**31 + 11, True):
        with pytest.raises(ValueError, match="p must be a prime"):
            ModpContext(p=bad)
    assert ModpContext(p=3).p == 3
    m = ModpContext(p=7)
    assert m.convert(-1) == 6 and m.convert(Fraction(1, 2)) == 4 and m.from_rational(fmpq(3, 5)) == 2
    with pytest.raises(ValueError, match="divides the denominator"):
        m.from_rational(fmpq(1, 14))
    assert m.asarray([[fmpq(1, 2), 3]]).tolist() == [[4, 3]] and m.asarray([8, -1]).tolist() == [1, 6]
    assert m.residual_ok(np.array([7, 14]), 1.0) and not m.residual_ok(np.array([7, 1]), 1.0)
    with pytest.raises(TypeError):
        m.to_float(np.array([1]))
    # the mp and ball contexts convert every kind of number at their precision
    mp = MpContext(dps=40)
    b200 = BallContext(prec=200)
    with b200.scope():
        third_ball = b200.convert(fmpq(1, 3))
    with mp.scope():
        assert mp.convert(fmpq(1, 3)) == mpmath.mpf(1) / 3 and mpmath.mp.dps == 40
        assert abs(mp.convert(third_ball) - mpmath.mpf(1) / 3) < mpmath.mpf(10) ** -39
        assert mp.residual_ok(np.array([mpmath.mpf(10) ** -30]), 1.0)  # 10^-30 <= 10^(-0.6 * 40) = 10^-24
        assert not mp.residual_ok(np.array([mpmath.mpf(10) ** -20]), 1.0)
    from flint import ctx as flint_ctx

    b = BallContext(prec=200)
    before = flint_ctx.prec
    with b.scope():
        assert flint_ctx.prec == 200
        third = b.convert(mpmath.mpf(1) / 3)
        assert abs(float(third.mid()) - 1 / 3) < 1e-16 and b.convert(Fraction(1, 4)) == b.convert(0.25)
        assert b.residual_ok(np.array([b.convert(1e-40)]), 1.0) and not b.residual_ok(np.array([b.convert(1e-10)]), 1.0)
    assert flint_ctx.prec == before != 200  # restored after the scope
    # the log context: sums and products of non-negative numbers by their logarithms
    lg = LogContext()
    assert lg.convert(0) == -math.inf and lg.from_rational(fmpq(0)) == -math.inf
    assert lg.from_rational(fmpq(3, 2)) == pytest.approx(math.log(1.5), rel=1e-15)
    assert float(lg.to_float(lg.div(lg.convert(6.0), lg.convert(3.0)))) == pytest.approx(2.0, rel=1e-15)
    assert lg.to_float(lg.ones((2,))).tolist() == [1.0, 1.0] and lg.to_float(lg.zeros((1,))).tolist() == [0.0]
    assert np.allclose(lg.to_float(lg.asarray([2.0, 0.0])), [2.0, 0.0])
    for bad in (lambda: lg.convert(-1.0), lambda: lg.from_rational(fmpq(-1, 2))):
        with pytest.raises(ValueError, match="non-negative"):
            bad()
    for bad in (lambda: lg.sub(1.0, 0.0), lambda: lg.dot(np.eye(2), np.eye(2)), lambda: lg.sin(1.0)):
        with pytest.raises(TypeError):
            bad()
    # float residuals: |r| <= scale 10^(-0.6 * 16)
    f = get_context("float")
    assert f.residual_ok(np.array([1e-10]), 1.0) and not f.residual_ok(np.array([1e-9]), 1.0)
    assert f.residual_ok(np.array([]), 1.0)


def test_rational_patch_weights_zero_inside_negative_or_corner():
    from paper_repro.core.labels import index_of
    from paper_repro.surfaces.patch import Patch, check_weights

    n, alpha = 1, 1.0
    idx = index_of(n)
    net = np.random.default_rng(4).normal(size=(delta(n), 3))
    w = np.ones(delta(n))
    w[idx["r_{2,1,1}"]] = 0.0  # the centre: zero weight is allowed away from the corners
    p = Patch(n, alpha, net, weights=w)
    pts = _points_on(alpha, 3, seed=8)
    # a zero weight removes that control point: moving it changes nothing
    moved = net.copy()
    moved[idx["r_{2,1,1}"]] += 100.0
    assert np.allclose(p(pts), Patch(n, alpha, moved, weights=w)(pts), rtol=0, atol=1e-13)
    ex, fl = check_weights(w * 3, n)  # divided by the largest weight (a power of two in float)
    assert fl.max() <= 1.0 and fl.min() == 0.0
    for bad_index, match in ((idx["r_{2,2,0}"], "corner weight"), (idx["g_{2,2,0}"], "corner weight")):
        wb = np.ones(delta(n))
        wb[bad_index] = 0.0
        with pytest.raises(ValueError, match=match):
            Patch(n, alpha, net, weights=wb)
    wn = np.ones(delta(n))
    wn[idx["r_{2,1,1}"]] = -0.5
    with pytest.raises(ValueError, match="non-negative"):
        Patch(n, alpha, net, weights=wn)
    with pytest.raises(ValueError, match="shape"):
        Patch(n, alpha, net, weights=np.ones(delta(n) + 1))
    ex, fl = check_weights([fmpq(1, 3)] * delta(n), n)  # exact weights stay exact: all equal to 1 after scaling
    assert all(x == 1 for x in ex) and fl.tolist() == [1.0] * delta(n)


def test_unit_normals_threshold_is_relative_to_the_tangents():
    from paper_repro.surfaces.patch import unit_normals

    # (3, P) rows; |du x dv| = 1e-9 for tangents of length 100: below tol (|du| + |dv|) = 1e-10 * 200 -> NaN
    du = np.array([[100.0, 100.0, 3.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    dv = np.array([[100.0, 0.0, 0.0], [1e-11, 100.0, 4.0], [0.0, 0.0, 0.0]])
    nrm = unit_normals(du, dv, 1e-10)
    assert np.isnan(nrm[:, 0]).all()
    assert np.allclose(nrm[:, 1], [0, 0, 1]) and np.allclose(nrm[:, 2], [0, 0, 1])  # x cross y = z
    # a cross product of 1e-7 with tangents of length 100 + 100 is kept (above 1e-10 * 200)
    du2, dv2 = du[:, :1].copy(), dv[:, :1].copy()
    dv2[1, 0] = 1e-9
    assert np.allclose(unit_normals(du2, dv2, 1e-10)[:, 0], [0, 0, 1])
    # the orientation: (0, 0, 1) x (1, 0, 0) = (0, 1, 0)
    assert np.allclose(unit_normals(np.array([[0.0], [0.0], [1.0]]), np.array([[1.0], [0.0], [0.0]]), 1e-12)[:, 0],
                       [0, 1, 0])


# --- core/univariate.py ----------------------------------------------------------------------------------------


def test_univariate_basis_is_a_partition_of_unity_in_every_arithmetic():
    import math

    import mpmath

    from paper_repro.core.univariate import A, bernstein, c_const, c_numerator, c_numerator_by_expansion

    for n in (1, 2, 3):
        exp = c_numerator_by_expansion(n)  # the coefficients of (X^2 + 2 c X Y + Y^2)^n, independently
        for i in range(2 * n + 1):
            assert c_numerator(n, i) == [int(exp[i][k]) for k in range(i + 1)], (n, i)
        alpha = 1.3
        t = np.array([0.0, 0.2, 0.9, alpha])
        a = A(n, alpha, t)
        assert a.shape == (4, 2 * n + 1) and a.min() >= -1e-15
        assert np.allclose(a.sum(axis=1), 1.0, rtol=0, atol=1e-14)  # Proposition (partition of unity)
        assert np.allclose(a[0], np.eye(2 * n + 1)[0], atol=1e-15)  # t = 0: only A_{2n,0}
        assert np.allclose(a[-1], np.eye(2 * n + 1)[-1], atol=1e-15)  # t = alpha: only A_{2n,2n}
        # the definition: c_{2n,i} sin^{2n-i}((alpha - t)/2) sin^i(t/2)
        i = 1
        want = c_const(n, i, alpha) * math.sin((alpha - 0.2) / 2) ** (2 * n - i) * math.sin(0.1) ** i
        assert a[1, i] == pytest.approx(want, rel=1e-13)
        with mpmath.workdps(40):
            amp = A(n, mpmath.mpf(alpha), [mpmath.mpf("0.2")], "mp")
            assert abs(sum(amp[0]) - 1) < mpmath.mpf(10) ** -38
            assert np.allclose(np.array(amp, dtype=float)[0], a[1], rtol=1e-14)
    # c_{2,1} = 2 cos(alpha/2) / sin^2(alpha/2), exactly at tan(alpha/4) = 1/2 (s = 4/5, c = 3/5)
    assert c_const(1, 1, rational_alpha(fmpq(1, 2)), "exact") == fmpq(2 * 3 * 25, 5 * 16)
    for bad in (4.0, -1.0, 0.0):  # alpha outside (0, pi)
        with pytest.raises(ValueError):
            c_const(1, 1, bad)
    with pytest.raises(ValueError, match=r"0 <= i <= 2n = 4, got 5"):
        c_numerator(2, 5)
    with pytest.raises(ValueError):
        c_numerator(1, -1)
    with pytest.raises(ValueError, match=r"t must lie in \[0, alpha\]"):
        A(1, 1.0, [1.1])
    with pytest.raises(ValueError, match=r"t must lie in \[0, alpha\]"):
        A(1, 1.0, [-0.01])
    # rounding: t within 1e-12 alpha outside [0, alpha] is taken (alpha = 3: -1e-12 and 3 + 2e-12), farther is not
    assert A(1, 3.0, [-1e-12, 3.0 + 2e-12]).shape == (2, 3)
    with pytest.raises(ValueError):
        A(1, 3.0, [-1e-11])
    b = bernstein(3, [0.25])
    assert [float(x) for x in b[0]] == [27 / 64, 27 / 64, 9 / 64, 1 / 64]


# --- core/layout.py --------------------------------------------------------------------------------------------


def test_layout_of_the_net_graph():
    from paper_repro.core.labels import BasisLabel, united_system
    from paper_repro.core.layout import barycentric, edges, net_edges, position

    for n in (1, 2, 3):
        es = net_edges(n)
        assert len(es) == 6 * n * n + 3 * n and len(set(es)) == len(es)  # documented count
        assert all(0 <= a < delta(n) and 0 <= b < delta(n) and a != b for a, b in es)
        # every node is on some edge, and the centre (row 0) is only entered, never left
        assert {x for e in es for x in e} == set(range(delta(n)))
        assert all(a != 0 for a, _ in es)
        for lab in united_system(n):
            bc = barycentric(lab)
            assert bc.min() >= 0 and bc.sum() == pytest.approx(1.0)
        assert len(edges(n)) >= len(es)
    # positions: corners of the drawing and the centroid
    corners = sorted(tuple(np.round(position(BasisLabel(c, 1, 0, 0)), 12)) for c in "RGB")  # sin^2 of u, v, w
    assert corners == sorted([(0.0, 0.0), (1.0, 0.0), (0.5, round(float(np.sqrt(3) / 2), 12))])
    assert position(BasisLabel("R", 1, 0, 0)).tolist() == [0.0, 0.0]
    assert barycentric(BasisLabel("R", 2, 2, 1)).tolist() == pytest.approx([2 / 5, 1 / 5, 2 / 5])


def test_merge_meshes_dimensions_and_normals():
    from paper_repro.surfaces.patch import merge_meshes

    f = np.array([[0, 1, 2]])
    for d in (1, 2, 4):  # any dimension d >= 1 of a net (Patch.mesh of a d-dimensional net)
        v, faces = merge_meshes([(np.ones((3, d)), f), (np.zeros((3, d)), f)])
        assert v.shape == (6, d) and faces.tolist() == [[0, 1, 2], [3, 4, 5]]
    with pytest.raises(ValueError, match="finite"):
        merge_meshes([(np.ones((3, 0)), f)])  # no coordinates
    with pytest.raises(ValueError, match="finite"):
        merge_meshes([(np.ones((3, 2)), f), (np.ones((3, 3)), f)])  # dimensions differ
    with pytest.raises(ValueError, match="normals with every mesh"):
        merge_meshes([(np.eye(3), f, np.eye(3)), (np.eye(3), f)])
    v, faces, nrm = merge_meshes([(np.eye(3), f, np.eye(3)), (np.eye(3), f, -np.eye(3))])
    assert nrm.tolist() == np.vstack([np.eye(3), -np.eye(3)]).tolist()
    with pytest.raises(ValueError, match="normals must have the shape"):
        merge_meshes([(np.eye(3), f, np.eye(2))])
    with pytest.raises(ValueError, match="faces must be an integer"):
        merge_meshes([(np.eye(3), f.astype(float))])
    with pytest.raises(ValueError, match="non-empty"):
        merge_meshes([])
    with pytest.raises(TypeError):
        merge_meshes("mesh")
    with pytest.raises(TypeError):
        merge_meshes([(np.eye(3),)])
    v, faces = merge_meshes([(np.eye(3), np.zeros((0, 3), dtype=np.int64))])  # no faces is a mesh too
    assert faces.shape == (0, 3)


# --- core/nets.py ----------------------------------------------------------------------------------------------


def test_nets_by_labels_and_their_checks():
    import copy
    import pickle
    from fractions import Fraction

    from paper_repro.core.labels import united_system
    from paper_repro.core.nets import LabelledNet, check_net, check_net_exact, net_from_labels

    n = 1
    labs = [lab.control_point for lab in united_system(n)]
    pts = {lab: [k, -k] for k, lab in enumerate(labs)}
    arr = net_from_labels(pts, n)
    assert arr.shape == (7, 2) and arr[:, 0].tolist() == list(range(7))
    # every function given once (its paper labels and aliases map to one row)
    with pytest.raises(ValueError, match="missing control points"):
        net_from_labels({labs[0]: [0, 0]}, n)
    with pytest.raises(ValueError, match="unknown control point"):
        net_from_labels({**pts, "r_{2,3,0}": [0, 0]}, n)
    with pytest.raises(TypeError, match="labels must be strings"):
        net_from_labels({**pts, 3: [0, 0]}, n)
    with pytest.raises(ValueError, match="different dimensions"):
        net_from_labels({**pts, labs[1]: [1, 2, 3]}, n)
    same = net_from_labels({**pts, "R_{2,1,1}": pts["r_{2,1,1}"]}, n)  # the same point under another name
    assert same.tolist() == arr.tolist()
    with pytest.raises(ValueError, match="conflicts"):  # R_{2n,0,0} = G_{2n,2n,0}: one point, two different values
        net_from_labels({**pts, "r_{2,0,0}": [99, 99]}, n)
    ex = check_net_exact([[Fraction(1, 3), 2]] * 7, n)
    assert ex.dtype == object and ex[0, 0] == Fraction(1, 3)
    assert check_net([[1, 2]] * 7, n).dtype == np.float64
    for bad, err in (([[1, 2]] * 6, ValueError), (np.zeros((7, 0)), ValueError), ([[1, np.nan]] * 7, ValueError),
                     ([["a", 1]] * 7, TypeError), ([[True, 1]] * 7, TypeError), ([[1j, 1]] * 7, TypeError),
                     ([[1, 2], [3]] + [[1, 2]] * 5, (TypeError, ValueError)), (np.zeros(7), ValueError)):
        with pytest.raises(err):
            check_net(bad, n)
    net = LabelledNet(np.arange(14.0).reshape(7, 2), n)
    assert net.labels() == labs
    assert net["r_{2,1,1}"].tolist() == net[labs.index("r_{2,1,1}")].tolist()
    net["g_{2,1,0}"] = [-1.0, -2.0]
    assert net[labs.index("g_{2,1,0}")].tolist() == [-1.0, -2.0]
    assert type(net + 1) is np.ndarray and type(net[1:3]) is np.ndarray
    for clone in (pickle.loads(pickle.dumps(net)), copy.deepcopy(net)):
        assert isinstance(clone, LabelledNet) and clone.n == 1 and clone["g_{2,1,0}"].tolist() == [-1.0, -2.0]
    flat = pickle.loads(pickle.dumps(net.reshape(-1)))
    assert type(flat) is np.ndarray and flat.shape == (14,)
    with pytest.raises(ValueError, match="7 rows expected"):
        LabelledNet(np.zeros((6, 2)), n)
    with pytest.raises(KeyError, match="r_{2,1,1}"):
        net["q"]


# --- core/exact_solve.py ---------------------------------------------------------------------------------------


class _Watched:
    """An fmpq_mat that counts (or refuses) the fraction-free fallback solve of :func:`solve_exact`."""

    def __init__(self, mat, allow=False):
        self.mat, self.allow, self.fallbacks = mat, allow, 0

    def nrows(self):
        return self.mat.nrows()

    def ncols(self):
        return self.mat.ncols()

    def table(self):
        return self.mat.table()

    def __mul__(self, other):
        return self.mat * other

    def solve(self, b, algorithm=None):
        self.fallbacks += 1
        assert self.allow, "the modular route should have given the solution"
        return self.mat.solve(b, algorithm=algorithm)


def test_exact_solve_against_flint_small_large_and_beyond_the_primes():
    from flint import fmpq_mat, fmpz

    from paper_repro.core.exact_solve import _primes, solve_exact, solve_exact_array, wang_pair

    ps = _primes()
    assert len(ps) == 64 and all(fmpz(p).is_prime() and p < 2**62 for p in ps) and list(ps) == sorted(ps)[::-1]
    assert ps[0] == 2**62 - 57  # the largest prime below 2^62
    m = 1_000_003
    for x, y in ((3, 7), (-5, 11), (0, 1), (13, -2)):
        a = x * pow(y, -1, m) % m
        got = wang_pair(a, m, 707)  # bound sqrt(m / 2)
        assert got is not None and fmpq(*got) == fmpq(x, y)
    rng = np.random.default_rng(9)
    for bits in (4, 200, 900):  # solutions of a few bits, of several primes, of many primes
        k = 3
        a = fmpq_mat(k, k, [fmpq(int(rng.integers(-50, 50)), int(rng.integers(1, 9))) for _ in range(k * k)])
        x = fmpq_mat(k, 2, [fmpq(int(rng.integers(1, 2**31)) ** (bits // 31 + 1) * (-1) ** j, 3 + j)
                            for j in range(2 * k)])
        b = a * x
        assert solve_exact(_Watched(a), b) == a.solve(b) == x  # by the modular route (no fallback)
    # a solution of about 4000 bits: beyond 64 primes of 62 bits, the fraction-free fallback gives it
    big = fmpq_mat(2, 1, [fmpq(fmpz(3) ** 2600, 7), fmpq(-1, fmpz(5) ** 1700)])
    a = fmpq_mat(2, 2, [2, 1, 1, 3])
    watched = _Watched(a, allow=True)
    assert solve_exact(watched, a * big) == big and watched.fallbacks == 1
    with pytest.raises(ZeroDivisionError):
        solve_exact(fmpq_mat(2, 2, [1, 2, 2, 4]), fmpq_mat(2, 1, [1, 1]))
    with pytest.raises(ValueError, match="square"):
        solve_exact(fmpq_mat(2, 3, [1] * 6), fmpq_mat(2, 1, [1, 1]))
    arr = solve_exact_array(np.array([[fmpq(2), fmpq(1)], [fmpq(1), fmpq(3)]], dtype=object),
                            np.array([fmpq(3), fmpq(4)], dtype=object))
    assert arr.shape == (2,) and arr.tolist() == [fmpq(1), fmpq(1)]


# --- core/derivatives_basis.py ---------------------------------------------------------------------------------


def test_basis_derivative_against_mp_differences_in_every_direction():
    from fractions import Fraction

    import mpmath

    from paper_repro.core.derivatives_basis import basis_derivative, check_direction, monomial_derivative
    from paper_repro.core.normalization import evaluate_normalized

    assert check_direction("u") == (1, 0, -1) and check_direction("v") == (0, 1, -1)
    assert check_direction((2, -0.5, -1.5)) == (Fraction(2), Fraction(-1, 2), Fraction(-3, 2))
    for bad, err in (((True, 0, -1), TypeError), ("x", ValueError), ((1, 0), ValueError), ((1, 1, 1), ValueError),
                     (3, TypeError), ((1, "a", -1), TypeError), ((np.inf, 0, -np.inf), ValueError),
                     ((1e309, 0, 0), ValueError)):
        with pytest.raises(err):
            check_direction(bad)
    n, alpha = 2, 1.2
    pts = np.array([[0.3, 0.5, 0.4], [0.1, 0.2, 0.9]])
    h = mpmath.mpf(10) ** -20
    with mpmath.workdps(50):
        a = mpmath.mpf(alpha)
        for d in ("u", "v", "w", (1.5, -2.0, 0.5)):
            du, dv, dw = (mpmath.mpf(float(x)) for x in check_direction(d))
            q = np.array([[mpmath.mpf(float(x)) for x in row] for row in pts], dtype=object)
            q[:, 2] = a - q[:, 0] - q[:, 1]
            step = np.array([du, dv, dw], dtype=object) * h
            fd = (evaluate_normalized(n, a, q + step, "mp", dps=50)
                  - evaluate_normalized(n, a, q - step, "mp", dps=50)) / (2 * h)
            for arith in ("float", "mp"):
                got = np.array(basis_derivative(n, alpha if arith == "float" else a, pts if arith == "float" else q, d,
                                                arith, dps=50), dtype=float)
                assert np.allclose(got, np.array(fd, dtype=float), rtol=1e-12, atol=1e-12), (d, arith)
    # the unscaled derivative: d/dx sin^a(x/2) cos^b(x/2) = (a/2) s^(a-1) c^(b+1) - (b/2) s^(a+1) c^(b-1)
    from paper_repro.core.context import get_context

    ctx = get_context("float")
    x = 0.7
    trig = [np.array([np.sin(x / 2)]), np.array([np.cos(x / 2)])] + [np.array([0.5])] * 4
    got = monomial_derivative(np.array([[3, 2, 0, 0, 0, 0]]), trig, (1, 0, -1), ctx)
    s, c = np.sin(x / 2), np.cos(x / 2)
    assert got[0, 0] == pytest.approx(1.5 * s**2 * c**3 - 1.0 * s**4 * c, rel=1e-14)


# --- core/normalizing_formula.py -------------------------------------------------------------------------------


def test_normalizing_formula_parts_and_levels():
    import math
    from math import comb

    from paper_repro.core.context import LogContext, get_context
    from paper_repro.core.domain import sample_rational_points
    from paper_repro.core.normalization import evaluate_normalized
    from paper_repro.core.normalizing_formula import (
        multiplicity,
        sanchez_reyes_numerators,
        scaled_table,
        sin_powers,
        t_weight,
    )

    for n in (1, 2, 3):
        for f in range(n + 1):
            for m in (1, 2, 3):  # [t^f] (1 - m t) (1 - t)^-(2n+1), from the binomial series
                want = comb(2 * n + f, f) - (m * comb(2 * n + f - 1, f - 1) if f else 0)
                assert t_weight(n, f, m) == want
    assert [multiplicity(2, i, j) for i, j in ((1, 0), (1, 1), (2, 2), (2, 0))] == [1, 2, 3, 1]
    assert sin_powers(2) == [4, 4, 4, 5, 5, 6]
    ex = get_context("exact")
    c = fmpq(3, 5)
    rows = sanchez_reyes_numerators(3, c, ex)  # [X^x] (1 + 2cX + X^2)^a
    assert [list(r) for r in rows[:3]] == [[1, 0, 0, 0], [1, 2 * c, 1, 0], [1, 4 * c, 2 + 4 * c * c, 4 * c]]
    s2 = fmpq(16, 25)
    for n in (1, 2, 3):
        full = scaled_table(n, c, s2, ex)
        assert len(full) == (n + 1) * (n + 2) // 2
        sizes = [n + 1 - j for j in range(n + 1)]  # level j holds i = j..n
        for k in range(n + 1):
            assert scaled_table(n, c, s2, ex, max_level=k) == full[: sum(sizes[: k + 1])]
            assert scaled_table(n, c, s2, ex, min_level=k) == full[sum(sizes[:k]):]
        lg = LogContext()
        logs = scaled_table(n, lg.from_rational(c), lg.from_rational(s2), lg)
        assert np.allclose(np.exp(np.array(logs, dtype=float)), [float(x) for x in full], rtol=1e-13)
        fl = scaled_table(n, 0.6, 0.64, get_context("float"))
        assert np.allclose(fl, [float(x) for x in full], rtol=1e-14)
        # the partition of unity (Definition of the normalized system), exactly, at rational points
        alpha = rational_alpha(fmpq(1, 2))  # s = 4/5, c = 3/5
        vals = evaluate_normalized(n, alpha, sample_rational_points(alpha, 3, seed=n), "exact")
        assert all(sum(row) == 1 for row in vals)
    with pytest.raises(ValueError, match="min_level"):
        scaled_table(1, c, s2, ex, min_level=-1)
    assert math.isfinite(float(scaled_table(2, 0.99, 1 - 0.99**2, get_context("float"))[-1]))


# --- surfaces/fitting.py ---------------------------------------------------------------------------------------


def test_fit_least_squares_interpolates_what_is_fixed():
    from paper_repro.surfaces.fitting import fit_least_squares
    from paper_repro.surfaces.patch import Patch

    n, a = 1, 1.0
    truth = Patch(n, a, np.random.default_rng(12).normal(size=(delta(n), 2)))
    pts = np.vstack([a * np.eye(3), _points_on(a, 40, seed=13)])  # the three corners first
    noisy = truth(pts) + np.random.default_rng(14).normal(scale=0.05, size=(43, 2))
    net, rms = fit_least_squares(pts, truth(pts), n, a, full_output=True)
    assert np.allclose(net, truth.net, atol=1e-10) and rms < 1e-12
    # corners=True: the corner values of the data are interpolated exactly (eqs. boundary_property_1..3)
    fitted = Patch(n, a, fit_least_squares(pts, noisy, n, a, corners=True))
    assert np.allclose(fitted(a * np.eye(3)), noisy[:3], rtol=0, atol=1e-12)
    given = np.array([[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]])
    assert np.allclose(Patch(n, a, fit_least_squares(pts, noisy, n, a, corners=given))(a * np.eye(3)), given)
    # a boundary curve in the span of the boundary basis is reproduced, the rest fitted
    for edge in ("u=0", "v=0", "w=0"):
        fb = Patch(n, a, fit_least_squares(pts, noisy, n, a, boundary={edge: lambda t, e=edge: truth.boundary_curve(
            e, t)}))
        assert np.allclose(fb.boundary_net(edge), truth.boundary_net(edge), atol=1e-12), edge
    # a corner that disagrees with a fitted edge is refused; one that agrees is fine
    with pytest.raises(ValueError, match="fixed twice"):
        fit_least_squares(pts, noisy, n, a, corners=given, boundary={"v=0": lambda t: truth.boundary_curve("v=0", t)})
    fit_least_squares(pts, noisy, n, a, corners=truth(a * np.eye(3)),
                      boundary={"v=0": lambda t: truth.boundary_curve("v=0", t)})
    one_d = fit_least_squares(pts, noisy[:, 0], n, a)  # values as a vector: d = 1
    assert one_d.shape == (delta(n), 1)
    with pytest.raises(ValueError, match="include the three corners"):
        fit_least_squares(pts[3:], noisy[3:], n, a, corners=True)
    with pytest.raises(ValueError, match="at least as many data points"):
        fit_least_squares(pts[3:6], noisy[3:6], n, a)
    with pytest.raises(ValueError, match="do not determine"):
        fit_least_squares(np.repeat(pts[5:6], 10, axis=0), np.repeat(noisy[5:6], 10, axis=0), n, a)
    with pytest.raises(ValueError, match="corners must be a finite"):
        fit_least_squares(pts, noisy, n, a, corners=np.ones((2, 2)))
    with pytest.raises(ValueError, match="edges are"):
        fit_least_squares(pts, noisy, n, a, boundary={"x=0": lambda t: t})
    with pytest.raises(TypeError):
        fit_least_squares(pts, noisy, n, a, boundary={"u=0": 3})
    with pytest.raises(TypeError):
        fit_least_squares(pts, noisy, n, a, boundary=[1])
    with pytest.raises(ValueError, match="curve"):
        fit_least_squares(pts, noisy, n, a, boundary={"u=0": lambda t: np.ones((len(t), 3))})
    with pytest.raises(ValueError, match="values must be"):
        fit_least_squares(pts, noisy[:-1], n, a)
    with pytest.raises(TypeError):
        fit_least_squares(pts, noisy, n, a, full_output=1)


def test_fit_in_float_mp_and_exact_agree_and_refuse_what_is_not_in_the_span():
    import mpmath

    from paper_repro.surfaces.fitting import fit, fit_float

    alpha = rational_alpha(fmpq(1, 3))
    a = float(alpha)
    exact = fit(lambda t: [t.cos(1, 0, 0), t.sin(0, 1, 0)], 1, alpha, "exact")
    with mpmath.workdps(40):
        mp = fit(lambda u, v, w: [mpmath.cos(u), mpmath.sin(v)], 1, alpha.mp(), "mp")
    fl = fit(lambda u, v, w: (np.cos(u), np.sin(v)), 1, a, "float")
    ex = np.array([[float(x) for x in row] for row in exact])
    assert np.allclose(np.array(mp, dtype=float), ex, atol=1e-14) and np.allclose(fl, ex, atol=1e-9)
    with pytest.raises(ValueError, match="not in the span"):
        fit_float(lambda u, v, w: (np.cos(3 * u),), 1, a)  # cos 3u is not in V_1
    with pytest.raises(TypeError, match="surface must be callable"):
        fit(3, 1, a)
    with pytest.raises(TypeError, match="with mpmath"):
        fit(lambda u, v, w: [np.cos(np.array(u, dtype=float)) + "x"], 1, a, "mp")


# --- core/normalization.py -------------------------------------------------------------------------------------


def test_normalizing_coefficients_in_every_arithmetic_against_the_collocation_solve():
    import math

    import mpmath

    from paper_repro.core.normalization import (
        certified_orbit_floats,
        coefficient_vector,
        coefficients,
        evaluate_normalized,
        log_scaled_orbit_coefficients,
        orbit_coefficients,
        orbit_coefficients_collocation,
        scaled_coefficient_vector,
        scaled_float_vector,
        scaled_orbit_coefficients,
    )
    from paper_repro.core.normalizing_formula import sin_powers

    alpha = rational_alpha(fmpq(1, 2))  # s = 4/5, c = 3/5
    a = float(alpha)
    for n in (1, 2, 3):
        solved = orbit_coefficients_collocation(n, alpha)  # the exact collocation solve: no formula
        assert orbit_coefficients(n, alpha, "exact") == solved
        s = fmpq(4, 5)
        assert scaled_orbit_coefficients(n, alpha, "exact") == [x * s**k for x, k in zip(solved, sin_powers(n))]
        want = [float(x) for x in solved]
        assert np.allclose(orbit_coefficients(n, a), want, rtol=1e-15)
        assert np.allclose([float(x) for x in orbit_coefficients(n, alpha.mp(), "mp", dps=40)], want, rtol=1e-15)
        assert np.allclose(certified_orbit_floats(n, alpha, False), want, rtol=1e-16)
        scaled = [float(x * s**k) for x, k in zip(solved, sin_powers(n))]
        assert np.allclose(np.exp(log_scaled_orbit_coefficients(n, a)), scaled, rtol=1e-13)
        assert np.allclose(scaled_orbit_coefficients(n, a), scaled, rtol=1e-15)
        vec, svec = coefficient_vector(n, a), scaled_coefficient_vector(n, a)
        assert vec.shape == svec.shape == (delta(n),) and np.allclose(scaled_float_vector(n, a), svec, rtol=1e-15)
        assert set(np.round(vec, 12)) == set(np.round(want, 12))  # every member takes its orbit's coefficient
        keyed = coefficients(n, a)
        assert len(keyed) >= delta(n) and all(isinstance(k, str) for k in keyed)
        assert np.allclose(sorted(set(np.round(list(coefficients(n, a, scaled=True).values()), 12))),
                           sorted(set(np.round(scaled, 12))))
        # the partition of unity in float at a tiny alpha (scaled route) and in mp
        pts = _points_on(1e-200, 4, seed=n)
        assert np.allclose(evaluate_normalized(n, 1e-200, pts).sum(axis=1), 1.0, rtol=0, atol=1e-13)
        with mpmath.workdps(30):
            q = np.array([[mpmath.mpf(float(x)) for x in row] for row in _points_on(a, 2, seed=5)], dtype=object)
            q[:, 2] = alpha.mp() - q[:, 0] - q[:, 1]
            tot = evaluate_normalized(n, alpha.mp(), q, "mp", dps=30).sum(axis=1)
            assert all(abs(x - 1) < mpmath.mpf(10) ** -28 for x in tot)
    # a tiny alpha: r grows like alpha^-(2n+j) and leaves float64; the scaled values stay finite
    with pytest.raises(ValueError, match="exceeds float64"):
        orbit_coefficients(2, 1e-200)
    # alpha -> 0 (c = 1, s = 0) in the formula of Question 1: [t^j X^i] (1 + X)^4 (1 - m t) / (1 - t)^5, by hand
    # 1, 4, 6 (j = 0), (5 - 2) 4 = 12 and (5 - 1) 6 = 24 (j = 1); the centre's is of size sin^2(alpha/2): 0 here
    tiny = scaled_orbit_coefficients(2, 1e-200)
    assert all(math.isfinite(x) and x >= 0 for x in tiny) and tiny[:5] == pytest.approx([1, 4, 6, 12, 24])
    with pytest.raises(ValueError):
        orbit_coefficients(1, rational_alpha(fmpq(1, 2)).__class__(0), "exact")  # tan(alpha/4) = 0
    with pytest.raises(TypeError):
        orbit_coefficients(1, 1.0, "exact")
    with pytest.raises(TypeError):
        coefficients(1, 1.0, scaled=1)


def test_bezier_triangle_without_the_bezier_package_says_so(monkeypatch):
    import sys

    from paper_repro.surfaces.limit import bezier_triangle

    monkeypatch.setitem(sys.modules, "bezier", None)  # import bezier raises ImportError
    with pytest.raises(ImportError, match="needs the 'bezier' package: pip install bezier"):
        bezier_triangle(np.zeros((7, 3)), 1)


def test_rational_alpha_near_default_denominator_and_a_failed_ball_solve(monkeypatch):
    from fractions import Fraction

    import flint

    from paper_repro.core import elevation as el

    # tan(0.319/4) is best approximated by 39/488 with denominators <= 1000 and by 80/1001 with <= 1001
    assert Fraction(np.tan(0.319 / 4)).limit_denominator(1000) == Fraction(39, 488)
    assert el.rational_alpha_near(0.319).t == fmpq(39, 488)  # the documented default: denominator 1000

    class Singular:  # a ball matrix that is not certified invertible
        def __init__(self, *args):
            pass

        def solve(self, *args, **kwargs):
            raise ZeroDivisionError

    monkeypatch.setattr(flint, "arb_mat", Singular)
    assert el._ball_solve(1, 1.0, 128) == (None, 0)  # nothing certified: 0 bits (the next precision doubles)


def test_layout_edges_point_to_the_middle_of_each_side_and_inwards():
    from paper_repro.core.layout import edges

    for n in (1, 2, 3):
        for a, b in edges(n):
            assert a.color == b.color
            if a.j == b.j:  # a side edge of level j: between neighbours, towards i = n (the middle of the side)
                assert abs(a.i - b.i) == 1 and abs(b.i - n) < abs(a.i - n)
            else:  # inward: the same i, from level j to level j + 1
                assert a.i == b.i and b.j == a.j + 1


def test_basis_derivative_beyond_float64_says_so_and_mp_gives_it():
    import sys

    import mpmath

    from paper_repro.core.derivatives_basis import basis_derivative

    a = sys.float_info.min  # the smallest alpha: the derivatives are of size 1/alpha = 4.5e307 times the coefficients
    corner = np.array([[a, 0.0, 0.0]])
    with pytest.raises(OverflowError, match="use arith='mp'"):
        basis_derivative(2, a, corner, "u")
    with mpmath.workdps(30):
        q = np.array([[mpmath.mpf(a), mpmath.mpf(0), mpmath.mpf(0)]], dtype=object)
        big = max(abs(x) for x in basis_derivative(2, mpmath.mpf(a), q, "u", "mp", dps=30)[0])
    assert big > sys.float_info.max  # it does exceed float64


def test_sample_rational_points_default_denominator_below_one_half():
    from paper_repro.core.domain import sample_rational_points

    # documented: 1000 for alpha >= 1/2, growing like 1/alpha below: continuous at 1/2, so 500 / alpha
    alpha = rational_alpha(fmpq(1, 40))
    cap = int(500 / float(alpha))
    default = sample_rational_points(alpha, 20, seed=0)
    assert default == sample_rational_points(alpha, 20, seed=0, max_denominator=cap)
    assert default != sample_rational_points(alpha, 20, seed=0, max_denominator=cap + 10)  # the cap matters here


def test_orbit_coefficients_beyond_the_certified_orders():
    import math

    from paper_repro.core.normalization import MAX_N_CERTIFIED, orbit_coefficients, scaled_orbit_coefficients
    from paper_repro.core.normalizing_formula import sin_powers

    n = MAX_N_CERTIFIED + 1  # the float route: r = (s^(2n+j) r) / s^(2n+j), the paper's scaling undone
    r = orbit_coefficients(n, 2.0)
    s = math.sin(1.0)
    want = [x / s**k for x, k in zip(scaled_orbit_coefficients(n, 2.0), sin_powers(n))]
    assert np.allclose(r, want, rtol=1e-12)


def test_collocate_fmpq_default_number_of_point_sets():
    from paper_repro.core.collocation import collocate_fmpq

    calls = []

    def singular(k):  # two equal collocation rows in every point set
        calls.append(k)
        return (np.array([[1, 1], [1, 1], [2, 1]], dtype=object), np.array([[1], [1], [3]], dtype=object))

    with pytest.raises(ArithmeticError, match="singular for 10 point sets"):  # the documented default: 10
        collocate_fmpq(singular, 2)
    assert calls == list(range(10))


# --- core/half_angle_rules.py ----------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [1, 2, 3])
def test_member_table_names_each_member_by_its_exponents(n):
    from paper_repro.core.half_angle_rules import member_table
    from paper_repro.core.labels import exponent_matrix

    # docs/elevation_and_derivative_for_all_n.md: M_X(m; Y, j) = S_X^{2n-m} S_Y^j C_Y^{m-j} S_Z^m, 0 <= j <= m <= n,
    # X != Y (Z the third variable); the names give exactly delta_n distinct monomials.  Exponent columns: (S_u, C_u,
    # S_v, C_v, S_w, C_w).
    K = member_table(n)
    assert K.shape == (3, 3, n + 1, n + 1)
    E = exponent_matrix(n)
    named = set()
    for x in range(3):
        for y in range(3):
            for m in range(n + 1):
                for j in range(n + 1):
                    k = int(K[x, y, m, j])
                    if x == y or j > m:
                        assert k == -1
                        continue
                    (z,) = {0, 1, 2} - {x, y}
                    want = [0] * 6
                    want[2 * x] += 2 * n - m
                    want[2 * y] += j
                    want[2 * y + 1] += m - j
                    want[2 * z] += m
                    assert E[k].tolist() == want, (x, y, m, j)
                    named.add(k)
    assert named == set(range(delta(n)))


# --- core/half_angle_matrices.py -------------------------------------------------------------------------------


def test_half_angle_refuses_a_float_alpha_in_exact_arithmetic():
    from flint import fmpq

    from paper_repro.core.context import ExactContext
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.exact_solve import ModularExactContext
    from paper_repro.core.half_angle_matrices import half_angle

    # exact arithmetic needs an exact kappa = cos(alpha/2), sigma = sin^2(alpha/2): a float alpha has no exact cosine
    for ctx in (ExactContext(), ModularExactContext()):
        with pytest.raises(TypeError, match="alpha must be a RationalAngle"):
            half_angle(1.0, ctx)
    # tan(alpha/4) = 1/2: cos(alpha/2) = (1 - t^2)/(1 + t^2) = 3/5, sin^2(alpha/2) = (2t/(1 + t^2))^2 = 16/25
    kappa, sigma = half_angle(rational_alpha(fmpq(1, 2)), ExactContext())
    assert (kappa, sigma) == (fmpq(3, 5), fmpq(16, 25))


def test_evaluate_terms_adds_once_per_rank_and_sums_each_entry(monkeypatch):
    from paper_repro.core.context import FloatContext
    from paper_repro.core.half_angle_matrices import elevation_form, evaluate_terms

    # documented: each entry the sum of its monomials, one elementwise addition per rank, so the number of additions
    # is the largest number of monomials in one entry (counted here from the form itself), not the number of terms
    form = elevation_form(3)
    rows, cols, a, b, coef = form
    keys, inverse, counts = np.unique(np.stack([rows, cols], axis=1), axis=0, return_inverse=True,
                                      return_counts=True)
    calls = []
    add = FloatContext.add

    def counting_add(self, x, y):
        calls.append(1)
        return add(self, x, y)

    monkeypatch.setattr(FloatContext, "add", counting_add)
    ctx = FloatContext()
    kappa, sigma = 0.8, 0.36
    erows, ecols, vals = evaluate_terms(form, kappa, sigma, ctx)
    assert len(calls) == counts.max() < len(rows)
    want = np.zeros(len(keys))
    np.add.at(want, inverse.ravel(), coef * kappa ** a * sigma ** b)
    assert np.array_equal(np.stack([erows, ecols], axis=1), keys)
    assert np.allclose(vals, want, rtol=1e-15, atol=0)


def test_half_angle_refuses_alpha_zero_as_a_rational_angle():
    from flint import fmpq

    from paper_repro.core.context import ExactContext, FloatContext
    from paper_repro.core.domain import RationalAngle
    from paper_repro.core.half_angle_matrices import half_angle

    zero = RationalAngle(fmpq(0))  # an angle of [0, pi) (rational_alpha would refuse it already)
    for ctx in (ExactContext(), FloatContext()):  # tan(alpha/4) = 0 is alpha = 0, outside (0, pi)
        with pytest.raises(ValueError, match="open interval"):
            half_angle(zero, ctx)


def test_derivative_nets_in_float_at_a_rational_angle():
    import math

    from flint import fmpq

    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.half_angle_matrices import derivative_nets

    # a RationalAngle in float arithmetic: kappa, sigma from the exact half-angle values, rounded once; the same
    # nets (to rounding) as the float alpha 4 atan(1/2) and as the exact nets rounded
    n = 2
    net = np.random.default_rng(3).normal(size=(delta(n), 2))
    angle = rational_alpha(fmpq(1, 2))
    qu, qv = derivative_nets(n, angle, net)
    fu, fv = derivative_nets(n, 4 * math.atan(0.5), net)
    assert np.allclose(qu, fu, rtol=0, atol=1e-13) and np.allclose(qv, fv, rtol=0, atol=1e-13)
    exact = np.array([[fmpq(int(round(x * 2**40)), 2**40) for x in row] for row in net], dtype=object)
    eu, ev = derivative_nets(n, angle, exact, "exact")
    scale = np.abs(qu).max() + np.abs(qv).max()
    assert np.abs(qu - eu.astype(float)).max() < 1e-10 * scale and np.abs(qv - ev.astype(float)).max() < 1e-10 * scale


def test_the_cached_integer_forms_are_read_only():
    from paper_repro.core.half_angle_matrices import derivative_form, elevation_form, product_form

    # documented ("read-only arrays"): the forms are cached and returned as they are, so a caller writing into one
    # would change every later matrix; numpy must refuse the write
    for form in (elevation_form(2), derivative_form(2), product_form(2, 0)):
        for arr in form:
            assert not arr.flags.writeable
            with pytest.raises(ValueError, match="read-only"):
                arr[0] = arr[0]



# --- surfaces/models.py ----------------------------------------------------------------------------------------


def test_models_refuse_empty_phases_and_bad_params_and_measure_with_two_samples():
    from paper_repro.surfaces.models import cyclide_pieces, model_gap, torus_pieces

    half_pi = np.pi / 2
    for phis, psis in (([], [0.0]), ([0.0], [])):  # documented: a non-empty sequence of phases
        with pytest.raises(ValueError, match="at least one phase"):
            torus_pieces(half_pi, 2.0, 1.0, phis, psis)
        with pytest.raises(ValueError, match="at least one phase"):
            cyclide_pieces(half_pi, {"a": 6, "b": 32 ** 0.5, "c": 2, "mu": 3}, phis, psis)
    for params in ({"a": 6, "b": 4, "c": 2}, {"a": 6, "b": 4, "c": 2, "mu": 3, "nu": 1}, [6, 4, 2, 3]):
        with pytest.raises(TypeError, match="params must be a dict with the keys"):
            cyclide_pieces(half_pi, params, [0.0], [0.0])
    # samples: at least 2 points per edge (documented: "samples below 2" is refused); with 2, the corners and the
    # ends of the diagonal, where the two triangles of the torus square share their exact corner points
    pieces = torus_pieces(half_pi, 2.0, 1.0, [0.0], [0.0])
    assert 0 <= model_gap(pieces, half_pi, samples=2) < 1e-12
    with pytest.raises(ValueError, match="samples"):
        model_gap(pieces, half_pi, samples=1)


# --- surfaces/fitting.py ---------------------------------------------------------------------------------------


def test_surface_coordinates_refuses_a_row_that_is_not_a_sequence():
    from paper_repro.surfaces.fitting import surface_coordinates

    for rows in ([1.0, 2.0], ["xy"], [b"xy"], [(1.0, 2.0), 3.0]):
        with pytest.raises(TypeError, match="surface must return a sequence of coordinates"):
            surface_coordinates(rows, exact=False)


def test_fit_float_reports_its_verification_points():
    from paper_repro.surfaces.fitting import fit_float

    # |u - v| is not a trigonometric polynomial: refused, naming the verification points of the signature's
    # default (verify=8) or of the call
    def kink(u, v, w):
        return (np.abs(u - v),)

    with pytest.raises(ValueError, match="at the 8 verification points"):
        fit_float(kink, 1, 1.0)
    with pytest.raises(ValueError, match="at the 3 verification points"):
        fit_float(kink, 1, 1.0, verify=3)


# --- core/fast.py ----------------------------------------------------------------------------------------------


def test_run_blocks_limits_blas_to_one_thread_by_default():
    from threadpoolctl import threadpool_info, threadpool_limits

    from paper_repro.core.fast import run_blocks

    def blas_threads() -> list[int]:
        return [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]

    seen: list[list[int]] = []
    with threadpool_limits(limits=2, user_api="blas"):  # the user's setting: two BLAS threads
        if not blas_threads() or max(blas_threads()) < 2:
            pytest.skip("no BLAS that takes two threads")
        run_blocks(4, lambda lo, hi, ws: seen.append(blas_threads()), block=1, workers=1)  # documented default
        assert seen and all(t == [1] * len(t) for t in seen)  # blas=True: single-threaded while the blocks run
        assert max(blas_threads()) == 2  # and the user's setting back after
        seen.clear()
        run_blocks(2, lambda lo, hi, ws: seen.append(blas_threads()), block=1, workers=1, blas=False)
        assert all(max(t) == 2 for t in seen)


def test_contract_derivatives_values_over_several_chunks():
    import math

    from paper_repro.core.domain import sample_points
    from paper_repro.core.fast import CHUNK, FloatKernel, scaled_trig_rows
    from paper_repro.core.labels import exponent_matrix

    # n = 4: 61 functions, two chunks of CHUNK = 32; the values pass must sum every chunk (the plain values route,
    # net @ basis_rows, is the reference), and the derivative pass is 2 sin(alpha/2) times the directional
    # derivative of those values (central differences, h = 1e-5: error O(h^2))
    n, alpha = 4, 1.2
    kern = FloatKernel(exponent_matrix(n))
    assert kern.F > CHUNK
    sa = math.sin(alpha / 2)
    pts = sample_points(alpha, 50, seed=5)
    s, c = scaled_trig_rows(pts, alpha, sa)
    net = np.random.default_rng(5).normal(size=(3, kern.F))
    basis = kern.basis_rows(s, c)

    def values_at(q):
        return net @ kern.basis_rows(*scaled_trig_rows(q, alpha, sa))

    h = 1e-5
    for dirs in ([(1, 0, -1)], [(1, 0, -1), (0, 1, -1)], [(1, -2, 1)]):
        vals, outs = kern.contract_derivatives(s, c, sa * sa, dirs, kern.split_net(net), values=True)
        assert np.allclose(vals, net @ basis, rtol=0, atol=1e-12 * (np.abs(net) @ np.abs(basis)).max())
        for k, d in enumerate(dirs):
            step = h * np.array(d, dtype=float)
            fd = 2 * sa * (values_at(pts + step) - values_at(pts - step)) / (2 * h)
            assert np.allclose(outs[k], fd, rtol=1e-7, atol=1e-7 * np.abs(fd).max()), d


def test_threads_without_sched_getaffinity_counts_the_cpus(monkeypatch):
    import os

    from paper_repro.core.fast import threads

    monkeypatch.delenv("PAPER_REPRO_THREADS", raising=False)
    monkeypatch.delattr(os, "sched_getaffinity", raising=False)  # as on macOS and Windows
    monkeypatch.setattr(os, "cpu_count", lambda: 6)
    assert threads() == 6
    monkeypatch.setattr(os, "cpu_count", lambda: None)  # documented by os: None when undetermined
    assert threads() == 1


def _blas_threads_in_run_blocks() -> list[list[int]]:
    from threadpoolctl import threadpool_info

    from paper_repro.core.fast import run_blocks

    seen: list[list[int]] = []
    run_blocks(2, lambda lo, hi, ws: seen.append(
        [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]), block=1, workers=1)
    return seen


def test_a_forked_child_limits_blas_in_run_blocks_too():
    import multiprocessing

    from threadpoolctl import threadpool_info, threadpool_limits

    # the fork handler (_forget_pool_after_fork) starts the child with no BLAS user: its first run_blocks sets the
    # one-thread limit as in the parent
    with threadpool_limits(limits=2, user_api="blas"):
        if max([i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"], default=1) < 2:
            pytest.skip("no BLAS that takes two threads")
        with multiprocessing.get_context("fork").Pool(1) as pool:
            seen = pool.apply(_blas_threads_in_run_blocks)
    assert seen and all(t == [1] * len(t) for t in seen)


def test_float_kernel_contract_and_blocks_against_the_plain_sum():
    from paper_repro.core.fast import FloatKernel
    from paper_repro.core.labels import exponent_matrix

    # unscaled rows: B_f(p) = prod_v sin(x_v/2)^a cos(x_v/2)^b with the exponents (a, b) of exponent_matrix, summed
    # here directly; contract gives sum_f B_f net_f, and with weights (sum_f B_f w_f net_f) / (sum_f B_f w_f)
    n = 2
    exps = exponent_matrix(n)
    kern = FloatKernel(exps)
    rng = np.random.default_rng(8)
    uvw = rng.uniform(0.1, 1.0, size=(7, 3))
    half = uvw / 2
    B = np.prod(np.sin(half[:, None, :]) ** exps[None, :, 0::2] * np.cos(half[:, None, :]) ** exps[None, :, 1::2],
                axis=2)
    net = rng.normal(size=(delta(n), 2))
    w = rng.uniform(0.5, 2.0, size=delta(n))
    assert np.allclose(kern.contract(uvw, net, block=3), B @ net, rtol=1e-13, atol=1e-13)
    rational = (B @ (w[:, None] * net)) / (B @ w)[:, None]
    assert np.allclose(kern.contract(uvw, w[:, None] * net, weights=w, block=3), rational, rtol=1e-13, atol=1e-13)
    got = list(kern.blocks(uvw, block=3))
    assert [sl for sl, _ in got] == [slice(0, 3), slice(3, 6), slice(6, 7)]
    assert np.allclose(np.vstack([b for _, b in got]), B, rtol=1e-13, atol=1e-15)


# --- core/fast_jit.py ------------------------------------------------------------------------------------------


def test_is_cached_reads_numbas_index_file_and_says_true_when_it_cannot_tell(tmp_path):
    from types import SimpleNamespace

    from paper_repro.core import fast_jit

    def dispatcher(index):  # the attribute path of numba's FunctionCache
        return SimpleNamespace(_cache=SimpleNamespace(_cache_file=SimpleNamespace(_index_path=str(index))))

    assert fast_jit._is_cached(dispatcher(tmp_path / "missing.nbi")) is False
    (tmp_path / "kernel.nbi").write_bytes(b"")
    assert fast_jit._is_cached(dispatcher(tmp_path / "kernel.nbi")) is True
    assert fast_jit._is_cached(object()) is True  # documented: True when that cannot be told (no numba cache)


def test_announce_compilation_returns_a_bool(monkeypatch):
    import io

    from paper_repro.core import fast_jit

    # documented: "Returns whether a line was written" -- False, not merely falsy, on both silent paths
    monkeypatch.setattr(fast_jit, "_ANNOUNCED", set())
    monkeypatch.setattr(fast_jit, "_compiled", lambda: {"values": None, "derivatives": None})  # nothing compiled
    monkeypatch.setattr(fast_jit, "_is_cached", lambda dispatcher: True)
    monkeypatch.delenv("PAPER_REPRO_NO_CACHE", raising=False)
    out = io.StringIO()
    assert fast_jit.announce_compilation("values", out) is False  # in numba's cache: silent
    assert fast_jit.announce_compilation("values", out) is False  # said (or skipped) once already
    monkeypatch.setattr(fast_jit, "_is_cached", lambda dispatcher: False)
    assert fast_jit.announce_compilation("derivatives", out) is True and out.getvalue().count("\n") == 1


def test_jit_derivatives_of_two_general_directions():
    import math

    from paper_repro.core import fast_jit
    from paper_repro.core.domain import sample_points
    from paper_repro.core.fast import FloatKernel, scaled_trig_rows
    from paper_repro.core.labels import exponent_matrix

    if not fast_jit.available():
        pytest.skip("numba is not installed: the compiled kernel does not run")
    # two directions that are not the normals' (u, v): the general two-direction pass (_d2_k3) for a 3-D net,
    # against 2 sin(alpha/2) times central differences of the values (h = 1e-5)
    n, alpha = 2, 1.1
    kern = FloatKernel(exponent_matrix(n))
    jit = fast_jit.JitKernel(kern)
    sa = math.sin(alpha / 2)
    pts = sample_points(alpha, 40, seed=9)
    s, c = scaled_trig_rows(pts, alpha, sa)
    net = np.random.default_rng(9).normal(size=(3, kern.F))
    dirs = np.array([(1.0, -2.0, 1.0), (0.0, 1.0, -1.0)])
    _, outs = jit.derivatives(s, c, sa * sa, dirs, net, np.empty((2, 3, s.shape[1])))
    h = 1e-5
    for r, d in enumerate(dirs):
        plus = net @ kern.basis_rows(*scaled_trig_rows(pts + h * d, alpha, sa))
        minus = net @ kern.basis_rows(*scaled_trig_rows(pts - h * d, alpha, sa))
        fd = 2 * sa * (plus - minus) / (2 * h)
        assert np.allclose(outs[r], fd, rtol=1e-7, atol=1e-7 * np.abs(fd).max()), d


# --- core/subdivision_products.py ------------------------------------------------------------------------------


def test_rounding_count_follows_its_definition():
    from paper_repro.core.half_angle_matrices import product_form
    from paper_repro.core.subdivision_products import rounding_count

    # docs/subdivision_for_all_n.md section 11, "Error estimate": K_1 = 93 for order one (derived there); per level k
    # 2 max(a + b) over the terms of the seven product forms (the inputs' occurrences, powers by repeated products)
    # + 1 (the weight R_1[h, g]) + (terms of one entry of the combined form - 1) + 1 + (entries of one row - 1) (the
    # sparse product); then 2 for the normalization. Counted here on the dictionary route's forms
    # (half_angle_matrices.product_form), not on the vectorised forms the code counts.
    def level(k: int) -> int:
        forms = [product_form(k - 1, h) for h in range(7)]
        rows = np.concatenate([f[0] for f in forms])
        cols = np.concatenate([f[1] for f in forms])
        deg = max(int((f[2] + f[3]).max()) for f in forms)
        run = int(np.unique(np.stack([rows, cols], axis=1), axis=0, return_counts=True)[1].max())
        row = int(np.unique(np.unique(np.stack([rows, cols], axis=1), axis=0)[:, 0], return_counts=True)[1].max())
        return 2 * deg + 1 + (run - 1) + 1 + (row - 1)

    assert rounding_count(1) == 93 + 2
    for n in (2, 3, 4):
        assert rounding_count(n) == 93 + sum(level(k) for k in range(2, n + 1)) + 2


# --- core/normalization.py -------------------------------------------------------------------------------------


def test_exact_coefficients_cache_validation_refuses_malformed_entries(monkeypatch):
    from flint import fmpq

    import paper_repro.core.normalization as nz
    from paper_repro.core.domain import rational_alpha

    m = len(nz.orbits(1))
    seen = {}

    def fake_cached(name, key, compute, validate):  # the disk cache, replaced: keep its validator
        seen["validate"] = validate
        return {"solution": ["1"] * m, "point_set": 0}

    monkeypatch.setattr(nz, "cached", fake_cached)
    assert nz.exact_coefficients_cached(1, rational_alpha(fmpq(1, 2))) == ([fmpq(1)] * m, 0)
    validate = seen["validate"]
    assert validate({"solution": ["-3/4"] * m, "point_set": 2}) is None
    for bad in (["1"] * (m + 1), ["1"] * (m - 1), "1" * m, ["1"] * (m - 1) + ["x"], None):
        assert "not a list of" in validate({"solution": bad, "point_set": 0}), bad
    assert validate({"solution": ["1"] * m, "point_set": "0"}) == "point_set is not an integer"


def test_cramer_degree_bound_is_4n_times_the_orbits():
    from paper_repro.core.normalization import cramer_degree_bound, orbits

    # each row times (1 + t^2)^{2n}: entries of degree <= 4n in t; Cramer with m = number of orbits unknowns
    for n in (1, 2, 3):
        assert cramer_degree_bound(n) == 4 * n * len(orbits(n))


def test_coefficient_vector_in_mp_keeps_the_digits_asked_for():
    import mpmath
    from flint import fmpq

    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import coefficient_vector

    angle = rational_alpha(fmpq(1, 3))
    exact = coefficient_vector(2, angle, "exact")
    with mpmath.workdps(15):  # the ambient precision is not what was asked for
        mp60 = coefficient_vector(2, angle, "mp", dps=60)
    with mpmath.workdps(60):
        err = max(abs(mpmath.mpf(int(e.p)) / int(e.q) - x) for e, x in zip(exact, mp60))
    assert err < mpmath.mpf(10) ** -50


def test_solve_reduced_verifies_at_its_default_three_points():
    from flint import fmpq

    from paper_repro.core.context import ExactContext
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import solve_reduced

    # the signature's verify=3: the identity checked at 3 further points (Collocation.verified), or as many as asked
    angle = rational_alpha(fmpq(1, 2))
    assert solve_reduced(1, angle, ExactContext()).verified == 3
    assert solve_reduced(1, angle, ExactContext(), verify=5).verified == 5


# --- core/transformation.py ------------------------------------------------------------------------------------


def test_transformation_matrix_refuses_entries_beyond_float64():
    from paper_repro.core.transformation import transformation_matrix

    # T_to_V of the normalized basis carries the normalizing coefficients: for n = 1 the centre's is
    # 1/sin^2(alpha/2) (Example normalizing_coefficients_n_1), about 4/alpha^2 = 4e400 at alpha = 1e-200: no float64
    with pytest.raises(OverflowError, match="exceeds float64"):
        transformation_matrix(1, 1e-200, "T_to_V")
    m = transformation_matrix(1, 1e-100, "T_to_V")  # 4e200: still a float64
    assert np.isfinite(m).all() and 1e200 < np.abs(m).max() < 1e201


# --- core/domain.py --------------------------------------------------------------------------------------------


def test_check_points_tolerance_is_relative_to_alpha():
    from paper_repro.core.domain import check_points

    # documented: accepted if |u + v + w - alpha| <= tol * alpha and u, v, w >= -tol * alpha
    tol = 1e-6
    for a in (0.01, 2.0):
        near = [a / 3, a / 3, a / 3 + 0.5 * tol * a]  # off by half the tolerance: accepted
        far = [a / 3, a / 3, a / 3 + 2.0 * tol * a]  # off by twice the tolerance: refused
        assert check_points([near], a, tol).shape == (1, 3)
        with pytest.raises(ValueError, match="is not on Omega"):
            check_points([far], a, tol)
        assert check_points([[a + 0.5 * tol * a, -0.5 * tol * a, 0.0]], a, tol).shape == (1, 3)
        with pytest.raises(ValueError, match="is not on Omega"):
            check_points([[a + 2 * tol * a, -2 * tol * a, 0.0]], a, tol)
