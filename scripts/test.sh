#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install the dependencies, build,
# and run the whole test suite through ctest. Tests that need the real meshes
# (../shared/meshes or $AKVF_DATA_DIR) report "skipped" when they are absent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)"
