"""The architecture the README describes: layers import only downwards, and no module outside the
context module compares arithmetic names."""

import ast
import re
from pathlib import Path

PKG = Path(__file__).resolve().parent.parent / "paper_repro"
#: Layer order, lowest first; a module may import from its own layer or lower ones.
LAYERS = ["util", "core", "printed", "surfaces", "claims", "figures", "app"]


def _layer(path: Path) -> str | None:
    rel = path.relative_to(PKG).parts
    return rel[0] if len(rel) > 1 else None


def _imports(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append(node.module)
        elif isinstance(node, ast.Import):
            out += [a.name for a in node.names]
    return out


def test_layers_import_only_downwards():
    bad = []
    for path in PKG.rglob("*.py"):
        layer = _layer(path)
        if layer is None:
            continue
        for mod in _imports(path):
            parts = mod.split(".")
            if parts[0] != "paper_repro" or len(parts) < 2 or parts[1] not in LAYERS:
                continue
            if LAYERS.index(parts[1]) > LAYERS.index(layer) and not (layer == "printed" and parts[1] == "printed"):
                bad.append(f"{path.relative_to(PKG)} imports {mod}")
    assert not bad, bad


def test_no_comparison_of_arithmetic_names_outside_the_context_module():
    pattern = re.compile(r"""(\.name\s*(==|!=|in)\s*\(?["'](float|mp|exact|ball|modp)["'])|"""
                         r"""(arith\s*(==|!=)\s*["'](float|mp|exact|ball|modp)["'])|(arith\s+(not\s+)?in\s*\()""")
    bad = [f"{p.relative_to(PKG)}:{k + 1}" for p in PKG.rglob("*.py") if p.name != "context.py"
           for k, line in enumerate(p.read_text(encoding="utf-8").splitlines()) if pattern.search(line)]
    assert not bad, bad


def test_the_checks_above_can_fail():
    assert _layer(PKG / "core" / "basis.py") == "core"
    assert "paper_repro.core.context" in _imports(PKG / "core" / "basis.py")
