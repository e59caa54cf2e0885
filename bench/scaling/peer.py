#!/usr/bin/python3
"""msmesh against a peer, Open3D's Taubin smoothing x10, as whole processes on the same meshes
(issue 20 item 4; docs/performance.md, "Against Open3D's Taubin x10").

    /usr/bin/python3 bench/scaling/peer.py [--sizes 1e4,1e5,1e6,5e6] [--rounds 3]
                                           [--exe build/msmesh [--exe /tmp/old/msmesh]] [--out docs]

For each size a noisy procedural mesh is made once as an OBJ in a temporary folder
(`msmesh shape sphere -r R -o clean.obj`, `msmesh noise clean.obj -o noisy.obj --sigma 0.2`;
the sphere is an icosphere of 20 * 4^k faces, k the nearest level to the size; --shape cube
gives 12 R^2 faces), plus the public meshes meshtgv_liu2021/fandisk (13K faces) and cone
(61K) from ../shared/data/meshes when that folder is present. Then, in --rounds alternating
rounds (A B A B ...):

    A  msmesh denoise noisy.obj -o out.obj -q              (the defaults, what a user runs)
    B  /usr/bin/python3 bench/scaling/open3d_taubin.py noisy.obj out_o3d.obj

each a whole process (interpreter start and `import open3d` count for B), timed by wall clock,
with its peak resident memory and CPU time (user + system, os.wait4). Several --exe run in turn in every
round (A1 A2 B), an A/B comparison of builds against the same peer runs. Printed: a markdown
table per mesh (median and min-max of each program's seconds and of the ratio msmesh / Open3D
of the runs of the same round; peak memory; KB per face = peak MB * 1000 / faces, with MB as
in docs/scaling.csv, 2^20 bytes), Open3D's own stage times, the growth exponent of msmesh's
median time from 100K faces up (least squares on log-log), and the machine probe
(build/bench/msmesh_probe) before and after. Written: OUT/scaling_peer.csv and, with
python3-matplotlib, OUT/images/scaling_peer.png; --json FILE also keeps every run, and
--from-json FILE remakes the table, CSV and plot from it without measuring.

Exit status: 0 done, 1 a run failed (its command and message are printed), 77 open3d is not
importable by --python (nothing measured; Debian: apt-get install python3-open3d).
"""
import argparse
import csv
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run as scaling_run  # noqa: E402  (bench/scaling/run.py: the same exponent fit)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MESHES = os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "meshes"))
REAL_MESHES = ["meshtgv_liu2021/fandisk/noisy.obj", "meshtgv_liu2021/cone/noisy.obj"]
OPEN3D_SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "open3d_taubin.py")
SKIPPED = 77


class RunError(Exception):
    pass


def run(cmd, workdir, name):
    """Runs cmd as a child process: (wall seconds, peak RSS in MB (2^20 bytes), CPU seconds).
    Its output goes to files (no pipe to fill up); a non-zero exit raises RunError with it."""
    out_path = os.path.join(workdir, name + ".stdout")
    err_path = os.path.join(workdir, name + ".stderr")
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL)
        _, status, ru = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)  # reaped here: Popen must not wait again
    if p.returncode != 0:
        with open(err_path, errors="replace") as f:
            message = f.read().strip()
        raise RunError(f"{' '.join(cmd)}: exit status {p.returncode}\n{message}")
    return wall, ru.ru_maxrss / 1024.0, ru.ru_utime + ru.ru_stime  # Linux: ru_maxrss in kilobytes


def probe(exe):
    if not exe or not os.path.exists(exe):
        return None
    return json.loads(subprocess.run([exe], check=True, capture_output=True, text=True).stdout)


def probe_line(name, p):
    return (f"machine {name}: triad {p['triad_gb_s']:.1f} GB/s, latency 2 MB {p['latency_ns_2mb']:.0f} ns, "
            f"16 MB {p['latency_ns_16mb']:.0f} ns, 64 MB {p['latency_ns_64mb']:.0f} ns, "
            f"share of two cores {p['cpu_share']:.2f} (build/bench/msmesh_probe)")


def resolution(shape, target):
    """The -r of `msmesh shape` nearest to `target` faces."""
    if shape == "sphere":  # src/shapes.cpp: level k = round(log4(0.6 r^2)), 20 * 4^k faces
        k = min(10, max(0, round(math.log(target / 20.0) / math.log(4.0))))
        return max(1, round(2**k / math.sqrt(0.6)))
    if shape == "cube":  # 12 r^2 faces
        return max(1, round(math.sqrt(target / 12.0)))
    raise ValueError(f"--shape {shape}: sphere or cube")


def faces_of(shape_message, path):
    m = re.search(r"(\d+) faces", shape_message)
    if m:
        return int(m.group(1))
    with open(path, "rb") as f:
        return sum(1 for line in f if line.startswith(b"f "))


def make_mesh(exe, shape, target, sigma, folder):
    """A noisy procedural OBJ of about `target` faces: (path, faces, label)."""
    os.makedirs(folder, exist_ok=True)
    clean, noisy = os.path.join(folder, "clean.obj"), os.path.join(folder, "noisy.obj")
    r = resolution(shape, target)
    made = subprocess.run([exe, "shape", shape, "-r", str(r), "-o", clean], capture_output=True, text=True)
    if made.returncode != 0:
        raise RunError(f"{exe} shape {shape} -r {r}: {made.stderr.strip()}")
    noised = subprocess.run([exe, "noise", clean, "-o", noisy, "--sigma", str(sigma)], capture_output=True, text=True)
    if noised.returncode != 0:
        raise RunError(f"{exe} noise {clean}: {noised.stderr.strip()}")
    faces = faces_of(made.stdout + made.stderr, clean)
    os.remove(clean)
    return noisy, faces, f"noisy {shape}, -r {r}"


def count_faces(path):
    with open(path, "rb") as f:
        return sum(1 for line in f if line.startswith(b"f "))


def fit_exponent(points):
    """Least-squares slope of log(seconds) against log(faces) of (faces, seconds) points."""
    return scaling_run.fit_exponent([{"faces": x, "s": y} for x, y in points], "s", lo=0)


def spread(values, fmt, bold=False):
    """'median (min–max)', the median in bold with `bold`; the value alone for one run."""
    v = sorted(values)
    med = fmt.format(statistics.median(v))
    med = f"**{med}**" if bold else med
    return med if len(v) == 1 else f"{med} ({fmt.format(v[0])}–{fmt.format(v[-1])})"


def open3d_missing(python):
    r = subprocess.run([python, "-c", "import open3d"], capture_output=True, text=True)
    if r.returncode == 0:
        return None
    last = (r.stderr.strip().splitlines() or ["no message"])[-1]
    return f"open3d is not importable by {python} ({last}); Debian: apt-get install python3-open3d"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default="1e4,1e5,1e6,5e6", help="face counts of the procedural meshes ('' for none)")
    ap.add_argument("--rounds", type=int, default=3, help="alternating rounds (pairs A B) per mesh")
    ap.add_argument("--exe", action="append", help="msmesh program(s), default build/msmesh; several alternate")
    ap.add_argument("--shape", default="sphere", choices=["sphere", "cube"])
    ap.add_argument("--sigma", type=float, default=0.2, help="noise, in mean edge lengths (msmesh noise)")
    ap.add_argument("--real", default=",".join(REAL_MESHES),
                    help="public meshes under ../shared/data/meshes, comma-separated ('' for none); "
                         "left out with a message when that folder is absent")
    ap.add_argument("--python", default="/usr/bin/python3", help="the interpreter of the Open3D runs")
    ap.add_argument("--probe", default=os.path.join(ROOT, "build", "bench", "msmesh_probe"))
    ap.add_argument("--tmp", default=None, help="folder for the temporary meshes (default: the system's)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"), help="scaling_peer.csv and images/ go here")
    ap.add_argument("--json", default="", help="also write every run here")
    ap.add_argument("--from-json", default="", help="measure nothing: remake the table, CSV and plot of a --json")
    args = ap.parse_args()
    if args.from_json:
        with open(args.from_json) as f:
            d = json.load(f)
        report(d["meshes"], d["exes"], d["probe_before"], d["probe_after"], args.out, "")
        return 0
    exes = [os.path.abspath(e) for e in (args.exe or [os.path.join(ROOT, "build", "msmesh")])]
    for exe in exes:
        if not os.access(exe, os.X_OK):
            print(f"peer.py: {exe} is not an executable (run scripts/build)", file=sys.stderr)
            return 1
    if args.rounds < 1:
        print("peer.py: --rounds must be at least 1", file=sys.stderr)
        return 1
    # Also the warm-up: Open3D's libraries are read from disk once before any timed run.
    missing = open3d_missing(args.python)
    if missing:
        print(f"peer.py: {missing}: nothing measured", file=sys.stderr)
        return SKIPPED
    sizes = [float(s) for s in args.sizes.split(",") if s.strip()]
    real = [m for m in args.real.split(",") if m.strip()]
    if real and not os.path.isdir(MESHES):
        print(f"peer.py: {MESHES} is absent: the public meshes {', '.join(real)} are left out", file=sys.stderr)
        real = []

    before = probe(args.probe)
    if before:
        print(probe_line("before", before), file=sys.stderr)
    results = []  # one per mesh: faces, label, runs
    tmp = tempfile.mkdtemp(prefix="msmesh_peer_", dir=args.tmp)
    try:
        inputs = []
        for m in real:
            path = os.path.join(MESHES, m)
            if not os.path.isfile(path):
                print(f"peer.py: {path} is absent: left out", file=sys.stderr)
                continue
            inputs.append(("real", m, path))
        inputs += [("size", s, None) for s in sizes]
        for i, (kind, what, path) in enumerate(inputs):
            folder = os.path.join(tmp, f"mesh{i}")
            os.makedirs(folder)
            if kind == "real":
                faces, label = count_faces(path), what
            else:
                path, faces, label = make_mesh(exes[0], args.shape, what, args.sigma, folder)
            print(f"peer.py: {label}: {faces} faces, {args.rounds} rounds", file=sys.stderr)
            runs = [[] for _ in exes]  # by position in --exe (the same program may come twice)
            peer = []
            out_ms, out_o3d = os.path.join(folder, "out.obj"), os.path.join(folder, "out_o3d.obj")
            times_path = os.path.join(folder, "o3d_times.json")
            for r in range(args.rounds):
                for j, exe in enumerate(exes):
                    w, mb, cpu = run([exe, "denoise", path, "-o", out_ms, "-q"], folder, f"msmesh{j}_{r}")
                    runs[j].append({"seconds": w, "peak_mb": mb, "cpu_seconds": cpu})
                    os.remove(out_ms)
                w, mb, cpu = run([args.python, OPEN3D_SCRIPT, path, out_o3d, "--times", times_path], folder, f"o3d_{r}")
                with open(times_path) as f:
                    stages = json.load(f)
                if stages["faces"] != faces:
                    raise RunError(f"{OPEN3D_SCRIPT} {path}: Open3D read {stages['faces']} faces, not {faces}")
                peer.append({"seconds": w, "peak_mb": mb, "cpu_seconds": cpu, **stages})
                os.remove(out_o3d)
                line = ", ".join(f"msmesh{'' if len(exes) == 1 else j + 1} {runs[j][-1]['seconds']:.2f} s"
                                 for j in range(len(exes)))
                print(f"  round {r + 1}: {line}, open3d {w:.2f} s", file=sys.stderr)
            results.append({"kind": kind, "label": label, "faces": faces, "size": what if kind == "size" else None,
                            "runs": runs, "peer": peer})
            if kind == "size":
                os.remove(path)  # the 5M-face OBJ is 230 MB
    except RunError as e:
        print(f"peer.py: a run failed: {e}", file=sys.stderr)
        return 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    after = probe(args.probe)
    report(results, exes, before, after, args.out, args.json)
    return 0


def report(results, exes, before, after, out, json_path):
    """Prints the table, writes OUT/scaling_peer.csv, the plot and (json_path) every run."""
    results.sort(key=lambda res: res["faces"])
    rounds = sorted({len(res["peer"]) for res in results})
    rows = []
    for res in results:
        peer = res["peer"]
        for j, exe in enumerate(exes):
            ms = res["runs"][j]
            ratio = [a["seconds"] / b["seconds"] for a, b in zip(ms, peer)]
            med = lambda runs, key: statistics.median(x[key] for x in runs)
            row = {"mesh": res["label"], "faces": res["faces"], "program": j + 1, "exe": exe, "rounds": len(ms),
                   "msmesh_s_median": med(ms, "seconds"), "msmesh_s_min": min(x["seconds"] for x in ms),
                   "msmesh_s_max": max(x["seconds"] for x in ms), "msmesh_cpu_s_median": med(ms, "cpu_seconds"),
                   "open3d_s_median": med(peer, "seconds"), "open3d_s_min": min(x["seconds"] for x in peer),
                   "open3d_s_max": max(x["seconds"] for x in peer), "open3d_cpu_s_median": med(peer, "cpu_seconds"),
                   "ratio_median": statistics.median(ratio), "ratio_min": min(ratio), "ratio_max": max(ratio),
                   "msmesh_peak_mb": med(ms, "peak_mb"), "open3d_peak_mb": med(peer, "peak_mb")}
            row["msmesh_kb_per_face"] = row["msmesh_peak_mb"] * 1000 / res["faces"]
            row["open3d_kb_per_face"] = row["open3d_peak_mb"] * 1000 / res["faces"]
            for stage in ("import", "read", "smooth", "write"):
                row[f"open3d_{stage}_s_median"] = med(peer, "seconds_" + stage)
            row["ratios"] = " ".join(f"{x:.3f}" for x in ratio)  # every round's, in order
            for name, p in (("before", before), ("after", after)):
                for k, v in (p or {}).items():
                    if k != "quick":
                        row[f"probe_{name}_{k}"] = v
            rows.append(row)
            res.setdefault("rows", []).append(row)

    print("\n### msmesh denoise (defaults) against Open3D Taubin x10, whole processes\n")
    many = len(exes) > 1
    print(f"| mesh | faces |{' program |' if many else ''} msmesh s | Open3D s | ratio msmesh / Open3D | "
          "CPU s msmesh / Open3D | msmesh peak MB (KB/face) | Open3D peak MB (KB/face) | "
          "Open3D import / read / smooth / write s |")
    print(f"|---|---:|{'---|' if many else ''}---:|---:|---:|---:|---:|---:|---:|")
    for res in results:
        for j, row in enumerate(res["rows"]):
            ms = [x["seconds"] for x in res["runs"][j]]
            o3 = [x["seconds"] for x in res["peer"]]
            ratio = [a / b for a, b in zip(ms, o3)]
            print(f"| {res['label']} | {res['faces']:,} |{f' {j + 1} |' if many else ''} {spread(ms, '{:.2f}')} | "
                  f"{spread(o3, '{:.2f}')} | {spread(ratio, '{:.2f}', bold=True)} | "
                  f"{row['msmesh_cpu_s_median']:.2f} / {row['open3d_cpu_s_median']:.2f} | "
                  f"{row['msmesh_peak_mb']:.0f} ({row['msmesh_kb_per_face']:.2f}) | "
                  f"{row['open3d_peak_mb']:.0f} ({row['open3d_kb_per_face']:.2f}) | "
                  f"{row['open3d_import_s_median']:.2f} / {row['open3d_read_s_median']:.2f} / "
                  f"{row['open3d_smooth_s_median']:.2f} / {row['open3d_write_s_median']:.2f} |")
    print(f"\nmedian (min–max) of {'/'.join(map(str, rounds))} alternating rounds; ratio: of the two runs of the same round; "
          "CPU s: user + system time of the process, median; KB/face: peak MB x 1000 / faces")
    if many:
        print("programs: " + ", ".join(f"{j + 1} = {e}" for j, e in enumerate(exes)))
    # From the mesh made for --sizes 1e5 up (the sphere nearest to 100K faces has 81,920).
    procedural = [res for res in results if res["kind"] == "size" and res["size"] >= 1e5]
    for j in range(len(exes)):
        ms_pts = [(res["faces"], res["rows"][j]["msmesh_s_median"]) for res in procedural]
        peer_pts = [(res["faces"], res["rows"][j]["open3d_s_median"]) for res in procedural]
        name = f"msmesh {j + 1}" if many else "msmesh"
        which = ", ".join(f"{res['faces']:,}" for res in procedural)
        print(f"growth exponent of {name}'s median time (procedural meshes of {which} faces): "
              f"{fit_exponent(ms_pts):.3f}" + ("" if j else f"; Open3D's: {fit_exponent(peer_pts):.3f}"))
    for name, p in (("before", before), ("after", after)):
        if p:
            print(probe_line(name, p))

    os.makedirs(out, exist_ok=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(out, "scaling_peer.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows([{k: round(v, 5) if isinstance(v, float) else v for k, v in r.items()} for r in rows])
    if json_path:
        with open(json_path, "w") as f:
            json.dump({"probe_before": before, "probe_after": after, "exes": exes,
                       "meshes": [{k: v for k, v in res.items() if k != "rows"} for res in results]}, f, indent=1)
    plot(results, exes, out)


def plot(results, exes, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("peer.py: matplotlib missing (apt-get install python3-matplotlib): no plot", file=sys.stderr)
        return
    procedural = [res for res in results if res["kind"] == "size"]
    if len(procedural) < 2:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=110)
    x = [res["faces"] for res in procedural]
    for j, exe in enumerate(exes):
        y = [statistics.median(r["seconds"] for r in res["runs"][j]) for res in procedural]
        ax.loglog(x, y, "o-", label="msmesh denoise (defaults)" + (f" {j + 1}" if len(exes) > 1 else ""))
    ax.loglog(x, [statistics.median(r["seconds"] for r in res["peer"]) for res in procedural], "s-",
              label="Open3D Taubin x10")
    ax.set_xlabel("faces")
    ax.set_ylabel("wall time of the whole process (s), median")
    ax.set_title("msmesh against Open3D, noisy procedural meshes")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    os.makedirs(os.path.join(out, "images"), exist_ok=True)
    fig.savefig(os.path.join(out, "images", "scaling_peer.png"))


if __name__ == "__main__":
    sys.exit(main())
