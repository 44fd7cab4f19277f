#!/bin/sh
# Runs every case of tests/data/bad_inputs/manifest.txt (its header explains the format): the
# exit status must be 1 or above 100, and the first line of stderr must contain the fragment.
# Each case runs under a 1 GiB address-space cap and a 20 s timeout; every failure is listed.
# Usage: check_bad_inputs.sh RECODE CASES_DIR SCRATCH_DIR
# A shell script rather than cmake -P: messages hold ';' and '[', which CMake lists would split.
recode=$1 cases=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
count=0 failures=0
set -f  # the arguments are split at spaces, never globbed
while IFS= read -r line; do
  case $line in '#'* | '') continue ;; esac
  arguments=${line%% => *}
  fragment=${line#* => }
  set --
  for word in $arguments; do
    case $word in
      @*) set -- "$@" "$cases/${word#@}" ;;
      mesh:*)
        mesh=${word#mesh:}
        printf '{"objects": [{"mesh": "%s"}, {"shape": {"type": "box", "size": [1, 1, 1]}}]}\n' \
          "$cases/$mesh" > "$scratch/$mesh.json"
        set -- "$@" "$scratch/$mesh.json" ;;
      *) set -- "$@" "$word" ;;
    esac
  done
  count=$((count + 1))
  (ulimit -v 1048576; cd "$scratch" && exec timeout 20 "$recode" "$@") \
    > /dev/null 2> "$scratch/stderr"
  status=$?
  first=$(head -n 1 "$scratch/stderr")
  case $first in *"$fragment"*) found=1 ;; *) found=0 ;; esac
  if [ "$found" = 0 ] || { [ "$status" != 1 ] && [ "$status" -le 100 ]; }; then
    failures=$((failures + 1))
    printf 'FAIL: recode %s\n  status %s, stderr: %s\n  expected: %s\n' \
      "$arguments" "$status" "$first" "$fragment"
  fi
done < "$cases/manifest.txt"
rm -rf "$scratch"
echo "$count bad inputs, $failures failed"
[ "$failures" = 0 ] && [ "$count" -ge 60 ]
