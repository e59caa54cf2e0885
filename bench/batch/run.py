#!/usr/bin/python3
"""msmesh batch throughput (docs/batch.md): meshes per minute of `msmesh batch denoise` with 1
and 2 workers against a shell loop of `msmesh denoise` over the same inputs, and the overhead
per task, on small and medium procedural meshes (msmesh shape + msmesh noise).

    /usr/bin/python3 bench/batch/run.py [--build build] [--count 40] [--sizes 4,30] [--repeat 1]

Every run writes to a fresh folder (nothing reused); the batch runs without thumbnails
(--no-thumbnails) unless --thumbnails. Prints a markdown table.
Columns: faces per mesh, the loop's and each batch's wall time and meshes per minute, the batch's
per-task overhead = (batch wall time - cluster start - the loop's time / workers) / meshes
per worker, and the cluster start time (LocalCluster + Client, measured on its own).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def sh(*args, **kw):
    subprocess.run([str(a) for a in args], check=True, stdout=subprocess.DEVNULL, **kw)


def make_inputs(program, folder, count, resolution):
    os.makedirs(folder)
    clean = os.path.join(folder, "..", f"clean-{resolution}.obj")
    sh(program, "shape", "fandisk", "-r", resolution, "-o", clean)
    for i in range(count):
        sh(program, "noise", clean, "-o", os.path.join(folder, f"m{i:03d}.obj"), "--seed", i, "-q")


def loop(program, inputs, out):
    os.makedirs(out)
    t0 = time.monotonic()
    subprocess.run(["bash", "-c", f'for f in "{inputs}"/*.obj; do "{program}" denoise "$f" -o "{out}/$(basename '
                    f'"$f")" -q || exit 1; done'], check=True)
    return time.monotonic() - t0


def batch(program, inputs, out, workers, thumbnails):
    """Wall time of the batch and the sum of its tasks' msmesh times (results.jsonl)."""
    args = [program, "batch", "denoise", inputs, "-o", out, "--workers", str(workers), "-q"]
    if not thumbnails:
        args.append("--no-thumbnails")
    t0 = time.monotonic()
    subprocess.run(args, check=True)
    wall = time.monotonic() - t0
    with open(os.path.join(out, "results.jsonl")) as f:
        records = [json.loads(line) for line in f]
    assert all(r["status"] == "ok" for r in records)
    return wall, sum(r["seconds"] for r in records)


def cluster_start(python, build, workers):
    code = ("import time,os;t=time.monotonic();from distributed import LocalCluster,Client;"
            f"c=LocalCluster(n_workers={workers},threads_per_worker=1,dashboard_address=':0',silence_logs=50);"
            "cl=Client(c);print(time.monotonic()-t);cl.close();c.close()")
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    out = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True, env=env)
    return float(out.stdout.strip().splitlines()[-1])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--count", type=int, default=40)
    p.add_argument("--sizes", default="4,30", help="msmesh shape fandisk resolutions")
    p.add_argument("--repeat", type=int, default=1, help="runs of each; the fastest is kept")
    p.add_argument("--thumbnails", action="store_true")
    a = p.parse_args()
    program = os.path.join(os.path.abspath(a.build), "msmesh")
    if not os.access(program, os.X_OK):
        sys.exit(f"bench/batch: {program}: no msmesh program (scripts/build first)")
    tmp = tempfile.mkdtemp(prefix="msmesh-batch-bench-")
    try:
        starts = {w: min(cluster_start(sys.executable, a.build, w) for _ in range(a.repeat)) for w in (1, 2)}
        print(f"{a.count} meshes each, {os.cpu_count()} cores; cluster start {starts[1]:.2f} s (1 worker), "
              f"{starts[2]:.2f} s (2 workers)\n")
        print("| faces | loop s | loop meshes/min | batch 1 worker s | meshes/min | msmesh s/task | overhead s/task "
              "| batch 2 workers s | meshes/min | msmesh s/task | overhead s/task |")
        print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for resolution in (int(s) for s in a.sizes.split(",")):
            inputs = os.path.join(tmp, f"in-{resolution}")
            make_inputs(program, inputs, a.count, resolution)
            faces = sum(1 for line in open(os.path.join(inputs, "m000.obj")) if line.startswith("f "))

            def fresh():
                return tempfile.mkdtemp(prefix="out-", dir=tmp) + "/o"

            t_loop = min(loop(program, inputs, fresh()) for _ in range(a.repeat))
            row = [f"{faces}", f"{t_loop:.2f}", f"{60 * a.count / t_loop:.0f}"]
            for w in (1, 2):
                t, work = min(batch(program, inputs, fresh(), w, a.thumbnails) for _ in range(a.repeat))
                overhead = (t - starts[w] - work / w) / (a.count / w)
                row += [f"{t:.2f}", f"{60 * a.count / t:.0f}", f"{work / a.count:.3f}", f"{overhead:.3f}"]
            print("| " + " | ".join(row) + " |", flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
