"""The printed dimension count of the proof of Theorem joint_systems_linear_independence, verbatim."""

from __future__ import annotations


def printed_index_sum(n: int) -> int:
    """The sum printed in the proof of Theorem joint_systems_linear_independence."""
    return 1 + 3 * sum(1 for j in range(n) for i in range(j, 2 * n - j))
