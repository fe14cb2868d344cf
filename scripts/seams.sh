#!/usr/bin/env bash
# --cut seams on the shared closed meshes and on the disk meshes whose
# distortion is above the bound (docs/results.md, "Seams that bound the
# distortion"): the energy with the first cut alone, then with the seams,
# as a Markdown table; also a generated sphere with thin spikes and a scene
# of several components. --large adds bunny_closed subdivided twice
# (midpoint subdivision, 111 456 faces) and a smooth sphere of 131 072
# faces (under 2 minutes).
# Usage: bash scripts/seams.sh [--large]   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| mesh | faces | --cut auto: energy | --cut seams: seams added, charts (straight cuts for the packing, pieces where the flip-free map overlapped, parted), seam length / sqrt(area), largest chart energy, coverage, inverted, overlap, optimizer s, wall s |"
echo "|---|---|---|---|"
meshes=("$DATA/tri/cow_closed.off" "$DATA/tri/bunny_closed.off" "$DATA/tri/camelhead.off")
# A generated sphere with thin spikes, whose flip-free maps wind over each
# other.
/usr/bin/python3 scripts/spiky_sphere.py "$work/spiky_sphere.off"
meshes+=("$work/spiky_sphere.off")
# Several components, as a scene: cow_closed, bunny_closed beside it, and
# cow_closed at 0.3 of its size.
/usr/bin/python3 - "$DATA/tri/cow_closed.off" "$DATA/tri/bunny_closed.off" "$work/cow_bunny_calf.off" <<'PY'
import sys
V, F = [], []
for path, scale, shift in ((sys.argv[1], 1, 0), (sys.argv[2], 1, 3), (sys.argv[1], 0.3, -3)):
    lines = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    nv, nf = int(lines[1][0]), int(lines[1][1])
    base = len(V)
    V += [(scale * float(l[0]) + shift, scale * float(l[1]), scale * float(l[2])) for l in lines[2:2 + nv]]
    F += [tuple(base + int(i) for i in l[1:4]) for l in lines[2 + nv:2 + nv + nf]]
with open(sys.argv[3], "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
    f.writelines("%.9g %.9g %.9g\n" % v for v in V)
    f.writelines("3 %d %d %d\n" % t for t in F)
PY
meshes+=("$work/cow_bunny_calf.off")
if [ "${1:-}" = "--large" ]; then
  /usr/bin/python3 - "$DATA/tri/bunny_closed.off" "$work/bunny_closed_x16.off" <<'PY'
import sys
lines = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
nv, nf = int(lines[1][0]), int(lines[1][1])
V = [tuple(map(float, l[:3])) for l in lines[2:2 + nv]]
F = [tuple(map(int, l[1:4])) for l in lines[2 + nv:2 + nv + nf]]
for _ in range(2):  # midpoint (1-to-4) subdivision
    mid, out = {}, []
    def m(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            mid[key] = len(V)
            V.append(tuple((p + q) / 2 for p, q in zip(V[a], V[b])))
        return mid[key]
    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    F = out
with open(sys.argv[2], "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
    f.writelines("%.9g %.9g %.9g\n" % v for v in V)
    f.writelines("3 %d %d %d\n" % t for t in F)
PY
  meshes+=("$work/bunny_closed_x16.off")
  # A smooth sphere as finely meshed (131 072 faces).
  /usr/bin/python3 scripts/spiky_sphere.py "$work/sphere_x64.off" --smooth 7
  meshes+=("$work/sphere_x64.off")
fi
for path in "${meshes[@]}"; do
  mesh=$(basename "$path")
  "$AKVF" param "$path" --quiet --cut auto --summary "$work/auto.json" > /dev/null
  start=$(date +%s.%N)
  "$AKVF" param "$path" --quiet --cut seams --summary "$work/seams.json" --out "$work/uv.obj" > /dev/null
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 - "$mesh" "$work/auto.json" "$work/seams.json" "$wall" <<'PY'
import json, sys
mesh, auto, seams, wall = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3])), float(sys.argv[4])
s, o = seams["seams"], seams["overlap"]
overlap = "none" if o["boundary_crossings"] == 0 and o["area_fraction"] == 0 else "%d crossings" % o["boundary_crossings"]
c = seams["cut"]
print("| %s | %d | %.4f | %d, %d (%d, %d, %d), %.2f, %.4f, %.1f %%, %d, %s, %.2f, %.2f |" % (
    mesh, seams["elements"], auto["distortion_energy"], s["added"], c["charts"], c["packing_splits"],
    s["overlap_pieces"], s["parted_charts"],
    s["seam_length"], max(s["chart_distortion"]), 100 * seams["uv_coverage"], seams["max_flips"], overlap,
    seams["seconds"], wall))
PY
done
