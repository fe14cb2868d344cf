#!/usr/bin/env bash
# The tables of the paper's AKVF under its settings (docs/performance.md):
# run it after scripts/build.sh; it prints Markdown. Times are the median of REPEAT
# runs (default 3) of `akvf param`, optimizer time only (the `seconds` of the
# last trace row), on the meshes of ../shared/meshes (or $AKVF_DATA_DIR).
# Takes about five minutes on the 2-core development machine.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
REPEAT=${REPEAT:-3}

# One run of the paper's AKVF (these tables study its settings; a later
# --precond overrides): prints "status iterations seconds energy grad_norm inverted".
run_once() {
  "$AKVF" param --precond akvf --injectivity local "$@" --quiet | awk '/^status/ {gsub(",", ""); print $2, $4, $6, $9, $12, $13}'
}

# Median over REPEAT runs of the seconds; the other fields from the last run
# (they are deterministic).
run_median() {
  local times=() line=""
  for _ in $(seq "$REPEAT"); do
    line=$(run_once "$@")
    times+=("$(echo "$line" | awk '{print $3}')")
  done
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  echo "$line" | awk -v m="$median" '{print $1, $2, m, $4, $5, $6}'
}

table_row() {  # label, then run_median output
  echo "$2" | awk -v label="$1" '{printf "| %s | %s | %s | %s | %s | %s | %s |\n", label, $2, $3, $4, $5, $6, $1}'
}

header() {
  echo "| $1 | iterations | seconds | final energy | gradient norm | inverted | status |"
  echo "|---|---|---|---|---|---|---|"
}

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)."
echo "Command: \`REPEAT=$REPEAT bash scripts/performance.sh\` (median of $REPEAT runs)."
echo

echo "### AKVF (\`--precond akvf\`), default settings (time to gradient norm < 1e-3)"
echo
header mesh
for m in camel_b.obj horse_b.obj camelhead.off; do
  table_row "$m" "$(run_median "$DATA/tri/$m")"
done
echo

echo "### Factorization reuse (\`--akvf-reuse\`)"
echo
header "mesh, tau"
for m in camel_b.obj cow_b.obj tricera_b.obj hilbert_b.obj horse_b.obj camelhead.off; do
  for tau in 0 0.03; do
    table_row "$m, $tau" "$(run_median "$DATA/tri/$m" --akvf-reuse "$tau")"
  done
done
echo

echo "### Backtracking factor (\`--ls-rho\`, the paper's text says 0.9)"
echo
header "mesh, rho"
for m in camel_b.obj horse_b.obj camelhead.off; do
  for rho in 0.5 0.9; do
    table_row "$m, $rho" "$(run_median "$DATA/tri/$m" --ls-rho "$rho")"
  done
done
echo

echo "### Flap optimization of §5.4 (\`--flaps\`)"
echo
header "mesh, flaps"
for m in camel_b.obj cow_b.obj tricera_b.obj horse_b.obj camelhead.off hilbert_b.obj lilium.obj snail.obj \
         inspired_mesh.obj bump-domain.obj; do
  for flaps in on off; do
    table_row "$m, $flaps" "$(REPEAT=1 run_median "$DATA/tri/$m" --flaps "$flaps")"
  done
done
echo

echo "### Identity (plain gradient descent) against AKVF, 20 s budget"
echo
header "mesh, preconditioner"
for m in camel_b.obj horse_b.obj; do
  table_row "$m, akvf" "$(REPEAT=1 run_median "$DATA/tri/$m")"
  table_row "$m, identity" "$(REPEAT=1 run_median "$DATA/tri/$m" --precond identity --time-limit 20 --max-iters 1000000)"
done
echo

echo "### Micro-benchmarks (\`./build/akvf_benchmarks\`)"
echo
echo '```'
./build/akvf_benchmarks 2>/dev/null | grep -E '^(Benchmark|-|[A-Z])'
echo '```'
