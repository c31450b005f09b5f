"""Checks of the transcribed lines (:mod:`paper_repro.printed.lines`), one module per part of the paper.

A check is registered with :func:`line_check` and returns a :class:`LineResult`: whether the line holds as
printed and, for an erratum, whether the corrected line holds; ``detail`` carries exact evidence (JSON-able,
machine-independent: exact rationals as strings, counts, booleans -- no raw floats).  A check never trusts the
printed formula: it compares it with an independent computation (the package's ``core``/``theory`` code, an
exact symbolic expansion, a count, evaluation at exact rational points).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

CHECKS: dict[str, Callable[[], LineResult]] = {}


@dataclass
class LineResult:
    holds_as_printed: bool
    corrected_holds: bool | None = None
    how: str = ""  # the independent computation, in a sentence ("exact expansion", "count for n = 1..12", ...)
    kind: str = "exact-evidence"  # "proof" | "exact-evidence" | "numeric-evidence"
    detail: dict[str, Any] = field(default_factory=dict)


def line_check(id: str) -> Callable[[Callable[[], LineResult]], Callable[[], LineResult]]:
    """Register the check named ``id`` (the ``check`` field of the lines it verifies)."""

    def deco(func: Callable[[], LineResult]) -> Callable[[], LineResult]:
        if id in CHECKS:
            raise ValueError(f"line check {id!r} registered twice")
        CHECKS[id] = func
        return func

    return deco


def load_checks() -> dict[str, Callable[[], LineResult]]:
    from paper_repro.printed.lines import PARTS

    for part in PARTS:
        try:
            importlib.import_module(f"paper_repro.claims.lines.{part}")
        except ModuleNotFoundError:
            continue
    return CHECKS
