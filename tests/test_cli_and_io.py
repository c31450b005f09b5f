import json
import os
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


# --- issue 31, item 3: the CLI refuses before it works --------------------------------------------------------------

def _no_work(monkeypatch):
    """Make any computation an error: the refusal must come before it."""
    from paper_repro.app import report

    def boom(*a, **k):
        raise AssertionError("computation started before the refusal")

    monkeypatch.setattr(report, "run_claims", boom)
    monkeypatch.setattr(report, "make_figures", boom)


@pytest.mark.parametrize("env,args,msg", [
    ({"PAPER_REPRO_KERNEL": "bogus"}, ("claims", "--only", "dimension", "--n", "2"), "PAPER_REPRO_KERNEL"),
    ({"PAPER_REPRO_THREADS": "abc"}, ("claims", "--only", "dimension", "--n", "2"), "PAPER_REPRO_THREADS"),
    ({"PAPER_REPRO_THREADS": "0"}, ("figures", "--only", "oriented_graph"), "PAPER_REPRO_THREADS"),
    ({}, ("claims", "--out", ""), "--out must name a folder"),
    ({}, ("figures", "--out", "{afile}"), "is a file, not a folder"),
    ({}, ("reproduce", "--out", "{afile}"), "is a file, not a folder"),
    ({"PAPER_REPRO_CACHE": "{afile}"}, ("claims", "--only", "dimension", "--n", "2"), "cache folder cannot be written"),
])
def test_cli_refuses_bad_environment_before_work(tmp_path, monkeypatch, capsys, env, args, msg):
    """Before: claims reported FAIL (exit 1), figures --out <file> printed a traceback, --out "" wrote into the
    clone."""
    from paper_repro.app.cli import main
    from paper_repro.util import cache

    afile = tmp_path / "afile"
    afile.write_text("x")
    monkeypatch.setattr(cache, "CACHE_DIR", None)
    monkeypatch.delenv("PAPER_REPRO_NO_CACHE", raising=False)
    monkeypatch.delenv("PAPER_REPRO_OUT", raising=False)
    for k, v in env.items():
        monkeypatch.setenv(k, v.format(afile=afile))
    _no_work(monkeypatch)
    assert main([a.format(afile=afile) for a in args]) == 2
    err = capsys.readouterr().err.strip()
    assert msg in err and len(err.splitlines()) == 1


def test_cli_refuses_readonly_out_and_cache(tmp_path):
    """Before: claims --out <read-only> computed for over 600 s, then failed; a read-only cache made claims FAIL."""
    import os
    import shutil

    if os.geteuid() == 0 and shutil.which("unshare") is None:
        pytest.skip("root without unshare: no folder is read-only")
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    pre = ["unshare", "--user"] if os.geteuid() == 0 else []
    env = {**os.environ, "PAPER_REPRO_CACHE": str(tmp_path / "cache")}
    env.pop("PAPER_REPRO_NO_CACHE", None)
    r = subprocess.run([*pre, sys.executable, "-m", "paper_repro", "claims", "--out", str(ro)], capture_output=True,
                       text=True, env=env, timeout=120)
    assert r.returncode == 2 and "--out: cannot write there: Permission denied" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "claims" not in r.stdout
    env["PAPER_REPRO_CACHE"] = str(ro)
    r = subprocess.run([*pre, sys.executable, "-m", "paper_repro", "claims", "--only", "dimension", "--n", "2"],
                       capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 2 and "cache folder cannot be written" in r.stderr, r.stderr


@pytest.mark.parametrize("alpha", ["1e-300", "1e-17", "3.14159265358"])
def test_cli_refuses_alpha_outside_a_claims_measured_range(monkeypatch, capsys, alpha):
    """Before: claims --only linear_independence --alpha 1e-300 (or 1e-17) --n 2 reported FAIL for a true claim."""
    from paper_repro.app.cli import main

    _no_work(monkeypatch)
    assert main(["claims", "--only", "linear_independence", "--alpha", alpha, "--n", "2"]) == 2
    err = capsys.readouterr().err
    assert "linear_independence" in err and "[1e-06, 3.1415926]" in err


def test_alpha_range_declared_in_registration():
    from paper_repro.util.registry import ALPHA_RANGES, CLAIMS, check_cli_range, load_all

    load_all()
    assert ALPHA_RANGES["linear_independence"][:2] == (1e-6, 3.1415926)
    check_cli_range(CLAIMS["linear_independence"], 2, 0.5)  # inside: accepted


# --- issue 33, item 6: output a person reads -------------------------------------------------------------------
def test_progress_off_a_terminal_is_one_line_per_loop(capsys):
    """About 100 `rank mod p t=1/3 n k/20: k` lines filled a `make reproduce` log: now one line per loop."""
    from paper_repro.util.progress import progress
    from paper_repro.util.sweep import sweep

    assert list(progress(range(20), "rank mod p")) == list(range(20))
    assert sweep(abs, [-3, 1, -2], workers=1, desc="claims") == [3, 1, 2]
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 2 and err[0].startswith("rank mod p: 20 of 20 done in ")
    assert err[1].startswith("claims: 3 of 3 done in "), err


def test_linear_independence_shows_one_bar_for_the_claim(monkeypatch, capsys):
    """Its ranks (now tasks per (n, alpha) and per (t, n) of the sweep) run under the sweep's one bar, not one line
    per order."""
    from paper_repro.app import report
    from paper_repro.util import cache
    from paper_repro.util.registry import load_all

    load_all()
    monkeypatch.setenv(cache.NO_CACHE_ENV, "1")
    monkeypatch.setenv("PAPER_REPRO_WORKERS", "1")
    small = {"ns": [1, 2], "alphas": ["pi/2"], "dps": 30, "svd_n_max": 2, "exact_ns": [1, 2, 3],
             "rational_ts": ["1/3", "1/7"]}
    assert report.run_claims(["linear_independence"], {"linear_independence": small}, write=False)
    bars = [line for line in capsys.readouterr().err.splitlines() if " done in " in line]
    assert len(bars) == 1 and bars[0].startswith("tasks, round 1: 10 of 10 done in "), bars


def test_reproduce_ends_with_a_summary_line(tmp_path, monkeypatch, capsys):
    """`make reproduce` ended with the annotated paper's raw JSON dict; now a sentence: claims passed, errata,
    files written, time."""
    from paper_repro.app import annotated_paper, cli, report
    from paper_repro.util import io

    def fake_claims(*a, **k):
        io.write_text(io.data_dir() / "claims.md", "x")
        return report.ClaimsRun(28, ("torus_exact",), 32)

    monkeypatch.setattr(report, "run_claims", fake_claims)
    monkeypatch.setattr(report, "make_figures", lambda only: io.write_text(io.figures_dir() / "a.svg", "<svg/>"))
    monkeypatch.setattr(annotated_paper, "write_paper", lambda: None)
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "old.json").write_text("{}")  # written before the run: not counted
    monkeypatch.setenv(io.OUT_ENV, str(tmp_path))  # --out sets it for good: restored after the test
    code = cli.main(["reproduce", "--out", str(tmp_path)])
    last = capsys.readouterr().out.strip().splitlines()[-1]
    assert code == 1
    assert re.fullmatch(r"reproduce: 28 of 29 claims passed \(failed: torus_exact\), 32 errata of the paper "
                        r"recorded, 2 files written, [0-9.]+ s\.", last), last


def test_the_annotated_paper_says_a_sentence_not_a_dict():
    from paper_repro.app.annotated_paper import paper_line

    line = paper_line("paper/index.html", {"badges": {"checked": 1, "erratum": 2, "excused": 0,
                                                      "not yet checked": 0}, "displays": 3, "math": 4,
                                           "math_fallback": 0, "unplaced_entries": 0, "unplaced_errata": 0})
    assert "{" not in line and line.endswith(".") and "2 errata" in line


def test_cli_reader_going_away_is_a_quiet_exit(tmp_path):
    """`python -m paper_repro labels 200 | head -1` printed a BrokenPipeError traceback (exit 1): now no traceback
    and exit 141 (128 + SIGPIPE, as a shell reports for a Unix tool).  labels 200 prints about 8 MB, far more than
    a pipe holds, so the writer is blocked when the reader closes."""
    env = {**os.environ, "PAPER_REPRO_CACHE": str(tmp_path / "cache")}
    proc = subprocess.Popen([sys.executable, "-m", "paper_repro", "labels", "200"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env)
    assert proc.stdout.readline().split()[1] == b"R_{400,200,200}"
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 141
    assert "Traceback" not in err and "BrokenPipe" not in err, err


@pytest.mark.parametrize("cmd", ["claims", "figures", "reproduce"])
def test_out_with_a_too_long_name_is_one_line_and_exit_2(cmd, tmp_path, capsys):
    from paper_repro.app import cli

    assert cli.main([cmd, "--out", str(tmp_path / ("a" * 300))]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: --out: cannot write there: File name too long"), err
