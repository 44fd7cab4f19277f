#!/usr/bin/env bash
# Writes the reference outputs whose bytes a speed-up must not change, one file each, into
# OUTDIR: compare two builds with `cmp` (docs/benchmarks.md, "How to compare two builds").
#
#   scripts/reference-outputs.sh build/apps/recode /tmp/outputs-new
#   for f in /tmp/outputs-old/*; do cmp -s "$f" "/tmp/outputs-new/${f##*/}" || echo "differs: ${f##*/}"; done
#
# The outputs: every built-in scene's `recode run --json --no-timing` at its default level; the
# adaptive, conservative and skip-apart modes on hand-grasp, random-cones and
# comb-translate-offset; finer levels (hand-grasp 2,304 in both modes, random-shapes 2,304 for
# 30 frames, comb-translate-aligned 1,024, comb-rotate-offset 4,096 skip-apart, random-cones
# 256); `recode pair --json` and its case maps with each MOR; `recode verify --suite` at
# widths 64 and 256. About 10 s on two cores.
set -euo pipefail

if [ $# -ne 2 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'
  echo "usage: $0 RECODE OUTDIR"
  [ $# -eq 2 ] && exit 0 || exit 2
fi
recode=$1
out=$2
if [ ! -x "$recode" ]; then
  echo "$0: $recode is not an executable (build it first: scripts/build.sh)" >&2
  exit 2
fi
mkdir -p "$out"

run() {  # run NAME ARGS...: `recode run ARGS --json --no-timing` into NAME.json
  local name=$1
  shift
  "$recode" run "$@" --json --no-timing > "$out/$name.json"
}

for scene in comb-translate-aligned comb-translate-offset comb-rotate-aligned comb-rotate-offset \
  random-cones random-shapes hand-grasp hierarchy-9; do
  run "run-$scene" "$scene"
done
for mode in adaptive conservative skip-apart; do
  for scene in hand-grasp random-cones comb-translate-offset; do
    run "run-$scene-$mode" "$scene" --mode "$mode"
  done
done
run run-hand-2304 hand-grasp --triangles-per-block 2304
run run-hand-2304-skip hand-grasp --triangles-per-block 2304 --mode skip-apart
run run-shapes-2304 random-shapes --triangles-per-block 2304 --frames 30
run run-cta-1024 comb-translate-aligned --triangles-per-block 1024
run run-cro-4096-skip comb-rotate-offset --triangles-per-block 4096 --mode skip-apart
run run-cones-256 random-cones --triangles-per-block 256
"$recode" pair --json --no-timing > "$out/pair.json"
for mor in min max full; do
  "$recode" pair --json --no-timing --mor "$mor" --dump-cases "$out/pair-$mor.pgm" > /dev/null
done
"$recode" verify --suite --width 64 --json --no-timing > "$out/suite-64.json"
"$recode" verify --suite --width 256 --json --no-timing > "$out/suite-256.json"
echo "wrote $(ls "$out" | wc -l) outputs to $out"
