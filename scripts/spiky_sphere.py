"""A sphere with thin spikes, whose flip-free maps wind over each other: an
octahedron subdivided four times (midpoint, onto the unit sphere), every
29th vertex pushed out to three times the radius (2048 faces), as OFF.
With --smooth LEVELS: the sphere subdivided LEVELS times, no spikes
(8 * 4^LEVELS faces).

Usage: /usr/bin/python3 scripts/spiky_sphere.py OUT.off [--smooth LEVELS]
"""
import math
import sys

V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
smooth = len(sys.argv) == 4 and sys.argv[2] == "--smooth"
if len(sys.argv) != 2 and not smooth:
    sys.exit("usage: spiky_sphere.py OUT.off [--smooth LEVELS]")
for _ in range(int(sys.argv[3]) if smooth else 4):
    mid, out = {}, []

    def m(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            mid[key] = len(V)
            p = [(s + t) / 2 for s, t in zip(V[a], V[b])]
            r = math.sqrt(sum(c * c for c in p))
            V.append(tuple(c / r for c in p))
        return mid[key]

    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    F = out
if not smooth:
    V = [tuple(3 * c for c in v) if i % 29 == 9 else v for i, v in enumerate(V)]
with open(sys.argv[1], "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
    f.writelines("%.9g %.9g %.9g\n" % v for v in V)
    f.writelines("3 %d %d %d\n" % t for t in F)
