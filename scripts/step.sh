#!/usr/bin/env bash
# Runs one step of a script and prints how long it took (wall time, whole seconds), also when
# it fails; with STEP_TIMES set, appends "NAME SECONDS STATUS" to that file for a summary.
#
#   scripts/step.sh NAME COMMAND [ARGS...]      exits with COMMAND's status
set -uo pipefail
name=$1
shift
start=$(date +%s)
"$@"
status=$?
seconds=$(($(date +%s) - start))
printf 'step %s: %d s (%d min %02d s)%s\n' "$name" "$seconds" $((seconds / 60)) \
  $((seconds % 60)) "$([ "$status" -eq 0 ] || echo ", FAILED with exit status $status")"
if [ -n "${STEP_TIMES:-}" ]; then
  echo "$name $seconds $status" >> "$STEP_TIMES"
fi
exit "$status"
