"""Arithmetic contexts: one formula, every arithmetic (in the spirit of mpmath's ``ctx_fp``/``ctx_mp``).

A context owns everything that depends on the arithmetic: how a number is made (``convert``,
``from_rational``), the ring operations on arrays (``add``, ``sub``, ``mul``, ``div``), ``sin``/``cos``
where they are meaningful, the half-angle values of points of Omega^alpha (the w formula is written
once, :meth:`Context.w_half`), a precision scope (:meth:`Context.scope`), and linear algebra with the
right library (:meth:`Context.solve`, :meth:`Context.rank`).  Modules below this one never compare
arithmetic names: they call the context they were given.

* :class:`FloatContext` (``'float'``) -- numpy float64, vectorised;
* :class:`MpContext` (``'mp'``) -- mpmath at its own ``dps`` (entered with :meth:`~Context.scope`);
* :class:`ExactContext` (``'exact'``) -- exact rationals, python-flint ``fmpq`` (``fmpq_mat`` solves);
* :class:`BallContext` (``'ball'``) -- python-flint ``arb`` balls at ``prec`` bits (``arb_mat`` solves);
* :class:`ModpContext` (``'modp'``) -- integers modulo a prime ``p < 2**31`` (``nmod_mat``): the image
  of an exact computation, used for fast exact rank certificates.

>>> ctx = get_context("exact")
>>> ctx.mul(ctx.asarray([1, 2]), ctx.asarray([fmpq(1, 3), fmpq(1, 4)])).tolist()
[1/3, 1/2]
>>> get_context("mp", dps=30).name, get_context("modp", p=7).p
('mp', 7)
>>> get_context("fast")
Traceback (most recent call last):
...
ValueError: arith must be one of ['ball', 'exact', 'float', 'modp', 'mp'] or a Context, got 'fast'
"""

from __future__ import annotations

import contextlib
import math
import numbers
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
from flint import arb, arb_mat, fmpq, fmpq_mat, fmpz_mat, nmod_mat
from flint import ctx as flint_ctx

from paper_repro.core.ordered import ordered_matmul

#: Default prime for modular computations (the Mersenne prime 2^31 - 1).
DEFAULT_PRIME = 2_147_483_647


def _to_fraction(x) -> Fraction:
    """Exact value of a rational-like scalar (int, Fraction, fmpq, float as its binary value, 'p/q')."""
    if isinstance(x, fmpq):
        return Fraction(int(x.p), int(x.q))
    if isinstance(x, str):
        return Fraction(x)
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"expected a number, got the boolean {x!r}")
    if isinstance(x, numbers.Rational):
        return Fraction(int(x.numerator), int(x.denominator))
    if isinstance(x, (numbers.Real, np.floating)):
        xf = float(x)
        if not math.isfinite(xf):
            raise ValueError(f"expected a finite number, got {xf}")
        return Fraction(xf)
    if isinstance(x, mpmath.mpf):
        if not mpmath.isfinite(x):
            raise ValueError(f"expected a finite number, got {x}")
        man, exp = x.man_exp
        return Fraction(int(man)) * Fraction(2) ** int(exp)
    raise TypeError(f"expected a rational or real number, got {type(x).__name__}")


def _unwrap(x):
    """numpy real scalars and 0-d arrays as Python numbers (mpmath and flint do not take numpy types)."""
    if isinstance(x, np.ndarray) and x.ndim == 0:
        x = x[()]
    if isinstance(x, np.longdouble):
        return float(x)
    if isinstance(x, (np.floating, np.integer)):
        return x.item()
    return x


@dataclass(frozen=True)
class Context:
    """Base class of the arithmetic contexts; the float64 behaviour is the default."""

    name: str = "float"
    #: ``True`` where values are exact images of rationals (exact, modp): such contexts take
    #: alpha and points through rational quarter-angle tangents and cannot evaluate sin/cos.
    exact: bool = False
    #: ``True`` where values are certified enclosures (ball): results must contain the true value.
    encloses: bool = False

    # --- numbers and arrays -------------------------------------------------------------------
    def convert(self, x):
        """One scalar of this arithmetic from a Python/numpy/mpmath/flint number."""
        return float(x)

    def from_rational(self, q: fmpq):
        """The scalar representing the exact rational ``q`` (as exactly as the arithmetic allows)."""
        return int(q.p) / int(q.q)

    def asarray(self, values) -> np.ndarray:
        return np.asarray(values, dtype=np.float64)

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.ones(shape, dtype=np.float64)

    def zeros(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.zeros(shape, dtype=np.float64)

    def add(self, a, b):
        return a + b

    def sub(self, a, b):
        return a - b

    def mul(self, a, b):
        return a * b

    def div(self, a, b):
        return a / b

    def dot(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Matrix product of two arrays of this arithmetic (float64: summed in a fixed order, the same bits on
        every CPU, :func:`~paper_repro.core.ordered.ordered_matmul`)."""
        if a.dtype == np.float64 and b.dtype == np.float64 and a.ndim == 2 and b.ndim == 2:
            return ordered_matmul(a, b)
        return a.dot(b)

    def to_float(self, a) -> np.ndarray:
        """Values as float64 (for plotting and comparisons)."""
        return np.asarray(a, dtype=np.float64)

    # --- transcendental functions ------------------------------------------------------------------
    def sin(self, a):
        return np.sin(a)

    def cos(self, a):
        return np.cos(a)

    # --- precision --------------------------------------------------------------------------------
    def scope(self):
        """Context manager in which this arithmetic's precision is in force (no-op where fixed)."""
        return contextlib.nullcontext(self)

    @property
    def digits(self) -> int:
        """Significant decimal digits of the arithmetic (``0`` for exact ones)."""
        return 16

    # --- half-angle values of points of Omega^alpha ----------------------------------------------
    @staticmethod
    def w_half(ctx: Context, sa, ca, su, cu, sv, cv):
        """``sin(w/2), cos(w/2)`` for ``w = alpha - u - v`` from the half-angle values of alpha, u, v.

        The angle-difference formulas, written once for every arithmetic::

            sin(w/2) = sin(a/2) cos((u+v)/2) - cos(a/2) sin((u+v)/2)
            cos(w/2) = cos(a/2) cos((u+v)/2) + sin(a/2) sin((u+v)/2)
        """
        c_uv = ctx.sub(ctx.mul(cu, cv), ctx.mul(su, sv))
        s_uv = ctx.add(ctx.mul(su, cv), ctx.mul(cu, sv))
        sw = ctx.sub(ctx.mul(sa, c_uv), ctx.mul(ca, s_uv))
        cw = ctx.add(ctx.mul(ca, c_uv), ctx.mul(sa, s_uv))
        return sw, cw

    def alpha_half(self, alpha):
        """``(sin(alpha/2), cos(alpha/2))`` as scalars of this arithmetic.

        ``alpha`` is a :class:`~paper_repro.core.domain.RationalAngle` (exact half-angle values) or,
        in the real arithmetics, a number.
        """
        sh = getattr(alpha, "sin_half", None)
        if sh is not None:
            return self.from_rational(sh), self.from_rational(alpha.cos_half)
        if self.exact:
            raise TypeError(f"arith {self.name!r} needs alpha as a RationalAngle (rational tan(alpha/4)), "
                            f"got {type(alpha).__name__}")
        half = self.div(self.convert(alpha), self.convert(2))
        return self.sin(half), self.cos(half)

    # --- linear algebra ---------------------------------------------------------------------------
    def solve(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Solution ``X`` of ``A X = B``: square systems exactly solved (``ZeroDivisionError`` if singular),
        overdetermined ones in the least-squares sense (float only)."""
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        if a.shape[0] != a.shape[1]:
            return np.linalg.lstsq(a, b, rcond=None)[0]
        try:
            return np.linalg.solve(a, b)
        except np.linalg.LinAlgError as exc:
            raise ZeroDivisionError(f"singular matrix: {exc}") from None

    def rank(self, a: np.ndarray) -> int:
        """Rank of ``a`` (numerical rank by SVD for the real arithmetics)."""
        return int(np.linalg.matrix_rank(np.asarray(a, dtype=np.float64)))

    def residual_ok(self, residual: np.ndarray, scale: float) -> bool:
        """Whether a verification residual is zero up to rounding amplified by the conditioning of the
        system: ``|r| <= scale 10^(-0.6 digits)`` (``scale`` = the size of the terms, ``|A| |x|``); an
        identity that does not hold leaves a residual of the order of ``scale``."""
        r = float(np.max(np.abs(self.to_float(residual)))) if np.size(residual) else 0.0
        return r <= max(scale, 1e-300) * 10.0 ** (-0.6 * self.digits)


@dataclass(frozen=True)
class FloatContext(Context):
    name: str = "float"


@dataclass(frozen=True)
class ObjectContext(Context):
    """Arithmetics on numpy object arrays of scalars; subclasses say how a scalar is made."""

    def asarray(self, values) -> np.ndarray:
        src = np.asarray(values, dtype=object)
        out = np.empty(src.shape, dtype=object)
        flat = out.reshape(-1)
        for k, x in enumerate(src.reshape(-1)):
            flat[k] = self.convert(x)
        return out

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        out = np.empty(shape, dtype=object)
        out.fill(self.convert(1))
        return out

    def zeros(self, shape: tuple[int, ...]) -> np.ndarray:
        out = np.empty(shape, dtype=object)
        out.fill(self.convert(0))
        return out

    def to_float(self, a) -> np.ndarray:
        return np.vectorize(lambda x: float(x), otypes=[np.float64])(np.asarray(a, dtype=object))

    def _map(self, f, a):
        arr = np.asarray(a, dtype=object)
        return np.frompyfunc(f, 1, 1)(arr) if arr.ndim else f(arr.item())


@dataclass(frozen=True)
class MpContext(ObjectContext):
    """mpmath at ``dps`` decimal digits; computations run inside :meth:`scope`."""

    name: str = "mp"
    dps: int = 50

    def __post_init__(self) -> None:
        if isinstance(self.dps, bool) or not isinstance(self.dps, numbers.Integral) or not 5 <= self.dps <= 10_000:
            raise ValueError(f"dps must be an integer from 5 to 10000, got {self.dps!r}")

    def convert(self, x):
        x = _unwrap(x)
        if isinstance(x, fmpq):
            return self.from_rational(x)
        if isinstance(x, Fraction):
            return mpmath.mpf(x.numerator) / x.denominator
        if isinstance(x, arb):
            return mpmath.mpf(x.mid().str(self.dps + 5, radius=False))
        return mpmath.mpf(x)

    def from_rational(self, q: fmpq):
        return mpmath.mpf(int(q.p)) / int(q.q)

    def sin(self, a):
        return self._map(mpmath.sin, a)

    def cos(self, a):
        return self._map(mpmath.cos, a)

    def scope(self):
        return mpmath.workdps(self.dps)

    @property
    def digits(self) -> int:
        return self.dps

    def solve(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``a x = b`` (``b`` one or more columns) by ``mpmath.lu_solve``; a square ``a`` is factorized once for all
        columns (:func:`_lu_solve_columns`: the same operations as one ``lu_solve`` per column, the same bits)."""
        with self.scope():
            mat = mpmath.matrix(np.asarray(a, dtype=object).tolist())
            rhs = np.asarray(b, dtype=object)
            cols = rhs.reshape(rhs.shape[0], -1)
            rhs_cols = [mpmath.matrix(list(cols[:, j])) for j in range(cols.shape[1])]
            try:
                if mat.rows == mat.cols:
                    sols = _lu_solve_columns(mat, rhs_cols)
                else:
                    sols = [mpmath.lu_solve(mat, col) for col in rhs_cols]
            except ZeroDivisionError:
                raise ZeroDivisionError("singular matrix") from None
            out = np.array([[s[i] for s in sols] for i in range(mat.rows)], dtype=object)
            return out.reshape((mat.rows,) + rhs.shape[1:])

    def rank(self, a: np.ndarray) -> int:
        """Gap criterion on the singular values: those above ``sigma_1 10^-(dps-10)`` count."""
        with self.scope():
            s = mpmath.svd_r(mpmath.matrix(np.asarray(a, dtype=object).tolist()), compute_uv=False)
            sv = sorted((s[k] for k in range(len(s))), reverse=True)
            tau = sv[0] * mpmath.mpf(10) ** (-(self.dps - 10))
            return sum(1 for x in sv if x > tau)


def _lu_solve_columns(mat, cols: list) -> list:
    """``[mpmath.lu_solve(mat, col) for col in cols]`` for a square ``mat``, with one LU factorization instead of one
    per column: ``lu_solve`` raises the precision by 10 bits, copies ``mat`` and ``col``, factorizes the copy
    (``LU_decomp``, never cached across calls since the copy is new) and solves with ``L_solve`` and ``U_solve``;
    here the same steps, the factorization shared.  Same operations at the same precision: the same bits.

    >>> m = mpmath.matrix([[2, 1], [1, 3]])
    >>> cols = [mpmath.matrix([1, 2]), mpmath.matrix([mpmath.mpf(1) / 3, 5])]
    >>> all(x == y for c, s in zip(cols, _lu_solve_columns(m, cols)) for x, y in zip(mpmath.lu_solve(m, c), s))
    True
    """
    ctx = mpmath.mp
    prec = ctx.prec
    try:
        ctx.prec += 10
        lu, p = ctx.LU_decomp(ctx.matrix(mat).copy())
        return [ctx.U_solve(lu, ctx.L_solve(lu, ctx.matrix(col).copy(), p)) for col in cols]
    finally:
        ctx.prec = prec


@dataclass(frozen=True)
class ExactContext(ObjectContext):
    """Exact rational arithmetic with python-flint ``fmpq``."""

    name: str = "exact"
    exact: bool = True

    def convert(self, x):
        if isinstance(x, fmpq):
            return x
        if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
            return fmpq(int(x))
        f = _to_fraction(x)
        return fmpq(f.numerator, f.denominator)

    def from_rational(self, q: fmpq):
        return q

    def sin(self, a):
        raise TypeError("arith 'exact' has no sin/cos: give alpha and points through rational quarter-angle "
                        "tangents (RationalAngle, RationalPoints)")

    cos = sin

    @property
    def digits(self) -> int:
        return 0

    def solve(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        a, b = np.asarray(a, dtype=object), np.asarray(b, dtype=object)
        cols = b.reshape(b.shape[0], -1)
        x = to_fmpq_mat(a).solve(to_fmpq_mat(cols))  # ZeroDivisionError if singular
        out = np.array([[x[i, j] for j in range(x.ncols())] for i in range(x.nrows())], dtype=object)
        return out.reshape((a.shape[1],) + b.shape[1:])

    def rank(self, a: np.ndarray) -> int:
        return to_fmpq_mat(np.asarray(a, dtype=object)).rank()

    def residual_ok(self, residual: np.ndarray, scale: float) -> bool:
        return all(x == 0 for x in np.asarray(residual, dtype=object).reshape(-1))


@dataclass(frozen=True)
class BallContext(ObjectContext):
    """Ball arithmetic with python-flint ``arb`` at ``prec`` bits (entered with :meth:`scope`)."""

    name: str = "ball"
    encloses: bool = True
    prec: int = 200

    def __post_init__(self) -> None:
        if isinstance(self.prec, bool) or not isinstance(self.prec, numbers.Integral) or not 20 <= self.prec:
            raise ValueError(f"prec must be an integer >= 20 (bits), got {self.prec!r}")

    def convert(self, x):
        """``x`` as a ball containing it: exact for ints, floats (numpy float64 and longdouble too) and finite mpf
        (from the binary mantissa and exponent, ``arb((man, exp))``, whatever their precision); a ball of radius about
        2^-prec for fmpq and Fraction p/q.

        >>> import mpmath
        >>> x = mpmath.mpf(0.5) + mpmath.mpf(2) ** -100
        >>> ctx = BallContext(prec=60)
        >>> with ctx.scope():
        ...     b = ctx.convert(x)
        >>> b.is_exact(), b.man_exp() == x.man_exp
        (True, True)
        """
        if isinstance(x, np.ndarray) and x.ndim == 0:
            x = x[()]
        if isinstance(x, np.longdouble) and np.isfinite(x):
            num, den = x.as_integer_ratio()                  # den a power of two: exact
            return arb((num, 1 - den.bit_length()))
        x = _unwrap(x)
        if isinstance(x, arb):
            return x
        if isinstance(x, fmpq):
            return self.from_rational(x)
        if isinstance(x, mpmath.mpf):
            if not mpmath.isfinite(x):
                return arb(float(x))
            man, exp = x.man_exp
            return arb((int(man), int(exp)))                 # exact: man 2^exp at any precision
        if isinstance(x, Fraction):
            return arb(x.numerator) / x.denominator
        return arb(x)

    def from_rational(self, q: fmpq):
        return arb(int(q.p)) / int(q.q)

    def sin(self, a):
        return self._map(lambda x: x.sin(), a)

    def cos(self, a):
        return self._map(lambda x: x.cos(), a)

    @contextlib.contextmanager
    def scope(self):
        old = flint_ctx.prec
        flint_ctx.prec = self.prec
        try:
            yield self
        finally:
            flint_ctx.prec = old

    @property
    def digits(self) -> int:
        return int(self.prec / 3.33)

    def to_float(self, a) -> np.ndarray:
        return np.vectorize(lambda x: float(x.mid()), otypes=[np.float64])(np.asarray(a, dtype=object))

    def solve(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        a, b = np.asarray(a, dtype=object), np.asarray(b, dtype=object)
        cols = b.reshape(b.shape[0], -1)
        with self.scope():
            x = arb_mat(a.tolist()).solve(arb_mat(cols.tolist()))  # ZeroDivisionError if not certified
        out = np.array([[x[i, j] for j in range(x.ncols())] for i in range(x.nrows())], dtype=object)
        return out.reshape((a.shape[1],) + b.shape[1:])

    def rank(self, a: np.ndarray) -> int:
        """Certified full rank or ``ValueError``: a ball matrix has a rank only where it is certified."""
        a = np.asarray(a, dtype=object)
        if a.shape[0] == a.shape[1]:
            with self.scope():
                try:
                    arb_mat(a.tolist()).inv()
                    return a.shape[0]
                except ZeroDivisionError:
                    pass
        raise ValueError("ball arithmetic certifies full rank of square matrices only; use 'exact' or 'modp'")

    def residual_ok(self, residual: np.ndarray, scale: float) -> bool:
        bound = arb(max(scale, 1e-300)) * arb(10) ** (-int(0.6 * self.digits))
        return all(abs(x).upper() <= bound for x in np.asarray(residual, dtype=object).reshape(-1))


@dataclass(frozen=True)
class ModpContext(Context):
    """Arithmetic modulo the prime ``p`` (``p < 2**31`` so products fit in int64)."""

    name: str = "modp"
    exact: bool = True
    p: int = DEFAULT_PRIME

    def __post_init__(self) -> None:
        if isinstance(self.p, bool) or not isinstance(self.p, numbers.Integral) or not (2 < self.p < 2**31):
            raise ValueError(f"p must be a prime with 2 < p < 2**31, got {self.p!r}")
        from flint import fmpz

        if not fmpz(int(self.p)).is_prime():  # a composite modulus has zero divisors: ranks mod p would mean nothing
            raise ValueError(f"p must be a prime with 2 < p < 2**31, got the composite number {int(self.p)}")

    def convert(self, x):
        if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
            return int(x) % self.p
        f = _to_fraction(x)
        return self.from_rational(fmpq(f.numerator, f.denominator))

    def from_rational(self, q: fmpq) -> int:
        """Image of a rational in F_p; ``ValueError`` if p divides its denominator."""
        d = int(q.q) % self.p
        if d == 0:
            raise ValueError(f"p = {self.p} divides the denominator of {q}; choose another prime")
        return int(q.p) * pow(d, -1, self.p) % self.p

    def asarray(self, values) -> np.ndarray:
        src = np.asarray(values, dtype=object)
        if src.dtype != object or all(isinstance(x, (int, np.integer)) for x in src.reshape(-1)):
            return np.asarray(values, dtype=np.int64) % self.p
        return np.array([self.convert(x) for x in src.reshape(-1)], dtype=np.int64).reshape(src.shape)

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.ones(shape, dtype=np.int64)

    def zeros(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.zeros(shape, dtype=np.int64)

    def add(self, a, b):
        return (a + b) % self.p

    def sub(self, a, b):
        return (a - b) % self.p

    def mul(self, a, b):
        return (a * b) % self.p

    def div(self, a, b):
        inv = np.vectorize(lambda x: pow(int(x), -1, self.p), otypes=[np.int64])(b)
        return (a * inv) % self.p

    def dot(self, a, b):
        return (np.asarray(a, dtype=object).dot(np.asarray(b, dtype=object)) % self.p).astype(np.int64)

    def to_float(self, a):
        raise TypeError("values modulo p have no real value")

    def sin(self, a):
        raise TypeError("arith 'modp' has no sin/cos: give alpha and points through rational quarter-angle "
                        "tangents (RationalAngle, RationalPoints)")

    cos = sin

    @property
    def digits(self) -> int:
        return 0

    def solve(self, a, b):
        a, b = np.asarray(a), np.asarray(b)
        cols = b.reshape(b.shape[0], -1)
        x = to_nmod_mat(a, self.p).solve(to_nmod_mat(cols, self.p))
        out = np.array([int(v) for v in x.entries()], dtype=np.int64).reshape(x.nrows(), x.ncols())
        return out.reshape((a.shape[1],) + b.shape[1:])

    def rank(self, a) -> int:
        """Exact rank over F_p (a lower bound of the rank over Q of the rational matrix it images)."""
        return to_nmod_mat(np.asarray(a), self.p).rank()

    def residual_ok(self, residual, scale: float) -> bool:
        return not np.any(np.asarray(residual) % self.p)


@dataclass(frozen=True)
class LogContext(Context):
    """Non-negative reals by their natural logarithms, in float64: never overflows or underflows.

    ``add`` is ``log(e^a + e^b)`` (``numpy.logaddexp``), ``mul`` is ``a + b``; zero is ``-inf``.  Only sums
    and products of non-negative quantities are meaningful here (there is no ``sub``): it evaluates the
    all-n formula of the normalizing coefficients, whose terms are all non-negative, far beyond the range
    of float64 (relative error about ``eps * |log value|`` per operation).

    >>> ctx = LogContext()
    >>> float(np.exp(ctx.add(ctx.convert(2.0), ctx.mul(ctx.convert(3.0), ctx.convert(5.0)))))
    17.0
    """

    name: str = "log"

    def convert(self, x):
        x = float(x)
        if x < 0:
            raise ValueError(f"the log context holds non-negative numbers only, got {x}")
        return math.log(x) if x > 0 else -math.inf

    def from_rational(self, q: fmpq):
        if q < 0:
            raise ValueError(f"the log context holds non-negative numbers only, got {q}")
        if q == 0:
            return -math.inf
        return math.log(int(q.p)) - math.log(int(q.q))  # math.log takes big integers exactly

    def ones(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.zeros(shape, dtype=np.float64)

    def zeros(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.full(shape, -np.inf, dtype=np.float64)

    def asarray(self, values) -> np.ndarray:
        return np.vectorize(self.convert, otypes=[np.float64])(np.asarray(values, dtype=object))

    def add(self, a, b):
        return np.logaddexp(a, b)

    def sub(self, a, b):
        raise TypeError("the log context has no subtraction (it holds sums of non-negative terms)")

    def mul(self, a, b):
        return np.add(a, b)

    def div(self, a, b):
        return np.subtract(a, b)

    def dot(self, a, b):
        raise TypeError("the log context has no matrix product")

    def to_float(self, a) -> np.ndarray:
        return np.exp(np.asarray(a, dtype=np.float64))

    def sin(self, a):
        raise TypeError("the log context has no sin/cos")

    cos = sin


_NAMES = ("ball", "exact", "float", "modp", "mp")


def get_context(arith: str | Context = "float", *, dps: int = 50, p: int = DEFAULT_PRIME,
                prec: int | None = None) -> Context:
    """Context by name: ``'float'``, ``'mp'`` (``dps`` digits), ``'exact'``, ``'ball'`` (``prec`` bits,
    default ``3.33 dps + 20``), ``'modp'`` (prime ``p``); a :class:`Context` is returned as it is."""
    if isinstance(arith, Context):
        return arith
    if not isinstance(arith, str) or arith not in _NAMES:
        raise ValueError(f"arith must be one of {list(_NAMES)} or a Context, got {arith!r}")
    if arith in ("mp", "ball"):
        from paper_repro.util.limits import MAX_DPS, MIN_DPS, check_int

        dps = 50 if dps is None else dps  # None: the default precision
        dps = check_int(dps, "dps", MIN_DPS, MAX_DPS, why="decimal digits of the mp arithmetic")
    if arith == "float":
        return FloatContext()
    if arith == "mp":
        return MpContext(dps=dps)
    if arith == "exact":
        return ExactContext()
    if arith == "ball":
        return BallContext(prec=prec if prec is not None else int(3.33 * dps) + 20)
    return ModpContext(p=p)


def power_table(x: np.ndarray, kmax: int, ctx: Context) -> np.ndarray:
    """Stack ``[x**0, x**1, ..., x**kmax]`` along a new first axis, using only ``ctx.mul``."""
    table = [ctx.ones(np.shape(x))]
    for _ in range(kmax):
        table.append(ctx.mul(table[-1], x))
    return np.stack(table)


def to_fmpq_mat(a: np.ndarray) -> fmpq_mat:
    """2-D object array of rationals to a flint matrix."""
    a = np.asarray(a, dtype=object)
    return fmpq_mat(a.shape[0], a.shape[1], [x for row in a for x in row])


def to_nmod_mat(a: np.ndarray, p: int) -> nmod_mat:
    """2-D integer array (entries in [0, p)) to a flint ``nmod_mat``."""
    a = np.asarray(a)
    if a.size == 0:
        return nmod_mat(a.shape[0], a.shape[1], [], p)
    rows = a.tolist() if a.dtype.kind in "iu" else [[int(x) for x in row] for row in a]  # tolist: Python ints
    return nmod_mat(fmpz_mat(rows), p)  # python-flint fills an fmpz_mat faster than an nmod_mat from a list


# Backwards-compatible names (the first round called contexts "arithmetics").
Arith = Context
get_arith = get_context
