"""Every line of the paper that states something, transcribed verbatim (issue: every line checked).

One module per part of the paper (``sec1_3``, ``sec4_5``, ``sec6``, ``sec7``), each a list
``LINES`` of :class:`Line`.  A line is a displayed formula (one row of an ``align`` counts as one), or an
inline statement of the text that can be wrong: an index set, a range, a bound, a parametrization, a count,
a figure caption's parameter values.  ``verbatim`` is the LaTeX as printed, copied from the source lines
``tex`` (1-based, inclusive) of ``shared/paper/triangular-trigonometric-patches.tex``; a test checks that it
occurs there (whitespace-normalised) whenever the source is beside the clone.

``status``:

* ``"checked"`` -- compared with an independent computation by the check ``check`` (a function registered in
  :mod:`paper_repro.claims.lines` under that id) and found to hold as printed;
* ``"erratum"`` -- the check finds the printed line wrong and a corrected line right; ``erratum`` holds
  ``printed``, ``corrected``, ``evidence`` and ``severity`` (``typo`` / ``statement`` / ``result``);
* ``"excused"`` -- nothing to compute (pure prose, a definition that introduces a name, a citation):
  ``reason`` says why.

``near`` is the nearest ``\\label`` (before the line, or the environment's own), from which reports print the
PDF's number (``paper_repro/resources/paper_index.json``).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from typing import Any

STATUSES = ("checked", "erratum", "excused")
KINDS = ("display", "inline", "index-set", "range", "bound", "parametrization", "count", "caption", "definition",
         "prose")
SEVERITIES = ("typo", "statement", "result")


@dataclass(frozen=True)
class Line:
    id: str
    tex: tuple[int, int]
    near: str
    kind: str
    verbatim: str
    says: str
    status: str
    check: str | None = None
    reason: str | None = None
    erratum: dict[str, Any] | None = field(default=None, hash=False, compare=False)

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"{self.id}: status must be one of {STATUSES}, got {self.status!r}")
        if self.kind not in KINDS:
            raise ValueError(f"{self.id}: kind must be one of {KINDS}, got {self.kind!r}")
        if self.status in ("checked", "erratum") and not self.check:
            raise ValueError(f"{self.id}: a {self.status} line names its check")
        if self.status == "excused" and not self.reason:
            raise ValueError(f"{self.id}: an excused line gives its reason")
        if self.status == "erratum":
            e = self.erratum or {}
            missing = {"printed", "corrected", "evidence", "severity"} - set(e)
            if missing or e.get("severity") not in SEVERITIES:
                raise ValueError(f"{self.id}: an erratum needs printed, corrected, evidence and a severity in "
                                 f"{SEVERITIES}")


PARTS = ("sec1_3", "sec4_5", "sec6", "sec7")


def all_lines() -> list[Line]:
    """Every transcribed line, in source order."""
    import importlib

    out: list[Line] = []
    for part in PARTS:
        try:
            mod = importlib.import_module(f"paper_repro.printed.lines.{part}")
        except ModuleNotFoundError:
            continue
        out += list(mod.LINES)
    ids = [x.id for x in out]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise ValueError(f"line ids used twice: {sorted(dup)}")
    return sorted(out, key=lambda x: x.tex)


# -- the one accessor of the transcriptions (and the mutation tests' way to change them) -------------------------
def _part_modules() -> list:
    import importlib

    out = []
    for part in PARTS:
        try:
            out.append(importlib.import_module(f"paper_repro.printed.lines.{part}"))
        except ModuleNotFoundError:
            continue
    return out


def line(line_id: str) -> Line:
    """The transcribed line ``line_id`` as it stands now (inside :func:`substituted`, the substituted text)."""
    for mod in _part_modules():
        for x in mod.LINES:
            if x.id == line_id:
                return x
    raise KeyError(f"no transcribed line {line_id!r}")


def verbatim(line_id: str) -> str:
    """The verbatim LaTeX of line ``line_id``: what a check reads (never a retyped copy of the formula)."""
    return line(line_id).verbatim


class _LiveTexts(dict):
    """``{line id: verbatim}`` read live through :func:`verbatim` (a module-level table of the transcriptions that
    still sees :func:`substituted`)."""

    def __getitem__(self, line_id: str) -> str:
        return verbatim(line_id)

    def get(self, line_id, default=None):
        try:
            return verbatim(line_id)
        except KeyError:
            return default


class _LiveLines(dict):
    """``{line id: Line}`` read live through :func:`line`."""

    def __getitem__(self, line_id: str) -> Line:
        return line(line_id)


def live_texts() -> dict[str, str]:
    """A mapping line id -> verbatim that reads the current transcription at every lookup."""
    return _LiveTexts()


def live_lines() -> dict[str, Line]:
    """A mapping line id -> :class:`Line` that reads the current transcription at every lookup."""
    return _LiveLines()


def lines_of(check_id: str) -> list[Line]:
    """The lines (checked or erratum) whose check is ``check_id``, in source order."""
    return sorted((x for mod in _part_modules() for x in mod.LINES if x.check == check_id and x.status != "excused"),
                  key=lambda x: x.tex)


def _clear_line_caches() -> None:
    """Forget everything computed from the transcriptions: the caches of the line checks and of the readers."""
    import sys

    for name, mod in list(sys.modules.items()):
        if not (name.startswith("paper_repro.claims.lines") or name.startswith("paper_repro.printed")):
            continue
        for obj in list(vars(mod).values()):
            if callable(obj) and hasattr(obj, "cache_clear") and getattr(obj, "__module__", "") == name:
                obj.cache_clear()


@contextmanager
def substituted(texts: dict[str, str]) -> Iterator[None]:
    """Inside the block, line ``id`` reads ``texts[id]`` instead of its transcription, for every reader (the
    ``LINES`` lists are changed in place, the caches of the checks cleared before and after).  The blank and
    mutation tests of the line checks (:mod:`paper_repro.claims.lines.mutation`) run the checks so."""
    mods = _part_modules()
    saved: list[tuple[list, int, Line]] = []
    found = set()
    for mod in mods:
        for k, x in enumerate(mod.LINES):
            if x.id in texts:
                saved.append((mod.LINES, k, x))
                mod.LINES[k] = replace(x, verbatim=texts[x.id])
                found.add(x.id)
    missing = set(texts) - found
    if missing:
        for lst, k, x in saved:
            lst[k] = x
        raise KeyError(f"no transcribed lines {sorted(missing)}")
    _clear_line_caches()
    try:
        yield
    finally:
        for lst, k, x in saved:
            lst[k] = x
        _clear_line_caches()
