"""The n = 1 subdivision matrices in closed form, proven for every alpha by a symbolic identity (issue 38, item 2).

1. Each entry of the exact S_k (``paper_repro.core.subdivision``) at nine rational-tangent alpha is interpolated as a
   rational function of c = cos(alpha/2) (numerator and denominator of degree <= 2) and the fit is confirmed at three
   further alpha (this is how the closed form is found; it is not the proof).
2. The proof: with X = exp(i u'/2), Y = exp(i v'/2), Z = exp(i alpha/4) every member of T-bar_2 (normalizing
   coefficients of Example normalizing_coefficients_n_1, written from sin(alpha/2) and cos(alpha/2)) is a rational
   function of X, Y, Z, and the identity sum_g S_k[g, f] T-bar^{alpha/2}_g(u', v', w') = T-bar^alpha_f(x_k(u', v', w'))
   (x_k the translation or point reflection) is checked as an identity of rational functions (numerator expanded to
   0): it holds for all u', v' and every alpha, so S_k(alpha) is the subdivision matrix for every alpha in (0, pi).

Run: ``python tools/subdivision_n1_proof.py`` (prints the closed forms and the sign facts).
"""

from __future__ import annotations

import sympy as sp
from flint import fmpq

from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import united_system
from paper_repro.core.subdivision import PARTS, subdivision_matrices

C = sp.Symbol("c")
FIT_TS = ["1/20", "1/9", "1/7", "1/5", "1/3", "2/5", "1/2", "2/3", "4/5"]
CHECK_TS = ["3/7", "5/8", "9/10"]


def _c_of(t: str) -> sp.Rational:
    a = rational_alpha(fmpq(*map(int, t.split("/"))))
    return sp.Rational(int(a.cos_half.p), int(a.cos_half.q))


def closed_forms() -> dict[str, sp.Matrix]:
    """S_k for n = 1 as matrices of rational functions of c, interpolated and confirmed at further alpha."""
    values = {t: dict(zip(PARTS, subdivision_matrices(1, rational_alpha(fmpq(*map(int, t.split("/")))), "exact")))
              for t in FIT_TS + CHECK_TS}
    out = {}
    for part in PARTS:
        m = sp.zeros(7, 7)
        for i in range(7):
            for j in range(7):
                xs = [_c_of(t) for t in FIT_TS]
                ys = [sp.Rational(int(values[t][part][i, j].p), int(values[t][part][i, j].q)) for t in FIT_TS]
                f = sp.factor(sp.polys.polyfuncs.rational_interpolate(list(zip(xs, ys)), 2, X=C))
                for t in CHECK_TS:
                    v = values[t][part][i, j]
                    if f.subs(C, _c_of(t)) != sp.Rational(int(v.p), int(v.q)):
                        raise AssertionError(f"fit of {part}[{i},{j}] fails at tan(alpha/4) = {t}")
                m[i, j] = f
        out[part] = m
    return out


def basis(x, y, z, half):
    """T-bar_2^beta at (u, v, w) given e^{iu/2} = x, e^{iv/2} = y, e^{iw/2} = z and e^{i beta/2} = half."""
    def sin(e):
        return (e - 1 / e) / (2 * sp.I)

    def cos(e):
        return (e + 1 / e) / 2

    su, cu, sv, cv, sw, cw = sin(x), cos(x), sin(y), cos(y), sin(z), cos(z)
    s, c = sin(half), cos(half)
    r220, r210, r211 = 1 / s**2, 2 * c / s**2, 2 / s  # Example normalizing_coefficients_n_1
    vals = {}
    for lab in united_system(1):
        ex = {"R": (su, sv, sw, cu, cv, cw), "G": (sw, su, sv, cw, cu, cv), "B": (sv, sw, su, cv, cw, cu)}
        a1, a2, a3, b1, b2, b3 = ex[lab.color]  # the R formula at the permuted arguments (G(u,v,w) = R(w,u,v))
        if lab.is_centre:
            vals[lab.paper] = r211 * su * sv * sw
        elif lab.i == 0:
            vals[lab.paper] = r220 * a1**2
        else:  # i = 1, j = 0: sin(x1/2) sin(x3/2) cos(x2/2)
            vals[lab.paper] = r210 * a1 * a3 * b2
    return [vals[lab.paper] for lab in united_system(1)]


def prove(forms: dict[str, sp.Matrix]) -> dict[str, bool]:
    """The symbolic identity for each part (True: proven for every alpha)."""
    X, Y, Z = sp.symbols("X Y Z", nonzero=True)
    c = ((Z**2 + Z**-2) / 2)  # cos(alpha/2), Z = e^{i alpha/4}
    sub = basis(X, Y, Z / (X * Y), Z)  # e^{iw'/2} = e^{i(alpha/4 - u'/2 - v'/2)}; parameter alpha/2, half angle alpha/4
    out = {}
    for part, m in forms.items():
        if part == "u":
            big = basis(X * Z, Y, Z / (X * Y), Z**2)
        elif part == "v":
            big = basis(X, Y * Z, Z / (X * Y), Z**2)
        elif part == "w":
            big = basis(X, Y, Z**2 / (X * Y), Z**2)
        else:
            big = basis(Z / X, Z / Y, X * Y, Z**2)
        mc = m.subs(C, c)
        ok = True
        for f in range(7):
            diff = sum(mc[g, f] * sub[g] for g in range(7)) - big[f]
            num, _ = sp.fraction(sp.together(diff))
            if sp.expand(num) != 0:
                ok = False
        out[part] = ok
    return out


if __name__ == "__main__":
    forms = closed_forms()
    labels = [lab.paper for lab in united_system(1)]
    for part, m in forms.items():
        print(f"S_{part} (rows: sub-net points, columns: net points; order {labels}):")
        sp.pprint(m)
    print("identity for every alpha:", prove(forms))
