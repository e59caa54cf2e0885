#!/usr/bin/python3
"""Denoising defaults on noise that is not in ../shared: procedural surfaces with smooth detail.

    /usr/bin/python3 bench/detail_waves.py [--msmesh build/msmesh [--msmesh OLD]] [--no-taubin]

`msmesh shape sphere -r 40` (20K faces) and `msmesh shape torus -r 48` (69K faces) get 12 plane
waves along their normals (random directions, wavelengths 4-16 mean edge lengths, RMS 0.21 edge
lengths, seed 42): a detailed "clean" surface that no public mesh is. Then seeded noise
(`msmesh noise --sigma S --direction D --seed 7`, S in 0.05 0.1 0.2 0.3 0.5, both directions),
denoised by every --msmesh at its defaults and by the baselines (`--method bilateral` of the
first --msmesh; Open3D's Taubin x10, bench/taubin.py, unless --no-taubin or python3-open3d is
missing), each scored with `msmesh eval --truth` against the wavy surface. Prints a markdown
table of MSAE x1e-3 and flipped faces. docs/presets.md, "Noise and detail", used it to check the
detail rule of `--preset auto` on surfaces the sweep does not have. Needs numpy and the msmesh
Python module (build/python, or --python).
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import scoring  # noqa: E402

SHAPES = (("sphere", 40), ("torus", 48))
SIGMAS = (0.05, 0.1, 0.2, 0.3, 0.5)


def wavy(msmesh_exe, name, resolution, folder, np, mm):
    """The procedural shape with 12 seeded plane waves along its vertex normals, as an OBJ."""
    base = os.path.join(folder, f"{name}_base.obj")
    subprocess.run([msmesh_exe, "shape", name, "-r", str(resolution), "-o", base, "-q"], check=True)
    V, F = mm.read_mesh(base)
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    h = np.linalg.norm(V[E[:, 0]] - V[E[:, 1]], axis=1).mean()
    fn = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    N = np.zeros_like(V)
    for k in range(3):
        np.add.at(N, F[:, k], fn)
    N /= np.linalg.norm(N, axis=1)[:, None]
    rng = np.random.default_rng(42)
    disp = np.zeros(len(V))
    for _ in range(12):
        d = rng.normal(size=3)
        d /= np.linalg.norm(d)
        wavelength = rng.uniform(4, 16) * h
        disp += np.sin(2 * np.pi * V @ d / wavelength + rng.uniform(0, 6.28)) * rng.uniform(0.1, 0.3) * h
    out = os.path.join(folder, f"{name}_waves.obj")
    mm.write_mesh(out, V + (disp / np.sqrt(6))[:, None] * N, F)
    return out, len(F)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--msmesh", action="append", default=[], help="msmesh executable (repeat to compare builds)")
    ap.add_argument("--python", default=os.path.join(ROOT, "build", "python"), help="folder of the msmesh module")
    ap.add_argument("--no-taubin", action="store_true", help="leave Open3D's Taubin x10 out")
    a = ap.parse_args()
    exes = [os.path.abspath(e) for e in (a.msmesh or [os.path.join(ROOT, "build", "msmesh")])]
    for e in exes:
        if not os.access(e, os.X_OK):
            print(f"bench/detail_waves.py: {e} is not an executable (build it: scripts/build)", file=sys.stderr)
            return 2
    sys.path.insert(0, a.python)
    import numpy as np
    import msmesh as mm

    use_taubin = not a.no_taubin and scoring.taubin_missing() is None
    if not a.no_taubin and not use_taubin:
        print(f"bench/detail_waves.py: no Taubin baseline ({scoring.taubin_missing()})", file=sys.stderr)
    cols = [f"msmesh {i + 1}" for i in range(len(exes))] + ["bilateral"] + (["Taubin x10"] if use_taubin else [])
    print("| surface | noise | sigma | noisy | " + " | ".join(cols) + " |")
    print("|---|---|---:|---:|" + "---:|" * len(cols))
    with tempfile.TemporaryDirectory() as work:
        for name, res in SHAPES:
            truth, faces = wavy(exes[0], name, res, work, np, mm)
            for direction in ("normal", "random"):
                for s in SIGMAS:
                    noisy = os.path.join(work, "noisy.obj")
                    scoring.run([exes[0], "noise", truth, "-o", noisy, "--sigma", str(s), "--direction", direction,
                                 "--seed", "7", "-q"])
                    scores = [scoring.evaluate(exes[0], noisy, truth)]
                    scores += [scoring.denoise(e, noisy, truth, [], work) for e in exes]
                    scores.append(scoring.denoise(exes[0], noisy, truth, ["--method", "bilateral"], work))
                    if use_taubin:
                        scores.append(scoring.taubin(exes[0], noisy, truth, work))
                    cells = [f"{x['msae_e3']:.2f} ({x['flipped']})" for x in scores]
                    print(f"| {name} waves ({faces} faces) | {direction} | {s} | " + " | ".join(cells) + " |", flush=True)
    print(f"\nMSAE x1e-3 (flipped faces) against the wavy surface; msmesh N = {', '.join(exes)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
