"""Machine checks of the explicitly constructed elevation matrix M and derivative matrix C (issue 30), independent of
the rules.

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
* :func:`identities_hold`, :func:`rules_hold`: the identities (I), (II) and each cotangent rule, both sides evaluated
  exactly at rational points from their own half-angle values (quarter tangents; w by the angle-difference formulas
  written out here, not the library's).
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
from paper_repro.core.context import Context, ExactContext, ModpContext, get_context, to_fmpq_mat
from paper_repro.core.derivatives_basis import monomial_derivative
from paper_repro.core.domain import RationalAngle, RationalPoints, scaled_half_angle_values
from paper_repro.core.half_angle_matrices import elevation_from_form, evaluate_terms
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.normalization import fixed_points
from paper_repro.util.validation import check_n

#: The prime of the unisolvency certificates.
PRIME = 2_147_483_629


#: Rational test points ``(tan(alpha/4), tan(u/4), tan(v/4))``: w = alpha - u - v need not be positive (the
#: identities hold on the whole plane).
POINTS = ((fmpq(1, 3), fmpq(1, 7), fmpq(2, 9)), (fmpq(2, 5), fmpq(3, 11), fmpq(-1, 13)),
          (fmpq(1, 50), fmpq(1, 300), fmpq(1, 170)), (fmpq(19, 20), fmpq(5, 17), fmpq(7, 23)))


def _quarter(t: fmpq) -> tuple[fmpq, fmpq]:
    d = 1 + t * t
    return 2 * t / d, (1 - t * t) / d


def half_angle_point(ta: fmpq, tu: fmpq, tv: fmpq) -> dict:
    """``kappa``, ``sigma`` and the scaled values ``S = (S_u, S_v, S_w)``, ``C = (C_u, C_v, C_w)`` at alpha =
    4 atan(ta), u = 4 atan(tu), v = 4 atan(tv), w = alpha - u - v (exact rationals)."""
    s, k = _quarter(ta)
    su, cu = _quarter(tu)
    sv, cv = _quarter(tv)
    suv, cuv = su * cv + cu * sv, cu * cv - su * sv
    sw, cw = s * cuv - k * suv, k * cuv + s * suv
    return {"kappa": k, "sigma": s * s, "S": (su / s, sv / s, sw / s), "C": (cu, cv, cw)}


def identities_hold(points=POINTS) -> bool:
    """(I) ``C_x = kappa S_x + S_y C_z + C_y S_z`` and (II) ``C_y C_z = sigma S_y S_z + kappa C_x + sigma S_x`` for
    every permutation (x, y, z) of (u, v, w), exactly at the points."""
    for pt in points:
        p = half_angle_point(*pt)
        k, s2, S, C = p["kappa"], p["sigma"], p["S"], p["C"]
        for x in range(3):
            for y in range(3):
                if x == y:
                    continue
                z = 3 - x - y
                if C[x] != k * S[x] + S[y] * C[z] + C[y] * S[z]:
                    return False
                if C[y] * C[z] != s2 * S[y] * S[z] + k * C[x] + s2 * S[x]:
                    return False
    return True


def _monomial(p: dict, e) -> fmpq:
    out = fmpq(1)
    for x in range(3):
        out *= p["S"][x] ** int(e[2 * x]) * p["C"][x] ** int(e[2 * x + 1])
    return out


def _terms_value(p: dict, n: int, terms) -> fmpq:
    e = exponent_matrix(n)
    return sum((int(c) * p["kappa"] ** int(a) * p["sigma"] ** int(b) * _monomial(p, e[int(t)])
                for a, b, c, t in terms), fmpq(0))


def rules_hold(n: int, points=POINTS[:2]) -> dict:
    """Each cotangent ``(C_x/S_x) m_g`` of :func:`~paper_repro.core.half_angle_rules.cotangent` (rules A, A_n, B and
    the cosine variable's rule), for every member g of T_{2n} and every variable x with a factor S_x, against the
    product of the half-angle values, exactly at the points: ``{"checked": k, "fails": [(x, g), ...], "ok"}``."""
    from paper_repro.core.half_angle_rules import cotangent

    pts = [half_angle_point(*pt) for pt in points]
    e = exponent_matrix(check_n(n))
    fails, checked = [], 0
    for g in range(delta(n)):
        for x in range(3):
            if not e[g, 2 * x]:
                continue
            terms = cotangent(n, x, g)
            for p in pts:
                checked += 1
                if p["C"][x] / p["S"][x] * _monomial(p, e[g]) != _terms_value(p, n, terms):
                    fails.append((x, g))
                    break
    return {"n": n, "checked": checked, "fails": fails, "ok": not fails}


def _dense(form, shape, alpha: RationalAngle, ctx) -> np.ndarray:
    kappa, s = ctx.from_rational(alpha.cos_half), ctx.from_rational(alpha.sin_half)
    rows, cols, vals = evaluate_terms(form, kappa, ctx.mul(s, s), ctx)
    out = ctx.zeros(shape)
    out[rows, cols] = vals
    return out


def _sparse_matmul_mod(a: np.ndarray, b: np.ndarray, p: int) -> np.ndarray:
    """``a @ b mod p`` for a sparse ``b`` (entries of both in [0, p), p < 2^31), one nonzero of ``b`` at a time:
    the same int64 array as :func:`~paper_repro.theory.modular._matmul_mod` (each step below 2^62 before its
    reduction).

    >>> _sparse_matmul_mod(np.array([[1, 2], [3, 4]]), np.array([[0, 5], [6, 0]]), 7).tolist()
    [[5, 5], [3, 1]]
    """
    rows, cols = np.nonzero(b)
    out = np.zeros((a.shape[0], b.shape[1]), dtype=np.int64)
    a = np.asarray(a, dtype=np.int64)
    for r, c, v in zip(rows.tolist(), cols.tolist(), np.asarray(b)[rows, cols].tolist()):
        out[:, c] = (out[:, c] + a[:, r] * int(v)) % p
    return out


def identity_check(kind: str, n: int, alpha: RationalAngle, form, *, arith: str | Context = "exact", extra: int = 3,
                   seed: int = 5, h: int | None = None) -> dict:
    """The identity of ``kind`` ('M': elevation n -> n + 1; 'C': derivative along u; 'P': the product with the
    member ``h`` of T_2, ``m_f m_h = sum_g P[g, f] m'_g``) for the merged ``form`` at
    ``delta + extra`` rational points, exactly over Q (``arith='exact'``) or over F_p (``'modp'``, p =
    :data:`PRIME`: the exact image, much faster; evidence for the identity over Q, not a proof of it); ``ok`` when it
    holds at every point and the points are unisolvent for the target system (rank over F_p, a lower bound of the
    rank over Q)."""
    n = check_n(n)
    if kind not in ("M", "C", "P"):
        raise ValueError(f"kind must be 'M' (elevation), 'C' (derivative) or 'P' (product), got {kind!r}")
    if (kind == "P") != (h is not None):
        raise ValueError("h (a member of T_2) is given exactly for kind 'P'")
    mod = ModpContext(p=PRIME)
    ctx = get_context(arith, p=PRIME)
    if not isinstance(ctx, (ExactContext, ModpContext)):
        raise ValueError(f"arith must be 'exact' or 'modp' (or such a context), got {arith!r}")
    if not isinstance(alpha, RationalAngle):
        raise TypeError(f"alpha must be a RationalAngle, got {type(alpha).__name__}")
    target = n if kind == "C" else n + 1
    count = delta(target) + extra
    tu, tv = fixed_points(target, count, seed)
    pts = RationalPoints(None, tu, tv, check=False)

    def values(c):
        trig = scaled_half_angle_values(pts, alpha, c)
        with c.scope():
            big = monomials(exponent_matrix(target), trig, c)
            if kind == "M":
                return big, monomials(exponent_matrix(n), trig, c)
            if kind == "P":  # the product's monomial: the exponents of m_f and m_h added
                return big, monomials(exponent_matrix(n) + exponent_matrix(1)[h], trig, c)
            s = c.from_rational(alpha.sin_half)
            return big, monomial_derivative(exponent_matrix(n), trig, (1, 0, -1), c, s2=c.mul(s, s))

    big, lhs = values(ctx)
    mat = _dense(form, (delta(target), delta(n)), alpha, ctx)
    if isinstance(ctx, ExactContext):
        holds = to_fmpq_mat(big) * to_fmpq_mat(mat) == to_fmpq_mat(lhs)
        big_p = values(mod)[0]
    else:
        holds = bool(np.array_equal(_sparse_matmul_mod(big, mat, ctx.p), lhs % ctx.p))
        big_p = big
    rank = mod.rank(big_p)
    return {"kind": kind, "n": n, "h": h, "t": str(alpha.t), "arith": ctx.name, "points": count, "holds": bool(holds),
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
    (:func:`~paper_repro.theory.derivative_matrix.table`, n <= 10) when ``recovered`` is None."""
    if recovered is None:
        from paper_repro.theory.derivative_matrix import table

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


def product_sum_is_elevation(n: int, alpha: RationalAngle, forms) -> bool:
    """``sum_h x_h P_h = M`` exactly at ``alpha`` (x_h the scaled normalizing coefficients of T_2): the products
    with the first-order partition of unity give back the elevation (``forms[h]`` the merged form of P_h)."""
    from paper_repro.core.half_angle_matrices import elevation_form, half_angle, scaled_coefficients

    ctx = ExactContext()
    kappa, sigma = half_angle(alpha, ctx)
    x1 = scaled_coefficients(1, kappa, sigma, ctx)
    total = ctx.zeros((delta(n + 1), delta(n)))
    for h, form in enumerate(forms):
        total = total + x1[h] * _dense(form, (delta(n + 1), delta(n)), alpha, ctx)
    return total.tolist() == _dense(elevation_form(n), (delta(n + 1), delta(n)), alpha, ctx).tolist()


def products_equivariant(n: int, forms) -> bool:
    """Symmetry: for each exchange pi of two variables (a permutation of the members of every order,
    :func:`~paper_repro.core.labels.variable_swap`), ``P_{pi h}[pi g, pi f] = P_h[g, f]`` as integer forms
    (``forms[h]`` the merged form of P_h)."""
    from paper_repro.core.labels import variable_swap

    def as_set(form, rows=None, cols=None) -> set:
        r, c, a, b, coef = (np.asarray(v) for v in form)
        if rows is not None:
            r, c = rows[r], cols[c]
        return set(zip(r.tolist(), c.tolist(), a.tolist(), b.tolist(), coef.tolist()))

    for sa, sb in ((0, 1), (1, 2), (0, 2)):
        p1, pn, pbig = variable_swap(1, sa, sb), variable_swap(n, sa, sb), variable_swap(n + 1, sa, sb)
        for h, form in enumerate(forms):
            if as_set(forms[int(p1[h])]) != as_set(form, pbig, pn):
                return False
    return True


def lowering_lemma(n: int) -> dict:
    """The lemma behind the products' route: for every member g of T_{2n} and variable x with ``S_x^e`` in m_g,
    e >= 1, every member in the rule's expansion of ``L_x m_g`` has a factor ``S_x^(e - 1)`` at least."""
    from paper_repro.core.half_angle_rules import cotangent

    e = exponent_matrix(check_n(n))
    fails = [(g, x) for g in range(delta(n)) for x in range(3) if e[g, 2 * x]
             and any(int(e[int(t), 2 * x]) < int(e[g, 2 * x]) - 1 for t in cotangent(n, x, g)[:, 3])]
    return {"n": n, "fails": fails, "ok": not fails}


def derivative_rule_terms(n: int) -> int:
    """Most rule terms in one column of C: for the member f with exponents p_x of S_x and q_x of C_x, the column is
    p_u L_u m_f - q_u sigma (S_u/C_u) m_f - p_w L_w m_f + q_w sigma (S_w/C_w) m_f, one rule term per non-zero
    exponent (docs/elevation_and_derivative_for_all_n.md).  A member has a cosine factor in at most one variable,
    so at most 3 of the 4 are present; this counts them from the exponent vectors of T_{2n}.

    >>> [derivative_rule_terms(n) for n in (1, 2, 3)]
    [2, 3, 3]
    """
    e = exponent_matrix(check_n(n))
    return int(max(sum(1 for k in (0, 1, 4, 5) if row[k]) for row in e))


def cotangent_applications(n: int) -> int:
    """Most applications of a cotangent rule ``L_y`` (each applied term by term) that the construction of Theorem P
    (:func:`paper_repro.core.half_angle_rules.product_column`) makes for one product m_f m_h, over the members f of
    T_{2n} and h of T_2: counted by instrumenting the construction itself (the applications of the rule function
    during each product; the edges take one, the corner S_Y^2 with j < m takes m - j <= n).

    >>> [cotangent_applications(n) for n in (1, 2, 3)]
    [1, 2, 3]
    """
    from paper_repro.core import half_angle_rules as rules

    check_n(n)
    original = rules._apply_cotangent
    calls = [0]

    def counting(*args, **kw):
        calls[0] += 1
        return original(*args, **kw)

    most = 0
    rules._apply_cotangent = counting
    try:
        for h in range(delta(1)):
            for f in range(delta(n)):
                calls[0] = 0
                rules.product_column(n, h, f)
                most = max(most, calls[0])
    finally:
        rules._apply_cotangent = original
    return most
