"""Triangular (rational) trigonometric patches (Definitions def:surface_patch, def:rational_patch).

A thin public class over the core: :class:`Patch` validates once and evaluates in any arithmetic
context; the float path is the blocked kernel of :mod:`paper_repro.core.fast`, the others go through
:func:`paper_repro.core.normalization.evaluate_normalized`.
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from paper_repro.core.context import Context, FloatContext, get_context
from paper_repro.core.derivatives_basis import DIRECTIONS, basis_derivative, check_direction
from paper_repro.core.domain import RationalAngle, RationalPoints, barycentric_to_uvw, check_points
from paper_repro.core.fast import FloatKernel, block_for, contract, run_blocks, trig_of_rows
from paper_repro.core.fast_jit import JIT_BLOCK, JitKernel
from paper_repro.core.fast_jit import available as jit_available
from paper_repro.core.half_angle_matrices import derivative_nets_checked
from paper_repro.core.labels import delta, delta_unchecked, exponent_matrix, index_of
from paper_repro.core.nets import LabelledNet, check_net, check_net_exact, net_from_labels  # noqa: F401 (re-exported)
from paper_repro.core.normalization import evaluate_normalized, scaled_float_vector
from paper_repro.core.ordered import ordered_matmul
from paper_repro.util.limits import MAX_MESH_RESOLUTION, check_int, check_real_array, real_scalar
from paper_repro.util.validation import DOMAIN_TOL, check_n, parse_alpha


def check_weights(weights, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Weights of a rational patch (eq. rational_patch): ``(exact, float64)``, both divided by their largest entry.

    A rational patch does not change when every weight is multiplied by the same factor, so the weights are
    normalised (float weights by a power of two, exactly): weights scaled by 1e-300 or 1e300 give the same points.
    They must be finite and >= 0; a zero weight at a corner control point (``r_{2n,2n,0}``, ``g_{2n,2n,0}``,
    ``b_{2n,2n,0}``) is refused, since at that corner every other blending function vanishes and the patch is 0/0
    there (inside the triangle every blending function is positive, so one positive weight suffices).
    """
    from fractions import Fraction

    from flint import fmpq

    from paper_repro.core.labels import index_of

    check_real_array(weights, "weights")
    try:
        w = np.asarray(weights, dtype=object)
        wf = w.astype(np.float64)
    except (TypeError, ValueError, OverflowError):
        raise TypeError("weights must be finite real numbers (float64 range)") from None
    if wf.shape != (delta(n),):
        raise ValueError(f"weights must have shape ({delta(n)},) for n = {n}, got {wf.shape}")
    if not np.all(np.isfinite(wf)) or np.any(wf < 0):
        raise ValueError("weights must be finite and non-negative")
    idx = index_of(n)
    corners = [f"{c}_{{{2 * n},{2 * n},0}}" for c in "rgb"]
    zero = [lab for lab in corners if wf[idx[lab]] == 0]
    if zero:
        raise ValueError(f"weights: the corner weight(s) {zero} are 0, so the rational patch is 0/0 at that corner; "
                         "corner weights must be positive")
    exact = all(isinstance(x, (int, np.integer, Fraction, fmpq)) for x in w)
    if exact:
        top = max(w, key=lambda x: Fraction(int(x.p), int(x.q)) if isinstance(x, fmpq) else Fraction(x))
        top = fmpq(int(top.p), int(top.q)) if isinstance(top, fmpq) else fmpq(Fraction(top).numerator,
                                                                               Fraction(top).denominator)
        w = np.array([fmpq(Fraction(x).numerator, Fraction(x).denominator) if not isinstance(x, fmpq) else x
                      for x in w], dtype=object) / top
    else:
        _, e = np.frexp(wf.max())
        wf = np.ldexp(wf, -int(e))  # exact division by a power of two
        w = wf.astype(object)
    return w, np.asarray(w.astype(np.float64), dtype=np.float64)

#: Relative size (per control point, unit-scale net) below which a cross product of tangents is rounding noise.
NORMAL_TOL = 2.0 ** -40


def unit_normals(du: np.ndarray, dv: np.ndarray, tol: float) -> np.ndarray:
    """``du x dv`` normalized; NaN where ``|du x dv| <= tol (|du| + |dv|)`` (rounding noise, :meth:`Patch.normals`).

    ``du`` and ``dv`` are ``(3, P)`` rows (the kernel's layout), and so is the result: every operation runs on
    contiguous rows of P values (``np.cross`` and ``np.linalg.norm`` on ``(P, 3)`` took as long as the derivatives
    at n = 1).
    """
    nrm = np.empty_like(du)
    for k in range(3):
        i, j = (k + 1) % 3, (k + 2) % 3
        np.multiply(du[i], dv[j], out=nrm[k])
        nrm[k] -= du[j] * dv[i]
    length = np.sqrt(_sumsq(nrm))
    small = length <= tol * (np.sqrt(_sumsq(du)) + np.sqrt(_sumsq(dv)))
    with np.errstate(invalid="ignore", divide="ignore"):
        nrm /= length
    nrm[:, small] = np.nan
    return nrm


def _sumsq(rows: np.ndarray) -> np.ndarray:
    """``x^2 + y^2 + z^2`` of ``(3, P)`` rows, in this order for every point (``np.einsum`` sums the three squares
    in an order that depends on P: a point alone and the same point in a batch got different last bits)."""
    out = rows[0] * rows[0]
    out += rows[1] * rows[1]
    out += rows[2] * rows[2]
    return out


def _pow2_exponent(a: np.ndarray) -> int:
    """``e`` with ``max |a| < 2^e`` (0 for a zero or empty array): dividing by ``2^e`` is exact."""
    m = float(np.max(np.abs(a))) if a.size else 0.0
    return math.frexp(m)[1] if m > 0 and math.isfinite(m) else 0


class Patch:
    """Triangular trigonometric patch s_n^alpha (eq. triangular_trig_surface), or its rational form
    (eq. rational_patch) when ``weights`` are given.

    Parameters
    ----------
    n : int
        The order, a positive integer.
    alpha : float or RationalAngle
        The shape parameter in (0, pi): a number (or text such as ``"pi/2"``), or a
        :class:`~paper_repro.core.domain.RationalAngle` (rational ``tan(alpha/4)``; needed for exact evaluation).
    net : array_like or mapping
        The control net, ``(delta_n, d)`` rows in the order of :func:`paper_repro.core.labels.united_system`
        -- the centre ``r_{2n,n,n}`` first, then the R, G, B functions, each colour by level ``j``
        ascending and ``i`` ascending -- or a mapping ``{'r_{4,3,1}': point, ...}`` keyed by the paper's
        labels.  Entries may be floats, ints, ``Fraction`` or ``fmpq`` (kept exactly for exact evaluation).
    weights : array_like, optional
        Non-negative weights of the rational patch, one per control point.
    arith : str or Context, optional
        Default arithmetic of :meth:`__call__`: ``'float'`` (the default), ``'mp'``, ``'exact'``, ``'ball'``,
        ``'modp'`` or a context.

    Examples
    --------
    Control-net order for n = 1 (delta_1 = 7):

    >>> from paper_repro.core.labels import united_system
    >>> [lab.control_point for lab in united_system(1)]
    ['r_{2,1,1}', 'r_{2,2,0}', 'r_{2,1,0}', 'g_{2,2,0}', 'g_{2,1,0}', 'b_{2,2,0}', 'b_{2,1,0}']

    The corners interpolate (u = alpha is the corner of r_{2,2,0}):

    >>> import numpy as np
    >>> net = np.arange(14.0).reshape(7, 2)
    >>> p = Patch(1, 1.0, net)
    >>> p([[1.0, 0.0, 0.0]]).round(12).tolist()
    [[2.0, 3.0]]

    Exact evaluation at rational points (alpha = 4 atan(1/2)):

    >>> from flint import fmpq
    >>> from paper_repro.core.domain import RationalPoints, rational_alpha
    >>> a = rational_alpha(fmpq(1, 2))
    >>> q = Patch(1, a, net.astype(int))
    >>> pts = RationalPoints(a, (fmpq(1, 5),), (fmpq(1, 7),))
    >>> exact = q(pts, arith="exact")
    >>> bool(abs(float(exact[0, 0]) - q(pts)[0, 0]) < 1e-13)
    True
    """

    def __init__(self, n: int, alpha, net, weights=None, arith: str | Context = "float"):
        self.n = check_n(n)
        alpha = parse_alpha(alpha)  # "pi/2" accepted; checked there (once)
        self.alpha = alpha if isinstance(alpha, RationalAngle) else real_scalar(alpha, "alpha")
        self.net_exact = check_net_exact(net, self.n, n_checked=True)
        #: float64 control net; rows also by paper label: ``patch.net["r_{4,3,1}"]``
        self.net = LabelledNet(self.net_exact.astype(np.float64), self.n, n_checked=True)
        self.ctx = get_context(arith)
        self.weights_exact = None
        self.weights = None
        if weights is not None:
            self.weights_exact, self.weights = check_weights(weights, self.n)

    def __repr__(self) -> str:
        kind = "rational " if self.weights is not None else ""
        return f"<{kind}Patch n={self.n} alpha={float(self.alpha):.6g} dim={self.net.shape[1]}>"

    @property
    def dimension(self) -> int:
        return self.net.shape[1]

    # --- the float fast path ----------------------------------------------------------------------
    @cached_property
    def _setup(self) -> dict:
        """Kernel, scaled coefficients and the net brought to unit scale (powers of two, so exact).

        A patch point is a convex combination of the control points, so the net is divided by a power of two
        ``2^e >= max |p_f|`` before the contraction and the result multiplied back: nets up to 1e308 give no
        overflow, and the bits are those of the unscaled product (multiplying by a power of two is exact).
        """
        a = float(self.alpha)
        coef = scaled_float_vector(self.n, a)  # s^{2n+j} r, finite for every alpha (n, alpha checked once, here)
        e = _pow2_exponent(self.net)
        unit = np.ldexp(self.net, -e)
        # derivatives: translation invariant (sum of the derivatives of a partition of unity is 0), so the net
        # is centred, then scaled again to unit size: the contraction error is relative to the net's extent
        mid = 0.5 * (unit.max(axis=0) + unit.min(axis=0))
        centred = unit - mid
        e2 = _pow2_exponent(centred)
        centred = np.ldexp(centred, -e2)
        if self.weights is None:
            cw = None
            cnet, dnet = coef[:, None] * unit, coef[:, None] * centred
        else:
            ew = _pow2_exponent(self.weights)
            cw = coef * np.ldexp(self.weights, -ew)
            cnet, dnet = cw[:, None] * unit, cw[:, None] * centred
        kernel = FloatKernel(exponent_matrix(self.n))
        daug_t = np.ascontiguousarray((dnet if cw is None else np.column_stack([dnet, cw])).T)
        return {"kernel": kernel, "jit": JitKernel(kernel) if jit_available() else None,
                "alpha": a, "sa": math.sin(a / 2),
                "cnet": cnet, "cw": cw, "exp": e, "dnet": dnet, "dexp": e + e2,
                "aug_t": np.ascontiguousarray((cnet if cw is None else np.column_stack([cnet, cw])).T),
                "daug_t": daug_t}

    def _float_points(self, points) -> np.ndarray:
        """Points as a float ``(P, 3)`` array (validated block by block in :meth:`_checked_rows`)."""
        if isinstance(points, RationalPoints):
            return points.uvw_float()
        if not isinstance(points, np.ndarray):
            return self._float_points(check_points(points, float(self.alpha), alpha_checked=True))
        arr = np.asarray(points)
        if arr.ndim != 2 or arr.shape[1:] != (3,) or arr.shape[0] == 0 or arr.dtype.kind not in "fiu":
            arr = check_points(points, float(self.alpha), alpha_checked=True)  # raises the documented error
        return arr

    def _checked_rows(self, arr: np.ndarray, lo: int, hi: int) -> np.ndarray:
        """Points ``lo:hi`` as contiguous ``(3, P)`` float rows (the kernel's layout), checked to lie on Omega^alpha.

        Two row operations decide (a NaN or inf makes the sum non-finite); anything off goes to the full check,
        which raises the documented error naming the point.  On rows this is a few element-wise operations:
        ``sum(axis=1)`` and ``min(axis=1)`` of the ``(P, 3)`` block took as long as the sines and cosines.
        """
        rows = np.ascontiguousarray(np.asarray(arr[lo:hi]).T, dtype=np.float64)
        a = float(self.alpha)
        slack = DOMAIN_TOL * a
        u, v, w = rows
        sums = u + v
        sums += w
        sums -= a
        low = np.minimum(u, v)
        np.minimum(low, w, out=low)
        if not (np.all(np.abs(sums, out=sums) <= slack) and np.all(low >= -slack)):
            check_points(np.asarray(arr[lo:hi], dtype=np.float64), self.alpha, offset=lo)
        return rows

    def _float_call(self, points) -> np.ndarray:
        """The fast path: points validated and evaluated block by block (work memory independent of P),
        blocks spread over threads (:func:`paper_repro.core.fast.run_blocks`)."""
        st = self._setup
        kernel, jit, aug_t, rational = st["kernel"], st["jit"], st["aug_t"], st["cw"] is not None
        arr = self._float_points(points)
        out = np.empty((arr.shape[0], self.dimension))

        def work(lo: int, hi: int, ws) -> None:
            s, c = trig_of_rows(self._checked_rows(arr, lo, hi), st["alpha"], st["sa"])
            if jit is not None:  # the compiled kernel: (P, d), or (P, d + 1) with the weights' column last
                if rational:
                    y = jit.values(s, c, aug_t, ws.get("y", (hi - lo, aug_t.shape[0])))
                    np.divide(y[:, :-1], y[:, -1:], out=out[lo:hi])
                else:
                    jit.values(s, c, aug_t, out[lo:hi])
                return
            y = contract(aug_t, kernel.basis_rows(s, c, ws))  # (d, P), or (d + 1, P) with the weights' row last
            out[lo:hi] = (y[:-1] / y[-1]).T if rational else y.T

        block = JIT_BLOCK if jit is not None else block_for(delta_unchecked(self.n))
        run_blocks(arr.shape[0], work, block, blas=jit is None)
        return np.ldexp(out, st["exp"], out=out) if st["exp"] else out

    @cached_property
    def _derivative_nets(self) -> tuple[np.ndarray, np.ndarray]:
        """``(q_u, q_v)``, ``(delta_n, m)``: the nets of ``2 sin(alpha/2)`` times the derivatives along u and v of the
        centred unit-scale net (and the weights' column), on the same scaled monomials
        from the closed-form derivative matrix C (:func:`~paper_repro.core.half_angle_matrices.derivative_nets`,
        proven for every n in docs/elevation_and_derivative_for_all_n.md; cos(alpha/2) correctly rounded)."""
        st = self._setup
        return derivative_nets_checked(self.n, st["alpha"], np.asarray(st["daug_t"].T, dtype=np.float64),
                                       FloatContext())

    def _float_derivatives(self, points, directions, normals: bool = False) -> tuple[list[np.ndarray], int]:
        """``2 sin(alpha/2) 2^-E`` times the derivatives along ``directions`` (bounded), and E; with ``normals``
        (two directions) the unit normals instead, computed block by block (no full-size intermediate).

        For every n the derivative of the patch is a patch of the same order (the closed-form C,
        :mod:`paper_repro.core.half_angle_matrices`): the derivatives along the directions (and, for a rational
        patch, the values) are one point evaluation of the stacked nets ``du q_u + dv q_v``, with the kernel of
        :meth:`_float_call` -- one route for every n (the monomials' brackets, :meth:`FloatKernel.derivatives_rows`
        and the compiled ``JitKernel.derivatives``, remain only as an independent cross-check in the tests).
        Rational patches by the quotient rule ``(N' - P D') / D``.
        """
        st = self._setup
        kernel, rational = st["kernel"], st["cw"] is not None
        arr = self._float_points(points)
        outs = [np.empty((arr.shape[0], self.dimension)) for _ in range(1 if normals else len(directions))]
        tol = NORMAL_TOL * delta_unchecked(self.n)

        jit = st["jit"]
        dirs = np.array(directions, dtype=np.float64)
        m = st["daug_t"].shape[0]  # coordinates, and the weights' row for a rational patch
        qu, qv = self._derivative_nets
        parts = [st["daug_t"]] if rational else []
        parts += [(d[0] * qu + d[1] * qv).T for d in dirs]  # d = du u + dv v in the plane (dw = -du - dv)
        stacked = np.ascontiguousarray(np.concatenate(parts))

        def work(lo: int, hi: int, ws) -> None:
            s, c = trig_of_rows(self._checked_rows(arr, lo, hi), st["alpha"], st["sa"])
            if jit is not None:
                rows = jit.values(s, c, stacked, ws.get("js", (hi - lo, stacked.shape[0]))).T
            else:
                rows = contract(stacked, kernel.basis_rows(s, c, ws))
            y = rows[:m] if rational else None
            dys = [rows[k: k + m] for k in range(m if rational else 0, rows.shape[0], m)]
            if rational:  # (d, P) rows
                assert y is not None
                den = y[-1]
                pt = y[:-1] / den
                res = [(dy[:-1] - pt * dy[-1]) / den for dy in dys]
            else:
                res = dys
            if normals:
                outs[0][lo:hi] = unit_normals(res[0], res[1], tol).T
            else:
                for o, r in zip(outs, res):
                    o[lo:hi] = r.T

        block = JIT_BLOCK if jit is not None else block_for(delta_unchecked(self.n))
        run_blocks(arr.shape[0], work, block, blas=jit is None)
        return outs, st["dexp"]

    # --- evaluation -------------------------------------------------------------------------------
    def basis(self, points, arith: str | Context | None = None, dps: int = 50) -> np.ndarray:
        """Blending values T-bar_{2n}^alpha at the points: ``(P, delta_n)``."""
        return evaluate_normalized(self.n, self.alpha, points, self._ctx(arith, dps))

    def _ctx(self, arith, dps) -> Context:
        return self.ctx if arith is None else get_context(arith, dps=dps)

    def __call__(self, points, arith: str | Context | None = None, dps: int = 50) -> np.ndarray:
        """Patch points at ``points``: ``(P, 3)`` real ``(u, v, w)`` of Omega^alpha or :class:`RationalPoints`.

        The float path works in blocks (memory independent of the number of points); ``arith='mp'``
        evaluates with mpmath at ``dps`` digits, ``'exact'`` exactly (rational-tangent alpha and
        :class:`RationalPoints`; the net's float entries are taken as their exact binary values).
        """
        ctx = self._ctx(arith, dps)
        if isinstance(ctx, FloatContext):
            return self._float_call(points)
        b = evaluate_normalized(self.n, self.alpha, points, ctx)
        return self._combine(b, ctx)

    def from_blending_values(self, b: np.ndarray, arith: str | Context | None = None, dps: int = 50) -> np.ndarray:
        """Patch points from blending values ``b`` (``(P, delta_n)``, :func:`evaluate_normalized` at the points in
        the arithmetic ``arith``): what :meth:`__call__` computes after evaluating them, for a caller that needs the
        blending values too (``claim float_accuracy``: its mp reference evaluates them once, not twice)."""
        return self._combine(b, self._ctx(arith, dps))

    def reference(self, points, dps: int = 50) -> np.ndarray:
        """A high-precision reference for the float path: ``(P, d)`` floats.

        The points' ``u`` and ``v`` are taken as their exact binary values, ``w`` is recomputed as
        ``alpha - u - v`` at ``dps`` digits (so points that are on Omega^alpha only up to rounding are
        moved onto it), the patch is evaluated with mpmath and rounded to float64 at the end.  This is
        what the accuracy tests and ``tools/fuzz_api.py`` compare the float path with.

        >>> p = Patch(1, 1.0, np.arange(21.0).reshape(7, 3))
        >>> pts = [[0.2, 0.3, 0.5]]
        >>> bool(abs(p.reference(pts) - p(pts)).max() < 1e-14)
        True
        """
        import mpmath

        dps = check_int(dps, "dps", 15, 1000)
        pts = self._float_points(points)
        with mpmath.workdps(dps):
            a = self.alpha.mp() if isinstance(self.alpha, RationalAngle) else mpmath.mpf(self.alpha)
            q = np.array([[mpmath.mpf(float(x)) for x in row] for row in pts], dtype=object)
            q[:, 2] = a - q[:, 0] - q[:, 1]
            return np.array(self(q, arith="mp", dps=dps), dtype=float)

    def _combine(self, b: np.ndarray, ctx: Context) -> np.ndarray:
        with ctx.scope():
            net = ctx.asarray(self.net_exact)
            if self.weights is None:
                return ctx.dot(b, net)
            bw = ctx.mul(b, ctx.asarray(self.weights_exact)[None, :])
            return ctx.div(ctx.dot(bw, net), bw.sum(axis=1)[:, None])

    def derivative(self, points, direction: str | tuple = "u", arith: str | Context | None = None,
                   dps: int = 50) -> np.ndarray:
        """Directional derivative of the patch along Omega^alpha: ``(P, d)``.

        ``direction`` is ``'u'`` (d/du with v fixed, w = alpha - u - v), ``'v'`` (d/dv with u fixed),
        ``'w'`` (d/dw with u fixed) or a triple ``(du, dv, dw)`` with ``du + dv + dw = 0``
        (:data:`~paper_repro.core.derivatives_basis.DIRECTIONS`).  Rational patches use the quotient rule.

        The float path is blocked like point evaluation (memory independent of the number of points). For
        every n the derivative of the patch is a patch of the same order: the centred net at unit scale multiplied
        by the derivative matrix C, whose entries are integer polynomials in cos(alpha/2) (closed form proven for
        every n: docs/elevation_and_derivative_for_all_n.md, claim ``derivative_all_n``); then one point
        evaluation of that net (as fast as a point, within rounding of the direct route).  It
        is multiplied by ``2^E / (2 sin(alpha/2))`` once (one power-of-two step), so it is finite for every alpha
        in (0, pi) unless the derivative itself (of size extent / alpha) exceeds float64: then ``OverflowError``
        says so.  A triple direction is taken as ``du u + dv v`` (``dw = -du - dv``).
        """
        ctx = self._ctx(arith, dps)
        if isinstance(ctx, FloatContext):
            d = [float(x) for x in check_direction(direction)]
            # the direction brought to unit size by a power of two (exact), its exponent put back with the net's
            kd = math.frexp(max(abs(x) for x in d))[1] if any(d) else 0
            (y,), e = self._float_derivatives(points, [tuple(math.ldexp(x, -kd) for x in d)])
            m, k = math.frexp(2 * self._setup["sa"])  # 2 sin(alpha/2) = m 2^k, m in [0.5, 1)
            with np.errstate(over="ignore"):
                out = np.ldexp(np.divide(y, m, out=y), e - k + kd, out=y)
            if out.size and not (math.isfinite(np.max(out)) and math.isfinite(np.min(out))):  # no (P, d) mask
                raise OverflowError(f"the derivative exceeds float64's range (alpha = {float(self.alpha):.3g}, net "
                                    f"extent 2^{e}): its size is about extent / sin(alpha/2); evaluate it with "
                                    "arith='mp', or scale the net down")
            return out
        b = evaluate_normalized(self.n, self.alpha, points, ctx)
        db = basis_derivative(self.n, self.alpha, points, direction, ctx)
        with ctx.scope():
            net = ctx.asarray(self.net_exact)
            if self.weights is None:
                return ctx.dot(db, net)
            w = ctx.asarray(self.weights_exact)[None, :]
            bw, dbw = ctx.mul(b, w), ctx.mul(db, w)
            den, dden = bw.sum(axis=1)[:, None], dbw.sum(axis=1)[:, None]
            num, dnum = ctx.dot(bw, net), ctx.dot(dbw, net)
            return ctx.div(ctx.sub(ctx.mul(dnum, den), ctx.mul(num, dden)), ctx.mul(den, den))

    def normals(self, points) -> np.ndarray:
        """Unit normals (float, 3-D nets): the normalized cross product of the derivatives along
        ``'u'`` and ``'v'`` (:data:`~paper_repro.core.derivatives_basis.DIRECTIONS`); NaN where it vanishes.

        Computed blocked (memory independent of the number of points) from the derivatives of the net
        centred and scaled to unit size (so nets of any scale, 1e-300..1e300, give the same normals), without
        the positive factor 1/(2 sin(alpha/2)); one 6-coordinate point evaluation (see
        :meth:`derivative`).  "Vanishes" means: the cross product is below what rounding
        can produce, ``|d_u x d_v| <= NORMAL_TOL * delta_n * (|d_u| + |d_v|)`` (unit-scale net), as at a
        degenerate corner where a tangent is 0 or the two are parallel.
        """
        if self.dimension != 3:
            raise ValueError(f"normals need a 3-D control net, this one is {self.dimension}-D")
        (nrm,), _ = self._float_derivatives(points, [DIRECTIONS["u"], DIRECTIONS["v"]], normals=True)
        return nrm

    def at_barycentric(self, bary) -> np.ndarray:
        """Patch points at barycentric ``(x, y, z)`` rows (x + y + z = 1, the point alpha (x, y, z))."""
        return self(barycentric_to_uvw(self.alpha, bary))

    def boundary_net(self, edge: str) -> np.ndarray:
        """Control polygon of a boundary curve (the paper's list after Definition def:surface_patch):
        ``'u=0'``: g_{2n,2n-i,0}, ``'v=0'``: r_{2n,2n-i,0}, ``'w=0'``: b_{2n,2n-i,0}, i = 0..2n."""
        letters = {"u=0": "g", "v=0": "r", "w=0": "b"}
        if edge not in letters:
            raise ValueError(f"edge must be one of {sorted(letters)}, got {edge!r}")
        idx = index_of(self.n)
        return np.stack([self.net[idx[f"{letters[edge]}_{{{2 * self.n},{2 * self.n - i},0}}"]]
                         for i in range(2 * self.n + 1)])

    def boundary_curve(self, edge: str, t) -> np.ndarray:
        """The boundary curve as a univariate curve sum_i p_i A_{2n,2n-i}(t) (eq. univariate_basis);
        t is w on u=0, u on v=0, v on w=0."""
        from paper_repro.core.univariate import A

        a = A(self.n, float(self.alpha), check_curve_parameter(t, float(self.alpha)))  # columns A_{2n,0..2n}
        return ordered_matmul(a[:, ::-1], self.boundary_net(edge))  # the same bits on every CPU (not BLAS)

    def mesh(self, resolution: int = 16, normals: bool = False):
        """Triangle mesh on a barycentric grid: ``(vertices (V, d), faces (F, 3))``, and the unit vertex
        normals ``(V, 3)`` as a third item when ``normals`` is True (3-D nets; see :meth:`normals`).  Always
        evaluated in float64, whatever the patch's default ``arith`` (a mesh is for drawing and export)."""
        if not isinstance(normals, (bool, np.bool_)):
            raise TypeError(f"normals must be True or False, got {normals!r}")
        return mesh_of(self, resolution, bool(normals))


    def plot(self, ax=None, net: bool = True, surface: bool = True, resolution: int = 24,
             surface_color: str = "#d8d8d8", net_color: str = "#1f5fbf", labels: bool = False):
        """Draw the patch and its control net in 3-D with matplotlib, as Fig. 7 (``fig:third_order_patch``) does.

        Parameters
        ----------
        ax : matplotlib 3-D axes, optional
            Where to draw; a new figure with one 3-D axes when omitted.
        net : bool
            Draw the control points and the edges of the net (:func:`~paper_repro.core.layout.net_edges`).
        surface : bool
            Draw the surface, a :meth:`mesh` of ``resolution`` steps a side, shaded.
        resolution : int
            Steps a side of the surface's mesh.
        surface_color, net_color : str
            Matplotlib colours of the surface and of the net.
        labels : bool
            Write each control point's paper label (``r_{6,5,0}``, ...) next to it.

        Returns
        -------
        The matplotlib axes (``mpl_toolkits.mplot3d.Axes3D``), its aspect ratio equal on the three axes.

        >>> import numpy as np, matplotlib
        >>> matplotlib.use("Agg")
        >>> from paper_repro.core.labels import delta
        >>> ax = Patch(1, "pi/2", np.random.default_rng(0).normal(size=(delta(1), 3))).plot()
        >>> len(ax.lines), len(ax.collections)   # 9 edges; the surface and the points
        (9, 2)
        """
        if self.dimension != 3:
            raise ValueError(f"plot draws 3-D nets, this one is {self.dimension}-D")
        import matplotlib.pyplot as plt
        from matplotlib.colors import LightSource

        from paper_repro.core.labels import united_system
        from paper_repro.core.layout import net_edges

        if ax is None:
            ax = plt.figure(figsize=(6, 5)).add_subplot(projection="3d")
        pts = np.asarray(self.net, dtype=np.float64)
        if surface:
            verts, faces = self.mesh(resolution)
            ax.plot_trisurf(verts[:, 0], verts[:, 1], verts[:, 2], triangles=faces, color=surface_color,
                            shade=True, lightsource=LightSource(azdeg=315, altdeg=45), linewidth=0,
                            antialiased=True, edgecolor="none", alpha=0.9)
        if net:
            for a, b in net_edges(self.n):
                ax.plot(*pts[[a, b]].T, color=net_color, lw=1.0)
            ax.scatter(*pts.T, color=net_color, s=14, depthshade=False)
            if labels:
                for lab, p in zip(united_system(self.n), pts):
                    ax.text(*p, f" {lab.control_point}", fontsize=7)
        shown = [pts] + ([verts] if surface else [])
        lo, hi = np.min([x.min(axis=0) for x in shown], axis=0), np.max([x.max(axis=0) for x in shown], axis=0)
        ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(np.maximum(hi - lo, 1e-9 * max(float((hi - lo).max()), 1.0)))
        ax.set_xlabel("x"), ax.set_ylabel("y"), ax.set_zlabel("z")
        return ax


def check_curve_parameter(t, alpha: float) -> np.ndarray:
    """``t`` as a float64 array of real, finite values in ``[0, alpha]`` (within the domain tolerance);
    ``TypeError``/``ValueError`` naming ``t`` otherwise (NaN gave NaN points, complex values raw errors).

    >>> check_curve_parameter([0, 0.5], 1.0).tolist()
    [0.0, 0.5]
    """
    from paper_repro.util.limits import check_real_array
    from paper_repro.util.validation import DOMAIN_TOL

    if np.ndim(t) == 0:
        from paper_repro.util.limits import real_scalar

        real_scalar(t, "t")
    else:
        check_real_array(t, "t")
    arr = np.asarray(t, dtype=np.float64)
    if not np.isfinite(arr).all():
        raise ValueError("t must be finite (NaN or infinite values given)")
    tol = DOMAIN_TOL * alpha
    if arr.size and (arr.min() < -tol or arr.max() > alpha + tol):
        raise ValueError(f"t must lie in [0, alpha] = [0, {alpha!r}], got values from {arr.min()!r} to {arr.max()!r}")
    return arr


def triangle_grid(resolution: int) -> tuple[np.ndarray, np.ndarray]:
    """Barycentric grid points ``(V, 3)`` and faces ``(F, 3)`` of a triangle with ``resolution`` steps a side:
    ``(r + 1)(r + 2)/2`` points ``(i/r, j/r, 1 - (i + j)/r)`` and ``r^2`` faces (the grid of :meth:`Patch.mesh`;
    map the rows to :math:`\\Omega^\\alpha` with ``alpha * bary`` or use :meth:`Patch.at_barycentric`).

    >>> bary, faces = triangle_grid(2)
    >>> bary.tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.5, 0.5], [0.0, 1.0, 0.0], [0.5, 0.0, 0.5], [0.5, 0.5, 0.0], [1.0, 0.0, 0.0]]
    >>> faces.tolist()
    [[0, 3, 1], [3, 4, 1], [1, 4, 2], [3, 5, 4]]
    """
    r = check_int(resolution, "resolution", 1, MAX_MESH_RESOLUTION,
                  why="(r+1)(r+2)/2 vertices and r^2 faces; the budget is about 0.5 M vertices")
    rows = np.arange(r + 1)
    length = r + 1 - rows                                   # points on row i: j = 0..r-i
    offset = np.concatenate([[0], np.cumsum(length)[:-1]])  # id(i, j) = offset[i] + j
    i = np.repeat(rows, length)
    j = np.arange(i.size) - offset[i]
    bary = np.column_stack([i / r, j / r, 1 - (i + j) / r])
    # faces in the order (i, j) = (0, 0), (0, 1), ...: the "up" triangle, then the "down" one where it exists
    cells = i + j < r
    ci, cj = i[cells], j[cells]
    up = np.column_stack([offset[ci] + cj, offset[np.minimum(ci + 1, r)] + cj, offset[ci] + cj + 1])
    has_down = ci + cj + 1 < r
    down = np.column_stack([offset[np.minimum(ci + 1, r)] + cj, offset[np.minimum(ci + 1, r)] + cj + 1,
                            offset[ci] + cj + 1])[has_down]
    start = np.arange(ci.size) + np.concatenate([[0], np.cumsum(has_down)[:-1]])
    faces = np.empty((ci.size + int(has_down.sum()), 3), dtype=np.int64)
    faces[start] = up
    faces[start[has_down] + 1] = down
    return bary, faces


def mesh_of(patch: Patch, resolution: int = 16, normals: bool = False):
    bary, faces = triangle_grid(resolution)
    verts = patch(barycentric_to_uvw(patch.alpha, bary), arith="float")  # float64 whatever patch.ctx is
    if not normals:
        return verts, faces
    nrm = patch.normals(barycentric_to_uvw(patch.alpha, bary))
    return verts, faces, nrm


def merge_meshes(meshes: list[tuple[np.ndarray, ...]]) -> tuple[np.ndarray, ...]:
    """Concatenate meshes ``(vertices, faces[, normals])`` (vertices are not welded): finite ``(V, d)`` vertices
    (one d for all: :meth:`Patch.mesh` of d-dimensional nets), integer ``(F, 3)`` faces indexing them, normals
    with every mesh or with none (``ValueError`` otherwise).

    >>> import numpy as np
    >>> v, f = np.eye(3), np.array([[0, 1, 2]])
    >>> merged = merge_meshes([(v, f), (v + 1, f)])
    >>> merged[1].tolist()
    [[0, 1, 2], [3, 4, 5]]
    """
    if isinstance(meshes, (str, bytes)) or not hasattr(meshes, "__iter__"):
        raise TypeError(f"meshes must be a list of (vertices, faces[, normals]) tuples, got {type(meshes).__name__}")
    meshes = list(meshes)
    if not meshes:
        raise ValueError("meshes must be a non-empty list of (vertices, faces[, normals]) tuples, got an empty list")
    for k, m in enumerate(meshes):
        if not isinstance(m, (tuple, list)) or len(m) not in (2, 3):
            raise TypeError(f"meshes[{k}] must be a tuple (vertices, faces[, normals]), got {type(m).__name__}")
    if len({len(m) for m in meshes}) != 1:
        raise ValueError("meshes: give normals with every mesh or with none (some have (vertices, faces, normals), "
                         "others (vertices, faces)); merging would drop the normals")
    from paper_repro.util.limits import check_real_array

    verts, faces, extra, offset = [], [], [], 0
    for k, m in enumerate(meshes):
        check_real_array(m[0], f"meshes[{k}] vertices")
        v = np.asarray(m[0], dtype=np.float64)
        dim = verts[0].shape[1] if verts else (v.shape[1] if v.ndim == 2 else 3)
        if v.ndim != 2 or v.shape[1] != dim or dim == 0 or not np.isfinite(v).all():
            raise ValueError(f"meshes[{k}]: vertices must be a finite (V, {dim}) array (the dimension of every mesh "
                             f"the same, as Patch.mesh gives for a net of that dimension), got shape {v.shape}")
        f = np.asarray(m[1])
        if f.ndim != 2 or f.shape[1] != 3 or (f.size and not np.issubdtype(f.dtype, np.integer)):
            raise ValueError(f"meshes[{k}]: faces must be an integer (F, 3) array, got shape {f.shape} of {f.dtype}")
        if f.size and (f.min() < 0 or f.max() >= len(v)):
            raise ValueError(f"meshes[{k}]: faces must index its vertices 0..{len(v) - 1}, got indices from "
                             f"{int(f.min())} to {int(f.max())}")
        verts.append(v)
        faces.append(f.astype(np.int64) + offset)
        if len(m) > 2:
            check_real_array(m[2], f"meshes[{k}] normals")
            nrm = np.asarray(m[2], dtype=np.float64)
            if nrm.shape != v.shape:
                raise ValueError(f"meshes[{k}]: normals must have the shape of its vertices {v.shape}, got "
                                 f"{nrm.shape}")
            extra.append(nrm)
        offset += len(v)
    out = (np.concatenate(verts), np.concatenate(faces))
    return out + (np.concatenate(extra),) if extra else out
