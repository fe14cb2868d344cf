#!/usr/bin/env bash
# The cost of global injectivity (docs/design.md, "Global injectivity"): every
# shared disk mesh parameterized with the default method, flip-free only
# (--injectivity local, the paper's Algorithm 1) and globally injective (the
# default), as a Markdown table of iterations, optimizer seconds, the final
# distortion energy and the overlap each leaves.
# Usage: bash scripts/injectivity.sh   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
summary=$(mktemp --suffix=.json)
trap 'rm -f "$summary"' EXIT

echo "| mesh | faces | local: iterations, s, energy, overlap | global: iterations, s, energy, overlap |"
echo "|---|---|---|---|"
for mesh in camel_b.obj cow_b.obj tricera_b.obj horse_b.obj camelhead.off hilbert_b.obj lilium.obj snail.obj \
            inspired_mesh.obj bump-domain.obj; do
  row="| $mesh |"
  for injectivity in local global; do
    rm -f "$summary"
    "$AKVF" param "$DATA/tri/$mesh" --quiet --injectivity "$injectivity" --summary "$summary" > /dev/null 2>&1 || true
    cell=$(/usr/bin/python3 - "$summary" "$injectivity" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
faces = s["elements"]
o = s["overlap"]
overlap = "none" if o["boundary_crossings"] == 0 and o["area_fraction"] == 0 else \
    "%d crossings, %.3g %% of the area" % (o["boundary_crossings"], 100 * o["area_fraction"])
text = "%d, %.3f, %.7f, %s" % (s["iterations"], s["seconds"], s["distortion_energy"], overlap)
print(("%d | " % faces if sys.argv[2] == "local" else "") + text + " |")
PY
)
    row="$row $cell"
  done
  echo "$row"
done
