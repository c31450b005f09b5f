"""Claim ``limit_formula``: the alpha -> 0 limit factors in closed form (Question que:limiting_case).

See :mod:`paper_repro.core.limit_formula`.  For n <= ``closed_form_n_max`` the formula is compared with the
limits P(1) of the closed forms, which are proven for every alpha (so the formula is proven there).  For
n <= ``checks_n_max`` the two finite facts (B) partition of unity of the limit monomials and (C) their
linear independence are verified exactly; with the paper's Theorem joint_systems_linear_independence (A)
they prove the formula for that n.  Consequences stated for the same n: the limit of an order-n patch is a
Bezier triangle of degree exactly 3n - 1 and the conversion weights to its Bernstein basis are >= 0.
"""

from __future__ import annotations

from paper_repro.core.closed_forms import proof_cached
from paper_repro.core.limit_formula import conversion_weights_nonnegative, limit_checks, limit_terms_formula
from paper_repro.core.limits import limit_terms
from paper_repro.util.registry import Outcome, claim
from paper_repro.util.sweep import sweep


@claim("limit_formula", paper_ref=["que:limiting_case", "fig:limit_cases_n_1_2_3",
                                   "fig:conversion_of_limit_cases_n_1_2_3"],
       statement="Question que:limiting_case: R-bar_{2n,2n-i,j} tends to L x^{2n-i} y^j z^i with "
                 "L = (2n+j)!/((2n-i)! j! i!) times 1 (j = 0), (2n-j)/(2n+j) (i = j), 2n/(2n+j) (j < i), 0 (centre). "
                 "Proven for n <= {closed_form_n_max} (limits of the proven closed forms) and, given the paper's "
                 "independence theorem, for n <= {checks_n_max} (limit partition of unity and independence of the "
                 "limit monomials, exact); so for these n the limit patch is a Bezier triangle of degree exactly "
                 "3n-1 with non-negative conversion weights. For all n: conjecture.",
       kind="proof", closed_form_n_max=12, checks_n_max=20,
       extended={"closed_form_n_max": 30, "checks_n_max": 40})
def run(closed_form_n_max: int, checks_n_max: int) -> Outcome:
    by_closed_forms = []
    for n in range(1, closed_form_n_max + 1):
        if proof_cached(n)["proved"] and limit_terms(n) == limit_terms_formula(n):
            by_closed_forms.append(n)
    checks = sweep(limit_checks, list(range(checks_n_max, 0, -1)), desc="limit formula (B), (C)")
    checks = sorted(checks, key=lambda r: r["n"])
    by_checks = [r["n"] for r in checks if r["partition_of_unity"] and r["monomials_independent"]]
    degree_ok = all(r["degree"] == 3 * r["n"] - 1 for r in checks)
    weights_ok = all(conversion_weights_nonnegative(n) for n in range(1, checks_n_max + 1))
    ok = (by_closed_forms == list(range(1, closed_form_n_max + 1)) and by_checks == list(range(1, checks_n_max + 1))
          and degree_ok and weights_ok)
    return Outcome(ok, {
        "formula_equals_limits_of_proven_closed_forms_for_n": [min(by_closed_forms or [0]),
                                                               max(by_closed_forms or [0])],
        "limit_partition_of_unity_and_independence_for_n": [min(by_checks or [0]), max(by_checks or [0])],
        "per_n": [{k: r[k] for k in ("n", "partition_of_unity", "monomials_rank", "delta_n", "degree")}
                  for r in checks],
        "degree_3n_minus_1": degree_ok, "conversion_weights_nonnegative": weights_ok,
        "scope": (f"proof for n <= {closed_form_n_max} (closed forms proven for every alpha); proof for n <= "
                  f"{checks_n_max} assuming Theorem joint_systems_linear_independence (A), with (B) and (C) exact; "
                  "conjecture for larger n (B and C open for all n)"),
        "cross_checks": "tests/test_limit_formula.py compares the limit net with the bezier package "
                        "(Triangle of degree 3n-1, and Triangle.elevate applied three times)"})
