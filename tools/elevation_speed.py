"""Cold timings of the closed-form elevation matrix (issue 30 goals: n = 10 <= 50 ms, n = 30 <= 1 s), each in a fresh
process after the imports: wall time and CPU time (on a loaded machine the wall time is the CPU time stretched by
the load; both are printed), and the same for a second alpha (the integer form of M is then cached).

    .venv/bin/python tools/elevation_speed.py [n ...]
"""

from __future__ import annotations

import os
import subprocess
import sys

PROBE = """
import time
import paper_repro.core.elevation as E
t1, p1 = time.perf_counter(), time.process_time()
E.elevation_matrix({n}, 1.234)
t2, p2 = time.perf_counter(), time.process_time()
E.elevation_matrix({n}, 2.0)
t3, p3 = time.perf_counter(), time.process_time()
print(f"{{t2 - t1:.3f}} {{p2 - p1:.3f}} {{t3 - t2:.3f}} {{p3 - p2:.3f}}")
"""


def main(argv: list[str]) -> int:
    ns = [int(x) for x in argv] or [5, 10, 20, 30, 40]
    print(f"load average: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print("n | cold wall s | cold CPU s | next alpha wall s | next alpha CPU s")
    for n in ns:
        out = subprocess.run([sys.executable, "-c", PROBE.format(n=n)], capture_output=True, text=True, check=True)
        print(n, "|", " | ".join(out.stdout.split()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
