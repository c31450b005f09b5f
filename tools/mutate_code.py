"""``make mutate-code``: a mutation test of the library code -> reports/mutate_code.{md,json} (issue 39, item 6).

For each module of :data:`MODULES` (every core and surfaces module), ``--per-module`` mutants are drawn (seeded, so
the same on every run of the same source) from the operators below, each applied at one site of the module's source:

* ``compare``: ``<`` <-> ``<=``, ``>`` <-> ``>=``, ``==`` <-> ``!=``, ``is`` <-> ``is not``, ``in`` <-> ``not in``;
* ``arith``: ``+`` <-> ``-``, ``*`` <-> ``/``, ``//`` -> ``/``, ``**`` -> ``*``;
* ``const``: an integer constant ``k`` -> ``k + 1``; ``True`` <-> ``False``;
* ``bool``: ``and`` <-> ``or``; ``not x`` -> ``x``;
* ``return``: ``return x`` -> ``return None`` (not in ``__init__``);
* ``raise``: a ``raise`` statement -> ``pass`` (a check that never fires).

Each mutant is written into a scratch copy of the package (never into the work tree) and the tests that cover the
module (:data:`MODULES`: test files, and the module's own doctests, which run first) run against it with
``pytest -x`` and a time limit (five times the unmutated run, at least 60 s); a mutant is *killed* when they fail
(or time out).  Before the mutants, the unmutated module must pass the same command (otherwise every mutant would
count as killed).  A surviving mutant is either a gap in the tests or *equivalent* (it changes nothing observable):
equivalent ones are recorded with the mathematical or programmatic reason in :data:`EQUIVALENT`, keyed by
:func:`mutant_key` (module, enclosing function, operator, a hash of the mutated expression and its occurrence in
that function: stable when other code of the module moves), and the rate counts only the others.  Goal: >= 95 % of
the non-equivalent mutants killed in every module.  Modules of :data:`SKIPPED` are not run (the reason is
reported).

``--module`` runs some modules and merges their records into the existing ``--out``/mutate_code.json (the other
modules' records are kept), so a long run can be made module by module.  ``--resume`` reuses the killed records of
the existing json when the module's source is unchanged (its sha256 is recorded), so only survivors and new mutants
run again after tests were added.  Usage::

    .venv/bin/python tools/mutate_code.py [--module core/elevation.py ...] [--per-module 30] [--seed 0] [--jobs 1]
        [--resume] [--out reports]
"""

from __future__ import annotations

import argparse
import ast
import functools
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

_NOT_CLI = "not cli and not ctrl_c and not watchdog"

#: module (below paper_repro/) -> the tests that cover it (files or node ids; the module's doctests always run first;
#: tests/test_mutation_gaps.py next: with ``pytest -x`` a mutant it kills costs one short file)
MODULES: dict[str, list[str]] = {
    "core/alphas.py": ["tests/test_mutation_gaps.py"],
    "core/basis.py": ["tests/test_mutation_gaps.py", "tests/test_basis_arithmetics.py"],
    "core/collocation.py": ["tests/test_mutation_gaps.py", "tests/test_collocation.py",
                            "tests/test_transformation_all_n.py"],
    "core/context.py": ["tests/test_mutation_gaps.py", "tests/test_basis_arithmetics.py", "tests/test_collocation.py",
                        "tests/test_elevation_all_n.py", "tests/test_modp_elimination.py"],
    "core/derivatives_basis.py": ["tests/test_mutation_gaps.py", "tests/test_derivative_tables.py"],
    "core/domain.py": ["tests/test_mutation_gaps.py", "tests/test_code_gaps.py", "tests/test_domain_of_validity.py"],
    "core/elevation.py": ["tests/test_mutation_gaps.py", "tests/test_code_gaps.py", "tests/test_elevation_all_n.py",
                          "tests/test_limits_elevation.py"],
    "core/exact_solve.py": ["tests/test_mutation_gaps.py", "tests/test_speed_exact_routines.py"],
    "core/fast.py": ["tests/test_mutation_gaps.py", "tests/test_fast_kernel.py", "tests/test_patch_arithmetics.py"],
    "core/fast_jit.py": ["tests/test_mutation_gaps.py", "tests/test_fast_jit.py", "tests/test_fast_kernel.py"],
    "core/fourier.py": ["tests/test_mutation_gaps.py", "tests/test_independence.py",
                        "tests/test_transformation_all_n.py"],
    "core/half_angle_matrices.py": ["tests/test_mutation_gaps.py", "tests/test_code_gaps.py",
                                    "tests/test_pairwise_products.py", "tests/test_elevation_all_n.py"],
    "core/half_angle_rules.py": ["tests/test_mutation_gaps.py", "tests/test_pairwise_products.py",
                                 "tests/test_elevation_all_n.py", "tests/test_code_gaps.py"],
    "core/labels.py": ["tests/test_mutation_gaps.py", "tests/test_labels.py", "tests/test_net_layout.py"],
    "core/layout.py": ["tests/test_mutation_gaps.py", "tests/test_figures_readable.py", "tests/test_labels.py",
                       "tests/test_net_layout.py"],
    "core/nets.py": ["tests/test_mutation_gaps.py", "tests/test_trust.py"],
    "core/normalization.py": ["tests/test_mutation_gaps.py", "tests/test_normalization.py",
                              "tests/test_foundation_claims.py"],
    "core/normalizing_formula.py": ["tests/test_mutation_gaps.py", "tests/test_question1_all_n.py"],
    "core/ordered.py": ["tests/test_mutation_gaps.py", "tests/test_limits_elevation.py"],
    "core/transformation.py": ["tests/test_mutation_gaps.py", "tests/test_transformation_all_n.py"],
    "core/univariate.py": ["tests/test_mutation_gaps.py", "tests/test_univariate.py", "tests/test_normalization.py"],
    "surfaces/fitting.py": ["tests/test_mutation_gaps.py", "tests/test_library_api.py",
                            "tests/test_patches_surfaces.py"],
    "surfaces/limit.py": ["tests/test_mutation_gaps.py", "tests/test_library_api.py", "tests/test_limits_elevation.py"],
    "surfaces/mesh.py": ["tests/test_mutation_gaps.py", "tests/test_patches_surfaces.py"],
    "surfaces/models.py": ["tests/test_mutation_gaps.py", "tests/test_patches_surfaces.py",
                           "tests/test_patch_arithmetics.py"],
    "surfaces/patch.py": ["tests/test_mutation_gaps.py", "tests/test_code_gaps.py", "tests/test_patches_surfaces.py",
                          "tests/test_patch_arithmetics.py", "tests/test_library_api.py"],
    "surfaces/tessellation.py": ["tests/test_tessellation.py", "tests/test_tessellation_ball.py"],
    "surfaces/joins.py": ["tests/test_joins.py"],
    "core/subdivision.py": ["tests/test_subdivision.py", "tests/test_subdivision_speed.py"],
    "core/subdivision_products.py": ["tests/test_mutation_gaps.py", "tests/test_subdivision_speed.py"],
}

#: pytest ``-k`` expression per module (default: every fast test of the files): the CLI round trips of
#: tests/test_domain_of_validity.py (subprocesses, 40 s) exercise the CLI, not these modules' code paths, and the
#: exact check of the printed torus net (40 s) the torus model (surfaces/models.py), which keeps it
_NOT_TORUS = "not printed_torus_net"
SELECT: dict[str, str] = {"core/domain.py": _NOT_CLI,
                          "surfaces/patch.py": _NOT_TORUS, "surfaces/mesh.py": _NOT_TORUS,
                          "surfaces/fitting.py": _NOT_TORUS}

#: modules not run, and why
SKIPPED: dict[str, str] = {}

#: equivalent mutants: :func:`mutant_key` -> why nothing observable changes
EQUIVALENT: dict[str, str] = {
    "core/collocation.py:collocate:const0:6b86b273#0":
        "reshape(x.shape[0], -1) -> reshape(x.shape[0], -2): numpy (2.x) takes any negative size as the one inferred "
        "dimension, so the array is the same",
    "core/basis.py:evaluate:const0:5feceb66#0":
        "count = 0 -> 1 for points without len(): count only feeds the size check count * delta_n > 2e8, and "
        "1 * delta_n <= delta_1000 = 3,003,001 for every n that check_n admits (n <= 1000), so it never fires",
    "core/nets.py:net_from_labels:const0:6b86b273#1":
        "reshape(-1) -> reshape(-2): numpy (2.x) takes any negative size as the one inferred dimension",
    "core/exact_solve.py:_primes:arith0:748b9007#0":
        "x = 2**62 - 1 -> 2**62 + 1 at the start of the descent by 2: 2^62 + 1 = 4^31 + 1 is divisible by 5 "
        "(4 = -1 mod 5), so it is skipped and the primes found are the same",
    "core/exact_solve.py:_reconstruct_row:compare0:faf20822#1":
        "y > half -> y >= half after the denominator is widened: mod is a product of odd primes, so y = half = "
        "(mod - 1)/2 is either kept or becomes -(mod + 1)/2; both exceed bound = isqrt(mod // 2) in size, and the "
        "next line returns None in both cases",
    "core/exact_solve.py:_reconstruct_row:compare0:72066a7e#1":
        "-bound <= y -> -bound < y: a numerator of exactly -bound is refused, so the row is reconstructed at the "
        "next prime (a larger bound) instead; the returned X is the same exactly checked solution, without the "
        "fallback (the module's design: the choices change the speed, never the result)",
    "core/normalizing_formula.py:_scalar:bool0:c0319d08#0":
        "not len and not getitem -> not len or not getitem: differs only for an object with exactly one of the two; "
        "the scalars the contexts hold (float, int, mpf, fmpq, fmpz, arb: neither; fmpq_poly: both; numpy scalars: "
        "np.generic, taken by the first test) never have exactly one",
    "core/basis.py:_monomials_by_pairs:const0:d4735e3a#4":
        "exps[:, 2 var: 2 var + 2] -> exps[:, 2 var: 3 var + 2]: for v (var = 1) the slice takes w's sine exponent "
        "as a third column; np.unique then groups by (a, b, e) instead of (a, b), finer groups of the same "
        "sin^a cos^b (only columns 0 and 1 of the keys are used), so every product is the same",
    "core/context.py:ObjectContext.asarray:const0:6b86b273#1":
        "src.reshape(-1) -> reshape(-2): numpy (2.x) takes any negative size as the one inferred dimension",
    "core/context.py:ModpContext.asarray:const0:6b86b273#0":
        "src.reshape(-1) -> reshape(-2): numpy (2.x) takes any negative size as the one inferred dimension",
    "core/normalization.py:orbit_coefficients:const0:d4735e3a#0":
        "log(alpha / 2) -> log(alpha / 3) in the branch s = sin(alpha/2) <= 0, which no valid alpha reaches: "
        "check_alpha admits alpha >= 2.2e-308, and then s >= 1.1e-308 > 0 (float64 subnormals)",
    "surfaces/limit.py:bezier_order:const0:6b86b273#0":
        "for j in range(N + 1) -> range(N + 2): the extra j = N + 1 has the inner range(N + 1 - j) = range(0), "
        "empty, so the list is the same",
    "core/elevation.py:_elevation_matrix_float:const0:60a33e6c#0":
        "setflags(write=False) -> write=True on the cached float E: its only reader, elevation_matrix, returns a copy, "
        "so no caller can reach the cached array to write it",
    "core/elevation.py:_elevation_matrix_float:const0:b17ef6d1#0":
        "lru_cache(maxsize=16) -> 17: one more cached matrix; every value is the same (recomputed or cached)",
    "core/fourier.py:related:compare1:969bbaed#0":
        "-n <= z <= 2n -> -n <= z < 2n for the common sum z of condition 1: on E_n x E_n (the relation's domain, "
        "Definition equivalence_relation_definition) a_k + b_k <= 2n, so z = 2n only for a = b = (n, n, n), which "
        "condition 2 relates anyway (differences all 0, z = 0 in {-n..2n}): related() is the same on every pair",
    "core/fourier.py:cos_sin_combination:compare0:ceeb01dc#0":
        "power < 0 -> power <= 0: for power = 0 the branch negates s and sets power = -0 = 0; the loop then runs "
        "range(0) times, so the negated s is never used (the next factor rebinds s), and (re, im) are the same",
    "core/transformation.py:_item:const0:5feceb66#0":
        "x.ndim == 0 -> x.ndim == 1 in _item: 0-d arrays are no longer unwrapped (a 1-d x[()] is x itself, as "
        "before).  The only 0-d arrays that reach it are the context's 1 and 0 (zeta^0, and the powers' start in "
        "_pow); stored into a float array they give the same value, stored into an object array they stay 0-d "
        "arrays, but every such entry is only an operand of a ring operation (_cmul's products, scaled_table's "
        "arithmetic), and numpy's ufuncs on object operands apply Python's operator to the elements and return "
        "the element for a 0-d result: the same values and the same element types (fmpq, mpf, arb) in every "
        "output (checked: every entry of the exact and mp matrices, both directions, is an fmpq resp. mpf)",
    "surfaces/fitting.py:fit_exact:const0:6f4b6612#0":
        "fit_exact's default seed 21 -> 22: other rational collocation points.  For a surface in the span the exact "
        "net is unique (T_2n is a basis, and collocate solves exactly and verifies at 4 more points, drawing new "
        "points if the system is singular), so every seed returns the same rationals; a surface outside the span is "
        "refused at every seed whose d + 4 points it does not happen to fit exactly (no such surface is a caller's)",
    "core/subdivision_products.py:swap_permutation:arith0:1497f389#0":
        "T_{2 * n} -> T_{2 / n} in the text of an AssertionError no input reaches (pragma: no cover): T_2n is "
        "invariant under every exchange of two variables (the paper's cyclic rule and the reflection "
        "R_{2n,2n-i,j}(w, v, u) = R_{2n,i,j}(u, v, w); core/labels.variable_swap checks the same for every n it "
        "builds), so every exchanged exponent vector is found and the message is never formatted",
    "core/normalization.py:orbit_coefficients:compare0:e254fbf0#0":
        "x / s^k if s^k > 0 else exp(lx) -> s^k >= 0 in the float route for n > MAX_N_CERTIFIED: differs only when "
        "s^k underflows to exactly 0 while lx = ln x - k ln s <= ln(float max) (else the ValueError before it), "
        "i.e. a positive scaled coefficient x below 2^-1074 * 1.8e308 = 8.9e-16 at an alpha where s^k < 2^-1075.  "
        "On the evidence of a sweep, not a proof: n = 101, alpha = 10^-300 .. 1 (151 values), 787,880 (alpha, "
        "coefficient) pairs with s^k = 0, none with a finite coefficient",
    "surfaces/tessellation.py:_mesh.keys:arith0:9ff733e2#0":
        "(kind span + val + root) span + t + root -> (kind span - val + root) span + t + root: the encoding of a "
        "lattice line (kind, val) and a position t on it.  span = 4 root + 2 is the width the original needs (val "
        "+ root in [0, span)); with -val the block of kind k is k span + [-2 root - 1, 2 root], the same width, so "
        "the blocks of the three kinds still do not overlap and (kind, val) -> block stays injective, and t is "
        "encoded as before (keys increase with t inside a block).  line_keys and every searchsorted range between "
        "keys(kind, val, t0) and keys(kind, val, t1) therefore hold the same points: the mesh is the same",
    "surfaces/joins.py:_closed_form:arith0:a3379d8f#1":
        "a + b + e + g -> a + b + e - g in the text of an AssertionError no input reaches (pragma: no cover): every "
        "edge monomial has degree 2n (docs/joins_for_all_n.md, Lemma 1; the condition itself is not mutated here), "
        "so the message is never formatted",
    "core/elevation.py:start_precision:const0:d4735e3a#0":
        "2 near_pi -> 3 near_pi in the first ball precision of the certified solve (a cross-check, not the library "
        "route): it only raises the start, by near_pi = log2(1/(pi - alpha)) < 52 bits (a float alpha < pi is at "
        "most pi - 4.4e-16), so by at most one 64-bit word.  The start already covers the loss near pi (measured: "
        "it grows like 1 near_pi, n = 1..5 lose 23..97 bits at alpha = 2 .. pi - 1e-15), so the first solve still "
        "certifies (solves = 1), and E is certified to 2^-64 either way: the same certified result.  What changes "
        "is the cost and the diagnostics: the reported precision (one word more at most) and the ball midpoints "
        "below the certified radius (entries that are exactly 0 differ by 1e-35..1e-73, measured at p and p + 64 "
        "bits).  The documented promises (one solve; every entry to 2^-64) hold for both; a test of the value of "
        "the start itself would retype the formula (the module's design, like exact_solve's: the choices change "
        "the speed, never the certified result)",
}

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


def _apply(source: str, site_index: int) -> tuple[str, str, int, str, str] | None:
    """The source with mutant ``site_index`` applied: (new source, operator, line, the original text of the node,
    the mutated statement's first line), or None if it does not compile."""
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
    mutated = "pass" if op == "raise" else ""
    try:
        new = ast.unparse(ast.fix_missing_locations(tree))
        compile(new, "<mutant>", "exec")
    except (SyntaxError, ValueError):
        return None
    changed = [b for a, b in zip(_unparsed(source).splitlines(), new.splitlines()) if a != b]
    return new, op, line, snippet, (changed[0].strip() if changed else mutated)


@functools.cache
def _unparsed(source: str) -> str:
    """The module as :func:`ast.unparse` writes it (the mutants' layout), to show the mutated statement."""
    return ast.unparse(ast.parse(source))


def _qualnames(tree: ast.AST) -> dict[int, str]:
    """id(node) -> the dotted name of the innermost function or class around it ('<module>' at top level)."""
    out: dict[int, str] = {}

    def visit(node: ast.AST, name: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                inner = child.name if name == "<module>" else f"{name}.{child.name}"
                out[id(child)] = name
                visit(child, inner)
            else:
                out[id(child)] = name
                visit(child, name)

    visit(tree, "<module>")
    return out


def mutant_keys(module: str, source: str) -> list[str]:
    """The key of every site of :func:`_sites` (same order): ``module:function:operator+variant:hash#occurrence``,
    the hash of the original expression's text; the occurrence counts equal (function, operator, text) sites."""
    tree = ast.parse(source)
    names = _qualnames(tree)
    seen: dict[tuple, int] = {}
    keys = []
    lines = [line.encode() for line in source.splitlines(keepends=True)]
    for op, node, variant in _sites(tree):
        snippet = _segment(lines, node)
        base = (names.get(id(node), "<module>"), f"{op}{variant}", hashlib.sha256(snippet.encode()).hexdigest()[:8])
        occ = seen.get(base, 0)
        seen[base] = occ + 1
        keys.append(f"{module}:{base[0]}:{base[1]}:{base[2]}#{occ}")
    return keys


def _segment(lines: list[bytes], node: ast.AST) -> str:
    """:func:`ast.get_source_segment` on the module's lines, encoded once (the offsets count UTF-8 bytes)."""
    first, last = node.lineno - 1, node.end_lineno - 1  # type: ignore[attr-defined]
    if first == last:
        return lines[first][node.col_offset: node.end_col_offset].decode()  # type: ignore[attr-defined]
    parts = [lines[first][node.col_offset:], *lines[first + 1: last], lines[last][: node.end_col_offset]]  # type: ignore[attr-defined]
    return b"".join(parts).decode()


def mutant_key(module: str, source: str, site_index: int) -> str:
    """The stable key of mutant ``site_index`` of ``module`` (the key of :data:`EQUIVALENT`)."""
    return mutant_keys(module, source)[site_index]


def _command(module: str, tests: list[str]) -> list[str]:
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "-m", "not slow and not benchmark"]
    if module in SELECT:
        cmd += ["-k", SELECT[module]]
    return cmd + [f"paper_repro/{module}", *tests]


def run_mutant(module: str, new_source: str | None, tests: list[str], timeout: float) -> tuple[bool, float]:
    """Whether the tests fail on the mutant (killed; ``new_source`` None: the unmutated module), and the seconds."""
    with tempfile.TemporaryDirectory(prefix="mutant-") as tmp:
        pkg = Path(tmp) / "paper_repro"
        shutil.copytree(ROOT / "paper_repro", pkg, ignore=shutil.ignore_patterns("__pycache__"))
        if new_source is not None:
            (pkg / module).write_text(new_source)
        shutil.copytree(ROOT / "tests", Path(tmp) / "tests", ignore=shutil.ignore_patterns("__pycache__"))
        shutil.copy(ROOT / "pyproject.toml", Path(tmp) / "pyproject.toml")
        for extra in ("data", "figures", "docs", "tools", "requirements.lock", "README.md", "Makefile"):
            src = ROOT / extra
            if src.exists():
                (Path(tmp) / extra).symlink_to(src)
        env = dict(os.environ, PAPER_REPRO_NO_CACHE="1", PYTHONDONTWRITEBYTECODE="1")
        t0 = time.perf_counter()
        try:
            p = subprocess.run(_command(module, tests), cwd=tmp, env=env, capture_output=True, text=True,
                               timeout=timeout)
            killed = p.returncode != 0
        except subprocess.TimeoutExpired:
            killed = True
        return killed, time.perf_counter() - t0


def _report(records: list[dict], per_module: int, seed: int, goal: float) -> tuple[str, bool]:
    """reports/mutate_code.md from all records: the rate per module, each survivor, each equivalent with its reason."""
    by_mod: dict[str, list[int]] = {}
    for r in records:
        k = by_mod.setdefault(r["module"], [0, 0, 0])
        if r["equivalent"]:
            k[2] += 1
        else:
            k[0] += r["killed"]
            k[1] += 1
    md = ["# Mutation test of the library code (tools/mutate_code.py, `make mutate-code`)", "",
          f"A deterministic sample of each module's mutation sites (seed {seed}; `--per-module`, {per_module} in the "
          "last run; the count per module is killed + survived + equivalent below), "
          "each run against the tests that cover the module (tools/mutate_code.py MODULES) and its doctests, "
          "`pytest -x`; killed = the tests fail or time out. Equivalent mutants (nothing observable changes) are "
          "listed with their reason below and in tools/mutate_code.py EQUIVALENT, and not counted in the rate. "
          f"Goal: >= {100 * goal:.0f} % of the non-equivalent mutants killed in every module.", "",
          "| module | killed | of (non-equivalent) | equivalent | rate |", "|---|---|---|---|---|"]
    ok = True
    for mod in sorted(by_mod):
        k, n, e = by_mod[mod]
        rate = k / n if n else 1.0
        ok &= rate >= goal
        md.append(f"| {mod} | {k} | {n} | {e} | {100 * rate:.1f} % |")
    tk, tn = sum(v[0] for v in by_mod.values()), sum(v[1] for v in by_mod.values())
    md.append(f"| **all** | {tk} | {tn} | {sum(v[2] for v in by_mod.values())} | "
              f"{100 * tk / max(tn, 1):.1f} % |")
    skipped = {m: why for m, why in SKIPPED.items() if m not in by_mod}
    if skipped:
        md += ["", "Not run: " + "; ".join(f"`{m}` ({why})" for m, why in skipped.items()) + "."]
    missing = [m for m in MODULES if m not in by_mod and m not in SKIPPED and (ROOT / "paper_repro" / m).exists()]
    if missing:
        md += ["", "Not measured yet (no records in this json; run `make mutate-code`, or `tools/mutate_code.py "
               "--module ...`): " + ", ".join(f"`{m}`" for m in missing) + "."]
    stale = sorted({r["module"] for r in records if (ROOT / "paper_repro" / r["module"]).exists() and r.get(
        "source_sha") != hashlib.sha256((ROOT / "paper_repro" / r["module"]).read_bytes()).hexdigest()})
    if stale:
        md += ["", "Measured on an older source (the module changed since; run it again): "
               + ", ".join(f"`{m}`" for m in stale) + "."]
    killed_by = [r for r in records if r.get("killed_by")]
    if killed_by:
        md += ["", f"{len(killed_by)} mutant(s) that survived the full run were killed on a recheck (`--recheck`) by "
               "tests added since: " + ", ".join(f"`{r['key']}`" for r in killed_by) + "."]
    md += ["", "## Survivors (not equivalent: gaps in the tests)", ""]
    surv = [r for r in records if not r["killed"] and not r["equivalent"]]
    md += [f"* `{r['module']}:{r['line']}` {r['op']}: `{r['snippet']}` -> `{r.get('mutated', '')}` ({r['key']})"
           for r in surv] or ["None."]
    md += ["", "## Equivalent mutants (why nothing observable changes)", ""]
    md += [f"* `{r['module']}:{r['line']}` {r['op']}: `{r['snippet']}` -> `{r.get('mutated', '')}`: "
           f"{r['equivalent']}" for r in records if r["equivalent"]] or ["None."]
    return "\n".join(md) + "\n", ok


def recheck(a: argparse.Namespace) -> int:
    """``--recheck TEST...``: the survivors of the existing json run again against the given tests only."""
    jpath = Path(a.out) / "mutate_code.json"
    records = json.loads(jpath.read_text())
    modules = a.module or sorted({r["module"] for r in records})
    for module in modules:
        source = (ROOT / "paper_repro" / module).read_text()
        sha = hashlib.sha256(source.encode()).hexdigest()
        todo = [r for r in records if r["module"] == module and not r["killed"] and not r["equivalent"]
                and r.get("source_sha") == sha]
        if not todo:
            continue
        base_killed, base_secs = run_mutant(module, None, a.recheck, 1800.0)
        if base_killed:
            print(f"{module}: {a.recheck} fail on the unmutated module; not rechecked", flush=True)
            continue
        keys = mutant_keys(module, source)
        for r in todo:
            m = _apply(source, keys.index(r["key"]))
            assert m is not None
            killed, secs = run_mutant(module, m[0], a.recheck, a.timeout or max(60.0, 5 * base_secs))
            if killed:
                r.update(killed=True, seconds=round(secs, 1), killed_by=" ".join(a.recheck))
            print(f"{module}:{r['line']} {r['op']}: {'killed' if killed else 'SURVIVED'} (recheck) {r['key']}",
                  flush=True)
        jpath.write_text(json.dumps(records, indent=1) + "\n")
    for r in records:
        r["equivalent"] = EQUIVALENT.get(r["key"])
    md, ok = _report(records, a.per_module, a.seed, a.goal)
    (Path(a.out) / "mutate_code.md").write_text(md)
    jpath.write_text(json.dumps(records, indent=1) + "\n")
    return 0 if ok else 1


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--module", nargs="*", default=None, help="modules below paper_repro/ (default: all of MODULES "
                    "but SKIPPED); their records are merged into the existing json")
    ap.add_argument("--per-module", type=int, default=30)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=None, help="seconds per mutant (default: 5 x the unmutated run,"
                    " at least 60)")
    ap.add_argument("--goal", type=float, default=0.95)
    ap.add_argument("--resume", action="store_true", help="reuse killed records of the json (same module source)")
    ap.add_argument("--out", default="reports")
    ap.add_argument("--recheck", nargs="+", default=None, metavar="TEST",
                    help="run only these tests against the survivors of the existing json (same module source): a "
                         "survivor they kill is killed (a subset of the tests failing means the full set fails); "
                         "the others stay survivors of the full run.  No new mutants are drawn")
    a = ap.parse_args(argv)
    if a.recheck:
        return recheck(a)
    modules = a.module or [m for m in MODULES if m not in SKIPPED and (ROOT / "paper_repro" / m).exists()]
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    jpath = out / "mutate_code.json"
    old = json.loads(jpath.read_text()) if jpath.exists() else []
    records = [r for r in old if r["module"] not in modules] if a.module else []
    status = 0
    for module in modules:
        tests = [t for t in MODULES.get(module, []) if (ROOT / t.split("::")[0]).exists()]
        source = (ROOT / "paper_repro" / module).read_text()
        sha = hashlib.sha256(source.encode()).hexdigest()
        reuse = {r["key"]: r for r in old if a.resume and r["module"] == module and r.get("source_sha") == sha
                 and r["killed"]}
        sites = _sites(ast.parse(source))
        keys = mutant_keys(module, source)
        rng = random.Random(f"{a.seed}/{module}")
        order = rng.sample(range(len(sites)), len(sites))
        chosen = []
        for k in order:
            m = _apply(source, k)
            if m is not None:
                chosen.append((keys[k], *m))
            if len(chosen) >= a.per_module:
                break
        todo = [c for c in chosen if c[0] not in reuse]
        timeout = a.timeout or 60.0
        if todo:  # the unmutated module must pass (else every mutant would count as killed); sets the time limit
            base_killed, base_secs = run_mutant(module, None, tests, 1800.0)
            if base_killed:
                print(f"{module}: the tests fail on the unmutated module; not mutated", flush=True)
                status = 2
                continue
            timeout = a.timeout or max(60.0, 5 * base_secs)
            print(f"{module}: unmutated run {base_secs:.0f} s; timeout {timeout:.0f} s; {len(todo)} mutants to run, "
                  f"{len(chosen) - len(todo)} killed before (same source)", flush=True)
        with ThreadPoolExecutor(a.jobs) as ex:
            futs = {c[0]: ex.submit(run_mutant, module, c[1], tests, timeout) for c in todo}
            for key, _new, op, line, snippet, mutated in chosen:
                if key in reuse:
                    killed, secs = True, reuse[key]["seconds"]
                else:
                    killed, secs = futs[key].result()
                records.append({"module": module, "line": line, "op": op, "key": key, "snippet": snippet[:100],
                                "mutated": mutated[:160], "killed": killed, "seconds": round(secs, 1),
                                "source_sha": sha, "equivalent": EQUIVALENT.get(key)})
                print(f"{module}:{line} {op}: {'killed' if killed else 'SURVIVED'} ({secs:.0f} s) {key}",
                      flush=True)
        jpath.write_text(json.dumps(records, indent=1) + "\n")
        md, _ = _report(records, a.per_module, a.seed, a.goal)
        (out / "mutate_code.md").write_text(md)
    md, ok = _report(records, a.per_module, a.seed, a.goal)
    (out / "mutate_code.md").write_text(md)
    jpath.write_text(json.dumps(records, indent=1) + "\n")
    return status or (0 if ok else 1)


if __name__ == "__main__":
    raise SystemExit(main())
