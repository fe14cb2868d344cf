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

Usage: /usr/bin/python3 scripts/perturbed_meshes.py DATA OUT
"""
import math
import os
import random
import sys


def read_mesh(path):
    """Vertices and triangles of an OBJ or OFF file (polygons fanned)."""
    vertices, faces = [], []
    with open(path) as f:
        if path.endswith(".off"):
            tokens = f.read().split()
            assert tokens[0] == "OFF", path
            nv, nf = int(tokens[1]), int(tokens[2])
            at = 4
            for _ in range(nv):
                vertices.append([float(t) for t in tokens[at:at + 3]])
                at += 3
            for _ in range(nf):
                n = int(tokens[at])
                faces.append([int(t) for t in tokens[at + 1:at + 1 + n]])
                at += 1 + n
        else:
            for line in f:
                t = line.split()
                if t and t[0] == "v":
                    vertices.append([float(c) for c in t[1:4]])
                elif t and t[0] == "f":
                    faces.append([int(c.split("/")[0]) - 1 for c in t[1:]])
    triangles = [[p[0], p[i], p[i + 1]] for p in faces for i in range(1, len(p) - 1)]
    return vertices, triangles


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


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: perturbed_meshes.py DATA OUT")
    data, out = sys.argv[1], os.path.join(sys.argv[2], "tri")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(1)
    names = sorted(n for n in os.listdir(os.path.join(data, "tri")) if n.endswith("_b.obj") or n == "camelhead.off")
    for name in names:
        vertices, triangles = read_mesh(os.path.join(data, "tri", name))
        stem = os.path.splitext(name)[0]
        write_obj(os.path.join(out, stem + "_jitter.obj"), jittered(vertices, triangles, rng), triangles)
    write_obj(os.path.join(out, "cone_strip.obj"), *cone_strip(rng))
    print("wrote %d meshes to %s" % (len(names) + 1, out))


main()
