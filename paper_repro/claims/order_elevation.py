"""Claim ``order_elevation``: Example exmp:degree_elevation_from_1_to_2 and general elevation n -> n+1."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from flint import fmpq

from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.elevation import elevate, elevation_matrix_exact
from paper_repro.core.labels import delta, index_of, united_system
from paper_repro.printed.limits import printed_elevation_rows
from paper_repro.surfaces.patch import Patch
from paper_repro.util.measured import bound, sig
from paper_repro.util.registry import Outcome, claim


def _q(x) -> fmpq:
    return fmpq(x.numerator, x.denominator) if isinstance(x, Fraction) else (x if isinstance(x, fmpq) else fmpq(x))


def printed_matrix(alpha) -> list[list[fmpq]]:
    c2, s2 = alpha.cos_half**2, alpha.sin_half**2
    i1, i2 = index_of(1), index_of(2)
    mat = [[fmpq(0)] * delta(1) for _ in range(delta(2))]
    for lab, terms in printed_elevation_rows(c2, s2).items():
        for wt, l1 in terms:
            mat[i2[lab]][i1[l1]] += _q(wt)
    return mat


def node_distance(net: np.ndarray, n: int, alpha: float) -> float:
    """max distance from each control point to the patch point at its node's barycentric position."""
    from paper_repro.core.layout import CORNERS, position

    patch = Patch(n, alpha, net)
    worst = 0.0
    u, v, w = CORNERS["u"], CORNERS["v"], CORNERS["w"]
    for k, lab in enumerate(united_system(n)):
        p = position(lab)
        mat = np.array([[u[0], v[0], w[0]], [u[1], v[1], w[1]], [1, 1, 1]])
        bary = np.linalg.solve(mat, [p[0], p[1], 1])
        bary = np.clip(bary, 0, 1) / np.clip(bary, 0, 1).sum()
        worst = max(worst, float(np.linalg.norm(patch.at_barycentric([bary])[0] - net[k])))
    return worst


@claim("order_elevation", paper_ref=["exmp:degree_elevation_from_1_to_2", "fig:degree_elevation_from_1_to_2",
                                     "sec:open_problems"],
       statement="The printed 1->2 elevated control points equal the exact elevation and are convex combinations; "
                 "general elevation n->n+1 exists (V_n in V_{n+1}) and its weights are non-negative at all sampled "
                 "alpha (tan(alpha/4) in {ts}) for n = 1..{n_max} (evidence).",
       kind="exact-evidence", ts=["1/20", "1/7", "1/3", "1/2", "2/3", "9/10", "19/20"], n_max=6, random_nets=20,
       seed=17, chain_alpha="2/5", chain_orders=6, extended={"n_max": 8})
def run(ts, n_max, random_nets, seed, chain_alpha, chain_orders) -> Outcome:
    alphas = [rational_alpha(fmpq(*map(int, t.split("/")))) for t in ts]
    printed_ok = {t: printed_matrix(a) == elevation_matrix_exact(1, a) for t, a in zip(ts, alphas)}
    printed_convex = all(min(min(r) for r in printed_matrix(a)) >= 0 for a in alphas)
    rng = np.random.default_rng(seed)
    patch_dev = 0.0
    for a in alphas:
        af = float(a)
        pts = sample_points(af, 200, seed=seed)
        for _ in range(random_nets // len(alphas) + 1):
            net1 = rng.normal(size=(delta(1), 3))
            net2 = np.array([[float(x) for x in row] for row in printed_matrix(a)]) @ net1
            patch_dev = max(patch_dev, float(np.max(np.abs(Patch(1, af, net1)(pts) - Patch(2, af, net2)(pts)))))
    general = {}
    for n in range(1, n_max + 1):
        mins = [min(min(r) for r in elevation_matrix_exact(n, a)) for a in alphas]
        general[str(n)] = {"min_weight": str(min(mins)), "all_non_negative": all(m >= 0 for m in mins)}
    # repeated elevation: distance of the control net to the patch
    ca = rational_alpha(fmpq(*map(int, chain_alpha.split("/"))))
    net = rng.normal(size=(delta(1), 3))
    chain = [node_distance(net, 1, float(ca))]
    for k in range(1, chain_orders):
        net = elevate(net, k, ca)
        chain.append(node_distance(net, k + 1, float(ca)))
    ok = all(printed_ok.values()) and printed_convex and patch_dev < 1e-12 and \
        all(g["all_non_negative"] for g in general.values())
    return Outcome(ok, {
        "printed_equals_exact_elevation": printed_ok, "printed_weights_non_negative": printed_convex,
        "patch_max_deviation_float64": bound(patch_dev, 1e-12), "general_elevation": general,
        "repeated_elevation_net_to_patch_distance": {"alpha": f"4 atan({chain_alpha})",
                                                     "by_order": [sig(x, 4) for x in chain]},
        "scope": "exact at sampled rational-tangent alpha (evidence for all alpha); non-negativity of general "
                 "elevation weights is evidence toward the open problem; distances of float64 nets to 4 digits"},
        raw={"patch_max_deviation_float64": patch_dev, "repeated_elevation_net_to_patch_distance": chain})
