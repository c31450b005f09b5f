"""Arithmetics in which the formulas of the package are evaluated.

One formula, several arithmetics: the evaluators only ever *multiply* values (the basis
functions are monomials in half-angle sines and cosines), so an arithmetic is a way to hold an
array of numbers and to multiply two such arrays.

* ``float`` -- numpy float64, vectorised over many points;
* ``mp`` -- mpmath at a chosen precision (numpy object arrays of ``mpf``);
* ``exact`` -- exact rationals, python-flint ``fmpq`` (numpy object arrays);
* ``modp`` -- integers modulo a prime ``p < 2**31`` (numpy int64, reduced after each product);
  the image of an exact computation, used for fast exact rank certificates.
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np
from flint import arb, fmpq, fmpq_mat, nmod_mat

#: Default prime for modular computations (the Mersenne prime 2^31 - 1).
DEFAULT_PRIME = 2_147_483_647


@dataclass(frozen=True)
class Arith:
    """Base class; subclasses define how arrays are built and multiplied."""

    name: str = "float"

    def asarray(self, values) -> np.ndarray:
        return np.asarray(values, dtype=np.float64)

    def mul(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return a * b

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.ones(shape, dtype=np.float64)


@dataclass(frozen=True)
class FloatArith(Arith):
    name: str = "float"


@dataclass(frozen=True)
class ObjectArith(Arith):
    """Arithmetics on numpy object arrays of scalars; subclasses say how a scalar is made (``convert``)."""

    def convert(self, x):
        raise NotImplementedError

    def asarray(self, values) -> np.ndarray:
        out = np.empty(np.shape(values), dtype=object)
        flat = out.reshape(-1)
        for k, x in enumerate(np.asarray(values, dtype=object).reshape(-1)):
            flat[k] = self.convert(x)
        return out

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        out = np.empty(shape, dtype=object)
        out.fill(self.convert(1))
        return out


@dataclass(frozen=True)
class MpArith(ObjectArith):
    """mpmath arithmetic; ``dps`` decimal digits (applied by callers with ``mpmath.workdps``)."""

    name: str = "mp"
    dps: int = 50

    def convert(self, x):
        return mpmath.mpf(x)


@dataclass(frozen=True)
class ExactArith(ObjectArith):
    """Exact rational arithmetic with python-flint ``fmpq``."""

    name: str = "exact"

    def convert(self, x):
        return x if isinstance(x, fmpq) else fmpq(x)


@dataclass(frozen=True)
class BallArith(ObjectArith):
    """Ball arithmetic with python-flint ``arb`` (precision set by ``flint.ctx.prec``)."""

    name: str = "ball"

    def convert(self, x):
        return arb(x)


@dataclass(frozen=True)
class ModpArith(Arith):
    """Arithmetic modulo the prime ``p`` (``p < 2**31`` so products fit in int64)."""

    name: str = "modp"
    p: int = DEFAULT_PRIME

    def __post_init__(self) -> None:
        if not (2 < self.p < 2**31):
            raise ValueError(f"p must be a prime with 2 < p < 2**31, got {self.p}")

    def asarray(self, values) -> np.ndarray:
        return np.asarray(values, dtype=np.int64) % self.p

    def mul(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return (a * b) % self.p

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.ones(shape, dtype=np.int64)

    def from_fmpq(self, x: fmpq) -> int:
        """Image of a rational in F_p; ``ValueError`` if p divides its denominator."""
        q = int(x.q) % self.p
        if q == 0:
            raise ValueError(f"p = {self.p} divides the denominator of {x}; choose another prime")
        return int(x.p) * pow(q, -1, self.p) % self.p


def get_arith(arith: str | Arith = "float", *, dps: int = 50, p: int = DEFAULT_PRIME) -> Arith:
    """Arithmetic by name: ``'float'``, ``'mp'`` (``dps`` digits), ``'exact'``, ``'modp'`` (prime ``p``)."""
    if isinstance(arith, Arith):
        return arith
    table = {"float": lambda: FloatArith(), "mp": lambda: MpArith(dps=dps), "exact": lambda: ExactArith(),
             "modp": lambda: ModpArith(p=p)}
    if arith not in table:
        raise ValueError(f"arith must be one of {sorted(table)}, got {arith!r}")
    return table[arith]()


def power_table(x: np.ndarray, kmax: int, arith: Arith) -> np.ndarray:
    """Stack ``[x**0, x**1, ..., x**kmax]`` along a new first axis, using only ``arith.mul``."""
    table = [arith.ones(np.shape(x))]
    for _ in range(kmax):
        table.append(arith.mul(table[-1], x))
    return np.stack(table)


def to_fmpq_mat(a: np.ndarray) -> fmpq_mat:
    """2-D object array of ``fmpq`` to a flint matrix."""
    return fmpq_mat(a.shape[0], a.shape[1], [x for row in a for x in row])


def to_nmod_mat(a: np.ndarray, p: int) -> nmod_mat:
    """2-D int64 array (entries in [0, p)) to a flint ``nmod_mat``."""
    return nmod_mat(a.shape[0], a.shape[1], [int(x) for x in a.reshape(-1)], p)
