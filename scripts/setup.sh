#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds with. Idempotent: packages
# already present are left alone, and apt-get is skipped entirely when nothing
# is missing.
#   bash scripts/setup.sh          everything: the library, tests, Python, browser
#   bash scripts/setup.sh --demo   only what the `akvf` program needs (scripts/demo.sh)
set -euo pipefail
packages=(  # the library and the `akvf` program
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev libtbb-dev libceres-dev libopenblas-dev nlohmann-json3-dev libpng-dev
  libjs-three  # three.js, embedded in the HTML views (akvf view)
)
if [ "${1:-}" = "--demo" ]; then
  :
elif [ -n "${1:-}" ]; then
  echo "usage: bash scripts/setup.sh [--demo]" >&2
  exit 2
else packages+=(
  doctest-dev libbenchmark-dev
  pybind11-dev python3-dev python3-pybind11 python3-numpy python3-pytest  # the Python module (python/)
  python3-jsonschema  # the tests check every --summary against docs/run_summary.schema.json
  clang libclang-rt-14-dev  # scripts/sanitize.sh: ASan, UBSan and libFuzzer
  libhypre-dev  # algebraic multigrid (hypre's BoomerAMG) for --linear-solver amg
  libcgal-dev  # CGAL's ARAP parameterizer, a peer in akvf_speed (experiments/speed)
  chromium  # the browser test of the views (tests/browser/check_pages.py), headless
)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
