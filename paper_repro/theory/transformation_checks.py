"""Independent checks of the basis transformation for every n (:mod:`paper_repro.core.transformation`, Question 7.2).

The formula is proven by hand in docs/transformation_for_all_n.md.  The program checks it against computations that
do not use it:

* **exact solves** (:func:`solve_check`): at a rational-tangent alpha, collocation at delta_n alpha-independent plane
  points of small height (:func:`~paper_repro.core.normalization.fixed_points`), evaluated exactly (flint ``fmpq``)
  from the members' monomials (:mod:`paper_repro.core.basis`) and the Fourier functions
  (:mod:`paper_repro.core.fourier`), solved exactly (``fmpq_mat.solve``); the formula's matrix must equal the
  solution, and the identity must also hold at 3 further points.  Both directions: T X = V and V X = T;
* **recovered closed forms** (:func:`closed_form_check`): the entries (P(c) + s Q(c))/s^K that the modular recovery
  of :mod:`paper_repro.theory.elevation_forms` found and proved for n <= 4 (frozen in
  ``paper_repro/resources/transformation_closed_forms_recovered.json``); the formula, run symbolically over the ring
  Q[c, s]/(c^2 + s^2 - 1) (:class:`HalfAngle`), must give the same function for every entry -- a polynomial
  identity, so a proof for every alpha for those n.

:func:`formula_entry_forms` gives the formula's matrices as :class:`~paper_repro.theory.matrix_forms.EntryForm`
(the format of ``data/basis_transformation/closed_forms_n*.json``).

>>> s, c = HalfAngle.s(), HalfAngle.c()
>>> s * s + c * c == HalfAngle.one()
True
"""

from __future__ import annotations

import json
from functools import cache, lru_cache
from importlib import resources

import numpy as np
from flint import fmpq, fmpq_mat, fmpq_poly

from paper_repro.core.basis import evaluate
from paper_repro.core.collocation import collocate_fmpq
from paper_repro.core.context import ExactContext, ModpContext, to_fmpq_mat
from paper_repro.core.domain import RationalAngle, RationalPoints
from paper_repro.core.fourier import evaluate_v
from paper_repro.core.labels import delta, united_system
from paper_repro.core.normalization import fixed_points
from paper_repro.core.transformation import expansion_matrix, scaled_theta, transformation_matrix, v_columns
from paper_repro.theory.matrix_forms import EntryForm, _reduce

ONE_MINUS_C2 = fmpq_poly([1, 0, -1])


class HalfAngle:
    """``P(c) + s Q(c)``: an element of Q[c, s]/(c^2 + s^2 - 1) (c = cos(alpha/2), s = sin(alpha/2)); the
    representation is unique, so ``==`` is equality of functions of alpha."""

    __slots__ = ("p", "q")

    def __init__(self, p: fmpq_poly, q: fmpq_poly | None = None):
        self.p, self.q = p, q if q is not None else fmpq_poly([])

    @classmethod
    def one(cls) -> HalfAngle:
        return cls(fmpq_poly([1]))

    @classmethod
    def c(cls) -> HalfAngle:
        return cls(fmpq_poly([0, 1]))

    @classmethod
    def s(cls) -> HalfAngle:
        return cls(fmpq_poly([]), fmpq_poly([1]))

    @staticmethod
    def _lift(x) -> HalfAngle:
        if isinstance(x, HalfAngle):
            return x
        if isinstance(x, (int, fmpq)):
            return HalfAngle(fmpq_poly([x]))
        return NotImplemented  # type: ignore[return-value]

    def __add__(self, o):
        o = self._lift(o)
        return NotImplemented if o is NotImplemented else HalfAngle(self.p + o.p, self.q + o.q)

    __radd__ = __add__

    def __neg__(self) -> HalfAngle:
        return HalfAngle(-self.p, -self.q)

    def __sub__(self, o):
        o = self._lift(o)
        return NotImplemented if o is NotImplemented else HalfAngle(self.p - o.p, self.q - o.q)

    def __rsub__(self, o):
        o = self._lift(o)
        return NotImplemented if o is NotImplemented else o - self

    def __mul__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return NotImplemented
        return HalfAngle(self.p * o.p + ONE_MINUS_C2 * self.q * o.q, self.p * o.q + self.q * o.p)

    __rmul__ = __mul__

    def __eq__(self, o) -> bool:
        o = self._lift(o)
        return o is not NotImplemented and self.p == o.p and self.q == o.q

    def __hash__(self) -> int:
        return hash((str(self.p), str(self.q)))

    def __repr__(self) -> str:
        return f"HalfAngle({self.p}, {self.q})"

    def times_s_power(self, k: int) -> HalfAngle:
        out = self
        for _ in range(k):
            out = out * HalfAngle.s()
        return out


def _form(x: HalfAngle, k: int) -> EntryForm:
    return _reduce(EntryForm(k, x.p, x.q))


@cache
def formula_entry_forms(n: int) -> dict[str, list[list[EntryForm]]]:
    """The formula's unnormalized matrices as closed forms in c and s: ``'N'`` (T = V N; rows V_n, columns T_{2n})
    and ``'N_inverse'`` (V = T N^{-1}; rows T_{2n}, columns V_n), each entry written with s^{3n} in the denominator
    and then reduced (:func:`~paper_repro.theory.matrix_forms._reduce`) -- the form the modular recovery used."""
    ctx = ExactContext()
    s, c = np.empty((), dtype=object), np.empty((), dtype=object)
    s[()], c[()] = HalfAngle.s(), HalfAngle.c()
    theta = v_columns(n, scaled_theta(n, s, c, ctx), ctx)  # s^{2n+j} theta
    big_n = expansion_matrix(n, s, c, ctx)
    d = delta(n)
    labels = united_system(n)

    def lift(x) -> HalfAngle:
        return HalfAngle._lift(x)

    n_inv = [[_form(lift(theta[f, v]).times_s_power(n - labels[f].j), 3 * n) for v in range(d)] for f in range(d)]
    n_fwd = [[_form(lift(big_n[v, f]).times_s_power(3 * n), 3 * n) for f in range(d)] for v in range(d)]
    return {"N": n_fwd, "N_inverse": n_inv}


def _same(a: EntryForm, b: EntryForm) -> bool:
    """Equality of (P + sQ)/s^K as functions: cross-multiplied in Q[c, s]/(c^2 + s^2 - 1)."""
    return (HalfAngle(a.P, a.Q).times_s_power(b.K) == HalfAngle(b.P, b.Q).times_s_power(a.K))


@cache
def recovered_closed_forms() -> dict[str, dict[str, list[list[EntryForm]]]]:
    """The closed forms recovered and proven by :func:`paper_repro.theory.elevation_forms.closed_forms_and_proof`
    (n = 1..4), frozen as a resource: ``{n: {'N': ..., 'N_inverse': ...}}``."""
    text = resources.files("paper_repro.resources").joinpath("transformation_closed_forms_recovered.json").read_text()
    raw = json.loads(text)

    def entry(e) -> EntryForm:
        return EntryForm(int(e[0]), fmpq_poly([fmpq(*map(int, x.split("/"))) if "/" in x else fmpq(int(x))
                                               for x in e[1]]),
                         fmpq_poly([fmpq(*map(int, x.split("/"))) if "/" in x else fmpq(int(x)) for x in e[2]]))

    return {n: {k: [[entry(e) for e in row] for row in m] for k, m in v.items()} for n, v in raw["forms"].items()}


def closed_form_check(n: int, forms: dict[str, list[list[EntryForm]]] | None = None) -> dict:
    """The formula's closed forms (:func:`formula_entry_forms`) against ``forms`` (default: the recovered ones) --
    equality of functions of alpha, entry by entry, both directions."""
    forms = forms if forms is not None else recovered_closed_forms()[str(n)]
    mine = formula_entry_forms(n)
    bad = {k: sum(1 for r1, r2 in zip(mine[k], forms[k]) for a, b in zip(r1, r2) if not _same(a, b))
           for k in ("N", "N_inverse")}
    return {"ok": not any(bad.values()), "mismatches": bad, "entries": 2 * delta(n) ** 2}


def _points(n: int, count: int, seed: int) -> RationalPoints:
    tu, tv = fixed_points(n, count, seed)
    return RationalPoints(None, tu, tv, check=False)


@lru_cache(maxsize=2)
def _values(n: int, alpha: RationalAngle, sd: int) -> tuple[np.ndarray, np.ndarray]:
    """T_{2n} and V_n at the delta_n + 3 plane points of seed ``sd`` (exact object arrays: delta_n collocation rows,
    then 3 verification rows); kept for the other direction of :func:`solve_check`."""
    ctx = ExactContext()
    pts = _points(n, delta(n) + 3, sd)
    return evaluate(n, alpha, pts, ctx), evaluate_v(n, alpha, pts, ctx)


def solve_check(n: int, alpha: RationalAngle, direction: str, matrix=None, seed: int = 31) -> dict:
    """Exact collocation solve of ``direction`` ('V_to_T': T X = V, X = N^{-1}; 'T_to_V': V X = T, X = N) at
    delta_n plane points, verified at 3 more (:func:`~paper_repro.core.collocation.collocate_fmpq`), compared with
    ``matrix`` (default: the formula's unnormalized matrix, :func:`~paper_repro.core.transformation.
    transformation_matrix` with ``normalized=False``)."""
    d = delta(n)
    if matrix is None:
        matrix = transformation_matrix(n, alpha, direction, normalized=False)
    mine = to_fmpq_mat(np.asarray(matrix, dtype=object))

    def system(k: int):
        t_vals, v_vals = _values(n, alpha, seed + k)
        return (t_vals, v_vals) if direction == "V_to_T" else (v_vals, t_vals)

    try:
        res = collocate_fmpq(system, d, attempts=10, what=f"transformation {direction}, n = {n}")
    except ArithmeticError as exc:
        singular = "singular" in str(exc)
        return {"ok": False, "error": "10 singular point sets" if singular else str(exc),
                "verified_at_3_more": False}
    x = res.solution
    equal = x == mine
    mismatches = 0 if equal else sum(1 for i in range(d) for j in range(d) if x[i, j] != mine[i, j])
    return {"ok": bool(equal), "formula_equals_solve": bool(equal), "verified_at_3_more": True,
            "mismatches": mismatches, "seed": seed + res.point_set}


def unisolvent_mod_p(n: int, seed: int = 31, prime: int = 2_147_483_629) -> bool:
    """Whether the first plane point set of :func:`solve_check` is unisolvent for T_{2n} at tan(alpha/4) = 1/3
    (rank modulo a prime; used by the tests to confirm the solve is not a least-squares artefact)."""
    from paper_repro.core.domain import rational_alpha

    ctx = ModpContext(p=prime)
    vals = evaluate(n, rational_alpha(fmpq(1, 3)), _points(n, delta(n), seed), ctx)
    return ctx.rank(vals) == delta(n)


def forms_as_json(forms: list[list[EntryForm]]) -> list[list[list]]:
    """Compact JSON of closed forms: ``[K, P, Q]`` per entry (ascending coefficients as strings)."""
    return [[[e.K, [str(x) for x in e.P.coeffs()] or ["0"], [str(x) for x in e.Q.coeffs()] or ["0"]] for e in row]
            for row in forms]


def matrix_product_is_identity(n: int, alpha: RationalAngle) -> bool:
    """M^{-1} M = I exactly for the normalized matrices of both directions (a consistency check, not independent)."""
    a = to_fmpq_mat(np.asarray(transformation_matrix(n, alpha, "V_to_T"), dtype=object))
    b = to_fmpq_mat(np.asarray(transformation_matrix(n, alpha, "T_to_V"), dtype=object))
    d = delta(n)
    return b * a == fmpq_mat(d, d, [fmpq(int(i == j)) for i in range(d) for j in range(d)])


__all__ = ["HalfAngle", "formula_entry_forms", "recovered_closed_forms", "closed_form_check", "solve_check",
           "unisolvent_mod_p", "forms_as_json", "matrix_product_is_identity"]
