"""Verbatim transcriptions of every printed normalizing-coefficient formula.

Nothing here is computed from anything else in the package: each entry is the paper's text, with
its LaTeX label.  ``s = sin(alpha/2)``, ``c = cos(alpha/2)``, ``C(i) = c_{2n,i}^alpha`` (the univariate
constants).  Expressions are plain Python in ``s``, ``c`` and ``C`` so that they evaluate in exact
rationals (``fmpq``) and in mpmath alike.

* ``FINAL`` -- right-hand closed forms of Examples normalizing_coefficients_n_1..3:
  ``(numerator coefficients in c, ascending; power of s in the denominator)``.
* ``INTERMEDIATE`` -- the middle expressions of the same Examples (in terms of c_{2n,i}).
* :func:`remark_level_0` (Remark normalizing_coeff_of_level_0) and :func:`prop_level_1`
  (Proposition prop:level_1_coefficients, eq. level_1_coefficients), for any n.
* :func:`from_1_to_2` -- Example exmp:from_1_to_2: second order coefficients in terms of first order ones.
"""

from __future__ import annotations

from collections.abc import Callable

# label -> (paper_ref, numerator coefficients of c ascending, power of s)
FINAL: dict[str, tuple[str, list[int], int]] = {
    # Example normalizing_coefficients_n_1
    "r_{2,2,0}": ("normalizing_coefficients_n_1", [1], 2),
    "r_{2,1,0}": ("normalizing_coefficients_n_1", [0, 2], 2),
    # printed 2 sin(a/2) / sin^2(a/2), which is identically 2 / sin(a/2):
    "r_{2,1,1}": ("normalizing_coefficients_n_1", [2], 1),
    # Example normalizing_coefficients_n_2
    "r_{4,4,0}": ("normalizing_coefficients_n_2", [1], 4),
    "r_{4,3,0}": ("normalizing_coefficients_n_2", [0, 4], 4),
    "r_{4,2,0}": ("normalizing_coefficients_n_2", [2, 0, 4], 4),
    "r_{4,3,1}": ("normalizing_coefficients_n_2", [4, 0, 8], 5),
    "r_{4,2,1}": ("normalizing_coefficients_n_2", [0, 16, 0, 8], 5),
    "r_{4,2,2}": ("normalizing_coefficients_n_2", [10, 0, 20], 4),
    # Example normalizing_coefficients_n_3
    "r_{6,6,0}": ("normalizing_coefficients_n_3", [1], 6),
    "r_{6,5,0}": ("normalizing_coefficients_n_3", [0, 6], 6),
    "r_{6,4,0}": ("normalizing_coefficients_n_3", [3, 0, 12], 6),
    "r_{6,3,0}": ("normalizing_coefficients_n_3", [0, 12, 0, 8], 6),
    "r_{6,5,1}": ("normalizing_coefficients_n_3", [6, 0, 24], 7),
    "r_{6,4,1}": ("normalizing_coefficients_n_3", [0, 42, 0, 48], 7),
    "r_{6,3,1}": ("normalizing_coefficients_n_3", [12, 0, 84, 0, 24], 7),
    "r_{6,4,2}": ("normalizing_coefficients_n_3", [24, 0, 162, 0, 24], 8),
    "r_{6,3,2}": ("normalizing_coefficients_n_3", [0, 144, 0, 252, 0, 24], 8),
    "r_{6,3,3}": ("normalizing_coefficients_n_3", [56, 0, 324, 0, -276, 0, -104], 9),
}

PRINTED_LATEX: dict[str, str] = {
    "r_{2,1,1}": r"\frac{2\sin\frac{\alpha}{2}}{\sin^{2}\frac{\alpha}{2}}",
    "r_{4,2,2}": r"\frac{10+20\cos^{2}\frac{\alpha}{2}}{\sin^{4}\frac{\alpha}{2}}",
    "r_{6,3,3}": r"\frac{-104\cos^{6}\frac{\alpha}{2}-276\cos^{4}\frac{\alpha}{2}+324\cos^{2}\frac{\alpha}{2}+56}"
                 r"{\sin^{9}\frac{\alpha}{2}}",
}


def final_value(label: str, s, c):
    """Value of the printed final closed form of ``label`` at ``s = sin(a/2)``, ``c = cos(a/2)``."""
    _, num, k = FINAL[label]
    acc = 0 * c
    for coef in reversed(num):
        acc = acc * c + coef
    return acc / s**k


# label -> (paper_ref, expression in s, c, C)
INTERMEDIATE: dict[str, tuple[str, Callable]] = {
    "r_{2,2,0}": ("normalizing_coefficients_n_1", lambda s, c, C: C(2)),
    "r_{2,1,0}": ("normalizing_coefficients_n_1", lambda s, c, C: C(1)),
    "r_{2,1,1}": ("normalizing_coefficients_n_1", lambda s, c, C: 2 / s * C(2) - 1 / s * C(1) * c),
    "r_{4,4,0}": ("normalizing_coefficients_n_2", lambda s, c, C: C(4)),
    "r_{4,3,0}": ("normalizing_coefficients_n_2", lambda s, c, C: C(3)),
    "r_{4,2,0}": ("normalizing_coefficients_n_2", lambda s, c, C: C(2)),
    "r_{4,3,1}": ("normalizing_coefficients_n_2", lambda s, c, C: 2 / s * C(2)),
    "r_{4,2,1}": ("normalizing_coefficients_n_2", lambda s, c, C: 2 / s * C(2) * c + 3 / s * C(3)),
    "r_{4,2,2}": ("normalizing_coefficients_n_2",
                  lambda s, c, C: -6 / s**2 * C(4) - 3 * c / s**2 * C(3) + (6 / s**2 - 3 * c**2 / s**2 + 2) * C(2)),
    "r_{6,6,0}": ("normalizing_coefficients_n_3", lambda s, c, C: C(6)),
    "r_{6,5,0}": ("normalizing_coefficients_n_3", lambda s, c, C: C(5)),
    "r_{6,4,0}": ("normalizing_coefficients_n_3", lambda s, c, C: C(4)),
    "r_{6,3,0}": ("normalizing_coefficients_n_3", lambda s, c, C: C(3)),
    "r_{6,5,1}": ("normalizing_coefficients_n_3", lambda s, c, C: 2 / s * C(4)),
    "r_{6,4,1}": ("normalizing_coefficients_n_3", lambda s, c, C: 3 / s * C(3) + 2 * c / s * C(4)),
    "r_{6,3,1}": ("normalizing_coefficients_n_3", lambda s, c, C: 4 / s * C(4) + 3 * c / s * C(3)),
    "r_{6,4,2}": ("normalizing_coefficients_n_3", lambda s, c, C: C(4) * (2 + 6 / s**2) + C(3) * 6 / s**2 * c),
    "r_{6,3,2}": ("normalizing_coefficients_n_3",
                  lambda s, c, C: -10 / s**2 * C(5) + (8 * c**3 / s**2 + 8 * c) * C(4)
                  + (6 * c**2 / s**2 + 12 / s**2 + 3) * C(3)),
    "r_{6,3,3}": ("normalizing_coefficients_n_3",
                  lambda s, c, C: 20 / s**3 * C(6) + 50 / s**3 * c * C(5)
                  - (56 / s**3 * c**4 - 60 / s**3 * c**2 - 8 / s + 56 / s * c**2 - 4 / s**3) * C(4)
                  - (10 / s**3 * c**3 - 3 / s * c + 12 / s**3 * c) * C(3)),
}


def remark_level_0(n: int, i: int, C: Callable):
    """Remark normalizing_coeff_of_level_0: r_{2n,2n-i,0} = c_{2n,2n-i} = c_{2n,i}, i = 0..n."""
    return C(2 * n - i)


def prop_level_1(n: int, i: int, s, c, C: Callable):
    """Proposition prop:level_1_coefficients (n >= 2), eq. level_1_coefficients, i = 1..n:
    r_{2n,2n-1,1} = 2/s c_{2n,2n-2};  r_{2n,2n-i,1} = i/s c_{2n,2n-i} c + (i+1)/s c_{2n,2n-(i+1)}."""
    if i == 1:
        return 2 / s * C(2 * n - 2)
    return i / s * C(2 * n - i) * c + (i + 1) / s * C(2 * n - (i + 1))


def from_1_to_2(s, c, r: dict) -> dict:
    """Example exmp:from_1_to_2: second order coefficients from first order ones (verbatim).

    ``r`` maps first-order labels (r_, g_, b_ of {2,2,0}, {2,1,0} and r_{2,1,1}) to values.
    Returns the printed right-hand sides keyed by second-order label.
    """
    r220, r210, r211 = r["r_{2,2,0}"], r["r_{2,1,0}"], r["r_{2,1,1}"]
    g220, g210, b220, b210 = r["g_{2,2,0}"], r["g_{2,1,0}"], r["b_{2,2,0}"], r["b_{2,1,0}"]
    sin_a = 2 * s * c  # sin(alpha)
    tan_h = s / c  # tan(alpha/2)
    return {
        "r_{4,4,0}": r220**2, "g_{4,4,0}": g220**2, "b_{4,4,0}": b220**2,
        "r_{4,3,0}": 2 * r220 * r210, "g_{4,3,0}": 2 * g220 * g210, "b_{4,3,0}": 2 * b220 * b210,
        "r_{4,2,0}": 2 * r220 * g220 + r210**2, "g_{4,2,0}": 2 * g220 * b220 + g210**2,
        "b_{4,2,0}": 2 * r220 * b220 + b210**2,
        "r_{4,1,0}": 2 * r210 * g220, "g_{4,1,0}": 2 * g210 * b220, "b_{4,1,0}": 2 * r220 * b210,
        "r_{4,3,1}": 2 * r220 * r211 + r220**2 * g210 * sin_a + 2 * (1 + r220 * c**2) * r210 * b210 * s,
        "g_{4,3,1}": 2 * r211 * g220 + 2 * r210 * (1 + g220 * c**2) * g210 * s + g220**2 * b210 * sin_a,
        "b_{4,3,1}": 2 * r211 * b220 + r210 * b220**2 * sin_a + 2 * g210 * (1 + b220 * c**2) * b210 * s,
        "r_{4,2,1}": (2 * r210 * r211 + r220 * r210 * g210 * tan_h + r210**2 * g210 * s
                      + r210 * b210**2 * s + r210 * g220 * b210 * tan_h),
        "g_{4,2,1}": (2 * r211 * g210 + r210 * g210**2 * s + r210 * g210 * b220 * tan_h
                      + g220 * g210 * b210 * tan_h + g210**2 * b210 * s),
        "b_{4,2,1}": (2 * r211 * b210 + r220 * g210 * b210 * tan_h + r210 * b220 * b210 * tan_h
                      + r210**2 * b210 * s + g210 * b210**2 * s),
        "r_{4,2,2}": (r211**2 + 2 * r220 * g220 + 2 * r220 * b220 + 2 * g220 * b220 + 2 * r210 * g210
                      + 2 * r210 * b210 + 2 * g210 * b210),
    }
