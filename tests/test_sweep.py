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


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="reads the fork server's signal state in /proc")
def test_the_fork_server_is_born_ignoring_ctrl_c():
    """CI run 34: a terminal's Ctrl-C reaches the whole process group; the fork server, which CPython sets to ignore
    SIGINT only after its preload (numpy, flint: about a second), died with a traceback.  It is now launched with
    SIGINT ignored, which survives exec: ignored at once, long before the preload ends.  Fresh interpreter, so
    this test's own process has no fork server yet."""
    import subprocess
    import sys

    code = """if True:
        import multiprocessing.forkserver as fs, time
        from paper_repro.util.sweep import process_context
        t = time.perf_counter()
        process_context()
        status = open(f"/proc/{fs._forkserver._forkserver_pid}/status").read()
        ignored = int(next(l for l in status.splitlines() if l.startswith("SigIgn:")).split()[1], 16)
        print(bool(ignored & 2), time.perf_counter() - t < 0.3)
    """
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    ignored, early = out.stdout.split()
    if early != "True":
        pytest.skip("the check came too late to tell a launch state from the preload's own SIG_IGN")
    assert ignored == "True"


def test_ctrl_c_during_submit_is_raised_after_every_worker_is_known(monkeypatch):
    """CI run 34: a Ctrl-C inside ``submit`` (between a worker's start and the pool's note of it) orphaned the
    worker, which died with a traceback after this process removed the queues.  The submits now run to their end
    and the interrupt is raised after them (then every worker is terminated)."""
    import signal
    import threading
    from concurrent.futures import ProcessPoolExecutor

    from paper_repro.util import sweep as sweep_module
    from paper_repro.util.sweep import process_context

    if threading.current_thread() is not threading.main_thread():
        pytest.skip("signal handlers need the main thread")
    submitted = []

    class InterruptedPool(ProcessPoolExecutor):
        def submit(self, fn, /, *args, **kwargs):
            fut = super().submit(fn, *args, **kwargs)
            submitted.append(fut)
            if len(submitted) == 2:
                signal.raise_signal(signal.SIGINT)  # a Ctrl-C while the submits are under way
            return fut

    pools, queues = [], []

    def pool(workers, initializer=None):
        pools.append(InterruptedPool(max_workers=workers, mp_context=process_context()))
        queues.append(pools[-1]._call_queue)
        return pools[-1]

    monkeypatch.setattr(sweep_module, "process_pool", pool)
    # Ctrl-C live, as in a terminal: a suite started in the background (``cmd &``, nohup) inherits SIGINT ignored,
    # and then the held interrupt is rightly dropped (this test failed so in a background CI run)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            sweep(_square, list(range(6)), workers=2)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert len(submitted) == 6  # before the fix: 2, the interrupt came out of the second submit
    # the stopped pool's queues stay referenced, so their semaphores are released by this thread, never half-way by
    # the executor's manager thread at an ``os._exit`` (Python 3.12: "leaked semaphore ... No such file")
    assert any(kept is queues[0] for kept, _ in sweep_module._STOPPED_QUEUES)


def test_the_cli_tells_multiprocessing_it_is_exiting_on_ctrl_c():
    """CI: after Ctrl-C a stopped pool's queue feeder thread printed "Exception in thread QueueFeederThread" when its
    pipe was closed under it; the CLI, which exits 130 right after, sets multiprocessing's exiting flag so the
    feeder drops its write quietly.  In a subprocess: the flag is process-wide."""
    import subprocess
    import sys

    code = ("import multiprocessing.util as u\nfrom paper_repro.app import cli\nbefore = u._exiting\n"
            "try:\n    cli._on_sigint(2, None)\nexcept KeyboardInterrupt:\n    print(before, u._exiting, flush=True)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.split() == ["False", "True"], out.stderr
