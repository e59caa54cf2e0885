#!/usr/bin/python3
"""Small-mesh latency targets of docs/performance.md (Fandisk 13K faces, Cone 61K faces):
full default denoise (`msmesh denoise MESH --preset cad --json`, seconds_normals +
seconds_vertices, no I/O; with --default: `msmesh denoise MESH -o OUT` at the defaults, preset
auto with its noise estimate, as a whole process), repeated in alternating rounds, with the machine probe
(build/bench/msmesh_probe) before and after, so that a figure carries the state of the
machine it was taken on. Several --exe make it an A/B comparison: the builds run in turn in
every round, so slow phases of the machine hit all of them alike.

    /usr/bin/python3 bench/small_meshes.py [--rounds 10] [--exe build/msmesh --exe /tmp/old/msmesh]
                                           [--mesh meshtgv_liu2021/cone/noisy.obj ...] [--json out.json]

Reads the public meshes from ../shared/data/meshes (never copied into the repository); exits
with a message when that folder is absent.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MESHES = os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "meshes"))
DEFAULT_MESHES = ["meshtgv_liu2021/fandisk/noisy.obj", "meshtgv_liu2021/cone/noisy.obj"]


def probe(exe):
    if not os.path.exists(exe):
        return None
    return json.loads(subprocess.run([exe], check=True, capture_output=True, text=True).stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=10)
    ap.add_argument("--exe", action="append", help="msmesh program(s); default build/msmesh")
    ap.add_argument("--mesh", action="append", help="paths under ../shared/data/meshes")
    ap.add_argument("--probe", default=os.path.join(ROOT, "build", "bench", "msmesh_probe"))
    ap.add_argument("--json", default="", help="also write every run here")
    ap.add_argument("--default", action="store_true",
                    help="time `msmesh denoise MESH -o OUT` at its defaults (preset auto, noise estimate included) as a "
                         "whole process (wall time), instead of the normal filtering + vertex update of --preset cad")
    args = ap.parse_args()
    exes = args.exe or [os.path.join(ROOT, "build", "msmesh")]
    meshes = args.mesh or DEFAULT_MESHES
    if not os.path.isdir(MESHES):
        print(f"small_meshes: {MESHES} is absent: nothing to measure", file=sys.stderr)
        return 0
    for exe in exes:
        if not os.access(exe, os.X_OK):
            print(f"small_meshes: {exe} is not an executable (run scripts/build)", file=sys.stderr)
            return 1

    before = probe(args.probe)
    times = {(e, m): [] for e in exes for m in meshes}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.ply")
        for _ in range(args.rounds):
            for m in meshes:
                for e in exes:
                    cmd = [e, "denoise", os.path.join(MESHES, m), "-o", out, "--json"]
                    t0 = time.perf_counter()
                    r = subprocess.run(cmd + ([] if args.default else ["--preset", "cad"]),
                                       check=True, capture_output=True, text=True)
                    wall = time.perf_counter() - t0
                    d = json.loads(r.stdout)
                    times[(e, m)].append(wall if args.default else d["seconds_normals"] + d["seconds_vertices"])
    after = probe(args.probe)

    for name, p in (("before", before), ("after", after)):
        if p:
            print(f"machine {name}: triad {p['triad_gb_s']:.1f} GB/s, latency 2 MB {p['latency_ns_2mb']:.0f} ns, "
                  f"16 MB {p['latency_ns_16mb']:.0f} ns, 64 MB {p['latency_ns_64mb']:.0f} ns, "
                  f"share of two cores {p['cpu_share']:.2f}")
    what = "whole process, defaults" if args.default else "normal filtering + vertex update, --preset cad"
    print(f"\ntimes: {what}")
    print(f"\n| mesh | program | median s | min s | max s | runs |")
    print("|---|---|---:|---:|---:|---:|")
    for m in meshes:
        for e in exes:
            t = sorted(times[(e, m)])
            print(f"| {m} | {e} | {statistics.median(t):.3f} | {t[0]:.3f} | {t[-1]:.3f} | {len(t)} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"probe_before": before, "probe_after": after,
                       "runs": [{"exe": e, "mesh": m, "seconds": times[(e, m)]} for e in exes for m in meshes]}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
