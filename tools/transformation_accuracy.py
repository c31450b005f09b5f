"""Float accuracy of the transformation (Question 7.2), the product matrices and subdivision at the edges of (0, pi)
against a high-precision reference, n <= 30 (issue 39, item 1).

For each n and alpha: the float64 matrix (the inner route, without the refusal of ``transformation_matrix``) against a
reference, the largest error relative to the largest entry, and its ratio to the documented bound
(:func:`~paper_repro.core.transformation.v_to_t_float_bound` for 'V_to_T',
:func:`~paper_repro.core.transformation.t_to_v_float_bound` for 'T_to_V',
:func:`~paper_repro.core.half_angle_matrices.product_float_bound` for Q = ``product_matrix(n, h)``: entrywise, all
seven h for n <= 10, three beyond).

The references:

* n <= 10: mpmath at ``DPS + 2 log10(1/alpha)`` digits (the cancellation of 'V_to_T' costs about 2 log10(1/alpha)
  digits), as before;
* n > 10, 'V_to_T' and 'T_to_V': the same formulas (docs/transformation_for_all_n.md) evaluated in double-double
  arithmetic (:class:`DoubleDoubleContext`: about 32 digits, vectorised numpy, 20-25 times the float cost instead of
  the 200-2000 of mpmath: 28 s for both directions at n = 30).  It is checked twice: against the mp reference at every
  n <= 10 point (column "dd - mp"), and, at every n > 10 point, by the residual of the *two independent routes*
  (the generating function gives 'V_to_T', the binomial expansion 'T_to_V'): ``|A (X v) - v| / (|A| |X| |v|)``
  for three random vectors v, computed in double-double (column "residual");
* Q: mpmath at 30 digits (mp has no exponent range to underflow at alpha = 1e-300); for n > 10 and alpha >= 1e-60
  double-double (mp took 40 s for three h at n = 15 on the loaded machine).

Where the float result overflows (``transformation_matrix`` raises ``OverflowError``), the log10 of the largest true
entry is given (``x_f`` in mp times the largest entry of the expansion N of the member, docs: M^{-1} = N diag(x)).

Subdivision (report only, n <= 10, alpha = 1e-300 and pi - 1e-12): :func:`subdivision_matrices_float` against the
certified mp route, the largest error and the largest entry of its running-error bound B.

Writes ``reports/transformation_accuracy.{md,json}`` (raw floats: a report, not data).  Usage::

    PYTHONPATH=. .venv/bin/python tools/transformation_accuracy.py [--n 1 2 3 5 8 10 15 20 25 30] [--no-subdivision]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import time
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.context import Context, FloatContext, get_context
from paper_repro.core.half_angle_matrices import PRODUCT_FLOAT_FLOOR, product_float_bound, product_matrix
from paper_repro.core.transformation import (
    FLOAT_REL_GOAL,
    half_angle,
    scaled_normalizing,
    t_to_v_float_bound,
    transformation_in_context,
    v_to_t_float_alpha_min,
    v_to_t_float_bound,
)
from paper_repro.util.io import write_text

ALPHAS_SMALL_N = (1e-300, 1e-150, 1e-100, 1e-90, 1e-60, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 1.0, 3.0, math.pi - 1e-12)
ALPHAS_LARGE_N = (1e-300, 1e-100, 1e-60, 1e-6, 1e-3, 1e-2, 1.0, 3.0, math.pi - 1e-12)
DPS = 30
EPS = 2.0**-52
#: Below this alpha the 'V_to_T' reference is not computed (the float result is refused; 1/s^{3n} leaves the range).
V_TO_T_REFERENCE_MIN = 1e-6


# --- double-double arithmetic ------------------------------------------------------------------------------------
_SPLIT = 134217729.0  # 2^27 + 1 (Dekker's split)
_BIG = 2.0**995  # above this the split would overflow: split the scaled value


def _pack(hi, lo) -> np.ndarray:
    out = np.empty(np.broadcast(hi, lo).shape, dtype=np.complex128)
    out.real = hi
    out.imag = lo
    return out


def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _quick_two_sum(a, b):
    s = a + b
    return s, b - (s - a)


def _split(a):
    big = np.abs(a) > _BIG
    if np.any(big):
        a = np.where(big, a * 2.0**-28, a)
        hi, lo = _split(a)
        return np.where(big, hi * 2.0**28, hi), np.where(big, lo * 2.0**28, lo)
    t = _SPLIT * a
    hi = t - (t - a)
    return hi, a - hi


def _two_prod(a, b):
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


@dataclass(frozen=True)
class DoubleDoubleContext(Context):
    """Double-double numbers hi + lo (|lo| <= ulp(hi)/2, about 32 digits), carried as complex128 ``hi + i lo`` so
    that numpy's indexing, broadcasting and assignment work unchanged; only :meth:`add`, :meth:`sub`, :meth:`mul`,
    :meth:`div` know the meaning (Dekker's and Knuth's error-free transformations, the accurate addition of
    Bailey's QD library).  The exponent range is float64's.

    >>> dd = DoubleDoubleContext()
    >>> x = dd.div(dd.from_rational(fmpq(1)), dd.from_rational(fmpq(3)))
    >>> Fraction(float(x.real)) + Fraction(float(x.imag)) - Fraction(1, 3) < Fraction(1, 10**31)
    True
    """

    name: str = "dd"

    def convert(self, x):
        if isinstance(x, np.ndarray):
            x = x[()]
        if isinstance(x, (complex, np.complexfloating)):
            return complex(x)
        if isinstance(x, fmpq):
            return self.from_rational(x)
        if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
            hi = float(int(x))
            return complex(hi, float(int(x) - int(hi)))
        if isinstance(x, mpmath.mpf):
            hi = float(x)
            return complex(hi, float(x - hi))
        return complex(float(x), 0.0)

    def from_rational(self, q: fmpq):
        f = Fraction(int(q.p), int(q.q))
        hi = float(f)
        return complex(hi, float(f - Fraction(hi)))

    def asarray(self, values) -> np.ndarray:
        src = np.asarray(values, dtype=object)
        return np.array([self.convert(x) for x in src.reshape(-1)], dtype=np.complex128).reshape(src.shape)

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.ones(shape, dtype=np.complex128)

    def zeros(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.zeros(shape, dtype=np.complex128)

    def add(self, a, b):
        a, b = np.asarray(a), np.asarray(b)
        s, e = _two_sum(a.real, b.real)
        t, f = _two_sum(a.imag, b.imag)
        s, e = _quick_two_sum(s, e + t)
        return _pack(*_quick_two_sum(s, e + f))

    def sub(self, a, b):
        return self.add(a, -np.asarray(b))

    def mul(self, a, b):
        a, b = np.asarray(a), np.asarray(b)
        p, e = _two_prod(a.real, b.real)
        return _pack(*_quick_two_sum(p, e + (a.real * b.imag + a.imag * b.real)))

    def div(self, a, b):
        a, b = np.asarray(a), np.asarray(b)
        q1 = a.real / b.real
        r = self.sub(a, self.mul(b, _pack(q1, 0.0)))
        q2 = r.real / b.real
        r = self.sub(r, self.mul(b, _pack(q2, 0.0)))
        q3 = r.real / b.real
        return self.add(_pack(*_quick_two_sum(q1, q2)), _pack(q3, 0.0))

    def to_float(self, a) -> np.ndarray:
        a = np.asarray(a)
        return a.real + a.imag

    def sin(self, a):
        raise NotImplementedError("the double-double context takes alpha through alpha_half (mpmath)")

    cos = sin

    def alpha_half(self, alpha):
        with mpmath.workdps(60):
            half = mpmath.mpf(float(alpha)) / 2  # a float is an exact binary rational
            return np.asarray(self.convert(mpmath.sin(half))), np.asarray(self.convert(mpmath.cos(half)))

    @property
    def digits(self) -> int:
        return 31


DD = DoubleDoubleContext()


def dd_matvec(a: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``a @ v`` in double-double (a column at a time, a fixed order)."""
    acc = DD.zeros((a.shape[0],))
    for j in range(a.shape[1]):
        acc = DD.add(acc, DD.mul(a[:, j], v[j]))
    return acc


# --- the matrices ------------------------------------------------------------------------------------------------
def float_matrix(n: int, alpha: float, direction: str) -> np.ndarray:
    """The float64 route of ``transformation_matrix(n, alpha, direction)`` without its refusals."""
    ctx = FloatContext()
    s, c = half_angle(alpha, ctx)
    with np.errstate(over="ignore", invalid="ignore"):
        return transformation_in_context(n, s, c, ctx, direction)


def mp_matrix(n: int, alpha: float, direction: str) -> np.ndarray:
    """The mp reference as float64 pairs (hi, lo) packed like the double-double ones."""
    dps = DPS + int(2 * max(0.0, -math.log10(alpha)))
    ctx = get_context("mp", dps=dps)
    with mpmath.workdps(dps):
        s, c = half_angle(mpmath.mpf(alpha), ctx)
        m = transformation_in_context(n, s, c, ctx, direction)
        return np.array([[DD.convert(x) for x in row] for row in m], dtype=np.complex128)


def dd_matrix(n: int, alpha: float, direction: str) -> np.ndarray:
    s, c = DD.alpha_half(alpha)
    with np.errstate(over="ignore", invalid="ignore"):
        return transformation_in_context(n, s, c, DD, direction)


def rel_error(fl: np.ndarray, ref: np.ndarray) -> float:
    """max |fl - ref| / max |ref| with ref = hi + lo (the difference formed as (fl - hi) - lo)."""
    ref = np.asarray(ref)
    if ref.dtype == np.complex128:
        diff, scale = (fl - ref.real) - ref.imag, np.abs(ref.real).max()
    else:
        diff, scale = fl - ref, np.abs(ref).max()
    return float(np.abs(diff).max() / scale)


def dd_distance(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / max |b| of two double-double matrices (the pairs subtracted part by part)."""
    return float(np.abs((a.real - b.real) + (a.imag - b.imag)).max() / np.abs(b.real).max())


def route_residual(a: np.ndarray, x: np.ndarray, seed: int = 0) -> float:
    """``max |A (X v) - v| / max (|A| |X| |v|)`` in double-double for three random v: A = T_to_V (binomial expansion),
    X = V_to_T (generating function), two independent routes whose product is the identity."""
    rng = np.random.default_rng(seed)
    worst = 0.0
    for _ in range(3):
        v = rng.normal(size=a.shape[1])
        r = DD.sub(dd_matvec(a, dd_matvec(x, v.astype(np.complex128))), v.astype(np.complex128))
        scale = np.abs(a.real) @ (np.abs(x.real) @ np.abs(v))
        worst = max(worst, float(np.abs(r.real).max() / scale.max()))
    return worst


def log10_true_max_t_to_v(n: int, alpha: float) -> float:
    """log10 of the largest entry of the true normalized 'T_to_V' matrix N diag(x) (x_f = s^{-(2n+j)} (s^{2n+j} x_f)
    in mp; N, the expansion, has no 1/s and is taken in float)."""
    ctx = FloatContext()
    s, c = half_angle(alpha, ctx)
    big_n = transformation_in_context(n, s, c, ctx, "T_to_V", normalized=False)
    col_max = np.abs(big_n).max(axis=0)
    from paper_repro.core.labels import united_system

    mctx = get_context("mp", dps=30)
    with mpmath.workdps(30):
        sm, cm = half_angle(mpmath.mpf(alpha), mctx)
        scaled = scaled_normalizing(n, sm, cm, mctx)
        logs = [float(mpmath.log10(abs(scaled[f]) / abs(sm[()]) ** (2 * n + lab.j)) + math.log10(col_max[f]))
                for f, lab in enumerate(united_system(n)) if col_max[f] > 0]
    return max(logs)


def product_errors(n: int, alpha: float, h: int) -> dict:
    """Q = product_matrix(n, h) in float against mp (30 digits; double-double for n > 10 and alpha >= 1e-60):
    normwise (to the largest entry), entrywise (over the entries of size >= 1e-280) and the ratio to the stated
    entrywise bound (2 n + 8) eps |Q| + PRODUCT_FLOAT_FLOOR."""
    qf = product_matrix(n, h, alpha)
    if n > 10 and alpha >= 1e-60:  # double-double (20 times faster; the same formulas, no underflow up there)
        ref = product_matrix(n, h, alpha, DD)
    else:
        with mpmath.workdps(DPS):
            qm = product_matrix(n, h, mpmath.mpf(alpha), "mp")
            ref = np.array([[DD.convert(x) for x in row] for row in qm], dtype=np.complex128)
    diff = np.abs((qf - ref.real) - ref.imag)
    big = np.abs(ref.real) >= 1e-280
    top = np.abs(ref.real).max()
    return {"h": h, "normwise": float(diff.max() / top) if top > 0 else float(diff.max()),
            "entrywise": float((diff[big] / np.abs(ref.real[big])).max()) if big.any() else 0.0,
            "ratio": float((diff / (product_float_bound(n) * np.abs(ref.real) + PRODUCT_FLOAT_FLOOR)).max())}


def products(n: int, alpha: float) -> dict:
    """The worst over the h measured: all seven for n <= 10; beyond, the centre R_{2,1,1}, B_{2,2,0} and B_{2,1,0}
    (the first two below 1e-60, where the reference is mp)."""
    t0 = time.perf_counter()
    hs = range(7) if n <= 10 else (0, 5, 6) if alpha >= 1e-60 else (0, 5)  # mp at n = 20: 50 s per h
    per = [product_errors(n, alpha, h) for h in hs]
    return {"hs": list(hs), "normwise": max(p["normwise"] for p in per), "entrywise": max(p["entrywise"] for p in per),
            "ratio": max(p["ratio"] for p in per), "worst_h": max(per, key=lambda p: p["ratio"])["h"],
            "bound": product_float_bound(n), "reference_s": round(time.perf_counter() - t0, 2)}


# --- one (n, alpha) point ----------------------------------------------------------------------------------------
def measure(n: int, alpha: float) -> dict:
    t0 = time.perf_counter()
    rec: dict = {"n": n, "alpha": alpha, "alpha_min": v_to_t_float_alpha_min(n)}
    refs: dict = {}
    for direction in ("V_to_T", "T_to_V"):
        cell: dict = {}
        if direction == "V_to_T":
            cell["bound"] = v_to_t_float_bound(n, alpha)
            cell["state"] = "refused" if alpha < v_to_t_float_alpha_min(n) else "returned"
        else:
            cell["bound"] = t_to_v_float_bound(n)
        if direction == "V_to_T" and alpha < V_TO_T_REFERENCE_MIN:
            rec[direction] = cell
            continue
        fl = float_matrix(n, alpha, direction)
        if not np.isfinite(fl).all():  # transformation_matrix raises OverflowError here
            cell["state"] = "overflow: refused"
            if direction == "T_to_V":
                cell["log10_true_max"] = log10_true_max_t_to_v(n, alpha)
            rec[direction] = cell
            continue
        cell.setdefault("state", "returned")
        t1 = time.perf_counter()
        if n <= 10:
            ref = mp_matrix(n, alpha, direction)
            cell["reference"] = "mp"
            dd = dd_matrix(n, alpha, direction)
            cell["dd_minus_mp"] = dd_distance(dd, ref) if np.isfinite(dd.real).all() else None
        else:
            ref = dd_matrix(n, alpha, direction)
            cell["reference"] = "dd"
        cell["reference_s"] = round(time.perf_counter() - t1, 2)
        cell["error"] = rel_error(fl, ref)
        cell["ratio"] = cell["error"] / cell["bound"]
        refs[direction] = ref
        rec[direction] = cell
    if n > 10 and len(refs) == 2:
        t1 = time.perf_counter()
        rec["route_residual"] = route_residual(refs["T_to_V"], refs["V_to_T"])
        rec["route_residual_s"] = round(time.perf_counter() - t1, 2)
    rec["Q"] = products(n, alpha)
    rec["seconds"] = round(time.perf_counter() - t0, 1)
    return rec


#: Up to this n the certified mp route of subdivision runs at alpha = 1e-300 itself (22 s at n = 4, about 8 times more
#: per n); beyond, the reference for 1e-300 is the certified S at SUBDIVISION_PROXY_ALPHA.
SUBDIVISION_DIRECT_N = 4
SUBDIVISION_PROXY_ALPHA = 1e-30


def subdivision_edges(ns, alphas=(1e-300, math.pi - 1e-12), proxy: float = SUBDIVISION_PROXY_ALPHA) -> list[dict]:
    """Subdivision (report only): the float product route against the certified mp route (30 digits).  For
    alpha = 1e-300 and n > SUBDIVISION_DIRECT_N the reference is S(proxy), 1e-30 or 1e-10: S is even and smooth at 0
    (proven for n <= 2, docs/subdivision_for_all_n.md section 9; measured S(alpha) - S(0) ~ alpha^2/32 beyond), so
    the two differ by about 1e-61 or 3e-22 -- evidence, not a proof, for those n."""
    from paper_repro.core.subdivision import subdivision_matrices
    from paper_repro.core.subdivision_products import subdivision_matrices_float

    out = []
    for n in ns:
        for alpha in alphas:
            t0 = time.perf_counter()
            ref_alpha = alpha if alpha > 1e-100 or n <= SUBDIVISION_DIRECT_N else proxy
            flo, bnd = subdivision_matrices_float(n, alpha, bound=True)
            with mpmath.workdps(DPS):
                mp = subdivision_matrices(n, mpmath.mpf(ref_alpha), "mp", dps=DPS)
                ref = [np.array([[DD.convert(x) for x in row] for row in m], dtype=np.complex128) for m in mp]
            errs = [np.abs((f - r.real) - r.imag) for f, r in zip(flo, ref)]
            # the stated bound |S_float - S| <= B + (2 eps_x + 3u)(|S_float| + B), here with eps_x = 0, and the
            # reference's own accuracy (30 digits, absolute: entries whose ball contains 0 are within 1e-30 of 0)
            u, tol = 2.0**-53, 10.0 ** (2 - DPS)
            excess = max(float((e - (b + 3 * u * (np.abs(f) + b)) - tol).max()) for e, b, f in zip(errs, bnd, flo))
            out.append({"n": n, "alpha": alpha, "reference_alpha": ref_alpha,
                        "max_abs_err": max(float(e.max()) for e in errs),
                        "bound_max": max(float(b.max()) for b in bnd), "excess_over_bound": excess,
                        "row_sum_defect": max(float(np.abs(f.sum(axis=1) - 1).max()) for f in flo),
                        "seconds": round(time.perf_counter() - t0, 1)})
            print(json.dumps(out[-1]), flush=True)
    return out


def _proxy_offset(s: dict) -> float:
    """What a proxy reference may differ by: S(alpha_ref) - S(0) ~ alpha_ref^2 / 32 (0 without a proxy)."""
    return 0.0 if s["reference_alpha"] == s["alpha"] else s["reference_alpha"] ** 2


# --- the report --------------------------------------------------------------------------------------------------
def _fmt_cell(cell: dict, direction: str) -> str:
    if "error" not in cell:
        if "log10_true_max" in cell:
            return f"overflow: refused (true max entry 1e{cell['log10_true_max']:.0f})"
        return cell.get("state", "refused") + " (not measured)"
    extra = f", {cell['state']}" if direction == "V_to_T" else ""
    return f"{cell['error']:.1e} ({cell['ratio']:.2f} of bound{extra})"


def markdown(recs: list[dict], sub: list[dict], load: tuple) -> str:
    rows = []
    for r in recs:
        res = f"{r['route_residual']:.0e}" if "route_residual" in r else ""
        ddmps = [r[d]["dd_minus_mp"] for d in ("V_to_T", "T_to_V") if r[d].get("dd_minus_mp") is not None]
        ddmp = f"{max(ddmps):.0e}" if ddmps else ""
        rows.append(f"| {r['n']} | {r['alpha']:.6g} | {_fmt_cell(r['V_to_T'], 'V_to_T')} | "
                    f"{_fmt_cell(r['T_to_V'], 'T_to_V')} | {r['Q']['normwise']:.1e} / {r['Q']['entrywise']:.1e} "
                    f"({r['Q']['ratio']:.2f}) | {r['V_to_T'].get('reference', r['T_to_V'].get('reference', ''))} | "
                    f"{ddmp} | {res} | {r['seconds']} |")
    summary = []
    for n in sorted({r["n"] for r in recs}):
        sel = [r for r in recs if r["n"] == n]
        vt = [r["V_to_T"]["ratio"] for r in sel if "ratio" in r["V_to_T"] and r["V_to_T"]["state"] == "returned"]
        vt_all = [r["V_to_T"]["ratio"] for r in sel if "ratio" in r["V_to_T"]]
        tv = [r["T_to_V"]["ratio"] for r in sel if "ratio" in r["T_to_V"]]
        q = [r["Q"]["ratio"] for r in sel]
        refs = [r[d]["reference_s"] for r in sel for d in ("V_to_T", "T_to_V") if "reference_s" in r[d]]
        summary.append(f"| {n} | {max(vt):.2f} | {max(vt_all):.2f} | {max(tv):.2f} | {max(q):.2f} | "
                       f"{max(refs):.1f} |")
    sub_rows = [f"| {s['n']} | {s['alpha']:.6g} | {s['reference_alpha']:.6g} | {s['max_abs_err']:.2e} | "
                f"{s['bound_max']:.1e} | "
                f"{'yes' if s['excess_over_bound'] <= _proxy_offset(s) else 'NO'} | {s['row_sum_defect']:.1e} | "
                f"{s['seconds']} |"
                for s in sub]
    worst = max(r["V_to_T"]["ratio"] for r in recs if r["V_to_T"].get("state") == "returned" and "ratio" in r["V_to_T"])
    return "\n".join([
        "# Float accuracy of the transformation, the product matrices and subdivision "
        "(tools/transformation_accuracy.py)",
        "",
        f"Not data: measurements of this machine's run (load average at start {load[0]:.1f}). Error = the largest "
        "|float - reference| relative to the largest entry of the reference; ratio = error / documented bound. "
        "'V_to_T' has the bound eps ((12 n + 8) / alpha^2 + max(12 n + 8, 1.7^n / 3)) and is refused in float "
        f"where it exceeds {FLOAT_REL_GOAL:g} (below alpha = {v_to_t_float_alpha_min(1):.2g} at n = 1, "
        f"{v_to_t_float_alpha_min(10):.2g} at n = 10, {v_to_t_float_alpha_min(30):.2g} at n = 30); the row "
        "alpha = 1.01 alpha_min(n) is the smallest alpha it returns. Below 1e-6 its reference is not computed. "
        "'T_to_V' has the bound eps max(4 n + 4, 1.6^n / 5) and raises OverflowError where an entry leaves float64 "
        "(the true largest entry is given). Q = product_matrix(n, h), the worst h (all seven for n <= 10; R_{2,1,1}, "
        "B_{2,2,0}, B_{2,1,0} beyond): normwise / entrywise error (entries >= 1e-280), ratio = the largest "
        "|Q_float - Q| / ((2 n + 8) eps |Q| + 1e-290), the stated entrywise bound.",
        "",
        "References: n <= 10 mpmath (30 digits + 2 log10(1/alpha)); n > 10 double-double (the same formulas, about 32 "
        "digits). 'dd - mp': the double-double matrices against mp at n <= 10 (relative to the largest entry). "
        "'residual': |A (X v) - v| / (|A| |X| |v|) in double-double, A = T_to_V (binomial expansion) and X = V_to_T "
        "(generating function), two independent routes. Q: mpmath at 30 digits (double-double for n > 10 and "
        "alpha >= 1e-60).",
        "",
        "## Summary: the largest error / bound per n",
        "",
        "| n | V_to_T (returned) | V_to_T (also refused alphas >= 1e-6) | T_to_V | Q (entrywise) | "
        "slowest reference (s) |",
        "|---|---|---|---|---|---|", *summary, "",
        f"Largest error / bound of a returned V_to_T: {worst:.2f} (must stay below 1).", "",
        "## Every point", "",
        "| n | alpha | V_to_T | T_to_V | Q normwise / entrywise (ratio) | ref | dd - mp | residual | s |",
        "|---|---|---|---|---|---|---|---|---|", *rows, "",
        "## Subdivision at the edges (report only)", "",
        "subdivision_matrices_float (the product route, below 1e-100 computed at 1e-100) against the certified mp "
        "route at 30 digits, the four matrices; bound = the largest entry of the running-error bound B; 'within' = "
        "every entry within B + 3u (|S_float| + B) (the stated bound with eps_x = 0), plus 1e-28 (the reference's "
        "own accuracy) and, with a proxy reference, alpha_ref^2 (S(alpha_ref) - S(0) ~ alpha_ref^2 / 32).", "",
        "| n | alpha | reference at | max abs error | bound | within | max row-sum defect | s |",
        "|---|---|---|---|---|---|---|---|",
        *sub_rows, ""])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="*", default=[1, 2, 3, 5, 8, 10, 15, 20, 25, 30])
    ap.add_argument("--subdivision-n", type=int, nargs="*", default=list(range(1, 11)))
    ap.add_argument("--subdivision-proxy", type=float, default=SUBDIVISION_PROXY_ALPHA,
                    help="the reference alpha for subdivision at 1e-300 beyond n = 4 (1e-30: 155 s at n = 7)")
    ap.add_argument("--combine", nargs="*", default=None,
                    help="write the report from these JSON files of earlier runs (parts run in parallel)")
    ap.add_argument("--out", default="reports")
    a = ap.parse_args(argv)
    load = os.getloadavg()
    if a.combine is not None:
        parts = [json.loads(Path(f).read_text()) for f in a.combine]
        recs = sorted((r for p in parts for r in p["points"]), key=lambda r: (r["n"], r["alpha"]))
        sub = sorted((s for p in parts for s in p["subdivision"]), key=lambda s: (s["n"], s["alpha"]))
        load = tuple(max(p["load"][k] for p in parts) for k in range(3))
    else:
        recs, sub = [], subdivision_edges(a.subdivision_n, proxy=a.subdivision_proxy)
        for n in a.n:
            alphas = ALPHAS_SMALL_N if n <= 10 else ALPHAS_LARGE_N
            for alpha in sorted({*alphas, 1.01 * v_to_t_float_alpha_min(n)}):
                recs.append(measure(n, alpha))
                print(json.dumps(recs[-1]), flush=True)
    out = Path(a.out)
    write_text(out / "transformation_accuracy.json", json.dumps({"load": load, "points": recs, "subdivision": sub},
                                                                indent=1) + "\n")
    if recs:
        write_text(out / "transformation_accuracy.md", markdown(recs, sub, load))
    bad = [r for r in recs if any(r[d].get("state") == "returned" and r[d].get("ratio", 0) >= 1
                                  for d in ("V_to_T", "T_to_V")) or r["Q"]["ratio"] >= 1]
    for r in bad:
        print("BOUND FAILS:", r["n"], r["alpha"])
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
