"""Python side of issue 16, class 8: paths that cannot reach the C++ side unchanged are
refused as open() refuses them, and noise never returns non-finite coordinates."""
import numpy as np
import pytest

import msmesh

V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
F = np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])


@pytest.mark.parametrize("path", [b"\xff\xfe.obj", b"dir/\xc3(.ply", "a\udcff.obj"])
def test_path_that_is_not_utf8_is_invalid_input(path):
    with pytest.raises(msmesh.InvalidInputError, match="UTF-8"):
        msmesh.read_mesh(path)
    with pytest.raises(msmesh.InvalidInputError, match="UTF-8"):
        msmesh.write_mesh(path, V, F)


@pytest.mark.parametrize("path", ["a.obj\0.ply", b"a.obj\0.ply", "\0"])
def test_nul_byte_in_a_path_is_a_value_error_like_open(tmp_path, path):
    with pytest.raises(ValueError, match="null byte"):
        msmesh.write_mesh(path, V, F)
    with pytest.raises(ValueError, match="null byte"):
        msmesh.read_mesh(path)
    assert not (tmp_path / "a.obj").exists()


def test_utf8_bytes_path_works(tmp_path):
    p = tmp_path / "m\u00e9sh.obj"
    msmesh.write_mesh(str(p).encode(), V, F)
    V2, F2 = msmesh.read_mesh(str(p).encode())
    assert F2.shape == (4, 3)


@pytest.mark.parametrize("sigma", [1e308, 1e200, 1e7, float("inf"), float("nan")])
def test_absurd_sigma_is_refused(sigma):
    with pytest.raises(ValueError, match="sigma"):
        msmesh.add_noise(V, F, sigma=sigma)


def test_noise_that_would_overflow_is_refused():
    with pytest.raises(ValueError):
        msmesh.add_noise(V * 1e300, F, sigma=1e5)


@pytest.mark.parametrize("seed", [2**53 + 1, 2**60, -1])
def test_seed_beyond_the_exact_range_is_refused(seed):
    with pytest.raises(ValueError, match="seed"):
        msmesh.add_noise(V, F, seed=seed)


def test_large_but_finite_sigma_gives_finite_output():
    out = msmesh.add_noise(V, F, sigma=1e5, seed=1)
    assert np.isfinite(out).all()
