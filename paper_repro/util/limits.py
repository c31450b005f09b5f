"""Domain of validity of the public API: accepted types, ranges and sizes (budgets from a measured cost model).

Every check raises ``TypeError`` (wrong kind of value) or ``ValueError`` (right kind, outside the range or the
budget) naming the parameter and the limit, before any work starts.  The budgets keep every call below about
20 s and 2 GB on one core of the reference machine (2 cores, 2026); the measurements behind each limit are
quoted next to it and in the README table ("Domain of validity"), produced by ``tools/fuzz_api.py --cost``.

>>> check_int(3, "times", 0, 20)
3
>>> check_int(-1, "times", 0, 20)
Traceback (most recent call last):
...
ValueError: times must be an integer from 0 to 20, got -1
>>> real_scalar(1j, "alpha")
Traceback (most recent call last):
...
TypeError: alpha must be a real number, got the complex number 1j
"""

from __future__ import annotations

import numbers

import numpy as np

#: Order elevation: E of order n -> n+1 from the closed form (core/half_angle_matrices.py; no solve), a dense
#: (delta_{n+1}, delta_n) float64 array.  Measured cold in a fresh process (tools/elevation_speed.py, 2 cores, load
#: about 3.4): n = 10 in 0.02-0.03 s, n = 30 in 0.3-0.47 s, n = 40 in 1.1 s CPU (1.7 s wall); peak memory (load about
#: 8): n = 30 179 MB, n = 40 409 MB, n = 50 874 MB (3.3 s CPU); time and memory grow as n^4.  n <= 40 keeps one
#: call well inside the 20 s and 2 GB budget also on a loaded machine, and repeated elevation 1 -> 41 too.
MAX_N_ELEVATION = 40
#: Repeated elevation: ``times`` steps (each bounded by MAX_N_ELEVATION).
MAX_ELEVATION_STEPS = MAX_N_ELEVATION
#: Fitting by mp collocation at 40 digits, delta_n unknowns (measured, loaded machine: n = 2, 3, 4, 5 in 1.8, 11, 44,
#: 118 s).
MAX_N_FIT = 4
#: Exact fitting (fmpq collocation; measured, loaded machine: n = 4, 6, 8, 10 in 0.6, 3.9, 13, 39 s).
MAX_N_FIT_EXACT = 8
#: Float fitting (least squares at 2 delta_n points; n = 10: 662 x 331, well under a second).
MAX_N_FIT_FLOAT = 10
#: Rational sample points (a Python loop; measured, loaded machine: 10^4 points in 28 s, 10^5 over 90 s).
MAX_RATIONAL_POINTS = 10_000
#: Limit Bezier net (exact conversion weights; measured, loaded machine: n = 10 in 1.2 s, n = 20 in 24 s, 180 MB).
MAX_N_BEZIER_LIMIT = 20
#: Mesh resolution r: (r+1)(r+2)/2 vertices, 2 r^2 faces (measured, loaded machine: r = 512 with normals, 132k
#: vertices, in 33 s and 210 MB; the grid is built in Python, so time grows as r^2).
MAX_MESH_RESOLUTION = 512
#: Random float points of :func:`~paper_repro.core.domain.sample_points`: about 52 bytes per point at the peak (the
#: Dirichlet draw and its temporaries; measured: 10^7 points in 5.6 s and 523 MB, loaded machine), so 3 x 10^7 stay
#: below 1.6 GB (10^8 needed 2.4 GB and more).
MAX_SAMPLE_POINTS = 30_000_000
#: ``python -m paper_repro labels N`` prints 3N(N+1)+1 lines: time grows as N^2 (measured, loaded machine: N = 200 in
#: 4.5 s, N = 1000 in 93 s), so N = 400 stays below about 20 s.
MAX_N_LABELS = 400
#: Basis transformation V_n <-> T-bar_{2n} (Question 7.2) by its closed form (core.transformation): a dense
#: delta_n x delta_n matrix in O(n^5) array operations; measured at n = 30, float: 1.2 s CPU per direction and 220 MB
#: (19 s wall on the loaded machine); memory grows about as n^4.
MAX_N_TRANSFORMATION = 30
#: Precision of the mp arithmetic (decimal digits).
MIN_DPS, MAX_DPS = 5, 10_000


def _plain(x: object) -> str:
    text = repr(x)
    return text if len(text) <= 40 else text[:37] + "..."


def check_int(value: object, name: str, lo: int, hi: int | None = None, *, why: str = "") -> int:
    """``value`` as an int if it is an integer (Python or numpy, not bool) in ``[lo, hi]``."""
    rng = f"from {lo} to {hi}" if hi is not None else f">= {lo}"
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Integral, np.integer)):
        raise TypeError(f"{name} must be an integer {rng}, got {_plain(value)} of type {type(value).__name__}")
    v = int(value)
    if v < lo or (hi is not None and v > hi):
        raise ValueError(f"{name} must be an integer {rng}, got {v}" + (f" ({why})" if why else ""))
    return v


def real_scalar(x: object, name: str):
    """A real scalar as a plain Python/mpmath/flint number: numpy scalars and 0-d arrays unwrapped (``.item()``;
    ``np.longdouble`` to the nearest float64), ints, floats, ``Fraction``, mpmath ``mpf``, flint ``fmpq``/``arb``
    kept.  ``TypeError`` naming ``name`` for booleans, strings, complex numbers and arrays."""
    if isinstance(x, np.ndarray):
        if x.ndim != 0:
            raise TypeError(f"{name} must be a real number, got an array of shape {x.shape}")
        x = x[()]
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"{name} must be a real number, got the boolean {x!r}")
    if isinstance(x, (str, bytes)):
        raise TypeError(f"{name} must be a real number, got the string {_plain(x)}")
    if isinstance(x, (complex, np.complexfloating)) or type(x).__name__ in ("mpc", "acb"):
        raise TypeError(f"{name} must be a real number, got the complex number {_plain(x)}")
    if isinstance(x, np.longdouble):
        return float(x)
    if isinstance(x, np.generic):
        x = x.item()
        if not isinstance(x, (int, float)):
            raise TypeError(f"{name} must be a real number, got {type(x).__name__}")
        return x
    if isinstance(x, (numbers.Real,)) or type(x).__name__ in ("mpf", "fmpq", "fmpz", "arb", "RationalAngle"):
        return x
    raise TypeError(f"{name} must be a real number, got {_plain(x)} of type {type(x).__name__}")


def check_real_array(values, name: str) -> None:
    """Refuse complex, boolean, string and object entries that are not real numbers in an array-like input
    (numpy would silently truncate complex numbers and parse numeric strings)."""
    arr = values if isinstance(values, np.ndarray) else None
    if arr is None:
        try:
            arr = np.asarray(values, dtype=object)
        except ValueError:
            raise ValueError(f"{name} must be a rectangular array of real numbers (ragged rows given)") from None
    kind = arr.dtype.kind
    if kind == "c":
        raise TypeError(f"{name} must be real numbers, got complex entries")
    if kind in "USb":
        raise TypeError(f"{name} must be real numbers, got {'strings' if kind in 'US' else 'booleans'}")
    if kind == "O":
        for x in arr.reshape(-1):
            real_scalar(x, f"{name} entries")
