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
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(130)
sys.exit(code)
