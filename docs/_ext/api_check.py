"""Sphinx extension: the build fails (a warning under ``-W``) when a docstring's fields are garbled.

Napoleon reads a numpy-style ``Parameters`` section up to the next section header, so examples written after it
without an ``Examples`` header became about 60 "parameters" of ``Patch`` (issue 33).  After napoleon has turned
each docstring into reST fields, this checks that every ``:param X:`` names a parameter of the object's
signature and that no field holds a doctest line (``>>>``).
"""

from __future__ import annotations

import inspect
import re

from sphinx.util import logging

LOG = logging.getLogger(__name__)
PARAM = re.compile(r"^:param (?:[^:]*\s)?([^\s:]+):")
KEYWORD = re.compile(r"^:(?:keyword|kwarg|kwparam) ([^\s:]+):")


def field_problems(obj, lines: list[str]) -> list[str]:
    """What is wrong with the reST fields ``lines`` of ``obj`` (empty when nothing is)."""
    problems = []
    fields = [line for line in lines if line.startswith(":")]
    doctests = [line for line in fields if ">>>" in line]
    if doctests:
        problems.append(f"a field holds a doctest line ({doctests[0][:60]!r}): an `Examples` header is missing")
    params = [m.group(1) for line in lines for m in [PARAM.match(line) or KEYWORD.match(line)] if m]
    if not params:
        return problems
    try:
        signature = inspect.signature(obj)
    except (TypeError, ValueError):
        return problems
    names = set(signature.parameters)
    wild = any(p.kind in (p.VAR_KEYWORD,) for p in signature.parameters.values())
    unknown = [p for p in params if p.replace("\\", "").lstrip("*") not in names]
    if unknown and not (wild and len(unknown) <= 3):
        problems.append(f"{len(unknown)} documented parameter(s) not in the signature {signature}: "
                        f"{', '.join(map(repr, unknown[:6]))}")
    return problems


def check_docstring(app, what, name, obj, options, lines) -> None:
    for problem in field_problems(obj, lines):
        LOG.warning("garbled docstring of %s: %s", name, problem, type="api_check", subtype="fields")


def setup(app):
    app.setup_extension("sphinx.ext.napoleon")
    app.connect("autodoc-process-docstring", check_docstring, priority=900)  # after napoleon (500)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
