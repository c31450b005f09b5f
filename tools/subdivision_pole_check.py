"""The pole check of Proposition 11.6 per n: one row of the results table of docs/subdivision_for_all_n.md, section 11
("The pole check"), for each n given, and optionally the comparisons behind "Checked independently".

For each n: :func:`paper_repro.theory.subdivision_limit.limit_check` (every entry of the four S_k, as a rational
function of X = cos(alpha/4), decided for a pole at X = 1; S_k(0+) and dS_k/dX(1) exactly), printed as a markdown
row: n, delta_n, entries, non-zeros (u / middle), centre-row non-zeros (u / middle), max pole order, max ord xi',
max |dS/dX(1)| (corner / middle), whether the rows of S_k(0+) sum to 1, CPU seconds.

``--float``: also the largest |S_float(1e-100) - S(0+)| and |(S(1e-3) - S(1e-100)) + dS/dX(1) 1e-6/32| over the
four parts (the float route of :func:`paper_repro.core.subdivision.subdivision_matrix`).
``--collocation``: also whether the complete rational functions at X = 4/5 equal the exact collocation S at
tan(alpha/4) = 3/4 (:func:`~paper_repro.theory.subdivision_limit.exact_matrices_at`; degree ~ n^2, so n <= 10).
``--even``: also the entries that are not even in X (:func:`~paper_repro.theory.subdivision_limit.even_in_x`).

Run: ``PYTHONPATH=$PWD python tools/subdivision_pole_check.py 1 2 3 4 5 6 7 8`` (n = 12 about 16 s CPU, n = 16 about
77 s).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from flint import fmpq

from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import delta
from paper_repro.core.subdivision import PARTS, subdivision_matrices, subdivision_matrix
from paper_repro.theory.subdivision_limit import even_in_x, exact_matrices_at, limit_check

HEADER = ("| n | δ_n | entries (4δ_n²) | non-zeros u / middle | centre-row non-zeros u / middle | max pole order | "
          "max ord ξ′ | max abs(dS/dX(1)) corner / middle | rows of S(0⁺) sum to 1 | CPU s |\n"
          "|---|---|---|---|---|---|---|---|---|---|")


def row(n: int) -> tuple[str, object]:
    """The table row of order n and the :class:`~paper_repro.theory.subdivision_limit.LimitResult`."""
    start = time.process_time()
    res = limit_check(n)
    cpu = time.process_time() - start
    top = [max(abs(x) for x in m.reshape(-1)) for m in res.slopes]
    rows = all(sum(r, fmpq(0)) == 1 for m in res.limits for r in m)
    text = (f"| {n} | {delta(n)} | {res.entries} | {res.nonzero['u']} / {res.nonzero['middle']} | "
            f"{res.cancelled['u']} / {res.cancelled['middle']} | {res.max_pole} | {res.max_ord_xi_half} | "
            f"{top[0]} / {top[3]} | {rows} | {cpu:.2f} |")
    return text, res


def float_comparison(n: int, res) -> tuple[float, float]:
    """Largest |S_float(1e-100) - S(0+)| and largest residual of the alpha^2 term at alpha = 1e-3, over the parts."""
    err = resid = 0.0
    for k, part in enumerate(PARTS):
        lim = np.vectorize(float)(res.limits[k])
        slope = np.vectorize(float)(res.slopes[k])
        tiny = subdivision_matrix(n, 1e-100, part)
        err = max(err, float(np.abs(tiny - lim).max()))
        diff = subdivision_matrix(n, 1e-3, part) - tiny
        resid = max(resid, float(np.abs(diff + slope * 1e-6 / 32).max()))
    return err, resid


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ns", type=int, nargs="+")
    parser.add_argument("--float", dest="float_", action="store_true")
    parser.add_argument("--collocation", action="store_true")
    parser.add_argument("--even", action="store_true")
    args = parser.parse_args()
    print(HEADER, flush=True)
    for n in args.ns:
        text, res = row(n)
        print(text, flush=True)
        if args.float_:
            err, resid = float_comparison(n, res)
            print(f"  float: |S(1e-100) - S(0+)| <= {err:.2g}, alpha^2 residual at 1e-3 <= {resid:.2g}")
        if args.collocation:
            poly = exact_matrices_at(n, fmpq(4, 5))
            exact = subdivision_matrices(n, rational_alpha(fmpq(3, 4)), "exact")
            print("  equal to collocation at X = 4/5:", all(bool((a == b).all()) for a, b in zip(poly, exact)))
        if args.even:
            print("  entries not even in X:", even_in_x(n))


if __name__ == "__main__":
    main()
