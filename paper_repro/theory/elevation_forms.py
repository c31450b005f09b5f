"""Closed forms of the order-elevation matrices and the basis transformation (open questions of Section 7).

* Elevation: every function of T_{2n} is a combination of T_{2n+2}, ``f = sum_g M_{gf} g`` (span T_{2n} =
  H_n is contained in H_{n+1} = span T_{2n+2}); for the normalized systems T-bar_n = T-bar_{n+1} E with
  ``E_{gf} = x_f M_{gf} / x_g`` (x the normalizing coefficients, proven positive), so E >= 0 exactly when M >= 0.
* Transformation: T_{2n} = V_n N (the Fourier functions cos, sin(ru + gv + bw) of the paper) and
  V_n = T_{2n} N^{-1}; for the normalized basis V_n = T-bar M with ``M = diag(x)^{-1} N^{-1}`` and
  ``M^{-1} = N diag(x)``.

Entries are recovered and proven by :mod:`paper_repro.theory.matrix_forms`.
"""

from __future__ import annotations

from flint import fmpq, fmpq_mat

from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import collocate
from paper_repro.core.context import ExactContext, ModpContext, to_fmpq_mat
from paper_repro.core.domain import RationalPoints, rational_alpha, sample_rational_points
from paper_repro.core.fourier import evaluate_v
from paper_repro.core.labels import delta, exponent_matrix
from paper_repro.core.normalization import fixed_points
from paper_repro.theory.matrix_forms import prove_matrix_identity, recover_entries

PRIME = 2**31 - 1
T0 = fmpq(1, 3)


def _plane(n_points: int, order: int, seed: int) -> RationalPoints:
    tu, tv = fixed_points(order, n_points, seed)
    return RationalPoints(None, tu, tv, check=False)


def _solve(t: fmpq, basis, target, count: int, seed: int) -> fmpq_mat:
    alpha = rational_alpha(t)
    ctx = ExactContext()

    def system(k: int):
        pts = sample_rational_points(alpha, count + 3, seed=seed + k)
        return basis(alpha, pts, ctx), target(alpha, pts, ctx)

    return to_fmpq_mat(collocate(ctx, system, count, what="matrix closed forms").solution)


def _t_functions(n: int):
    return lambda a, p, c: evaluate(n, a, p, c)


def _v_functions(n: int):
    return lambda a, p, c: evaluate_v(n, a, p, c)


def _w_degree(n: int) -> int:
    e = exponent_matrix(n)
    return int((e[:, 4] + e[:, 5]).max())


def _rank_at(points: RationalPoints, values) -> int:
    a = values(rational_alpha(T0), points, ModpContext(p=PRIME))
    return ModpContext(p=PRIME).rank(a)


def closed_forms_and_proof(kind: str, n: int) -> dict:
    """``kind`` 'elevation' (M: T_{2n} -> T_{2n+2}) or 'transformation' (N: T_{2n} = V_n N, and N^{-1}).

    Returns the entry forms and the proof record(s)."""
    if kind == "elevation":
        basis, target, order = _t_functions(n + 1), _t_functions(n), n + 1
        r_basis, r_target = _w_degree(n + 1), _w_degree(n)
        pairs = [("M", basis, target, r_basis, r_target)]
    elif kind == "transformation":
        order = n
        pairs = [("N", _v_functions(n), _t_functions(n), 2 * n, _w_degree(n)),
                 ("N_inverse", _t_functions(n), _v_functions(n), _w_degree(n), 2 * n)]
    else:
        raise ValueError(f"kind must be 'elevation' or 'transformation', got {kind!r}")
    d = delta(order)
    out = {}
    for name, b, tg, rb, rt in pairs:
        forms = recover_entries(lambda t, b=b, tg=tg: _solve(t, b, tg, d, seed=21), K=3 * order,
                                max_degree=6 * order + 6)
        for seed in range(31, 41):  # a point set singular at t0 is replaced (the rank is what certifies it)
            pts = _plane(d, order, seed=seed)
            rank = _rank_at(pts, b)
            if rank == d:
                break

        def at(values, pts=pts):
            return lambda t: to_fmpq_mat(values(rational_alpha(t), pts, ExactContext()))

        proof = prove_matrix_identity(forms, at(b), at(tg), rb, rt)
        proof["points_rank_mod_p"] = rank
        proof["points_unisolvent"] = rank == d
        proof["proved"] = proof["proved"] and rank == d
        out[name] = {"forms": forms, "proof": proof}
    return out
