"""Lemma lem:sign_cos_power_derivative and Proposition derivative_cosine_sine as printed: the sign rules of the
derivatives at 0, read from the transcriptions of eqs. sign_cos_power_derivative, sign_sin_power_derivative and
derivative_cosine_sine_at_0 (:func:`paper_repro.printed.lines.sec3_read.read_sign_function`), never retyped.
``None`` where the printed case analysis gives no single value (no branch applies, or branches that apply
disagree)."""

from __future__ import annotations

from paper_repro.printed.lines import verbatim
from paper_repro.printed.lines.sec3_read import read_sign_function, sign_of


def printed_sign_cos(i: int, p: int) -> int | None:
    """eq. sign_cos_power_derivative at (i, p), as printed."""
    return sign_of(read_sign_function(verbatim("sec1_3-sign-cos")), i=i, p=p)


def printed_sign_sin(j: int, p: int) -> int | None:
    """eq. sign_sin_power_derivative at (j, p), as printed."""
    return sign_of(read_sign_function(verbatim("sec1_3-sign-sin")), j=j, p=p)


def printed_sign_m(j: int, z: int, i: int = 1) -> int | None:
    """eq. derivative_cosine_sine_at_0 at (j, z), as printed (its branches do not name i)."""
    return sign_of(read_sign_function(verbatim("sec1_3-proposition-M")), i=i, j=j, z=z)
