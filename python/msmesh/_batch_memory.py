"""The memory a batch task needs, estimated before it is scheduled: the library's estimate
(denoise_memory_estimate in include/msmesh/denoise.h: about 1000 bytes per face, 200 for the
bilateral baseline) times the face count read from the file's header, so that the run never
hands a worker a mesh larger than its memory limit.

The face count comes from the header (PLY ``element face``, OFF counts, binary STL count),
from counting face lines (OBJ, ascii STL; also under .gz), else from ``msmesh info --json``
(glTF). Polygons count as one face, so the estimate of a polygonal mesh is low by the ratio
of its triangles to its polygons.
"""

import gzip
import json
import os
import struct
import subprocess
from typing import Optional, Sequence

BYTES_PER_FACE = 1000.0  # src/denoise.cpp kBytesPerFace
BILATERAL_BYTES_PER_FACE = 200.0  # src/denoise.cpp kBilateralBytesPerFace


def _open(path: str):
    return gzip.open(path, "rb") if path.lower().endswith(".gz") else open(path, "rb")


def _format(path: str) -> str:
    name = path.lower()
    if name.endswith(".gz"):
        name = name[:-3]
    return os.path.splitext(name)[1]


def _ply_faces(f) -> Optional[int]:
    if f.readline().strip() != b"ply":
        return None
    for _ in range(10000):
        line = f.readline()
        if not line:
            return None
        words = line.split()
        if len(words) == 3 and words[0] == b"element" and words[1] == b"face":
            return int(words[2])
        if words[:1] == [b"end_header"]:
            return 0
    return None


def _off_faces(f) -> Optional[int]:
    first = True
    for _ in range(10000):
        line = f.readline()
        if not line:
            return None
        words = line.split(b"#")[0].split()
        if not words:
            continue
        if first and words[0].endswith(b"OFF"):
            first = False
            words = words[1:]
            if not words:
                continue
        return int(words[1])
    return None


def _count_lines(f, prefixes: Sequence[bytes]) -> int:
    count = 0
    for line in f:
        if line.lstrip().startswith(prefixes):
            count += 1
    return count


def _stl_faces(f, path: str) -> Optional[int]:
    head = f.read(84)
    if len(head) == 84 and not path.lower().endswith(".gz"):
        (n,) = struct.unpack("<I", head[80:84])
        if 84 + 50 * n == os.path.getsize(path):
            return n
    if head.lstrip().startswith(b"solid"):
        f.seek(0)
        return _count_lines(f, (b"facet",))
    return None


def face_count(path: str, program: Optional[str] = None) -> Optional[int]:
    """The number of faces of a mesh file, or None when it cannot be told (a bad file: the task
    will fail with msmesh's own message)."""
    fmt = _format(path)
    try:
        with _open(path) as f:
            if fmt == ".ply":
                return _ply_faces(f)
            if fmt == ".off":
                return _off_faces(f)
            if fmt == ".obj":
                return _count_lines(f, (b"f ", b"f\t"))
            if fmt == ".stl":
                return _stl_faces(f, path)
    except (OSError, ValueError, IndexError, EOFError, struct.error):
        return None
    if program is None:
        return None
    try:
        out = subprocess.run([program, "info", path, "--json"], capture_output=True, text=True, timeout=600)
        return int(json.loads(out.stdout)["faces"]) if out.returncode == 0 else None
    except (OSError, ValueError, KeyError, subprocess.TimeoutExpired):
        return None


def memory_estimate(faces: Optional[int], command: str, options: Sequence[str]) -> float:
    """Bytes a task needs (0 when the face count is unknown)."""
    if not faces:
        return 0.0
    per_face = BYTES_PER_FACE
    opts = list(options)
    bilateral = "--method=bilateral" in opts or any(
        a == "--method" and i + 1 < len(opts) and opts[i + 1] == "bilateral" for i, a in enumerate(opts))
    if command == "eval" or (command == "denoise" and bilateral):
        per_face = BILATERAL_BYTES_PER_FACE
    return per_face * faces


def parse_bytes(text: str) -> int:
    """'4G', '512M', '1.5e9' -> bytes."""
    text = text.strip()
    units = {"K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}
    suffix = text[-1:].upper()
    if suffix == "B" and len(text) > 1 and text[-2:-1].upper() in units:
        text, suffix = text[:-1], text[-2:-1].upper()
    if suffix in units:
        return int(float(text[:-1]) * units[suffix])
    return int(float(text))


def format_bytes(n: float) -> str:
    for unit, size in (("GB", 1 << 30), ("MB", 1 << 20), ("KB", 1 << 10)):
        if n >= size:
            return f"{n / size:.1f} {unit}"
    return f"{int(n)} B"
