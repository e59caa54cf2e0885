"""Attributes through msmesh.read_mesh / msmesh.write_mesh (docs/python.md, "Files and attributes").

Run as the other Python tests: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests -q
"""

import gzip

import numpy as np
import pytest

import msmesh


def sheet(n=6):
    """A grid with colours, per-corner uv with a seam, materials, groups and a property."""
    xs, ys = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    V = np.c_[xs.ravel(), ys.ravel(), 0.01 * np.sin(7 * xs.ravel())]
    F = []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            F += [(a, a + 1, a + n + 1), (a, a + n + 1, a + n)]
    F = np.array(F, dtype=np.int32)
    left = V[F].mean(axis=1)[:, 0] < 0.5
    order = np.r_[np.flatnonzero(left), np.flatnonzero(~left)]
    F, left = F[order], left[order]
    texcoords = np.r_[V[:, :2] * [0.5, 1], V[:, :2] * [0.5, 1] + [0.5, 0]]
    face_texcoords = F + np.where(left, 0, n * n)[:, None]
    return msmesh.Mesh(
        V=V, F=F,
        vertex_colors=np.tile([[1.0, 0.5, 0.0]], (n * n, 1)),
        texcoords=texcoords, face_texcoords=face_texcoords.astype(np.int32),
        material_names=["left", "right"], face_materials=np.where(left, 0, 1).astype(np.int32),
        group_names=["a", "b"], face_groups=np.where(left, 0, 1).astype(np.int32),
        vertex_properties={"quality": np.arange(n * n) % 200}, vertex_property_types={"quality": "uint8"},
    )


def test_plain_read_mesh_still_returns_v_and_f(tmp_path):
    m = sheet()
    assert msmesh.write_mesh(tmp_path / "m.ply", m.V, m.F) == []
    V, F = msmesh.read_mesh(tmp_path / "m.ply")
    np.testing.assert_array_equal(V, m.V)
    np.testing.assert_array_equal(F, m.F)


def test_obj_round_trip_keeps_seams_materials_and_groups(tmp_path):
    m = sheet()
    lost = msmesh.write_mesh(tmp_path / "m.obj", m)
    assert lost == ["OBJ cannot hold extra vertex properties ('quality'): not written"]
    r = msmesh.read_mesh(tmp_path / "m.obj", attributes=True)
    assert isinstance(r, msmesh.Mesh)
    np.testing.assert_array_equal(r.F, m.F)
    np.testing.assert_array_equal(r.face_texcoords, m.face_texcoords)
    np.testing.assert_array_equal(r.texcoords, m.texcoords)
    np.testing.assert_array_equal(r.vertex_colors, m.vertex_colors)
    assert r.material_names == ["left", "right"] and r.group_names == ["a", "b"]
    np.testing.assert_array_equal(r.face_materials, m.face_materials)
    assert r.uv is None and r.vertex_properties == {}


def test_ply_keeps_face_colours_and_typed_properties(tmp_path):
    m = sheet()
    fc = np.tile([[0.0, 1.0, 0.0, 0.6]], (len(m.F), 1))
    fc[:, 3] = np.round(fc[:, 3] * 255) / 255
    msmesh.write_mesh(tmp_path / "m.ply.gz", m, face_colors=fc, binary=False)
    with gzip.open(tmp_path / "m.ply.gz", "rt") as fh:
        assert "property uchar quality" in fh.read()
    r = msmesh.read_mesh(tmp_path / "m.ply.gz", attributes=True)
    np.testing.assert_allclose(r.face_colors, fc, atol=1e-12)
    np.testing.assert_array_equal(r.vertex_properties["quality"], np.arange(36) % 200)
    assert r.vertex_property_types == {"quality": "uint8"}
    # PLY stores texture coordinates per corner (face `texcoord` lists): the same per corner.
    np.testing.assert_array_equal(r.texcoords[r.face_texcoords], m.texcoords[m.face_texcoords])


def test_glb_keeps_colours_uv_and_materials(tmp_path):
    m = sheet()
    msmesh.write_mesh(tmp_path / "m.glb", m)
    r = msmesh.read_mesh(tmp_path / "m.glb", attributes=True)
    assert r.position_type == "float32"
    assert r.material_names == ["left", "right"]
    assert isinstance(r.gltf_document, bytes) and r.gltf_document[:4] == b"glTF"
    # Denoise the positions and write back: the document (materials) is kept.
    V2, _report = msmesh.denoise(r.V, r.F, preset="smooth")
    r.V = V2
    assert msmesh.write_mesh(tmp_path / "out.glb", r) == []
    back = msmesh.read_mesh(tmp_path / "out.glb", attributes=True)
    np.testing.assert_allclose(back.V, V2, atol=1e-6)
    np.testing.assert_array_equal(back.face_texcoords, r.face_texcoords)
    np.testing.assert_allclose(back.texcoords, r.texcoords, atol=1e-7)
    np.testing.assert_allclose(back.vertex_colors, r.vertex_colors, atol=1e-7)


def test_losses_are_returned_and_bad_attributes_refused(tmp_path):
    m = sheet()
    lost = msmesh.write_mesh(tmp_path / "m.stl", m)
    assert "STL cannot hold vertex colours: not written" in lost
    assert "STL cannot hold materials per face: not written" in lost
    with pytest.raises(msmesh.InvalidInputError, match="face_colors must be empty or #F by 3 or 4"):
        msmesh.write_mesh(tmp_path / "x.ply", m.V, m.F, face_colors=np.zeros((3, 3)))
    with pytest.raises(msmesh.InvalidInputError, match="unknown attribute"):
        msmesh.write_mesh(tmp_path / "x.ply", m.V, m.F, colours=np.zeros((3, 3)))
    assert not (tmp_path / "x.ply").exists()


def test_read_notes_name_what_was_dropped(tmp_path):
    (tmp_path / "l.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n")
    r = msmesh.read_mesh(tmp_path / "l.obj", attributes=True)
    assert r.notes == ["1 OBJ line elements ('l') are not kept"]


def test_corrupt_gzip_is_an_io_error_naming_the_file(tmp_path):
    m = sheet()
    msmesh.write_mesh(tmp_path / "m.obj.gz", m.V, m.F)
    data = (tmp_path / "m.obj.gz").read_bytes()
    (tmp_path / "cut.obj.gz").write_bytes(data[: len(data) // 2])
    with pytest.raises(msmesh.IoError, match="cut.obj.gz: truncated gzip file"):
        msmesh.read_mesh(tmp_path / "cut.obj.gz")
