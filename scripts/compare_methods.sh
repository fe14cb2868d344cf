#!/usr/bin/env bash
# Time to gradient norm < 1e-3 for every preconditioner and L-BFGS on the
# paper's meshes, symmetric Dirichlet, same Tutte start, one run each with a
# time budget (default 30 s; BUDGET=60 bash scripts/compare_methods.sh).
# Prints Markdown for docs/performance.md. Run after scripts/build.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
AKVF=./build/akvf
DATA=${AKVF_DATA_DIR:-../shared/meshes}
BUDGET=${BUDGET:-30}
MESHES=${MESHES:-"camel_b.obj cow_b.obj horse_b.obj camelhead.off"}
METHODS="akvf slim laplacian newton lbfgs"
[ -x "$AKVF" ] || { echo "build first: bash scripts/build.sh" >&2; exit 1; }

echo "Command: \`BUDGET=$BUDGET bash scripts/compare_methods.sh\` on $(nproc) cores, $(date -u +%Y-%m-%d)."
echo
echo "| mesh | method | status | iterations | seconds | final energy | gradient norm | time / AKVF's |"
echo "|---|---|---|---|---|---|---|---|"
for m in $MESHES; do
  akvf_time=""
  for method in $METHODS; do
    line=$("$AKVF" param "$DATA/tri/$m" --quiet --precond "$method" --max-iters 100000 --time-limit "$BUDGET" \
           | awk '/^status/ {gsub(",", ""); print $2, $4, $6, $9, $12}')
    set -- $line
    [ "$method" = akvf ] && akvf_time=$3
    ratio=$(awk -v t="$3" -v a="$akvf_time" -v s="$1" 'BEGIN { r = t / a; printf (s == "converged" ? "%.1f" : ">= %.1f"), r }')
    echo "| $m | $method | $1 | $2 | $3 | $4 | $5 | $ratio |"
  done
done
