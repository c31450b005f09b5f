import meshio
import mpmath
import numpy as np
import pytest
from flint import fmpq
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.claims.torus import exact_torus, printed_net
from paper_repro.core.domain import rational_alpha, sample_points
from paper_repro.core.labels import delta, index_of
from paper_repro.printed.torus import corrected_points, mp_function, torus
from paper_repro.surfaces.fitting import fit_exact, fit_mp
from paper_repro.surfaces.mesh import export_mesh
from paper_repro.surfaces.models import cyclide_parts, cyclide_pieces, model_gap
from paper_repro.surfaces.patch import Patch

from .strategies import alphas


def test_fit_exact_torus_matches_mp():
    alpha = rational_alpha((1, 3))
    exact = fit_exact(exact_torus(fmpq(2), fmpq(1)), 2, alpha)
    with mpmath.workdps(40):
        mp = fit_mp(lambda u, v, w: torus(u, v, w, 2, 1), 2, alpha.mp())
        assert max(abs(mpmath.mpf(int(x.p)) / int(x.q) - y) for r1, r2 in zip(exact, mp) for x, y in zip(r1, r2)) \
            < mpmath.mpf(10) ** -30


def test_fit_rejects_surface_outside_space():
    with pytest.raises(ValueError, match="not in the span"):
        fit_mp(lambda u, v, w: (mpmath.exp(u), v, w), 1, 1.0)


@given(alphas)
def test_printed_torus_net_is_exact_except_erratum(alpha):
    with mpmath.workdps(30):
        a = mpmath.mpf(alpha)
        comp = fit_mp(lambda u, v, w: torus(u, v, w, 4, 3), 2, a, dps=30)
        pr = printed_net(a, mpmath.mpf(4), mpmath.mpf(3))
        k = index_of(2)["b_{4,3,1}"]
        diff = np.array([[float(abs(pr[i, j] - comp[i, j])) for j in range(3)] for i in range(19)])
        diff_wo = diff.copy()
        diff_wo[k, 0] = 0
        assert diff_wo.max() < 1e-15
        fixed = corrected_points()["b_{4,3,1}.x"][2]  # the erratum's fix applied to the transcription
        assert abs(mp_function(fixed)(a, 4, 3) - comp[k, 0]) < 1e-20


def test_mesh_export_round_trip(tmp_path):
    patch = Patch(2, 1.0, np.random.default_rng(1).normal(size=(delta(2), 3)))
    v, f = patch.mesh(6)
    assert len(f) == 36 and len(v) == 28
    for ext in ("obj", "ply"):
        path = tmp_path / f"m.{ext}"
        export_mesh(path, v, f)
        back = meshio.read(path)
        assert np.allclose(back.points, v, atol=1e-12) and np.array_equal(back.cells[0].data, f)


def test_cyclide_one_square():
    al = np.pi / 2
    with mpmath.workdps(30):
        params = {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}
    pieces = cyclide_pieces(al, params, [0.0], [0.0])
    assert all(p.patch.weights.min() >= 0 for p in pieces)
    pts = sample_points(al, 20, seed=2)
    for p in pieces:
        parts = (cyclide_parts(U, V, 6, mpmath.sqrt(32), 2, 3) for U, V in p.uv(pts, al))
        ref = [[float(x / W) for x in X] for X, W in parts]
        assert np.abs(p.patch(pts) - np.array(ref)).max() < 1e-12
    assert model_gap(pieces, al) < 1e-12


def test_rational_patch_with_equal_weights_is_polynomial():
    net = np.random.default_rng(3).normal(size=(delta(2), 3))
    pts = sample_points(1.2, 50, seed=0)
    assert np.abs(Patch(2, 1.2, net, weights=np.full(delta(2), 2.5))(pts) - Patch(2, 1.2, net)(pts)).max() < 1e-13


@given(st.integers(1, 3))
def test_mesh_resolution_validation(n):
    with pytest.raises(ValueError, match="resolution"):
        Patch(n, 1.0, np.zeros((delta(n), 3))).mesh(0)


def _mesh_with_normals():
    p = Patch(2, 1.0, np.random.default_rng(3).normal(size=(19, 3)))
    return p.mesh(3, normals=True)


@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")  # meshio reading STL
def test_export_mesh_writes_every_meshio_surface_format(tmp_path):
    """Issue 33: the tutorial said "any format meshio writes" while export_mesh took .obj and .ply only."""
    import importlib.util

    from paper_repro.surfaces.mesh import NEEDS, NORMALS, formats

    v, f, nrm = _mesh_with_normals()
    written = []
    for ext, filetype in formats().items():
        path = tmp_path / f"m{ext}"
        needs = next((pkg for pkg, exts in NEEDS.items() if ext in exts), None)
        if needs and importlib.util.find_spec(needs) is None:
            with pytest.raises(ValueError, match=needs):
                export_mesh(path, v, f, nrm)
            continue
        export_mesh(path, v, f, nrm)
        back = meshio.read(path, file_format=filetype)
        tri = np.concatenate([c.data for c in back.cells if c.type == "triangle"])
        # the triangles' corners (STL stores float32 corners per triangle, merged again by meshio's reader)
        assert len(tri) == len(f) and np.allclose(back.points[tri], v[f], atol=1e-6 * abs(v).max()), ext
        if ext in NORMALS and ext not in (".obj", ".ply"):
            key = "Normals" if "Normals" in back.point_data else None
            stored = (back.point_data[key] if key else
                      np.stack([back.point_data[f"Normals_{k}"] for k in range(3)], axis=1))
            assert np.allclose(stored, nrm, atol=1e-6), ext
        written.append(ext)
    assert {".stl", ".vtk", ".vtu", ".obj", ".ply", ".off", ".msh"} <= set(written)


def test_export_mesh_refuses_what_no_format_holds(tmp_path):
    v, f, nrm = _mesh_with_normals()
    with pytest.raises(ValueError, match="cannot hold this mesh .*2D"):
        export_mesh(tmp_path / "m.svg", v, f)
    with pytest.raises(ValueError, match="'.xyz' is not a mesh format.*formats()"):
        export_mesh(tmp_path / "m.xyz", v, f)
    assert list(tmp_path.iterdir()) == []


def test_obj_faces_reference_their_normals(tmp_path):
    """meshio wrote `vn` lines but faces `f a b c`, so trimesh-like readers ignored the normals: f a//a b//b c//c."""
    v, f, nrm = _mesh_with_normals()
    path = export_mesh(tmp_path / "m.obj", v, f, nrm)
    rows = [line.split() for line in path.read_text().splitlines() if line and not line.startswith("#")]
    verts = np.array([r[1:] for r in rows if r[0] == "v"], dtype=float)
    normals = np.array([r[1:] for r in rows if r[0] == "vn"], dtype=float)
    faces = [r[1:] for r in rows if r[0] == "f"]
    assert np.array_equal(verts, v) and np.array_equal(normals, np.nan_to_num(nrm))
    assert len(faces) == len(f)
    for face, want in zip(faces, f, strict=True):
        pairs = [corner.split("//") for corner in face]
        assert all(len(p) == 2 and p[0] == p[1] for p in pairs), face  # vertex k uses normal k
        assert [int(p[0]) - 1 for p in pairs] == list(want)
    assert np.array_equal(meshio.read(path).points, v)  # still a valid OBJ for meshio
    try:
        import trimesh
    except ImportError:
        return
    tm = trimesh.load(path, process=False)
    assert np.allclose(tm.vertex_normals, nrm / np.linalg.norm(nrm, axis=1)[:, None], atol=1e-9)


def test_ply_normals_round_trip_and_gzip_is_byte_stable(tmp_path):
    v, f, nrm = _mesh_with_normals()
    back = meshio.read(export_mesh(tmp_path / "m.ply", v, f, nrm))
    assert np.allclose(np.stack([back.point_data[k] for k in ("nx", "ny", "nz")], axis=1), nrm)
    raw = export_mesh(tmp_path / "m.vol.gz", v, f).read_bytes()
    assert raw[:2] == b"\x1f\x8b" and raw[4:8] == b"\0\0\0\0" and not raw[3] & 0x08  # no time, no file name
    assert raw == export_mesh(tmp_path / "other.vol.gz", v, f).read_bytes()


def test_at_barycentric_names_the_rows_the_user_gave():
    """`at_barycentric([[0.5, 0.5, 0.5]])` spoke of the scaled point (0.6, 0.6, 0.6) not being on Omega^alpha."""
    import numpy as np
    import pytest

    from paper_repro.surfaces.patch import Patch

    p = Patch(1, 1.2, np.zeros((7, 3)))
    with pytest.raises(ValueError, match=r"bary row 0 = \(0.5, 0.5, 0.5\) sums to 1.5: barycentric rows"):
        p.at_barycentric([[0.5, 0.5, 0.5]])
    with pytest.raises(ValueError, match=r"row 1 = \(1.5, -0.5, 0\) has a negative entry"):
        p.at_barycentric([[1, 0, 0], [1.5, -0.5, 0]])
    with pytest.raises(TypeError):
        p.at_barycentric([[0.5 + 0j, 0.5, 0]])
    one = np.asarray(p.at_barycentric([1 / 3, 1 / 3, 1 / 3]), dtype=float).reshape(-1)
    assert np.array_equal(one, np.asarray(p.at_barycentric([[1 / 3, 1 / 3, 1 / 3]]), dtype=float)[0])


def test_a_cold_derivative_validates_n_and_alpha_once():
    """Inner code calls inner code: a first Patch and derivative at a new (n, alpha) ran check_n 15 times and
    check_alpha 3 times (inner builders called public functions)."""
    import collections
    import sys

    import numpy as np

    import paper_repro.util.validation as val
    from paper_repro.surfaces.patch import Patch

    targets = {val.check_n.__code__: "check_n", val.check_alpha.__code__: "check_alpha"}
    calls: collections.Counter = collections.Counter()

    def prof(frame, event, arg):
        if event == "call" and frame.f_code in targets:
            calls[targets[frame.f_code]] += 1

    n, alpha = 4, 1.2345678901  # an (n, alpha) no other test uses: cold caches for the alpha-dependent parts
    old = sys.getprofile()
    sys.setprofile(prof)
    try:
        p = Patch(n, alpha, np.random.default_rng(0).normal(size=(61, 3)))
        p.derivative([[0.3, 0.4, alpha - 0.7]], "u")
    finally:
        sys.setprofile(old)
    assert calls["check_alpha"] == 1, calls
    assert calls["check_n"] <= 2, calls  # the patch's own check, and exponent_matrix's on a first n in the process
