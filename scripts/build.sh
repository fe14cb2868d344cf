#!/usr/bin/env bash
# Configures and builds the project (Release) in ./build. Used by demo.sh and
# test.sh; run scripts/setup.sh first on a fresh machine.
#   bash scripts/build.sh          everything: library, program, tests, benchmarks, Python module
#   bash scripts/build.sh --demo   only the `akvf` program, as a unity build (each library's
#                                  sources compiled in a few batches: about half the time)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--demo" ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DAKVF_BUILD_TESTS=OFF -DAKVF_BUILD_BENCHMARKS=OFF -DAKVF_BUILD_PYTHON=OFF \
    -DCMAKE_UNITY_BUILD=ON
  cmake --build build -j "$(nproc)" --target akvf
elif [ -n "${1:-}" ]; then
  echo "usage: bash scripts/build.sh [--demo]" >&2
  exit 2
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DAKVF_BUILD_TESTS=ON -DAKVF_BUILD_BENCHMARKS=ON -DAKVF_BUILD_PYTHON=ON \
    -DCMAKE_UNITY_BUILD=OFF
  cmake --build build -j "$(nproc)"
fi
