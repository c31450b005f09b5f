"""The float product route of midpoint subdivision (paper_repro.core.subdivision_products; issue 38, items 1 and 6;
docs/subdivision_for_all_n.md, section 11).

The references are independent of the route: the certified ball computation of S = M_{alpha/2} Rot M_alpha^{-1}
(``_certified_float_matrices``, within 2^-60 + half an ulp of the exact S), the exact S at a RationalAngle, and the
patch itself evaluated on the sub-triangle (``evaluate_normalized``, which knows nothing of subdivision).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from paper_repro.core.context import FloatContext, MpContext
from paper_repro.core.domain import rational_alpha
from paper_repro.core.half_angle_matrices import _float_half_angle, scaled_coefficients
from paper_repro.core.half_angle_rules import merge, product_terms
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.core.subdivision import (
    PARTS,
    _certified_float_matrices,
    subdivide,
    subdivision_matrices,
    to_parent,
)
from paper_repro.core.subdivision_products import (
    ALPHA_TINY,
    factorization,
    product_terms_fast,
    subdivision_matrices_float,
)

U = 2.0 ** -53


def _eps_x(n: int, alpha: float) -> float:
    """Relative error of the float scaled coefficients x (at alpha and alpha/2) against 40-digit mp."""
    worst = 0.0
    with mpmath.workdps(40):
        ctx = MpContext(dps=40)
        for a in (alpha, alpha / 2):
            half = mpmath.mpf(a) / 2
            xm = scaled_coefficients(n, mpmath.cos(half), mpmath.sin(half) ** 2, ctx)
            xf = scaled_coefficients(n, *_float_half_angle(a), FloatContext())
            worst = max(worst, max(float(abs((mpmath.mpf(float(f)) - m) / m)) for f, m in zip(xf, xm)))
    return worst


def stated_bound(n: int, alpha: float) -> tuple[tuple[np.ndarray, ...], list[np.ndarray]]:
    """The float matrices and the running-error bound of docs/subdivision_for_all_n.md, section 11:
    |S_float - S| <= B + (2 eps_x + 3u)(|S_float| + B), B the rounding part computed by the route."""
    mats, rounding = subdivision_matrices_float(n, alpha, bound=True)
    eps = 2 * _eps_x(n, alpha) + 3 * U
    return mats, [b + eps * (abs(s) + b) for s, b in zip(mats, rounding)]


def test_product_terms_fast_equals_the_dictionary_route():
    """The vectorised Theorem P forms are the proven dictionary construction, term for term (n <= 5, every h)."""
    for n in range(1, 6):
        for h in range(7):
            fast = product_terms_fast(n, h)
            slow = merge(product_terms(n, h))
            assert all(np.array_equal(x, y) for x, y in zip(fast, slow)), (n, h)


def test_factorization_adds_exponents():
    for n in range(2, 9):
        fp, h = factorization(n)
        assert (exponent_matrix(n) == exponent_matrix(n - 1)[fp] + exponent_matrix(1)[h]).all()


@pytest.mark.parametrize("alpha", [1e-3, 1.0, math.pi - 1e-3])
def test_float_route_within_its_bound_of_the_certified_route(alpha):
    """Entry by entry: |float - certified| <= stated bound + the reference's own 2^-60 + half an ulp."""
    for n in (1, 2, 3, 4):
        ref = _certified_float_matrices(n, alpha)
        mats, bound = stated_bound(n, alpha)
        for part, s, r, b in zip(PARTS, mats, ref, bound):
            err = np.abs(s - r)
            assert (err <= b + 2.0 ** -60 + U * np.abs(r)).all(), (n, part, float(err.max()))
            assert err.max() < 2e-15, (n, part, float(err.max()))  # measured: at most 1.3e-15 for n <= 6


def test_float_route_equals_exact_at_a_rational_angle():
    alpha = rational_alpha("1/2")
    for n in (1, 2, 3):
        exact = subdivision_matrices(n, alpha, "exact")
        mats, bound = stated_bound(n, float(alpha.mp()))
        for e, s, b in zip(exact, mats, bound):
            err = np.abs(np.array(e, dtype=float) - s)
            assert (err <= b + U * np.abs(s)).all(), (n, float(err.max()))


def test_the_bound_can_fail():
    """A wrong matrix (one entry moved by 1e-12) is outside the bound: the comparison above can fail."""
    n, alpha = 3, 1.0
    ref = _certified_float_matrices(n, alpha)
    mats, bound = stated_bound(n, alpha)
    wrong = mats[3].copy()
    wrong[5, 7] += 1e-12
    assert not (np.abs(wrong - ref[3]) <= bound[3] + 2.0 ** -60 + U * np.abs(ref[3])).all()


@pytest.mark.parametrize("n", [6, 12])
def test_rows_sum_to_one(n):
    """Partition of unity on both sides: S 1 = 1 (measured within 4e-15 up to n = 20; K u is the stated scale)."""
    for alpha in (1e-3, 0.5, 2.0, math.pi - 1e-3):
        for s in subdivision_matrices(n, alpha):
            assert np.abs(s.sum(axis=1) - 1).max() < 1e-14, (n, alpha)


@pytest.mark.parametrize("n, alpha", [(6, 0.3), (8, 2.9), (10, 1.0)])
def test_sub_patch_equals_patch_on_sub_triangle(n, alpha):
    """The sub-net's patch on Omega^{alpha/2} equals the patch at the mapped points (both evaluated directly)."""
    rng = np.random.default_rng(n)
    net = rng.normal(size=(delta(n), 3))
    pts = rng.dirichlet(np.ones(3), size=25) * (alpha / 2)
    sub_basis = evaluate_normalized(n, alpha / 2, pts)
    for part, q in zip(PARTS, subdivide(net, n, alpha)):
        lhs = sub_basis @ q
        rhs = evaluate_normalized(n, alpha, to_parent(pts, alpha, part)) @ net
        assert np.abs(lhs - rhs).max() < 1e-12 * (1 + np.abs(rhs).max()), (n, part)


def test_small_alpha_is_computed_at_alpha_tiny():
    """Below 1e-100 the route computes at 1e-100 (S(alpha) - S(1e-100) = O(1e-200)); at 1e-30 it agrees with the
    certified route to its bound; at 1e-300 the result is that of 1e-100, finite, rows summing to 1."""
    mats, bound = stated_bound(2, 1e-30)
    ref = _certified_float_matrices(2, 1e-30)
    for s, r, b in zip(mats, ref, bound):
        assert (np.abs(s - r) <= b + 2.0 ** -60 + U * np.abs(r)).all()
    tiny = subdivision_matrices(5, 1e-300)
    same = subdivision_matrices(5, ALPHA_TINY)
    assert all(np.array_equal(a, b) and np.isfinite(a).all() for a, b in zip(tiny, same))
    assert all(np.abs(s.sum(axis=1) - 1).max() < 1e-14 for s in tiny)


def test_subdivide_same_bits_for_any_layout():
    """The sparse product sums in a fixed order: a Fortran-ordered or strided net gives the same bits."""
    n = 5
    net = np.random.default_rng(3).normal(size=(delta(n), 6))
    a = subdivide(net[:, :3], n, 1.1)
    b = subdivide(np.asfortranarray(net[:, :3]), n, 1.1)
    c = subdivide(net[:, ::2], n, 1.1)
    d = subdivide(net[:, [0, 2, 4]], n, 1.1)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))
    assert all(np.array_equal(x, y) for x, y in zip(c, d))


def test_refusals_name_the_parameter():
    with pytest.raises(ValueError, match="n must"):
        subdivision_matrices(31, 1.0)
    with pytest.raises(ValueError, match="alpha"):
        subdivision_matrices(2, 0.0)
    with pytest.raises(ValueError, match="alpha"):
        subdivide(np.zeros((delta(2), 3)), 2, math.pi)
    with pytest.raises(ValueError, match="net"):
        subdivide(np.zeros((delta(2) + 1, 3)), 2, 1.0)


def test_cotangent_csc_fast_equals_the_rules():
    """The vectorised cotangent operators are the proven rules (half_angle_rules.cotangent), column by column as
    sets of terms, for n <= 6 and every variable."""
    from paper_repro.core.half_angle_rules import _cotangent_csc
    from paper_repro.core.subdivision_products import cotangent_csc_fast

    for n in range(1, 7):
        for var in range(3):
            fast, slow = cotangent_csc_fast(n, var), _cotangent_csc(n, var)
            assert np.array_equal(fast[0], slow[0]), (n, var)
            for c in range(len(fast[0]) - 1):
                a = sorted(zip(*(x[fast[0][c]:fast[0][c + 1]].tolist() for x in fast[1:])))
                b = sorted(zip(*(x[slow[0][c]:slow[0][c + 1]].tolist() for x in slow[1:])))
                assert a == b, (n, var, c)


def test_vectorised_names_equal_the_rules():
    """member_table_fast, member_parts_fast and swap_permutation are half_angle_rules.member_table, member_parts
    and labels.variable_swap (n <= 8)."""
    from paper_repro.core.half_angle_rules import member_parts, member_table
    from paper_repro.core.labels import variable_swap
    from paper_repro.core.subdivision_products import member_parts_fast, member_table_fast, swap_permutation

    for n in range(1, 9):
        assert np.array_equal(member_table(n), member_table_fast(n)), n
        assert np.array_equal(member_parts(n), member_parts_fast(n)), n
        assert all(np.array_equal(variable_swap(n, 0, v), swap_permutation(n, v)) for v in (1, 2)), n


def test_cached_tables_are_read_only():
    """The cached integer tables are shared by every later call: none may be modified in place."""
    from paper_repro.core import subdivision_products as m

    arrays = [*m.factorization(3), m.member_table_fast(3), m.member_parts_fast(3), m.swap_permutation(3, 1),
              *m._padded_rule_a(3), *m.cotangent_csc_fast(3, 0), *m.product_terms_fast(2, 4), *m._level_terms(3),
              *m._stabilizer_rows(3, "u"), *m._stabilizer_rows(3, "middle")]
    assert all(not a.flags.writeable for a in arrays)


def test_symmetries_hold_for_the_certified_matrices():
    """The symmetry the route fills with (docs/subdivision_for_all_n.md, section 11): R[pi g, pi f] = R[g, f] for
    the exchanges commuting with the part's map, and corner v is corner u with u and v exchanged -- checked on the
    certified matrices (ball route, which knows nothing of the symmetries), not on the route's own output."""
    from paper_repro.core.subdivision_products import swap_permutation, symmetry_permutations

    n, alpha = 3, 0.7
    ref = _certified_float_matrices(n, alpha)
    tol = 2.0 ** -58
    for pi in symmetry_permutations(n, "u"):
        assert np.abs(ref[0][np.ix_(pi, pi)] - ref[0]).max() <= tol
    for pi in symmetry_permutations(n, "middle"):
        assert np.abs(ref[3][np.ix_(pi, pi)] - ref[3]).max() <= tol
    for k, var in ((1, 1), (2, 2)):
        p = swap_permutation(n, var)
        assert np.abs(ref[0][np.ix_(p, p)] - ref[k]).max() <= tol
    assert len(symmetry_permutations(n, "middle")) == 6
    assert len({tuple(p) for p in symmetry_permutations(n, "middle")}) == 6


@pytest.mark.parametrize("alpha", [1e-3, 0.3, math.pi - 1e-12])
def test_orbit_route_within_its_bound_of_the_certified_route(alpha):
    """n = 5 (members in orbits of size 1, 2, 3 and 6): every entry of the four float matrices within the stated
    bound of the certified route (expected values from the ball route only)."""
    n = 5
    ref = _certified_float_matrices(n, alpha)
    mats, bound = stated_bound(n, alpha)
    for part, s, r, b in zip(PARTS, mats, ref, bound):
        err = np.abs(s - r)
        assert (err <= b + 2.0 ** -60 + U * np.abs(r)).all(), (part, float(err.max()))
        assert err.max() < 2e-15, (part, float(err.max()))


def test_one_part_is_the_same_bits_as_the_four():
    """subdivision_matrix(n, alpha, part) runs only its part's recursion: the same bits as the four together."""
    from paper_repro.core.subdivision import subdivision_matrix

    for n in (1, 4, 7):
        four = subdivision_matrices(n, 1.3)
        for k, part in enumerate(PARTS):
            assert np.array_equal(subdivision_matrix(n, 1.3, part), four[k]), (n, part)
            (one,) = subdivision_matrices_float(n, 1.3, parts=(part,))
            assert np.array_equal(one, four[k]), (n, part)


def test_exponent_matrix_is_the_labels_exponents():
    """The vectorised exponent_matrix is the exponents of the labels of united_system (n <= 30)."""
    from paper_repro.core.labels import exponents, united_system

    for n in range(1, 31):
        ref = np.array([exponents(lab) for lab in united_system(n)], dtype=np.int64)
        assert np.array_equal(ref, exponent_matrix(n)), n


def test_centre_embedding_columns_are_the_dictionary_route():
    """The product forms built by the centre embedding (order n - 1 copied, 6n columns built) are the proven
    dictionary construction term for term at n = 6, 7 (n <= 5: test_product_terms_fast_equals_the_dictionary_route)."""
    for n in (6, 7):
        for h in (0, 2, 5):
            fast = product_terms_fast(n, h)
            slow = merge(product_terms(n, h))
            assert all(np.array_equal(x, y) for x, y in zip(fast, slow)), (n, h)


def test_float_cache_bounded_by_bytes(monkeypatch):
    """The float matrix caches hold at most max(budget, the largest single value) bytes, drop the least recently
    used first, and a result recomputed after an eviction has the same bits (the referee's point on ~8 GB at
    n = 30 with 32 entries per cache)."""
    import paper_repro.core.subdivision as sub

    cache = sub.ByteBoundedCache(2_000_000)  # a few matrices of n = 5..8 (delta_8 = 217: one S is 377 kB)
    monkeypatch.setattr(sub, "FLOAT_CACHE", cache)
    first = {}
    largest = 0
    for n in (5, 6, 7, 8, 5):
        for alpha in (0.4, 1.3):
            four = sub.subdivision_matrices(n, alpha)
            one = sub.subdivision_matrix(n, alpha, "w")
            nets = sub.subdivide(np.ones((delta(n), 2)), n, alpha)
            largest = max([largest] + [size for _, size in cache._data.values()])
            assert cache.nbytes <= max(cache.budget, largest)
            assert cache.nbytes == sum(sub._nbytes(cache._data[k][0]) for k in cache.keys())
            ref = subdivision_matrices_float(n, alpha)  # uncached
            key = (n, alpha)
            if key in first:
                assert all(np.array_equal(a, b) for a, b in zip(first[key], four))
            first[key] = four
            assert all(np.array_equal(a, b) for a, b in zip(ref, four))
            assert np.array_equal(one, ref[2])
            assert all(abs(p - 1).max() < 1e-13 for p in nets)
    assert len(cache.keys()) < 4 * 2 * 3  # evictions happened (24 distinct keys were inserted)
    assert cache.keys()[-1] == ("stacked", 5, 1.3)  # the most recent is kept
    assert largest < cache.budget  # no single value above the budget: the bound is the budget itself
    assert sub.FLOAT_CACHE_BYTES == 512 * 2**20


@pytest.mark.parametrize("n", [9, 10])
def test_float_route_equals_exact_entrywise_beyond_eight(n):
    """Entry by entry against the exact S for n >= 9 (the referee's point 5: before, n >= 9 was checked only through
    the sub-patch at random points, blind to entries whose basis function is tiny there).  tan(alpha/4) = 3/4, so
    cos(alpha/4) = 4/5 is rational and the exact route (the transformation, no product route) runs in Q; within
    the error estimate plus the rounding of alpha, and within 2e-15 (measured 1.4e-16 at n = 9, 2.2e-16 at n = 10)."""
    alpha = rational_alpha("3/4")
    exact = subdivision_matrices(n, alpha, "exact")
    mats, bound = stated_bound(n, float(alpha.mp()))
    for part, e, s, b in zip(PARTS, exact, mats, bound):
        err = np.abs(np.array(e, dtype=float) - s)
        assert (err <= b + U * np.abs(s)).all(), (n, part, float(err.max()))
        assert err.max() < 2e-15, (n, part, float(err.max()))


@pytest.mark.parametrize("n", [3, 5, 10])
def test_float_matrices_exactly_symmetric(n):
    """The orbit route writes every column from a computed one; a computed column whose member is fixed by a
    nontrivial pi is made constant on its stabilizer's orbits first (the referee's point 1 of the second pass,
    docs/subdivision_for_all_n.md section 11.1), so the output is bitwise invariant: S^u under v <-> w, S^mid under
    all six exchanges, S^v and S^w the bitwise conjugates of S^u; the same for the estimate B.  Failed before the
    fix at n = 3, 5, 10, alpha = 1.1 (n = 10: 564 entries of S^u differed, in the columns with a nontrivial
    stabilizer)."""
    from paper_repro.core.subdivision_products import swap_permutation, symmetry_permutations

    mats, bound = subdivision_matrices_float(n, 1.1, bound=True)
    for m in (mats, bound):
        for k, family in ((0, "u"), (3, "middle")):
            for pi in symmetry_permutations(n, family):
                assert np.array_equal(m[k][np.ix_(pi, pi)], m[k]), (n, family)
        for k in (1, 2):
            p = swap_permutation(n, k)
            assert np.array_equal(m[0][np.ix_(p, p)], m[k]), (n, PARTS[k])


@pytest.mark.parametrize("n", [3, 5, 10])
def test_symmetric_net_gives_exactly_symmetric_sub_nets(n):
    """A net constant on the orbits of the six exchanges: its sub-nets S^u P (under v <-> w) and S^mid P (under all
    six) are exactly symmetric when each row is summed correctly rounded (math.fsum: the rounded products of row
    pi g are those of row g, so only the matrices' symmetry matters).  ``subdivide`` sums each row in column order,
    which is not invariant under pi: its sub-nets are symmetric only up to that rounding (checked against the
    correctly rounded sums with the standard bound of a recursive dot product, gamma_{d+1} |S| |P| + u |sum|)."""
    from paper_repro.core.subdivision_products import symmetry_permutations

    d = delta(n)
    perms = symmetry_permutations(n, "middle")
    net = np.random.default_rng(n).standard_normal(d)[np.stack(perms).min(axis=0)]
    assert all(np.array_equal(net[p], net) for p in perms)
    mats = subdivision_matrices_float(n, 1.1)
    subs = subdivide(net[:, None], n, 1.1)
    for k, family in ((0, "u"), (3, "middle")):
        exact_sum = np.array([math.fsum(mats[k][g] * net) for g in range(d)])
        for pi in symmetry_permutations(n, family):
            assert np.array_equal(exact_sum[pi], exact_sum), (n, family)
        gamma = (d + 1) * U / (1 - (d + 1) * U)
        assert (np.abs(subs[k][:, 0] - exact_sum) <= gamma * (np.abs(mats[k]) @ np.abs(net)) + U * np.abs(exact_sum)
                ).all(), (n, family)
