"""Closed forms, in cos(alpha/2) and sin(alpha/2), of matrices that depend on alpha, and their proof.

Used for the order-elevation matrices (T_{2n} in terms of T_{2n+2}) and the basis transformation between
T-bar_{2n} and V_n (open questions of Section 7).  An entry is sought as

    m(alpha) = (P(c) + s Q(c)) / s^K,      c = cos(alpha/2), s = sin(alpha/2),

* **recovery** (:func:`recover_entries`): exact matrices at alpha = 4 atan(1/k), ``s^K m`` fitted exactly by
  P + sQ of increasing degree and verified at further alpha (evidence);
* **proof** (:func:`prove_identity_at_points`): the defining identity ``target_k = sum_j m_jk basis_j`` is
  checked as an identity of rational functions of t = tan(alpha/4) at delta alpha-independent plane points
  whose collocation matrix of ``basis`` has full rank modulo p at one alpha.  Every function involved lies in
  the alpha-independent space H_N of trigonometric polynomials with hexagon frequencies |K|,|L|,|K-L| <= N
  (dimension delta_N, see ``docs/proof_of_closed_forms.md``); for all but finitely many alpha the basis spans
  H_N and the points are unisolvent for it, so the residual vanishes identically; by continuity for every
  alpha in (0, pi);
* **sign** (:func:`sign_on_0_pi`): exact Sturm root counts of numerator and denominator in t on (0, 1).

>>> e = EntryForm(2, fmpq_poly([0, 2]), fmpq_poly([0]))   # 2c / s^2
>>> str(e.value(fmpq(1, 2)))                                # t = 1/2: c = 3/5, s = 4/5
'15/8'
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from flint import fmpq, fmpq_mat, fmpq_poly

from paper_repro.core.domain import rational_alpha
from paper_repro.theory.closed_forms import sturm_count
from paper_repro.theory.ratfunc import RatFunc, half_angle_functions, poly_at


@dataclass(frozen=True)
class EntryForm:
    """``(P(c) + s Q(c)) / s^K``."""

    K: int
    P: fmpq_poly
    Q: fmpq_poly

    def value(self, t: fmpq) -> fmpq:
        a = rational_alpha(t)
        s, c = a.sin_half, a.cos_half
        return (self.P(c) + s * self.Q(c)) / s**self.K

    def ratfunc(self, s: RatFunc, c: RatFunc) -> RatFunc:
        return (poly_at(self.P.coeffs(), c) + s * poly_at(self.Q.coeffs(), c)) / s**self.K

    def is_zero(self) -> bool:
        return self.P.is_zero() and self.Q.is_zero()

    def as_json(self) -> dict:
        return {"sin_power_K": self.K, "P": [str(x) for x in self.P.coeffs()] or ["0"],
                "Q": [str(x) for x in self.Q.coeffs()] or ["0"]}

    def latex(self) -> str:
        if self.is_zero():
            return "0"
        num = _poly_latex(self.P)
        if not self.Q.is_zero():
            q = _poly_latex(self.Q)
            num = (f"{num} + s\\left({q}\\right)" if not self.P.is_zero() else f"s\\left({q}\\right)")
        den = "s" if self.K == 1 else f"s^{{{self.K}}}"
        return num if self.K == 0 else f"\\frac{{{num}}}{{{den}}}"


def _poly_latex(p: fmpq_poly) -> str:
    terms = []
    for k, a in reversed(list(enumerate(p.coeffs()))):
        if a == 0:
            continue
        mag = abs(a)
        coef = "" if (mag == 1 and k > 0) else (str(mag) if mag.q == 1 else f"\\tfrac{{{mag.p}}}{{{mag.q}}}")
        mono = "" if k == 0 else ("c" if k == 1 else f"c^{{{k}}}")
        terms.append(("-" if a < 0 else "+", coef + mono))
    if not terms:
        return "0"
    head = ("-" if terms[0][0] == "-" else "") + terms[0][1]
    return head + "".join(f" {sg} {b}" for sg, b in terms[1:])


def _reduce(e: EntryForm) -> EntryForm:
    """Cancel s^2 = 1 - c^2 while both parts allow it (a canonical, shorter form of the same function)."""
    one_minus = fmpq_poly([1, 0, -1])
    k, p, q = e.K, e.P, e.Q
    if p.is_zero() and not q.is_zero() and k >= 1:  # s Q / s^K = Q / s^(K-1)
        p, q, k = q, fmpq_poly([0]), k - 1
    while k >= 2 and (p % one_minus).is_zero() and (q % one_minus).is_zero() and not (p.is_zero() and q.is_zero()):
        p, q, k = p // one_minus, q // one_minus, k - 2
    if k == 1 and not p.is_zero() and (p % one_minus).is_zero():  # (P + sQ)/s = Q + s P/(1 - c^2)
        p, q, k = q, p // one_minus, 0
    if p.is_zero() and q.is_zero():
        k = 0
    return EntryForm(k, p, q)


def recover_entries(matrix_at: Callable[[fmpq], fmpq_mat], K: int, max_degree: int, verify: int = 3
                    ) -> list[list[EntryForm]]:
    """Closed forms of every entry of ``matrix_at(t)`` (exact at rational t); ``ArithmeticError`` if none with
    P, Q of degree <= ``max_degree``."""
    cache: dict[int, fmpq_mat] = {}

    def mat(k: int) -> fmpq_mat:
        if k not in cache:
            cache[k] = matrix_at(fmpq(1, k + 2))
        return cache[k]

    degree = 2
    while degree <= max_degree:
        count = 2 * (degree + 1) + verify
        alphas = [rational_alpha(fmpq(1, k + 2)) for k in range(count)]
        rows = [[a.cos_half**i for i in range(degree + 1)] + [a.sin_half * a.cos_half**i for i in range(degree + 1)]
                for a in alphas]
        fit = fmpq_mat(2 * (degree + 1), 2 * (degree + 1), [x for r in rows[: 2 * (degree + 1)] for x in r])
        try:
            inv = fit.inv()
        except ZeroDivisionError:
            degree += 1
            continue
        first = mat(0)
        out, ok = [], True
        for i in range(first.nrows()):
            line = []
            for j in range(first.ncols()):
                ys = [mat(k)[i, j] * alphas[k].sin_half ** K for k in range(count)]
                sol = inv * fmpq_mat(2 * (degree + 1), 1, ys[: 2 * (degree + 1)])
                coef = [sol[r, 0] for r in range(2 * (degree + 1))]
                if any(sum((c * x for c, x in zip(coef, rows[k])), fmpq(0)) != ys[k]
                       for k in range(2 * (degree + 1), count)):
                    ok = False
                    break
                line.append(_reduce(EntryForm(K, fmpq_poly(coef[: degree + 1]), fmpq_poly(coef[degree + 1:]))))
            if not ok:
                break
            out.append(line)
        if ok:
            return out
        degree += 1
    raise ArithmeticError(f"no closed form (P + sQ)/s^{K} with degree <= {max_degree}")


def prove_identity_at_points(value_at_point: Callable[[fmpq, fmpq, RatFunc, RatFunc], list],
                             check: Callable[[list], bool], points: list[tuple[fmpq, fmpq]]) -> bool:
    """``check(value_at_point(tu, tv, s, c))`` at every point, with s, c = sin, cos(alpha/2) as rational functions
    of t = tan(alpha/4) (the identity holds for every t at that point)."""
    s, c = half_angle_functions()
    return all(check(value_at_point(tu, tv, s, c)) for tu, tv in points)


def sign_on_0_pi(f: RatFunc) -> int:
    """Sign of a rational function of t on 0 < t < 1 (alpha in (0, pi)): +1, -1, 0 if identically zero;
    ``None`` if it changes sign or has a pole there (exact Sturm counts)."""
    if f.num.is_zero():
        return 0
    for p in (f.num, f.den):
        roots = sturm_count(p, fmpq(0), fmpq(1)) - (1 if p(fmpq(1)) == 0 else 0)
        if roots:
            return None
    v = f.num(fmpq(1, 2)) / f.den(fmpq(1, 2))
    return 1 if v > 0 else -1


def entry_degree(e: EntryForm) -> int:
    """d of the entry: (P + sQ)/s^K = num(t) / ((2t)^K (1+t^2)^{d-K}) with deg num <= 2d."""
    return max(e.P.degree(), e.Q.degree() + 1, 0)


def prove_matrix_identity(forms: list[list[EntryForm]], basis_at, target_at, r_basis: int, r_target: int,
                          ts: list[fmpq] | None = None) -> dict:
    """Prove ``target(p) = basis(p) M`` at fixed plane points for every alpha, M given by ``forms``.

    ``basis_at(t)``/``target_at(t)`` give the exact ``(points, J)``/``(points, F)`` fmpq matrices at
    tan(alpha/4) = t; every basis (target) function at a fixed point is gamma * (polynomial of degree
    <= 2r in t) / (1+t^2)^r with r <= ``r_basis`` (``r_target``).  Multiplied by (2t)^Kmax (1+t^2)^E the
    residual is a polynomial of degree <= 2E + 2Kmax, so its vanishing at that many + 1 distinct t != 0 is an
    identity in t.  (Unisolvence of the points is certified separately by a rank.)
    """
    nonzero = [e for row in forms for e in row if not e.is_zero()]
    k_max = max((e.K for e in nonzero), default=0)
    big_e = max([entry_degree(e) + r_basis - e.K for e in nonzero] + [r_target, 0])
    bound = 2 * big_e + 2 * k_max
    ts = ts or [fmpq(1, k) for k in range(2, bound + 3)]
    if len(ts) < bound + 1:
        raise ValueError(f"ts: need at least {bound + 1} values of t, got {len(ts)}")
    rows, cols = len(forms), len(forms[0])
    for t in ts[: bound + 1]:
        m = fmpq_mat(rows, cols, [e.value(t) for row in forms for e in row])
        if basis_at(t) * m != target_at(t):
            return {"proved": False, "degree_bound": bound, "failed_at_t": str(t)}
    return {"proved": True, "degree_bound": bound, "t_values": bound + 1}
