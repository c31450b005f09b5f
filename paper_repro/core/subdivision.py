"""Midpoint subdivision of triangular trigonometric patches (eq. triangular_trig_surface), for every n.

The midpoints of the edges of Omega^alpha cut it into four triangles.  Each is the image of Omega^{alpha/2}:

* the corner sub-triangles ``part = 'u'``, ``'v'``, ``'w'`` (the one at the vertex where u, v or w equals alpha) by a
  translation, e.g. ``(u, v, w) = (u' + alpha/2, v', w')`` for ``'u'``;
* the middle one (``part = 'middle'``) by the point reflection ``(u, v, w) = (alpha/2 - u', alpha/2 - v',
  alpha/2 - w')``: its vertex (0, alpha/2, alpha/2) is the image of the corner u' = alpha/2 of Omega^{alpha/2}.

The space V_n (cos and sin of r u + g v + b w, :mod:`paper_repro.core.fourier`) is invariant under both maps: the
frequency (r, g, b) goes to itself with a phase, r alpha/2 (translation of u) or (r + g + b) alpha/2 (reflection),
i.e. a 2 x 2 rotation block of its (cos, sin) pair.  Hence the restriction of an order-n patch with parameter alpha to
a sub-triangle is an order-n patch with parameter alpha/2, with the unique control net (T_{2n} is linearly
independent)

    Q = S P,    S = M_{alpha/2} Rot M_alpha^{-1},

with M_beta the V_n -> T-bar_{2n}^beta transformation of :func:`~paper_repro.core.transformation.transformation_matrix`
('V_to_T'; M_alpha^{-1} is its 'T_to_V') and Rot the block rotation.  The proof: docs/subdivision_for_all_n.md.

Arithmetic.  M_{alpha/2} has entries of size about 1/sin(alpha/4)^{2n} while S is bounded (about 1), so the product
above cancels: in float64 it loses every digit (measured: n = 4 at alpha = 0.1 has an error of 3e3; n = 6 at
alpha = 1 9e-5).  So ``'float'`` does not use it: it takes the *product route* of
:mod:`paper_repro.core.subdivision_products` (no solve, no M_alpha: the seven order-one restrictions by
substitution and the cotangent rules, then the products of Theorem P level by level; proof in
docs/subdivision_for_all_n.md, section 11), with an entrywise first-order error estimate (heuristic, a-posteriori)
and a measured error of at most a few units of 1e-15 against the certified route (entrywise for n <= 8 and at
n = 9, 10 against the exact S at a RationalAngle, tests/test_subdivision_speed.py; for n <= 20 only through the
sub-patch against the patch in mp, reports/subdivision_accuracy.md).  Below
alpha = 1e-100 the float route computes at 1e-100 (measured S(alpha) - S(1e-100) ~ alpha^2/32: about 1e-200 there).
``'mp'`` computes S = M_{alpha/2} Rot M_alpha^{-1} in ball arithmetic (python-flint ``arb``) at a precision raised
until every entry is certified to ``2^-(prec + 10)``, then rounds the midpoints (the reference the float route is
checked against; ``_certified_float_matrices`` does the same to 2^-60 and rounds to float64).  ``'ball'`` returns
the balls at the context's own precision (their radii say what is known).
``'exact'`` needs a :class:`~paper_repro.core.domain.RationalAngle` (rational tan(alpha/4), so s = sin(alpha/2) and
c = cos(alpha/2) are rational); cos(alpha/4) = sqrt((1 + c)/2) need not be rational, so the computation runs in the
field Q(sqrt((1 + c)/2)) (:class:`QuadNumber`) and the result is checked to be rational (it always was: S has entries
in Q(s, c), see the proof page), an object array of flint ``fmpq``.

>>> from paper_repro.core.domain import rational_alpha
>>> s = subdivision_matrix(1, rational_alpha("1/2"), "middle")
>>> [str(x) for x in s[0]]  # the middle sub-net's centre: -1/2 of the centre, a = 5/16, b = 3/16 (c = 3/5)
['-1/2', '5/16', '3/16', '5/16', '3/16', '5/16', '3/16']
>>> sum(s[0]) == 1
True
"""

from __future__ import annotations

import math
import threading
from collections import OrderedDict
from collections.abc import Callable
from fractions import Fraction
from functools import lru_cache
from typing import NamedTuple

import mpmath
import numpy as np
import scipy.sparse as sp
from flint import arb, arb_mat, fmpq, fmpq_mat, fmpz
from flint import ctx as flint_ctx

from paper_repro.core.context import (
    BallContext,
    Context,
    ExactContext,
    FloatContext,
    MpContext,
    get_context,
    to_fmpq_mat,
)
from paper_repro.core.domain import RationalAngle, open_alpha
from paper_repro.core.fourier import v_system
from paper_repro.core.labels import delta
from paper_repro.core.nets import check_net, check_net_exact
from paper_repro.core.subdivision_products import subdivision_matrices_float
from paper_repro.core.transformation import transformation_in_context
from paper_repro.util.limits import MAX_N_TRANSFORMATION, check_int

#: The four sub-triangles, in the order of :class:`SubNets`.
PARTS = ("u", "v", "w", "middle")
#: Largest order (the transformation's limit, :data:`~paper_repro.util.limits.MAX_N_TRANSFORMATION`).
MAX_N_SUBDIVISION = MAX_N_TRANSFORMATION
#: Bits to which the float64 route certifies every entry before rounding.
FLOAT_BITS = 60
#: Byte budget of the float matrix caches (the four S, one S, the stacked CSR, the CSR of each S; one budget for all):
#: at n = 30 one S is 62 MB, so entry counts alone (32 each) could hold about 8 GB.
FLOAT_CACHE_BYTES = 512 * 2**20
#: Largest ball precision tried (bits) before giving up.
MAX_PREC = 1 << 14
#: Largest depth of :func:`subdivide_to_depth` (4^k sub-nets).
MAX_DEPTH = 8


class SubNets(NamedTuple):
    """The four sub-nets of :func:`subdivide` (each a patch of the same order with parameter alpha/2): the corner
    sub-triangles at the vertices u = alpha, v = alpha, w = alpha, then the middle (point-reflected) one."""

    u: np.ndarray
    v: np.ndarray
    w: np.ndarray
    middle: np.ndarray


# --- the field Q(sqrt(d)) for the exact route ----------------------------------------------------------------------
class QuadNumber:
    """``a + b sqrt(d)`` with rational a, b and a fixed rational d > 0 (not checked to be a non-square: the
    representation is then not unique, and :func:`_rational_part` reports it).

    >>> r = QuadNumber(fmpq(0), fmpq(1), fmpq(2))
    >>> (r * r).a, (1 / r).b
    (2, 1/2)
    """

    __slots__ = ("a", "b", "d")

    def __init__(self, a, b, d):
        self.a, self.b, self.d = fmpq(a), fmpq(b), d

    def _lift(self, x) -> QuadNumber:
        return x if isinstance(x, QuadNumber) else QuadNumber(fmpq(x), fmpq(0), self.d)

    def __add__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        x = self._lift(x)
        return QuadNumber(self.a + x.a, self.b + x.b, self.d)

    __radd__ = __add__

    def __neg__(self):
        return QuadNumber(-self.a, -self.b, self.d)

    def __sub__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        return self + (-self._lift(x))

    def __rsub__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        return self._lift(x) - self

    def __mul__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        x = self._lift(x)
        return QuadNumber(self.a * x.a + self.d * self.b * x.b, self.a * x.b + self.b * x.a, self.d)

    __rmul__ = __mul__

    def __truediv__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        x = self._lift(x)
        norm = x.a * x.a - self.d * x.b * x.b
        if norm == 0:
            raise ZeroDivisionError("division by zero in Q(sqrt(d))")
        return self * QuadNumber(x.a / norm, -x.b / norm, self.d)

    def __rtruediv__(self, x):
        if isinstance(x, np.ndarray):
            return NotImplemented
        return self._lift(x) / self

    def __eq__(self, x) -> bool:
        x = self._lift(x)
        return self.a == x.a and self.b == x.b

    __hash__ = None  # type: ignore[assignment]

    def __float__(self) -> float:
        return float(self.a) + float(self.b) * math.sqrt(float(self.d))

    def __repr__(self) -> str:
        return f"QuadNumber({self.a}, {self.b}, {self.d})"


class QuadContext(ExactContext):
    """Exact arithmetic in Q(sqrt(d)) on numpy object arrays of :class:`QuadNumber` (only what the closed forms of
    :mod:`paper_repro.core.transformation` use: the ring operations and division)."""

    def __init__(self, d: fmpq):
        object.__setattr__(self, "d", d)

    def convert(self, x):
        if isinstance(x, QuadNumber):
            return x
        return QuadNumber(ExactContext.convert(self, x), fmpq(0), self.d)

    def from_rational(self, q: fmpq):
        return QuadNumber(q, fmpq(0), self.d)


def _split(a: np.ndarray) -> tuple[fmpq_mat, fmpq_mat]:
    """The rational and irrational parts of a matrix over Q(sqrt(d)) as two ``fmpq_mat``."""
    flat = a.reshape(-1)
    re = np.array([x.a for x in flat], dtype=object).reshape(a.shape)
    im = np.array([x.b for x in flat], dtype=object).reshape(a.shape)
    return to_fmpq_mat(re), to_fmpq_mat(im)


def _quad_matmul(x: np.ndarray, y: np.ndarray, d: fmpq) -> tuple[fmpq_mat, fmpq_mat]:
    """(A + B r)(C + D r) = (AC + d BD) + (AD + BC) r, r = sqrt(d), by four ``fmpq_mat`` products."""
    xa, xb = _split(x)
    ya, yb = _split(y)
    return xa * ya + (xb * yb) * d, xa * yb + xb * ya


def _fmpq_to_array(m: fmpq_mat) -> np.ndarray:
    return np.array([[m[i, j] for j in range(m.ncols())] for i in range(m.nrows())], dtype=object)


# --- the rotation of the Fourier coefficients --------------------------------------------------------------------
@lru_cache(maxsize=64)
def _pairs(n: int) -> tuple[tuple[int, tuple[int, int, int]], ...]:
    """``(k, rep)`` for each (cos, sin) pair of V_n's columns k, k + 1 (:func:`~paper_repro.core.fourier.v_system`)."""
    vs = v_system(n)
    out = []
    for k in range(1, len(vs), 2):
        (kc, rep), (ks, rep2) = vs[k], vs[k + 1]
        if kc != "cos" or ks != "sin" or rep != rep2:  # pragma: no cover - the layout of v_system
            raise AssertionError("V_n is not laid out as (cos, sin) pairs")
        out.append((k, rep))
    return tuple(out)


def _phase(rep: tuple[int, int, int], part: str) -> int:
    """The phase of the frequency ``rep`` in units of alpha/2: rep[variable] (translation), sum(rep) (middle)."""
    return sum(rep) if part == "middle" else rep["uvw".index(part)]


def rotate_rows(coeffs: np.ndarray, n: int, s, c, part: str, ctx: Context) -> np.ndarray:
    """``Rot @ coeffs``: the Fourier coefficients (rows in V_n's order) of the patch in the sub-triangle's own
    coordinates, from those in Omega^alpha's (``s``, ``c`` = sin, cos(alpha/2) in ``ctx``).

    Translation by alpha/2 in the variable x: cos(theta + phi) = cos(phi) cos(theta) - sin(phi) sin(theta) gives
    (a_c, a_s) -> (cos(phi) a_c + sin(phi) a_s, -sin(phi) a_c + cos(phi) a_s) with phi = rep_x alpha/2; the point
    reflection: cos(Phi - theta) and sin(Phi - theta) give (cos(Phi) a_c + sin(Phi) a_s, sin(Phi) a_c - cos(Phi) a_s)
    with Phi = (r + g + b) alpha/2.
    """
    out = coeffs.copy()
    top = 3 * n
    cos_m = [ctx.from_rational(fmpq(1))]
    sin_m = [ctx.from_rational(fmpq(0))]
    for _ in range(top):  # (c + i s)^m, in a fixed order
        cm, sm = cos_m[-1], sin_m[-1]
        cos_m.append(ctx.sub(ctx.mul(cm, c), ctx.mul(sm, s)))
        sin_m.append(ctx.add(ctx.mul(cm, s), ctx.mul(sm, c)))
    for k, rep in _pairs(n):
        m = _phase(rep, part)
        cp, sp = cos_m[m], sin_m[m]
        ac, as_ = coeffs[k], coeffs[k + 1]
        if part == "middle":
            out[k] = ctx.add(ctx.mul(cp, ac), ctx.mul(sp, as_))
            out[k + 1] = ctx.sub(ctx.mul(sp, ac), ctx.mul(cp, as_))
        else:
            out[k] = ctx.add(ctx.mul(cp, ac), ctx.mul(sp, as_))
            out[k + 1] = ctx.sub(ctx.mul(cp, as_), ctx.mul(sp, ac))
    return out


# --- validation -----------------------------------------------------------------------------------------------------
def check_part(part: object) -> str:
    """``part`` if it is one of :data:`PARTS`; ``TypeError``/``ValueError`` naming ``part`` otherwise."""
    if not isinstance(part, str):
        raise TypeError(f"part must be one of {list(PARTS)}, got {part!r} of type {type(part).__name__}")
    if part not in PARTS:
        raise ValueError(f"part must be one of {list(PARTS)}, got {part!r}")
    return part


def _check_n(n: object) -> int:
    return check_int(n, "n", 1, MAX_N_SUBDIVISION, why="the transformation's limit: dense delta_n x delta_n matrices")


_check_alpha = open_alpha  # one rule for alpha (core.domain)


def _context(arith, alpha, dps: int) -> Context:
    if arith is None:
        arith = "exact" if isinstance(alpha, RationalAngle) else "float"
    ctx = get_context(arith, dps=dps)
    if ctx.exact and not isinstance(alpha, RationalAngle):
        raise TypeError(f"arith {ctx.name!r} needs alpha as a RationalAngle (rational tan(alpha/4)), "
                        f"got {type(alpha).__name__}")
    if ctx.exact and type(ctx) is not ExactContext:
        raise ValueError(f"arith must be 'float', 'mp', 'exact' or 'ball' for subdivision, got {ctx.name!r}")
    return ctx


def half_alpha(alpha):
    """alpha/2 in the form alpha was given: a float or mpf halved; a :class:`RationalAngle` with tan(alpha/8)
    rational (i.e. 1 + tan^2(alpha/4) a rational square) as a RationalAngle, otherwise ``ValueError`` (alpha/2 has
    no rational quarter-angle tangent; the exact sub-nets still exist, :func:`subdivision_matrix`, but a second
    exact level needs this).

    >>> half_alpha(rational_alpha_of("3/4")).t
    1/3
    """
    alpha = _check_alpha(alpha)
    if isinstance(alpha, RationalAngle):
        t = alpha.t
        root = (1 + t * t).sqrt() if _is_square(1 + t * t) else None
        if root is None:
            raise ValueError(f"alpha/2 has no rational tan(alpha/8): 1 + tan^2(alpha/4) = {1 + t * t} is not a "
                             "rational square; choose tan(alpha/4) = 2pq/(q^2 - p^2) for exact repeated subdivision")
        return RationalAngle(t / (1 + root))
    return alpha / 2


def rational_alpha_of(t) -> RationalAngle:
    """Shorthand for :func:`~paper_repro.core.domain.rational_alpha` (doctests)."""
    from paper_repro.core.domain import rational_alpha

    return rational_alpha(t)


def _is_square(q: fmpq) -> bool:
    if q < 0:
        return False
    p, r = int(q.p), int(q.q)
    return math.isqrt(p) ** 2 == p and math.isqrt(r) ** 2 == r


# --- the four matrices in each arithmetic -----------------------------------------------------------------------------
def _exact_matrices(n: int, alpha: RationalAngle) -> tuple[np.ndarray, ...]:
    """The four S exactly (object arrays of fmpq) through Q(sqrt((1 + c)/2))."""
    s, c = alpha.sin_half, alpha.cos_half
    d = (1 + c) / 2  # cos^2(alpha/4)
    if _is_square(d):
        ctx: Context = ExactContext()
        c4 = d.sqrt()
        s4 = s / (2 * c4)
        conv = fmpq
    else:
        ctx = QuadContext(d)
        c4 = QuadNumber(fmpq(0), fmpq(1), d)
        s4 = QuadNumber(fmpq(0), s / (2 * d), d)  # sin(alpha/4) = s / (2 cos(alpha/4)) = s sqrt(d) / (2d)
        conv = ctx.from_rational

    def scal(x):
        out = ctx.zeros(())
        out[()] = x
        return out

    sc, cc = scal(conv(s)), scal(conv(c))
    tinv = transformation_in_context(n, sc, cc, ctx, "T_to_V")
    m2 = transformation_in_context(n, scal(s4), scal(c4), ctx, "V_to_T")
    out = []
    for part in PARTS:
        rot = rotate_rows(tinv, n, conv(s), conv(c), part, ctx)
        if isinstance(ctx, QuadContext):
            re, im = _quad_matmul(m2, rot, d)
            if any(im[i, j] != 0 for i in range(im.nrows()) for j in range(im.ncols())):
                raise ArithmeticError(f"subdivision ({part}) at n = {n}, tan(alpha/4) = {alpha.t}: an entry has an "
                                      "irrational part (the rationality of S failed)")
            mat = _fmpq_to_array(re)
        else:
            mat = _fmpq_to_array(to_fmpq_mat(m2) * to_fmpq_mat(rot))
        mat.setflags(write=False)
        out.append(mat)
    return tuple(out)


#: Extra bits of a rational alpha's ball above the working precision (as for a RationalAngle's 4 atan(t)): the
#: subdivision matrices at alpha / 2^k amplify alpha's radius, and must still be certified to 2^-prec.
RATIONAL_ALPHA_EXTRA_BITS = 1024


def _arb_of(alpha, prec: int | None = None) -> arb:
    """alpha as an arb containing it.  Exact for a float, an int and an mpf of any precision (binary rationals:
    ``arb((man, exp))`` keeps every bit of the mantissa, whatever flint's working precision); an fmpq or Fraction
    p/q is enclosed in a ball of radius about 2^-(``prec`` + :data:`RATIONAL_ALPHA_EXTRA_BITS`) (``prec`` default
    flint's current precision); an arb (a ball enclosing alpha, e.g. 4 atan(t) / 2^k for a RationalAngle halved k
    times) is kept as it is.  ``TypeError`` naming alpha for any other type (no silent rounding).

    >>> import mpmath
    >>> with mpmath.workdps(40):
    ...     a = _arb_of(mpmath.mpf(1) / 3)
    >>> a.is_exact(), a.man_exp()[0].bit_length() > 53
    (True, True)
    >>> b = _arb_of(fmpq(1, 3), 53)
    >>> (3 * b).contains(1), b.is_exact(), bool(b.rad() < arb(2) ** -1000)
    (True, False, True)
    """
    if isinstance(alpha, arb):
        return alpha
    if isinstance(alpha, mpmath.mpf):
        if not mpmath.isfinite(alpha):
            raise ValueError(f"alpha must be finite, got {alpha!r}")
        man, exp = alpha.man_exp
        return arb((int(man), int(exp)))
    if isinstance(alpha, (fmpq, Fraction)):
        p, q = (int(alpha.p), int(alpha.q)) if isinstance(alpha, fmpq) else (alpha.numerator, alpha.denominator)
        bits = (flint_ctx.prec if prec is None else prec) + RATIONAL_ALPHA_EXTRA_BITS
        old = flint_ctx.prec
        flint_ctx.prec = bits
        try:
            return arb(p) / q
        finally:
            flint_ctx.prec = old
    if isinstance(alpha, np.ndarray) and alpha.ndim == 0:
        return _arb_of(alpha[()], prec)
    if isinstance(alpha, np.longdouble):
        num, den = alpha.as_integer_ratio()              # den a power of two: exact
        return arb((num, 1 - den.bit_length()))
    if isinstance(alpha, (float, np.floating)):
        return arb(float(alpha))                         # exact (float16/32/64 are float64 values)
    if isinstance(alpha, (int, fmpz, np.integer)) and not isinstance(alpha, bool):
        return arb(int(alpha))
    raise TypeError(f"alpha must be a float, int, mpf, fmpq, Fraction or RationalAngle in ball arithmetic, got "
                    f"{type(alpha).__name__} {alpha!r}")


def _ball_matrices(n: int, alpha, prec: int) -> tuple[list[arb_mat], float]:
    """The four S as ``arb_mat`` at ``prec`` bits and the largest radius."""
    ctx = BallContext(prec=prec)
    with ctx.scope():
        if isinstance(alpha, RationalAngle):  # s, c rational; cos(alpha/4) = sqrt((1 + c)/2)
            s0, c0 = ctx.from_rational(alpha.sin_half), ctx.from_rational(alpha.cos_half)
            c4 = ((1 + c0) / 2).sqrt()
            s4 = s0 / (2 * c4)
        else:
            half = _arb_of(alpha) / 2
            s0, c0 = half.sin(), half.cos()
            s4, c4 = (half / 2).sin(), (half / 2).cos()
        s, c = _scalar(ctx, s0), _scalar(ctx, c0)
        tinv = transformation_in_context(n, s, c, ctx, "T_to_V")
        m2 = arb_mat(transformation_in_context(n, _scalar(ctx, s4), _scalar(ctx, c4), ctx, "V_to_T").tolist())
        mats, rad = [], 0.0
        for part in PARTS:
            mat = m2 * arb_mat(rotate_rows(tinv, n, s[()], c[()], part, ctx).tolist())
            rad = max(rad, max(float(mat[i, j].rad()) for i in range(mat.nrows()) for j in range(mat.ncols())))
            mats.append(mat)
    return mats, rad


def _scalar(ctx: Context, x):
    out = ctx.zeros(())
    out[()] = x
    return out


def start_precision(n: int, alpha: float, bits: int) -> int:
    """First ball precision tried: the bits wanted plus the bits the product loses, measured (float64 error of the
    direct product against the balls, n = 2, 4, 6 at alpha = 1e-3, 0.1, 1, 3) at about 6.6 n at alpha = 1 and
    3.6 n log2(1/alpha) as alpha -> 0, with a margin; :func:`_certified` raises it if the radii say so."""
    small = max(0.0, math.log2(1.0 / alpha))
    lost = 8 * n + 4 * n * small + 16
    return 64 * math.ceil((bits + lost + 32) / 64)


def _certified(n: int, alpha, bits: int) -> tuple[list[arb_mat], int]:
    """The four S as balls with every radius below 2^-bits: ``(matrices, precision used)``."""
    prec = start_precision(n, float(alpha), bits)
    while prec <= MAX_PREC:
        mats, rad = _ball_matrices(n, alpha, prec)
        if math.isfinite(rad) and rad <= 2.0 ** -bits:
            return mats, prec
        lost = prec if rad == 0 or not math.isfinite(rad) else prec + math.log2(rad)
        prec = max(prec + 64, 64 * math.ceil((lost + bits + 64) / 64))
    raise ArithmeticError(f"subdivision at n = {n}, alpha = {float(alpha)!r}: not certified to 2^-{bits} "
                          f"at {MAX_PREC} bits")


def _nbytes(value) -> int:
    """Bytes held by a cached value: numpy arrays, scipy CSR matrices, tuples of them."""
    if isinstance(value, tuple):
        return sum(_nbytes(v) for v in value)
    if isinstance(value, sp.csr_matrix):
        return value.data.nbytes + value.indices.nbytes + value.indptr.nbytes
    return int(value.nbytes)


class ByteBoundedCache:
    """A least-recently-used cache bounded by the bytes of its values: after an insertion the oldest entries are
    dropped until the total is at most ``budget`` or only the new entry is left (so it holds at most
    max(budget, the largest single value) bytes).  Thread-safe; a value is computed outside the lock.

    >>> c = ByteBoundedCache(100)
    >>> a = c.get("a", lambda: np.zeros(10)); b = c.get("b", lambda: np.zeros(10))  # 80 bytes each
    >>> list(c.keys()), c.nbytes
    (['b'], 80)
    """

    def __init__(self, budget: int) -> None:
        self.budget = budget
        self.nbytes = 0
        self._data: OrderedDict = OrderedDict()
        self._lock = threading.Lock()

    def get(self, key, compute: Callable[[], object]):
        with self._lock:
            if key in self._data:
                self._data.move_to_end(key)
                return self._data[key][0]
        value = compute()
        size = _nbytes(value)
        with self._lock:
            if key not in self._data:
                self._data[key] = (value, size)
                self.nbytes += size
            while self.nbytes > self.budget and len(self._data) > 1:
                _, (_, old) = self._data.popitem(last=False)
                self.nbytes -= old
        return value

    def keys(self) -> list:
        with self._lock:
            return list(self._data)

    def clear(self) -> None:
        with self._lock:
            self._data.clear()
            self.nbytes = 0


#: The float matrices of the product route, bounded by :data:`FLOAT_CACHE_BYTES`.
FLOAT_CACHE = ByteBoundedCache(FLOAT_CACHE_BYTES)


def _read_only(arrays):
    for arr in arrays:
        arr.setflags(write=False)
    return arrays


def _float_matrices(n: int, alpha: float) -> tuple[np.ndarray, ...]:
    """The four S in float64 by the product route (:mod:`paper_repro.core.subdivision_products`), read-only;
    cached in :data:`FLOAT_CACHE`."""
    return FLOAT_CACHE.get(("four", n, alpha), lambda: _read_only(subdivision_matrices_float(n, alpha)))


def _float_part(n: int, alpha: float, part: str) -> np.ndarray:
    """One S in float64 by the product route, read-only (the same values as ``_float_matrices(n, alpha)``)."""
    return FLOAT_CACHE.get(("part", n, alpha, part),
                           lambda: _read_only(subdivision_matrices_float(n, alpha, parts=(part,)))[0])


@lru_cache(maxsize=8)
def _certified_float_matrices(n: int, alpha: float) -> tuple[np.ndarray, ...]:
    """The four S from S = M_{alpha/2} Rot M_alpha^{-1} in ball arithmetic, every entry certified to 2^-60 before
    rounding to float64 (the reference of the float route: within 2^-60 plus half an ulp of the exact S; costs
    seconds from n = 8 on, ``tools/subdivision_accuracy.py``)."""
    mats, _ = _certified(n, alpha, FLOAT_BITS)
    out = []
    for mat in mats:
        # an entry whose ball contains 0 is within 2^-FLOAT_BITS of 0: 0.0 keeps the bound (and S's exact zeros)
        arr = np.array([[0.0 if mat[i, j].contains(0) else float(mat[i, j].mid()) for j in range(mat.ncols())]
                        for i in range(mat.nrows())])
        arr.setflags(write=False)
        out.append(arr)
    return tuple(out)


@lru_cache(maxsize=32)
def _exact_cached(n: int, alpha: RationalAngle) -> tuple[np.ndarray, ...]:
    return _exact_matrices(n, alpha)


def subdivision_matrices(n: int, alpha, arith: str | Context | None = None, *, dps: int = 50) -> tuple[np.ndarray, ...]:
    """The four matrices of :func:`subdivision_matrix` in the order of :data:`PARTS` (shared work: M_alpha^{-1} and
    M_{alpha/2} are built once)."""
    n = _check_n(n)
    alpha = _check_alpha(alpha)
    ctx = _context(arith, alpha, dps)
    if ctx.exact:
        return _exact_cached(n, alpha)
    if isinstance(ctx, BallContext):
        mats, _ = _ball_matrices(n, alpha, ctx.prec)
        return tuple(np.array(m.tolist(), dtype=object) for m in mats)
    if isinstance(ctx, MpContext):
        with ctx.scope():
            bits = mpmath.mp.prec + 10
            mats, _ = _certified(n, alpha, bits)
            return tuple(np.array([[mpmath.mpf(m[i, j].mid().str(int(bits / 3.3) + 5, radius=False))
                                    for j in range(m.ncols())] for i in range(m.nrows())], dtype=object)
                         for m in mats)
    return tuple(x.copy() for x in _float_matrices(n, float(alpha)))


def _shared(n: int, alpha, ctx: Context, dps: int) -> tuple[np.ndarray, ...]:
    """:func:`subdivision_matrices` without the copy of the cached float matrices (read-only; internal use)."""
    if isinstance(ctx, FloatContext):
        return _float_matrices(n, float(alpha))
    return subdivision_matrices(n, alpha, ctx, dps=dps)


def subdivision_matrix(n: int, alpha, part: str, arith: str | Context | None = None, *, dps: int = 50) -> np.ndarray:
    """The ``(delta_n, delta_n)`` matrix S with ``Q = S P``: Q is the control net, with parameter alpha/2, of the
    patch of control net P (parameter alpha, eq. triangular_trig_surface) restricted to the sub-triangle ``part``
    (``'u'``, ``'v'``, ``'w'``: the corner at that vertex; ``'middle'``), rows and columns in the order of
    :func:`~paper_repro.core.labels.united_system`.

    ``alpha``: a real number in (0, pi) or a :class:`~paper_repro.core.domain.RationalAngle`; ``arith``: ``'float'``
    (default for a real alpha; the product route, no solve; entrywise within 1.8e-15 of the certified value measured
    for n <= 8 and within its first-order error estimate, a heuristic a-posteriori estimate, in the tests; for
    9 <= n <= 20 measured through the sub-patch against the patch in mp (2.3e-16 of max |P|) and entrywise against
    the exact S at n = 9, 10 at one RationalAngle; docs/subdivision_for_all_n.md section 11), ``'mp'``
    (``dps`` digits, certified), ``'ball'`` (balls at the context's precision) or ``'exact'`` (default for a
    RationalAngle; flint ``fmpq``).  ``n`` from 1 to :data:`MAX_N_SUBDIVISION`.  Every row sums to 1 (partition
    of unity on both sides); S has negative entries (not a corner-cutting scheme, docs/subdivision_for_all_n.md).

    >>> import numpy as np
    >>> s = subdivision_matrix(2, 1.0, "u")
    >>> s.shape, bool(abs(s.sum(axis=1) - 1).max() < 1e-14)
    ((19, 19), True)
    """
    part = check_part(part)
    n = _check_n(n)
    alpha = _check_alpha(alpha)
    ctx = _context(arith, alpha, dps)
    if isinstance(ctx, FloatContext):  # only the matrix asked for (its recursion: the corners', or the middle's)
        return _float_part(n, float(alpha), part).copy()
    return subdivision_matrices(n, alpha, ctx, dps=dps)[PARTS.index(part)]


def _csr_apply(mat: sp.csr_matrix, net: np.ndarray) -> np.ndarray:
    """``mat @ net`` one coordinate at a time (scipy's ``csr_matvec``: each row summed in the order of its entries,
    a plain C loop, the same bits for every layout of ``net`` and every SIMD dispatch of numpy; faster than the
    multi-vector loop for d = 3)."""
    cols = np.ascontiguousarray(net.T)
    out = np.empty((mat.shape[0], net.shape[1]))
    for c in range(net.shape[1]):
        out[:, c] = mat @ cols[c]
    return out


def _apply(mat, net: np.ndarray) -> np.ndarray:
    if isinstance(mat, sp.csr_matrix):
        return _csr_apply(mat, net)
    if net.dtype == object and all(isinstance(x, fmpq) for x in mat.reshape(-1)[:1]):
        try:
            return _fmpq_to_array(to_fmpq_mat(mat) * to_fmpq_mat(net))
        except (TypeError, ValueError):
            pass
    return mat.dot(net)


def _checked_net(net, n: int, ctx: Context) -> np.ndarray:
    """The net validated (:func:`~paper_repro.core.nets.check_net`); exact entries as fmpq, mp/ball ones kept."""
    if ctx.exact:
        arr = check_net_exact(net, n)
        return np.array([[ExactContext().convert(x) for x in row] for row in arr], dtype=object)
    if isinstance(ctx, (MpContext, BallContext)):
        return check_net_exact(net, n)
    if isinstance(net, np.ndarray) and net.dtype.kind in "fiu" and net.ndim == 2:  # the fast path of a numeric array
        if net.shape[0] != delta(n) or net.shape[1] < 1:
            raise ValueError(f"net must have shape (delta_n, d) = ({delta(n)}, d) for n = {n}, got {net.shape}")
        arr = net.astype(np.float64)
        if not np.isfinite(arr).all():
            raise ValueError("net must be finite")
        return arr
    return check_net(net, n)


def subdivide(net, n: int, alpha, arith: str | Context | None = None, *, dps: int = 50) -> SubNets:
    """The four sub-nets ``SubNets(u, v, w, middle)`` of the patch with control net ``net`` (``(delta_n, d)`` array
    or ``{label: point}``): each is the control net, with parameter alpha/2 (:func:`half_alpha`), of the patch
    restricted to that sub-triangle (:func:`to_parent` maps its points).  Arithmetic as :func:`subdivision_matrix`
    (an exact net needs ``arith='exact'``, the default for a RationalAngle).

    >>> import numpy as np
    >>> from paper_repro.core.labels import delta
    >>> parts = subdivide(np.ones((delta(2), 3)), 2, 1.0)  # a constant patch stays constant
    >>> bool(all(abs(p - 1).max() < 1e-14 for p in parts))
    True
    """
    n = _check_n(n)
    alpha = _check_alpha(alpha)
    ctx = _context(arith, alpha, dps)
    arr = _checked_net(net, n, ctx)
    if isinstance(ctx, FloatContext):  # one sparse product with the four matrices stacked
        d = delta(n)
        out = _csr_apply(_stacked_float(n, float(alpha)), arr)
        return SubNets(*(out[k * d:(k + 1) * d] for k in range(4)))
    mats = _shared(n, alpha, ctx, dps)
    return SubNets(*(_apply(m, arr) for m in mats))


def _stacked_float(n: int, alpha: float) -> sp.csr_matrix:
    """The four float S stacked, ``(4 delta_n, delta_n)``, as a CSR matrix of the nonzero entries: its product with a
    net sums each row in the order of the columns (scipy's ``csr_matvecs``, a plain C loop: no BLAS; the same bits
    wherever it runs unfused, docs/subdivision_for_all_n.md section 11) and skips S's zeros (about 80 % of a corner
    matrix, 40 % of the middle one at n = 10)."""
    return FLOAT_CACHE.get(("stacked", n, alpha), lambda: sp.csr_matrix(np.vstack(_float_matrices(n, alpha))))


def _float_csr(n: int, alpha: float) -> tuple[sp.csr_matrix, ...]:
    return FLOAT_CACHE.get(("csr", n, alpha), lambda: tuple(sp.csr_matrix(m) for m in _float_matrices(n, alpha)))


def subdivide_to_depth(net, n: int, alpha, k: int, arith: str | Context | None = None, *, dps: int = 50
                       ) -> dict[tuple[str, ...], np.ndarray]:
    """``k`` levels of midpoint subdivision: ``{path: net}`` for the 4^k paths (tuples of :data:`PARTS`, the first
    part the sub-triangle of Omega^alpha, the next within it, ...); every net has parameter alpha / 2^k.  The
    scheme is non-stationary: level l uses S(n, alpha / 2^l).  ``k`` from 0 to :data:`MAX_DEPTH`.  In exact
    arithmetic every alpha / 2^l (l < k) must be a RationalAngle (:func:`half_alpha`).

    >>> import numpy as np
    >>> nets = subdivide_to_depth(np.eye(7)[:, :2], 1, 1.0, 2)
    >>> len(nets), sorted(nets)[0]
    (16, ('middle', 'middle'))
    """
    n = _check_n(n)
    alpha = _check_alpha(alpha)
    k = check_int(k, "k", 0, MAX_DEPTH, why="4^k sub-nets")
    ctx = _context(arith, alpha, dps)
    level: dict[tuple[str, ...], np.ndarray] = {(): _checked_net(net, n, ctx)}
    a = alpha
    for step in range(k):
        mats = _float_csr(n, float(a)) if isinstance(ctx, FloatContext) else _shared(n, a, ctx, dps)
        level = {path + (part,): _apply(m, arr) for path, arr in level.items() for part, m in zip(PARTS, mats)}
        if step + 1 < k:
            a = half_alpha(a)
    return level


def to_parent(points, alpha, part: str) -> np.ndarray:
    """Points ``(u', v', w')`` of Omega^{alpha/2} (an ``(P, 3)`` float or object array) mapped onto the sub-triangle
    ``part`` of Omega^alpha: ``(u' + alpha/2, v', w')`` (and likewise for 'v', 'w') or ``alpha/2 - (u', v', w')``
    ('middle').  ``alpha`` a number (its type is kept: mpf stays mpf).

    >>> to_parent([[0.5, 0.0, 0.0]], 1.0, "middle").tolist()
    [[0.0, 0.5, 0.5]]
    """
    part = check_part(part)
    arr = np.asarray(points)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"points must have shape (P, 3), got {np.shape(points)}")
    half = alpha / 2
    if part == "middle":
        return half - arr
    out = arr.copy()
    col = "uvw".index(part)
    out[:, col] = out[:, col] + half
    return out


__all__ = ["PARTS", "MAX_N_SUBDIVISION", "SubNets", "subdivision_matrix", "subdivision_matrices", "subdivide",
           "subdivide_to_depth", "to_parent", "half_alpha", "rotate_rows", "QuadNumber", "check_part"]
