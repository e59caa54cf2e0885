#!/usr/bin/python3
"""Open3D's Taubin smoothing as a denoising baseline (bench/quality, bench/sweep).

    /usr/bin/python3 bench/taubin.py IN.obj OUT.obj [--iterations 10]

Runs `open3d.geometry.TriangleMesh.filter_smooth_taubin(number_of_iterations=10)` with Open3D's
default lambda = 0.5 and mu = -0.53 (Debian package python3-open3d). The mesh is read and written
here (OBJ or OFF, triangles), not by Open3D, so that the vertex and face order stay those of the
input and the result can be scored against the ground truth face by face (`msmesh eval`).
"""
import argparse
import importlib
import sys

_O3D = None
_O3D_ERROR = None


def open3d_module():
    """The open3d module, or None (then missing_reason() says why)."""
    global _O3D, _O3D_ERROR
    if _O3D is None and _O3D_ERROR is None:
        try:
            importlib.import_module("numpy")  # Open3D needs it, and so does this file
            import open3d  # imported lazily: it takes a second or two

            _O3D = open3d
        except Exception as e:  # ImportError, or a broken install
            _O3D_ERROR = f"{type(e).__name__}: {e}"
    return _O3D


def missing_reason():
    open3d_module()
    if _O3D_ERROR is None:
        return None
    return (f"open3d is not importable by {sys.executable} ({_O3D_ERROR}); the Taubin baseline is "
            "skipped (Debian: apt-get install python3-open3d)")


def read_mesh(path):
    """(V float64 n x 3, F int32 m x 3) of a triangle OBJ or OFF file, in file order."""
    import numpy as np

    with open(path, "r", errors="replace") as f:
        text = f.read()
    if path.lower().endswith(".off"):
        tokens = []
        for line in text.splitlines():
            line = line.split("#", 1)[0].strip()
            if line:
                tokens.extend(line.split())
        if not tokens or not tokens[0].endswith("OFF"):
            raise ValueError(f"{path}: not an OFF file (no OFF header)")
        i = 1
        nv, nf = int(tokens[i]), int(tokens[i + 1])
        i += 3
        V = np.array(tokens[i:i + 3 * nv], dtype=np.float64).reshape(nv, 3)
        i += 3 * nv
        F = []
        for _ in range(nf):
            k = int(tokens[i])
            if k != 3:
                raise ValueError(f"{path}: a face with {k} vertices (triangles only)")
            F.append((int(tokens[i + 1]), int(tokens[i + 2]), int(tokens[i + 3])))
            i += 1 + k
        return V, np.array(F, dtype=np.int32).reshape(-1, 3)
    if not path.lower().endswith(".obj"):
        raise ValueError(f"{path}: only OBJ and OFF are read here")
    V, F = [], []
    for line in text.splitlines():
        if line.startswith("v "):
            V.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("f "):
            idx = []
            for tok in line.split()[1:]:
                k = int(tok.split("/")[0])
                idx.append(k - 1 if k > 0 else len(V) + k)
            if len(idx) != 3:
                raise ValueError(f"{path}: a face with {len(idx)} vertices (triangles only)")
            F.append(idx)
    return np.array(V, dtype=np.float64).reshape(-1, 3), np.array(F, dtype=np.int32).reshape(-1, 3)


def write_obj(path, V, F):
    """OBJ with every coordinate written so that it reads back to the same double."""
    with open(path, "w") as f:
        f.write("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in V.tolist()))
        f.write("".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F.tolist()))


def taubin(V, F, iterations=10):
    import numpy as np

    o3d = open3d_module()
    if o3d is None:
        raise RuntimeError(missing_reason())
    m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
    s = m.filter_smooth_taubin(number_of_iterations=iterations)
    out = np.asarray(s.vertices).copy()
    # Open3D divides by the neighbour count: a vertex of no face becomes NaN. It has nothing to
    # smooth towards, so it keeps its position (it is in no face, so no score sees it).
    bad = ~np.isfinite(out).all(axis=1)
    out[bad] = V[bad]
    return out


def smooth_file(src, dst, iterations=10):
    V, F = read_mesh(src)
    write_obj(dst, taubin(V, F, iterations), F)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--iterations", type=int, default=10)
    a = ap.parse_args()
    if missing_reason():
        print(f"bench/taubin.py: {missing_reason()}", file=sys.stderr)
        return 2
    try:
        smooth_file(a.input, a.output, a.iterations)
    except (OSError, ValueError) as e:
        print(f"bench/taubin.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
