"""The alpha -> 0 limit: closed formula of the limit factors, and cross-checks with the `bezier` package
(a well-kept implementation of Bezier triangles that no one here wrote)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from flint import fmpq

from paper_repro.core.domain import rational_alpha
from paper_repro.core.elevation import elevation_matrix_exact
from paper_repro.core.labels import delta
from paper_repro.surfaces.patch import Patch
from paper_repro.theory.limit_formula import (
    limit_checks,
    limit_factor,
    limit_terms_formula,
    monomials_rank,
    partition_of_unity_holds,
    uniform_factor,
)
from paper_repro.theory.limits import bezier_limit, limit_terms

bezier = pytest.importorskip("bezier")


def _triangle(n_deg: int, bez: dict) -> bezier.Triangle:
    """bezier's node order: (i, j) = powers of (s, t), j outer; weight s^i t^j (1-s-t)^(N-i-j).
    With s = x, t = y, 1-s-t = z the node (i, j) is our p_{i, j, N-i-j}."""
    nodes = [bez[(i, j, n_deg - i - j)] for j in range(n_deg + 1) for i in range(n_deg + 1 - j)]
    return bezier.Triangle(np.asfortranarray(np.array(nodes, dtype=np.float64).T), degree=n_deg)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
def test_formula_equals_limits_of_the_closed_forms(n):
    assert limit_terms(n) == limit_terms_formula(n)


def test_formula_printed_examples():
    # n = 1: R-bar_{2,1,1} -> 0 (centre), R-bar_{2,1,0} -> 2 x z (Bernstein)
    assert limit_factor(1, 1, 1) == 0 and limit_factor(1, 1, 0) == 2
    # a level-1 diagonal and an interior factor, from the definition (2n+j)!/(a! b! c!) * rho
    assert limit_factor(3, 1, 1) == fmpq(5040, 120) * fmpq(5, 7)
    assert limit_factor(3, 3, 2) == fmpq(40320, 6 * 2 * 6) * fmpq(6, 8)


def test_checks_fail_for_a_wrong_formula(monkeypatch):
    import paper_repro.theory.limit_formula as lf

    good = lf.limit_factor
    monkeypatch.setattr(lf, "limit_factor", lambda n, i, j: good(n, i, j) * (2 if (i, j) == (2, 1) else 1))
    assert not partition_of_unity_holds(3)
    monkeypatch.setattr(lf, "limit_factor", good)
    assert limit_checks(3)["partition_of_unity"] and monomials_rank(3) == delta(3)


@pytest.mark.parametrize("n", [1, 2, 3])
def test_limit_net_in_bezier_equals_the_limit_of_the_trigonometric_patch(n):
    """Trigonometric patch at alpha = 2^-9 and 2^-10 (mpmath, 40 digits), Richardson-extrapolated (the error
    is O(alpha^2)), against bezier.Triangle of degree 3n - 1 with our limit net."""
    net = np.random.default_rng(n).integers(-9, 10, size=(delta(n), 3)).astype(float)
    deg, bez = bezier_limit(net, n)
    assert deg == 3 * n - 1
    tri = _triangle(deg, bez)
    xy = np.array([[1 / 8, 1 / 4], [1 / 2, 1 / 8], [3 / 8, 3 / 8], [1 / 16, 3 / 4], [0.0, 0.5]])
    ours = tri.evaluate_cartesian_multi(np.asfortranarray(xy)).T
    vals = []
    with mpmath.workdps(40):
        for k in (9, 10):
            alpha = mpmath.mpf(2) ** -k
            pts = np.array([[alpha * mpmath.mpf(x), alpha * mpmath.mpf(y), alpha * (1 - mpmath.mpf(x) - mpmath.mpf(y))]
                            for x, y in xy], dtype=object)
            vals.append(Patch(n, alpha, net)(pts, arith="mp", dps=40))
        limit = (4 * vals[1] - vals[0]) / 3
    err = np.max(np.abs(np.array(limit, dtype=float) - ours))
    assert err < 1e-9 * max(1.0, np.max(np.abs(ours)))
    assert np.max(np.abs(np.array(vals[1], dtype=float) - ours)) > 1e-9  # the extrapolation is not idle


@pytest.mark.parametrize("n", [1, 2])
def test_limit_of_trigonometric_elevation_is_bezier_elevate_three_times(n):
    """limit(E(alpha) net, order n+1) at two small rational alpha, extrapolated, equals
    Triangle(limit net, 3n-1).elevate().elevate().elevate() (degree 3n+2)."""
    net = np.random.default_rng(10 + n).integers(-9, 10, size=(delta(n), 3)).astype(float)
    deg, bez = bezier_limit(net, n)
    tri = _triangle(deg, bez).elevate().elevate().elevate()
    lims = []
    for t in (fmpq(1, 200), fmpq(1, 400)):
        e = np.array([[float(x) for x in row] for row in elevation_matrix_exact(n, rational_alpha(t))])
        deg1, bez1 = bezier_limit(e @ net, n + 1)
        assert deg1 == 3 * n + 2
        lims.append(np.array([bez1[(i, j, deg1 - i - j)] for j in range(deg1 + 1) for i in range(deg1 + 1 - j)]))
    extrapolated = (4 * lims[1] - lims[0]) / 3
    err = np.max(np.abs(extrapolated - tri.nodes.T))
    assert err < 1e-7 * np.max(np.abs(tri.nodes))


@pytest.mark.parametrize("n", [1, 2, 3, 4, 7])
def test_lemmas_of_the_proof_for_every_n_hold(n):
    r = limit_checks(n)
    assert r["exponent_set"] and r["uniform_factor"] and r["telescoping"] and r["partition_of_unity"]
    assert r["monomials_independent"] and r["degree"] == 3 * n - 1


def test_lemma_checks_can_fail(monkeypatch):
    """Each lemma check rejects a wrong input: a duplicated exponent triple, a wrong factor, a wrong
    multinomial in the telescoping identity."""
    import paper_repro.theory.limit_formula as lf

    good_terms = lf.limit_terms_formula
    monkeypatch.setattr(lf, "limit_terms_formula", lambda n: good_terms(n)[:-1] + [good_terms(n)[0]])
    assert not lf.exponent_set_characterised(3)
    monkeypatch.setattr(lf, "limit_terms_formula", good_terms)
    good = lf.limit_factor
    monkeypatch.setattr(lf, "limit_factor", lambda n, i, j: good(n, i, j) + (1 if (i, j) == (3, 1) else 0))
    assert not lf.uniform_factor_agrees(3)
    monkeypatch.setattr(lf, "limit_factor", good)
    good_m = lf._multinomial
    monkeypatch.setattr(lf, "_multinomial", lambda s: good_m(s) + (1 if s == (2, 2, 1) else 0))
    assert not lf.telescoping_holds(2)


def test_uniform_factor_by_hand():
    # s = (3, 1, 1), n = 2: multinomial 20, minimum 1 twice: 20 - 2 * 4!/(3! 0! 1!) = 12 = 20 * (5 - 2)/5
    assert uniform_factor((3, 1, 1)) == 12
    # centre (2, 2, 2): 90 - 3 * 30 = 0
    assert uniform_factor((2, 2, 2)) == 0


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_conversion_rows_are_convex_combinations_from_both_sources(n):
    from paper_repro.theory.limits import conversion_is_convex, conversion_matrix

    assert conversion_is_convex(n, "formula") and conversion_is_convex(n, "closed_forms")
    assert conversion_matrix(n, "formula") == conversion_matrix(n, "closed_forms")


def test_peeled_rank_is_the_rank_of_the_whole_matrix():
    """The boundary peeling (monomials_rank) against one elimination of the whole homogenised matrix: on the
    limit monomials (full rank) and on random row sets, some with repeated or dependent rows (the fallback)."""
    import random

    from paper_repro.theory.limit_formula import _full_rank, peeled_rank

    for n in range(1, 9):
        exps = [t for _, t in limit_terms_formula(n)]
        assert peeled_rank(exps, 3 * n) == _full_rank(exps, 3 * n) == delta(n)
    rng = random.Random(5)
    fallbacks = 0
    for _ in range(60):
        top = rng.randint(0, 9)
        triples = [(a, b, c) for a in range(top + 1) for b in range(top + 1 - a) for c in range(top + 1 - a - b)]
        exps = [rng.choice(triples) for _ in range(rng.randint(1, 2 * top + 4))]
        full = _full_rank(exps, top)
        assert peeled_rank(exps, top) == full, (top, exps)
        fallbacks += full < len(exps)
    assert fallbacks > 10  # the dependent case is exercised


def test_peeled_rank_rejects_bad_rows():
    from paper_repro.theory.limit_formula import peeled_rank

    with pytest.raises(ValueError, match="exps"):
        peeled_rank([(2, 2, 0)], 3)


@pytest.mark.parametrize("n", [1, 2, 5])
def test_partition_of_unity_at_rational_points(n):
    """(B) independently of partition_of_unity_holds: sum_f L_f x^a y^b z^c = 1 at exact points of the simplex."""
    assert partition_of_unity_holds(n)
    for x, y in [(fmpq(1, 3), fmpq(1, 5)), (fmpq(2, 7), fmpq(5, 11)), (fmpq(0), fmpq(1, 2))]:
        z = 1 - x - y
        assert sum((c * x ** a * y ** b * z ** e for c, (a, b, e) in limit_terms_formula(n)), fmpq(0)) == 1


def test_monomials_rank_sees_a_dependent_set(monkeypatch):
    """A repeated limit monomial (here on the boundary, then inside) lowers the rank: the peeling falls back to the
    whole elimination and reports the same rank as it."""
    import paper_repro.theory.limit_formula as lf

    good = lf.limit_terms_formula(3)
    for level in (0, 1):
        victim = next(k for k, (_, t) in enumerate(good) if min(t) == level)
        terms = list(good)
        other = next(k for k in range(len(terms)) if k != victim and min(terms[k][1]) == min(terms[victim][1]))
        terms[victim] = (terms[victim][0], terms[other][1])
        monkeypatch.setattr(lf, "limit_terms_formula", lambda n, terms=terms: terms)
        rank = lf.monomials_rank(3)
        assert rank == lf._full_rank([t for _, t in terms], 9) == delta(3) - 1
        assert not lf.limit_checks(3)["monomials_independent"]
