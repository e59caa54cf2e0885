"""msmesh.render(), compare(), write_png() and info(): the same pictures and figures as
`msmesh render`, `msmesh compare` and `msmesh info --json`, argument checks, and the library's
defaults. The CLI is found as in test_msmesh.py ($MSMESH_CLI, else next to the build)."""

import json
import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

import msmesh


def cli_path():
    env = os.environ.get("MSMESH_CLI")
    if env:
        return env
    candidate = pathlib.Path(msmesh.__file__).resolve().parents[2] / "msmesh"
    return str(candidate) if candidate.exists() else None


def read_png(path):
    """Decodes a small 8-bit RGB PNG (as msmesh writes them) into an (h, w, 3) uint8 array."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, width, height, idat = 8, 0, 0, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * 3
    out = np.zeros((height, stride), np.int32)
    prev = np.zeros(stride, np.int32)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, np.int32)
        for i in range(stride):
            a = cur[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[i] = (line[i] + p) & 255
        out[y] = cur
        prev = cur
    return out.reshape(height, width, 3).astype(np.uint8)


@pytest.fixture(scope="module")
def fandisk():
    return msmesh.make_shape("fandisk", 3)


def test_render_defaults_and_shape(fandisk):
    V, F = fandisk
    image = msmesh.render(V, F)
    assert image.dtype == np.uint8
    assert image.shape == (600, 800, 3)  # the render table's default size, as `msmesh render`
    assert msmesh.RENDER_PARAMETERS["width"]["defaults"][""] == 800
    assert msmesh.RENDER_PARAMETERS["azimuth"]["range"] == "in [-360, 360]"
    small = msmesh.render(V, F, width=64, height=48)
    assert small.shape == (48, 64, 3)
    assert (small[0, 0] == 255).all()  # white background
    assert (small[24, 32] < 250).any()  # the mesh in the middle


def test_render_up_axis_and_angles(fandisk):
    V, F = fandisk
    base = msmesh.render(V, F, width=80, height=60)
    assert not np.array_equal(base, msmesh.render(V, F, width=80, height=60, up="z"))
    assert np.array_equal(msmesh.render(V, F, width=80, height=60, up="z"),
                          msmesh.render(V, F, width=80, height=60, up="+z"))
    right = msmesh.render(V, F, width=80, height=60, view="right").astype(int)
    turned = msmesh.render(V, F, width=80, height=60, view="front", azimuth=90).astype(int)
    assert np.abs(right - turned).mean() < 0.5
    with pytest.raises(msmesh.InvalidInputError, match="azimuth"):
        msmesh.render(V, F, azimuth=400)
    with pytest.raises(msmesh.InvalidInputError, match="elevation"):
        msmesh.render(V, F, elevation=-91)
    with pytest.raises(msmesh.InvalidInputError, match="up"):
        msmesh.render(V, F, up="w")
    with pytest.raises(msmesh.InvalidInputError, match="view"):
        msmesh.render(V, F, view="sideways")
    with pytest.raises(TypeError, match="unexpected keyword argument 'zoom'"):
        msmesh.render(V, F, zoom=2)


def test_render_colours(fandisk):
    V, F = fandisk
    colors = np.zeros((V.shape[0], 3))
    colors[:, 0] = 1.0
    red = msmesh.render(V, F, width=60, height=60, vertex_colors=colors).astype(int)
    mid = red[30, 30]
    assert mid[0] > mid[1] + 60  # auto shows the colours
    grey = msmesh.render(V, F, width=60, height=60, vertex_colors=colors, color="none").astype(int)
    assert abs(grey[30, 30][0] - grey[30, 30][1]) <= 2
    with pytest.raises(msmesh.InvalidInputError, match="vertex_colors"):
        msmesh.render(V, F, color="file")
    with pytest.raises(msmesh.InvalidInputError, match=r"vertex_colors: row 0 .* outside \[0, 1\]"):
        msmesh.render(V, F, vertex_colors=colors * 2)
    with pytest.raises(msmesh.InvalidInputError, match="one row per vertex"):
        msmesh.render(V, F, vertex_colors=colors[:3])
    # Error colours add a colour bar strip below the picture.
    noisy = msmesh.add_noise(V, F, sigma=0.3, seed=1)
    err = msmesh.render(noisy, F, width=100, height=80, color="error", truth=(V, F))
    assert err.shape[0] > 80 and err.shape[1] == 100
    with pytest.raises(msmesh.InvalidInputError, match="truth"):
        msmesh.render(noisy, F, color="error")


def test_render_equals_the_cli(tmp_path, fandisk):
    cli = cli_path()
    if cli is None:
        pytest.skip("the msmesh program was not found (set MSMESH_CLI)")
    V, F = fandisk
    mesh = tmp_path / "f.ply"
    msmesh.write_mesh(mesh, V, F)
    V, F = msmesh.read_mesh(mesh)
    for args, kwargs in [([], {}),
                         (["--up", "z", "--view", "front", "--azimuth", "20", "--elevation", "10", "--size", "90x70"],
                          dict(up="z", view="front", azimuth=20, elevation=10, width=90, height=70)),
                         (["--feature-edges", "30", "--perspective", "--size", "64x64"],
                          dict(feature_edges=30, perspective=True, width=64, height=64))]:
        out = tmp_path / "cli.png"
        subprocess.run([cli, "render", str(mesh), "-o", str(out), "-q"] + args, check=True)
        py = tmp_path / "py.png"
        msmesh.render(V, F, py, **kwargs)
        assert py.read_bytes() == out.read_bytes(), args  # the encoder is deterministic


def test_compare_scale_from_the_results(tmp_path):
    V, F = msmesh.make_shape("sphere", 2)
    noisy = msmesh.add_noise(V, F, sigma=0.4, seed=2)
    result = msmesh.add_noise(V, F, sigma=0.03, seed=2)
    image, report = msmesh.compare([(noisy, F), (result, F), (V, F)], tmp_path / "s.png", truth=(V, F),
                                   color="error", captions=["noisy", "result", "truth"], width=100, height=100)
    assert image.ndim == 3 and image.shape[1] >= 300
    assert (tmp_path / "s.png").exists()
    assert report["noisy_panel"] == 0
    assert report["saturated"]
    assert "noisy input saturates" in report["scale_note"]
    assert report["error_top"] < report["panels"][0]["mean_angle_deg"]
    _, all_panels = msmesh.compare([(noisy, F), (result, F), (V, F)], truth=(V, F), color="error",
                                   noisy_panel=None, width=100, height=100)
    assert all_panels["noisy_panel"] is None
    assert all_panels["error_top"] > 2 * report["error_top"]
    _, chosen = msmesh.compare([(noisy, F), (result, F)], truth=(V, F), color="error", noisy_panel=1,
                               width=60, height=60)
    assert chosen["noisy_panel"] == 1
    # The defaults are the CLI's: panels of 400x400.
    plain, r = msmesh.compare([(V, F)])
    assert plain.shape[1] == 400 + 16 and r["panels"] == []
    with pytest.raises(msmesh.InvalidInputError, match="noisy_panel"):
        msmesh.compare([(V, F)], noisy_panel=3)
    with pytest.raises(msmesh.InvalidInputError, match="captions"):
        msmesh.compare([(V, F)], captions=["a", "b"])
    with pytest.raises(msmesh.InvalidInputError, match="meshes"):
        msmesh.compare([])
    with pytest.raises(msmesh.InvalidInputError, match=r"meshes\[0\] F"):
        msmesh.compare([(V, F + 1000)])
    with pytest.raises(msmesh.InvalidInputError, match="truth"):
        msmesh.compare([(V, F)], color="error")


def test_compare_equals_the_cli(tmp_path):
    cli = cli_path()
    if cli is None:
        pytest.skip("the msmesh program was not found (set MSMESH_CLI)")
    V, F = msmesh.make_shape("cube", 3)
    noisy = msmesh.add_noise(V, F, sigma=0.3, seed=4)
    for name, mesh in (("clean.ply", V), ("noisy.ply", noisy)):
        msmesh.write_mesh(tmp_path / name, mesh, F)
    V, F = msmesh.read_mesh(tmp_path / "clean.ply")
    noisy, _ = msmesh.read_mesh(tmp_path / "noisy.ply")
    out = tmp_path / "cli.png"
    subprocess.run([cli, "compare", str(tmp_path / "noisy.ply"), str(tmp_path / "clean.ply"), "--truth",
                    str(tmp_path / "clean.ply"), "--color", "error", "--size", "120x100", "--up", "z",
                    "--captions", "noisy,clean", "-o", str(out), "-q"], check=True)
    msmesh.compare([(noisy, F), (V, F)], tmp_path / "py.png", truth=(V, F), color="error", width=120, height=100,
                   up="z", captions=["noisy", "clean"])
    assert (tmp_path / "py.png").read_bytes() == out.read_bytes()


def test_write_png_checks(tmp_path):
    image = np.full((4, 5, 3), 200, np.uint8)
    msmesh.write_png(tmp_path / "a.png", image)
    assert np.array_equal(read_png(tmp_path / "a.png"), image)
    with pytest.raises(msmesh.InvalidInputError, match="uint8"):
        msmesh.write_png(tmp_path / "b.png", image.astype(float))
    with pytest.raises(msmesh.InvalidInputError, match="shape"):
        msmesh.write_png(tmp_path / "b.png", image[:, :, 0])
    with pytest.raises(msmesh.IoError):
        msmesh.write_png(tmp_path / "no" / "such" / "c.png", image)


# ---- info -------------------------------------------------------------------------------------

def test_info_known_shapes():
    V, F = msmesh.make_shape("cube", 2)
    i = msmesh.info(V, F)
    assert i["area"] == pytest.approx(24)
    assert i["volume"] == pytest.approx(8)
    assert i["watertight"] and i["genus"] == 0 and i["euler_characteristic"] == 2
    V, F = msmesh.make_shape("torus", 2)
    assert msmesh.info(V, F)["genus"] == 1
    # An open square: no volume, one boundary loop, genus 0.
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    i = msmesh.info(V, F)
    assert i["volume"] is None and not i["watertight"] and i["boundary_loops"] == 1
    assert i["euler_characteristic"] == 1 and i["genus"] == 0 and i["area"] == pytest.approx(1)
    assert i["component_details"][0]["closed"] is False
    with pytest.raises(msmesh.InvalidInputError, match="F: row 0"):
        msmesh.info(V, [[0, 1, 9]])


def test_info_equals_the_cli(tmp_path):
    cli = cli_path()
    if cli is None:
        pytest.skip("the msmesh program was not found (set MSMESH_CLI)")
    V, F = msmesh.make_shape("holes", 4)
    path = tmp_path / "holes.ply"
    msmesh.write_mesh(path, V, F)
    V, F = msmesh.read_mesh(path)
    out = json.loads(subprocess.run([cli, "info", str(path), "--json"], check=True, capture_output=True,
                                    text=True).stdout)
    mine = msmesh.info(V, F)
    file_only = {"file", "dropped_degenerate_faces", "vertex_colors", "texture_coordinates",
                 "texture_coordinates_with_seams", "vertex_normals"}
    assert set(out) - file_only == set(mine)

    def same(a, b, where):
        if isinstance(b, dict):
            assert set(a) == set(b), where
            for k in b:
                same(a[k], b[k], f"{where}.{k}")
        elif isinstance(b, (list, tuple)):
            assert len(a) == len(b), where
            for i, (x, y) in enumerate(zip(a, b)):
                same(x, y, f"{where}[{i}]")
        elif isinstance(b, float):
            assert a == pytest.approx(b, rel=1e-9, abs=1e-12), where
        else:
            assert a == b and type(a) is type(b), where

    for key, value in mine.items():
        same(out[key], value, key)
