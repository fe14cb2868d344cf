#!/usr/bin/env bash
# Hostile output paths for every command that writes (param, deform, plot,
# view, demo, experiment) on the real program: a symbolic link, a FIFO, a character
# device (when run as root), a folder, an unwritable folder, an output equal
# to an input and two equal outputs. Each must either work without replacing
# anything it should not, or fail with the documented exit code before any
# work, writing nothing.
# Usage: hostile_outputs_test.sh AKVF_BINARY
set -uo pipefail
akvf=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect CODE DESCRIPTION COMMAND...: runs the command, checks its exit code.
expect() {
  local want=$1 what=$2
  shift 2
  "$@" > "$dir/stdout" 2> "$dir/stderr"
  local got=$?
  [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$dir/stderr"))"
}

cd "$dir"
cat > m.obj <<'MESH'
v 0 0 0
v 1 0 0
v 1 1 0.2
v 0 1 0
v 0.5 0.5 0.1
f 1 2 5
f 2 3 5
f 3 4 5
f 4 1 5
MESH
cat > t.mesh <<'MESH'
MeshVersionFormatted 1
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
1 1 1 0
Tetrahedra
2
1 2 3 4 0
2 3 4 5 0
End
MESH
printf '0 0 0 0\n4 1.2 1 1\n' > c.txt
"$akvf" param m.obj -q --trace trace.csv --out tex.obj > /dev/null || fail "setup: param"
cp m.obj m.orig; cp t.mesh t.orig; cp c.txt c.orig; cp trace.csv trace.orig
cat > e.json <<'JSON'
{"name": "e", "meshes": [{"label": "a", "file": "m.obj"}], "methods": [{"label": "m", "max_iters": 3}]}
JSON

# 1. A symbolic link stays a link; the file it names gets the content.
ln -s real_uv.obj link_uv.obj
expect 0 "param --out LINK" "$akvf" param m.obj -q --out link_uv.obj
[ -L link_uv.obj ] && grep -q '^vt ' real_uv.obj || fail "param --out LINK: link replaced or target not written"
ln -s real.vtk link.vtk
expect 0 "deform --out LINK" "$akvf" deform t.mesh --constraints c.txt -q --max-iters 2 --out link.vtk
[ -L link.vtk ] && grep -q POINTS real.vtk || fail "deform --out LINK"
ln -s real.svg link.svg
expect 0 "plot --out LINK" "$akvf" plot trace.csv --out link.svg
[ -L link.svg ] && grep -q '<svg' real.svg || fail "plot --out LINK"
ln -s real.html link.html
expect 0 "view --out LINK" "$akvf" view tex.obj --out link.html
[ -L link.html ] && grep -q '<html' real.html || fail "view --out LINK"
mkdir demo_real && ln -s demo_real demo_link
expect 0 "demo --out-dir LINK" "$akvf" demo --out-dir demo_link -q
[ -L demo_link ] && [ -f demo_real/demo_uv.obj ] || fail "demo --out-dir LINK"

# 2. A FIFO receives the output in place.
mkfifo pipe
cat pipe > from_pipe &
expect 0 "param --trace FIFO" "$akvf" param m.obj -q --trace pipe
wait
[ -p pipe ] && grep -q '^iter,' from_pipe || fail "param --trace FIFO: not a FIFO any more or nothing received"
cat pipe > from_pipe &
expect 0 "deform --trace FIFO" "$akvf" deform t.mesh --constraints c.txt -q --max-iters 2 --trace pipe
wait
[ -p pipe ] && grep -q '^iter,' from_pipe || fail "deform --trace FIFO"
cat pipe > from_pipe &
expect 0 "plot --out FIFO" "$akvf" plot trace.csv --out pipe
wait
[ -p pipe ] && grep -q '<svg' from_pipe || fail "plot --out FIFO"

# 3. A character device is written in place, never renamed over (as root a rename would replace /dev/null).
for out in "--out /dev/null" "--trace /dev/null" "--svg /dev/null" "--png /dev/null" "--summary /dev/null" \
  "--view /dev/null"; do
  expect 0 "param $out" "$akvf" param m.obj -q $out
done
[ ! -e /dev/null.mtl ] && [ ! -e /dev/null_checker.png ] || fail "--out /dev/null wrote a texture into /dev"
expect 0 "deform --out /dev/null" "$akvf" deform t.mesh --constraints c.txt -q --max-iters 2 --trace /dev/null
expect 0 "deform --summary /dev/null" "$akvf" deform t.mesh --constraints c.txt -q --max-iters 2 --summary /dev/null
expect 0 "plot --out /dev/null" "$akvf" plot trace.csv --out /dev/null
expect 0 "view --out /dev/null" "$akvf" view tex.obj --out /dev/null
[ -c /dev/null ] || fail "/dev/null is no longer a character device"

# 4. A folder as output: exit 4 before any work, nothing written.
mkdir folder
expect 4 "param --out FOLDER" "$akvf" param m.obj -q --out folder
expect 4 "param --trace FOLDER" "$akvf" param m.obj -q --trace folder
expect 4 "param --png IN-A-MISSING-FOLDER" "$akvf" param m.obj -q --png missing/x.png
expect 4 "param --summary FOLDER" "$akvf" param m.obj -q --summary folder
expect 4 "deform --out FOLDER" "$akvf" deform t.mesh --constraints c.txt -q --out folder
expect 4 "plot --out FOLDER" "$akvf" plot trace.csv --out folder
mkdir folder.html
expect 4 "param --view FOLDER" "$akvf" param m.obj -q --view folder.html
expect 4 "view --out FOLDER" "$akvf" view tex.obj --out folder.html
[ -z "$(ls -A folder.html)" ] || fail "something was written into folder.html"
[ -z "$(ls -A folder)" ] || fail "something was written into folder"
grep -q '^status' "$dir/stdout" && fail "the optimization ran before the output was checked"
printf 'x' > plainfile
expect 4 "demo --out-dir FILE" "$akvf" demo --out-dir plainfile -q
expect 4 "experiment --out-dir FILE" "$akvf" experiment e.json --data-dir . --out-dir plainfile
[ "$(cat plainfile)" = x ] || fail "plainfile changed"

# 5. An unwritable folder: exit 4 (as root, checked as the user nobody when possible).
mkdir locked && chmod 555 locked
as_user=()
if [ "$(id -u)" -eq 0 ]; then
  chmod 755 "$dir"
  if command -v setpriv > /dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups "$akvf" --version > /dev/null 2>&1; then
    as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  else
    echo "note: cannot run as an unprivileged user here; the unwritable-folder cases are skipped"
  fi
fi
if [ "$(id -u)" -ne 0 ] || [ ${#as_user[@]} -gt 0 ]; then
  expect 4 "param --out LOCKED/x.obj" "${as_user[@]}" "$akvf" param m.obj -q --out locked/x.obj
  expect 4 "deform --trace LOCKED/t.csv" "${as_user[@]}" "$akvf" deform t.mesh --constraints c.txt -q --trace locked/t.csv
  expect 4 "plot --out LOCKED/p.svg" "${as_user[@]}" "$akvf" plot trace.csv --out locked/p.svg
  expect 4 "demo --out-dir LOCKED" "${as_user[@]}" "$akvf" demo --out-dir locked -q
  expect 4 "experiment --out-dir LOCKED/r" "${as_user[@]}" "$akvf" experiment e.json --data-dir . --out-dir locked/r
  [ -z "$(ls -A locked)" ] || fail "something was written into the locked folder"
fi

# 6. An output equal to an input, directly or through a link: exit 2, inputs intact.
ln -s m.obj mesh_alias.obj
expect 2 "param --trace INPUT" "$akvf" param m.obj -q --trace m.obj
expect 2 "param --out ALIAS-OF-INPUT" "$akvf" param m.obj -q --out mesh_alias.obj
expect 2 "deform --out INPUT" "$akvf" deform t.mesh --constraints c.txt -q --out t.mesh
expect 2 "deform --trace CONSTRAINTS" "$akvf" deform t.mesh --constraints c.txt -q --trace c.txt
expect 2 "plot --out INPUT" "$akvf" plot trace.csv --out trace.csv
cp tex.obj tex.orig; ln -s tex.obj tex_alias.html
expect 2 "view --out ALIAS-OF-INPUT" "$akvf" view tex.obj --out tex_alias.html
expect 2 "view --out = --summary" "$akvf" view tex.obj --summary tex_alias.html --out tex_alias.html
cmp -s tex.obj tex.orig || fail "view replaced its input"
cmp -s m.obj m.orig && cmp -s t.mesh t.orig && cmp -s c.txt c.orig && cmp -s trace.csv trace.orig || fail "an input changed"

# 7. Two outputs naming one file: exit 2, nothing written.
expect 2 "param --out X --trace X --svg X" "$akvf" param m.obj -q --out x.obj --trace x.obj --svg x.obj
expect 2 "param --png X --summary X" "$akvf" param m.obj -q --png x.png --summary x.png
expect 2 "param --png = the texture of --out" "$akvf" param m.obj -q --out y.obj --png y_checker.png
expect 2 "param --view X --summary X" "$akvf" param m.obj -q --view z.html --summary z.html
[ ! -e x.png ] && [ ! -e y.obj ] && [ ! -e y.mtl ] && [ ! -e z.html ] || fail "a clashing output was written"
expect 2 "deform --out X --trace X" "$akvf" deform t.mesh --constraints c.txt -q --out x.mesh --trace x.mesh
[ ! -e x.obj ] && [ ! -e x.mesh ] || fail "a clashing output was written"

leftovers=$(find . -name '*.tmp*' | head -3)
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"
if [ "$failures" -ne 0 ]; then
  echo "$failures hostile-output checks failed"
  exit 1
fi
echo "hostile outputs: every case behaved"
