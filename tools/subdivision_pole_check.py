"""The pole check of Proposition 11.6 per n: one row of the results table of docs/subdivision_for_all_n.md, section 11
("The pole check"), for each n given, and optionally the comparisons behind "Checked independently".

For each n: :func:`paper_repro.theory.subdivision_limit.limit_check` (every entry of the four S_k, as a rational
function of X = cos(alpha/4), decided for a pole at X = 1; S_k(0+) and dS_k/dX(1) exactly), printed as a markdown
row: n, delta_n, entries, non-zeros (u / middle), centre-row non-zeros (u / middle), max pole order, max ord xi',
max |dS/dX(1)| (corner / middle), whether the rows of S_k(0+) sum to 1, whether the Theorem P forms the check ran on
(``_level_terms``, levels 2..n) equal the proof code's (:func:`~paper_repro.theory.subdivision_limit.
level_forms_equal_proof_code`), CPU seconds.

``--float``: also the largest |S_float(1e-100) - S(0+)| and |(S(1e-3) - S(1e-100)) + dS/dX(1) 1e-6/32| over the
four parts (the float route of :func:`paper_repro.core.subdivision.subdivision_matrix`; it evaluates the same
Theorem P forms ``_level_terms``, so it checks the arithmetic and the truncation, not the forms).
``--collocation``: also whether the complete rational functions at X = 4/5 equal the exact collocation S at
tan(alpha/4) = 3/4 (:func:`~paper_repro.theory.subdivision_limit.exact_matrices_at`; degree ~ n^2, so n <= 10; the
R part is independent of the product forms, xi (Theorem B, ``scaled_table``) is shared).
``--even``: also the entries that are not even in X (:func:`~paper_repro.theory.subdivision_limit.even_in_x`).
``--compare-upto N``: run ``--collocation``/``--even`` (the slow ones) only for n <= N.
``--mp N [N ...]``: for these n, the certified route M_{alpha/2} Rot_k M_alpha^{-1} (ball arithmetic, 40 digits, no
product forms and no ``_level_terms``) at alpha = 1/100 against S(0+) - dS/dX(1) alpha^2/32: the largest
|S_mp - S(0+)| (the alpha^2 term) and |S_mp - S(0+) + dS/dX(1) alpha^2/32| (O(alpha^4) if the limits and slopes are
right) over every entry of the four parts (n = 12 about 70 s CPU).
``--out PATH``: also write the report (markdown) to PATH, atomically; its content is deterministic except the
section "Timings" at its end (CPU seconds, which vary from run to run).

Run: ``PYTHONPATH=$PWD python tools/subdivision_pole_check.py 1 2 3 4 5 6 7 8`` (n = 12 about 16 s CPU, n = 16 about
77 s); ``make bench`` writes ``reports/subdivision_pole_check.md``.
"""

from __future__ import annotations

import argparse
import sys
import time

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import delta
from paper_repro.core.subdivision import PARTS, subdivision_matrices, subdivision_matrix
from paper_repro.theory.subdivision_limit import (
    even_in_x,
    exact_matrices_at,
    level_forms_equal_proof_code,
    limit_check,
)
from paper_repro.util.io import write_text

COLUMNS = ("| n | δ_n | entries (4δ_n²) | non-zeros u / middle | centre-row non-zeros u / middle | max pole order | "
           "max ord ξ′ | max abs(dS/dX(1)) corner / middle | rows of S(0⁺) sum to 1 | forms = proof code's |")
HEADER = COLUMNS + " CPU s |\n" + "|---" * 11 + "|"
FILE_HEADER = COLUMNS + "\n" + "|---" * 10 + "|"


def row(n: int) -> tuple[str, object, float]:
    """The table row of order n (without the CPU column), the
    :class:`~paper_repro.theory.subdivision_limit.LimitResult` and the CPU seconds of ``limit_check``."""
    start = time.process_time()
    res = limit_check(n)
    cpu = time.process_time() - start
    top = [max(abs(x) for x in m.reshape(-1)) for m in res.slopes]
    rows = all(sum(r, fmpq(0)) == 1 for m in res.limits for r in m)
    text = (f"| {n} | {delta(n)} | {res.entries} | {res.nonzero['u']} / {res.nonzero['middle']} | "
            f"{res.cancelled['u']} / {res.cancelled['middle']} | {res.max_pole} | {res.max_ord_xi_half} | "
            f"{top[0]} / {top[3]} | {rows} | {level_forms_equal_proof_code(n)} |")
    return text, res, cpu


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


def mp_comparison(n: int, res, alpha: str = "0.01", dps: int = 40) -> tuple[str, str]:
    """Largest |S_mp - S(0+)| and |S_mp - S(0+) + dS/dX(1) alpha^2/32| over every entry of the four parts, S_mp the
    certified route (``'mp'``: M_{alpha/2} Rot_k M_alpha^{-1} in ball arithmetic, no product forms) at ``alpha``."""
    with mpmath.workdps(dps):
        a = mpmath.mpf(alpha)
        mats = subdivision_matrices(n, a, "mp", dps=dps)
        a2 = a ** 2 / 32
        d0 = d1 = mpmath.mpf(0)
        for k in range(len(PARTS)):
            for (g, f), v in np.ndenumerate(mats[k]):
                lim, sl = res.limits[k][g, f], res.slopes[k][g, f]
                lim = mpmath.mpf(int(lim.p)) / int(lim.q)
                sl = mpmath.mpf(int(sl.p)) / int(sl.q)
                d0 = max(d0, abs(v - lim))
                d1 = max(d1, abs(v - lim + sl * a2))
        return mpmath.nstr(d0, 3), mpmath.nstr(d1, 3)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ns", type=int, nargs="+")
    parser.add_argument("--float", dest="float_", action="store_true")
    parser.add_argument("--collocation", action="store_true")
    parser.add_argument("--even", action="store_true")
    parser.add_argument("--compare-upto", type=int, default=None, help="--collocation/--even only for n <= N")
    parser.add_argument("--mp", type=int, nargs="*", default=[], help="n for the certified mp comparison, alpha=1/100")
    parser.add_argument("--out", default=None, help="also write the report (markdown) here, atomically")
    args = parser.parse_args(argv)
    command = "PYTHONPATH=$PWD python tools/subdivision_pole_check.py " + " ".join(
        sys.argv[1:] if argv is None else argv)
    rows: list[str] = []
    notes: list[str] = []
    timings: list[str] = []
    print(HEADER, flush=True)
    for n in args.ns:
        text, res, cpu = row(n)
        rows.append(text)
        timings.append(f"| {n} | limit_check | {cpu:.2f} |")
        print(f"{text} {cpu:.2f} |", flush=True)
        compare = args.compare_upto is None or n <= args.compare_upto
        lines = []
        if args.float_:
            start = time.process_time()
            err, resid = float_comparison(n, res)
            timings.append(f"| {n} | float route at 1e-100 and 1e-3 | {time.process_time() - start:.2f} |")
            lines.append(f"float: |S(1e-100) - S(0+)| <= {err:.2g}, alpha^2 residual at 1e-3 <= {resid:.2g}")
        if compare and args.collocation:
            start = time.process_time()
            poly = exact_matrices_at(n, fmpq(4, 5))
            exact = subdivision_matrices(n, rational_alpha(fmpq(3, 4)), "exact")
            same = all(bool((a == b).all()) for a, b in zip(poly, exact))
            timings.append(f"| {n} | collocation at X = 4/5 | {time.process_time() - start:.2f} |")
            lines.append(f"equal to the exact collocation at X = 4/5 (every entry, four parts): {same}")
        if compare and args.even:
            start = time.process_time()
            odd = even_in_x(n)
            timings.append(f"| {n} | even_in_x | {time.process_time() - start:.2f} |")
            lines.append(f"entries not even in X: {odd}")
        if n in args.mp:
            start = time.process_time()
            d0, d1 = mp_comparison(n, res)
            timings.append(f"| {n} | mp at alpha = 1/100 | {time.process_time() - start:.2f} |")
            lines.append(f"certified mp at alpha = 1/100 (40 digits): max |S_mp - S(0+)| = {d0}, "
                         f"max |S_mp - S(0+) + dS/dX(1) alpha^2/32| = {d1}")
        for line in lines:
            print("  " + line, flush=True)
        notes += [f"- n = {n}: {line}" for line in lines]
    if args.out:
        text = "\n".join([
            "# The pole check of Proposition 11.6 (docs/subdivision_for_all_n.md, section 11)", "",
            f"Written by `{command}`.", "",
            "Every entry of the four S_k, a rational function of X = cos(α/4), decided exactly for a pole at X = 1 "
            "(`paper_repro.theory.subdivision_limit.limit_check`): a computer-assisted proof. It computes with the "
            "fast implementation `_level_terms` of Theorem P's integer forms; the column \"forms = proof code's\" "
            "records that these forms equal, term for term, those of the proofs' dictionary construction "
            "(`half_angle_rules.product_terms`) at every level 2..n, so the check rests on the proof code's forms. "
            "The comparisons: the float route (the same forms: it checks the arithmetic and the truncation), the "
            "exact collocation at X = 4/5 (the R part independent, ξ of Theorem B shared), the certified mp route "
            "at α = 1/100 (independent of the product forms).", "",
            FILE_HEADER, *rows, "", "## Comparisons", "", *(notes or ["(none run)"]), "",
            "## Timings (CPU seconds of this run; not deterministic, everything above is)", "",
            "| n | what | CPU s |", "|---|---|---|", *timings, ""])
        write_text(args.out, text)


if __name__ == "__main__":
    main()
