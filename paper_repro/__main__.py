import os
import sys

try:
    from paper_repro.app.cli import main
except KeyboardInterrupt:  # Ctrl-C while importing: one line, exit 130
    print("interrupted (Ctrl-C)", file=sys.stderr)
    sys.exit(130)

code = main()
if code == 130:
    # interrupted: the workers are stopped and every file was written atomically, so skip the interpreter's
    # shutdown (joining executor threads can take seconds on a loaded machine) and exit at once
    # Release the worker pool's semaphores first (multiprocessing's exit-time finalizers of priority >= 0: they
    # unlink them), so the fork server's resource tracker has nothing to report as leaked
    from multiprocessing import util as _mp_util

    _mp_util._run_finalizers(0)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(130)
try:
    sys.stdout.flush()  # the last buffered lines: a reader that went away is a quiet exit, not a traceback
except BrokenPipeError:
    from paper_repro.app.cli import quiet_broken_pipe

    code = quiet_broken_pipe()
sys.exit(code)
