"""Closed forms of the normalizing coefficients and their positivity (open Question 1).

For every orbit representative ``r_{2n,2n-i,j}`` we look for a polynomial P with rational
coefficients such that ``r_{2n,2n-i,j}^alpha = P(cos(alpha/2)) / sin^{2n+j}(alpha/2)``.

* Recovery (:func:`recover`): exact coefficients at rational-tangent alpha
  (:mod:`paper_repro.core.normalization`), ``y = r s^{2n+j}`` interpolated exactly in ``c = cos(alpha/2)``
  with increasing degree until the interpolant also matches at ``verify`` further alpha.
  That alone is *evidence*.
* Proof (:func:`prove`): with the alpha-independent collocation points every coefficient is a
  rational function of t = tan(alpha/4) whose numerator and denominator have degree <= 4nm
  (:func:`paper_repro.core.normalization.cramer_degree_bound`); ``P(c)/s^k`` is one with numerator degree
  <= 2 max(deg P, k) and denominator degree <= 2 max(deg P - k, 0) + k.  Their difference, cleared of
  denominators, has degree <= B = 4nm + 2 max(deg P, k) + k, so agreement at B + 1 distinct t (where
  the fixed collocation matrix is non-singular) proves the closed form for *every* alpha.
* Positivity (:func:`sign_on_unit_interval`): exact real-root count of P on the open interval
  0 < c < 1 (Sturm sequence in flint's exact ``fmpq_poly`` arithmetic) and its sign at one point.
  With a proven closed form this proves ``r > 0`` for all alpha in (0, pi).
"""

from __future__ import annotations

from dataclasses import dataclass

from flint import fmpq, fmpq_mat, fmpq_poly
from tqdm import tqdm

from paper_repro.core.domain import RationalAngle, rational_alpha
from paper_repro.core.normalization import (
    cramer_degree_bound,
    exact_coefficients_cached,
    orbits,
    parse_fmpq,
    solve_reduced_exact,
)
from paper_repro.util.cache import cached


def t_grid(count: int, start: int = 2) -> list[RationalAngle]:
    """Distinct shape parameters alpha = 4 atan(1/k), k = start, start+1, ... (all in (0, pi))."""
    return [rational_alpha(fmpq(1, k)) for k in range(start, start + count)]


def sin_power(label_j: int, n: int) -> int:
    return 2 * n + label_j


def interpolate(xs: list[fmpq], ys: list[fmpq]) -> fmpq_poly:
    """Exact interpolating polynomial through (xs, ys) (Vandermonde solve with flint)."""
    d = len(xs)
    vander = fmpq_mat(d, d, [x**k for x in xs for k in range(d)])
    coeffs = vander.solve(fmpq_mat(d, 1, ys))
    return fmpq_poly([coeffs[k, 0] for k in range(d)])


@dataclass
class ClosedForm:
    label: str
    sin_power: int
    numerator: fmpq_poly  # in c = cos(alpha/2)

    def value(self, alpha: RationalAngle) -> fmpq:
        return self.numerator(alpha.cos_half) / alpha.sin_half ** self.sin_power

    def as_json(self) -> dict:
        coeffs = [str(x) for x in self.numerator.coeffs()] or ["0"]
        return {"sin_power": self.sin_power, "numerator": coeffs}


def _values(n: int, alphas: list[RationalAngle]) -> list[list[fmpq]]:
    return [exact_coefficients_cached(n, a)[0] for a in alphas]


def recover(n: int, verify: int = 4, max_degree: int | None = None) -> dict[str, ClosedForm]:
    """Closed forms ``P(c)/s^{2n+j}`` of every orbit representative, verified at ``verify`` extra alpha.

    Raises ``ArithmeticError`` if no polynomial of degree <= ``max_degree`` (default 6n + 4) fits.
    """
    orb = orbits(n)
    limit = max_degree if max_degree is not None else 6 * n + 4
    degree = 2 * n + 2
    while degree <= limit:
        alphas = t_grid(degree + 1 + verify)
        vals = _values(n, alphas)
        forms: dict[str, ClosedForm] = {}
        ok = True
        for o, (rep, _) in enumerate(orb):
            k = sin_power(rep.j, n)
            ys = [vals[a][o] * alphas[a].sin_half ** k for a in range(len(alphas))]
            xs = [a.cos_half for a in alphas]
            poly = interpolate(xs[: degree + 1], ys[: degree + 1])
            if any(poly(xs[a]) != ys[a] for a in range(degree + 1, len(alphas))):
                ok = False
                break
            forms[rep.coefficient] = ClosedForm(rep.coefficient, k, poly)
        if ok:
            return forms
        degree += n + 1
    raise ArithmeticError(f"no closed form P(c)/s^(2n+j) with deg P <= {limit} found for n = {n}")


def proof_points_needed(n: int, forms: dict[str, ClosedForm]) -> int:
    """B + 1 with B = 4nm + 2 max(deg P, k) + k, maximised over the forms."""
    worst = max(2 * max(f.numerator.degree(), f.sin_power) + f.sin_power for f in forms.values())
    return cramer_degree_bound(n) + worst + 1


def prove(n: int, forms: dict[str, ClosedForm], progress: bool = False) -> dict:
    """Check ``forms`` at B + 1 distinct alpha with the fixed (first) collocation point set.

    Returns ``{"proved": bool, "points_needed": B+1, "points_checked": ..., "mismatch": label or None}``.
    """
    need = proof_points_needed(n, forms)
    orb = orbits(n)
    checked, k = 0, 2
    bar = tqdm(total=need, desc=f"proof n={n}", leave=False, disable=not progress)
    while checked < need:
        alpha = rational_alpha(fmpq(1, k))
        k += 1
        try:
            sol, _ = solve_reduced_exact(n, alpha, verify=0, attempts=1)
        except ArithmeticError:
            continue  # fixed point set singular at this t: not usable for the degree argument
        for o, (rep, _) in enumerate(orb):
            if forms[rep.coefficient].value(alpha) != sol[o]:
                bar.close()
                return {"proved": False, "points_needed": need, "points_checked": checked,
                        "mismatch": rep.coefficient, "t": str(alpha.t)}
        checked += 1
        bar.update(1)
    bar.close()
    return {"proved": True, "points_needed": need, "points_checked": checked, "mismatch": None}


def sturm_count(p: fmpq_poly, a: fmpq, b: fmpq) -> int:
    """Number of distinct real roots of ``p`` in the half-open interval (a, b] (Sturm's theorem)."""
    if p.degree() <= 0:
        return 0
    p = p / p.gcd(p.derivative())  # square-free part: same distinct roots
    seq = [p, p.derivative()]
    while seq[-1].degree() > 0:
        rem = -(seq[-2] % seq[-1])
        if rem.is_zero():
            break
        seq.append(rem)

    def variations(x: fmpq) -> int:
        signs = [v for v in (q(x) for q in seq) if v != 0]
        return sum(1 for u, v in zip(signs, signs[1:]) if (u > 0) != (v > 0))

    return variations(a) - variations(b)


def sign_on_unit_interval(p: fmpq_poly) -> dict:
    """Roots of ``p`` in the open interval (0, 1) and its sign there (``+1``/``-1``, or 0 if it changes)."""
    roots = sturm_count(p, fmpq(0), fmpq(1)) - (1 if p(fmpq(1)) == 0 else 0)
    mid = p(fmpq(1, 2))
    sign = 0 if roots or mid == 0 else (1 if mid > 0 else -1)
    return {"roots_in_open_unit_interval": roots, "sign": sign}


def closed_forms_cached(n: int) -> dict[str, ClosedForm]:
    """:func:`recover`, memoised on disk."""
    stored = cached("closed_forms", {"n": n}, lambda: {k: v.as_json() for k, v in recover(n).items()})
    return {k: ClosedForm(k, v["sin_power"], fmpq_poly([parse_fmpq(x) for x in v["numerator"]]))
            for k, v in stored.items()}
