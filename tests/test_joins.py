"""Joins along an edge (paper_repro.surfaces.joins): checked against Patch evaluation and Patch.derivative (which
know nothing of the edge coefficients), on random nets (hypothesis) and on the torus pieces of Section 6."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro.core.labels import delta, united_system
from paper_repro.core.univariate import A
from paper_repro.surfaces.joins import (
    EDGES,
    ROLES,
    c1_second_row,
    directions,
    edge_derivatives,
    edge_join_error,
    edge_points,
    edge_rows,
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
    other = c1_second_row(net, n, alpha, edge, rng.normal(size=net.shape), lam=lam, mu=mu)
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
    err = edge_join_error(net, other, n, alpha, edge)
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
    other = c1_second_row(net, 1, 1.1, "v", rng.normal(size=(7, 3)))
    assert np.allclose(other[idx["011"]], net[idx["200"]] + net[idx["101"]] - net[idx["110"]])


def test_join_error_sees_a_broken_join():
    rng = np.random.default_rng(4)
    net = rng.normal(size=(delta(2), 3))
    other = c1_second_row(net, 2, 1.0, "w", rng.normal(size=net.shape))
    _, s = edge_rows(2, "w")
    bent = other.copy()
    bent[s[2]] += 0.1
    err = edge_join_error(net, bent, 2, 1.0, "w")
    assert err["C0"] < 1e-12 and err["C1"] > 1e-3 and err["G1"] > 1e-3
    b, _ = edge_rows(2, "w")
    torn = other.copy()
    torn[b[1]] += 0.1
    assert edge_join_error(net, torn, 2, 1.0, "w")["C0"] == pytest.approx(0.1)


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
        err = edge_join_error(np.asarray(by[lo].net), np.asarray(by[up].net), 2, alpha, edge)
        assert err["C0"] < 1e-12 and err["C1"] < 1e-10, (edge, err)


@pytest.mark.parametrize("kwargs, exc, word", [
    ({"edge": "x"}, ValueError, "edge"), ({"edge": 1}, TypeError, "edge"),
    ({"alpha": float("nan")}, ValueError, "alpha"),
    ({"alpha": 0.0}, ValueError, "alpha"), ({"alpha": 1j}, TypeError, "alpha"), ({"n": 0}, ValueError, "n must"),
    ({"n": True}, TypeError, "n must"), ({"n": 9}, ValueError, "n must"), ({"lam": 0.0}, ValueError, "lam"),
    ({"lam": float("nan")}, ValueError, "lam"), ({"mu": float("inf")}, ValueError, "mu"),
    ({"net": np.zeros((6, 3))}, ValueError, "net"), ({"neighbour": np.zeros((7, 2))}, ValueError, "neighbour")])
def test_bad_input_refused(kwargs, exc, word):
    args = {"net": np.zeros((7, 3)), "n": 1, "alpha": 1.0, "edge": "v", "neighbour": None}
    args.update(kwargs)
    extra = {k: args.pop(k) for k in ("lam", "mu") if k in args}
    with pytest.raises(exc, match=word):
        c1_second_row(args["net"], args["n"], args["alpha"], args["edge"], args["neighbour"], **extra)


@pytest.mark.parametrize("n, alpha", [(1, 0.7), (2, 1.3), (3, 2.9)])
def test_subdivision_pieces_join_c1(n, alpha):
    """Cross-check of subdivision and joins: the corner sub-patch 'u' and the middle one are point-reflected
    neighbours across their edge u = 0 (u' = u - alpha/2 and u'' = alpha/2 - u), pieces of one patch: C1."""
    from paper_repro.core.subdivision import subdivide

    net = np.random.default_rng(n).normal(size=(delta(n), 3))
    parts = subdivide(net, n, alpha)
    for corner in ("u", "v", "w"):
        err = edge_join_error(getattr(parts, corner), parts.middle, n, alpha / 2, corner)
        assert err["C0"] < 1e-12 and err["C1"] < 1e-8 * (1 + 1 / alpha), (corner, err)
