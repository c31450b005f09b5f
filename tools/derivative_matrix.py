"""The derivative of a patch as a patch of the same order: the matrix C with d/du T-bar_n = T-bar_n C (issue 21).

The span of T_{2n} is closed under d/du (it is the span of cos/sin(pu + qv) over the hexagon |p|, |q|, |p - q| <= n,
``paper_repro.theory.question1.hexagon_check``), so the derivative along u of a patch with net ``p`` is the patch
of the same order with net ``C^T``-transformed: ``sum_f dB_f p_f = sum_g B_g (C p)_g``; its normals are one
6-coordinate point evaluation.  The package tables of C (:mod:`paper_repro.theory.derivative_matrix`,
integer polynomials in cos(alpha/2) recovered modulo primes).  This tool solves for C independently, in certified
ball arithmetic (flint ``arb``, collocation at the alpha-independent points of the elevation solve), and reports,
per n, its nonzero pattern and the time of the solve (what a float path would pay per (n, alpha) without the
tables); ``tests/test_derivative_tables.py`` checks the tables against this solve.  Evidence for one alpha at a time:
an entry whose ball excludes 0 is certainly nonzero; one whose ball contains 0 with a radius below 2^-100 is
counted as zero (not proven zero).

Writes ``reports/derivative_matrix.md`` (timings: a report, not data).  Usage::

    .venv/bin/python tools/derivative_matrix.py [--ns 1,2,3,4,5,6,8,10] [--alphas 1,1e-3] [--ns-small 1,2,3,4,6]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from flint import arb, arb_mat

from paper_repro.core.context import BallContext
from paper_repro.core.derivatives_basis import basis_derivative
from paper_repro.core.domain import RationalPoints
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized, fixed_points


def derivative_matrix(n: int, alpha: float, prec: int) -> tuple[arb_mat | None, float]:
    """C (ball entries) with T-bar_n' = T-bar_n C along u at ``prec`` bits, or None if the solve is not certified;
    and the seconds it took."""
    t0 = time.perf_counter()
    ctx = BallContext(prec=prec)
    m = delta(n)
    tu, tv = fixed_points(n, m, 7)
    pts = RationalPoints(None, tu, tv, check=False)
    with ctx.scope():
        a = arb(alpha)
        vals = evaluate_normalized(n, a, pts, ctx)
        ders = basis_derivative(n, a, pts, "u", ctx)
        try:
            c = arb_mat(vals.tolist()).solve(arb_mat(ders.tolist()), algorithm="precond")
        except ZeroDivisionError:
            return None, time.perf_counter() - t0
    return c, time.perf_counter() - t0


def pattern(c: arb_mat) -> tuple[list[int], int, int]:
    """Nonzeros per column (certainly nonzero), entries counted as zero, entries undecided (radius >= 2^-100)."""
    tiny = arb(2) ** -100
    cols, zeros, undecided = [], 0, 0
    for j in range(c.ncols()):
        k = 0
        for i in range(c.nrows()):
            x = c[i, j]
            if not x.contains(0):
                k += 1
            elif x.rad() < tiny:
                zeros += 1
            else:
                undecided += 1
        cols.append(k)
    return cols, zeros, undecided


def table(ns: list[int], alpha: float) -> list[str]:
    """The report's table for one alpha (printed as it goes)."""
    lines = [f"## alpha = {alpha!r}", "", "| n | δ_n | bits | nonzero | of δ_n² | max per column | zero | undecided | "
             "seconds |", "|---|---|---|---|---|---|---|---|---|"]
    for n in ns:
        prec = 256 + 32 * n
        c, secs = derivative_matrix(n, alpha, prec)
        while c is None or pattern(c)[2]:
            prec *= 2
            c, secs = derivative_matrix(n, alpha, prec)
        cols, zeros, undecided = pattern(c)
        row = (f"| {n} | {delta(n)} | {prec} | {sum(cols)} | {sum(cols) / delta(n) ** 2:.3f} | {max(cols)} | "
               f"{zeros} | {undecided} | {secs:.2f} |")
        print(row, flush=True)
        lines.append(row)
    return lines + [""]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", default="1,2,3,4,5,6,8,10", help="orders at the first alpha")
    ap.add_argument("--alphas", default="1,1e-3", help="comma-separated alphas")
    ap.add_argument("--ns-small", default="1,2,3,4,6", help="orders at the further alphas")
    ap.add_argument("--out", default="reports/derivative_matrix.md")
    args = ap.parse_args()
    lines = ["# The derivative along u as a matrix of the same order (tools/derivative_matrix.py)", "",
             "C with d/du T-bar_n = T-bar_n C, solved in ball arithmetic (collocation at the elevation solve's "
             "alpha-independent points); 'nonzero': the ball excludes 0; 'zero': the ball contains 0 with radius "
             "< 2^-100 (not proven); 'undecided': neither. Seconds: one solve, this machine.", ""]
    for k, alpha in enumerate(float(a) for a in args.alphas.split(",")):
        ns = args.ns if k == 0 else args.ns_small
        lines += table([int(x) for x in ns.split(",")], alpha)
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text("\n".join(lines))
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
