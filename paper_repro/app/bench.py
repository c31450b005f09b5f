"""`make bench`: patch evaluation against the `bezier` package and the mpmath route, in one run.

Writes ``reports/bench.json`` and ``reports/bench.md`` (timings are machine-dependent, so they live in
``reports/``, never in ``data/``):

* Patch / bezier ratios (issue 21) at ``points`` random points of Omega^alpha (alpha = pi/2), best of ``repeat``,
  n = 1, 3, 6, 10, each in a fresh process, four times: idle and loaded (one busy process per core minus one,
  started and stopped by the bench, each ending by itself after 15 min at the latest), with the default BLAS
  threads and with ``OPENBLAS_NUM_THREADS=1``: :class:`~paper_repro.surfaces.patch.Patch` with the kernel's
  default threads and with one, ``bezier.Triangle.evaluate_cartesian_multi`` of degree 3n - 1 (the degree of the
  alpha -> 0 limit), ``Patch.derivative`` and ``Patch.normals`` against bezier's hodograph route;
* the physical floor (three sin/cos pairs, the distinct s^a c^b products, one dot product of length delta_n per
  coordinate; micro-benchmarks on cache-sized blocks) and Patch's one-thread time as a multiple of it;
* the work memory (tracemalloc peak beyond input and output) of evaluation, derivative and normals at 1e5 and
  1e7 points; the mpmath route per point, extrapolated;
* (without ``--patch-only``) exact normalizing coefficients (flint) against the same collocation in mpmath, the
  exact rank certificate, the closed-form recovery.

Run: ``python -m paper_repro.app.bench [--points N] [--repeat R] [--ns 1,3,6,10] [--patch-only] [--quick]``.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time
import tracemalloc

import numpy as np

from paper_repro.core.context import ExactContext, MpContext
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.labels import delta
from paper_repro.core.normalization import orbits, solve_reduced, solve_reduced_exact
from paper_repro.surfaces.patch import Patch
from paper_repro.util.io import reports_dir, write_json, write_text


def _best(f, repeat: int) -> float:
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t0)
    return best


def _peak_bytes(f) -> int:
    tracemalloc.start()
    f()
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


def _growth(ns: list[int], ts: list[float]) -> float | None:
    """Least-squares exponent k of t ~ C n^k."""
    pairs = [(math.log(n), math.log(t)) for n, t in zip(ns, ts) if t > 0]
    if len(pairs) < 2:
        return None
    x, y = np.array(pairs).T
    return round(float(np.polyfit(x, y, 1)[0]), 2)


def _bezier_setup(n: int, rng):
    """A random ``bezier.Triangle`` of degree 3n - 1 in 3-D and its two hodographs (degree 3n - 2, 6 rows)."""
    import bezier
    from bezier.hazmat.triangle_helpers import jacobian_both

    deg = 3 * n - 1
    nodes = np.asfortranarray(rng.normal(size=(3, (deg + 1) * (deg + 2) // 2)))
    tri = bezier.Triangle(nodes, degree=deg, copy=False)
    hod = bezier.Triangle(np.asfortranarray(jacobian_both(nodes, deg, 3)), degree=deg - 1, copy=False)
    return deg, tri, hod


def _bezier_normals(hod, bary):
    d = hod.evaluate_cartesian_multi(bary)
    nrm = np.cross(d[:3].T, d[3:].T)
    return nrm / np.linalg.norm(nrm, axis=1, keepdims=True)


def _kernel_name() -> str:
    """The float path's kernel in this process: ``numba`` (the compiled kernel, extra ``fast``) or ``numpy``."""
    from paper_repro.core.fast_jit import available

    return "numba" if available() else "numpy"


def patch_ratios(ns: list[int], points: int, repeat: int) -> list[dict]:
    """Patch against bezier in this process (its environment decides BLAS threads): point evaluation with the
    kernel's default threads and with one thread (``PAPER_REPRO_THREADS=1``), derivative and normals against
    bezier's hodograph route (the two first-derivative triangles of degree 3n - 2, evaluated at the points)."""
    alpha = math.pi / 2
    pts = sample_points(alpha, points, seed=1)
    bary = np.asfortranarray(pts[:, :2] / alpha)  # (P, 2) barycentric (s, t), Fortran order as bezier wants
    rows = []
    for n in ns:
        rng = np.random.default_rng(n)
        patch = Patch(n, alpha, rng.normal(size=(delta(n), 3)))
        patch(pts[:10])  # coefficients and kernel set up outside the timing
        deg, tri, hod = _bezier_setup(n, rng)
        t_ours = _best(lambda p=patch: p(pts), repeat)
        t_bez = _best(lambda t=tri: t.evaluate_cartesian_multi(bary), repeat)
        os.environ["PAPER_REPRO_THREADS"] = "1"
        try:
            t_one = _best(lambda p=patch: p(pts), repeat)
        finally:
            os.environ.pop("PAPER_REPRO_THREADS")
        os.environ["PAPER_REPRO_KERNEL"] = "numpy"
        try:
            numpy_patch = Patch(n, alpha, patch.net)
            numpy_patch(pts[:10])
            t_numpy = _best(lambda p=numpy_patch: p(pts), repeat)
        finally:
            os.environ.pop("PAPER_REPRO_KERNEL")
        t_der = _best(lambda p=patch: p.derivative(pts, "u"), repeat)
        t_nrm = _best(lambda p=patch: p.normals(pts), repeat)
        t_bder = _best(lambda h=hod: h.evaluate_cartesian_multi(bary), repeat)  # both derivatives at once
        t_bnrm = _best(lambda h=hod: _bezier_normals(h, bary), repeat)
        rows.append({"n": n, "delta_n": delta(n), "bezier_degree": deg, "points": points, "kernel": _kernel_name(),
                     "patch_numpy_path_s": round(t_numpy, 4),
                     "patch_s": round(t_ours, 4), "patch_1thread_s": round(t_one, 4), "bezier_s": round(t_bez, 4),
                     "ratio_patch_over_bezier": round(t_ours / t_bez, 3),
                     "thread_speedup": round(t_one / t_ours, 2),
                     "derivative_s": round(t_der, 4), "normals_s": round(t_nrm, 4),
                     "derivative_over_point": round(t_der / t_ours, 2), "normals_over_point": round(t_nrm / t_ours, 2),
                     "bezier_hodographs_s": round(t_bder, 4), "bezier_normals_s": round(t_bnrm, 4),
                     "derivative_over_bezier": round(t_der / t_bder, 3),
                     "normals_over_bezier": round(t_nrm / t_bnrm, 3)})
        print(f"  n={n}: patch {t_ours:.3f}s (1 thread {t_one:.3f}s, numpy path {t_numpy:.3f}s) "
              f"bezier {t_bez:.3f}s ratio {t_ours / t_bez:.3f}; "
              f"derivative {t_der:.3f}s normals {t_nrm:.3f}s; bezier hodographs {t_bder:.3f}s normals {t_bnrm:.3f}s",
              flush=True)
    return rows


def mp_route(ns: list[int], points: int, mp_points: int) -> list[dict]:
    """The mpmath route (30 digits) per point, extrapolated to ``points``, against Patch's float path."""
    alpha = math.pi / 2
    pts = sample_points(alpha, points, seed=1)
    rows = []
    for n in ns:
        patch = Patch(n, alpha, np.random.default_rng(n).normal(size=(delta(n), 3)))
        patch(pts[:10])
        t_ours = _best(lambda p=patch: p(pts), 3)
        few = pts[:mp_points]
        t_mp = _best(lambda p=patch: p(few, arith="mp", dps=30), 1) / mp_points * points
        rows.append({"n": n, "points": points, "patch_s": round(t_ours, 4), "mp_route_s_extrapolated": round(t_mp, 1),
                     "speedup_vs_mp": round(t_mp / t_ours)})
        print(f"  n={n}: mp route ~{t_mp:.0f}s ({t_mp / t_ours:.0f}x)", flush=True)
    return rows


def memory_rows(n: int, sizes: list[int]) -> list[dict]:
    """Peak traced memory (tracemalloc) of evaluation, derivative and normals beyond input and output, per size."""
    alpha = math.pi / 2
    patch = Patch(n, alpha, np.random.default_rng(n).normal(size=(delta(n), 3)))
    rows = []
    for size in sizes:
        pts = sample_points(alpha, size, seed=2)
        out_bytes = size * 3 * 8
        row = {"n": n, "points": size}
        for name, f, outs in (("evaluation", lambda p=pts: patch(p), 1),
                              ("derivative", lambda p=pts: patch.derivative(p), 1),
                              ("normals", lambda p=pts: patch.normals(p), 1)):
            f()  # set-up outside
            row[f"{name}_work_MB"] = round((_peak_bytes(f) - outs * out_bytes) / 1e6, 1)
        rows.append(row)
        print(f"  memory n={n} points={size:,}: " + ", ".join(f"{k} {v}" for k, v in row.items() if k.endswith("MB")),
              flush=True)
    return rows


def floor_estimate(ns: list[int], points: int, repeat: int) -> list[dict]:
    """The physical floor per point (issue 21), from micro-benchmarks of its operations on cache-sized blocks, one
    thread: three sin/cos pairs, the distinct s^a c^b products of the three variables (one multiply each), and one
    dot product of length delta_n per coordinate.  Patch's one-thread time as a multiple of it."""
    from paper_repro.core.fast import FloatKernel, single_threaded_blas
    from paper_repro.core.fast_jit import JIT_BLOCK as BLOCK
    from paper_repro.core.labels import exponent_matrix

    alpha = math.pi / 2
    pts = sample_points(alpha, points, seed=1)
    rng = np.random.default_rng(0)
    blk = pts[:BLOCK].copy()
    nblocks = points / BLOCK
    rows = []
    for n in ns:
        kern = FloatKernel(exponent_matrix(n))
        products = sum(len(p) for p in kern.pairs)
        # each operation at the block size where it is fastest per point (a floor: the best case of each)
        t_trig = t_prod = t_dot = math.inf
        for size in FLOOR_BLOCKS:
            half = pts[:size].copy()
            x, y, o = rng.random((size, products)), rng.random((size, products)), np.empty((size, products))
            b, net = rng.random((size, delta(n))), rng.random((delta(n), 3))
            r = np.empty((size, 3))
            bt, nt, rt = np.ascontiguousarray(b.T), np.ascontiguousarray(net.T), np.empty((3, size))
            scale = points / size
            with single_threaded_blas():
                t_trig = min(t_trig, _best(lambda h=half: (np.sin(h), np.cos(h)), 50 * repeat) * scale)
                t_prod = min(t_prod, _best(lambda x=x, y=y, o=o: np.multiply(x, y, out=o), 50 * repeat) * scale)
                # the dot products in both layouts (BLAS is faster with the points last: 101 against 135-257
                # ns/point at n = 6)
                t_dot = min(t_dot, _best(lambda b=b, net=net, r=r: np.dot(b, net, out=r), 50 * repeat) * scale,
                            _best(lambda bt=bt, nt=nt, rt=rt: np.dot(nt, bt, out=rt), 50 * repeat) * scale)
        floor = t_trig + t_prod + t_dot
        patch = Patch(n, alpha, rng.normal(size=(delta(n), 3)))
        patch(pts[:10])
        os.environ["PAPER_REPRO_THREADS"] = "1"
        try:
            t_one = _best(lambda p=patch: p(pts), repeat)
            # the same method as the floor: best of many single blocks (a busy machine has quiet moments)
            t_blk = _best(lambda p=patch: p(blk), 50 * repeat) * nblocks
        finally:
            os.environ.pop("PAPER_REPRO_THREADS")
        rows.append({"n": n, "points": points, "products": products, "sincos_s": round(t_trig, 4),
                     "products_s": round(t_prod, 4), "dot_s": round(t_dot, 4), "floor_s": round(floor, 4),
                     "floor_ns_per_point": round(floor / points * 1e9, 1), "patch_1thread_s": round(t_one, 4),
                     "multiple_of_floor": round(t_one / floor, 2), "patch_block_best_s": round(t_blk, 4),
                     "multiple_of_floor_same_method": round(t_blk / floor, 2)})
        print(f"  floor n={n}: {floor:.3f}s ({floor / points * 1e9:.0f} ns/point: sincos {t_trig:.3f}, {products} "
              f"products {t_prod:.3f}, dot {t_dot:.3f}); Patch 1 thread {t_one:.3f}s = {t_one / floor:.2f}x, "
              f"best block x blocks {t_blk:.3f}s = {t_blk / floor:.2f}x", flush=True)
    return rows


_REFERENCE_WORK = ("import numpy as np, time\nx = np.random.default_rng(0).random(8192)\nt = time.perf_counter()\n"
                   "for _ in range(3000):\n    np.sin(x)\nprint(time.perf_counter() - t)")


def interleaved(ns: list[int], points: int, reps: int = 6) -> dict:
    """Rounds (``reps``) of: Patch point evaluation with one thread, the same with the default threads, the
    derivative along u and the normals (default threads), idle and with one busy process per core minus one.
    Alternating the four in every round exposes them to the same load, so the ratios (threads' speed-up;
    derivative and normals over a point evaluation, per round) are not skewed by a load that changes between
    separate best-of runs.  Also the machine's own reference: the same fixed numeric work in one process, then in
    as many processes as cores at once (the throughput gain the hardware gives, the ceiling for threads)."""
    import subprocess
    import sys

    cores = os.cpu_count() or 1
    alpha = math.pi / 2
    pts = sample_points(alpha, points, seed=1)

    def reference() -> float:
        one = float(subprocess.run([sys.executable, "-c", _REFERENCE_WORK], capture_output=True, text=True,
                                   check=True).stdout)
        procs = [subprocess.Popen([sys.executable, "-c", _REFERENCE_WORK], stdout=subprocess.PIPE, text=True)
                 for _ in range(cores)]
        many = max(float(p.communicate()[0]) for p in procs)
        return cores * one / many

    out = {"cores": cores, "reps": reps, "machine_gain": round(max(reference() for _ in range(3)), 2), "rows": []}
    for load in ("idle", "loaded"):
        busy = _start_busy(load, 300)
        try:
            for n in ns:
                patch = Patch(n, alpha, np.random.default_rng(n).normal(size=(delta(n), 3)))
                patch(pts[:10])
                patch.normals(pts[:10])
                work = {"1": lambda p=patch: p(pts), "default": lambda p=patch: p(pts),
                        "derivative": lambda p=patch: p.derivative(pts, "u"), "normals": lambda p=patch: p.normals(pts)}
                times: dict[str, list[float]] = {k: [] for k in work}
                for _ in range(reps):
                    for k, f in work.items():
                        if k == "1":
                            os.environ["PAPER_REPRO_THREADS"] = "1"
                        try:
                            times[k].append(_best(f, 1))
                        finally:
                            os.environ.pop("PAPER_REPRO_THREADS", None)
                one, many = times["1"], np.array(times["default"])
                per_round = {k: np.array(times[k]) / many for k in ("derivative", "normals")}
                row = {"load": load, "n": n, "one_min_s": round(min(one), 4), "default_min_s": round(min(many), 4),
                       "speedup_min": round(min(one) / min(many), 2),
                       "speedup_median": round(float(np.median(one) / np.median(many)), 2)}
                for k, r in per_round.items():
                    row[f"{k}_min_s"] = round(min(times[k]), 4)
                    row[f"{k}_over_point_median"] = round(float(np.median(r)), 2)
                    row[f"{k}_over_point_max"] = round(float(np.max(r)), 2)
                out["rows"].append(row)
                print(f"  interleaved {load} n={n}: 1 thread {min(one):.3f}s, default {min(many):.3f}s, speed-up "
                      f"{row['speedup_min']} (min) {row['speedup_median']} (median); derivative / point "
                      f"{row['derivative_over_point_median']} (median), normals / point "
                      f"{row['normals_over_point_median']} (median)", flush=True)
        finally:
            _stop_busy(busy)
    return out


#: The closed-form matrices timed by :func:`closed_forms` (issue 30): (label, call with ``n``), and the goals (s, cold).
CLOSED_FORMS = {
    "elevation_matrix": "paper_repro.elevation_matrix({n}, 1.0)",
    "transformation_matrix": "paper_repro.transformation_matrix({n}, 1.0)",
    "product_matrix B_{{2,2,0}}": "paper_repro.product_matrix({n}, 'B_{{2,2,0}}', 1.0)",
}
CLOSED_FORM_GOALS = {("elevation_matrix", 10): 0.05, ("elevation_matrix", 30): 1.0}
_COLD_CALL = """
import time, paper_repro
{function}  # imported before the clock starts (the package imports its names on first use)
t = time.perf_counter(); {call}; cold = time.perf_counter() - t
t = time.perf_counter(); {call}; warm = time.perf_counter() - t
print(cold, warm)
"""


def closed_forms(ns: dict[str, list[int]]) -> list[dict]:
    """Each closed-form matrix of issue 30 in a fresh process (the package imported first, then the first call --
    *cold*: its integer form built -- and a second call, *warm*), idle and with one busy process per core minus one;
    best of two fresh processes."""
    import subprocess
    import sys

    rows = []
    for load in ("idle", "loaded"):
        busy = _start_busy(load, 600)
        try:
            for name, call in CLOSED_FORMS.items():
                for n in ns[name]:
                    code = _COLD_CALL.format(call=call.format(n=n), function=call.split("(")[0])
                    runs = [tuple(map(float, subprocess.run([sys.executable, "-c", code], capture_output=True,
                                                            text=True, check=True).stdout.split()))
                            for _ in range(2)]
                    cold, warm = min(r[0] for r in runs), min(r[1] for r in runs)
                    goal = CLOSED_FORM_GOALS.get((name, n))
                    label = name.replace("{{", "{").replace("}}", "}")
                    rows.append({"load": load, "function": label, "n": n,
                                 "cold_s": round(cold, 4), "warm_s": round(warm, 4), "goal_cold_s": goal,
                                 "meets_goal": None if goal is None else cold <= goal})
                    print(f"  closed form {load} {label} n={n}: cold {cold:.3f}s, warm {warm:.3f}s", flush=True)
        finally:
            _stop_busy(busy)
    return rows


#: Goals of issue 38, item 6 (seconds): subdivision_matrix cold at n = 10 and 30; subdividing an order-10 net.
SUBDIVISION_GOALS = {("cold", 10): 0.05, ("cold", 30): 1.0, ("apply", 10): 1e-3}
_SUBDIVISION_CALL = """
import time, numpy as np
from paper_repro.core.subdivision import subdivision_matrix, subdivision_matrices, subdivide
from paper_repro.core.labels import delta
n = {n}
c = time.process_time(); t = time.perf_counter(); subdivision_matrix(n, 1.0, "u")
cold, cold_cpu = time.perf_counter() - t, time.process_time() - c
c = time.process_time(); t = time.perf_counter(); subdivision_matrix(n, 0.7, "u")
warm, warm_cpu = time.perf_counter() - t, time.process_time() - c
c = time.process_time(); subdivision_matrices(n, 0.9); four_cpu = time.process_time() - c
net = np.random.default_rng(0).normal(size=(delta(n), 3))
subdivide(net, n, 1.0)
best = min((lambda t0: (subdivide(net, n, 1.0), time.perf_counter() - t0)[1])(time.perf_counter())
           for _ in range({reps}))
print(cold, warm, best, cold_cpu, warm_cpu, four_cpu)
"""


def subdivision_timings(ns: list[int], reps: int = 200, cwd: str | None = None) -> list[dict]:
    """Midpoint subdivision (issue 38, item 6), each n in a fresh process: ``subdivision_matrix(n, 1.0, 'u')`` cold
    (the matrix and every integer form it needs built in that call; wall and CPU time of the process), then at
    alpha = 0.7 (the forms cached, the matrix new: *warm*), the four matrices at alpha = 0.9 (forms cached, CPU), and
    ``subdivide`` of a random 3-coordinate net once the matrices are known (best of ``reps`` calls, validation
    included).  Best of two processes.  ``cwd``: the directory the processes import paper_repro from (another
    version of the code, e.g. an export of an earlier commit; default: the current directory)."""
    import subprocess
    import sys

    rows = []
    for n in ns:
        code = _SUBDIVISION_CALL.format(n=n, reps=reps)
        runs = [tuple(map(float, subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                                check=True, cwd=cwd).stdout.split())) for _ in range(2)]
        cold, warm, apply, cold_cpu, warm_cpu, four_cpu = (min(r[k] for r in runs) for k in range(6))
        row = {"n": n, "cold_s": round(cold, 4), "warm_s": round(warm, 4), "apply_s": round(apply, 6),
               "cold_cpu_s": round(cold_cpu, 4), "warm_cpu_s": round(warm_cpu, 4), "four_cpu_s": round(four_cpu, 4),
               "goal_cold_s": SUBDIVISION_GOALS.get(("cold", n)), "goal_apply_s": SUBDIVISION_GOALS.get(("apply", n))}
        rows.append(row)
        print(f"  subdivision n={n}: cold {cold:.3f}s (CPU {cold_cpu:.3f}s), warm {warm:.3f}s (CPU {warm_cpu:.3f}s), "
              f"four {four_cpu:.3f}s CPU, subdivide {apply * 1e3:.3f} ms", flush=True)
    return rows


def subdivision_markdown(rows: list[dict], load: tuple[float, ...] | None = None,
                         load_end: tuple[float, ...] | None = None) -> list[str]:
    def met(x, goal):
        return "" if goal is None or x is None else ("yes" if x <= goal else "**no**")

    out = ["## Midpoint subdivision (issue 38, item 6), each n in a fresh process", "",
           "`subdivision_matrix(n, 1.0, 'u')` *cold* (the matrix and the integer forms of the product route "
           "built in that call; wall and CPU time of the process), *warm* (a new α = 0.7, the forms cached), the four "
           "matrices at a new α (`subdivision_matrices(n, 0.9)`, forms cached, CPU) and `subdivide` of a random "
           "3-coordinate net once the matrices are known (best of 200 calls, validation included); best of two "
           "processes. Goals: cold n = 10 ≤ 0.05 s, n = 30 ≤ 1 s; subdivide n = 10 well under 1 ms; *met* judged on "
           "the CPU time (the machine is shared: wall time counts the other processes)."
           + ("" if load is None else f" Load average at start {load[0]:.1f}")
           + ("" if load_end is None else f", at end {load_end[0]:.1f}")
           + ("" if load is None else " (2 cores)."), "",
           "| n | cold wall (s) | cold CPU (s) | goal | met | warm wall (s) | warm CPU (s) | four, CPU (s) | "
           "subdivide (ms) | goal (ms) | met |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    out += [f"| {r['n']} | {r['cold_s']} | {r.get('cold_cpu_s', '')} | "
            f"{'' if r['goal_cold_s'] is None else r['goal_cold_s']} | "
            f"{met(r.get('cold_cpu_s', r['cold_s']), r['goal_cold_s'])} | {r['warm_s']} | {r.get('warm_cpu_s', '')} | "
            f"{r.get('four_cpu_s', '')} | {r['apply_s'] * 1e3:.3f} | "
            f"{'' if r['goal_apply_s'] is None else r['goal_apply_s'] * 1e3} | {met(r['apply_s'], r['goal_apply_s'])} |"
            for r in rows]
    return out + [""]


#: Block sizes of the floor's micro-benchmarks (each operation is taken at its best).
FLOOR_BLOCKS = (256, 1024, 8192)


def _start_busy(load: str, seconds: float) -> list:
    """For ``load == 'loaded'``: one busy process per core minus one (each ends by itself after ``seconds``)."""
    import subprocess
    import sys

    if load != "loaded":
        return []
    return [subprocess.Popen([sys.executable, "-c", f"from paper_repro.app.bench import _busy; _busy({seconds})"])
            for _ in range(max(1, (os.cpu_count() or 1) - 1))]


def _stop_busy(busy: list) -> None:
    for p in busy:
        p.terminate()
    for p in busy:
        p.wait()


def _busy(seconds: float) -> None:  # pragma: no cover - runs in the load processes
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


def ratio_runs(ns: list[int], points: int, repeat: int, busy_seconds: float = 900.0) -> list[dict]:
    """:func:`patch_ratios` in fresh processes: {idle, loaded} x {default BLAS threads, OPENBLAS_NUM_THREADS=1}.

    "loaded" starts one busy process per core minus one (at least one), each ending by itself after
    ``busy_seconds`` at the latest, and stops them (by their process ids) when the measurement is done."""
    import json
    import subprocess
    import sys
    import tempfile

    runs = []
    for load in ("idle", "loaded"):
        for setting in ("default", "OPENBLAS_NUM_THREADS=1"):
            env = dict(os.environ)
            env.pop("PAPER_REPRO_THREADS", None)
            if setting != "default":
                env.update(OPENBLAS_NUM_THREADS="1")
            busy = _start_busy(load, busy_seconds)
            print(f"patch vs bezier, {load}, BLAS threads {setting}:", flush=True)
            try:
                with tempfile.TemporaryDirectory() as tmp:
                    out = os.path.join(tmp, "rows.json")
                    subprocess.run([sys.executable, "-m", "paper_repro.app.bench", "--ratios-only", out,
                                    "--points", str(points), "--repeat", str(repeat),
                                    "--ns", ",".join(map(str, ns))], env=env, check=True)
                    with open(out) as fh:
                        rows = json.load(fh)
            finally:
                _stop_busy(busy)
            runs.append({"load": load, "busy_processes": len(busy), "blas_threads": setting, "rows": rows})
    return runs


def exact_comparison(ns: list[int]) -> dict:
    """Exact coefficients at one alpha three ways: the collocation solved with flint ``fmpq_mat``, the same
    collocation with mpmath at 50 digits, and the closed forms proven for every alpha (evaluated exactly;
    forms and proof are computed -- or read from the cache -- before the clock starts)."""
    from paper_repro.theory.closed_forms import closed_forms_cached, proof_cached

    alpha = rational_alpha((1, 3))
    rows = []
    for n in ns:
        t_ex = _best(lambda n=n: solve_reduced(n, alpha, ExactContext(), verify=1), 1)
        ctx = MpContext(dps=50)
        t_mp = _best(lambda n=n: solve_reduced(n, float(alpha), ctx, verify=1), 1)
        forms, proved = closed_forms_cached(n), proof_cached(n)["proved"]
        t_cf = _best(lambda forms=forms: [f.value(alpha) for f in forms.values()], 5)
        sol, _ = solve_reduced_exact(n, alpha)
        same = [forms[rep.coefficient].value(alpha) for rep, _ in orbits(n)] == sol
        rows.append({"n": n, "unknowns": (n + 1) * (n + 2) // 2, "exact_s": round(t_ex, 4), "mp50_s": round(t_mp, 4),
                     "ratio_mp_over_exact": round(t_mp / t_ex, 2), "closed_form_s": round(t_cf, 6),
                     "closed_form_proven": proved, "closed_form_equals_solve": same,
                     "ratio_mp_over_closed_form": round(t_mp / t_cf)})
        print(f"exact coefficients n={n}: flint {t_ex:.3f}s  mpmath {t_mp:.3f}s  closed form {t_cf * 1e3:.3f}ms",
              flush=True)
    return {"alpha": "4 atan(1/3)", "rows": rows,
            "growth_exponent_exact": _growth([r["n"] for r in rows], [r["exact_s"] for r in rows]),
            "growth_exponent_mp": _growth([r["n"] for r in rows], [r["mp50_s"] for r in rows]),
            "growth_exponent_closed_form": _growth([r["n"] for r in rows], [r["closed_form_s"] for r in rows])}


def _rank_job(n: int) -> dict:
    """Exact rank certificate of T_{2n} mod p at delta_n rational points (run in a fresh process: peak RSS)."""
    import resource

    from paper_repro.core.basis import evaluate
    from paper_repro.core.context import ModpContext
    from paper_repro.core.domain import sample_rational_points

    alpha = rational_alpha((1, 3))
    t0 = time.perf_counter()
    pts = sample_rational_points(alpha, delta(n), seed=5, max_denominator=10**6)
    t1 = time.perf_counter()
    ctx = ModpContext()
    a = evaluate(n, alpha, pts, ctx)
    t2 = time.perf_counter()
    rank = ctx.rank(a)
    t3 = time.perf_counter()
    return {"n": n, "delta_n": delta(n), "rank_mod_p": rank, "points_s": round(t1 - t0, 3),
            "matrix_s": round(t2 - t1, 3), "rank_s": round(t3 - t2, 3), "total_s": round(t3 - t0, 3),
            "peak_rss_MB": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1)}


def _rank_mp_job(n: int) -> dict:
    """The mpmath route to the same certificate: LU with partial pivoting at 50 digits of the same matrix
    (evaluated in mp at the same rational points), pivots above 10^-40 of the largest counted."""
    import mpmath

    from paper_repro.core.basis import evaluate
    from paper_repro.core.context import MpContext
    from paper_repro.core.domain import sample_rational_points

    alpha = rational_alpha((1, 3))
    t0 = time.perf_counter()
    pts = sample_rational_points(alpha, delta(n), seed=5, max_denominator=10**6)
    ctx = MpContext(dps=50)
    a = evaluate(n, alpha, pts, ctx)
    with ctx.scope():
        lu, _ = mpmath.mp.LU_decomp(mpmath.matrix(a.tolist()))
        piv = [abs(lu[i, i]) for i in range(lu.rows)]
        rank = sum(1 for x in piv if x > max(piv) * mpmath.mpf(10) ** -40)
    return {"n": n, "rank_mp": rank, "mp_total_s": round(time.perf_counter() - t0, 3)}


def rank_table(ns: list[int], mp_ns: list[int] | None = None) -> dict:
    """Time and peak memory of the exact rank certificate versus n, each n in a fresh process."""
    from concurrent.futures import ProcessPoolExecutor

    rows = []
    for n in ns:
        with ProcessPoolExecutor(max_workers=1) as ex:
            rows.append(ex.submit(_rank_job, n).result())
        r = rows[-1]
        print(f"rank mod p n={n}: delta={r['delta_n']} rank={r['rank_mod_p']} {r['total_s']}s "
              f"{r['peak_rss_MB']} MB", flush=True)
    mp_rows = []
    for n in mp_ns or []:
        mp = _rank_mp_job(n)
        fast = _rank_job(n)  # the exact route again, in this process, for the ratio of the same run
        mp.update(modp_total_s=fast["total_s"], ratio_mp_over_modp=round(mp["mp_total_s"] / fast["total_s"]))
        mp_rows.append(mp)
        print(f"rank n={n}: mpmath {mp['mp_total_s']}s, mod p {fast['total_s']}s", flush=True)
    return {"rows": rows, "growth_exponent_total": _growth(ns, [r["total_s"] for r in rows]),
            "mp_route": mp_rows,
            "growth_exponent_mp": _growth([r["n"] for r in mp_rows], [r["mp_total_s"] for r in mp_rows])}


def recovery_table(ns: list[int]) -> dict:
    """Time of the closed-form recovery (exact solves at several alpha, interpolation) per n, no cache."""
    from paper_repro.theory import closed_forms

    rows = []
    env = os.environ.get("PAPER_REPRO_NO_CACHE")
    os.environ["PAPER_REPRO_NO_CACHE"] = "1"
    try:
        for n in ns:
            t = _best(lambda n=n: closed_forms.recover(n), 1)
            rows.append({"n": n, "recovery_s": round(t, 3)})
            print(f"closed-form recovery n={n}: {t:.2f}s", flush=True)
    finally:
        if env is None:
            os.environ.pop("PAPER_REPRO_NO_CACHE", None)
        else:
            os.environ["PAPER_REPRO_NO_CACHE"] = env
    return {"rows": rows, "growth_exponent": _growth(ns, [r["recovery_s"] for r in rows])}


def machine() -> dict:
    import bezier
    import flint
    import mpmath

    return {"python": platform.python_version(), "platform": platform.platform(), "cpus": os.cpu_count(),
            "processor": platform.processor() or platform.machine(), "numpy": np.__version__,
            "bezier": bezier.__version__, "python-flint": flint.__version__, "mpmath": mpmath.__version__}


def markdown(rep: dict) -> str:
    out = ["# Benchmarks", "", "Generated by `make bench` (machine-dependent; not part of `data/`).", "",
           f"Machine: {rep['machine']['processor']}, {rep['machine']['cpus']} CPUs, Python {rep['machine']['python']}, "
           f"numpy {rep['machine']['numpy']}, bezier {rep['machine']['bezier']}. Load average (1, 5, 15 min) at "
           f"start {rep['load_average_at_start']}, at end {rep['load_average_at_end']} (the machine is shared).", "",
           f"## Patch against bezier, {rep['points']:,} random points of Ω^α, α = π/2 (best of {rep['repeat']}), "
           "one process each", "",
           "Each table is one fresh process; *loaded*: one busy process per core minus one, started and stopped by "
           "the bench. Columns: Patch with the kernel's default threads and with one (`PAPER_REPRO_THREADS=1`); "
           "`bezier.Triangle.evaluate_cartesian_multi` of degree 3n − 1; derivative (`Patch.derivative`, 'u') and "
           "normals (`Patch.normals`) against bezier's hodograph route (the two first-derivative triangles of degree "
           "3n − 2 from `jacobian_both`, evaluated at the points; normals: their cross product, normalized). "
           "*kernel*: the float path's kernel (`numba`: the compiled kernel of the extra `fast`, "
           "`paper_repro.core.fast_jit`; `numpy`: the blocked numpy/BLAS kernel); *numpy path*: the same evaluation "
           "with `PAPER_REPRO_KERNEL=numpy` in the same process. "
           f"Goals (issue 21): Patch / bezier ≤ {GOALS}.", ""]
    for run in rep["ratios"]:
        out += [f"### {run['load']} ({run['busy_processes']} busy processes), BLAS threads: {run['blas_threads']}", "",
                "| n | δ_n | kernel | Patch (s) | Patch, 1 thread (s) | threads speed-up | numpy path (s) | "
                "bezier (s) | **Patch / bezier** | derivative (s) | "
                "normals (s) | derivative / point | normals / point | derivative / bezier hodographs | "
                "normals / bezier normals |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in run["rows"]:
            out.append(f"| {r['n']} | {r['delta_n']} | {r.get('kernel', 'numpy')} | {r['patch_s']} | "
                       f"{r['patch_1thread_s']} | {r['thread_speedup']}× | {r.get('patch_numpy_path_s', '–')} | "
                       f"{r['bezier_s']} | "
                       f"**{r['ratio_patch_over_bezier']}** | {r['derivative_s']} | {r['normals_s']} | "
                       f"{r['derivative_over_point']} | {r['normals_over_point']} | {r['derivative_over_bezier']} | "
                       f"{r['normals_over_bezier']} |")
        out.append("")
    if "threads" in rep:
        th = rep["threads"]
        out += ["## Threads: one against the default, interleaved", "",
                f"Point evaluation with `PAPER_REPRO_THREADS=1` and with the default ({th['cores']} threads), "
                f"alternating, {th['reps']} rounds each; *loaded*: one busy process per core minus one. The machine's "
                f"own ceiling: a fixed numeric work (numpy sines) in {th['cores']} processes at once gives "
                f"**{th['machine_gain']}×** the throughput of one process (best of 3). With one core busy, two "
                "threads can at most get 4/3 of a core (three runnable tasks on two cores): 1.33×.", "",
                "| load | n | 1 thread, min (s) | default, min (s) | speed-up (min) | speed-up (median) |",
                "|---|---|---|---|---|---|"]
        out += [f"| {r['load']} | {r['n']} | {r['one_min_s']} | {r['default_min_s']} | {r['speedup_min']}× | "
                f"{r['speedup_median']}× |" for r in th["rows"]]
        out.append("")
        if "normals_over_point_median" in th["rows"][0]:
            out += ["## Derivative and normals against a point evaluation, interleaved", "",
                    "In the same rounds as the threads' table (default threads): `Patch.derivative(points, 'u')` "
                    "and `Patch.normals(points)` each divided by the point evaluation of the same round (goal: "
                    "within 2×). The per-setting tables above divide best-of times taken minutes apart.", "",
                    "| load | n | point, min (s) | derivative, min (s) | normals, min (s) | derivative / point "
                    "(median) | (max) | normals / point (median) | (max) |", "|---|---|---|---|---|---|---|---|---|"]
            out += [f"| {r['load']} | {r['n']} | {r['default_min_s']} | {r['derivative_min_s']} | "
                    f"{r['normals_min_s']} | {r['derivative_over_point_median']} | {r['derivative_over_point_max']} | "
                    f"**{r['normals_over_point_median']}** | {r['normals_over_point_max']} |" for r in th["rows"]]
            out.append("")
    if rep.get("closed_forms"):
        out += ["## Closed-form matrices (issue 30), each in a fresh process", "",
                "The package imported first; *cold*: the first call (its integer form built), *warm*: a second call "
                "in the same process; α = 1.0, float; best of two processes. *loaded*: one busy process per core "
                "minus one. Goals (issue 30): `elevation_matrix` cold n = 10 ≤ 0.05 s, n = 30 ≤ 1 s.", "",
                "| load | function | n | cold (s) | warm (s) | goal (s) | met |", "|---|---|---|---|---|---|---|"]
        out += [f"| {r['load']} | `{r['function']}` | {r['n']} | {r['cold_s']} | {r['warm_s']} | "
                f"{'' if r['goal_cold_s'] is None else r['goal_cold_s']} | "
                f"{'' if r['meets_goal'] is None else ('yes' if r['meets_goal'] else '**no**')} |"
                for r in rep["closed_forms"]]
        out.append("")
    if rep.get("subdivision"):
        out += subdivision_markdown(rep["subdivision"])
    out += ["## The physical floor (one thread)", "",
            f"Micro-benchmarks on blocks of {rep.get('floor_block', 1024)} points (each operation at the size where "
            "it is fastest per point), scaled to the point count: three sin/cos pairs, "
            "one multiply per distinct product s^a c^b of the three variables, one dot product of length δ_n per "
            "coordinate. Patch's one-thread time as a multiple of it (goal ≤ 3×): the whole run (best of the repeats), "
            "and by the floor's own method (best of many single blocks, times the number of blocks), which is the "
            "fair comparison on a busy machine.", "",
            "| n | products | sin/cos (s) | products (s) | dot (s) | floor (s) | ns / point | Patch, 1 thread (s) | "
            "multiple | Patch, best block × blocks (s) | multiple, same method |",
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    out += [f"| {r['n']} | {r['products']} | {r['sincos_s']} | {r['products_s']} | {r['dot_s']} | {r['floor_s']} | "
            f"{r['floor_ns_per_point']} | {r['patch_1thread_s']} | {r['multiple_of_floor']}× | "
            f"{r['patch_block_best_s']} | {r['multiple_of_floor_same_method']}× |" for r in rep["floor"]]
    out += ["", "## Work memory beyond input and output (tracemalloc peak)", "",
            "tracemalloc sees numpy's allocations; the compiled kernel's own work arrays (per call: the power rows, "
            "the pair tables and the accumulators of one tile of 256 points, under 1 MB at n = 10) are allocated by "
            "numba's runtime, outside it. Neither grows with the number of points.", "",
            "| n | points | evaluation (MB) | derivative (MB) | normals (MB) |", "|---|---|---|---|---|"]
    out += [f"| {r['n']} | {r['points']:,} | {r['evaluation_work_MB']} | {r['derivative_work_MB']} | "
            f"{r['normals_work_MB']} |" for r in rep["memory"]]
    out += ["", "## The mpmath route (30 digits, extrapolated from a few points)", "",
            "| n | Patch (s) | mpmath route (s) | speed-up |", "|---|---|---|---|"]
    out += [f"| {r['n']} | {r['patch_s']} | {r['mp_route_s_extrapolated']} | {r['speedup_vs_mp']}× |"
            for r in rep["mp"]]
    if "exact" not in rep:
        return "\n".join(out + [""])
    ex = rep["exact"]
    out += ["", f"## Exact normalizing coefficients at α = {ex['alpha']}: flint, mpmath (50 digits), "
            "proven closed forms", "", "| n | unknowns | flint fmpq_mat solve (s) | mpmath lu_solve (s) | "
            "mpmath / flint | proven closed forms, exact (s) | mpmath / closed forms |",
            "|---|---|---|---|---|---|---|"]
    for r in ex["rows"]:
        out.append(f"| {r['n']} | {r['unknowns']} | {r['exact_s']} | {r['mp50_s']} | {r['ratio_mp_over_exact']} | "
                   f"{r['closed_form_s']} | {r['ratio_mp_over_closed_form']}× |")
    out += ["", f"Growth exponents (t ~ n^k): flint {ex['growth_exponent_exact']}, mpmath {ex['growth_exponent_mp']}, "
            f"closed forms {ex['growth_exponent_closed_form']}. The two solves run the same collocation (the same "
            "points, the same orbit sums); their ratio is the cost of fmpq against 50-digit mpf arithmetic. The "
            "closed forms (`data/normalization/closed_forms*.json`, proven for every alpha, `make reproduce`) give "
            "the same exact rationals (checked in the run) by evaluating one polynomial per orbit; recovery and "
            "proof are a one-off cost per n (`reports/question1.md`).", "",
            "## Exact rank certificate of T_{2n} (mod 2^31 - 1, delta_n rational points), each n in a fresh process",
            "", "| n | δ_n | rank mod p | points (s) | matrix (s) | rank (s) | total (s) | peak RSS (MB) |",
            "|---|---|---|---|---|---|---|---|"]
    for r in rep["rank"]["rows"]:
        out.append(f"| {r['n']} | {r['delta_n']} | {r['rank_mod_p']} | {r['points_s']} | {r['matrix_s']} | "
                   f"{r['rank_s']} | {r['total_s']} | {r['peak_rss_MB']} |")
    out += ["", f"Growth exponent of the total time: {rep['rank']['growth_exponent_total']}.", "",
            "The mpmath route to the same certificate (LU with partial pivoting at 50 digits of the same "
            "matrix), beside the exact route in the same run:", "",
            "| n | rank (mpmath) | mpmath (s) | mod p (s) | mpmath / mod p |", "|---|---|---|---|---|"]
    out += [f"| {r['n']} | {r['rank_mp']} | {r['mp_total_s']} | {r['modp_total_s']} | {r['ratio_mp_over_modp']}× |"
            for r in rep["rank"]["mp_route"]]
    out += ["", f"Growth exponent of the mpmath route: {rep['rank']['growth_exponent_mp']}.", "",
            "## Closed-form recovery (Question 1), no cache", "", "| n | recovery (s) |", "|---|---|"]
    out += [f"| {r['n']} | {r['recovery_s']} |" for r in rep["recovery"]["rows"]]
    out += ["", f"Growth exponent: {rep['recovery']['growth_exponent']}.", ""]
    return "\n".join(out)


#: Goal ratios Patch / bezier (issue 21).
GOALS = {3: 0.2, 6: 0.5, 10: 1.0}


def main(argv: list[str] | None = None) -> int:
    import json

    ap = argparse.ArgumentParser(prog="python -m paper_repro.app.bench")
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="small sizes (a smoke run)")
    ap.add_argument("--patch-only", action="store_true", help="only the patch sections (no exact/rank/recovery)")
    ap.add_argument("--ns", default=None, help="orders for the patch tables, comma-separated (default 1,3,6,10)")
    ap.add_argument("--ratios-only", metavar="JSON", help=argparse.SUPPRESS)  # one process of ratio_runs
    ap.add_argument("--subdivision-only", action="store_true",
                    help="only the subdivision timings -> reports/bench_subdivision.{json,md}")
    ap.add_argument("--subdivision-before", metavar="DIR", default=None,
                    help="with --subdivision-only: also time the code in DIR (an export of an earlier commit), first")
    ap.add_argument("--before-label", default=None, help="how the report names the code of --subdivision-before")
    args = ap.parse_args(argv)
    sub_ns = [2, 4] if args.quick else list(range(1, 11)) + [15, 20, 25, 30]
    if args.subdivision_only:
        load = os.getloadavg()
        before = None
        if args.subdivision_before:
            print(f"before: the code of {args.subdivision_before}", flush=True)
            before = subdivision_timings(sub_ns, cwd=args.subdivision_before)
        rows = subdivision_timings(sub_ns)
        load_end = os.getloadavg()
        write_json(reports_dir() / "bench_subdivision.json", {"machine": machine(), "load_average_at_start": list(load),
                                                              "load_average_at_end": list(load_end),
                                                              "subdivision": rows, "before": before,
                                                              "before_label": args.before_label})
        md = ["# Subdivision timings", ""] + subdivision_markdown(rows, load, load_end)
        if before is not None:
            md += ["### Before: " + (args.before_label or args.subdivision_before), "",
                   "The same measurements of that code, in the same run (measured first, just before the table "
                   "above).", ""] + subdivision_markdown(before)[4:]
        write_text(reports_dir() / "bench_subdivision.md", "\n".join(md))
        print(f"wrote {reports_dir() / 'bench_subdivision.md'}")
        return 0
    points = 20_000 if args.quick else args.points
    ns = [int(x) for x in args.ns.split(",")] if args.ns else ([1, 3] if args.quick else [1, 3, 6, 10])
    if args.ratios_only:
        with open(args.ratios_only, "w") as fh:
            json.dump(patch_ratios(ns, points, args.repeat), fh)
        return 0
    rep = {"machine": machine(), "repeat": args.repeat, "points": points, "goals": GOALS,
           "load_average_at_start": list(os.getloadavg()),
           "ratios": ratio_runs(ns, points, args.repeat),
           "threads": interleaved(ns if args.quick else [3, 6, 10, 20], points, 2 if args.quick else 6),
           "closed_forms": closed_forms({k: [2, 3] if args.quick else [10, 20, 30] + ([40] if k == "elevation_matrix"
                                                                                      else [])
                                         for k in CLOSED_FORMS}),
           "floor": floor_estimate([3, 6] if not args.quick else [3], points, args.repeat),
           "floor_block": ", ".join(map(str, FLOOR_BLOCKS)),
           "memory": memory_rows(3, [10**4, 10**5] if args.quick else [10**5, 10**7]),
           "mp": mp_route(ns, points, mp_points=20 if args.quick else 100),
           "subdivision": subdivision_timings(sub_ns)}
    if not args.patch_only:
        rep.update(exact=exact_comparison([2, 3] if args.quick else [2, 3, 4, 5, 6, 7, 8]),
                   rank=rank_table([2, 4] if args.quick else [5, 10, 15, 20, 25, 30, 35, 40],
                                   [2] if args.quick else [2, 4, 6, 8]),
                   recovery=recovery_table([1, 2] if args.quick else [1, 2, 3, 4, 5, 6]))
    rep["load_average_at_end"] = list(os.getloadavg())
    write_json(reports_dir() / "bench.json", rep)
    write_text(reports_dir() / "bench.md", markdown(rep))
    print(f"wrote {reports_dir() / 'bench.json'} and {reports_dir() / 'bench.md'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
