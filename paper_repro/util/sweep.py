"""Sweeps over parameters (claims, benchmarks, extended runs) through a ``concurrent.futures.Executor``.

By default local processes on every core (``os.cpu_count()``; ``PAPER_REPRO_WORKERS`` overrides, ``1`` runs
in this process); any executor a caller passes is used as it is -- a ``ProcessPoolExecutor``, a
``ThreadPoolExecutor`` or a ``dask.distributed`` client's executor (``client.get_executor()``), so a sweep
can run on a cluster::

    from dask.distributed import Client          # pip install 'paper_repro[dask]'
    client = Client("scheduler-address:8786")     # or Client() for a local cluster
    results = sweep(task, items, executor=client.get_executor())

Results come back in the order of ``items`` whatever order the workers finish in, so a sweep's output
does not depend on the executor.  ``task`` must be a module-level function (picklable).

>>> from concurrent.futures import ThreadPoolExecutor
>>> with ThreadPoolExecutor(2) as ex:
...     sweep(abs, [-3, 1, -2], executor=ex)
[3, 1, 2]
>>> sweep(abs, [-1], workers=1)
[1]
"""

from __future__ import annotations

import os
import signal
import sys
import time
from collections.abc import Callable, Iterable
from concurrent.futures import Executor, ProcessPoolExecutor, as_completed
from typing import TypeVar

T = TypeVar("T")
R = TypeVar("R")


def default_workers() -> int:
    env = os.environ.get("PAPER_REPRO_WORKERS")
    if env:
        if not env.isdigit() or int(env) < 1:
            raise ValueError(f"PAPER_REPRO_WORKERS must be a positive integer, got {env!r}")
        return int(env)
    return os.cpu_count() or 1


def sweep(task: Callable[[T], R], items: Iterable[T], *, executor: Executor | None = None,
          workers: int | None = None, initializer: Callable[[], None] | None = None,
          desc: str | None = None, label: Callable[[T], str] = str) -> list[R]:
    """``[task(item) for item in items]``, computed by ``executor`` (or local processes), in order.

    ``initializer`` runs once in each new local worker process (e.g. to register claims); ``desc``
    prints one plain progress line per finished item to stderr.
    """
    seq = list(items)
    n = workers if workers is not None else default_workers()
    if executor is None and (n <= 1 or len(seq) <= 1):
        if initializer:
            initializer()
        out = []
        for k, item in enumerate(seq, 1):
            out.append(task(item))
            if desc:
                print(f"{desc} {k}/{len(seq)}: {label(item)}", file=sys.stderr, flush=True)
        return out
    own = executor is None
    ex = executor or ProcessPoolExecutor(max_workers=n, initializer=_quiet_worker,
                                         initargs=(initializer,))
    futures: dict = {}
    try:
        futures = {ex.submit(task, item): k for k, item in enumerate(seq)}
        results: list = [None] * len(seq)
        for done, fut in enumerate(as_completed(futures), 1):
            k = futures[fut]
            results[k] = fut.result()
            if desc:
                print(f"{desc} {done}/{len(seq)}: {label(seq[k])}", file=sys.stderr, flush=True)
        return results
    except BaseException:
        # Ctrl-C (or an error): cancel the pending work at once instead of draining the queue, and stop our
        # own workers (they ignore SIGINT, so only the parent reports it); results are written atomically
        # after a sweep, so an interrupted sweep leaves data/ and the cache as they were.
        # Nothing here takes a future's lock in this thread: a Ctrl-C that lands while this thread holds one of
        # concurrent.futures' internal locks (a with-statement interrupted between acquire and its try block)
        # would deadlock against the executor's manager thread (seen as a rare hang on Python 3.12/3.13).
        if own:
            _terminate(ex)
            own = False
        else:
            _in_background(lambda: [fut.cancel() for fut in futures], 0.5)
        raise
    finally:
        if own:
            ex.shutdown()


def interruptible(task: Callable[[T], R], item: T) -> R:
    """``task(item)`` in a forked child process, so that Ctrl-C stops it at once even while it is inside a C
    call that holds the GIL (flint's ball solves do): the parent waits, and on KeyboardInterrupt terminates the
    child and re-raises.  For work of a second or more (a fork costs about 10 ms).  The child is forked, not
    spawned, so a user's script needs no ``if __name__ == "__main__"`` guard; where ``fork`` is not available
    the task runs in this process (and Ctrl-C acts when the C call returns).  ``item`` and the result must be
    picklable.

    >>> interruptible(abs, -3)
    3
    """
    import multiprocessing as mp
    import warnings

    if "fork" not in mp.get_all_start_methods():
        return task(item)
    ex = ProcessPoolExecutor(max_workers=1, mp_context=mp.get_context("fork"), initializer=_quiet_worker,
                             initargs=(None,))
    try:
        with warnings.catch_warnings():
            # Python >= 3.12 warns when a process with threads forks; the child only runs ``task`` (flint and
            # numpy object arithmetic, no lock shared with the kernel's idle thread pool) and exits.
            warnings.simplefilter("ignore", DeprecationWarning)
            fut = ex.submit(task, item)
        return fut.result()
    except BaseException:
        _terminate(ex)
        raise
    finally:
        ex.shutdown()


def _quiet_worker(initializer: Callable[[], None] | None) -> None:
    """Worker start-up: ignore SIGINT (the parent handles Ctrl-C and stops the workers), then ``initializer``."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if initializer:
        initializer()


def _in_background(func: Callable[[], object], seconds: float) -> None:
    """Run ``func`` in a daemon thread and wait for it at most ``seconds`` (it may block on a lock)."""
    import threading

    t = threading.Thread(target=func, daemon=True)
    t.start()
    t.join(timeout=seconds)


def _terminate(ex: Executor) -> None:
    """Stop a local pool now: worker processes terminated first (so nothing waits on them), then pending futures
    cancelled.  The executor's own shutdown runs in a daemon thread given half a second: if Ctrl-C arrived while
    the executor held one of its internal locks (e.g. while it was starting a worker), shutting it down from this
    thread could wait forever; the caller exits right after, so a thread left waiting does not matter."""
    procs = list((getattr(ex, "_processes", None) or {}).values())
    for p in procs:
        p.terminate()
    _in_background(lambda: ex.shutdown(wait=False, cancel_futures=True), 0.5)
    deadline = time.monotonic() + 1.0  # one second in all, not per worker
    for p in procs:
        p.join(timeout=max(0.0, deadline - time.monotonic()))
    for p in procs:
        if p.is_alive():
            p.kill()
