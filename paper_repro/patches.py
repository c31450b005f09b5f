"""Triangular (rational) trigonometric patches (Definitions def:surface_patch, def:rational_patch).

A control net of order n is a ``(delta_n, d)`` array whose rows follow the internal order of
:func:`paper_repro.labels.united_system`; :func:`net_from_labels` builds one from a mapping keyed by
the paper's labels (``'r_{4,3,1}'``, ``'g_{4,4,0}'``, ...; aliases such as ``'r_{4,0,0}'`` =
``'g_{4,4,0}'`` are accepted if consistent).
"""

from __future__ import annotations

import re
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

    def basis(self, points, arith: str = "float", dps: int = 50) -> np.ndarray:
        return evaluate_normalized(self.n, self.alpha, points, arith, dps=dps)

    def __call__(self, points, arith: str = "float", dps: int = 50) -> np.ndarray:
        """Evaluate at ``(P, 3)`` points ``(u, v, w)`` of Omega^alpha: ``(P, d)``.

        ``arith='mp'`` evaluates the basis with mpmath at ``dps`` digits (points may be mpf; the net's
        float entries are taken as exact binary values).
        """
        b = self.basis(points, arith, dps)
        net = self.net if arith == "float" else self.net.astype(object)
        if self.weights is None:
            return b.dot(net)
        w = self.weights if arith == "float" else self.weights.astype(object)
        bw = b * w[None, :]
        return bw.dot(net) / bw.sum(axis=1)[:, None]

    def at_barycentric(self, bary) -> np.ndarray:
        return self(barycentric_to_uvw(self.alpha, bary))

    def boundary_net(self, edge: str) -> np.ndarray:
        """Control polygon of a boundary curve (the paper's list after Definition def:surface_patch):
        ``'u=0'``: g_{2n,2n-i,0}, ``'v=0'``: r_{2n,2n-i,0}, ``'w=0'``: b_{2n,2n-i,0}, i = 0..2n."""
        letter = {"u=0": "g", "v=0": "r", "w=0": "b"}[edge]
        idx = index_of(self.n)
        return np.stack([self.net[idx[f"{letter}_{{{2 * self.n},{2 * self.n - i},0}}"]] for i in range(2 * self.n + 1)])

    def boundary_curve(self, edge: str, t) -> np.ndarray:
        """The boundary curve as a univariate curve sum_i p_i A_{2n,2n-i}(t) (eq. univariate_basis);
        t is w on u=0, u on v=0, v on w=0."""
        from .univariate import A

        a = A(self.n, self.alpha, np.asarray(t, dtype=np.float64))  # columns A_{2n,0..2n}
        return a[:, ::-1] @ self.boundary_net(edge)

    def mesh(self, resolution: int = 16) -> tuple[np.ndarray, np.ndarray]:
        """Triangle mesh: vertices ``(V, d)`` on a barycentric grid, faces ``(F, 3)``."""
        r = int(resolution)
        if r < 1:
            raise ValueError(f"resolution must be a positive integer, got {resolution}")
        ids, bary = {}, []
        for i in range(r + 1):
            for j in range(r + 1 - i):
                ids[(i, j)] = len(bary)
                bary.append((i / r, j / r, 1 - (i + j) / r))
        faces = []
        for i in range(r):
            for j in range(r - i):
                faces.append((ids[(i, j)], ids[(i + 1, j)], ids[(i, j + 1)]))
                if i + j + 1 < r:
                    faces.append((ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]))
        return self.at_barycentric(np.array(bary)), np.array(faces, dtype=np.int64)


def merge_meshes(meshes: list[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """Concatenate meshes (vertices are not welded)."""
    verts, faces, offset = [], [], 0
    for v, f in meshes:
        verts.append(v)
        faces.append(f + offset)
        offset += len(v)
    return np.concatenate(verts), np.concatenate(faces)


def export_mesh(path, vertices: np.ndarray, faces: np.ndarray) -> None:
    """Write a triangle mesh (OBJ, PLY, ... by extension) with meshio, atomically."""
    import meshio

    from .io import atomic_path

    mesh = meshio.Mesh(np.asarray(vertices, dtype=np.float64), [("triangle", np.asarray(faces, dtype=np.int32))])
    suffix = str(path).rsplit(".", 1)[-1]
    with atomic_path(path) as tmp:
        meshio.write(tmp, mesh, file_format={"obj": "obj", "ply": "ply"}.get(suffix, suffix))
        # meshio writes the current time into the (ASCII) header; drop it so reruns give identical bytes
        raw = tmp.read_bytes()
        tmp.write_bytes(re.sub(rb"Created by meshio v([0-9.]+), [0-9T:.\-]+", rb"Created by meshio v\1", raw, count=1))
