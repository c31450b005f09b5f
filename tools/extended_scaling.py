"""Predict the wall time of the extended run on P workers from measured per-task CPU costs (issue 32).

Usage: ``python tools/extended_scaling.py build/task_costs_extended.json RUN_LOG [--workers 2 8 32 128]``

``RUN_LOG`` is the stderr of the measured run (``tasks, round R: k/N: label`` lines give each task's round when the
costs file has none).  Rounds are barriers (a round's tasks need the previous round's results), so the prediction
is, per round, a longest-first list schedule of its tasks on P workers (at least max(longest task, work / P)),
summed over the rounds.  Whole claims that are not split are round-1 tasks.  The claims' code between rounds runs
in the client (serial) and is not included: it is reported separately where the log has the rounds' wall times.
Prints Markdown.
"""

from __future__ import annotations

import argparse
import heapq
import json
import re
from collections import defaultdict


def lpt(costs: list[float], workers: int) -> float:
    """Makespan of the longest-first list schedule of ``costs`` on ``workers`` identical workers.

    >>> lpt([4, 3, 3, 2], 2)
    6
    """
    loads = [0.0] * workers
    heapq.heapify(loads)
    for c in sorted(costs, reverse=True):
        heapq.heappush(loads, heapq.heappop(loads) + c)
    return max(loads)


def rounds_from_log(text: str) -> dict[str, int]:
    out = {}
    for m in re.finditer(r"^tasks, round (\d+): \d+/\d+: (.*)$", text, re.M):
        out[m.group(2)] = int(m.group(1))
    return out


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("costs")
    ap.add_argument("log")
    ap.add_argument("--workers", type=int, nargs="+", default=[2, 8, 32, 128])
    args = ap.parse_args()
    costs = json.loads(open(args.costs).read())
    log = open(args.log).read()
    where = rounds_from_log(log)
    by_round: dict[int, list[tuple[float, str]]] = defaultdict(list)
    for label, rec in costs.items():
        rnd = rec.get("round") or where.get(label)
        if rnd is not None:
            by_round[rnd].append((rec["cpu"], label))
    walls = {int(m.group(1)): float(m.group(2))
             for m in re.finditer(r"^tasks, round (\d+): \d+ tasks, ([\d.]+) s wall", log, re.M)}
    print("| round | tasks | CPU s | longest task | its CPU s | measured wall s |")
    print("|---|---|---|---|---|---|")
    for rnd in sorted(by_round):
        items = sorted(by_round[rnd], reverse=True)
        print(f"| {rnd} | {len(items)} | {sum(c for c, _ in items):.0f} | `{items[0][1]}` | {items[0][0]:.0f} | "
              f"{walls.get(rnd, float('nan')):.0f} |")
    total = sum(c for items in by_round.values() for c, _ in items)
    crit = sum(max(c for c, _ in items) for items in by_round.values())
    print(f"\nTotal work {total:.0f} CPU s; critical path (sum over rounds of the longest task) {crit:.0f} s.\n")
    print("| workers | predicted wall of the task rounds, s | work / P, s | efficiency |")
    print("|---|---|---|---|")
    for p in args.workers:
        wall = sum(lpt([c for c, _ in items], p) for items in by_round.values())
        print(f"| {p} | {wall:.0f} | {total / p:.0f} | {total / p / wall:.0%} |")
    top = sorted(((c, label) for items in by_round.values() for c, label in items), reverse=True)[:12]
    print("\nThe 12 longest tasks (CPU s):\n")
    print("| task | CPU s |")
    print("|---|---|")
    for c, label in top:
        print(f"| `{label}` | {c:.1f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
