"""The results promised bit-identical on every CPU (README, "Same bits on every CPU") have the pinned bits.

``tests/fixtures/cpu_bits.json`` holds the sha256 of each promised item of ``tools/cpu_bits.py`` as computed on the
reference machine; this test recomputes them.  Under another OpenBLAS kernel (``make test-cpus``, and CI's
``make test-bits-other-cpu``) or numba target it checks that the bits do not depend on the CPU (issue 31)."""

import importlib.util
import json
import math
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("cpu_bits", ROOT / "tools" / "cpu_bits.py")
cpu_bits = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cpu_bits)


def test_promised_results_have_the_pinned_bits():
    pinned = json.loads((ROOT / "tests" / "fixtures" / "cpu_bits.json").read_text())
    got = cpu_bits.fingerprints(cpu_bits.compute(promised_only=True))
    assert set(got) == set(pinned)
    differ = sorted(k for k in got if got[k] != pinned[k])
    assert not differ, f"other bits than the pinned ones (tools/cpu_bits.py pin after an intended change): {differ}"


def test_the_comparison_can_fail():
    values = cpu_bits.compute(promised_only=True)
    item = sorted(values)[0]
    last_bit = math.nextafter(float.fromhex(values[item][0]), math.inf).hex()  # one unit in the last place
    changed = dict(values, **{item: [last_bit] + values[item][1:]})
    assert cpu_bits.fingerprints(changed)[item] != cpu_bits.fingerprints(values)[item]
