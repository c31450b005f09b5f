"""The constrained trivariate Fourier system V_n^alpha (Section sec:coincidence).

* ``E_n = {r u + g v + b w : 0 <= r, g, b <= n}``, stored as triples ``(r, g, b)``;
* the relation of Definition equivalence_relation_definition, transcribed verbatim
  (:func:`related`): equivalence_conditions_1 (sums equal to a common z) or equivalence_conditions_2
  (differences equal to a common z), z in {-n, ..., 2n};
* quotient sets by union-find over the relation (the transitive closure; whether the relation is
  already transitive is reported by :func:`is_transitive`);
* V_n by Proposition iterative_construction_of_trivariate_extension: 1 and cos, sin of one
  representative of each new class, evaluated in any arithmetic of :mod:`paper_repro.arith`
  (cos and sin of integer combinations of u, v, w are polynomials in the half-angle values, so they
  are exact rationals at rational points).
"""

from __future__ import annotations

from functools import cache
from itertools import product

import mpmath
import numpy as np

from .arith import Arith, get_arith
from .domain import half_angle_values
from .validation import check_n

Triple = tuple[int, int, int]


def E(n: int) -> list[Triple]:
    """E_n as triples (r, g, b), 0 <= r, g, b <= n, lexicographic order."""
    return list(product(range(n + 1), repeat=3))


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


def is_transitive(n: int) -> bool:
    """Whether ~ restricted to E_n is transitive (then the classes are exactly the relation's)."""
    for cl in classes(n):
        members = sorted(cl)
        if not all(related(a, b, n) or a == b for a in members for b in members):
            return False
    return True


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


def evaluate_v(n: int, alpha, points, arith: str | Arith = "float", *, dps: int = 50) -> np.ndarray:
    """Values of V_n^alpha at ``points`` (``(P, 3)`` real points or :class:`RationalPoints`): ``(P, delta_n)``.

    Uses only ring operations on the half-angle values: cos x = c^2 - s^2, sin x = 2 s c for x = u, v, w,
    then complex multiplication for the integer combination.
    """
    ar = get_arith(arith, dps=dps)
    ctx = mpmath.workdps(dps) if ar.name == "mp" else _null()
    with ctx:
        su, cu, sv, cv, sw, cw = half_angle_values(points, alpha, ar)
        full = [(_sub(ar, ar.mul(cu, cu), ar.mul(su, su)), _add(ar, ar.mul(su, cu), ar.mul(su, cu))),
                (_sub(ar, ar.mul(cv, cv), ar.mul(sv, sv)), _add(ar, ar.mul(sv, cv), ar.mul(sv, cv))),
                (_sub(ar, ar.mul(cw, cw), ar.mul(sw, sw)), _add(ar, ar.mul(sw, cw), ar.mul(sw, cw)))]
        npts = len(su)
        cols = []
        for kind, t in v_system(n):
            re, im = ar.ones((npts,)), _sub(ar, ar.ones((npts,)), ar.ones((npts,)))
            for var, power in enumerate(t):
                for _ in range(power):
                    c, s = full[var]
                    re, im = _sub(ar, ar.mul(re, c), ar.mul(im, s)), _add(ar, ar.mul(re, s), ar.mul(im, c))
            cols.append(re if kind in ("1", "cos") else im)
        return np.stack(cols, axis=1)


class _null:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


def _add(ar: Arith, a, b):
    out = a + b
    return out % ar.p if ar.name == "modp" else out


def _sub(ar: Arith, a, b):
    out = a - b
    return out % ar.p if ar.name == "modp" else out
