"""Mesh export (OBJ, PLY) with optional vertex normals, atomically and byte-stable.

>>> import tempfile, pathlib, numpy as np
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> export_mesh(d / "t.obj", np.eye(3), np.array([[0, 1, 2]])).name
't.obj'
>>> export_mesh(d / "t.stl", np.eye(3), np.array([[0, 1, 2]]))
Traceback (most recent call last):
...
ValueError: path: the extension must be one of ['.obj', '.ply'], got '.stl'
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from paper_repro.util.io import atomic_path
from paper_repro.util.limits import check_real_array

FORMATS = {".obj": "obj", ".ply": "ply"}


def _check_mesh(vertices, faces, normals) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    check_real_array(vertices, "vertices")
    if normals is not None:
        check_real_array(normals, "normals")
    try:
        v = np.asarray(vertices, dtype=np.float64)
        f = np.asarray(faces)
    except (TypeError, ValueError):
        raise TypeError("vertices must be a (V, 3) array of numbers and faces a (F, 3) array of indices") from None
    if v.ndim != 2 or v.shape[1] != 3 or v.shape[0] == 0:
        raise ValueError(f"vertices must have shape (V, 3) with V >= 1, got {v.shape}")
    if not np.all(np.isfinite(v)):
        raise ValueError("vertices must be finite")
    if f.ndim != 2 or f.shape[1] != 3 or not np.issubdtype(f.dtype, np.integer):
        raise ValueError(f"faces must be an integer array of shape (F, 3), got {f.shape} of {f.dtype}")
    if f.size and (f.min() < 0 or f.max() >= len(v)):
        raise ValueError(f"faces must index vertices 0..{len(v) - 1}")
    nrm = None
    if normals is not None:
        nrm = np.asarray(normals, dtype=np.float64)
        if nrm.shape != v.shape:
            raise ValueError(f"normals must have the shape of vertices {v.shape}, got {nrm.shape}")
        nrm = np.nan_to_num(nrm, nan=0.0)
    return v, f.astype(np.int32), nrm


def export_mesh(path, vertices, faces, normals=None) -> Path:
    """Write a triangle mesh to ``path`` (``.obj`` or ``.ply``), with vertex normals if given.

    The parent folder must exist (``ValueError`` otherwise); the file is written atomically and without
    meshio's timestamp, so reruns give identical bytes.
    """
    import meshio

    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in FORMATS:
        raise ValueError(f"path: the extension must be one of {sorted(FORMATS)}, got {target.suffix!r}")
    if not target.parent.is_dir():
        raise ValueError(f"path: the folder {str(target.parent)!r} does not exist")
    v, f, nrm = _check_mesh(vertices, faces, normals)
    point_data = {}
    if nrm is not None:
        point_data = {"obj:vn": nrm} if suffix == ".obj" else {"nx": nrm[:, 0], "ny": nrm[:, 1], "nz": nrm[:, 2]}
    mesh = meshio.Mesh(v, [("triangle", f)], point_data=point_data)
    with atomic_path(target) as tmp:
        meshio.write(tmp, mesh, file_format=FORMATS[suffix])
        raw = tmp.read_bytes()
        # meshio writes the current time into the (ASCII) header; drop it so reruns give identical bytes
        tmp.write_bytes(re.sub(rb"Created by meshio v([0-9.]+), [0-9T:.\-]+", rb"Created by meshio v\1", raw, count=1))
    return target
