"""Claim ``float_accuracy``: the fast float64 path against the mp route, over alpha in [1e-3, pi - 1e-3].

For each order n and each alpha of a grid that includes both ends (geometric near 0, linear in the
middle, mirrored near pi), seeded random points of Omega^alpha (corners and edge points included) are
evaluated by the float path of :class:`~paper_repro.surfaces.patch.Patch` (blocked kernel) and by the
mpmath route at 30 digits, at the point with the same u, v and w = alpha - u - v exactly (so the float
input's own rounding off the plane counts as error of the float path, as it does for a user).
Measured: the max |sum of the blending values - 1| (partition of unity) and the max error of patch
points of a seeded random net, relative to the net's largest coordinate (norm-wise relative error; a
pointwise relative error is meaningless where a patch point is 0).  Published in
``data/accuracy/float_vs_mp.json``; figure ``float_accuracy``.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from paper_repro.core.domain import sample_points
from paper_repro.core.labels import delta
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.surfaces.patch import Patch
from paper_repro.util.measured import bound, decade_bound, sig
from paper_repro.util.registry import Outcome, claim
from paper_repro.util.tasks import Task


def alpha_grid(count: int) -> list[float]:
    """``count`` alpha in [1e-3, pi - 1e-3], both ends included, dense near the ends."""
    k = count // 3
    low = np.geomspace(1e-3, 0.3, k)
    mid = np.linspace(0.3, math.pi - 0.3, count - 2 * k + 2)[1:-1]
    high = math.pi - low[::-1]
    return [float(a) for a in np.concatenate([low, mid, high])]


def test_points(alpha: float, count: int, seed: int) -> np.ndarray:
    corners = np.eye(3) * alpha
    edges = np.array([[0.5, 0.5, 0.0], [0.0, 0.3, 0.7], [0.9, 0.0, 0.1]]) * alpha
    return np.vstack([corners, edges, sample_points(alpha, count, seed=seed, interior=False)])


def errors(n: int, alpha: float, count: int, seed: int, dps: int) -> tuple[float, float]:
    pts = test_points(alpha, count, seed)
    net = np.random.default_rng(seed + n).normal(size=(delta(n), 3))
    patch = Patch(n, alpha, net)
    fl_basis = evaluate_normalized(n, alpha, pts)
    fl_points = patch(pts)
    with mpmath.workdps(dps):
        # the reference point: u, v as given (exact binary values), w = alpha - u - v exactly on the plane
        a = mpmath.mpf(alpha)
        exact_pts = np.array([[mpmath.mpf(u), mpmath.mpf(v), a - mpmath.mpf(u) - mpmath.mpf(v)] for u, v, _ in pts],
                             dtype=object)
        mp_basis = evaluate_normalized(n, a, exact_pts, "mp", dps=dps)
        mp_points = patch.from_blending_values(mp_basis, arith="mp", dps=dps)  # = patch(exact_pts, arith="mp")
        mp_basis_sum = mp_basis.sum(axis=1)
        pou_mp = max(abs(float(x - 1)) for x in mp_basis_sum)
    if pou_mp > 1e-25:
        raise ArithmeticError(f"mp route not a partition of unity (n={n}, alpha={alpha}): {pou_mp}")
    pou = float(np.max(np.abs(fl_basis.sum(axis=1) - 1.0)))
    ref = np.vectorize(float)(mp_points)
    rel = float(np.max(np.abs(fl_points - ref)) / np.max(np.abs(net)))
    return pou, rel


def errors_at(n: int, alpha_count: int, count: int, seed: int, dps: int) -> list[tuple[float, float]]:
    """Task: :func:`errors` of order n at every alpha of :func:`alpha_grid` (the k-th with seed ``seed + k``)."""
    return [errors(n, alpha, count, seed + k, dps) for k, alpha in enumerate(alpha_grid(alpha_count))]


@claim("float_accuracy", paper_ref=["normalized_united_system", "triangular_trig_surface"],
       statement="The float64 path is accurate: for n = {ns} and {alpha_count} values of alpha in [1e-3, pi - 1e-3] "
                 "(both ends included), the partition of unity holds to |sum - 1| <= {tolerance} and patch points "
                 "agree with the mp route ({dps} digits) to {tolerance} relative to the net.",
       kind="numeric-evidence", ns=[1, 2, 3, 4, 5, 6], alpha_count=24, points=24, seed=31, dps=30, tolerance=1e-13,
       split=True)
def run(ns, alpha_count, points, seed, dps, tolerance):
    grid = alpha_grid(alpha_count)
    rows, raw_rows = [], []
    per_n = yield [Task(errors_at, (n, alpha_count, points, seed, dps)) for n in ns]  # one task per n, in order
    for n, errs in zip(ns, per_n):
        for alpha, (pou, rel) in zip(grid, errs):
            raw_rows.append({"n": n, "alpha": alpha, "partition_of_unity": pou, "patch_relative": rel})
            rows.append({"n": n, "alpha": sig(alpha, 6), "partition_of_unity_below": decade_bound(pou),
                         "patch_relative_below": decade_bound(rel)})
    worst_pou = max(r["partition_of_unity"] for r in raw_rows)
    worst_rel = max(r["patch_relative"] for r in raw_rows)
    return Outcome(worst_pou <= tolerance and worst_rel <= tolerance, {
        "max_partition_of_unity_error": bound(worst_pou, tolerance),
        "max_patch_relative_error": bound(worst_rel, tolerance),
        "alpha_range": ["1e-3", "pi - 1e-3"], "points_per_alpha": points + 6,
        "worst_by_n_below": {str(n): max(max(r["partition_of_unity_below"], r["patch_relative_below"])
                                         for r in rows if r["n"] == n) for n in ns},
        "published": "errors are float64 rounding level and differ between machines in their last bits: data/ "
                     "holds the bound they clear and, per row, the next power of ten above each error; the raw "
                     "errors are in build/measured_raw.json"},
        data={"accuracy/float_vs_mp.json": {"reference": f"mpmath, {dps} digits",
                                            "values": "per row the smallest power of ten >= the measured error",
                                            "rows": rows}},
        raw={"rows": raw_rows})
