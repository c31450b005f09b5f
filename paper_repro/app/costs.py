"""The cost model of the swept tasks: measured CPU seconds per task, a power law in n per task function, and the
predictions made from it (the order in which a sweep submits tasks, ``--n-max``'s estimate, and
``reports/extended_scaling.md``).

Measured costs go to ``build/task_costs{suffix}.json`` (machine-dependent, never to ``data/``): per task label
``{"name", "n", "cpu", "wall"}``.  A task's *n* is its first integer argument (or the ``n`` of a closed-form
record it receives).  The prediction for a task never measured is the power law ``a n^b`` fitted (least squares in
log-log) on the measured tasks of the same function with n >= 5; a function never measured costs ``n^4 / 1000``
seconds (a rough guess that only orders the first run).

>>> fit_power([(10, 1.0), (20, 16.0)])
(0.0001, 4.0)
>>> predict_with({"f": (1e-4, 4.0)}, "f", 30)
81.0
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from paper_repro.util.io import build_dir, write_json
from paper_repro.util.tasks import Task

MIN_FIT_N = 5


def task_n(task: Task) -> int | None:
    """The order n a task works at: its first int argument, or the ``n`` of a record argument."""
    for a in task.args:
        if isinstance(a, bool):
            continue
        if isinstance(a, int):
            return a
        if isinstance(a, dict) and isinstance(a.get("n"), int):
            return a["n"]
    return None


def costs_path(extended: bool) -> Path:
    return build_dir() / f"task_costs{'_extended' if extended else ''}.json"


def load(extended: bool) -> dict[str, dict[str, Any]]:
    """Measured costs ``{label: {"name", "n", "cpu", "wall"}}`` of earlier runs (both suffixes merged, this one
    winning); ``{}`` if none."""
    out: dict[str, dict[str, Any]] = {}
    for ext in (not extended, extended):
        try:
            out.update(json.loads(costs_path(ext).read_text()))
        except (OSError, ValueError):
            pass
    return out


def record_costs(extended: bool, measured: dict[str, dict[str, Any]]) -> None:
    """Merge this run's measured task costs into ``build/task_costs{suffix}.json``."""
    old = {}
    try:
        old = json.loads(costs_path(extended).read_text())
    except (OSError, ValueError):
        pass
    old.update(measured)
    write_json(costs_path(extended), dict(sorted(old.items())))


def fit_power(points: list[tuple[int, float]]) -> tuple[float, float]:
    """``(a, b)`` of ``cpu = a n^b`` by least squares on ``log cpu`` (points with n >= 1 and cpu > 0)."""
    pts = [(math.log(n), math.log(c)) for n, c in points if n >= 1 and c > 0]
    if not pts:
        return 1e-3, 4.0
    if len(pts) == 1 or len({x for x, _ in pts}) == 1:
        x, y = pts[0]
        return float(f"{math.exp(y - 4.0 * x):.3g}"), 4.0
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    b = sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)
    return float(f"{math.exp(my - b * mx):.3g}"), float(f"{b:.3g}")


def model(measured: dict[str, dict[str, Any]]) -> dict[str, tuple[float, float]]:
    """Power law per task function, fitted on the measured tasks with n >= MIN_FIT_N (else on all)."""
    by_name: dict[str, list[tuple[int, float]]] = {}
    for rec in measured.values():
        if rec.get("n") is not None:
            by_name.setdefault(rec["name"], []).append((rec["n"], rec["cpu"]))
    out = {}
    for name, pts in by_name.items():
        big = [p for p in pts if p[0] >= MIN_FIT_N]
        out[name] = fit_power(big if len(big) >= 2 else pts)
    return out


def predict_with(laws: dict[str, tuple[float, float]], name: str, n: int | None) -> float:
    a, b = laws.get(name, (1e-3, 4.0))
    return a * (n or 1) ** b


class CostModel:
    """Predicted CPU seconds of a task: its measured cost if this very task was measured, else the power law of
    its function."""

    def __init__(self, extended: bool):
        self.measured = load(extended)
        self.laws = model(self.measured)

    def predict(self, task: Task) -> float:
        rec = self.measured.get(task.label)
        if rec is not None:
            return float(rec["cpu"])
        return predict_with(self.laws, task.name, task_n(task))
