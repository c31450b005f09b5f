"""Question 1: multimodular recovery, the identity proof, and the cache that serves both."""

from __future__ import annotations

import threading
import time

import pytest
from flint import fmpq, fmpq_poly

from paper_repro.core.context import ExactContext, ModpContext
from paper_repro.core.domain import RationalPoints, rational_alpha
from paper_repro.core.normalization import orbits, reduced_matrix
from paper_repro.printed.normalization import FINAL
from paper_repro.theory import identity_proof as ip
from paper_repro.theory.closed_forms import ClosedForm, prove
from paper_repro.theory.modular import (
    ReducedSystemModp,
    primes_below,
    rational_reconstruction,
    recover_modular,
)
from paper_repro.util import cache as cache_mod


@pytest.mark.parametrize("n", [4, 7])
def test_fast_modp_matrix_is_the_reduced_matrix(n):
    p = primes_below()[3]
    system = ReducedSystemModp(n, p, seed=1)
    for alpha in (rational_alpha(fmpq(2, 7)), rational_alpha(fmpq(1, 9))):
        direct = reduced_matrix(n, alpha, system.points, ModpContext(p=p))
        assert (system.matrix(alpha) == direct).all()


def test_values_modp_builds_each_point_set_once(monkeypatch):
    """The alpha-independent part of the system is built once per point set, not once per shape parameter."""
    from paper_repro.theory import modular

    built = []
    real = modular.ReducedSystemModp.__init__

    def init(self, *args, **kwargs):
        built.append(args)
        real(self, *args, **kwargs)

    monkeypatch.setattr(modular.ReducedSystemModp, "__init__", init)
    modular.values_modp(3, primes_below()[0], 9)
    assert len(built) == len(set(built)) <= 4


def test_rational_reconstruction():
    m = primes_below()[0] * primes_below()[1]
    x = fmpq(-123457, 9871)
    image = int(x.p) * pow(int(x.q), -1, m) % m
    assert rational_reconstruction(image, m) == x
    # too small a modulus: the image of x does not give x back (x needs |num|, den <= sqrt(m/2))
    p0 = primes_below()[0]
    assert rational_reconstruction(int(x.p) * pow(int(x.q), -1, p0) % p0, p0) != x
    # 5 = -2 (mod 7) and -2/1, 5/1 are outside the bound sqrt(7/2) < 2: no fraction reconstructs
    assert rational_reconstruction(5, 7) is None
    # every fraction within the bound comes back from its image (uniqueness of Wang's reconstruction)
    for num in range(-7, 8):
        for den in range(1, 8):
            q = fmpq(num, den)
            assert rational_reconstruction(int(q.p) * pow(int(q.q), -1, 101) % 101, 101) == q, q


def test_recovered_forms_equal_the_printed_examples():
    """Independent source: the paper's final forms of Examples n = 1, 2, 3 (as functions of alpha)."""
    for n in (1, 2, 3):
        forms = recover_modular(n)
        for t in (fmpq(1, 2), fmpq(2, 9)):
            a = rational_alpha(t)
            s, c = a.sin_half, a.cos_half
            for lab, (_ref, num, k) in FINAL.items():
                if lab.startswith(f"r_{{{2 * n},"):
                    assert forms[lab].value(a) == fmpq_poly(num)(c) / s**k, lab


@pytest.mark.parametrize("n", [2, 3])
def test_residual_polynomial_matches_a_direct_exact_evaluation(n):
    """The cleared residual of a *wrong* candidate equals s^K (1+t^2)^(d+K+R) du^P dv^Q times the exact residual
    computed from the basis functions (no clearing, no polynomials) at more values of t than its degree bound:
    the whole polynomial (grouping, Horner scheme, powers of 1 + t^2) is checked, not one value."""
    forms = dict(recover_modular(n))
    lab = sorted(forms)[len(forms) // 2]
    forms[lab] = ClosedForm(lab, forms[lab].sin_power, forms[lab].numerator + fmpq_poly([1, 1]))
    cache = ip.prepare(n, forms)
    tu, tv = fmpq(1, 5), fmpq(3, 7)
    poly = ip.residual_at_point(n, forms, tu, tv, _cache=cache)
    assert not poly.is_zero()
    bound = 2 * (cache["d"] + cache["K"] + cache["R"])
    assert poly.degree() <= bound
    du, dv = tu.p**2 + tu.q**2, tv.p**2 + tv.q**2
    pts = RationalPoints(None, (tu,), (tv,), check=False)
    for k in range(bound + 1):
        t = fmpq(1, k + 2)
        alpha = rational_alpha(t)
        row = reduced_matrix(n, alpha, pts, ExactContext())[0]
        rho = sum(forms[rep.coefficient].value(alpha) * row[o] for o, (rep, _) in enumerate(orbits(n))) - 1
        scale = alpha.sin_half ** cache["K"] * (1 + t**2) ** (cache["d"] + cache["K"] + cache["R"])
        scale *= fmpq(int(du)) ** cache["P"] * fmpq(int(dv)) ** cache["Q"]
        assert poly(t) == rho * scale


def test_residual_polynomial_of_the_true_forms_is_zero_and_of_a_changed_one_is_not():
    """n = 6 (several sine and cosine powers of w/2 per orbit): zero at the proof points for the recovered forms;
    one coefficient changed by 1 gives a non-zero residual at the first point."""
    n = 6
    forms = dict(recover_modular(n))
    pts = ip.proof_points(n, 4)
    cache = ip.prepare(n, forms)
    assert all(ip.residual_at_point(n, forms, x, y, _cache=cache).is_zero() for x, y in zip(pts.tu, pts.tv))
    lab = sorted(forms)[-1]
    f = forms[lab]
    coeffs = list(f.numerator.coeffs())
    coeffs[len(coeffs) // 2] += 1
    forms[lab] = ClosedForm(lab, f.sin_power, fmpq_poly(coeffs))
    assert not ip.residual_at_point(n, forms, pts.tu[0], pts.tv[0]).is_zero()


@pytest.mark.parametrize("n", [1, 3, 5])
def test_proof_accepts_true_forms_and_rejects_any_changed_one(n):
    forms = recover_modular(n)
    res = prove(n, forms)
    assert res["proved"] and res["independence"]["full"] and res["unisolvence"]["full"]
    for rep, _ in orbits(n)[:: max(1, len(orbits(n)) // 4)]:
        bad = dict(forms)
        f = forms[rep.coefficient]
        bad[rep.coefficient] = ClosedForm(f.label, f.sin_power, f.numerator + fmpq_poly([0, 0, 0, 1]))
        out = prove(n, bad)
        assert not out["proved"] and out["mismatch"] == rep.coefficient


def test_proof_rejects_a_wrong_sine_power():
    forms = dict(recover_modular(2))
    f = forms["r_{4,2,0}"]
    forms["r_{4,2,0}"] = ClosedForm(f.label, f.sin_power + 1, f.numerator)
    assert not prove(2, forms)["proved"]


def test_proof_points_are_alpha_independent_and_distinct():
    pts = ip.proof_points(6, 40)
    assert len(set(zip(pts.tu, pts.tv))) == 40


def test_cache_computes_once_under_concurrency(tmp_path, monkeypatch):
    monkeypatch.setattr(cache_mod, "CACHE_DIR", tmp_path)
    monkeypatch.delenv("PAPER_REPRO_NO_CACHE", raising=False)
    calls = []

    def compute():
        calls.append(1)
        time.sleep(0.3)
        return {"x": 1}

    results = []
    threads = [threading.Thread(target=lambda: results.append(cache_mod.cached("t", {"a": 1}, compute)))
               for _ in range(3)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert len(calls) == 1 and results == [{"x": 1}] * 3


def test_cache_stores_nothing_when_the_computation_fails(tmp_path, monkeypatch):
    monkeypatch.setattr(cache_mod, "CACHE_DIR", tmp_path)
    monkeypatch.delenv("PAPER_REPRO_NO_CACHE", raising=False)

    def boom():
        raise RuntimeError("crash")

    with pytest.raises(RuntimeError):
        cache_mod.cached("t", {"a": 2}, boom)
    assert not list(tmp_path.rglob("*.json"))
    assert cache_mod.cached("t", {"a": 2}, lambda: 7) == 7


def _eval_published(entry: dict, n: int, i: int, c: fmpq) -> fmpq:
    """Evaluate a published level formula from its JSON terms alone (C_{n,k}: the printed univariate constant)."""
    from paper_repro.core.univariate import c_numerator

    total = fmpq(0)
    for t in entry["terms"]:
        k = i + t["shift_k"]
        ck = fmpq_poly(c_numerator(n, k))(c) if 0 <= k <= 2 * n else fmpq(0)
        q = fmpq(*map(int, t["coefficient"].split("/"))) if "/" in t["coefficient"] else fmpq(int(t["coefficient"]))
        total += q * c ** t["c_power"] * i ** t["i_power"] * n ** t["n_power"] * ck
    return total


def test_published_level_formulas_match_an_independent_exact_solve():
    """data/normalization/general_formulas.json against exact collocation solves (no closed forms involved),
    at n = 13, beyond every fitted range and beyond make reproduce's proven range."""
    import json

    from paper_repro.core.normalization import solve_reduced_exact
    from paper_repro.util.io import DATA

    gf = json.loads((DATA / "normalization" / "general_formulas.json").read_text())
    alpha = rational_alpha(fmpq(2, 7))
    n = 13
    sol, _ = solve_reduced_exact(n, alpha, verify=0)
    exact = {rep.coefficient: x for (rep, _), x in zip(orbits(n), sol)}
    s, c = alpha.sin_half, alpha.cos_half
    checked = 0
    for e in gf["levels"]:
        if "terms" not in e:
            continue
        j = e["level"]
        cases = {"interior": range(j + 1, n + 1), "diagonal": [j], "all": range(j, n + 1)}[e["kind"]]
        for i in cases:
            value = _eval_published(e, n, i, c) / s ** (2 * n + j)
            assert value == exact[f"r_{{{2 * n},{2 * n - i},{j}}}"], (j, e["kind"], i)
            checked += 1
    assert checked > 40


def test_matrix_identity_proof_rejects_a_changed_entry():
    """The elevation closed forms prove; changing one non-zero entry makes the identity fail."""
    from paper_repro.theory import elevation_forms as ef
    from paper_repro.theory.matrix_forms import EntryForm, prove_matrix_identity

    res = ef.closed_forms_and_proof("elevation", 1)["M"]
    assert res["proof"]["proved"] and res["proof"]["points_unisolvent"]
    forms = [list(row) for row in res["forms"]]
    i, j = next((i, j) for i, row in enumerate(forms) for j, e in enumerate(row) if not e.is_zero())
    e = forms[i][j]
    forms[i][j] = EntryForm(e.K, e.P + fmpq_poly([0, 1]), e.Q)
    pts = ef._plane(19, 2, seed=31)
    from paper_repro.core.context import ExactContext, to_fmpq_mat

    def at(values):
        return lambda t: to_fmpq_mat(values(rational_alpha(t), pts, ExactContext()))

    out = prove_matrix_identity(forms, at(ef._t_functions(2)), at(ef._t_functions(1)), 4, 2)
    assert not out["proved"]


def test_elevation_forms_agree_with_the_exact_elevation_matrix():
    """Independent route: the normalized exact elevation matrix E (core.elevation, collocation with the
    normalized bases) equals x_f M_gf / x_g with M from the closed forms, at a rational alpha."""
    from paper_repro.core.elevation import elevation_matrix_exact
    from paper_repro.core.normalization import coefficient_vector
    from paper_repro.theory.elevation_forms import closed_forms_and_proof

    n, t = 2, fmpq(2, 9)
    forms = closed_forms_and_proof("elevation", n)["M"]["forms"]
    a = rational_alpha(t)
    x_n, x_n1 = coefficient_vector(n, a, "exact"), coefficient_vector(n + 1, a, "exact")
    e = elevation_matrix_exact(n, a)
    for g, row in enumerate(forms):
        for f, entry in enumerate(row):
            assert e[g][f] == x_n[f] * entry.value(t) / x_n1[g]


def test_values_modp_skips_a_singular_shape_parameter(monkeypatch):
    """A shape parameter at which every point set is singular modulo p is replaced by the next one."""
    from paper_repro.theory import modular

    real = modular.ReducedSystemModp.solve

    def solve(self, alpha):
        if alpha.t == fmpq(1, 3):
            raise ZeroDivisionError("singular")
        return real(self, alpha)

    monkeypatch.setattr(modular.ReducedSystemModp, "solve", solve)
    vals, alphas = modular.values_modp(2, primes_below()[0], 4)
    assert [a.t for a in alphas] == [fmpq(1, 2), fmpq(1, 4), fmpq(1, 5), fmpq(1, 6)] and vals.shape == (4, 6)
    forms = recover_modular(2)
    assert prove(2, forms)["proved"]


def test_published_centre_end_values_match_independent_exact_solves():
    """The centre's two end-value formulas of data/normalization/general_formulas.json against exact collocation
    solves near alpha = 0 and alpha = pi (no closed forms involved): the coefficient is a rational function of
    t = tan(alpha/4), smooth at both ends, so the exact values at t = 1e-6 and t = 1 - 1e-9 are within
    O(t^2) and O(1 - t) of the limits."""
    import json

    from paper_repro.core.normalization import solve_reduced_exact
    from paper_repro.theory.general_formulas import eval_expression
    from paper_repro.util.io import DATA

    gf = json.loads((DATA / "normalization" / "general_formulas.json").read_text())
    by_kind = {e["kind"]: e for e in gf["levels"]}
    for n in (4, 9):
        centre = f"r_{{{2 * n},{n},{n}}}"
        for kind, t, scale, tol in (("centre_alpha_to_0", fmpq(1, 10**6), 3 * n - 2, 1e-8),
                                    ("centre_alpha_to_pi", 1 - fmpq(1, 10**9), 0, 1e-7)):
            alpha = rational_alpha(t)
            sol, _ = solve_reduced_exact(n, alpha, verify=0)
            value = {rep.coefficient: x for (rep, _), x in zip(orbits(n), sol)}[centre] * alpha.sin_half ** scale
            want = eval_expression(by_kind[kind]["expression"], n)
            assert abs(float(value) / want - 1) < tol, (n, kind, float(value), want)


def test_interior_regularities_hold_for_found_levels_and_can_fail():
    from paper_repro.theory.general_formulas import fit, interior_pattern, latex, printed_level_formulas

    for level, n_fit in ((2, 8), (3, 9)):
        assert all(interior_pattern(fit(level, "interior", n_fit)).values())
    # the printed level 1 (i c C_{n,i} + (i+1) C_{n,i+1}) has unequal s^0 parts: the check says so
    assert not interior_pattern(printed_level_formulas()[1])["s0_parts_equal_F_j"]
    # the factored rendering of level 2, derived by hand from the fitted polynomial with c^2 = 1 - s^2
    assert latex(fit(2, "interior", 8)) == (
        "P_{n,i,2}(c) = \\left((i + 1) n - \\tfrac{1}{2} \\, i (i - 1) s^{2}\\right) C_{n,i} + "
        "\\left((i + 1) n c\\right) C_{n,i+1}")
