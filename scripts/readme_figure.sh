#!/usr/bin/env bash
# The README's figure, docs/figures/camelhead_view.png: `akvf param
# camelhead.off --view` (the default run) drawn by headless Chromium with the
# browser test's flags (tests/browser/check_pages.py), 1200 x 640 pixels.
# Usage: bash scripts/readme_figure.sh   (after scripts/build.sh; needs chromium)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/shared_meshes.sh
command -v chromium > /dev/null || { echo "chromium not found (bash scripts/setup.sh installs it)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$AKVF" param "$DATA/tri/camelhead.off" --quiet --view "$work/camelhead_view.html" --out "$work/uv.obj"
chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --window-size=1200,640 \
  --virtual-time-budget=15000 --hide-scrollbars --user-data-dir="$work/profile" \
  --screenshot="$work/camelhead_view.png" "file://$work/camelhead_view.html" 2> /dev/null
mv "$work/camelhead_view.png" docs/figures/camelhead_view.png
echo "wrote docs/figures/camelhead_view.png"
