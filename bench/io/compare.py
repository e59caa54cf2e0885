#!/usr/bin/python3
"""Before/after I/O speed: runs two msmesh_io_bench binaries alternately on the same files.

    bench/io/compare.py OLD_BENCH NEW_BENCH [--pairs 5] [--subdivisions 8] [--formats obj,...]

Each pair runs OLD then NEW once (one read and one write per format each), so that the machine's
drift falls on both alike; prints per format and operation the median wall time over the pairs,
the spread (min..max), the ratio old/new of the medians, MB/s of the file size, and the median
CPU time (user + system: on a loaded machine the wall time also holds the wait for a core) as a
markdown table for docs/performance.md.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

FORMATS = {"obj": "mesh.obj", "off": "mesh.off", "ply-ascii": "ascii.ply", "ply-binary": "binary.ply",
           "stl-binary": "binary.stl", "stl-ascii": "ascii.stl"}


def run(bench, folder, args):
    out = subprocess.run([bench, "--repeats", "1", "--samples", "--dir", folder] + args, check=True,
                         capture_output=True, text=True).stdout
    times = {}
    for line in out.splitlines():
        if line.startswith("sample "):
            _, fmt, op, wall, cpu = line.split()
            times[(fmt, op)] = (float(wall), float(cpu))
    return times


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--pairs", type=int, default=5)
    ap.add_argument("--subdivisions", type=int, default=8)
    ap.add_argument("--formats", default=",".join(FORMATS))
    a = ap.parse_args()
    args = ["--subdivisions", str(a.subdivisions), "--formats", a.formats]
    samples = {"old": {}, "new": {}}
    with tempfile.TemporaryDirectory(prefix="msmesh_io_compare_") as folder:
        for i in range(a.pairs):
            for name, bench in (("old", a.old), ("new", a.new)):
                for key, sec in run(bench, folder, args).items():
                    samples[name].setdefault(key, []).append(sec)
            print(f"pair {i + 1}/{a.pairs} done", file=sys.stderr)
        sizes = {f: os.path.getsize(os.path.join(folder, FORMATS[f])) / 1e6 for f in a.formats.split(",")}
    print("| format | MB | op | before s (min..max) | after s (min..max) | before/after | before MB/s | after MB/s "
          "| CPU s before | CPU s after | after MB/s of CPU time |")
    print("|---|---:|---|---|---|---:|---:|---:|---:|---:|---:|")
    for f in a.formats.split(","):
        for op in ("read", "write"):
            o, n = samples["old"].get((f, op)), samples["new"].get((f, op))
            if not o or not n:
                continue
            ow, nw = [t[0] for t in o], [t[0] for t in n]
            mo, mn = statistics.median(ow), statistics.median(nw)
            co, cn = statistics.median(t[1] for t in o), statistics.median(t[1] for t in n)
            print(f"| {f} | {sizes[f]:.1f} | {op} | {mo:.3f} ({min(ow):.3f}..{max(ow):.3f}) | "
                  f"{mn:.3f} ({min(nw):.3f}..{max(nw):.3f}) | {mo / mn:.2f} | {sizes[f] / mo:.0f} | {sizes[f] / mn:.0f} | "
                  f"{co:.3f} | {cn:.3f} | {sizes[f] / cn:.0f} |")


if __name__ == "__main__":
    main()
