#!/usr/bin/env bash
# The installed CMake package as a user meets it: installs this build into a
# temporary prefix, then configures, builds and runs every project under
# examples/ against it (find_package(akvf 0.2 CONFIG REQUIRED), akvf::akvf),
# and, when the build has the Python module, runs examples/python with the
# installed package.
# Usage: examples_test.sh CMAKE BUILD_DIR SOURCE_DIR [PYTHON SITE_PACKAGES_DIR]
set -euo pipefail
cmake=$1 build=$2 source=$3 python=${4:-} site=${5:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log"
[ -f "$work/prefix/include/akvf/akvf.h" ] || { echo "no include/akvf/akvf.h in the prefix"; exit 1; }
[ -f "$work/prefix/lib/cmake/akvf/akvfConfigVersion.cmake" ] || { echo "no version file in the prefix"; exit 1; }
[ -x "$work/prefix/bin/akvf" ] || { echo "no akvf program in the prefix"; exit 1; }
"$work/prefix/bin/akvf" --version
for example in "$source"/examples/*/; do
  [ -f "$example/CMakeLists.txt" ] || continue
  name=$(basename "$example")
  echo "== $name"
  "$cmake" -S "$example" -B "$work/$name" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
    > "$work/$name.configure.log" || { cat "$work/$name.configure.log"; exit 1; }
  "$cmake" --build "$work/$name" -j 2 > "$work/$name.build.log" || { cat "$work/$name.build.log"; exit 1; }
  "$work/$name/$name"
done
if [ -n "$python" ]; then
  echo "== python"
  [ -f "$work/prefix/$site/akvf/__init__.py" ] || { echo "no akvf package in $work/prefix/$site"; exit 1; }
  PYTHONPATH="$work/prefix/$site" "$python" "$source/examples/python/parameterize.py"
fi
echo "every example built against the installed package and ran"
