"""Theorem G and the conjecture of docs/subdivision_for_all_n.md, section 9, at the claim's four alpha.

For each n given and tan(alpha/8) in {1/20, 1/7, 1/3, 2/5}: whether the G columns of the library's exact S_u equal
the explicit columns of Theorem G, the number of negative entries of S_u, the number predicted by Theorem G's
polynomials (the G columns alone), the number outside the G columns (the conjecture: 0), and the middle matrix's
negative entries.  Exact arithmetic; 2-34 s per (n, alpha) for n = 5..8 on the loaded machine.

Run: ``python tools/subdivision_g_columns.py 5 6 7 8``.
"""

from __future__ import annotations

import sys
import time

from flint import fmpq

from paper_repro.claims.subdivision import alphas_from_eighth, theorem_g_check
from paper_repro.core.subdivision import subdivision_matrices
from paper_repro.theory.subdivision_signs import negative_count_at

T8 = ["1/20", "1/7", "1/3", "2/5"]

if __name__ == "__main__":
    for n in [int(x) for x in sys.argv[1:]] or [2, 3, 4]:
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
