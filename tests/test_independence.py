import mpmath
import numpy as np
import pytest
from flint import fmpq
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.claims.basis_transformation import transformation
from paper_repro.claims.linear_independence import modp_case, numeric_case
from paper_repro.core.basis import evaluate
from paper_repro.core.context import ModpContext
from paper_repro.core.domain import rational_alpha, sample_rational_points
from paper_repro.core.fourier import classes, evaluate_v, new_classes, partners, related, v_labels
from paper_repro.core.labels import delta
from paper_repro.figures.independence import elimination
from paper_repro.printed.coincidence import printed_representatives
from paper_repro.printed.derivatives import printed_sign_cos, printed_sign_m, printed_sign_sin
from paper_repro.theory.derivatives import (
    cos_power_derivative,
    mixed_derivative,
    sign,
    sin_power_derivative,
)
from paper_repro.theory.rank import ball_sigma_min_bound, modp_rank, mp_singular_values, numeric_rank

from .strategies import rational_alphas, rational_points


def test_numeric_rank_gap_criterion_and_control():
    rng = np.random.default_rng(0)
    with mpmath.workdps(40):
        a = np.array([[mpmath.mpf(float(x)) for x in row] for row in rng.normal(size=(6, 6))], dtype=object)
        assert numeric_rank(mp_singular_values(a, 40), 40) == 6
        a[:, 5] = a[:, 0] + a[:, 1]
        assert numeric_rank(mp_singular_values(a, 40), 40) == 5
        # the last column is exactly the sum (floats are exact at 40 digits), and the ball inverse takes the entries
        # exactly: no invertibility can be certified
        with pytest.raises(ZeroDivisionError):
            ball_sigma_min_bound(a, 40)
        a[5, 5] += mpmath.mpf(10) ** -35  # invertible, but only just
        lower, _ = ball_sigma_min_bound(a, 40)
        assert 0 < lower < mpmath.mpf(10) ** -30


def test_linear_independence_small_cases():
    for n in (1, 2, 3):
        res = numeric_case(n, "pi/3", 50, 4, 5)
        assert res["rank"] == delta(n)
        assert modp_case(n, "1/3", 5) == delta(n)
        assert modp_case(n, "1/3", 5, control=True) == delta(n) - 1
    res = numeric_case(5, "pi/2", 50, 4, 5)  # ball-arithmetic path
    assert res["rank"] == delta(5) and "certified" in res["method"]
    assert numeric_case(5, "pi/2", 50, 4, 5, control=True)["rank"] != delta(5)


@given(st.integers(1, 14))
def test_class_counts(n):
    assert len(classes(n)) == 1 + 3 * n * (n + 1) // 2
    new = new_classes(n)
    assert len(new) == 3 * n
    reps = printed_representatives(n)
    assert {next(c for c in classes(n) if r in c) for r in reps} == set(new)


@given(st.integers(1, 6), st.tuples(*[st.integers(0, 6)] * 3), st.tuples(*[st.integers(0, 6)] * 3))
def test_partners_enumeration_agrees_with_the_verbatim_relation(n, a, b):
    # partners() (used to build the classes) enumerates b = a + z(1,1,1) and b = z(1,1,1) - a directly;
    # related() is the printed definition: both must say the same for every pair of E_n
    a = tuple(min(x, n) for x in a)
    b = tuple(min(x, n) for x in b)
    assert (b in partners(a, n)) == related(a, b, n)
    assert related(a, a, n)


def test_v2_matches_paper():
    assert "cos(v+2w)" in v_labels(2) and "sin(u+2v)" in v_labels(2) and len(v_labels(2)) == 19


@given(st.data(), st.integers(1, 3), rational_alphas())
def test_v_exact_float_agree(data, n, alpha):
    pts = data.draw(rational_points(alpha, max_size=3))
    ex = evaluate_v(n, alpha, pts, "exact")
    fl = evaluate_v(n, alpha, pts, "float")
    assert np.max(np.abs(np.array([[float(x) for x in row] for row in ex]) - fl)) < 1e-12
    ar = ModpContext()
    mp_ = evaluate_v(n, alpha, pts, ar)
    assert [ar.from_rational(x) for x in ex.ravel()] == [int(x) for x in mp_.ravel()]


def test_coincidence_rank_small():
    alpha = rational_alpha((2, 5))
    ar = ModpContext()
    for n in (1, 2, 3):
        pts = sample_rational_points(alpha, delta(n) + 4, seed=1)
        both = np.hstack([evaluate(n, alpha, pts, ar), evaluate_v(n, alpha, pts, ar)])
        assert modp_rank(both, ar.p) == delta(n)


def test_derivative_values():
    assert cos_power_derivative(2, fmpq(1), 2) == -2  # (cos^2 t)'' at 0
    assert sin_power_derivative(3, fmpq(2), 3) == 6 * 8  # j! mu^j
    assert printed_sign_cos(2, 2) == 1 and sign(cos_power_derivative(2, fmpq(1), 2)) == -1  # the erratum
    assert printed_sign_cos(1, 2) is None


@given(st.integers(0, 6), st.integers(0, 6), st.integers(1, 16), st.sampled_from([fmpq(1, 3), fmpq(2), fmpq(5, 4)]),
       st.sampled_from([fmpq(1, 2), fmpq(3)]))
def test_proposition_and_sine_rule(i, j, z, lam, mu):
    if i + j:
        assert printed_sign_m(j, z) == sign(mixed_derivative(i, lam, j, mu, z))
    if j:
        assert printed_sign_sin(j, z) == sign(sin_power_derivative(j, mu, z))


def test_elimination_leaves_centre():
    for n in (2, 3):
        steps = elimination(n)
        assert len(steps) == 3 * n


def test_basis_transformation_n1():
    m, ok = transformation(1, "1/2")
    assert ok and m.nrows() == 7


def test_span_residual_detects_functions_outside_the_space(monkeypatch):
    from paper_repro.claims import coincidence

    assert coincidence.span_residual(2, "pi/4", 40, 9) < 1e-25
    real = coincidence.evaluate_v
    # the last delta_2 functions of V_3 include order-3 frequencies, which are not in span T_4
    monkeypatch.setattr(coincidence, "evaluate_v",
                        lambda n, alpha, pts, arith, dps: real(n + 1, alpha, pts, arith, dps=dps)[:, -delta(n):])
    assert coincidence.span_residual(2, "pi/4", 40, 9) > 1e-6
