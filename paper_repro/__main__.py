import sys

from paper_repro.app.cli import main

sys.exit(main())
