"""Fuzz the public API and the CLI with hostile and edge inputs (issue 22): every case must give a correct
result or a ValueError/TypeError naming the parameter -- never a raw exception, a NaN, a silent wrong answer,
a hang (> 20 s) or a memory blow-up (address space capped at 3 GB).

    python tools/fuzz_api.py [--classes small_alpha,...] [--cli] [--json out.json] [--seed 0]

Each case is a snippet run in a worker process (restarted after a timeout or a crash) and an expectation:
``("err", words)`` -- ValueError/TypeError whose message contains one of ``words``; ``("ok", check)`` -- returns a
value ``r`` for which the expression ``check`` holds; ``("ok|err", check, words)`` -- either.  Outcomes: good,
wrong-exception (raw exception or a message not naming the parameter), silent-wrong (accepted bad input, or a wrong
or non-finite answer), hang (timeout or MemoryError).  Counts are printed per class.
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing as mp
import os
import random
import subprocess
import sys
import time
from collections import Counter, defaultdict

TIMEOUT = 20.0
MEM_BYTES = 3 * 1024**3

PRELUDE = """
import math, numpy as np, mpmath
from fractions import Fraction
from flint import fmpq
import paper_repro as P
from paper_repro import *
from paper_repro.core.labels import delta, united_system
def mp_patch(n, alpha, net, pts, weights=None):
    return Patch(n, alpha, net, weights=weights).reference(pts, dps=50)
def rel(a, b, scale):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.max(np.abs(a - b))) / scale
def finite(r):
    return bool(np.all(np.isfinite(np.asarray(r, dtype=float))))
"""


def _worker(conn):
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEM_BYTES, MEM_BYTES))
    ns: dict = {}
    exec(PRELUDE, ns)
    while True:
        msg = conn.recv()
        if msg is None:
            return
        code, check = msg
        local = dict(ns)
        try:
            exec(code, local)
            r = local.get("r")
            ok = None
            if check:
                local["r"] = r
                try:
                    ok = bool(eval(check, local))
                except Exception as exc:  # a failing check is a wrong answer
                    ok = f"check raised {type(exc).__name__}: {exc}"[:200]
            conn.send(("ret", ok))
        except MemoryError:
            conn.send(("mem", "MemoryError"))
        except BaseException as exc:  # noqa: BLE001 -- we classify every exception
            conn.send(("exc", (type(exc).__name__, str(exc).splitlines()[0][:300] if str(exc) else "",
                               isinstance(exc, (ValueError, TypeError)))))


class Runner:
    def __init__(self):
        self.proc = None
        self.conn = None

    def start(self):
        ctx = mp.get_context("fork")
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_worker, args=(child,), daemon=True)
        self.proc.start()

    def run(self, code, check, timeout=TIMEOUT):
        if self.proc is None or not self.proc.is_alive():
            self.start()
        self.conn.send((code, check))
        if self.conn.poll(timeout):
            try:
                return self.conn.recv()
            except EOFError:
                self.proc = None
                return ("mem", "worker died")
        self.proc.kill()
        self.proc.join()
        self.proc = None
        return ("hang", f"no answer in {timeout:.0f} s")


def classify(expect, res):
    kind, payload = res
    if kind in ("hang", "mem"):
        return "hang", payload
    want = expect[0]
    if kind == "ret":
        if want == "err":
            return "silent-wrong", "accepted (no error)"
        if payload is True or (payload is None and not expect[1]):
            return "good", ""
        return "silent-wrong", f"check failed: {payload}"
    name, msg, documented = payload
    if name == "MemoryError":
        return "hang", msg
    words = expect[1] if want == "err" else expect[2] if want == "ok|err" else ()
    if documented and words and any(w.lower() in msg.lower() for w in words):
        return "good", ""
    return "wrong-exception", f"{name}: {msg}"


# ------------------------------------------------------------------------------------------------- cases
def cases(rng: random.Random, with_cli: bool):
    out = []

    def add(cls, code, *expect):
        out.append((cls, code, expect))

    pi = math.pi
    tiny = [1e-3, 1e-8, 1e-17, 1e-30, 1e-60, 1e-154, 1e-200, 1e-300, sys.float_info.min]
    near_pi = [pi - 1e-3, pi - 1e-8, 3.1415926535897, math.nextafter(pi, 0)]
    # --- subnormal alpha (below the smallest normal float64): refused, naming alpha
    for a in (5e-324, 1e-310):
        for code in (f"r = evaluate_normalized(2, {a!r}, [[0.0, 0.0, {a!r}]])", f"r = coefficients(3, {a!r})",
                     f"r = Patch(2, {a!r}, np.zeros((19, 3)))", f"r = elevate(np.zeros((7, 3)), 1, {a!r})"):
            add("small_alpha", code, "err", ("alpha",))
    # --- small alpha (valid input): coefficients (scaled), evaluate_normalized, Patch, derivatives
    for a in tiny + near_pi:
        for n in (1, 2, 3, 6, 8):
            add("small_alpha", f"r = evaluate_normalized({n}, {a!r}, sample_points({a!r}, 5, seed=1))",
                "ok", "finite(r) and abs(r.sum(axis=1) - 1).max() < 1e-12 and r.min() > -1e-15")
            add("small_alpha", f"r = list(coefficients({n}, {a!r}).values())", "ok|err",
                "finite(r) and min(r) > 0", ("exceeds float64", "alpha"))
            add("small_alpha", f"net = np.random.default_rng({n}).normal(size=(delta({n}), 3)); "
                f"pts = sample_points({a!r}, 4, seed=2); r = (Patch({n}, {a!r}, net)(pts), mp_patch({n}, {a!r}, net, pts))",
                "ok", "finite(r[0]) and rel(r[0], r[1], 1.0) < 1e-11")
            add("small_alpha", f"net = np.random.default_rng({n}).normal(size=(delta({n}), 3)); "
                f"r = Patch({n}, {a!r}, net).derivative(sample_points({a!r}, 4, seed=2), 'u') * {a!r}",
                "ok", "finite(r)")
    # --- order elevation: affine invariance and agreement with the original patch (mp reference)
    for _ in range(60):
        n = rng.choice([1, 1, 2, 2, 3, 4])
        a = rng.choice(tiny[:8] + near_pi + [rng.uniform(0.01, 3.1) for _ in range(4)])
        shift = rng.choice([1.0, 1e3, 1e8])
        add("elevation", f"net = np.random.default_rng(1).normal(size=(delta({n}), 3)); "
            f"e1 = elevate(net, {n}, {a!r}); e2 = elevate(net + {shift!r}, {n}, {a!r}); "
            f"r = rel(e2 - {shift!r}, e1, {shift!r})", "ok", "r < 1e-14")
        add("elevation", f"E = elevation_matrix({n}, {a!r}); r = abs(E.sum(axis=1) - 1).max()", "ok", "r < 1e-14")
        add("elevation", f"net = np.random.default_rng(1).normal(size=(delta({n}), 3)); e = elevate(net, {n}, {a!r}); "
            f"pts = sample_points({a!r}, 4, seed=3); r = rel(mp_patch({n + 1}, {a!r}, e, pts), "
            f"mp_patch({n}, {a!r}, net, pts), 1.0)", "ok", "r < 1e-12")
    # --- rational weights
    for scale in (1e-320, 1e-300, 1e-150, 1.0, 1e150, 1e300, 1e307, 1e308):
        for n in (1, 2, 3):
            add("weights", f"net = np.random.default_rng(5).normal(size=(delta({n}), 3)); "
                f"w = np.random.default_rng(6).uniform(0.5, 2, delta({n})); pts = sample_points(1.0, 6, seed=3); "
                f"r = (Patch({n}, 1.0, net, weights=w * {scale!r})(pts), mp_patch({n}, 1.0, net, pts, w * {scale!r}))",
                "ok|err", "finite(r[0]) and rel(r[0], r[1], 1.0) < 1e-13", ("weights must be finite",))
            add("weights", f"net = np.random.default_rng(5).normal(size=(delta({n}), 3)); "
                f"w = np.random.default_rng(6).uniform(0.5, 2, delta({n})) * {scale!r}; "
                f"r = Patch({n}, 1.0, net, weights=w).derivative(sample_points(1.0, 6, seed=3), 'v')", "ok|err",
                "finite(r)", ("weights must be finite",))
    for arith in ("float", "mp", "exact"):
        for wz in ("np.zeros(7)", "np.r_[0.0, np.ones(6)]", "np.r_[np.ones(6), 0.0]", "np.r_[-1.0, np.ones(6)]",
                   "np.r_[np.ones(6), np.nan]"):
            pts = "rational_alpha((1, 2)), ((1, 5),), ((1, 7),))" if arith == "exact" else None
            call = (f"p = Patch(1, rational_alpha((1, 2)), np.arange(14).reshape(7, 2), weights={wz}); "
                    f"r = p(RationalPoints(rational_alpha((1, 2)), ((1, 5), (1, 100)), ((1, 7), (1, 100))), "
                    f"arith={arith!r}); r = np.asarray(r, dtype=float)")
            del pts
            # a zero corner weight makes the patch undefined at that corner: refused; interior zeros are fine
            corner_zero = wz == "np.r_[np.ones(6), 0.0]"
            if wz.startswith("np.r_[0.0"):  # the centre r_{2,1,1} has weight 0: defined everywhere
                add("weights", call, "ok", "finite(r)")
            elif corner_zero:
                add("weights", call, "ok|err", "finite(r)", ("weights",))
            else:
                add("weights", call, "err", ("weights",))
    # --- complex input
    for code in ("r = coefficients(1, 1+0j)", "r = coefficients(1, np.complex128(1))", "r = Patch(1, 1j, np.zeros((7, 3)))",
                 "r = evaluate_normalized(1, 1.0, np.array([[0.3, 0.3, 0.4]], dtype=complex))",
                 "r = evaluate_normalized(1, 1.0, [[0.3+1j, 0.3, 0.4]])",
                 "r = Patch(1, 1.0, np.zeros((7, 3)))(np.array([[0.3, 0.3, 0.4]], dtype=complex))",
                 "r = Patch(1, 1.0, np.zeros((7, 3)) + 1j)", "r = Patch(1, 1.0, np.zeros((7, 3)), weights=np.ones(7) + 0j)",
                 "r = sample_points(1+0j, 3)", "r = elevate(np.zeros((7, 3)) + 0j, 1, 1.0)",
                 "r = coefficients(1, mpmath.mpc(1, 0), 'mp')", "r = evaluate(1, 1j, [[0.3, 0.3, 0.4]])"):
        add("complex", code, "err", ("alpha", "points", "net", "weights", "complex"))
    for arr in ("np.zeros((3, 3)) + 1j", "np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=complex)"):
        add("complex", f"import tempfile, pathlib; d = pathlib.Path(tempfile.mkdtemp()); "
            f"r = export_mesh(d / 'm.obj', {arr}, np.array([[0, 1, 2]]))", "err", ("vertices",))
    # --- precision arguments
    for dps in (0, False, True, 3.5, -1, 10**9, "50", None, 4):
        expect = ("err", ("dps",)) if dps is not None else ("ok", "")
        add("precision", f"r = get_context('mp', dps={dps!r})", *expect)
        add("precision", f"r = get_context('ball', dps={dps!r})", *expect)
        add("precision", f"r = coefficients(1, 1.0, 'mp', dps={dps!r})", *expect)
        add("precision", f"r = evaluate_normalized(1, 1.0, [[0.3, 0.3, 0.4]], 'mp', dps={dps!r})", *expect)
    # --- sizes (budgets): refused up front or done within the time/memory budget
    size_cases = [
        "r = coefficients(60, 1.0)", "r = coefficients(40, rational_alpha((1, 3)), 'exact')",
        "r = coefficients(1000, 1.0)", "r = coefficients(10**6, 1.0)", "r = coefficients(300, 1.0, 'mp')",
        "r = elevate(np.zeros((7, 3)), 1, 1.0, times=50)", "r = elevate(np.zeros((7, 3)), 1, 1.0, times=10**9)",
        "r = elevation_matrix(41, 1.0)", "r = elevation_matrix(10**6, 1.0)",
        "r = fit(lambda u, v, w: [math.cos(u), math.sin(v)], 8, 1.0)",
        "r = fit(lambda u, v, w: [math.cos(u), math.sin(v)], 20, 1.0)",
        "r = sample_rational_points(rational_alpha((1, 2)), 10**6)", "r = sample_rational_points(rational_alpha((1, 2)), 10**9)",
        "r = bezier_limit(np.zeros((delta(1000), 3)), 1000)", "r = bezier_limit(np.zeros((delta(60), 3)), 60)",
        "r = Patch(6, 1.0, np.zeros((delta(6), 3))).derivative(sample_points(1.0, 10**6), 'u')",
        "r = Patch(6, 1.0, np.random.default_rng(0).normal(size=(delta(6), 3))).normals(sample_points(1.0, 10**6))",
        "r = Patch(2, 1.0, np.zeros((19, 3))).mesh(4096)", "r = Patch(2, 1.0, np.zeros((19, 3))).mesh(10**6)",
        "r = sample_points(1.0, 10**9)", "r = united_system(10**6)", "r = delta(10**9)",
        "r = evaluate(30, 1.0, sample_points(1.0, 10**6))",
    ]
    for code in size_cases:
        add("sizes", code, "ok|err", "", ("n must", "times", "count", "resolution", "points", "at most", "from", "exceeds float64"))
    # --- types
    type_alphas = ["np.float32(1.0)", "np.float16(1.0)", "np.longdouble(1.0)", "np.array(1.0)", "fmpq(1, 3)",
                   "Fraction(1, 3)", "mpmath.mpf(1)", "np.int64(1)", "1"]
    for ta in type_alphas:
        for arith in ("float", "mp"):
            add("types", f"r = np.asarray(evaluate_normalized(2, {ta}, [[0.3, 0.3, 0.4 - 1.0 + float({ta})]], "
                f"{arith!r}), dtype=float)", "ok|err", "finite(r) and abs(r.sum() - 1) < 1e-12", ("alpha",))
            add("types", f"r = [float(x) for x in coefficients(2, {ta}, {arith!r}).values()]", "ok|err",
                "finite(r)", ("alpha",))
            add("types", f"p = Patch(2, {ta}, np.zeros((19, 3)) + 1.0); r = np.asarray(p(sample_points(float({ta}), 3), "
                f"arith={arith!r}), dtype=float)", "ok|err", "rel(r, 1.0, 1.0) < 1e-12", ("alpha",))
    # alpha as text is accepted by design (parse_alpha: '1.0', '3/2', 'pi/2'; issue 22 lists strings like 'pi/2'
    # among the accepted reals) and must equal the float; text that is not a number is refused
    for text, value in (("'1.0'", "1.0"), ("'pi/2'", "math.pi / 2"), ("'2pi/3'", "2 * math.pi / 3")):
        add("types", f"r = (list(coefficients(2, {text}).values()), list(coefficients(2, {value}).values()))",
            "ok", "r[0] == r[1]")
    for bad in ("np.bool_(True)", "True", "'one'", "'pi/0'", "b'1'", "None", "[1.0]", "np.array([1.0])", "object()",
                "{1.0}"):
        add("types", f"r = coefficients(1, {bad})", "err", ("alpha",))
        add("types", f"r = Patch(1, {bad}, np.zeros((7, 3)))", "err", ("alpha",))
        add("types", f"r = evaluate_normalized(1, {bad}, [[0.3, 0.3, 0.4]])", "err", ("alpha",))
    for bad in ("[['0.3', '0.3', '0.4']]", "np.array([['0.3', '0.3', '0.4']])", "[[True, False, False]]",
                "np.array([[b'0.3', b'0.3', b'0.4']])"):
        add("types", f"r = evaluate_normalized(1, 1.0, {bad})", "err", ("points",))
        add("types", f"r = Patch(1, 1.0, np.zeros((7, 3)))({bad})", "err", ("points",))
    for bad in ("['1'] * 7", "np.array(['1'] * 7)", "[True] * 7", "np.ones(7, dtype=bool)"):
        add("types", f"r = Patch(1, 1.0, np.zeros((7, 3)), weights={bad})", "err", ("weights",))
    for bad in ("np.full((7, 3), '1')", "[['1', '2', '3']] * 7", "np.ones((7, 3), dtype=bool)"):
        add("types", f"r = Patch(1, 1.0, {bad})", "err", ("net",))
    for tt in ("(1, 2)", "Fraction(1, 3)", "fmpq(1, 3)", "'1/3'", "0.5", "(1, 0)", "(0, 1)", "(1, 1)", "(3, 2)",
               "(-1, 3)", "1j", "np.bool_(True)", "float('nan')", "(1, 2, 3)", "None", "Fraction(1, 10**400)",
               "np.float32(0.5)", "np.int64(0)", "(np.int64(1), np.int64(3))"):
        valid = tt in ("(1, 2)", "Fraction(1, 3)", "fmpq(1, 3)", "0.5", "Fraction(1, 10**400)", "np.float32(0.5)",
                       "(np.int64(1), np.int64(3))", "'1/3'")
        # (t = 1e-400 gives alpha = 4e-400, which float64 rounds to 0.0: the correctly rounded value)
        add("types", f"a = rational_alpha({tt}); r = float(a)", *(("ok|err", "0 <= r < math.pi", ("t",)) if valid
                                                                   else ("err", ("t", "alpha"))))
    # --- misc: elevate times, fit tol_digits, labels of another order
    for times in (-1, -5, 1.5, True, "1", None, 0, 2):
        ok = times in (0, 2)
        add("misc", f"r = elevate(np.zeros((7, 3)) + 1.0, 1, 1.0, times={times!r})",
            *(("ok", "np.allclose(r, 1.0)") if ok else ("err", ("times",))))
    for td in (-5, 0, 1.5, True, "3", 5, 200):
        ok = td == 5
        add("misc", f"r = fit(lambda u, v, w: [math.exp(u)], 1, 1.0, tol_digits={td!r})",
            *(("err", ("surface",)) if ok else ("err", ("tol_digits",))))
        add("misc", f"r = fit(lambda u, v, w: [math.cos(u)], 1, 1.0, tol_digits={td!r})",
            *(("ok", "") if ok else ("err", ("tol_digits",))))
    for n_lab, n in ((2, 1), (1, 2), (1, 1), (3, 2)):
        add("misc", f"r = evaluate({n}, 1.0, [[0.3, 0.3, 0.4]], labels=united_system({n_lab}))",
            *(("ok", "r.shape == (1, delta(1))") if n_lab == n else ("err", ("labels",))))
    # --- layouts: strings, lists, object arrays, Fortran-ordered and non-contiguous arrays
    base = "sample_points(1.0, 8, seed=4)"
    layouts = [f"{base}.tolist()", f"np.asfortranarray({base})", f"np.ascontiguousarray({base}[::-1])",
               f"np.repeat({base}, 2, axis=0)[::2]", f"{base}.astype(object)", f"{base}.astype(np.float32)",
               f"np.array([[mpmath.mpf(x) for x in row] for row in {base}], dtype=object)",
               f"{base}.T.copy().T", f"tuple(map(tuple, {base}))", f"{base}.astype(np.longdouble)",
               f"np.lib.stride_tricks.as_strided({base}, shape=(4, 3), strides=(48, 8))"]
    for lay in layouts:
        for n in (1, 3):
            tol = "1e-6" if "float32" in lay else "1e-13"
            # float32 rounding moves points off Omega^alpha by ~1e-8 > the 1e-12 tolerance: a refusal naming the
            # points is the documented answer there
            exp = ("ok|err", f"finite(r[0]) and rel(r[0], r[1], 1.0) < {tol}", ("points",)) if "float32" in lay \
                else ("ok", f"finite(r[0]) and rel(r[0], r[1], 1.0) < {tol}")
            add("layouts", f"net = np.random.default_rng(0).normal(size=(delta({n}), 3)); p = Patch({n}, 1.0, net); "
                f"q = {lay}; r = (np.asarray(p(q), dtype=float), p(np.asarray(q, dtype=float)))", *exp)
            add("layouts", f"q = {lay}; r = (evaluate_normalized({n}, 1.0, q), "
                f"evaluate_normalized({n}, 1.0, np.asarray(q, dtype=float)))", *exp)
            add("layouts", f"net = np.asfortranarray(np.random.default_rng(0).normal(size=(delta({n}), 3))); "
                f"r = (elevate(net, {n}, 1.0), elevate(np.ascontiguousarray(net), {n}, 1.0))", "ok",
                "np.array_equal(r[0], r[1])")
    for bad in ("'points'", "[[]]", "[[0.3, 0.3]]", "np.zeros((2, 2, 3))", "[[0.3, 0.3, [0.4]]]",
                "[[float('nan'), 0.3, 0.4]]", "np.array([[0.3, 0.3, 0.4]], dtype=object) * np.nan", "{0: 1}",
                "[[None, None, None]]", "np.empty((0, 3))", "3"):
        add("layouts", f"r = Patch(1, 1.0, np.zeros((7, 3)))({bad})", "err", ("points",))
        add("layouts", f"r = evaluate_normalized(1, 1.0, {bad})", "err", ("points",))
        add("layouts", f"r = Patch(1, 1.0, np.zeros((7, 3))).derivative({bad})", "err", ("points",))
    # --- scale of the net (float kernel: issue 21's helper), convex-combination property
    for sc in (1e-300, 1e-200, 1e-160, 1e160, 1e200, 1e300, 1e306, 1e307, 1.7e308):
        for n in (1, 3):
            add("scale", f"net = np.random.default_rng(0).uniform(-1, 1, size=(delta({n}), 3)) * {sc!r}; "
                f"r = Patch({n}, 1.0, net)(sample_points(1.0, 5)) / {sc!r}", "ok",
                "finite(r) and np.abs(r).max() <= 1 + 1e-12")
            add("scale", f"net = np.random.default_rng(0).uniform(-1, 1, size=(delta({n}), 3)) * {sc!r}; "
                f"r = Patch({n}, 1.0, net).normals(sample_points(1.0, 5))", "ok",
                "finite(r) and np.allclose(np.linalg.norm(r, axis=1), 1)")
    # --- random valid calls (hypothesis-like): evaluate_normalized vs mp, Patch vs mp
    for _ in range(120):
        n = rng.randint(1, 5)
        a = rng.choice([rng.uniform(1e-3, 3.14), 10 ** rng.uniform(-300, 0), math.pi - 10 ** rng.uniform(-12, -1)])
        add("random_valid", f"net = np.random.default_rng({rng.randrange(1000)}).normal(size=(delta({n}), 3)); "
            f"pts = sample_points({a!r}, 3, seed={rng.randrange(1000)}); "
            f"r = (Patch({n}, {a!r}, net)(pts), mp_patch({n}, {a!r}, net, pts))", "ok",
            "finite(r[0]) and rel(r[0], r[1], 1.0) < 1e-11")
    # --- this round's surfaces (issue 39/40): the transformation in float at small alpha, its direction, the target
    # order of elevate, barycentric rows, the cluster door and --out
    for n in (1, 3, 10, 30):
        for a in (1e-300, 1e-30, 1e-8, 1e-4):
            add("round5", f"r = transformation_matrix({n}, {a!r})", "err", ("arith='mp'", "RationalAngle"))
        add("round5", f"r = transformation_matrix({n}, 1e-30, 'T_to_V') if {n} <= 3 else np.ones(1)", "ok|err",
            "finite(r)", ("OverflowError", "exceeds float64"))
    for d in ("np.array(['V_to_T', 'T_to_V'])", "None", "1", "'v_to_t'", "b'V_to_T'"):
        add("round5", f"r = transformation_matrix(2, 1.0, direction={d})", "err", ("direction",))
    add("round5", "r = elevate(np.zeros((7, 3)), 1, 1.0, 2)", "err", ("positional", "argument"))
    for to, times in (("0", "None"), ("1", "None"), ("3", "1"), ("10**9", "None"), ("2.5", "None"), ("True", "None")):
        add("round5", f"r = elevate(np.zeros((7, 3)), 1, 1.0, to={to}, times={times})", "ok|err",
            "r.shape[0] in (7, 19)", ("to", "times"))
    for bary in ("[[0.5, 0.5, 0.5]]", "[[1.5, -0.5, 0]]", "[[float('nan'), 0.5, 0.5]]", "[[0.5 + 0j, 0.5, 0]]",
                 "[[0.5, 0.5]]", "'xyz'"):
        add("round5", f"r = Patch(1, 1.0, np.zeros((7, 3))).at_barycentric({bary})", "err", ("bary",))
    # --- the tessellator (issue 38, item 5): bad input refused naming the parameter; valid input within tol
    tes = "from paper_repro.surfaces.tessellation import tessellate; "
    net19 = "np.random.default_rng(0).normal(size=(19, 3))"
    for arg, words in (("n=0", ("n",)), ("n=7", ("n",)), ("n=2.0", ("n",)), ("n='2'", ("n",)), ("n=None", ("n",)),
                       ("alpha=0.0", ("alpha",)), ("alpha=math.pi", ("alpha",)), ("alpha=-1", ("alpha",)),
                       ("alpha=float('nan')", ("alpha",)), ("alpha=1j", ("alpha",)), ("alpha='abc'", ("alpha",)),
                       ("alpha=None", ("alpha",)), ("tol=0", ("tol",)), ("tol=-1e-3", ("tol",)),
                       ("tol=float('nan')", ("tol",)), ("tol=float('inf')", ("tol",)), ("tol='1e-3'", ("tol",)),
                       ("tol=None", ("tol",)), ("tol=[1e-3]", ("tol",)), ("tol=1e-300", ("tol",)),
                       ("tol=1j", ("tol",)), ("leaf_resolution=0", ("leaf_resolution",)),
                       ("leaf_resolution=10**9", ("leaf_resolution",)), ("leaf_resolution=2.5", ("leaf_resolution",)),
                       ("max_depth=-1", ("max_depth",)), ("max_depth=10**6", ("max_depth",)),
                       ("max_vertices=0", ("max_vertices",)), ("max_vertices=10, tol=1e-6", ("max_vertices",)),
                       # the ball and mp routes (arith, dps; their own vertex limit)
                       ("arith='exact'", ("arith",)), ("arith=None", ("arith",)), ("arith='BALL'", ("arith",)),
                       ("arith=2", ("arith",)), ("arith='float', dps=30", ("dps",)),
                       ("arith='ball', dps=5", ("dps",)), ("arith='ball', dps=10**6", ("dps",)),
                       ("arith='mp', dps=2.5", ("dps",)), ("arith='ball', dps='30'", ("dps",)),
                       ("arith='ball', max_vertices=10**7", ("max_vertices",)), ("arith='ball', n=7", ("n",)),
                       ("arith='ball', alpha=0.0", ("alpha",)), ("arith='mp', alpha=float('nan')", ("alpha",)),
                       ("arith='ball', tol=-1e-3", ("tol",)), ("arith='ball', tol=1e-300", ("tol",)),
                       ("arith='ball', leaf_resolution=0", ("leaf_resolution",)),
                       ("arith='ball', max_vertices=10, tol=1e-6", ("max_vertices",))):
        kw = dict(x.split("=", 1) for x in ("n=2", "alpha=1.0", "tol=1e-3"))
        for part in arg.split(", "):
            key, val = part.split("=", 1)
            kw[key] = val
        call = ", ".join(f"{k}={v}" for k, v in kw.items())
        add("tessellate", tes + f"r = tessellate({net19}, {call})", "err", words)
    for bad in ("np.zeros((7, 3))", "np.full((19, 3), np.nan)", "'net'", "None", "np.zeros((19, 0))",
                "np.zeros((19, 3)) + 1j", "[[1, 2, 3]] * 19 + [['a', 'b', 'c']]", "np.zeros((19, 3, 2))"):
        add("tessellate", tes + f"r = tessellate({bad}, 2, 1.0, 1e-3)", "err", ("net",))
    check = ("finite(r[0].points) and r[0].triangles.min() >= 0 and r[0].triangles.max() < len(r[0].points) "
             "and r[0].bound <= r[1] and r[2] <= r[0].bound")
    for n in (1, 2, 3):
        for a in (1e-8, 1e-3, 0.7, "'pi/2'", pi - 1e-3, 3.1415926535897):
            for tol, scale in ((1e-2, 1.0), (1e-3, 1.0), (1e-1, 1e6), (1e-9, 1e-6)):
                add("tessellate", tes + f"net = np.random.default_rng({n}).normal(size=(delta({n}), 3)) * {scale!r}; "
                    f"t = {tol!r}; m = tessellate(net, {n}, {a}, t, max_vertices=400_000); "
                    "c = m.params[m.triangles].mean(axis=1); "
                    f"d = float(np.linalg.norm(Patch({n}, {a}, net)(c) - m.points[m.triangles].mean(axis=1), "
                    "axis=1).max()); r = (m, t, d)", "ok|err", check, ("max_vertices",))
    for n in (1, 2):
        for a in (1e-3, 0.7, "'pi/2'", pi - 1e-3):
            add("tessellate", tes + f"net = np.random.default_rng({n}).normal(size=(delta({n}), 3)); t = 1e-2; "
                f"m = tessellate(net, {n}, {a}, t, arith='ball'); c = m.params[m.triangles].mean(axis=1); "
                f"d = float(np.linalg.norm(Patch({n}, {a}, net)(c) - m.points[m.triangles].mean(axis=1), "
                "axis=1).max()); r = (m, t, d)", "ok|err", check, ("max_vertices",))
    # --- joins along an edge (issue 38, item 4): every public function of paper_repro.surfaces.joins refuses hostile
    # input naming the parameter, before any work; valid calls at extreme alpha give finite, joined results
    joins = {
        "edge_derivatives": "edge_derivatives({n}, {a}, {e})",
        "c1_neighbour_row": "c1_neighbour_row({net}, {n}, {a}, {e})",
        "g1_neighbour_row": "g1_neighbour_row({net}, {n}, {a}, {e}, lam={lam}, mu={mu})",
        "join_neighbour": "join_neighbour({net}, {n}, {a}, {e}, {nb}, lam={lam}, mu={mu})",
        "join_error": "join_error({net}, {nb2}, {n}, {a}, {e})",
    }
    good = {"n": "2", "a": "1.0", "e": "'v'", "net": "np.ones((19, 3))", "nb": "None", "nb2": "np.ones((19, 3))",
            "lam": "1.5", "mu": "0.25"}
    hostile = [("a", bad, ("alpha",)) for bad in ("float('nan')", "float('inf')", "-1.0", "0.0", "4.0", "1j",
                                                     "np.complex128(1)", "'x'", "None", "np.array([1.0, 2.0])",
                                                     "mpmath.mpf('nan')", "5e-324")]
    hostile += [("n", bad, ("n must",)) for bad in ("True", "False", "0", "-3", "2.5", "10**9", "101", "'2'", "None",
                                                     "np.float64(2)")]
    hostile += [("e", bad, ("edge",)) for bad in ("'x'", "'V'", "''", "1", "None", "b'v'", "('v',)", "['u']")]
    hostile += [("net", bad, ("net",)) for bad in ("np.ones((18, 3))", "np.ones((19,))", "np.ones((19, 3, 1))",
                                                    "np.full((19, 3), np.nan)", "np.full((19, 3), np.inf)",
                                                    "'net'", "[[1j] * 3] * 19", "np.ones((19, 0))")]
    hostile += [("nb", bad, ("neighbour",)) for bad in ("np.ones((19, 2))", "np.ones((7, 3))",
                                                         "np.full((19, 3), np.nan)")]
    hostile += [("nb2", bad, ("neighbour",)) for bad in ("np.ones((19, 2))", "np.ones((7, 3))", "None",
                                                          "np.full((19, 3), np.inf)")]
    hostile += [("lam", bad, ("lam",)) for bad in ("0", "-1.0", "float('nan')", "float('inf')", "1j", "True",
                                                    "'1'", "None", "np.array([1.0, 2.0])", "-10**400")]
    hostile += [("mu", bad, ("mu",)) for bad in ("float('nan')", "float('-inf')", "1j", "False", "'0'", "None",
                                                  "mpmath.mpf('inf')")]
    for template in joins.values():
        for key, bad, words in hostile:
            if "{" + key + "}" not in template:
                continue
            args = dict(good, **{key: bad})
            add("joins", "r = " + template.format(**args), "err", words)
    for arith, words in (("'modp'", ("arith",)), ("'ball'", ("arith",)), ("'fast'", ("arith",)), ("1", ("arith",)),
                         ("'exact'", ("RationalAngle",))):
        add("joins", f"r = edge_derivatives(2, 1.0, 'v', {arith})", "err", words)
        add("joins", f"r = join_error(np.ones((19, 3)), np.ones((19, 3)), 2, 1.0, 'w', arith={arith})", "err", words)
    add("joins", "r = edge_derivatives(2, 1.0, 'v', 'mp', dps=3)", "err", ("dps",))
    # valid calls at extreme alpha and order: finite, and the builders' joins have zero defects
    for a in (1e-300, 1e-30, 1e-3, 1.0, math.pi - 1e-8, math.nextafter(math.pi, 0)):
        for n in (1, 3, 12):
            add("joins", f"D, T = edge_derivatives({n}, {a!r}, 'u'); r = (D * {a!r}, T * {a!r})", "ok",
                "finite(r[0]) and finite(r[1])")
            add("joins", f"net = np.random.default_rng({n}).normal(size=(delta({n}), 3)); "
                f"o = join_neighbour(net, {n}, {a!r}, 'w', lam=2.0, mu=-0.5); "
                f"r = join_error(net, o, {n}, {a!r}, 'w')", "ok",
                "r['C0'] == 0 and abs(r['lam'] - 2) < 1e-6 and abs(r['mu'] + 0.5) < 1e-6")
    add("joins", "r = join_error(np.ones((19, 3)), np.ones((19, 3)), 2, RationalAngle(fmpq(1, 3)), 'u')", "ok",
        "r['C0'] == 0 and r['C1'] == 0 and r['G1'] == 0")
    add("joins", "r = c1_neighbour_row(np.ones((19, 3)), 2, '2*pi/3', 'v', arith='mp', dps=30)", "ok",
        "abs(np.asarray(r, dtype=float) - 1).max() < 1e-25")
    # --- midpoint subdivision: hostile input refused naming the parameter; valid calls finite, rows summing to 1, the
    # sub-patch equal to the patch on its sub-triangle (float route against the patch itself)
    good = {"net": "np.ones((19, 3))", "n": "2", "a": "1.0", "part": "'u'", "k": "1"}
    sub = {"subdivision_matrix": "subdivision_matrix({n}, {a}, {part})", "subdivide": "subdivide({net}, {n}, {a})",
           "subdivide_to_depth": "subdivide_to_depth({net}, {n}, {a}, {k})"}
    bad_args = [("a", b, ("alpha",)) for b in ("float('nan')", "float('inf')", "-1.0", "0.0", "4.0", "1j", "'x'",
                                               "None", "5e-324")]
    bad_args += [("n", b, ("n",)) for b in ("True", "0", "-3", "2.5", "10**9", "'2'", "None")]
    bad_args += [("part", b, ("part",)) for b in ("'x'", "''", "1", "None", "['u']")]
    bad_args += [("net", b, ("net",)) for b in ("np.ones((18, 3))", "np.full((19, 3), np.nan)", "'net'",
                                                "np.ones((19, 3)) + 1j", "np.ones((19, 3, 2))")]
    bad_args += [("k", b, ("k",)) for b in ("-1", "1.5", "'1'", "None", "10**6")]
    for template in sub.values():
        for key, b, words in bad_args:
            if "{" + key + "}" in template:
                add("subdivision", "r = " + template.format(**dict(good, **{key: b})), "err", words)
    for a in (1e-300, 1e-30, 1e-3, 1.0, math.pi - 1e-8):
        for n in (1, 3, 6):
            add("subdivision", f"S = subdivision_matrix({n}, {a!r}, 'middle'); "
                "r = (S, np.abs(S.sum(axis=1) - 1).max())", "ok", "finite(r[0]) and r[1] < 1e-12")
        add("subdivision", f"net = np.random.default_rng(2).normal(size=(19, 3)); q = subdivide(net, 2, {a!r}); "
            f"x = sample_points({a!r} / 2, 20, seed=1); from paper_repro.core.subdivision import to_parent; "
            f"r = rel(Patch(2, {a!r} / 2, q.w)(x), Patch(2, {a!r}, net)(to_parent(x, {a!r}, 'w')), 1.0)", "ok",
            "r < 1e-12")
    # --- the stated float bounds of the transformation and the products: bad n/alpha refused naming it; valid calls
    #     give the documented shape (finite or inf, positive); the refusal threshold is where the bound says
    fb = ("from paper_repro.core.transformation import v_to_t_float_bound, t_to_v_float_bound, "
          "v_to_t_float_alpha_min, transformation_matrix; "
          "from paper_repro.core.half_angle_matrices import product_float_bound; ")
    for b in ("True", "0", "-3", "2.5", "10**9", "'2'", "None", "np.int64(31)"):
        for f in ("v_to_t_float_bound({}, 1.0)", "t_to_v_float_bound({})", "v_to_t_float_alpha_min({})",
                  "product_float_bound({})"):
            if not (b == "np.int64(31)" and f.startswith("product")):  # the products' bound holds to n = 1000
                add("float_bounds", fb + "r = " + f.format(b), "err", ("n",))
    add("float_bounds", fb + "r = product_float_bound(np.int64(1001))", "err", ("n",))
    for b in ("float('nan')", "float('inf')", "-1.0", "0.0", "4.0", "1j", "'x'", "None", "5e-324"):
        add("float_bounds", fb + f"r = v_to_t_float_bound(3, {b})", "err", ("alpha",))
    for n in (1, 10, 30):
        for a in (1e-300, 1e-100, 1e-8, 1e-3, 1.0, math.pi - 1e-12):
            add("float_bounds", fb + f"r = v_to_t_float_bound({n}, {a!r})", "ok",
                "r > 0 and (r == math.inf or math.isfinite(r))")
        add("float_bounds", fb + f"r = (t_to_v_float_bound({n}), product_float_bound({n}))", "ok",
            "0 < r[0] < 1e-9 and 0 < r[1] < 1e-13")
        add("float_bounds", fb + f"a = v_to_t_float_alpha_min({n}); "
            f"T = transformation_matrix({n}, a * 1.01) if {n} <= 10 else None; r = (a, T)", "ok",
            "1e-4 < r[0] < 1e-2 and (r[1] is None or np.isfinite(r[1]).all())")
        add("float_bounds", fb + f"r = transformation_matrix({n}, v_to_t_float_alpha_min({n}) * 0.99)", "err",
            ("alpha",))

    if with_cli:
        py = sys.executable
        for sched in ("tcp://127.0.0.1:1", "tcp://no-such-host.invalid:8786", "tls://127.0.0.1:1"):
            out.append(("cli", ("cli", [py, "-m", "paper_repro", "claims", "--only", "dimension", "--scheduler",
                                        sched]), ()))
        out.append(("cli", ("cli", [py, "-m", "paper_repro", "claims", "--out", "/tmp/" + "a" * 300]), ()))
        for alpha in ("3.1415926535897", "1e-17", "1e-300", "pi/0", "1/0", "0/0", "pi", "0", "-1", "nan", "inf",
                      "1j", "abc"):
            for claim in ("partition_of_unity", "coincidence", "torus_exact", "patch_properties"):
                out.append(("cli", ("cli", [py, "-m", "paper_repro", "claims", "--only", claim, "--alpha", alpha]), ()))
        for n in ("1000", "0", "-1", "1.5", "x", "10**6"):
            for claim in ("partition_of_unity", "dimension", "nonnegativity"):
                out.append(("cli", ("cli", [py, "-m", "paper_repro", "claims", "--only", claim, "--n", n]), ()))
    return out


def run_cli(argv, timeout=400.0):
    """A CLI case is good when it exits 0/1 with a verdict on the mathematics (no 'Traceback'), or exits 2 with
    one line on stderr naming the option."""
    env = dict(os.environ, PAPER_REPRO_WORKERS="1")
    try:
        p = subprocess.run(argv, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return "hang", f"no exit in {timeout:.0f} s"
    err = p.stderr.strip()
    if "Traceback" in p.stderr or "Error:" in p.stderr.replace("error:", ""):
        return "wrong-exception", err.splitlines()[-1][:200] if err else ""
    if p.returncode == 2:
        lines = [ln for ln in err.splitlines() if ln.strip()]
        named = any(o in err for o in ("--alpha", "--n", "alpha", "n must"))
        return ("good", "") if len(lines) == 1 and named else ("wrong-exception", err[:200])
    if p.returncode == 1:
        return "silent-wrong", "a claim reported FAIL: " + p.stdout.strip().splitlines()[-1][:150]
    if p.returncode == 0:
        return "good", ""
    return "wrong-exception", f"exit {p.returncode}: {err[:200]}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--classes", help="comma-separated classes to run (default: all)")
    ap.add_argument("--cli", action="store_true", help="also fuzz the command line (slow)")
    ap.add_argument("--json", help="write every case and its outcome to this file")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--timeout", type=float, default=TIMEOUT)
    args = ap.parse_args(argv)
    all_cases = cases(random.Random(args.seed), args.cli)
    if args.classes:
        keep = set(args.classes.split(","))
        all_cases = [c for c in all_cases if c[0] in keep]
    runner = Runner()
    counts: dict[str, Counter] = defaultdict(Counter)
    records = []
    t0 = time.time()
    for cls, code, expect in all_cases:
        if isinstance(code, tuple) and code[0] == "cli":
            outcome, detail = run_cli(code[1])
            code = " ".join(code[1][2:])
        else:
            outcome, detail = classify(expect, runner.run(code, expect[1] if expect[0] == "ok" else
                                                          expect[1] if expect[0] == "ok|err" else "",
                                                          args.timeout))
        counts[cls][outcome] += 1
        records.append({"class": cls, "code": code, "outcome": outcome, "detail": detail})
        if outcome != "good":
            print(f"[{cls}] {outcome}: {code[:150]} -> {detail[:200]}", flush=True)
    if runner.proc is not None:
        runner.conn.send(None)
    kinds = ("good", "wrong-exception", "silent-wrong", "hang")
    print(f"\n{len(records)} cases in {time.time() - t0:.0f} s")
    print(f"{'class':14s} " + " ".join(f"{k:>15s}" for k in kinds))
    total = Counter()
    for cls in sorted(counts):
        total.update(counts[cls])
        print(f"{cls:14s} " + " ".join(f"{counts[cls][k]:15d}" for k in kinds))
    print(f"{'total':14s} " + " ".join(f"{total[k]:15d}" for k in kinds))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"counts": {c: dict(v) for c, v in counts.items()}, "cases": records}, fh, indent=1)
    return 0 if total["good"] == len(records) else 1


if __name__ == "__main__":
    sys.exit(main())
