"""The subdivision matrices as rational functions of X = cos(alpha/4) and the pole check at X = 1
(paper_repro.theory.subdivision_limit; docs/subdivision_for_all_n.md, section 11, Proposition 11.6)."""

from __future__ import annotations

import numpy as np
import pytest
from flint import fmpq, fmpq_poly

import paper_repro.theory.subdivision_limit as sl
from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import united_system
from paper_repro.core.subdivision import PARTS, subdivision_matrices, subdivision_matrix
from paper_repro.theory.subdivision_limit import (
    even_in_x,
    exact_matrices_at,
    limit_check,
    numerators,
    rows_where_xi_half_vanishes,
)

#: The seven members of T_2 in the order of docs/subdivision_for_all_n.md section 5's tables.
ORDER_5 = ["R_{2,1,1}", "R_{2,2,0}", "R_{2,1,0}", "G_{2,2,0}", "G_{2,1,0}", "B_{2,2,0}", "B_{2,1,0}"]


def _section5_tables(a, b, p, q, h, half, one) -> dict[str, list[list]]:
    """The two 7 x 7 tables of section 5 (S_u and S_middle), typed from the page with its letters
    a = 1/(2(1 + c)), b = c/(2(1 + c)), p = 2a, q = 2b, h = (1 - c)/(2(1 + c)) and its constants 1/2 and 1 (as
    parameters, so that the derivatives can be written with the same tables)."""
    s_u = [[half, a, b, 0, -b, 0, b],
           [0, one, 0, 0, 0, 0, 0],
           [0, p, q, 0, 0, 0, 0],
           [0, a, q, a, 0, 0, 0],
           [h, a, b, 0, b, 0, b],
           [0, a, 0, 0, 0, a, q],
           [0, p, 0, 0, 0, 0, q]]
    s_mid = [[-half, a, b, a, b, a, b],
             [0, 0, 0, a, q, a, 0],
             [h, 0, b, 0, b, a, b],
             [0, a, 0, 0, 0, a, q],
             [h, a, b, 0, b, 0, b],
             [0, a, q, a, 0, 0, 0],
             [h, 0, b, a, b, 0, b]]
    return {"u": s_u, "middle": s_mid}


def _in_library_order(table: list[list]) -> np.ndarray:
    labels = [lab.paper for lab in united_system(1)]
    pos = [ORDER_5.index(name) for name in labels]
    return np.array([[fmpq(table[pos[g]][pos[f]]) for f in range(7)] for g in range(7)], dtype=object)


def test_n1_limit_is_section5_at_c_1():
    """At alpha -> 0 (X = 1, c = cos(alpha/2) = 1) section 5's letters become a = b = 1/4, p = q = 1/2, h = 0 (by
    hand): S_u(0+) and S_middle(0+) are the tables with these values."""
    quarter, half = fmpq(1, 4), fmpq(1, 2)
    want = _section5_tables(quarter, quarter, half, half, fmpq(0), half, fmpq(1))
    res = limit_check(1)
    assert (res.limits[PARTS.index("u")] == _in_library_order(want["u"])).all()
    assert (res.limits[PARTS.index("middle")] == _in_library_order(want["middle"])).all()


def test_n1_slopes_are_section5_derivatives():
    """d/dX at X = 1 of section 5's letters, by hand with c = 2X^2 - 1: a = 1/(4X^2) -> -1/2; b = 1/2 - 1/(4X^2) ->
    1/2; p = 1/(2X^2) -> -1; q = 1 - p -> 1; h = (1 - X^2)/(2X^2) -> -1; the constants -> 0."""
    want = _section5_tables(fmpq(-1, 2), fmpq(1, 2), fmpq(-1), fmpq(1), fmpq(-1), fmpq(0), fmpq(0))
    res = limit_check(1)
    for part in ("u", "middle"):
        assert (res.slopes[PARTS.index(part)] == _in_library_order(want[part])).all(), part


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_no_pole_at_x_1(n):
    """Every entry of the four S_k: no pole at X = 1; the only row whose xi'_g vanishes at X = 1 is the centre
    R_{2n,n,n} (so the check is not vacuous there), to order 1; S_k(0+) has rows summing to 1."""
    res = limit_check(n)
    assert res.max_pole == 0 and res.entries == 4 * len(united_system(n)) ** 2
    assert res.max_ord_xi_half == 1
    assert [united_system(n)[g].paper for g in rows_where_xi_half_vanishes(n)] == [f"R_{{{2 * n},{n},{n}}}"]
    assert all(sum(row, fmpq(0)) == 1 for m in res.limits for row in m)
    assert min(res.cancelled.values()) > 0


def test_a_wrong_numerator_gives_a_pole(monkeypatch):
    """The check can fail: add 1 to the numerator of R_1^u[centre, R_{2,2,0}] (a wrong order-one restriction) and
    the entry S_u[centre, R_{2,2,0}] gets a pole of order 1 at X = 1 (xi'_centre vanishes there to order 1)."""
    true = sl.order_one_numerators

    def wrong(part):
        out = [list(row) for row in true(part)]
        if part == "u":
            labels = [lab.paper for lab in united_system(1)]
            out[labels.index("R_{2,1,1}")][labels.index("R_{2,2,0}")] += 1
        return tuple(tuple(row) for row in out)

    monkeypatch.setattr(sl, "order_one_numerators", wrong)
    res = limit_check(1)
    assert res.poles["u"] == 1 and res.poles["middle"] == 0
    labels = [lab.paper for lab in united_system(1)]
    assert res.pole_entries["u"] == [(labels.index("R_{2,1,1}"), labels.index("R_{2,2,0}"))]
    assert res.pole_entries["v"] == res.pole_entries["w"] == res.pole_entries["middle"] == []


def test_no_pole_entries_unchanged():
    """Without the change no entry is listed (the same function, so the test above is not vacuous)."""
    assert all(v == [] for v in limit_check(1).pole_entries.values())


@pytest.mark.parametrize("n", [1, 4, 9])
def test_level_forms_equal_proof_code(n):
    """The forms the check runs on (``_level_terms``) equal the proofs' dictionary construction, levels 2..n."""
    assert sl.level_forms_equal_proof_code(n)


def test_level_forms_comparison_can_fail(monkeypatch):
    """One coefficient of the level-3 forms changed (a wrong fast build) is seen."""
    import paper_repro.core.subdivision_products as sp_mod

    true = sp_mod._level_terms

    def wrong(k):
        out = list(true(k))
        if k == 3:
            coef = out[4].copy()
            coef[len(coef) // 2] += 1
            out[4] = coef
        return tuple(out)

    monkeypatch.setattr(sl, "_level_terms", wrong)
    assert sl.level_forms_equal_proof_code(2)
    assert not sl.level_forms_equal_proof_code(3)


@pytest.mark.parametrize("n", [1, 2, 3])
@pytest.mark.parametrize("t8", [fmpq(1, 3), fmpq(1, 5)])
def test_rational_functions_equal_collocation(n, t8):
    """The complete rational functions at X = cos(alpha/4) = (1 - t8^2)/(1 + t8^2) equal the exact collocation S
    (M_{alpha/2} Rot_k M_alpha^{-1}) at tan(alpha/4) = 2 t8/(1 - t8^2), every entry of the four parts."""
    x0 = (1 - t8 * t8) / (1 + t8 * t8)
    exact = subdivision_matrices(n, rational_alpha(2 * t8 / (1 - t8 * t8)), "exact")
    assert all((a == b).all() for a, b in zip(exact_matrices_at(n, x0), exact))


@pytest.mark.parametrize("n", [2, 3])
def test_degree_bound_suffices(n):
    """The coefficients of the numerators beyond the degree bound are zero (more terms add only zeros)."""
    for part in ("u", "middle"):
        full, terms = numerators(n, part)
        more, _ = numerators(n, part, terms + 3)
        assert all(m is None for m in more[terms:])
        assert all((a is None and b is None) or a == b for a, b in zip(full, more[:terms]))


@pytest.mark.parametrize("n", [1, 2, 4])
def test_limit_against_float_route(n):
    """The float route at alpha = 1e-100 (ALPHA_TINY) is S(0+) to rounding, and S(1e-3) - S(1e-100) is
    -r'(1) alpha^2/32 + O(alpha^4) (X = cos(alpha/4) = 1 - alpha^2/32 + ...): a wrong slope would miss by about
    alpha^2/32 = 3e-8."""
    res = limit_check(n)
    alpha = 1e-3
    for k, part in enumerate(PARTS):
        lim = np.vectorize(float)(res.limits[k])
        slope = np.vectorize(float)(res.slopes[k])
        tiny = subdivision_matrix(n, 1e-100, part)
        assert np.abs(tiny - lim).max() < 1e-15
        diff = subdivision_matrix(n, alpha, part) - tiny
        assert np.abs(diff + slope * alpha**2 / 32).max() < 1e-14
        assert np.abs(diff).max() > 1e-9  # the alpha^2 term is there (n >= 1: some r'(1) != 0)


@pytest.mark.parametrize("n", [1, 2, 3])
def test_entries_are_even_in_x(n):
    """Every r(X) is even (so S_k has entries in Q(cos(alpha/2)), X^2 = (1 + cos(alpha/2))/2): exact, complete
    polynomials; n = 1 agrees with section 5 (every entry there a rational function of c)."""
    assert even_in_x(n) == {part: 0 for part in PARTS}


def test_evenness_check_can_fail(monkeypatch):
    """With xi'_g multiplied by X (not even) the entries of the non-zero columns stop being even: the check counts
    them."""
    true = sl.scaled_xi
    x = fmpq_poly([0, 1])
    monkeypatch.setattr(sl, "scaled_xi", lambda n, half: tuple(p * x for p in true(n, half)) if half else true(n, half))
    assert min(even_in_x(1).values()) > 0


@pytest.mark.parametrize("part", PARTS)
def test_order_one_numerators_every_part(part):
    """N_1^k[:, h] / (2X)^e(h) is ``order_one_restriction``'s R_1^k at a float X = cos(alpha/4), every part (the
    doctest covers the middle only)."""
    from paper_repro.core.subdivision_products import order_one_restriction

    e = sl.sine_degree(1)
    num = sl.order_one_numerators(part)
    for kp in (np.cos(0.3), np.cos(0.01), np.cos(0.7)):
        r1 = np.array([[float(num[g][h](kp)) / (2 * kp) ** int(e[h]) for h in range(7)] for g in range(7)])
        assert np.abs(r1 - order_one_restriction(part, kp, 1 - kp * kp)).max() < 1e-14


@pytest.mark.parametrize("call, exc, words", [
    (lambda L: L.limit_check(0), ValueError, "n must"),
    (lambda L: L.limit_check(21), ValueError, "n must"),
    (lambda L: L.limit_check(2.0), TypeError, "n must"),
    (lambda L: L.limit_check(1, terms=0), ValueError, "terms"),
    (lambda L: L.numerators(1, "x"), ValueError, "part must"),
    (lambda L: L.exact_matrices_at(1, 0.8), TypeError, "x0 must"),
    (lambda L: L.exact_matrices_at(1, fmpq(1, 2)), ValueError, "x0 = cos"),   # below cos(pi/4)
    (lambda L: L.exact_matrices_at(1, 1), ValueError, "x0 = cos"),            # alpha = 0
    (lambda L: L.even_in_x(None), TypeError, "n must"),
])
def test_hostile_input_is_refused_naming_the_parameter(call, exc, words):
    from paper_repro.theory import subdivision_limit as L

    with pytest.raises(exc, match=words):
        call(L)
