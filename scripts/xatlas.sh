#!/usr/bin/env bash
# `--cut seams` beside xatlas (docs/results.md, "Seams beside xatlas") on the
# shared closed meshes and camelhead: charts, symmetric Dirichlet energy
# (the whole atlas and its largest chart), seam length over the square root
# of the area, the UV square's coverage, inverted triangles and wall
# seconds, as a Markdown table. xatlas runs as the npm package xatlasjs
# 0.2.0 (its WebAssembly build) under Node, with its default options,
# measured by experiments/peers/xatlas.mjs; the package is installed once
# into build/peers/xatlas.
# Usage: bash scripts/xatlas.sh   (after scripts/build.sh; needs node and npm)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
peers=build/peers/xatlas
if [ ! -f "$peers/node_modules/xatlasjs/dist/node/xatlas.js" ]; then
  mkdir -p "$peers"
  npm install --prefix "$peers" --no-save --no-audit --no-fund xatlasjs@0.2.0 > /dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| mesh | faces | method | charts | energy: atlas, largest chart | seam length / sqrt(area) | coverage | inverted | wall s |"
echo "|---|---|---|---|---|---|---|---|---|"
for mesh in cow_closed.off bunny_closed.off camelhead.off; do
  start=$(date +%s.%N)
  "$AKVF" param "$DATA/tri/$mesh" --quiet --cut seams --summary "$work/seams.json" --out "$work/uv.obj" > /dev/null
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 - "$mesh" "$work/seams.json" "$wall" <<'PY'
import json, sys
mesh, s, wall = sys.argv[1], json.load(open(sys.argv[2])), float(sys.argv[3])
seams = s["seams"]
print("| %s | %d | akvf --cut seams | %d | %.4f, %.4f | %.2f | %.1f %% | %d | %.2f |" % (
    mesh, s["elements"], len(seams["chart_distortion"]), s["distortion_energy"], max(seams["chart_distortion"]),
    seams["seam_length"], 100 * s["uv_coverage"], s["max_flips"], wall))
PY
  start=$(date +%s.%N)
  node experiments/peers/xatlas.mjs "$PWD/$peers" "$DATA/tri/$mesh" > "$work/xatlas.json"
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 - "$work/xatlas.json" "$wall" <<'PY'
import json, sys
x, wall = json.load(open(sys.argv[1])), float(sys.argv[2])
print("| %s | %d | xatlas | %d | %.4f, %.4f | %.2f | %.1f %% | %d | %.2f |" % (
    x["mesh"], x["faces"], x["charts"], x["energy"], x["largest_chart_energy"], x["seam_length"],
    100 * x["coverage"], x["inverted"], wall))
PY
done
