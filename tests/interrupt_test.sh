#!/usr/bin/env bash
# Ctrl-C on a long `akvf param` run: exit code 130, a trace whose last row says
# "interrupted", and a complete UV OBJ (written through a temporary name).
# Usage: interrupt_test.sh AKVF_BINARY
set -euo pipefail
akvf=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# Waits until the run's trace (still under its temporary name) has an
# iteration row, so the signal lands inside the loop however slow the build
# (sanitizers make the set-up take seconds).
wait_for_iterations() {
  for _ in $(seq 600); do
    [ -f "$1.partial" ] && [ "$(wc -l < "$1.partial")" -ge 2 ] && return 0
    sleep 0.1
  done
  echo "no iteration in $1 after 60 s"; exit 1
}
# A 60 x 60 grid on a bumpy height field: identity preconditioning takes many thousands of iterations.
bash "$(dirname "$0")/grid_mesh.sh" > "$dir/grid.obj"
"$akvf" param "$dir/grid.obj" --precond identity --max-iters 1000000 --grad-tol 0 --time-limit 60 \
  --out "$dir/uv.obj" --trace "$dir/trace.csv" --quiet > "$dir/stdout" 2> "$dir/stderr" &
pid=$!
wait_for_iterations "$dir/trace.csv"
sleep 1
kill -INT "$pid"
set +e
wait "$pid"
code=$?
set -e
[ "$code" -eq 130 ] || { echo "expected exit code 130, got $code"; cat "$dir/stderr"; exit 1; }
tail -n 1 "$dir/trace.csv" | grep -q ',interrupted$' || { echo "last trace row does not say interrupted"; tail -n 2 "$dir/trace.csv"; exit 1; }
grep -q '^status interrupted' "$dir/stdout" || { echo "no status line"; cat "$dir/stdout"; exit 1; }
vertices=$(grep -c '^v ' "$dir/uv.obj")
uvs=$(grep -c '^vt ' "$dir/uv.obj")
[ "$vertices" -eq 3600 ] && [ "$uvs" -eq 3600 ] || { echo "incomplete UV OBJ: $vertices v, $uvs vt"; exit 1; }
ls "$dir" | grep -qv -e grid.obj -e uv.obj -e uv.mtl -e uv_checker.png -e trace.csv -e stdout -e stderr && { echo "temporary files left: $(ls "$dir")"; exit 1; }
echo "interrupted cleanly after $(($(wc -l < "$dir/trace.csv") - 2)) iterations"

# --cut seams: the signal ends the rounds of seams too (and the cuts for the
# packing are not made): a sphere with thin spikes, whose rounds take
# seconds, exits within a few seconds of it, its outputs whole.
/usr/bin/python3 "$(dirname "$0")/../scripts/spiky_sphere.py" "$dir/spiky.off"
"$akvf" param "$dir/spiky.off" --cut seams --out "$dir/spiky_uv.obj" --trace "$dir/spiky.csv" --quiet \
  > "$dir/stdout" 2> "$dir/stderr" &
pid=$!
wait_for_iterations "$dir/spiky.csv"
kill -INT "$pid"
signalled=$(date +%s)
set +e
wait "$pid"
code=$?
set -e
[ "$code" -eq 130 ] || { echo "--cut seams: expected exit code 130, got $code"; cat "$dir/stderr"; exit 1; }
[ $(($(date +%s) - signalled)) -le 5 ] || { echo "--cut seams: the run went on $(($(date +%s) - signalled)) s after the signal"; exit 1; }
tail -n 1 "$dir/spiky.csv" | grep -q ',interrupted$' || { echo "--cut seams: last trace row does not say interrupted"; exit 1; }
# Pieces and parting come after every round of seams, so a stop in the
# first round leaves none (rounds that went on unsolved after the signal made both).
! grep -e 'lay over itself' -e 'parted in two' "$dir/stdout" || { echo "--cut seams: rounds went on after the signal"; exit 1; }
[ "$(grep -c '^f ' "$dir/spiky_uv.obj")" -eq 2048 ] || { echo "--cut seams: incomplete UV OBJ"; exit 1; }
echo "--cut seams interrupted cleanly"

# Later in the rounds (pieces, parting, the cuts for the packing, between the
# optimizer's loops) a signal ends the run as cleanly; a run that ended
# before the signal exits 0.
for delay in 2 6; do
  rm -f "$dir/spiky.csv" "$dir/spiky_uv.obj"
  "$akvf" param "$dir/spiky.off" --cut seams --out "$dir/spiky_uv.obj" --trace "$dir/spiky.csv" --quiet \
    > "$dir/stdout" 2> "$dir/stderr" &
  pid=$!
  wait_for_iterations "$dir/spiky.csv"
  sleep "$delay"
  kill -INT "$pid" 2> /dev/null || true
  signalled=$(date +%s)
  set +e
  wait "$pid"
  code=$?
  set -e
  [ "$code" -eq 0 ] && continue
  [ "$code" -eq 130 ] || { echo "--cut seams, signal ${delay} s in: exit code $code"; cat "$dir/stderr"; exit 1; }
  [ $(($(date +%s) - signalled)) -le 5 ] || { echo "--cut seams, signal ${delay} s in: went on after it"; exit 1; }
  tail -n 1 "$dir/spiky.csv" | grep -q ',interrupted$' || { echo "--cut seams, signal ${delay} s in: no interrupted row"; exit 1; }
  [ "$(grep -c '^f ' "$dir/spiky_uv.obj")" -eq 2048 ] || { echo "--cut seams, signal ${delay} s in: incomplete UV OBJ"; exit 1; }
done
echo "--cut seams interrupted cleanly later in the rounds"

# Before the first iteration (here: reading a FIFO nobody writes to) a signal
# ends the process at once: `timeout` sends SIGTERM after 1 s and reports 124
# when the command then ends (137 if it had to send SIGKILL 5 s later).
mkfifo "$dir/pipe.obj"
set +e
timeout -k 5 1 "$akvf" param "$dir/pipe.obj" --quiet > /dev/null 2>&1
code=$?
set -e
[ "$code" -eq 124 ] || { echo "reading a FIFO: SIGTERM did not end the run (exit $code)"; exit 1; }
echo "a signal while reading ends the run at once"
