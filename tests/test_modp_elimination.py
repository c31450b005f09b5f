"""The exact rank mod p with float64 BLAS products (theory/modp_elimination), against flint's nmod_mat and exact
integers; the per-pair monomial evaluation of exact contexts, against entry-by-entry modular powers; the split
claim linear_independence, against itself run in another order."""

import numpy as np
import pytest
from flint import fmpq, nmod_mat

from paper_repro.claims import linear_independence as li
from paper_repro.core.basis import evaluate
from paper_repro.core.context import ModpContext
from paper_repro.core.domain import half_angle_values, rational_alpha, sample_rational_points
from paper_repro.core.fourier import all_related, related
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.theory import modp_elimination as me
from paper_repro.util.registry import CLAIMS
from paper_repro.util.tasks import drive, drive_inline

P = 2**31 - 1


def flint_rank(a, p=P):
    a = np.asarray(a, dtype=np.int64) % p
    return nmod_mat(a.shape[0], a.shape[1], [int(x) for x in a.reshape(-1)], p).rank()


def test_the_float64_products_are_below_2_to_the_53():
    assert me.EXACT_BOUND == me.MAX_INNER * (2**15 - 1 + 2**16 - 1) ** 2
    assert me.EXACT_BOUND < 2**53


@pytest.mark.parametrize("k", [1, 3, 64, 5000])
def test_mulmod_is_the_exact_product_at_the_largest_entries(k):
    rng = np.random.default_rng(k)
    left = np.where(rng.random((5, k)) < 0.7, P - 1, rng.integers(0, P, (5, k)))
    right = np.where(rng.random((k, 4)) < 0.7, P - 1, rng.integers(0, P, (k, 4)))
    exact = left.astype(object).dot(right.astype(object)) % P
    assert (me.mulmod(left, right, P) == exact.astype(np.int64)).all()
    with pytest.raises(ValueError, match="inner dimension"):
        me.mulmod(np.zeros((1, me.MAX_INNER + 1), dtype=np.int64), np.zeros((me.MAX_INNER + 1, 1), dtype=np.int64), P)


@pytest.mark.parametrize("size", [1, 2, 7, 8, 9, 31, 64, 100, 257])
@pytest.mark.parametrize("deficit", [0, 1, 5])
def test_rank_agrees_with_flint(size, deficit):
    rng = np.random.default_rng(size * 10 + deficit)
    rank = max(size - deficit, 0)
    a = rng.integers(0, P, (size, rank)).astype(object).dot(rng.integers(0, P, (rank, size)).astype(object)) % P
    a = a.astype(np.int64)
    assert me.modp_rank_blas(a, P) == flint_rank(a) == rank


@pytest.mark.parametrize("size,zero", [(60, 20), (100, 50), (150, 40)])
def test_rank_of_deficient_matrices_that_need_row_exchanges(size, zero):
    """A rank-deficient matrix whose leading block is zero: the elimination exchanges rows in almost every column,
    and a wrong exchange shows up as a wrong rank (a generic matrix stays full rank under most bugs)."""
    rng = np.random.default_rng(size + zero)
    rank = size - 7
    x, y = rng.integers(0, P, (size, rank)), rng.integers(0, P, (rank, size))
    x[:zero, rank // 2:] = 0  # the first rows of x and the first columns of y live in complementary coordinates:
    y[:rank // 2, :zero] = 0  # a[:zero, :zero] = 0, and the rank is at most size - 7
    a = (x.astype(object).dot(y.astype(object)) % P).astype(np.int64)
    assert not a[:zero, :zero].any()
    a[rng.permutation(size)] = a.copy()
    assert me.modp_rank_blas(a, P) == flint_rank(a) < size


def test_rank_with_zero_pivots_and_small_prime():
    a = np.zeros((40, 40), dtype=np.int64)
    a[np.arange(40), (np.arange(40) * 7) % 40] = 3  # a permutation: every pivot needs a row exchange
    assert me.modp_rank_blas(a, P) == 40
    b = np.random.default_rng(1).integers(0, 5, (90, 90))
    assert me.modp_rank_blas(b, 5) == flint_rank(b, 5)
    c = np.random.default_rng(2).integers(0, P, (30, 50))  # not square: flint
    assert me.modp_rank_blas(c, P) == flint_rank(c) == 30
    with pytest.raises(ValueError, match="2-D"):
        me.modp_rank_blas(np.zeros(3, dtype=np.int64), P)


@pytest.mark.parametrize("n,t", [(2, "1/3"), (4, "1/7"), (6, "1/3")])
def test_collocation_rank_and_values_mod_p(n, t):
    """The collocation matrix mod p entry by entry (Python modular powers of the half-angle values), and its rank by
    flint: the claim's task gives the same."""
    alpha = rational_alpha(fmpq(*map(int, t.split("/"))))
    ctx = ModpContext()
    pts = sample_rational_points(alpha, delta(n), seed=5)
    trig = [np.asarray(x) for x in half_angle_values(pts, alpha, ctx)]
    exps = exponent_matrix(n)
    ref = np.array([[np.prod([pow(int(trig[s][i]), int(e[s]), P) for s in range(6)], dtype=object) % P
                     for e in exps] for i in range(delta(n))], dtype=object).astype(np.int64)
    a = evaluate(n, alpha, pts, ctx)
    assert (a == ref).all()
    assert li.modp_case(n, t, 5) == flint_rank(ref) == delta(n)
    ref[:, -1] = (ref[:, 0] + ref[:, 1]) % P
    assert li.modp_case(n, t, 5, control=True) == flint_rank(ref) == delta(n) - 1


def test_all_related_is_the_pairwise_relation():
    rng = np.random.default_rng(3)
    for _ in range(2000):
        n = int(rng.integers(1, 5))
        a = tuple(int(x) for x in rng.integers(-1, n + 2, 3))
        members = [a] + [tuple(int(x) for x in rng.integers(-1, n + 2, 3)) for _ in range(int(rng.integers(0, 3)))]
        z = int(rng.integers(-2 * n - 3, 3 * n + 4))  # a partner by either condition, z inside or outside -n..2n
        members.append(tuple(a[k] + z for k in range(3)) if rng.random() < 0.5 else tuple(z - a[k] for k in range(3)))
        assert all_related(members, n) == all(related(a, b, n) or a == b for a in members for b in members)


def test_split_claim_does_not_depend_on_the_order_of_its_tasks():
    params = dict(ns=[1, 2], alphas=["pi/3", "2pi/3"], dps=30, svd_n_max=1, exact_ns=[1, 2, 3],
                  rational_ts=["1/3", "1/7"], seed=5)
    inline = drive_inline(CLAIMS["linear_independence"].body(**params))
    body = CLAIMS["linear_independence"].body(**params)
    backwards = drive({"li": body}, lambda batch: [t() for t in reversed(batch)][::-1])["li"]
    assert inline == backwards and inline.passed
    assert [(r["n"], r["alpha"]) for r in inline.measured["numeric"]] == [(1, "pi/3"), (1, "2pi/3"), (2, "pi/3"),
                                                                          (2, "2pi/3")]
    assert inline.measured["exact_rank_mod_p"] == {t: {"1": 7, "2": 19, "3": 37} for t in ("1/3", "1/7")}
