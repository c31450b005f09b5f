"""Joins along an edge (paper_repro.surfaces.joins): the closed form of the edge coefficients checked against Patch
evaluation and Patch.derivative (float), against the exact derivative of the blending functions
(core.derivatives_basis.basis_derivative at rational edge points) and between the arithmetics, the builders against
the derivatives of the two patches (hypothesis), and the torus pieces of Section 6."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro.core.labels import delta, united_system
from paper_repro.core.univariate import A
from paper_repro.surfaces.joins import (
    EDGES,
    MAX_N_JOINS,
    ROLES,
    c1_neighbour_row,
    directions,
    edge_derivatives,
    edge_points,
    edge_rows,
    g1_neighbour_row,
    join_error,
    join_neighbour,
)
from paper_repro.surfaces.patch import Patch


def _reflect(pts: np.ndarray, alpha: float, edge: str) -> np.ndarray:
    """The point reflection through the midpoint of ``edge``: x -> 2m - x."""
    p, z, o = ROLES[edge]
    mid = np.zeros(3)
    mid[p] = mid[o] = alpha / 2
    return 2 * mid - pts


nets = st.integers(0, 2**32 - 1)


@settings(max_examples=12, deadline=None)
@given(seed=nets, n=st.integers(1, 3), alpha=st.floats(0.3, 3.0), edge=st.sampled_from(EDGES))
def test_edge_coefficients_match_patch_derivatives(seed, n, alpha, edge):
    net = np.random.default_rng(seed).normal(size=(delta(n), 3))
    patch = Patch(n, alpha, net)
    d_mat, t_mat = edge_derivatives(n, alpha, edge)
    ts = np.linspace(0.05, 0.95, 7) * alpha
    pts = edge_points(alpha, edge, ts)
    cross, tangent = directions(edge)
    basis = A(n, alpha, ts)
    assert np.allclose(basis @ (d_mat @ net), patch.derivative(pts, cross), atol=1e-8 * (1 + 1 / alpha))
    assert np.allclose(basis @ (t_mat @ net), patch.derivative(pts, tangent), atol=1e-8 * (1 + 1 / alpha))
    b, _ = edge_rows(n, edge)
    assert np.allclose(basis @ net[b], patch(pts), atol=1e-12)  # the boundary property


@settings(max_examples=12, deadline=None)
@given(seed=nets, n=st.integers(1, 3), alpha=st.floats(0.3, 3.0), edge=st.sampled_from(EDGES),
       lam=st.floats(0.2, 3.0), mu=st.floats(-2.0, 2.0))
def test_c1_and_g1_builders_join_smoothly(seed, n, alpha, edge, lam, mu):
    rng = np.random.default_rng(seed)
    net = rng.normal(size=(delta(n), 3))
    other = join_neighbour(net, n, alpha, edge, rng.normal(size=net.shape), lam=lam, mu=mu)
    a, b = Patch(n, alpha, net), Patch(n, alpha, other)
    ts = np.linspace(0.1, 0.9, 5) * alpha
    pts = edge_points(alpha, edge, ts)
    mirror = _reflect(pts, alpha, edge)
    assert np.allclose(a(pts), b(mirror), atol=1e-12)  # C0
    cross, tangent = directions(edge)
    # the neighbour as a function of the common plane is x -> b(2m - x): its derivative along e is -b'(2m - x; e)
    theirs = -b.derivative(mirror, cross)
    want = lam * a.derivative(pts, cross) - mu * a.derivative(pts, tangent)
    assert np.allclose(theirs, want, atol=1e-7 * (1 + 1 / alpha))
    err = join_error(net, other, n, alpha, edge)
    assert err["C0"] < 1e-12 and err["G1"] < 1e-8 * (1 + 1 / alpha)
    assert abs(err["lam"] - lam) < 1e-6 and abs(err["mu"] - mu) < 1e-6
    if lam != 1.0 or mu != 0.0:
        assert err["C1"] > 0


def test_n1_parallelogram_rule():
    """Issue 38: for n = 1 the C1 neighbour across v = 0 has P'_011 = P_200 + P_101 - P_110 (P_abc: the member with
    sine exponents (a, b, c))."""
    names = {"R_{2,1,1}": "111", "R_{2,2,0}": "200", "R_{2,1,0}": "101", "G_{2,2,0}": "002", "G_{2,1,0}": "011",
             "B_{2,2,0}": "020", "B_{2,1,0}": "110"}
    idx = {names[lab.paper]: k for k, lab in enumerate(united_system(1))}
    rng = np.random.default_rng(3)
    net = rng.normal(size=(7, 3))
    other = join_neighbour(net, 1, 1.1, "v", rng.normal(size=(7, 3)))
    assert np.allclose(other[idx["011"]], net[idx["200"]] + net[idx["101"]] - net[idx["110"]])


def test_join_error_sees_a_broken_join():
    rng = np.random.default_rng(4)
    net = rng.normal(size=(delta(2), 3))
    other = join_neighbour(net, 2, 1.0, "w", rng.normal(size=net.shape))
    _, s = edge_rows(2, "w")
    bent = other.copy()
    bent[s[2]] += 0.1
    err = join_error(net, bent, 2, 1.0, "w")
    assert err["C0"] < 1e-12 and err["C1"] > 1e-3 and err["G1"] > 1e-3
    b, _ = edge_rows(2, "w")
    torn = other.copy()
    torn[b[1]] += 0.1
    assert join_error(net, torn, 2, 1.0, "w")["C0"] == pytest.approx(0.1)


def test_torus_pieces_are_c1():
    """The torus of Example exmp:torus: lower and upper pieces are point-reflected neighbours across each shared edge
    (diagonal 'w', and 'v', 'u' between squares) and join C1 (the same smooth map of (U, V) on both sides)."""
    from paper_repro.surfaces.models import torus_pieces

    alpha = math.pi / 2
    pieces = torus_pieces(alpha, 2.0, 1.0, [0.0, alpha], [0.0, alpha])
    by = {(p.phi, p.psi, p.upper): p.patch for p in pieces}
    pairs = [((0.0, 0.0, False), (0.0, 0.0, True), "w"),      # the diagonal of a square
             ((0.0, alpha, False), (0.0, 0.0, True), "v"),     # V = alpha
             ((alpha, 0.0, False), (0.0, 0.0, True), "u")]     # U = alpha
    for lo, up, edge in pairs:
        err = join_error(np.asarray(by[lo].net), np.asarray(by[up].net), 2, alpha, edge)
        assert err["C0"] < 1e-12 and err["C1"] < 1e-10, (edge, err)


@pytest.mark.parametrize("kwargs, exc, word", [
    ({"edge": "x"}, ValueError, "edge"), ({"edge": 1}, TypeError, "edge"),
    ({"alpha": float("nan")}, ValueError, "alpha"),
    ({"alpha": 0.0}, ValueError, "alpha"), ({"alpha": 1j}, TypeError, "alpha"), ({"n": 0}, ValueError, "n must"),
    ({"n": True}, TypeError, "n must"), ({"n": MAX_N_JOINS + 1}, ValueError, "n must"),
    ({"lam": 0.0}, ValueError, "lam"),
    ({"lam": float("nan")}, ValueError, "lam"), ({"mu": float("inf")}, ValueError, "mu"),
    ({"net": np.zeros((6, 3))}, ValueError, "net"), ({"neighbour": np.zeros((7, 2))}, ValueError, "neighbour")])
def test_bad_input_refused(kwargs, exc, word):
    args = {"net": np.zeros((7, 3)), "n": 1, "alpha": 1.0, "edge": "v", "neighbour": None}
    args.update(kwargs)
    extra = {k: args.pop(k) for k in ("lam", "mu") if k in args}
    with pytest.raises(exc, match=word):
        join_neighbour(args["net"], args["n"], args["alpha"], args["edge"], args["neighbour"], **extra)


@pytest.mark.parametrize("n, alpha", [(1, 0.7), (2, 1.3), (3, 2.9)])
def test_subdivision_pieces_join_c1(n, alpha):
    """Cross-check of subdivision and joins: the corner sub-patch 'u' and the middle one are point-reflected
    neighbours across their edge u = 0 (u' = u - alpha/2 and u'' = alpha/2 - u), pieces of one patch: C1."""
    from paper_repro.core.subdivision import subdivide

    net = np.random.default_rng(n).normal(size=(delta(n), 3))
    parts = subdivide(net, n, alpha)
    for corner in ("u", "v", "w"):
        err = join_error(getattr(parts, corner), parts.middle, n, alpha / 2, corner)
        assert err["C0"] < 1e-12 and err["C1"] < 1e-8 * (1 + 1 / alpha), (corner, err)


# --- every arithmetic: the closed form against exact derivatives, the arithmetics against each other ----------------
def _edge_rational_points(alpha, edge: str, taus):
    """Rational points of ``edge`` (quarter-angle tangents) and their half-angle values (s, S) of the parameter and
    the other variable."""
    from paper_repro.core.domain import RationalPoints

    ta = alpha.t
    if edge == "v":
        tu, tv = list(taus), [0] * len(taus)
    elif edge == "u":
        tu, tv = [0] * len(taus), list(taus)
    else:
        tu, tv = list(taus), [(ta - x) / (1 + ta * x) for x in taus]
    return RationalPoints(alpha, tuple(tu), tuple(tv))


def _exact_A(n: int, alpha, pts, edge: str) -> np.ndarray:
    """A_{2n,k}(t) = c_{2n,k} sin^{2n-k}((alpha - t)/2) sin^k(t/2) exactly at the edge points (eq. univariate_basis)."""
    from paper_repro.core.univariate import c_const

    p, _, o = ROLES[edge]
    half = pts.half_angle_values()
    s, big_s = half[2 * p], half[2 * o]
    c = [c_const(n, k, alpha, "exact") for k in range(2 * n + 1)]
    return np.array([[c[k] * big_s[j] ** (2 * n - k) * s[j] ** k for k in range(2 * n + 1)] for j in range(len(pts))],
                    dtype=object)


@pytest.mark.parametrize("n, t", [(1, "1/3"), (2, "1/7"), (3, "2/3"), (4, "1/2")])
def test_exact_closed_form_equals_the_exact_derivatives(n, t):
    """sum_k A_{2n,k}(t) D[k, f] is the exact cross-boundary derivative of every blending function at 2n + 3 rational
    edge points (more than the 2n + 1 that fix a trigonometric polynomial of degree n), T likewise; and the boundary
    row restricts to the A_{2n,k} (boundary property)."""
    from flint import fmpq

    from paper_repro.core.derivatives_basis import basis_derivative
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import evaluate_normalized

    alpha = rational_alpha(t)
    taus = [fmpq(k, 2 * n + 4) * alpha.t for k in range(1, 2 * n + 4)]
    for edge in EDGES:
        pts = _edge_rational_points(alpha, edge, taus)
        basis = _exact_A(n, alpha, pts, edge)
        d_mat, t_mat = edge_derivatives(n, alpha, edge, "exact")
        cross, tangent = directions(edge)
        assert (basis.dot(d_mat) == basis_derivative(n, alpha, pts, cross, "exact")).all()
        assert (basis.dot(t_mat) == basis_derivative(n, alpha, pts, tangent, "exact")).all()
        b, _ = edge_rows(n, edge)
        values = evaluate_normalized(n, alpha, pts, "exact")
        assert (values[:, b] == basis).all() and all(x == 0 for x in np.delete(values, b, axis=1).reshape(-1))


def test_arithmetics_agree():
    """mp at 40 digits and float64 against the exact closed form at the same RationalAngle (n = 5, every edge)."""
    from paper_repro.core.domain import rational_alpha

    alpha = rational_alpha("2/5")
    for edge in EDGES:
        exact = edge_derivatives(5, alpha, edge, "exact")
        mp = edge_derivatives(5, alpha, edge, "mp", dps=40)
        fl = edge_derivatives(5, alpha, edge, "float")
        for e, m, f in zip(exact, mp, fl):
            scale = max(abs(float(x)) for x in e.reshape(-1))
            with mpmath.workdps(60):
                gap = max(abs(mpmath.mpf(int(x.p)) / int(x.q) - y) for x, y in zip(e.reshape(-1), m.reshape(-1)))
            assert gap < 1e-36 * scale
            assert np.abs(f - e.astype(float)).max() < 1e-14 * scale


def test_exact_builders_join_exactly():
    """Exact nets: the C1 neighbour has C0 = C1 = G1 = 0 exactly; a G1 neighbour with lam = 2/3, mu = -1/5 is found
    back exactly by join_error (lam, mu), with C1 != 0."""
    from flint import fmpq

    from paper_repro.core.domain import rational_alpha

    alpha = rational_alpha("1/4")
    rng = np.random.default_rng(7)
    net = [[fmpq(int(x), 7) for x in row] for row in rng.integers(-20, 20, size=(delta(2), 3))]
    for edge in EDGES:
        c1 = join_neighbour(net, 2, alpha, edge)  # exact by default for a RationalAngle
        err = join_error(net, c1, 2, alpha, edge)
        assert (err["C0"], err["C1"], err["G1"], err["lam"], err["mu"]) == (0, 0, 0, 1, 0) and err["scale"] > 0
        g1 = join_neighbour(net, 2, alpha, edge, lam=fmpq(2, 3), mu=fmpq(-1, 5))
        err = join_error(net, g1, 2, alpha, edge)
        assert err["C0"] == 0 and err["C1"] != 0 and err["G1"] == 0
        assert (err["lam"], err["mu"]) == (fmpq(2, 3), fmpq(-1, 5))
        _, s = edge_rows(2, edge)
        assert (c1_neighbour_row(net, 2, alpha, edge) == c1[s]).all()
        assert (g1_neighbour_row(net, 2, alpha, edge, lam=fmpq(2, 3), mu=fmpq(-1, 5)) == g1[s]).all()


def test_g1_fit_refuses_negative_lam():
    """A neighbour with d'_{2n-k} = +d_k (folded back onto our side) is not G1: the fit with lam >= 0 leaves a
    residual, and lam = 0 flags it."""
    from flint import fmpq

    from paper_repro.core.domain import rational_alpha

    alpha = rational_alpha("1/3")
    net = [[fmpq(k * k - 3 * j, 5) for j in range(3)] for k in range(delta(1))]
    folded = join_neighbour(net, 1, alpha, "v", lam=1)
    d_mat, _ = edge_derivatives(1, alpha, "v")
    b, s = edge_rows(1, "v")
    arr = np.array(net, dtype=object)
    # second row with d'_{2n-k} = +d_k (lam = -1): solved here directly
    want = (d_mat.dot(arr))[::-1] - d_mat[:, b].dot(folded[b])
    from paper_repro.core.context import ExactContext

    folded[s] = ExactContext().solve(np.ascontiguousarray(d_mat[:, s]), want)
    err = join_error(net, folded, 1, alpha, "v")
    assert err["C0"] == 0 and err["G1"] != 0 and err["lam"] == 0


@pytest.mark.parametrize("edge", EDGES)
def test_second_row_block_structure_every_n(edge):
    """Lemma 4's hypothesis, for n = 1..40, 60, 80 and MAX_N_JOINS (100): on every edge the second row restricts (cross
    derivative) to (1/2) x the 2n + 1 monomials s^{2n-i} S^i (i = 1..2n-1), S^{2n-1} c and s^{2n-1} C (s, c of the
    parameter; S, C of the other variable), and the boundary row to monomials of degree 2n; the tangent derivative
    of the second row vanishes."""
    from flint import fmpq

    from paper_repro.core.labels import exponent_matrix
    from paper_repro.surfaces.joins import edge_terms

    for n in [*range(1, 41), 60, 80, MAX_N_JOINS]:
        exps = exponent_matrix(n)
        b, s = edge_rows(n, edge)
        cross, tangent = directions(edge)
        got = sorted(tuple(term[1:]) for f in s for term in edge_terms(exps[f], edge, cross))
        want = sorted([(2 * n - i, 0, i, 0) for i in range(1, 2 * n)] + [(0, 1, 2 * n - 1, 0), (2 * n - 1, 0, 0, 1)])
        assert got == want, n
        assert all(term[0] == fmpq(1, 2) for f in s for term in edge_terms(exps[f], edge, cross))
        assert not any(edge_terms(exps[f], edge, tangent) for f in s)
        assert all(sum(term[1:]) == 2 * n for f in b for d in (cross, tangent) for term in edge_terms(exps[f], edge, d))


def test_float_edge_coefficients_at_high_order():
    """n = 20 in float64 against mp (30 digits) at a small and a large alpha: the closed form loses nothing."""
    for alpha in (1e-3, 3.0):
        fl = edge_derivatives(20, alpha, "w")
        mp = edge_derivatives(20, alpha, "w", "mp", dps=30)
        for f, m in zip(fl, mp):
            m = m.astype(float)
            assert np.abs(f - m).max() <= 1e-14 * np.abs(m).max()


@pytest.mark.parametrize("alpha", [1.0, 1e-3, 1e-8, 1e-30, 1e-300])
def test_n1_float_builder_is_accurate_at_small_alpha(alpha):
    """n = 1: the centre's pivot of the second-row block is O(alpha^2), so a float64 solve would lose
    2 log10(1/alpha) digits; the builder then solves in mp (g1_neighbour_row) and the parallelogram rules of the C1
    neighbour (alpha-independent) hold to rounding at every alpha."""
    names = {"R_{2,1,1}": "111", "R_{2,2,0}": "200", "R_{2,1,0}": "101", "G_{2,2,0}": "002", "G_{2,1,0}": "011",
             "B_{2,2,0}": "020", "B_{2,1,0}": "110"}
    idx = {names[lab.paper]: k for k, lab in enumerate(united_system(1))}
    net = np.random.default_rng(3).normal(size=(7, 3))
    other = join_neighbour(net, 1, alpha, "v")
    assert np.abs(other[idx["011"]] - (net[idx["200"]] + net[idx["101"]] - net[idx["110"]])).max() < 1e-14
    assert np.abs(other[idx["111"]] - (net[idx["200"]] + net[idx["002"]] - net[idx["111"]])).max() < 1e-14
    err = join_error(net, other, 1, alpha, "v")
    assert err["C0"] == 0 and err["C1"] < 1e-14 * err["scale"] and abs(err["lam"] - 1) < 1e-14
