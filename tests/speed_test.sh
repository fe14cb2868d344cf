#!/usr/bin/env bash
# akvf_speed's 2D rows on a generated disk (a bumpy 60 x 60 grid): each
# method's own stop, read from a run that went on to a tighter tolerance, is
# where `akvf param` with the default tolerance stops (iterations, energy),
# and every method that converges reaches the "to 1e-6" target; --refine-to
# subdivides a smaller mesh.
# Usage: speed_test.sh AKVF_SPEED_BINARY AKVF_BINARY
set -euo pipefail
speed=$1
akvf=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/tri"
bash "$(dirname "$0")/grid_mesh.sh" > "$dir/tri/grid.obj"
for energy in symmetric-dirichlet arap; do
  "$speed" --data "$dir" --min-faces 0 --only 2d --energy "$energy" --methods akvf,newton > "$dir/table.md"
  cat "$dir/table.md"
  for method in akvf newton; do
    # Columns: | mesh | faces | unit | CHOLMOD unit | method | iterations | ... | status | energy | iterations to 1e-6 | ...
    row=$(grep "| $method |" "$dir/table.md") || { echo "no $method row"; exit 1; }
    iterations=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $7); print $7}')
    status=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $12); print $12}')
    energy_row=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $13); print $13}')
    to_target=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $14); print $14}')
    cli=$("$akvf" param "$dir/tri/grid.obj" --energy "$energy" --precond "$method" --injectivity local --quiet \
      --out "$dir/uv.obj" | grep '^status')
    echo "akvf param: $cli"
    read -r cli_iterations cli_energy < <(echo "$cli" | sed -E 's/.* after ([0-9]+) iterations.*energy ([^,]+),.*/\1 \2/')
    [ "$status" = converged ] && echo "$cli" | grep -q '^status converged' ||
      { echo "$energy $method: not converged ($status; $cli)"; exit 1; }
    [ "$iterations" = "$cli_iterations" ] ||
      { echo "$energy $method: own stop at $iterations iterations, akvf param at $cli_iterations"; exit 1; }
    awk -v a="$energy_row" -v b="$cli_energy" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-8 * b + 1e-14) }' ||
      { echo "$energy $method: own stop at energy $energy_row, akvf param at $cli_energy"; exit 1; }
    [ "$to_target" != - ] || { echo "$energy $method: converged but never within the target"; exit 1; }
  done
done
# --refine-to: the grid (6962 faces) subdivided once, to 27848, and labelled so.
"$speed" --data "$dir" --refine-to 10000 --only 2d --methods default > "$dir/refined.md"
grep -q '^| grid.obj x4 | 27848 |.*| converged |' "$dir/refined.md" ||
  { cat "$dir/refined.md"; echo "--refine-to 10000: no converged row for grid.obj x4 with 27848 faces"; exit 1; }
echo "ok"
