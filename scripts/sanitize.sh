#!/usr/bin/env bash
# The library suites under AddressSanitizer and UndefinedBehaviorSanitizer: raster (with the
# pipeline's invariants on), the kit's reference model and the golden vectors, the JSON layer,
# the core layers, the collision API and the explain library's data for the interactive page.
# Run by CI after the main suite; anything the sanitizers find fails the run. The programs, the
# oracles and the GPU-API devices are left out: they call into Embree, CGAL and Mesa, whose own
# code is not built with the sanitizers.
#
#   scripts/sanitize.sh [BUILD_DIR]     (default build-sanitize)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Warnings are the main build's job (scripts/build.sh, -Werror): with the sanitizers GCC 12
# reports false "maybe uninitialized" warnings inside libstdc++'s <regex>.
# -O1 -g1: what the sanitizers need (ASan's checks at -O1, file:line in reports), and about half
# the compile time of RelWithDebInfo's -O2 -g, most of this script's time.
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRECODE_WERROR=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DRECODE_WITH_EMBREE=OFF -DRECODE_WITH_CGAL=OFF -DRECODE_WITH_OSMESA=OFF -DRECODE_WITH_EGL=OFF \
  -DRECODE_WITH_VULKAN=OFF -DRECODE_WITH_PEERS=OFF -DRECODE_BUILD_BENCHMARKS=OFF \
  -DRECODE_BUILD_EXAMPLES=OFF >/dev/null
suites=(recode_raster_tests recode_raster_invariant_tests recode_geometry_tests recode_pair_tests
        recode_refine_tests recode_scene_tests recode_sim_tests recode_api_tests
        recode_backends_exact_tests recode_explain_tests)
cmake --build "$dir" -j "$jobs" --target "${suites[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The suites run side by side, as many as there are cores (ctest runs their test cases side by
# side too), each into its own log, printed whole when the suite fails.
run_suite() {  # run_suite SUITE: runs it into $dir/sanitize-SUITE.log; a failure leaves .failed
  local suite=$1 exe log start
  exe=$(find "$dir/tests" -type f -name "$suite" -perm -u+x | head -n 1)
  log="$dir/sanitize-$suite.log"
  start=$(date +%s)
  rm -f "$log.failed"
  if "$exe" --reporter compact >"$log" 2>&1; then
    echo "sanitize: $suite passed ($(($(date +%s) - start)) s): $(grep -v "^$" "$log" | tail -n 1)"
  else
    echo "sanitize: $suite FAILED ($(($(date +%s) - start)) s)"
    touch "$log.failed"
  fi
}
running=0
for suite in "${suites[@]}"; do
  if ((running >= jobs)); then
    wait -n
    running=$((running - 1))
  fi
  run_suite "$suite" &
  running=$((running + 1))
done
wait
failed=0
for suite in "${suites[@]}"; do
  if [ -e "$dir/sanitize-$suite.log.failed" ]; then
    echo "sanitize: $suite's output ($dir/sanitize-$suite.log):"
    cat "$dir/sanitize-$suite.log"
    failed=1
  fi
done
if [ "$failed" -ne 0 ]; then
  echo "sanitize: a suite failed under ASan and UBSan"
  exit 1
fi
echo "sanitize: every suite passed under ASan and UBSan"
