"""Checks of the transcribed lines (:mod:`paper_repro.printed.lines`), one module per part of the paper.

A check is registered with :func:`line_check` and returns a :class:`LineResult`: whether the line holds as
printed and, for an erratum, whether the corrected line holds; ``detail`` carries exact evidence (JSON-able,
machine-independent: exact rationals as strings, counts, booleans -- no raw floats).  A check never trusts the
printed formula: it compares it with an independent computation (the package's ``core``/``theory`` code, an
exact symbolic expansion, a count, evaluation at exact rational points).

The ``kind`` of a result (:data:`LINE_KINDS`) says how far the check settles its line:

* ``proof`` -- everything the line states, for every n and alpha it states it for: a symbolic identity, or a line
  about fixed orders (an Example at n = 2, a count for T_6) checked completely;
* ``exhaustive`` -- exact and complete, but only for the finite range of n (or of another index) that ``how``
  names, while the line states it for every n: a proof for that range, not beyond it;
* ``exact-evidence`` -- exact arithmetic at sampled parameters (rational-tangent alpha, rational points);
* ``numeric-evidence`` -- floating-point or high-precision values at sampled parameters.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

CHECKS: dict[str, Callable[[], LineResult]] = {}

#: Kinds of a line check, strongest first (see the module docstring).
LINE_KINDS = ("proof", "exhaustive", "exact-evidence", "numeric-evidence")

#: How an exhaustive result names its finite range: ``n = 1..12``, ``n <= 6``, ``m = 0..20``, ``r <= 10``, ...
RANGE_WORDS = re.compile(r"\b[a-z] (?:= -?\d+\.\.\d+|<= \d+|= \d+(?:, \d+)+)")


@dataclass
class LineResult:
    holds_as_printed: bool
    corrected_holds: bool | None = None
    how: str = ""  # the independent computation, in a sentence ("exact expansion", "count for n = 1..12", ...)
    kind: str = "exact-evidence"  # one of LINE_KINDS
    detail: dict[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in LINE_KINDS:
            raise ValueError(f"kind must be one of {LINE_KINDS}, got {self.kind!r}")
        if self.kind == "exhaustive" and not RANGE_WORDS.search(self.how):
            raise ValueError(f"an exhaustive result names its range in how (e.g. 'n = 1..12'), got {self.how!r}")


def line_check(id: str) -> Callable[[Callable[[], LineResult]], Callable[[], LineResult]]:
    """Register the check named ``id`` (the ``check`` field of the lines it verifies)."""

    def deco(func: Callable[[], LineResult]) -> Callable[[], LineResult]:
        if id in CHECKS:
            raise ValueError(f"line check {id!r} registered twice")
        CHECKS[id] = func
        return func

    return deco


def items_result(items: Callable[[], dict[str, Any]], how: str, kind: str,
                 errors: tuple[type[BaseException], ...]) -> LineResult:
    """The line holds when every item of ``items()`` (read from the transcription, then computed) is true; an error of
    ``errors`` means the line could not be read as the check reads it, and is a failure that says why (``unread``)."""
    try:
        out = items()
    except errors as exc:
        return LineResult(False, how=how, kind=kind, detail={"unread": str(exc)})
    return LineResult(all(out.values()), how=how, kind=kind, detail=out)


#: Check modules beyond one per part: Section 5's checks (lines of part sec4_5 from source line 1907 on) live in
#: ``sec5`` (it imports helpers of ``sec4_5``, so ``sec4_5`` cannot import it back without an import circle).
EXTRA_MODULES = ("sec5",)


def load_checks() -> dict[str, Callable[[], LineResult]]:
    from paper_repro.printed.lines import PARTS

    for part in (*PARTS, *EXTRA_MODULES):
        try:
            importlib.import_module(f"paper_repro.claims.lines.{part}")
        except ModuleNotFoundError:
            continue
    return CHECKS
