"""The index set of T_{2n}^alpha and the single map between paper labels and internal indices.

Every function of the joint system (eq. ``united_system``) is a monomial in the six half-angle
values ``sin(u/2), cos(u/2), sin(v/2), cos(v/2), sin(w/2), cos(w/2)``.  This module stores each
function as its paper label together with its exponent vector; every evaluator of the package
(:mod:`paper_repro.core.basis`) works from these exponent vectors, so the formulas of
eqs. ``R_system_leq_n``, ``R_system_geq_n`` are written exactly once, here.

Paper conventions (Section ``sec:RGB``):

* ``R_{2n,2n-i,j}`` with level ``j = 0..n`` and ``i = j..2n-j`` (eq. ``R_system``);
  for ``i <= n`` (eq. ``R_system_leq_n``)::

      R_{2n,2n-i,j}(u,v,w) = sin^{2n-i}(u/2) sin^i(w/2) cos^{i-j}(v/2) sin^j(v/2)

  and for ``i > n`` (eq. ``R_system_geq_n``)::

      R_{2n,2n-i,j}(u,v,w) = sin^i(w/2) sin^{2n-i}(u/2) cos^{2n-i-j}(v/2) sin^j(v/2).

* ``G_{...}(u,v,w) = R_{...}(w,u,v)`` and ``B_{...}(u,v,w) = R_{...}(v,w,u)`` (eq. ``G_system``,
  ``B_system``); the explicit G and B formulas printed in the paper are transcribed separately in
  :mod:`paper_repro.claims.symmetry` and compared with these.
* ``T_{2n}`` (eq. ``united_system``) keeps, for each colour, the levels ``j = 0..n-1`` with
  ``i = j..2n-1-j``, plus the centre ``R_{2n,n,n} = G_{2n,n,n} = B_{2n,n,n}``.

Internal order of ``T_{2n}`` (the one used for every matrix, vector and control net): first the
centre, then colours R, G, B; within a colour by level ``j`` ascending, then by ``i`` ascending.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

import numpy as np

from paper_repro.util.validation import check_n

COLORS = ("R", "G", "B")

#: Slots of an exponent vector: sin/cos of u/2, v/2, w/2.
SLOTS = ("sin u/2", "cos u/2", "sin v/2", "cos v/2", "sin w/2", "cos w/2")


@dataclass(frozen=True)
class BasisLabel:
    """One function of the systems R_{2n}, G_{2n}, B_{2n}.

    ``color`` is ``"R"``, ``"G"`` or ``"B"``; ``n`` the order; ``i`` and ``j`` the paper's running
    indices, so that the paper label is ``{color}_{2n,2n-i,j}``.
    """

    color: str
    n: int
    i: int
    j: int

    @property
    def first(self) -> int:
        """The middle index ``2n - i`` of the label."""
        return 2 * self.n - self.i

    @property
    def is_centre(self) -> bool:
        return self.i == self.n and self.j == self.n

    @property
    def name(self) -> str:
        """Label in the function's own colour, e.g. ``G_{4,2,2}`` for the centre seen as a G function."""
        return f"{self.color}_{{{2 * self.n},{self.first},{self.j}}}"

    @property
    def paper(self) -> str:
        """Paper label, e.g. ``R_{4,3,1}``; the centre is always written ``R_{2n,n,n}``."""
        color = "R" if self.is_centre else self.color
        return f"{color}_{{{2 * self.n},{self.first},{self.j}}}"

    @property
    def coefficient(self) -> str:
        """Paper name of the normalizing coefficient, e.g. ``r_{4,3,1}``."""
        return self.paper[0].lower() + self.paper[1:]

    @property
    def control_point(self) -> str:
        """Paper name of the control point, e.g. ``r_{4,3,1}`` (bold in the paper)."""
        return self.coefficient


def r_exponents(n: int, i: int, j: int) -> tuple[int, int, int, int, int, int]:
    """Exponents of ``R_{2n,2n-i,j}`` (eqs. R_system_leq_n, R_system_geq_n) in :data:`SLOTS`."""
    if not (0 <= j <= n and j <= i <= 2 * n - j):
        raise ValueError(f"(i, j) = ({i}, {j}) is not an index of R_{{2n}} for n = {n}")
    m = i if i <= n else 2 * n - i  # cos power of v/2 is m - j in both branches
    return (2 * n - i, 0, j, m - j, i, 0)


# Action of a permutation of the variables on exponent vectors.  A function F(u,v,w) composed
# with a substitution is again a monomial; ``_compose`` gives the exponents of
# F(x_{s[0]}, x_{s[1]}, x_{s[2]}) where x = (u, v, w).
def compose(exps: tuple[int, ...], s: tuple[int, int, int]) -> tuple[int, ...]:
    """Exponents of ``F(x[s[0]], x[s[1]], x[s[2]])`` given the exponents of ``F(u, v, w)``."""
    out = [0] * 6
    for slot in range(3):  # argument position of F
        target = s[slot]  # variable that is fed into that position
        out[2 * target] += exps[2 * slot]
        out[2 * target + 1] += exps[2 * slot + 1]
    return tuple(out)


#: G(u,v,w) = R(w,u,v) and B(u,v,w) = R(v,w,u): the arguments fed to R, as variable indices.
CYCLIC = {"R": (0, 1, 2), "G": (2, 0, 1), "B": (1, 2, 0)}


def exponents(label: BasisLabel) -> tuple[int, ...]:
    """Exponent vector of any R, G or B function, from the R formula and the cyclic rule."""
    return compose(r_exponents(label.n, label.i, label.j), CYCLIC[label.color])


def full_system(n: int, color: str) -> tuple[BasisLabel, ...]:
    """The full system ``R_{2n}``, ``G_{2n}`` or ``B_{2n}`` (eqs. R_system..B_system), (n+1)^2 labels."""
    if color not in COLORS:
        raise ValueError(f"color must be one of {list(COLORS)}, got {color!r}")
    return _full_system(check_n(n), color)


@cache
def _full_system(n: int, color: str) -> tuple[BasisLabel, ...]:
    return tuple(BasisLabel(color, n, i, j) for j in range(n + 1) for i in range(j, 2 * n - j + 1))


def united_system(n: int) -> tuple[BasisLabel, ...]:
    """The labels of ``T_{2n}`` (eq. united_system) in the package's internal order (``n`` is checked first, so an
    unhashable ``n`` gets the message of :func:`check_n`, not a TypeError of the cache)."""
    return _united_system(check_n(n))


@cache
def _united_system(n: int) -> tuple[BasisLabel, ...]:
    labels = [BasisLabel("R", n, n, n)]
    for color in COLORS:
        labels += [BasisLabel(color, n, i, j) for j in range(n) for i in range(j, 2 * n - j)]
    return tuple(labels)


@cache
def exponent_matrix(n: int) -> np.ndarray:
    """``(delta_n, 6)`` integer array: the exponent vectors of ``T_{2n}`` in internal order."""
    n = check_n(n)
    # the order of united_system: the centre, then per colour j = 0..n-1, i = j..2n-j-1 (vectorised; tested equal
    # to the labels' exponents)
    j, i = (np.concatenate([np.full(2 * n - 2 * jj, jj) for jj in range(n)]),
            np.concatenate([np.arange(jj, 2 * n - jj) for jj in range(n)]))
    m = np.where(i <= n, i, 2 * n - i)
    r = np.stack([2 * n - i, np.zeros_like(i), j, m - j, i, np.zeros_like(i)], axis=1)
    blocks = [np.array([r_exponents(n, n, n)], dtype=np.int64)]
    for color in COLORS:
        s = CYCLIC[color]
        out = np.zeros_like(r)
        for slot in range(3):  # as compose: argument ``slot`` of R is fed the variable s[slot]
            out[:, 2 * s[slot]:2 * s[slot] + 2] += r[:, 2 * slot:2 * slot + 2]
        blocks.append(out)
    arr = np.concatenate(blocks).astype(np.int64)
    arr.setflags(write=False)
    return arr


@cache
def variable_swap(n: int, a: int, b: int) -> np.ndarray:
    """The permutation ``pi`` of T_{2n}'s internal indices with ``f_{pi[k]}(x) = f_k(x with the variables a and b
    exchanged)`` (0 = u, 1 = v, 2 = w) for the monomials of :func:`exponent_matrix`: T_{2n} is invariant under
    every permutation of (u, v, w) (the cyclic rule and ``R_{2n,2n-i,j}(w, v, u) = R_{2n,i,j}(u, v, w)``);
    ``ValueError`` if an exchanged exponent vector were not in T_{2n}.

    >>> variable_swap(1, 0, 1).tolist(), variable_swap(1, 0, 2).tolist()
    ([0, 5, 4, 3, 2, 1, 6], [0, 3, 2, 1, 6, 5, 4])
    """
    if not (0 <= a <= 2 and 0 <= b <= 2 and a != b):
        raise ValueError(f"a and b must be two different variables among 0, 1, 2, got {a}, {b}")
    exps = exponent_matrix(n)
    index = {tuple(int(x) for x in row): k for k, row in enumerate(exps)}
    cols = list(range(6))
    cols[2 * a: 2 * a + 2], cols[2 * b: 2 * b + 2] = cols[2 * b: 2 * b + 2], cols[2 * a: 2 * a + 2]
    try:
        pi = np.array([index[tuple(int(x) for x in row)] for row in exps[:, cols]], dtype=np.int64)
    except KeyError as err:
        raise ValueError(f"T_{{{2 * n}}} is not invariant under exchanging variables {a} and {b}") from err
    pi.setflags(write=False)
    return pi


@cache
def index_of(n: int) -> dict[str, int]:
    """Map from paper label (``'R_{4,3,1}'``, also ``'r_{4,3,1}'``) to internal index in T_{2n}.

    Aliases are included: every label of the full systems R_{2n}, G_{2n}, B_{2n} that denotes
    the same function as a member of T_{2n} (e.g. ``R_{2n,0,0} = G_{2n,2n,0}``, the centre
    ``G_{2n,n,n}``) maps to that member's index.
    """
    by_exps = {exponents(lab): k for k, lab in enumerate(united_system(n))}
    out: dict[str, int] = {}
    for color in COLORS:
        for lab in full_system(n, color):
            k = by_exps[exponents(lab)]
            name = f"{color}_{{{2 * n},{lab.first},{lab.j}}}"
            out[name] = k
            out[name[0].lower() + name[1:]] = k
    return out


_LABEL_RE = re.compile(r"^([RGBrgb])_\{?(\d+),(\d+),(\d+)\}?$")


def parse_label(text: str) -> BasisLabel:
    """Parse ``'R_{4,3,1}'``, ``'g_{6,5,0}'`` or ``'R_4,3,1'`` into a :class:`BasisLabel`."""
    if not isinstance(text, str):
        raise TypeError(f"label must be a string like 'R_{{4,3,1}}', got {text!r} of type {type(text).__name__}")
    m = _LABEL_RE.match(text.strip())
    if not m:
        raise ValueError(f"label {text!r} is not of the form X_{{2n,2n-i,j}} with X in R, G, B")
    color, two_n, first, j = m.group(1).upper(), int(m.group(2)), int(m.group(3)), int(m.group(4))
    if two_n % 2 or two_n == 0:
        raise ValueError(f"label {text!r}: the first index must be 2n with n >= 1")
    n = two_n // 2
    lab = BasisLabel(color, n, two_n - first, j)
    r_exponents(n, lab.i, lab.j)  # validates the range
    return lab


def delta(n: int) -> int:
    """The printed dimension formula delta_n = 3n(n+1) + 1 (Theorem joint_systems_linear_independence)."""
    check_n(n)
    return delta_unchecked(n)


def delta_unchecked(n: int) -> int:
    """:func:`delta` for inner code whose ``n`` is already checked (a public function validates once)."""
    return 3 * n * (n + 1) + 1
