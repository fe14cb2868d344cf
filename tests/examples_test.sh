#!/usr/bin/env bash
# The installed CMake package as a user meets it: installs this build into a
# temporary prefix, then configures, builds and runs every project under
# examples/ against it (find_package(akvf 0.2 CONFIG REQUIRED), akvf::akvf),
# builds tests/consumer (the public API alone: parameterize, a .glb and an
# HTML view; #include <framework/...> must fail), and, when the build has
# the Python module, runs examples/python with the installed package.
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
# Only include/akvf/*.h is installed: no library folder on a user's path.
for folder in framework solvers energies preconditioners io akvf/framework akvf/internal akvf/solvers; do
  [ ! -e "$work/prefix/include/$folder" ] || { echo "include/$folder is installed: only include/akvf/*.h is public"; exit 1; }
done
echo "== consumer (tests/consumer: the public API alone)"
"$cmake" -S "$source/tests/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$work/consumer.configure.log" || { cat "$work/consumer.configure.log"; exit 1; }
"$cmake" --build "$work/consumer" -j 2 --target consumer > "$work/consumer.build.log" || { cat "$work/consumer.build.log"; exit 1; }
mkdir "$work/consumer-out"
"$work/consumer/consumer" "$work/consumer-out" | tee "$work/consumer.out"
[ -s "$work/consumer-out/grid.glb" ] || { echo "the consumer wrote no grid.glb"; exit 1; }
if grep -q "^view written" "$work/consumer.out"; then
  [ -s "$work/consumer-out/grid.html" ] || { echo "the consumer wrote no grid.html"; exit 1; }
fi
for target in framework_mesh_mesh_topology_h solvers_sparse_cholesky_h akvf_internal_parameterization_h; do
  if "$cmake" --build "$work/consumer" --target "$target" > "$work/$target.log" 2>&1; then
    echo "$target built: an internal header is reachable from the installed package"; exit 1
  fi
  grep -q "No such file or directory" "$work/$target.log" || { cat "$work/$target.log"; exit 1; }
done
echo "internal headers are not reachable: ok"
if [ -n "$python" ]; then
  echo "== python"
  [ -f "$work/prefix/$site/akvf/__init__.py" ] || { echo "no akvf package in $work/prefix/$site"; exit 1; }
  PYTHONPATH="$work/prefix/$site" "$python" "$source/examples/python/parameterize.py"
fi
echo "every example built against the installed package and ran"
