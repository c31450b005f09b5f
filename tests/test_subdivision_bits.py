"""The float subdivision route gives the same bits whatever SIMD loops numpy dispatches to
(docs/subdivision_for_all_n.md, section 11, "Implementation"; the referee's point 2 in "Referee report and answers").

The referee's method: :func:`~paper_repro.core.subdivision_products.subdivision_matrices_float` for n in {4, 8} and
alpha in {0.3, 1, 2.5}, hashed, in a fresh process run normally and with numpy's dispatch limited
(``NPY_DISABLE_CPU_FEATURES`` listing every AVX512 feature of the machine and the X86_V4 group numpy 2.4 dispatches
to).  Before the fix numpy's ``power`` (SVML under AVX512) made 851 of 609 720 entries differ.  The test first shows
that the limited run really changes numpy's bits (``np.power`` on an array differs), else it is skipped: on a machine
without AVX512 there is nothing to compare.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]

_ROUTE = """
import hashlib
import numpy as np
from paper_repro.core.subdivision_products import subdivision_matrices_float
h = hashlib.sha256()
for n in (4, 8):
    for a in (0.3, 1.0, 2.5):
        for m in subdivision_matrices_float(n, a):
            h.update(np.ascontiguousarray(m).tobytes())
print(h.hexdigest())
"""

_POWER = """
import hashlib
import numpy as np
x = np.linspace(0.5, 0.99, 80000)
print(hashlib.sha256((x ** np.arange(80000) % 37).tobytes()).hexdigest())
"""


def _avx512_features() -> list[str]:
    try:
        from numpy._core._multiarray_umath import __cpu_features__ as feats
    except ImportError:  # pragma: no cover - numpy < 2
        from numpy.core._multiarray_umath import __cpu_features__ as feats
    return [k for k, v in feats.items() if v and (k.startswith("AVX512") or k == "X86_V4")]


def _run(code: str, limit: list[str]) -> str:
    env = {k: v for k, v in os.environ.items() if not k.startswith("NPY_")}
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    if limit:
        env["NPY_DISABLE_CPU_FEATURES"] = " ".join(limit)
    out = subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True,
                         timeout=300, check=True)
    return out.stdout.strip()


@pytest.mark.bits
def test_float_route_bits_independent_of_numpy_dispatch():
    limit = _avx512_features()
    if not limit:
        pytest.skip("no AVX512 on this machine: numpy's dispatch cannot be limited below it")
    if _run(_POWER, []) == _run(_POWER, limit):
        pytest.skip("limiting numpy's dispatch does not change np.power here: the comparison would prove nothing")
    assert _run(_ROUTE, []) == _run(_ROUTE, limit)


def test_power_table_is_repeated_multiplication():
    """The powers of the float route are products from the left, never ``pow``."""
    from paper_repro.core.subdivision_products import _power, power_table

    for x in (0.3, 0.9987654321, 1e-50):
        t = power_table(x, 40)
        acc = 1.0
        for k in range(41):
            assert t[k] == acc == _power(x, k)
            acc *= x
    assert np.array_equal(power_table(0.5, 3), [1.0, 0.5, 0.25, 0.125])
