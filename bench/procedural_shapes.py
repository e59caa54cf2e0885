#!/usr/bin/python3
"""Denoising defaults on noise that is not in ../shared: msmesh's procedural shapes, A against B.

    /usr/bin/python3 bench/procedural_shapes.py [--msmesh build/msmesh] [--a "--polish 0"] [--b ""] [--fine]
                                                [--correlation K]

`msmesh shape NAME -r R` for cube 24, fandisk 32, pyramid 32, cylinder 32, torus 32 and sphere 16
(2.4K-31K faces; cube, fandisk and pyramid have creases and flat parts, the others are smooth),
seeded noise (`msmesh noise --sigma S --direction D --seed 17`, S in 0.05 0.1 0.2 0.3 0.5 0.7, both
directions), each denoised twice by `msmesh denoise IN -o OUT` plus the arguments of --a and of
--b (default: "--polish 0" against the defaults), scored with `msmesh eval --truth` against the
clean shape. Prints a markdown table of MSAE x1e-3, the class `auto` chose, the ratio B / A, the
geometric means and the cases where B is worse by more than 1 %. docs/presets.md, "The polish",
used it; `--msmesh OLD --msmesh NEW` with --a "" --b "" compares two builds instead.
--fine: the same shapes finer (cube 64, fandisk, pyramid, cylinder and torus 80, sphere 64;
49K-192K faces, √area / mean edge 138-264) at S in 0.1 0.3 0.5, where the shape class once read
fine smooth surfaces as flat (docs/presets.md, "The flat test at any resolution").
--correlation K: correlated noise like a depth camera's (`msmesh noise --correlation K`, made by
B's executable: builds before it existed lack the option), S in 0.1 0.2 0.3 0.5; docs/presets.md,
"Correlated noise".
"""
import argparse
import math
import os
import shlex
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import scoring  # noqa: E402

SHAPES = (("cube", 24), ("fandisk", 32), ("pyramid", 32), ("cylinder", 32), ("torus", 32), ("sphere", 16))
SIGMAS = (0.05, 0.1, 0.2, 0.3, 0.5, 0.7)
FINE_SHAPES = (("cube", 64), ("fandisk", 80), ("pyramid", 80), ("cylinder", 80), ("torus", 80), ("sphere", 64))
FINE_SIGMAS = (0.1, 0.3, 0.5)
CORRELATED_SIGMAS = (0.1, 0.2, 0.3, 0.5)


def denoise(exe, noisy, clean, args, folder):
    """MSAE x1e-3 of `exe denoise noisy ARGS` against clean, and the class auto chose."""
    out = os.path.join(folder, "out.ply")
    stdout, _ = scoring.run([exe, "denoise", noisy, "-o", out, "--json", "-q"] + args)
    preset = scoring.last_json(stdout).get("preset", "")
    return scoring.evaluate(exe, out, clean)["msae_e3"], preset


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--msmesh", action="append", default=[], help="msmesh executable (twice: A's and B's)")
    ap.add_argument("--a", default="--polish 0", help="arguments of run A (default: %(default)s)")
    ap.add_argument("--b", default="", help="arguments of run B (default: none, the defaults)")
    ap.add_argument("--fine", action="store_true", help="finer shapes (49K-192K faces), sigma 0.1 0.3 0.5")
    ap.add_argument("--correlation", type=int, default=0,
                    help="correlated noise: msmesh noise --correlation K (0: white), sigma 0.1 0.2 0.3 0.5")
    args = ap.parse_args()
    exes = args.msmesh or [os.path.join(ROOT, "build", "msmesh")]
    exe_a, exe_b = exes[0], exes[-1]
    for exe in (exe_a, exe_b):
        if not os.access(exe, os.X_OK):
            sys.exit(f"bench/procedural_shapes.py: {exe} is not an executable (build first: scripts/build)")
    a_args, b_args = shlex.split(args.a), shlex.split(args.b)
    print(f"A: {exe_a} {args.a}\nB: {exe_b} {args.b}\n")
    print("| shape | faces | noise | sigma | class A / B | MSAE A | MSAE B | B / A |")
    print("|---|---:|---|---:|---|---:|---:|---:|")
    logs_a, logs_b, worse, cases = [], [], [], 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, resolution in FINE_SHAPES if args.fine else SHAPES:
            clean = os.path.join(tmp, f"{name}.obj")
            scoring.run([exe_a, "shape", name, "-r", str(resolution), "-o", clean, "-q"])
            faces = scoring.run([exe_a, "info", clean])[0].split("faces:")[1].split()[0]
            for direction in ("normal", "random"):
                sigmas = FINE_SIGMAS if args.fine else CORRELATED_SIGMAS if args.correlation else SIGMAS
                for sigma in sigmas:
                    noisy = os.path.join(tmp, "noisy.obj")
                    noise = [exe_b if args.correlation else exe_a, "noise", clean, "-o", noisy, "--sigma", str(sigma),
                             "--direction", direction, "--seed", "17", "-q"]
                    scoring.run(noise + (["--correlation", str(args.correlation)] if args.correlation else []))
                    ma, ca = denoise(exe_a, noisy, clean, a_args, tmp)
                    mb, cb = denoise(exe_b, noisy, clean, b_args, tmp)
                    cases += 1
                    logs_a.append(math.log(ma))
                    logs_b.append(math.log(mb))
                    if mb > 1.01 * ma:
                        worse.append(f"{name} {direction} {sigma}")
                    print(f"| {name} | {faces} | {direction} | {sigma} | {ca} / {cb} | {ma:.3f} | {mb:.3f} | "
                          f"{mb / ma:.2f} |", flush=True)
    print(f"\ngeometric mean of MSAE: A {math.exp(sum(logs_a) / cases):.3f}, B {math.exp(sum(logs_b) / cases):.3f}; "
          f"B worse than A by more than 1 %: {len(worse)} of {cases}" + (f" ({', '.join(worse)})" if worse else ""))


if __name__ == "__main__":
    main()
