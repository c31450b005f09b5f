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
from paper_repro.core.labels import delta
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


@pytest.mark.parametrize("rechecksum", [False, True])
@pytest.mark.parametrize("change", [_drop_row, _nan_row, lambda v: []], ids=["missing-row", "nan-row", "empty"])
def test_bad_elevation_entry_is_recomputed_with_one_warning(fresh_cache, change, rechecksum):
    """Before: a row missing gave a (delta_{n+1} - 1, 3) net silently, NaN rows a NaN net, ``[]`` an error."""
    n = 2
    net = np.random.default_rng(0).random((delta(n), 3))
    good = el.elevate(net, n, 1.0)
    path = _elevation_entry(fresh_cache)
    _tamper(path, change, rechecksum)
    el._elevation_matrix_float.cache_clear()
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        again = el.elevate(net, n, 1.0)
    assert again.shape == (delta(n + 1), 3) and np.array_equal(again, good)
    assert len(_cache_warnings(rec)) == 1 and "recomputed and rewritten" in _cache_warnings(rec)[0]
    el._elevation_matrix_float.cache_clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error", cache.CacheWarning)  # rewritten: read back without a warning
        assert np.array_equal(el.elevate(net, n, 1.0), good)


@pytest.mark.parametrize("text", ["[]", "", "{", "null", '{"name": "elevation_matrix"}'])
def test_unparsable_entry_is_recomputed(fresh_cache, text):
    """Before: a file holding ``[]`` raised AttributeError ('list' object has no attribute 'get')."""
    n = 1
    good = el.elevation_matrix(n, 0.5)
    _elevation_entry(fresh_cache).write_text(text)
    el._elevation_matrix_float.cache_clear()
    with pytest.warns(cache.CacheWarning, match="recomputed"):
        assert np.array_equal(el.elevation_matrix(n, 0.5), good)


def test_entry_of_other_parameters_is_not_used(fresh_cache):
    """An entry whose stored parameters are not those of its key (a copied file) is recomputed."""
    a = cache.cached("t", {"k": 1}, lambda: {"x": 1})
    b = cache.cached("t", {"k": 2}, lambda: {"x": 2})
    p1 = fresh_cache / "t" / f"{cache.key('t', {'k': 1})}.json"
    p2 = fresh_cache / "t" / f"{cache.key('t', {'k': 2})}.json"
    shutil.copy(p2, p1)
    with pytest.warns(cache.CacheWarning, match="parameters"):
        assert cache.cached("t", {"k": 1}, lambda: {"x": 1}) == a != b


def test_validators_of_every_cached_user(fresh_cache):
    """Each ``cached(...)`` user validates its values: a consistent entry of the wrong shape is recomputed."""
    from paper_repro.core.domain import rational_alpha
    from paper_repro.core.normalization import exact_coefficients_cached
    from paper_repro.theory.closed_forms import closed_forms_cached, proof_cached

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
    """Before: ``PAPER_REPRO_CACHE`` naming a file gave a raw NotADirectoryError from elevation_matrix."""
    afile = tmp_path / "afile"
    afile.write_text("x")
    monkeypatch.setattr(cache, "CACHE_DIR", afile)
    monkeypatch.delenv(cache.NO_CACHE_ENV, raising=False)
    monkeypatch.setattr(cache, "_WARNED_UNUSABLE", set())
    el._elevation_matrix_float.cache_clear()
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        e = el.elevation_matrix(1, 0.7)
        el._elevation_matrix_float.cache_clear()
        assert np.array_equal(el.elevation_matrix(1, 0.7), e)
    el._elevation_matrix_float.cache_clear()
    assert e.shape == (delta(2), delta(1))
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
