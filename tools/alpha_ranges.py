"""Measure where each claim that takes ``--alpha`` decides its statement (issue 31, item 3).

Runs every such claim at its largest order (or ``--n``) and alphas from 1e-300 to pi - 1e-14, without the cache,
each in a child process with a time limit; prints pass / FAIL / error / timeout per alpha and the seconds taken.
The ranges declared in the claims' registrations (``alpha_range=``) are the contiguous passing ranges measured here.

    python tools/alpha_ranges.py [--only ID ...] [--n N] [--timeout S]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

ALPHAS = ["1e-300", "1e-100", "1e-30", "1e-17", "1e-12", "1e-8", "1e-5", "1e-3", "0.01", "0.03", "0.06", "0.1",
          "3.1", "3.13", "3.14", "3.1415", "3.14159", "3.1415926", "3.14159265358"]
CHILD = """
import json, sys
from paper_repro.util.registry import CLAIMS, load_all, run_claim, cli_overrides
load_all()
cid, n, alpha = sys.argv[1], int(sys.argv[2]), sys.argv[3]
res, out, sec = run_claim(CLAIMS[cid], cli_overrides(CLAIMS[cid], n, alpha))
print(json.dumps({"status": res.status, "error": res.measured.get("error")}))
"""


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", nargs="+")
    ap.add_argument("--n", type=int)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--alphas", nargs="+", default=ALPHAS)
    args = ap.parse_args()
    from paper_repro.util.registry import CLAIMS, load_all, n_range

    load_all()
    env = {**os.environ, "PAPER_REPRO_NO_CACHE": "1"}
    for cid, c in CLAIMS.items():
        if "alphas" not in c.defaults or (args.only and cid not in args.only):
            continue
        n = args.n or n_range(c) or 1
        for a in args.alphas:
            t0 = time.perf_counter()
            try:
                res = subprocess.run([sys.executable, "-c", CHILD, cid, str(n), a], capture_output=True, text=True,
                                     timeout=args.timeout, env=env)
                lines = res.stdout.strip().splitlines()
                rec = json.loads(lines[-1]) if lines else {"status": "crash", "error": res.stderr[-200:]}
            except subprocess.TimeoutExpired:
                rec = {"status": "timeout", "error": None}
            print(f"{cid} n={n} alpha={a}: {rec['status']} {time.perf_counter() - t0:.1f} s"
                  + (f"  ({str(rec['error'])[:150]})" if rec.get("error") else ""), flush=True)


if __name__ == "__main__":
    main()
