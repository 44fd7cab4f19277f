#!/usr/bin/env bash
# Sets up, builds, and runs the main job on the built-in default.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/apps/recode pair "$@"
