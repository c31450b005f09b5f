"""Cost model of the public API (issue 22): time and peak memory vs size, one call per line, each in a fresh
process (so caches and earlier allocations do not count).  The limits of :mod:`paper_repro.util.limits` are
read off this table (budget: about 20 s and 2 GB per call).

    python tools/cost_model.py [GROUP ...]        # groups: coefficients elevation fit rational_points bezier mesh
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

SETUP = ("import math, mpmath, numpy as np; from paper_repro import *; from paper_repro.core.labels import delta; "
         "from paper_repro.core.domain import rational_alpha; ")
GROUPS = {
    "coefficients": [f"coefficients({n}, 1.0, {a!r})" for a in ("float",) for n in (10, 60, 150)]
    + [f"coefficients({n}, 1.0, 'mp')" for n in (10, 20, 40)]
    + [f"coefficients({n}, rational_alpha((1, 3)), 'exact')" for n in (10, 20, 40, 80)],
    "elevation": [f"elevation_matrix({n}, {a!r})" for n in (10, 20, 30, 40) for a in (1.0, 1e-9)],
    "fit": [f"fit(lambda u, v, w: [mpmath.cos(u - v), mpmath.sin(w)], {n}, 1.0)" for n in (2, 3, 4, 5)]
    + [f"fit(lambda t: [t.cos(1, 0, 0)], {n}, rational_alpha((1, 3)), 'exact')" for n in (2, 3, 4)],
    "rational_points": [f"sample_rational_points(rational_alpha((1, 2)), {c})" for c in (10**4, 10**5)],
    "bezier": [f"bezier_limit(np.zeros((delta({n}), 3)), {n})" for n in (10, 20, 30)],
    "mesh": [f"Patch(2, 1.0, np.zeros((19, 3))).mesh({r}, normals=True)" for r in (512, 1024)],
}

PROBE = """
import resource, time, sys
{setup}
t0 = time.perf_counter()
{call}
dt = time.perf_counter() - t0
print(dt, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
"""


def measure(call: str, timeout: float = 90.0) -> tuple[float | None, float | None]:
    env = dict(os.environ, PAPER_REPRO_NO_CACHE="1")
    try:
        out = subprocess.run([sys.executable, "-c", PROBE.format(setup=SETUP, call=call)], capture_output=True,
                             text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return None, None
    if out.returncode:
        return float("nan"), float("nan")
    t, m = out.stdout.split()[-2:]
    return float(t), float(m)


def main(argv: list[str]) -> int:
    rows = []
    for group in argv or list(GROUPS):
        for call in GROUPS[group]:
            t, m = measure(call)
            rows.append({"group": group, "call": call, "seconds": t, "peak_MB": m})
            shown = "timeout" if t is None else f"{t:8.2f} s {m:8.0f} MB"
            print(f"{group:16s} {call[:70]:70s} {shown}", flush=True)
    os.makedirs("build", exist_ok=True)
    with open("build/cost_model.json", "w") as fh:
        json.dump(rows, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
