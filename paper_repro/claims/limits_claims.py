"""Claims ``bernstein_limit``, ``bezier_limit_degree`` and ``bezier_conversion`` (alpha -> 0).

See :mod:`paper_repro.theory.limits` for the derivation of the limits from the closed forms.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.labels import index_of, united_system
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.printed.limits import CONVERSION_N2, CONVERSION_N3
from paper_repro.theory.closed_forms import proof_cached
from paper_repro.theory.limit_formula import multinomial
from paper_repro.theory.limits import bernstein_index, conversion_matrix, limit_degree, limit_terms
from paper_repro.util.registry import Outcome, claim


def _q(x: Fraction) -> fmpq:
    return fmpq(x.numerator, x.denominator)


def limit_error(n: int, k: int, grid: int, dps: int) -> mpmath.mpf:
    """max over a barycentric grid and all functions of |T-bar(alpha x, alpha y, alpha z) - limit|, alpha = 2^-k."""
    terms = limit_terms(n)
    with mpmath.workdps(dps):
        alpha = mpmath.mpf(2) ** -k
        bary = [(mpmath.mpf(i) / grid, mpmath.mpf(j) / grid) for i in range(grid + 1) for j in range(grid + 1 - i)]
        pts = np.array([[alpha * x, alpha * y, alpha * (1 - x - y)] for x, y in bary], dtype=object)
        vals = evaluate_normalized(n, alpha, pts, "mp", dps=dps)
        worst = mpmath.mpf(0)
        for p, (x, y) in enumerate(bary):
            z = 1 - x - y
            for f, (c, (a, b, cc)) in enumerate(terms):
                lim = mpmath.mpf(int(c.p)) / int(c.q) * x**a * y**b * z**cc
                worst = max(worst, abs(vals[p, f] - lim))
        return worst


def limit_table(n: int) -> dict:
    out = {}
    for lab, (c, t) in zip(united_system(n), limit_terms(n)):
        m = sum(t)
        out[lab.paper] = {"limit_coefficient": str(c), "monomial_xyz": list(t), "bernstein": bernstein_index(t),
                          "limit_over_bernstein": str(c / multinomial(m, t))}
    return out


@claim("bernstein_limit", paper_ref=["que:limiting_case", "fig:limit_cases_n_1_2_3"],
       statement="As alpha -> 0 (u = alpha x, v = alpha y, w = alpha z) each normalized function of level j tends to "
                 "P(1) x^a y^b z^c, a rational multiple of the Bernstein polynomial P^{2n+j}_{a,b,c}; the centre tends "
                 "to 0 (exactly, n = 1..{n_max}). Convergence is of order alpha^2 (numerically, "
                 "n in {convergence_ns}).",
       kind="exact-evidence", n_max=10, convergence_ns=[1, 2, 3, 5], ks=list(range(2, 9)), grid=6, dps=40)
def run_limit(n_max, convergence_ns, ks, grid, dps) -> Outcome:
    orders, errors = {}, {}
    for n in convergence_ns:
        errs = [limit_error(n, k, grid, dps) for k in ks]
        slope = -np.polyfit(np.array(ks, float), np.array([float(mpmath.log(e, 2)) for e in errs]), 1)[0]
        orders[str(n)] = round(float(slope), 3)
        errors[str(n)] = {f"2^-{k}": mpmath.nstr(e, 3) for k, e in zip(ks, errs)}
    centre_zero = all(limit_terms(n)[0][0] == 0 for n in range(1, n_max + 1))
    exact_bernstein_levels = {str(n): sorted({lab.j for lab, (c, t) in zip(united_system(n), limit_terms(n))
                                              if c == multinomial(sum(t), t)}) for n in range(1, n_max + 1)}
    data = {"limits/limit_terms.json": {str(n): limit_table(n) for n in range(1, n_max + 1)}}
    ok = centre_zero and all(abs(o - 2) < 0.1 for o in orders.values())
    return Outcome(ok, {
        "centre_limit_zero_for_all_n": centre_zero, "observed_order": orders, "expected_order": 2,
        "max_error": errors, "levels_whose_limit_is_exactly_the_Bernstein_polynomial": exact_bernstein_levels,
        "note": "level 0 limits are the Bernstein polynomials P^{2n}_{a,0,c}; for n >= 2 higher levels are rational "
                "multiples of P^{2n+j}_{a,b,c} (data/limits/limit_terms.json)",
        "scope": "limit coefficients exact from the closed forms, proven for every alpha for these n (claim "
                 "nonnegativity_extended); the convergence order is numeric evidence"}, data=data)


@claim("bezier_limit_degree", paper_ref=["que:limiting_case"],
       statement="Question que:limiting_case answered for n = 1..{n_max} (proof for these n; for all n see claim "
                 "limit_formula): the alpha -> 0 limit of an order-n patch is a "
                 "Bezier triangle of degree exactly 3n-1 (levels j give degrees 2n+j, the centre vanishes).",
       kind="proof", n_max=10)
def run_degree(n_max) -> Outcome:
    rows = {}
    for n in range(1, n_max + 1):
        degrees = sorted({sum(t) for c, t in limit_terms(n) if c != 0})
        rows[str(n)] = {"degree": limit_degree(n), "degrees_present": degrees,
                        "centre_vanishes": limit_terms(n)[0][0] == 0}
    ok = all(r["degree"] == 3 * int(n) - 1 and r["centre_vanishes"] and r["degrees_present"] ==
             list(range(2 * int(n), 3 * int(n))) for n, r in rows.items())
    ok &= all(proof_cached(n)["proved"] for n in range(1, n_max + 1))
    return Outcome(ok, {"per_n": rows, "rational_patches": "weights and weighted points convert with the same "
                                                          "matrix (homogeneous coordinates): a rational Bezier "
                                                          "triangle of degree 3n-1",
                        "scope": "exact limit coefficients from the closed forms, proven for every alpha for these n"})


def _render(terms: dict[str, fmpq]) -> str:
    return " + ".join(f"{w} {lab}" for lab, w in terms.items() if w != 0)


@claim("bezier_conversion", paper_ref=["que:limiting_case", "fig:conversion_of_limit_cases_n_1_2_3"],
       statement="The printed conversions of order-2 and order-3 control nets to quintic and octic Bezier nets agree "
                 "with the general conversion, except the index/label misprints recorded as errata "
                 "(p_{8,8,0}, p_{2,1,5}, p_{3,2,3}).",
       kind="proof")
def run_conversion() -> Outcome:
    errata, checked, mismatches = [], 0, []
    for n, table in ((2, CONVERSION_N2), (3, CONVERSION_N3)):
        idx, w = conversion_matrix(n)
        ix = index_of(n)
        labs = [lab.control_point for lab in united_system(n)]
        for key, terms in table.items():
            checked += 1
            t = tuple(int(x) for x in key[3:-1].split(","))
            vec = [fmpq(0)] * len(labs)
            for wt, lab in terms:
                vec[ix[lab]] += _q(wt)
            printed = " + ".join(f"{wt} {lab}" for wt, lab in terms)
            if t not in idx:  # not an index of degree N: find the computed point with these weights
                match = [s for s in idx if w[idx.index(s)] == vec]
                corrected = f"p_{{{','.join(map(str, match[0]))}}}" if match else "no index has these weights"
                errata.append({"id": f"conversion-{key}", "paper_ref": "que:limiting_case", "item": key,
                               "severity": "typo",  # not an index at all: the intended point is clear
                               "printed": f"{key} = {printed}", "corrected": f"{corrected} = {printed}",
                               "evidence": f"{key} is not an index of the degree-{3 * n - 1} Bezier net "
                                           f"(indices sum to {3 * n - 1}); the printed weights are those of "
                                           f"{corrected} in the exact general conversion"})
                mismatches.append(key)
                continue
            row = w[idx.index(t)]
            if row != vec:
                comp = {labs[f]: row[f] for f in range(len(labs))}
                errata.append({"id": f"conversion-{key}", "paper_ref": "que:limiting_case", "item": key,
                               "severity": "statement",  # a valid formula that gives a wrong point as written
                               "printed": f"{key} = {printed}", "corrected": f"{key} = {_render(comp)}",
                               "evidence": "exact general conversion (limit of the normalized basis written in "
                                           f"the degree-{3 * n - 1} Bernstein basis)"})
                mismatches.append(key)
    expected = {"p_{8,8,0}", "p_{2,1,5}", "p_{3,2,3}"}
    return Outcome(set(mismatches) == expected, {"printed_formulas_checked": checked, "mismatches": mismatches,
                                                 "scope": "exact comparison; the conversion weights do not depend "
                                                          "on alpha"}, errata=errata)
