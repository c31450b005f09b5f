import json
import re
import subprocess
import sys

import pytest

from paper_repro.app.gallery import gallery_html
from paper_repro.util.io import atomic_path, write_json


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "paper_repro", *args], capture_output=True, text=True)


def test_cli_claims_only_partial_run():
    r = _cli("claims", "--only", "dimension", "--n", "4")
    assert r.returncode == 0, r.stderr
    assert "dimension" in r.stdout and "PASS" in r.stdout


@pytest.mark.parametrize("args,msg", [(("claims", "--n", "0"), "--n must be a positive integer"),
                                      (("claims", "--alpha", "4"), "alpha must lie"),
                                      (("claims", "--only", "nope"), "unknown claim")])
def test_cli_bad_input(args, msg):
    r = _cli(*args)
    assert r.returncode == 2 and msg in r.stderr


def test_cli_labels():
    r = _cli("labels", "1")
    assert r.returncode == 0 and "R_{2,1,1}" in r.stdout


def test_atomic_write_leaves_nothing_on_error(tmp_path):
    target = tmp_path / "x.json"
    with pytest.raises(RuntimeError):
        with atomic_path(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("boom")
    assert not target.exists() and list(tmp_path.iterdir()) == []
    write_json(target, {"a": 1})
    assert json.loads(target.read_text()) == {"a": 1}


def test_gallery_is_offline_and_renders_math():
    page = gallery_html([{"id": "x", "caption": "coefficients r_{4,3,1}^alpha versus alpha", "paper_label": None,
                          "paper_number": None, "claims": [], "generator": "m:f", "parameters": {},
                          "command": "python -m paper_repro figures --only x",
                          "files": [{"path": "figures/x.png", "sha256": "0" * 64}], "outputs": ["figures/x.png"]}])
    external = re.findall(r"""(?:src|href)=["'](?:https?:)?//""", page)
    assert not external, external
    assert "<math" in page and "r_{4,3,1}" not in page.split("<h2 id=\"figures\">")[1].split("</figure>")[0]
    assert "vendor/plotly.min.js" in page
