"""``make mutate-lines``: the blank test and the mutation test of every line check -> reports/mutate_lines.{md,json}.

Usage: ``python tools/mutate_lines.py [--part sec1_3 ...] [--check ID ...] [--most 2] [--claims] [--out reports]``.
A mutant is killed when the check's verdict changes or it raises (paper_repro/claims/lines/mutation.py); each
survivor is listed with its line, operator and the change, unless it is recorded as equivalent (with its reason) in
paper_repro/claims/lines/equivalents.py.  Exit 1 when the kill rate of the non-equivalent mutants is below --goal.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from paper_repro.claims.lines.mutation import blank_test, check_ids, mutation_test, summary
from paper_repro.util.io import write_text


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--part", nargs="*", default=None, help="sec1_3, sec4_5, sec6, sec7 (default: all)")
    ap.add_argument("--check", nargs="*", default=None, help="only these check ids")
    ap.add_argument("--most", type=int, default=2, help="sites per operator and line (default 2)")
    ap.add_argument("--claims", action="store_true", help="also the lines resolved to claims (slow)")
    ap.add_argument("--goal", type=float, default=0.95)
    ap.add_argument("--out", default="reports")
    a = ap.parse_args(argv)
    from paper_repro.printed.lines import lines_of

    ids = a.check or check_ids(a.claims)
    if a.part:
        ids = [c for c in ids if any(x.id.split("-")[0] in a.part for x in lines_of(c))]
    blank = blank_test(ids)
    recs = mutation_test(ids, most=a.most)
    s = summary(recs)
    survivors_blank = [b for b in blank if not b["killed"]]
    survivors = [r for r in recs if not r["killed"] and not r["equivalent"]]
    out = Path(a.out)
    scope = f"parts {', '.join(a.part)}" if a.part else "every part"
    md = [f"# Mutation test of the line checks ({scope})", "",
          "Made by `make mutate-lines` (tools/mutate_lines.py). A check must fail when its line is blanked or changed "
          "so that it says something else; a mutant that keeps the line true is recorded as equivalent, with the "
          "reason, in `paper_repro/claims/lines/equivalents.py`.", "",
          f"* checks: {len(ids)}; blank test: {len(blank) - len(survivors_blank)} of {len(blank)} fail on a blank "
          f"line ({len(survivors_blank)} survivors)",
          f"* mutants: {s['mutants']} ({s['equivalent']} equivalent); killed {s['killed']} of {s['counted']} "
          f"= {100 * s['rate']:.1f} % (goal {100 * a.goal:.0f} %)", "",
          "| operator | killed | of |", "|---|---|---|"]
    md += [f"| {op} | {v['killed']} | {v['of']} |" for op, v in s["by_op"].items()]
    md += ["", "## Survivors of the blank test", ""]
    md += [f"* `{b['check']}` ({', '.join(b['lines'])}): verdict {b['verdict']} unchanged" for b in survivors_blank]
    md += ["", "## Surviving mutants", "", "| line | check | operator | change |", "|---|---|---|---|"]
    from paper_repro.claims.lines.equivalents import UNCHECKABLE

    md[-2:] = ["| line | check | operator | change | why it survives |", "|---|---|---|---|---|"]
    md += [f"| {r['line']} | {r['check']} | {r['op']} | `{r['where'].replace('|', '/')}` | "
           f"{UNCHECKABLE.get(r['key'], 'a gap of the check')} |" for r in survivors]
    md += ["", "## Equivalent mutants", "", "| mutant | reason |", "|---|---|"]
    md += [f"| {r['key']} | {r['equivalent']} |" for r in recs if r["equivalent"]]
    suffix = "" if not (a.part or a.check) else "_" + "_".join(a.part or ["some"])
    write_text(out / f"mutate_lines{suffix}.md", "\n".join(md) + "\n")
    write_text(out / f"mutate_lines{suffix}.json",
               json.dumps({"summary": s, "blank_survivors": survivors_blank, "survivors": survivors},
                          indent=1, default=str) + "\n")
    print(f"mutate-lines: blank survivors {len(survivors_blank)}; killed {s['killed']} of {s['counted']} "
          f"non-equivalent mutants ({100 * s['rate']:.1f} %); {out}/mutate_lines{suffix}.md")
    return 0 if (s["rate"] >= a.goal and not survivors_blank) else 1


if __name__ == "__main__":
    sys.exit(main())
