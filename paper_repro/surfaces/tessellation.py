"""Adaptive tessellation of a patch (eq. triangular_trig_surface) by midpoint subdivision, within a tolerance.

Beyond the paper.  The proofs and the measurements: ``docs/tessellation.md``.

The bound (proven, §2 of docs/tessellation.md).  Write a patch over the parameter plane (u, v) (w = beta - u - v).

* *Second derivatives from the net.*  For every n the derivative of a patch is a patch of the same order and the
  same alpha (the closed-form matrix C of :func:`~paper_repro.core.half_angle_matrices.derivative_nets`, proven for
  every n in docs/elevation_and_derivative_for_all_n.md).  So s_uu, s_uv, s_vv are patches with nets
  P_uu, P_uv, P_vv (:func:`second_derivative_nets`), and by the convex hull property (the blending functions are
  non-negative and sum to 1: claim ``partition_of_unity``; non-negativity for every n by Corollary C of
  docs/question1_for_all_n.md, a hand proof beyond the paper, and by claim ``nonnegativity_extended`` for
  n <= 12 -- the paper proves it only for n <= 3, claim ``nonnegativity``) |s_ab(x)| <= m_ab = max_f |P_ab,f|
  on the whole triangle.  Hence every second directional derivative, unit direction e in (u, v), satisfies
  |D^2 s(x)[e, e]| <= M = lambda_max([[m_uu, m_uv], [m_uv, m_vv]]) (:func:`second_derivative_bound`).
* *Linear interpolation.*  On a triangle tau of the (u, v) plane whose vertices lie in a disc of radius rho, the
  affine interpolant I of s at its vertices satisfies |s(x) - I(x)| <= M rho^2 / 2 for x in tau (Taylor with
  integral remainder, and sum_i lambda_i |x - x_i|^2 = sum_i lambda_i |x_i - c|^2 - |x - c|^2 <= rho^2 for the
  disc's centre c).  Every triangle the tessellator emits lies in one cell of its leaf's grid, a right-isosceles
  triangle of hypotenuse l, inside the disc of radius l / 2 about the hypotenuse's midpoint (Thales): so
  |s - I| <= M l^2 / 8 (:data:`INTERPOLATION_DIVISOR`; l^2 / 6 holds on every triangle).

Midpoint subdivision (:mod:`paper_repro.core.subdivision`) gives the nets of the sub-patches; the sub-triangles are
images of Omega^{alpha/2} by translations and point reflections of (u, v), isometries, so the bound of a sub-net
holds for the parent patch over that sub-triangle.  Under subdivision M tends to the true maximum of the second
derivative (the derivative's nets converge to it, measured in docs/tessellation.md), so refining the tree tightens
the bound; a leaf is then cut into a uniform grid of r steps, r chosen so that M l^2 / 8 <= tol.

Cracks: neighbouring leaves of different depth or grid step share their edge points.  Every leaf edge takes every
mesh point that any leaf puts on the same segment; a grid cell with such extra points on its boundary is
re-triangulated as a fan around its centroid (a new surface point).  Every triangle of the fan lies inside the
cell, so its longest edge is at most the cell's and the bound holds unchanged.  The mesh is conforming: along every
shared segment both sides use the same sorted points.

Vertices are evaluated on the given patch (:class:`~paper_repro.surfaces.patch.Patch`, float64), not taken from the
sub-nets.  What is proven and what is measured depends on the arithmetic (``arith``):

* ``'float'`` (default): the inequality is proven; it is evaluated in float64 (the sub-nets, their derivative nets
  and the vertices carry rounding errors, not bounded rigorously; M is multiplied by :func:`rounding_factor` of the
  depth and an allowance for the vertices is subtracted from tol, see :func:`tessellate`), and the tests verify the
  deviation a posteriori by dense sampling.
* ``'ball'`` (python-flint arb; docs/tessellation.md, "Rigorous route (ball arithmetic)"): the sub-nets and the
  second-derivative nets are balls containing the exact ones of the float64 input net (taken as exact); M is the
  upper end of a ball enclosing lambda_max of the 2 x 2 matrix of upper bounds of the m_ab; the leaf bounds are
  upper ends of balls; the vertices are s at the exact lattice parameters (rational multiples of alpha, the fan
  centroids too) evaluated in balls and rounded to float64, with |s(x_i) - vertex_i| bounded by the ball's radius
  plus the rounding.  ``Tessellation.bound`` is then a proven upper bound of max_x |s(x) - mesh(x)|, mesh the
  piecewise-linear interpolant of the returned float64 vertices over the exact lattice triangulation; no measured
  allowance is used.  ``params`` are those exact parameters rounded to float64.
* ``'mp'`` (mpmath at ``dps`` digits): the same computation, not rigorous; the allowances of the float route with
  2^-52 replaced by mpmath's 2^-prec (floor 10^(6 - dps)).

>>> import numpy as np
>>> from paper_repro.core.labels import delta
>>> rng = np.random.default_rng(1)
>>> mesh = tessellate(rng.random((delta(1), 3)), 1, 1.0, 1e-3)
>>> mesh.points.shape[1], mesh.triangles.shape[1], bool(mesh.bound <= 1e-3)
(3, 3, True)
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import lru_cache
from typing import NamedTuple

import mpmath
import numpy as np
from flint import arb, arb_mat, fmpq, fmpz

from paper_repro.core.basis import monomials
from paper_repro.core.context import BallContext, Context, FloatContext, MpContext, get_context
from paper_repro.core.domain import RationalAngle, open_alpha
from paper_repro.core.half_angle_matrices import derivative_nets, derivative_nets_checked
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.nets import check_net, check_net_exact
from paper_repro.core.normalization import scaled_coefficient_vector, scaled_float_vector
from paper_repro.core.subdivision import _arb_of, _certified, subdivision_matrices
from paper_repro.surfaces.patch import Patch, triangle_grid
from paper_repro.util.limits import check_int, real_scalar
from paper_repro.util.validation import check_alpha, parse_alpha

#: Largest order: each level of the tree needs the four subdivision matrices at a new alpha / 2^k (certified ball
#: arithmetic, :func:`~paper_repro.core.subdivision.subdivision_matrices`); measured cold per level on the loaded
#: machine: n = 2 about 0.02 s, n = 4 about 0.5 s, n = 6 1-2 s, so n <= 6 keeps a tree of 10 levels under ~20 s.
MAX_N_TESSELLATE = 6
#: Largest depth of the subdivision tree.
MAX_TESSELLATE_DEPTH = 14
#: Default vertex budget: about 0.9 s CPU per million vertices at n = 2 (tree, grids, welding, evaluation; 1.5 s CPU
#: for the 1.7 M vertices of the torus piece at tol 1e-6, tools/tessellation_bench.py, docs/tessellation.md §3), and
#: about 250 bytes per vertex at the peak: 4 M vertices stay below ~5 s CPU and 1 GB.
MAX_VERTICES = 4_000_000
#: Largest tree level population (nodes times delta_n times d floats kept per level).
MAX_TREE_FLOATS = 20_000_000
#: Early refusal: the tree stops when its current level asks for more than this many times max_vertices.
EARLY_REFUSAL = 16
#: The interpolation constant: |s - I| <= M l^2 / INTERPOLATION_DIVISOR on every triangle inside a right-isosceles
#: grid cell of hypotenuse l (the disc lemma, docs/tessellation.md §2, Lemma B; 6 on an arbitrary triangle).
INTERPOLATION_DIVISOR = 8.0
#: Floor of the relative allowance for float64 rounding in M (the sub-nets, their derivative nets; not proven).
ROUNDING_ALLOWANCE = 1e-6
#: Depth-aware part of the allowance: C 4^k eps at depth k.  Measured (float tree against a 40-digit tree, chains to
#: depth 14, n = 2 and 6, docs/tessellation.md §3): |relative error of M| <= 4.2 * 4^k eps; C = 256 is 60 times that.
ROUNDING_GROWTH = 256.0
#: Allowed leaf grid steps: m 2^j with m in {1, 3, 5, 7}, j <= 10 (consecutive steps differ by a factor 2, 1.5, 1.33
#: from 1 to 4 and by at most 1.25 from 4 on), so all points lie on one lattice alpha / (105 * 2^K).
LATTICE = 105
_STEPS = sorted({m << j for m in (1, 3, 5, 7) for j in range(0, 11)})
#: Measured floor of alpha on the float route: below about 1e-75.5 (n = 1..6, bisection on random nets,
#: docs/tessellation.md "Referee report and answers (ball route)", point 5) the float64 second-derivative nets
#: overflow (NaN) and the tree refuses at once, naming alpha.
FLOAT_ALPHA_FLOOR = 1e-75
#: Largest K of the lattice (the line keys, below about 5.5 * (4 * 105 * 2^K)^2, stay below 2^63).
MAX_LATTICE_BITS = 21


class Tessellation(NamedTuple):
    """A triangle mesh of a patch: ``points`` ``(V, d)`` on the surface, ``triangles`` ``(F, 3)`` vertex indices,
    ``params`` ``(V, 3)`` the points' (u, v, w) on Omega^alpha, ``bound`` the proven bound (evaluated in float64
    with measured allowances on the float route, in mpmath on the mp route, rigorously in ball arithmetic on the
    ball route) of the parametric deviation max |s(x) - mesh(x)| (mesh(x) the piecewise-linear map of the parameter
    triangulation; it bounds the distance of every mesh point from the surface and of every surface point from the
    mesh), ``leaves`` the number of subdivision leaves, ``depth`` the deepest one and ``fans`` the number of grid
    cells re-triangulated around their centroid to take a neighbour's edge points (no cracks)."""

    points: np.ndarray
    triangles: np.ndarray
    params: np.ndarray
    bound: float
    leaves: int
    depth: int
    fans: int


# --- the bound --------------------------------------------------------------------------------------------------
@lru_cache(maxsize=64)
def _coefficients(n: int, beta: float) -> np.ndarray:
    """The normalizing factors ``T-bar_f = coef_f m_f`` of the scaled monomials m_f (positive for every n)."""
    return scaled_float_vector(n, beta)


def derivative_nets_t(nets: np.ndarray, n: int, beta: float) -> tuple[np.ndarray, np.ndarray]:
    """The nets, in the normalized basis T-bar^beta, of d/du and d/dv (w = beta - u - v) of the patches with nets
    ``nets`` (``(N, delta_n, d)``): ``(N, delta_n, d)`` each.  From the closed-form derivative matrix C on the scaled
    monomials (:func:`~paper_repro.core.half_angle_matrices.derivative_nets`): with T-bar_f = coef_f m_f,
    ``D P = diag(1/coef) C diag(coef) P / (2 sin(beta/2))``.

    >>> import numpy as np
    >>> du, dv = derivative_nets_t(np.ones((1, 7, 2)), 1, 1.0)   # a constant patch: zero derivative
    >>> float(abs(du).max()), float(abs(dv).max())
    (0.0, 0.0)
    """
    count, dn, dim = nets.shape
    coef = _coefficients(n, beta)
    flat = np.ascontiguousarray(nets.transpose(1, 0, 2).reshape(dn, count * dim))
    qu, qv = derivative_nets(n, beta, coef[:, None] * flat)
    scale = 1.0 / (2.0 * math.sin(beta / 2.0) * coef[:, None])
    back = (lambda q: (q * scale).reshape(dn, count, dim).transpose(1, 0, 2))
    return back(qu), back(qv)


def second_derivative_nets(nets: np.ndarray, n: int, beta: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The nets of s_uu, s_uv, s_vv (in T-bar^beta) of the patches with nets ``nets`` (``(N, delta_n, d)``).  The
    nets are centred first (derivatives ignore a translation; less cancellation)."""
    centred = nets - nets.mean(axis=1, keepdims=True)
    du, dv = derivative_nets_t(centred, n, beta)
    duu, duv = derivative_nets_t(du, n, beta)
    _, dvv = derivative_nets_t(dv, n, beta)
    return duu, duv, dvv


def second_derivative_bound(nets, n: int, beta: float) -> np.ndarray:
    """For each net (``(N, delta_n, d)`` or one ``(delta_n, d)``), M with |D^2 s(x)[e, e]| <= M for every x of
    Omega^beta and every unit direction e of the (u, v) plane: the largest eigenvalue of
    [[m_uu, m_uv], [m_uv, m_vv]], m_ab = max_f |P_ab,f| (proven: the convex hull property of the second-derivative
    patches; evaluated in float64).

    >>> import numpy as np
    >>> from paper_repro.core.labels import delta
    >>> float(second_derivative_bound(np.zeros((delta(2), 3)), 2, 1.0)[0])
    0.0
    """
    arr = np.asarray(nets, dtype=np.float64)
    if arr.ndim == 2:
        arr = arr[None]
    duu, duv, dvv = second_derivative_nets(arr, n, beta)
    m_uu, m_uv, m_vv = (np.linalg.norm(x, axis=2).max(axis=1) for x in (duu, duv, dvv))
    return 0.5 * (m_uu + m_vv) + np.sqrt(0.25 * (m_uu - m_vv) ** 2 + m_uv ** 2)


def rounding_factor(depth: int) -> float:
    """The factor applied to the float64 M of the nodes at ``depth`` k: 1 + max(:data:`ROUNDING_ALLOWANCE`,
    :data:`ROUNDING_GROWTH` 4^k eps).  The relative error of M measured against a 40-digit tree grows like 4^k eps
    (the second-derivative nets of a sub-net of side h = alpha / 2^k amplify its rounding by about 1/h^2);
    docs/tessellation.md §3.  Not a proven bound.

    >>> rounding_factor(0) == 1 + ROUNDING_ALLOWANCE, rounding_factor(14) > 1 + 3e-6
    (True, True)
    """
    return 1.0 + max(ROUNDING_ALLOWANCE, ROUNDING_GROWTH * 4.0 ** depth * 2.0 ** -52)


def _need(beta: float, m_bound: np.ndarray, tol: float) -> np.ndarray:
    """The unrounded grid step: M l^2 / 8 = M beta^2 / (4 r^2) <= tol, l = sqrt(2) beta / r."""
    return beta * np.sqrt(np.maximum(m_bound, 0.0) * 2.0 / (INTERPOLATION_DIVISOR * tol))


def steps_for(beta: float, m_bound: np.ndarray, tol: float) -> np.ndarray:
    """The grid steps r per leaf (allowed values m 2^j, m in {1, 3, 5, 7}, j <= 10, so r <= 7168) with
    ``M l^2 / 8 <= tol``, l = sqrt(2) beta / r the hypotenuse of a grid cell (legs beta / r in the (u, v) plane):
    r >= beta sqrt(M / (4 tol)).  ``ValueError`` naming tol when more than 7168 steps are needed.

    >>> steps_for(1.0, np.array([4.0, 400.0, 401.0]), 1.0).tolist()   # need 1, 10, 10.01
    [1, 10, 12]
    """
    need = _need(beta, m_bound, tol)
    idx = np.searchsorted(np.array(_STEPS, dtype=np.float64), need, side="left")
    if idx.size and idx.max() >= len(_STEPS):
        raise ValueError(f"tol = {tol!r} needs a leaf grid of more than {_STEPS[-1]} steps; raise tol or max_depth")
    return np.array(_STEPS, dtype=np.int64)[idx]


# --- validation -------------------------------------------------------------------------------------------------
def _exact_value(x: object) -> Fraction | None:
    """A finite real number as the exact Fraction it denotes (int, float, longdouble, mpf, fmpq, fmpz, Fraction; an
    arb by its lower end), ``None`` for other types or non-finite values."""
    if isinstance(x, np.ndarray) and x.ndim == 0:
        x = x[()]
    try:
        if isinstance(x, arb):
            x = x.lower()
            if not x.is_finite():
                return None
            man, exp = x.man_exp()
            return Fraction(int(man)) * Fraction(2) ** int(exp)
        if isinstance(x, mpmath.mpf):
            if not mpmath.isfinite(x):
                return None
            man, exp = x.man_exp
            return Fraction(int(man)) * Fraction(2) ** int(exp)
        if isinstance(x, fmpq):
            return Fraction(int(x.p), int(x.q))
        if isinstance(x, fmpz):
            return Fraction(int(x))
        if isinstance(x, (np.floating, float)):
            return Fraction(*x.as_integer_ratio()) if np.isfinite(x) else None
        if isinstance(x, (int, np.integer, Fraction)) and not isinstance(x, (bool, np.bool_)):
            return Fraction(x)
    except (TypeError, ValueError, OverflowError):  # pragma: no cover - the types above convert
        return None
    return None


def _check_tol(tol: object) -> float:
    """tol as a float64 rounded *down* when it is not one (a Fraction, mpf, fmpq, longdouble, ...): a bound
    ``<= float(tol)`` is then ``<= tol`` exactly.

    >>> from fractions import Fraction
    >>> t = _check_tol(Fraction(1, 10))
    >>> Fraction(t) <= Fraction(1, 10) < Fraction(math.nextafter(t, 1.0)), _check_tol(0.1) == 0.1
    (True, True)
    """
    exact = _exact_value(tol)
    x = real_scalar(tol, "tol")
    try:
        x = float(x)
    except (TypeError, ValueError, OverflowError) as exc:  # pragma: no cover - real_scalar gives numbers
        raise TypeError(f"tol must be a positive real number, got {tol!r}") from exc
    if not math.isfinite(x) or x <= 0:
        raise ValueError(f"tol must be a positive finite real number, got {tol!r}")
    if exact is not None and Fraction(x) > exact:
        x = math.nextafter(x, 0.0)                       # round down: bound <= x <= tol
    if x <= 0:
        raise ValueError(f"tol must be a positive finite real number, got {tol!r}")
    return x


def _check_inputs(net, n, alpha, tol, leaf_resolution, max_depth, max_vertices):
    n = check_int(n, "n", 1, MAX_N_TESSELLATE, why="each tree level builds the subdivision matrices at a new alpha")
    alpha = check_alpha(parse_alpha(alpha) if isinstance(alpha, str) else alpha)
    tol = _check_tol(tol)
    leaf_resolution = check_int(leaf_resolution, "leaf_resolution", 1, 256)
    max_depth = check_int(max_depth, "max_depth", 0, MAX_TESSELLATE_DEPTH)
    max_vertices = check_int(max_vertices, "max_vertices", 3, 50_000_000)
    arr = check_net(net, n)
    if arr.shape[1] == 0:
        raise ValueError("net must have at least one coordinate column, got shape " + str(arr.shape))
    extent = float(np.abs(arr).max())
    floor = 1e-12 * max(extent, 1e-300)
    if tol <= floor:
        raise ValueError(f"tol = {tol!r} is below float64's resolution for this net (extent {extent:.3g}): "
                         f"tol must exceed 1e-12 times the largest coordinate, {floor:.3g}")
    return arr, n, alpha, tol, leaf_resolution, max_depth, max_vertices


# --- the tree ---------------------------------------------------------------------------------------------------
class _Leaves(NamedTuple):
    level: np.ndarray   # depth k
    a: np.ndarray       # right-angle vertex (a, b) in units alpha / 2^(max_depth + 1)
    b: np.ndarray
    sign: np.ndarray    # +1: (u', v') -> (a + u', b + v'); -1: (a - u', b - v')
    steps: np.ndarray   # r
    bound: np.ndarray   # M beta^2 / (4 r^2) = M l^2 / 8


def _leaves_of_level(k: int, beta: float, m_bound: np.ndarray, tol: float, floats_per_node: int,
                     leaf_resolution: int, max_depth: int, max_vertices: int) -> np.ndarray:
    """Which nodes of tree level ``k`` (legs ``beta``, bounds ``m_bound``) are leaves: those whose unrounded step
    need is at most ``leaf_resolution``, or all of them at ``max_depth`` or when the next level would hold more than
    :data:`MAX_TREE_FLOATS` floats.  Refuses (``ValueError`` naming tol and max_vertices) a level whose grids would
    need more than :data:`EARLY_REFUSAL` times ``max_vertices`` vertices.  The float and the ball/mp trees share it."""
    need = _need(beta, m_bound, tol)
    estimate = float(((need + 2) * (need + 3) / 2).sum())
    if estimate > EARLY_REFUSAL * max_vertices:
        raise ValueError(f"tol = {tol:.3g} needs about {estimate:.3g} vertices at depth {k} (the bound of this "
                         f"level), far above max_vertices = {max_vertices}; raise tol (the count grows like 1/tol) "
                         "or max_vertices")
    last = k == max_depth or 4 * int((need > leaf_resolution).sum()) * floats_per_node > MAX_TREE_FLOATS
    return np.ones(len(m_bound), dtype=bool) if last else need <= leaf_resolution


def _tree(arr: np.ndarray, n: int, alpha: float, tol: float, leaf_resolution: int, max_depth: int,
          max_vertices: int) -> _Leaves:
    """Breadth-first subdivision: a node becomes a leaf when its unrounded grid step ``need`` is at most
    ``leaf_resolution`` (the rounded step may exceed it), at ``max_depth``, or when the next level would exceed
    :data:`MAX_TREE_FLOATS`.  Refused early (``ValueError``
    naming max_vertices) when the grids the current level asks for exceed :data:`EARLY_REFUSAL` times
    ``max_vertices``: refining lowers the count only as far as the bound tightens (measured: the bound of the root
    is at most 3.7 times the sampled maximum of the second derivative, docs/tessellation.md)."""
    dn, dim = arr.shape
    unit = 1 << (max_depth + 1)                       # root leg in lattice units
    nets = arr[None].copy()
    a = np.zeros(1, dtype=np.int64)
    b = np.zeros(1, dtype=np.int64)
    sign = np.ones(1, dtype=np.int64)
    cap = np.full(1, np.inf)                          # the ancestors' bounds hold on the node too: keep the least
    out: list[tuple] = []
    for k in range(max_depth + 1):
        beta = alpha / (1 << k)
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # an overflow is refused just below
            m_bound = np.minimum(second_derivative_bound(nets, n, beta) * rounding_factor(k), cap)
        if not np.isfinite(m_bound).all():
            raise ValueError(f"alpha = {alpha!r}: the float64 second-derivative bound M is not finite at depth {k} "
                             f"(beta = alpha / 2^{k}; the derivative nets' scaling overflows float64, measured for "
                             f"alpha below about {FLOAT_ALPHA_FLOOR:g} for n = 1..6); use arith='ball' or a larger "
                             "alpha")
        leaf = _leaves_of_level(k, beta, m_bound, tol, dn * dim, leaf_resolution, max_depth, max_vertices)
        if leaf.any():
            r = steps_for(beta, m_bound[leaf], tol)
            out.append((np.full(int(leaf.sum()), k), a[leaf], b[leaf], sign[leaf], r,
                        m_bound[leaf] * 2.0 * beta ** 2 / (INTERPOLATION_DIVISOR * r.astype(np.float64) ** 2)))
        keep = ~leaf
        if not keep.any():
            break
        half = unit >> (k + 1)
        mats = subdivision_matrices(n, beta)
        parent, pa, pb, ps = nets[keep], a[keep], b[keep], sign[keep]
        cap = np.tile(m_bound[keep], 4)
        kids = [np.einsum("ij,njd->nid", m, parent) for m in mats]
        nets = np.concatenate(kids)
        a = np.concatenate([pa + ps * half, pa, pa, pa + ps * half])
        b = np.concatenate([pb, pb + ps * half, pb, pb + ps * half])
        sign = np.concatenate([ps, ps, ps, -ps])
    cols = list(zip(*out))
    return _Leaves(*(np.concatenate(c) for c in cols))


# --- the mesh ---------------------------------------------------------------------------------------------------
@lru_cache(maxsize=32)
def _grid(r: int) -> tuple[np.ndarray, np.ndarray, dict]:
    """Integer grid ``(i, j)`` of ``r`` steps, its faces, and ``{(edge, segment): (face, local edge)}`` for the cells
    on the leaf's edges: edge 0 is j = 0 (segment i), edge 1 is i = 0 (segment j), edge 2 is i + j = r (segment j)."""
    bary, faces = triangle_grid(r)
    ij = np.rint(bary[:, :2] * r).astype(np.int64)
    cells: dict = {}
    for f, face in enumerate(faces):
        for e in range(3):
            p, q = ij[face[e]], ij[face[(e + 1) % 3]]
            if p[1] == 0 and q[1] == 0:
                cells[(0, int(min(p[0], q[0])))] = (f, e)
            elif p[0] == 0 and q[0] == 0:
                cells[(1, int(min(p[1], q[1])))] = (f, e)
            elif p.sum() == r and q.sum() == r:
                cells[(2, int(min(p[1], q[1])))] = (f, e)
    return ij, faces, cells


def _mesh(leaves: _Leaves, max_depth: int, max_vertices: int):
    """The conforming triangulation of the leaves' grids: ``(xy, faces, centroids, root)`` with ``xy`` ``(V, 2)`` the
    integer lattice points (unit alpha / root; the points on leaf edges welded, first), ``faces`` ``(F, 3)``
    indices into the points followed by the ``centroids`` ``(C, 2)`` (lattice coordinates of the fan centres)."""
    steps = leaves.steps
    bits = np.array([int(r).bit_length() for r in steps])
    big = max(max_depth + 1, int((leaves.level + bits).max()) + 1)
    if big > MAX_LATTICE_BITS:
        raise ValueError(f"the leaf grids need a lattice of alpha / (105 * 2^{big}), finer than 2^{MAX_LATTICE_BITS}: "
                         "raise tol or lower max_depth")
    scale = LATTICE * (1 << (big - max_depth - 1))    # lattice unit alpha / (105 * 2^big)
    root = LATTICE * (1 << big)
    a, b, s = leaves.a * scale, leaves.b * scale, leaves.sign
    side = root >> leaves.level
    groups = {int(r): np.nonzero(steps == r)[0] for r in np.unique(steps)}
    total = sum(len(idx) * len(_grid(r)[0]) for r, idx in groups.items())
    if total > max_vertices:
        raise ValueError(f"the mesh needs about {total} vertices, above max_vertices = {max_vertices}; raise tol "
                         "(the count grows like 1/tol) or max_vertices")
    wide = root + 1

    def lattice(idx, r, ij):
        g = (side[idx] // r)[:, None]
        return (a[idx][:, None] + s[idx][:, None] * g * ij[None, :, 0],
                b[idx][:, None] + s[idx][:, None] * g * ij[None, :, 1])

    # points on leaf edges: welded through their lattice keys; interior grid points: one id each
    bkeys = []
    for r, idx in groups.items():
        ij, _, _ = _grid(r)
        on = (ij[:, 0] == 0) | (ij[:, 1] == 0) | (ij.sum(axis=1) == r)
        x, y = lattice(idx, r, ij[on])
        bkeys.append((x * wide + y).ravel())
    ub = np.unique(np.concatenate(bkeys))
    nb = len(ub)
    xs, ys, fs, face_base, table_of = [ub // wide], [ub % wide], [], {}, {}
    nv, nf = nb, 0
    for r, idx in groups.items():
        ij, faces, _ = _grid(r)
        on = (ij[:, 0] == 0) | (ij[:, 1] == 0) | (ij.sum(axis=1) == r)
        inner = np.nonzero(~on)[0]
        table = np.empty((len(idx), len(ij)), dtype=np.int64)
        x, y = lattice(idx, r, ij[on])
        table[:, on] = np.searchsorted(ub, x * wide + y)
        table[:, inner] = nv + np.arange(len(idx) * len(inner)).reshape(len(idx), len(inner))
        if len(inner):
            x, y = lattice(idx, r, ij[inner])
            xs.append(x.ravel())
            ys.append(y.ravel())
        nv += len(idx) * len(inner)
        fs.append(table[:, faces].reshape(-1, 3))
        face_base[r], table_of[r] = nf, table
        nf += len(idx) * len(faces)
    xy = np.column_stack([np.concatenate(xs), np.concatenate(ys)])
    faces_all = np.concatenate(fs)
    # the edge points on each line of the lattice: kind 0 v = const (t = u), 1 u = const (t = v), 2 u + v = const
    # (t = v); every edge point that lies on a leaf's edge belongs to that edge's polyline
    span = 4 * root + 2

    def keys(kind, val, t):
        return (kind * span + val + root) * span + t + root

    bx, by = xy[:nb, 0], xy[:nb, 1]
    line_keys = np.unique(np.concatenate([keys(0, by, bx), keys(1, bx, by), keys(2, bx + by, by)]))
    rings: dict[int, dict[int, list]] = {}
    for r, idx in groups.items():
        _, gfaces, cells = _grid(r)
        g, si = side[idx] // r, s[idx]
        edges = ((0, b[idx], a[idx]), (1, a[idx], b[idx]), (2, a[idx] + b[idx] + si * side[idx], b[idx]))
        for e, (kind, val, t0) in enumerate(edges):
            t1 = t0 + si * side[idx]
            lo = np.searchsorted(line_keys, keys(kind, val, np.minimum(t0, t1)), "left")
            hi = np.searchsorted(line_keys, keys(kind, val, np.maximum(t0, t1)), "right")
            for m in np.nonzero(hi - lo > r + 1)[0].tolist():
                t = line_keys[lo[m]:hi[m]] - keys(kind, val[m], 0)
                d = (t - t0[m]) * si[m]                     # distance from the edge's start, in the grid direction
                gm, t0m, sm, vm = int(g[m]), int(t0[m]), int(si[m]), int(val[m])
                base_face = face_base[r] + m * len(gfaces)
                for dist in d[d % gm != 0].tolist():
                    f, le = cells[(e, dist // gm)]
                    pos = t0m + sm * dist
                    px, py = ((pos, vm), (vm, pos), (vm - pos, pos))[kind]
                    rings.setdefault(base_face + f, {}).setdefault(le, []).append(px * wide + py)
    # each cell with extra points: a fan around its centroid; ring entries are vertex ids (>= 0) or, for the extra
    # points, -(lattice key + 1), looked up in ``ub`` at once below
    new_faces: list[tuple[int, int, int]] = []
    centroids: list[tuple[float, float]] = []
    corner_rows = faces_all[list(rings)].tolist() if rings else []
    for corners, by_edge in zip(corner_rows, rings.values()):
        cxy = xy[corners].tolist()
        ring: list[int] = []
        for le in range(3):
            ring.append(corners[le])
            pts = by_edge.get(le)
            if pts:
                (x0, y0), (x1, y1) = cxy[le], cxy[(le + 1) % 3]
                dx, dy = x1 - x0, y1 - y0
                ordered = sorted(set(pts), key=lambda k: (k // wide - x0) * dx + (k % wide - y0) * dy)
                ring.extend(-(k + 1) for k in ordered)
        centroids.append(((cxy[0][0] + cxy[1][0] + cxy[2][0]) / 3.0, (cxy[0][1] + cxy[1][1] + cxy[2][1]) / 3.0))
        c = len(centroids) - 1
        new_faces.extend((c, p, q) for p, q in zip(ring, ring[1:] + ring[:1]))
    if rings:
        fan = np.array(new_faces, dtype=np.int64)
        fan[:, 0] += len(xy)
        extra = fan[:, 1:] < 0
        fan[:, 1:][extra] = np.searchsorted(ub, -fan[:, 1:][extra] - 1)
        keep = np.ones(len(faces_all), dtype=bool)
        keep[list(rings)] = False
        faces_all = np.concatenate([faces_all[keep], fan])
    return xy, faces_all, np.array(centroids, dtype=np.float64).reshape(-1, 2), root


# --- the ball and mp routes -------------------------------------------------------------------------------------
#: The arithmetics of :func:`tessellate`.
ARITHS = ("float", "ball", "mp")
#: Default digits of the ball route (working precision 3.33 dps + 20 bits) and of the mp route.
DEFAULT_DPS = 30
#: dps accepted by the ball and mp routes (the cost of every arb/mpf operation grows with it).
MIN_TESS_DPS, MAX_TESS_DPS = 16, 200
#: Work limit of the ball and mp routes, in vertices times delta_n: every vertex is evaluated at its exact lattice
#: parameter in arb (mpf), about 6 + 6 delta_n ball operations.  Measured on the torus piece (elevated for n >= 3;
#: tools/tessellation_ball_cost.py, docs/tessellation.md, "Rigorous route"): 16 us of CPU per vertex at n = 1
#: (delta 7) to 230 us at n = 6 (delta 127), about 1.6-2.3 us per vertex and function (wall 2-3 times more on the
#: loaded 2-core machine); 2.5 M keeps the ball route's vertices near 5 s CPU, 15 s wall (131 578 vertices at n = 2,
#: 19 685 at n = 6).  The default ``max_vertices`` of these routes is 2.5 M // delta_n, and a larger one is refused.
MAX_BALL_WORK = 2_500_000
#: Tree limit of the ball and mp routes, in nodes times delta_n (summed over the levels): a node costs about 70 us
#: per function in ball arithmetic (its second-derivative nets and four children, measured at n = 2 and 6 from depth
#: 3 on: 1.2 ms per node at n = 2, 28 ms at n = 6), so 200 000 keeps the tree near 15 s (10 500 nodes at n = 2).
MAX_BALL_TREE_WORK = 200_000


def _up(x) -> float:
    """The smallest float64 >= the upper end of the ball ``x`` (a rigorous float upper bound; inf if unbounded)."""
    u = x.upper()
    f = float(u)
    if not math.isfinite(f) or not u.is_finite():
        return math.inf
    while not arb(f) >= u:
        f = math.nextafter(f, math.inf)
    return f


def _check_arith(arith: object, dps: object) -> tuple[Context, int | None]:
    """The context of ``arith`` (one of :data:`ARITHS`, read by :func:`~paper_repro.core.context.get_context`) and
    the digits of the ball/mp routes (``None`` for float64, which takes no ``dps``)."""
    if not isinstance(arith, str) or arith not in ARITHS:
        raise ValueError(f"arith must be one of {list(ARITHS)}, got {arith!r}")
    if isinstance(get_context(arith), FloatContext):
        if dps is not None:
            raise ValueError(f"dps applies to arith 'ball' and 'mp' only (float64 has no digits to choose), got "
                             f"dps = {dps!r}")
        return FloatContext(), None
    dps = DEFAULT_DPS if dps is None else dps
    dps = check_int(dps, "dps", MIN_TESS_DPS, MAX_TESS_DPS, why="digits of every ball/mpf operation")
    return get_context(arith, dps=dps), dps


class _Route:
    """The tree and the vertices of :func:`tessellate` in an object arithmetic (``ctx``): the nets of a level as an
    ``(delta_n, N, d)`` object array.  Subclasses: :class:`_BallRoute` (rigorous) and :class:`_MpRoute`."""

    ctx: Context
    n: int
    alpha: object            # alpha in the arithmetic (an arb ball, exact for a float or mpf alpha; an mpf)
    alpha_float: float

    def beta(self, k: int):
        return self.alpha / (1 << k)

    def start(self, arr: np.ndarray) -> np.ndarray:
        with self.ctx.scope():
            return np.array([[[self.ctx.convert(float(x)) for x in row]] for row in arr], dtype=object)

    def _derivative_matrices(self, k: int) -> tuple:
        """D_u, D_v at alpha / 2^k, ``(delta_n, delta_n)`` object arrays: the nets in T-bar^beta of d/du and d/dv
        of the patch with net P are D_u P, D_v P (the closed-form C, as in :func:`derivative_nets_t`)."""
        beta = self.beta(k)
        ctx = self.ctx
        with ctx.scope():
            coef = scaled_coefficient_vector(self.n, beta, ctx)
            dn = len(coef)
            diag = ctx.zeros((dn, dn))
            for i in range(dn):
                diag[i, i] = coef[i]
            qu, qv = derivative_nets_checked(self.n, beta, diag, ctx)
            two_s = self._sin(beta / 2) * 2
            scale = np.array([1 / (c * two_s) for c in coef], dtype=object)[:, None]
            return qu * scale, qv * scale

    def _levels(self, k: int) -> dict:
        cache = self.__dict__.setdefault("_cache", {})
        if k not in cache:
            du, dv = self._derivative_matrices(k)
            second = (self._matmul(du, du), self._matmul(dv, du), self._matmul(dv, dv))
            cache[k] = {"second": second, "mats": None}
        return cache[k]

    def bound(self, nets: np.ndarray, k: int) -> np.ndarray:
        """For each node, a float M >= lambda_max([[m_uu, m_uv], [m_uv, m_vv]]) (rigorous in :class:`_BallRoute`)."""
        dn, count, dim = nets.shape
        mids = self._mids(nets)
        centre = mids.mean(axis=0)                        # any translation: D annihilates constants
        with self.ctx.scope():
            centred = nets - centre.astype(object)[None]
            flat = centred.reshape(dn, count * dim)
            ms = [self._norm_max(self._matmul(d, flat).reshape(dn, count, dim))
                  for d in self._levels(k)["second"]]
            return np.array([self._lambda_max(uu, vv, uv, k) for uu, uv, vv in zip(*ms)])

    def children(self, nets: np.ndarray, k: int) -> list[np.ndarray]:
        dn, count, dim = nets.shape
        level = self._levels(k)
        if level["mats"] is None:
            level["mats"] = self._subdivision(k)
        flat = nets.reshape(dn, count * dim)
        with self.ctx.scope():
            return [self._matmul(m, flat).reshape(dn, count, dim) for m in level["mats"]]

    def steps(self, k: int, m_bound: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
        """The grid steps r (as :func:`steps_for`) and the leaf bounds M beta^2 / (4 r^2) evaluated in the
        arithmetic (rounded up), each <= tol (a step raised where the rounded bound exceeds tol)."""
        r = steps_for(self.alpha_float / (1 << k), m_bound * (1 + 1e-9), tol)
        out = np.empty(len(r))
        for i, (m, ri) in enumerate(zip(m_bound.tolist(), r.tolist())):
            while True:
                out[i] = self._leaf_bound(m, k, ri)
                if out[i] <= tol:
                    break
                nxt = [x for x in _STEPS if x > ri]
                if not nxt:
                    raise ValueError(f"tol = {tol!r} needs a leaf grid of more than {_STEPS[-1]} steps; raise tol "
                                     "or max_depth")
                ri = nxt[0]
            r[i] = ri
        return r, out

    def vertices(self, net: np.ndarray, xy: np.ndarray, csum: np.ndarray, root: int):
        """s at the exact lattice parameters (u, v) = alpha xy / root and at the fan centroids alpha csum /
        (3 root), rounded to float64: ``(points, params, err)`` with err >= max_i |s(x_i) - points_i| (rigorous in
        :class:`_BallRoute`)."""
        ctx = self.ctx
        with ctx.scope():
            num = np.concatenate([3 * xy, csum]).astype(object)          # parameters times 3 root / alpha
            third = self.alpha / (3 * root)
            u = np.array([third * int(x) for x in num[:, 0]], dtype=object)
            v = np.array([third * int(y) for y in num[:, 1]], dtype=object)
            w = np.array([third * (3 * root - int(x) - int(y)) for x, y in num], dtype=object)
            sa = self._sin(self.alpha / 2)
            trig = []
            for x in (u, v, w):
                half = x / 2
                trig += [ctx.sin(half) / sa, ctx.cos(half)]
            coef = scaled_coefficient_vector(self.n, self.alpha, ctx)
            values = monomials(exponent_matrix(self.n), trig, ctx) * coef[None, :]
            surf = self._matmul(values, self.start(net)[:, 0, :])
            params = self._mids(np.column_stack([u, v, w]))
            points = self._mids(surf)
            err = self._vertex_error(surf, points)
        return points, np.maximum(params, 0.0), err


class _BallRoute(_Route):
    """Ball arithmetic (python-flint arb): every quantity an enclosure; the nets' balls contain the exact sub-nets of
    the float64 input net (taken as exact), M and the leaf bounds are upper ends of balls rounded up."""

    rigorous = True

    def __init__(self, n: int, alpha, dps: int) -> None:
        self.n = n
        self.ctx = BallContext(prec=int(3.33 * dps) + 20)
        if isinstance(alpha, RationalAngle):
            # 4 atan(t): a ball of radius about 2^-(prec + 1024), so that the subdivision matrices at alpha / 2^k can
            # be certified to 2^-prec (they amplify alpha's radius by up to 2^(8n + 4n log2(2^k / alpha)))
            with BallContext(prec=self.ctx.prec + 1024).scope():
                self.alpha = 4 * (arb(int(alpha.t.p)) / int(alpha.t.q)).atan()
        else:
            # exact for float, int, longdouble and mpf (any precision); a ball of radius ~2^-(prec + 1024) for an
            # fmpq or Fraction p/q; TypeError naming alpha otherwise
            self.alpha = _arb_of(alpha, self.ctx.prec)
        with BallContext(prec=self.ctx.prec + 1100).scope():
            if not (self.alpha > 0 and self.alpha < arb.pi()):
                raise ValueError(f"alpha must lie in the open interval (0, pi) (checked in ball arithmetic), got "
                                 f"{alpha!r}")
        self.alpha_float = float(self.alpha.mid())

    def start(self, arr: np.ndarray) -> np.ndarray:
        """The net as balls, each entry taken exactly as given (:meth:`BallContext.convert`: floats, ints,
        longdouble and mpf exactly from their binary mantissa and exponent; fmpq and Fraction p/q as a ball of
        radius about 2^-prec), not rounded to float64 first."""
        with self.ctx.scope():
            return np.array([[[self.ctx.convert(x) for x in row]] for row in arr], dtype=object)

    def beta(self, k: int):
        """alpha / 2^k: exact (a division by 2^k at a precision above alpha's midpoint keeps every bit)."""
        with BallContext(prec=self.ctx.prec + 1100).scope():
            return self.alpha / (1 << k)

    def _sin(self, x):
        return x.sin()

    def _subdivision(self, k: int) -> list:
        mats, _ = _certified(self.n, self.beta(k), self.ctx.prec)
        return mats

    @staticmethod
    def _matmul(a, b) -> np.ndarray:
        if not isinstance(a, arb_mat):
            a = arb_mat(np.asarray(a, dtype=object).tolist())
        return np.array((a * arb_mat(np.asarray(b, dtype=object).tolist())).tolist(), dtype=object)

    @staticmethod
    def _mids(x: np.ndarray) -> np.ndarray:
        return np.vectorize(lambda y: float(y.mid()), otypes=[np.float64])(x)

    @staticmethod
    def _norm_max(x: np.ndarray) -> np.ndarray:
        """Per node (axis 1), a float >= max_f |x_f| (Euclidean norm over the coordinates)."""
        mag = np.vectorize(lambda y: y.abs_upper(), otypes=[object])(x)
        norms = np.vectorize(lambda y: _up(y.sqrt()), otypes=[np.float64])((mag * mag).sum(axis=2))
        return norms.max(axis=0)

    def _lambda_max(self, a: float, b: float, c: float, k: int) -> float:
        """Upper bound of lambda_max([[a, c], [c, b]]) (increasing in a, b and |c| >= 0: the bound of exact upper
        bounds is an upper bound), evaluated in balls, rounded up."""
        a, b, c = arb(a), arb(b), arb(c)
        return _up((a + b) / 2 + (((a - b) / 2) ** 2 + c * c).sqrt())

    def _leaf_bound(self, m: float, k: int, r: int) -> float:
        with self.ctx.scope():
            beta = self.beta(k)
            return _up(arb(m) * 2 * beta * beta / (INTERPOLATION_DIVISOR * r * r))   # M l^2 / 8, l^2 = 2 beta^2 / r^2

    @staticmethod
    def _vertex_error(surf: np.ndarray, points: np.ndarray) -> float:
        diff = surf - points.astype(object)
        mag = np.vectorize(lambda y: y.abs_upper(), otypes=[object])(diff)
        norms = np.vectorize(lambda y: _up(y.sqrt()), otypes=[np.float64])((mag * mag).sum(axis=1))
        return float(norms.max())

    def total(self, leaf_max: float, err: float) -> float:
        return _up(arb(leaf_max) + arb(err))


class _MpRoute(_Route):
    """mpmath at ``dps`` digits: the same computation, not rigorous (the rounding of mpf arithmetic is allowed for
    as on the float route, with eps = 2^-prec instead of 2^-52)."""

    rigorous = False

    def __init__(self, n: int, alpha, dps: int) -> None:
        self.n, self.dps = n, dps
        self.ctx = MpContext(dps=dps)
        with self.ctx.scope():
            self.alpha = 4 * mpmath.atan(mpmath.mpf(int(alpha.t.p)) / int(alpha.t.q)) if isinstance(
                alpha, RationalAngle) else mpmath.mpf(alpha)
            self.eps = mpmath.mpf(2) ** -mpmath.mp.prec
        self.alpha_float = float(self.alpha)

    def _sin(self, x):
        return mpmath.sin(x)

    def _allowance(self, k: int) -> float:
        return float(max(mpmath.mpf(10) ** (6 - self.dps), ROUNDING_GROWTH * 4 ** k * self.eps))

    def _subdivision(self, k: int) -> list:
        return list(subdivision_matrices(self.n, self.beta(k), self.ctx))

    @staticmethod
    def _matmul(a, b) -> np.ndarray:
        return np.dot(np.asarray(a, dtype=object), np.asarray(b, dtype=object))

    @staticmethod
    def _mids(x: np.ndarray) -> np.ndarray:
        return np.asarray(x, dtype=object).astype(np.float64)

    @staticmethod
    def _norm_max(x: np.ndarray) -> np.ndarray:
        return np.vectorize(lambda y: float(mpmath.sqrt(y)), otypes=[np.float64])((x * x).sum(axis=2)).max(axis=0)

    def _lambda_max(self, a: float, b: float, c: float, k: int) -> float:
        lam = 0.5 * (a + b) + math.sqrt(0.25 * (a - b) ** 2 + c * c)
        return math.nextafter(lam * (1.0 + self._allowance(k)), math.inf)

    def _leaf_bound(self, m: float, k: int, r: int) -> float:
        with self.ctx.scope():
            beta = self.beta(k)
            return math.nextafter(float(mpmath.mpf(m) * 2 * beta * beta / (INTERPOLATION_DIVISOR * r * r)), math.inf)

    def _vertex_error(self, surf: np.ndarray, points: np.ndarray) -> float:
        diff = surf - points.astype(object)
        worst = max(mpmath.sqrt(sum(x * x for x in row)) for row in diff)
        return math.nextafter(float(worst) + self._allowance(0) * float(np.abs(points).max(initial=1.0)),
                              math.inf)

    def total(self, leaf_max: float, err: float) -> float:
        return math.nextafter(leaf_max + err, math.inf)


def check_tiling(xy: np.ndarray, triangles: np.ndarray, csum: np.ndarray, root: int) -> None:
    """Verify exactly, in integers, that ``triangles`` tile Omega^alpha: the premise "x lies in a triangle of the
    mesh, with barycentric coordinates lambda" of the ball route's bound (docs/tessellation.md §2, Theorem).

    Coordinates: 3 ``xy`` for the lattice points (unit alpha / (3 ``root``)) and ``csum`` for the fan centroids
    (vertex ids ``len(xy)`` on), so Omega^alpha is the triangle (0, 0), (3R, 0), (0, 3R), R = ``root``.  Checked:
    (a) every vertex lies in that closed triangle; (b) every triangle is positively oriented (twice its signed area
    > 0); (c) the twice-areas sum to (3R)^2; (d) no directed edge occurs twice, and a directed edge whose reverse
    does not occur lies on one side of the boundary.  These imply the tiling: by (d) the boundary of the 2-chain
    sum of the triangles lies in the boundary of Omega, so the number of triangles covering a point off all edges is
    constant inside Omega and 0 outside (a); by (b) and (c) that constant is 1.  So the triangles have disjoint
    interiors and their union is Omega.  ``ArithmeticError`` naming the failed check.  Cost O(F log F), integers
    below 2^63 (3R <= 3 * 105 * 2^21).

    >>> check_tiling(np.array([[0, 0], [1, 0], [0, 1]]), np.array([[0, 1, 2]]), np.zeros((0, 2), int), 1)
    >>> check_tiling(np.array([[0, 0], [1, 0], [0, 1]]), np.array([[0, 2, 1]]), np.zeros((0, 2), int), 1)
    Traceback (most recent call last):
    ...
    ArithmeticError: tiling check (b): 1 triangle(s) not positively oriented
    """
    big = 3 * int(root)
    pts = np.concatenate([3 * np.asarray(xy, dtype=np.int64),
                          np.asarray(csum, dtype=np.int64).reshape(-1, 2)])
    x, y = pts[:, 0], pts[:, 1]
    if not ((x >= 0) & (y >= 0) & (x + y <= big)).all():
        raise ArithmeticError("tiling check (a): a vertex lies outside Omega^alpha")
    tri = np.asarray(triangles, dtype=np.int64)
    p0, p1, p2 = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    twice = (p1[:, 0] - p0[:, 0]) * (p2[:, 1] - p0[:, 1]) - (p2[:, 0] - p0[:, 0]) * (p1[:, 1] - p0[:, 1])
    if not (twice > 0).all():
        raise ArithmeticError(f"tiling check (b): {int((twice <= 0).sum())} triangle(s) not positively oriented")
    total = sum(twice.tolist())                           # Python integers: no overflow
    if total != big * big:
        raise ArithmeticError(f"tiling check (c): the twice-areas sum to {total}, not (3R)^2 = {big * big}")
    nv = len(pts)
    tail = tri.reshape(-1)
    head = tri[:, [1, 2, 0]].reshape(-1)
    keys = tail * nv + head
    order = np.sort(keys)
    if (order[1:] == order[:-1]).any():
        raise ArithmeticError("tiling check (d): a directed edge occurs twice")
    lone = ~np.isin(head * nv + tail, order)
    ta, he = tail[lone], head[lone]
    on_side = (((x[ta] == 0) & (x[he] == 0)) | ((y[ta] == 0) & (y[he] == 0))
               | ((x[ta] + y[ta] == big) & (x[he] + y[he] == big)))
    if not on_side.all():
        raise ArithmeticError(f"tiling check (d): {int((~on_side).sum())} edge(s) without a reverse twin lie inside "
                              "Omega^alpha")


def _tree_route(route: _Route, arr: np.ndarray, tol: float, leaf_resolution: int, max_depth: int,
                max_vertices: int) -> _Leaves:
    """:func:`_tree` on a :class:`_Route` (the same leaves rule and refusals; the nets and bounds in the route's
    arithmetic)."""
    dn, dim = arr.shape
    unit = 1 << (max_depth + 1)
    nets = route.start(arr)
    a = np.zeros(1, dtype=np.int64)
    b = np.zeros(1, dtype=np.int64)
    sign = np.ones(1, dtype=np.int64)
    cap = np.full(1, np.inf)
    out: list[tuple] = []
    visited = 1
    for k in range(max_depth + 1):
        beta = route.alpha_float / (1 << k)
        m_bound = np.minimum(route.bound(nets, k), cap)
        if not np.isfinite(m_bound).all():
            raise ValueError(f"alpha = {route.alpha_float!r}: the bound M of the second derivatives (about "
                             f"|P| / alpha^2) exceeds float64 at depth {k}; alpha must be above about 1e-152 times the "
                             "square root of the net's largest coordinate (a larger alpha or a smaller net)")
        leaf = _leaves_of_level(k, beta, m_bound, tol, dn * dim, leaf_resolution, max_depth, max_vertices)
        if leaf.any():
            r, bnd = route.steps(k, m_bound[leaf], tol)
            out.append((np.full(int(leaf.sum()), k), a[leaf], b[leaf], sign[leaf], r, bnd))
        keep = ~leaf
        if not keep.any():
            break
        visited += 4 * int(keep.sum())
        if visited * dn > MAX_BALL_TREE_WORK:
            raise ValueError(f"tol = {tol:.3g} with leaf_resolution = {leaf_resolution} needs more than {visited} tree "
                             f"nodes by depth {k + 1}, above the ball/mp routes' tree limit {MAX_BALL_TREE_WORK} / "
                             f"delta_n = {MAX_BALL_TREE_WORK // dn}; raise tol or leaf_resolution")
        half = unit >> (k + 1)
        parent, pa, pb, ps = nets[:, keep], a[keep], b[keep], sign[keep]
        cap = np.tile(m_bound[keep], 4)
        nets = np.concatenate(route.children(parent, k), axis=1)
        a = np.concatenate([pa + ps * half, pa, pa, pa + ps * half])
        b = np.concatenate([pb, pb + ps * half, pb, pb + ps * half])
        sign = np.concatenate([ps, ps, ps, -ps])
    cols = list(zip(*out))
    return _Leaves(*(np.concatenate(c) for c in cols))


def tessellate(net, n: int, alpha, tol, *, arith: str = "float", dps: int | None = None, leaf_resolution: int = 64,
               max_depth: int = 10, max_vertices: int | None = None) -> Tessellation:
    """A triangle mesh of the patch with control net ``net`` (``(delta_n, d)``, eq. triangular_trig_surface) whose
    parametric deviation from the surface is at most ``tol``: max over x of |s(x) - mesh(x)| <= tol, with mesh(x)
    the piecewise-linear map of the parameter triangulation (so every mesh point is within tol of the surface and
    every surface point within tol of the mesh).

    Adaptive: midpoint subdivision (:func:`~paper_repro.core.subdivision.subdivision_matrices`) until the bound of
    a node (:func:`second_derivative_bound`) allows a grid of at most ``leaf_resolution`` steps, or ``max_depth``;
    each leaf is cut into the uniform grid its bound asks for; leaves of different depth or step are joined without
    cracks (shared edge points, centroid fans).  The guarantee is the proven bound of the module docstring, evaluated
    in float64 with M multiplied by :func:`rounding_factor` of the node's depth and 1e-13 times the net's largest
    absolute coordinate (its extent) subtracted from tol for the vertices' rounding (allowances, not proven); the
    tests verify it a posteriori by dense sampling.  ``Tessellation.bound`` is the largest leaf bound plus that
    1e-13 extent.  A node is a leaf when its unrounded step need <= ``leaf_resolution``, at ``max_depth``, or when
    the next level would hold more than :data:`MAX_TREE_FLOATS` floats.

    Refused before work (``TypeError``/``ValueError`` naming the parameter): ``n`` outside 1..
    :data:`MAX_N_TESSELLATE`, alpha outside (0, pi), ``tol`` not positive or below 1e-12 times the net's largest
    coordinate, a malformed net, ``leaf_resolution`` outside 1..256, ``max_depth`` outside 0..14, ``max_vertices``
    outside 3..5e7; during the (cheap) tree, a level asking for more than 16 ``max_vertices`` or a leaf needing more
    than 7168 steps (``ValueError`` naming max_vertices or tol); after it, a mesh above ``max_vertices`` or a lattice
    finer than alpha / (105 2^21) (``ValueError`` naming tol and max_depth).

    ``arith``: ``'float'`` (default; float64, the bound up to measured rounding allowances), ``'ball'`` (python-flint
    arb at 3.33 ``dps`` + 20 bits: ``bound`` is a proven upper bound of max_x |s(x) - mesh(x)|, mesh the
    piecewise-linear interpolant of the returned float64 vertices over the exact lattice triangulation of
    Omega^alpha; the module docstring) or ``'mp'`` (mpmath at ``dps`` digits; not rigorous, its allowances about
    10^(6 - dps)).  ``dps``: 16..200, default 30, only with 'ball' and 'mp'.  On these two routes alpha may also be
    an mpf or a :class:`~paper_repro.core.domain.RationalAngle` (4 atan(t), enclosed in a ball), ``max_vertices``
    is at most :data:`MAX_BALL_WORK` // delta_n (default that limit; every vertex is evaluated in arb/mpf) and the
    tree at most :data:`MAX_BALL_TREE_WORK` // delta_n nodes (``ValueError`` naming tol and leaf_resolution).  The
    float route and its results do not depend on these parameters (the same bits as before they existed).

    >>> import numpy as np
    >>> from paper_repro.core.labels import delta
    >>> mesh = tessellate(np.zeros((delta(2), 3)), 2, 1.0, 1e-6)   # a point: one triangle
    >>> len(mesh.triangles), mesh.leaves
    (1, 1)
    >>> net = np.random.default_rng(1).random((delta(1), 3))
    >>> ball = tessellate(net, 1, 1.0, 1e-2, arith="ball")        # a proven bound
    >>> bool(ball.bound <= 1e-2), len(ball.points) == len(tessellate(net, 1, 1.0, 1e-2).points)
    (True, True)
    """
    ctx, dps = _check_arith(arith, dps)
    if not isinstance(ctx, FloatContext):
        return _tessellate_route(net, n, alpha, tol, ctx, dps, leaf_resolution, max_depth, max_vertices)
    max_vertices = MAX_VERTICES if max_vertices is None else max_vertices
    arr, n, alpha, tol, leaf_resolution, max_depth, max_vertices = _check_inputs(
        net, n, alpha, tol, leaf_resolution, max_depth, max_vertices)
    extent = float(np.abs(arr).max())
    # vertices are float64 patch values: an allowance of 1e-13 times the net's size for their rounding (measured
    # errors of Patch evaluation are below 1e-15 relative)
    tol_eff = tol - 1e-13 * extent
    leaves = _tree(arr, n, alpha, tol_eff, leaf_resolution, max_depth, max_vertices)
    xy, tri, centroids, root = _mesh(leaves, max_depth, max_vertices)
    unit = alpha / root
    uv = np.concatenate([xy.astype(np.float64), centroids]) * unit
    w = np.concatenate([(root - xy.sum(axis=1)).astype(np.float64), root - centroids.sum(axis=1)]) * unit
    params = np.column_stack([uv, np.maximum(w, 0.0)])
    points = Patch(n, alpha, arr)(params)
    bound = float(leaves.bound.max()) + 1e-13 * extent
    return Tessellation(points, tri, params, bound, int(len(leaves.steps)), int(leaves.level.max()), len(centroids))


def _tessellate_route(net, n, alpha, tol, ctx: Context, dps: int, leaf_resolution, max_depth, max_vertices
                      ) -> Tessellation:
    """:func:`tessellate` with ``arith`` 'ball' or 'mp' (inputs checked as on the float route; alpha may be a
    float, an mpf or a :class:`~paper_repro.core.domain.RationalAngle`)."""
    n = check_int(n, "n", 1, MAX_N_TESSELLATE, why="each tree level builds the subdivision matrices at a new alpha")
    ball = isinstance(ctx, BallContext)
    arith = "ball" if ball else "mp"
    limit = MAX_BALL_WORK // delta(n)
    max_vertices = limit if max_vertices is None else max_vertices
    max_vertices = check_int(max_vertices, "max_vertices", 3, limit,
                             why=f"every vertex is evaluated in arith {arith!r} (the limit is {MAX_BALL_WORK} / "
                                 "delta_n, about 15 s)")
    exact_alpha = open_alpha(alpha)
    arr, n, _, tol, leaf_resolution, max_depth, max_vertices = _check_inputs(
        net, n, float(exact_alpha), tol, leaf_resolution, max_depth, max_vertices)
    route: _Route = (_BallRoute if ball else _MpRoute)(n, exact_alpha, dps)
    # the ball route takes the net's entries as given (exactly, or p/q in a ball); the mp route its float64 rounding
    given = check_net_exact(net, n) if ball else arr
    extent = float(np.abs(arr).max())
    # the vertices' own error (ball radius plus rounding to float64, about 1e-16 of the extent) is measured below and
    # added; the tree works to tol less a reserve of 1e-13 extent for it
    leaves = _tree_route(route, given, tol - 1e-13 * extent, leaf_resolution, max_depth, max_vertices)
    xy, tri, centroids, root = _mesh(leaves, max_depth, max_vertices)
    csum = np.rint(centroids * 3.0).astype(np.int64)      # the centroids' lattice coordinates are integers / 3
    if ball:
        check_tiling(xy, tri, csum, root)                  # the premise of the bound, verified exactly
    points, params, err = route.vertices(given, xy, csum, root)
    bound = route.total(float(leaves.bound.max()), err)
    if bound > tol:
        raise ArithmeticError(f"the {arith} bound {bound!r} exceeds tol = {tol!r} (vertex error {err!r}); raise "
                              "tol or dps")
    return Tessellation(points, tri, params, bound, int(len(leaves.steps)), int(leaves.level.max()), len(centroids))


__all__ = ["tessellate", "Tessellation", "second_derivative_bound", "second_derivative_nets", "derivative_nets_t",
           "steps_for", "rounding_factor", "check_tiling", "MAX_N_TESSELLATE", "MAX_VERTICES", "ARITHS",
           "MAX_BALL_WORK", "MAX_BALL_TREE_WORK"]
