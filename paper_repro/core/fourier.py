"""The constrained trivariate Fourier system V_n^alpha (Section sec:coincidence).

* ``E_n = {r u + g v + b w : 0 <= r, g, b <= n}``, stored as triples ``(r, g, b)``;
* the relation of Definition equivalence_relation_definition, transcribed verbatim
  (:func:`related`): equivalence_conditions_1 (sums equal to a common z) or equivalence_conditions_2
  (differences equal to a common z), z in {-n, ..., 2n};
* quotient sets by union-find over the relation (the transitive closure; whether the relation is
  already transitive is reported by :func:`is_transitive`);
* V_n by Proposition iterative_construction_of_trivariate_extension: 1 and cos, sin of one
  representative of each new class, evaluated in any arithmetic of :mod:`paper_repro.core.context`
  (cos and sin of integer combinations of u, v, w are polynomials in the half-angle values, so they
  are exact rationals at rational points).
"""

from __future__ import annotations

from functools import cache
from itertools import product

import numpy as np

from paper_repro.core.context import Context, get_context
from paper_repro.core.domain import half_angle_values
from paper_repro.util.validation import check_n

Triple = tuple[int, int, int]


def E(n: int) -> list[Triple]:
    """E_n as triples (r, g, b), 0 <= r, g, b <= n, lexicographic order."""
    return [(r, g, b) for r, g, b in product(range(n + 1), repeat=3)]


def related(a: Triple, b: Triple, n: int) -> bool:
    """Definition equivalence_relation_definition: exists z in {-n..2n} with
    (r2+r1 = g2+g1 = b2+b1 = z) or (r2-r1 = g2-g1 = b2-b1 = z)."""
    s = {a[k] + b[k] for k in range(3)}
    d = {b[k] - a[k] for k in range(3)}
    return (len(s) == 1 and -n <= s.pop() <= 2 * n) or (len(d) == 1 and -n <= d.pop() <= 2 * n)


def partners(a: Triple, n: int) -> list[Triple]:
    """All b in E_n with a ~ b: b = a + z(1,1,1) (condition 2) or b = z(1,1,1) - a (condition 1)."""
    lo, hi = min(a), max(a)
    out = [(a[0] + z, a[1] + z, a[2] + z) for z in range(max(-n, -lo), min(2 * n, n - hi) + 1)]
    out += [(z - a[0], z - a[1], z - a[2]) for z in range(max(-n, hi), min(2 * n, n + lo) + 1)]
    return out


@cache
def classes(n: int) -> tuple[frozenset[Triple], ...]:
    """E_n / ~ (classes of the transitive closure), ordered by their smallest element."""
    n = int(n)
    elems = E(n)
    parent = {e: e for e in elems}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a in elems:
        for b in partners(a, n):
            ra, rb = find(a), find(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    groups: dict[Triple, set[Triple]] = {}
    for e in elems:
        groups.setdefault(find(e), set()).add(e)
    return tuple(sorted((frozenset(g) for g in groups.values()), key=min))


def all_related(members, n: int) -> bool:
    """Whether every two members of a set of triples are related (:func:`related`) or equal: all pairs at once, with
    numpy arrays of the sums ``a + b`` and differences ``b - a``.

    >>> all_related([(1, 1, 1), (0, 0, 0)], 2), all_related([(1, 0, 0), (0, 0, 0)], 2)
    (True, False)
    """
    m = np.array(sorted(members), dtype=np.int64).reshape(-1, 3)  # (k, 3)
    ok = (m[:, None, :] == m[None, :, :]).all(axis=2)  # a == b
    for v in (m[:, None, :] + m[None, :, :], m[None, :, :] - m[:, None, :]):  # (k, k, 3)
        z = v[..., 0]
        ok |= (z == v[..., 1]) & (z == v[..., 2]) & (-n <= z) & (z <= 2 * n)
    return bool(ok.all())


def is_transitive(n: int) -> bool:
    """Whether ~ restricted to E_n is transitive (then the classes are exactly the relation's): within each class,
    every two members are related (:func:`all_related`).

    >>> is_transitive(3)
    True
    """
    return all(all_related(cl, n) for cl in classes(n))


def new_classes(n: int) -> list[frozenset[Triple]]:
    """Classes of E_n containing no element of E_{n-1} (the classes new at order n)."""
    return [cl for cl in classes(n) if all(max(e) == n for e in cl)]


def printed_representatives(n: int) -> list[Triple]:
    """Proposition iterative_construction_of_trivariate_extension, verbatim:
    {[0u+gv+nw]}_{g=0}^{n-1} u {[nu+0v+bw]}_{b=0}^{n-1} u {[ru+nv+0w]}_{r=0}^{n-1}."""
    return ([(0, g, n) for g in range(n)] + [(n, 0, b) for b in range(n)] + [(r, n, 0) for r in range(n)])


@cache
def v_system(n: int) -> tuple[tuple[str, Triple], ...]:
    """V_n as ``(kind, (r, g, b))`` with kind ``'1'``, ``'cos'``, ``'sin'``, built order by order."""
    n = check_n(n, "n") if n else 0
    out: list[tuple[str, Triple]] = [("1", (0, 0, 0))]
    for k in range(1, n + 1):
        for rep in printed_representatives(k):
            out += [("cos", rep), ("sin", rep)]
    return tuple(out)


def v_labels(n: int) -> list[str]:
    def arg(t: Triple) -> str:
        parts = [f"{c}{v}" if c != 1 else v for c, v in zip(t, "uvw") if c]
        return "+".join(parts) or "0"

    return ["1" if kind == "1" else f"{kind}({arg(t)})" for kind, t in v_system(n)]


def full_angles(half: list, ctx: Context) -> list[tuple]:
    """``[(cos u, sin u), (cos v, sin v), (cos w, sin w)]`` from the six half-angle values
    (``cos x = c^2 - s^2``, ``sin x = 2 s c``), in the context ``ctx``."""
    su, cu, sv, cv, sw, cw = half
    return [(ctx.sub(ctx.mul(c, c), ctx.mul(s, s)), ctx.add(ctx.mul(s, c), ctx.mul(s, c)))
            for s, c in ((su, cu), (sv, cv), (sw, cw))]


def cos_sin_combination(full: list[tuple], triple: Triple, ctx: Context, one) -> tuple:
    """``(cos, sin)`` of ``r u + g v + b w`` by complex multiplication of the full-angle values.

    ``full`` as returned by :func:`full_angles`; ``one`` is the context's 1 (scalar or array); negative
    multiples use the conjugate.  The single implementation of the recurrence.
    """
    re, im = one, ctx.sub(one, one)
    for (c, s), power in zip(full, triple):
        if power < 0:
            s, power = ctx.sub(ctx.sub(s, s), s), -power
        for _ in range(power):
            re, im = ctx.sub(ctx.mul(re, c), ctx.mul(im, s)), ctx.add(ctx.mul(re, s), ctx.mul(im, c))
    return re, im


def evaluate_v(n: int, alpha, points, arith: str | Context = "float", *, dps: int = 50) -> np.ndarray:
    """Values of V_n^alpha at ``points`` (``(P, 3)`` real points or :class:`RationalPoints`): ``(P, delta_n)``.

    Uses only ring operations on the half-angle values (:func:`full_angles`, :func:`cos_sin_combination`).
    """
    ctx = get_context(arith, dps=dps)
    half = half_angle_values(points, alpha, ctx)
    with ctx.scope():
        full = full_angles(half, ctx)
        one = ctx.ones((len(half[0]),))
        cols = []
        for kind, t in v_system(n):
            re, im = cos_sin_combination(full, t, ctx, one)
            cols.append(re if kind in ("1", "cos") else im)
        return np.stack(cols, axis=1)
