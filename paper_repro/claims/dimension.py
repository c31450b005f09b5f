"""Claim ``dimension``: delta_n = 3n(n+1) + 1 (Theorem joint_systems_linear_independence).

Three independent counts are compared for every n in the range:

1. the printed closed form ``3n(n+1) + 1``;
2. the printed index sum of the proof, ``1 + 3 sum_{j=0}^{n-1} sum_{i=j}^{2n-1-j} 1``;
3. the number of *distinct* functions in the union of R_{2n}, G_{2n} and B_{2n} built from the full systems
   (eqs. R_system..B_system, (n+1)^2 labels each), identified by their exponent vectors --
   i.e. the set the graph describes, without using the index ranges of eq. united_system.

Linear independence (that these functions are a basis) is the separate claim of issue 3.
"""

from __future__ import annotations

from paper_repro.core.labels import COLORS, delta, exponents, full_system, united_system
from paper_repro.printed.dimension import printed_index_sum
from paper_repro.util.registry import Outcome, claim


def distinct_functions(n: int) -> int:
    """Number of distinct monomials in the union of the full R, G, B systems."""
    return len({exponents(lab) for c in COLORS for lab in full_system(n, c)})


@claim("dimension", paper_ref=["joint_systems_linear_independence", "united_system", "dimension"],
       statement="T_{2n} has delta_n = 3n(n+1)+1 functions: the printed closed form, the printed index "
                 "sum and the number of distinct functions of the union of R_{2n}, G_{2n} and B_{2n} agree, "
                 "for n = {n_min}..{n_max}.",
       kind="proof", n_min=1, n_max=50)
def run(n_min: int, n_max: int) -> Outcome:
    bad = []
    for n in range(n_min, n_max + 1):
        counts = (delta(n), printed_index_sum(n), distinct_functions(n), len(united_system(n)),
                  len({exponents(lab) for lab in united_system(n)}))
        if len(set(counts)) != 1:
            bad.append({"n": n, "closed_form": counts[0], "index_sum": counts[1], "distinct_union": counts[2],
                        "united_system_labels": counts[3], "distinct_in_T": counts[4]})
    sample = {str(n): delta(n) for n in (1, 2, 3, 10, 20, 30, 50) if n_min <= n <= n_max}
    return Outcome(not bad, {"n_checked": n_max - n_min + 1, "delta_n_sample": sample, "mismatches": bad})
