"""Claim ``boundary``: the boundary properties (eqs. boundary_property_1..3).

On each edge of Omega^alpha the joint system reduces to the univariate B-basis divided by its
constants::

    T_{2n}|_{v=0} = {A_{2n,2n-i}(u) / c_{2n,2n-i}}_{i=0}^{2n}     (boundary_property_1)
    T_{2n}|_{u=0} = {A_{2n,2n-i}(w) / c_{2n,2n-i}}_{i=0}^{2n}     (boundary_property_2)
    T_{2n}|_{w=0} = {A_{2n,2n-i}(v) / c_{2n,2n-i}}_{i=0}^{2n}     (boundary_property_3)

Checked at high precision (mpmath) on points of each edge: the functions of T_{2n} that do not
vanish on the edge are matched one-to-one with the 2n+1 univariate functions (a bijection is
required, found by values, not by labels), all other functions vanish identically there.
"""

from __future__ import annotations

import mpmath
import numpy as np

from paper_repro.core.alphas import alpha_mp
from paper_repro.core.basis import evaluate
from paper_repro.core.labels import united_system
from paper_repro.core.univariate import A, c_const
from paper_repro.util.measured import bound
from paper_repro.util.registry import Outcome, claim


#: Matching tolerance at ``dps`` digits: values are O(1), so residuals are rounding only.
def _tol(dps: int) -> mpmath.mpf:
    return mpmath.mpf(10) ** (-(dps - 10))


EDGES = {  # edge name -> (index of the vanishing variable, index of the univariate variable)
    "v=0": (1, 0),  # boundary_property_1: A(u)
    "u=0": (0, 2),  # boundary_property_2: A(w)
    "w=0": (2, 1),  # boundary_property_3: A(v)
}


def edge_points(alpha, edge: str, count: int) -> np.ndarray:
    """``count`` points of the edge, the univariate variable running over (0, alpha)."""
    zero, var = EDGES[edge]
    other = 3 - zero - var
    pts = np.empty((count, 3), dtype=object)
    for k in range(count):
        t = alpha * mpmath.mpf(k + 1) / (count + 1)
        pts[k, zero], pts[k, var], pts[k, other] = mpmath.mpf(0), t, alpha - t
    return pts


def check_edge(n: int, alpha, edge: str, count: int, dps: int) -> dict:
    with mpmath.workdps(dps):
        pts = edge_points(alpha, edge, count)
        vals = evaluate(n, alpha, pts, "mp", dps=dps)
        t = pts[:, EDGES[edge][1]]
        expected = A(n, alpha, t, "mp")
        for i in range(2 * n + 1):  # A_{2n,2n-i} / c_{2n,2n-i}, column index i
            expected[:, 2 * n - i] = expected[:, 2 * n - i] / c_const(n, 2 * n - i, alpha, "mp")
        labels = united_system(n)
        surviving = [k for k in range(vals.shape[1]) if any(x != 0 for x in vals[:, k])]
        tol = _tol(dps)
        matching: dict[str, str] = {}
        used: set[int] = set()
        worst = mpmath.mpf(0)
        for k in surviving:
            errs = [max(abs(vals[p, k] - expected[p, 2 * n - i]) for p in range(count)) for i in range(2 * n + 1)]
            best = min(range(2 * n + 1), key=lambda i: errs[i])
            if errs[best] <= tol and best not in used:
                used.add(best)
                matching[labels[k].paper] = f"A_{{{2 * n},{2 * n - best}}}/c_{{{2 * n},{2 * n - best}}}"
                worst = max(worst, errs[best])
        ok = len(surviving) == 2 * n + 1 and len(matching) == 2 * n + 1
        return {"ok": ok, "surviving": len(surviving), "matched": len(matching), "max_abs_error": worst,
                "matching": matching}


@claim("boundary", paper_ref=["boundary_property_1", "boundary_property_2", "boundary_property_3"],
       statement="On each edge of Omega^alpha exactly 2n+1 functions of T_{2n} survive and they are the "
                 "univariate B-basis functions A_{2n,2n-i}/c_{2n,2n-i} (eqs. boundary_property_1..3); "
                 "n = {ns}, alpha in {alphas}, {dps} digits.",
       kind="numeric-evidence", ns=list(range(1, 9)), alphas=["pi/6", "pi/3", "pi/2", "2pi/3", "5pi/6", "3.1"],
       points_per_edge=12, dps=50)
def run(ns: list[int], alphas: list[str], points_per_edge: int, dps: int) -> Outcome:
    failures, worst = [], mpmath.mpf(0)
    sample_matching = {}
    for n in ns:
        for a_text in alphas:
            with mpmath.workdps(dps):
                alpha = alpha_mp(a_text)
            for edge in EDGES:
                res = check_edge(n, alpha, edge, points_per_edge, dps)
                worst = max(worst, res["max_abs_error"])
                if not res["ok"]:
                    failures.append({"n": n, "alpha": a_text, "edge": edge, "surviving": res["surviving"],
                                     "matched": res["matched"]})
                if n == 2 and a_text == alphas[0]:
                    sample_matching[edge] = res["matching"]
    return Outcome(not failures, {
        "max_abs_error": bound(worst, 10.0 ** -(dps - 10)), "tolerance": f"1e-{dps - 10}", "dps": dps,
        "cases": len(ns) * len(alphas) * 3, "failures": failures, "matching_n_2": sample_matching},
        raw={"max_abs_error": mpmath.nstr(worst, 5)})
