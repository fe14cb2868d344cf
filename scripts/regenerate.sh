#!/usr/bin/env bash
# Regenerates every committed result in one run on one machine (results as
# the contract, docs/robustness.md): the paper's Table 1 and Figures 1, 3, 6,
# 7, 8 and the subdivided meshes (docs/results/), docs/pairs.md and Figure 8's
# plots and traces (docs/figures/) in place, and into OUT (default
# build/regenerated) the tables the reference docs quote: the speed table
# per energy and in 3D, the thread benchmarks, CGAL's ARAP, the seams and
# xatlas tables, global injectivity's cost, Figure 8's and cube_4k's tables.
# Each step's output and seconds go to OUT/<step>.md and OUT/steps.tsv.
# 75-120 minutes on the 2-core development VM (Figure 6 alone 33-61); run it
# with nothing else on the machine, since every table has timings.
# Usage: bash scripts/regenerate.sh [OUT]   (after scripts/build.sh; needs
# node and npm for xatlas, ../shared/meshes or $AKVF_DATA_DIR)
# STEPS=name,name,... runs only those steps (the names of OUT/steps.tsv):
# after a change that moves some results only.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-build/regenerated}
DATA=${AKVF_DATA_DIR:-../shared/meshes}
[ -x build/akvf ] || { echo "build first: bash scripts/build.sh" >&2; exit 1; }
[ -d "$DATA/tri" ] || { echo "meshes not found: $DATA (set AKVF_DATA_DIR)" >&2; exit 1; }
mkdir -p "$OUT"
{
  echo "commit $(git describe --always --dirty 2>/dev/null || echo unknown)"
  echo "date $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "machine $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
} > "$OUT/run.txt"
printf 'step\tseconds\texit\n' > "$OUT/steps.tsv"

# step NAME COMMAND...: runs COMMAND, its stdout to OUT/NAME.md, its stderr
# to OUT/NAME.log, and its wall seconds and exit code to OUT/steps.tsv; a
# failed step is reported and the run goes on with the next.
failed=0
wanted() { [ -z "${STEPS:-}" ] || [[ ",$STEPS," == *",$1,"* ]]; }
step() {
  local name=$1
  shift
  rc=0
  wanted "$name" || return 0
  echo "[$(date -u +%H:%M:%S)] $name: $*" >&2
  local start=$SECONDS
  "$@" > "$OUT/$name.md" 2> "$OUT/$name.log" || rc=$?
  printf '%s\t%d\t%d\n' "$name" $((SECONDS - start)) "$rc" >> "$OUT/steps.tsv"
  if [ "$rc" -ne 0 ]; then
    echo "  $name failed (exit $rc): $OUT/$name.log" >&2
    failed=$((failed + 1))
  fi
}

for manifest in table1 figure1 figure3 figure7 figure8 subdivided_meshes figure6; do
  wanted "$manifest" && rm -rf "docs/results/$manifest"  # the runner keeps a folder only for its own manifest's results
  step "$manifest" ./build/akvf experiment "experiments/manifests/$manifest.json" --out-dir "docs/results/$manifest"
done
step figure8_plots bash scripts/figure8.sh
step pairs bash scripts/pairs.sh
wanted pairs && [ "$rc" -eq 0 ] && cp "$OUT/pairs.md" docs/pairs.md  # rc: the last step's exit code
# Medians of five runs, taken in turn over the methods.
step speed ./build/akvf_speed --repeat 5
for energy in arap mips amips exp-symmetric-dirichlet; do
  step "speed_$energy" ./build/akvf_speed --only 2d --energy "$energy" --repeat 5
done
step threads ./build/akvf_benchmarks \
  --benchmark_filter='^(NumericFactorization|Solve)/horse_b.obj/x(16|64)(/threads:1)?$' \
  --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
step injectivity bash scripts/injectivity.sh
step seams bash scripts/seams.sh --large
step xatlas bash scripts/xatlas.sh
cube4k() {
  for p in akvf newton laplacian slim identity; do
    echo "$p: $(./build/akvf deform "$DATA/tet/cube_4k.obj" --preset slim-cube --energy exp-symmetric-dirichlet \
      --precond $p --max-iters 100 --quiet | grep status)"
  done
  echo "akvf --akvf-as-written: $(./build/akvf deform "$DATA/tet/cube_4k.obj" --preset slim-cube \
    --energy exp-symmetric-dirichlet --precond akvf --akvf-as-written --max-iters 100 --quiet | grep status)"
}
step cube_4k cube4k
echo "done: $OUT (steps.tsv has each step's seconds and exit code); $failed step(s) failed" >&2
[ "$failed" -eq 0 ]
