"""Disk meshes beside the shared ones, for checks on meshes no constant was
chosen on: writes OUT/tri/ for `akvf_speed --data OUT` and the other
scripts that read a data folder's tri/.

- NAME_jitter.obj for each disk mesh NAME_b.obj and for camelhead.off of
  DATA/tri: every vertex moved by a seeded Gaussian of standard deviation a
  fifth of the mean edge length (rest triangles far from the scan's regular
  ones);
- cone_strip.obj: a strip of 1200 x 6 vertices (11990 faces, diagonals
  chosen at random) laid three times around a cone rising half a unit per
  unit of radius, and a little along its length, so it is nearly
  developable and its isometric flattening winds about 2.7 times around
  itself (`--injectivity local` lets it overlap).

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/perturbed_meshes.py DATA OUT
(after scripts/build.sh: the meshes are read by the akvf module).
"""
import math
import os
import random
import sys

try:
    import akvf
except ImportError as error:
    sys.exit("perturbed_meshes.py: cannot import the akvf module (%s); build it with bash scripts/build.sh "
             "and run with PYTHONPATH=build/python /usr/bin/python3" % error)


def write_obj(path, vertices, triangles):
    with open(path + ".partial", "w") as f:
        for v in vertices:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for t in triangles:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in t))
    os.replace(path + ".partial", path)


def jittered(vertices, triangles, rng):
    edges = [math.dist(vertices[t[i]], vertices[t[(i + 1) % 3]]) for t in triangles for i in range(3)]
    sigma = 0.2 * sum(edges) / len(edges)
    return [[c + rng.gauss(0, sigma) for c in v] for v in vertices]


def cone_strip(rng, n=1200, m=6, length=200.0, width=1.0, turns=3):
    vertices = []
    for j in range(m):
        for i in range(n):
            x, y = length * i / (n - 1), width * j / (m - 1)
            angle = 2 * math.pi * turns * x / length
            vertices.append([(3 + y) * math.cos(angle), (3 + y) * math.sin(angle), 0.5 * y + 0.02 * x])
    triangles = []
    for j in range(m - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i, (j + 1) * n + i + 1
            triangles += [[a, b, d], [a, d, c]] if rng.random() < 0.5 else [[a, b, c], [b, d, c]]
    return vertices, triangles


def perturbed_meshes(data):
    """(file name, vertices, triangles) of each mesh written, in order."""
    rng = random.Random(1)
    names = sorted(n for n in os.listdir(os.path.join(data, "tri")) if n.endswith("_b.obj") or n == "camelhead.off")
    for name in names:
        V, F = akvf.read_mesh(os.path.join(data, "tri", name))
        vertices, triangles = V.tolist(), F.tolist()
        yield os.path.splitext(name)[0] + "_jitter.obj", jittered(vertices, triangles, rng), triangles
    yield ("cone_strip.obj",) + cone_strip(rng)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: perturbed_meshes.py DATA OUT")
    data, out = sys.argv[1], os.path.join(sys.argv[2], "tri")
    os.makedirs(out, exist_ok=True)
    count = 0
    for name, vertices, triangles in perturbed_meshes(data):
        write_obj(os.path.join(out, name), vertices, triangles)
        count += 1
    print("wrote %d meshes to %s" % (count, out))


if __name__ == "__main__":
    main()
