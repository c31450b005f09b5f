"""Proof, for every alpha, that candidate closed forms are the normalizing coefficients (Question 1).

Candidates: ``x_o(alpha) = P_o(c) / s^{k_o}`` for every orbit o of T_{2n} (c = cos(alpha/2), s = sin(alpha/2)),
e.g. from :func:`paper_repro.theory.modular.recover_modular` or printed in the paper.

**The argument** (written out in ``docs/proof_of_closed_forms.md``).  On the plane u + v + w = alpha write
the functions of T_{2n} in the coordinates (u, v).  Each is a product of powers of half-angle sines and
cosines whose exponents satisfy: the degrees in (u, w), (v, w) and (u, v) are each at most 2n and even.
Hence every function, and the constant 1, lies in the space H_n of real trigonometric polynomials
``sum c_{K,L} e^{i(K u + L v)}`` with integer frequencies in the hexagon |K|, |L|, |K - L| <= n; H_n does not
depend on alpha and has real dimension 3n^2 + 3n + 1 = delta_n.

1. *Independence at one alpha.*  The delta_n x delta_n collocation matrix of T_{2n} at alpha-independent
   plane points has full rank modulo a prime at alpha_0 (so over Q: a rank modulo p is a lower bound).
   Its determinant is a rational function of t = tan(alpha/4), non-zero at t_0, hence zero for at most
   finitely many alpha: outside a finite set E_1, T_{2n}^alpha is a basis of H_n and 1 is in its span.
2. *A unisolvent set for the symmetric part.*  The orbit sums F_o of the m = (n+1)(n+2)/2 orbits
   (permutations of u, v, w) span the permutation-invariant part of H_n whenever T_{2n}^alpha is a basis.
   At N >= m alpha-independent points the N x m matrix A(t) of the F_o has full rank modulo p at t_0,
   so outside a finite set E_2 it has full column rank.
3. *The identity at the points, for every alpha.*  At each of the N points the residual
   ``sum_o x_o(alpha) F_o - 1``, multiplied by ``s^K (1 + t^2)^{d + K + R}``, is a polynomial in t with
   rational coefficients; it is computed exactly and is the zero polynomial (:func:`residual_at_point`: the
   sum grouped by the exponents of sin(w/2), cos(w/2) and evaluated by Horner's rule in them).
4. For alpha outside E_1 and E_2: ``1 = sum_o y_o F_o`` for some y (step 1, and the symmetry of 1), and
   A(t)(x - y) = 0 by step 3, so x = y and ``sum_o x_o F_o = 1`` on the whole plane.  Both sides are
   continuous in alpha, so the identity holds for every alpha in (0, pi): the candidates form a partition
   of unity with T_{2n}^alpha for every alpha.  They are *the* normalizing coefficients wherever T_{2n}^alpha
   is linearly independent: outside E_1 by step 1, and for every alpha by Theorem
   joint_systems_linear_independence of the paper (checked here by exact ranks at sampled alpha only).

Positivity of P_o on 0 < c < 1 (Sturm, :func:`paper_repro.theory.closed_forms.sign_on_unit_interval`) then
proves x_o(alpha) > 0 for every alpha in (0, pi).

>>> from paper_repro.theory.modular import recover_modular
>>> prove_identity(2, recover_modular(2))["proved"]
True
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from math import gcd

from flint import fmpq, fmpz_mat, fmpz_poly

from paper_repro.core.basis import evaluate
from paper_repro.core.context import ModpContext
from paper_repro.core.domain import RationalPoints, rational_alpha
from paper_repro.core.labels import exponent_matrix, united_system
from paper_repro.core.normalization import fixed_points, orbits, reduced_matrix
from paper_repro.util.validation import check_n

#: The prime of the rank certificates (2^31 - 1) and the shape parameter t_0 = tan(alpha_0/4) they use.
PRIME = 2**31 - 1
T0 = fmpq(1, 3)

_OMEGA = fmpz_poly([1, 0, 1])  # 1 + t^2


@dataclass(frozen=True)
class ProofPoints:
    """alpha-independent points of the plane: quarter tangents of u and v."""

    tu: tuple[fmpq, ...]
    tv: tuple[fmpq, ...]

    def rational(self) -> RationalPoints:
        return RationalPoints(None, self.tu, self.tv, check=False)


def proof_points(n: int, count: int, seed: int = 7) -> ProofPoints:
    tu, tv = fixed_points(n, count, seed)
    return ProofPoints(tuple(tu), tuple(tv))


def independence_certificate(n: int, seed: int = 11) -> dict:
    """Step 1: rank modulo :data:`PRIME` of T_{2n} at delta_n alpha-independent plane points, alpha_0 = 4 atan(T0)."""
    d = len(united_system(n))
    pts = proof_points(n, d, seed).rational()
    a = evaluate(n, rational_alpha(T0), pts, ModpContext(p=PRIME))
    rank = ModpContext(p=PRIME).rank(a)
    return {"rank": rank, "delta_n": d, "full": rank == d, "prime": PRIME, "t0": str(T0)}


def unisolvence_certificate(n: int, pts: ProofPoints) -> dict:
    """Step 2: rank modulo :data:`PRIME` of the N x m orbit-sum matrix at the proof points, alpha_0."""
    m = len(orbits(n))
    a = reduced_matrix(n, rational_alpha(T0), pts.rational(), ModpContext(p=PRIME))
    rank = ModpContext(p=PRIME).rank(a)
    return {"rank": rank, "orbits": m, "points": len(pts.tu), "full": rank == m}


def _powers(p, kmax: int) -> list:
    out = [p**0]
    for _ in range(kmax):
        out.append(out[-1] * p)
    return out


def _scaled_candidates(n: int, forms: dict, d: int, big_k: int, scale: int) -> list[fmpz_poly]:
    """``scale * P_o(c) s^{K - k_o} (1 + t^2)^{d + K}``: integer polynomials in t, in orbit order.

    ``(1 + t^2)^d P(c) = sum_i a_i (1 - t^2)^i (1 + t^2)^{d - i}``: one integer matrix product for all orbits.
    """
    one_minus = _powers(fmpz_poly([1, 0, -1]), d)
    omega = _powers(_OMEGA, d + big_k)
    basis = [one_minus[i] * omega[d - i] for i in range(d + 1)]
    reps = [forms[rep.coefficient] for rep, _ in orbits(n)]
    coef = fmpz_mat([[int(a * scale) for a in f.numerator.coeffs()] + [0] * (d + 1 - len(f.numerator.coeffs()))
                     for f in reps])
    hats = coef * fmpz_mat([[int(x) for x in h.coeffs()] + [0] * (2 * d + 1 - len(h.coeffs())) for h in basis])
    factor = {k: fmpz_poly([0, 2]) ** (big_k - k) * omega[k] for k in {f.sin_power for f in reps}}
    return [fmpz_poly(row) * factor[f.sin_power] for row, f in zip(hats.table(), reps)]


def prepare(n: int, forms: dict) -> dict:
    """What every point shares: exponents, orbits, the cleared candidates and right-hand side, and the candidates
    times every power of 1 + t^2 that :func:`residual_at_point` needs."""
    exps = exponent_matrix(n)
    orbit_of = [0] * len(exps)
    for o, (_, members) in enumerate(orbits(n)):
        for k in members:
            orbit_of[k] = o
    d = max(max(f.numerator.degree(), 0) for f in forms.values())
    big_k = max(f.sin_power for f in forms.values())
    scale = 1
    for f in forms.values():
        for a in f.numerator.coeffs():
            scale = scale * int(a.q) // gcd(scale, int(a.q))
    r_max = int((exps[:, 4] + exps[:, 5]).max())
    p_max = int((exps[:, 0] + exps[:, 1] + exps[:, 4] + exps[:, 5]).max())
    q_max = int((exps[:, 2] + exps[:, 3] + exps[:, 4] + exps[:, 5]).max())
    by_orbit: list[list[tuple[int, ...]]] = [[] for _ in orbits(n)]
    for row, o in zip(exps, orbit_of):
        by_orbit[o].append(tuple(int(x) for x in row))
    omega = _powers(_OMEGA, r_max)
    scaled = _scaled_candidates(n, forms, d, big_k, scale)
    # the terms grouped by the w exponents (a, b) = (e4, e5): [(orbit, members with these exponents)]
    by_key: dict[tuple[int, int], dict[int, list[tuple[int, ...]]]] = {}
    for o, members in enumerate(by_orbit):
        for e in members:
            by_key.setdefault((e[4], e[5]), {}).setdefault(o, []).append(e)
    shifted: dict[tuple[int, int], fmpz_poly] = {}
    for o in range(len(scaled)):
        prev, poly = 0, scaled[o]
        for c in sorted({r_max - e[4] - e[5] for e in by_orbit[o]}):
            poly = shifted[o, c] = poly * omega[c - prev]
            prev = c
    b_max: dict[int, int] = {}
    for a, b in by_key:
        b_max[a] = max(b, b_max.get(a, b))
    out = {"by_orbit": by_orbit, "R": r_max, "P": p_max, "Q": q_max, "kmax": int(exps.max()),
           "omega": omega, "scaled": scaled, "by_key": {k: list(v.items()) for k, v in by_key.items()},
           "shifted": shifted, "a_max": max(a for a, _ in by_key),
           "b_max": b_max,
           "rhs": fmpz_poly([0, 2]) ** big_k * _OMEGA ** (d + r_max) * scale, "d": d, "K": big_k}
    return out


def _split(x: fmpq) -> tuple[int, int]:
    return int(x.p), int(x.q)


def residual_at_point(n: int, forms: dict, tu: fmpq, tv: fmpq, *, _cache: dict | None = None) -> fmpz_poly:
    """Step 3 at one point: ``s^K (1+t^2)^{d+K+R} (sum_o x_o F_o - 1)``, times a positive integer, as an
    integer polynomial in t = tan(alpha/4) (zero exactly when the identity holds at the point).

    With ``sigma``, ``kappa`` the cleared sin(w/2), cos(w/2) (quadratics in t) and ``S_o`` the cleared
    candidates, the polynomial is ``sum_{a, b} sigma^a kappa^b Z_ab - rhs`` with
    ``Z_ab = sum_o G_{o,ab} (1+t^2)^{R-a-b} S_o``, where the integer ``G_{o,ab}`` sums the point factors of
    the members of orbit o whose w exponents are (a, b).  The products ``(1+t^2)^c S_o`` do not depend on the
    point (:func:`prepare`); the double sum is evaluated by Horner's rule in sigma (outer) and kappa (inner),
    so a point costs one integer times a polynomial per (orbit, a, b) and one multiplication by a quadratic per
    (a, b) -- instead of a product of two long polynomials per orbit.  Same polynomial, exactly.

    >>> from paper_repro.theory.modular import recover_modular
    >>> forms = recover_modular(2)
    >>> residual_at_point(2, forms, fmpq(1, 5), fmpq(3, 7)).is_zero()
    True
    """
    cache = _cache if _cache is not None else prepare(n, forms)
    (a, qa), (b, qb) = _split(fmpq(tu)), _split(fmpq(tv))
    du, dv = a * a + qa * qa, b * b + qb * qb  # sin(u/2) = su/du, cos(u/2) = cu/du, same for v
    su, cu, sv, cv = 2 * a * qa, qa * qa - a * a, 2 * b * qb, qb * qb - b * b
    sab, cab = su * cv + cu * sv, cu * cv - su * sv  # (du dv) sin((u+v)/2), (du dv) cos((u+v)/2)
    # w/2 = alpha/2 - (u+v)/2:  sin(w/2) = sigma / (du dv (1+t^2)), cos(w/2) = kappa / (du dv (1+t^2))
    r_max, p_max, q_max = cache["R"], cache["P"], cache["Q"]
    sig = fmpz_poly([-sab, 2 * cab, sab])
    kap = fmpz_poly([cab, 2 * sab, -cab])
    kmax = cache["kmax"]
    pw = [_powers(x, kmax) for x in (su, cu, sv, cv)]
    pdu, pdv = _powers(du, p_max), _powers(dv, q_max)
    shifted = cache["shifted"]
    by_key = cache["by_key"]
    total = fmpz_poly([0])
    for ka in range(cache["a_max"], -1, -1):
        inner = fmpz_poly([0])
        for kb in range(cache["b_max"].get(ka, -1), -1, -1):
            inner *= kap
            group = by_key.get((ka, kb))
            if group is None:
                continue
            r = ka + kb
            c = r_max - r
            for o, members in group:
                g = 0
                for e in members:
                    g += (pw[0][e[0]] * pw[1][e[1]] * pw[2][e[2]] * pw[3][e[3]]
                          * pdu[p_max - e[0] - e[1] - r] * pdv[q_max - e[2] - e[3] - r])
                inner += shifted[o, c] * g
        total = total * sig + inner
    return total - cache["rhs"] * (pdu[p_max] * pdv[q_max])


#: Proof points beyond the number of orbits (the unisolvence certificate needs only that many; a margin).
EXTRA_POINTS = 3


def prove_identity(n: int, forms: dict, *, extra: int = EXTRA_POINTS, progress: bool = False) -> dict:
    """Steps 1-3 for the candidates ``forms`` ``{orbit representative label: ClosedForm}``.

    ``proved`` is True when both rank certificates are full and every residual polynomial is zero.
    """
    n = check_n(n)
    m = len(orbits(n))
    missing = [rep.coefficient for rep, _ in orbits(n) if rep.coefficient not in forms]
    if missing:
        raise ValueError(f"forms: no candidate for {missing[:3]} (n = {n})")
    pts = proof_points(n, m + extra)
    cert1 = independence_certificate(n)
    cert2 = unisolvence_certificate(n, pts)
    cache = prepare(n, forms)
    failed = []
    for k, (tu, tv) in enumerate(zip(pts.tu, pts.tv)):
        if not residual_at_point(n, forms, tu, tv, _cache=cache).is_zero():
            failed.append(k)
            break
        if progress and (k + 1) % 100 == 0:
            print(f"identity proof n={n}: {k + 1}/{len(pts.tu)} points", file=sys.stderr, flush=True)
    return {"proved": cert1["full"] and cert2["full"] and not failed, "independence": cert1,
            "unisolvence": cert2, "points": len(pts.tu), "residuals_zero": not failed,
            "first_nonzero_residual_point": failed[0] if failed else None,
            "residual_degree_bound": 2 * (cache["d"] + cache["K"] + cache["R"])}
