"""The compiled kernel of the float path (numba, the optional extra ``fast``; issue 21) against the numpy path.

* The basis values are the numpy path's to the last bit (same power rows, same pair table, same product order).
* The contraction sums the functions in their order, the numpy path's BLAS in an order of its own: the two differ
  by at most twice the dot-product bound ``gamma_F sum_f |B_f| |p_f|`` (each is within it of the exact sum).
* Derivatives and normals: the same, with the bound of the bracket's terms.
* The compiled path gives each point the same bits whatever its block, tile or thread (one point alone, or in a
  batch of 10^5, with 1 or 3 threads).
* ``PAPER_REPRO_KERNEL=numpy`` and a missing numba both select the numpy path.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro import Patch
from paper_repro.core import fast_jit
from paper_repro.core.domain import sample_points
from paper_repro.core.fast import FloatKernel, scaled_trig_rows
from paper_repro.core.labels import delta, exponent_matrix

pytestmark = pytest.mark.skipif(fast_jit._numba is None, reason="numba is not installed (extra 'fast')")

U = 2.0 ** -53


def _gamma(k: int) -> float:
    return k * U / (1 - k * U)


def _rows(n_pts, alpha, seed):
    pts = sample_points(alpha, n_pts, seed=seed)
    return scaled_trig_rows(pts, alpha, math.sin(alpha / 2))


@pytest.mark.parametrize("n", [1, 2, 3, 6, 10])
def test_basis_values_are_the_numpy_bits(n):
    kern = FloatKernel(exponent_matrix(n))
    jit = fast_jit.JitKernel(kern)
    s, c = _rows(3 * fast_jit.TILE + 5, 1.3, n)
    basis = kern.basis_rows(s, c)
    eye = np.eye(kern.F)
    got = jit.values(s, c, eye, np.empty((s.shape[1], kern.F)))  # net = identity: out[p, f] = B_f(p)
    assert np.array_equal(got.T, basis)


@settings(max_examples=40, deadline=None)
@given(n=st.integers(1, 10), alpha=st.floats(1e-3, math.pi - 1e-3), seed=st.integers(0, 2**16),
       dim=st.integers(1, 4), scale=st.sampled_from([1.0, 1e-200, 1e200]))
def test_contraction_within_dot_product_bound(n, alpha, seed, dim, scale):
    kern = FloatKernel(exponent_matrix(n))
    jit = fast_jit.JitKernel(kern)
    s, c = _rows(300, alpha, seed)
    net = np.random.default_rng(seed).normal(size=(dim, kern.F)) * scale
    basis = kern.basis_rows(s, c)
    numpy_path = (net @ basis).T
    got = jit.values(s, c, net, np.empty((s.shape[1], dim)))
    bound = 2 * _gamma(kern.F) * (np.abs(net) @ np.abs(basis)).T
    assert np.all(np.abs(got - numpy_path) <= bound)


@settings(max_examples=30, deadline=None)
@given(n=st.integers(1, 8), alpha=st.floats(1e-3, math.pi - 1e-3), seed=st.integers(0, 2**16),
       dirs=st.sampled_from([[(1, 0, -1)], [(0, 1, -1)], [(1, -2, 1)], [(1, 0, -1), (0, 1, -1)], [(0, 0, 0)]]),
       values=st.booleans())
def test_derivative_brackets_within_bound(n, alpha, seed, dirs, values):
    kern = FloatKernel(exponent_matrix(n))
    jit = fast_jit.JitKernel(kern)
    s, c = _rows(200, alpha, seed)
    s2 = math.sin(alpha / 2) ** 2
    net = np.random.default_rng(seed).normal(size=(3, kern.F))
    ref_vals, ref = kern.contract_derivatives(s, c, s2, dirs, kern.split_net(net), values=True)
    outs = np.empty((len(dirs), 3, s.shape[1]))
    vals = np.empty((3, s.shape[1])) if values else None
    vals, outs = jit.derivatives(s, c, s2, np.array(dirs, float), net, outs, vals)
    # the terms: |d_v| dg_v g_w1 g_w2 per variable (numpy's brackets of the unit directions), summed in absolute value
    _, parts = kern.derivatives_rows(s, c, s2, [(1, 0, 0), (0, 1, 0), (0, 0, 1)])
    for r, d in enumerate(dirs):
        terms = sum(abs(d[v]) * np.abs(parts[v]) for v in range(3))
        bound = 2 * _gamma(kern.F + 4) * (np.abs(net) @ terms)
        assert np.all(np.abs(outs[r] - ref[r]) <= bound)
    if values:
        basis = kern.basis_rows(s, c)
        assert np.all(np.abs(vals - ref_vals) <= 2 * _gamma(kern.F) * (np.abs(net) @ basis))


@pytest.mark.parametrize("n", [1, 3, 6, 10])
def test_normals_pass_has_the_general_bits(n):
    """The (u, v) pass of the normals (``q_0 - q_2``, ``q_1 - q_2``) against the general two-direction pass: with
    the directions doubled the general pass computes exactly twice every product and sum (scaling by 2 is exact),
    so halving it must give the (u, v) pass's bits."""
    kern = FloatKernel(exponent_matrix(n))
    jit = fast_jit.JitKernel(kern)
    s, c = _rows(2 * fast_jit.TILE + 7, 0.9, n)
    s2 = math.sin(0.45) ** 2
    net = np.random.default_rng(n).normal(size=(3, kern.F))
    uv = np.empty((2, 3, s.shape[1]))
    jit.derivatives(s, c, s2, np.array([(1, 0, -1), (0, 1, -1)], float), net, uv)
    general = np.empty_like(uv)
    jit.derivatives(s, c, s2, np.array([(2, 0, -2), (0, 2, -2)], float), net, general)
    assert np.array_equal(uv, general / 2)


def _patch(n, alpha, rational, seed=0):
    rng = np.random.default_rng(seed)
    w = rng.uniform(0.5, 2, size=delta(n)) if rational else None
    return Patch(n, alpha, rng.normal(size=(delta(n), 3)), w)


@pytest.mark.parametrize("rational", [False, True])
def test_patch_paths_agree(monkeypatch, rational):
    n, alpha = 4, 1.2
    pts = sample_points(alpha, 2000, seed=3)
    monkeypatch.setenv("PAPER_REPRO_KERNEL", "numpy")
    p_np = _patch(n, alpha, rational)
    assert p_np._setup["jit"] is None
    monkeypatch.delenv("PAPER_REPRO_KERNEL")
    p_jit = _patch(n, alpha, rational)
    assert p_jit._setup["jit"] is not None
    extent = np.abs(p_np.net).max()
    # both are within a few units of rounding of the exact patch point (test_fast_kernel: 1e-14 against mp)
    assert np.abs(p_jit(pts) - p_np(pts)).max() <= 64 * delta(n) * U * extent
    for d in ("u", (1, -2, 1)):
        a, b = p_jit.derivative(pts, d), p_np.derivative(pts, d)
        assert np.abs(a - b).max() <= 1e-12 * np.abs(b).max()
    na, nb = p_jit.normals(pts), p_np.normals(pts)
    assert np.abs(na - nb).max() <= 1e-12


@pytest.mark.parametrize("rational", [False, True])
def test_a_point_has_the_same_bits_alone_in_a_batch_and_with_threads(monkeypatch, rational):
    n, alpha = 3, 1.1
    p = _patch(n, alpha, rational)
    pts = sample_points(alpha, 3 * fast_jit.JIT_BLOCK + 17, seed=5)
    picks = [0, 1, fast_jit.TILE + 3, fast_jit.JIT_BLOCK + 1, len(pts) - 1]
    results = {}
    for k in ("1", "3"):
        monkeypatch.setenv("PAPER_REPRO_THREADS", k)
        results[k] = (p(pts), p.derivative(pts, "u"), p.normals(pts))
    for a, b in zip(results["1"], results["3"]):
        assert np.array_equal(a, b, equal_nan=True)
    for i in picks:
        alone = (p(pts[i:i + 1]), p.derivative(pts[i:i + 1], "u"), p.normals(pts[i:i + 1]))
        for a, b in zip(alone, results["1"]):
            assert np.array_equal(a[0], b[i], equal_nan=True)


def test_kernel_switch_and_missing_numba(monkeypatch):
    monkeypatch.setenv("PAPER_REPRO_KERNEL", "numpy")
    assert not fast_jit.available()
    monkeypatch.setenv("PAPER_REPRO_KERNEL", "")
    assert fast_jit.available()
    monkeypatch.setattr(fast_jit, "_numba", None)
    assert not fast_jit.available()
    p = _patch(2, 1.0, False)  # the numpy path, as without numba
    assert p._setup["jit"] is None
    pts = sample_points(1.0, 50, seed=1)
    assert np.allclose(p(pts), p.reference(pts[:50]), rtol=0, atol=1e-13)


def test_kernel_setting_is_validated(monkeypatch):
    monkeypatch.setenv("PAPER_REPRO_KERNEL", "fortran")
    with pytest.raises(ValueError, match="PAPER_REPRO_KERNEL must be one of auto, numba, numpy"):
        fast_jit.available()
    monkeypatch.setenv("PAPER_REPRO_KERNEL", "numba")
    assert fast_jit.available()
    monkeypatch.setattr(fast_jit, "_numba", None)
    with pytest.raises(ValueError, match="numba is not installed"):
        fast_jit.available()
