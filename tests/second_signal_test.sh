#!/usr/bin/env bash
# A signal while an output is being written ends the process at once and
# leaves no `*.tmpPID` file (the handler deletes the pending temporaries): the
# second signal inside an optimizer's loop, the first one anywhere else.
# Usage: second_signal_test.sh SECOND_SIGNAL_WRITER
set -uo pipefail
writer=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for mode in loop outside; do
  "$writer" "$dir/out.txt" "$mode"
  code=$?
  [ "$code" -eq 130 ] || { echo "$mode: expected death by SIGINT (130), got $code"; exit 1; }
  [ -z "$(ls -A "$dir")" ] || { echo "$mode: left behind: $(ls -A "$dir")"; exit 1; }
done
echo "a signal during a write: process ended, no temporary file left"
