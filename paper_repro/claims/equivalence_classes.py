"""Claim ``equivalence_classes``: Definition equivalence_relation_definition, Proposition
iterative_construction_of_trivariate_extension and Corollary dimension, exhaustively for n <= n_max."""

from __future__ import annotations

from paper_repro.core.fourier import (
    classes,
    is_transitive,
    new_classes,
    printed_representatives,
    related,
    v_labels,
    v_system,
)
from paper_repro.core.labels import delta
from paper_repro.printed.coincidence import EXAMPLES_N3, PRINTED_V2
from paper_repro.util.cache import cached, keys_and_types
from paper_repro.util.registry import Outcome, claim


def per_n(n: int) -> dict:
    cl = classes(n)
    new = new_classes(n)
    reps = printed_representatives(n)
    rep_classes = [next(c for c in cl if r in c) for r in reps]
    return {"classes": len(cl), "new_classes": len(new), "representatives_distinct": len(set(rep_classes)) == len(reps),
            "representatives_are_the_new_classes": set(rep_classes) == set(new), "transitive": is_transitive(n),
            "functions_in_V": len(v_system(n)), "delta_n": delta(n)}


#: The fields of a stored per-n record (validated before a cached record is used).
_RECORD = keys_and_types(classes=int, new_classes=int, representatives_distinct=bool,
                         representatives_are_the_new_classes=bool, transitive=bool, functions_in_V=int, delta_n=int)


@claim("equivalence_classes", paper_ref=["equivalence_relation_definition", "equivalence_conditions_1",
                                         "equivalence_conditions_2", "iterative_construction_of_trivariate_extension",
                                         "dimension"],
       statement="For n = 1..{n_max}: at order n exactly 3n new equivalence classes (6n new functions) "
                 "appear, represented by the printed representatives; V_n consists of delta_n functions "
                 "(a count; their independence at sampled alpha is claim coincidence); the worked examples "
                 "(n = 2, 3) hold.",
       kind="proof", n_max=30)
def run(n_max: int) -> Outcome:
    rows = {str(n): cached("equivalence_classes", {"n": n}, lambda n=n: per_n(n), validate=_RECORD)
            for n in range(1, n_max + 1)}
    bad = [n for n, r in rows.items() if not (r["new_classes"] == 3 * int(n) and r["representatives_distinct"]
                                              and r["representatives_are_the_new_classes"]
                                              and r["functions_in_V"] == r["delta_n"]
                                              and r["classes"] == 1 + 3 * int(n) * (int(n) + 1) // 2)]
    examples = [related(a, b, 3) == expect for a, b, expect in EXAMPLES_N3]
    n2 = [related((1, 1, 1), (0, 0, 0), 2), related((1, 1, 0), (0, 0, 1), 2), related((1, 0, 1), (0, 1, 0), 2),
          related((0, 1, 1), (1, 0, 0), 2), related((0, 2, 2), (2, 0, 0), 2)]
    v2 = set(v_labels(2)) == PRINTED_V2
    return Outcome(not bad and all(examples) and all(n2) and v2, {
        "n_range": [1, n_max], "failing_n": bad,
        "relation_transitive_for_all_n": all(r["transitive"] for r in rows.values()),
        "worked_examples_n_3": examples, "n_2_derivation_relations": n2, "printed_V2_equals_computed": v2,
        "sample": {k: rows[k] for k in ("1", "2", "3", str(n_max)) if k in rows}})
