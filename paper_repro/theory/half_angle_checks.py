"""Machine checks of the closed-form elevation matrix M and derivative matrix C (issue 30), independent of the rules.

The rules (:mod:`paper_repro.core.half_angle_rules`) are proven for every n in
docs/elevation_and_derivative_for_all_n.md.  These checks compare what the rules build with routes that know nothing
of them; each takes the integer form as an argument, so a test can hand it a deliberately wrong one and see it fail.

* :func:`identity_check`: the matrix identity itself, exactly over Q at a rational-tangent alpha, at ``delta + extra``
  rational points of the plane u + v + w = alpha where the target system is certified unisolvent (full rank modulo a
  prime bounds the rank over Q from below).  For M: ``m_f(p) = sum_g M[g, f] m'_g(p)``; for C:
  ``2 s d/du m_f(p) = sum_g C[g, f] m_g(p)`` (the derivative of each monomial by
  :func:`~paper_repro.core.derivatives_basis.monomial_derivative`).  Holding at a unisolvent set, the matrix *is*
  the exact collocation solution there (uniqueness, Theorem joint_systems_linear_independence).
* :func:`collocation_equal`: E against the literal exact collocation solve of
  :func:`~paper_repro.core.elevation.elevation_matrix_exact` (small n: it solves a dense rational system).
* :func:`kappa_polynomials`, :func:`tables_equal`: C with sigma = 1 - kappa^2, against the package tables recovered
  modulo two primes (:mod:`paper_repro.theory.derivative_matrix`; n <= 10) or a fresh recovery (n = 11, 12).
* :func:`nonnegative`, :func:`row_sums_exact`: every coefficient of M's bivariate form > 0; rows of the exact E sum
  to 1.

>>> from paper_repro.core.domain import rational_alpha
>>> from paper_repro.core.half_angle_matrices import elevation_form
>>> identity_check("M", 2, rational_alpha(fmpq(1, 3)), elevation_form(2))["ok"]
True
"""

from __future__ import annotations

from math import comb

import numpy as np
from flint import fmpq

from paper_repro.core.basis import monomials
from paper_repro.core.context import ExactContext, ModpContext, to_fmpq_mat
from paper_repro.core.derivatives_basis import monomial_derivative
from paper_repro.core.domain import RationalAngle, RationalPoints, scaled_half_angle_values
from paper_repro.core.half_angle_matrices import elevation_from_form, evaluate_terms
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.normalization import fixed_points
from paper_repro.theory.modular import _matmul_mod
from paper_repro.util.validation import check_n

#: The prime of the unisolvency certificates.
PRIME = 2_147_483_629


def _dense(form, shape, alpha: RationalAngle, ctx) -> np.ndarray:
    kappa, s = ctx.from_rational(alpha.cos_half), ctx.from_rational(alpha.sin_half)
    rows, cols, vals = evaluate_terms(form, kappa, ctx.mul(s, s), ctx)
    out = ctx.zeros(shape)
    out[rows, cols] = vals
    return out


def identity_check(kind: str, n: int, alpha: RationalAngle, form, *, arith: str = "exact", extra: int = 3,
                   seed: int = 5) -> dict:
    """The identity of ``kind`` ('M': elevation n -> n + 1; 'C': derivative along u) for the merged ``form`` at
    ``delta + extra`` rational points, exactly over Q (``arith='exact'``) or over F_p (``'modp'``, p =
    :data:`PRIME`: the exact image, much faster; evidence for the identity over Q, not a proof of it); ``ok`` when it
    holds at every point and the points are unisolvent for the target system (rank over F_p, a lower bound of the
    rank over Q)."""
    n = check_n(n)
    if kind not in ("M", "C"):
        raise ValueError(f"kind must be 'M' (elevation) or 'C' (derivative), got {kind!r}")
    if arith not in ("exact", "modp"):
        raise ValueError(f"arith must be 'exact' or 'modp', got {arith!r}")
    if not isinstance(alpha, RationalAngle):
        raise TypeError(f"alpha must be a RationalAngle, got {type(alpha).__name__}")
    target = n + 1 if kind == "M" else n
    count = delta(target) + extra
    tu, tv = fixed_points(target, count, seed)
    pts = RationalPoints(None, tu, tv, check=False)
    mod = ModpContext(p=PRIME)
    ctx = ExactContext() if arith == "exact" else mod

    def values(c):
        trig = scaled_half_angle_values(pts, alpha, c)
        with c.scope():
            big = monomials(exponent_matrix(target), trig, c)
            if kind == "M":
                return big, monomials(exponent_matrix(n), trig, c)
            s = c.from_rational(alpha.sin_half)
            return big, monomial_derivative(exponent_matrix(n), trig, (1, 0, -1), c, s2=c.mul(s, s))

    big, lhs = values(ctx)
    mat = _dense(form, (delta(target), delta(n)), alpha, ctx)
    if arith == "exact":
        holds = to_fmpq_mat(big) * to_fmpq_mat(mat) == to_fmpq_mat(lhs)
        big_p = values(mod)[0]
    else:
        holds = bool(np.array_equal(_matmul_mod(big, mat, PRIME), lhs % PRIME))
        big_p = big
    rank = mod.rank(big_p)
    return {"kind": kind, "n": n, "t": str(alpha.t), "arith": arith, "points": count, "holds": bool(holds),
            "rank_mod_p": int(rank), "unisolvent": rank == delta(target), "ok": bool(holds) and rank == delta(target)}


def collocation_equal(n: int, alpha: RationalAngle, form) -> bool:
    """E from ``form`` equals the literal exact collocation solve (:func:`~paper_repro.core.elevation.
    elevation_matrix_exact`, seeded rational points of the triangle, verified at three more)."""
    from paper_repro.core.elevation import elevation_matrix_exact

    ctx = ExactContext()
    kappa, s = ctx.from_rational(alpha.cos_half), ctx.from_rational(alpha.sin_half)
    e = elevation_from_form(form, n, kappa, s * s, ctx)
    return e.tolist() == [list(r) for r in elevation_matrix_exact(n, alpha)]


def row_sums_exact(n: int, alpha: RationalAngle, form) -> bool:
    """The rows of the exact E (from ``form``) sum to 1."""
    ctx = ExactContext()
    kappa, s = ctx.from_rational(alpha.cos_half), ctx.from_rational(alpha.sin_half)
    e = elevation_from_form(form, n, kappa, s * s, ctx)
    return all(sum(row, fmpq(0)) == 1 for row in e.tolist())


def nonnegative(form) -> dict:
    """Signs of the bivariate form: ``ok`` when every coefficient is positive (zero sums are dropped by the merge)."""
    coef = np.asarray(form[4])
    return {"monomials": int(len(coef)), "min_coefficient": int(coef.min()) if len(coef) else 0,
            "ok": bool(len(coef) and coef.min() > 0)}


def kappa_polynomials(form) -> dict[tuple[int, int], tuple[int, ...]]:
    """The form with sigma = 1 - kappa^2: ``{(row, col): ascending integer coefficients in kappa}`` (zero entries
    dropped, trailing zeros stripped)."""
    out: dict[tuple[int, int], dict[int, int]] = {}
    for r, c, a, b, coef in zip(*(np.asarray(x).tolist() for x in form)):
        poly = out.setdefault((r, c), {})
        for t in range(b + 1):
            d = a + 2 * t
            poly[d] = poly.get(d, 0) + coef * comb(b, t) * (-1) ** t
    res = {}
    for key, poly in out.items():
        top = max((d for d, v in poly.items() if v), default=-1)
        if top >= 0:
            res[key] = tuple(poly.get(d, 0) for d in range(top + 1))
    return res


def _strip(coefs) -> tuple[int, ...]:
    c = [int(x) for x in coefs]
    while c and c[-1] == 0:
        c.pop()
    return tuple(c)


def tables_equal(n: int, form, recovered=None) -> bool:
    """C (``form``, in kappa) equals the recovered polynomials ``(rows, cols, coefs)``: the package table
    (:func:`~paper_repro.core.derivative_tables.table`, n <= 10) when ``recovered`` is None."""
    if recovered is None:
        from paper_repro.core.derivative_tables import table

        recovered = table(n)
    rows, cols, coefs = recovered
    theirs = {(int(r), int(c)): _strip(co) for r, c, co in zip(rows, cols, coefs)}
    return kappa_polynomials(form) == {k: v for k, v in theirs.items() if v}


def perturbed(form, which: int = 0, by: int = 1) -> tuple[np.ndarray, ...]:
    """A deliberately wrong copy of a merged form: coefficient ``which`` changed by ``by`` (for the tests that show
    each check can fail)."""
    out = tuple(np.array(x, copy=True) for x in form)
    out[4][which] += by
    return out
