"""The claims' tasks on a dask.distributed cluster (issue 32): a LocalCluster of 2 worker processes gives the same
bytes as the process pool, a killed worker changes nothing, Ctrl-C cancels the pending tasks, and a cluster with
other versions is refused before any work.  dask and distributed are in requirements.lock: nothing is skipped."""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import distributed
import pytest

from paper_repro.app import cluster, report
from paper_repro.util import cache
from paper_repro.util.io import set_output_root
from paper_repro.util.registry import CLAIMS, load_all
from paper_repro.util.sweep import sweep
from paper_repro.util.tasks import Task, drive, drive_inline, timed

#: Each heavy claim at small n (a few seconds of work in all).
SMALL = {"nonnegativity_extended": {"n_min": 1, "n_max": 4, "publish_n_max": 4, "table_n_max": 2},
         "normalizing_closed_forms": {"ts": ["1/2", "1/3", "2/5"], "level_n_max": 3, "proof_n_max": 4},
         "limit_formula": {"closed_form_n_max": 4, "checks_n_max": 6},
         "general_formulas": {"max_level": 3, "n_max": 9, "n_cons": 12}}


@pytest.fixture(scope="module")
def client():
    """Two worker processes, no cache anywhere (the workers inherit the environment when they start)."""
    old = os.environ.get(cache.NO_CACHE_ENV)
    os.environ[cache.NO_CACHE_ENV] = "1"
    import logging

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=logging.CRITICAL) as lc, distributed.Client(lc) as c:
        c.wait_for_workers(2, timeout="60s")
        yield c
    if old is None:
        os.environ.pop(cache.NO_CACHE_ENV, None)
    else:
        os.environ[cache.NO_CACHE_ENV] = old


def _data_bytes(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted((root / "data").rglob("*")) if p.is_file()}


def _run(out: Path, executor=None) -> dict[str, bytes]:
    load_all()
    set_output_root(out)
    try:
        assert report.run_claims(list(SMALL), SMALL, extended=True, write=True, executor=executor)
    finally:
        set_output_root(None)
    return _data_bytes(out)


def test_local_cluster_gives_the_bytes_of_the_process_pool(client, tmp_path, monkeypatch):
    monkeypatch.setenv(cache.NO_CACHE_ENV, "1")
    monkeypatch.setenv("PAPER_REPRO_WORKERS", "2")
    procs = _run(tmp_path / "processes")
    dask = _run(tmp_path / "dask", client.get_executor())
    assert set(procs) == {"data/claims_extended.json", "data/claims_extended.md",
                          "data/normalization/closed_forms_extended.json",
                          "data/normalization/general_formulas_extended.json",
                          "data/normalization/general_formulas_extended.md"}
    assert dask == procs
    claims = json.loads(procs["data/claims_extended.json"])
    assert [c["id"] for c in claims] == [c for c in CLAIMS if c in SMALL]
    assert all(c["status"] == "pass" for c in claims)
    # and the outcome equals the claims run inline, one task after the other
    for c in claims:
        inline = CLAIMS[c["id"]].func(**{**CLAIMS[c["id"]].defaults, **(CLAIMS[c["id"]].extended or {}),
                                         **SMALL[c["id"]]})
        assert inline.measured == c["measured"], c["id"]


def _die_once(marker: str, value: int) -> int:
    """Kill this worker process the first time (SIGKILL: no clean-up), answer the second time."""
    if not os.path.exists(marker):
        Path(marker).write_text("killed once")
        os.kill(os.getpid(), signal.SIGKILL)
    return value * value


def test_a_killed_worker_changes_nothing(client, tmp_path):
    """The scheduler gives the task of a dead worker to another one (the nanny restarts the dead one)."""
    from paper_repro.theory.closed_forms import record

    tasks = [Task(record, (n,)) for n in (1, 2, 3)] + [Task(_die_once, (str(tmp_path / "marker"), 7))]
    got = [r for r, _, _ in sweep(timed, tasks, executor=client.get_executor())]
    assert (tmp_path / "marker").exists()  # a worker was killed
    assert got == [t() for t in tasks[:3]] + [49]


def _slow(x: int) -> int:
    time.sleep(1.5)
    return x


def test_interrupt_cancels_the_clusters_pending_tasks(client):
    def stop(item):  # the first finished task: Ctrl-C lands while the others are pending
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweep(_slow, list(range(12)), executor=client.get_executor(), desc="x", label=stop)
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)):
        time.sleep(0.2)
    assert client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)) == 0


def test_workers_with_other_versions_are_refused_before_any_work(client):
    client.wait_for_workers(2, timeout="60s")  # the worker killed above is back
    expected = cluster.expected_versions()
    assert cluster.check_workers(client, "local:2", expected) == 2
    with pytest.raises(cluster.ClusterMismatch, match=r"has numpy .* \(here 0\.0\)") as err:
        cluster.check_workers(client, "local:2", dict(expected, numpy="0.0"))
    assert len(str(err.value).splitlines()) == 1 and "2 of 2 workers differ" in str(err.value)
    with pytest.raises(cluster.ClusterMismatch, match="package source sha256"):
        cluster.check_workers(client, "local:2", dict(expected, code="0" * 16))
    assert client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)) == 0


def test_the_lock_pins_what_the_workers_run(client):
    expected = cluster.expected_versions()
    lock = (Path(__file__).parents[1] / "requirements.lock").read_text()
    assert f"numpy=={expected['numpy']} " in lock and f"python-flint=={expected['python-flint']} " in lock


@pytest.mark.parametrize("value", ["local:0", "local:", "local:9999", "tcp://", "tcp://host", "tcp://h:70000",
                                   "http://h:8786", "h:8786", ""])
def test_bad_scheduler_values_are_one_line_and_exit_2(value, capsys, monkeypatch):
    from paper_repro.app import cli

    monkeypatch.delenv(cluster.SCHEDULER_ENV, raising=False)
    assert cli.main(["claims", "--only", "dimension", "--scheduler", value]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: --scheduler:") and repr(value) in err, err


def test_the_environment_variable_is_validated_too(capsys, monkeypatch):
    from paper_repro.app import cli

    monkeypatch.setenv(cluster.SCHEDULER_ENV, "local:two")
    assert cli.main(["reproduce"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "PAPER_REPRO_SCHEDULER" in err and "'local:two'" in err
    monkeypatch.setenv(cluster.SCHEDULER_ENV, "local:1")
    assert cli.main(["claims", "--n-max", "1000"]) == 2  # --n-max too, before any cluster starts
    assert "--n-max: an integer from 2 to 200" in capsys.readouterr().err


def test_ctrl_c_on_a_local_cluster_exits_130():
    env = dict(os.environ, PAPER_REPRO_NO_CACHE="1", PAPER_REPRO_SCHEDULER="local:2")
    p = subprocess.Popen([sys.executable, "-m", "paper_repro", "claims", "--only", "limit_formula", "--extended"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, start_new_session=True)
    deadline = time.monotonic() + 90
    seen = ""
    while time.monotonic() < deadline and "versions checked" not in seen:
        line = p.stdout.readline()
        if not line:
            break
        seen += line
    assert "versions checked" in seen, seen + p.stderr.read()
    time.sleep(1.0)  # tasks are running now (the extended lemmas take minutes)
    t0 = time.perf_counter()
    os.killpg(p.pid, signal.SIGINT)
    _, err = p.communicate(timeout=30)
    assert p.returncode == 130, err
    assert "interrupted (Ctrl-C)" in err and time.perf_counter() - t0 < 10


def test_split_claims_give_the_same_outcome_inline_and_driven_together():
    """Driving several claims in one flat batch per round (equal tasks computed once) gives what each gives alone."""
    load_all()
    calls = []

    def runner(batch):
        calls.append(len(batch))
        return [t() for t in reversed(batch)][::-1]

    together = drive({cid: CLAIMS[cid].body(**{**CLAIMS[cid].defaults, **p}) for cid, p in SMALL.items()
                      if cid != "general_formulas"}, runner)
    for cid, out in together.items():
        alone = drive_inline(CLAIMS[cid].body(**{**CLAIMS[cid].defaults, **SMALL[cid]}))
        assert out == alone, cid
    # the closed forms of order 1..4 are asked by three claims but computed once per round
    assert calls[0] < sum(len(CLAIMS[c].body(**{**CLAIMS[c].defaults, **SMALL[c]}).send(None))
                          for c in together)


def test_the_proof_in_chunks_is_the_proof_in_one_piece(monkeypatch):
    """records(): the identity proof split into certificate and residual-chunk tasks gives the dict prove() gives."""
    from paper_repro.theory import closed_forms as cf

    monkeypatch.setenv(cache.NO_CACHE_ENV, "1")
    monkeypatch.setattr(cf, "PROOF_CHUNK", 7)
    (_, recs) = drive_inline(_returning(cf.records([6, 9])))
    for rec in recs:
        whole = {k: v for k, v in cf.prove(rec["n"], cf.closed_forms_cached(rec["n"])).items() if k in cf.PROOF_KEYS}
        assert rec["proof"] == json.loads(json.dumps(whole)) and rec["proof"]["proved"]
        assert list(rec["proof"]) == list(cf.PROOF_KEYS)


def _returning(gen):
    return (yield from gen)


def test_n_max_estimate_comes_from_the_cost_model_before_any_work(tmp_path, monkeypatch):
    """--n-max: the first round's tasks are known without computing anything; their cost is predicted from the
    measured costs (here a fabricated file: the prediction is the fitted power law)."""
    load_all()
    set_output_root(tmp_path)
    try:
        (tmp_path / "build").mkdir()
        costs = {f"closed_forms.recovered({n})": {"name": "closed_forms.recovered", "n": n, "cpu": n ** 3 / 1000,
                                                  "wall": 1.0} for n in (5, 10, 20)}
        (tmp_path / "build" / "task_costs_extended.json").write_text(json.dumps(costs))
        est = report.estimate_cpu(report.n_max_overrides(40))
    finally:
        set_output_root(None)
    assert est["longest"][1].startswith(("closed_forms.recovered(40)", "general_formulas.centre_end_values"))
    assert est["measured_tasks"] == 3 and est["tasks"] > 100
    from paper_repro.app.costs import CostModel

    set_output_root(tmp_path)
    try:
        assert abs(CostModel(True).predict(Task(cf_recovered, (40,))) - 64.0) < 1e-6
    finally:
        set_output_root(None)


def cf_recovered(n):  # stands for closed_forms.recovered in the cost model's eyes
    raise AssertionError("never called")


cf_recovered.__module__ = "paper_repro.theory.closed_forms"
cf_recovered.__name__ = "recovered"


def test_extended_run_in_a_fresh_folder_draws_no_figure_and_says_so(tmp_path, capsys):
    """`reproduce --extended --out FRESH` used to crash in the figures step (the figures read data/claims.json,
    which only the non-extended run writes).  An extended run now redraws no figure: in a fresh folder it says so in
    one line and writes nothing there; beside a non-extended run's output it refreshes the manifest and gallery."""
    load_all()
    set_output_root(tmp_path)
    try:
        assert report.refresh_gallery() is False
        assert not (tmp_path / "figures").exists()
        out = capsys.readouterr().out.strip().splitlines()
        assert len(out) == 1 and "without --extended" in out[0]
        (tmp_path / "data").mkdir()
        (tmp_path / "data" / "claims.json").write_text("[]")
        (tmp_path / "figures").mkdir()
        (tmp_path / "figures" / "manifest.json").write_text("[]")
        assert report.refresh_gallery() is True
        assert (tmp_path / "figures" / "index.html").exists()
        assert len(json.loads((tmp_path / "figures" / "manifest.json").read_text())) == len(report.FIGURE_REGISTRY)
    finally:
        set_output_root(None)


def test_an_extended_run_leaves_the_standard_line_table_alone(tmp_path, monkeypatch):
    """data/paper_lines.json quotes the statements of the checking claims, which name the run's ranges: an extended
    run used to rewrite the standard table with its own ranges (a dirty tree after `make reproduce-extended`)."""
    import dataclasses

    from paper_repro.util.registry import CLAIMS, Outcome

    load_all()
    # the mechanism under test is the writing of the standard-run-only table, not the line checks: a stand-in body
    # that publishes the same data file (the cache is off, so nothing computed here is stored under the real key)
    monkeypatch.setenv("PAPER_REPRO_NO_CACHE", "1")
    real = CLAIMS["every_line"]

    def body(claim_results=None, prepared=None):
        from paper_repro.claims.every_line import coverage

        cov = coverage([])
        return Outcome(True, {"coverage": cov}, data={"paper_lines.json": {"coverage": cov, "lines": []}})

    monkeypatch.setitem(CLAIMS, "every_line", dataclasses.replace(real, func=body, prepare=None))
    set_output_root(tmp_path)
    try:
        report.run_claims(["every_line"], None, extended=True, write=True)
        assert (tmp_path / "data" / "claims_extended.json").exists()
        assert not (tmp_path / "data" / "paper_lines.json").exists()
        report.run_claims(["every_line"], None, extended=False, write=True)
        assert (tmp_path / "data" / "paper_lines.json").exists()
    finally:
        set_output_root(None)


def test_the_runner_asks_for_fresh_workers_before_every_round_but_the_first(tmp_path):
    """A cluster's workers are restarted between rounds, as the local process pool is new every round (a worker
    process that ran the first round computed the second round's proofs 2.7 times slower, measured)."""
    from concurrent.futures import ThreadPoolExecutor

    calls = []
    with ThreadPoolExecutor(2) as ex:
        ex.fresh_workers = lambda: calls.append(1)
        set_output_root(tmp_path)
        try:
            runner = report.TaskRunner(True, ex)
            assert runner([Task(pow, (2, 3))]) == [8] and calls == []
            assert runner([Task(pow, (3, 2)), Task(pow, (2, 2))]) == [9, 4] and calls == [1]
            assert runner([Task(pow, (1, 1))]) == [1] and calls == [1, 1]
        finally:
            set_output_root(None)


def test_fresh_workers_are_new_processes(client):
    from paper_repro.app.cluster import fresh_workers

    before = set(client.run(os.getpid).values())
    assert fresh_workers(client, "local:2")
    after = set(client.run(os.getpid).values())
    assert len(after) == 2 and not before & after


# -- the cluster door: a wrong address answers in one line, whatever listens there -----------------------------
def _serve(kind: str):
    """A local server on a free port: 'hold' accepts and says nothing, 'http' answers like a web server (after the
    request), 'garbage' writes bytes that are no dask handshake, 'close' closes at once."""
    import socket
    import threading

    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    held = []

    def run():
        while True:
            try:
                c, _ = srv.accept()
            except OSError:
                return
            if kind == "garbage":
                c.sendall(b"HTTP/1.0 200 OK\r\n\r\nhello")
            if kind == "close":
                c.close()
            else:
                held.append(c)

    threading.Thread(target=run, daemon=True).start()
    return srv, f"tcp://127.0.0.1:{srv.getsockname()[1]}"


@pytest.mark.parametrize("kind, says", [("hold", "sent no dask handshake"), ("garbage", "does not speak dask"),
                                        ("close", "closed the connection")])
def test_a_peer_that_is_no_scheduler_is_refused_by_the_probe(kind, says):
    srv, address = _serve(kind)
    try:
        with pytest.raises(ValueError, match=says):
            cluster.probe_scheduler(address, 0.5)
    finally:
        srv.close()


def test_refused_port_unknown_host_and_tls_without_settings_are_refused(monkeypatch):
    import socket

    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()  # nothing listens there now
    with pytest.raises(ValueError, match="connection refused"):
        cluster.probe_scheduler(f"tcp://127.0.0.1:{port}", 0.5)
    with pytest.raises(ValueError, match="unknown host"):
        cluster.probe_scheduler("tcp://no-such-host.invalid:8786", 0.5)
    with pytest.raises(ValueError, match="tls:// address needs TLS settings"):
        cluster.tls_security()


def test_a_real_scheduler_passes_the_probe(client):
    cluster.probe_scheduler(client.scheduler.address, 2.0)


def test_the_cli_answers_a_silent_peer_in_one_line_and_exit_2():
    srv, address = _serve("hold")
    try:
        env = dict(os.environ, PAPER_REPRO_NO_CACHE="1")
        env.pop(cluster.SCHEDULER_ENV, None)
        p = subprocess.run([sys.executable, "-m", "paper_repro", "claims", "--only", "dimension", "--scheduler",
                            address], capture_output=True, text=True, env=env, timeout=120)
    finally:
        srv.close()
    assert p.returncode == 2, p.stderr
    assert p.stderr.count("\n") == 1 and "sent no dask handshake" in p.stderr, p.stderr
    assert "Traceback" not in p.stderr + p.stdout and "Exception ignored" not in p.stderr + p.stdout
