#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install what the `akvf` program
# needs, build only it, and run the demo (the bent bar of the paper's Figure 2, built in code).
# Outputs go to ./akvf-demo (UV OBJ, trace CSV, SVG layout).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --demo
bash scripts/build.sh --demo
./build/akvf demo --out-dir akvf-demo
