"""Independent check of the transformation rules of issue 30 (Question 7.2, que:open_problem_basis_transformation).

The conjecture handed to the project: for phi = (a, b, d) with |a-b|, |a-d|, |b-d| <= n, the coefficients theta_f of
g_phi = exp(i(au + bv + dw)) = sum_f theta_f f over the *unnormalized* members of T_{2n} are coefficients of

    Gamma_phi(t, W) = zeta^{2b} A^{n+a-b} Abar^{n-a+b} (1 + Abar W)^{n+a-d} (1 + A W)^{n-a+d} / (1 - ct)^{2n},

zeta = c + is, A = c + s^2 t + is(1 - ct) (s = sin(alpha/2), c = cos(alpha/2)): s^{2n+j} theta of R_{2n,2n-k,j}
(j < k <= n) is [t^j W^k] Gamma_(a,b,d); the mirror R_{2n,k,j} takes Gamma_(d,b,a); the diagonal R_{2n,2n-k,k}
(k < n) is [t^k]([W^k] Gamma_(a,b,d) - ct/(1-ct) [W^k] Gamma_(a,d,b)); the centre subtracts Gamma_(a,d,b) and
Gamma_(d,a,b); G and B apply the R rule to (d,a,b) and (b,d,a).  The reverse direction (T in terms of V) is the
binomial expansion of the half-angle sines and cosines.

This tool does not use :mod:`paper_repro.core.transformation`: it implements the rules with Gaussian rationals
(pairs of flint fmpq) and dictionaries of bivariate truncated series, and compares them, at rational-tangent alpha,
with exact collocation solves (flint fmpq_mat, delta_n plane points of small height, verified at 3 more points):

* V_to_T: T Ninv = V (columns: the functions of V_n in the unnormalized T_{2n});
* T_to_V: V N = T (columns: the members of T_{2n} in V_n).

Each deliberately wrong variant of the rules (``--variants``) must produce mismatches.  Usage::

    .venv/bin/python tools/transformation_rules.py --n-max 7 --t 1/2,1/50,9/10,2/7 [--variants]
"""

from __future__ import annotations

import argparse
import time
from math import comb

from flint import fmpq, fmpq_mat

from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import collocate_fmpq
from paper_repro.core.context import ExactContext
from paper_repro.core.domain import RationalPoints, rational_alpha
from paper_repro.core.fourier import evaluate_v, v_system
from paper_repro.core.labels import delta, exponent_matrix, united_system
from paper_repro.core.normalization import fixed_points

Z, ONE = fmpq(0), fmpq(1)
Gauss = tuple[fmpq, fmpq]


def cmul(a: Gauss, b: Gauss) -> Gauss:
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def cadd(a: Gauss, b: Gauss) -> Gauss:
    return (a[0] + b[0], a[1] + b[1])


def cscale(k: fmpq, a: Gauss) -> Gauss:
    return (k * a[0], k * a[1])


def cpow(z: Gauss, e: int) -> Gauss:
    """z^e for a unimodular z (negative e: the conjugate)."""
    out, base = (ONE, Z), (z if e >= 0 else (z[0], -z[1]))
    for _ in range(abs(e)):
        out = cmul(out, base)
    return out


class Series:
    """Bivariate series in t and W truncated above degree N in each; Gaussian-rational coefficients."""

    def __init__(self, N: int, d: dict[tuple[int, int], Gauss]):
        self.N, self.d = N, d

    def __mul__(self, o: Series) -> Series:
        out: dict[tuple[int, int], Gauss] = {}
        for (j1, k1), x in self.d.items():
            for (j2, k2), y in o.d.items():
                j, k = j1 + j2, k1 + k2
                if j <= self.N and k <= self.N:
                    out[(j, k)] = cadd(out.get((j, k), (Z, Z)), cmul(x, y))
        return Series(self.N, out)

    def __pow__(self, e: int) -> Series:
        r = Series(self.N, {(0, 0): (ONE, Z)})
        for _ in range(e):
            r = r * self
        return r

    def get(self, j: int, k: int) -> Gauss:
        return self.d.get((j, k), (Z, Z))


def gamma(n: int, phi: tuple[int, int, int], s: fmpq, c: fmpq) -> Series:
    """Gamma_phi(t, W) truncated at t^n, W^n."""
    a, b, d = phi
    A = Series(n, {(0, 0): (c, s), (1, 0): (s * s, -s * c)})
    Ab = Series(n, {(0, 0): (c, -s), (1, 0): (s * s, s * c)})
    AW = Series(n, {(0, 0): (ONE, Z), (0, 1): (c, s), (1, 1): (s * s, -s * c)})
    AbW = Series(n, {(0, 0): (ONE, Z), (0, 1): (c, -s), (1, 1): (s * s, s * c)})
    geo = Series(n, {(j, 0): (c ** j * comb(2 * n - 1 + j, j), Z) for j in range(n + 1)})  # 1/(1 - ct)^{2n}
    pre = Series(n, {(0, 0): cpow((c, s), 2 * b)})
    return pre * A ** (n + a - b) * Ab ** (n - a + b) * AbW ** (n + a - d) * AW ** (n - a + d) * geo


RIGHT = {"diag": True, "centre": 2, "mirror": True, "g_perm": "dab"}
VARIANTS = {"diagonal without its correction": {"diag": False},
            "centre with one correction term": {"centre": 1},
            "mirror without the u<->w swap": {"mirror": False},
            "G by the B permutation": {"g_perm": "bda"}}


def theta(n: int, phi: tuple[int, int, int], s: fmpq, c: fmpq, cache: dict, rules: dict = RIGHT) -> list[Gauss]:
    """theta_f (unnormalized members, internal order) of g_phi by the conjectured rules."""
    def G(p):
        if p not in cache:
            cache[p] = gamma(n, p, s, c)
        return cache[p]

    def corrected(p, others, j, k):  # [t^j]([W^k] Gamma_p - ct/(1-ct) sum_q [W^k] Gamma_q)
        val = G(p).get(j, k)
        for q in others:
            for ell in range(1, j + 1):
                val = cadd(val, cscale(-c ** ell, G(q).get(j - ell, k)))
        return val

    def r_rule(p, i, j):
        a, b, d = p
        if i == n and j == n:
            return corrected(p, [(a, d, b), (d, a, b)][: rules["centre"]], n, n), 3 * n
        if i == j:
            return corrected(p, [(a, d, b)] if rules["diag"] else [], j, j), 2 * n + j
        if i <= n:
            return G(p).get(j, i), 2 * n + j
        return G((d, b, a) if rules["mirror"] else p).get(j, 2 * n - i), 2 * n + j

    a, b, d = phi
    perm = {"R": (a, b, d), "G": (d, a, b) if rules["g_perm"] == "dab" else (b, d, a), "B": (b, d, a)}
    out = []
    for lab in united_system(n):
        val, e = r_rule(perm[lab.color], lab.i, lab.j)
        out.append(cscale(1 / s ** e, val))
    return out


def rules_v_to_t(n: int, alpha, rules: dict = RIGHT) -> fmpq_mat:
    """Ninv with V = T Ninv (rows: members of T_{2n}; columns: V_n), by the rules."""
    s, c, d = alpha.sin_half, alpha.cos_half, delta(n)
    m, cache = fmpq_mat(d, d), {}
    for col, (kind, trip) in enumerate(v_system(n)):
        th = theta(n, trip, s, c, cache, rules)
        for r in range(d):
            m[r, col] = th[r][0] if kind in ("1", "cos") else th[r][1]
    return m


def half_angle_expansion(a: int, b: int) -> dict[int, Gauss]:
    """sin^a(x/2) cos^b(x/2) = sum_e coef_e exp(i e x / 2): (X - 1/X)^a (X + 1/X)^b / ((2i)^a 2^b), X = e^{ix/2}."""
    poly: dict[int, Gauss] = {0: (ONE, Z)}
    for sign in [-1] * a + [1] * b:
        new: dict[int, Gauss] = {}
        for e, v in poly.items():
            new[e + 1] = cadd(new.get(e + 1, (Z, Z)), v)
            new[e - 1] = cadd(new.get(e - 1, (Z, Z)), cscale(fmpq(sign), v))
        poly = new
    f = (ONE, Z)
    for _ in range(a):
        f = cmul(f, (Z, fmpq(-1, 2)))  # 1/(2i) = -i/2
    f = cscale(fmpq(1, 2 ** b), f)
    return {e: cmul(v, f) for e, v in poly.items() if v != (Z, Z)}


def expansion_t_to_v(n: int, alpha) -> fmpq_mat:
    """N with T = V N (rows: V_n; columns: members of T_{2n}), by the binomial expansion.

    exp(i(e_u u + e_v v + e_w w)/2) on u + v + w = alpha is zeta^{e_w - 2 sigma rho_w} exp(i sigma rho.(u,v,w)) for
    the representative rho of V_n and the sign sigma with (e_u - e_w, e_v - e_w)/2 = sigma (rho_u - rho_w,
    rho_v - rho_w); the real part of K exp(i sigma theta) is Re K cos theta - sigma Im K sin theta."""
    s, c, d = alpha.sin_half, alpha.cos_half, delta(n)
    index = {}
    for k, (kind, rep) in enumerate(v_system(n)):
        if kind != "sin":
            p, q = rep[0] - rep[2], rep[1] - rep[2]
            index[(p, q)] = (k, k + 1, rep, 1)
            index[(-p, -q)] = (k, k + 1, rep, -1)
    out = fmpq_mat(d, d)
    for col, ex in enumerate(exponent_matrix(n)):
        parts = [half_angle_expansion(int(ex[2 * x]), int(ex[2 * x + 1])) for x in range(3)]
        acc: dict[int, fmpq] = {}
        for eu, cu in parts[0].items():
            for ev, cv in parts[1].items():
                for ew, cw in parts[2].items():
                    kc, ks, rep, sign = index[((eu - ew) // 2, (ev - ew) // 2)]
                    co = cmul(cmul(cmul(cu, cv), cw), cpow((c, s), ew - 2 * sign * rep[2]))
                    acc[kc] = acc.get(kc, Z) + co[0]
                    if rep != (0, 0, 0):
                        acc[ks] = acc.get(ks, Z) - sign * co[1]
        for r, v in acc.items():
            out[r, col] = v
    return out


def exact_solve(n: int, alpha, direction: str, seed: int = 31) -> fmpq_mat:
    """The independent computation: collocation at delta_n alpha-independent plane points (small heights), solved
    exactly, verified at 3 more points (:func:`paper_repro.core.collocation.collocate_fmpq`).  'V_to_T': T X = V;
    'T_to_V': V X = T."""
    d, ctx = delta(n), ExactContext()

    def system(k: int):
        tu, tv = fixed_points(n, d + 3, seed + k)
        pts = RationalPoints(None, tu, tv, check=False)
        t_vals, v_vals = evaluate(n, alpha, pts, ctx), evaluate_v(n, alpha, pts, ctx)
        return (t_vals, v_vals) if direction == "V_to_T" else (v_vals, t_vals)

    return collocate_fmpq(system, d, attempts=10, what=f"n = {n}", algorithm=None).solution


def mismatches(a: fmpq_mat, b: fmpq_mat) -> int:
    return sum(1 for i in range(a.nrows()) for j in range(a.ncols()) if a[i, j] != b[i, j])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n-max", type=int, default=7)
    ap.add_argument("--n-min", type=int, default=1)
    ap.add_argument("--t", default="1/2,1/50,9/10,2/7", help="tan(alpha/4) values")
    ap.add_argument("--variants", action="store_true", help="also run the wrong variants (n <= 3)")
    args = ap.parse_args()
    ts = [fmpq(*map(int, x.split("/"))) for x in args.t.split(",")]
    for n in range(args.n_min, args.n_max + 1):
        for t in ts:
            alpha = rational_alpha(t)
            t0 = time.perf_counter()
            f1 = rules_v_to_t(n, alpha)
            t1 = time.perf_counter()
            x1 = exact_solve(n, alpha, "V_to_T")
            t2 = time.perf_counter()
            f2 = expansion_t_to_v(n, alpha)
            t3 = time.perf_counter()
            x2 = exact_solve(n, alpha, "T_to_V")
            t4 = time.perf_counter()
            print(f"n = {n}, tan(alpha/4) = {t}: V_to_T rules {t1 - t0:.2f} s, solve {t2 - t1:.2f} s, "
                  f"mismatches {mismatches(f1, x1)}; T_to_V expansion {t3 - t2:.2f} s, solve {t4 - t3:.2f} s, "
                  f"mismatches {mismatches(f2, x2)}", flush=True)
    if args.variants:
        alpha = rational_alpha(fmpq(1, 2))
        for name, change in VARIANTS.items():
            rules = dict(RIGHT, **change)
            bad = {n: mismatches(rules_v_to_t(n, alpha, rules), exact_solve(n, alpha, "V_to_T")) for n in (1, 2, 3)}
            print(f"wrong variant '{name}': mismatches at n = 1, 2, 3: {bad}")


if __name__ == "__main__":
    main()
