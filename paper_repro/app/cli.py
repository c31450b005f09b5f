"""Command line: python -m paper_repro {claims,figures,reproduce,paper,labels}.

  claims [--only ID ...] [--n N] [--alpha A] [--extended] [--n-max N] [--scheduler SPEC] [--list]
      run claims and print the table; a full run (no --only/--n/--alpha) also writes data/,
      a partial run only prints
  figures [--only ID ...] [--list]
      regenerate figures, figures/manifest.json and the gallery figures/index.html
  reproduce [--extended] [--n-max N] [--scheduler local:N|tcp://HOST:PORT]
      everything: claims, data, figures, gallery, annotated paper; exit 1 if a claim fails
      (--scheduler, or $PAPER_REPRO_SCHEDULER: the claims' tasks on a dask cluster, docs/cluster.md;
      --n-max N: the extended ranges pushed to order N, the estimated CPU time printed first)
  paper
      the annotated paper paper/index.html (needs the paper's LaTeX source beside the clone)
  labels N
      the paper labels of T_{2n} with their internal indices and exponents

Bad input: one line on stderr and exit 2.  Ctrl-C: one line, pending work cancelled, exit 130.

Outputs go below --out DIR (default: the clone's root in a checkout, else the current
directory; never the install location).  Cache: $PAPER_REPRO_CACHE, else .cache/ in a checkout,
else the user's cache folder; PAPER_REPRO_NO_CACHE=1 switches it off.
"""

from __future__ import annotations

import argparse
import sys

from paper_repro.core.labels import SLOTS, exponents, united_system
from paper_repro.util.registry import CLAIMS, FIGURES, load_all

from . import report


def _parse_alpha(text: str) -> str:
    from paper_repro.util.validation import parse_alpha

    parse_alpha(text, "--alpha")  # validates: ValueError names --alpha and the range
    return text


class _Parser(argparse.ArgumentParser):
    """argparse, but a bad argument is one line on stderr (``error: ...``) and exit 2, without the usage block."""

    def error(self, message: str):
        print(f"error: {message}", file=sys.stderr)
        raise SystemExit(2)


def _first_line(text: str) -> str:
    """The first sentence of a docstring or statement, without RST markup."""
    import re

    line = " ".join((text or "").strip().split())
    line = re.sub(r":\w+:`~?([^`]+)`", r"\1", line).replace("``", "").replace("`", "")
    cut = line.find(". ")
    line = line[: cut + 1] if 0 < cut < 110 else line
    return line if len(line) <= 110 else line[:107] + "..."


def _list(kind: str) -> int:
    reg = CLAIMS if kind == "claims" else FIGURES
    width = max(len(k) for k in reg)
    for cid, item in reg.items():
        text = item.statement if kind == "claims" else item.caption
        print(f"{cid.ljust(width)}  {_first_line(text)}")
    return 0


INTERRUPTED = "interrupted (Ctrl-C): pending work cancelled; data/ and the cache are unchanged"
#: Seconds after Ctrl-C before the watchdog ends the process itself (the orderly path takes at most 1.5 s).
WATCHDOG_SECONDS = 1.8
_reported = False


def _watchdog() -> None:
    """Started by Ctrl-C: if the orderly shutdown has not ended the process after WATCHDOG_SECONDS (say the
    interrupted thread holds a lock that the executor's manager thread waits on), kill the child processes and
    exit 130.  Files are written atomically (temp file + rename), so data/ and the cache stay valid."""
    import multiprocessing
    import os
    import threading

    def hard_exit() -> None:
        for child in multiprocessing.active_children():
            child.kill()
        if not _reported:
            os.write(2, (INTERRUPTED + "\n").encode())
        os._exit(130)

    timer = threading.Timer(WATCHDOG_SECONDS, hard_exit)
    timer.daemon = True
    timer.start()


def _on_sigint(signum, frame) -> None:  # noqa: ARG001 - signal handler signature
    _watchdog()
    # The command ends now (exit 130): tell multiprocessing that this process is exiting, so the queue feeder
    # threads of a stopped pool drop their writes quietly instead of printing a traceback when the pipes they
    # feed are closed under them (seen in CI: "Exception in thread QueueFeederThread ... in _feed").  The same
    # flag multiprocessing sets itself at interpreter exit; ``os._exit`` skips that, so it is set here.
    import multiprocessing.util

    multiprocessing.util._exiting = True
    raise KeyboardInterrupt


#: Exit status after the reader of standard output went away (128 + SIGPIPE, what a shell reports for a
#: Unix tool killed by SIGPIPE).
BROKEN_PIPE = 141


def quiet_broken_pipe() -> int:
    """Point the process's standard output at ``os.devnull`` (so the interpreter's final flush does not print a
    second error) and return :data:`BROKEN_PIPE`; no traceback.  Only the real stdout is redirected (a caller's
    replacement, as in tests, is left alone)."""
    import os

    if sys.stdout is sys.__stdout__ and sys.stdout is not None:
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)
        except (OSError, ValueError):
            pass
    return BROKEN_PIPE


def main(argv: list[str] | None = None) -> int:
    """Run a command; bad input is one line and exit 2, Ctrl-C one line and exit 130 (pending work cancelled,
    within 2 s: a watchdog ends the process if the orderly shutdown does not)."""
    global _reported
    import signal
    import threading

    previous = None
    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGINT, _on_sigint)
    try:
        return _main(argv)
    except KeyboardInterrupt:
        _reported = True
        print(INTERRUPTED, file=sys.stderr)
        return 130
    except BrokenPipeError:  # the reader went away (``... | head -1``): stop quietly, as Unix tools do
        return quiet_broken_pipe()
    finally:
        if previous is not None:  # called from Python (tests, notebooks): give Ctrl-C back as it was
            signal.signal(signal.SIGINT, previous)


#: Commands that write below the output root (``claims`` only in a full run: a partial run prints).
WRITES = ("figures", "reproduce", "paper")
#: Commands that compute (and use the cache and the kernel).
COMPUTES = ("claims", "figures", "reproduce", "paper")


def _check_environment(args: argparse.Namespace) -> None:
    """Refuse, before any work, what would make the run fail late: a bad ``PAPER_REPRO_KERNEL`` or
    ``PAPER_REPRO_THREADS``, an ``--out`` that is empty, a file or not writable, the output root of a command that
    writes when it is not writable, and an unwritable cache folder.  ``ValueError`` with one line."""
    import os

    from paper_repro.core import fast, fast_jit
    from paper_repro.util import cache
    from paper_repro.util.io import output_root, unwritable

    if getattr(args, "list", False):
        return
    fast_jit.available()  # ValueError naming PAPER_REPRO_KERNEL
    fast.threads()  # ValueError naming PAPER_REPRO_THREADS
    out = getattr(args, "out", None)
    if out is not None:
        if not out.strip():
            raise ValueError("--out must name a folder, got an empty string")
        why = unwritable(os.path.expanduser(out))
        if why:
            raise ValueError(f"--out: cannot write there: {why}")
    full_claims = args.cmd == "claims" and not (args.only or args.n is not None or args.alpha is not None)
    if out is None and (args.cmd in WRITES or full_claims):
        why = unwritable(output_root())
        if why:
            raise ValueError(f"the output folder cannot be written: {why}; give --out DIR")
    if args.cmd in COMPUTES and cache.enabled():
        why = cache.unusable()
        if why:
            raise ValueError(f"the cache folder cannot be written: {why}; set {cache.CACHE_ENV} to a writable folder "
                             f"or {cache.NO_CACHE_ENV}=1")


def _cluster_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--scheduler", metavar="SPEC", help="run the claims' tasks on a dask.distributed cluster: "
                   "'local:N' (N local worker processes) or 'tcp://HOST:PORT' (a running scheduler); default "
                   "$PAPER_REPRO_SCHEDULER, else local processes (docs/cluster.md)")
    p.add_argument("--n-max", type=int, metavar="N", help="push the extended ranges of the heavy claims to order N "
                   "(implies --extended; prints the estimated CPU time first)")


def _main(argv: list[str] | None = None) -> int:
    parser = _Parser(prog="python -m paper_repro", description=__doc__,
                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="cmd", required=True, parser_class=_Parser)
    out_help = "write data/, figures/, build/ below DIR (default: the clone in a checkout, else the current directory)"
    pc = sub.add_parser("claims", help="run registered claims", description="Run claims and print the table.")
    pc.add_argument("--list", action="store_true", help="print the claim ids with one-line descriptions and exit")
    pc.add_argument("--only", nargs="+", metavar="ID", help="claim ids to run (see --list)")
    pc.add_argument("--n", type=int, help="run at this order n only (claims that take n)")
    pc.add_argument("--alpha", type=str, help="run at this alpha only, in (0, pi), e.g. 'pi/3', '2pi/3' or '1.2'")
    pc.add_argument("--extended", action="store_true", help="use the extended parameter ranges (larger n; slow)")
    pc.add_argument("--out", metavar="DIR", help=out_help)
    _cluster_options(pc)
    pf = sub.add_parser("figures", help="regenerate figures and the gallery",
                        description="Regenerate figures, figures/manifest.json and the gallery figures/index.html.")
    pf.add_argument("--list", action="store_true", help="print the figure ids with one-line descriptions and exit")
    pf.add_argument("--only", nargs="+", metavar="ID", help="figure ids to regenerate (see --list)")
    pf.add_argument("--out", metavar="DIR", help=out_help)
    pr = sub.add_parser("reproduce", help="claims, data, figures and gallery",
                        description="Every claim, data/, figures/ and the gallery; exit 1 if a claim fails.")
    pr.add_argument("--extended", action="store_true",
                    help="use the extended parameter ranges (larger n; about 6 minutes cold on 2 cores)")
    pr.add_argument("--out", metavar="DIR", help=out_help)
    _cluster_options(pr)
    sub.add_parser("paper", help="the annotated paper paper/index.html",
                   description="The annotated paper paper/index.html (needs the LaTeX source beside the clone).")
    pl = sub.add_parser("labels", help="print the labels of T_{2n}",
                        description="The paper labels of T_{2n}: internal index, label, level and monomial.")
    pl.add_argument("n", type=int, help="the order n (T_{2n} has 3n(n+1)+1 functions)")
    args = parser.parse_args(argv)
    try:  # the environment, --scheduler / $PAPER_REPRO_SCHEDULER and --n-max: validated before any work
        _check_environment(args)
        from paper_repro.app.cluster import scheduler_from

        scheduler = scheduler_from(getattr(args, "scheduler", None))
        n_max_overrides = report.n_max_overrides(args.n_max) if getattr(args, "n_max", None) is not None else None
    except ValueError as exc:
        print(f"error: {str(exc).splitlines()[0]}", file=sys.stderr)
        return 2
    if getattr(args, "out", None) is not None:
        from paper_repro.util.io import set_output_root

        set_output_root(args.out)
    load_all()
    if getattr(args, "list", False):
        return _list(args.cmd)
    try:
        if args.cmd == "labels":
            from paper_repro.util.limits import MAX_N_LABELS, check_int
            from paper_repro.util.validation import check_n

            n = check_int(check_n(args.n, "N"), "N", 1, MAX_N_LABELS,
                          why="3N(N+1)+1 lines, time grows as N^2: N = 1000 took 93 s")
            for k, lab in enumerate(united_system(n)):
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
            if n_max_overrides is not None:
                per_claim = {cid: {**ov, **n_max_overrides.get(cid, {})} for cid, ov in per_claim.items()}
            with report.claims_executor(scheduler, per_claim if n_max_overrides else None,
                                        args.extended or n_max_overrides is not None) as ex:
                ok = report.run_claims(list(per_claim), per_claim, extended=args.extended or bool(n_max_overrides),
                                       write=not partial, executor=ex)
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
            import time

            from paper_repro.util.io import data_dir, figures_dir, output_root

            start, start_ns = time.perf_counter(), time.time_ns()
            extended = args.extended or n_max_overrides is not None
            with report.claims_executor(scheduler, n_max_overrides, extended) as ex:
                ok = report.run_claims(None, n_max_overrides, extended=extended, write=True, executor=ex)
            if ok and not args.extended:
                from paper_repro.app import gallery

                gallery.REPRODUCED = True
            if extended:  # the figures are drawn from the non-extended data: only the gallery page is refreshed
                report.refresh_gallery()
            else:
                report.make_figures(None)
            from paper_repro.app.annotated_paper import write_paper

            write_paper()
            written = report.files_written_since(start_ns, [data_dir(), figures_dir(), output_root() / "paper",
                                                            output_root() / "README.md"])
            print(report.reproduce_summary(ok, written, time.perf_counter() - start))
            return 0 if ok else 1
    except (ValueError, TypeError) as exc:
        print(f"error: {str(exc).splitlines()[0] if str(exc) else type(exc).__name__}", file=sys.stderr)
        return 2
    return 0
