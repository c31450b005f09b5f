"""Claim ``symmetry``: the cyclic relations and the six symmetry properties of Fig. oriented_graph(b).

Read from the transcriptions of Section sec:RGB (:mod:`paper_repro.printed.symmetry` parses them at call time;
exponents in the order of :data:`paper_repro.core.labels.SLOTS`), and compared with the R formula + cyclic rule that
:mod:`paper_repro.core.labels` uses to build R, G and B:

* printed explicit R, G and B formulas (i <= n and i > n), on their printed index sets, which must split the full
  systems (eq. R_system) into the two halves;
* printed relations ``R_{2n,2n-i,j}(u,v,w) = R_{2n,i,j}(w,v,u)``, ``G_{2n,2n-i,j}(u,v,w) = G_{2n,i,j}(u,w,v)``,
  ``B_{2n,2n-i,j}(u,v,w) = B_{2n,i,j}(v,u,w)`` (i > n);
* caption of Fig. oriented_graph(b): R, G, B families are each symmetric in (w,u), (v,w), (u,v);
  adjacent families R-G, G-B, B-R are exchanged by (v,u), (u,w), (w,v); their number is the "six" of the
  Introduction.

Monomial identities are checked exactly on exponent vectors (a proof for each n in range) and
numerically at high precision at random points (the evaluators themselves).
"""

from __future__ import annotations

import mpmath
import numpy as np

from paper_repro.core.alphas import alpha_mp
from paper_repro.core.basis import evaluate
from paper_repro.core.labels import BasisLabel, compose, exponents, full_system
from paper_repro.printed import symmetry as printed
from paper_repro.printed.latex_math import LatexMathError
from paper_repro.util.measured import bound
from paper_repro.util.registry import Outcome, claim


def family_image(n: int, sub: tuple[int, int, int], color: str, target: str) -> dict[str, str] | None:
    """Label map ``X(sub) -> Y`` if the substitution maps family ``color`` onto family ``target``."""
    targets = {exponents(lab): lab.name for lab in full_system(n, target)}
    out = {}
    for lab in full_system(n, color):
        img = compose(exponents(lab), sub)
        if img not in targets:
            return None
        out[lab.name] = targets[img]
    return out if len(set(out.values())) == len(targets) else None


def structural_checks(n: int) -> list[str]:
    """Exact (exponent-vector) checks of the printed objects at order n; a list of failures (empty if all hold).
    A line that cannot be read is a failure."""
    try:
        return _structural(n)
    except (LatexMathError, ValueError) as exc:
        return [f"unread: {exc}"]


def _structural(n: int) -> list[str]:
    fails = []
    full = {(i, j) for j in range(n + 1) for i in range(j, 2 * n - j + 1)}
    high = {(i, j) for i, j in full if i > n}
    for color in "RGB":
        sets = {}
        for half in ("low", "high"):
            formula, iset = printed.explicit(color, half)
            sets[half] = printed.pairs(iset, n)
            for i, j in sets[half]:
                if (i, j) not in full:
                    fails.append(f"printed {color} ({half}) lists ({i}, {j}), no member of {color}_{{2n}}")
                elif formula(n, i, j) != exponents(BasisLabel(color, n, i, j)):
                    fails.append(f"printed {color}_{{{2 * n},{2 * n - i},{j}}} ({half}) != the graph's")
        low, hi = sets["low"], sets["high"]
        if set(low) & set(hi) or set(low) | set(hi) != full or len(low) + len(hi) != len(full):
            fails.append(f"the printed halves of {color} do not split {color}_{{2n}}")
        left, right, iset = printed.half_relation(color)
        rel = printed.pairs(iset, n)
        if set(rel) != high:
            fails.append(f"the printed relation of {color} is not over the half i > n")
        for i, j in rel:
            ends = []
            for col, first, level, perm in (left, right):
                env = {"n": n, "i": i, "j": j}
                li, lj = 2 * n - int(eval_index(first, env)), int(eval_index(level, env))
                if col != color or (li, lj) not in full:
                    ends.append(None)
                else:
                    ends.append(compose(exponents(BasisLabel(color, n, li, lj)), perm))
            if None in ends or ends[0] != ends[1]:
                fails.append(f"printed half relation fails for {color}_{{{2 * n},{2 * n - i},{j}}}")
    props = printed.six_properties()
    if len(props) != printed.six_count() or len({p[1:] for p in props}) != len(props):
        fails.append(f"{len(props)} distinct properties in the caption, the text announces {printed.six_count()}")
    for name, sub, color, target in props:
        if family_image(n, sub, color, target) is None:
            fails.append(f"substitution {name} does not map family {color} onto {target}")
    return fails


def eval_index(expr: str, env: dict[str, int]) -> int:
    """Value of a printed index (as read by :mod:`paper_repro.printed.symmetry`) at ``env``."""
    import sympy

    return int(sympy.sympify(expr).subs({sympy.Symbol(k): v for k, v in env.items()}))


def numeric_check(n: int, alpha_text: str, count: int, dps: int, seed: int) -> mpmath.mpf:
    """Max |X(sigma(p)) - Y(p)| over the six properties and the cyclic rule, at random points."""
    rng = np.random.default_rng(seed)
    with mpmath.workdps(dps):
        alpha = alpha_mp(alpha_text)
        bary = rng.dirichlet(np.ones(3), size=count)
        pts = np.array([[alpha * mpmath.mpf(float(b)) for b in row[:2]] for row in bary], dtype=object)
        pts = np.column_stack([pts, alpha - pts[:, 0] - pts[:, 1]])
        worst = mpmath.mpf(0)
        checks = [(sub, color, target) for _, sub, color, target in printed.six_properties()]
        checks += [((2, 0, 1), "R", "G"), ((1, 2, 0), "R", "B")]  # G(u,v,w) = R(w,u,v), B = R(v,w,u)
        for sub, color, target in checks:
            src = list(full_system(n, color))
            if (sub, color, target) in checks[-2:]:
                tgt = [BasisLabel(target, n, lab.i, lab.j) for lab in src]
            else:
                mp = family_image(n, sub, color, target)
                by_name = {lab.name: lab
                           for lab in full_system(n, target)}
                tgt = [by_name[mp[lab.name]] for lab in src]
            lhs = evaluate(n, alpha, pts[:, list(sub)], "mp", dps=dps, labels=src)
            rhs = evaluate(n, alpha, pts, "mp", dps=dps, labels=tgt)
            worst = max(worst, max(abs(x) for x in (lhs - rhs).reshape(-1)))
        return worst


@claim("symmetry", paper_ref=["fig:oriented_graph", "R_system", "R_system_leq_n", "R_system_geq_n", "G_system",
                              "B_system"],
       statement="For n = 1..{n_max}: the printed R, G and B formulas (read from the transcriptions) equal those "
                 "of the graph construction (G = R(w,u,v), B = R(v,w,u)) on their printed index sets, which split "
                 "the full systems, and the printed half relations and the six symmetry properties of "
                 "Fig. oriented_graph(b) hold (exact identities of exponent vectors, a proof for each n in that "
                 "range; not for larger n).",
       kind="proof", n_max=10, alphas=["pi/6", "pi/2", "5pi/6"], points=8, dps=40, seed=7)
def run(n_max: int, alphas: list[str], points: int, dps: int, seed: int) -> Outcome:
    fails = {n: structural_checks(n) for n in range(1, n_max + 1)}
    fails = {str(n): f for n, f in fails.items() if f}
    if fails:
        return Outcome(False, {"exact_monomial_checks": fails, "n_range": [1, n_max]})
    worst = mpmath.mpf(0)
    for n in range(1, n_max + 1):
        for k, a in enumerate(alphas):
            worst = max(worst, numeric_check(n, a, points, dps, seed + 100 * n + k))
    tol = mpmath.mpf(10) ** (-(dps - 10))
    try:
        maps = {name: family_image(2, sub, c, t) for name, sub, c, t in printed.six_properties()}
    except LatexMathError as exc:
        return Outcome(False, {"exact_monomial_checks": fails, "unread": str(exc)})
    return Outcome(not fails and worst <= tol, {
        "exact_monomial_checks": "all hold" if not fails else fails, "n_range": [1, n_max],
        "numeric_max_abs_error": bound(worst, 10.0 ** -(dps - 10)), "numeric_tolerance": f"1e-{dps - 10}",
        "label_maps_n_2": maps}, raw={"numeric_max_abs_error": mpmath.nstr(worst, 5)})
