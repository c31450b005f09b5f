"""``make mutate-code``: a mutation test of the library code -> reports/mutate_code.{md,json}.

For each module of :data:`MODULES` (the core and surfaces modules), ``--per-module`` mutants are drawn (seeded, so
the same on every run) from the operators below, each applied at one site of the module's source:

* ``compare``: ``<`` <-> ``<=``, ``>`` <-> ``>=``, ``==`` <-> ``!=``, ``is`` <-> ``is not``, ``in`` <-> ``not in``;
* ``arith``: ``+`` <-> ``-``, ``*`` <-> ``/``, ``//`` -> ``/``, ``**`` -> ``*``;
* ``const``: an integer constant ``k`` -> ``k + 1``; ``True`` <-> ``False``;
* ``bool``: ``and`` <-> ``or``; ``not x`` -> ``x``;
* ``return``: ``return x`` -> ``return None`` (not in ``__init__``);
* ``raise``: a ``raise`` statement -> ``pass`` (a check that never fires).

Each mutant is written into a scratch copy of the package (never into the work tree) and the tests that cover the
module (:data:`MODULES`: test files and doctests) run against it with ``pytest -x`` and a time limit; a mutant is
*killed* when they fail (or time out).  A surviving mutant is either a gap in the tests or *equivalent* (it changes
nothing observable): record equivalent ones with the reason in :data:`EQUIVALENT` (key: module, line, operator,
the mutated line), so the rate counts only the others.  Goal: >= 95 % of the non-equivalent mutants killed in every
module.  Usage::

    .venv/bin/python tools/mutate_code.py [--module core/elevation.py ...] [--per-module 30] [--seed 0] [--jobs 2]
"""

from __future__ import annotations

import argparse
import ast
import hashlib
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: module (below paper_repro/) -> the tests that cover it (files or node ids; the module's doctests always run)
MODULES: dict[str, list[str]] = {
    "core/elevation.py": ["tests/test_elevation_all_n.py", "tests/test_limits_elevation.py", "tests/test_code_gaps.py",
                          "tests/test_domain_of_validity.py"],
    "core/transformation.py": ["tests/test_transformation_all_n.py"],
    "core/collocation.py": ["tests/test_collocation.py", "tests/test_transformation_all_n.py"],
    "core/domain.py": ["tests/test_domain_of_validity.py", "tests/test_code_gaps.py", "tests/test_patches_surfaces.py"],
    "core/normalization.py": ["tests/test_normalization.py", "tests/test_foundation_claims.py"],
    "core/half_angle_matrices.py": ["tests/test_pairwise_products.py", "tests/test_elevation_all_n.py",
                                    "tests/test_code_gaps.py"],
    "core/layout.py": ["tests/test_figures_readable.py", "tests/test_labels.py"],
    "surfaces/patch.py": ["tests/test_patches_surfaces.py", "tests/test_patch_arithmetics.py", "tests/test_code_gaps.py",
                          "tests/test_library_api.py"],
    "surfaces/joins.py": ["tests/test_joins.py"],
    "core/subdivision.py": ["tests/test_subdivision.py", "tests/test_subdivision_speed.py"],
    "core/subdivision_products.py": ["tests/test_subdivision_speed.py"],
}

#: equivalent mutants: "module:line:operator:mutated line" -> why nothing observable changes
EQUIVALENT: dict[str, str] = {}

_CMP = {ast.Lt: ast.LtE, ast.LtE: ast.Lt, ast.Gt: ast.GtE, ast.GtE: ast.Gt, ast.Eq: ast.NotEq, ast.NotEq: ast.Eq,
        ast.Is: ast.IsNot, ast.IsNot: ast.Is, ast.In: ast.NotIn, ast.NotIn: ast.In}
_ARITH = {ast.Add: ast.Sub, ast.Sub: ast.Add, ast.Mult: ast.Div, ast.Div: ast.Mult, ast.FloorDiv: ast.Div,
          ast.Pow: ast.Mult}


def _sites(tree: ast.AST) -> list[tuple[str, ast.AST, int]]:
    """(operator, node, variant) of every place a mutant can be made (docstrings and annotations excluded)."""
    out: list[tuple[str, ast.AST, int]] = []
    doc_nodes = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(getattr(first, "value", None), ast.Constant):
                doc_nodes.add(id(first.value))
    in_init = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef) and node.name == "__init__":
            in_init |= {id(n) for n in ast.walk(node)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            for k, op in enumerate(node.ops):
                if type(op) in _CMP:
                    out.append(("compare", node, k))
        elif isinstance(node, ast.BinOp) and type(node.op) in _ARITH:
            out.append(("arith", node, 0))
        elif isinstance(node, ast.Constant) and id(node) not in doc_nodes:
            if isinstance(node.value, bool) or (isinstance(node.value, int) and not isinstance(node.value, bool)):
                out.append(("const", node, 0))
        elif isinstance(node, ast.BoolOp):
            out.append(("bool", node, 0))
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            out.append(("bool", node, 1))
        elif isinstance(node, ast.Return) and node.value is not None and id(node) not in in_init:
            out.append(("return", node, 0))
        elif isinstance(node, ast.Raise):
            out.append(("raise", node, 0))
    return out


def _apply(source: str, site_index: int) -> tuple[str, str, int, str] | None:
    """The source with mutant ``site_index`` applied: (new source, operator, line, the original text of the node),
    or None if it does not compile."""
    tree = ast.parse(source)
    sites = _sites(tree)
    op, node, variant = sites[site_index]
    line = getattr(node, "lineno", 0)
    snippet = ast.get_source_segment(source, node) or ""
    if op == "compare":
        node.ops[variant] = _CMP[type(node.ops[variant])]()
    elif op == "arith":
        node.op = _ARITH[type(node.op)]()
    elif op == "const":
        node.value = (not node.value) if isinstance(node.value, bool) else node.value + 1
    elif op == "bool" and variant == 0:
        node.op = ast.Or() if isinstance(node.op, ast.And) else ast.And()
    elif op == "bool":
        for parent in ast.walk(tree):  # replace `not x` by `x`
            for field, value in ast.iter_fields(parent):
                if value is node:
                    setattr(parent, field, node.operand)
                elif isinstance(value, list) and node in value:
                    value[value.index(node)] = node.operand
    elif op == "return":
        node.value = ast.Constant(None)
    elif op == "raise":
        for parent in ast.walk(tree):
            for _field, value in ast.iter_fields(parent):
                if isinstance(value, list) and node in value:
                    value[value.index(node)] = ast.Pass(lineno=node.lineno, col_offset=node.col_offset)
    try:
        new = ast.unparse(ast.fix_missing_locations(tree))
        compile(new, "<mutant>", "exec")
    except (SyntaxError, ValueError):
        return None
    return new, op, line, snippet


def run_mutant(module: str, new_source: str, tests: list[str], timeout: float) -> tuple[bool, float]:
    """Whether the tests fail on the mutant (killed), and the seconds they took."""
    with tempfile.TemporaryDirectory(prefix="mutant-") as tmp:
        pkg = Path(tmp) / "paper_repro"
        shutil.copytree(ROOT / "paper_repro", pkg, ignore=shutil.ignore_patterns("__pycache__"))
        (pkg / module).write_text(new_source)
        shutil.copytree(ROOT / "tests", Path(tmp) / "tests", ignore=shutil.ignore_patterns("__pycache__"))
        shutil.copy(ROOT / "pyproject.toml", Path(tmp) / "pyproject.toml")
        for extra in ("data", "figures", "docs", "tools", "requirements.lock", "README.md", "Makefile"):
            src = ROOT / extra
            if src.exists():
                (Path(tmp) / extra).symlink_to(src)
        env = dict(os.environ, PAPER_REPRO_NO_CACHE="1", PYTHONDONTWRITEBYTECODE="1")
        cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "-m", "not slow and not benchmark",
               f"paper_repro/{module}", *tests]
        t0 = time.perf_counter()
        try:
            p = subprocess.run(cmd, cwd=tmp, env=env, capture_output=True, text=True, timeout=timeout)
            killed = p.returncode != 0
        except subprocess.TimeoutExpired:
            killed = True
        return killed, time.perf_counter() - t0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--module", nargs="*", default=None, help="modules below paper_repro/ (default: all of MODULES)")
    ap.add_argument("--per-module", type=int, default=30)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--goal", type=float, default=0.95)
    ap.add_argument("--out", default="reports")
    a = ap.parse_args(argv)
    modules = a.module or [m for m in MODULES if (ROOT / "paper_repro" / m).exists()]
    records = []
    for module in modules:
        tests = [t for t in MODULES.get(module, []) if (ROOT / t.split("::")[0]).exists()]
        source = (ROOT / "paper_repro" / module).read_text()
        sites = _sites(ast.parse(source))
        rng = random.Random(f"{a.seed}/{module}")
        order = rng.sample(range(len(sites)), len(sites))
        chosen = []
        for k in order:
            m = _apply(source, k)
            if m is not None:
                chosen.append(m)
            if len(chosen) >= a.per_module:
                break
        with ThreadPoolExecutor(a.jobs) as ex:
            futs = [ex.submit(run_mutant, module, new, tests, a.timeout) for new, _, _, _ in chosen]
            for (new, op, line, snippet), fut in zip(chosen, futs):
                killed, secs = fut.result()
                key = f"{module}:{line}:{op}:{hashlib.sha256(snippet.encode()).hexdigest()[:8]}"
                records.append({"module": module, "line": line, "op": op, "key": key, "snippet": snippet[:80],
                                "killed": killed,
                                "seconds": round(secs, 1), "equivalent": EQUIVALENT.get(key)})
                print(f"{module}:{line} {op}: {'killed' if killed else 'SURVIVED'} ({secs:.0f} s)", flush=True)
    by_mod: dict[str, list[int]] = {}
    for r in records:
        if r["equivalent"]:
            continue
        k = by_mod.setdefault(r["module"], [0, 0])
        k[0] += r["killed"]
        k[1] += 1
    md = ["# Mutation test of the library code (tools/mutate_code.py)", "",
          f"{a.per_module} mutants per module (seed {a.seed}), each run against the tests that cover the module "
          "(tools/mutate_code.py MODULES) and its doctests; killed = the tests fail. Equivalent mutants are listed "
          "with their reason in tools/mutate_code.py EQUIVALENT and not counted.", "",
          "| module | killed | of | rate |", "|---|---|---|---|"]
    ok = True
    for mod, (k, n) in by_mod.items():
        rate = k / n if n else 1.0
        ok &= rate >= a.goal
        md.append(f"| {mod} | {k} | {n} | {100 * rate:.0f} % |")
    md += ["", "## Survivors (line of the module, operator)", ""]
    md += [f"* `{r['module']}:{r['line']}` {r['op']}: `{r['snippet']}`" for r in records
           if not r["killed"] and not r["equivalent"]]
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "mutate_code.md").write_text("\n".join(md) + "\n")
    (out / "mutate_code.json").write_text(json.dumps(records, indent=1) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
