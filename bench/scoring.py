"""Shared by bench/quality and bench/sweep: run a denoiser on a noisy mesh and score the result
against the ground truth with `msmesh eval --json --truth` (one metric for every method), and the
score cache.

The cache (a JSON file, by default build/bench_cache.json) keeps the scores of results that do not
change when msmesh's defaults change: the released results of other methods, Open3D's Taubin
smoothing and msmesh's bilateral method. Its key is the input's name, the MD5 of the input's and
the truth's bytes and the method, so a changed input misses the cache. Reruns then only run
msmesh's default (and the --methods rows). --refresh recomputes them (for example after a change
to the bilateral method), --no-cache does not read or write the file.
"""
import fcntl
import hashlib
import json
import math
import os
import subprocess
import tempfile
import threading
import time

import taubin as taubin_mod

METRICS = ("msae_e3", "mean_angle_deg", "flipped", "dist_mean_e3", "dist_max_e3", "truth_folded",
           "flipped_outside_folds", "msae_outside_folds_e3")


def file_md5(path, _memo={}, _lock=threading.Lock()):
    st = os.stat(path)
    key = (path, st.st_size, st.st_mtime_ns)
    with _lock:
        if key in _memo:
            return _memo[key]
    h = hashlib.md5()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    with _lock:
        _memo[key] = h.hexdigest()
    return _memo[key]


class Cache:
    """Scores by key, in a JSON file written atomically (a temporary file renamed over it)."""

    def __init__(self, path, read=True, write=True):
        self.path, self.write, self.read = path, write, read
        self.data, self.mine = {}, set()
        self.lock = threading.Lock()
        self.hits = self.misses = 0
        if path and read and os.path.exists(path):
            try:
                with open(path) as f:
                    self.data = json.load(f)
            except (OSError, ValueError) as e:
                print(f"bench: cache {path} unreadable ({e}); starting a new one")

    @staticmethod
    def key(name, noisy, truth, method):
        return f"{name}|{file_md5(noisy)[:16]}|{file_md5(truth)[:16]}|{method}"

    def get(self, key):
        with self.lock:
            v = self.data.get(key) if (self.read or key in self.mine) else None
            if v is None:
                self.misses += 1
            else:
                self.hits += 1
            return v

    def put(self, key, value):
        with self.lock:
            self.data[key] = value
            self.mine.add(key)
            if not (self.path and self.write):
                return
            d = os.path.dirname(os.path.abspath(self.path))
            os.makedirs(d, exist_ok=True)
            # Two benchmarks may share the file: under a lock, merge what the other wrote.
            with open(self.path + ".lock", "w") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX)
                try:
                    with open(self.path) as f:
                        disk = json.load(f)
                except (OSError, ValueError):
                    disk = {}
                disk.update(self.data)
                self.data = disk
                fd, tmp = tempfile.mkstemp(dir=d, prefix=".bench_cache.")
                with os.fdopen(fd, "w") as f:
                    json.dump(self.data, f, indent=0, sort_keys=True)
                os.replace(tmp, self.path)


def run(cmd):
    """(stdout, wall seconds); RuntimeError with the command and its stderr on failure."""
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    dt = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f"exit {p.returncode}: {' '.join(cmd)}\n{p.stderr.strip()}")
    return p.stdout, dt


def last_json(stdout):
    for line in reversed(stdout.strip().splitlines()):
        line = line.strip()
        if line.startswith("{"):
            return json.loads(line)
    raise ValueError("no JSON object in the output")


def evaluate(msmesh, result, truth):
    out, _ = run([msmesh, "eval", result, "--truth", truth, "--json"])
    j = last_json(out)
    return {k: j[k] for k in METRICS if k in j}


def denoise(msmesh, noisy, truth, args, workdir):
    """`msmesh denoise NOISY -o OUT ARGS --json -q`, scored with msmesh eval. The score dict gets
    `seconds` (normal filtering + vertex update when the JSON has them, else the wall time) and
    `info` (the JSON's preset / estimate fields, when present)."""
    fd, out = tempfile.mkstemp(dir=workdir, suffix=".ply")
    os.close(fd)
    try:
        stdout, wall = run([msmesh, "denoise", noisy, "-o", out, "--json", "-q"] + list(args))
        try:
            j = last_json(stdout)
        except ValueError:
            j = {}
        s = evaluate(msmesh, out, truth)
    finally:
        if os.path.exists(out):
            os.remove(out)
    if "seconds_normals" in j and "seconds_vertices" in j:
        s["seconds"] = j["seconds_normals"] + j["seconds_vertices"]
    else:
        s["seconds"] = wall
    info = {k: j[k] for k in ("preset", "preset_reason", "noise_sigma", "noise_level", "estimate", "estimates")
            if k in j}
    if info:
        s["info"] = info
    return s


def taubin(msmesh, noisy, truth, workdir, iterations=10):
    fd, out = tempfile.mkstemp(dir=workdir, suffix=".obj")
    os.close(fd)
    try:
        t0 = time.time()
        taubin_mod.smooth_file(noisy, out, iterations)
        dt = time.time() - t0
        s = evaluate(msmesh, out, truth)
    finally:
        os.remove(out)
    s["seconds"] = dt
    return s


def cached(cache, key, fn):
    """cache[key], else fn() stored under key (errors are not cached)."""
    v = cache.get(key) if cache else None
    if v is None:
        v = fn()
        if cache:
            cache.put(key, v)
    return v


def geomean(values):
    vals = [v for v in values if v is not None and v > 0]
    if not vals:
        return None
    return math.exp(sum(math.log(v) for v in vals) / len(vals))


def fmt(v, digits=2):
    if v is None or v == "":
        return ""
    if isinstance(v, float):
        return f"{v:.{digits}f}"
    return str(v)


def taubin_missing():
    return taubin_mod.missing_reason()
