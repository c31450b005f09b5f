"""tools/mutate_code.py (``make mutate-code``): its mutants and their keys, without running any (issue 39, item 6)."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("mutate_code", ROOT / "tools" / "mutate_code.py")
mc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(mc)

SOURCE = '''
def f(x, n=2):
    if x < n and not x:
        raise ValueError("x")
    return x + 1


def g(y):
    return y * 2 == 4
'''


def test_every_module_is_listed_and_its_keys_are_unique():
    listed = set(mc.MODULES)
    on_disk = {str(p.relative_to(ROOT / "paper_repro")) for d in ("core", "surfaces")
               for p in (ROOT / "paper_repro" / d).glob("*.py") if p.name != "__init__.py"}
    assert on_disk <= listed, on_disk - listed
    for module in sorted(on_disk):
        keys = mc.mutant_keys(module, (ROOT / "paper_repro" / module).read_text())
        assert len(keys) == len(set(keys)), module
    assert all(k in mc.MODULES for k in mc.SKIPPED)


def test_mutants_are_the_documented_operators_and_keys_survive_code_moving_elsewhere():
    keys = mc.mutant_keys("m.py", SOURCE)
    muts = {k: mc._apply(SOURCE, i) for i, k in enumerate(keys)}
    shown = {k: m[4] for k, m in muts.items() if m is not None}
    assert shown["m.py:f:compare0:" + mc.hashlib.sha256(b"x < n").hexdigest()[:8] + "#0"] == \
        "if x <= n and (not x):"
    assert shown["m.py:f:raise0:" + mc.hashlib.sha256(b'raise ValueError("x")').hexdigest()[:8] + "#0"] == "pass"
    assert "return None" in shown.values() and "if x < n and x:" in shown.values()
    assert "def f(x, n=3):" in shown.values() and "return y / 2 == 4" in shown.values()
    assert "return y * 2 != 4" in shown.values() and "if x < n or not x:" in shown.values()
    for k, m in muts.items():  # each mutant compiles and differs from the module
        assert m is not None and ast.unparse(ast.parse(SOURCE)) != m[0], k
    moved = "import os\n\n\ndef h():\n    return 1 + 1\n" + SOURCE  # new code above: the keys of f and g stay
    assert set(keys) <= set(mc.mutant_keys("m.py", moved))
