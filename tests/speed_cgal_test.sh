#!/usr/bin/env bash
# akvf_speed's CGAL peer on a generated disk (a bumpy 60 x 60 grid): a row for
# CGAL's ARAP parameterizer with its iterations, its inverted triangles per
# iterate and its energy scored as ours; `cgal` refused with another energy.
# Usage: speed_cgal_test.sh AKVF_SPEED_BINARY
set -euo pipefail
speed=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/tri"
bash "$(dirname "$0")/grid_mesh.sh" > "$dir/tri/grid.obj"
"$speed" --data "$dir" --min-faces 0 --only 2d --energy arap --methods newton,cgal > "$dir/table.md"
cat "$dir/table.md"
row=$(grep '| cgal (own start and stop) |' "$dir/table.md") || { echo "no CGAL row"; exit 1; }
# Columns: | mesh | faces | unit | CHOLMOD unit | method | iterations | seconds | ... | status | energy | ...
iterations=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $7); print $7}')
[ "$iterations" -ge 1 ] || { echo "CGAL's iterations not counted: $iterations"; exit 1; }
echo "$row" | grep -q 'inverted: start [0-9]*, iterates at most [0-9]*, final 0' || { echo "CGAL's map on a flat-ish grid should end flip-free"; exit 1; }
energy=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $13); print $13}')
awk -v e="$energy" 'BEGIN { exit !(e + 0 > 0 && e + 0 < 1) }' || { echo "CGAL's ARAP energy not scored: $energy"; exit 1; }
newton=$(grep '| newton |' "$dir/table.md" | awk -F'|' '{gsub(/ /, "", $13); print $13}')
# Newton converges to a minimum of the same energy; CGAL's local/global stops near it.
awk -v e="$energy" -v n="$newton" 'BEGIN { exit !(n <= e * (1 + 1e-3)) }' || { echo "newton $newton above CGAL $energy"; exit 1; }
set +e
"$speed" --data "$dir" --only 2d --energy mips --methods cgal > /dev/null 2> "$dir/err"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q 'use it with --energy arap' "$dir/err" || { echo "cgal with mips: exit $code"; cat "$dir/err"; exit 1; }
echo "ok"
