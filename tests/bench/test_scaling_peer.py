#!/usr/bin/python3
"""ctest scaling_peer (label bench): bench/scaling/peer.py and open3d_taubin.py end to end on
one tiny procedural mesh, one round, two --exe (the A/B path).

    /usr/bin/python3 tests/bench/test_scaling_peer.py MSMESH

Exits 77 (ctest: skipped) with a message when open3d is not importable by /usr/bin/python3
(python3-open3d is not among the packages of scripts/deps --test).
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PEER = os.path.join(ROOT, "bench", "scaling", "peer.py")
OPEN3D_TAUBIN = os.path.join(ROOT, "bench", "scaling", "open3d_taubin.py")
PYTHON = "/usr/bin/python3"


def check(condition, message):
    if not condition:
        print(f"FAILED: {message}", file=sys.stderr)
        sys.exit(1)


def read_obj(path):
    V, F = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if t and t[0] == "v":
                V.append(tuple(float(x) for x in t[1:4]))
            elif t and t[0] == "f":
                F.append(tuple(int(x.split("/")[0]) for x in t[1:]))
    return V, F


def test_open3d_taubin(msmesh, tmp):
    """The peer smooths: same faces, every vertex moved towards its neighbours, stage times."""
    clean, noisy, out = (os.path.join(tmp, n) for n in ("clean.obj", "noisy.obj", "o3d.obj"))
    subprocess.run([msmesh, "shape", "sphere", "-r", "10", "-o", clean], check=True, capture_output=True)
    subprocess.run([msmesh, "noise", clean, "-o", noisy, "--sigma", "0.2"], check=True, capture_output=True)
    times = os.path.join(tmp, "times.json")
    r = subprocess.run([PYTHON, OPEN3D_TAUBIN, noisy, out, "--times", times], capture_output=True, text=True)
    check(r.returncode == 0, f"open3d_taubin.py failed: {r.stderr}")
    V0, F0 = read_obj(noisy)
    V1, F1 = read_obj(out)
    check(len(F1) == len(F0) == 1280 and len(V1) == len(V0),
          f"faces {len(F0)} -> {len(F1)}, vertices {len(V0)} -> {len(V1)}")
    # Open3D's OBJ reader renumbers the vertices (first use order): compare what does not depend on it.
    edges = {}
    for f in F1:
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            edges[(min(a, b), max(a, b))] = edges.get((min(a, b), max(a, b)), 0) + 1
    check(len(edges) == 1920 and set(edges.values()) == {2}, "the result is not the closed 1280-face sphere")
    # The clean icosphere has radius 1 and the noise is along the normals: smoothing evens out
    # the radii (their spread about their mean, so that a slight shrinkage does not count).
    def radius_spread(V):
        r = [math.sqrt(x * x + y * y + z * z) for x, y, z in V]
        mean = sum(r) / len(r)
        return math.sqrt(sum((x - mean) ** 2 for x in r) / len(r))

    check(radius_spread(V1) < 0.5 * radius_spread(V0),
          f"Taubin x10 did not denoise: spread of the radii {radius_spread(V0):.5f} -> {radius_spread(V1):.5f}")
    with open(times) as f:
        t = json.load(f)
    check(t["faces"] == 1280 and all(t["seconds_" + s] >= 0 for s in ("import", "read", "smooth", "write")), str(t))
    check(t["seconds_script"] >= t["seconds_import"] + t["seconds_read"] + t["seconds_smooth"], str(t))
    r = subprocess.run([PYTHON, OPEN3D_TAUBIN, os.path.join(tmp, "absent.obj"), out], capture_output=True, text=True)
    check(r.returncode == 1 and "absent.obj" in r.stderr, f"a missing input: exit {r.returncode}, {r.stderr}")


def test_peer(msmesh, tmp):
    out = os.path.join(tmp, "docs")
    runs = os.path.join(tmp, "runs.json")
    cmd = [PYTHON, PEER, "--sizes", "1e3", "--rounds", "1", "--real", "", "--exe", msmesh, "--exe", msmesh,
           "--out", out, "--json", runs, "--tmp", tmp, "--probe", ""]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, f"{' '.join(cmd)}: exit {r.returncode}\n{r.stdout}\n{r.stderr}")
    check("| noisy sphere, -r 10 | 1,280 | 1 |" in r.stdout and "| noisy sphere, -r 10 | 1,280 | 2 |" in r.stdout,
          f"no table row per program for the 1280-face sphere:\n{r.stdout}")
    with open(os.path.join(out, "scaling_peer.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 2, f"{len(rows)} CSV rows, expected one per program")
    with open(runs) as f:
        meshes = json.load(f)["meshes"]
    check(len(meshes) == 1 and meshes[0]["faces"] == 1280, str(meshes))
    for row in rows:
        check(int(row["faces"]) == 1280 and int(row["rounds"]) == 1 and row["exe"] == os.path.abspath(msmesh), str(row))
        ms, o3 = float(row["msmesh_s_median"]), float(row["open3d_s_median"])
        check(ms > 0 and o3 > 0, str(row))
        run_ms = meshes[0]["runs"][int(row["program"]) - 1][0]["seconds"]
        check(math.isclose(run_ms, ms, rel_tol=1e-3), f"the CSV median {ms} is not the one run {run_ms} of --json")
        check(math.isclose(float(row["ratio_median"]), ms / o3, rel_tol=1e-3),
              f"ratio {row['ratio_median']} != {ms}/{o3}")
        peak = float(row["msmesh_peak_mb"])
        check(1 < peak < 1000, f"msmesh peak {peak} MB for 1280 faces")
        check(math.isclose(float(row["msmesh_kb_per_face"]), peak * 1000 / 1280, rel_tol=1e-3), str(row))
        # The Open3D process holds the interpreter and the library: more than msmesh at this size.
        check(float(row["open3d_peak_mb"]) > peak, str(row))
        check(o3 >= float(row["open3d_import_s_median"]) + float(row["open3d_smooth_s_median"]), str(row))
    check(not [n for n in os.listdir(tmp) if n.startswith("msmesh_peer_")], "peer.py left its temporary folder")
    # --from-json remakes the same CSV from the runs, measuring nothing.
    again = os.path.join(tmp, "again")
    r = subprocess.run([PYTHON, PEER, "--from-json", runs, "--out", again], capture_output=True, text=True)
    check(r.returncode == 0, f"--from-json: exit {r.returncode}\n{r.stderr}")
    with open(os.path.join(out, "scaling_peer.csv")) as f, open(os.path.join(again, "scaling_peer.csv")) as g:
        check(f.read() == g.read(), "--from-json wrote another CSV than the run")
    r = subprocess.run([PYTHON, PEER, "--sizes", "1e3", "--rounds", "1", "--real", "", "--out", out,
                        "--exe", os.path.join(tmp, "no_msmesh")], capture_output=True, text=True)
    check(r.returncode == 1 and "no_msmesh" in r.stderr, f"a missing --exe: exit {r.returncode}, {r.stderr}")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    msmesh = sys.argv[1]
    r = subprocess.run([PYTHON, "-c", "import open3d"], capture_output=True, text=True)
    if r.returncode != 0:
        print(f"SKIPPED: open3d is not importable by {PYTHON} (apt-get install python3-open3d): "
              f"{(r.stderr.strip().splitlines() or [''])[-1]}")
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_open3d_taubin(msmesh, tmp)
        test_peer(msmesh, tmp)
    print("scaling_peer: open3d_taubin.py and peer.py work end to end")
    return 0


if __name__ == "__main__":
    sys.exit(main())
