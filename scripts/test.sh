#!/usr/bin/env bash
# Sets up, builds, and runs the whole test suite under ctest, printing each step's wall time.
#
#   scripts/test.sh             set up, build, ctest
#   scripts/test.sh --ctest     ctest alone, on what scripts/build.sh built (.ci/run times the
#                               steps one by one)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
case "${1:-}" in
  "")
    scripts/step.sh setup scripts/setup.sh
    scripts/step.sh build scripts/build.sh
    scripts/step.sh ctest scripts/test.sh --ctest
    ;;
  --ctest) ctest --test-dir build --output-on-failure -j "$jobs" ;;
  *) echo "usage: scripts/test.sh [--ctest]" >&2; exit 2 ;;
esac
