import sys

try:
    from paper_repro.app.cli import main
except KeyboardInterrupt:  # Ctrl-C while importing: one line, exit 130
    print("interrupted (Ctrl-C)", file=sys.stderr)
    sys.exit(130)

sys.exit(main())
