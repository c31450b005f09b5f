"""``--scheduler``: the sweeps on a ``dask.distributed`` cluster (docs/cluster.md).

* ``local:N`` starts a ``LocalCluster`` of N worker processes (one thread each) on this machine;
* ``tcp://HOST:PORT`` (or ``tls://``) connects to a running scheduler (``dask scheduler``, ``dask worker``).

``PAPER_REPRO_SCHEDULER`` gives the same value when the option is not given.  Before any work, every worker is
asked for its ``paper_repro.__version__``, the sha256 of its package source (the code fingerprint that keys the
cache) and its numpy and python-flint versions; a worker without the package, or with other versions than this
process and the lock, stops the run with one line (:class:`ClusterMismatch`).

>>> parse_scheduler("local:2")
('local', 2)
>>> parse_scheduler("tcp://10.0.0.5:8786")
('address', 'tcp://10.0.0.5:8786')
>>> parse_scheduler("local:0")
Traceback (most recent call last):
...
ValueError: --scheduler: expected 'local:N' (N from 1 to 512 worker processes) or 'tcp://HOST:PORT', got 'local:0'
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

SCHEDULER_ENV = "PAPER_REPRO_SCHEDULER"
MAX_LOCAL = 512
#: distributions whose versions must agree on every worker (numerical results depend on them)
PINNED = ("numpy", "python-flint")


class ClusterMismatch(ValueError):
    """A worker lacks the package or runs other versions than this process and the lock (one line)."""


def parse_scheduler(text: str, option: str = "--scheduler") -> tuple[str, Any]:
    """``("local", N)`` or ``("address", "tcp://HOST:PORT")``; ``ValueError`` naming ``option`` otherwise."""
    allowed = (f"{option}: expected 'local:N' (N from 1 to {MAX_LOCAL} worker processes) or 'tcp://HOST:PORT', "
               f"got {text!r}")
    m = re.fullmatch(r"local:(\d{1,4})", text or "")
    if m:
        n = int(m.group(1))
        if not 1 <= n <= MAX_LOCAL:
            raise ValueError(allowed)
        return "local", n
    m = re.fullmatch(r"(tcp|tls)://([A-Za-z0-9.\-]+|\[[0-9A-Fa-f:]+\]):(\d{1,5})", text or "")
    if m and 1 <= int(m.group(3)) <= 65535:
        return "address", text
    raise ValueError(allowed)


#: seconds a wrong ``--scheduler`` address may cost at most: the connect, then the peer's first bytes
PROBE_SECONDS = 4.0
#: a dask comm frame header: the count of frames, then one 8-byte length per frame (distributed.comm.utils)
_MAX_FRAMES, _MAX_FRAME = 64, 1 << 30


def _split_address(address: str) -> tuple[str, str, int]:
    scheme, rest = address.split("://", 1)
    host, port = rest.rsplit(":", 1)
    return scheme, host.strip("[]"), int(port)


def tls_security():
    """The ``distributed.Security`` that dask's configuration supplies for ``tls://`` (a client certificate or CA
    named under ``distributed.comm.tls``), else ``ValueError`` saying how to configure it (docs/cluster.md)."""
    import dask
    from distributed.security import Security

    sec = Security()
    if not (sec.tls_ca_file or sec.tls_client_cert or dask.config.get("distributed.comm.tls.client.cert", None)):
        raise ValueError("--scheduler: a tls:// address needs TLS settings in dask's configuration "
                         "(distributed.comm.tls.ca-file, .client.cert, .client.key; see docs/cluster.md); none are set")
    return sec


def probe_scheduler(address: str, seconds: float = PROBE_SECONDS) -> None:
    """Refuse in one line, within about ``2 * seconds``, an address where no dask scheduler listens: nothing there,
    a refused port, an unknown host, or a peer that does not open with dask's handshake (an HTTP server, the
    dashboard port, a peer that holds the connection silently).  A dask listener writes its handshake as soon as it
    accepts (``distributed.comm.core``): 8 bytes counting the frames, then 8 bytes per frame length.  ``tls://`` is
    probed for the connection only (the handshake is encrypted) and needs :func:`tls_security`.

    >>> probe_scheduler("tcp://127.0.0.1:1", 1.0)
    Traceback (most recent call last):
    ...
    ValueError: --scheduler: no dask scheduler answers at tcp://127.0.0.1:1 (connection refused)
    """
    import socket
    import struct

    scheme, host, port = _split_address(address)
    where = f"--scheduler: no dask scheduler answers at {address}"
    try:
        sock = socket.create_connection((host, port), timeout=seconds)
    except ConnectionRefusedError:
        raise ValueError(f"{where} (connection refused)") from None
    except socket.gaierror:
        raise ValueError(f"{where} (unknown host {host})") from None
    except TimeoutError:
        raise ValueError(f"{where} (no answer to the connection within {seconds:g} s)") from None
    except OSError as exc:
        raise ValueError(f"{where} ({exc.strerror or type(exc).__name__})") from None
    with sock:
        if scheme == "tls":
            return
        sock.settimeout(seconds)
        head = b""
        try:
            while len(head) < 16:
                chunk = sock.recv(16 - len(head))
                if not chunk:
                    break
                head += chunk
        except TimeoutError:
            raise ValueError(f"{where} (the peer accepted the connection but sent no dask handshake within "
                             f"{seconds:g} s: is this the dashboard or another service's port? a scheduler usually "
                             f"listens on 8786)") from None
        except OSError as exc:
            raise ValueError(f"{where} ({exc.strerror or type(exc).__name__})") from None
    if len(head) < 16:
        raise ValueError(f"{where} (the peer closed the connection without a dask handshake)")
    nframes, first = struct.unpack("<QQ", head)
    if not (1 <= nframes <= _MAX_FRAMES and first <= _MAX_FRAME) or head.startswith((b"HTTP", b"SSH-", b"<")):
        raise ValueError(f"{where} (the peer does not speak dask's protocol: it opened with {head[:8]!r})")


def scheduler_from(option: str | None) -> tuple[str, Any] | None:
    """The parsed ``--scheduler`` value, else ``PAPER_REPRO_SCHEDULER``'s, else ``None`` (local processes)."""
    if option is not None:
        return parse_scheduler(option, "--scheduler")
    env = os.environ.get(SCHEDULER_ENV)
    if env:
        return parse_scheduler(env, SCHEDULER_ENV)
    return None


def expected_versions() -> dict[str, str | None]:
    """What every worker must have: this process's paper_repro version and code fingerprint, and the lock's
    numpy and python-flint pins (this process's own versions outside a checkout)."""
    from importlib.metadata import PackageNotFoundError, version

    import paper_repro
    from paper_repro.util.cache import code_fingerprint
    from paper_repro.util.io import ROOT, in_checkout

    out: dict[str, str | None] = {"paper_repro": paper_repro.__version__, "code": code_fingerprint()}
    pins = {}
    lock = ROOT / "requirements.lock"
    if in_checkout() and lock.exists():
        for line in lock.read_text().splitlines():
            if "==" in line:
                name, ver = line.split()[0].split("==")
                pins[re.sub(r"[-_.]+", "-", name).lower()] = ver
    for dist in PINNED:
        try:
            out[dist] = pins.get(dist) or version(dist)
        except PackageNotFoundError:
            out[dist] = None
    return out


def _probe():
    """What a worker runs (pickled by value: it needs nothing importable beyond the standard library)."""

    def probe() -> dict:
        from importlib.metadata import PackageNotFoundError, version

        out: dict = {}
        try:
            import paper_repro
            from paper_repro.util.cache import code_fingerprint

            out["paper_repro"] = paper_repro.__version__
            out["code"] = code_fingerprint()
        except Exception:  # noqa: BLE001 - no package (or a broken one): reported as missing
            out["paper_repro"] = out["code"] = None
        for dist in ("numpy", "python-flint"):
            try:
                out[dist] = version(dist)
            except PackageNotFoundError:
                out[dist] = None
        return out

    return probe


def mismatch(workers: dict[str, dict], expected: dict[str, str | None], where: str) -> str | None:
    """One line naming the first worker that differs from ``expected`` (and how many do), else ``None``.

    >>> ok = {"paper_repro": "1.0", "code": "ab", "numpy": "2.0", "python-flint": "0.7"}
    >>> mismatch({"tcp://w:1": ok}, ok, "local:1") is None
    True
    >>> print(mismatch({"tcp://w:1": dict(ok, paper_repro=None)}, ok, "tcp://s:8786"))
    scheduler tcp://s:8786: worker tcp://w:1 cannot import paper_repro (1 of 1 workers differ); install the same \
paper_repro, numpy 2.0 and python-flint 0.7 on every worker (docs/cluster.md)
    """
    if not workers:
        return f"scheduler {where}: no worker connected (start workers with `dask worker {where}`; docs/cluster.md)"
    bad = {w: v for w, v in sorted(workers.items()) if any(v.get(k) != expected[k] for k in expected)}
    if not bad:
        return None
    w, v = next(iter(bad.items()))
    if v.get("paper_repro") is None:
        what = "cannot import paper_repro"
    else:
        diffs = [f"{k} {v.get(k)} (here {expected[k]})" for k in expected if v.get(k) != expected[k]]
        what = "has " + ", ".join(diffs).replace("code ", "package source sha256 ")
    return (f"scheduler {where}: worker {w} {what} ({len(bad)} of {len(workers)} workers differ); install the same "
            f"paper_repro, numpy {expected['numpy']} and python-flint {expected['python-flint']} on every worker "
            "(docs/cluster.md)")


def check_workers(client, where: str, expected: dict[str, str | None] | None = None) -> int:
    """:class:`ClusterMismatch` if a worker differs (see :func:`mismatch`); returns the number of workers."""
    workers = client.run(_probe())
    line = mismatch(workers, expected or expected_versions(), where)
    if line:
        raise ClusterMismatch(line)
    return len(workers)


def fresh_workers(client, where: str) -> bool:
    """Restart the cluster's worker processes (through their nannies) before a sweep's next round, as the local
    process pool starts fresh processes for every round.  Measured (2 workers, this machine): a worker process that
    has run the first round's claims computes the identity proofs of the second round -- big-integer polynomial
    products in flint -- 2.7 times slower (479 against 175 CPU s); the cause inside the process was not found.
    A worker without a nanny cannot be restarted: then the round runs on the old processes (one line says so)."""
    try:
        client.restart(timeout="120s", wait_for_workers=True)
        return True
    except Exception as exc:  # noqa: BLE001 - only slower without it
        print(f"scheduler {where}: workers not restarted before the next round ({type(exc).__name__}); "
              "the round runs on the same processes", flush=True)
        return False


@contextmanager
def open_executor(spec: tuple[str, Any], *, expected: dict[str, str | None] | None = None,
                  timeout: float = 20.0) -> Iterator[Any]:
    """A ``concurrent.futures`` executor on the cluster of ``spec`` (:func:`parse_scheduler`), its workers
    checked; on exit (Ctrl-C included) pending tasks are cancelled, the client closed and a local cluster stopped."""
    import logging

    try:
        import distributed
    except ImportError as exc:
        raise ValueError("--scheduler needs dask.distributed: pip install 'paper_repro[dask]' (it is in "
                         "requirements.lock)") from exc
    kind, value = spec
    cluster, security = None, None
    where = f"local:{value}" if kind == "local" else value
    if kind == "local":
        cluster = distributed.LocalCluster(n_workers=value, threads_per_worker=1, processes=True,
                                           dashboard_address=None, silence_logs=logging.CRITICAL)
        address = cluster.scheduler_address
    else:
        address = value
        security = tls_security() if address.startswith("tls://") else None
        probe_scheduler(address)
    try:
        try:
            import dask

            with dask.config.set({"distributed.comm.timeouts.connect": f"{min(timeout, 8.0)}s"}):
                client = distributed.Client(address, timeout=f"{min(timeout, 8.0)}s", set_as_default=False,
                                            **({"security": security} if security else {}))
        except (OSError, TimeoutError, ValueError) as exc:
            raise ValueError(f"--scheduler: no dask scheduler answers at {address} ({type(exc).__name__})") from None
        try:
            if kind == "local":
                client.wait_for_workers(value, timeout=f"{max(timeout, 60.0)}s")
            n = check_workers(client, where, expected)
            print(f"scheduler {where}: {n} workers, versions checked", flush=True)
            executor = client.get_executor()
            executor.fresh_workers = lambda: fresh_workers(client, where)
            try:
                yield executor
            except BaseException:
                executor.shutdown(wait=False)  # cancels the cluster's pending tasks of this run
                raise
        finally:
            client.close(timeout=5)
    finally:
        if cluster is not None:
            cluster.close(timeout=5)
