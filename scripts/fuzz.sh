#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with Clang, AddressSanitizer and UndefinedBehaviorSanitizer,
# the libraries instrumented too, and runs each for a fixed number of executions from a seed
# corpus made of this tree's data (scenes, golden vectors, meshes), of small seeds for the formats
# the tree has no data in (fuzz/seeds/: STL, PLY) and of the inputs that once found a defect
# (fuzz/regressions/). A crash, a sanitizer report,
# a leak, a timeout or an exception other than the readers' own errors fails the script.
#
#   scripts/fuzz.sh [RUNS] [BUILD_DIR]      (defaults: 20000 runs per target, build-fuzz)
# CI runs the default; a long run: scripts/fuzz.sh 10000000
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20000}
dir=${2:-build-fuzz}
jobs=$(nproc 2>/dev/null || echo 2)
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
flags+=" -fsanitize-coverage-ignorelist=$PWD/fuzz/coverage_ignorelist.txt"
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DRECODE_LIBRARY_ONLY=ON -DRECODE_BUILD_FUZZERS=ON >/dev/null
targets=(scene_fuzzer command_stream_fuzzer obj_fuzzer off_fuzzer stl_fuzzer ply_fuzzer)
cmake --build "$dir" -j "$jobs" --target "${targets[@]}"

# Each target starts from a copy of its seeds: libFuzzer adds what it finds to the first corpus
# folder, which must not be the source tree.
seed() {
  local target=$1; shift
  local corpus="$dir/corpus/$target"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  find "$@" -type f -exec cp -t "$corpus" {} +
  echo "$corpus"
}
declare -A seeds=(
  [scene_fuzzer]="data/scenes tests/data/bad_inputs"
  [command_stream_fuzzer]="data/golden/fill_square.json data/golden/masks_and_cull.json data/golden/recode_passes.json"
  [obj_fuzzer]="data/meshes fuzz/regressions/obj"
  [off_fuzzer]="data/meshes"
  [stl_fuzzer]="fuzz/seeds/stl"
  [ply_fuzzer]="fuzz/seeds/ply"
)
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in "${targets[@]}"; do
  # shellcheck disable=SC2086
  corpus=$(seed "$target" ${seeds[$target]})
  echo "fuzz: $target, $runs runs from $(ls "$corpus" | wc -l) seeds"
  log="$dir/corpus/$target.log"
  # assimp leaks when its PLY importer fails (fuzz/lsan_assimp.supp); RECODE's leaks still count.
  lsan=""
  if [ "$target" = ply_fuzzer ]; then lsan="suppressions=$PWD/fuzz/lsan_assimp.supp"; fi
  if ! LSAN_OPTIONS="$lsan" "$dir/fuzz/$target" -runs="$runs" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$dir/corpus/$target-" "$corpus" >"$log" 2>&1; then
    tail -n 80 "$log"
    echo "fuzz: $target found something (whole log: $log; the input is saved as crash-*/leak-*/timeout-*)"
    exit 1
  fi
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb)|DONE" "$log" || true
done
echo "fuzz: every target ran $runs inputs without a finding"
