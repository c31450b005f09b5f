"""Section sec:coincidence, verbatim: the worked examples of the equivalence relation, the printed V_2,
and the representatives of Proposition iterative_construction_of_trivariate_extension."""

from __future__ import annotations

from paper_repro.core.fourier import printed_representatives  # noqa: F401 (the construction of V_n uses it)

#: Worked examples of the text after Definition equivalence_relation_definition (n = 3), verbatim.
EXAMPLES_N3 = [((0, 0, 1), (1, 1, 0), True), ((1, 3, 2), (2, 0, 1), True), ((2, 0, 1), (0, 2, 1), True),
               ((1, 3, 2), (0, 2, 1), True), ((1, 0, 0), (0, 1, 0), False)]
#: The printed V_2 (Section sec:coincidence), as function labels.
PRINTED_V2 = {"1", "cos(u)", "sin(u)", "cos(v)", "sin(v)", "cos(w)", "sin(w)", "cos(2w)", "sin(2w)", "cos(v+2w)",
              "sin(v+2w)", "cos(2u)", "sin(2u)", "cos(2u+w)", "sin(2u+w)", "cos(2v)", "sin(2v)", "cos(u+2v)",
              "sin(u+2v)"}
