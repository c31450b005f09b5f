"""The library API of issue 20: alpha as text, labelled nets, least-squares fitting with interpolation, the
alpha -> 0 limit as a bezier.Triangle, where outputs and the cache go, the CLI lists."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import paper_repro as pr
from paper_repro.app import cli
from paper_repro.theory.limits import bernstein_eval
from paper_repro.util import cache, io
from paper_repro.util.registry import CLAIMS, FIGURES, load_all
from paper_repro.util.validation import parse_alpha


@pytest.mark.parametrize("text, value", [("pi/2", math.pi / 2), ("2pi/3", 2.0943951023931957),
                                         ("2*pi/3", 2.0943951023931957),
                                         ("π/4", math.pi / 4), ("0.5 pi", math.pi / 2), ("1.25", 1.25),
                                         ("3/2", 1.5), (" pi / 6 ", 0.5235987755982989)])
def test_parse_alpha_reads_text(text, value):
    assert parse_alpha(text) == value  # the nearest float (2 * math.pi / 3 is one ulp below it)


@pytest.mark.parametrize("bad", ["pi", "0", "-1", "4", "2pi", "tau/2", "", "pi/0.5"])
def test_parse_alpha_rejects_naming_the_parameter(bad):
    with pytest.raises(ValueError, match="alpha"):
        parse_alpha(bad)


def test_alpha_text_everywhere_in_the_api():
    net = np.random.default_rng(0).normal(size=(19, 3))
    pts = pr.sample_points("pi/2", 5, seed=1)
    assert np.array_equal(pts, pr.sample_points(np.pi / 2, 5, seed=1))
    assert np.array_equal(pr.Patch(2, "pi/2", net)(pts), pr.Patch(2, np.pi / 2, net)(pts))
    third = 1.0471975511965979  # the float nearest to pi/3 (np.pi / 3 is one ulp below it)
    assert pr.coefficients(2, "pi/3") == pr.coefficients(2, third)
    assert np.array_equal(pr.evaluate_normalized(2, "pi/3", pts * (2 / 3)), pr.evaluate_normalized(2, third,
                                                                                                    pts * (2 / 3)))
    assert np.array_equal(pr.elevate(net, 2, "pi/2"), pr.elevate(net, 2, np.pi / 2))
    with pytest.raises(ValueError, match="alpha"):
        pr.Patch(2, "pi", net)


def test_net_by_paper_label():
    net = np.arange(57.0).reshape(19, 3)
    p = pr.Patch(2, 1.0, net)
    labels = p.net.labels()
    assert len(labels) == 19 and len(set(labels)) == 19
    for k, lab in enumerate(labels):
        assert p.net[lab].tolist() == net[k].tolist()
    assert p.net["R_{4,3,1}"].tolist() == p.net["r_{4,3,1}"].tolist()
    assert p.net["r_{4,0,0}"].tolist() == p.net["g_{4,4,0}"].tolist()  # aliases of one function
    with pytest.raises(KeyError, match="no control point labelled"):
        p.net["r_{6,3,1}"]
    assert type(p.net * 2) is np.ndarray and type(p.net[1:3]) is np.ndarray


def test_bezier_triangle_nodes_in_bezier_order():
    bezier = pytest.importorskip("bezier")
    net = np.random.default_rng(3).normal(size=(37, 3))
    tri = pr.bezier_triangle(net, 3)
    assert isinstance(tri, bezier.Triangle) and tri.degree == 8
    N, bez = pr.bezier_limit(net, 3)
    st = np.random.default_rng(4).dirichlet(np.ones(3), size=20)[:, :2]
    ours = bernstein_eval(N, np.c_[1 - st.sum(axis=1), st], bez)
    assert np.allclose(tri.evaluate_cartesian_multi(np.asfortranarray(st)).T, ours, atol=1e-13)
    # and it is the limit: a patch at a small alpha is close to it
    small = pr.Patch(3, 1e-4, net)
    assert np.allclose(small.at_barycentric(np.c_[1 - st.sum(axis=1), st]), ours, atol=1e-6)


def test_least_squares_reproduces_a_patch_and_interpolates():
    rng = np.random.default_rng(5)
    truth = pr.Patch(2, "pi/2", rng.normal(size=(19, 3)))
    pts = pr.sample_points("pi/2", 300, seed=6)
    net = pr.fit_least_squares(pts, truth(pts), 2, "pi/2")
    assert np.allclose(net, truth.net, atol=1e-10)
    noisy = truth(pts) + 0.05 * rng.normal(size=(300, 3))
    corners = truth(np.pi / 2 * np.eye(3))
    fitted = pr.Patch(2, "pi/2", pr.fit_least_squares(pts, noisy, 2, "pi/2", corners=corners))
    assert np.allclose(fitted(np.pi / 2 * np.eye(3)), corners, atol=1e-12)
    free = pr.Patch(2, "pi/2", pr.fit_least_squares(pts, noisy, 2, "pi/2"))
    assert not np.allclose(free(np.pi / 2 * np.eye(3)), corners, atol=1e-6)  # the constraint did something
    t = np.linspace(0, np.pi / 2, 7)
    edge = pr.fit_least_squares(pts, noisy, 2, "pi/2", boundary={"u=0": lambda s: truth.boundary_curve("u=0", s)})
    assert np.allclose(pr.Patch(2, "pi/2", edge).boundary_curve("u=0", t), truth.boundary_curve("u=0", t), atol=1e-10)
    with pytest.raises(ValueError, match="must agree"):
        pr.fit_least_squares(pts, noisy, 2, "pi/2", corners=corners + 1,
                             boundary={"u=0": lambda s: truth.boundary_curve("u=0", s)})
    with pytest.raises(ValueError, match="values"):
        pr.fit_least_squares(pts, noisy[:-1], 2, "pi/2")


def test_outputs_follow_out_and_never_the_install_location(tmp_path, monkeypatch):
    monkeypatch.delenv(io.OUT_ENV, raising=False)
    assert io.in_checkout() and io.output_root() == io.ROOT  # a clone: data/ and figures/ of the clone
    monkeypatch.setattr(io, "in_checkout", lambda: False)  # as installed: the current directory
    monkeypatch.chdir(tmp_path)
    assert io.data_dir() == tmp_path / "data" and io.figures_dir() == tmp_path / "figures"
    io.set_output_root(tmp_path / "out")
    try:
        assert io.data_dir() == tmp_path / "out" / "data" and io.DATA == tmp_path / "out" / "data"
    finally:
        io.set_output_root(None)


def test_cache_dir_rules(tmp_path, monkeypatch):
    monkeypatch.setattr(cache, "CACHE_DIR", None)
    monkeypatch.delenv(cache.CACHE_ENV, raising=False)
    assert cache.cache_dir() == io.ROOT / ".cache"
    monkeypatch.setattr(cache, "in_checkout", lambda: False)
    pytest.importorskip("platformdirs")
    user = cache.cache_dir()
    assert "paper_repro" in user.parts and not str(user).startswith(str(io.PACKAGE))
    monkeypatch.setenv(cache.CACHE_ENV, str(tmp_path))
    assert cache.cache_dir() == tmp_path
    monkeypatch.setenv(cache.NO_CACHE_ENV, "1")
    assert not cache.enabled()
    assert cache.cached("t", {"a": 1}, lambda: 5) == 5 and not any(Path(tmp_path).iterdir())


def test_cli_lists_and_plain_help(capsys):
    load_all()
    assert cli.main(["claims", "--list"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [ln.split()[0] for ln in out] == list(CLAIMS) and all("``" not in ln for ln in out)
    assert cli.main(["figures", "--list"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [ln.split()[0] for ln in out] == list(FIGURES)
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    text = capsys.readouterr().out
    assert "``" not in text and ":func:" not in text and "--out DIR" in text
    for sub in (["figures", "--help"], ["labels", "--help"], ["reproduce", "--help"]):
        with pytest.raises(SystemExit):
            cli.main(sub)
        helptext = capsys.readouterr().out
        assert "``" not in helptext
    assert "figure ids" in cli_help("figures") and "the order n" in cli_help("labels")
    assert "write data/, figures/" in cli_help("reproduce").replace("\n", " ").replace("  ", " ")


def cli_help(cmd: str) -> str:
    import contextlib
    import io as _io

    buf = _io.StringIO()
    with contextlib.redirect_stdout(buf), pytest.raises(SystemExit):
        cli.main([cmd, "--help"])
    return buf.getvalue()


def test_version_is_exported():
    assert isinstance(pr.__version__, str) and pr.__version__.count(".") == 2
    assert (Path(pr.__file__).parent / "py.typed").is_file()
    for name in pr.__all__:
        assert hasattr(pr, name), name


def _np_torus(u, v, w):
    return ((2 + np.sin(u)) * np.cos(v), (2 + np.sin(u)) * np.sin(v), np.cos(u))


def test_fit_float_takes_a_numpy_written_surface():
    """Issue 33: fit(surface, 2, alpha, 'float') called surface with mpf: TypeError: loop of ufunc does not support
    argument 0 of type mpf.  The float route fits with floats; the torus is exact at order 2 (Example 6.1)."""
    import mpmath

    alpha = np.pi / 2
    net = pr.fit(_np_torus, 2, alpha, "float")
    assert net.dtype == np.float64 and net.shape == (19, 3)
    q = pr.sample_points(alpha, 60, seed=11)
    exact = np.array([_np_torus(*p) for p in q])
    assert abs(pr.Patch(2, alpha, net)(q) - exact).max() < 1e-12
    # independent: the mp fit of the same torus written with mpmath
    mp_net = pr.fit(lambda u, v, w: ((2 + mpmath.sin(u)) * mpmath.cos(v), (2 + mpmath.sin(u)) * mpmath.sin(v),
                                     mpmath.cos(u)), 2, alpha, "mp", dps=30).astype(float)
    assert abs(net - mp_net).max() < 1e-11
    with pytest.raises(ValueError, match=r"not in the span of T_\{2\}"):
        pr.fit(_np_torus, 1, alpha, "float")  # the torus needs order 2


def test_fit_says_what_the_surface_must_take():
    with pytest.raises(TypeError, match=r"^surface: fit\(\.\.\., 'mp'\) calls it with mpmath numbers .*arith='float'"):
        pr.fit(_np_torus, 2, 1.0, "mp")
    with pytest.raises(TypeError, match=r"surface coordinates \(point 0\) must be a real number"):
        pr.fit(lambda u, v, w: ("a", "b"), 2, 1.0, "float")
    with pytest.raises(ValueError, match="n must be"):
        pr.fit(_np_torus, 11, 1.0, "float")


def test_first_compilation_is_announced_once(monkeypatch):
    """The first evaluation in a new environment compiled for 10-17 s in silence: one line on stderr, once."""
    import io as _io

    from paper_repro.core import fast_jit

    if not fast_jit.available():
        pytest.skip("numba is not installed: nothing is compiled")
    monkeypatch.setattr(fast_jit, "_ANNOUNCED", set())
    monkeypatch.setattr(fast_jit, "_is_cached", lambda dispatcher: False)
    monkeypatch.delenv("PAPER_REPRO_NO_CACHE", raising=False)
    out = _io.StringIO()
    assert fast_jit.announce_compilation("values", out)
    assert not fast_jit.announce_compilation("values", out)
    lines = out.getvalue().splitlines()
    assert len(lines) == 1 and "compiling the float64 point kernel" in lines[0] and "once per environment" in lines[0]
    monkeypatch.setattr(fast_jit, "_is_cached", lambda dispatcher: True)
    assert not fast_jit.announce_compilation("derivatives", out)  # already in numba's cache: silent


@pytest.mark.slow
def test_first_compilation_message_in_a_fresh_cache(tmp_path):
    import subprocess
    import sys

    from paper_repro.core import fast_jit

    if not fast_jit.available():
        pytest.skip("numba is not installed")
    code = "import numpy as np, paper_repro as pr; pr.Patch(1, 1.0, np.ones((7, 3)))(pr.sample_points(1.0, 3))"
    env = {**__import__("os").environ, "PAPER_REPRO_CACHE": str(tmp_path), "PAPER_REPRO_KERNEL": "numba"}
    env.pop("PAPER_REPRO_NO_CACHE", None)
    first = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300)
    second = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300)
    assert first.stderr.count("compiling the float64 point kernel") == 1, first.stderr
    assert "compiling" not in second.stderr, second.stderr
