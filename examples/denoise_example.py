#!/usr/bin/env python3
"""Denoises a mesh with the msmesh Python package and prints the error figures.

    PYTHONPATH=build/python /usr/bin/python3 examples/denoise_example.py
        the built-in fandisk shape, with seeded Gaussian noise added
    ... examples/denoise_example.py clean.ply
        a clean mesh of yours, with seeded noise added; errors against the clean mesh
    ... examples/denoise_example.py noisy.obj --truth clean.obj -o result.ply
        a noisy mesh as it is; errors against the given ground truth

Options choose the preset, the method, the noise and where to write the result.
"""

import argparse
import sys
import time

import msmesh


def print_errors(label, e):
    if e["same_connectivity"]:
        normals = (f"MSAE {e['msae_e3']:8.3f} e-3   mean angle {e['mean_angle_deg']:6.2f} deg   "
                   f"flipped {e['flipped']:4d}   ")
    else:
        normals = "(different connectivity: no normal errors)   "
    print(f"  {label:<8} {normals}distance mean/RMS/max "
          f"{e['distance_mean'] * 1e3:.3f}/{e['distance_rms'] * 1e3:.3f}/{e['distance_max'] * 1e3:.3f} e-3")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mesh", nargs="?", help="mesh file (obj, off, ply, stl); default: built-in fandisk shape")
    p.add_argument("--truth", help="ground truth of `mesh`: denoise `mesh` as it is, without adding noise")
    p.add_argument("--resolution", type=int, default=12, help="resolution of the built-in shape (default 12)")
    p.add_argument("--sigma", type=float, default=0.3, help="noise, in mean edge lengths (default 0.3)")
    p.add_argument("--seed", type=int, default=1, help="noise seed (default 1)")
    p.add_argument("--preset", default="cad", choices=msmesh.preset_names())
    p.add_argument("--method", default="nmstv", choices=["nmstv", "mstv", "bilateral"])
    p.add_argument("-o", "--output", help="write the denoised mesh here")
    a = p.parse_args(argv)

    if a.truth and not a.mesh:
        p.error("--truth needs a mesh")
    if a.mesh is None:
        V_truth, F_truth = msmesh.make_shape("fandisk", a.resolution)
        source = f"built-in fandisk (resolution {a.resolution})"
    else:
        V_truth, F_truth = msmesh.read_mesh(a.truth or a.mesh)
        source = a.truth or a.mesh
    F = F_truth
    if a.truth:
        V_noisy, F = msmesh.read_mesh(a.mesh)
        print(f"{a.mesh}: {V_noisy.shape[0]} vertices, {F.shape[0]} faces; truth {a.truth}")
    else:
        V_noisy = msmesh.add_noise(V_truth, F, sigma=a.sigma, seed=a.seed)
        print(f"{source}: {V_truth.shape[0]} vertices, {F.shape[0]} faces; "
              f"noise sigma {a.sigma} mean edge lengths, seed {a.seed}")

    def show_progress(event):  # a one-line progress display on a terminal
        print(f"\r  {event.stage:<18} {event.iteration:3d}/{event.max_iterations:<3d}", end="", file=sys.stderr)

    interactive = sys.stderr.isatty()
    t0 = time.perf_counter()
    V_denoised, report = msmesh.denoise(V_noisy, F, preset=a.preset, method=a.method,
                                        progress=show_progress if interactive else None)
    if interactive:
        print("\r\x1b[K", end="", file=sys.stderr)
    print(f"denoised with {a.method}, preset {report['preset']} in {time.perf_counter() - t0:.2f} s "
          f"({report['normal_iterations']} normal + {report['vertex_iterations']} vertex iterations)")

    print("errors against the truth (distances relative to its bounding-box diagonal):")
    print_errors("input", msmesh.evaluate(V_noisy, F, V_truth, F_truth))
    print_errors("result", msmesh.evaluate(V_denoised, F, V_truth, F_truth))

    if a.output:
        msmesh.write_mesh(a.output, V_denoised, F)
        print(f"wrote {a.output}")


if __name__ == "__main__":
    try:
        main()
    except msmesh.Error as e:  # bad file or parameter: the library's message names it
        sys.exit(f"error: {e}")
