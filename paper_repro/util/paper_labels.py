"""Reading the committed index of the paper's labels (``paper_repro/resources/paper_index.json``, package data built by
:mod:`paper_repro.app.paper_index`): how the PDF names a label, for every layer that speaks of the paper.

>>> pdf_name("exmp:torus")
'Example 6.1'
>>> display_of("exmp:torus")
'Example 6.1 [exmp:torus]'
"""

from __future__ import annotations

import json
from functools import cache

from paper_repro.util.io import RESOURCES

INDEX = RESOURCES / "paper_index.json"


@cache
def _load() -> tuple[dict, ...]:
    return tuple(json.loads(INDEX.read_text(encoding="utf-8"))["labels"])


def load_index() -> list[dict]:
    """The committed index: one record per ``\\label`` (label, kind, env, number, display, section)."""
    return [dict(r) for r in _load()]


def pdf_name(label: str, index: list[dict] | None = None) -> str:
    """How the PDF refers to ``label`` (``'Eq. (26)'``, ``'Proposition 3.1'``); the label itself if unnumbered."""
    for rec in index if index is not None else _load():
        if rec["label"] == label:
            return rec["display"] if rec["display"] and rec["number"] else label
    return label


def display_of(label: str, index: list[dict] | None = None) -> str:
    """The PDF's name with the label as the secondary key, e.g. ``'Eq. (12) [united_system]'``."""
    name = pdf_name(label, index)
    return f"{name} [{label}]" if name != label else label
