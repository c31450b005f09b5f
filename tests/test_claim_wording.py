"""Claims say exactly what their code does (issue 19, item 2), and data/ holds only machine-independent values
(item 3): each check below is shown to reject a wrong input."""

import numpy as np
import pytest
from flint import fmpq, fmpq_poly

from paper_repro.core.labels import delta
from paper_repro.surfaces.patch import Patch
from paper_repro.util.measured import bound, bound_holds, data_violations, decade_bound, sig, violations
from paper_repro.util.registry import CLAIMS, Claim, Outcome, load_all, run_claim

load_all()


# -- univariate: the key identity is a polynomial identity in sin/cos, not a sample -----------------------------------
def test_univariate_identity_is_proven_as_a_polynomial_identity():
    from paper_repro.claims.univariate import base_identity_residual

    assert base_identity_residual().is_zero()
    assert not base_identity_residual(1).is_zero() and not base_identity_residual(3).is_zero()
    assert "rational_alphas" not in CLAIMS["univariate"].defaults  # nothing sampled is called a proof


# -- patch_properties: tangent planes with exact derivatives ----------------------------------------------------------
@pytest.mark.parametrize("n", [1, 2, 3])
def test_tangent_plane_check_passes_the_right_plane_and_rejects_a_wrong_one(n):
    from paper_repro.claims.surfaces_claims import CORNERS, tangent_plane_exact, tangent_plane_residual

    rng = np.random.default_rng(n)
    patch = Patch(n, 1.3, rng.normal(size=(delta(n), 3)))
    assert max(tangent_plane_residual(patch, c) for c in CORNERS) < 1e-12
    # the plane of the terminal edge of one boundary polygon and the first point of the *wrong* other polygon
    wrong = (f"r_{{{2 * n},{2 * n - 1},0}}", f"g_{{{2 * n},1,0}}")
    assert tangent_plane_residual(patch, "r", wrong) > 1e-3  # far above the claim's tolerance 1e-9
    net = [[int(x) for x in row] for row in rng.integers(-9, 10, size=(delta(n), 3))]
    assert all(tangent_plane_exact(n, fmpq(1, 3), net, c) for c in CORNERS)
    assert not tangent_plane_exact(n, fmpq(1, 3), net, "r", wrong)


def test_patch_properties_tolerance_is_not_loose():
    import inspect

    from paper_repro.claims import surfaces_claims

    src = inspect.getsource(surfaces_claims.run_properties)
    assert "1e-4" not in src and "h = 1e-6" not in src and 'res["tangent_planes"] < tol' in src


# -- elevation_closed_forms: the positivity it uses is checked ---------------------------------------------------------
def test_elevation_checks_positive_normalizing_coefficients(monkeypatch):
    from paper_repro.claims import matrix_closed_forms as m
    from paper_repro.theory.closed_form import ClosedForm

    assert m.normalizing_coefficients_positive(1) == {"closed_forms_proven": True, "numerators_positive_on_(0,1)": True}
    # a proven form whose numerator changes sign on (0, 1) is caught
    monkeypatch.setattr(m, "closed_forms_cached",
                        lambda n: {"r_{2,2,0}": ClosedForm("r_{2,2,0}", 2, fmpq_poly([1, -3]))})
    assert m.normalizing_coefficients_positive(1)["numerators_positive_on_(0,1)"] is False


def test_symmetry_statement_states_its_range():
    assert "{n_max}" in CLAIMS["symmetry"].statement


# -- independence_proof_steps: the printed proof lines are run --------------------------------------------------------
def test_proof_lines_catch_a_line_that_does_not_hold(monkeypatch):
    from paper_repro.claims import independence_proof as ip
    from paper_repro.claims.lines import LineResult
    from paper_repro.printed.lines import Line

    lines = [Line("sec1_3-a", (700, 700), "chain_rule", "display", "x", "x", "checked", check="good"),
             Line("sec1_3-b", (710, 710), "chain_rule", "display", "y", "y", "erratum", check="err",
                  erratum={"printed": "y", "corrected": "z", "evidence": "e", "severity": "typo"}),
             Line("sec1_3-c", (720, 720), "chain_rule", "display", "g", "g", "erratum",
                  check="claim:independence_proof_steps",
                  erratum={"printed": "y", "corrected": "z", "evidence": "e", "severity": "typo"}),
             Line("sec1_3-out", (100, 100), "united_system", "display", "o", "o", "checked", check="bad")]
    checks = {"good": lambda: LineResult(True), "err": lambda: LineResult(False, True),
              "bad": lambda: LineResult(False)}
    monkeypatch.setattr("paper_repro.printed.lines.all_lines", lambda: lines)
    monkeypatch.setattr("paper_repro.claims.lines.load_checks", lambda: checks)
    out = ip.proof_lines()
    assert out["lines"] == 3 and out["checked"] == ["sec1_3-a"] and out["erratum"] == ["sec1_3-b"]
    assert out["resolved_to_this_claim"] == ["sec1_3-c"] and not out["failures"]  # line outside the proof ignored
    checks["good"] = lambda: LineResult(False)
    assert ip.proof_lines()["failures"] == ["sec1_3-a"]
    checks["good"], checks["err"] = (lambda: LineResult(True)), (lambda: LineResult(True, True))
    assert ip.proof_lines()["failures"] == ["sec1_3-b"]  # an erratum whose printed form holds is no erratum


# -- data/: machine-independent values only ---------------------------------------------------------------------------
def test_helpers():
    assert bound(3e-15, 1e-12) == "< 1e-12" and bound_holds(bound(3e-15, 1e-12))
    assert not bound_holds(bound(2e-12, 1e-12))
    assert sig(0.036532646271739466, 3) == 0.0365 and decade_bound(4.44e-16) == 1e-15
    assert decade_bound(1e-15) == 1e-15 and decade_bound(1.0000001e-15) == 1e-14


def test_rule_finds_raw_floats():
    assert violations({"a": 8.881784197001252e-15}) == ["a"]  # rounding level
    assert violations({"b": [0.036532646271739466]}) == ["b/0"]  # too many digits
    assert violations({"c": "5.74e-41", "d": "3.193e-51"}) == ["c", "d"]  # mp rounding level as text
    assert violations({"ok": [1e-12, "< 1e-30", "1e-40", 2.0001, 7, "0.0001425", True, None, "1.538e-6"]}) == []
    files = {"x.json": {"rows": [{"e": 4.44e-16}]}, "m.obj": {"__mesh__": {"vertices": [[0.1234567891]]}},
             "dupin/nets.json": {"p": 4.53488372093023}}
    assert data_violations(files) == ["x.json:rows/0/e"]


def test_runner_fails_a_claim_that_publishes_a_raw_float(tmp_path, monkeypatch):
    from paper_repro.util import cache

    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path)
    raw = Claim("raw", ["x"], "s", "proof", lambda: Outcome(True, {"gap": 5.329070518200751e-15}), {})
    res, _, _ = run_claim(raw)
    assert res.status == "fail" and "gap" in res.measured["error"]
    clean = Claim("clean", ["x"], "s", "proof", lambda: Outcome(True, {"gap": bound(5.3e-15, 1e-12)},
                                                              raw={"gap": 5.329070518200751e-15}), {})
    res, out, _ = run_claim(clean)
    assert res.status == "pass" and out.raw == {"gap": 5.329070518200751e-15}
    in_data = Claim("in_data", ["x"], "s", "proof", lambda: Outcome(True, {}, data={"f.json": [1.2345678901]}), {})
    assert run_claim(in_data)[0].status == "fail"


# -- question1_all_n: the lemmas run at every alpha the statement names (issue 31, item 6) ----------------------------
def test_question1_statement_names_the_alphas_of_its_lemmas():
    st = CLAIMS["question1_all_n"].statement
    assert "{ts}" in st and "only" in st and "not a proof for the others" in st
    assert "hold exactly for n <= {n_lemma};" not in st  # the old wording, with no alpha


def test_question1_lemmas_are_checked_at_every_named_alpha(monkeypatch):
    """A lemma failing at the second alpha only fails the claim (a check run at the first alpha only would pass)."""
    from paper_repro.claims import question1_all_n as claim
    from paper_repro.core.domain import rational_alpha

    small = dict(n_closed=1, n_lemma=2, n_hexagon=1, n_weights=1, sampled_n=[2], ts=["1/3", "3/4"])
    assert claim.run(**small).passed
    bad_alpha = rational_alpha(fmpq(3, 4))
    orig = claim.q1.order_table

    def wrong_at_second(n, alpha, *a, **k):
        out = orig(n, alpha, *a, **k)
        return {**out, "ok": False} if alpha.t == bad_alpha.t else out

    monkeypatch.setattr(claim.q1, "order_table", wrong_at_second)
    res = claim.run(**small)
    assert not res.passed and "n=1,t=3/4" in res.measured["lemmas_exact_for_n"]
    assert "n=1,t=1/3" not in res.measured["lemmas_exact_for_n"]


# -- general_formulas: what is proven for every n and what for the stated n only (issue 31, item 6) ------------------
def test_general_formulas_does_not_call_the_centre_end_values_consequences():
    st = CLAIMS["general_formulas"].statement
    assert "follow from it" not in st and "not proven for every n" in st and "for each n <= {n_cons}" in st
    assert "(t-1)" not in st and "(mu-1)" in st and "mu the number of minimal entries" in st


def test_the_alpha_to_0_entry_names_mu_not_t():
    from paper_repro.theory.general_formulas import ALL_LEVELS_AT_1

    assert "(\\mu-1)" in ALL_LEVELS_AT_1["latex"] and ALL_LEVELS_AT_1["where"].startswith("mu = ")
    assert "(t-1)" not in ALL_LEVELS_AT_1["latex"]


def test_derivative_docstrings_cite_the_proof():
    """The integer-polynomial derivative matrix was a found pattern until proven (issue 31, item 6); now that
    docs/elevation_and_derivative_for_all_n.md proves it for every n (issue 30), the docstrings cite the proof and
    none calls it a pattern."""
    from paper_repro.core import fast_jit

    for doc in (Patch.derivative.__doc__, fast_jit.__doc__):
        text = " ".join(doc.split())
        assert "elevation_and_derivative_for_all_n" in text and "found pattern," not in text


# -- issue 37, item 5: claims worded as their code -------------------------------------------------------------------
def _statement(cid: str) -> str:
    from paper_repro.util.registry import fill_statement

    return " ".join(fill_statement(CLAIMS[cid].statement, CLAIMS[cid].defaults).split())


def _doc(name: str) -> str:
    from pathlib import Path

    return " ".join((Path(__file__).resolve().parents[1] / "docs" / name).read_text(encoding="utf-8").split())


def test_question1_all_n_says_the_hand_proof_carries_every_n():
    st = _statement("question1_all_n")
    assert "hand proof with machine-checked lemmas" not in st
    assert "the hand proof (docs/question1_for_all_n.md; also Theorem 3.1) carries every n and alpha" in st
    assert "lemmas only in the ranges below (for n <= 12 at 4 alpha" in st and "not a proof for every n" in st


def test_general_formulas_says_which_n_confirm_independently():
    from paper_repro.claims.general_formulas import N_FIT

    st = _statement("general_formulas")
    assert "a hand proof with machine-checked lemmas, for every n" not in st
    assert all(f"{N_FIT[k]} (level {k})" in st for k in N_FIT)
    assert "for those n the agreement holds by construction" in st and "are independent confirmation" in st
    import inspect

    from paper_repro.claims import general_formulas

    assert '"independent_confirmation_for_n"' in inspect.getsource(general_formulas.run)


def test_derivative_all_n_counts_three_rule_terms_per_column(monkeypatch):
    from paper_repro.claims import half_angle_all_n as h
    from paper_repro.theory import half_angle_checks as hc

    st = _statement("derivative_all_n")
    assert "at most 4 rule terms" not in st and "at most 3 rule terms per column" in st
    assert [hc.derivative_rule_terms(n) for n in range(1, 7)] == [2, 3, 3, 3, 3, 3]
    small = {"ts": ["1/7"], "n_tables": 3, "n_recovered": [], "n_exact": 1, "n_modp": 2}
    out = h.run_derivative(**small)
    assert out.passed and out.measured["max_rule_terms_per_column_by_n"] == {1: 2, 2: 3, 3: 3}
    monkeypatch.setattr(hc, "derivative_rule_terms", lambda n: 4)  # a column with four rule terms fails the claim
    assert not h.run_derivative(**small).passed
    assert "at most four rule applications" not in _doc("elevation_and_derivative_for_all_n.md")


def test_pairwise_products_counts_the_cotangent_applications(monkeypatch):
    from paper_repro.claims import half_angle_all_n as h
    from paper_repro.theory import half_angle_checks as hc

    assert "the applications counted in the construction: at most n, and n attained, for n <= 15" in \
        _statement("pairwise_products_all_n")
    assert [hc.cotangent_applications(n) for n in range(1, 6)] == [1, 2, 3, 4, 5]
    small = {"ts": ["1/7"], "n_exact": 1, "n_modp": 2, "n_lemma": 3, "n_signs": 4, "n_symmetry": 2, "n_sum": 1}
    assert h.run_products(**small).passed
    monkeypatch.setattr(hc, "cotangent_applications", lambda n: n + 1)  # more than n applications fails the claim
    assert not h.run_products(**small).passed


def test_linear_independence_says_singular_values_only_for_small_n():
    st = _statement("linear_independence")
    assert "high precision singular values for n = 1..8" not in st
    assert "all singular values by mpmath SVD for n <= 4, beyond only a certified lower bound of sigma_min" in st


def test_coincidence_says_what_is_shown():
    from paper_repro.claims import coincidence

    st = _statement("coincidence")
    assert "numerically at alpha in pi/4, 3pi/4)" not in st
    assert "50-digit singular values give numeric rank delta_n of [T-bar | V] for n = 1..4" in st
    assert "for n = 5..8 (no rank computed)" in st and "A rank mod p is a lower bound of the rank over Q" in st
    doc = " ".join(coincidence.__doc__.split())
    assert "a proof of span T = span V" not in doc and "does not prove rank_Q [T | V] = delta_n" in doc


def test_m_and_c_are_explicit_constructions_not_closed_forms():
    from paper_repro.core import half_angle_matrices
    from paper_repro.theory import half_angle_checks

    for cid in ("elevation_all_n", "derivative_all_n"):
        st = _statement(cid)
        assert "in closed form" not in st and "explicit construction" in st
    for mod in (half_angle_matrices, half_angle_checks):
        first = " ".join(mod.__doc__.split("\n\n")[0].split())
        assert "closed form" not in first.replace("only rule (A) is a closed form", "")
        assert "explicit" in first


def test_docs_say_the_library_E_uses_theorem_B():
    text = _doc("elevation_and_derivative_for_all_n.md")
    assert "The library's E does not:" in text and "Theorem B's formula, `scaled_coefficients`" in text


def test_transformation_all_n_cites_question1_for_all_n():
    from paper_repro.claims import transformation_all_n

    assert "rests on docs/question1_for_all_n.md" in _statement("transformation_all_n")
    assert "docs/question1_for_all_n.md" in transformation_all_n.__doc__.split("\n\n")[1]


def test_level_and_ring_are_two_words_in_the_elevation_proof():
    text = _doc("elevation_and_derivative_for_all_n.md")
    assert "*Level and ring (two words, two indices).*" in text
    for old in ("level-$n$ member", "level-$N$ member", "Rule (A$_n$): level $n$", "at level $m = n$",
                "functions at each level $m < n$", "this member has level $n < N$"):
        assert old not in text, old


def test_m_inverse_growth_is_worded_as_measured():
    """The doc's words: like s^{-3n} only as alpha -> 0; at alpha = 1, 44 to 136 times per order (n <= 7).  Measured
    again here for n <= 5 (float, the library's M^{-1})."""
    from paper_repro.core.transformation import transformation_matrix

    text = _doc("transformation_for_all_n.md")
    assert "$M^{-1}$ grows like $s^{-3n}$ only as $\\alpha \\to 0$" in text and "grows $44$ to $136$ times" in text
    sizes = [float(np.abs(np.asarray(transformation_matrix(n, 1.0, "T_to_V"), dtype=float)).max()) for n in range(1, 6)]
    ratios = [b / a for a, b in zip(sizes, sizes[1:])]
    assert all(44 <= r <= 136 for r in ratios), ratios
    assert all(r > 4 * (1 / np.sin(0.5)) ** 3 for r in ratios)  # far from the s^{-3} ~ 9 per order of alpha -> 0
