"""Check the conjectures of issue 30 (identities I, II; rules A, A_n, B; C and M) by exact rational arithmetic.

Independent of the library's evaluators: the half-angle values are computed here from rational quarter tangents
(tan(alpha/4), tan(u/4), tan(v/4); w = alpha - u - v by the angle-difference formulas written out below), and
each side of each rule is a product of these values.  Usage::

    .venv/bin/python tools/half_angle_conjectures.py [--nmax-rules 7] [--nmax-tables 10] [--nmax-colloc 8]
"""

from __future__ import annotations

import argparse
import json
import sys
import time

from flint import fmpq

from paper_repro.core import half_angle_rules as hr
from paper_repro.core.labels import delta, exponent_matrix


def quarter(t: fmpq) -> tuple[fmpq, fmpq]:
    """(sin(x/2), cos(x/2)) for tan(x/4) = t."""
    d = 1 + t * t
    return 2 * t / d, (1 - t * t) / d


def point(ta: fmpq, tu: fmpq, tv: fmpq) -> dict:
    """Half-angle data at alpha = 4 atan(ta), u = 4 atan(tu), v = 4 atan(tv), w = alpha - u - v."""
    s, k = quarter(ta)
    su, cu = quarter(tu)
    sv, cv = quarter(tv)
    suv, cuv = su * cv + cu * sv, cu * cv - su * sv          # (u + v)/2
    sw, cw = s * cuv - k * suv, k * cuv + s * suv              # w/2 = alpha/2 - (u + v)/2
    return {"s": s, "k": k, "S": (su / s, sv / s, sw / s), "C": (cu, cv, cw)}


POINTS = [(fmpq(1, 3), fmpq(1, 7), fmpq(2, 9)), (fmpq(2, 5), fmpq(3, 11), fmpq(-1, 13)),
          (fmpq(1, 50), fmpq(1, 300), fmpq(1, 170)), (fmpq(19, 20), fmpq(5, 17), fmpq(7, 23))]


def mono(p: dict, e) -> fmpq:
    out = fmpq(1)
    for x in range(3):
        out *= p["S"][x] ** int(e[2 * x]) * p["C"][x] ** int(e[2 * x + 1])
    return out


def check_identities() -> None:
    for pt in POINTS:
        p = point(*pt)
        k, s2 = p["k"], p["s"] ** 2
        S, C = p["S"], p["C"]
        for x in range(3):
            for y in range(3):
                if x == y:
                    continue
                z = 3 - x - y
                assert C[x] == k * S[x] + S[y] * C[z] + C[y] * S[z], ("I", pt, x, y)
                assert C[y] * C[z] == s2 * S[y] * S[z] + k * C[x] + s2 * S[x], ("II", pt, x, y)
    print("identities (I), (II): hold at", len(POINTS), "points x 6 permutations")


def terms_value(p: dict, n: int, terms) -> fmpq:
    e = exponent_matrix(n)
    k, s2 = p["k"], p["s"] ** 2
    return sum((int(c) * k ** int(a) * s2 ** int(b) * mono(p, e[int(t)]) for a, b, c, t in terms), fmpq(0))


def check_rules(nmax: int) -> None:
    count = {"A": 0, "A_n": 0, "B": 0}
    for n in range(1, nmax + 1):
        pts = [point(*pt) for pt in POINTS[:2]]
        for x in range(3):
            for y in range(3):
                if x == y:
                    continue
                z = 3 - x - y
                for m in range(n + 1):
                    for j in range(m + 1):
                        e = exponent_matrix(n)[hr.member_table(n)[x, y, m, j]]  # the member M_X(m; Y, j)
                        for p in pts:
                            base = mono(p, e)
                            cot = p["C"][x] / p["S"][x] * base
                            if m < n:
                                assert cot == terms_value(p, n, hr._rule_a(n, x, m, y, j)), ("A", n, x, y, m, j)
                                count["A"] += 1
                                if m >= 1:
                                    lhs = p["C"][z] / p["S"][z] * base
                                    assert lhs == terms_value(p, n, hr._rule_b(n, x, m, y, j)), ("B", n, x, y, m, j)
                                    count["B"] += 1
                            else:
                                assert cot == terms_value(p, n, hr._rule_an(n, x, y, j)), ("A_n", n, x, y, j)
                                count["A_n"] += 1
    print(f"rules A, A_n, B for n <= {nmax}: hold exactly at 2 points ({count})")


def to_kappa(terms) -> dict:
    """Merged terms as {(row, col): {kappa power: int}} with sigma = 1 - kappa^2."""
    from math import comb
    out: dict = {}
    for r, c, a, b, coef in zip(*terms):
        poly = out.setdefault((int(r), int(c)), {})
        for t in range(int(b) + 1):
            d = int(a) + 2 * t
            poly[d] = poly.get(d, 0) + int(coef) * comb(int(b), t) * (-1) ** t
    return {key: {d: v for d, v in p.items() if v} for key, p in out.items() if any(p.values())}


def check_tables(nmax: int) -> None:
    from paper_repro.theory.derivative_matrix import table
    for n in range(1, nmax + 1):
        mine = to_kappa(hr.derivative_terms(n))
        rows, cols, coefs = table(n)
        theirs = {(int(r), int(c)): {d: int(v) for d, v in enumerate(co) if v} for r, c, co in zip(rows, cols, coefs)}
        assert mine == theirs, f"C differs from the table at n = {n}"
        print(f"  C at n = {n}: equal to the table ({len(theirs)} entries)", flush=True)
    print(f"C from the rules = derivative_tables.json for n <= {nmax}")


def check_recovered(ns) -> None:
    from paper_repro.theory.derivative_matrix import derivative_polynomials
    for n in ns:
        t0 = time.time()
        rows, cols, coefs = derivative_polynomials(n)
        theirs = {(int(r), int(c)): {d: int(v) for d, v in enumerate(co) if v} for r, c, co in zip(rows, cols, coefs)}
        assert to_kappa(hr.derivative_terms(n)) == theirs, f"C differs from the modular recovery at n = {n}"
        print(f"C from the rules = modular recovery at n = {n} ({time.time() - t0:.0f} s)", flush=True)


def exact_matrix(terms, shape, kappa: fmpq, s2: fmpq) -> list[list[fmpq]]:
    out = [[fmpq(0)] * shape[1] for _ in range(shape[0])]
    for r, c, a, b, coef in zip(*terms):
        out[r][c] += int(coef) * kappa ** int(a) * s2 ** int(b)
    return out


ALPHAS = [fmpq(1, 1000), fmpq(1, 7), fmpq(1, 2), fmpq(5, 7), fmpq(99, 100)]  # tan(alpha/4); near 0 .. near pi


def check_elevation(nmax: int) -> None:
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.elevation import elevation_matrix_exact
    from paper_repro.core.normalization import scaled_coefficient_vector
    for n in range(1, nmax + 1):
        t0 = time.time()
        terms = hr.merge(hr.elevation_terms(n))
        assert int(terms[4].min()) > 0, f"negative coefficient at n = {n}"
        for t in ALPHAS:
            al = rational_alpha(t)
            k, s2 = al.cos_half, al.sin_half ** 2
            m = exact_matrix(terms, (delta(n + 1), delta(n)), k, s2)
            x = scaled_coefficient_vector(n, al, "exact")
            x1 = scaled_coefficient_vector(n + 1, al, "exact")
            e = [[x[f] * m[g][f] / x1[g] for f in range(delta(n))] for g in range(delta(n + 1))]
            assert all(sum(row, fmpq(0)) == 1 for row in e), f"row sums at n = {n}, t = {t}"
            ref = elevation_matrix_exact(n, al)
            assert e == [list(r) for r in ref], f"E differs from collocation at n = {n}, t = {t}"
        print(f"  E at n = {n}: = collocation at {len(ALPHAS)} alphas, rows sum to 1 ({time.time() - t0:.1f} s)",
              flush=True)


def check_nonnegative(nmax: int) -> None:
    for n in range(1, nmax + 1):
        terms = hr.merge(hr.elevation_terms(n))
        assert int(terms[4].min()) > 0
        rows = {}
        for r, c in zip(terms[0], terms[1]):
            rows.setdefault(int(r), set()).add(int(c))
        print(f"  n = {n}: {len(terms[0])} monomials, max row nonzeros {max(map(len, rows.values()))} "
              f"(9n - 2 = {9 * n - 2})", flush=True)
    print(f"M in Z>=0[kappa, sigma] for n <= {nmax}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--nmax-rules", type=int, default=7)
    ap.add_argument("--nmax-tables", type=int, default=10)
    ap.add_argument("--recovered", type=int, nargs="*", default=[])
    ap.add_argument("--nmax-colloc", type=int, default=8)
    ap.add_argument("--nmax-signs", type=int, default=15)
    args = ap.parse_args(argv)
    check_identities()
    check_rules(args.nmax_rules)
    check_tables(args.nmax_tables)
    check_recovered(args.recovered)
    check_nonnegative(args.nmax_signs)
    check_elevation(args.nmax_colloc)
    print(json.dumps({"ok": True}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
