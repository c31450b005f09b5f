"""The faster exact routines of the speed pass (issue 32) against independent computations: the modular solve with
exact check (:mod:`paper_repro.core.exact_solve`), the inverse route of ``_nmod_solve`` for many right-hand sides,
the sparse product of the identity checks modulo p, and the split claims against their tasks run in another
order (the outcome may not depend on the order in which the tasks are computed)."""

from __future__ import annotations

import random

import numpy as np
import pytest
from flint import fmpq, fmpq_mat, nmod_mat

from paper_repro.core import exact_solve as es
from paper_repro.core.context import ExactContext, to_fmpq_mat
from paper_repro.core.domain import rational_alpha, sample_rational_points
from paper_repro.core.elevation import elevation_matrix_exact, elevation_system
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized

P31 = 2_147_483_629


def _random_system(rng: random.Random, m: int, k: int, bits: int) -> tuple[fmpq_mat, fmpq_mat]:
    def q():
        return fmpq(rng.randrange(-2**bits, 2**bits), rng.randrange(1, 2**bits))

    return fmpq_mat(m, m, [q() for _ in range(m * m)]), fmpq_mat(m, k, [q() for _ in range(m * k)])


@pytest.mark.parametrize("m,k,bits", [(1, 1, 5), (4, 3, 10), (12, 5, 40), (6, 9, 200)])
def test_solve_exact_equals_flint_solve_on_random_systems(m, k, bits):
    rng = random.Random(m * 1000 + k + bits)
    a, b = _random_system(rng, m, k, bits)
    assert es.solve_exact(a, b) == a.solve(b, algorithm="fflu") == a.solve(b)


def test_solve_exact_on_the_elevation_system_equals_fraction_free_elimination():
    """The system of claim order_elevation (large entries, small solution): the modular route, and the whole
    collocation through ModularExactContext, against flint's fraction-free solve and the plain ExactContext."""
    alpha = rational_alpha(fmpq(1, 20))
    n = 3
    m = delta(n + 1)
    pts = sample_rational_points(alpha, m, seed=4)
    ctx = ExactContext()
    a = to_fmpq_mat(evaluate_normalized(n + 1, alpha, pts, ctx))
    b = to_fmpq_mat(evaluate_normalized(n, alpha, pts, ctx))
    assert es.solve_exact(a, b) == a.solve(b, algorithm="fflu")
    plain = elevation_system(n, alpha, ExactContext()).solution.tolist()
    assert elevation_matrix_exact(n, alpha) == plain


def test_solve_exact_falls_back_when_the_solution_is_too_large_for_the_primes(monkeypatch):
    """With two primes no reconstruction of 200-bit entries passes the check: the fraction-free fallback gives the
    solution all the same."""
    first = es._primes()[:2]
    monkeypatch.setattr(es, "_primes", lambda: first)
    rng = random.Random(3)
    a, b = _random_system(rng, 5, 2, 200)
    assert es.solve_exact(a, b) == a.solve(b)


def test_solve_exact_singular_raises_and_never_returns_a_wrong_solution():
    a = fmpq_mat(3, 3, [1, 2, 3, 2, 4, 6, fmpq(1, 3), 5, 7])
    with pytest.raises(ZeroDivisionError):
        es.solve_exact(a, fmpq_mat(3, 1, [1, 2, 3]))
    with pytest.raises(ValueError, match="square"):
        es.solve_exact(fmpq_mat(2, 3, [1] * 6), fmpq_mat(2, 1, [1, 1]))


def test_the_exact_check_rejects_a_wrong_reconstruction(monkeypatch):
    """If the reconstruction were wrong the exact check A X = B must refuse it (and the fallback answer): a corrupted
    reconstruction is never returned."""
    real = es._reconstruct_row

    def corrupted(res, mod, bound):
        out = real(res, mod, bound)
        return None if out is None else ([y + 1 for y in out[0]], out[1])

    monkeypatch.setattr(es, "_reconstruct_row", corrupted)
    rng = random.Random(5)
    a, b = _random_system(rng, 4, 2, 8)
    assert es.solve_exact(a, b) == a.solve(b)


def test_nmod_solve_with_many_right_hand_sides_equals_flint_solve():
    from paper_repro.theory.modular import _nmod_solve

    rng = np.random.default_rng(0)
    for m, k in [(3, 200), (14, 2000), (5, 5)]:
        a, b = rng.integers(0, P31, (m, m)), rng.integers(0, P31, (m, k))
        ref = nmod_mat(m, m, a.reshape(-1).tolist(), P31).solve(nmod_mat(m, k, b.reshape(-1).tolist(), P31))
        assert _nmod_solve(a, b, P31).tolist() == [[int(ref[i, j]) for j in range(k)] for i in range(m)]
    with pytest.raises(ZeroDivisionError):
        _nmod_solve(np.array([[1, 2], [2, 4]]), np.ones((2, 100), dtype=np.int64), P31)


def test_matmul_mod_and_the_sparse_product_equal_python_integer_products():
    from paper_repro.theory.half_angle_checks import _sparse_matmul_mod
    from paper_repro.theory.modular import _matmul_mod

    rng = np.random.default_rng(1)
    a = rng.integers(0, P31, (7, 9))
    b = np.where(rng.random((9, 6)) < 0.3, rng.integers(0, P31, (9, 6)), 0)
    ref = [[sum(int(a[i, t]) * int(b[t, j]) for t in range(9)) % P31 for j in range(6)] for i in range(7)]
    assert _matmul_mod(a, b, P31).tolist() == ref
    assert _sparse_matmul_mod(a, b, P31).tolist() == ref


@pytest.mark.parametrize("cid,params", [
    ("order_elevation", {"n_max": 2, "ts": ["1/3", "2/3"], "chain_ts": ["1/5"], "chain_ns": [1], "chain_steps": 2}),
    ("elevation_all_n", {"ts": ["1/2"], "n_rules": 1, "n_exact": 1, "n_modp": 2, "n_collocation": 1, "n_signs": 2,
                         "n_rows": 2}),
    ("derivative_all_n", {"ts": ["1/2"], "n_tables": 2, "n_recovered": [], "n_exact": 1, "n_modp": 2}),
    ("pairwise_products_all_n", {"ts": ["1/2"], "n_exact": 1, "n_modp": 2, "n_lemma": 2, "n_signs": 1,
                                 "n_symmetry": 1, "n_sum": 1}),
    ("transformation_all_n", {"n_solve": 2, "n_solve_ends": 1, "n_closed": 1}),
])
def test_split_claims_do_not_depend_on_the_order_of_their_tasks(cid, params):
    """The split claims (tasks per n, alpha) give the same outcome when their tasks are computed in reverse order."""
    from dataclasses import asdict

    from paper_repro.util.registry import CLAIMS, load_all
    from paper_repro.util.tasks import drive

    load_all()
    c = CLAIMS[cid]
    full = {**c.defaults, **params}

    def reverse(tasks):
        out = [t() for t in reversed(tasks)]
        return out[::-1]

    forward = c.func(**full)
    backward = drive({cid: c.body(**full)}, reverse)[cid]
    assert forward.passed
    assert asdict(forward) == asdict(backward)
