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

import contextlib
import os
import signal
import sys
import time
from collections.abc import Callable, Iterable, Iterator
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


def process_context():
    """The start method of the local worker processes: ``forkserver`` where there is one (Linux, macOS), else
    ``spawn``.  Not ``fork``: forking a process that runs threads (the float kernel's pool, numba's, BLAS's) can
    leave a child waiting on a lock another thread held, and Python 3.12 warns about it (``DeprecationWarning``:
    "use of fork() may lead to deadlocks").  The fork server imports the package once and forks the workers from
    that clean, single-threaded process, so a worker starts in milliseconds with the claims importable.

    >>> process_context().get_start_method() in ("forkserver", "spawn")
    True
    """
    import multiprocessing as mp

    if "forkserver" in mp.get_all_start_methods():
        from multiprocessing import forkserver

        ctx = mp.get_context("forkserver")
        # The server imports every claim and figure module once (what each worker's ``load_all`` would import: about
        # 1 s of CPU per worker and per pool, and a new pool starts every round of tasks and for the figures).
        from paper_repro.util.registry import CLAIM_MODULES, FIGURE_MODULES

        ctx.set_forkserver_preload(["paper_repro.util.registry", "numpy", "mpmath", "flint",
                                    *CLAIM_MODULES, *FIGURE_MODULES])
        # Start the fork server now with SIGINT ignored: an ignored signal stays ignored across fork and exec, so
        # neither the server (CPython ignores SIGINT there only after the preload, which takes a second) nor the
        # workers it forks (restored to the server's start-up disposition) can die of a Ctrl-C with a traceback.
        # A terminal's Ctrl-C reaches the whole process group; only the parent reports it (issue 31, CI run 34).
        _start_ignoring_sigint(forkserver.ensure_running)
        return ctx
    return mp.get_context("spawn")


@contextlib.contextmanager
def _sigint_blocked() -> Iterator[None]:
    """Block SIGINT in this thread for the ``with`` body (no-op without ``pthread_sigmask``: Windows).  A Ctrl-C
    meanwhile stays pending and reaches this thread when the block ends -- unless another thread of the process
    has SIGINT unblocked: the kernel may hand it that thread instead.

    >>> with _sigint_blocked():
    ...     pass
    """
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


@contextlib.contextmanager
def deferred_sigint() -> Iterator[None]:
    """Hold a Ctrl-C back for the ``with`` body and deliver it to the previous handler when the body ends (a
    critical section: the body runs to its end, then ``KeyboardInterrupt`` is raised as usual).  Only the main
    thread receives Python signal handlers; elsewhere the body runs as it is.

    With Ctrl-C live (as in a terminal; a process started in the background inherits SIGINT ignored, and then the
    held interrupt is dropped, as it would have been):

    >>> previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    >>> steps = []
    >>> try:
    ...     with deferred_sigint():
    ...         signal.raise_signal(signal.SIGINT)
    ...         steps.append("body ended")
    ... except KeyboardInterrupt:
    ...     steps.append("interrupted")
    >>> steps
    ['body ended', 'interrupted']
    >>> _ = signal.signal(signal.SIGINT, previous)
    """
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append((signum, frame)))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous if previous is not None else signal.default_int_handler)
        if caught:
            if callable(previous):
                previous(*caught[0])
            elif previous == signal.SIG_DFL:
                signal.raise_signal(signal.SIGINT)


def _start_ignoring_sigint(start: Callable[[], object]) -> None:
    """Run ``start`` (which launches a process) with SIGINT ignored, so the process starts with SIGINT ignored even
    through ``exec``.  Only the main thread can change handlers; elsewhere ``start`` just runs.  The cost: a Ctrl-C
    during the launch (fork server and resource tracker: 4 ms measured on the 2-core test machine, once per process)
    is held pending by the blocked main thread, but is lost if the kernel gives it to another
    thread, which ignores it; pressing Ctrl-C again works."""
    import threading

    if threading.current_thread() is not threading.main_thread():
        start()
        return
    with _sigint_blocked():
        previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
        try:
            start()
        finally:
            signal.signal(signal.SIGINT, previous if previous is not None else signal.default_int_handler)


def process_pool(workers: int, initializer: Callable[[], None] | None = None) -> ProcessPoolExecutor:
    """Local worker processes (:func:`process_context`) that ignore Ctrl-C and run ``initializer`` first."""
    return ProcessPoolExecutor(max_workers=workers, mp_context=process_context(), initializer=_quiet_worker,
                               initargs=(initializer,))


def sweep(task: Callable[[T], R], items: Iterable[T], *, executor: Executor | None = None,
          workers: int | None = None, initializer: Callable[[], None] | None = None,
          desc: str | None = None, label: Callable[[T], str] = str) -> list[R]:
    """``[task(item) for item in items]``, computed by ``executor`` (or local processes), in order.

    ``initializer`` runs once in each new local worker process (e.g. to register claims); ``desc`` shows the
    progress on stderr (:class:`~paper_repro.util.progress.Ticker`: a bar on a terminal, else one line at the end).
    """
    from paper_repro.util.progress import Ticker

    seq = list(items)
    n = workers if workers is not None else default_workers()
    ticker = Ticker(len(seq), desc or "", stream=sys.stderr if desc else None)
    if executor is None and (n <= 1 or len(seq) <= 1):
        if initializer:
            initializer()
        out = []
        for item in seq:
            out.append(task(item))
            ticker.step(label(item))
        ticker.close()
        return out
    own = executor is None
    ex = executor or process_pool(n, initializer)
    futures: dict = {}
    try:
        # Ctrl-C is held back while submitting: a submit may start a worker, and an interrupt between the start
        # and the pool's note of it would orphan the worker (it then dies with a traceback once this process has
        # exited and removed the queues' semaphores); raised right after, every worker is known and is stopped.
        with deferred_sigint():
            futures = {ex.submit(task, item): k for k, item in enumerate(seq)}
        results: list = [None] * len(seq)
        for fut in as_completed(futures):
            k = futures[fut]
            results[k] = fut.result()
            ticker.step(label(seq[k]))
        ticker.close()
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
            with deferred_sigint():  # the child is forked here: it inherits the deferring handler, then ignores SIGINT
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


#: The queues of pools stopped by Ctrl-C (see :func:`_terminate`); a few pipes and semaphores per interrupt.
_STOPPED_QUEUES: list = []


def _terminate(ex: Executor) -> None:
    """Stop a local pool now: worker processes terminated first (so nothing waits on them), then pending futures
    cancelled.  The executor's own shutdown runs in a daemon thread given half a second: if Ctrl-C arrived while
    the executor held one of its internal locks (e.g. while it was starting a worker), shutting it down from this
    thread could wait forever; the caller exits right after, so a thread left waiting does not matter."""
    procs = list((getattr(ex, "_processes", None) or {}).values())
    for p in procs:
        p.terminate()
    # Keep the pool's queues alive: dropped by the shutdown below, they would be collected in the executor's
    # manager thread, whose semaphore clean-up (unlink, then tell the resource tracker) an exit right after could cut
    # in half -- the tracker then warned of a leaked semaphore it could not find (Python 3.12 under load).  Kept,
    # they are cleaned up by this thread: at exit, or by the CLI's ``_run_finalizers(0)`` before ``os._exit``.
    _STOPPED_QUEUES.append((getattr(ex, "_call_queue", None), getattr(ex, "_result_queue", None)))
    _in_background(lambda: ex.shutdown(wait=False, cancel_futures=True), 0.5)
    deadline = time.monotonic() + 1.0  # one second in all, not per worker
    for p in procs:
        p.join(timeout=max(0.0, deadline - time.monotonic()))
    for p in procs:
        if p.is_alive():
            p.kill()
