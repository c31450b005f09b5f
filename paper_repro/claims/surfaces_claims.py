"""Claims ``dupin_cyclide`` and ``patch_properties`` (Section sec:applications), and the exported meshes."""

from __future__ import annotations

import mpmath
import numpy as np
from flint import fmpq
from scipy.spatial import Delaunay

from paper_repro.core.domain import RationalPoints, rational_alpha, sample_points
from paper_repro.core.labels import delta, index_of, united_system
from paper_repro.surfaces.models import cyclide_parts, cyclide_pieces, model_gap, torus_pieces
from paper_repro.surfaces.patch import Patch, merge_meshes
from paper_repro.util.measured import MESH_DECIMALS, bound, sig
from paper_repro.util.registry import ALPHA_RANGES, Outcome, claim

CYCLIDE = {"a": "6", "b": "sqrt(32)", "c": "2", "mu": "3"}


def _cyclide_params(dps: int = 30) -> dict:
    with mpmath.workdps(dps):
        return {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}


def _mesh_data(pieces, resolution: int) -> dict:
    v, f = merge_meshes([p.patch.mesh(resolution) for p in pieces])
    return {"__mesh__": {"vertices": np.round(v, MESH_DECIMALS).tolist(), "faces": f.tolist()}}


@claim("dupin_cyclide", paper_ref=["Dupin_in_3d", "def:rational_patch", "fig:dupin_03",
                                   "sec:triangular_rational_trigonometric_patches"],
       statement="The ring Dupin cyclide (a=6, b=4 sqrt 2, c=2, mu=3, alpha=pi/2) is described exactly by second order "
                 "rational patches with non-negative weights: 16 cover the triangles u+v <= alpha of the 4x4 phase "
                 "grid, 32 the whole cyclide; neighbours join (float64: deviation from the cyclide and join gaps "
                 "< 1e-12 at {points} seeded points per patch).",
       kind="numeric-evidence", points=150, mesh_resolution=10)
def run_dupin(points, mesh_resolution) -> Outcome:
    al = float(mpmath.pi / 2)
    phases = [k * al for k in range(4)]
    params = _cyclide_params()
    pieces = cyclide_pieces(al, params, phases, phases)
    pts = sample_points(al, points, seed=1)
    dev = 0.0
    for p in pieces:
        ref = []
        for U, V in p.uv(pts, al):
            X, W = cyclide_parts(U, V, params["a"], params["b"], params["c"], params["mu"])
            ref.append([float(x / W) for x in X])
        dev = max(dev, float(np.max(np.abs(p.patch(pts) - np.array(ref)))))
    weights = np.array([p.patch.weights for p in pieces])
    nets = {}
    for p in pieces:
        key = f"phi={round(p.phi / al)}pi/2,psi={round(p.psi / al)}pi/2,{'upper' if p.upper else 'lower'}"
        nets[key] = {lab.control_point: {"point": [round(float(x), 14) for x in p.patch.net[k]],
                                         "weight": round(float(p.patch.weights[k]), 14)}
                     for k, lab in enumerate(united_system(2))}
    lower = [p for p in pieces if not p.upper]
    data = {"dupin/nets.json": {"parameters": CYCLIDE, "alpha": "pi/2",
                                "convention": "lower: U = phi + u, V = psi + v; upper: U = phi + alpha - u, "
                                              "V = psi + alpha - v (eq. Dupin_in_3d with U = u + phi, V = v + psi)",
                                "patches": nets},
            "meshes/dupin_cyclide.obj": _mesh_data(pieces, mesh_resolution),
            "meshes/dupin_cyclide.ply": _mesh_data(pieces, mesh_resolution)}
    gap_all, gap_16 = model_gap(pieces, al), model_gap(lower, al)
    ok = weights.min() >= 0 and dev < 1e-12 and gap_all < 1e-12
    return Outcome(ok, {"patches": len(pieces), "patches_paper_16": len(lower),
                        "min_weight": sig(float(weights.min()), 6),
                        "max_deviation_from_cyclide": bound(dev, 1e-12), "max_join_gap_all_32": bound(gap_all, 1e-12),
                        "max_join_gap_16": bound(gap_16, 1e-12),
                        "note": "G1/curvature continuity across joins is inherited: every patch coincides with the "
                                "smooth cyclide to the deviation above (float64; the bound it clears is published, "
                                "the raw value is machine-dependent)"}, data=data,
                   raw={"max_deviation_from_cyclide": dev, "max_join_gap_all_32": gap_all, "max_join_gap_16": gap_16})


def _random_net(rng, n):
    return rng.normal(size=(delta(n), 3))


#: The corners of Omega^alpha (as multiples of alpha), the control point there, the two terminal edges of the
#: boundary control polygons through it (def:surface_patch: the tangent plane at a corner is spanned by them) and
#: the two directions along Omega^alpha leaving the corner along the boundary curves.
CORNERS = {
    "r": ((1, 0, 0), "r_{{{m},{m},0}}", ("r_{{{m},{k},0}}", "b_{{{m},1,0}}"), ((-1, 0, 1), (-1, 1, 0))),
    "g": ((0, 0, 1), "g_{{{m},{m},0}}", ("g_{{{m},{k},0}}", "r_{{{m},1,0}}"), ((0, 1, -1), (1, 0, -1))),
    "b": ((0, 1, 0), "b_{{{m},{m},0}}", ("b_{{{m},{k},0}}", "g_{{{m},1,0}}"), ((1, -1, 0), (0, -1, 1))),
}


def _corner_names(n: int, letter: str, edges: tuple[str, str] | None = None) -> tuple[str, tuple[str, str]]:
    _, corner, default, _ = CORNERS[letter]
    fmt = {"m": 2 * n, "k": 2 * n - 1}
    return corner.format(**fmt), (tuple(edges) if edges else tuple(e.format(**fmt) for e in default))


def tangent_plane_residual(patch: Patch, letter: str, edges: tuple[str, str] | None = None) -> float:
    """max over the two boundary directions d of |N . P_d| / (|P_d| |N|) at the corner ``letter``, N the normal of
    the plane spanned by the terminal edges (``edges``: other control points, to show a wrong plane fails), P_d
    the exact derivative of the library (:meth:`Patch.derivative`) evaluated in float64: ~1e-15 for the right
    plane, the sine of the angle between the planes otherwise."""
    n, al, net = patch.n, float(patch.alpha), np.asarray(patch.net, dtype=float)
    idx = index_of(n)
    corner, (a, b) = _corner_names(n, letter, edges)
    at, _, _, directions = CORNERS[letter]
    c0 = net[idx[corner]]
    normal = np.cross(net[idx[a]] - c0, net[idx[b]] - c0)
    worst = 0.0
    for d in directions:
        der = patch.derivative(np.array([[al * x for x in at]]), d, "float")[0]
        worst = max(worst, abs(float(normal @ der)) / (np.linalg.norm(der) * np.linalg.norm(normal)))
    return worst


def tangent_plane_exact(n: int, t_alpha: fmpq, net: list[list[int]], letter: str,
                        edges: tuple[str, str] | None = None) -> bool:
    """Exactly (rational alpha = 4 atan(t_alpha), integer net): det[e1, e2, P_d] == 0 for both boundary directions
    d at the corner ``letter`` (the derivative lies in the plane of the terminal edges) and P_d != 0."""
    alpha = rational_alpha(t_alpha)
    patch = Patch(n, alpha, np.array(net, dtype=object), arith="exact")
    idx = index_of(n)
    corner, (a, b) = _corner_names(n, letter, edges)
    at, _, _, directions = CORNERS[letter]
    tu, tv = (alpha.t if at[0] else fmpq(0)), (alpha.t if at[1] else fmpq(0))
    pts = RationalPoints(alpha, (tu,), (tv,))
    c0 = [fmpq(x) for x in net[idx[corner]]]
    e1 = [fmpq(x) - y for x, y in zip(net[idx[a]], c0)]
    e2 = [fmpq(x) - y for x, y in zip(net[idx[b]], c0)]
    for d in directions:
        p = [fmpq(x) for x in patch.derivative(pts, d, "exact")[0]]
        det = (e1[0] * (e2[1] * p[2] - e2[2] * p[1]) - e1[1] * (e2[0] * p[2] - e2[2] * p[0])
               + e1[2] * (e2[0] * p[1] - e2[1] * p[0]))
        if det != 0 or all(x == 0 for x in p):
            return False
    return True


@claim("patch_properties", paper_ref=["def:surface_patch", "def:rational_patch", "triangular_trig_surface",
                                      "rational_patch", "sec:triangular_trigonometric_patches", "sec:applications"],
       statement="Patches are affinely invariant, lie in the convex hull of their nets (n <= 3), interpolate the "
                 "corners, have the printed boundary curves and corner tangent planes; rational patches are "
                 "projectively invariant. Torus patches join continuously. Seeded random nets, n in {ns}, alpha in "
                 "{alphas}, float64 to < 1e-9; tangent planes also exactly at tan(alpha/4) in {tangent_ts}.",
       kind="numeric-evidence", ns=[1, 2, 3], alphas=["0.4", "pi/2", "2.8"], nets=4, points=400, seed=23,
       tangent_ts=["1/3", "2/3"])
def run_properties(ns, alphas, nets, points, seed, tangent_ts) -> Outcome:
    from paper_repro.core.alphas import alpha_float

    rng = np.random.default_rng(seed)
    res = {"affine": 0.0, "convex_hull_outside": 0, "corners": 0.0, "boundary": 0.0, "tangent_planes": 0.0,
           "projective": 0.0}
    for n in ns:
        for a_text in alphas:
            al = alpha_float(a_text)
            pts = sample_points(al, points, seed=seed)
            for _ in range(nets):
                net = _random_net(rng, n)
                patch = Patch(n, al, net)
                vals = patch(pts)
                A, t = rng.normal(size=(3, 3)), rng.normal(size=3)
                moved = Patch(n, al, net @ A.T + t)(pts)
                res["affine"] = max(res["affine"], float(np.abs(moved - (vals @ A.T + t)).max()))
                hull = Delaunay(net)
                res["convex_hull_outside"] += int(np.sum(hull.find_simplex(vals, tol=1e-12) < 0))
                idx = index_of(n)
                corners = {"r": np.array([[al, 0, 0]]), "g": np.array([[0, 0, al]]), "b": np.array([[0, al, 0]])}
                for letter, p in corners.items():
                    corner = net[idx[f"{letter}_{{{2 * n},{2 * n},0}}"]]
                    res["corners"] = max(res["corners"], float(np.abs(patch(p)[0] - corner).max()))
                tt = np.linspace(0, al, 7)
                for edge, dom in (("v=0", np.c_[tt, 0 * tt, al - tt]), ("u=0", np.c_[0 * tt, al - tt, tt]),
                                  ("w=0", np.c_[al - tt, tt, 0 * tt])):
                    gap = float(np.abs(patch.boundary_curve(edge, tt) - patch(dom)).max())
                    res["boundary"] = max(res["boundary"], gap)
                # tangent planes at the three corners: spanned by the terminal edges (exact derivatives)
                for letter in CORNERS:
                    res["tangent_planes"] = max(res["tangent_planes"], tangent_plane_residual(patch, letter))
                # rational patch: projective invariance
                w = rng.uniform(0.2, 2.0, size=delta(n))
                H = np.eye(4) + 0.1 * rng.normal(size=(4, 4))
                hom = np.c_[net, np.ones(len(net))] @ H.T
                new_w = w * hom[:, 3]
                if np.all(new_w > 0):
                    lhs = Patch(n, al, hom[:, :3] / hom[:, 3:], weights=new_w)(pts)
                    img = np.c_[Patch(n, al, net, weights=w)(pts), np.ones(points)] @ H.T
                    res["projective"] = max(res["projective"], float(np.abs(lhs - img[:, :3] / img[:, 3:]).max()))
    exact_rng = np.random.default_rng(seed)
    exact_planes = {}
    for n in ns:
        for t in tangent_ts:
            net = [[int(x) for x in row] for row in exact_rng.integers(-9, 10, size=(delta(n), 3))]
            exact_planes[f"n={n}, tan(alpha/4)={t}"] = all(
                tangent_plane_exact(n, fmpq(*map(int, t.split("/"))), net, letter) for letter in CORNERS)
    al = float(mpmath.pi / 2)
    mu = 3.0
    rho = (1 + 5**0.5) / 2 * mu
    tor = torus_pieces(al, rho, mu, [0.0, al], [0.0, al, 2 * al])
    res["torus_join_gap"] = model_gap(tor, al)
    data = {"meshes/torus.obj": _mesh_data(tor, 10), "meshes/torus.ply": _mesh_data(tor, 10)}
    tol = 1e-9  # float64 evaluation of O(1) nets (rounding level ~1e-15)
    ok = (res["affine"] < tol and res["convex_hull_outside"] == 0 and res["corners"] < tol and res["boundary"] < tol
          and res["tangent_planes"] < tol and res["projective"] < tol and res["torus_join_gap"] < tol
          and all(exact_planes.values()))
    raw = {k: v for k, v in res.items() if isinstance(v, float)}
    measured = {k: (bound(v, tol) if isinstance(v, float) else v) for k, v in res.items()}
    measured["tangent_planes_exact"] = exact_planes
    measured["tolerance"] = tol
    measured["scope"] = (f"random nets (seeded), n in {ns}, alpha in {alphas}, float64 (each maximum published as the "
                         "bound it clears); convex hull: Delaunay point location; tangent planes at the three corners: "
                         "sine of the angle between the derivatives along both boundary directions (exact derivatives "
                         "of the library, Patch.derivative) and the plane of the terminal edges, < 1e-9 (a wrong plane "
                         "gives the sine of its angle, O(1) for random nets), and exactly (determinant 0) for integer "
                         f"nets at tan(alpha/4) in {tangent_ts}")
    return Outcome(ok, measured, data=data, raw=raw)

#: --alpha range where the claim has been run and verified (the issue-22 fuzzing measured the earlier finite-difference
#: tangent check: 2.8e-4 at alpha = 0.01 and 3.7e-4 at 3.14 against 1e-4); the derivative-based check that replaced it
#: was not measured outside this range, so the range stays.
ALPHA_RANGES["patch_properties"] = (0.06, 3.13, "run and verified in this range; the tangent-plane check outside it "
                                                "was not measured")
