"""Control nets of surfaces whose coordinates lie in V_n (exact description by a patch).

``fit(surface, n, alpha)``: the coordinates of ``surface(u, v, w)`` (a callable on Omega^alpha, or on
the plane u + v + w = alpha) are interpolated in the normalized basis T-bar_{2n}^alpha at delta_n
points; if they lie in the space the interpolant *is* the surface, which is checked at further
points (``ValueError`` otherwise).  Arithmetics: mpmath (any alpha) or exact rationals (rational-tangent
alpha and a surface that maps rational points to rationals, e.g. trigonometric polynomials with
rational coefficients, evaluated through :class:`ExactTrig`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from flint import fmpq

from paper_repro.core.collocation import collocate
from paper_repro.core.context import Context, ExactContext, FloatContext, MpContext, get_context
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    half_angle_values,
    mp_domain_points,
    sample_points,
    sample_rational_points,
)
from paper_repro.core.fourier import cos_sin_combination, full_angles
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.util.limits import MAX_DPS, MAX_N_FIT, MAX_N_FIT_EXACT, MAX_N_FIT_FLOAT, MIN_DPS, check_int
from paper_repro.util.validation import check_alpha


@dataclass
class ExactTrig:
    """sin/cos of integer combinations of u, v, w at a rational point, exactly (for exact fitting)."""

    full: list[tuple[fmpq, fmpq]]  # (cos, sin) of u, v, w

    def _cs(self, r: int, g: int, b: int) -> tuple[fmpq, fmpq]:
        return cos_sin_combination(self.full, (r, g, b), _EXACT, fmpq(1))

    def cos(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[0]

    def sin(self, r: int = 0, g: int = 0, b: int = 0) -> fmpq:
        return self._cs(r, g, b)[1]


_EXACT = ExactContext()


def exact_trig_points(pts: RationalPoints) -> list[ExactTrig]:
    half = half_angle_values(pts, None, _EXACT)
    full = full_angles(half, _EXACT)
    return [ExactTrig([(c[k], s[k]) for c, s in full]) for k in range(len(pts))]


def surface_coordinates(rows, exact: bool) -> list[list]:
    """What a surface returned at each point, checked: a sequence (not text) of the same number (>= 1) of real
    finite coordinates at every point -- rationals (``fmpq``, ``int``, ``Fraction``; a finite float is its binary
    value) in exact arithmetic.  ``TypeError``/``ValueError`` naming ``surface`` and the point otherwise (complex,
    text, a changing coordinate count, NaN: mpmath's and flint's own words reached the user).

    >>> surface_coordinates([[1, 2], (3, 4)], exact=False)
    [[1, 2], [3, 4]]
    >>> surface_coordinates([[1, 2], [3]], exact=False)
    Traceback (most recent call last):
    ...
    ValueError: surface returned 1 coordinate(s) at point 1 but 2 at point 0: it must return the same number everywhere
    """
    import math
    from fractions import Fraction

    import mpmath

    from paper_repro.util.limits import real_scalar

    out: list[list] = []
    for k, row in enumerate(rows):
        if isinstance(row, (str, bytes)) or not hasattr(row, "__iter__"):
            raise TypeError(f"surface must return a sequence of coordinates, got {row!r} at point {k}")
        row = list(row)
        if not row:
            raise ValueError(f"surface returned no coordinates at point {k}")
        if out and len(row) != len(out[0]):
            raise ValueError(f"surface returned {len(row)} coordinate(s) at point {k} but {len(out[0])} at point 0: "
                             "it must return the same number everywhere")
        for x in row:
            x = real_scalar(x, f"surface coordinates (point {k})")
            if exact and not isinstance(x, (int, float, Fraction, fmpq)) and type(x).__name__ != "fmpz":
                raise TypeError(f"surface coordinates (point {k}) must be exact rationals in exact arithmetic, got "
                                f"{type(x).__name__}")
            finite = math.isfinite(x) if isinstance(x, float) else \
                bool(mpmath.isfinite(x)) if type(x).__name__ == "mpf" else \
                x.is_finite() if type(x).__name__ == "arb" else True
            if not finite:
                raise ValueError(f"surface coordinates (point {k}) must be finite, got {x!r}")
        out.append(row)
    return out


def fit_exact(surface: Callable[[ExactTrig], list[fmpq]], n: int, alpha: RationalAngle, verify: int = 4,
              seed: int = 21) -> list[list[fmpq]]:
    """Exact control net (rows in internal order) of ``surface``, a function of :class:`ExactTrig`.

    ``ValueError`` if the surface is not in the span (the verification points disagree).
    """
    n = check_int(n, "n", 1, MAX_N_FIT_EXACT, why="exact collocation with delta_n unknowns; see the README table")
    if not isinstance(alpha, RationalAngle):
        raise TypeError(f"alpha must be a RationalAngle for exact fitting, got {type(alpha).__name__}")
    d = delta(n)

    def system(k: int):
        pts = sample_rational_points(alpha, d + verify, seed=seed + k)
        basis = evaluate_normalized(n, alpha, pts, _EXACT)
        return basis, _EXACT.asarray(surface_coordinates([surface(t) for t in exact_trig_points(pts)], exact=True))

    try:
        net = collocate(_EXACT, system, d, what="fit").solution
    except ArithmeticError as exc:
        raise ValueError(f"surface: its coordinates are not in the span of T_{{{2 * n}}} ({exc})") from None
    return net.tolist()


def fit_mp(surface: Callable, n: int, alpha, dps: int = 40, verify: int = 4, seed: int = 21,
           tol_digits: int | None = None) -> np.ndarray:
    """Control net (object array of mpf) of ``surface(u, v, w) -> sequence`` by collocation in mpmath.

    ``ValueError`` if the surface is not in the span: the residual at the verification points exceeds
    ``10^-(tol_digits)`` relative (default ``dps - 15`` digits).
    """
    n = check_int(n, "n", 1, MAX_N_FIT, why="mp collocation with delta_n unknowns; see the README table")
    check_alpha(alpha)
    dps = check_int(dps, "dps", MIN_DPS, MAX_DPS)
    if tol_digits is not None:
        tol_digits = check_int(tol_digits, "tol_digits", 1, dps - 1,
                               why="the verification tolerance 10^-tol_digits must lie above the working precision")
    d = delta(n)
    ctx = MpContext(dps=dps)

    def system(k: int):
        with ctx.scope():
            a = ctx.convert(alpha)
            pts = mp_domain_points(a, d + verify, seed + k)
            basis = evaluate_normalized(n, a, pts, ctx)
            return basis, _values(surface, pts, "mp")

    try:
        res = collocate(ctx, system, d, what="fit", rtol=10.0 ** (-(tol_digits or dps - 15)))
    except ArithmeticError as exc:
        raise ValueError(f"surface: not in the span of T_{{{2 * n}}} ({exc})") from None
    return res.solution


def _values(surface: Callable, pts, route: str) -> np.ndarray:
    """``surface`` at every point, as rows; a surface written for another arithmetic gets one sentence."""
    try:
        rows = [surface(*p) for p in pts]
    except TypeError as exc:
        if route == "mp":
            need = ("mpmath numbers (mpf): write it with mpmath (mpmath.sin, ...), or fit a numpy-written "
                    "surface with arith='float'")
        else:
            need = "Python floats u, v, w and returns a sequence of real coordinates"
        raise TypeError(f"surface: fit(..., {route!r}) calls it with {need} (it raised {exc})") from None
    return np.array(surface_coordinates(rows, exact=False), dtype=object)  # checked: real, finite, same count


def fit_float(surface: Callable, n: int, alpha, verify: int = 8, seed: int = 21, rtol: float = 1e-9) -> np.ndarray:
    """Control net (float64 ``(delta_n, d)``) of ``surface(u, v, w) -> sequence`` called with floats.

    For a surface written with numpy (``np.sin``): least squares in the normalized basis at ``2 delta_n``
    seeded points of Omega^alpha, verified at ``verify`` further points.  ``ValueError`` if the residual there
    exceeds ``rtol`` times the size of the terms (the surface is not in the span, or float64 cannot tell).

    >>> import numpy as np
    >>> net = fit_float(lambda u, v, w: (np.cos(u), np.sin(v)), 1, np.pi / 2)
    >>> net.shape
    (7, 2)
    """
    n = check_int(n, "n", 1, MAX_N_FIT_FLOAT, why="float least squares with delta_n unknowns")
    check_alpha(alpha)
    verify = check_int(verify, "verify", 1, 10_000)
    alpha = float(alpha)
    d = delta(n)
    pts = sample_points(alpha, 2 * d + verify, seed=seed)
    values = _values(surface, pts, "float")
    try:
        values = values.astype(np.float64)
    except (TypeError, ValueError):
        raise TypeError("surface: fit(..., 'float') needs real coordinates convertible to float64, got "
                        f"{type(values.flat[0]).__name__}") from None
    if values.ndim != 2 or not np.all(np.isfinite(values)):
        raise ValueError("surface: fit(..., 'float') needs a finite sequence of coordinates at every point")
    basis = evaluate_normalized(n, alpha, pts)
    net = np.linalg.lstsq(basis[:2 * d], values[:2 * d], rcond=None)[0]
    resid = np.abs(basis[2 * d:] @ net - values[2 * d:])
    scale = max(float(np.max(np.abs(basis[2 * d:]) @ np.abs(net))), float(np.max(np.abs(values))), 1e-300)
    if float(np.max(resid)) > rtol * scale:
        raise ValueError(f"surface: not in the span of T_{{{2 * n}}} in float64 (residual {float(np.max(resid)):.1e}"
                         f" of {scale:.1e} at the {verify} verification points; allowed {rtol:g} relative)")
    return net


def fit(surface: Callable, n: int, alpha, arith: str | Context = "mp", **kwargs):
    """Control net of ``surface`` in the normalized basis of order ``n`` (collocation, verified).

    Exact arithmetics: ``alpha`` a :class:`RationalAngle`, ``surface(trig) -> coordinates`` called with an
    :class:`ExactTrig` (exact sin/cos of integer combinations of u, v, w); returns rows of rationals.
    ``'mp'``: ``surface(u, v, w) -> coordinates`` called with mpmath numbers (write it with ``mpmath.sin``);
    returns an object array of mpf (``dps`` keyword, default 40).  ``'float'``: called with floats (write it
    with ``numpy``); returns float64 (:func:`fit_float`).  ``ValueError`` if the surface is not in the span.

    >>> from flint import fmpq
    >>> from paper_repro.core.domain import rational_alpha
    >>> net = fit(lambda t: [t.cos(1, 0, 0), t.sin(0, 1, 0)], 1, rational_alpha(fmpq(1, 3)), "exact")
    >>> len(net), len(net[0])
    (7, 2)
    """
    if not callable(surface):
        raise TypeError(f"surface must be callable, got {type(surface).__name__}")
    ctx = get_context(arith)
    if ctx.exact:
        return fit_exact(surface, n, alpha, **kwargs)
    if isinstance(ctx, FloatContext):
        return fit_float(surface, n, alpha, **kwargs)
    return fit_mp(surface, n, alpha, **kwargs)


#: The boundary curves of a patch: the edge of Omega^alpha and the point of it at parameter t
#: (as in :meth:`paper_repro.surfaces.patch.Patch.boundary_curve`: t is w on u=0, u on v=0, v on w=0).
EDGES: dict[str, Callable[[np.ndarray, float], np.ndarray]] = {
    "u=0": lambda t, a: np.stack([0.0 * t, a - t, t], axis=1),
    "v=0": lambda t, a: np.stack([t, 0.0 * t, a - t], axis=1),
    "w=0": lambda t, a: np.stack([a - t, t, 0.0 * t], axis=1),
}


def _columns_on(basis: np.ndarray) -> np.ndarray:
    """Indices of the basis functions that do not vanish at the given points."""
    return np.flatnonzero(np.abs(basis).max(axis=0) > 1e-14)


def fit_least_squares(points, values, n: int, alpha, *, corners=None, boundary=None,
                      full_output: bool = False):
    """Control net of order ``n`` whose patch fits scattered data ``values`` at ``points`` by least squares.

    The patch is ``sum_k p_k T-bar_k(u, v, w)`` (eq. triangular_trig_surface); the free control points minimise
    ``sum_i |patch(points_i) - values_i|^2`` (float64, ``numpy.linalg.lstsq``).  Optionally some control points
    are fixed first, so that the patch *interpolates*:

    * ``corners``: a ``(3, d)`` array, the surface points at the corners ``(alpha, 0, 0)``, ``(0, alpha, 0)``,
      ``(0, 0, alpha)`` of Omega^alpha (the patch passes through a corner control point there: eqs.
      boundary_property_1..3), or ``True`` to take them from the data (points at the corners must then be
      among ``points``);
    * ``boundary``: ``{edge: curve}`` with edge ``'u=0'``, ``'v=0'`` or ``'w=0'`` and ``curve(t) -> (m, d)``
      points for parameters ``t`` in ``[0, alpha]`` (t is w on u=0, u on v=0, v on w=0, as in
      :meth:`~paper_repro.surfaces.patch.Patch.boundary_curve`).  The 2n+1 control points of that edge are
      fitted to the curve at 8n + 1 parameters; if the curve lies in the span of the boundary basis
      (eq. univariate_basis) the patch reproduces it exactly.  A corner shared with a fitted edge must agree
      with it (``ValueError`` otherwise).

    ``points`` are ``(P, 3)`` points of Omega^alpha (or :func:`~paper_repro.core.domain.sample_points`),
    ``values`` a ``(P, d)`` array, ``alpha`` a number or text such as ``"pi/2"``.  Returns the net as a
    :class:`~paper_repro.core.nets.LabelledNet` (``net["r_{4,3,1}"]``), and with ``full_output`` also the
    root-mean-square residual at the data points.

    >>> import numpy as np
    >>> from paper_repro import Patch, sample_points
    >>> truth = Patch(2, "pi/2", np.random.default_rng(1).normal(size=(19, 3)))
    >>> pts = sample_points("pi/2", 200, seed=2)
    >>> net, rms = fit_least_squares(pts, truth(pts), 2, "pi/2", full_output=True)
    >>> bool(np.allclose(net, truth.net)), rms < 1e-12
    (True, True)
    >>> curve = lambda t: truth.boundary_curve("v=0", t)
    >>> fixed = fit_least_squares(pts[:30], truth(pts[:30]) + 0.1, 2, "pi/2", boundary={"v=0": curve})
    >>> bool(np.allclose(Patch(2, "pi/2", fixed).boundary_net("v=0"), truth.boundary_net("v=0")))
    True
    """
    from paper_repro.core.domain import check_points
    from paper_repro.core.nets import LabelledNet
    from paper_repro.util.limits import check_real_array
    from paper_repro.util.validation import check_n, parse_alpha

    n = check_n(n)
    a = float(parse_alpha(alpha))
    pts = check_points(points, a)
    if not isinstance(full_output, (bool, np.bool_)):
        raise TypeError(f"full_output must be True or False, got {full_output!r}")
    if boundary is not None and not isinstance(boundary, dict):
        raise TypeError(f"boundary must be a dict {{edge: curve}} with edges {sorted(EDGES)}, got "
                        f"{type(boundary).__name__}")
    for edge, curve in (boundary or {}).items():
        if edge not in EDGES:
            raise ValueError(f"boundary: edges are {sorted(EDGES)}, got {edge!r}")
        if not callable(curve):
            raise TypeError(f"boundary[{edge!r}] must be a callable curve(t) -> (m, d) points, got "
                            f"{type(curve).__name__}")
    if isinstance(corners, (str, bytes)):
        raise TypeError(f"corners must be a (3, d) array of real numbers or True, got the string {corners!r:.40}")
    if not (corners is None or isinstance(corners, (bool, np.bool_))):
        check_real_array(corners, "corners")
    check_real_array(values, "values")
    vals = np.asarray(values, dtype=np.float64)
    if vals.ndim == 1:
        vals = vals[:, None]
    if vals.ndim != 2 or vals.shape[0] != len(pts) or not np.isfinite(vals).all():
        raise ValueError(f"values must be a finite ({len(pts)}, d) array, one row per point; got shape "
                         f"{np.shape(values)}")
    d = vals.shape[1]
    size = delta(n)
    fixed: dict[int, np.ndarray] = {}

    def fix(k: int, p: np.ndarray, what: str) -> None:
        if k in fixed and not np.allclose(fixed[k], p, rtol=1e-9, atol=1e-9 * (1 + np.abs(p).max())):
            raise ValueError(f"{what}: the control point {k} is fixed twice with different values "
                             f"({fixed[k].tolist()} and {p.tolist()}): corners and boundary curves must agree")
        fixed[k] = p

    for edge, curve in (boundary or {}).items():
        t = np.linspace(0.0, a, 8 * n + 1)
        raw = curve(t)
        check_real_array(raw, f"boundary[{edge!r}] curve points")
        target = np.asarray(raw, dtype=np.float64)
        if target.ndim == 1 and d == 1 and target.shape == t.shape:
            target = target[:, None]
        if target.shape != (len(t), d):
            raise ValueError(f"boundary[{edge!r}]: curve(t) must return a ({len(t)}, {d}) array for {len(t)} "
                             f"parameters t (one point of the data's dimension {d} per t), got shape "
                             f"{target.shape}")
        if not np.isfinite(target).all():
            raise ValueError(f"boundary[{edge!r}]: curve(t) must return finite points, got NaN or infinity")
        b = np.asarray(evaluate_normalized(n, a, EDGES[edge](t, a)), dtype=np.float64)
        cols = _columns_on(b)
        sol = np.linalg.lstsq(b[:, cols], target, rcond=None)[0]
        for k, p in zip(cols, sol):
            fix(int(k), p, f"boundary[{edge!r}]")
    if corners is not None and corners is not False:
        corner_pts = a * np.eye(3)
        if corners is True:
            hit = [np.flatnonzero(np.abs(pts - c).max(axis=1) <= 1e-12 * a) for c in corner_pts]
            if any(len(h) == 0 for h in hit):
                raise ValueError("corners=True: the points must include the three corners of Omega^alpha")
            cvals = np.stack([vals[h[0]] for h in hit])
        else:
            cvals = np.asarray(corners, dtype=np.float64)
            if cvals.shape != (3, d) or not np.isfinite(cvals).all():
                raise ValueError(f"corners must be a finite (3, {d}) array (the surface at (alpha,0,0), "
                                 f"(0,alpha,0), (0,0,alpha)) or True, got shape {np.shape(corners)}"
                                 + ("" if cvals.shape != (3, d) else " with NaN or infinity"))
        b = np.asarray(evaluate_normalized(n, a, corner_pts), dtype=np.float64)
        for row, p in zip(b, cvals):
            cols = _columns_on(row[None, :])
            if len(cols) != 1:  # pragma: no cover - the endpoint property (boundary_property_1..3) says one
                raise ArithmeticError(f"corner: {len(cols)} basis functions do not vanish at a corner")
            fix(int(cols[0]), p, "corners")
    basis = np.asarray(evaluate_normalized(n, a, pts), dtype=np.float64)
    free = [k for k in range(size) if k not in fixed]
    rhs = vals.copy()
    net = np.zeros((size, d))
    for k, p in fixed.items():
        net[k] = p
        rhs -= np.outer(basis[:, k], p)
    if free:
        if len(pts) < len(free):
            raise ValueError(f"points: {len(free)} free control points need at least as many data points, "
                             f"got {len(pts)}")
        sol, _, rank, _ = np.linalg.lstsq(basis[:, free], rhs, rcond=None)
        if rank < len(free):
            raise ValueError(f"points: the data points do not determine the {len(free)} free control points "
                             f"(rank {rank}); give more points spread over Omega^alpha")
        net[free] = sol
    out = LabelledNet(net, n)
    if full_output:
        rms = float(np.sqrt(np.mean((basis @ net - vals) ** 2)))
        return out, rms
    return out
