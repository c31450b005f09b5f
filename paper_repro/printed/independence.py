"""The index sets of the equalities in the proof of Theorem joint_systems_linear_independence, as printed.

Each function returns the labels (``"R_{2n,2n-i,j}"`` etc., in the paper's own colour, the centre as
``R_{2n,n,n}``) of the functions the printed equality still contains, read from the transcriptions of its rows
(:mod:`paper_repro.printed.lines.sec1_3`) with :func:`paper_repro.printed.parsed.function_terms` -- sums, bounds,
constants and functions as printed, never retyped.
"""

from __future__ import annotations

from paper_repro.printed.lines import verbatim
from paper_repro.printed.parsed import function_terms, term_indices

#: equation label -> the transcribed lines of its rows
ROWS = {
    "linear_combination_union": ("sec1_3-L-R-row", "sec1_3-L-G-row", "sec1_3-L-B-row"),
    "linear_combination_union_reduced_null_equality_1": ("sec1_3-Ltilde-row1", "sec1_3-Ltilde-row2",
                                                         "sec1_3-Ltilde-row3"),
    "linear_combination_union_reduced_null_equality_2": ("sec1_3-Lhat-row1", "sec1_3-Lhat-row2", "sec1_3-Lhat-row3"),
    "linear_combination_union_reduced_null_equality_3": ("sec1_3-L0-row1", "sec1_3-L0-row2"),
    "induction_hypothesis_for_linear_independence": ("sec1_3-Lr-row1", "sec1_3-Lr-row2", "sec1_3-Lr-row3"),
    "induction_hypothesis_nex_step": ("sec1_3-Lr1-row1", "sec1_3-Lr1-row2", "sec1_3-Lr1-row3"),
    "reduced_y_derivative_L_r_tilde": ("sec1_3-Ltilde-r-row1", "sec1_3-Ltilde-r-row2", "sec1_3-Ltilde-r-row3"),
    "reduced_x_derivative_L_r_hat": ("sec1_3-Lhat-r-row1", "sec1_3-Lhat-r-row2", "sec1_3-Lhat-r-row3"),
    "induction_hypothesis_for_linear_independence_n_minus_2": ("sec1_3-Ln2-row1", "sec1_3-Ln2-row2",
                                                               "sec1_3-Ln2-row3"),
    "induction_hypothesis_for_linear_independence_n_minus_1": ("sec1_3-Ln1",),
}


def printed_set(label: str, n: int, r: int = 0) -> set[str]:
    """Labels named by the printed rows of equation ``label`` at order n and step r."""
    out: set[str] = set()
    for line_id in ROWS[label]:
        for color, i, j in term_indices(function_terms(verbatim(line_id)), n=n, r=r):
            out.add(f"{color}_{{{2 * n},{2 * n - i},{j}}}")
    return out


def linear_combination_union(n: int) -> set[str]:
    return printed_set("linear_combination_union", n)


def reduced_null_equality_1(n: int) -> set[str]:
    return printed_set("linear_combination_union_reduced_null_equality_1", n)


def reduced_null_equality_2(n: int) -> set[str]:
    return printed_set("linear_combination_union_reduced_null_equality_2", n)


def reduced_null_equality_3(n: int) -> set[str]:
    return printed_set("linear_combination_union_reduced_null_equality_3", n)


def induction_hypothesis(n: int, r: int) -> set[str]:
    return printed_set("induction_hypothesis_for_linear_independence", n, r)


def induction_next_step(n: int, r: int) -> set[str]:
    return printed_set("induction_hypothesis_nex_step", n, r)


def reduced_y_derivative_tilde(n: int, r: int) -> set[str]:
    return printed_set("reduced_y_derivative_L_r_tilde", n, r)


def reduced_x_derivative_hat(n: int, r: int) -> set[str]:
    return printed_set("reduced_x_derivative_L_r_hat", n, r)


def hypothesis_n_minus_2(n: int) -> set[str]:
    return printed_set("induction_hypothesis_for_linear_independence_n_minus_2", n)


def hypothesis_n_minus_1(n: int) -> set[str]:
    return printed_set("induction_hypothesis_for_linear_independence_n_minus_1", n)
