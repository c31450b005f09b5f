"""Theorem G and the conjecture of docs/subdivision_for_all_n.md, section 9, at the claim's four alpha.

For each n given and tan(alpha/8) in {1/20, 1/7, 1/3, 2/5}: whether the G columns of the library's exact S_u equal
the explicit columns of Theorem G, the number of negative entries of S_u, the number predicted by Theorem G's
polynomials (the G columns alone), the number outside the G columns (the conjecture: 0), and the middle matrix's
negative entries.  Exact arithmetic; 2-34 s per (n, alpha) for n = 5..8 on the loaded machine.

Run: ``python tools/subdivision_g_columns.py 5 6 7 8``.  With ``--tan4``: instead, at the eight tan(alpha/4) of
:data:`T4` (alpha/2 need not be a RationalAngle), the number of negative entries of S_u and whether it equals the
prediction (equality means none outside the G columns, since Theorem G's count is the count in those columns).
"""

from __future__ import annotations

import sys
import time

from flint import fmpq

from paper_repro.claims.subdivision import alphas_from_eighth, theorem_g_check
from paper_repro.core.domain import rational_alpha
from paper_repro.core.subdivision import subdivision_matrices, subdivision_matrix
from paper_repro.theory.subdivision_signs import negative_count_at

T8 = ["1/20", "1/7", "1/3", "2/5"]
T4 = ["1/50", "1/10", "1/4", "1/2", "2/3", "4/5", "19/20", "99/100"]


def at_tan4(n: int) -> list[tuple[int, bool]]:
    """(negative entries of S_u, equal to Theorem G's count) at each tan(alpha/4) of :data:`T4`."""
    out = []
    for t in T4:
        alpha = rational_alpha(t)
        s = subdivision_matrix(n, alpha, "u", "exact")
        total = sum(1 for x in s.reshape(-1) if x < 0)
        out.append((total, total == negative_count_at(n, alpha.t)))
    return out


if __name__ == "__main__":
    ns = [int(x) for x in sys.argv[1:] if not x.startswith("--")] or [2, 3, 4]
    if "--tan4" in sys.argv:
        for n in ns:
            print(f"n = {n}, tan(alpha/4) in {T4}: {at_tan4(n)}", flush=True)
        sys.exit(0)
    for n in ns:
        for t8 in T8:
            t0 = time.perf_counter()
            alpha, half = alphas_from_eighth(fmpq(*map(int, t8.split("/"))))
            mats = subdivision_matrices(n, alpha, "exact")
            neg = sum(1 for x in mats[0].reshape(-1) if x < 0)
            check = theorem_g_check(n, alpha, half, mats[0], neg)
            middle = sum(1 for x in mats[3].reshape(-1) if x < 0)
            print(f"n = {n}, tan(alpha/8) = {t8}: Theorem G columns equal: {check['theorem_g_columns']}; negative "
                  f"entries of S_u {neg}, predicted {negative_count_at(n, alpha.t)}, outside the G columns "
                  f"{check['negatives_outside_g']}; middle {middle} ({time.perf_counter() - t0:.1f} s)", flush=True)
