"""The pairwise products with the first-order members for every n (issue 30; Theorem P of
docs/elevation_and_derivative_for_all_n.md; sec:open_problems): the rules against independent evaluations, the
library function, and that every check of claim pairwise_products_all_n rejects a deliberately wrong variant."""

from __future__ import annotations

import numpy as np
import pytest
from flint import fmpq

from paper_repro.claims.half_angle_all_n import recurrence_holds
from paper_repro.core import half_angle_rules as hr
from paper_repro.core.basis import evaluate
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.half_angle_matrices import elevation_matrix_ctx, product_form, product_matrix
from paper_repro.core.labels import delta, index_of
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.theory import half_angle_checks as hc

TS = [fmpq(1, 1000), fmpq(1, 2), fmpq(99, 100)]
ALPHA = rational_alpha(fmpq(2, 5))


def _forms(n):
    return [product_form(n, h) for h in range(delta(1))]


def test_the_members_of_order_one_are_named_as_in_the_paper():
    """R_{2,2,0} = s^2 S_u^2, G_{2,2,0} = s^2 S_w^2, B_{2,2,0} = s^2 S_v^2, R_{2,1,0} = s^2 S_u S_w C_v,
    G_{2,1,0} = s^2 S_v S_w C_u, B_{2,1,0} = s^2 S_u S_v C_w (G(u,v,w) = R(w,u,v), B(u,v,w) = R(v,w,u))."""
    parts = hr.order_one_parts()
    idx = index_of(1)
    expect = {"R_{2,1,1}": ("centre", -1), "R_{2,2,0}": ("corner", 0), "G_{2,2,0}": ("corner", 2),
              "B_{2,2,0}": ("corner", 1), "R_{2,1,0}": ("edge", 1), "G_{2,1,0}": ("edge", 0),
              "B_{2,1,0}": ("edge", 2)}
    assert {lab: parts[idx[lab]] for lab in expect} == expect


@pytest.mark.parametrize("n", [1, 2, 3])
def test_every_product_identity_holds_exactly_over_Q(n):
    for t in TS:
        a = rational_alpha(t)
        for h, form in enumerate(_forms(n)):
            assert hc.identity_check("P", n, a, form, h=h)["ok"], (n, h, t)


def test_product_identity_mod_p_to_n_5_and_a_wrong_product_fails():
    for n in (4, 5):
        for h, form in enumerate(_forms(n)):
            assert hc.identity_check("P", n, ALPHA, form, h=h, arith="modp")["ok"]
    form = _forms(3)[5]  # the corner B_{2,2,0}: the hard case
    for k in (0, len(form[4]) // 2, len(form[4]) - 1):
        assert not hc.identity_check("P", 3, ALPHA, hc.perturbed(form, k, 1), h=5)["ok"]
        assert not hc.identity_check("P", 3, ALPHA, hc.perturbed(form, k, 1), h=5, arith="modp")["ok"]
    # the product with another member of T_2 is not this one
    assert not hc.identity_check("P", 3, ALPHA, form, h=3)["ok"]


def test_products_are_positive_forms_and_a_negative_coefficient_is_caught():
    for n in range(1, 9):
        for form in _forms(n):
            assert hc.nonnegative(form)["ok"]
    assert not hc.nonnegative(hc.perturbed(_forms(2)[6], 0, -5))["ok"]


def test_lowering_lemma_holds_and_a_rule_that_breaks_it_is_caught(monkeypatch):
    for n in range(1, 11):
        assert hc.lowering_lemma(n)["ok"]
    real = hr.cotangent

    def broken(n, var, g):  # send every L_x of the centre to a member without S_x (a corner of another variable)
        out = real(n, var, g)
        if g == 0:
            out = out.copy()
            exps = hr.exponent_matrix(n)
            out[0, 3] = int(np.flatnonzero(exps[:, 2 * var] == 0)[0])
        return out

    monkeypatch.setattr(hr, "cotangent", broken)
    assert not hc.lowering_lemma(3)["ok"]


def test_sum_over_h_is_the_elevation_and_the_recurrence_holds_and_wrong_forms_fail():
    for n in (1, 2, 3, 4):
        for t in TS:
            assert hc.product_sum_is_elevation(n, rational_alpha(t), _forms(n))
            assert recurrence_holds(n, rational_alpha(t), _forms(n))
    bad = _forms(3)
    bad[4] = hc.perturbed(bad[4], 3, 1)
    assert not hc.product_sum_is_elevation(3, ALPHA, bad)
    assert not recurrence_holds(3, ALPHA, bad)


def test_products_are_equivariant_and_a_wrong_form_is_caught():
    for n in range(1, 7):
        assert hc.products_equivariant(n, _forms(n))
    bad = _forms(3)
    bad[1] = hc.perturbed(bad[1], 0, 1)
    assert not hc.products_equivariant(3, bad)


@pytest.mark.parametrize("n", [1, 3, 6])
def test_product_matrix_reproduces_the_product_of_normalized_members_in_float(n):
    """f-bar h-bar = sum_g Q[g, f] g-bar' at random points, against the library's own evaluation of the normalized
    bases (a route that solves nothing: Theorem B's coefficients times the monomials)."""
    alpha = 1.3
    pts = sample_points(alpha, 40, seed=3)
    small, one, big = (evaluate_normalized(k, alpha, pts) for k in (n, 1, n + 1))
    for lab in ("B_{2,2,0}", "G_{2,1,0}", "B_{2,1,0}", "R_{2,2,0}"):
        q = product_matrix(n, lab, alpha)
        h = index_of(1)[lab]
        assert q.min() >= 0
        lhs = small * one[:, [h]]
        np.testing.assert_allclose(big @ q, lhs, rtol=1e-12, atol=1e-14)


def test_product_matrix_exact_sums_to_the_elevation_and_mp_agrees():
    a = rational_alpha(fmpq(1, 3))
    qs = [product_matrix(2, h, a, "exact") for h in range(7)]
    assert (sum(qs[1:], qs[0]) == elevation_matrix_ctx(2, a, "exact")).all()
    assert all(min(x for x in q.ravel().tolist()) >= 0 for q in qs)
    f = product_matrix(2, "B_{2,2,0}", 4 * np.arctan(1 / 3))  # tan(alpha/4) = 1/3, rounded to float
    exact = np.array([[float(x) for x in row] for row in qs[5].tolist()])
    np.testing.assert_allclose(f, exact, rtol=1e-14, atol=1e-16)


def test_product_of_unnormalized_members_matches_the_basis_values():
    """The scaled form against the un-normalized members of :func:`evaluate` (a second, independent route)."""
    alpha = 0.9
    pts = sample_points(alpha, 30, seed=8)
    s = np.sin(alpha / 2)
    from paper_repro.core.labels import exponent_matrix

    for n in (2, 4):
        small, one, big = (evaluate(k, alpha, pts) for k in (n, 1, n + 1))
        # un-normalized member = s^(number of sines) * scaled member
        sines = [exponent_matrix(k)[:, 0::2].sum(axis=1) for k in (n, 1, n + 1)]
        for h in range(7):
            p = np.zeros((delta(n + 1), delta(n)))
            rows, cols, aa, bb, coef = product_form(n, h)
            kap, sig = np.cos(alpha / 2), np.sin(alpha / 2) ** 2
            np.add.at(p, (rows, cols), coef * kap ** aa * sig ** bb)
            scaled_prod = (small / s ** sines[0]) * (one[:, [h]] / s ** sines[1][h])
            np.testing.assert_allclose((big / s ** sines[2]) @ p, scaled_prod, rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("bad", [0, 41, 2.0, True])
def test_product_matrix_refuses_bad_n(bad):
    with pytest.raises((ValueError, TypeError), match="n"):
        product_matrix(bad, 0, 1.0)


@pytest.mark.parametrize("bad", [-1, 7, "Q_{2,2,0}", "B_{4,4,0}", 1.0, None, True])
def test_product_matrix_refuses_bad_h(bad):
    with pytest.raises(ValueError, match="h must be"):
        product_matrix(2, bad, 1.0)


def test_product_matrix_refuses_bad_alpha():
    for bad in (0.0, 3.2, float("nan")):
        with pytest.raises(ValueError, match="alpha"):
            product_matrix(2, 0, bad)


def test_the_claim_is_registered_as_a_proof_and_passes_on_a_small_range():
    from paper_repro.util.registry import CLAIMS, load_all

    load_all()
    c = CLAIMS["pairwise_products_all_n"]
    assert c.kind == "proof"
    out = c.func(ts=["1/2"], n_exact=2, n_modp=3, n_lemma=5, n_signs=4, n_symmetry=3, n_sum=3)
    assert out.passed


def test_product_matrix_at_a_tiny_float_alpha_is_finite_and_sums_to_the_elevation():
    """Hostile pass: alpha = 1e-300 gave NaN (the scaled coefficients underflow); floats below ALPHA_TINY are taken
    there, as elevation_matrix does."""
    for a in (1e-300, 1e-30):
        qs = [product_matrix(3, h, a) for h in range(7)]
        assert all(np.isfinite(q).all() and q.min() >= 0 for q in qs)
        np.testing.assert_allclose(sum(qs).sum(axis=1), 1.0, atol=1e-15)
