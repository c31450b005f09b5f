"""The basis transformation between V_n and T_{2n} for every n (Question 7.2, que:open_problem_basis_transformation).

V_n^alpha is the Fourier system of :mod:`paper_repro.core.fourier` (1 and cos, sin(ru + gv + bw) of the representatives
of Proposition iterative_construction_of_trivariate_extension), T_{2n}^alpha the joint system of eq. united_system
(:mod:`paper_repro.core.labels`) and T-bar its normalized form (eq. normalized_united_system, with the normalizing
coefficients x_f of Theorem B, :mod:`paper_repro.core.normalizing_formula`).  Both span the same space (Theorem A of
docs/question1_for_all_n.md), and docs/transformation_for_all_n.md proves, for every n >= 1 and alpha in (0, pi):

**V in terms of T** (the generating function).  For phi = (a, b, d) with |a - b|, |a - d|, |b - d| <= n write
g_phi = exp(i(au + bv + dw)) = sum_f theta_f f over the *unnormalized* members f, and let

    Gamma_phi(t, W) = zeta^{2b} A^{n+a-b} Abar^{n-a+b} (1 + Abar W)^{n+a-d} (1 + A W)^{n-a+d} / (1 - ct)^{2n},

with s = sin(alpha/2), c = cos(alpha/2), zeta = c + is, A = c + s^2 t + is(1 - ct), Abar its conjugate.  Then

* R_{2n,2n-k,j}, 0 <= j < k <= n:     s^{2n+j} theta = [t^j W^k] Gamma_(a,b,d);
* the mirror R_{2n,k,j}, j < k < n:   s^{2n+j} theta = [t^j W^k] Gamma_(d,b,a);
* the diagonal R_{2n,2n-k,k}, k < n:  s^{2n+k} theta = [t^k] ([W^k] Gamma_(a,b,d) - ct/(1-ct) [W^k] Gamma_(a,d,b));
* the centre R_{2n,n,n}:              s^{3n} theta = [t^n] ([W^n] Gamma_(a,b,d)
                                                            - ct/(1-ct) ([W^n] Gamma_(a,d,b) + [W^n] Gamma_(d,a,b)));
* G members: the R rule at (d, a, b); B members: the R rule at (b, d, a).

cos and sin of au + bv + dw take the real and imaginary parts.  At phi = 0 this is Theorem B.

**T in terms of V** (the binomial expansion).  sin(x/2) = (X - 1/X)/(2i), cos(x/2) = (X + 1/X)/2 with X = e^{ix/2}
turn a member into a sum of exp(i(e_u u + e_v v + e_w w)/2); on u + v + w = alpha such a term is
zeta^{e_w - 2 sigma rho_w} exp(i sigma (rho_u u + rho_v v + rho_w w)) for the unique representative rho of V_n and
sign sigma with (e_u - e_w, e_v - e_w)/2 = sigma (rho_u - rho_w, rho_v - rho_w).

The matrices (:func:`transformation_matrix`): rows and columns in the package's orders -- T-bar (or T) in the internal
order of :func:`~paper_repro.core.labels.united_system`, V_n in the order of :func:`~paper_repro.core.fourier.v_system`
(labels :func:`~paper_repro.core.fourier.v_labels`):

* ``'V_to_T'``: M with V_n = T-bar M; column v holds the coefficients of the v-th function of V_n in T-bar, and
  ``M @ a`` turns the coefficients ``a`` of a function in V_n into its control coefficients in T-bar;
* ``'T_to_V'``: M^{-1} with T-bar = V_n M^{-1}; column f holds T-bar_f in V_n, and ``M^{-1} @ net`` turns a control
  net into the Fourier coefficients of the patch.

With ``normalized=False`` the same for the unnormalized T_{2n}: V_n = T N^{-1} and T = V_n N, so M = diag(x)^{-1} N^{-1}
and M^{-1} = N diag(x).  Everything is computed through a context (:mod:`paper_repro.core.context`), with complex
numbers as pairs of real ones, sums in a fixed order and no BLAS: exact (flint ``fmpq``) at a
:class:`~paper_repro.core.domain.RationalAngle`, float64 otherwise, with s and c taken from flint ``arb`` (correctly
rounded, not libm), so the float result is bit-for-bit the same on every machine.

At n = 1, tan(alpha/4) = 1/2 (s = 4/5, c = 3/5), cos(w) in T-bar has the coefficients 1, 1, 1, -7/25, 1, 1, 1 (the
column the exact collocation solve of claim ``basis_transformation`` published in
``data/basis_transformation/n1.json``):

>>> from paper_repro.core.domain import rational_alpha
>>> m = transformation_matrix(1, rational_alpha("1/2"), "V_to_T")
>>> [str(x) for x in m[:, 1]]
['1', '1', '1', '-7/25', '1', '1', '1']
>>> [str(x) for x in (transformation_matrix(1, rational_alpha("1/2"), "T_to_V") @ m)[:, 1]]
['0', '1', '0', '0', '0', '0', '0']
"""

from __future__ import annotations

from functools import cache
from math import comb

import numpy as np
from flint import arb, fmpq

from paper_repro.core.context import Context, FloatContext, get_context
from paper_repro.core.domain import RationalAngle
from paper_repro.core.fourier import v_system
from paper_repro.core.labels import delta, exponent_matrix, united_system
from paper_repro.core.normalization import orbits
from paper_repro.core.normalizing_formula import scaled_table
from paper_repro.util.limits import MAX_N_TRANSFORMATION, check_int
from paper_repro.util.validation import check_alpha, parse_alpha

DIRECTIONS = ("V_to_T", "T_to_V")

Pair = tuple  # (real part, imaginary part), each a scalar or array of the context

#: Permutations of phi = (a, b, d) as index maps, psi = (phi[p0], phi[p1], phi[p2]).  The R rule at p uses p, its
#: mirror (p2, p1, p0), the diagonal correction (p0, p2, p1) and the centre's second correction (p2, p0, p1); the G
#: rule is the R rule at (d, a, b) and the B rule at (b, d, a).
PERMUTATIONS = ((0, 1, 2), (2, 1, 0), (0, 2, 1), (2, 0, 1), (1, 0, 2), (1, 2, 0))
_BASE = {"R": (0, 1, 2), "G": (2, 0, 1), "B": (1, 2, 0)}


def _compose(p: tuple[int, int, int], q: tuple[int, int, int]) -> tuple[int, int, int]:
    """The index map of psi -> (psi[q0], psi[q1], psi[q2]) applied after phi -> (phi[p0], phi[p1], phi[p2])."""
    return (p[q[0]], p[q[1]], p[q[2]])


_MIRROR, _CORR, _EXTRA = (2, 1, 0), (0, 2, 1), (2, 0, 1)


# --- complex arithmetic on pairs -------------------------------------------------------------------------------
def _cmul(ctx: Context, x: Pair, y: Pair) -> Pair:
    return (ctx.sub(ctx.mul(x[0], y[0]), ctx.mul(x[1], y[1])), ctx.add(ctx.mul(x[0], y[1]), ctx.mul(x[1], y[0])))


def _rscale(ctx: Context, k, x: Pair) -> Pair:
    """A real ``k`` times a complex ``x``."""
    return (ctx.mul(k, x[0]), ctx.mul(k, x[1]))


def _scalar(ctx: Context, x):
    """A scalar of the context as a 0-d array (numpy then broadcasts it as one element in every arithmetic)."""
    out = ctx.zeros(())
    out[()] = x
    return out


def _item(x):
    """A 0-d array as its element (operations on 0-d object arrays already return elements)."""
    return x[()] if isinstance(x, np.ndarray) and x.ndim == 0 else x


def _int(ctx: Context, k: int):
    return _scalar(ctx, ctx.from_rational(fmpq(k)))


def _zeta_powers(ctx: Context, s, c, top: int) -> dict[int, Pair]:
    """zeta^m = (c + is)^m for |m| <= top (negative m: the conjugate)."""
    out = {0: (_int(ctx, 1), _int(ctx, 0))}
    for m in range(1, top + 1):
        out[m] = _cmul(ctx, out[m - 1], (c, s))
    for m in range(1, top + 1):
        out[-m] = (out[m][0], ctx.sub(_int(ctx, 0), out[m][1]))
    return out


# --- the half-angle values of alpha -------------------------------------------------------------------------------
def half_angle(alpha, ctx: Context) -> tuple:
    """``(s, c)`` = sin, cos(alpha/2) as 0-d arrays of ``ctx``: exact at a RationalAngle; in float from flint arb at
    128 bits, rounded once (the same bits on every machine, unlike libm); otherwise the context's own sin/cos."""
    if isinstance(alpha, RationalAngle):
        return _scalar(ctx, ctx.from_rational(alpha.sin_half)), _scalar(ctx, ctx.from_rational(alpha.cos_half))
    if type(ctx) is FloatContext:
        from flint import ctx as flint_ctx

        old = flint_ctx.prec
        flint_ctx.prec = 128
        try:
            half = arb(float(alpha)) / 2
            s, c = float(half.sin().mid()), float(half.cos().mid())
        finally:
            flint_ctx.prec = old
        return _scalar(ctx, s), _scalar(ctx, c)
    s, c = ctx.alpha_half(alpha)
    return _scalar(ctx, s), _scalar(ctx, c)


# --- V in terms of T: the generating function --------------------------------------------------------------------
@cache
def _phis(n: int) -> tuple[tuple[int, int, int], ...]:
    """The frequencies phi of V_n's columns: (0, 0, 0) and the representatives, in v_system order, each once."""
    out: list[tuple[int, int, int]] = []
    for _, rep in v_system(n):
        if rep not in out:
            out.append(rep)
    return tuple(out)


@cache
def _psi_table(n: int) -> tuple[tuple[tuple[int, int, int], ...], np.ndarray]:
    """The distinct permuted frequencies psi and ``index[phi, perm]`` (perm in :data:`PERMUTATIONS`)."""
    psis: dict[tuple[int, int, int], int] = {}
    index = np.zeros((len(_phis(n)), len(PERMUTATIONS)), dtype=np.int64)
    for r, phi in enumerate(_phis(n)):
        for q, p in enumerate(PERMUTATIONS):
            psi = (phi[p[0]], phi[p[1]], phi[p[2]])
            index[r, q] = psis.setdefault(psi, len(psis))
    return tuple(psis), index


def gamma_coefficients(n: int, psis, s, c, ctx: Context) -> Pair:
    """``[t^j W^k] Gamma_psi`` for every psi of ``psis`` and 0 <= j, k <= n: a pair of ``(len(psis), n+1, n+1)`` arrays
    indexed ``[psi, k, j]``.

    [W^k] Gamma_psi = zeta^{2b} sum_l binom(n+a-d, l) binom(n-a+d, k-l) A^{n+a-b+k-l} Abar^{n-a+b+l} / (1-ct)^{2n};
    the table U[e1, e2] = A^{e1} Abar^{e2} / (1 - ct)^{2n} (truncated after t^n, e1, e2 <= 3n) is built once."""
    top = 3 * n
    s2 = ctx.mul(s, s)
    zero = _int(ctx, 0)
    a_lin = ((c, s), (s2, ctx.sub(zero, ctx.mul(s, c))))            # A = (c + is) + (s^2 - isc) t
    abar_lin = ((c, ctx.sub(zero, s)), (s2, ctx.mul(s, c)))          # its conjugate

    def times_linear(x: Pair, lin) -> Pair:
        head = _cmul(ctx, x, lin[0])
        tail = _cmul(ctx, (x[0][..., :-1], x[1][..., :-1]), lin[1])
        re, im = head[0].copy(), head[1].copy()
        re[..., 1:] = ctx.add(re[..., 1:], tail[0])
        im[..., 1:] = ctx.add(im[..., 1:], tail[1])
        return re, im

    # row e1 = 0: Abar^{e2}
    re = ctx.zeros((top + 1, top + 1, n + 1))
    im = ctx.zeros((top + 1, top + 1, n + 1))
    cur = (ctx.zeros((n + 1,)), ctx.zeros((n + 1,)))
    cur[0][0] = ctx.from_rational(fmpq(1))
    for e2 in range(top + 1):
        re[0, e2], im[0, e2] = cur
        cur = times_linear(cur, abar_lin)
    for e1 in range(1, top + 1):
        re[e1], im[e1] = times_linear((re[e1 - 1], im[e1 - 1]), a_lin)
    # divide by (1 - ct)^{2n}: convolve with w_j = binom(2n-1+j, j) c^j (fixed order, j' ascending)
    weights = [ctx.mul(_int(ctx, comb(2 * n - 1 + j, j)), _pow(ctx, c, j)) for j in range(n + 1)]
    u_re, u_im = ctx.zeros(re.shape), ctx.zeros(im.shape)
    for j in range(n + 1):
        acc_re, acc_im = ctx.zeros(re.shape[:2]), ctx.zeros(re.shape[:2])
        for jp in range(j + 1):
            acc_re = ctx.add(acc_re, ctx.mul(weights[j - jp], re[..., jp]))
            acc_im = ctx.add(acc_im, ctx.mul(weights[j - jp], im[..., jp]))
        u_re[..., j], u_im[..., j] = acc_re, acc_im
    arr = np.array(psis, dtype=np.int64).reshape(-1, 3)
    a, b, d = arr[:, 0], arr[:, 1], arr[:, 2]
    q_exp, p_exp = n + a - d, n - a + d
    binom = ctx.zeros((2 * n + 1, n + 1))
    for m in range(2 * n + 1):
        for ell in range(min(m, n) + 1):
            binom[m, ell] = ctx.from_rational(fmpq(comb(m, ell)))
    out_re = ctx.zeros((len(arr), n + 1, n + 1))
    out_im = ctx.zeros((len(arr), n + 1, n + 1))
    for k in range(n + 1):
        acc_re, acc_im = ctx.zeros((len(arr), n + 1)), ctx.zeros((len(arr), n + 1))
        for ell in range(k + 1):
            coef = ctx.mul(binom[q_exp, ell], binom[p_exp, k - ell])
            e1, e2 = n + a - b + k - ell, n - a + b + ell
            acc_re = ctx.add(acc_re, ctx.mul(coef[:, None], u_re[e1, e2]))
            acc_im = ctx.add(acc_im, ctx.mul(coef[:, None], u_im[e1, e2]))
        out_re[:, k], out_im[:, k] = acc_re, acc_im
    zeta = _zeta_powers(ctx, s, c, 2 * n)
    z_re = ctx.zeros((len(arr),))
    z_im = ctx.zeros((len(arr),))
    for r, bb in enumerate(b):
        z_re[r], z_im[r] = _item(zeta[2 * int(bb)][0]), _item(zeta[2 * int(bb)][1])
    return _cmul(ctx, (z_re[:, None, None], z_im[:, None, None]), (out_re, out_im))


def _pow(ctx: Context, x, k: int):
    out = _int(ctx, 1)
    for _ in range(k):
        out = ctx.mul(out, x)
    return out


@cache
def _member_rules(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[tuple[int, int, int, int]]]:
    """For each member of T_{2n}: the permutation index, W power k and t power j of its plain rule (mirrors
    included); and the diagonal members and the centre as (member, base perm, correction perm, extra perm or -1)."""
    perm_index = {p: q for q, p in enumerate(PERMUTATIONS)}
    perm, kk, jj, special = [], [], [], []
    for f, lab in enumerate(united_system(n)):
        base = _BASE[lab.color]
        if lab.i > n:
            perm.append(perm_index[_compose(base, _MIRROR)])
            kk.append(2 * n - lab.i)
        else:
            perm.append(perm_index[base])
            kk.append(lab.i)
        jj.append(lab.j)
        if lab.i == lab.j:
            extra = perm_index[_compose(base, _EXTRA)] if lab.j == n else -1
            special.append((f, perm_index[base], perm_index[_compose(base, _CORR)], extra))
    return np.array(perm), np.array(kk), np.array(jj), special


def scaled_theta(n: int, s, c, ctx: Context) -> Pair:
    """``s^{2n+j} theta_f`` for every member f (rows, internal order) and every phi of V_n's columns (``_phis``):
    a pair of ``(delta_n, len(_phis(n)))`` arrays."""
    psis, index = _psi_table(n)
    g_re, g_im = gamma_coefficients(n, psis, s, c, ctx)
    perm, kk, jj, special = _member_rules(n)
    rows = index[:, perm].T  # (delta_n, phis): the psi of each member's plain rule
    th_re = g_re[rows, kk[:, None], jj[:, None]]
    th_im = g_im[rows, kk[:, None], jj[:, None]]
    for f, base, corr, extra in special:
        k = int(jj[f])
        val_re, val_im = g_re[index[:, base], k, k], g_im[index[:, base], k, k]
        for ell in range(1, k + 1):
            c_l = _pow(ctx, c, ell)
            sub_re, sub_im = g_re[index[:, corr], k, k - ell], g_im[index[:, corr], k, k - ell]
            if extra >= 0:
                sub_re = ctx.add(sub_re, g_re[index[:, extra], k, k - ell])
                sub_im = ctx.add(sub_im, g_im[index[:, extra], k, k - ell])
            val_re = ctx.sub(val_re, ctx.mul(c_l, sub_re))
            val_im = ctx.sub(val_im, ctx.mul(c_l, sub_im))
        th_re[f], th_im[f] = val_re, val_im
    return th_re, th_im


def v_columns(n: int, th: Pair, ctx: Context) -> np.ndarray:
    """The real matrix whose column v is Re (1, cos) or Im (sin) of the column of phi(v)."""
    where = {phi: r for r, phi in enumerate(_phis(n))}
    out = ctx.zeros((th[0].shape[0], delta(n)))
    for col, (kind, rep) in enumerate(v_system(n)):
        out[:, col] = th[1 if kind == "sin" else 0][:, where[rep]]
    return out


# --- T in terms of V: the binomial expansion ---------------------------------------------------------------------
@cache
def _half_angle_expansion(a: int, b: int) -> tuple[fmpq, ...]:
    """Real coefficients r_e (e = -(a+b), -(a+b)+2, ..., a+b) with sin^a(x/2) cos^b(x/2) = (-i)^a sum_e r_e X^e,
    X = e^{ix/2}: the coefficients of (X - 1/X)^a (X + 1/X)^b / 2^{a+b}."""
    top = a + b
    poly = [0] * (2 * top + 1)  # poly[e + top] = coefficient of X^e
    poly[top] = 1
    for sign in [-1] * a + [1] * b:  # multiply by X + sign / X
        new = [0] * (2 * top + 1)
        for e in range(-top, top + 1):
            x = poly[e + top]
            if x:
                new[e + 1 + top] += x
                new[e - 1 + top] += sign * x
        poly = new
    poly = poly[::2]  # the exponents -top, -top + 2, ..., top
    return tuple(fmpq(x, 2 ** (a + b)) for x in poly)


@cache
def _v_cells(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """For each V_n column: the grid cell (p, q) + n of sign +1 and of sign -1, rho_w, and whether it is a sin
    column; for '1' both cells are (n, n)."""
    plus_p, plus_q, minus_p, minus_q, rho_w, is_sin = [], [], [], [], [], []
    for kind, rep in v_system(n):
        p, q = rep[0] - rep[2], rep[1] - rep[2]
        plus_p.append(p + n)
        plus_q.append(q + n)
        minus_p.append(-p + n)
        minus_q.append(-q + n)
        rho_w.append(rep[2])
        is_sin.append(kind == "sin")
    return (np.array(plus_p), np.array(plus_q), np.array(minus_p), np.array(minus_q),
            np.array([rho_w, is_sin], dtype=np.int64))


@cache
def _degree_groups(n: int) -> tuple[tuple[tuple[int, int, int], np.ndarray], ...]:
    """The members of T_{2n} grouped by their degrees (d_u, d_v, d_w) in the three variables (about 6n groups)."""
    groups: dict[tuple[int, int, int], list[int]] = {}
    for f, ex in enumerate(exponent_matrix(n)):
        key = (int(ex[0] + ex[1]), int(ex[2] + ex[3]), int(ex[4] + ex[5]))
        groups.setdefault(key, []).append(f)
    return tuple((key, np.array(members)) for key, members in sorted(groups.items()))


def expansion_matrix(n: int, s, c, ctx: Context) -> np.ndarray:
    """N with T = V_n N: column f holds the member f of T_{2n} in V_n (binomial expansion, see the module docstring).

    For each member the coefficients of exp(i(pu + qv)) are gathered on the grid |p|, |q| <= n:
    G[p, q] = (-i)^{a_u+a_v+a_w} sum_{e_w} r^w_{e_w} zeta^{e_w} r^u_{2p+e_w} r^v_{2q+e_w} (e_w ascending); then column
    v of V_n receives Re(G[+] zeta^{-2 rho_w}) + Re(G[-] zeta^{2 rho_w}) (1, cos) or
    -Im(G[+] zeta^{-2 rho_w}) + Im(G[-] zeta^{2 rho_w}) (sin), G[+-] at +-(rho_u - rho_w, rho_v - rho_w).  Members
    with the same degrees are processed together."""
    d = delta(n)
    zeta = _zeta_powers(ctx, s, c, 3 * n)
    plus_p, plus_q, minus_p, minus_q, extra = _v_cells(n)
    rho_w, is_sin = extra[0], extra[1].astype(bool)
    zp_re, zp_im = ctx.zeros((d,)), ctx.zeros((d,))
    zm_re, zm_im = ctx.zeros((d,)), ctx.zeros((d,))
    for col, rw in enumerate(rho_w):
        zp_re[col], zp_im[col] = _item(zeta[-2 * int(rw)][0]), _item(zeta[-2 * int(rw)][1])
        zm_re[col], zm_im[col] = _item(zeta[2 * int(rw)][0]), _item(zeta[2 * int(rw)][1])
    exps = exponent_matrix(n)
    out = ctx.zeros((d, d))
    size = 2 * n + 1

    def coefficients(members: np.ndarray, slot: int, degree: int) -> np.ndarray:
        arr = ctx.zeros((len(members), degree + 1))
        for r, f in enumerate(members):
            a = int(exps[f, 2 * slot])
            for e, x in enumerate(_half_angle_expansion(a, degree - a)):
                arr[r, e] = ctx.from_rational(x)
        return arr

    for (du, dv, dw), members in _degree_groups(n):
        ru, rv, rw = coefficients(members, 0, du), coefficients(members, 1, dv), coefficients(members, 2, dw)
        outer = ctx.mul(ru[:, :, None], rv[:, None, :])
        g_re = ctx.zeros((len(members), size, size))
        g_im = ctx.zeros((len(members), size, size))
        for iw in range(dw + 1):
            ew = 2 * iw - dw
            k_re = ctx.mul(rw[:, iw], zeta[ew][0])[:, None, None]
            k_im = ctx.mul(rw[:, iw], zeta[ew][1])[:, None, None]
            p0, q0 = (-du - ew) // 2 + n, (-dv - ew) // 2 + n
            block = (slice(None), slice(p0, p0 + du + 1), slice(q0, q0 + dv + 1))
            g_re[block] = ctx.add(g_re[block], ctx.mul(k_re, outer))
            g_im[block] = ctx.add(g_im[block], ctx.mul(k_im, outer))
        turn = (exps[members, 0] + exps[members, 2] + exps[members, 4]) % 4  # multiply by (-i)^turn
        zero = ctx.zeros(g_re.shape)
        neg_re, neg_im = ctx.sub(zero, g_re), ctx.sub(zero, g_im)
        x_re, x_im = g_re.copy(), g_im.copy()
        for t, (new_re, new_im) in ((1, (g_im, neg_re)), (2, (neg_re, neg_im)), (3, (neg_im, g_re))):
            x_re[turn == t], x_im[turn == t] = new_re[turn == t], new_im[turn == t]
        plus = _cmul(ctx, (x_re[:, plus_p, plus_q], x_im[:, plus_p, plus_q]), (zp_re, zp_im))
        minus = _cmul(ctx, (x_re[:, minus_p, minus_q], x_im[:, minus_p, minus_q]), (zm_re, zm_im))
        cols = ctx.add(plus[0], minus[0])
        cols[:, is_sin] = ctx.sub(minus[1], plus[1])[:, is_sin]
        cols[:, 0] = x_re[:, n, n]  # the constant 1: its two cells coincide at (0, 0), counted once
        out[:, members] = cols.T
    return out


# --- normalization and the public function ----------------------------------------------------------------------
def scaled_normalizing(n: int, s, c, ctx: Context) -> np.ndarray:
    """``s^{2n+j} x_f`` of every member (internal order), Theorem B (:func:`scaled_table`)."""
    table = scaled_table(n, _item(c), _item(ctx.mul(s, s)), ctx)
    out = ctx.zeros((delta(n),))
    for (_, members), x in zip(orbits(n), table):
        for k in members:
            out[k] = x
    return out


def _inverse_sin_powers(n: int, s, ctx: Context) -> np.ndarray:
    """``1 / s^{2n+j}`` of every member (internal order), as products of 1/s (no intermediate underflow)."""
    inv = ctx.div(_int(ctx, 1), s)
    powers = {e: _pow(ctx, inv, e) for e in range(2 * n, 3 * n + 1)}
    out = ctx.zeros((delta(n),))
    for f, lab in enumerate(united_system(n)):
        out[f] = _item(powers[2 * n + lab.j])
    return out


def transformation_in_context(n: int, s, c, ctx: Context, direction: str, normalized: bool = True) -> np.ndarray:
    """The matrix of :func:`transformation_matrix` from ``s``, ``c`` given as 0-d arrays of ``ctx`` (no checks)."""
    with ctx.scope():
        if direction == "V_to_T":
            th = v_columns(n, scaled_theta(n, s, c, ctx), ctx)
            scale = (ctx.div(_int(ctx, 1), scaled_normalizing(n, s, c, ctx)) if normalized
                     else _inverse_sin_powers(n, s, ctx))
            return ctx.mul(th, scale[:, None])
        big_n = expansion_matrix(n, s, c, ctx)
        if not normalized:
            return big_n
        return ctx.mul(big_n, ctx.mul(scaled_normalizing(n, s, c, ctx), _inverse_sin_powers(n, s, ctx))[None, :])


#: The float matrices lose digits: 'V_to_T' to cancellation as alpha -> 0 (about eps / alpha^2) and, in both
#: directions, geometrically in n (about 1.6^n eps; 'V_to_T' most near alpha = pi, 'T_to_V' at small alpha).  Measured
#: for n <= 30 and alpha in [1e-300, pi - 1e-12] (``tools/transformation_accuracy.py`` -> ``reports/
#: transformation_accuracy.md``; the reference: mp for n <= 10, double-double beyond), the largest error relative to
#: the largest entry stays below :func:`v_to_t_float_bound` / :func:`t_to_v_float_bound`.  Float 'V_to_T' results
#: whose bound exceeds :data:`FLOAT_REL_GOAL` are refused.
FLOAT_REL_GOAL = 1e-8
_EPS = 2.0**-52


def _growth(n: int, rate: float, divisor: float, linear: int) -> float:
    """``max(linear, rate^n / divisor)``: the n-dependence of the float bounds (a measured geometric growth)."""
    return max(float(linear), rate**n / divisor)


def v_to_t_float_bound(n: int, alpha: float) -> float:
    """Bound of the relative error (to the largest entry) of the float 'V_to_T' matrix:
    ``eps ((12 n + 8) / alpha^2 + max(12 n + 8, 1.7^n / 3))``, a measured bound.

    The first term is the cancellation as alpha -> 0 (measured at most 120 eps / alpha^2 up to n = 30); the second
    the growth in n at large alpha (measured 126, 518, 6375 eps at n = 12, 15, 20 near alpha = 3.1, about 1.65^n).
    Until this bound, ``(12 n + 8) eps (1 + 1/alpha^2)`` (set from n <= 10) was exceeded 2.4 times at n = 15,
    alpha = 3 and 4.8 times at n = 20.  The form was fitted on n <= 20; n = 25 and 30 are out of sample.

    >>> v_to_t_float_bound(3, 1.0) < 1e-13, v_to_t_float_bound(3, 1e-4) > 1e-8, v_to_t_float_bound(3, 1e-300)
    (True, True, inf)
    >>> round(v_to_t_float_bound(20, 3.0) / 2.0**-52)
    13575
    """
    n = check_int(n, "n", 1, MAX_N_TRANSFORMATION, why="the bound is measured up to n = 30")
    alpha = check_alpha(alpha)
    inv = 1.0 / alpha  # not 1 / alpha^2: alpha^2 underflows to 0 below alpha = 1.5e-162 (then the bound is inf)
    return _EPS * ((12 * n + 8) * inv * inv + _growth(n, 1.7, 3.0, 12 * n + 8))


def t_to_v_float_bound(n: int) -> float:
    """Bound of the relative error (to the largest entry) of the float 'T_to_V' matrix wherever it is finite:
    ``eps max(4 n + 4, 1.6^n / 5)`` at every alpha, a measured bound (the largest errors: 18.5 eps at n = 10, 135 at
    n = 15, 1279 at n = 20, at alpha <= 0.01; fitted on n <= 20).  Where an entry leaves float64 (about 1/s^{3n}),
    :func:`transformation_matrix` raises OverflowError.

    >>> t_to_v_float_bound(10) / 2.0**-52, round(t_to_v_float_bound(20) / 2.0**-52)
    (44.0, 2418)
    """
    n = check_int(n, "n", 1, MAX_N_TRANSFORMATION, why="the bound is measured up to n = 30")
    return _growth(n, 1.6, 5.0, 4 * n + 4) * _EPS


def v_to_t_float_alpha_min(n: int) -> float:
    """The smallest alpha at which the float 'V_to_T' matrix keeps :data:`FLOAT_REL_GOAL` (its bound's threshold;
    ``inf`` if the bound exceeds it at every alpha)."""
    return _alpha_min(check_int(n, "n", 1, MAX_N_TRANSFORMATION, why="the bound is measured up to n = 30"))


def _alpha_min(n: int) -> float:
    """:func:`v_to_t_float_alpha_min` for inner code (``n`` already checked)."""
    room = FLOAT_REL_GOAL - _growth(n, 1.7, 3.0, 12 * n + 8) * _EPS
    return float(np.sqrt((12 * n + 8) * _EPS / room)) if room > 0 else float("inf")


def transformation_matrix(n: int, alpha, direction: str = "V_to_T", *, normalized: bool = True,
                          arith: str | Context | None = None, dps: int = 50) -> np.ndarray:
    """The basis transformation between :math:`V_n^\\alpha` and :math:`\\bar T_{2n}^\\alpha` (Question 7.2), every n.

    ``direction``: ``'V_to_T'`` gives :math:`M` with :math:`V_n = \\bar T_{2n} M` (column v: the v-th function of
    :math:`V_n` in :math:`\\bar T_{2n}`; ``M @ a`` turns Fourier coefficients into control coefficients);
    ``'T_to_V'`` gives :math:`M^{-1}` with :math:`\\bar T_{2n} = V_n M^{-1}` (``M^{-1} @ net`` turns a control net
    into Fourier coefficients).  Rows/columns: :math:`\\bar T_{2n}` in the order of
    :func:`~paper_repro.core.labels.united_system`, :math:`V_n` in the order of
    :func:`~paper_repro.core.fourier.v_labels`.  ``normalized=False``: the same for the unnormalized
    :math:`T_{2n}` (:math:`V_n = T_{2n} N^{-1}`, :math:`T_{2n} = V_n N`).

    ``alpha``: a :class:`~paper_repro.core.domain.RationalAngle` (then exact: an object array of flint ``fmpq``) or a
    real number in (0, pi) (then float64, bit-stable); ``arith`` overrides the arithmetic (``'float'``, ``'exact'``,
    ``'mp'`` with ``dps`` digits, ``'ball'``, or a context).  ``n`` from 1 to
    :data:`~paper_repro.util.limits.MAX_N_TRANSFORMATION`.  Float results: ``'V_to_T'`` is within
    :func:`v_to_t_float_bound` (relative to its largest entry) and refused (``ValueError``) where that bound exceeds
    :data:`FLOAT_REL_GOAL`, below alpha = :func:`v_to_t_float_alpha_min` (6.7e-4 at n = 1, 2.9e-3 at n = 30);
    ``'T_to_V'`` is within :func:`t_to_v_float_bound` and raises ``OverflowError`` where an entry exceeds float64
    (measured for n <= 30, alpha in [1e-300, pi - 1e-12]: reports/transformation_accuracy.md).
    """
    n = check_int(n, "n", 1, MAX_N_TRANSFORMATION, why="a dense delta_n x delta_n matrix built in O(n^5) operations")
    if not isinstance(direction, str):
        raise TypeError(f"direction must be one of {list(DIRECTIONS)} (a string), got {type(direction).__name__}")
    if direction not in DIRECTIONS:
        raise ValueError(f"direction must be one of {list(DIRECTIONS)}, got {direction!r}")
    if not isinstance(normalized, (bool, np.bool_)):
        raise TypeError(f"normalized must be True or False, got {normalized!r}")
    alpha = parse_alpha(alpha)
    if not isinstance(alpha, RationalAngle):
        check_alpha(alpha)
    if arith is None:
        arith = "exact" if isinstance(alpha, RationalAngle) else "float"
    ctx = get_context(arith, dps=dps)
    if (direction == "V_to_T" and isinstance(ctx, FloatContext) and not isinstance(alpha, RationalAngle)
            and float(alpha) < _alpha_min(n)):
        raise ValueError(f"transformation_matrix(n={n}, alpha={float(alpha)!r}, 'V_to_T') in float64 loses its digits "
                         f"to cancellation below alpha = {_alpha_min(n):.2g} (measured bound "
                         f"v_to_t_float_bound > {FLOAT_REL_GOAL:g} relative): give arith='mp' or alpha as a "
                         f"RationalAngle (exact); the 'T_to_V' direction is accurate at every alpha")
    if ctx.exact and not isinstance(alpha, RationalAngle):
        raise TypeError(f"arith {ctx.name!r} needs alpha as a RationalAngle (rational tan(alpha/4)), "
                        f"got {type(alpha).__name__}")
    # float: an entry beyond float64 is reported by the OverflowError below, not by numpy's RuntimeWarnings first
    with ctx.scope() if not isinstance(ctx, FloatContext) else np.errstate(over="ignore", invalid="ignore"):
        s, c = half_angle(alpha, ctx)
        out = transformation_in_context(n, s, c, ctx, direction, bool(normalized))
    if out.dtype == np.float64 and not np.isfinite(out).all():
        raise OverflowError(f"an entry of the {direction} matrix of order n = {n} exceeds float64 at alpha = "
                            f"{float(alpha)!r}; give alpha as a RationalAngle for exact values")
    return out


__all__ = ["DIRECTIONS", "FLOAT_REL_GOAL", "v_to_t_float_bound", "t_to_v_float_bound", "v_to_t_float_alpha_min",
           "transformation_matrix", "transformation_in_context", "gamma_coefficients", "scaled_theta",
           "expansion_matrix", "scaled_normalizing", "half_angle", "v_columns"]
