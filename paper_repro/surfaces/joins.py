"""Joins of two triangular trigonometric patches along a shared edge (beyond the paper).

Edges are named by the variable that vanishes on them: ``'v'`` is the edge v = 0 of Omega^alpha, parametrized by
t = u from the corner w = alpha (t = 0) to the corner u = alpha (t = alpha); ``'u'`` (u = 0) by t = w and ``'w'``
(w = 0) by t = v -- the parametrizations of the paper's boundary curves (Section 2, ``sec:RGB``): along edge
``'v'`` the patch is ``sum_k A_{2n,k}(t) r_{2n,k,0}`` (eq. ``boundary_property_1``).

* **The boundary row**: the 2n + 1 members that do not vanish on the edge (sine exponent 0 in the vanishing
  variable), row k the one restricted to a multiple of ``A_{2n,k}``; **the second row**: the 2n + 1 members with
  sine exponent 1 in it (:func:`edge_rows`).  Every other member vanishes to second order on the edge.
* **Cross-boundary derivative and tangent**: along the edge, the derivative into the patch (direction (0, 1, -1)
  for ``'v'``: v grows, u fixed) and the derivative along the edge (direction (1, 0, -1)) are trigonometric
  polynomials of degree n in t, ``sum_k A_{2n,k}(t) d_k`` and ``sum_k A_{2n,k}(t) t_k`` with d = D P, t = T P linear
  in the net (:func:`edge_derivatives`).  D involves only the boundary and second rows; T only the boundary row.
  D and T are computed in **closed form**, no solve and no collocation, in every arithmetic (``'float'``, ``'mp'``,
  ``'exact'`` at a :class:`~paper_repro.core.domain.RationalAngle`): each member restricted to the edge is a
  monomial in s = sin(t/2), c = cos(t/2), S = sin((alpha - t)/2), C = cos((alpha - t)/2) of degree 2n, and with
  sigma = s / sin(alpha/2), Sigma = S / sin(alpha/2) one has c = Sigma + cos(alpha/2) sigma,
  C = sigma + cos(alpha/2) Sigma and A_{2n,k} = N_k sigma^k Sigma^{2n-k} (N_k = sin^{2n}(alpha/2) c_{2n,k}, eq.
  ``univariate_basis``), so the coefficients are binomial expansions (docs/joins_for_all_n.md, Proposition 2).
* **The neighbour on the point-reflected side**: a patch whose domain is the image of Omega^alpha under the point
  reflection through the edge's midpoint (for ``'v'``: (u, v, w) -> (alpha - u, -v, alpha - w); the lower and upper
  pieces of the torus and the cyclide of Section 6 are such neighbours).  Its edge parameter runs backwards, so
  (A_{2n,k}(alpha - t) = A_{2n,2n-k}(t)):

  - C0 holds iff its boundary row is ours reversed: P'_{2n-k} = P_k (the same alpha);
  - C1 (in the common parameter plane) iff moreover d'_{2n-k} = -d_k;
  - G1 with constant multipliers (sufficient): d'_{2n-k} = -lam d_k + mu t_k, lam > 0.

:func:`c1_neighbour_row` and :func:`g1_neighbour_row` return the neighbour's second row for C1 or G1 (the second-row
block of D is triangular with a nonzero diagonal for every n, docs Lemma 3); :func:`join_neighbour` the
whole neighbour net; :func:`join_error` reports the C0, C1 and G1 defects.  (For whole models, the torus and the
cyclide, :func:`paper_repro.surfaces.models.model_gap` measures sampled C0 gaps of every shared edge.)

>>> import numpy as np
>>> from paper_repro.core.labels import delta
>>> net = np.random.default_rng(0).normal(size=(delta(1), 3))
>>> other = join_neighbour(net, 1, 1.0, "v")
>>> err = join_error(net, other, 1, 1.0, "v")
>>> bool(err["C0"] == 0 and err["C1"] < 1e-14 and err["G1"] < 1e-14)
True
>>> from paper_repro.core.domain import rational_alpha
>>> exact = join_error(net.round(2), join_neighbour(net.round(2), 1, rational_alpha("1/3"), "u",
...                    arith="exact"), 1, rational_alpha("1/3"), "u", arith="exact")
>>> exact["C0"], exact["C1"], exact["G1"], exact["lam"], exact["mu"]
(0, 0, 0, 1, 0)
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from flint import fmpq

from paper_repro.core.context import Context, ExactContext, FloatContext, MpContext, get_context
from paper_repro.core.domain import RationalAngle, open_alpha
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.nets import check_net, check_net_exact
from paper_repro.core.normalization import scaled_coefficient_vector
from paper_repro.core.univariate import c_numerator
from paper_repro.util.limits import check_int, real_scalar

#: Edges by the variable that vanishes on them.
EDGES = ("u", "v", "w")
#: (parameter variable, vanishing variable, other variable) of each edge: the parametrizations of the paper's
#: boundary curves (R along v = 0 with t = u, G along u = 0 with t = w, B along w = 0 with t = v).
ROLES = {"v": (0, 1, 2), "u": (2, 0, 1), "w": (1, 2, 0)}
#: Largest order accepted, every arithmetic: a cost limit.  The closed form costs O(n^3) scalar operations; one cold
#: call of :func:`edge_derivatives` (``tools/joins_accuracy.py``, 2 cores shared with other jobs) took at n = 40
#: 0.04 s float, 0.26-0.83 s mp (50 digits), 0.06-0.20 s exact; at n = 100 0.5 s float, 2.7 s mp, 1.0 s exact (the
#: mp normalizing coefficients stop at n = 120).  Float64 loses nothing with n (docs/joins_for_all_n.md section 7:
#: relative deviation from mp about 1e-15 up to n = 100), so the float limit is this cost limit, not accuracy.
MAX_N_JOINS = 100
#: Arithmetics accepted.
ARITHS = ("float", "mp", "exact")


def check_edge(edge: object) -> str:
    """``edge`` if it is one of :data:`EDGES`, else ``TypeError``/``ValueError`` naming ``edge``."""
    if not isinstance(edge, str):
        raise TypeError(f"edge must be one of {list(EDGES)}, got {edge!r} of type {type(edge).__name__}")
    if edge not in EDGES:
        raise ValueError(f"edge must be one of {list(EDGES)} (the variable that vanishes on it), got {edge!r}")
    return edge


def _unit(var: int, sign: int) -> np.ndarray:
    out = np.zeros(3, dtype=np.int64)
    out[var] = sign
    return out


def directions(edge: str) -> tuple[tuple[int, int, int], tuple[int, int, int]]:
    """(cross-boundary direction, tangent direction) of ``edge``: +vanishing - other, +parameter - other.

    >>> directions("v")
    ((0, 1, -1), (1, 0, -1))
    """
    p, z, o = ROLES[check_edge(edge)]
    cross = _unit(z, 1) + _unit(o, -1)
    tangent = _unit(p, 1) + _unit(o, -1)
    return tuple(int(x) for x in cross), tuple(int(x) for x in tangent)  # type: ignore[return-value]


@lru_cache(maxsize=128)
def edge_rows(n: int, edge: str) -> tuple[np.ndarray, np.ndarray]:
    """Internal indices of the boundary row (2n + 1 members, ordered by k = their sine exponent in the parameter
    variable, so that row k restricts to a multiple of A_{2n,k}) and of the second row (the 2n + 1 members with sine
    exponent 1 in the vanishing variable, ordered by their sine exponent in the parameter variable, then in the
    other one).

    >>> [len(r) for r in edge_rows(3, "w")]
    [7, 7]
    """
    p, z, o = ROLES[check_edge(edge)]
    exps = exponent_matrix(n)
    first = [f for f in range(len(exps)) if exps[f, 2 * z] == 0]
    second = [f for f in range(len(exps)) if exps[f, 2 * z] == 1]
    first.sort(key=lambda f: exps[f, 2 * p])
    second.sort(key=lambda f: (exps[f, 2 * p], exps[f, 2 * o]))
    if len(first) != 2 * n + 1 or len(second) != 2 * n + 1 or \
            [int(exps[f, 2 * p]) for f in first] != list(range(2 * n + 1)):  # pragma: no cover - labels' layout
        raise AssertionError("the boundary rows of T_{2n} are not as the boundary property says")
    b, s = np.array(first), np.array(second)
    b.setflags(write=False)
    s.setflags(write=False)
    return b, s


def edge_points(alpha: float, edge: str, ts: np.ndarray) -> np.ndarray:
    """The points of ``edge`` at parameters ``ts`` as ``(P, 3)`` (u, v, w), float64."""
    p, z, o = ROLES[check_edge(edge)]
    pts = np.zeros((len(ts), 3))
    pts[:, p] = ts
    pts[:, o] = alpha - np.asarray(ts)
    return pts


# --- the closed form -------------------------------------------------------------------------------------------------
def edge_terms(exps, edge: str, direction: tuple[int, int, int]) -> list[tuple[fmpq, int, int, int, int]]:
    """The derivative along ``direction`` of the monomial with exponent vector ``exps`` (sin/cos exponents of u/2,
    v/2, w/2, the layout of :func:`~paper_repro.core.labels.exponent_matrix`), restricted to ``edge``, as terms
    ``(coefficient, a, b, e, g)`` meaning ``coefficient * s^a c^b S^e C^g`` (s, c = sin, cos of half the parameter
    variable; S, C of half the other one).  Uses d/dx sin^a(x/2) cos^b(x/2) = (a/2) sin^{a-1} cos^{b+1}
    - (b/2) sin^{a+1} cos^{b-1} and sin(0) = 0, cos(0) = 1 for the vanishing variable.

    >>> edge_terms((1, 0, 1, 0, 1, 0), "v", (0, 1, -1))  # R_{2,1,1} = sin(u/2) sin(v/2) sin(w/2): (1/2) s S
    [(1/2, 1, 0, 1, 0)]
    """
    p, z, o = ROLES[edge]
    ex = [int(x) for x in exps]
    out: list[tuple[fmpq, int, int, int, int]] = []
    for var in range(3):
        comp = direction[var]
        if comp == 0:
            continue
        if var == z:  # only sin^1: (1/2) cos^{b+1}(0) times the rest; sin^{a+1}(0) = 0
            if ex[2 * z] == 1:
                out.append((fmpq(comp, 2), ex[2 * p], ex[2 * p + 1], ex[2 * o], ex[2 * o + 1]))
            continue
        if ex[2 * z] != 0:  # the factor sin^a(z/2), a >= 1, vanishes on the edge
            continue
        a, b = ex[2 * var], ex[2 * var + 1]
        for coef, da, db in ((fmpq(comp * a, 2), -1, 1), (fmpq(-comp * b, 2), 1, -1)):
            if coef == 0:
                continue
            new = list(ex)
            new[2 * var] += da
            new[2 * var + 1] += db
            out.append((coef, new[2 * p], new[2 * p + 1], new[2 * o], new[2 * o + 1]))
    return out


def _conv(x: np.ndarray, y: np.ndarray, ctx: Context) -> np.ndarray:
    """Coefficients of the product of two polynomials (ascending), in ``ctx``."""
    if isinstance(ctx, FloatContext):
        return np.convolve(x, y)
    out = ctx.zeros((len(x) + len(y) - 1,))
    for i, xi in enumerate(x):
        out[i:i + len(y)] = ctx.add(out[i:i + len(y)], ctx.mul(y, xi))
    return out


def _closed_form(n: int, alpha, edge: str, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
    """(sin(alpha/2) D, sin(alpha/2) T) in ``ctx`` (inside its scope), by the binomial expansions of the module
    docstring.  Scaled so that the entries are bounded as alpha -> 0 (D and T are of size 1/alpha): the join
    conditions are homogeneous in (D, T), so the builders and the G1 fit work with these."""
    m = 2 * n
    exps = exponent_matrix(n)
    b_idx, s_idx = edge_rows(n, edge)
    cross, tangent = directions(edge)
    sb, cb = ctx.alpha_half(alpha)
    scaled = scaled_coefficient_vector(n, alpha, ctx)  # sin^{total sine exponent}(alpha/2) x_f, bounded
    one = ctx.convert(1)
    cpow = [one]
    for _ in range(m):
        cpow.append(ctx.mul(cpow[-1], cb))
    # (Sigma + cb sigma)^k and (sigma + cb Sigma)^k, ascending powers of sigma
    lc = [ctx.asarray([ctx.mul(ctx.convert(math.comb(k, r)), cpow[r]) for r in range(k + 1)]) for k in range(m + 1)]
    lC = [ctx.asarray([ctx.mul(ctx.convert(math.comb(k, r)), cpow[k - r]) for r in range(k + 1)]) for k in range(m + 1)]
    norm = ctx.asarray([sum((ctx.mul(ctx.convert(q), cpow[i]) for i, q in enumerate(c_numerator(n, k))),
                            ctx.convert(0)) for k in range(m + 1)])
    sb_pow = {-1: one, 0: sb, 1: ctx.mul(sb, sb)}  # sin(alpha/2)^(1 + k)
    products: dict[tuple[int, int], np.ndarray] = {}
    d_mat, t_mat = ctx.zeros((m + 1, delta(n))), ctx.zeros((m + 1, delta(n)))
    for f in np.r_[b_idx, s_idx]:
        ex = exps[f]
        total_sine = int(ex[0] + ex[2] + ex[4])
        for target, direction in ((d_mat, cross), (t_mat, tangent)):
            col = ctx.zeros((m + 1,))
            for coef, a, b, e, g in edge_terms(ex, edge, direction):
                if a + b + e + g != m:  # pragma: no cover - proven (docs/joins_for_all_n.md, Lemma 1)
                    raise AssertionError(f"member {f}: edge monomial of degree {a + b + e + g}, not 2n = {m}")
                if (b, g) not in products:
                    products[(b, g)] = _conv(lc[b], lC[g], ctx)
                factor = ctx.mul(ctx.mul(ctx.from_rational(coef), scaled[f]), sb_pow[a + e - total_sine])
                col[a:a + b + g + 1] = ctx.add(col[a:a + b + g + 1], ctx.mul(products[(b, g)], factor))
            target[:, f] = ctx.div(col, norm)
    return d_mat, t_mat


# --- arguments ---------------------------------------------------------------------------------------------------
_check_alpha = open_alpha  # one rule for alpha (core.domain)


def _context(arith, alpha, dps) -> Context:
    if arith is None:
        arith = "exact" if isinstance(alpha, RationalAngle) else "float"
    if isinstance(arith, str) and arith not in ARITHS:
        raise ValueError(f"arith must be one of {list(ARITHS)} or their Context, got {arith!r}")
    ctx = get_context(arith, dps=dps)
    if type(ctx) not in (FloatContext, MpContext, ExactContext):
        raise ValueError(f"arith must be one of {list(ARITHS)} or their Context, got {ctx.name!r}")
    if ctx.exact and not isinstance(alpha, RationalAngle):
        raise TypeError(f"arith {ctx.name!r} needs alpha as a RationalAngle (rational tan(alpha/4)), "
                        f"got {type(alpha).__name__}")
    return ctx


def _check(n, alpha, edge, arith, dps) -> tuple[int, object, str, Context]:
    n = check_int(n, "n", 1, MAX_N_JOINS, why="the closed form of the edge coefficients costs O(n^3) scalar "
                  "operations (measured: tools/joins_accuracy.py)")
    a = _check_alpha(alpha)
    edge = check_edge(edge)
    return n, a, edge, _context(arith, a, dps)


@lru_cache(maxsize=64)
def _cached(n: int, alpha, edge: str, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
    with ctx.scope():
        d, t = _closed_form(n, alpha, edge, ctx)
    d.setflags(write=False)
    t.setflags(write=False)
    return d, t


def _matrices(n: int, alpha, edge: str, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
    """(sin(alpha/2) D, sin(alpha/2) T): bounded for every alpha (the join conditions are homogeneous in them)."""
    return _cached(n, alpha, edge, ctx)


def _sin_half(alpha, ctx: Context):
    with ctx.scope():
        return ctx.alpha_half(alpha)[0]


def _net(net, n: int, ctx: Context, name: str) -> np.ndarray:
    """The net validated; in ``ctx``'s scalars (exact: fmpq, a float as its binary value; mp: mpf)."""
    if isinstance(ctx, FloatContext):
        return check_net(net, n, name)
    arr = check_net_exact(net, n, name)
    with ctx.scope():
        return ctx.asarray(arr)


def edge_derivatives(n: int, alpha, edge: str = "v", arith: str | Context | None = None, *,
                     dps: int = 50) -> tuple[np.ndarray, np.ndarray]:
    """``(D, T)``, each ``(2n + 1, delta_n)``: the cross-boundary derivative of a patch with net P along ``edge`` is
    ``sum_k A_{2n,k}(t) (D P)_k`` and its derivative along the edge ``sum_k A_{2n,k}(t) (T P)_k``.

    Closed form (module docstring; docs/joins_for_all_n.md, Proposition 2), every n up to :data:`MAX_N_JOINS`.
    ``arith``: ``'float'`` (default for a real alpha), ``'mp'`` (``dps`` digits) or ``'exact'`` (default for a
    :class:`~paper_repro.core.domain.RationalAngle`; entries ``fmpq``).

    >>> d, t = edge_derivatives(1, 1.0, "v")
    >>> d.shape, bool(abs(t.sum(axis=1)).max() < 1e-15)  # a constant patch has no derivative
    ((3, 7), True)
    >>> from paper_repro.core.domain import rational_alpha
    >>> d, t = edge_derivatives(2, rational_alpha("1/2"), "w")
    >>> all(x == 0 for x in d.sum(axis=1)), type(d[0, 0]).__name__
    (True, 'fmpq')
    """
    n, a, edge, ctx = _check(n, alpha, edge, arith, dps)
    d, t = _matrices(n, a, edge, ctx)
    sb = _sin_half(a, ctx)
    with ctx.scope(), np.errstate(over="ignore"):
        d, t = ctx.div(d, sb), ctx.div(t, sb)
    if isinstance(ctx, FloatContext) and not (np.isfinite(d).all() and np.isfinite(t).all()):
        raise OverflowError(f"alpha: the edge derivatives are of size 1/alpha and exceed float64's range at alpha = "
                            f"{float(a):.3g}; use arith='mp'")  # type: ignore[arg-type]
    return np.array(d), np.array(t)


def _reverse(rows: np.ndarray) -> np.ndarray:
    return rows[::-1]


def _multiplier(x, name: str, ctx: Context, positive: bool):
    """``lam``/``mu`` checked (a finite real; ``lam > 0``) and converted to ``ctx`` (exact: a float is its binary
    value; give fmpq or a Fraction for an exact rational)."""
    v = real_scalar(x, name)
    try:
        f = float(v)
    except OverflowError:  # an integer or rational beyond float64: finite
        f = 0.0
    if not math.isfinite(f):
        raise ValueError(f"{name} must be finite, got {x!r}")
    if positive and not v > 0:
        raise ValueError(f"{name} must be a positive real number, got {x!r}")
    return ctx.convert(v)


def g1_neighbour_row(net, n: int, alpha, edge: str = "v", *, lam, mu, arith: str | Context | None = None,
                     dps: int = 50) -> np.ndarray:
    """The second row (``(2n + 1, d)``, ordered as ``edge_rows(n, edge)[1]``) of the neighbour on the
    point-reflected side of ``edge`` that joins the patch of ``net`` G1 with constant multipliers,
    ``d'_{2n-k} = -lam d_k + mu t_k`` (``lam > 0``), given C0 (the neighbour's boundary row is ours reversed).

    The second-row block of D is invertible for every n (docs Lemma 3; after ordering it is triangular
    with a nonzero diagonal), so the row is unique.  Solved in ``arith`` (exact: fmpq).  In float and mp the solve
    loses about log10(largest entry / smallest pivot) digits of the block -- for n = 1 about 2 log10(2/alpha) + 0.7
    (the centre's pivot is O(alpha^2)), for n >= 2 under 3 digits at every alpha measured -- so when more than
    :data:`LOST_DIGITS_OK` would be lost the row is solved in mp with that many extra digits and rounded
    (:func:`_work_context`).
    """
    n, a, edge, ctx = _check(n, alpha, edge, arith, dps)
    with ctx.scope():
        lam_c = _multiplier(lam, "lam", ctx, True)
        mu_c = _multiplier(mu, "mu", ctx, False)
    arr = _net(net, n, ctx, "net")
    work = _work_context(n, a, edge, ctx)
    if work is not ctx:
        with work.scope():
            row = _second_row(work.asarray(arr), n, a, edge, work, work.convert(lam_c), work.convert(mu_c))
        if isinstance(ctx, FloatContext):
            return work.to_float(row)
        with ctx.scope():
            return ctx.asarray(row)
    return _second_row(arr, n, a, edge, ctx, lam_c, mu_c)


#: Digits the float/mp solve of the second row may lose before it is redone at higher precision.
LOST_DIGITS_OK = 1


def _pivot_rows(n: int, edge: str) -> list[int]:
    """For each second-row member (edge_rows order), the row of D where its column is the pivot of the triangular
    block (docs/joins_for_all_n.md, Lemma 3): the cross derivative is (1/2) s^a c^b S^e C^g with b + g <= 1, whose
    expansion has its coefficient at sigma^(a + g) with no other column sharing that row but through the two cosine
    members."""
    exps = exponent_matrix(n)
    cross, _ = directions(edge)
    rows = []
    for f in edge_rows(n, edge)[1]:
        (term,) = edge_terms(exps[f], edge, cross)
        rows.append(term[1] + term[4])
    return rows


def _lost_digits(n: int, alpha, edge: str, ctx: Context) -> float:
    """log10(largest |entry| / smallest |pivot|) of the second-row block in ``ctx``, over the pivots whose row holds
    another column's entry too (rows 1 and 2n - 1; inf if such a pivot underflowed).  A pivot alone in its row
    (rows 0 and 2n; small near alpha = pi) divides a right-hand side computed to full relative accuracy: measured
    harmless (n = 1..10 at alpha = pi - 1e-3, pi - 1e-8: float within 1e-14 of mp); a small shared pivot (the
    centre's for n = 1, O(alpha^2)) divides a difference of O(1) terms and loses that many digits."""
    d_mat, _ = _matrices(n, alpha, edge, ctx)
    block = d_mat[:, edge_rows(n, edge)[1]]
    with ctx.scope():
        big = max(abs(x) for x in block.reshape(-1))
        shared = [(j, r) for j, r in enumerate(_pivot_rows(n, edge)) if sum(1 for x in block[r] if x != 0) > 1]
        if not shared:
            return 0.0
        small = min(abs(block[r, j]) for j, r in shared)
        if small == 0:
            return math.inf
        if isinstance(ctx, MpContext):
            import mpmath

            return float(mpmath.log10(big / small))
        return math.log10(float(big) / float(small))


def _work_context(n: int, alpha, edge: str, ctx: Context) -> Context:
    """``ctx`` itself when the second-row solve loses at most :data:`LOST_DIGITS_OK` digits in it (and always for
    exact); otherwise an mp context with the lost digits added (measured in mp, where nothing underflows)."""
    if ctx.exact:
        return ctx
    lost = _lost_digits(n, alpha, edge, ctx)
    if lost <= LOST_DIGITS_OK:
        return ctx
    if not math.isfinite(lost):
        lost = _lost_digits(n, alpha, edge, MpContext(dps=30))
    return MpContext(dps=min(10_000, ctx.digits + math.ceil(lost) + 10))


def _second_row(arr: np.ndarray, n: int, alpha, edge: str, ctx: Context, lam_c, mu_c) -> np.ndarray:
    d_mat, t_mat = _matrices(n, alpha, edge, ctx)
    b, s = edge_rows(n, edge)
    with ctx.scope():
        boundary = _reverse(arr[b])  # the neighbour's boundary row (C0)
        want = _reverse(ctx.add(ctx.mul(ctx.dot(d_mat, arr), -lam_c), ctx.mul(ctx.dot(t_mat, arr), mu_c)))
        rhs = ctx.sub(want, ctx.dot(np.ascontiguousarray(d_mat[:, b]), boundary))
        return ctx.solve(np.ascontiguousarray(d_mat[:, s]), rhs)


def c1_neighbour_row(net, n: int, alpha, edge: str = "v", *, arith: str | Context | None = None,
                     dps: int = 50) -> np.ndarray:
    """The second row of the C1 neighbour (``d'_{2n-k} = -d_k``): :func:`g1_neighbour_row` with lam = 1, mu = 0.
    For n = 1 across v = 0 it is the parallelogram rule P'_011 = P_200 + P_101 - P_110 (tested).

    >>> import numpy as np
    >>> row = c1_neighbour_row(np.eye(7), 1, 1.0, "v")
    >>> row.shape
    (3, 7)
    """
    return g1_neighbour_row(net, n, alpha, edge, lam=1, mu=0, arith=arith, dps=dps)


def join_neighbour(net, n: int, alpha, edge: str = "v", neighbour=None, *, lam=1, mu=0,
                   arith: str | Context | None = None, dps: int = 50) -> np.ndarray:
    """The net of the neighbour on the point-reflected side of ``edge``: a copy of ``neighbour`` (default: zeros)
    with its boundary row set to ours reversed (C0) and its second row from :func:`g1_neighbour_row` (C1 for the
    default ``lam = 1, mu = 0``).  The other rows do not enter the join (they vanish to second order on the edge)."""
    n, a, edge, ctx = _check(n, alpha, edge, arith, dps)
    arr = _net(net, n, ctx, "net")
    if neighbour is None:
        other = ctx.zeros(arr.shape)
    else:
        other = _net(neighbour, n, ctx, "neighbour").copy()
        if other.shape != arr.shape:
            raise ValueError(f"neighbour must have the shape of net {arr.shape}, got {other.shape}")
    b, s = edge_rows(n, edge)
    other[b] = _reverse(arr[b])
    other[s] = g1_neighbour_row(arr, n, a, edge, lam=lam, mu=mu, arith=ctx, dps=dps)
    return other


def _fit_multipliers(x: np.ndarray, y: np.ndarray, r: np.ndarray, ctx: Context) -> tuple[object, object]:
    """(lam, mu) minimizing sum (lam x + mu y - r)^2 subject to lam >= 0 (normal equations, in ``ctx``)."""
    def dot(p, q):
        return sum((ctx.mul(pi, qi) for pi, qi in zip(p, q)), ctx.convert(0))

    zero = ctx.convert(0)
    xx, xy, yy, xr, yr = dot(x, x), dot(x, y), dot(y, y), dot(x, r), dot(y, r)
    det = ctx.sub(ctx.mul(xx, yy), ctx.mul(xy, xy))
    if det != 0:
        lam = ctx.div(ctx.sub(ctx.mul(xr, yy), ctx.mul(yr, xy)), det)
        if lam >= 0:
            return lam, ctx.div(ctx.sub(ctx.mul(yr, xx), ctx.mul(xr, xy)), det)
        return zero, ctx.div(yr, yy)
    if yy != 0:
        if xx != 0:  # x parallel to y: every lam gives the same residual; take lam = 1
            one = ctx.convert(1)
            return one, ctx.div(ctx.sub(yr, xy), yy)
        return zero, ctx.div(yr, yy)
    if xx != 0:
        lam = ctx.div(xr, xx)
        return (lam if lam >= 0 else zero), zero
    return zero, zero


def join_error(net, neighbour, n: int, alpha, edge: str = "v", *, arith: str | Context | None = None,
               dps: int = 50) -> dict[str, object]:
    """Defects of the join of the patch of ``net`` with the patch of ``neighbour`` on the point-reflected side of
    ``edge`` (same n, same alpha), as scalars of ``arith`` (exact: fmpq; exactly 0 iff the condition holds):

    * ``'C0'`` = max |P_k - P'_{2n-k}| over the boundary rows and coordinates (0 iff the boundary curves coincide;
      the A_{2n,k} are a partition of unity, so the gap of the curves is at most this);
    * ``'C1'`` = max |d_k + d'_{2n-k}| (given C0: 0 iff C1);
    * ``'G1'`` = max |d'_{2n-k} + lam d_k - mu t_k| at the (``'lam'``, ``'mu'``) that minimize the sum of the squares
      of these residuals subject to lam >= 0.  0 iff some lam >= 0, mu fit exactly; with C0 and ``lam > 0`` that is
      G1 with constant multipliers (sufficient for G1; docs/joins_for_all_n.md, Theorem 4).  ``lam = 0`` flags a
      failed G1 fit;
    * ``'scale'`` = max |d_k|, the size of our cross-boundary coefficients (of order 1/alpha times the net's size):
      in float, C1 and G1 defects of a smooth join are rounding errors of about 1e-16 times ``'scale'``.
    """
    n, a, edge, ctx = _check(n, alpha, edge, arith, dps)
    arr = _net(net, n, ctx, "net")
    other = _net(neighbour, n, ctx, "neighbour")
    if other.shape != arr.shape:
        raise ValueError(f"neighbour must have the shape of net {arr.shape}, got {other.shape}")
    d_mat, t_mat = _matrices(n, a, edge, ctx)
    b, _ = edge_rows(n, edge)
    with ctx.scope():
        def maxabs(v: np.ndarray):
            return max((abs(x) for x in np.asarray(v).reshape(-1)), default=ctx.convert(0))

        c0 = maxabs(ctx.sub(arr[b], _reverse(other[b])))
        d, t = ctx.dot(d_mat, arr), ctx.dot(t_mat, arr)
        d_other = _reverse(ctx.dot(d_mat, other))  # row k: d'_{2n-k}
        c1 = maxabs(ctx.add(d, d_other))
        x, y, r = ctx.mul(d, -1).reshape(-1), t.reshape(-1), d_other.reshape(-1)
        lam, mu = _fit_multipliers(x, y, r, ctx)
        g1 = maxabs(ctx.sub(r, ctx.add(ctx.mul(x, lam), ctx.mul(y, mu))))
        scale = maxabs(d)
        sb = ctx.alpha_half(a)[0]  # d, t above are sin(alpha/2) times the coefficients
        with np.errstate(over="ignore"):
            c1, g1, scale = ctx.div(c1, sb), ctx.div(g1, sb), ctx.div(scale, sb)
    if isinstance(ctx, FloatContext):
        c0, c1, g1, lam, mu, scale = (float(v) for v in (c0, c1, g1, lam, mu, scale))  # type: ignore[arg-type]
    return {"C0": c0, "C1": c1, "G1": g1, "lam": lam, "mu": mu, "scale": scale}


__all__ = ["EDGES", "ROLES", "MAX_N_JOINS", "check_edge", "directions", "edge_rows", "edge_points", "edge_terms",
           "edge_derivatives", "g1_neighbour_row", "c1_neighbour_row", "join_neighbour", "join_error"]
