"""Figure regression: a figure cannot change unnoticed.

``figures/manifest.json`` records the SHA-256 of every figure file (PNG and SVG).  Here (1) every file on disk
has the hash the manifest records, so a figure changed without regenerating the manifest and gallery fails;
(2) the figures are regenerated into a temporary directory and must come out byte for byte as recorded, so
a code change that alters a figure fails until the figures are regenerated (``make figures``) and the new
bytes committed -- and the figures are byte-stable.  The cheapest figure is regenerated in the fast suite,
every figure in the slow one (`make test-all`, `make report`).
"""

import hashlib
import json
import re

import pytest

from paper_repro.app.report import _data_fingerprint, _up_to_date, figure_files
from paper_repro.app.test_report import reuse_certified_results
from paper_repro.util.cache import code_fingerprint
from paper_repro.util.io import FIGURES, ROOT
from paper_repro.util.registry import FIGURES as REGISTRY
from paper_repro.util.registry import load_all

load_all()
MANIFEST = {m["id"]: m for m in json.loads((FIGURES / "manifest.json").read_text())}
#: The figure regenerated in the fast suite (the cheapest); every other one is regenerated in the slow suite.
FAST = {"oriented_graph"}


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _unlocked_drawing_stack() -> str:
    """The packages that draw or compute the figures whose installed version is not requirements.lock's."""
    from importlib.metadata import version

    lock = (ROOT / "requirements.lock").read_text()
    off = []
    for pkg in ("matplotlib", "numpy"):
        m = re.search(rf"^{pkg}==([^\s]+)", lock, flags=re.M)
        if m and version(pkg) != m.group(1):
            off.append(f"{pkg} {version(pkg)} installed, {m.group(1)} locked")
    return "; ".join(off)


def test_manifest_lists_every_registered_figure():
    assert set(MANIFEST) == set(REGISTRY)


@pytest.mark.parametrize("fid", sorted(REGISTRY))
def test_files_on_disk_are_those_of_the_manifest(fid):
    recorded = {f["path"]: f["sha256"] for f in MANIFEST[fid]["files"]}
    files = figure_files(REGISTRY[fid])
    assert len(recorded) == len(files) == 2 * len(REGISTRY[fid].outputs)
    for path in files:
        rel = path.relative_to(ROOT).as_posix()
        assert _sha(path.read_bytes()) == recorded[rel], f"{rel} differs from figures/manifest.json: run make figures"


@pytest.mark.parametrize("fid", [f if f in FAST else pytest.param(f, marks=pytest.mark.slow)
                                 for f in sorted(REGISTRY)])
def test_regenerated_figure_has_the_recorded_bytes(fid, tmp_path, record_property):
    off = _unlocked_drawing_stack()
    if off:
        pytest.skip(f"figures are byte-identical only with the locked drawing stack: {off} (e.g. make test-min)")
    if reuse_certified_results() and _up_to_date(fid, _data_fingerprint()):
        # make report: make reproduce drew this figure with this code (same code fingerprint) from this data/, and
        # the files on disk are what it drew; test_files_on_disk_are_those_of_the_manifest checks them
        record_property("reused", f"drawn by make reproduce with code {code_fingerprint()}")
        return
    fig = REGISTRY[fid]
    fig.func(tmp_path)
    recorded = {f["path"].rsplit("/", 1)[-1]: f["sha256"] for f in MANIFEST[fid]["files"]}
    for name, sha in recorded.items():
        assert _sha((tmp_path / name).read_bytes()) == sha, (
            f"figure {fid}: {name} regenerated differs from figures/manifest.json (the code changed the figure: "
            "run make figures and commit the figures, or find what made it non-deterministic)")


def test_the_comparison_can_fail(tmp_path):
    fid = "oriented_graph"
    png = tmp_path / REGISTRY[fid].outputs[0]
    png.write_bytes((FIGURES / png.name).read_bytes() + b"\0")  # one byte more
    recorded = {f["path"].rsplit("/", 1)[-1]: f["sha256"] for f in MANIFEST[fid]["files"]}
    assert _sha(png.read_bytes()) != recorded[png.name]
