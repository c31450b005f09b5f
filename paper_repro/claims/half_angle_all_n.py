"""Claims ``elevation_all_n`` and ``derivative_all_n``: order elevation and the derivative matrix C in closed form for
every n (issue 30; Example exmp:degree_elevation_from_1_to_2 and Question 1 of sec:open_problems).

Both matrices are built from two half-angle identities by the rules of :mod:`paper_repro.core.half_angle_rules`,
proven for every n and alpha in docs/elevation_and_derivative_for_all_n.md.  The checks below compare what the
rules build with routes that know nothing of them (:mod:`paper_repro.theory.half_angle_checks`); their ranges are
the parameters of each claim.
"""

from __future__ import annotations

import time

from flint import fmpq

from paper_repro.core.domain import rational_alpha
from paper_repro.core.half_angle_matrices import derivative_form, elevation_form
from paper_repro.theory import half_angle_checks as hc
from paper_repro.util.registry import Outcome, claim

#: tan(alpha/4) of the sampled shape parameters: alpha = 4 atan(t) from about 0.004 (near 0) to 3.12 (near pi).
TS = ["1/1000", "1/7", "1/2", "5/7", "99/100"]


def _alphas(ts: list[str]):
    return [rational_alpha(fmpq(*map(int, t.split("/")))) for t in ts]


def _failures(rows: dict) -> list:
    return [k for k, v in rows.items() if not (v["ok"] if isinstance(v, dict) else v)]


@claim("elevation_all_n", paper_ref=["exmp:degree_elevation_from_1_to_2", "sec:open_problems",
                                     "joint_systems_linear_independence"],
       statement="Order elevation n -> n+1 in closed form for every n >= 1 and alpha in (0, pi): m_f = sigma m'_{Pf} "
                 "+ L_x L_x m'_{Pf} with the cotangent rules (A), (A_n), (B) of two half-angle identities, so every "
                 "entry of M lies in Z_{>=0}[cos(alpha/2), sin^2(alpha/2)], E = diag(x')^{-1} M diag(x) >= 0 and its "
                 "rows sum to 1: elevation is a convex combination for every n and alpha (proof: "
                 "docs/elevation_and_derivative_for_all_n.md). Machine checks: the identities (I), (II) and every "
                 "cotangent rule used hold exactly at rational points for n <= {n_rules}; the identity holds exactly "
                 "over Q at a "
                 "unisolvent rational point set (= exact collocation) for n <= {n_exact} and modulo a prime for "
                 "n <= {n_modp}, at tan(alpha/4) in {ts}; E = the literal exact collocation solve for "
                 "n <= {n_collocation} there; every coefficient of the bivariate form > 0 for n <= {n_signs}; "
                 "exact row sums 1 for n <= {n_rows} at the same alpha.",
       kind="proof", ts=TS, n_rules=5, n_exact=4, n_modp=8, n_collocation=3, n_signs=15, n_rows=8,
       extended={"ts": TS, "n_rules": 9, "n_exact": 8, "n_modp": 12, "n_collocation": 6, "n_signs": 25,
                 "n_rows": 10})
def run_elevation(ts, n_rules, n_exact, n_modp, n_collocation, n_signs, n_rows) -> Outcome:
    t0 = time.perf_counter()
    alphas = _alphas(ts)
    identities = hc.identities_hold()
    rules = {n: hc.rules_hold(n) for n in range(1, n_rules + 1)}
    ident = {}
    for n in range(1, max(n_exact, n_modp) + 1):
        for t, a in zip(ts, alphas):
            arith = "exact" if n <= n_exact else "modp"
            ident[f"n={n} t={t}"] = hc.identity_check("M", n, a, elevation_form(n), arith=arith)
    colloc = {f"n={n} t={t}": hc.collocation_equal(n, a, elevation_form(n))
              for n in range(1, n_collocation + 1) for t, a in zip(ts, alphas)}
    signs = {n: hc.nonnegative(elevation_form(n)) for n in range(1, n_signs + 1)}
    rows = {f"n={n} t={t}": hc.row_sums_exact(n, a, elevation_form(n))
            for n in range(1, n_rows + 1) for t, a in zip(ts, alphas)}
    bad = {"identities_I_II": [] if identities else ["fail"], "rules": _failures(rules),
           "identity": _failures(ident), "collocation": _failures(colloc), "signs": _failures(signs),
           "row_sums": _failures(rows)}
    ok = not any(bad.values())
    return Outcome(ok, {
        "identities_I_II_exact_at_points": len(hc.POINTS), "rules_exact_for_n": f"1..{n_rules}",
        "rule_evaluations": sum(v["checked"] for v in rules.values()),
        "identity_exact_over_Q_for_n": f"1..{n_exact}", "identity_mod_p_for_n": f"{n_exact + 1}..{n_modp}",
        "prime": hc.PRIME, "alphas": [f"4 atan({t})" for t in ts],
        "equals_literal_exact_collocation_for_n": f"1..{n_collocation}",
        "bivariate_form_positive_for_n": f"1..{n_signs}",
        "monomials_by_n": {n: v["monomials"] for n, v in signs.items()},
        "exact_row_sums_one_for_n": f"1..{n_rows}",
        "failures": bad,
        "proof": "docs/elevation_and_derivative_for_all_n.md (hand proof for every n; the checks are independent "
                 "evidence for the stated ranges)"},
        raw={"seconds": time.perf_counter() - t0})


@claim("derivative_all_n", paper_ref=["sec:open_problems", "joint_systems_linear_independence"],
       statement="The derivative matrix C (2 s d/du m_f = sum_g C[g,f] m_g on the scaled monomials of T_{2n}, "
                 "u = (1, 0, -1)) in closed form for every n >= 1 and alpha in (0, pi): C = (D_u - D_w) expanded by "
                 "the cotangent rules, at most 4 rule terms per column, every entry an integer polynomial in "
                 "cos(alpha/2) and sin^2(alpha/2) (proof: docs/elevation_and_derivative_for_all_n.md). Machine "
                 "checks: with sin^2 = 1 - cos^2 it equals the package tables recovered modulo two primes for "
                 "n <= {n_tables} (a fresh recovery for n in {n_recovered}); the identity holds exactly over Q at a "
                 "unisolvent rational point set (= exact collocation) for n <= {n_exact} and modulo a prime for "
                 "n <= {n_modp}, at tan(alpha/4) in {ts}.",
       kind="proof", ts=TS, n_tables=10, n_recovered=[3], n_exact=4, n_modp=8,
       extended={"ts": TS, "n_tables": 10, "n_recovered": [11, 12], "n_exact": 8, "n_modp": 12})
def run_derivative(ts, n_tables, n_recovered, n_exact, n_modp) -> Outcome:
    from paper_repro.theory.derivative_matrix import derivative_polynomials

    t0 = time.perf_counter()
    alphas = _alphas(ts)
    tables = {n: hc.tables_equal(n, derivative_form(n)) for n in range(1, n_tables + 1)}
    recovered = {n: hc.tables_equal(n, derivative_form(n), derivative_polynomials(n)) for n in n_recovered}
    ident = {}
    for n in range(1, max(n_exact, n_modp) + 1):
        for t, a in zip(ts, alphas):
            arith = "exact" if n <= n_exact else "modp"
            ident[f"n={n} t={t}"] = hc.identity_check("C", n, a, derivative_form(n), arith=arith)
    bad = {"tables": _failures(tables), "recovered": _failures(recovered), "identity": _failures(ident)}
    ok = not any(bad.values())
    return Outcome(ok, {
        "equals_recovered_tables_for_n": f"1..{n_tables}",
        "equals_fresh_modular_recovery_for_n": list(n_recovered),
        "identity_exact_over_Q_for_n": f"1..{n_exact}", "identity_mod_p_for_n": f"{n_exact + 1}..{n_modp}",
        "prime": hc.PRIME, "alphas": [f"4 atan({t})" for t in ts],
        "entries_by_n": {n: len(hc.kappa_polynomials(derivative_form(n))) for n in range(1, n_tables + 1)},
        "failures": bad,
        "proof": "docs/elevation_and_derivative_for_all_n.md (hand proof for every n; the checks are independent "
                 "evidence for the stated ranges)"},
        raw={"seconds": time.perf_counter() - t0})


def _product_forms(n: int) -> list:
    from paper_repro.core.half_angle_matrices import product_form

    return [product_form(n, h) for h in range(7)]


def recurrence_holds(n: int, alpha, forms) -> bool:
    """The paper's first consequence, exactly at ``alpha``: ``x'_g = sum_{f, h} x_f x_h P_h[g, f]`` (scaled
    normalizing coefficients of orders n, 1 and n + 1; those of order n + 1 from Theorem B's formula)."""
    from paper_repro.core.context import ExactContext
    from paper_repro.core.half_angle_matrices import evaluate_terms, half_angle, scaled_coefficients

    ctx = ExactContext()
    kappa, sigma = half_angle(alpha, ctx)
    x, x1, x2 = (scaled_coefficients(k, kappa, sigma, ctx) for k in (n, 1, n + 1))
    total = ctx.zeros((len(x2),))
    for h, form in enumerate(forms):
        rows, cols, vals = evaluate_terms(form, kappa, sigma, ctx)
        for r, c, v in zip(rows.tolist(), cols.tolist(), vals.tolist()):
            total[r] += x1[h] * x[c] * v
    return total.tolist() == x2.tolist()


@claim("pairwise_products_all_n", paper_ref=["sec:open_problems", "exmp:from_1_to_2",
                                            "exmp:degree_elevation_from_1_to_2"],
       statement="The products the paper 'could not write' (sec:open_problems, after Question 1), for every n >= 1 and "
                 "alpha in (0, pi): each normalized member of T-bar_{2n} times each of the seven normalized members of "
                 "T-bar_2 -- B_{2,2,0}, G_{2,1,0}, B_{2,1,0} among them -- is a combination of T-bar_{2(n+1)} with "
                 "coefficients x_f x_h P_h[g, f] / x'_g, P_h in Z_{>=0}[cos(alpha/2), sin^2(alpha/2)]: one member, "
                 "two, or a cotangent rule (A), (A_n), (B) applied at most n times (proof: "
                 "docs/elevation_and_derivative_for_all_n.md, Theorem P). Hence, as the paper wished: the recurrence "
                 "x'_g = sum_{f,h} x_f x_h P_h[g, f] between normalizing coefficients of consecutive orders, their "
                 "symmetry and positivity inherited from order to order, and the elevation (sum_h x_h P_h = M). "
                 "Machine checks: each product identity exactly over Q at a unisolvent rational point set for "
                 "n <= {n_exact} and modulo a prime for n <= {n_modp}, at tan(alpha/4) in {ts}; the lowering lemma "
                 "for orders <= {n_lemma}; every coefficient of each P_h positive for n <= {n_signs}; "
                 "P_{πh}[πg, πf] = P_h[g, f] for the three exchanges π of two variables for n <= {n_symmetry}; "
                 "sum_h x_h P_h = M and the recurrence exactly for n <= {n_sum} at the same alpha.",
       kind="proof", ts=TS, n_exact=3, n_modp=6, n_lemma=16, n_signs=15, n_symmetry=10, n_sum=6,
       extended={"ts": TS, "n_exact": 5, "n_modp": 10, "n_lemma": 31, "n_signs": 25, "n_symmetry": 20, "n_sum": 10})
def run_products(ts, n_exact, n_modp, n_lemma, n_signs, n_symmetry, n_sum) -> Outcome:
    t0 = time.perf_counter()
    alphas = _alphas(ts)
    ident = {}
    for n in range(1, max(n_exact, n_modp) + 1):
        forms = _product_forms(n)
        for t, a in zip(ts, alphas):
            arith = "exact" if n <= n_exact else "modp"
            for h, form in enumerate(forms):
                ident[f"n={n} h={h} t={t}"] = hc.identity_check("P", n, a, form, arith=arith, h=h)
    lemma = {n: hc.lowering_lemma(n) for n in range(1, n_lemma + 1)}
    signs = {f"n={n} h={h}": hc.nonnegative(form) for n in range(1, n_signs + 1)
             for h, form in enumerate(_product_forms(n))}
    symmetry = {n: hc.products_equivariant(n, _product_forms(n)) for n in range(1, n_symmetry + 1)}
    sums = {f"n={n} t={t}": hc.product_sum_is_elevation(n, a, _product_forms(n))
            for n in range(1, n_sum + 1) for t, a in zip(ts, alphas)}
    recurrence = {f"n={n} t={t}": recurrence_holds(n, a, _product_forms(n))
                  for n in range(1, n_sum + 1) for t, a in zip(ts, alphas)}
    bad = {"identity": _failures(ident), "lowering_lemma": _failures(lemma), "signs": _failures(signs),
           "symmetry": _failures(symmetry), "sum_is_elevation": _failures(sums), "recurrence": _failures(recurrence)}
    ok = not any(bad.values())
    return Outcome(ok, {
        "products": "h = R_{2,1,1}, R_{2,2,0}, R_{2,1,0}, G_{2,2,0}, G_{2,1,0}, B_{2,2,0}, B_{2,1,0} (the seven "
                    "members of T_2)",
        "identity_exact_over_Q_for_n": f"1..{n_exact}", "identity_mod_p_for_n": f"{n_exact + 1}..{n_modp}",
        "prime": hc.PRIME, "alphas": [f"4 atan({t})" for t in ts],
        "lowering_lemma_for_orders": f"1..{n_lemma}",
        "every_coefficient_positive_for_n": f"1..{n_signs}",
        "monomials_by_n": {n: sum(v["monomials"] for k, v in signs.items() if k.startswith(f"n={n} "))
                           for n in range(1, n_signs + 1)},
        "equivariant_for_n": f"1..{n_symmetry}",
        "sum_is_elevation_and_recurrence_exact_for_n": f"1..{n_sum}",
        "failures": bad,
        "proof": "docs/elevation_and_derivative_for_all_n.md, Theorem P, Lemma L, Corollary P (hand proof for "
                 "every n on the refereed cotangent rules; the checks are independent evidence for the stated ranges)"},
        raw={"seconds": time.perf_counter() - t0})
