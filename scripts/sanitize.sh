#!/usr/bin/env bash
# The robustness checks of docs/robustness.md, run by CI after the Release
# tests: builds everything with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-sanitize, runs the whole test suite
# there, then runs each libFuzzer target for FUZZ_SECONDS (default 20) from
# its seed corpus in tests/fuzz/seeds (plus experiments/manifests/*.json for the
# manifest target). Any sanitizer report or fuzzer finding
# fails the script; a finding's input is kept in build-sanitize/fuzz-findings.
# Usage: bash scripts/sanitize.sh            (after scripts/setup.sh)
#        FUZZ_SECONDS=600 bash scripts/sanitize.sh   (the 10-minute runs)
#        SKIP_TESTS=1 / SKIP_FUZZ=1 to run one half.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-sanitize
fuzz_seconds=${FUZZ_SECONDS:-20}

mkdir -p "$build"
# Without hypre: Open MPI, which hypre needs, leaves allocations of its
# MPI_Init that LeakSanitizer reports from plugin frames it cannot name (so no
# suppression matches them). The multigrid tests then check the build's
# "install libhypre-dev" refusal; the Release suite runs the multigrid path.
# Without CGAL: it is only akvf_speed's peer, third-party code the Release
# suite runs.
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DAKVF_SANITIZE=ON -DAKVF_BUILD_FUZZERS=ON -DAKVF_BUILD_BENCHMARKS=OFF -DAKVF_WITH_HYPRE=OFF -DAKVF_WITH_CGAL=OFF \
  > "$build/configure.log" \
  || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"

# Every report aborts with a stack trace; leaks are reported at exit.
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if [ -z "${SKIP_TESTS:-}" ]; then
  (cd "$build" && ctest --output-on-failure -j "$(nproc)")
fi

if [ -z "${SKIP_FUZZ:-}" ]; then
  findings=$build/fuzz-findings
  mkdir -p "$findings"
  for seeds in tests/fuzz/seeds/*/; do
    name=$(basename "$seeds")
    corpus=$build/fuzz-corpus/$name  # grows across runs; the committed seeds stay as they are
    mkdir -p "$corpus" "$findings/$name"
    # The project's own manifests seed the manifest target too.
    if [ "$name" = manifest ]; then cp experiments/manifests/*.json "$corpus"/; fi
    echo "fuzz_$name: ${fuzz_seconds} s from $(ls "$seeds" | wc -l) seeds"
    "$build/fuzz/fuzz_$name" "$corpus" "$seeds" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=1024 -max_len=16384 -print_final_stats=1 -artifact_prefix="$findings/$name/" \
      > "$findings/$name.log" 2>&1 || { tail -n 60 "$findings/$name.log"; echo "fuzz_$name: FINDING (input in $findings/$name/)"; exit 1; }
    grep -E "^Done|^stat::new_units_added|^stat::peak_rss_mb" "$findings/$name.log" | tr -s ' ' | tr '\n' ' '
    echo
  done
fi
