"""Claim ``joins_all_n``: smooth joins of two patches along a shared edge (issue 38, item 4; beyond the paper).

The statement (proven for every n in docs/joins_for_all_n.md; computed by
:mod:`paper_repro.surfaces.joins`): along an edge the cross-boundary derivative and the tangent of a patch are
``sum_k A_{2n,k}(t) d_k`` and ``sum_k A_{2n,k}(t) t_k`` with d = D P, t = T P in closed form; with the neighbour on
the point-reflected triangle, C0 iff P'_{2n-k} = P_k, C1 iff moreover d'_{2n-k} = -d_k, and G1 (constant
multipliers, sufficient) if d'_{2n-k} = -lam d_k + mu t_k with lam > 0; the second-row block of D is invertible, so
the C1/G1 neighbour's second row is unique.

What the program checks, exactly (rational arithmetic, alpha = 4 atan(t) with t rational):

1. **the closed form**: ``sum_k A_{2n,k}(t_j) D[k, f]`` equals the exact cross-boundary derivative of every blending
   function f (:func:`~paper_repro.core.derivatives_basis.basis_derivative`, which knows nothing of edges) at
   2n + 3 rational points of every edge (a trigonometric polynomial of degree n is fixed by 2n + 1), T likewise;
   the second-row block of D is invertible (its exact rank);
2. **the builders**: on an integer-valued net, the C1 neighbour (:func:`~paper_repro.surfaces.joins.join_neighbour`)
   and a G1 neighbour with (lam, mu) = (2/3, -1/5): both patches' first derivatives, computed independently by
   basis_derivative at rational edge points and at their point reflections, satisfy g = s, dg/dcross = ds/dcross
   (C1) or = lam ds/dcross - mu ds/dtangent (G1) exactly; ``join_error`` gives C0 = C1 = G1 = 0, resp.
   C0 = G1 = 0 with (lam, mu) found back;
3. **the pieces of Section 6** (Example exmp:torus; the Dupin cyclide of Fig. fig:dupin_03, in homogeneous
   coordinates (X, Y/b, Z/b, W) as the model of :func:`paper_repro.surfaces.models.cyclide_parts`): exact order-2
   nets of the lower triangle of a phase square, of its upper triangle, and of the lower triangles of the squares
   above and to the right (:func:`~paper_repro.surfaces.fitting.fit_exact`, by collocation, independent of the
   joins module), joined across the diagonal (edge w), V = const (edge v) and U = const (edge u): C0 and C1
   defects exactly 0.  For the torus that is C1 of the surface pieces; for the cyclide C1 of the homogeneous
   pieces, hence C1 (so G1) of the rational pieces wherever W != 0 (the quotient X/W and its first derivatives are
   functions of the homogeneous values and first derivatives; docs/joins_for_all_n.md section 5).

Kind: exact-evidence at the sampled alpha and n; the hand proof carries every n and alpha.
"""

from __future__ import annotations

import numpy as np
from flint import fmpq

from paper_repro.core.context import to_fmpq_mat
from paper_repro.core.derivatives_basis import basis_derivative
from paper_repro.core.domain import RationalAngle, RationalPoints, rational_alpha
from paper_repro.core.labels import delta
from paper_repro.core.univariate import c_const
from paper_repro.surfaces.fitting import ExactTrig, fit_exact
from paper_repro.surfaces.joins import EDGES, ROLES, directions, edge_derivatives, edge_rows, join_error, join_neighbour
from paper_repro.util.registry import Outcome, claim


def _sub_quarter(a: fmpq, b: fmpq) -> fmpq:
    """tan((x - y)/4) from tan(x/4) = a, tan(y/4) = b."""
    return (a - b) / (1 + a * b)


def edge_points(alpha: RationalAngle, edge: str, taus) -> RationalPoints:
    """Rational points of ``edge`` whose parameter variable has quarter-angle tangent ``tau`` (edge 'u': the other
    variable v has it; the parameter w follows)."""
    ta = alpha.t
    if edge == "v":
        tu, tv = list(taus), [fmpq(0)] * len(taus)
    elif edge == "u":
        tu, tv = [fmpq(0)] * len(taus), list(taus)
    else:
        tu, tv = list(taus), [_sub_quarter(ta, x) for x in taus]
    return RationalPoints(alpha, tuple(tu), tuple(tv))


def reflected(pts: RationalPoints, alpha: RationalAngle, edge: str) -> RationalPoints:
    """The images of edge points under the point reflection through the edge's midpoint (x(t) -> x(alpha - t))."""
    ta = alpha.t
    if edge == "v":
        return RationalPoints(alpha, tuple(_sub_quarter(ta, x) for x in pts.tu), pts.tv)
    if edge == "u":
        return RationalPoints(alpha, pts.tu, tuple(_sub_quarter(ta, x) for x in pts.tv))
    return RationalPoints(alpha, pts.tv, pts.tu)


def exact_basis(n: int, alpha: RationalAngle, pts: RationalPoints, edge: str) -> np.ndarray:
    """A_{2n,k}(t) = c_{2n,k} sin^{2n-k}((alpha - t)/2) sin^k(t/2) at the edge points (eq. univariate_basis)."""
    p, _, o = ROLES[edge]
    half = pts.half_angle_values()
    s, big_s = half[2 * p], half[2 * o]
    c = [c_const(n, k, alpha, "exact") for k in range(2 * n + 1)]
    return np.array([[c[k] * big_s[j] ** (2 * n - k) * s[j] ** k for k in range(2 * n + 1)]
                     for j in range(len(pts))], dtype=object)


def _taus(alpha: RationalAngle, count: int) -> list[fmpq]:
    return [fmpq(k, count + 1) * alpha.t for k in range(1, count + 1)]


def closed_form_check(n: int, alpha: RationalAngle) -> dict:
    """Check 1 at order ``n``: every edge."""
    out = {}
    for edge in EDGES:
        pts = edge_points(alpha, edge, _taus(alpha, 2 * n + 3))
        basis = exact_basis(n, alpha, pts, edge)
        d_mat, t_mat = edge_derivatives(n, alpha, edge, "exact")
        cross, tangent = directions(edge)
        _, s = edge_rows(n, edge)
        out[edge] = {
            "cross": bool((basis.dot(d_mat) == basis_derivative(n, alpha, pts, cross, "exact")).all()),
            "tangent": bool((basis.dot(t_mat) == basis_derivative(n, alpha, pts, tangent, "exact")).all()),
            "second_row_block_invertible": to_fmpq_mat(d_mat[:, s]).rank() == 2 * n + 1,
        }
    return out


def derivatives_agree(net, other, n: int, alpha: RationalAngle, edge: str, lam: fmpq | int = 1,
                      mu: fmpq | int = 0) -> bool:
    """At 2n + 3 rational edge points x: g(x) = s(x) and the derivatives of g(x) = s'(2m - x) along the cross and
    tangent directions, -(D_e s')(2m - x), equal lam ds/dcross - mu ds/dtangent and ds/dtangent (exact values of
    basis_derivative times the nets)."""
    from paper_repro.core.normalization import evaluate_normalized

    arr, oth = np.array(net, dtype=object), np.array(other, dtype=object)
    pts = edge_points(alpha, edge, _taus(alpha, 2 * n + 3))
    mirror = reflected(pts, alpha, edge)
    cross, tangent = directions(edge)
    same = (evaluate_normalized(n, alpha, pts, "exact").dot(arr) ==
            evaluate_normalized(n, alpha, mirror, "exact").dot(oth)).all()
    ds_c = basis_derivative(n, alpha, pts, cross, "exact").dot(arr)
    ds_t = basis_derivative(n, alpha, pts, tangent, "exact").dot(arr)
    dg_c = -basis_derivative(n, alpha, mirror, cross, "exact").dot(oth)
    dg_t = -basis_derivative(n, alpha, mirror, tangent, "exact").dot(oth)
    return bool(same and (dg_t == ds_t).all() and (dg_c == lam * ds_c - mu * ds_t).all())


def builders_check(n: int, alpha: RationalAngle, seed: int) -> dict:
    """Check 2 at order ``n``: every edge, the C1 neighbour and the G1 neighbour with (lam, mu) = (2/3, -1/5)."""
    rng = np.random.default_rng(seed + n)
    net = [[fmpq(int(x)) for x in row] for row in rng.integers(-9, 10, size=(delta(n), 3))]
    lam, mu = fmpq(2, 3), fmpq(-1, 5)
    out = {}
    for edge in EDGES:
        c1 = join_neighbour(net, n, alpha, edge, arith="exact")
        g1 = join_neighbour(net, n, alpha, edge, lam=lam, mu=mu, arith="exact")
        e1, e2 = join_error(net, c1, n, alpha, edge, arith="exact"), join_error(net, g1, n, alpha, edge, arith="exact")
        out[edge] = {
            "C1_derivatives_agree": derivatives_agree(net, c1, n, alpha, edge),
            "G1_derivatives_agree": derivatives_agree(net, g1, n, alpha, edge, lam, mu),
            "join_error_C1": (e1["C0"], e1["C1"], e1["G1"], e1["lam"], e1["mu"]) == (0, 0, 0, 1, 0),
            "join_error_G1": e2["C0"] == 0 and e2["G1"] == 0 and e2["C1"] != 0 and (e2["lam"], e2["mu"]) == (lam, mu),
        }
    return out


# --- the pieces of Section 6 -------------------------------------------------------------------------------------
def _cs(t: fmpq) -> tuple[fmpq, fmpq]:
    """(cos x, sin x) for tan(x/4) = t."""
    s, c = 2 * t / (1 + t * t), (1 - t * t) / (1 + t * t)
    return c * c - s * s, 2 * s * c


def _rotate(phase: tuple[fmpq, fmpq], by: tuple[fmpq, fmpq]) -> tuple[fmpq, fmpq]:
    """(cos, sin) of the sum of two angles."""
    return phase[0] * by[0] - phase[1] * by[1], phase[1] * by[0] + phase[0] * by[1]


def piece(model, phi, psi, alpha: RationalAngle, upper: bool):
    """The surface of one triangle of the phase square (phi, psi) ((cos, sin) pairs) as a function of ExactTrig:
    lower: U = phi + u, V = psi + v; upper: U = phi + alpha - u, V = psi + alpha - v (the convention of
    :func:`paper_repro.surfaces.models.torus_pieces`)."""
    ca, sa = _cs(alpha.t)

    def angle(t: ExactTrig, var: int, ph):
        c0, s0 = t.cos(*[int(k == var) for k in range(3)]), t.sin(*[int(k == var) for k in range(3)])
        if upper:  # alpha - x
            c0, s0 = ca * c0 + sa * s0, sa * c0 - ca * s0
        return ph[0] * c0 - ph[1] * s0, ph[1] * c0 + ph[0] * s0

    def surface(t: ExactTrig):
        cu, su = angle(t, 0, phi)
        cv, sv = angle(t, 1, psi)
        return model(cu, su, cv, sv)

    return surface


def torus_model(rho: fmpq, mu: fmpq):
    """The torus of Example exmp:torus (eq. toroidal_triangle): ((rho + mu sin U) cos V, (rho + mu sin U) sin V,
    mu cos U)."""
    return lambda cu, su, cv, sv: [(rho + mu * su) * cv, (rho + mu * su) * sv, mu * cu]


def cyclide_model(a: fmpq, b2: fmpq, c: fmpq, mu: fmpq):
    """The ring Dupin cyclide (eq. Dupin_in_3d) in homogeneous coordinates (X, Y/b, Z/b, W), b^2 = ``b2``."""
    return lambda cu, su, cv, sv: [mu * (c - a * cu * cv) + b2 * cu, (a - mu * cv) * su, (c * cu - mu) * sv,
                                   a - c * cu * cv]


def pieces_check(model, alpha: RationalAngle, phi, psi) -> dict:
    """Check 3 for one phase square: its lower and upper triangles across the diagonal (edge w), the upper one with
    the lower triangle of the square above (V + alpha, edge v) and of the square to the right (U + alpha, edge u)."""
    rot = _cs(alpha.t)
    lower = fit_exact(piece(model, phi, psi, alpha, False), 2, alpha)
    upper = fit_exact(piece(model, phi, psi, alpha, True), 2, alpha)
    above = fit_exact(piece(model, phi, _rotate(psi, rot), alpha, False), 2, alpha)
    right = fit_exact(piece(model, _rotate(phi, rot), psi, alpha, False), 2, alpha)
    out = {}
    for name, first, edge in (("diagonal (w)", lower, "w"), ("V = const (v)", above, "v"),
                              ("U = const (u)", right, "u")):
        err = join_error(first, upper, 2, alpha, edge, arith="exact")
        out[name] = {"C0": err["C0"] == 0, "C1": err["C1"] == 0,
                     "derivatives_agree": derivatives_agree(first, upper, 2, alpha, edge)}
    return out


@claim("joins_all_n", paper_ref=["boundary_property_1", "univariate_basis", "exmp:torus", "fig:dupin_03"],
       statement="Beyond the paper (issue 38): two order-n patches with parameter alpha on point-reflected triangles "
                 "sharing an edge join C0 iff P'_(2n-k) = P_k, C1 iff moreover d'_(2n-k) = -d_k, G1 (sufficient) if "
                 "d'_(2n-k) = -lam d_k + mu t_k, lam > 0, with d = D P, t = T P in closed form and the second-row "
                 "block of D invertible (hand proof for every n, docs/joins_for_all_n.md). Exact "
                 "checks at tan(alpha/4) in {ts}, n = 1..{n_max}, every edge: the closed form equals the exact "
                 "derivatives of the blending functions at 2n + 3 edge points, the block has full rank, the C1 and "
                 "G1 (lam, mu) = (2/3, -1/5) builders give neighbours whose values and derivatives satisfy the "
                 "conditions at 2n + 3 edge points, and join_error gives C0 = C1 = G1 = 0 (C1 neighbour), C0 = G1 = 0 "
                 "with (lam, mu) found back (G1 neighbour). The torus (rho, mu) = {torus} and the Dupin cyclide "
                 "(a, b^2, c, mu) = {cyclide} pieces of Section 6 (exact order-2 nets at tan(alpha/4) in "
                 "{ts_pieces}, phase squares (phi, psi) with both phases' (cos, sin) in {phases}): C0 and C1 "
                 "defects exactly 0, and the first derivatives equal at 7 edge points, across the diagonal, V = const "
                 "and U = const (the cyclide: of the homogeneous nets, hence C1 of the rational pieces where W != 0).",
       kind="exact-evidence", ts=["1/7", "1/3", "3/5"], n_max=4, seed=3, torus=["2", "1"],
       cyclide=["6", "32", "2", "3"], ts_pieces=["1/3", "1/2"], phases=[["1", "0"], ["3/5", "4/5"]],
       extended={"n_max": 8})
def run(ts: list[str], n_max: int, seed: int, torus: list[str], cyclide: list[str], ts_pieces: list[str],
        phases: list[list[str]]) -> Outcome:
    closed, built = {}, {}
    for t in ts:
        alpha = rational_alpha(fmpq(*map(int, t.split("/"))))
        for n in range(1, n_max + 1):
            closed[f"n={n}, tan(alpha/4)={t}"] = closed_form_check(n, alpha)
            built[f"n={n}, tan(alpha/4)={t}"] = builders_check(n, alpha, seed)
    closed_ok = all(all(v.values()) for e in closed.values() for v in e.values())
    built_ok = all(all(v.values()) for e in built.values() for v in e.values())
    ph = [tuple(fmpq(*map(int, (x + "/1").split("/")[:2])) for x in p) for p in phases]
    models = {"torus": torus_model(*(fmpq(int(x)) for x in torus)),
              "cyclide (homogeneous)": cyclide_model(*(fmpq(int(x)) for x in cyclide))}
    pieces = {}
    for name, model in models.items():
        for t in ts_pieces:
            alpha = rational_alpha(fmpq(*map(int, t.split("/"))))
            for phi in ph:
                for psi in ph:
                    pieces[f"{name}, tan(alpha/4)={t}, phi={phi}, psi={psi}"] = pieces_check(model, alpha, phi, psi)
    pieces_ok = all(all(v.values()) for e in pieces.values() for v in e.values())
    measured = {
        "closed_form_equals_exact_derivatives": (f"every edge, n = 1..{n_max}, tan(alpha/4) in {ts}"
                                                 if closed_ok else closed),
        "builders_C1_G1_exact": f"every edge, n = 1..{n_max}" if built_ok else built,
        "section6_pieces": ("torus: C1 across the three kinds of shared edge; cyclide: C1 of the homogeneous nets "
                            "(so C1, hence G1, of the rational pieces where W != 0); exact" if pieces_ok else pieces),
        "scope": "exact at the sampled alpha and n (evidence for others); the conditions, the closed form and the "
                 "invertibility are proven for every n and alpha in docs/joins_for_all_n.md",
    }
    return Outcome(closed_ok and built_ok and pieces_ok, measured)


__all__ = ["run", "closed_form_check", "builders_check", "pieces_check", "derivatives_agree", "edge_points",
           "reflected", "exact_basis", "piece", "torus_model", "cyclide_model"]
