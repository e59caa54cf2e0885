#!/usr/bin/python3
"""Open3D's Taubin smoothing x10 as a user runs it: the peer of bench/scaling/peer.py.

    /usr/bin/python3 bench/scaling/open3d_taubin.py IN.obj OUT.obj [--iterations 10] [--times T.json]

Does exactly what a user of Open3D (Debian package python3-open3d) does:

    m = o3d.io.read_triangle_mesh(IN)
    m = m.filter_smooth_taubin(number_of_iterations=10)   # Open3D's default lambda 0.5, mu -0.53
    o3d.io.write_triangle_mesh(OUT, m)

with Open3D's own reader and writer (bench/taubin.py, the quality baseline, reads and writes
with its own code instead, to keep the face order for scoring). The driver times the whole
process (interpreter start and `import open3d` included); --times also writes the seconds of
each stage measured here: import, read, smooth, write.

Exit status: 0 done, 1 the mesh could not be read or written, 2 open3d is not importable.
"""
import argparse
import json
import sys
import time

T_START = time.perf_counter()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--iterations", type=int, default=10)
    ap.add_argument("--times", default="", help="write the seconds per stage here (JSON)")
    a = ap.parse_args()
    t0 = time.perf_counter()
    try:
        import open3d as o3d
    except Exception as e:  # ImportError, or a broken install
        print(f"open3d_taubin.py: open3d is not importable by {sys.executable} ({type(e).__name__}: {e}); "
              "Debian: apt-get install python3-open3d", file=sys.stderr)
        return 2
    t1 = time.perf_counter()
    m = o3d.io.read_triangle_mesh(a.input)
    t2 = time.perf_counter()
    if not m.has_triangles():
        print(f"open3d_taubin.py: {a.input}: Open3D read no triangles (missing or unreadable file)", file=sys.stderr)
        return 1
    m = m.filter_smooth_taubin(number_of_iterations=a.iterations)
    t3 = time.perf_counter()
    if not o3d.io.write_triangle_mesh(a.output, m):
        print(f"open3d_taubin.py: {a.output}: Open3D could not write the mesh", file=sys.stderr)
        return 1
    t4 = time.perf_counter()
    if a.times:
        with open(a.times, "w") as f:
            json.dump({"seconds_import": t1 - t0, "seconds_read": t2 - t1, "seconds_smooth": t3 - t2,
                       "seconds_write": t4 - t3, "seconds_script": t4 - T_START,
                       "vertices": len(m.vertices), "faces": len(m.triangles), "open3d": o3d.__version__}, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
