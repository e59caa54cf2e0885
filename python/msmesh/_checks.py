"""Input checks of the msmesh package: turn array-likes into the exact arrays the compiled
module expects, or raise InvalidInputError (a ValueError) naming the argument, the element and
the value. Everything here runs before any C++ is called."""

import numbers
import operator
import os

import numpy as np

from ._core import InvalidInputError

_INT32_MIN = np.iinfo(np.int32).min
_INT32_MAX = np.iinfo(np.int32).max


def _as_array(x, name):
    if x is None:
        raise InvalidInputError(f"{name}: expected an array, got None")
    try:
        return np.asarray(x)
    except Exception as exc:  # ragged lists and the like
        raise InvalidInputError(f"{name}: cannot be read as an array ({exc})") from None


def _check_matrix_shape(a, name, columns, allow_empty):
    if a.ndim != 2 or a.shape[1] != columns:
        raise InvalidInputError(f"{name}: shape must be (n, {columns}), got {a.shape}")
    if a.shape[0] == 0 and not allow_empty:
        raise InvalidInputError(f"{name}: is empty (shape {a.shape})")


def _first_bad_row(mask):
    """Row index of the first True entry of a boolean matrix or vector."""
    flat = int(np.flatnonzero(mask.reshape(mask.shape[0], -1).any(axis=1))[0])
    return flat


def real_matrix(x, name, columns=3, allow_empty=False):
    """(n, columns) C-contiguous float64 array of finite values."""
    a = _as_array(x, name)
    if a.dtype == np.bool_ or not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise InvalidInputError(f"{name}: dtype must be real numbers, got {a.dtype}")
    _check_matrix_shape(a, name, columns, allow_empty)
    a = np.ascontiguousarray(a, dtype=np.float64)
    bad = ~np.isfinite(a)
    if bad.any():
        row = _first_bad_row(bad)
        raise InvalidInputError(f"{name}: row {row} is not finite: {a[row].tolist()}")
    return a


def real_vector(x, name, length=None):
    """(length,) C-contiguous float64 array of finite values (any length when None)."""
    a = _as_array(x, name)
    if a.dtype == np.bool_ or not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise InvalidInputError(f"{name}: dtype must be real numbers, got {a.dtype}")
    if a.ndim != 1 or (length is not None and a.shape[0] != length):
        raise InvalidInputError(f"{name}: shape must be ({'n' if length is None else length},), got {a.shape}")
    a = np.ascontiguousarray(a, dtype=np.float64)
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size:
        raise InvalidInputError(f"{name}: entry {int(bad[0])} is not finite: {a[bad[0]]}")
    return a


def faces(x, num_vertices, name="F", allow_empty=False, allow_repeated=False):
    """(n, 3) C-contiguous int32 array of valid triangle indices into num_vertices vertices.

    Integer arrays must fit in int32; float arrays must hold whole numbers."""
    a = _as_array(x, name)
    if a.dtype == np.bool_:
        raise InvalidInputError(f"{name}: dtype must be integer, got bool")
    _check_matrix_shape(a, name, 3, allow_empty)
    if np.issubdtype(a.dtype, np.integer):
        if a.size and (a.min() < _INT32_MIN or a.max() > _INT32_MAX):
            raise InvalidInputError(f"{name}: indices do not fit in int32 (range {a.min()}..{a.max()})")
    elif np.issubdtype(a.dtype, np.floating):
        bad = ~np.isfinite(a) | (a != np.round(a)) if a.size else np.zeros(a.shape, bool)
        if bad.any():
            row = _first_bad_row(bad)
            raise InvalidInputError(f"{name}: row {row} holds non-integer indices: {a[row].tolist()}")
    else:
        raise InvalidInputError(f"{name}: dtype must be integer, got {a.dtype}")
    if a.size:
        out_of_range = (a < 0) | (a >= num_vertices)
        if out_of_range.any():
            row = _first_bad_row(out_of_range)
            raise InvalidInputError(
                f"{name}: row {row} = {a[row].astype(np.int64).tolist()} has an index out of range [0, {num_vertices})")
    a = np.ascontiguousarray(a, dtype=np.int32)
    if a.size and not allow_repeated:
        repeated = (a[:, 0] == a[:, 1]) | (a[:, 1] == a[:, 2]) | (a[:, 0] == a[:, 2])
        if repeated.any():
            row = int(np.flatnonzero(repeated)[0])
            raise InvalidInputError(f"{name}: face {row} = {a[row].tolist()} repeats a vertex")
    return a


def labels(x, name):
    """(n,) int32 array of non-negative labels."""
    a = _as_array(x, name)
    if a.ndim != 1:
        raise InvalidInputError(f"{name}: shape must be (n,), got {a.shape}")
    if a.dtype == np.bool_ or not np.issubdtype(a.dtype, np.integer):
        raise InvalidInputError(f"{name}: dtype must be integer, got {a.dtype}")
    if a.size and (a.min() < 0 or a.max() > _INT32_MAX):
        raise InvalidInputError(f"{name}: labels must be in [0, {_INT32_MAX}], got {a.min()}..{a.max()}")
    return np.ascontiguousarray(a, dtype=np.int32)


def mesh(V, F, prefix="", allow_empty_faces=False):
    """Checked (V, F): V (n, 3) float64, F (m, 3) int32 indexing V."""
    V = real_matrix(V, prefix + "V")
    F = faces(F, V.shape[0], prefix + "F", allow_empty=allow_empty_faces)
    return V, F


def real(value, name, minimum=None):
    """A finite Python float (bools rejected)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InvalidInputError(f"{name}: must be a real number, got {value!r}")
    value = float(value)
    if not np.isfinite(value):
        raise InvalidInputError(f"{name}: must be finite, got {value}")
    if minimum is not None and value < minimum:
        raise InvalidInputError(f"{name}: must be >= {minimum}, got {value}")
    return value


def integer(value, name, minimum=None, maximum=_INT32_MAX):
    """A Python int (bools and floats with a fraction rejected)."""
    if isinstance(value, bool):
        raise InvalidInputError(f"{name}: must be an integer, got {value!r}")
    if isinstance(value, numbers.Integral):
        value = int(value)
    elif isinstance(value, numbers.Real) and float(value).is_integer():
        value = int(value)
    else:
        try:
            value = operator.index(value)
        except TypeError:
            raise InvalidInputError(f"{name}: must be an integer, got {value!r}") from None
    if minimum is not None and value < minimum:
        raise InvalidInputError(f"{name}: must be >= {minimum}, got {value}")
    if maximum is not None and value > maximum:
        raise InvalidInputError(f"{name}: must be <= {maximum}, got {value}")
    return value


def boolean(value, name):
    if not isinstance(value, (bool, np.bool_)):
        raise InvalidInputError(f"{name}: must be True or False, got {value!r}")
    return bool(value)


def choice(value, name, valid):
    if not isinstance(value, str) or value not in valid:
        raise InvalidInputError(f"{name}: must be one of {', '.join(valid)}; got {value!r}")
    return value


def path(value, name="path"):
    try:
        p = os.fspath(value)
    except TypeError:
        raise InvalidInputError(f"{name}: must be a str or os.PathLike, got {type(value).__name__}") from None
    if isinstance(p, bytes):
        p = os.fsdecode(p)  # undecodable bytes become lone surrogates, refused below
    if not p:
        raise InvalidInputError(f"{name}: is empty")
    if "\0" in p:  # as open(): the C++ side would stop at the NUL and use another file
        raise InvalidInputError(f"{name}: embedded null byte in {p!r}")
    try:
        p.encode("utf-8")
    except UnicodeEncodeError:
        raise InvalidInputError(f"{name}: {p!r} is not valid UTF-8; msmesh takes UTF-8 file names "
                                "(rename the file, or pass a str)") from None
    return p


def progress(value):
    if value is not None and not callable(value):
        raise InvalidInputError(f"progress: must be callable or None, got {type(value).__name__}")
    return value


def colors(x, num_rows, name="vertex_colors"):
    """(num_rows, 3) float64 RGB array with values in [0, 1], or None."""
    if x is None:
        return None
    a = real_matrix(x, name, allow_empty=num_rows == 0)
    if a.shape[0] != num_rows:
        raise InvalidInputError(f"{name}: must have one row per vertex ({num_rows}), got {a.shape[0]}")
    bad = (a < 0) | (a > 1)
    if bad.any():
        row = _first_bad_row(bad)
        raise InvalidInputError(f"{name}: row {row} = {a[row].tolist()} is outside [0, 1] (RGB as fractions)")
    return a


def mesh_pair(value, name):
    """A (V, F) pair given as a tuple or list of two arrays, checked as mesh()."""
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise InvalidInputError(f"{name}: must be a (V, F) pair, got {type(value).__name__}")
    return mesh(value[0], value[1], prefix=name + " ")


def image(x, name="image"):
    """(height, width, 3) C-contiguous uint8 array."""
    a = _as_array(x, name)
    if a.ndim != 3 or a.shape[2] != 3 or a.shape[0] == 0 or a.shape[1] == 0:
        raise InvalidInputError(f"{name}: shape must be (height, width, 3), got {a.shape}")
    if a.dtype != np.uint8:
        raise InvalidInputError(f"{name}: dtype must be uint8, got {a.dtype}")
    return np.ascontiguousarray(a)
