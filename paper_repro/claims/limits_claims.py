"""Claims ``bernstein_limit``, ``bezier_limit_degree`` and ``bezier_conversion`` (alpha -> 0).

See :mod:`paper_repro.theory.limits` for the derivation of the limits from the closed forms.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
from flint import fmpq

from paper_repro.core.labels import index_of, united_system
from paper_repro.core.normalization import evaluate_normalized
from paper_repro.theory.closed_forms import proof_cached
from paper_repro.theory.limit_formula import multinomial
from paper_repro.theory.limits import bernstein_index, conversion_matrix, limit_degree, limit_terms
from paper_repro.util.registry import Outcome, claim


def _q(x: Fraction) -> fmpq:
    return fmpq(x.numerator, x.denominator)


def limit_error(n: int, k: int, grid: int, dps: int) -> mpmath.mpf:
    """max over a barycentric grid and all functions of |T-bar(alpha x, alpha y, alpha z) - limit|, alpha = 2^-k."""
    terms = limit_terms(n)
    with mpmath.workdps(dps):
        alpha = mpmath.mpf(2) ** -k
        bary = [(mpmath.mpf(i) / grid, mpmath.mpf(j) / grid) for i in range(grid + 1) for j in range(grid + 1 - i)]
        pts = np.array([[alpha * x, alpha * y, alpha * (1 - x - y)] for x, y in bary], dtype=object)
        vals = evaluate_normalized(n, alpha, pts, "mp", dps=dps)
        worst = mpmath.mpf(0)
        for p, (x, y) in enumerate(bary):
            z = 1 - x - y
            for f, (c, (a, b, cc)) in enumerate(terms):
                lim = mpmath.mpf(int(c.p)) / int(c.q) * x**a * y**b * z**cc
                worst = max(worst, abs(vals[p, f] - lim))
        return worst


def limit_table(n: int) -> dict:
    out = {}
    for lab, (c, t) in zip(united_system(n), limit_terms(n)):
        m = sum(t)
        out[lab.paper] = {"limit_coefficient": str(c), "monomial_xyz": list(t), "bernstein": bernstein_index(t),
                          "limit_over_bernstein": str(c / multinomial(m, t))}
    return out


@claim("bernstein_limit", paper_ref=["que:limiting_case", "fig:limit_cases_n_1_2_3"],
       statement="As alpha -> 0 (u = alpha x, v = alpha y, w = alpha z) each normalized function of level j tends to "
                 "P(1) x^a y^b z^c, a rational multiple of the Bernstein polynomial P^{2n+j}_{a,b,c}; the centre tends "
                 "to 0 (exactly, n = 1..{n_max}). Convergence is of order alpha^2 (numerically, "
                 "n in {convergence_ns}).",
       kind="exact-evidence", n_max=10, convergence_ns=[1, 2, 3, 5], ks=list(range(2, 9)), grid=6, dps=40)
def run_limit(n_max, convergence_ns, ks, grid, dps) -> Outcome:
    orders, errors = {}, {}
    for n in convergence_ns:
        errs = [limit_error(n, k, grid, dps) for k in ks]
        slope = -np.polyfit(np.array(ks, float), np.array([float(mpmath.log(e, 2)) for e in errs]), 1)[0]
        orders[str(n)] = round(float(slope), 3)
        errors[str(n)] = {f"2^-{k}": mpmath.nstr(e, 3) for k, e in zip(ks, errs)}
    centre_zero = all(limit_terms(n)[0][0] == 0 for n in range(1, n_max + 1))
    exact_bernstein_levels = {str(n): sorted({lab.j for lab, (c, t) in zip(united_system(n), limit_terms(n))
                                              if c == multinomial(sum(t), t)}) for n in range(1, n_max + 1)}
    data = {"limits/limit_terms.json": {str(n): limit_table(n) for n in range(1, n_max + 1)}}
    ok = centre_zero and all(abs(o - 2) < 0.1 for o in orders.values())
    return Outcome(ok, {
        "centre_limit_zero_for_all_n": centre_zero, "observed_order": orders, "expected_order": 2,
        "max_error": errors, "levels_whose_limit_is_exactly_the_Bernstein_polynomial": exact_bernstein_levels,
        "note": "level 0 limits are the Bernstein polynomials P^{2n}_{a,0,c}; for n >= 2 higher levels are rational "
                "multiples of P^{2n+j}_{a,b,c} (data/limits/limit_terms.json)",
        "scope": "limit coefficients exact from the closed forms, proven for every alpha for these n (claim "
                 "nonnegativity_extended); the convergence order is numeric evidence"}, data=data)


@claim("bezier_limit_degree", paper_ref=["que:limiting_case"],
       statement="Question que:limiting_case answered for n = 1..{n_max} (proof for these n; for all n see claim "
                 "limit_formula): the alpha -> 0 limit of an order-n patch is a "
                 "Bezier triangle of degree exactly 3n-1 (levels j give degrees 2n+j, the centre vanishes).",
       kind="proof", n_max=10)
def run_degree(n_max) -> Outcome:
    rows = {}
    for n in range(1, n_max + 1):
        degrees = sorted({sum(t) for c, t in limit_terms(n) if c != 0})
        rows[str(n)] = {"degree": limit_degree(n), "degrees_present": degrees,
                        "centre_vanishes": limit_terms(n)[0][0] == 0}
    ok = all(r["degree"] == 3 * int(n) - 1 and r["centre_vanishes"] and r["degrees_present"] ==
             list(range(2 * int(n), 3 * int(n))) for n, r in rows.items())
    ok &= all(proof_cached(n)["proved"] for n in range(1, n_max + 1))
    return Outcome(ok, {"per_n": rows, "rational_patches": "weights and weighted points convert with the same "
                                                          "matrix (homogeneous coordinates): a rational Bezier "
                                                          "triangle of degree 3n-1",
                        "scope": "exact limit coefficients from the closed forms, proven for every alpha for these n"})


def _render(terms: dict[str, fmpq]) -> str:
    return " + ".join(f"{w} {lab}" for lab, w in terms.items() if w != 0)


def printed_conversions() -> list[tuple[str, str, tuple[int, int, int], list[tuple[Fraction, str]]]]:
    """Every printed Bezier point of the alpha -> 0 conversions (before Question que:limiting_case), read from the
    transcribed lines (``sec7-conv2-*``, ``sec7-conv3-*`` of :mod:`paper_repro.printed.lines.sec7`) by the strict
    reader (:func:`paper_repro.printed.parsed.conversion`, terms in the printed order): ``(line id, printed key
    p_{d,e,f}, index, [(weight, control point), ...])``.  No copy of the formulas: a changed transcription changes
    the claim."""
    from paper_repro.printed.lines import sec7 as lines7
    from paper_repro.printed.parsed import conversion as strict_conversion

    out = []
    for ln in lines7.LINES:
        if ln.id.startswith(("sec7-conv2-", "sec7-conv3-")):
            idx, terms = strict_conversion(ln.verbatim)
            out.append((ln.id, f"p_{{{idx[0]},{idx[1]},{idx[2]}}}", idx, terms))
    return out


def _recorded_correction(text: str) -> tuple[tuple[int, int, int], list[tuple[Fraction, str]]]:
    """The correction recorded on an erratum line, ``p_{d,e,f} = w lab + w lab ...``, read.  This is our own plain
    notation (the erratum's ``corrected`` field, typed in printed/lines/sec7.py), not the paper's LaTeX: plain string
    splits, strict (``ValueError`` on anything else).

    >>> _recorded_correction("p_{8,8,0} = 1 r_{4,4,0} + 1/2 g_{4,1,0}")
    ((8, 8, 0), [(Fraction(1, 1), 'r_{4,4,0}'), (Fraction(1, 2), 'g_{4,1,0}')])
    """
    head, sep, rhs = text.strip().partition(" = ")
    idx = head.removeprefix("p_{").removesuffix("}").split(",")
    if not sep or not head.startswith("p_{") or not head.endswith("}") or len(idx) != 3 or \
            not all(i.isdigit() for i in idx) or not rhs:
        raise ValueError(f"unread correction {text!r}")
    terms = []
    for part in rhs.split(" + "):
        w, lab = part.split(" ")
        terms.append((Fraction(w), lab))
    return (int(idx[0]), int(idx[1]), int(idx[2])), terms


def _slips(printed: tuple, corrected: tuple) -> int:
    """How many items (each index of p; each term's weight or point) differ between a printed and a corrected
    point."""
    (i1, t1), (i2, t2) = printed, corrected
    index = sum(a != b for a, b in zip(i1, i2))
    if len(t1) != len(t2):
        return index + 1 + abs(len(t1) - len(t2)) + sum(a != b for a, b in zip(t1, t2))
    return index + sum((w1 != w2) + (l1 != l2) for (w1, l1), (w2, l2) in zip(t1, t2))


@claim("bezier_conversion", paper_ref=["que:limiting_case", "fig:conversion_of_limit_cases_n_1_2_3"],
       statement="The printed conversions of order-2 and order-3 control nets to quintic and octic Bezier nets (read "
                 "from the transcribed lines) agree with the general conversion, except the index/label misprints "
                 "recorded as errata on the lines (p_{8,8,0}, p_{2,1,5}, p_{3,2,3}).",
       kind="proof")
def run_conversion() -> Outcome:
    from paper_repro.printed.lines import line

    errata, checked, mismatches, expected, records = [], 0, [], set(), {}
    for line_id, key, t, terms in printed_conversions():
        erratum = line(line_id).erratum if line(line_id).status == "erratum" else None
        if erratum:  # the recorded correction must hold, and differ from the printed line in one slip
            cidx, cterms = _recorded_correction(erratum["corrected"])
            records[line_id] = {"recorded_correction": erratum["corrected"], "slips": _slips((t, terms),
                                                                                              (cidx, cterms))}
        orders = {int(lab.split("{")[1].split(",")[0]) for _, lab in terms}
        if len(orders) != 1 or next(iter(orders)) % 2:
            raise ValueError(f"{line_id}: control points of orders {orders}")
        n = orders.pop() // 2
        if line(line_id).status == "erratum":
            expected.add(key)
        idx, w = conversion_matrix(n)
        ix = index_of(n)
        labs = [lab.control_point for lab in united_system(n)]
        checked += 1
        vec = [fmpq(0)] * len(labs)
        for wt, lab in terms:
            vec[ix[lab]] += _q(wt)
        if erratum:
            cvec = [fmpq(0)] * len(labs)
            for wt, lab in cterms:
                cvec[ix[lab]] += _q(wt)
            records[line_id]["recorded_correction_holds"] = cidx in idx and w[idx.index(cidx)] == cvec \
                and all(lab in labs for _, lab in cterms)
        printed = " + ".join(f"{wt} {lab}" for wt, lab in terms)
        if t not in idx:  # not an index of degree N: find the computed point with these weights
            match = [s for s in idx if w[idx.index(s)] == vec]
            corrected = f"p_{{{','.join(map(str, match[0]))}}}" if match else "no index has these weights"
            errata.append({"id": f"conversion-{key}", "paper_ref": "que:limiting_case", "item": key,
                           "severity": "typo",  # not an index at all: the intended point is clear
                           "printed": f"{key} = {printed}", "corrected": f"{corrected} = {printed}",
                           "evidence": f"{key} is not an index of the degree-{3 * n - 1} Bezier net "
                                       f"(indices sum to {3 * n - 1}); the printed weights are those of "
                                       f"{corrected} in the exact general conversion"})
            mismatches.append(key)
            continue
        row = w[idx.index(t)]
        if row != vec:
            comp = {labs[f]: row[f] for f in range(len(labs))}
            errata.append({"id": f"conversion-{key}", "paper_ref": "que:limiting_case", "item": key,
                           "severity": "statement",  # a valid formula that gives a wrong point as written
                           "printed": f"{key} = {printed}", "corrected": f"{key} = {_render(comp)}",
                           "evidence": "exact general conversion (limit of the normalized basis written in "
                                       f"the degree-{3 * n - 1} Bernstein basis)"})
            mismatches.append(key)
    corrections = all(r["recorded_correction_holds"] and r["slips"] == 1 for r in records.values())
    return Outcome(set(mismatches) == expected and checked > 0 and corrections,
                   {"printed_formulas_checked": checked, "mismatches": mismatches, "errata_lines": records,
                    "scope": "exact comparison of the formulas read from the transcription; the conversion weights do "
                             "not depend on alpha"}, errata=errata)
