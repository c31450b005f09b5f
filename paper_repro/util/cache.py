"""On-disk cache of long computations, keyed by their parameters.

A cached value is the JSON of the computation's result (exact rationals as strings), stored in
``<cache dir>/<name>/<sha256 of the canonical parameters>.json`` together with the parameters
themselves; a cache hit returns exactly what the computation returned, so caches never change
results.  Bump :data:`CACHE_VERSION` when a computation's meaning changes.

The cache folder (:func:`cache_dir`): ``$PAPER_REPRO_CACHE`` if set; else ``.cache/`` of the clone when the
package runs from a checkout; else the user's cache folder (``platformdirs.user_cache_dir("paper_repro")``,
e.g. ``~/.cache/paper_repro`` on Linux) -- never the install location.  ``PAPER_REPRO_NO_CACHE=1`` switches
the cache off (nothing read, nothing written).
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
from collections.abc import Callable
from functools import lru_cache
from pathlib import Path
from typing import TypeVar

from paper_repro.util.io import PACKAGE, ROOT, dumps, in_checkout, write_text

CACHE_VERSION = 3  # 3: equivalence-class records renamed dim_V -> functions_in_V
#: A fixed cache folder overriding :func:`cache_dir` (tests set it); ``None``: the rules of :func:`cache_dir`.
CACHE_DIR: Path | None = None
CACHE_ENV = "PAPER_REPRO_CACHE"
NO_CACHE_ENV = "PAPER_REPRO_NO_CACHE"


def enabled() -> bool:
    """False when ``PAPER_REPRO_NO_CACHE`` is set to anything but ``''``/``0``."""
    return os.environ.get(NO_CACHE_ENV, "") in ("", "0")


def cache_dir() -> Path:
    """The cache folder: ``$PAPER_REPRO_CACHE``, else ``.cache/`` in a checkout, else the user's cache folder."""
    if CACHE_DIR is not None:
        return Path(CACHE_DIR)
    env = os.environ.get(CACHE_ENV)
    if env:
        return Path(env).expanduser().resolve()
    if in_checkout():
        return ROOT / ".cache"
    import platformdirs

    return Path(platformdirs.user_cache_dir("paper_repro", appauthor=False))

T = TypeVar("T")


def key(name: str, params: dict) -> str:
    canon = json.dumps({"v": CACHE_VERSION, "name": name, "params": params}, sort_keys=True)
    return hashlib.sha256(canon.encode()).hexdigest()[:32]


def cached(name: str, params: dict, compute: Callable[[], T], *, report_hit: bool = False):
    """Return ``compute()``, memoised on disk under ``name`` and the JSON-serialisable ``params``.

    An exception raised by ``compute`` propagates and nothing is stored.  With ``report_hit`` the
    result is ``(value, True if it came from the cache)``.  ``PAPER_REPRO_NO_CACHE=1`` bypasses the
    cache (nothing read, nothing written).
    """
    if not enabled():
        value = json.loads(dumps(compute()))
        return (value, False) if report_hit else value
    path = cache_dir() / name / f"{key(name, params)}.json"
    hit = _read(path, params)
    if hit is not None:
        return (hit["value"], True) if report_hit else hit["value"]
    # one process computes a given entry at a time: another one asking for it meanwhile (claims run in
    # parallel processes) waits for the lock and then reads the stored result
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path.with_suffix(".lock"), "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            hit = _read(path, params)
            if hit is not None:
                return (hit["value"], True) if report_hit else hit["value"]
            value = json.loads(dumps(compute()))  # the same JSON form a cache hit returns
            write_text(path, dumps({"name": name, "params": params, "value": value}))
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)
    return (value, False) if report_hit else value


def _read(path, params: dict) -> dict | None:
    if not path.exists():
        return None
    try:
        stored = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    return stored if stored.get("params") == json.loads(json.dumps(params)) else None


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """sha256 of every source file of the package: part of the key of cached claim results, so that
    any change of the code invalidates them.  Computed once per process (at first use, when the
    modules are loaded), so that editing files during a run cannot file old results under a new key."""
    h = hashlib.sha256()
    pkg = PACKAGE
    for path in sorted(pkg.rglob("*.py")):
        h.update(path.relative_to(pkg).as_posix().encode())
        h.update(path.read_bytes())
    return h.hexdigest()[:16]
