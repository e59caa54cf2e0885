"""Tests of the msmesh Python package.

Run from the repository root after building with -DMSMESH_BUILD_PYTHON=ON:
    PYTHONPATH=build-py/python /usr/bin/python3 -m pytest python/tests -q
The CLI comparison finds the msmesh program through $MSMESH_CLI, else next to the build's
python/ folder (<build>/msmesh); it is skipped when neither exists.
"""

import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import msmesh


# ---- helpers ----------------------------------------------------------------------------------

def cli_path():
    env = os.environ.get("MSMESH_CLI")
    if env:
        return pathlib.Path(env)
    # <build>/python/msmesh/__init__.py -> <build>/msmesh
    return pathlib.Path(msmesh.__file__).resolve().parents[2] / "msmesh"


def small_tetrahedron():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return V, F


@pytest.fixture(scope="module")
def noisy_fandisk():
    V, F = msmesh.make_shape("fandisk", 6)
    return msmesh.add_noise(V, F, sigma=0.2, seed=7), F, V


def assert_close_relative(a, b, rtol=1e-9):
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape
    scale = max(np.abs(b).max(), 1e-300)
    err = np.abs(a - b).max() / scale
    assert err <= rtol, f"relative difference {err:.3e} > {rtol:.0e}"


# ---- results equal the CLI's ------------------------------------------------------------------

CLI_CASES = [
    ("cad", "nmstv", {}),
    ("smooth", "mstv", {"rho": 0.5, "normal_iterations": 12, "vertex_iterations": 8, "omega3": 0.05, "nu": 1.2}),
    ("auto", "nmstv", {"alpha": 3.0, "beta": 0.05, "v0": 0.5}),
    ("cad", "bilateral", {"sigma_r": 0.3, "bilateral_iterations": 5, "vertex_iterations": 7}),
    ("paper", "nmstv", {"prefilter": 2}),
    ("auto", "nmstv", {"strength": 2.5}),
]


@pytest.mark.parametrize("preset,method,params", CLI_CASES)
def test_denoise_equals_cli(tmp_path, noisy_fandisk, preset, method, params):
    cli = cli_path()
    if not cli.exists():
        pytest.skip(f"CLI not found at {cli} (set MSMESH_CLI)")
    V, F, _ = noisy_fandisk
    noisy, out = tmp_path / "noisy.ply", tmp_path / "out.ply"
    msmesh.write_mesh(noisy, V, F)  # binary PLY holds doubles: an exact round trip
    V_read, F_read = msmesh.read_mesh(noisy)
    np.testing.assert_array_equal(V_read, V)
    np.testing.assert_array_equal(F_read, F)

    args = [str(cli), "denoise", str(noisy), "-o", str(out), "--preset", preset, "--method", method, "-q"]
    for name, value in params.items():
        args += ["--" + name.replace("_", "-"), repr(value)]
    subprocess.run(args, check=True, capture_output=True, timeout=300)
    V_cli, F_cli = msmesh.read_mesh(out)

    V_py, report = msmesh.denoise(V, F, preset=preset, method=method, **params)
    np.testing.assert_array_equal(F_cli, F)
    assert_close_relative(V_py, V_cli)
    assert report["method"] == method
    assert report["preset"] in ("cad", "smooth", "paper")
    if preset != "auto":
        assert report["preset"] == preset


def test_choose_preset_counts_creases_on_lines(noisy_fandisk):
    V, F, V_truth = noisy_fandisk
    c = msmesh.choose_preset(V_truth, F)  # the clean fandisk: its creases are long lines
    assert c["preset"] == "cad", c["reason"]
    assert c["sharp_fraction"] > 0 and c["crease_line_fraction"] == pytest.approx(c["sharp_fraction"], rel=0.05)
    assert "on lines of 40 edges or more" in c["reason"]


def test_noise_estimate_and_strength(noisy_fandisk):
    V, F, V_truth = noisy_fandisk
    e = msmesh.estimate_noise(V, F)  # seeded sigma 0.2 along the normals
    assert 0.14 < e["sigma"] < 0.3 and e["sigma_rms"] >= e["sigma"] * 0.9
    assert "noise sigma" in e["summary"]
    assert e["sigma"] ** 2 == pytest.approx(e["sigma_noise"] ** 2 + e["detail"] ** 2)
    _, r = msmesh.denoise(V, F)
    assert r["noise_sigma_rms"] == pytest.approx(e["sigma_rms"]) and r["strength"] == 1.0
    assert r["noise_sigma_noise"] == pytest.approx(e["sigma_noise"]) and r["noise_detail"] == pytest.approx(e["detail"])
    assert 0 < e["across_ratio"] < 1 and r["noise_across_ratio"] == pytest.approx(e["across_ratio"])  # along the normals
    assert "noise sigma" in r["preset_reason"]
    assert 0 <= r["auto_crease_line_fraction"] <= r["auto_sharp_fraction"]
    assert 0 <= r["auto_steep_line_fraction"] <= r["auto_crease_line_fraction"]
    _, r2 = msmesh.denoise(V, F, strength=3.0)
    assert r2["noise_level_used"] == pytest.approx(3.0 * r["noise_level_used"])
    assert r2["parameters"]["alpha"] <= r["parameters"]["alpha"]
    for bad in (0.0, 11.0, float("nan"), "2"):
        with pytest.raises(msmesh.InvalidInputError, match="strength"):
            msmesh.denoise(V, F, strength=bad)
    with pytest.raises(msmesh.InvalidInputError, match="strength"):
        msmesh.denoise(V, F, method="bilateral", strength=2.0)
    S = msmesh.taubin_smooth(V, F, iterations=3)
    assert S.shape == V.shape and np.isfinite(S).all()
    np.testing.assert_array_equal(msmesh.taubin_smooth(V, F, iterations=0), V)


def test_a_featureless_surface_is_reported():
    V, F = msmesh.make_shape("torus", 16)
    noisy = msmesh.add_noise(V, F, sigma=0.1, seed=3)
    _, r = msmesh.denoise(noisy, F)
    assert r["auto_featureless"] is True and r["preset"] == "cad", r["preset_reason"]
    assert r["auto_quadric_excess"] < r["auto_featureless_limit"]
    assert "featureless" in r["preset_reason"]
    C, G = msmesh.make_shape("cube", 12)
    _, c = msmesh.denoise(msmesh.add_noise(C, G, sigma=0.1, seed=3), G)
    assert c["auto_featureless"] is False


def test_a_second_round_under_heavy_noise():
    # Auto runs a second round on its result under heavy noise (weight 1 from sigma_rms 0.4), the
    # same as the CLI's; the caller's parameters reach both rounds.
    V, F = msmesh.make_shape("cube", 12)
    noisy = msmesh.add_noise(V, F, sigma=0.7, seed=3)
    W, r = msmesh.denoise(noisy, F)
    assert r["auto_second_round"] == 1.0, r["preset_reason"]
    assert r["second_round_reason"].startswith("chosen automatically")
    one, _ = msmesh.denoise(noisy, F, preset=r["preset"], **r["parameters"])
    again, _ = msmesh.denoise(one, F)
    np.testing.assert_allclose(W, again, atol=1e-12)
    _, light = msmesh.denoise(msmesh.add_noise(V, F, sigma=0.1, seed=3), F)
    assert light["auto_second_round"] == 0.0 and "second_round_reason" not in light


def test_small_components_are_kept_and_reported():
    S, G = msmesh.make_shape("sphere", 8)
    C, H = msmesh.make_shape("cube", 1)  # 12 triangles
    V = np.vstack([S, C + [4.0, 0.0, 0.0]])
    F = np.vstack([G, H + len(S)])
    noisy = msmesh.add_noise(V, F, sigma=0.05, seed=3)
    out, r = msmesh.denoise(noisy, F)
    assert r["kept_components"] == 1 and r["kept_faces"] == 12
    assert "without the 12 faces of 1 component(s)" in r["preset_reason"]
    np.testing.assert_array_equal(out[len(S):], noisy[len(S):])
    assert np.abs(out[: len(S)] - noisy[: len(S)]).max() > 1e-4
    every, e = msmesh.denoise(noisy, F, min_component_faces=0)
    assert e["kept_components"] == 0 and e["kept_faces"] == 0
    assert np.abs(every[len(S):] - noisy[len(S):]).max() > 1e-4


def test_unreachable_targets_are_reported():
    V, F = msmesh.make_shape("fandisk", 16)
    noisy = msmesh.add_noise(V, F, sigma=0.25, seed=3)  # one round (no second round below 0.3)
    out, r = msmesh.denoise(noisy, F)
    assert r["preset"] == "cad" and r["parameters"]["unreachable_angle"] == 10
    assert 0 < r["unreachable_faces"] < len(F) // 50
    np.testing.assert_allclose(np.linalg.norm(r["normals"], axis=1), 1.0, atol=1e-9)
    off, o = msmesh.denoise(noisy, F, unreachable_angle=0)
    assert o["unreachable_faces"] == 0
    err = msmesh.evaluate(out, F, V, F)["msae"]
    err_off = msmesh.evaluate(off, F, V, F)["msae"]
    assert err < 0.9 * err_off


def test_jet_fitted_targets_are_reported():
    V, F = msmesh.make_shape("torus", 16)
    noisy = msmesh.add_noise(V, F, sigma=0.1, seed=3)
    out, r = msmesh.denoise(noisy, F)
    assert r["jet_faces"] > len(F) // 2
    assert r["parameters"]["jet_rings"] == 3
    off, o = msmesh.denoise(noisy, F, jet_rings=0)
    assert o["jet_faces"] == 0
    err = msmesh.evaluate(out, F, V, F)["msae"]
    err_off = msmesh.evaluate(off, F, V, F)["msae"]
    assert err < err_off, (err, err_off)


def test_correlated_noise_reads_scan_like(tmp_path):
    V, F = msmesh.make_shape("pyramid", 24)
    white = msmesh.add_noise(V, F, sigma=0.2, seed=11)
    noisy = msmesh.add_noise(V, F, sigma=0.2, seed=11, correlation=2)
    # Same RMS length as the white draw it was averaged from, but neighbours move alike.
    assert np.linalg.norm(noisy - V) == pytest.approx(np.linalg.norm(white - V), rel=1e-9)
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    across = lambda X: np.linalg.norm((X - V)[E[:, 0]] - (X - V)[E[:, 1]])  # noqa: E731
    assert across(noisy) < 0.5 * across(white)
    _, r = msmesh.denoise(noisy, F)
    assert "detail counted 3.00 times" in r["preset_reason"], r["preset_reason"]
    assert r["noise_detail_as_noise"] == 1.0
    assert r["noise_level_used"] > 1.5 * r["noise_sigma_rms"]
    cli = cli_path()
    if cli.exists():  # the same noise as `msmesh noise --correlation`
        src, out = tmp_path / "p.ply", tmp_path / "n.ply"
        msmesh.write_mesh(src, V, F)
        subprocess.run([str(cli), "noise", str(src), "-o", str(out), "--sigma", "0.2", "--seed", "11",
                        "--correlation", "2", "-q"], check=True, capture_output=True, timeout=60)
        np.testing.assert_array_equal(msmesh.read_mesh(out)[0], noisy)
    for bad in (-1, 1001, 1.5):
        with pytest.raises(msmesh.InvalidInputError, match="correlation"):
            msmesh.add_noise(V, F, correlation=bad)
    with pytest.raises(msmesh.InvalidInputError, match="impulsive"):
        msmesh.add_noise(V, F, impulsive=0.1, correlation=2)


def test_denoise_report(noisy_fandisk):
    V, F, V_truth = noisy_fandisk
    V_new, r = msmesh.denoise(V, F, preset="cad", normal_iterations=10, vertex_iterations=10)
    assert V_new.shape == V.shape and V_new.dtype == np.float64 and V_new.flags.c_contiguous
    assert r["normals"].shape == F.shape
    assert r["v"].shape == (r["edges"].shape[0],)
    assert 1 <= r["normal_iterations"] <= 10
    # at most 10 per vertex update: one more after jet-fitted targets
    assert 1 <= r["vertex_iterations"] <= (20 if r["jet_faces"] else 10)
    assert len(r["residual_history"]) == r["normal_iterations"]
    assert len(r["vertex_change_history"]) == r["vertex_iterations"]
    assert r["parameters"]["normal_iterations"] == 10
    assert r["parameters"]["rho"] == msmesh._core.preset_options("cad").normals.rho
    assert r["seconds_total"] >= 0
    np.testing.assert_allclose(np.linalg.norm(r["normals"], axis=1), 1.0, atol=1e-9)
    before = msmesh.evaluate(V, F, V_truth, F)
    after = msmesh.evaluate(V_new, F, V_truth, F)
    assert after["same_connectivity"] and after["msae"] < before["msae"]
    assert after["msae_e3"] == pytest.approx(after["msae"] * 1e3)


def test_inputs_are_not_modified(noisy_fandisk):
    V, F, _ = noisy_fandisk
    V0, F0 = V.copy(), F.copy()
    msmesh.denoise(V, F, normal_iterations=2, vertex_iterations=2)
    np.testing.assert_array_equal(V, V0)
    np.testing.assert_array_equal(F, F0)


def test_filter_then_update_matches_denoise(noisy_fandisk):
    V, F, _ = noisy_fandisk
    params = {"normal_iterations": 8}
    N, v, nr = msmesh.filter_normals(V, F, preset="cad", **params)
    V_two, vr = msmesh.update_vertices(V, F, N, np.clip(v, 0, 1), preset="cad", vertex_iterations=6)
    # (planes=0, jet_rings=0, unreachable_angle=0: denoise's planar regions, jet-fitted and
    # dropped targets, between and after the two stages, would change the targets)
    V_one, r = msmesh.denoise(V, F, preset="cad", vertex_iterations=6, planes=0, jet_rings=0, unreachable_angle=0,
                              **params)
    assert_close_relative(N, r["normals"])
    assert_close_relative(V_two, V_one)
    assert nr["normal_iterations"] == r["normal_iterations"]
    assert vr["vertex_iterations"] == r["vertex_iterations"]


def test_accepts_lists_float_faces_and_int64(tmp_path):
    V, F = small_tetrahedron()
    a = msmesh.add_noise(V.tolist(), F.tolist(), sigma=0.1, seed=3)
    b = msmesh.add_noise(V.astype(np.float32).astype(float), F.astype(np.float64), sigma=0.1, seed=3)
    c = msmesh.add_noise(np.asfortranarray(V), F.astype(np.int64), sigma=0.1, seed=3)
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(a, c)
    d = msmesh.add_noise(V, F, sigma=0.1, seed=4)
    assert not np.array_equal(a, d)


# ---- the validation layer -----------------------------------------------------------------------

def bad_inputs():
    V, F = small_tetrahedron()
    nan_V = V.copy()
    nan_V[2, 1] = np.nan
    inf_V = V.copy()
    inf_V[0, 0] = np.inf
    return [
        ("V wrong shape", V[:, :2], F, "V: shape"),
        ("V 1-d", V.ravel(), F, "V: shape"),
        ("F wrong shape", V, F[:, :2], "F: shape"),
        ("V NaN", nan_V, F, "V: row 2 is not finite"),
        ("V Inf", inf_V, F, "V: row 0 is not finite"),
        ("index out of range", V, np.vstack([F, [1, 2, 4]]), "out of range"),
        ("negative index", V, np.vstack([F, [-1, 2, 3]]), "out of range"),
        ("float faces", V, F + 0.5, "non-integer"),
        ("NaN faces", V, np.where(F == 3, np.nan, F), "non-integer"),
        ("int64 too big", V, np.vstack([F, [0, 1, 2**40]]).astype(np.int64), "int32"),
        ("repeated vertex", V, np.vstack([F, [1, 1, 2]]), "repeats a vertex"),
        ("empty V", np.zeros((0, 3)), np.zeros((0, 3), int), "V: is empty"),
        ("empty F", V, np.zeros((0, 3), int), "F: is empty"),
        ("string V", np.array([["a", "b", "c"]]), F, "dtype"),
        ("bool F", V, F > 1, "dtype"),
    ]


@pytest.mark.parametrize("label,V,F,message", bad_inputs(), ids=[b[0] for b in bad_inputs()])
@pytest.mark.parametrize("call", [
    lambda V, F: msmesh.denoise(V, F),
    lambda V, F: msmesh.add_noise(V, F),
    lambda V, F: msmesh.filter_normals(V, F),
    lambda V, F: msmesh.evaluate(V, F, V, F),
], ids=["denoise", "add_noise", "filter_normals", "evaluate"])
def test_bad_arrays_raise_value_error(label, V, F, message, call):
    with pytest.raises(ValueError, match=message) as info:
        call(V, F)
    assert isinstance(info.value, msmesh.InvalidInputError)


def test_bad_parameters():
    V, F = small_tetrahedron()
    with pytest.raises(ValueError, match="preset"):
        msmesh.denoise(V, F, preset="sharp")
    with pytest.raises(ValueError, match="method"):
        msmesh.denoise(V, F, method="tv")
    with pytest.raises(TypeError, match="unexpected keyword argument 'alhpa'"):
        msmesh.denoise(V, F, alhpa=1.0)
    with pytest.raises(TypeError, match="omega1"):
        msmesh.filter_normals(V, F, omega1=1.0)  # a vertex-update parameter
    with pytest.raises(ValueError, match="normal_iterations"):
        msmesh.denoise(V, F, normal_iterations=2.5)
    with pytest.raises(ValueError, match="alpha"):
        msmesh.denoise(V, F, alpha=float("nan"))
    with pytest.raises(ValueError, match="alpha"):  # range checked by the library's validate()
        msmesh.denoise(V, F, alpha=-1.0)
    with pytest.raises(ValueError, match="sigma"):
        msmesh.add_noise(V, F, sigma=-0.1)
    with pytest.raises(ValueError, match="direction"):
        msmesh.add_noise(V, F, direction="up")
    with pytest.raises(ValueError, match="seed"):
        msmesh.add_noise(V, F, seed=-1)
    with pytest.raises(ValueError, match="N: must have one row per face"):
        msmesh.update_vertices(V, F, np.ones((3, 3)))
    with pytest.raises(ValueError, match="progress"):
        msmesh.denoise(V, F, progress=42)
    with pytest.raises(ValueError, match="name"):
        msmesh.make_shape("teapot", 4)
    with pytest.raises(ValueError, match="resolution"):
        msmesh.make_shape("cube", 0)


# ---- files ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("ext,binary", [("ply", True), ("ply", False), ("obj", True), ("off", True)])
def test_write_read_round_trip(tmp_path, ext, binary):
    V, F = msmesh.make_shape("sphere", 2)
    path = tmp_path / f"mesh.{ext}"
    msmesh.write_mesh(path, V, F, binary=binary)
    V2, F2 = msmesh.read_mesh(str(path))
    np.testing.assert_array_equal(F2, F)
    np.testing.assert_allclose(V2, V, rtol=0, atol=1e-15)


def test_io_errors_are_oserrors(tmp_path):
    with pytest.raises(OSError) as info:
        msmesh.read_mesh(tmp_path / "missing.obj")
    assert isinstance(info.value, msmesh.IoError) and isinstance(info.value, msmesh.Error)
    assert "missing.obj" in str(info.value)
    V, F = small_tetrahedron()
    with pytest.raises(OSError):
        msmesh.write_mesh(tmp_path / "mesh.xyz", V, F)
    with pytest.raises(OSError):
        msmesh.write_mesh(tmp_path / "no_such_folder" / "mesh.ply", V, F)


def test_exception_hierarchy():
    assert issubclass(msmesh.InvalidInputError, ValueError)
    assert issubclass(msmesh.IoError, OSError)
    assert issubclass(msmesh.SolverError, RuntimeError)
    for cls in (msmesh.InvalidInputError, msmesh.IoError, msmesh.SolverError, msmesh.Cancelled):
        assert issubclass(cls, msmesh.Error)


# ---- evaluate, noise and shapes ------------------------------------------------------------------

def test_evaluate():
    V, F = msmesh.make_shape("cube", 4)
    e = msmesh.evaluate(V, F, V, F)
    assert e["same_connectivity"]
    assert e["msae"] == 0 and e["flipped"] == 0 and e["distance_max"] == pytest.approx(0, abs=1e-12)
    e = msmesh.evaluate(V, F[::-1], V, F)  # faces listed in another order
    assert not e["same_connectivity"] and e["msae"] is None
    e = msmesh.evaluate(V, F[:, ::-1], V, F)  # every face reversed: all flipped
    assert e["same_connectivity"] and e["flipped"] == F.shape[0]
    assert e["truth_folded"] == 0 and e["flipped_outside_folds"] == F.shape[0]
    T = F.copy()
    T[5] = T[5][[0, 2, 1]]  # the truth turns one face over: the result's flat face there is no error of its own
    e = msmesh.evaluate(V, F, V, T)
    assert e["flipped"] == 1 and e["truth_folded"] == 1
    assert e["flipped_outside_folds"] == 0 and e["msae_outside_folds_e3"] == pytest.approx(0, abs=1e-12)


def test_add_noise_is_seeded():
    V, F = msmesh.make_shape("torus", 3)
    a = msmesh.add_noise(V, F, sigma=0.3, direction="random", seed=11)
    b = msmesh.add_noise(V, F, sigma=0.3, direction="random", seed=11)
    np.testing.assert_array_equal(a, b)
    moved = np.linalg.norm(a - V, axis=1) > 0
    assert moved.all()
    c = msmesh.add_noise(V, F, sigma=1.0, impulsive=0.1, seed=11)
    moved = np.linalg.norm(c - V, axis=1) > 0
    assert 0 < moved.sum() < V.shape[0]


def test_shapes():
    for name in msmesh.shape_names():
        V, F = msmesh.make_shape(name, 3)
        assert V.ndim == 2 and V.shape[1] == 3 and F.shape[1] == 3 and F.dtype == np.int32
        assert F.min() >= 0 and F.max() < V.shape[0]


# ---- progress, cancellation and the GIL ---------------------------------------------------------

def test_progress_is_called(noisy_fandisk):
    V, F, _ = noisy_fandisk
    events = []
    msmesh.denoise(V, F, normal_iterations=4, vertex_iterations=3, progress=events.append)
    assert events and all(isinstance(e, msmesh.ProgressEvent) for e in events)
    stages = {e.stage for e in events}
    assert len(stages) >= 2, stages
    assert max(e.iteration for e in events) >= 3
    assert "ProgressEvent(stage=" in repr(events[0])


@pytest.mark.parametrize("method", ["nmstv", "bilateral"])
def test_progress_false_cancels(noisy_fandisk, method):
    V, F, _ = noisy_fandisk
    calls = []

    def stop_at_second(event):
        calls.append(event)
        return len(calls) < 2

    with pytest.raises(msmesh.Cancelled):
        msmesh.denoise(V, F, method=method, progress=stop_at_second)
    assert len(calls) == 2
    with pytest.raises(msmesh.Cancelled):
        msmesh.filter_normals(V, F, progress=lambda e: False)
    with pytest.raises(msmesh.Cancelled):
        msmesh.update_vertices(V, F, np.tile([0.0, 0.0, 1.0], (F.shape[0], 1)), progress=lambda e: False)


def test_progress_exception_propagates(noisy_fandisk):
    V, F, _ = noisy_fandisk

    def boom(event):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        msmesh.denoise(V, F, progress=boom)


def test_gil_is_released():
    V, F = msmesh.make_shape("cube", 40)
    V = msmesh.add_noise(V, F, sigma=0.2, seed=1)

    # How fast this thread counts when it has the interpreter to itself.
    count, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < 0.2:
        count += 1
    rate = count / (time.perf_counter() - t0)

    result = {}
    worker = threading.Thread(target=lambda: result.update(
        out=msmesh.denoise(V, F, preset="cad", normal_iterations=10, vertex_iterations=10)))
    count = 0
    t0 = time.perf_counter()
    worker.start()
    while worker.is_alive():
        count += 1
    elapsed = time.perf_counter() - t0
    worker.join()

    assert "out" in result
    assert elapsed > 0.2, "denoise finished too fast to tell"
    # With the GIL held for the whole call, this loop would stall until it returned. The
    # machine may be busy (the library's own threads share the cores): ask for 5% of the rate.
    assert count > 0.05 * rate * elapsed, f"counted {count} in {elapsed:.2f} s at {rate:.0f}/s alone"


# ---- applications (bound when the library has them) ---------------------------------------------

needs_segment = pytest.mark.skipif(not hasattr(msmesh, "segment"), reason="built without segment.h")
needs_inpaint = pytest.mark.skipif(not hasattr(msmesh, "inpaint"), reason="built without inpaint.h")


@needs_segment
def test_segment_and_feature_lines():
    V, F = msmesh.make_shape("cube", 4)
    labels, r = msmesh.segment(V, F)
    assert labels.shape == (F.shape[0],) and labels.dtype == np.int32
    assert r["count"] == 6 == len(np.unique(labels)) == r["areas"].shape[0]
    assert r["v"].shape == (r["edges"].shape[0],)
    lines = msmesh.feature_lines(V, F, r["v_normalized"], threshold=0.5)
    assert lines and all(line.dtype == np.int32 and line.size >= 2 for line in lines)
    assert len(msmesh.feature_lines(V, F)) == len(lines)  # v from filter_normals, as the CLI
    assert msmesh.rand_index(labels, labels) == 1.0
    with pytest.raises(ValueError, match="angle = 200"):
        msmesh.segment(V, F, angle=200.0)
    with pytest.raises(msmesh.Cancelled):
        msmesh.segment(V, F, progress=lambda e: False)


@needs_segment
def test_segment_equals_cli(tmp_path, noisy_fandisk):
    cli = cli_path()
    if not cli.exists():
        pytest.skip(f"CLI not found at {cli} (set MSMESH_CLI)")
    V, F, _ = noisy_fandisk
    msmesh.write_mesh(tmp_path / "in.ply", V, F)
    subprocess.run([str(cli), "segment", str(tmp_path / "in.ply"), "-o", str(tmp_path / "out.ply"), "--labels",
                    str(tmp_path / "labels.txt"), "--denoise", "--angle", "20", "-q"],
                   check=True, capture_output=True, timeout=300)
    labels_cli = np.loadtxt(tmp_path / "labels.txt", dtype=np.int64)
    labels, r = msmesh.segment(V, F, denoise=True, angle=20)
    np.testing.assert_array_equal(labels, labels_cli)
    assert r["V_denoised"].shape == V.shape


@needs_inpaint
def test_inpaint_fills_punched_holes():
    V, F = msmesh.make_shape("cube", 6)
    Vh, Fh, info = msmesh.punch_holes(V, F, count=2, radius=1.5, seed=3)
    assert info["punched"] == 2 and Fh.shape[0] < F.shape[0]
    holes = msmesh.find_holes(Vh, Fh)
    assert len(holes) == 2 and all(h["loop"].dtype == np.int32 for h in holes)
    V2, F2, r = msmesh.inpaint(Vh, Fh, normal_iterations=10, vertex_iterations=10)
    assert r["filled"] == 2 and [h["action"] for h in r["holes"]] == ["filled", "filled"]
    assert F2.shape[0] > Fh.shape[0] and r["new_faces"].sum() == F2.shape[0] - Fh.shape[0]
    np.testing.assert_array_equal(V2[: Vh.shape[0]], Vh)  # input vertices stay put
    assert msmesh.find_holes(V2, F2) == []
    e = msmesh.inpaint_errors(Vh, Fh, V2, F2, V, F)
    assert e["points"] > 0 and 0 <= e["distance_max"] < 0.2  # a sanity bound; quality is tested in C++


def test_solver_choice_gives_the_same_result():
    V, F = msmesh.make_shape("cube", 6)
    Vn = msmesh.add_noise(V, F, sigma=0.2, seed=3)
    # Both at 1e-10: at the default tolerance the v-step may stop at its Jacobi guess (about
    # 4 epsilon^2 from the solution), whichever solver the N-step takes.
    a, ra = msmesh.denoise(Vn, F, preset="cad", solver="cholesky", solver_tolerance=1e-10)
    b, rb = msmesh.denoise(Vn, F, preset="cad", solver="cg", solver_tolerance=1e-10)
    assert np.abs(a - b).max() < 1e-6
    assert sum(rb["n_solver_iterations"]) > 0 and sum(ra["n_solver_iterations"]) == 0
    assert sum(rb["vertex_solver_iterations"]) > 0
    with pytest.raises(msmesh.InvalidInputError, match="solver"):
        msmesh.denoise(Vn, F, solver="lu")


def test_threads_setting_applies_to_every_thread_and_keeps_results():
    V, F = msmesh.make_shape("fandisk", 10)
    Vn = msmesh.add_noise(V, F, sigma=0.2, seed=5)
    default = msmesh.threads()
    assert default >= 1
    try:
        msmesh.set_threads(1)
        assert msmesh.threads() == 1
        seen = []
        worker = threading.Thread(target=lambda: seen.append(msmesh.threads()))
        worker.start()
        worker.join()
        assert seen == [1]  # process-wide for Python, not only the calling thread
        one, _ = msmesh.denoise(Vn, F, preset="cad")
        msmesh.set_threads(2)
        two, _ = msmesh.denoise(Vn, F, preset="cad")
        assert np.array_equal(one, two)  # the same bits for any thread count
        for bad in (-1, 4097, 1.5, True, "2"):
            with pytest.raises(msmesh.InvalidInputError, match="threads"):
                msmesh.set_threads(bad)
        assert msmesh.threads() == 2  # a refused value changes nothing
    finally:
        msmesh.set_threads(0)
    assert msmesh.threads() == default
