"""The architecture the README describes: layers import only downwards, and no module outside the
context module compares arithmetic names."""

import ast
import re
import subprocess
import sys
from pathlib import Path

PKG = Path(__file__).resolve().parent.parent / "paper_repro"
#: Layer order, lowest first; a module may import from its own layer or lower ones.
LAYERS = ["util", "core", "theory", "printed", "surfaces", "claims", "figures", "app"]


def _layer(path: Path) -> str | None:
    rel = path.relative_to(PKG).parts
    return rel[0] if len(rel) > 1 else None


def _imports(path: Path) -> list[str]:
    """Every module named by an import of ``path`` (``from a import b`` gives ``a`` and ``a.b``)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append(node.module)
            out += [f"{node.module}.{a.name}" for a in node.names]
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


def _module_name(path: Path) -> str:
    rel = path.relative_to(PKG.parent).with_suffix("")
    parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
    return ".".join(parts)


def _import_graph() -> dict[str, set[str]]:
    """Module -> the package modules it imports anywhere (function-level imports included)."""
    modules = {_module_name(p): p for p in PKG.rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        deps = set()
        for mod in _imports(path):
            # ``from paper_repro.core import labels`` names a module too: keep the longest known prefix
            while mod and mod not in modules:
                mod = mod.rpartition(".")[0]
            if mod and mod != name and mod != "paper_repro":
                deps.add(mod)
        graph[name] = deps
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_circles():
    """No two modules import each other, directly or through others (function-level imports count)."""
    assert _cycles(_import_graph()) == []


def test_the_cycle_check_can_fail():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_importing_the_package_imports_nothing_heavy():
    """``python -m paper_repro`` imports the package before any of our code runs (runpy): a Ctrl-C then would be
    Python's own traceback.  The package's public names are imported on first use, so that window is only the
    interpreter's start-up; the names still work (``from paper_repro import Patch``)."""
    code = ("import sys, paper_repro; heavy = [m for m in ('numpy', 'flint', 'mpmath', 'paper_repro.core') "
            "if m in sys.modules]; assert not heavy, heavy; from paper_repro import Patch, coefficients; "
            "assert Patch.__module__ == 'paper_repro.surfaces.patch'; "
            "assert coefficients(1, 'pi/2') == coefficients(1, 3.141592653589793 / 2); "
            "assert set(paper_repro.__all__) <= set(dir(paper_repro))")
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)
