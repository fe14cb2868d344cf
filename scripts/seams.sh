#!/usr/bin/env bash
# --cut seams on the shared closed meshes and on the disk meshes whose
# distortion is above the bound (docs/results.md, "Seams that bound the
# distortion"): the energy with the first cut alone, then with the seams,
# as a Markdown table.
# Usage: bash scripts/seams.sh   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| mesh | faces | --cut auto: energy | --cut seams: seams added, seam length / sqrt(area), largest chart energy, inverted, overlap, optimizer s, wall s |"
echo "|---|---|---|---|"
for mesh in cow_closed.off bunny_closed.off camelhead.off; do
  "$AKVF" param "$DATA/tri/$mesh" --quiet --cut auto --summary "$work/auto.json" > /dev/null
  start=$(date +%s.%N)
  "$AKVF" param "$DATA/tri/$mesh" --quiet --cut seams --summary "$work/seams.json" --out "$work/uv.obj" > /dev/null
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 - "$mesh" "$work/auto.json" "$work/seams.json" "$wall" <<'PY'
import json, sys
mesh, auto, seams, wall = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3])), float(sys.argv[4])
s, o = seams["seams"], seams["overlap"]
overlap = "none" if o["boundary_crossings"] == 0 and o["area_fraction"] == 0 else "%d crossings" % o["boundary_crossings"]
print("| %s | %d | %.4f | %d, %.2f, %.4f, %d, %s, %.2f, %.2f |" % (
    mesh, seams["elements"], auto["distortion_energy"], s["added"], s["seam_length"], max(s["chart_distortion"]),
    seams["max_flips"], overlap, seams["seconds"], wall))
PY
done
