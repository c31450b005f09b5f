"""The subdivision matrices of order n in closed form, proven for every alpha by a symbolic identity (issue 38).

Generalizes ``tools/subdivision_n1_proof.py`` (n = 1, where the normalizing coefficients are typed from Example
normalizing_coefficients_n_1) to any small n, with the normalizing coefficients of the library's all-n formula
(Theorem B of docs/question1_for_all_n.md, :func:`paper_repro.core.transformation.scaled_normalizing`) evaluated
over sympy:

1. each entry of the exact S_k (``paper_repro.core.subdivision``) at 22 rational-tangent alpha is interpolated as a
   rational function of c = cos(alpha/2) of the smallest degree that reproduces the remaining alpha (how the closed
   form is found, not the proof; ``None`` if some entry is not a rational function of c alone of degree <= 6);
2. the proof: with X = exp(i u'/2), Y = exp(i v'/2), Z = exp(i alpha/4) every member of T-bar_{2n} is a rational
   function of X, Y, Z, and sum_g S_k[g, f] T-bar^{alpha/2}_g = T-bar^alpha_f o x_k is checked as an identity of
   rational functions (numerator expanded to 0) for every column f and part k: it holds for all u', v' and every
   alpha, so (by uniqueness, docs/subdivision_for_all_n.md section 3) S_k(alpha) is the subdivision matrix for every
   alpha in (0, pi).

Run: ``python tools/subdivision_closed_form_proof.py 2`` (prints the degrees, the signs proven for every alpha and
the identity; ``--signs-only`` skips the identity).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass

import numpy as np
import sympy as sp
from flint import fmpq

from paper_repro.core.context import ObjectContext
from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import delta, exponent_matrix, united_system
from paper_repro.core.subdivision import PARTS, subdivision_matrices
from paper_repro.core.transformation import scaled_normalizing

C = sp.Symbol("c")
TS = ["1/20", "1/9", "1/7", "1/5", "1/4", "1/3", "2/5", "3/7", "1/2", "4/7", "3/5", "2/3", "5/7", "3/4", "4/5",
      "5/6", "6/7", "7/8", "8/9", "9/10", "10/11", "11/12"]
MAX_DEGREE = 6


@dataclass(frozen=True)
class SympyContext(ObjectContext):
    """The library's closed forms evaluated over sympy expressions (exact, symbolic)."""

    name: str = "sympy"
    exact: bool = True

    def convert(self, x):
        return sp.Rational(int(x.p), int(x.q)) if isinstance(x, fmpq) else sp.sympify(x)

    def from_rational(self, q: fmpq):
        return sp.Rational(int(q.p), int(q.q))


def _q(x: fmpq) -> sp.Rational:
    return sp.Rational(int(x.p), int(x.q))


def closed_forms(n: int) -> dict[str, sp.Matrix] | None:
    """S_k of order n as matrices of rational functions of c (interpolated, confirmed at the other alpha)."""
    values = {t: subdivision_matrices(n, rational_alpha(fmpq(*map(int, t.split("/")))), "exact") for t in TS}
    cs = [_q(rational_alpha(fmpq(*map(int, t.split("/")))).cos_half) for t in TS]
    d = delta(n)
    out = {}
    for k, part in enumerate(PARTS):
        m = sp.zeros(d, d)
        for i in range(d):
            for j in range(d):
                ys = [_q(values[t][k][i, j]) for t in TS]
                if all(y == 0 for y in ys):
                    continue
                for deg in range(0, MAX_DEGREE + 1):
                    pts = list(zip(cs, ys))
                    f = (sp.polys.polyfuncs.rational_interpolate(pts[:2 * deg + 1], deg, X=C) if deg else ys[0])
                    if all(sp.sympify(f).subs(C, c) == y for c, y in pts[2 * deg + 1:]):
                        m[i, j] = sp.factor(f)
                        break
                else:
                    return None
        out[part] = m
    return out


def basis(n: int, x, y, z, half):
    """T-bar_{2n}^beta at (u, v, w) given e^{iu/2} = x, e^{iv/2} = y, e^{iw/2} = z and e^{i beta/2} = half."""
    def sin(e):
        return (e - 1 / e) / (2 * sp.I)

    def cos(e):
        return (e + 1 / e) / 2

    s, c = sin(half), cos(half)
    ctx = SympyContext()
    ss, cc = np.empty((), dtype=object), np.empty((), dtype=object)
    ss[()], cc[()] = s, c
    scaled = scaled_normalizing(n, ss, cc, ctx)  # s^{2n+j} x_f (Theorem B)
    vals = []
    trig = (sin(x), cos(x), sin(y), cos(y), sin(z), cos(z))
    for f, ex in enumerate(exponent_matrix(n)):
        term = scaled[f]
        for slot in range(6):
            base = trig[slot] / s if slot % 2 == 0 else trig[slot]
            term = term * base ** int(ex[slot])
        vals.append(term)
    return vals


def prove(n: int, forms: dict[str, sp.Matrix]) -> dict[str, bool]:
    """The symbolic identity for each part (True: proven for every alpha)."""
    X, Y, Z = sp.symbols("X Y Z", nonzero=True)
    c = (Z**2 + Z**-2) / 2  # cos(alpha/2), Z = e^{i alpha/4}
    sub = basis(n, X, Y, Z / (X * Y), Z)  # parameter alpha/2: half angle alpha/4
    targets = {"u": (X * Z, Y, Z / (X * Y)), "v": (X, Y * Z, Z / (X * Y)), "w": (X, Y, Z**2 / (X * Y)),
               "middle": (Z / X, Z / Y, X * Y)}
    out = {}
    for part, m in forms.items():
        big = basis(n, *targets[part], Z**2)
        mc = m.subs(C, c)
        ok = True
        for f in range(delta(n)):
            diff = sum(mc[g, f] * sub[g] for g in range(delta(n)) if mc[g, f] != 0) - big[f]
            num, _ = sp.fraction(sp.together(diff))
            if sp.expand(num) != 0:
                ok = False
                break
        out[part] = ok
    return out


def negative_entries(forms: dict[str, sp.Matrix]) -> dict[str, list[str]]:
    """The entries negative for every c in (0, 1) (checked: the numerator and denominator have no root in (0, 1) and
    the value at c = 1/2 is negative), with their row and column labels."""
    labels = [lab.paper for lab in united_system(int(round((np.sqrt(12 * forms["u"].rows - 3) - 3) / 6)))]
    out: dict[str, list[str]] = {}
    for part, m in forms.items():
        found = []
        for i in range(m.rows):
            for j in range(m.cols):
                e = m[i, j]
                if e == 0 or e.subs(C, sp.Rational(1, 2)) >= 0:
                    continue
                num, den = sp.fraction(sp.factor(e))
                roots = [r for r in sp.Poly(num * den, C).real_roots() if 0 < r < 1]
                if not roots:
                    found.append(f"{labels[i]} <- {labels[j]}: {e}")
        out[part] = found
    return out


def sign_summary(forms: dict[str, sp.Matrix]) -> dict[str, dict[str, int]]:
    """Per part, how many entries are 0 (identically), > 0 for every c in (0, 1), < 0 for every c in (0, 1), change
    sign in (0, 1) (a root of odd multiplicity of the numerator or denominator there), or touch 0 or a pole in (0, 1)
    without changing sign (``root_no_sign_change``: a root of even multiplicity only).

    An entry is counted positive or negative only if the product numerator * denominator has no real root at all in
    the open interval (0, 1), of any multiplicity; then its sign there is the sign at c = 1/2. Excluding sign changes
    alone (roots of odd multiplicity) would not give exact counts: an entry with a double root would vanish at one
    alpha."""
    out = {}
    for part, m in forms.items():
        counts = {"zero": 0, "positive": 0, "negative": 0, "sign_changing": 0, "root_no_sign_change": 0}
        for e in m:
            if e == 0:
                counts["zero"] += 1
                continue
            num, den = sp.fraction(sp.factor(e))
            poly = sp.Poly(num * den, C)
            inside = [r for r in poly.real_roots() if 0 < r < 1] if poly.degree() > 0 else []  # with multiplicity
            odd = [r for r in set(inside) if inside.count(r) % 2]
            if odd:
                counts["sign_changing"] += 1
            elif inside:
                counts["root_no_sign_change"] += 1
            elif e.subs(C, sp.Rational(1, 2)) > 0:
                counts["positive"] += 1
            else:
                counts["negative"] += 1
        out[part] = counts
    return out


def degrees(forms: dict[str, sp.Matrix]) -> tuple[int, int]:
    """The largest numerator and denominator degrees in c over all entries of all parts."""
    dn = dd = 0
    for m in forms.values():
        for e in m:
            if e != 0:
                num, den = sp.fraction(sp.cancel(sp.together(e)))
                dn = max(dn, sp.Poly(num, C).degree())
                dd = max(dd, sp.Poly(den, C).degree())
    return dn, dd


if __name__ == "__main__":
    args = sys.argv[1:]
    signs_only = "--signs-only" in args  # skip the symbolic identity (3 minutes at n = 2)
    for n in [int(x) for x in args if not x.startswith("--")] or [1, 2]:
        forms = closed_forms(n)
        if forms is None:
            print(f"n = {n}: some entry is not a rational function of c of degree <= {MAX_DEGREE}")
            continue
        print(f"n = {n}: (numerator, denominator) degrees in c at most {degrees(forms)}", flush=True)
        print(f"n = {n}: signs for every alpha in (0, pi): {sign_summary(forms)}", flush=True)
        if not signs_only:
            print(f"n = {n}: identity for every alpha: {prove(n, forms)}", flush=True)
        for part, entries in negative_entries(forms).items():
            print(f"  {part}: {len(entries)} entries negative for every alpha in (0, pi)")
            for e in entries:
                print("   ", e)
