"""The index sets of the equalities in the proof of Theorem joint_systems_linear_independence, verbatim.

Each function returns the labels (``"R_{2n,2n-i,j}"`` etc., in the paper's own colour, the centre as
``R_{2n,n,n}``) of the functions the printed equality still contains, read off its sums exactly as printed.
"""

from __future__ import annotations


def _lab(color: str, n: int, i: int, j: int) -> str:
    return f"{color}_{{{2 * n},{2 * n - i},{j}}}"


def _levels(colors: str, n: int, j_from: int, j_to: int) -> set[str]:
    """sum_{j=j_from}^{j_to} sum_{i=j}^{2n-1-j} for each colour."""
    return {_lab(c, n, i, j) for c in colors for j in range(j_from, j_to + 1) for i in range(j, 2 * n - j)}


def _centre(n: int) -> set[str]:
    return {_lab("R", n, n, n)}


def linear_combination_union(n: int) -> set[str]:
    """Eq. linear_combination_union: centre, and R, G, B with j = 0..n-1, i = j..2n-1-j."""
    return _centre(n) | _levels("RGB", n, 0, n - 1)


def reduced_null_equality_1(n: int) -> set[str]:
    """Eq. linear_combination_union_reduced_null_equality_1 (L-tilde)."""
    return (_centre(n) | _levels("R", n, 1, n - 1) | {_lab("G", n, i, 0) for i in range(1, 2 * n)}
            | _levels("G", n, 1, n - 1) | _levels("B", n, 0, n - 1))


def reduced_null_equality_2(n: int) -> set[str]:
    """Eq. linear_combination_union_reduced_null_equality_2 (L-hat)."""
    return (_centre(n) | _levels("R", n, 1, n - 1) | _levels("G", n, 1, n - 1)
            | {_lab("B", n, i, 0) for i in range(1, 2 * n)} | _levels("B", n, 1, n - 1))


def reduced_null_equality_3(n: int) -> set[str]:
    """Eq. linear_combination_union_reduced_null_equality_3 (L_0)."""
    return _centre(n) | _levels("RGB", n, 1, n - 1)


def induction_hypothesis(n: int, r: int) -> set[str]:
    """Eq. induction_hypothesis_for_linear_independence (L_r), r = 0..n-1."""
    return _centre(n) | _levels("RGB", n, r + 1, n - 1)


def induction_next_step(n: int, r: int) -> set[str]:
    """Eq. induction_hypothesis_nex_step (L_{r+1}), r = 0..n-2."""
    return _centre(n) | _levels("RGB", n, r + 2, n - 1)


def reduced_y_derivative_tilde(n: int, r: int) -> set[str]:
    """Eq. reduced_y_derivative_L_r_tilde (L-tilde_r)."""
    return (_centre(n) | _levels("R", n, r + 2, n - 1) | {_lab("G", n, i, r + 1) for i in range(r + 2, 2 * n - r - 1)}
            | _levels("G", n, r + 2, n - 1) | _levels("B", n, r + 1, n - 1))


def reduced_x_derivative_hat(n: int, r: int) -> set[str]:
    """Eq. reduced_x_derivative_L_r_hat (L-hat_r)."""
    return (_centre(n) | _levels("R", n, r + 2, n - 1) | _levels("G", n, r + 2, n - 1)
            | {_lab("B", n, i, r + 1) for i in range(r + 2, 2 * n - r - 1)} | _levels("B", n, r + 2, n - 1))


def hypothesis_n_minus_2(n: int) -> set[str]:
    """Eq. induction_hypothesis_for_linear_independence_n_minus_2: centre and level n-1 with i = n-1..n."""
    return _centre(n) | {_lab(c, n, i, n - 1) for c in "RGB" for i in range(n - 1, n + 1)}


def hypothesis_n_minus_1(n: int) -> set[str]:
    """Eq. induction_hypothesis_for_linear_independence_n_minus_1: the centre only."""
    return _centre(n)
