#!/usr/bin/env bash
# Configures and builds the project (Release) in ./build. Used by demo.sh and
# test.sh; run scripts/setup.sh first on a fresh machine.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
