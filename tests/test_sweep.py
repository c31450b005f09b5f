"""Sweeps through executors: order kept, any executor accepted, a dask cluster (tests/test_cluster.py too)."""

import os
from concurrent.futures import ThreadPoolExecutor

import pytest

from paper_repro.util.sweep import default_workers, process_pool, sweep


def _square(x):
    return x * x


def test_order_is_kept_with_processes_threads_and_inline():
    items = list(range(12))
    expected = [x * x for x in items]
    with process_pool(2) as ex:  # forkserver: no fork of this (threaded) process, no DeprecationWarning on 3.12+
        assert sweep(_square, items, executor=ex) == expected
    with ThreadPoolExecutor(3) as ex:
        assert sweep(_square, items, executor=ex) == expected
    assert sweep(_square, items, workers=1) == expected
    assert sweep(_square, items, workers=2) == expected


def test_workers_from_environment(monkeypatch):
    monkeypatch.setenv("PAPER_REPRO_WORKERS", "3")
    assert default_workers() == 3
    monkeypatch.setenv("PAPER_REPRO_WORKERS", "zero")
    with pytest.raises(ValueError, match="PAPER_REPRO_WORKERS"):
        default_workers()
    monkeypatch.delenv("PAPER_REPRO_WORKERS")
    assert default_workers() == (os.cpu_count() or 1)


def test_a_claim_sweep_gives_the_same_results_inline_and_in_processes():
    from paper_repro.app.report import _run_one
    from paper_repro.util.registry import load_all

    load_all()
    jobs = [("dimension", {"n_min": 1, "n_max": 6}, False), ("symmetry", None, False)]
    inline = [r[0].as_dict() for r in sweep(_run_one, jobs, workers=1)]
    procs = [r[0].as_dict() for r in sweep(_run_one, jobs, workers=2, initializer=load_all)]
    assert inline == procs and all(r["status"] == "pass" for r in inline)


def test_dask_local_cluster():
    import distributed  # in requirements.lock (extra paper_repro[dask]): a missing one fails, never skips

    with distributed.Client(processes=False, n_workers=1, threads_per_worker=2, dashboard_address=None) as client:
        assert sweep(_square, [3, 1, 2], executor=client.get_executor()) == [9, 1, 4]


def test_local_workers_are_not_forked_from_this_threaded_process():
    """Python 3.12+ warned 6 times in this file: fork() of a process with threads may deadlock the child.  Local
    workers come from a fork server (or spawn); with a thread running here no DeprecationWarning is raised."""
    import threading
    import warnings

    from paper_repro.util.sweep import process_context

    assert process_context().get_start_method() in ("forkserver", "spawn")
    stop = threading.Event()
    busy = threading.Thread(target=stop.wait, daemon=True)
    busy.start()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", DeprecationWarning)
            assert sweep(_square, list(range(6)), workers=2) == [x * x for x in range(6)]
    finally:
        stop.set()
