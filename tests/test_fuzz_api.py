"""Fuzzing the public API with hypothesis: every bad input gets a ValueError/TypeError that names the
parameter -- never a traceback from deep inside numpy/flint, a hang or a silent wrong answer."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from paper_repro import (
    Patch,
    coefficients,
    elevate,
    evaluate,
    evaluate_normalized,
    export_mesh,
    rational_alpha,
    sample_points,
)
from paper_repro.core.labels import delta

bad_n = st.one_of(st.integers(max_value=0), st.floats(), st.text(max_size=3), st.none(), st.booleans(),
                  st.just(1.5), st.just([1]))
bad_alpha = st.one_of(st.floats().filter(lambda a: not (0 < a < math.pi)), st.text(max_size=3), st.none(),
                      st.sampled_from([0, math.pi, -1, 4, float("nan"), float("inf"), -float("inf"), 0.0]))
bad_points = st.one_of(
    st.just([]), st.just([[0.5, 0.5]]), st.just([[0.5, 0.2, 0.3, 0.0]]), st.just([[float("nan"), 0.5, 0.5]]),
    st.just([[2.0, -0.5, -0.5]]), st.just([[0.9, 0.9, 0.9]]), st.just("points"), st.just([["a", "b", "c"]]),
    st.just(np.zeros((2, 2, 3))), st.just([[float("inf"), 0.0, 0.0]]))

ERR = (ValueError, TypeError)


def _names(exc: Exception, *words: str) -> bool:
    text = str(exc)
    return any(w in text for w in words)


@settings(max_examples=30)
@given(bad_n)
def test_bad_n(n):
    for call in (lambda: evaluate(n, 1.0, [[0.3, 0.3, 0.4]]), lambda: coefficients(n, 1.0),
                 lambda: Patch(n, 1.0, np.zeros((7, 3)))):
        with pytest.raises(ERR) as info:
            call()
        assert _names(info.value, "n must"), str(info.value)


@settings(max_examples=30)
@given(bad_alpha)
def test_bad_alpha(alpha):
    for call in (lambda: evaluate_normalized(1, alpha, [[0.3, 0.3, 0.4]]), lambda: coefficients(2, alpha),
                 lambda: Patch(1, alpha, np.zeros((7, 3))), lambda: sample_points(alpha, 3)):
        with pytest.raises(ERR) as info:
            call()
        assert _names(info.value, "alpha"), str(info.value)


@settings(max_examples=30)
@given(bad_points)
def test_bad_points(points):
    p = Patch(1, 1.0, np.zeros((7, 3)))
    for call in (lambda: evaluate(1, 1.0, points), lambda: p(points), lambda: p.derivative(points)):
        with pytest.raises(ERR) as info:
            call()
        assert _names(info.value, "points"), str(info.value)


@settings(max_examples=30)
@given(st.one_of(st.just(np.zeros((6, 3))), st.just(np.zeros((7,))), st.just(np.full((7, 3), np.nan)),
                 st.just([["x"] * 3] * 7), st.just({"r_{2,2,0}": (0, 0, 0)}), st.just({"q_{2,2,0}": (0, 0, 0)}),
                 st.just(np.zeros((7, 0))), st.just([[0, 0, 0]] * 6 + [[0, 0]])))
def test_bad_nets(net):
    with pytest.raises(ERR) as info:
        Patch(1, 1.0, net)
    assert _names(info.value, "net"), str(info.value)
    with pytest.raises(ERR):
        elevate(net, 1, 1.0)


@settings(max_examples=20)
@given(st.one_of(st.just(np.ones(6)), st.just(-np.ones(7)), st.just(np.zeros(7)), st.just(np.full(7, np.nan)),
                 st.just(["a"] * 7)))
def test_bad_weights(weights):
    with pytest.raises(ERR) as info:
        Patch(1, 1.0, np.zeros((7, 3)), weights)
    assert _names(info.value, "weights"), str(info.value)


def test_bad_arith_counts_and_sizes(tmp_path):
    with pytest.raises(ValueError, match="arith must be one of"):
        evaluate(1, 1.0, [[0.3, 0.3, 0.4]], "quad")
    with pytest.raises(ValueError, match="count must be an integer from 0"):
        sample_points(1.0, -1)
    with pytest.raises(ValueError, match="count must be an integer from 0"):
        sample_points(1.0, 10**12)  # would not fit in memory: refused at once
    with pytest.raises(ValueError, match="resolution must be an integer"):
        Patch(1, 1.0, np.zeros((7, 3))).mesh(10**6)
    with pytest.raises(TypeError, match="RationalPoints"):
        evaluate(1, 1.0, [[0.3, 0.3, 0.4]], "exact")
    with pytest.raises(ValueError, match="is not a mesh format"):
        export_mesh(tmp_path / "m.xyz", np.eye(3), [[0, 1, 2]])
    with pytest.raises(ValueError, match="does not exist"):
        export_mesh(tmp_path / "no" / "such" / "m.obj", np.eye(3), [[0, 1, 2]])
    assert not (tmp_path / "no").exists()
    with pytest.raises(ValueError, match="faces must index"):
        export_mesh(tmp_path / "m.obj", np.eye(3), [[0, 1, 5]])
    with pytest.raises(ValueError, match="direction"):
        Patch(1, 1.0, np.zeros((7, 3))).derivative([[0.3, 0.3, 0.4]], (1, 1, 1))
    with pytest.raises(ValueError, match="n must"):
        delta(0)
    with pytest.raises(ValueError, match="exceeds float64"):
        coefficients(200, 1.0)  # r itself is about e^710 there: a clear refusal, never inf
    with pytest.raises(ValueError, match="n must be at most 200 for normalizing coefficients in arith 'exact'"):
        coefficients(201, rational_alpha((1, 2)), "exact")  # refused before any work (cost n^3 on O(n)-digit numbers)
    with pytest.raises(ValueError, match="n must be a positive integer from 1 to 1000"):
        evaluate(10**6, 1.0, [[0.3, 0.3, 0.4]])
    with pytest.raises(ValueError, match="evaluate fewer points"):
        evaluate(40, 1.0, np.tile([[0.3, 0.3, 0.4]], (50_000, 1)))  # 50000 x 4921 values: refused, not an OOM
    with pytest.raises(ValueError, match="alpha"):
        rational_alpha((0, 1))


def test_messages_print_plain_numbers():
    with pytest.raises(ValueError) as info:
        evaluate(1, 1.0, [[0.9, 0.9, 0.9]])
    assert "np.float64" not in str(info.value) and "mpf(" not in str(info.value)
    import mpmath

    with pytest.raises(ValueError) as info:
        coefficients(1, mpmath.mpf(0))
    assert "mpf(" not in str(info.value)


@settings(max_examples=25)
@given(st.integers(1, 4), st.floats(1e-3, math.pi - 1e-3), st.integers(0, 2**32 - 1))
def test_good_inputs_never_raise_and_partition_unity(n, alpha, seed):
    pts = sample_points(alpha, 5, seed=seed)
    vals = evaluate_normalized(n, alpha, pts)
    assert vals.shape == (5, delta(n)) and np.all(np.isfinite(vals))
    assert np.max(np.abs(vals.sum(axis=1) - 1)) < 1e-9


def test_the_hostile_suite_of_this_round_passes():
    """tools/fuzz_api.py's class round5 (the float transformation at small alpha, its direction, elevate's target,
    barycentric rows): every case a correct result or a clear ValueError/TypeError."""
    import subprocess
    import sys
    from pathlib import Path

    tool = Path(__file__).parents[1] / "tools" / "fuzz_api.py"
    p = subprocess.run([sys.executable, str(tool), "--classes", "round5"], capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    assert "round5" in p.stdout and " 0               0               0" in p.stdout.splitlines()[-1], p.stdout


def _hostile_class_passes(cls: str, timeout: int) -> None:
    """Run one class of tools/fuzz_api.py on this checkout's package: every case good (no wrong exception, no silent
    wrong result, no hang)."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).parents[1]  # this checkout's package, also in a worktree beside an installed one
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(root), os.environ.get("PYTHONPATH")]))}
    p = subprocess.run([sys.executable, str(root / "tools" / "fuzz_api.py"), "--classes", cls],
                       capture_output=True, text=True, timeout=timeout, env=env)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    assert cls in p.stdout and " 0               0               0" in p.stdout.splitlines()[-1], p.stdout


@pytest.mark.slow
def test_the_hostile_suite_of_the_tessellator_passes():
    """tools/fuzz_api.py's class tessellate: every bad input refused naming its parameter, every valid one a mesh
    within its bound and tol (checked at the triangles' centroids), or a refusal naming max_vertices."""
    _hostile_class_passes("tessellate", 1200)


def test_the_hostile_joins_class_passes():
    """tools/fuzz_api.py's class joins: NaN/inf/complex/out-of-range alpha, bool and huge n, bad edge names, wrong net
    shapes, bad lam/mu/arith/dps for every public function of paper_repro.surfaces.joins give a ValueError/TypeError
    naming the parameter; valid calls at alpha from 1e-300 to pi- are finite and joined."""
    _hostile_class_passes("joins", 600)


def test_the_hostile_subdivision_class_passes():
    """tools/fuzz_api.py's class subdivision: bad alpha, n, part, net and depth refused naming the parameter for
    subdivision_matrix, subdivide and subdivide_to_depth; at alpha from 1e-300 to pi- the matrices are finite with rows
    summing to 1 and a sub-patch equals the patch on its sub-triangle."""
    _hostile_class_passes("subdivision", 600)


def test_the_hostile_float_bounds_class_passes():
    """tools/fuzz_api.py's class float_bounds: v_to_t_float_bound, t_to_v_float_bound, v_to_t_float_alpha_min and
    product_float_bound refuse bad n and alpha naming the parameter; valid calls are positive (inf where alpha^2
    underflows); transformation_matrix returns just above v_to_t_float_alpha_min and refuses just below it."""
    _hostile_class_passes("float_bounds", 600)
