"""Claim ``limit_formula``: the alpha -> 0 limit factors in closed form, for every n (Question que:limiting_case).

See :mod:`paper_repro.theory.limit_formula` and the written proof ``docs/limit_for_all_n.md``.  The proof for
every n rests on four lemmas, each a finite statement per n; they are checked exactly for
n <= ``checks_n_max``.  Independently of that proof, for n <= ``closed_form_n_max`` the formula is compared
with the limits P(1) of the closed forms, which are proven for every alpha.  Consequences (every n): the limit
of an order-n patch is a Bezier triangle of degree 3n - 1 whose control points are convex combinations of
the trigonometric control points with the explicit weights of :func:`paper_repro.theory.limits.conversion_matrix`.
"""

from __future__ import annotations

from paper_repro.theory.closed_forms import proof_cached, records, remember
from paper_repro.theory.limit_formula import conversion_weights_nonnegative, limit_checks, limit_terms_formula
from paper_repro.theory.limits import conversion_is_convex, limit_terms
from paper_repro.util.registry import Outcome, claim
from paper_repro.util.tasks import Task


def agrees_with_closed_forms(rec: dict) -> bool:
    """The formula equals the limits P(1) of the proven closed forms of order ``rec["n"]`` (a task)."""
    remember(rec)
    n = rec["n"]
    return bool(proof_cached(n)["proved"] and limit_terms(n) == limit_terms_formula(n))


LEMMAS = ("exponent_set", "uniform_factor", "telescoping", "partition_of_unity", "monomials_independent")


@claim("limit_formula", paper_ref=["que:limiting_case", "fig:limit_cases_n_1_2_3",
                                   "fig:conversion_of_limit_cases_n_1_2_3"],
       statement="Question que:limiting_case, answered for every n >= 1: R-bar_{2n,2n-i,j} tends to "
                 "L x^{2n-i} y^j z^i with L = (2n+j)!/((2n-i)! j! i!) times 1 (j = 0), (2n-j)/(2n+j) (i = j), "
                 "2n/(2n+j) (j < i), 0 (centre), so the limit of an order-n (rational) patch is a (rational) Bezier "
                 "triangle of degree 3n-1 whose control points are convex combinations of the original ones. "
                 "Proof for every n: written argument docs/limit_for_all_n.md (no assumption beyond it; neither the "
                 "paper's independence theorem nor the closed forms are used); its four finite lemmas checked "
                 "exactly for n <= {checks_n_max}; independently, the formula equals the limits of the closed forms "
                 "(proven for every alpha) for n <= {closed_form_n_max}.",
       kind="proof", closed_form_n_max=12, checks_n_max=20,
       extended={"closed_form_n_max": 30, "checks_n_max": 40}, split=True)
def run(closed_form_n_max: int, checks_n_max: int):
    # tasks: the lemmas per n, and the closed forms per n (shared with the other claims of the run); then the
    # comparison with the closed forms per n
    convex_top = min(checks_n_max, 12)
    forms_ns = sorted(set(range(1, closed_form_n_max + 1)) | set(range(1, convex_top + 1)))
    checks, recs = yield from records(forms_ns, [Task(limit_checks, (n,)) for n in range(1, checks_n_max + 1)])
    for rec in recs:
        remember(rec)
    agree = yield [Task(agrees_with_closed_forms, (rec,)) for rec in recs if rec["n"] <= closed_form_n_max]
    by_closed_forms = [n for n, ok in zip(range(1, closed_form_n_max + 1), agree) if ok]
    by_checks = [r["n"] for r in checks if all(r[k] for k in LEMMAS)]
    degree_ok = all(r["degree"] == 3 * r["n"] - 1 for r in checks)
    weights_ok = all(conversion_weights_nonnegative(n) for n in range(1, checks_n_max + 1))
    convex_n = [n for n in range(1, min(checks_n_max, 12) + 1) if conversion_is_convex(n)]
    ok = (by_closed_forms == list(range(1, closed_form_n_max + 1)) and by_checks == list(range(1, checks_n_max + 1))
          and degree_ok and weights_ok and convex_n == list(range(1, min(checks_n_max, 12) + 1)))
    return Outcome(ok, {
        "formula_equals_limits_of_proven_closed_forms_for_n": [min(by_closed_forms or [0]),
                                                               max(by_closed_forms or [0])],
        "lemmas_checked_exactly_for_n": [min(by_checks or [0]), max(by_checks or [0])],
        "per_n": [{k: r[k] for k in ("n",) + LEMMAS + ("monomials_rank", "delta_n", "degree")} for r in checks],
        "degree_3n_minus_1": degree_ok, "conversion_weights_nonnegative": weights_ok,
        "conversion_rows_sum_to_one_for_n": [min(convex_n or [0]), max(convex_n or [0])],
        "scope": ("proof for every n >= 1 (written proof docs/limit_for_all_n.md, its lemmas checked exactly for "
                  f"n <= {checks_n_max}); the formula also agrees with the limits of the closed forms, proven for "
                  f"every alpha, for n <= {closed_form_n_max}"),
        "cross_checks": "tests/test_limit_formula.py compares the limit net with the bezier package "
                        "(Triangle of degree 3n-1, and Triangle.elevate applied three times)"})
