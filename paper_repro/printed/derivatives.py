"""Lemma lem:sign_cos_power_derivative and Proposition derivative_cosine_sine, verbatim: the printed sign
rules of the derivatives at 0 (``None`` where the printed case analysis gives no value)."""

from __future__ import annotations


def printed_sign_cos(i: int, p: int) -> int | None:
    """eq. sign_cos_power_derivative: -1 if p-i = 2r with r odd; 0 if p odd; +1 if p-i = 2r with r even."""
    if p % 2 == 1:
        return 0
    if (p - i) % 2 == 0:
        r = (p - i) // 2
        return -1 if r % 2 == 1 else 1
    return None  # p even, p - i odd: no printed case applies


def printed_sign_sin(j: int, p: int) -> int | None:
    """eq. sign_sin_power_derivative: -1 if p>=j, p-j=2r, r odd; 0 if p<j or (p-j odd and p>j);
    +1 if p>=j, p-j=2r, r even."""
    if p < j or ((p - j) % 2 == 1 and p > j):
        return 0
    r = (p - j) // 2
    return -1 if r % 2 == 1 else 1


def printed_sign_m(j: int, z: int) -> int | None:
    """eq. derivative_cosine_sine_at_0 (z >= 1, i + j != 0): -1 if z-j = 2 mod 4 and z>=j;
    0 if z<j or (z-j = +-1 mod 4 and z>j); +1 if z-j = 0 mod 4 and z>=j."""
    if z < j:
        return 0
    d = (z - j) % 4
    if d == 2:
        return -1
    if d in (1, 3) and z > j:
        return 0
    if d == 0:
        return 1
    return None
