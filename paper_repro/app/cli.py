"""Command line: ``python -m paper_repro {claims,figures,reproduce,labels}``.

* ``claims [--only ID ...] [--n N] [--alpha A] [--extended]`` -- run claims and print the table.
  A full run (no ``--only``/``--n``/``--alpha``) also writes ``data/``; a partial run only prints.
* ``figures [--only ID ...]`` -- regenerate figures, ``figures/manifest.json`` and the gallery.
* ``reproduce [--extended]`` -- everything: claims, data, figures, gallery, annotated paper; exit 1 if a claim fails.
* ``paper`` -- the annotated paper ``paper/index.html`` (needs the paper's LaTeX source beside the clone).
* ``labels N`` -- the paper labels of T_{2n} with their internal indices and exponents.
"""

from __future__ import annotations

import argparse
import sys

from paper_repro.core.labels import SLOTS, exponents, united_system
from paper_repro.util.registry import CLAIMS, FIGURES, load_all

from . import report


def _parse_alpha(text: str) -> str:
    from paper_repro.core.alphas import alpha_float

    alpha_float(text)  # validates: ValueError names alpha and the range
    return text


class _Parser(argparse.ArgumentParser):
    """argparse, but a bad argument is one line on stderr (``error: ...``) and exit 2, without the usage block."""

    def error(self, message: str):
        print(f"error: {message}", file=sys.stderr)
        raise SystemExit(2)


def main(argv: list[str] | None = None) -> int:
    """Run a command; bad input is one line and exit 2, Ctrl-C one line and exit 130 (pending work cancelled)."""
    try:
        return _main(argv)
    except KeyboardInterrupt:
        print("interrupted (Ctrl-C): pending work cancelled; data/ and the cache are unchanged", file=sys.stderr)
        return 130


def _main(argv: list[str] | None = None) -> int:
    parser = _Parser(prog="python -m paper_repro", description=__doc__,
                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="cmd", required=True, parser_class=_Parser)
    pc = sub.add_parser("claims", help="run registered claims")
    pc.add_argument("--only", nargs="+", metavar="ID", help="claim ids to run")
    pc.add_argument("--n", type=int, help="run at this order n only (claims that take n)")
    pc.add_argument("--alpha", type=str, help="run at this alpha only, e.g. 'pi/3' or '1.2'")
    pc.add_argument("--extended", action="store_true", help="use the extended parameter ranges")
    pf = sub.add_parser("figures", help="regenerate figures and the gallery")
    pf.add_argument("--only", nargs="+", metavar="ID")
    pr = sub.add_parser("reproduce", help="claims, data, figures and gallery")
    pr.add_argument("--extended", action="store_true")
    sub.add_parser("paper", help="the annotated paper paper/index.html")
    pl = sub.add_parser("labels", help="print the labels of T_{2n}")
    pl.add_argument("n", type=int)
    args = parser.parse_args(argv)
    load_all()
    try:
        if args.cmd == "labels":
            from paper_repro.util.validation import check_n

            for k, lab in enumerate(united_system(check_n(args.n, "N"))):
                e = exponents(lab)
                mono = " ".join(f"{SLOTS[s]}^{e[s]}" for s in range(6) if e[s])
                print(f"{k:4d}  {lab.paper:14s} level {lab.j}  {mono}")
            return 0
        if args.cmd == "claims":
            unknown = sorted(set(args.only or []) - set(CLAIMS))
            if unknown:
                raise ValueError(f"--only: unknown claim id(s) {unknown}; known: {sorted(CLAIMS)}")
            from paper_repro.core.alphas import alpha_float
            from paper_repro.util.registry import check_cli_range, cli_overrides
            from paper_repro.util.validation import check_n

            n = check_n(args.n, "--n") if args.n is not None else None
            alpha = _parse_alpha(args.alpha) if args.alpha is not None else None
            per_claim: dict[str, dict] = {}
            skipped = []
            for cid in args.only or list(CLAIMS):
                ov = cli_overrides(CLAIMS[cid], n, alpha)
                if ov is None:
                    if args.only:
                        raise ValueError(f"claim {cid!r} takes no {'--n' if n is not None else '--alpha'}; "
                                         f"it takes {sorted(CLAIMS[cid].defaults)}")
                    skipped.append(cid)
                else:
                    check_cli_range(CLAIMS[cid], n, None if alpha is None else alpha_float(alpha))
                    per_claim[cid] = ov
            if skipped:
                print(f"skipped (they take no --n/--alpha): {', '.join(skipped)}")
            partial = bool(args.only or n is not None or alpha is not None)
            ok = report.run_claims(list(per_claim), per_claim, extended=args.extended, write=not partial)
            return 0 if ok else 1
        if args.cmd == "paper":
            from paper_repro.app.annotated_paper import write_paper

            write_paper()
            return 0
        if args.cmd == "figures":
            unknown = sorted(set(args.only or []) - set(FIGURES))
            if unknown:
                raise ValueError(f"--only: unknown figure id(s) {unknown}; known: {sorted(FIGURES)}")
            report.make_figures(args.only)
            return 0
        if args.cmd == "reproduce":
            ok = report.run_claims(None, None, extended=args.extended, write=True)
            report.make_figures(None)
            from paper_repro.app.annotated_paper import write_paper

            write_paper()
            return 0 if ok else 1
    except (ValueError, TypeError) as exc:
        print(f"error: {str(exc).splitlines()[0] if str(exc) else type(exc).__name__}", file=sys.stderr)
        return 2
    return 0
