#!/usr/bin/python3
"""Parameterize a triangle mesh from Python with akvf, printing progress.

    /usr/bin/python3 examples/python/parameterize.py [MESH.obj|MESH.off] [--out UV.obj] [--precond NAME]

Without a mesh it builds a curved grid, so it runs with no files. Run it
with Debian's interpreter (the one the module is built for) and the package
on the path: PYTHONPATH=build/python after scripts/build.sh, or the prefix's
site-packages folder after cmake --install (docs/python.md).
"""
import argparse

import numpy as np

import akvf


def curved_grid(n=30):
    xs, ys = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    V = np.stack([xs.ravel(), ys.ravel(), 0.4 * np.sin(3 * xs.ravel()) * np.cos(2 * ys.ravel())], axis=1)
    quads = [(i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1)
             for i in range(n - 1) for j in range(n - 1)]
    F = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    return V, F


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh", nargs="?", help="a disk-topology OBJ or OFF mesh (default: a curved grid)")
    parser.add_argument("--out", help="write the mesh with its UVs (OBJ)")
    parser.add_argument("--precond", default="akvf-newton", help="see akvf.preconditioners() (default: the library's, akvf-newton)")
    args = parser.parse_args()

    V, F = akvf.read_mesh(args.mesh) if args.mesh else curved_grid()
    print("akvf %s: %d vertices, %d triangles, preconditioner %s" % (akvf.__version__, len(V), len(F), args.precond))

    def progress(row, uv):
        if row["iter"] % 10 == 0:
            print("  iteration %4d  energy %.10g  gradient norm %.3e" % (row["iter"], row["energy"], row["grad_norm"]))

    result = akvf.parameterize(V, F, precond=args.precond, callback=progress)
    print("%s after %d iterations, %.3f s: energy %.10g (%d factorizations)" % (
        result.status, result.iterations, result.statistics["seconds"], result.energy,
        result.statistics["factorizations"]))
    if args.out:
        akvf.write_mesh(args.out, V, F, result.uv, texture="none")
        print("wrote", args.out)
    return 0 if result.status == "converged" else 1


if __name__ == "__main__":
    raise SystemExit(main())
