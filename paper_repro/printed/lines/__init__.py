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

from dataclasses import dataclass, field
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
