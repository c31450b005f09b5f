"""Claim ``partition_of_unity``: the normalized system T-bar_{2n} sums to one (Section
sec:partition_of_unity), with unique coefficients obeying symmetry_condition_1..3.

* exact: at rational-tangent alpha the coefficients are exact rationals and sum_f x_f f(p) == 1 is
  checked exactly at random rational points of Omega^alpha (exact evidence: sampled alpha);
* symmetry: the full delta_n-unknown system (no symmetry assumed) has the same solution as the
  reduced orbit system, and the printed conditions symmetry_condition_1..3 hold (exact);
* float64 and mpmath: partition of unity at seeded random points over several alpha.
"""

from __future__ import annotations

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.alphas import alpha_float, alpha_mp
from paper_repro.core.basis import evaluate
from paper_repro.core.domain import rational_alpha, sample_points, sample_rational_points
from paper_repro.core.labels import index_of
from paper_repro.core.normalization import coefficient_vector, evaluate_normalized, solve_full_exact
from paper_repro.util.measured import bound
from paper_repro.util.registry import Outcome, claim


def printed_symmetry_conditions(n: int) -> list[tuple[str, str]]:
    """Pairs of coefficient labels the paper says are equal (symmetry_condition_1..3), verbatim ranges."""
    pairs = []
    for j in range(n):
        for i in range(j + 1, n):  # symmetry_condition_1: r_{2n,2n-i,j} = r_{2n,i,j}
            pairs.append((f"r_{{{2 * n},{2 * n - i},{j}}}", f"r_{{{2 * n},{i},{j}}}"))
        for i in range(j, 2 * n - j):  # conditions 2 and 3: g = r, b = r
            pairs.append((f"g_{{{2 * n},{2 * n - i},{j}}}", f"r_{{{2 * n},{2 * n - i},{j}}}"))
            pairs.append((f"b_{{{2 * n},{2 * n - i},{j}}}", f"r_{{{2 * n},{2 * n - i},{j}}}"))
    return pairs


@claim("partition_of_unity", paper_ref=["sec:partition_of_unity", "normalizing_weights", "symmetry_condition_1",
                                        "symmetry_condition_2", "symmetry_condition_3", "normalized_united_system"],
       statement="T-bar_{2n} is a partition of unity with unique coefficients that satisfy the printed symmetry "
                 "conditions; the reduced (symmetric) system gives the same coefficients as the full one "
                 "(exactly at tan(alpha/4) in {rational_ts} for n = {ns}; the full system for n <= "
                 "{full_system_n_max}).",
       kind="exact-evidence", ns=list(range(1, 9)), rational_ts=["1/5", "1/3", "2/5", "3/4"], exact_points=6,
       full_system_n_max=4, alphas=["0.1", "pi/6", "pi/2", "5pi/6", "3.1"], float_points=2000, mp_points=5, seed=11)
def run(ns, rational_ts, exact_points, full_system_n_max, alphas, float_points, mp_points, seed) -> Outcome:
    exact_fail, sym_fail = [], []
    for n in ns:
        for k, t in enumerate(rational_ts):
            alpha = rational_alpha(fmpq(*map(int, t.split("/"))))
            vec = coefficient_vector(n, alpha, "exact")
            pts = sample_rational_points(alpha, exact_points, seed=seed + k)
            vals = evaluate(n, alpha, pts, "exact")
            for p in range(len(pts)):
                if sum((vals[p, f] * vec[f] for f in range(len(vec))), fmpq(0)) != 1:
                    exact_fail.append({"n": n, "t": t, "point": p})
            if n <= full_system_n_max:
                full = solve_full_exact(n, alpha)
                if list(full) != list(vec):
                    sym_fail.append({"n": n, "t": t, "what": "full system differs from reduced"})
                idx = index_of(n)
                for a, b in printed_symmetry_conditions(n):
                    if full[idx[a]] != full[idx[b]]:
                        sym_fail.append({"n": n, "t": t, "what": f"{a} != {b}"})
    worst_float, worst_mp, min_value = 0.0, mpmath.mpf(0), np.inf
    for n in ns:
        for k, a_text in enumerate(alphas):
            a = alpha_float(a_text)
            vals = evaluate_normalized(n, a, sample_points(a, float_points, seed=seed + k))
            worst_float = max(worst_float, float(np.max(np.abs(vals.sum(axis=1) - 1))))
            min_value = min(min_value, float(vals.min()))
            with mpmath.workdps(50):
                am = alpha_mp(a_text)
                pts = np.array([[am * x for x in row] for row in np.asarray(
                    sample_points(1.0, mp_points, seed=seed + 50 + k), dtype=object)], dtype=object)
                pts[:, 2] = am - pts[:, 0] - pts[:, 1]
                mv = evaluate_normalized(n, am, pts, "mp", dps=50)
                worst_mp = max(worst_mp, max(abs(sum(row) - 1) for row in mv))
    # float64 tolerance: a sum of delta_n non-negative terms each with relative error <= ~(3n+2) eps
    tol_float = 1e-12
    passed = not exact_fail and not sym_fail and worst_float <= tol_float and worst_mp <= mpmath.mpf(10) ** -30
    return Outcome(passed, {
        "exact_identity_failures": exact_fail, "symmetry_failures": sym_fail,
        "exact_checked": {"n": ns, "tan_alpha_4": rational_ts, "points_per_case": exact_points,
                          "full_system_up_to_n": full_system_n_max},
        "float64_max_abs_error": bound(worst_float, tol_float), "float64_tolerance": tol_float,
        "mp50_max_abs_error": bound(worst_mp, 1e-30), "mp_tolerance": "1e-30",
        "min_normalized_value_float_non_negative": bool(min_value >= 0),
        "scope": "exact at sampled rational-tangent alpha (evidence for all alpha); "
                 "see claim nonnegativity for proofs over all alpha",
    }, raw={"float64_max_abs_error": worst_float, "mp50_max_abs_error": mpmath.nstr(worst_mp, 5),
            "min_normalized_value_float": min_value})
