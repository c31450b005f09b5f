"""Signs of the subdivision matrices and the de Casteljau question (docs/subdivision_for_all_n.md, sections 9, 10;
paper_repro.theory.subdivision_signs, paper_repro.theory.decasteljau).  The cheap parts (about 10 s)."""

from __future__ import annotations

from math import comb

import pytest
from flint import fmpq, fmpq_mat

from paper_repro.claims.subdivision import alphas_from_eighth
from paper_repro.core.domain import rational_alpha
from paper_repro.core.subdivision import subdivision_matrix
from paper_repro.theory import decasteljau as dc
from paper_repro.theory import subdivision_signs as ss


@pytest.mark.parametrize("n", [1, 2, 3])
def test_theorem_g_columns_equal_the_library(n):
    """Theorem G: the G columns of S_u from the rotation polynomials and the normalizing coefficients equal the
    library's S_u = M_{alpha/2} Rot M_alpha^{-1} (another route), every row, at two alpha; and not at a third alpha
    (the comparison can fail)."""
    for t8 in (fmpq(1, 20), fmpq(1, 3)):
        alpha, _ = alphas_from_eighth(t8)
        s = subdivision_matrix(n, alpha, "u", "exact")
        cols = ss.explicit_g_columns(n, t8)
        for key, col in ss.g_index(n).items():
            assert [s[r, col] for r in range(s.shape[0])] == [cols[key].get(r, fmpq(0)) for r in range(s.shape[0])]
    other = ss.explicit_g_columns(n, fmpq(1, 7))
    assert any(s[r, col] != other[key].get(r, fmpq(0)) for key, col in ss.g_index(n).items()
               for r in range(s.shape[0]))


def test_witness_closed_form_for_every_n_sampled():
    """Corollary W: S_u[G_{2n,2n-1,1}, G_{2n,2n-1,0}] = g(alpha) (-s') / g'(alpha/2) equals the closed form
    c(c - 1)/(2^{n+1}(1 + c)^n((n - 1)c + n)) (n >= 2), -c/(2(1 + c)) (n = 1), n = 1..8 at two alpha (the
    derivation by hand from Theorem B checked against the library's normalizing coefficients), and is negative; the
    n >= 2 formula is not the n = 1 entry."""
    for t8 in (fmpq(1, 20), fmpq(2, 5)):
        alpha, half = alphas_from_eighth(t8)
        for n in range(1, 9):
            idx = ss.g_index(n)
            entry = ss.explicit_g_columns_at(n, alpha, half)[(1, 0)][idx[(1, 1)]]
            assert entry == ss.witness_entry(n, alpha.cos_half) < 0
        c = alpha.cos_half
        assert ss.witness_entry(1, c) != c * (c - 1) / (4 * (1 + c))


def test_hand_negative_pairs_and_n_squared():
    """Corollary N: in the block of order m the m entries of hand_negative_pairs are single negative monomials in T
    (negative on 0 < T < 1), distinct; summed over i = 0..2n (m = min(i, 2n - i)) they are n^2."""
    for m in range(0, 41):
        pairs = ss.hand_negative_pairs(m)
        assert len(pairs) == len(set(pairs)) == m
        for p, j in pairs:
            coeffs = ss.poly(m, p, j)
            assert sum(1 for a in coeffs if a != 0) == 1 and coeffs[-1] < 0
    for n in range(1, 60):
        assert sum(len(ss.hand_negative_pairs(min(i, 2 * n - i))) for i in range(2 * n + 1)) == n * n


def test_poly_is_the_expansion():
    """(*) against sympy's expansion of sin^j(x + theta) cos^{m-j}(x + theta) / cos^m(theta), m <= 6."""
    import sympy as sp

    s_, c_, t_ = sp.symbols("S C T")
    for m in range(7):
        for j in range(m + 1):
            expr = sp.Poly(sp.expand((s_ + c_ * t_) ** j * (c_ - s_ * t_) ** (m - j)), s_, c_)
            for p in range(m + 1):
                want = expr.coeff_monomial(s_**p * c_ ** (m - p))
                got = sum(a * t_**k for k, a in enumerate(ss.poly(m, p, j)))
                assert sp.expand(want - got) == 0


def test_sign_classes_n3_and_small_alpha_count():
    """The two sign-changing entries of n = 3 (docs section 5c: c = cos(alpha/2) = 1/3, i.e. T^2 = 1/2); the exact
    sign-definite counts of the G columns for n <= 4; near alpha = 0 the G columns have binom(n + 2, 3) negative
    entries (p > j, p - j odd)."""
    assert ss.sign_class(3, 1, 1) == ("changes", ("sqrt(2)/2",))
    assert ss.sign_class(3, 2, 2)[0] == "changes"
    counts = {n: ss.g_column_signs(n) for n in range(1, 5)}
    assert [counts[n]["negative"] for n in range(1, 5)] == [1, 4, 10, 20]
    assert [counts[n]["changes"] for n in range(1, 5)] == [0, 0, 2, 7]
    for n in range(1, 11):
        assert ss.negative_count_at(n, fmpq(1, 10**6)) == comb(n + 2, 3)
        floor_sum = 2 * sum((m + 1) ** 2 // 4 for m in range(n)) + (n + 1) ** 2 // 4
        assert floor_sum == comb(n + 2, 3)


def test_predicted_count_is_the_total_count():
    """The conjecture of section 9 (every negative entry of S_u lies in a G column), exact at one alpha, n = 2, 3
    (n <= 8 at four alpha in the docs)."""
    for n in (2, 3):
        for t in ("9/10",):
            alpha = rational_alpha(t)
            s = subdivision_matrix(n, alpha, "u", "exact")
            assert sum(1 for x in s.reshape(-1) if x < 0) == ss.negative_count_at(n, alpha.t)


@pytest.mark.slow
def test_n1_not_corner_cutting_for_every_alpha():
    """n = 1: the machine-proven closed form (tools/subdivision_n1_proof.py) has -1/2 in the middle (centre <- centre)
    and -c/(2(1 + c)) in corner u (centre <- G_{2,1,0}), negative for every c in (0, 1), the latter equal to
    Corollary W."""
    import importlib.util
    from pathlib import Path

    import sympy as sp

    path = Path(__file__).resolve().parents[1] / "tools" / "subdivision_n1_proof.py"
    spec = importlib.util.spec_from_file_location("subdivision_n1_proof", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    forms = mod.closed_forms()
    labels = [lab.paper for lab in __import__("paper_repro.core.labels", fromlist=["x"]).united_system(1)]
    centre, g210 = labels.index("R_{2,1,1}"), labels.index("G_{2,1,0}")
    c = mod.C
    assert sp.simplify(forms["middle"][centre, centre] + sp.Rational(1, 2)) == 0
    assert sp.simplify(forms["u"][centre, g210] + c / (2 * (1 + c))) == 0
    assert sp.simplify(forms["u"][centre, g210].subs(c, sp.Rational(3, 5)) - sp.Rational(-3, 16)) == 0


def test_lp_certificate_n2():
    """De Casteljau, variant 'coefficients' (w >= 0, rows sum to 1) at n = 2: an exact Farkas certificate; scaled by
    -1 it is no certificate; the 'cone' variant (no row sums) and the 'points' variant (seven points) have none
    (feasible: the equalities alone are consistent)."""
    t8 = fmpq(1, 5)
    cert, opt, k = dc.certificate(2, t8, "coefficients")
    assert cert is not None and cert.value < 0 and cert.min_entry >= 0 and opt < -1
    assert dc.verify(k, cert.y, cert.z) == (cert.value, cert.min_entry)
    neg = fmpq_mat(cert.y.nrows(), cert.y.ncols(), [-x for x in cert.y.entries()])
    val, low = dc.verify(k, neg, [-x for x in cert.z])
    assert not (val < 0 and low >= 0)
    for variant in ("cone", "points"):
        cert2, opt2, _ = dc.certificate(2, t8, variant)
        assert cert2 is None and abs(opt2) < 1e-9
    assert dc.equalities_consistent(k)  # so the certificate is about the signs
    k_bad = fmpq_mat(k.nrows(), k.ncols(), [x * 2 for x in k.entries()])
    assert not dc.equalities_consistent(k_bad)


@pytest.mark.slow
def test_grid_certificate_n2():
    """The strongest variant at n = 2: weights of any sign, >= 0 at 38 rational grid points: exact certificate."""
    cert, opt = dc.grid_certificate(2, fmpq(1, 5), 8)
    assert cert is not None and cert.points == 38 and cert.value < 0 and cert.min_entry >= 0
    assert all(cert.u[i, j] >= 0 for i in range(cert.u.nrows()) for j in range(cert.u.ncols()))
    kp, lag, _ = dc._lagrange_parts(2, fmpq(1, 5), 8)
    ent = dc.grid_dual_entries(kp, lag, cert.y, cert.u)
    assert min(ent[r, c] + cert.z[r] for r in range(ent.nrows()) for c in range(ent.ncols())) >= 0


def test_theorem_g_for_the_corners_v_and_w():
    """Theorem G for S_v (members with cos(v/2)) and S_w (cos(w/2)): the G columns moved by the cyclic relabelling
    u -> v -> w -> u (compose with (1, 2, 0), resp. (2, 0, 1)), every row, n = 3 at one alpha."""
    from paper_repro.core.labels import compose, exponent_matrix
    from paper_repro.core.subdivision import subdivision_matrices

    n = 3
    alpha, half = alphas_from_eighth(fmpq(1, 3))
    mats = subdivision_matrices(n, alpha, "exact")
    exps = [tuple(int(x) for x in r) for r in exponent_matrix(n)]
    rows = {e: k for k, e in enumerate(exps)}
    cols = ss.explicit_g_columns_at(n, alpha, half)
    for s, shift in ((mats[1], (1, 2, 0)), (mats[2], (2, 0, 1))):
        for key, col in ss.g_index(n).items():
            moved = rows[compose(exps[col], shift)]
            want = {rows[compose(exps[r], shift)]: v for r, v in cols[key].items()}
            assert [s[r, moved] for r in range(s.shape[0])] == [want.get(r, fmpq(0)) for r in range(s.shape[0])]
