"""The compiled kernel of the fast float64 path (optional: ``numba``, ``pip install paper_repro[fast]``).

The same products as :class:`paper_repro.core.fast.FloatKernel`, fused into one loop per tile of
:data:`TILE` points, so the ``(delta_n, P)`` basis matrix is never stored: per tile the power rows of the scaled
half-angle sines ``S`` and cosines ``c`` (computed by numpy, so both paths start from the same bits), the table of
the distinct products ``S^a c^b`` of each variable, then for each function ``f`` in order the basis value
``(t_u * t_v) * t_w`` and its contribution to every coordinate.  The basis values are bitwise those of the numpy
path; the contraction sums the functions in their order, where the numpy path's BLAS product sums in an order of
its own, so the two paths differ by rounding only: at most ``gamma_F sum_f |B_f| |p_f|`` per coordinate
(``gamma_F = F u / (1 - F u)``, ``u = 2^-53``; both are dot products of the same F terms), tested in
``tests/test_fast_jit.py``.  Every point is computed by the same operations whatever its tile, block or thread,
so the result does not depend on the number of threads.

Derivatives and normals: for every n a patch's derivative is a patch of the same order (the derivative matrix C in
closed form, :mod:`paper_repro.core.half_angle_matrices`; proven for every n in
docs/elevation_and_derivative_for_all_n.md, no longer a found pattern), so they run through the values pass with the
derivative nets (the normals' two directions as 6 coordinates in one group, :data:`GROUP`).  The derivative pass
(:func:`_derivs_impl`, the monomials' brackets) is kept as an independent cross-check in the tests.

The functions take ``nogil=True``: the kernel's thread pool (:func:`paper_repro.core.fast.run_blocks`) runs blocks
side by side.  ``PAPER_REPRO_KERNEL=numpy`` turns this path off.
"""

from __future__ import annotations

import importlib.util
import os
import sys
import threading

import numpy as np

#: Points per tile inside the compiled loop: the tables (about 40-120 rows) and the accumulators of a tile stay
#: in the core's L1/L2 cache.
TILE = 256

#: Coordinates per pass over the functions in the values kernel: 6 takes a patch's two derivatives (normals) in one
#: pass, the basis value computed once per function and point.
GROUP = 6

#: Points per block of the compiled path (a block is one call from a thread of
#: :func:`paper_repro.core.fast.run_blocks`): the numpy work around the call (the trigonometric rows) is per block.
JIT_BLOCK = 8192

#: numba's module spec when it is installed (found without importing it: ``import numba`` takes 0.7 s, paid on the
#: first compiled evaluation only, not by every ``import paper_repro``)
_numba = importlib.util.find_spec("numba")


KERNELS = ("auto", "numba", "numpy")


def available() -> bool:
    """True when the compiled path runs.  ``PAPER_REPRO_KERNEL``: ``auto`` (or unset: numba when it is installed),
    ``numba`` (required: an error without it) or ``numpy``.

    >>> import os; os.environ["PAPER_REPRO_KERNEL"] = "numpy"; available()
    False
    >>> del os.environ["PAPER_REPRO_KERNEL"]
    """
    choice = os.environ.get("PAPER_REPRO_KERNEL", "").strip().lower() or "auto"
    if choice not in KERNELS:
        raise ValueError(f"PAPER_REPRO_KERNEL must be one of {', '.join(KERNELS)}, got {choice!r}")
    if choice == "numba" and _numba is None:
        raise ValueError("PAPER_REPRO_KERNEL=numba, but numba is not installed (pip install 'paper_repro[fast]')")
    return choice != "numpy" and _numba is not None


def _powers_tile(x, top, out, lo, n):
    for p in range(n):
        out[0, p] = 1.0
    for k in range(1, top + 1):
        for p in range(n):
            out[k, p] = out[k - 1, p] * x[lo + p]


def _tables(S, C, lo, n, pa, pb, var_of, smax, cmax, sp, cp, tab):
    """tab[q, :n] = S_v^a c_v^b for every pair q (variable var_of[q]) of the tile starting at point lo."""
    for v in range(3):
        _powers_tile(S[v], smax[v], sp[v], lo, n)
        _powers_tile(C[v], cmax[v], cp[v], lo, n)
    for q in range(pa.shape[0]):
        v = var_of[q]
        a = pa[q]
        b = pb[q]
        for p in range(n):
            tab[q, p] = sp[v, a, p] * cp[v, b, p]


def _dtables(n, pa, pb, var_of, s2, sp, cp, dtab):
    """dtab[q] = a S^(a-1) c^(b+1) - (b s2) S^(a+1) c^(b-1): the operations of FloatKernel._dtable, in its order."""
    for q in range(pa.shape[0]):
        v = var_of[q]
        a = pa[q]
        b = pb[q]
        am = a - 1 if a > 0 else 0
        bm = b - 1 if b > 0 else 0
        fa = float(a)
        bs = b * s2
        if s2 != 0.0:
            for p in range(n):
                dtab[q, p] = (sp[v, am, p] * cp[v, b + 1, p]) * fa - (sp[v, a + 1, p] * cp[v, bm, p]) * bs
        else:
            for p in range(n):
                dtab[q, p] = (sp[v, am, p] * cp[v, b + 1, p]) * fa


def _vgroup(tab, i0, i1, i2, n, kw, c0, c1, c2, c3, c4, c5, acc):
    """acc[k, p] += c_k * B(p) for the kw <= 6 coordinates of one group (one pass over the tile, B in a register)."""
    if kw == 6:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g
            acc[1, p] += c1 * g
            acc[2, p] += c2 * g
            acc[3, p] += c3 * g
            acc[4, p] += c4 * g
            acc[5, p] += c5 * g
    elif kw == 5:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g
            acc[1, p] += c1 * g
            acc[2, p] += c2 * g
            acc[3, p] += c3 * g
            acc[4, p] += c4 * g
    elif kw == 4:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g
            acc[1, p] += c1 * g
            acc[2, p] += c2 * g
            acc[3, p] += c3 * g
    elif kw == 3:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g
            acc[1, p] += c1 * g
            acc[2, p] += c2 * g
    elif kw == 2:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g
            acc[1, p] += c1 * g
    else:
        for p in range(n):
            g = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
            acc[0, p] += c0 * g


def _coefs(net, k0, kw, f):
    c0 = net[k0, f]
    c1 = net[k0 + 1, f] if kw > 1 else 0.0
    c2 = net[k0 + 2, f] if kw > 2 else 0.0
    c3 = net[k0 + 3, f] if kw > 3 else 0.0
    c4 = net[k0 + 4, f] if kw > 4 else 0.0
    c5 = net[k0 + 5, f] if kw > 5 else 0.0
    return c0, c1, c2, c3, c4, c5


def _values_impl(S, C, pa, pb, var_of, smax, cmax, idx, net, out):
    """out[p, k] = sum_f net[k, f] * B_f(p) for the (3, P) rows S, C; out is (P, m).  The coordinates are taken
    :data:`GROUP` at a time (one pass over the functions per group), each sum in the order of the functions."""
    P = S.shape[1]
    m = net.shape[0]
    F = idx.shape[1]
    top = max(max(smax), max(cmax))
    sp = np.empty((3, top + 2, TILE))
    cp = np.empty((3, top + 2, TILE))
    tab = np.empty((pa.shape[0], TILE))
    acc = np.empty((GROUP, TILE))
    for lo in range(0, P, TILE):
        n = min(TILE, P - lo)
        _tables(S, C, lo, n, pa, pb, var_of, smax, cmax, sp, cp, tab)
        for k0 in range(0, m, GROUP):
            kw = min(GROUP, m - k0)
            acc[:, :n] = 0.0
            for f in range(F):
                c0, c1, c2, c3, c4, c5 = _coefs(net, k0, kw, f)
                _vgroup(tab, idx[0, f], idx[1, f], idx[2, f], n, kw, c0, c1, c2, c3, c4, c5, acc)
            for p in range(n):
                for k in range(kw):
                    out[lo + p, k0 + k] = acc[k, p]


def _d1_k3(tab, dtab, i0, i1, i2, n, e0, e1, e2, c0, c1, c2, acc):
    """One function's contribution to three coordinates, one direction: the bracket
    ``(e_0 q_0 + e_1 q_1) + e_2 q_2`` (``q_v = dg_v g_w1 g_w2``, w1 < w2) per point, in registers."""
    for p in range(n):
        g0 = tab[i0, p]
        g1 = tab[i1, p]
        g2 = tab[i2, p]
        o = (e0 * ((dtab[i0, p] * g1) * g2) + e1 * ((dtab[i1, p] * g0) * g2)) + e2 * ((dtab[i2, p] * g0) * g1)
        acc[0, p] += c0 * o
        acc[1, p] += c1 * o
        acc[2, p] += c2 * o


def _d1z_k3(tab, dtab, ix, iy, iz, n, ex, ez, c0, c1, c2, acc):
    """:func:`_d1_k3` for a direction whose component of variable y is 0 (the named directions 'u', 'v', 'w'):
    ``e_x (dg_x g_y) g_z + e_z (dg_z g_x) g_y``, two partial products instead of three."""
    for p in range(n):
        gx = tab[ix, p]
        gy = tab[iy, p]
        gz = tab[iz, p]
        o = ex * ((dtab[ix, p] * gy) * gz) + ez * ((dtab[iz, p] * gx) * gy)
        acc[0, p] += c0 * o
        acc[1, p] += c1 * o
        acc[2, p] += c2 * o


def _d2_k3(tab, dtab, i0, i1, i2, n, e, c0, c1, c2, acc):
    """:func:`_d1_k3` for two directions (the rows of ``e``) at once (normals), into acc rows 0-2 and 3-5."""
    e00, e01, e02 = e[0, 0], e[0, 1], e[0, 2]
    e10, e11, e12 = e[1, 0], e[1, 1], e[1, 2]
    for p in range(n):
        g0 = tab[i0, p]
        g1 = tab[i1, p]
        g2 = tab[i2, p]
        q0 = (dtab[i0, p] * g1) * g2
        q1 = (dtab[i1, p] * g0) * g2
        q2 = (dtab[i2, p] * g0) * g1
        o = (e00 * q0 + e01 * q1) + e02 * q2
        o2 = (e10 * q0 + e11 * q1) + e12 * q2
        acc[0, p] += c0 * o
        acc[1, p] += c1 * o
        acc[2, p] += c2 * o
        acc[3, p] += c0 * o2
        acc[4, p] += c1 * o2
        acc[5, p] += c2 * o2


def _uv_k3(tab, dtab, i0, i1, i2, n, c0, c1, c2, acc):
    """:func:`_d2_k3` for the directions u = (1, 0, -1) and v = (0, 1, -1) (normals): ``q_0 - q_2`` and
    ``q_1 - q_2``, the same bits as the general bracket (a product by 1 is exact, a product by 0 adds a zero)."""
    for p in range(n):
        g0 = tab[i0, p]
        g1 = tab[i1, p]
        g2 = tab[i2, p]
        q2 = (dtab[i2, p] * g0) * g1
        o = (dtab[i0, p] * g1) * g2 - q2
        o2 = (dtab[i1, p] * g0) * g2 - q2
        acc[0, p] += c0 * o
        acc[1, p] += c1 * o
        acc[2, p] += c2 * o
        acc[3, p] += c0 * o2
        acc[4, p] += c1 * o2
        acc[5, p] += c2 * o2


def _derivs_impl(S, C, pa, pb, var_of, smax, cmax, idx, net, s2, dirs, values, outs, vals):
    """Per direction row of ``dirs`` ((D, 3) floats), ``outs[r, k, p] = sum_f net[k, f] * bracket_r,f(p)`` (2s times
    the directional derivative of B_f), and with ``values`` also ``vals[k, p] = sum_f net[k, f] B_f(p)``: rows, the
    layout of :meth:`paper_repro.core.fast.FloatKernel.contract_derivatives`.

    Per function and point the partial products ``q_v = dg_v g_w1 g_w2`` (w1 < w2), the bracket
    ``(d_0 q_0 + d_1 q_1) + d_2 q_2`` of each direction, contracted with the net.  Three coordinates with one or two
    directions and no values (the common case: a 3D patch, its derivative or normals) run in one straight pass per
    function (:func:`_d1_k3`, :func:`_d1z_k3`, :func:`_d2_k3`, and :func:`_uv_k3` for the normals' u and v);
    otherwise the same products go through rows of the tile."""
    P = S.shape[1]
    m = net.shape[0]
    F = idx.shape[1]
    D = dirs.shape[0]
    top = max(max(smax), max(cmax)) + 1
    sp = np.empty((3, top + 2, TILE))
    cp = np.empty((3, top + 2, TILE))
    tab = np.empty((pa.shape[0], TILE))
    dtab = np.empty((pa.shape[0], TILE))
    smax1 = smax + 1
    cmax1 = cmax + 1
    fast = m == 3 and not values and D <= 2
    g = np.empty(TILE)
    o = np.empty(TILE)
    part = np.empty((3, TILE))
    acc = np.empty((D, m, TILE))
    acc3 = np.empty((6, TILE))
    vacc = np.empty((m, TILE))
    # the straight pass of the fast case, chosen once: one direction with exactly one zero component (two partial
    # products, zero = that component), the normals' u and v, or the general one- or two-direction pass
    zero = -1
    if D == 1 and (dirs[0, 0] == 0.0) + (dirs[0, 1] == 0.0) + (dirs[0, 2] == 0.0) == 1:
        zero = 0 if dirs[0, 0] == 0.0 else (1 if dirs[0, 1] == 0.0 else 2)
    x = (zero + 1) % 3
    z = (zero + 2) % 3
    uv = (D == 2 and dirs[0, 0] == 1.0 and dirs[0, 1] == 0.0 and dirs[0, 2] == -1.0
          and dirs[1, 0] == 0.0 and dirs[1, 1] == 1.0 and dirs[1, 2] == -1.0)
    for lo in range(0, P, TILE):
        n = min(TILE, P - lo)
        _tables(S, C, lo, n, pa, pb, var_of, smax1, cmax1, sp, cp, tab)  # power rows one further
        _dtables(n, pa, pb, var_of, s2, sp, cp, dtab)
        if fast:
            acc3[:, :n] = 0.0
            for f in range(F):
                if zero >= 0:
                    _d1z_k3(tab, dtab, idx[x, f], idx[zero, f], idx[z, f], n, dirs[0, x], dirs[0, z],
                            net[0, f], net[1, f], net[2, f], acc3)
                elif uv:
                    _uv_k3(tab, dtab, idx[0, f], idx[1, f], idx[2, f], n, net[0, f], net[1, f], net[2, f], acc3)
                elif D == 1:
                    _d1_k3(tab, dtab, idx[0, f], idx[1, f], idx[2, f], n, dirs[0, 0], dirs[0, 1], dirs[0, 2],
                           net[0, f], net[1, f], net[2, f], acc3)
                else:
                    _d2_k3(tab, dtab, idx[0, f], idx[1, f], idx[2, f], n, dirs, net[0, f], net[1, f], net[2, f],
                           acc3)
            for r in range(D):
                for k in range(3):
                    for p in range(n):
                        outs[r, k, lo + p] = acc3[3 * r + k, p]
            continue
        acc[:, :, :n] = 0.0
        vacc[:, :n] = 0.0
        for f in range(F):
            i0 = idx[0, f]
            i1 = idx[1, f]
            i2 = idx[2, f]
            for p in range(n):
                g0 = tab[i0, p]
                g1 = tab[i1, p]
                g2 = tab[i2, p]
                part[0, p] = (dtab[i0, p] * g1) * g2
                part[1, p] = (dtab[i1, p] * g0) * g2
                part[2, p] = (dtab[i2, p] * g0) * g1
            for r in range(D):
                e0 = dirs[r, 0]
                e1 = dirs[r, 1]
                e2 = dirs[r, 2]
                for p in range(n):
                    o[p] = (e0 * part[0, p] + e1 * part[1, p]) + e2 * part[2, p]
                for k in range(m):
                    c = net[k, f]
                    for p in range(n):
                        acc[r, k, p] += c * o[p]
            if values:
                for p in range(n):
                    g[p] = (tab[i0, p] * tab[i1, p]) * tab[i2, p]
                for k in range(m):
                    c = net[k, f]
                    for p in range(n):
                        vacc[k, p] += c * g[p]
        for r in range(D):
            for k in range(m):
                for p in range(n):
                    outs[r, k, lo + p] = acc[r, k, p]
        if values:
            for k in range(m):
                for p in range(n):
                    vals[k, lo + p] = vacc[k, p]


_COMPILED: dict | None = None
#: numba cache files found bad in this process (one warning for all of them)
_BAD_CACHE: list[str] = []


def _safe_cache_class():
    """A numba ``FunctionCache`` that never lets a corrupted cache file reach the user: a truncated, empty or garbage
    ``.nbi``/``.nbc`` (``UnpicklingError``, ``EOFError``, or any error while rebuilding) is deleted, the function is
    compiled afresh and its cache rewritten, with one :class:`~paper_repro.util.cache.CacheWarning` per process; a
    cache that cannot be saved is skipped."""
    import glob
    import warnings

    from numba.core.caching import FunctionCache

    from paper_repro.util.cache import CacheWarning

    class SafeFunctionCache(FunctionCache):
        def _drop(self, exc: BaseException) -> None:
            cache_file = self._cache_file
            index = cache_file._index_path
            stem = index[: -len(".nbi")]
            for path in [index, *glob.glob(glob.escape(stem) + ".*.nbc")]:
                try:
                    os.unlink(path)
                except OSError:
                    pass
            if not _BAD_CACHE:
                warnings.warn(f"numba's cache of the compiled kernel was unreadable ({type(exc).__name__}: {exc}, "
                              f"{os.path.dirname(index)}): recompiled and rewritten", CacheWarning, stacklevel=2)
            _BAD_CACHE.append(index)

        def load_overload(self, sig, target_context):
            try:
                return super().load_overload(sig, target_context)
            except Exception as exc:  # noqa: BLE001 - any failure to read the cache means: compile
                self._drop(exc)
                return None

        def save_overload(self, sig, data):
            try:
                super().save_overload(sig, data)
            except Exception as exc:  # noqa: BLE001 - a cache that cannot be written is only skipped
                self._drop(exc)

    return SafeFunctionCache


_ANNOUNCED: set[str] = set()
_ANNOUNCE_LOCK = threading.Lock()


def _is_cached(dispatcher) -> bool:
    """Whether numba's on-disk cache holds an index for ``dispatcher`` (True when that cannot be told)."""
    try:
        return os.path.exists(dispatcher._cache._cache_file._index_path)  # numba's FunctionCache: its index file
    except AttributeError:
        return True


def announce_compilation(kind: str, stream=None) -> bool:
    """Say once per process, on stderr, that the first evaluation compiles (10-17 s of silence before).

    ``kind`` is ``"values"`` or ``"derivatives"``; nothing is said when numba's on-disk cache already holds the
    function (a later process loads it in about 1 s).  Returns whether a line was written.
    """
    with _ANNOUNCE_LOCK:
        if kind in _ANNOUNCED:
            return False
        _ANNOUNCED.add(kind)
        from paper_repro.util.cache import cache_dir, enabled

        if enabled() and _is_cached(_compiled()[kind]):
            return False

        where = (f"once per environment, kept in {cache_dir() / 'numba'}" if enabled()
                 else "in every process, since PAPER_REPRO_NO_CACHE is set")
        what = "point" if kind == "values" else "derivative"
        print(f"paper_repro: compiling the float64 {what} kernel (numba, about 10-20 s; {where})",
              file=stream or sys.stderr, flush=True)
        return True


def _compiled() -> dict:
    """The compiled functions, built on first use.  numba's on-disk cache goes to ``<cache_dir>/numba``
    (:func:`paper_repro.util.cache.cache_dir`; ``NUMBA_CACHE_DIR`` if set), never into the install location:
    a fresh process loads them in a fraction of a second instead of compiling for about 10 s.  With
    ``PAPER_REPRO_NO_CACHE`` set, or a cache folder that cannot be written (one
    :class:`~paper_repro.util.cache.CacheWarning`), nothing is written and every process compiles; a corrupted cache
    file is recompiled and rewritten (:func:`_safe_cache_class`).  No fast-math: no reassociation, no fused
    multiply-add, so the bits do not depend on the CPU's instruction set."""
    global _COMPILED
    if _COMPILED is None:
        import numba

        from paper_repro.util.cache import cache_dir, enabled, unusable, warn_unusable

        use_cache = enabled()
        if use_cache and not os.environ.get("NUMBA_CACHE_DIR"):
            folder = cache_dir() / "numba"
            why = unusable(folder)
            if why is None:
                setattr(numba.config, "CACHE_DIR", str(folder))  # noqa: B010 (config has no stubs)
            else:  # numba would fall back to __pycache__ beside the package, i.e. the install location
                warn_unusable(why)
                use_cache = False
        safe = _safe_cache_class() if use_cache else None

        def jit(func):
            disp = numba.njit(nogil=True, cache=False, fastmath=False, error_model="numpy")(func)
            if safe is not None:
                disp._cache = safe(func)  # what ``cache=True`` does (Dispatcher.enable_caching), with checks
            return disp

        g = globals()
        for name in ("_powers_tile", "_tables", "_dtables", "_vgroup", "_coefs", "_d1_k3", "_d1z_k3", "_d2_k3",
                     "_uv_k3"):
            g[name] = jit(g[name + "_py"])
        _COMPILED = {"values": jit(_values_impl), "derivatives": jit(_derivs_impl)}
    return _COMPILED


_powers_tile_py, _tables_py, _dtables_py = _powers_tile, _tables, _dtables
_vgroup_py, _coefs_py, _d1_k3_py, _d2_k3_py, _d1z_k3_py = _vgroup, _coefs, _d1_k3, _d2_k3, _d1z_k3
_uv_k3_py = _uv_k3


class JitKernel:
    """The compiled evaluator of the monomials with exponent rows ``exps`` (``(F, 6)``), with the tables of a
    :class:`~paper_repro.core.fast.FloatKernel` (the same distinct pairs per variable)."""

    def __init__(self, kernel):
        pa, pb, var_of = [], [], []
        off = []
        start = 0
        for v in range(3):
            pairs = kernel.pairs[v]
            pa.append(pairs[:, 0])
            pb.append(pairs[:, 1])
            var_of.append(np.full(len(pairs), v))
            off.append(start)
            start += len(pairs)
        self.pa = np.ascontiguousarray(np.concatenate(pa), dtype=np.int64)
        self.pb = np.ascontiguousarray(np.concatenate(pb), dtype=np.int64)
        self.var_of = np.ascontiguousarray(np.concatenate(var_of), dtype=np.int64)
        self.idx = np.ascontiguousarray(np.stack([kernel.index[v] + off[v] for v in range(3)]), dtype=np.int64)
        self.smax = np.array(kernel.smax, dtype=np.int64)
        self.cmax = np.array(kernel.cmax, dtype=np.int64)

    def values(self, s: np.ndarray, c: np.ndarray, net_t: np.ndarray, out: np.ndarray) -> np.ndarray:
        """``out[p] = net_t @ B(p)`` for ``(3, P)`` rows ``s``, ``c``; ``net_t`` is ``(m, F)``, ``out`` ``(P, m)``."""
        if "values" not in _ANNOUNCED:
            announce_compilation("values")
        _compiled()["values"](s, c, self.pa, self.pb, self.var_of, self.smax, self.cmax, self.idx, net_t, out)
        return out

    def derivatives(self, s, c, s2: float, dirs: np.ndarray, net_t: np.ndarray, outs: np.ndarray, vals=None):
        """Per direction row of ``dirs``, ``outs[r]`` (``(D, m, P)``) the contracted brackets (2s times the directional
        derivatives); ``vals`` (``(m, P)``) the values, if given."""
        if "derivatives" not in _ANNOUNCED:
            announce_compilation("derivatives")
        dirs = np.ascontiguousarray(dirs, dtype=np.float64)
        for r in range(0, dirs.shape[0], 2):  # the kernel takes one or two directions per pass
            with_values = vals is not None and r == 0
            _compiled()["derivatives"](s, c, self.pa, self.pb, self.var_of, self.smax, self.cmax, self.idx, net_t,
                                       float(s2), dirs[r:r + 2], with_values, outs[r:r + 2],
                                       vals if with_values else outs[r])
        return vals, outs
