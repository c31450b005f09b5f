"""CPU seconds (user + system) of a command and of every process it starts, the fork server's workers included.

Wall time on a shared machine measures the load; CPU time measures the work.  ``time``/``/usr/bin/time`` miss the
workers of ``make reproduce``: they are children of the multiprocessing fork server, which the main process never
waits for.  This tool makes itself a child subreaper (Linux ``prctl(PR_SET_CHILD_SUBREAPER)``), so every orphaned
descendant is reparented to it and reaped here; ``RUSAGE_CHILDREN`` then holds the CPU time of the whole tree.

Usage (a cold run: an empty cache folder, outputs in a scratch folder)::

    PAPER_REPRO_CACHE=$(mktemp -d) python tools/cpu_time.py python -m paper_repro reproduce --out /tmp/out

The last line on stderr: ``cpu_time: rc=0 wall=...s user=...s sys=...s cpu=...s maxrss=...MB``.  Per task CPU
seconds are in ``<out>/build/task_costs.json`` (written by the run).
"""

from __future__ import annotations

import ctypes
import os
import resource
import subprocess
import sys
import time

PR_SET_CHILD_SUBREAPER = 36


def main(argv: list[str]) -> int:
    if not argv:
        print(__doc__, file=sys.stderr)
        return 2
    if sys.platform.startswith("linux"):
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv)
    rc, wall = 1, 0.0
    while True:  # the command, then every orphan (fork server, workers) until none is left
        try:
            pid, status, _ = os.wait4(-1, 0)
        except ChildProcessError:
            break
        if pid == proc.pid:
            rc, wall = os.waitstatus_to_exitcode(status), time.perf_counter() - t0
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"cpu_time: rc={rc} wall={wall:.1f}s user={r.ru_utime:.1f}s sys={r.ru_stime:.1f}s "
          f"cpu={r.ru_utime + r.ru_stime:.1f}s maxrss={r.ru_maxrss / 1024:.0f}MB", file=sys.stderr)
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
