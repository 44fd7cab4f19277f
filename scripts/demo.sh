#!/usr/bin/env bash
# Sets up, builds, and runs the main job on the built-in default: only the packages and the
# build the `recode` program needs (scripts/setup.sh --demo, scripts/build.sh --demo, into
# build-demo/), each step's wall time printed; scripts/test.sh sets up and builds everything,
# into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/step.sh setup scripts/setup.sh --demo
scripts/step.sh build scripts/build.sh --demo
./build-demo/apps/recode pair "$@"
