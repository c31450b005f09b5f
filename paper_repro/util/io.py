"""Atomic, deterministic file output (temp file in the same folder, then ``os.replace``)."""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

#: The package's own folder (read only: nothing is ever written below it when installed).
PACKAGE = Path(__file__).resolve().parent.parent
#: What the package reads at run time (the paper index): package data, shipped in the wheel.
RESOURCES = PACKAGE / "resources"
#: The folder holding the package: the repository root in a checkout, ``site-packages`` when installed.
ROOT = PACKAGE.parent

#: Environment variable naming the output folder (``--out DIR`` of the command line sets it).
OUT_ENV = "PAPER_REPRO_OUT"


def in_checkout() -> bool:
    """True when the package runs from a clone of the repository (its ``pyproject.toml`` beside it)."""
    pyproject = ROOT / "pyproject.toml"
    try:
        return pyproject.is_file() and 'name = "paper_repro"' in pyproject.read_text(encoding="utf-8")
    except OSError:
        return False


def set_output_root(path: str | os.PathLike | None) -> None:
    """Send every output (``data/``, ``figures/``, ``build/``, ``reports/``) below ``path`` (``None``: the default).

    Also sets :data:`OUT_ENV`, so worker processes started afterwards write to the same place."""
    if path is None:
        os.environ.pop(OUT_ENV, None)
    else:
        os.environ[OUT_ENV] = str(Path(path).resolve())


def unwritable(folder: str | os.PathLike) -> str | None:
    """Why nothing can be written in ``folder`` (``None`` if it can): it is created if missing, then a file is
    created and removed in it.  The reason is one phrase, e.g. ``'Permission denied (/data)'``.

    >>> import tempfile; unwritable(tempfile.gettempdir()) is None
    True
    """
    path = Path(folder)
    try:
        if path.exists() and not path.is_dir():
            return f"{path} is a file, not a folder"
        path.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(prefix=".probe-", dir=path)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        return f"{exc.strerror or type(exc).__name__} ({path})"
    return None


def output_root() -> Path:
    """Where outputs go: ``$PAPER_REPRO_OUT`` if set (``--out DIR``), else the repository root in a checkout
    (so ``make reproduce`` writes ``data/`` and ``figures/`` of the clone), else the current directory.
    Never the install location of the package."""
    env = os.environ.get(OUT_ENV)
    if env:
        return Path(env).resolve()
    return ROOT if in_checkout() else Path.cwd().resolve()


def data_dir() -> Path:
    """``data/`` below :func:`output_root`: the deterministic results of the claims."""
    return output_root() / "data"


def figures_dir() -> Path:
    """``figures/`` below :func:`output_root`: figures, manifest and gallery."""
    return output_root() / "figures"


def build_dir() -> Path:
    """``build/`` below :func:`output_root`: timings and other non-deterministic by-products."""
    return output_root() / "build"


def reports_dir() -> Path:
    """``reports/`` below :func:`output_root`: benchmark and test reports."""
    return output_root() / "reports"


_DYNAMIC = {"DATA": data_dir, "FIGURES": figures_dir, "BUILD": build_dir}


def __getattr__(name: str) -> Path:
    """``DATA``, ``FIGURES``, ``BUILD``: the folders of :func:`data_dir` etc. at the time of the access
    (kept for older callers; new code calls the functions, which follow ``--out``)."""
    if name in _DYNAMIC:
        return _DYNAMIC[name]()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


@contextmanager
def atomic_path(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; on success it replaces ``path``, else it is removed."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=target.suffix, dir=target.parent)
    os.close(fd)
    os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the file the ordinary permissions
    try:
        yield Path(tmp)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_text(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` atomically (UTF-8, ``\\n`` line ends)."""
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def dumps(obj) -> str:
    """Stable JSON: 2-space indent, insertion order, trailing newline."""
    return json.dumps(obj, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def write_json(path: str | os.PathLike, obj) -> Path:
    return write_text(path, dumps(obj))


def rel(path: str | os.PathLike) -> str:
    """Path relative to the output root (the repository root in a checkout), with forward slashes."""
    p = Path(path).resolve()
    try:
        return p.relative_to(output_root()).as_posix()
    except ValueError:
        return p.as_posix()
