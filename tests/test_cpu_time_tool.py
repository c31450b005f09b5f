"""tools/cpu_time.py counts the CPU time of orphaned descendants (the fork server's workers of a run)."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

TOOL = Path(__file__).resolve().parent.parent / "tools" / "cpu_time.py"

#: The parent exits at once; its child, orphaned, burns about 0.4 s of CPU and is reaped by the tool.
ORPHAN = ("import os, time\n"
          "if os.fork() == 0:\n"
          "    t = time.process_time()\n"
          "    while time.process_time() - t < 0.4:\n"
          "        pass\n"
          "    os._exit(0)\n")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="child subreaper: Linux only")
def test_cpu_of_an_orphan_is_counted():
    out = subprocess.run([sys.executable, str(TOOL), sys.executable, "-c", ORPHAN], capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0, out.stderr
    cpu = float(re.search(r"cpu=([\d.]+)s", out.stderr).group(1))
    assert cpu >= 0.35, out.stderr


def test_exit_status_is_the_commands():
    out = subprocess.run([sys.executable, str(TOOL), sys.executable, "-c", "raise SystemExit(3)"],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 3 and "rc=3" in out.stderr
