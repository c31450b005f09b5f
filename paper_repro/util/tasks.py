"""Claims split into tasks, so that one claim can use every worker of a sweep (issue 32).

A *split* claim is written as a generator: it yields lists of :class:`Task` (its inner loop: per n, per alpha,
per prime), receives their results in the same order, and finally returns its ``Outcome``.  Two drivers run it:

* :func:`drive_inline` -- every task in this process, one after the other (``claim.func(**params)``, the tests);
* :func:`drive` -- every yielded task of every split claim of a run in one flat batch per round through a
  runner (:func:`paper_repro.util.sweep.sweep`: local processes or a ``dask.distributed`` cluster).  Tasks that
  are equal (same function, same arguments) are computed once per round and their result handed to each claim
  that asked (e.g. the closed forms of order n, used by four claims).

Both drivers hand the claim the results in the order it yielded the tasks, and the claim's code between the
yields runs in the driving process, so the outcome -- and every byte written from it -- does not depend on the
driver, the executor, the number of workers or the order in which tasks finish.

>>> def claim_body(ns):
...     squares = yield [Task(pow, (n, 2)) for n in ns]
...     return sum(squares)
>>> drive_inline(claim_body([1, 2, 3]))
14
>>> drive({"a": claim_body([1, 2]), "b": claim_body([2, 3])}, lambda tasks: [t() for t in tasks])
{'a': 5, 'b': 13}
"""

from __future__ import annotations

import hashlib
import pickle
import time
from collections.abc import Callable, Generator, Sequence
from dataclasses import dataclass
from typing import Any

ClaimBody = Generator[list["Task"], list[Any], Any]


@dataclass(frozen=True)
class Task:
    """``func(*args)``; ``func`` is a module-level function (picklable by reference, importable on a worker)."""

    func: Callable[..., Any]
    args: tuple = ()

    def __call__(self) -> Any:
        return self.func(*self.args)

    @property
    def name(self) -> str:
        return f"{self.func.__module__.rsplit('.', 1)[-1]}.{self.func.__name__}"

    @property
    def label(self) -> str:
        """Function and its small arguments, e.g. ``closed_forms.record(30)`` (a record argument shows its n)."""
        return f"{self.name}({', '.join(_short(a) for a in self.args)})"

    def key(self) -> str:
        """Equal tasks have equal keys (dedup within a round)."""
        body = pickle.dumps((self.func.__module__, self.func.__qualname__, self.args), protocol=4)
        return hashlib.sha256(body).hexdigest()


@dataclass
class TaskFailed:
    """A task's exception, carried back as a result: :func:`drive` raises it inside the claim that asked (which
    then fails, with the error, like a claim that raises), and the other claims go on."""

    error: Exception


def _short(a: Any) -> str:
    if isinstance(a, dict) and "n" in a:
        return f"record n={a['n']}"
    if isinstance(a, tuple | list) and a and all(isinstance(x, dict) and "n" in x for x in a):
        return f"records n={a[0]['n']}..{a[-1]['n']}"
    text = a if isinstance(a, str) else repr(a)
    if len(text) > 80 and isinstance(a, tuple | list) and a:
        return f"{len(a)} {type(a[0]).__name__}"
    return text if len(text) <= 80 else text[:77] + "..."


def timed(task: Task) -> tuple[Any, float, float]:
    """``(task(), wall seconds, CPU seconds)`` (an exception comes back as :class:`TaskFailed`): what a sweep runs,
    so that the driver can record the cost of every task.  CPU seconds are the cost model's unit: on a loaded
    machine wall time measures the load."""
    t0, c0 = time.perf_counter(), time.process_time()
    try:
        out = task()
    except Exception as exc:  # noqa: BLE001 - reported in the claim that asked for the task
        out = TaskFailed(exc)
    return out, time.perf_counter() - t0, time.process_time() - c0


def drive_inline(body: ClaimBody) -> Any:
    """Run a split claim's body in this process (tasks one after the other); returns what the body returns."""
    try:
        tasks = next(body)
        while True:
            tasks = body.send([t() for t in tasks])
    except StopIteration as stop:
        return stop.value


Runner = Callable[[list[Task]], Sequence[Any]]


def drive(bodies: dict[str, ClaimBody], runner: Runner, extra: Sequence[Task] = (),
          asked: dict[str, list[Task]] | None = None) -> dict[Any, Any]:
    """Run several split claims together: each round, the tasks every unfinished body yielded (and, in the first
    round, ``extra``: e.g. whole claims that are not split) go to ``runner`` as one list of distinct tasks; each
    body gets its own results back in its own order.  Returns ``{id: what the body returned, or the exception it
    raised}`` and, under the key ``None``, the results of ``extra``.  A result that is a :class:`TaskFailed` is
    raised inside the body that asked for the task.  ``asked``, if given, receives every task each body asked for."""
    done: dict[Any, Any] = {}
    waiting: dict[str, list[Task]] = {}
    for cid, body in bodies.items():
        try:
            waiting[cid] = next(body)
        except StopIteration as stop:
            done[cid] = stop.value
    extra = list(extra)
    while waiting or extra:
        batch: list[Task] = list(extra)
        index: dict[str, int] = {}
        for tasks in waiting.values():
            for t in tasks:
                k = t.key()
                if k not in index:
                    index[k] = len(batch)
                    batch.append(t)
        if asked is not None:
            for cid, tasks in waiting.items():
                asked.setdefault(cid, []).extend(tasks)
        results = list(runner(batch))
        if extra:
            done[None] = results[: len(extra)]
            extra = []
        for cid in list(waiting):
            got = [results[index[t.key()]] for t in waiting[cid]]
            failed = next((r.error for r in got if isinstance(r, TaskFailed)), None)
            try:
                waiting[cid] = bodies[cid].send(got) if failed is None else bodies[cid].throw(failed)
            except StopIteration as stop:
                done[cid] = stop.value
                del waiting[cid]
            except Exception as exc:  # noqa: BLE001 - the claim fails with its error; the others go on
                done[cid] = exc
                del waiting[cid]
    return done
