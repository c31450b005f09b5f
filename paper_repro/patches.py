"""Triangular (rational) trigonometric patches (Definitions def:surface_patch, def:rational_patch).

A control net of order n is a ``(delta_n, d)`` array whose rows follow the internal order of
:func:`paper_repro.labels.united_system`; :func:`net_from_labels` builds one from a mapping keyed by
the paper's labels (``'r_{4,3,1}'``, ``'g_{4,4,0}'``, ...; aliases such as ``'r_{4,0,0}'`` =
``'g_{4,4,0}'`` are accepted if consistent).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .domain import barycentric_to_uvw
from .labels import delta, index_of, united_system
from .normalization import evaluate_normalized
from .validation import check_alpha, check_n


def check_net(net, n: int, name: str = "net") -> np.ndarray:
    """Return the control net as a float array of shape ``(delta_n, d)``; ``ValueError`` if malformed."""
    n = check_n(n)
    arr = np.asarray(net, dtype=np.float64) if not isinstance(net, dict) else net_from_labels(net, n)
    if arr.ndim != 2 or arr.shape[0] != delta(n):
        raise ValueError(f"{name} must have shape (delta_n, d) = ({delta(n)}, d) for n = {n}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    return arr


def net_from_labels(points: dict, n: int) -> np.ndarray:
    """Control net array from ``{paper label: point}``; every function of T_{2n} must be given once."""
    idx = index_of(check_n(n))
    rows: dict[int, np.ndarray] = {}
    for lab, p in points.items():
        key = lab.strip().replace("\\mathbf", "").replace(" ", "")
        if key not in idx:
            raise ValueError(f"net: unknown control point label {lab!r} for order n = {n}")
        k = idx[key]
        v = np.asarray(p, dtype=np.float64)
        if k in rows and not np.array_equal(rows[k], v):
            raise ValueError(f"net: {lab!r} conflicts with another label of the same control point")
        rows[k] = v
    missing = [united_system(n)[k].control_point for k in range(delta(n)) if k not in rows]
    if missing:
        raise ValueError(f"net: missing control points {missing[:6]}{'...' if len(missing) > 6 else ''}")
    return np.stack([rows[k] for k in range(delta(n))])


@dataclass
class Patch:
    """Triangular trigonometric patch s_n^alpha (eq. triangular_trig_surface)."""

    n: int
    alpha: float
    net: np.ndarray
    weights: np.ndarray | None = field(default=None)  # rational patch (eq. rational_patch) if given

    def __post_init__(self) -> None:
        self.n = check_n(self.n)
        self.alpha = check_alpha(self.alpha)
        self.net = check_net(self.net, self.n)
        if self.weights is not None:
            w = np.asarray(self.weights, dtype=np.float64)
            if w.shape != (delta(self.n),):
                raise ValueError(f"weights must have shape ({delta(self.n)},), got {w.shape}")
            if np.any(w < 0) or not np.all(np.isfinite(w)) or w.sum() == 0:
                raise ValueError("weights must be finite, non-negative and not all zero (rank 1)")
            self.weights = w

    def basis(self, points) -> np.ndarray:
        return evaluate_normalized(self.n, self.alpha, points)

    def __call__(self, points) -> np.ndarray:
        """Evaluate at ``(P, 3)`` points ``(u, v, w)`` of Omega^alpha: ``(P, d)``."""
        b = self.basis(points)
        if self.weights is None:
            return b @ self.net
        bw = b * self.weights[None, :]
        return (bw @ self.net) / bw.sum(axis=1, keepdims=True)

    def at_barycentric(self, bary) -> np.ndarray:
        return self(barycentric_to_uvw(self.alpha, bary))
