"""The fast float64 path: patch points, derivatives and blending values in blocks, with per-variable
power tables of *scaled* half-angle sines.

Every function of T_{2n} of level j is ``s_u^a c_u^b s_v^c c_v^d s_w^e c_w^f`` (half-angle sines and
cosines, :mod:`paper_repro.core.labels`) with exactly ``a + c + e = 2n + j`` sine factors.  The kernel
works with the ratios ``S = sin(x/2) / sin(alpha/2)`` (in [0, 1] on Omega^alpha;
:func:`paper_repro.core.domain.scaled_half_angle_values`) and the scaled coefficients ``s^{2n+j} r``
(:func:`paper_repro.core.normalization.scaled_coefficient_vector`), so every factor is bounded for every
alpha in (0, pi), down to 1e-300.  Per block of points it computes, for each variable, the distinct products
``S^a c^b`` that occur (a few dozen columns), gathers and multiplies them into the ``(block, delta_n)``
basis matrix and contracts it with the (coefficient-scaled) control net by one BLAS product.  Peak memory
is ``O(block * delta_n)`` per worker, independent of the number of points.

Derivatives: ``d/dx (S^a c^b) = (a S^(a-1) c^(b+1) - b s^2 S^(a+1) c^(b-1)) / (2s)`` (``s = sin(alpha/2)``);
the kernel returns the bracket (bounded) and the caller applies the factor ``1/(2s)`` once, at the end.

Threads: the blocks are independent, so they run on a pool of threads (numpy releases the GIL), each block
with a single-threaded BLAS (``threadpoolctl``).  A block is computed by the same operations in the same
order whichever thread runs it and however many threads there are, so the result is the same to the last
bit with 1 or k threads (tested).  The thin ``(block, delta_n) x (delta_n, d)`` products are not worth
splitting: with a multi-threaded BLAS the threads wait on each other as soon as a core is busy.
``PAPER_REPRO_THREADS`` sets the number of threads (default: the CPUs this process may use).

>>> import numpy as np
>>> k = FloatKernel(np.array([[1, 0, 0, 0, 0, 0], [0, 0, 2, 1, 0, 0]]))
>>> half = np.array([[0.1, 0.2, 0.3]])
>>> s, c = np.sin(half), np.cos(half)
>>> got = k.basis(s, c)[0]
>>> bool(np.allclose(got, [s[0, 0], s[0, 1] ** 2 * c[0, 1]]))
True
"""

from __future__ import annotations

import itertools
import math
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor, wait
from contextlib import contextmanager, nullcontext

import numpy as np

from paper_repro.core.domain import SMALL_ALPHA

#: Points per block.  The (delta_n, block) work arrays should stay in the CPU caches: in the functions-x-points
#: layout 1024 measured fastest of 512..4096 for n = 3, 6, 10, evaluation and derivatives (interleaved runs,
#: min of 12, on this project's 2-core machine: 2x over 4096 at n = 3 and 10, 3x at n = 6).
BLOCK = 1024


def block_for(functions: int) -> int:
    """Points per block of a point evaluation with ``functions`` = delta_n monomials: about 2^18 table entries
    (2 MB) per block, a power of two from :data:`BLOCK` to 8192 (n = 1, 2: 8192; n = 3, 4: 4096; n = 5, 6: 2048;
    n >= 7: 1024).  Measured (interleaved runs, min of 5, 10^6 points, alpha = pi/2, 2 cores): with
    two threads n = 1: 0.35 -> 0.14 s, n = 3: 0.51 -> 0.27 s, n = 6: 0.77 -> 0.66 s against 1024-point blocks
    (the per-block Python work holds the GIL, so small blocks keep the second thread waiting); one thread
    0.28 -> 0.22 s (n = 1), 0.42 -> 0.34 s (n = 3), 0.84 -> 0.87 s (n = 6, within the noise).

    >>> [block_for(d) for d in (7, 37, 127, 331)]
    [8192, 4096, 2048, 1024]
    """
    target = (1 << 18) // max(1, functions)
    return max(BLOCK, min(8192, 1 << max(0, target.bit_length() - 1)))

#: Rows per BLAS product in :func:`contract`.  OpenBLAS's result for a ``(M, F) x (F, P)`` product depends on how
#: many threads it uses (it cuts the product differently), and threadpoolctl's limit is not reliably seen by calls
#: from other threads (joblib/threadpoolctl#205).  Measured with OpenBLAS 0.3.31: 5 or 6 rows differed with 1 and 2
#: threads under the Haswell kernel; 4 rows were enough there and under SkylakeX, but not under the Sandybridge,
#: Nehalem and Haswell kernels once 6 user threads evaluated at once (issue 31: test_concurrent_calls_from_user_threads
#: under ``OPENBLAS_CORETYPE``).  One row at a time (a product whose every entry is one dot product over F, whatever
#: the threads) gave the serial bits under every kernel.
BLAS_ROWS = 1


def contract(net_t: np.ndarray, basis: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """``net_t @ basis`` (``(M, F) x (F, P)``) as products of at most :data:`BLAS_ROWS` rows, so the bits do not
    depend on BLAS's threads.

    >>> a, b = np.arange(12.0).reshape(6, 2), np.ones((2, 3))
    >>> bool(np.array_equal(contract(a, b), a @ b))
    True
    """
    if out is None:
        out = np.empty((net_t.shape[0], basis.shape[1]))
    for k in range(0, net_t.shape[0], BLAS_ROWS):
        np.matmul(net_t[k: k + BLAS_ROWS], basis, out=out[k: k + BLAS_ROWS])
    return out


#: Functions per chunk of :meth:`FloatKernel.contract_derivatives` (a chunk's rows, 32 x 1024 doubles = 256 KB, stay
#: in the core's cache).  16, 32, 64, 128 measured once per block on this busy 2-core machine (noisy, 25% steal):
#: 32 was fastest at n = 6 and 10 (1.6x and 2.3x over the unchunked derivative), within the noise at n = 3.
CHUNK = 32

#: The kernel's thread pools, one per size (``PAPER_REPRO_THREADS`` values used in this process; never shut down,
#: so a call on one thread cannot find its pool shut down by a call on another).
_POOLS: dict[int, ThreadPoolExecutor] = {}
_POOL_LOCK = threading.Lock()
#: Set on the kernel's worker threads: a call made from one of them (a profiling or tracing hook, a callback)
#: runs its blocks inline instead of waiting for the pool it is running on.
_WORKER = threading.local()
_CONTROLLER = None
_BLAS_LOCK = threading.Lock()
_BLAS_USERS = 0
_BLAS_LIMITER = None


#: Most threads ``PAPER_REPRO_THREADS`` may ask for (each thread evaluates a block of points; more threads than
#: this is a typing error, not a machine).
MAX_THREADS = 1024


def threads() -> int:
    """Threads the kernel uses: ``PAPER_REPRO_THREADS`` if set (an integer in [1, MAX_THREADS]), else the CPUs
    available."""
    env = os.environ.get("PAPER_REPRO_THREADS", "").strip()
    if env:
        try:
            k = int(env)
        except ValueError:
            raise ValueError(f"PAPER_REPRO_THREADS must be an integer in [1, {MAX_THREADS}], got {env!r}") from None
        if not 1 <= k <= MAX_THREADS:
            raise ValueError(f"PAPER_REPRO_THREADS must be an integer in [1, {MAX_THREADS}], got {env!r}")
        return k
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def _forget_pool_after_fork() -> None:
    """In a forked child the pools' threads do not exist (only the forking thread is copied), but the executors
    do, with their idle-worker counts: a block submitted to one would wait forever.  The child starts with no
    pool (a new one is made on first use) and fresh locks (the parent's may have been held at the fork)."""
    global _POOLS, _POOL_LOCK, _BLAS_LOCK, _BLAS_USERS, _BLAS_LIMITER
    _POOLS, _POOL_LOCK = {}, threading.Lock()
    _BLAS_LOCK, _BLAS_USERS, _BLAS_LIMITER = threading.Lock(), 0, None


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_pool_after_fork)


def _pool(size: int) -> ThreadPoolExecutor:
    with _POOL_LOCK:
        pool = _POOLS.get(size)
        if pool is None:
            pool = _POOLS[size] = ThreadPoolExecutor(max_workers=size, thread_name_prefix="paper_repro",
                                                     initializer=_mark_worker)
        return pool


def _mark_worker() -> None:
    _WORKER.active = True


@contextmanager
def single_threaded_blas():
    """BLAS limited to one thread while any call of the numpy kernel runs (``threadpoolctl``; a no-op when it is
    not installed).  The limit is process-wide, so calls on several threads share one: the first sets it, the
    last restores the user's setting (two overlapping ``limit`` contexts would restore each other's values)."""
    global _CONTROLLER, _BLAS_USERS, _BLAS_LIMITER
    if _CONTROLLER is None:
        try:
            from threadpoolctl import ThreadpoolController  # type: ignore[import-untyped]
        except ImportError:  # pragma: no cover - threadpoolctl is a dependency
            _CONTROLLER = False
        else:
            _CONTROLLER = ThreadpoolController()
    if _CONTROLLER is False:
        yield
        return
    with _BLAS_LOCK:
        if _BLAS_USERS == 0:
            _BLAS_LIMITER = _CONTROLLER.limit(limits=1, user_api="blas")
        _BLAS_USERS += 1
    try:
        yield
    finally:
        with _BLAS_LOCK:
            _BLAS_USERS -= 1
            if _BLAS_USERS == 0 and _BLAS_LIMITER is not None:
                _BLAS_LIMITER.restore_original_limits()
                _BLAS_LIMITER = None


class Workspace(dict):
    """Work arrays of one thread for one call, reused from block to block (by name and shape).

    Allocating the ``(F, P)`` arrays afresh for every block costs a page fault per 4 KB each time (the allocator
    gives large blocks back to the system on free): measured 10x the arithmetic for the derivatives on a busy
    machine.  A workspace lives for one call, so memory is bounded by one block per thread and is returned after.
    """

    def get(self, name: str, shape: tuple[int, ...]) -> np.ndarray:  # type: ignore[override]
        arr = dict.get(self, name)
        if arr is None or arr.shape != shape:
            arr = self[name] = np.empty(shape)
        return arr


def run_blocks(count: int, work: Callable[[int, int, Workspace], None], block: int = BLOCK,
               workers: int | None = None, blas: bool = True) -> None:
    """Call ``work(start, stop, workspace)`` on every block of ``range(count)``, on ``workers`` threads (default
    :func:`threads`); each thread has its own :class:`Workspace` for the call.  With ``blas`` (the numpy kernel),
    BLAS single-threaded meanwhile.  The first failing block (in order) raises its exception.  Called on one of
    the pool's own threads, the blocks run inline (waiting for the pool there could wait for ever)."""
    starts = list(range(0, count, block))
    size = threads() if workers is None else int(workers)
    k = 1 if getattr(_WORKER, "active", False) else min(size, len(starts))
    with single_threaded_blas() if blas else nullcontext():
        if k <= 1:
            ws = Workspace()
            for st in starts:
                work(st, min(st + block, count), ws)
            return
        # k long-lived tasks pull block numbers from a shared counter: k futures, not one per block (a future per
        # block is ~2 KB: 20 MB at 10^7 points), and the work memory stays one block per thread
        counter = itertools.count()
        lock = threading.Lock()
        errors: dict[int, BaseException] = {}
        stopped = [False]  # set by the waiting thread on Ctrl-C (a plain store: no lock taken on that path)

        def task() -> None:
            ws = Workspace()
            while True:
                with lock:
                    if errors or stopped[0]:
                        return
                    i = next(counter)
                if i >= len(starts):
                    return
                st = starts[i]
                try:
                    work(st, min(st + block, count), ws)
                except BaseException as exc:  # noqa: BLE001 - re-raised below, the first block's first
                    with lock:
                        errors[i] = exc
                    return

        try:
            futures = [_pool(size).submit(task) for _ in range(k)]
            # wait in short steps: a Ctrl-C that the kernel delivers to one of the worker threads (a process-wide
            # SIGINT may land on any thread) does not interrupt a blocking wait of this one; Python raises it here
            # when the timed wait returns
            while wait(futures, timeout=0.2).not_done:
                pass
            for f in futures:
                f.result()
        except BaseException:
            # Ctrl-C while waiting: the workers take no further block (each finishes the one it is in, a few ms),
            # so the call stops at once and the process can exit (before, they computed every remaining block)
            stopped[0] = True
            raise
        if errors:
            # every block before the first failing one was taken (the counter is monotonic) and has finished
            raise errors[min(errors)]


def scaled_trig(uvw: np.ndarray, alpha: float, sin_half_alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """``(S, C)``: sine ratios ``sin(x/2)/sin(alpha/2)`` (``x/alpha`` below :data:`SMALL_ALPHA`, as
    :func:`paper_repro.core.domain.scaled_half_angle_values`) and cosines ``cos(x/2)`` of ``(P, 3)`` points."""
    half = uvw * 0.5
    if alpha < SMALL_ALPHA:
        return np.clip(uvw / alpha, 0.0, None), np.cos(half)
    return np.sin(half) / sin_half_alpha, np.cos(half)


def scaled_trig_rows(uvw: np.ndarray, alpha: float, sin_half_alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`scaled_trig` transposed: ``(3, P)`` rows (contiguous per variable), the kernel's layout."""
    return trig_of_rows(np.ascontiguousarray(uvw.T), alpha, sin_half_alpha)


def trig_of_rows(rows: np.ndarray, alpha: float, sin_half_alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`scaled_trig` of contiguous ``(3, P)`` rows ``(u, v, w)``."""
    half = rows * 0.5
    if alpha < SMALL_ALPHA:
        return np.clip(rows / alpha, 0.0, None), np.cos(half)
    s = np.sin(half)
    s /= sin_half_alpha
    return s, np.cos(half, out=half)


class FloatKernel:
    """Evaluator of the monomials with exponent rows ``exps`` (``(F, 6)``) in float64.

    The work layout is "functions x points": per variable a ``(pairs, P)`` table of the distinct products
    ``S^a c^b`` (rows built from the power rows by two row gathers and one product), then the ``(F, P)``
    basis by three row gathers and two products, contracted with the net by one ``(d, F) x (F, P)`` product.
    Every array operation runs on contiguous rows of one block.
    """

    def __init__(self, exps: np.ndarray):
        exps = np.asarray(exps, dtype=np.int64)
        self.F = exps.shape[0]
        self.pairs: list[np.ndarray] = []  # per variable: distinct (s-power, c-power) rows
        self.index: list[np.ndarray] = []  # per variable: row of each function in the pair table
        self.smax: list[int] = []
        self.cmax: list[int] = []
        for var in range(3):
            sub = exps[:, 2 * var: 2 * var + 2]
            pairs, inv = np.unique(sub, axis=0, return_inverse=True)
            self.pairs.append(pairs)
            self.index.append(inv.reshape(-1))
            self.smax.append(int(pairs[:, 0].max()))
            self.cmax.append(int(pairs[:, 1].max()))

    @staticmethod
    def _powers(x: np.ndarray, top: int, out: np.ndarray | None = None) -> np.ndarray:
        """``(top + 1, P)`` rows ``x^0 .. x^top`` (successive products, as a loop would compute them)."""
        if out is None:
            out = np.empty((top + 1, x.shape[0]))
        out[0] = 1.0
        for k in range(1, top + 1):
            np.multiply(out[k - 1], x, out=out[k])
        return out

    def _table(self, var: int, sp: np.ndarray, cp: np.ndarray, ws: Workspace) -> np.ndarray:
        """``(npairs, P)`` values ``S^a c^b`` of the distinct pairs of variable ``var``."""
        pairs = self.pairs[var]
        shape = (len(pairs), sp.shape[1])
        out = np.take(sp, pairs[:, 0], axis=0, out=ws.get(f"t{var}", shape), mode="clip")
        out *= np.take(cp, pairs[:, 1], axis=0, out=ws.get("tt", shape), mode="clip")
        return out

    def _dtable(self, var: int, sp: np.ndarray, cp: np.ndarray, s2: float, ws: Workspace) -> np.ndarray:
        """``(npairs, P)`` bracket ``a S^(a-1) c^(b+1) - b s^2 S^(a+1) c^(b-1)`` (= 2s d/dx S^a c^b); the power rows
        go one further than for the values."""
        a, b = self.pairs[var][:, 0], self.pairs[var][:, 1]
        shape = (len(a), sp.shape[1])
        out = np.take(sp, np.maximum(a - 1, 0), axis=0, out=ws.get(f"d{var}", shape), mode="clip")
        out *= np.take(cp, b + 1, axis=0, out=ws.get("tt", shape), mode="clip")
        out *= a[:, None].astype(np.float64)
        if s2:
            second = np.take(sp, a + 1, axis=0, out=ws.get("tt", shape), mode="clip")
            second *= np.take(cp, np.maximum(b - 1, 0), axis=0, out=ws.get("tt2", shape), mode="clip")
            second *= (b * s2)[:, None]
            out -= second
        return out

    def _rows(self, s: np.ndarray, c: np.ndarray, extra: int, ws: Workspace) -> tuple[list, list]:
        """Per variable the power rows of the sines and of the cosines (one further when ``extra``)."""
        p = s.shape[1]
        sp = [self._powers(s[v], self.smax[v] + extra, ws.get(f"s{v}", (self.smax[v] + extra + 1, p)))
              for v in range(3)]
        cp = [self._powers(c[v], self.cmax[v] + extra, ws.get(f"c{v}", (self.cmax[v] + extra + 1, p)))
              for v in range(3)]
        return sp, cp

    def _gather(self, table: np.ndarray, var: int, out: np.ndarray) -> np.ndarray:
        # np.take with mode="clip" writes straight into ``out`` (mode="raise" buffers: 3x slower; indices are valid)
        return np.take(table, self.index[var], axis=0, out=out, mode="clip")

    def basis_rows(self, s: np.ndarray, c: np.ndarray, ws: Workspace | None = None) -> np.ndarray:
        """``(F, P)`` monomial values from ``(3, P)`` rows of (scaled) half-angle sines ``s`` and cosines ``c``.

        With a :class:`Workspace` the result lives in it (overwritten by the next block of the same thread).
        """
        ws = Workspace() if ws is None else ws
        shape = (self.F, s.shape[1])
        sp, cp = self._rows(s, c, 0, ws)
        out = self._gather(self._table(0, sp[0], cp[0], ws), 0, ws.get("basis", shape))
        tmp = ws.get("tmp", shape)
        out *= self._gather(self._table(1, sp[1], cp[1], ws), 1, tmp)
        out *= self._gather(self._table(2, sp[2], cp[2], ws), 2, tmp)
        return out

    def basis(self, s: np.ndarray, c: np.ndarray) -> np.ndarray:
        """``(P, F)`` monomial values from ``(P, 3)`` (scaled) half-angle sines ``s`` and cosines ``c`` (a copy)."""
        return self.basis_rows(np.ascontiguousarray(s.T), np.ascontiguousarray(c.T)).T.copy()

    def derivatives_rows(self, s: np.ndarray, c: np.ndarray, s2: float, directions, values: bool = False,
                         ws: Workspace | None = None) -> tuple[np.ndarray | None, list[np.ndarray]]:
        """From ``(3, P)`` rows: the monomial values ``(F, P)`` (if ``values``) and, per direction ``(du, dv, dw)``,
        ``2s`` times their directional derivatives ``(F, P)`` (bounded; divide by ``2s`` at the end).

        A direction with a zero component (all named ones) costs four products: for ``(x, 0, z)``,
        ``g_v (x g'_u g_w + z g_u g'_w)``; otherwise the three terms are summed.
        """
        ws = Workspace() if ws is None else ws
        shape = (self.F, s.shape[1])
        sp, cp = self._rows(s, c, 1, ws)
        g = [self._gather(self._table(v, sp[v], cp[v], ws), v, ws.get(f"g{v}", shape)) for v in range(3)]
        used = [v for v in range(3) if any(d[v] for d in directions)]
        dg = {v: self._gather(self._dtable(v, sp[v], cp[v], s2, ws), v, ws.get(f"dg{v}", shape)) for v in used}
        tmp = ws.get("tmp", shape)
        outs = []
        for k, d in enumerate(directions):
            outs.append(self._direction(d, g, dg, ws.get(f"o{k}", shape), tmp))
        vals = None
        if values:
            vals = np.multiply(g[0], g[1], out=tmp)
            vals *= g[2]
        return vals, outs

    @staticmethod
    def _direction(d, g: list, dg: dict, o: np.ndarray, tmp: np.ndarray) -> np.ndarray:
        """``o`` = ``sum_v d_v dg_v prod_{w != v} g_w`` (the bracket of the directional derivative), from the gathered
        values ``g`` and brackets ``dg``; ``tmp`` is scratch.  A direction with a zero component costs four products:
        for ``(x, 0, z)``, ``g_v (x g'_u g_w + z g_u g'_w)``; otherwise the three terms are summed."""
        nz = [v for v in range(3) if d[v]]
        if not nz:
            o[...] = 0.0
        elif len(nz) == 1:
            v = nz[0]
            w1, w2 = (w for w in range(3) if w != v)
            np.multiply(dg[v], g[w1], out=o)
            o *= g[w2]
            if d[v] != 1:
                o *= d[v]
        elif len(nz) == 2:
            x, z = nz
            y = 3 - x - z
            np.multiply(dg[x], g[z], out=o)
            if d[x] != 1:
                o *= d[x]
            np.multiply(dg[z], g[x], out=tmp)
            if d[z] == -1:
                o -= tmp
            else:
                if d[z] != 1:
                    tmp *= d[z]
                o += tmp
            o *= g[y]
        else:
            o[...] = 0.0
            for v in range(3):
                w1, w2 = (w for w in range(3) if w != v)
                np.multiply(dg[v], g[w1], out=tmp)
                tmp *= g[w2]
                if d[v] != 1:
                    tmp *= d[v]
                o += tmp
        return o

    def split_net(self, net_t: np.ndarray, chunk: int = CHUNK) -> list[np.ndarray]:
        """The ``(m, F)`` transposed net cut into contiguous column chunks of ``chunk`` functions, the operand of
        :meth:`contract_derivatives` (cut once per call, not per block)."""
        return [np.ascontiguousarray(net_t[:, lo:lo + chunk]) for lo in range(0, self.F, chunk)]

    def contract_derivatives(self, s: np.ndarray, c: np.ndarray, s2: float, directions, nets: list[np.ndarray],
                             values: bool = False, ws: Workspace | None = None
                             ) -> tuple[np.ndarray | None, list[np.ndarray]]:
        """From ``(3, P)`` rows: ``net_t @ values`` (``(m, P)``, if ``values``) and, per direction, ``net_t @`` the
        brackets of :meth:`derivatives_rows` (``2s`` times the directional derivatives), with ``nets`` =
        :meth:`split_net` of the ``(m, F)`` net.

        The same products as :meth:`derivatives_rows`, but the functions are taken :data:`CHUNK` at a time: the
        gathered rows, products and the partial contraction of a chunk stay in the core's cache, where the full
        ``(F, P)`` arrays (five to nine of them) spill to main memory (measured 1.5-2x faster for n >= 3).  The
        chunks are summed in order, so a block's result does not depend on the thread that computes it.  With two or
        more directions (normals) the partial products ``dg_v prod_{w != v} g_w`` of the variables used are contracted
        instead (six products per chunk for ``'u'`` and ``'v'``, not eight) and combined per direction at the end.
        """
        ws = Workspace() if ws is None else ws
        p = s.shape[1]
        chunk = nets[0].shape[1]
        m = nets[0].shape[0]
        sp, cp = self._rows(s, c, 1, ws)
        tabs = [self._table(v, sp[v], cp[v], ws) for v in range(3)]
        used = [v for v in range(3) if any(d[v] for d in directions)]
        dtabs = {v: self._dtable(v, sp[v], cp[v], s2, ws) for v in used}
        outs = [ws.get(f"acc{k}", (m, p)) for k in range(len(directions))]
        vals = ws.get("accv", (m, p)) if values else None
        part = ws.get("part", (m, p))
        parts = {v: ws.get(f"pt{v}", (m, p)) for v in used} if len(directions) > 1 else {}
        for i, net in enumerate(nets):
            lo = i * chunk
            hi = lo + net.shape[1]
            sh = (hi - lo, p)
            g = [np.take(tabs[v], self.index[v][lo:hi], axis=0, out=ws.get(f"cg{v}", sh), mode="clip")
                 for v in range(3)]
            dg = {v: np.take(dtabs[v], self.index[v][lo:hi], axis=0, out=ws.get(f"cd{v}", sh), mode="clip")
                  for v in used}
            o, tmp = ws.get("co", sh), ws.get("ct", sh)
            if len(directions) == 1:
                self._direction(directions[0], g, dg, o, tmp)
                if i == 0:
                    contract(net, o, out=outs[0])
                else:
                    outs[0] += contract(net, o, out=part)
            else:  # contract the partial products dg_v prod_{w != v} g_w, combined per direction after the chunks
                for v in used:
                    w1, w2 = (w for w in range(3) if w != v)
                    np.multiply(dg[v], g[w1], out=o)
                    o *= g[w2]
                    if i == 0:
                        contract(net, o, out=parts[v])
                    else:
                        parts[v] += contract(net, o, out=part)
            if values:
                np.multiply(g[0], g[1], out=o)
                o *= g[2]
                if i == 0:
                    contract(net, o, out=vals)
                else:
                    vals += contract(net, o, out=part)
        if parts:
            for k, d in enumerate(directions):
                o = outs[k]
                o[...] = 0.0
                for v in used:
                    if d[v] == 1:
                        o += parts[v]
                    elif d[v] == -1:
                        o -= parts[v]
                    elif d[v]:
                        o += d[v] * parts[v]
        return vals, outs

    def blocks(self, uvw: np.ndarray, block: int = BLOCK, alpha: float | None = None):
        """Yield ``(slice, basis values (P, F))`` per block of the ``(P, 3)`` points (scaled sines when ``alpha``)."""
        sa = math.sin(alpha / 2) if alpha is not None else 0.0
        for start in range(0, uvw.shape[0], block):
            blk = uvw[start:start + block]
            if alpha is None:
                half = np.ascontiguousarray(blk.T) * 0.5
                s, c = np.sin(half), np.cos(half)
            else:
                s, c = scaled_trig_rows(blk, alpha, sa)
            yield slice(start, start + blk.shape[0]), self.basis_rows(s, c).T.copy()

    def contract(self, uvw: np.ndarray, net: np.ndarray, weights: np.ndarray | None = None,
                 block: int = BLOCK, alpha: float | None = None, workers: int | None = None) -> np.ndarray:
        """``sum_f B_f(p) net_f`` (or the rational form with ``weights``) at every point: ``(P, d)``.

        ``net`` must already carry the normalizing coefficients (rows ``coef_f * point_f``; the scaled
        coefficients ``s^{2n+j} r`` when ``alpha`` is given, then the sines are scaled too); for a rational
        patch ``weights`` are ``coef_f * w_f`` and ``net`` rows ``coef_f * w_f * point_f``.
        """
        out = np.empty((uvw.shape[0], net.shape[1]))
        sa = math.sin(alpha / 2) if alpha is not None else 0.0
        aug_t = np.ascontiguousarray((net if weights is None else np.column_stack([net, weights])).T)

        def work(lo: int, hi: int, ws: Workspace) -> None:
            blk = uvw[lo:hi]
            if alpha is None:
                half = np.ascontiguousarray(blk.T) * 0.5
                s, c = np.sin(half), np.cos(half)
            else:
                s, c = scaled_trig_rows(blk, alpha, sa)
            y = aug_t @ self.basis_rows(s, c, ws)
            if weights is None:
                out[lo:hi] = y.T
            else:
                out[lo:hi] = (y[:-1] / y[-1]).T

        run_blocks(uvw.shape[0], work, block, workers)
        return out
