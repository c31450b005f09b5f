"""Mesh export in every format meshio writes a triangle surface to, with vertex normals where the format holds
them, atomically and byte-stable.

>>> import tempfile, pathlib, numpy as np
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> export_mesh(d / "t.obj", np.eye(3), np.array([[0, 1, 2]])).name
't.obj'
>>> export_mesh(d / "t.stl", np.eye(3), np.array([[0, 1, 2]])).name
't.stl'
>>> export_mesh(d / "t.svg", np.eye(3), np.array([[0, 1, 2]]))  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: path: '.svg' cannot hold this mesh (meshio writes only flat 2D meshes to SVG); use .obj, .ply, ...
"""

from __future__ import annotations

import gzip
import importlib.util
import re
import warnings
from pathlib import Path

import numpy as np

from paper_repro.util.io import atomic_path
from paper_repro.util.limits import check_real_array

#: Extensions meshio registers but that cannot hold a 3D triangle surface here (meshio 5.3, checked by writing and
#: reading back a mesh with normals: tests/test_patches_surfaces.py), with the reason given to the caller.
NOT_A_SURFACE = {
    ".ele": "TetGen files hold tetrahedra only", ".node": "TetGen files hold tetrahedra only",
    ".f3grid": "meshio's FLAC3D writer fails on triangles", ".su2": "meshio's SU2 writer fails on triangles",
    ".svg": "meshio writes only flat 2D meshes to SVG", ".ugrid": "meshio cannot read back its own UGRID file",
    **dict.fromkeys((".bdf", ".fem", ".nas"), "meshio's Nastran writer fails on negative coordinates of 12 digits"),
    **dict.fromkeys((".dato.gz", ".post.gz"), "meshio writes PERMAS .gz files uncompressed; use .dato or .post"),
}
#: Formats that store vertex normals, and how: OBJ as ``vn`` lines that the faces reference (``f a//a``), PLY as the
#: vertex properties ``nx ny nz``, the others as the point data ``Normals``.  Other formats hold no vertex normals.
NORMALS = (".obj", ".ply", ".vtk", ".vtu", ".avs", ".msh", ".dat", ".tec")
#: The packages some formats need beyond meshio (not dependencies of paper_repro).
NEEDS = {"h5py": (".cgns", ".h5m", ".hmf", ".med", ".xdmf", ".xmf"), "netCDF4": (".e", ".ex2", ".exo")}


def formats() -> dict[str, str]:
    """Every extension :func:`export_mesh` writes, and meshio's name of its format (Gmsh for ``.msh``).

    >>> f = formats()
    >>> f[".stl"], f[".vtk"], f[".msh"], ".svg" in f
    ('stl', 'vtk', 'gmsh', False)
    """
    import meshio

    return {ext: ("gmsh" if "gmsh" in types else types[0])
            for ext, types in sorted(meshio.extension_to_filetypes.items()) if ext not in NOT_A_SURFACE}


def _suffix(target: Path) -> str:
    """The longest registered extension of ``target`` (``.vol.gz`` before ``.gz``)."""
    name = target.name.lower()
    known = sorted([*formats(), *NOT_A_SURFACE], key=len, reverse=True)
    return next((ext for ext in known if name.endswith(ext)), target.suffix.lower())


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
        if np.isinf(nrm).any():
            raise ValueError("normals must be finite (infinite entries given); NaN marks a vertex without a normal")
        if np.isnan(nrm).all():
            raise ValueError("normals are NaN at every vertex (no normal defined anywhere): pass normals=None")
        nrm = np.nan_to_num(nrm, nan=0.0)  # a vertex without a normal (Patch.normals: NaN where degenerate)
    return v, f.astype(np.int32), nrm


def _write_obj(path: Path, v: np.ndarray, f: np.ndarray, nrm: np.ndarray) -> None:
    """OBJ with ``vn`` lines that the faces use (``f a//a b//b c//c``): readers such as trimesh then take the
    normals (meshio writes ``vn`` lines but plain ``f a b c`` faces, and the normals were ignored)."""
    lines = ["# Created by paper_repro (vertex normals referenced by the faces)"]
    lines += [f"v {p[0]} {p[1]} {p[2]}" for p in v]
    lines += [f"vn {q[0]} {q[1]} {q[2]}" for q in nrm]
    lines += ["f " + " ".join(f"{k}//{k}" for k in face) for face in (f.astype(np.int64) + 1)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def export_mesh(path, vertices, faces, normals=None) -> Path:
    """Write a triangle mesh to ``path`` in the format of its extension, with vertex normals if given.

    Every format meshio writes a triangle surface to (:func:`formats`: STL, VTK, VTU, OBJ, PLY, OFF, Gmsh
    ``.msh``, Abaqus ``.inp``, Nastran, Medit, ...; HDF5 and Exodus formats need ``h5py`` / ``netCDF4``).
    Normals are stored by the formats that hold vertex normals (:data:`NORMALS`): OBJ as ``vn`` lines referenced
    by the faces, PLY as ``nx ny nz``, VTK, VTU, AVS, Gmsh and Tecplot as the point data ``Normals``; the other
    formats have no place for them (STL stores face normals, which meshio computes from the triangles).
    A NaN normal marks a vertex without one (:meth:`~paper_repro.surfaces.patch.Patch.normals` at a degenerate
    point) and is written as the zero vector; normals that are NaN everywhere or infinite are refused.
    The parent folder must exist (``ValueError`` otherwise); the file is written atomically, without meshio's
    timestamp and with gzip's time and name zeroed, so reruns give identical bytes.
    """
    import meshio

    target = Path(path)
    suffix = _suffix(target)
    writers = formats()
    if suffix not in writers:
        why = f"cannot hold this mesh ({NOT_A_SURFACE[suffix]})" if suffix in NOT_A_SURFACE else "is not a mesh format"
        raise ValueError(f"path: {suffix or target.name!r} {why}; use .obj, .ply, .stl, .vtk, .vtu, .off, .msh, ... "
                         "(every one: paper_repro.surfaces.mesh.formats())")
    for package, exts in NEEDS.items():
        if suffix in exts and importlib.util.find_spec(package) is None:
            raise ValueError(f"path: meshio writes {suffix!r} files with the package {package}, which is not "
                             f"installed (pip install {package}), or choose another format such as .vtu or .ply")
    if not target.parent.is_dir():
        raise ValueError(f"path: the folder {str(target.parent)!r} does not exist")
    v, f, nrm = _check_mesh(vertices, faces, normals)
    if suffix == ".obj" and nrm is not None:
        with atomic_path(target) as tmp:
            _write_obj(tmp, v, f, nrm)
        return target
    point_data = {}
    if nrm is not None and suffix in NORMALS:
        point_data = {"nx": nrm[:, 0], "ny": nrm[:, 1], "nz": nrm[:, 2]} if suffix == ".ply" else {"Normals": nrm}
    mesh = meshio.Mesh(v, [("triangle", f)], point_data=point_data)
    with atomic_path(target) as tmp:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # meshio's notes on legacy formats
            meshio.write(tmp, mesh, file_format=writers[suffix])
        raw = tmp.read_bytes()
        if suffix == ".vol.gz":  # gzip's header holds the time and the temporary file's name; meshio's Netgen
            # writer compresses only when the file name ends in .vol.gz (the temporary one does not)
            raw = gzip.compress(gzip.decompress(raw) if raw[:2] == b"\x1f\x8b" else raw, mtime=0)
        # meshio writes the current time into the (ASCII) header; drop it so reruns give identical bytes
        tmp.write_bytes(re.sub(rb"Created by meshio v([0-9.]+), [0-9T:.\-]+", rb"Created by meshio v\1", raw, count=1))
    return target
