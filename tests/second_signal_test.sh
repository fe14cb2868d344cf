#!/usr/bin/env bash
# A second SIGINT while an output is being written ends the process at once
# and leaves no `*.tmpPID` file: the handler deletes the pending temporaries.
# Usage: second_signal_test.sh SECOND_SIGNAL_WRITER
set -uo pipefail
writer=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$writer" "$dir/out.txt"
code=$?
[ "$code" -eq 130 ] || { echo "expected death by SIGINT (130), got $code"; exit 1; }
[ -z "$(ls -A "$dir")" ] || { echo "left behind: $(ls -A "$dir")"; exit 1; }
echo "second signal: process ended, no temporary file left"
