"""Rank of collocation matrices: high precision (singular values) and exact (modulo a prime).

* :func:`mp_singular_values` -- mpmath SVD at a given precision;
* :func:`collocation_singular_values` -- the same for a normalized collocation matrix, memoised on disk (shared by a
  claim and a figure);
* :func:`ball_sigma_min_bound` -- certified lower bound of sigma_min (and upper bound of the
  condition number) from the inverse in flint ball arithmetic, used where mpmath SVD is slow;
* :func:`numeric_rank` -- rank by the gap criterion: sigma_i counts if ``sigma_i > sigma_1 * 10^-(dps-10)``
  (everything below is at the level of rounding of the working precision);
* :func:`modp_rank` -- exact rank over F_p (flint ``nmod_mat``); rank over F_p <= rank over Q, so full
  rank modulo p certifies full rank of the rational matrix.
"""

from __future__ import annotations

import mpmath
import numpy as np
from flint import arb, arb_mat, ctx

from paper_repro.core.context import ModpContext


def mp_singular_values(a: np.ndarray, dps: int) -> list[mpmath.mpf]:
    """Singular values (descending) of an object array of mpf, at ``dps`` digits."""
    with mpmath.workdps(dps):
        s = mpmath.svd_r(mpmath.matrix(a.tolist()), compute_uv=False)
        return sorted((s[k] for k in range(len(s))), reverse=True)


def _exact_pairs(count: int):
    """A validator of stored singular values: ``count`` pairs ``[mantissa as decimal text, exponent]``."""
    def check(value) -> str | None:
        if not isinstance(value, list) or len(value) != count:
            return f"not a list of {count} singular values"
        for m, e in value:
            if not isinstance(m, str) or not m.lstrip("-").isdigit() or isinstance(e, bool) or not isinstance(e, int):
                return f"{[m, e]!r} is not [mantissa text, integer exponent]"
        return None

    return check


def collocation_singular_values(n: int, alpha_text: str, dps: int, seed: int,
                                control: bool = False) -> list[mpmath.mpf]:
    """``mp_singular_values(collocation_mp(n, alpha_text, dps, seed, control), dps)``, memoised on disk: claim
    ``linear_independence`` and the figure ``singular_values`` ask for the same matrices (n <= 4 at alpha = pi/6 and
    5pi/6, 50 digits, seed 5), so a run computes them once.  Stored exactly (signed mantissa and exponent) and
    keyed by the code fingerprint as well as the parameters, so a stored value is the one this code computes.

    >>> from paper_repro.core.normalization import collocation_mp
    >>> fresh = mp_singular_values(collocation_mp(1, "pi/3", 30, 5), 30)
    >>> [s._mpf_ for s in collocation_singular_values(1, "pi/3", 30, 5)] == [s._mpf_ for s in fresh]
    True
    """
    from paper_repro.core.labels import delta
    from paper_repro.core.normalization import collocation_mp
    from paper_repro.util.cache import cached, code_fingerprint

    def compute() -> list[list]:
        sv = mp_singular_values(collocation_mp(n, alpha_text, dps, seed, control), dps)
        return [[str(-man if sign else man), int(exp)] for sign, man, exp, _ in (s._mpf_ for s in sv)]

    params = {"n": n, "alpha": alpha_text, "dps": dps, "seed": seed, "control": control, "code": code_fingerprint()}
    stored = cached("collocation_singular_values", params, compute, validate=_exact_pairs(delta(n)))
    with mpmath.workdps(dps):  # the working precision of the SVD: every stored mantissa fits, the values are exact
        return [mpmath.mpf((int(m), e)) for m, e in stored]


def numeric_rank(sv: list[mpmath.mpf], dps: int) -> int:
    """Gap criterion: singular values above ``sigma_1 * 10^-(dps - 10)``."""
    tau = sv[0] * mpmath.mpf(10) ** (-(dps - 10))
    return sum(1 for s in sv if s > tau)


def arb_matrix(a: np.ndarray) -> arb_mat:
    """The ``arb_mat`` of an object array of mpf (or integers), entry by entry exactly: flint takes an mpf's
    mantissa and exponent as they are, a ball of radius 0 (five times faster than through decimal strings).

    >>> x = -mpmath.mpf(1) / 3
    >>> m = arb_matrix(np.array([[x, 2]], dtype=object))
    >>> sign, man, exp, _ = x._mpf_
    >>> m[0, 0].rad() == 0 and m[0, 0].mid().man_exp() == (-man, exp), m[0, 1] == 2
    (True, True)
    """
    return arb_mat([[arb(x) for x in row] for row in a])


def ball_sigma_min_bound(a: np.ndarray, dps: int) -> tuple[mpmath.mpf, mpmath.mpf]:
    """Certified ``(lower bound of sigma_min, upper bound of the 2-norm condition number)``.

    Ball arithmetic (flint ``arb_mat.inv``): ``sigma_min = 1/||A^-1||_2 >= 1/||A^-1||_F`` and
    ``kappa_2 <= ||A||_F ||A^-1||_F``.  Entries are taken exactly (:func:`arb_matrix`: the enclosure is for the
    ``dps``-digit matrix ``a`` itself).  ``ZeroDivisionError`` if the inverse cannot be certified.
    """
    old = ctx.prec
    ctx.prec = int(3.4 * dps) + 64
    try:
        m = arb_matrix(a)
        inv = m.inv()
        rows, cols = a.shape
        fro_inv = sum((inv[i, j] ** 2 for i in range(rows) for j in range(cols)), arb(0)).sqrt()
        fro = sum((m[i, j] ** 2 for i in range(rows) for j in range(cols)), arb(0)).sqrt()
        lower = (1 / fro_inv).lower()
        kappa = (fro * fro_inv).upper()
        with mpmath.workdps(dps):
            return mpmath.mpf(lower.str(dps, radius=False)), mpmath.mpf(kappa.str(dps, radius=False))
    finally:
        ctx.prec = old


def modp_rank(a: np.ndarray, p: int) -> int:
    """Exact rank over F_p of an int64 array with entries in [0, p) (a lower bound of the rank over Q)."""
    return ModpContext(p=p).rank(a)

