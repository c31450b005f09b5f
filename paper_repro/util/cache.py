"""On-disk cache of long computations, keyed by their parameters.

A cached value is the JSON of the computation's result (exact rationals as strings), stored in
``<cache dir>/<name>/<sha256 of the canonical parameters>.json`` together with its name, its parameters and the
sha256 of the value's canonical JSON.  Bump :data:`CACHE_VERSION` when a computation's meaning changes.

The cache never changes an answer and never stops the work (issue 31):

* every entry is validated before use (:func:`cached`): it must be a JSON object whose name, parameters and
  checksum match, whose numbers are all finite, and which passes the caller's ``validate`` (shape, finiteness of
  encoded floats, ...).  A bad entry is recomputed and rewritten, with one :class:`CacheWarning`;
* an unusable cache folder (read-only, or ``PAPER_REPRO_CACHE`` naming a file) means working without the cache,
  with one :class:`CacheWarning` per process.

The cache folder (:func:`cache_dir`): ``$PAPER_REPRO_CACHE`` if set; else ``.cache/`` of the clone when the
package runs from a checkout; else the user's cache folder (``platformdirs.user_cache_dir("paper_repro")``,
e.g. ``~/.cache/paper_repro`` on Linux) -- never the install location.  ``PAPER_REPRO_NO_CACHE=1`` switches
the cache off (nothing read, nothing written).

>>> entry = {"name": "t", "params": {"a": 1}, "value": [1, 2], "sha256": checksum([1, 2])}
>>> problem(entry, "t", {"a": 1}, None) is None
True
>>> problem({**entry, "value": [1, 3]}, "t", {"a": 1}, None)
'its checksum does not match its value'
>>> problem([], "t", {"a": 1}, None)
'not a JSON object with name, params, value and sha256'
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import math
import os
import warnings
from collections.abc import Callable
from functools import lru_cache
from pathlib import Path
from typing import Any, TypeVar

from paper_repro.util.io import PACKAGE, ROOT, dumps, in_checkout, unwritable, write_text

CACHE_VERSION = 4  # 4: entries carry the sha256 of their value (validated on read); 3: dim_V -> functions_in_V
#: A fixed cache folder overriding :func:`cache_dir` (tests set it); ``None``: the rules of :func:`cache_dir`.
CACHE_DIR: Path | None = None
CACHE_ENV = "PAPER_REPRO_CACHE"
NO_CACHE_ENV = "PAPER_REPRO_NO_CACHE"


class CacheWarning(UserWarning):
    """A cache entry was bad (recomputed and rewritten) or the cache folder is unusable (work goes on without it)."""


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

#: Folders already reported unusable in this process (one warning each).
_WARNED_UNUSABLE: set[str] = set()


def unusable(folder: Path | None = None) -> str | None:
    """Why the cache folder cannot be written (``None`` if it can; :func:`paper_repro.util.io.unwritable`).
    ``folder`` defaults to :func:`cache_dir`."""
    return unwritable(cache_dir() if folder is None else folder)


def warn_unusable(reason: str) -> None:
    """One :class:`CacheWarning` per process and cache folder (:func:`cache_dir`, whatever subfolder failed): the cache
    cannot be written, the work goes on without it."""
    root = str(cache_dir())
    if root in _WARNED_UNUSABLE:
        return
    _WARNED_UNUSABLE.add(root)
    warnings.warn(f"the cache folder is not writable: {reason}; working without a cache (set {CACHE_ENV} to a "
                  f"writable folder, or {NO_CACHE_ENV}=1)", CacheWarning, stacklevel=3)


def key(name: str, params: dict) -> str:
    canon = json.dumps({"v": CACHE_VERSION, "name": name, "params": params}, sort_keys=True)
    return hashlib.sha256(canon.encode()).hexdigest()[:32]


def checksum(value: Any) -> str:
    """sha256 of the canonical JSON of a (JSON-form) value."""
    return hashlib.sha256(json.dumps(value, sort_keys=True, allow_nan=True).encode()).hexdigest()


def _nonfinite(obj: Any) -> bool:
    if isinstance(obj, float):
        return not math.isfinite(obj)
    if isinstance(obj, dict):
        return any(_nonfinite(v) for v in obj.values())
    if isinstance(obj, list):
        return any(_nonfinite(v) for v in obj)
    return False


def problem(stored: Any, name: str, params: dict, validate: Callable[[Any], str | None] | None) -> str | None:
    """What is wrong with a stored entry (``None``: nothing): its form, name, parameters, checksum, finiteness,
    then the caller's ``validate(value)`` (a reason, or ``None`` when the value is good)."""
    if not isinstance(stored, dict) or not {"name", "params", "value", "sha256"} <= set(stored):
        return "not a JSON object with name, params, value and sha256"
    if stored["name"] != name or stored["params"] != json.loads(json.dumps(params)):
        return "its name or parameters are not those of the key"
    value = stored["value"]
    if stored["sha256"] != checksum(value):
        return "its checksum does not match its value"
    if _nonfinite(value):
        return "it holds a NaN or infinite number"
    if validate is not None:
        try:
            why = validate(value)
        except Exception as exc:  # a malformed value may break the validator anywhere: that is a bad entry
            why = f"{type(exc).__name__}: {exc}"
        if why:
            return why
    return None


_MISS = object()


def _read(path: Path, name: str, params: dict, validate, warn: bool) -> Any:
    """The stored value, or ``_MISS`` (no entry, or a bad one: then one :class:`CacheWarning` if ``warn``)."""
    try:
        text = path.read_text(encoding="utf-8")
    except (FileNotFoundError, NotADirectoryError):  # no entry (or no folder: reported when writing)
        return _MISS
    except (OSError, ValueError) as exc:
        why = f"unreadable ({type(exc).__name__})"
    else:
        try:
            stored = json.loads(text)
        except ValueError:
            why = "not valid JSON"
        else:
            why = problem(stored, name, params, validate)
            if why is None:
                return stored["value"]
    if warn:
        warnings.warn(f"cache entry {name} {json.dumps(params, sort_keys=True)[:120]} is bad ({why}): recomputed "
                      f"and rewritten ({path})", CacheWarning, stacklevel=4)
    return _MISS


def cached(name: str, params: dict, compute: Callable[[], T], *, report_hit: bool = False,
           validate: Callable[[Any], str | None] | None = None):
    """Return ``compute()``, memoised on disk under ``name`` and the JSON-serialisable ``params``.

    ``validate(value)`` returns why a stored value is bad (``None`` if good): its shape, the finiteness of floats
    encoded as text, ...; name, parameters, checksum and finiteness of JSON numbers are always checked.  A bad
    entry is recomputed and rewritten with one :class:`CacheWarning`; an unusable cache folder means computing
    without it (one warning per process).  An exception raised by ``compute`` propagates and nothing is stored.
    With ``report_hit`` the result is ``(value, True if it came from the cache)``.  ``PAPER_REPRO_NO_CACHE=1``
    bypasses the cache (nothing read, nothing written).
    """
    def fresh():
        value = json.loads(dumps(compute()))  # the same JSON form a cache hit returns
        return (value, False) if report_hit else value

    if not enabled():
        return fresh()
    path = cache_dir() / name / f"{key(name, params)}.json"
    hit = _read(path, name, params, validate, warn=True)
    if hit is not _MISS:
        return (hit, True) if report_hit else hit
    # one process computes a given entry at a time: another one asking for it meanwhile (claims run in
    # parallel processes) waits for the lock and then reads the stored result
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        lock = open(path.with_suffix(".lock"), "a")  # noqa: SIM115 (closed below)
    except OSError as exc:
        warn_unusable(f"{exc.strerror or type(exc).__name__} ({cache_dir()})")
        return fresh()
    with lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            hit = _read(path, name, params, validate, warn=False)
            if hit is not _MISS:
                return (hit, True) if report_hit else hit
            value = json.loads(dumps(compute()))
            try:
                write_text(path, dumps({"name": name, "params": params, "value": value, "sha256": checksum(value)}))
            except OSError as exc:
                warn_unusable(f"{exc.strerror or type(exc).__name__} ({cache_dir()})")
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)
    return (value, False) if report_hit else value


def is_cached(name: str, params: dict, validate: Callable[[Any], str | None] | None = None) -> bool:
    """Whether :func:`cached` would return a stored value for ``name`` and ``params`` (nothing computed)."""
    return enabled() and _read(cache_dir() / name / f"{key(name, params)}.json", name, params, validate,
                               warn=False) is not _MISS


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


# --- validators of stored values (``validate=`` of :func:`cached`): a reason when the value is bad, else None -------

def hex_rows(rows: int, cols: int, field: str = "rows") -> Callable[[Any], str | None]:
    """A validator of ``value[field]``: ``rows`` lists of ``cols`` float64 hex strings, every one finite.

    >>> v = hex_rows(1, 2)
    >>> v({"rows": [["0x1.0p+0", "0x1.0p-1"]]}) is None
    True
    >>> v({"rows": [["0x1.0p+0", "nan"]]})
    'entry [0][1] is not a finite float64'
    >>> v({"rows": []})
    'shape (0, ?) instead of (1, 2)'
    """
    def check(value: Any) -> str | None:
        data = value[field]
        if not isinstance(data, list):
            return f"{field} is a {type(data).__name__}, not a list of rows"
        lengths = sorted({len(r) if isinstance(r, list) else -1 for r in data})
        if len(data) != rows or lengths != [cols]:
            cols_seen = "?" if not lengths else lengths[0] if len(lengths) == 1 else f"{lengths[0]}..{lengths[-1]}"
            return f"shape ({len(data)}, {cols_seen}) instead of ({rows}, {cols})"
        for i, row in enumerate(data):
            for j, x in enumerate(row):
                if not isinstance(x, str) or not math.isfinite(float.fromhex(x)):
                    return f"entry [{i}][{j}] is not a finite float64"
        return None

    return check


def rational_text(x: Any) -> bool:
    """True for the text of an exact rational (``'-3/4'``, ``'5'``) with a non-zero denominator.

    >>> rational_text("-3/4"), rational_text("1/0"), rational_text("nan"), rational_text(3)
    (True, False, False, False)
    """
    if not isinstance(x, str):
        return False
    parts = x.split("/")
    if len(parts) > 2 or not all(p.strip().lstrip("-").isdigit() for p in parts):
        return False
    return len(parts) == 1 or int(parts[1]) != 0


def keys_and_types(**fields: type | tuple[type, ...]) -> Callable[[Any], str | None]:
    """A validator of a dict value holding at least ``fields`` with these types (bool is not an int here).

    >>> keys_and_types(proved=bool)({"proved": True}) is None, keys_and_types(n=int)({"n": True})
    (True, 'field n is bool, not int')
    """
    def check(value: Any) -> str | None:
        if not isinstance(value, dict):
            return f"a {type(value).__name__}, not an object"
        for k, t in fields.items():
            if k not in value:
                return f"field {k} is missing"
            v = value[k]
            if (isinstance(v, bool) and bool not in (t if isinstance(t, tuple) else (t,))) or not isinstance(v, t):
                return f"field {k} is {type(v).__name__}, not {getattr(t, '__name__', t)}"
        return None

    return check
