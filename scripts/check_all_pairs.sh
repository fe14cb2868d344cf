#!/usr/bin/env bash
# Issue 3's acceptance check: every energy x method on every disk mesh of
# ../shared/meshes/tri for ITERS iterations (default 30): 0 inverted
# triangles at every iterate (the trace's flips column) and a final energy
# no higher than the start. Exits 1 on any violation. About 7 minutes here.
set -euo pipefail
cd "$(dirname "$0")/.."
AKVF=./build/akvf
DATA=${AKVF_DATA_DIR:-../shared/meshes}
ITERS=${ITERS:-30}
trace=$(mktemp)
trap 'rm -f "$trace"' EXIT
energies=$("$AKVF" list | awk '/^energies/{on=1; next} /^[a-z]/{on=0} on{print $1}')
# Every preconditioner, and every solver but `descent` (the preconditioned
# descent the preconditioners already run).
methods=$("$AKVF" list | awk '/^(preconditioners|solvers)/{on=1; next} /^[a-z]/{on=0} on && $1 != "descent"{print $1}')
failures=0 runs=0
for mesh in "$DATA"/tri/*_b.obj "$DATA"/tri/camelhead.off "$DATA"/tri/lilium.obj "$DATA"/tri/snail.obj \
            "$DATA"/tri/inspired_mesh.obj "$DATA"/tri/bump-domain.obj; do
  for e in $energies; do
    for m in $methods; do
      runs=$((runs + 1))
      : > "$trace"  # a run that fails before writing must not be judged by the previous trace
      "$AKVF" param "$mesh" --quiet --energy "$e" --precond "$m" --max-iters "$ITERS" --grad-tol 0 --injectivity local \
        --trace "$trace" > /dev/null 2>&1 || true
      # The warm start's rows (symmetric Dirichlet, before an overflowing
      # energy starts) open the trace: checked for flips, not compared in energy.
      verdict=$(awk -F, 'NR > 1 {if ($7 != 0) flips = 1}
                        NR > 1 && $11 != "warm-start" {if (!rows++) start = $3; last = $3}
                        END {if (!rows) print "no-trace"; else if (flips) print "flipped";
                             else if (last + 0 > start + 0) print "energy-rose"; else print "ok"}' "$trace")
      if [ "$verdict" != ok ]; then
        echo "FAIL $(basename "$mesh") $e $m: $verdict"
        failures=$((failures + 1))
      fi
    done
  done
done
echo "$runs runs, $failures failures"
[ "$failures" -eq 0 ]
