"""Issue 31, items 2-5: a cache that never changes an answer nor stops the work, a CLI that refuses before it
works, coefficients rounded from certified digits, and the hostile inputs of the issue.

Each test reproduces a case of the issue (what happened before the fix is said next to it)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from paper_repro.core import elevation as el
from paper_repro.util import cache

ROOT = Path(__file__).resolve().parent.parent


def _unshare_works() -> bool:
    """``unshare --user`` runs a process without root's capabilities: a 0555 folder is then really read-only."""
    if shutil.which("unshare") is None:
        return False
    try:
        return subprocess.run(["unshare", "--user", "true"], capture_output=True, timeout=20).returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


def _as_user(cmd: list[str]) -> list[str]:
    """``cmd`` run without write access to folders it does not own (root: through ``unshare --user``)."""
    return ["unshare", "--user", *cmd] if os.geteuid() == 0 else cmd


needs_readonly = pytest.mark.skipif(os.geteuid() == 0 and not _unshare_works(),
                                    reason="running as root without unshare: no folder is read-only")


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path / "cache")
    monkeypatch.delenv(cache.NO_CACHE_ENV, raising=False)
    el._elevation_matrix_float.cache_clear()
    yield tmp_path / "cache"
    el._elevation_matrix_float.cache_clear()


def _cache_warnings(record) -> list[str]:
    return [str(w.message) for w in record if issubclass(w.category, cache.CacheWarning)]


def _elevation_entry(folder: Path) -> Path:
    (path,) = (folder / "elevation_matrix").glob("*.json")
    return path


def _tamper(path: Path, change, rechecksum: bool) -> None:
    stored = json.loads(path.read_text())
    stored["value"] = change(stored["value"])
    if rechecksum:  # a writer that was wrong but consistent: only the shape/finiteness checks can see it
        stored["sha256"] = cache.checksum(stored["value"])
    path.write_text(json.dumps(stored))


def _drop_row(v):
    return {**v, "rows": v["rows"][:-1]}


def _nan_row(v):
    return {**v, "rows": [v["rows"][0], [float("nan").hex()] * len(v["rows"][1]), *v["rows"][2:]]}


@pytest.mark.parametrize("change", [_drop_row, _nan_row, lambda v: [], lambda v: {**v, "rows": "x"}],
                         ids=["missing-row", "nan-row", "empty", "text"])
def test_bad_matrix_entry_generic(fresh_cache, change):
    """The same cases through cached() alone (any user of a hex-float matrix, whatever elevation becomes)."""
    rows = [[float(i + j).hex() for j in range(3)] for i in range(4)]
    calls = []

    def compute():
        calls.append(1)
        return {"rows": rows}

    check = cache.hex_rows(4, 3)
    assert cache.cached("m", {"k": 1}, compute, validate=check) == {"rows": rows}
    (path,) = (fresh_cache / "m").glob("*.json")
    _tamper(path, change, rechecksum=True)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        assert cache.cached("m", {"k": 1}, compute, validate=check) == {"rows": rows}
    assert len(calls) == 2 and len(_cache_warnings(rec)) == 1
    assert json.loads(path.read_text())["value"] == {"rows": rows}  # rewritten


def _hex_matrix(rows: int, cols: int):
    """A cached user of a hex-float matrix (what elevation stored before its closed form), with its validator."""
    want = [[float(i + j).hex() for j in range(cols)] for i in range(rows)]

    def check(v):
        if not (isinstance(v, dict) and isinstance(v.get("rows"), list) and len(v["rows"]) == rows):
            raise ValueError("not a matrix of the expected shape")

    return (lambda: cache.cached("m", {"k": 1}, lambda: {"rows": want}, validate=check)), {"rows": want}


@pytest.mark.parametrize("text", ["[]", "", "{", "null", '{"name": "m"}'])
def test_unparsable_entry_is_recomputed(fresh_cache, text):
    """Before: a file holding ``[]`` raised AttributeError ('list' object has no attribute 'get')."""
    get, good = _hex_matrix(4, 3)
    assert get() == good
    (path,) = (fresh_cache / "m").glob("*.json")
    path.write_text(text)
    with pytest.warns(cache.CacheWarning, match="recomputed"):
        assert get() == good


def test_entry_of_other_parameters_is_not_used(fresh_cache):
    """An entry whose stored parameters are not those of its key (a copied file) is recomputed."""
    a = cache.cached("t", {"k": 1}, lambda: {"x": 1})
    b = cache.cached("t", {"k": 2}, lambda: {"x": 2})
    p1 = fresh_cache / "t" / f"{cache.key('t', {'k': 1})}.json"
    p2 = fresh_cache / "t" / f"{cache.key('t', {'k': 2})}.json"
    shutil.copy(p2, p1)
    with pytest.warns(cache.CacheWarning, match="parameters"):
        assert cache.cached("t", {"k": 1}, lambda: {"x": 1}) == a != b


def test_validators_of_every_cached_user(fresh_cache, monkeypatch):
    """Each ``cached(...)`` user validates its values: a consistent entry of the wrong shape is recomputed."""
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import exact_coefficients_cached
    from paper_repro.theory import closed_forms as cf
    from paper_repro.theory.closed_forms import closed_forms_cached, proof_cached

    monkeypatch.setattr(cf, "_REMEMBERED", {})  # records handed over in this process (dask tasks) bypass the disk

    alpha = rational_alpha((1, 2))
    sol = exact_coefficients_cached(1, alpha)
    forms = closed_forms_cached(1)
    proof = proof_cached(1)
    for name, change in (("orbit_coefficients", lambda v: {**v, "solution": v["solution"][:-1]}),
                         ("closed_forms", lambda v: dict(list(v.items())[:-1])),
                         ("closed_form_proof", lambda v: {**v, "proved": "yes"})):
        (path,) = (fresh_cache / name).glob("*.json")
        _tamper(path, change, rechecksum=True)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        assert exact_coefficients_cached(1, alpha) == sol
        assert {k: v.as_json() for k, v in closed_forms_cached(1).items()} == \
            {k: v.as_json() for k, v in forms.items()}
        assert proof_cached(1) == proof
    assert len(_cache_warnings(rec)) == 3


def test_claim_outcome_entry_is_validated(fresh_cache):
    from paper_repro.util.registry import CLAIMS, load_all, run_claim

    load_all()
    c = CLAIMS["dimension"]
    first, _, _ = run_claim(c, {"n_min": 1, "n_max": 2})
    (path,) = (fresh_cache / "claims").glob("*.json")
    _tamper(path, lambda v: {**v, "passed": "true"}, rechecksum=True)
    with pytest.warns(cache.CacheWarning):
        again, _, _ = run_claim(c, {"n_min": 1, "n_max": 2})
    assert again.status == first.status == "pass" and not again.cached


def test_cache_naming_a_file_works_without_cache(tmp_path, monkeypatch):
    """Before: ``PAPER_REPRO_CACHE`` naming a file gave a raw NotADirectoryError (elevation_matrix, then cached)."""
    afile = tmp_path / "afile"
    afile.write_text("x")
    monkeypatch.setattr(cache, "CACHE_DIR", afile)
    monkeypatch.delenv(cache.NO_CACHE_ENV, raising=False)
    monkeypatch.setattr(cache, "_WARNED_UNUSABLE", set())
    get, good = _hex_matrix(4, 3)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        assert get() == good and get() == good
    assert len(_cache_warnings(rec)) == 1 and "not writable" in _cache_warnings(rec)[0]
    assert cache.unusable(afile) is not None


def test_unwritable_cache_folder_simulated(tmp_path, monkeypatch):
    """A folder where nothing can be created (PermissionError on every write): computed, one warning."""
    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path)
    monkeypatch.delenv(cache.NO_CACHE_ENV, raising=False)
    monkeypatch.setattr(cache, "_WARNED_UNUSABLE", set())

    def denied(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(Path, "mkdir", denied)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        assert cache.cached("t", {"a": 1}, lambda: {"x": 1}) == {"x": 1}
        assert cache.cached("t", {"a": 2}, lambda: {"x": 2}) == {"x": 2}
    assert len(_cache_warnings(rec)) == 1


SCRIPT = """
import warnings, numpy as np
warnings.simplefilter("always")
from paper_repro.core import elevation as el
from paper_repro import Patch
net = np.arange(57.0).reshape(19, 3)
print(el.elevate(net, 2, 1.0).shape)
print(Patch(2, 1.0, net)([[0.2, 0.3, 0.5]]).round(9).tolist())
"""


def _run(env_cache: Path, readonly: bool = False) -> subprocess.CompletedProcess:
    env = {**os.environ, "PAPER_REPRO_CACHE": str(env_cache)}
    env.pop("PAPER_REPRO_NO_CACHE", None)
    env.pop("NUMBA_CACHE_DIR", None)
    cmd = [sys.executable, "-c", SCRIPT]
    return subprocess.run(_as_user(cmd) if readonly else cmd, capture_output=True, text=True, env=env, cwd=ROOT,
                          timeout=600)


@needs_readonly
def test_readonly_cache_folder_works_without_cache(tmp_path):
    """Before: a read-only cache folder gave a raw PermissionError from elevation_matrix (claims: FAIL), and numba
    fell back to writing its cache into the package's __pycache__ (the install location)."""
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    before = set((ROOT / "paper_repro" / "core" / "__pycache__").glob("fast_jit*.nb*"))
    res = _run(ro, readonly=True)
    assert res.returncode == 0, res.stderr
    assert res.stdout.splitlines()[0] == "(37, 3)"
    assert res.stderr.count("CacheWarning") == 1 and "not writable" in res.stderr
    assert set((ROOT / "paper_repro" / "core" / "__pycache__").glob("fast_jit*.nb*")) == before
    assert not any(ro.iterdir())


@pytest.mark.skipif(__import__("importlib").util.find_spec("numba") is None, reason="numba not installed")
def test_corrupted_numba_cache_is_recompiled_with_one_warning(tmp_path):
    """Before: a truncated, empty or garbage .nbi/.nbc made every Patch evaluation raise UnpicklingError or
    EOFError."""
    first = _run(tmp_path)
    assert first.returncode == 0, first.stderr
    files = sorted((tmp_path / "numba").rglob("*.nb[ic]"))
    assert files
    for k, path in enumerate(files):  # truncated, empty and garbage, each kind on several files
        data = path.read_bytes()
        path.write_bytes((data[:20], b"", bytes(range(7, 250)))[k % 3])
    second = _run(tmp_path)
    assert second.returncode == 0, second.stderr
    assert second.stdout == first.stdout
    assert second.stderr.count("CacheWarning") == 1 and "recompiled" in second.stderr
    third = _run(tmp_path)  # rewritten: no warning
    assert third.returncode == 0 and "CacheWarning" not in third.stderr and third.stdout == first.stdout


# --- item 5: the inputs answered wrongly before -----------------------------------------------------------------------

def _patch():
    from paper_repro.surfaces.patch import Patch

    return Patch(1, 1.0, np.arange(21.0).reshape(7, 3))


@pytest.mark.parametrize("direction", [(True, False, -1), ("0.5", 0, -0.5), ("1/2", 0, -0.5), (np.bool_(1), 0, -1)])
def test_derivative_direction_refuses_booleans_and_strings(direction):
    """Before: booleans and '0.5' were accepted as components ('1/2' was refused)."""
    with pytest.raises(TypeError, match="direction components must be real numbers"):
        _patch().derivative([[0.2, 0.3, 0.5]], direction)


def test_derivative_direction_still_takes_real_numbers():
    from fractions import Fraction

    p = _patch()
    a = p.derivative([[0.2, 0.3, 0.5]], (np.float64(0.5), Fraction(-1, 2), 0))
    b = p.derivative([[0.2, 0.3, 0.5]], (0.5, -0.5, 0.0))
    assert np.array_equal(a, b)


@pytest.mark.parametrize("t,exc,msg", [([float("nan")], ValueError, "t must be finite"),
                                       ([1j], TypeError, "t entries must be a real number"),
                                       (0.5 + 1j, TypeError, "t must be a real number"),
                                       (["0.5"], TypeError, "t entries must be"),
                                       ([0.5, 2.0], ValueError, r"\[0, alpha\]"), ([-0.1], ValueError, "alpha")])
def test_boundary_curve_checks_t(t, exc, msg):
    """Before: NaN gave NaN points, complex values raw float() errors."""
    with pytest.raises(exc, match=msg):
        _patch().boundary_curve("u=0", t)


def test_boundary_curve_in_range_unchanged():
    p = _patch()
    assert p.boundary_curve("u=0", [0.0, 0.5, 1.0]).shape == (3, 3)
    assert np.allclose(p.boundary_curve("u=0", [0.0])[0], p([[0.0, 1.0, 0.0]])[0])


def _alternating():
    state = {"k": 0}

    def surface(u, v, w):
        state["k"] += 1
        return [u, v] if state["k"] % 2 else [u]

    return surface


@pytest.mark.parametrize("arith,surface,exc,msg", [
    ("mp", lambda u, v, w: [u + 1j, v], TypeError, "surface coordinates .* complex"),
    ("mp", "alternating", ValueError, "surface returned .* same number"),
    ("mp", lambda u, v, w: ["a", v], TypeError, "surface coordinates .* string"),
    ("mp", lambda u, v, w: 3.0, TypeError, "surface must return a sequence of coordinates"),
    ("exact", lambda t: [float("nan"), t.sin(0, 1, 0)], ValueError, "surface coordinates .* finite"),
    ("exact", lambda t: ["1/2", t.sin(0, 1, 0)], TypeError, "surface coordinates .* string"),
    ("exact", lambda t: [1j, t.sin(0, 1, 0)], TypeError, "surface coordinates .* complex"),
])
def test_fit_checks_what_the_surface_returns(arith, surface, exc, msg):
    """Before: mpmath's and flint's own words (IndexError: matrix index out of range, cannot create mpf from 'a',
    expected a finite number), and '1/2' silently read as a rational."""
    from paper_repro.core.domain import rational_alpha
    from paper_repro.surfaces.fitting import fit

    if surface == "alternating":
        surface = _alternating()
    alpha = rational_alpha((1, 3)) if arith == "exact" else 1.0
    with pytest.raises(exc, match=msg):
        fit(surface, 1, alpha, arith)


@pytest.mark.parametrize("p", [4, 2**31 - 3, 9, 2**31 - 2])
def test_modp_refuses_composite_moduli(p):
    from paper_repro.core.context import get_context

    with pytest.raises(ValueError, match="composite"):
        get_context("modp", p=p)


def test_modp_takes_primes():
    from paper_repro.core.context import get_context

    assert get_context("modp", p=3).p == 3 and get_context("modp", p=2**31 - 1).p == 2**31 - 1


def test_raw_messages_replaced():
    """Before: 'need at least one array to concatenate', ''NoneType' object has no attribute 'strip'',
    'expected non-negative integer', 'unhashable type: 'list'', ''float' object is not iterable'."""
    from paper_repro.core.domain import RationalPoints, rational_alpha, sample_points
    from paper_repro.core.labels import full_system, parse_label, united_system
    from paper_repro.surfaces.patch import merge_meshes

    with pytest.raises(ValueError, match="meshes must be a non-empty list"):
        merge_meshes([])
    with pytest.raises(TypeError, match="label must be a string"):
        parse_label(None)
    with pytest.raises(ValueError, match="seed must be an integer >= 0"):
        sample_points(1.0, 5, seed=-1)
    with pytest.raises(TypeError, match="n must be a positive integer"):
        united_system([2])
    with pytest.raises(TypeError, match="n must be a positive integer"):
        full_system([2], "R")
    with pytest.raises(TypeError, match="tu must be a sequence of rationals"):
        RationalPoints(rational_alpha((1, 2)), 0.1, 0.1)


def test_sizes_over_budget_are_refused():
    """Before: sample_points(1.0, 10**8) needed 2.4 GB, `labels 1000` took 93 s."""
    from paper_repro.core.domain import sample_points
    from paper_repro.util.limits import MAX_N_LABELS, MAX_SAMPLE_POINTS

    with pytest.raises(ValueError, match="2 GB budget"):
        sample_points(1.0, 10**8)
    assert sample_points(1.0, 3).shape == (3, 3) and MAX_SAMPLE_POINTS < 10**8
    r = subprocess.run([sys.executable, "-m", "paper_repro", "labels", "1000"], capture_output=True, text=True,
                       timeout=60, cwd=ROOT)
    assert r.returncode == 2 and f"from 1 to {MAX_N_LABELS}" in r.stderr and not r.stdout


# --- item 4: float coefficients rounded from certified digits ---------------------------------------------------------

U53 = 2.0 ** -53  # the largest relative error of a correctly rounded float64


@pytest.mark.parametrize("n,alpha,dps", [(6, 1e-17, 450), (2, 1e-60, 450), (1, 1e-150, 700), (3, 1.0, 60),
                                         (4, 3.1415926, 80)])
def test_float_coefficients_are_correctly_rounded_at_float_alpha(n, alpha, dps):
    """Against the collocation solve in mpmath at ``dps`` digits (independent of the formula: a linear solve at
    alpha-independent points).  Before: 3.4e-13 relative (n = 6, 1e-17), 8e-14 (n = 2, 1e-60), 4.9e-14 (n = 1,
    1e-150): the division by s^(2n+j) went subnormal, or through exp(log)."""
    import mpmath

    from paper_repro.core.context import MpContext
    from paper_repro.core.normalization import orbit_coefficients, orbit_coefficients_collocation

    with mpmath.workdps(dps):
        ref = orbit_coefficients_collocation(n, mpmath.mpf(alpha), MpContext(dps=dps))
        got = orbit_coefficients(n, alpha)
        assert all(isinstance(g, float) for g in got)
        assert max(abs((g - r) / r) for g, r in zip(got, ref)) <= U53


@pytest.mark.parametrize("n,t", [(1, (999999, 1000000)), (2, (999, 1000)), (3, (1, 10**12)), (2, (1, 3))])
def test_float_coefficients_at_a_rational_angle_use_the_exact_angle(n, t):
    """Against the exact collocation solve (rationals, no formula), rounded once by Python: the same floats.
    Before: the float path computed at float(alpha), 2.3e-11 relative off at t = 999999/1000000."""
    from fractions import Fraction

    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import coefficients, exact_coefficients_cached, orbits

    alpha = rational_alpha(t)
    exact, _ = exact_coefficients_cached(n, alpha)
    got = coefficients(n, alpha)
    for (rep, _), x in zip(orbits(n), exact):
        assert got[rep.coefficient] == float(Fraction(int(x.p), int(x.q)))


def test_scaled_float_coefficients_are_certified_too():
    from fractions import Fraction

    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import coefficients

    alpha = rational_alpha((1, 10**9))
    ex = coefficients(3, alpha, "exact", scaled=True)
    got = coefficients(3, alpha, scaled=True)
    assert all(got[k] == float(Fraction(int(v.p), int(v.q))) for k, v in ex.items())


# ---------------------------------------------------------------- hostile pass of the public API (BAD.md)
# Each test below failed before its fix (checked by reverting the fix).

def test_parse_alpha_text_is_the_nearest_float():
    from fractions import Fraction

    import mpmath

    from paper_repro.util.validation import parse_alpha

    with mpmath.workdps(60):
        for text, exact in [("2pi/3", 2 * mpmath.pi / 3), ("2*pi/3", 2 * mpmath.pi / 3), ("π/3", mpmath.pi / 3),
                            ("0.7pi/3", mpmath.mpf("0.7") * mpmath.pi / 3), ("1.1/3", mpmath.mpf("1.1") / 3)]:
            got = parse_alpha(text)
            err = abs(mpmath.mpf(got) - exact)
            # no other float is closer: both neighbours are farther from the exact value
            assert err <= abs(mpmath.mpf(np.nextafter(got, 0)) - exact), text
            assert err <= abs(mpmath.mpf(np.nextafter(got, 4)) - exact), text
    assert parse_alpha("2pi/3") == 2.0943951023931957 and parse_alpha("π/3") == 1.0471975511965979
    assert parse_alpha("1/3") == float(Fraction(1, 3))


@pytest.mark.parametrize("text", ["5e-324", "1e-310", "1e-400"])
def test_parse_alpha_refuses_subnormal_text(text):
    from paper_repro.util.validation import parse_alpha

    with pytest.raises(ValueError, match=r"alpha must lie in \(0, pi\)|alpha must lie in the open interval"):
        parse_alpha(text)


def test_parse_alpha_does_not_echo_a_huge_text_and_huge_int_is_valueerror():
    from paper_repro.util.validation import parse_alpha

    with pytest.raises(ValueError, match="alpha") as info:
        parse_alpha("9" * 5000)
    assert len(str(info.value)) < 300
    with pytest.raises(ValueError, match=r"alpha must lie in the open interval \(0, pi\)"):
        parse_alpha(10**400)


def _fit_data():
    from paper_repro import sample_points

    pts = sample_points(1.0, 50)
    return pts, np.random.default_rng(0).normal(size=(50, 3))


@pytest.mark.parametrize("kwargs, kind, words", [
    (dict(corners=np.full((3, 3), np.nan)), ValueError, "corners must be a finite"),
    (dict(boundary={"u=0": lambda t: np.full((len(t), 3), np.nan)}), ValueError, r"boundary\['u=0'\].*finite"),
    (dict(corners="yes"), TypeError, "corners must be"),
    (dict(boundary={"u=0": lambda t: np.zeros(3)}), ValueError, r"curve\(t\) must return a \(9, 3\)"),
    (dict(boundary={"u=0": lambda t: np.zeros((3, len(t)))}), ValueError, r"boundary\['u=0'\]: curve\(t\)"),
    (dict(boundary={"u=0": 5}), TypeError, r"boundary\['u=0'\] must be a callable"),
    (dict(boundary=["u=0"]), TypeError, "boundary must be a dict"),
    (dict(full_output="y"), TypeError, "full_output must be True or False"),
])
def test_fit_least_squares_refuses_bad_corners_boundary_flags(kwargs, kind, words):
    from paper_repro.surfaces.fitting import fit_least_squares

    pts, vals = _fit_data()
    with pytest.raises(kind, match=words):
        fit_least_squares(pts, vals, 1, 1.0, **kwargs)


def test_fit_least_squares_refuses_numeric_strings_as_values():
    from paper_repro.surfaces.fitting import fit_least_squares

    pts, vals = _fit_data()
    with pytest.raises(TypeError, match="values must be real numbers"):
        fit_least_squares(pts, vals.astype(str), 1, 1.0)


def test_merge_meshes_refuses_mixing_normals_and_bad_faces():
    from paper_repro.surfaces.patch import merge_meshes

    v, f, n = np.eye(3), np.array([[0, 1, 2]]), np.ones((3, 3))
    assert len(merge_meshes([(v, f, n), (v, f, n)])) == 3
    with pytest.raises(ValueError, match="normals with every mesh or with none"):
        merge_meshes([(v, f, n), (v, f)])
    with pytest.raises(ValueError, match=r"meshes\[0\]: faces must index its vertices 0..2"):
        merge_meshes([(v, np.array([[0, 1, 7]]))])
    with pytest.raises(ValueError, match=r"meshes\[1\]: faces must index"):
        merge_meshes([(v, f), (v, np.array([[0, -1, 2]]))])
    with pytest.raises(ValueError, match=r"meshes\[1\]: vertices must be a finite \(V, 3\)"):
        merge_meshes([(v, f), (v[:, :2], f)])
    with pytest.raises(ValueError, match=r"meshes\[0\]: vertices must be a finite"):
        merge_meshes([(v * np.nan, f)])


def test_export_mesh_refuses_all_nan_or_infinite_normals(tmp_path):
    from paper_repro import export_mesh

    v, f = np.eye(3), np.array([[0, 1, 2]])
    with pytest.raises(ValueError, match="normals are NaN at every vertex"):
        export_mesh(tmp_path / "x.obj", v, f, np.full((3, 3), np.nan))
    with pytest.raises(ValueError, match="normals must be finite"):
        export_mesh(tmp_path / "x.ply", v, f, np.full((3, 3), np.inf))
    assert list(tmp_path.iterdir()) == []
    some = np.eye(3)
    some[0] = np.nan  # one vertex without a normal (a degenerate point): written as the zero vector
    text = export_mesh(tmp_path / "y.obj", v, f, some).read_text()
    assert "nan" not in text.lower() and "vn 0.0 0.0 0.0" in text


@pytest.mark.parametrize("call, kind, words", [
    (lambda m: m.torus_pieces(1.0, np.nan, 1.0, [0.0], [0.0]), ValueError, "rho must be a finite"),
    (lambda m: m.torus_pieces(1.0, 3.0, np.inf, [0.0], [0.0]), ValueError, "mu must be a finite"),
    (lambda m: m.torus_pieces(1.0, 3.0, 1.0, "a", [0.0]), TypeError, "phis must be a sequence"),
    (lambda m: m.torus_pieces(1.0, 3.0, 1.0, [0.0], [np.nan]), ValueError, "psis entries must be a finite"),
    (lambda m: m.cyclide_pieces(1.0, dict(a=6, c=2, mu=3), [0.0], [0.0]), TypeError, "params must be a dict with"),
    (lambda m: m.cyclide_pieces(1.0, [6, 4, 2, 3], [0.0], [0.0]), TypeError, "params must be a dict with"),
    (lambda m: m.cyclide_pieces(1.0, dict(a=6, b="4", c=2, mu=3), [0.0], [0.0]), TypeError, r"params\['b'\]"),
    (lambda m: m.model_gap([], 1.0), ValueError, "pieces must be a non-empty list"),
])
def test_models_refuse_bad_parameters_naming_them(call, kind, words):
    from paper_repro.surfaces import models

    with pytest.raises(kind, match=words):
        call(models)


def test_join_error_refuses_to_report_an_unmeasured_join_as_perfect():
    from paper_repro.surfaces.models import model_gap, torus_pieces

    pieces = torus_pieces(1.0, 3.0, 1.0, [0.0], [0.0])
    assert 0 <= model_gap(pieces, 1.0) < 1e-13  # the two triangles of one square meet on the diagonal
    with pytest.raises(ValueError, match="samples must be an integer from 2"):
        model_gap(pieces, 1.0, samples=0)
    with pytest.raises(ValueError, match="no join was measured"):
        model_gap(pieces[:1], 1.0)


def test_labelled_net_survives_pickle_and_copy():
    import copy
    import pickle

    from paper_repro.core.nets import LabelledNet

    net = LabelledNet(np.arange(57.0).reshape(19, 3), 2)
    for back in (pickle.loads(pickle.dumps(net)), pickle.loads(pickle.dumps(net, protocol=5)), copy.deepcopy(net),
                 copy.copy(net)):
        assert isinstance(back, LabelledNet) and back.n == 2
        assert np.array_equal(back, net) and back["r_{4,3,1}"].tolist() == net["r_{4,3,1}"].tolist()
    assert np.array_equal(pickle.loads(pickle.dumps(net.T)), net.T)  # a reshaped view pickles as an array


def test_patch_mesh_requires_bool_normals_and_works_for_an_exact_patch():
    import paper_repro as pr
    from paper_repro.core.domain import rational_alpha

    net = np.random.default_rng(0).normal(size=(7, 3))
    for bad in (1, "yes"):
        with pytest.raises(TypeError, match="normals must be True or False"):
            pr.Patch(1, 1.0, net).mesh(4, normals=bad)
    a = rational_alpha((1, 3))
    exact = pr.Patch(1, a, net, arith="exact").mesh(2)
    plain = pr.Patch(1, a, net).mesh(2)
    assert exact[0].dtype == np.float64 and np.array_equal(exact[0], plain[0]) and np.array_equal(exact[1], plain[1])


def test_sample_points_flags_and_seeds_are_checked():
    import paper_repro as pr
    from paper_repro.core.domain import rational_alpha, sample_rational_points

    with pytest.raises(TypeError, match="interior must be True or False"):
        pr.sample_points(1.0, 3, interior="no")
    a = rational_alpha((1, 2))
    with pytest.raises(ValueError, match="seed must be an integer >= 0"):
        sample_rational_points(a, 3, seed=-2)
    with pytest.raises(TypeError, match="max_denominator must be an integer >= 1"):
        sample_rational_points(a, 3, max_denominator=10.5)
    with pytest.raises(ValueError, match="max_denominator must be an integer >= 1"):
        sample_rational_points(a, 3, max_denominator=0)
