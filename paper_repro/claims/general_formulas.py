"""Claim ``general_formulas``: formulas of the normalizing coefficients by level, beyond the printed 0 and 1.

Levels 0 and 1 (Remark normalizing_coeff_of_level_0, Proposition prop:level_1_coefficients) and the levels
found by :func:`paper_repro.theory.general_formulas.fit` are compared with the proven closed forms
(:func:`paper_repro.theory.closed_forms.proof_cached`) for every n up to ``n_max``.  A level's status:

* **proven for n <= N**: the formula equals the closed form for every n <= N and those closed forms are
  proven for every alpha (so the formula is a theorem for n <= N; for larger n it is a conjecture);
* **not found**: no formula of the searched shape, or not searched (the centre, levels above ``max_level``).

Positivity for all n, *conditional* on a formula holding for all n, is stated where the formula is a sum
of terms positive on 0 < c < 1 (checked here for the stated range of n, argued in the Markdown).
Publishes ``data/normalization/general_formulas{suffix}.json`` and ``.md``.
"""

from __future__ import annotations

from flint import fmpq, fmpq_mat, fmpq_poly

from paper_repro.core.normalization import orbits
from paper_repro.theory.closed_forms import closed_forms_cached, proof_cached, records, remember
from paper_repro.theory.general_formulas import (
    ALL_LEVELS_AT_1,
    CENTRE_END_VALUES,
    Formula,
    centre_end_values,
    centre_end_values_from_formula,
    check,
    check_against_formula,
    eval_expression,
    fit,
    interior_pattern,
    printed_level_formulas,
)
from paper_repro.util.registry import Outcome, claim
from paper_repro.util.tasks import Task

ALL_N_LATEX = (r"s^{2n+j} r^\alpha_{2n,2n-i,j} = [t^j X^i]\, (1+s^2t^2)^n "
               r"\left(1 + 2(c+s^2t)X + (1+s^2t^2)X^2\right)^n \frac{1 - m c t}{(1 - c t)^{2n+1}}")

#: Fit range per level: small n, the rest of the range is a genuine check.
N_FIT = {2: 8, 3: 9, 4: 11, 5: 15}

POSITIVITY = {
    (2, "interior"): "P = (n(i+1) - binom(i,2) s^2) C_{n,i} + n(i+1) c C_{n,i+1}; every C_{n,k} > 0 on 0 < c < 1 "
                     "(a sum of positive terms) and n(i+1) - binom(i,2) s^2 >= n(i+1) - i(i-1)/2 > 0 for i <= n: "
                     "positive for every n >= 3 and every alpha, if the formula holds for that n",
    (2, "diagonal"): "P = (3n - 1 - 2c^2) C_{n,2} + 3(n-1) c C_{n,3} with 3n - 1 - 2c^2 >= 3n - 3 > 0: positive for "
                     "every n >= 3 and every alpha, if the formula holds for that n",
}


def _status(agrees: list[int], fails: list[int], proven: list[int], first: int) -> tuple[str, int]:
    if fails:
        return f"fails for n = {fails[:5]}", 0
    top = first - 1
    while top + 1 in agrees and top + 1 in proven:
        top += 1
    return (f"proven for n <= {top}" if top >= first else "not checked"), top


def _centre_recurrence(n_max: int, order: int = 2, deg_n: int = 2, deg_c: int = 4) -> dict:
    """Search linear recurrences sum_r q_r(n, c) P_{n+r} = 0 for the centre numerators (exact null space)."""
    pcs = {n: closed_forms_cached(n)[f"r_{{{2 * n},{n},{n}}}"].numerator for n in range(1, n_max + 1)}
    unknowns = [(r, a, e) for r in range(order + 1) for a in range(deg_n + 1) for e in range(deg_c + 1)]
    rows = []
    for n in range(1, n_max - order + 1):
        basis = [pcs[n + r] * fmpq_poly([0] * e + [1]) * n**a for r, a, e in unknowns]
        for d in range(max(p.degree() for p in basis) + 1):
            rows.append([p[d] for p in basis])
    rank = fmpq_mat(len(rows), len(unknowns), [x for r in rows for x in r]).rank() if rows else 0
    return {"searched": f"order <= {order}, degree <= {deg_n} in n and <= {deg_c} in c, data n <= {n_max}",
            "unknowns": len(unknowns), "rank": rank, "found": rank < len(unknowns)}


def fit_task(level: int, kind: str, n_fit: int, records: tuple[dict, ...]) -> Formula | None:
    """Task: :func:`~paper_repro.theory.general_formulas.fit` on the closed forms of ``records`` (n <= n_fit)."""
    for rec in records:
        remember(rec)
    return fit(level, kind, n_fit)


def checks_at(n: int, formulas: tuple[Formula, ...], max_level: int, rec: dict | None) -> dict:
    """Task: every formula at order ``n`` against the all-n formula (``consequence``), and, given the closed forms
    ``rec`` of order n, against them (``closed_forms``)."""
    if rec is not None:
        remember(rec)
    out: dict = {"consequence": [not check_against_formula(f, [n], max_level)["fails_for_n"] for f in formulas]}
    if rec is not None:
        out["closed_forms"] = [check(f, [n]) for f in formulas]
    return out


@claim("general_formulas", paper_ref=["normalizing_coeff_of_level_0", "prop:level_1_coefficients",
                                      "sec:open_problems"],
       statement="Open Question 1, general formulas: every coefficient of every level is given by the all-n formula "
                 "(claim question1_all_n: the hand proof carries every n; its lemmas are machine-checked for n <= 12 "
                 "at 4 alpha). The printed levels "
                 "0 and 1 and the fitted levels 2..{max_level}, P_{n,i,j} = A_j(n,i,c) C_{n,i} + B_j(n,i,c) C_{n,i+1} "
                 "(interior j < i <= n and diagonal i = j < n), equal the all-n formula as polynomials in c for each "
                 "n <= {n_cons} and the closed forms proven for every alpha for each n <= {n_max} (a proof for those "
                 "n; for larger n a conjecture). The fitted levels are fitted to the closed forms of n <= "
                 + ", ".join(f"{N_FIT[k]} (level {k})" for k in sorted(N_FIT)) + ": for those n the agreement "
                 "holds by construction; only the larger n (up to {n_max} against the closed forms, up to {n_cons} "
                 "against the all-n formula) are independent confirmation. The centre's end values "
                 "s^{3n-2} r_{2n,n,n} -> "
                 "2(4n-3)(3n-3)!/((n-1)!^2 n!) (alpha -> 0) and r_{2n,n,n} -> sum_k binom(n,k)^3 (Franel numbers, "
                 "alpha -> pi) equal the limits of the all-n formula for each n <= {n_cons} (a finite computation per "
                 "n; not proven for every n: a conjecture beyond). Every level at alpha -> 0, for every n: "
                 "s^{2n+j} r_{2n,2n-i,j} -> (2n+j)!/((2n-i)! j! i!) (2n-(mu-1)j)/(2n+j), mu the number of minimal "
                 "entries of (2n-i, j, i) (claim limit_formula).",
       kind="proof", max_level=4, n_max=12, n_cons=30, suffix="",
       extended={"max_level": 5, "n_max": 30, "n_cons": 60, "suffix": "_extended"}, split=True)
def run(max_level: int, n_max: int, n_cons: int, suffix: str):
    # tasks: the closed forms per n (shared with the other claims of the run), then the fits per level and kind,
    # then every formula per n (against the closed forms and against the all-n formula)
    fit_jobs = [(level, kind) for level in range(2, max_level + 1) for kind in ("interior", "diagonal")]
    top = max([n_max] + [N_FIT[level] for level, _ in fit_jobs])
    centre_from_formula, recs = yield from records(
        list(range(1, top + 1)), [Task(centre_end_values_from_formula, (n,)) for n in range(1, n_cons + 1)])
    for rec in recs:
        remember(rec)
    fitted = yield [Task(fit_task, (level, kind, N_FIT[level], tuple(recs[: N_FIT[level]])))
                    for level, kind in fit_jobs]
    proven = [n for n in range(1, n_max + 1) if proof_cached(n)["proved"]]
    entries, ok = [], True
    formulas: list[Formula] = list(printed_level_formulas())
    for (level, kind), f in zip(fit_jobs, fitted):
        if f is None:
            entries.append({"level": level, "kind": kind, "status": "not found",
                            "searched": f"two-term shape, fitted on n <= {N_FIT[level]}"})
            continue
        formulas.append(f)
    entries.append({"level": "all", "kind": "all-n formula", "cases": "0 <= j <= i <= n, every n",
                    "status": "proven for every n",
                    "latex": ALL_N_LATEX,
                    "quantity": "s^{2n+j} r_{2n,2n-i,j}, m the number of minimal entries of (2n-i, j, i)",
                    "where": "m = 1 for j < i, 2 for i = j < n, 3 at the centre i = j = n",
                    "source": "hand proof for every n, docs/question1_for_all_n.md (claim question1_all_n; its "
                              "lemmas machine-checked for n <= 12 at 4 alpha)"})
    per_n = yield [Task(checks_at, (n, tuple(formulas), max_level, recs[n - 1] if n <= n_max else None))
                   for n in range(1, max(n_cons, n_max) + 1)]
    for k, f in enumerate(formulas):
        first = 1 if f.kind == "all" else f.level + 1  # the smallest n with a case (level 1: n >= 2, as printed)
        res = {"agrees_for_n": [n for n in range(first, n_max + 1) for r in [per_n[n - 1]["closed_forms"][k]]
                                if r["agrees_for_n"]],
               "fails_for_n": [n for n in range(first, n_max + 1) for r in [per_n[n - 1]["closed_forms"][k]]
                               if r["fails_for_n"]]}
        status, top = _status(res["agrees_for_n"], res["fails_for_n"], proven, first)
        cons = {"fails_for_n": [n for n in range(first, n_cons + 1) if not per_n[n - 1]["consequence"][k]]}
        ok &= not res["fails_for_n"] and top == n_max and not cons["fails_for_n"]
        status = (f"equal to the all-n formula for each n <= {n_cons} (not proven for every n)"
                  if not cons["fails_for_n"] else f"differs from the all-n formula for n = {cons['fails_for_n'][:5]}")
        entry = f.as_json() | {"status": status, "agrees_for_n": [min(res["agrees_for_n"] or [0]),
                                                                  max(res["agrees_for_n"] or [0])],
                               "source": "printed" if f.level <= 1 else f"fitted on n <= {N_FIT[f.level]}",
                               "independent_confirmation_for_n": (
                                   "every n (printed, not fitted)" if f.level <= 1 else
                                   f"{N_FIT[f.level] + 1}..{n_max} (closed forms), {N_FIT[f.level] + 1}..{n_cons} "
                                   f"(all-n formula); n <= {N_FIT[f.level]} agree by construction"),
                               "closed_forms": f"equal to the closed forms proven for every alpha, n <= {top}",
                               "beyond": f"a derivation for every n is not written; checked consequence for n <= "
                                         f"{n_cons}"}
        if f.kind == "interior" and f.level >= 2:
            entry["regularities"] = interior_pattern(f)
        if (f.level, f.kind) in POSITIVITY:
            entry["positivity_for_all_n_if_the_formula_holds"] = POSITIVITY[(f.level, f.kind)]
        entries.append(entry)
    centre = _centre_recurrence(min(n_max, 22))
    entries.append({"level": "n (centre r_{2n,n,n})", "kind": "centre", "status": "given by the all-n formula "
                    "(m = 3); no short recurrence in n" + (" found" if centre["found"] else " of the searched shape"),
                    "searched": centre["searched"]})
    values = {n: centre_end_values(n) for n in range(1, n_max + 1)}
    from_formula = dict(zip(range(1, n_cons + 1), centre_from_formula))
    for e in CENTRE_END_VALUES:
        agrees = [n for n, v in values.items()
                  if v["vanishes_at_1"] and eval_expression(e["expression"], n) == v[e["kind"]]]
        fails = [n for n in values if n not in agrees]
        status, top = _status(agrees, fails, proven, 1)
        fails_f = [n for n, v in from_formula.items()
                   if not (v["vanishes_at_1"] and eval_expression(e["expression"], n) == v[e["kind"]])]
        ok &= not fails and top == n_max and not fails_f
        status = (f"equal to the limits of the all-n formula for each n <= {n_cons} (not proven for every n)"
                  if not fails_f else f"differs from the all-n formula for n = {fails_f[:5]}")
        entries.append({"level": "n (centre r_{2n,n,n})", "kind": e["kind"], "cases": e["name"], "status": status,
                        "source": "found by guessing the recurrence " + e["recurrence"] + "; equal to the proven "
                                  f"closed forms for n <= {top}", "quantity": e["quantity"],
                        "expression": e["expression"], "latex": e["latex"],
                        "beyond": f"no proof for every n (no recurrence certificate); checked for n <= {n_cons}"})
    def at_one_holds(n: int, rep, forms) -> bool:
        value = eval_expression(ALL_LEVELS_AT_1["expression"], n, i=rep.i, j=rep.j)
        return fmpq(value.numerator, value.denominator) == forms[rep.coefficient].numerator(fmpq(1))

    # the closed forms of each n read once (not once per orbit)
    at_one = bool(proven) and all(at_one_holds(n, rep, forms) for n in proven for forms in [closed_forms_cached(n)]
                                  for rep, _ in orbits(n))
    ok &= at_one
    entries.append(ALL_LEVELS_AT_1 | {"level": "all", "cases": ALL_LEVELS_AT_1["name"],
                                      "status": "proven for every n" if at_one else "fails",
                                      "source": "the alpha -> 0 limit theorem (claim limit_formula, docs/"
                                                f"limit_for_all_n.md); agrees with the closed forms for n <= {n_max}"})
    entries.append({"level": f"> {max_level}", "kind": "interior/diagonal", "status": "given by the all-n formula",
                    "searched": f"no two-term level formula fitted beyond level {max_level} (the fit grows as level^4 "
                                "unknowns); the all-n formula covers every level"})
    data = {f"normalization/general_formulas{suffix}.json": {"n_max": n_max, "proven_closed_forms_for_n": proven,
                                                           "definitions": {
                                                               "P": "r_{2n,2n-i,j} = P_{n,i,j}(c) / s^{2n+j}",
                                                               "C": "C_{n,k}(c) = coefficient of X^k in "
                                                                    "(1 + 2cX + X^2)^n = s^{2n} c_{2n,k}",
                                                               "c": "cos(alpha/2)", "s": "sin(alpha/2)"},
                                                           "levels": entries},
            f"normalization/general_formulas{suffix}.md": markdown(entries, n_max)}
    regular = [e["level"] for e in entries if all(e.get("regularities", {"": False}).values())]
    return Outcome(ok, {
        "levels": [{k: e[k] for k in ("level", "kind", "status")} for e in entries],
        "interior_regularities_hold_for_levels": regular,
        "scope": "the all-n formula is proven for every n (claim question1_all_n, a hand proof with machine-checked "
                 "lemmas); the level formulas and the centre's end values agree with it for each n <= "
                 f"{n_cons} and equal the closed forms proven for every alpha for n <= {n_max}; neither is proven "
                 "for every n"}, data=data)


def markdown(entries: list[dict], n_max: int) -> str:
    lines = ["# General formulas of the normalizing coefficients (Question 1)", "",
             "Generated by `make reproduce` (claim `general_formulas`). Notation: "
             "$r_{2n,2n-i,j}^\\alpha = P_{n,i,j}(c)/s^{2n+j}$, $c = \\cos\\frac{\\alpha}{2}$, "
             "$s = \\sin\\frac{\\alpha}{2}$, and $C_{n,k}(c)$ the coefficient of $X^k$ in $(1+2cX+X^2)^n$ "
             "(so $c^\\alpha_{2n,k} = C_{n,k}/s^{2n}$, eq. univariate_basis). "
             "The first row, the all-n formula, is proven for every n (docs/question1_for_all_n.md); the level "
             "formulas and the centre's end values below agree with it, checked as polynomial identities for each "
             "n stated (not proven for every n: a derivation for every n is not written), and they equal the closed "
             "forms proven for "
             f"every α for n ≤ {n_max}. The brackets are written with "
             "$c^2 = 1 - s^2$ and factored over Q (the fitted polynomials in c are in the JSON, `latex_expanded`).", "",
             "| level | cases | status | source |", "|---|---|---|---|"]
    for e in entries:
        lines.append(f"| {e['level']} | {e.get('cases', e['kind'])} | {e['status']} | "
                     f"{e.get('source', e.get('searched', ''))} |")
    lines.append("")
    regular = [e["level"] for e in entries if all(e.get("regularities", {"": False}).values())]
    if regular:
        lines += ["Two regularities of the interior formulas, checked exactly for the levels "
                  f"{', '.join(map(str, regular))} (a conjecture for every level j >= 2): the $s^0$ parts of both "
                  "brackets are equal to $F_j = (i+1)\\,\\frac{2n\\,(2n+j-1)!}{j!\\,(2n+1)!}$ (which makes "
                  "$P_{n,i,j}(1) = F_j \\binom{2n+1}{i+1}$ the α → 0 limit factor of claim `limit_formula`), and the "
                  "highest power of s in the first bracket is $s^{2\\lfloor j/2 \\rfloor}$ with coefficient "
                  "$(-1)^{\\lfloor j/2 \\rfloor}\\binom{i}{j}$.", ""]
    for e in entries:
        if "latex" in e:
            lines += [f"## Level {e['level']}, {e['cases']} ({e['status']})", "", f"$$ {e['latex']} $$", ""]
            if "where" not in e and "quantity" in e:
                lines += [f"{e['quantity']}; found as the solution of the {e['source']}; a conjecture for n beyond "
                          "the proven range.", ""]
            elif "where" in e:
                lines += [f"{e['quantity']}, {e['where']}; source: {e['source']}.", ""]
            if "positivity_for_all_n_if_the_formula_holds" in e:
                lines += [f"Positivity: {e['positivity_for_all_n_if_the_formula_holds']}.", ""]
    return "\n".join(lines)
