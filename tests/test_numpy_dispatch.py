"""The promised results have the same bits whatever SIMD code numpy dispatches its ufuncs to (marker ``bits``).

numpy picks at run time, per CPU, the SIMD code of its ufuncs: on an AVX512 machine float64 ``exp``, ``log``,
``power``, ``tan``, ... are Intel SVML (not correctly rounded), on an AVX2 or older one other code -- a user's
machine can get other last bits than this one (a ``kp ** np.arange(k)`` in the subdivision's product route did).
Here every promised item of ``tools/cpu_bits.py`` is recomputed in a child process with numpy's dispatch limited by
``NPY_DISABLE_CPU_FEATURES`` (``tools/cpu_bits.py numpy-env``: ``avx2`` = no AVX512, ``baseline`` = SSE4.2 on
x86-64) and compared with this process.  On a machine without AVX512 the ``avx2`` child runs what this process runs
(the comparison still covers ``baseline``).  ``make test-bits-numpy-dispatch`` runs every ``bits`` test that way.
"""

import importlib.util
import json
import os
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("cpu_bits", ROOT / "tools" / "cpu_bits.py")
cpu_bits = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cpu_bits)

#: What the child prints: the fingerprints of the promised items, numpy's dispatch, a probe of numpy's power.
_CHILD = """
import hashlib, json, sys
import numpy as np
sys.path.insert(0, {tools!r})
import cpu_bits
x = np.linspace(0.01, 3.0, 4099)
print(json.dumps({{"fp": cpu_bits.fingerprints(cpu_bits.compute(promised_only=True)),
                  "numpy": cpu_bits.numpy_dispatch(),
                  "power": hashlib.sha256(np.power(x, 7.3).tobytes()).hexdigest()}}))
"""


def _power_probe() -> str:
    import hashlib

    import numpy as np

    return hashlib.sha256(np.power(np.linspace(0.01, 3.0, 4099), 7.3).tobytes()).hexdigest()


@cache
def _here() -> dict:
    return {"fp": cpu_bits.fingerprints(cpu_bits.compute(promised_only=True)), "numpy": cpu_bits.numpy_dispatch(),
            "power": _power_probe()}


@cache
def _child(variant: str) -> dict:
    value = cpu_bits.numpy_env(variant)
    if value is None:
        pytest.skip(f"numpy variant {variant} does not apply to this numpy build")
    env = dict(os.environ, NPY_DISABLE_CPU_FEATURES=value, PYTHONWARNINGS="error::ImportWarning")
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT)] + [p for p in [os.environ.get("PYTHONPATH")] if p])
    out = subprocess.run([sys.executable, "-c", _CHILD.format(tools=str(ROOT / "tools"))], cwd=ROOT, env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def _svml_here() -> bool:
    """Whether this process runs numpy's AVX512 (SVML) float64 power."""
    current = str(cpu_bits.numpy_dispatch().get("power", ""))
    return "AVX512" in current or "X86_V4" in current


@pytest.mark.parametrize("variant", cpu_bits.NUMPY_VARIANTS)
def test_the_variant_limits_numpy_dispatch(variant):
    """The knob takes effect: the child's float64 power runs no AVX512 code (``baseline``: the baseline code)."""
    info = _child(variant)["numpy"]
    if "power" not in info:
        pytest.skip("numpy < 2.2: no numpy.lib.introspect.opt_func_info to read the dispatch from")
    assert "AVX512" not in info["power"] and "X86_V4" not in info["power"], info
    if variant == "baseline":
        assert info["power"].startswith("baseline"), info


def test_the_comparison_sees_numpy_dispatch():
    """Where this process runs SVML, numpy's own power has other bits in the ``avx2`` child: the comparison below
    would see a promised result that went through such a ufunc."""
    if not _svml_here():
        pytest.skip("numpy runs no AVX512 code here: nothing to tell apart")
    assert _child("avx2")["power"] != _here()["power"]


@pytest.mark.parametrize("variant", cpu_bits.NUMPY_VARIANTS)
@pytest.mark.parametrize("group", list(cpu_bits.PROMISED))
def test_promised_results_do_not_depend_on_numpy_dispatch(group, variant):
    here, there = _here()["fp"], _child(variant)["fp"]
    items = sorted(k for k in here if k.split("/")[0] == group)
    assert items and set(items) <= set(there)
    differ = [k for k in items if here[k] != there[k]]
    assert not differ, f"other bits with numpy's dispatch limited to {variant}: {differ}"
