"""Control nets of order n: arrays whose rows follow the internal order of T_{2n}, or label mappings.

A control net of order n is a ``(delta_n, d)`` array whose row ``k`` is the control point of the k-th
function of :func:`paper_repro.core.labels.united_system` (the centre ``r_{2n,n,n}`` first, then the R,
G and B functions, each colour by level j ascending and i ascending).  :func:`net_from_labels` builds one
from a mapping keyed by the paper's labels (``'r_{4,3,1}'``, ``'g_{4,4,0}'``, ...; aliases such as
``'r_{4,0,0}'`` = ``'g_{4,4,0}'`` are accepted if consistent).

>>> net = check_net([[0.0, 0.0]] * 7, 1)
>>> net.shape
(7, 2)
>>> check_net([[0.0, 0.0]] * 6, 1)
Traceback (most recent call last):
...
ValueError: net must have shape (delta_n, d) = (7, d) for n = 1, got (6, 2)
"""

from __future__ import annotations

import numbers

import numpy as np

from paper_repro.core.labels import delta, delta_unchecked, index_of, united_system
from paper_repro.util.validation import check_n


def _as_object_rows(net, name: str) -> np.ndarray:
    try:
        arr = np.asarray(net, dtype=object)
    except ValueError:
        raise ValueError(f"{name} must be a rectangular (delta_n, d) array of numbers (ragged rows given)") from None
    for x in arr.reshape(-1):
        numeric = isinstance(x, (numbers.Number, np.number)) or hasattr(x, "__float__")
        if isinstance(x, (bool, np.bool_, str, bytes)) or not numeric:
            raise TypeError(f"{name} entries must be real numbers, got {type(x).__name__}")
        if isinstance(x, (complex, np.complexfloating)) or type(x).__name__ == "mpc":
            raise TypeError(f"{name} entries must be real numbers, got the complex number {x!r}")
    return arr


def check_net_exact(net, n: int, name: str = "net", *, n_checked: bool = False) -> np.ndarray:
    """The control net as an object array of shape ``(delta_n, d)``, entries as given (for the exact
    and mp arithmetics); validated as :func:`check_net` (``n_checked``: inner callers that checked ``n``)."""
    n = n if n_checked else check_n(n)
    arr = net_from_labels(net, n) if isinstance(net, dict) else _as_object_rows(net, name)
    if arr.ndim != 2 or arr.shape[0] != delta_unchecked(n) or arr.shape[1] < 1:
        raise ValueError(f"{name} must have shape (delta_n, d) = ({delta_unchecked(n)}, d) for n = {n}, got "
                         f"{arr.shape}")
    try:
        fl = arr.astype(np.float64)
    except (TypeError, ValueError, OverflowError):
        raise TypeError(f"{name} entries must be real numbers") from None
    if not np.all(np.isfinite(fl)):
        raise ValueError(f"{name} must be finite")
    return arr


def check_net(net, n: int, name: str = "net") -> np.ndarray:
    """Return the control net as a float array of shape ``(delta_n, d)``; ``ValueError``/``TypeError``
    naming ``name`` if malformed (wrong shape, non-numbers, NaN or inf)."""
    return check_net_exact(net, n, name).astype(np.float64)


def net_from_labels(points: dict, n: int) -> np.ndarray:
    """Control net (object array) from ``{paper label: point}``; every function of T_{2n} given once."""
    idx = index_of(check_n(n))
    rows: dict[int, np.ndarray] = {}
    for lab, p in points.items():
        if not isinstance(lab, str):
            raise TypeError(f"net: labels must be strings like 'r_{{4,3,1}}', got {lab!r}")
        key = lab.strip().replace("\\mathbf", "").replace(" ", "")
        if key not in idx:
            raise ValueError(f"net: unknown control point label {lab!r} for order n = {n}")
        k = idx[key]
        v = _as_object_rows(p, f"net[{lab!r}]").reshape(-1)
        if k in rows and not np.array_equal(rows[k], v):
            raise ValueError(f"net: {lab!r} conflicts with another label of the same control point")
        rows[k] = v
    missing = [united_system(n)[k].control_point for k in range(delta(n)) if k not in rows]
    if missing:
        raise ValueError(f"net: missing control points {missing[:6]}{'...' if len(missing) > 6 else ''}")
    if len({len(r) for r in rows.values()}) != 1:
        raise ValueError("net: control points of different dimensions")
    return np.stack([rows[k] for k in range(delta(n))])


def _rebuild_labelled_net(array: np.ndarray, n: int) -> LabelledNet:
    """Unpickle a :class:`LabelledNet` (module level, so pickle finds it)."""
    return LabelledNet(array, n)


class LabelledNet(np.ndarray):
    """A control net ``(delta_n, d)`` whose rows are also reachable by the paper's labels.

    ``net["r_{4,3,1}"]`` (or ``"R_{4,3,1}"``, or any alias of the same function such as ``"g_{4,4,0}"`` for
    ``r_{4,0,0}``) is the control point of that function; integer indices and slices work as on any array
    (internal order, ``paper_repro labels N``).  Arithmetic on the net gives plain arrays.

    >>> net = LabelledNet(np.arange(21.0).reshape(7, 3), 1)
    >>> net["r_{2,1,1}"].tolist() == net[index_of(1)["r_{2,1,1}"]].tolist()
    True
    >>> net["x"]
    Traceback (most recent call last):
    ...
    KeyError: "net: no control point labelled 'x' for order n = 1 (labels like 'r_{2,1,1}', 'g_{2,1,0}')"
    """

    n: int

    def __new__(cls, array, n: int, *, n_checked: bool = False) -> LabelledNet:
        obj = np.asarray(array).view(cls)
        obj.n = n if n_checked else check_n(n)
        if obj.ndim < 1 or obj.shape[0] != delta_unchecked(obj.n):
            raise ValueError(f"net: {delta_unchecked(obj.n)} rows expected for order n = {obj.n}, got shape "
                             f"{obj.shape}")
        return obj

    def __array_finalize__(self, obj) -> None:
        self.n = getattr(obj, "n", 0)

    def __reduce__(self):
        """Pickle and copy keep the order ``n`` (numpy's own reduction keeps only the array)."""
        plain = np.asarray(self).copy()
        if self.n < 1 or plain.ndim < 1 or plain.shape[0] != delta(self.n):  # a reshaped view: a plain array
            return plain.__reduce__()
        return (_rebuild_labelled_net, (plain, self.n))

    def __array_wrap__(self, out_arr, context=None, return_scalar=False):
        return np.asarray(out_arr) if not return_scalar else out_arr[()]

    def _row(self, label: str) -> int:
        key = label.strip().replace("\\mathbf", "").replace(" ", "")
        try:
            return index_of(self.n)[key]
        except KeyError:
            raise KeyError(f"net: no control point labelled {label!r} for order n = {self.n} "
                           f"(labels like 'r_{{{2 * self.n},{2 * self.n - 1},1}}', "
                           f"'g_{{{2 * self.n},{2 * self.n - 1},0}}')") from None

    def __getitem__(self, key):
        if isinstance(key, str):
            return np.asarray(super().__getitem__(self._row(key)))
        out = super().__getitem__(key)
        return np.asarray(out) if isinstance(out, np.ndarray) else out

    def __setitem__(self, key, value) -> None:
        super().__setitem__(self._row(key) if isinstance(key, str) else key, value)

    def labels(self) -> list[str]:
        """The control point label of every row, in internal order (``net.labels()[k]`` names ``net[k]``)."""
        return [lab.control_point for lab in united_system(self.n)]
