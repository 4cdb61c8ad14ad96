#!/usr/bin/env bash
# Configures and builds filter_irregular (plugin, staged MeshLab runtime, tests, benchmarks)
# into build/ (or $BUILD_DIR). Runs setup.sh first, so it works on a fresh machine.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
build=${BUILD_DIR:-$here/build}
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} ${CMAKE_EXTRA:-} >/dev/null
cmake --build "$build" -j "$(nproc)"
