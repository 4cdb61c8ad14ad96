#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs ctest (GoogleTest unit tests
# of vcg_ext/ and the meshlabserver integration tests driven by pytest), then builds the unit
# tests once more with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/) and runs
# them there.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/build.sh"
(cd "$here/build" && ctest --output-on-failure -j 2)

# Sanitizers: unit tests and the randomized run (the plugins run inside un-instrumented MeshLab
# hosts), compiled against MeshLab 2025.07's vcglib, so vcg_ext/ is tested on both vcglibs.
asan="$here/build-asan"
cmake -S "$here" -B "$asan" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DFI_BUILD_PLUGIN=OFF -DFI_BUILD_PLUGIN_2025=OFF \
  -DFI_BUILD_BENCH=OFF -DFI_VCGLIB_DIR="$here/.deps/meshlab2025-src/src/vcglib" \
  -DCMAKE_CXX_FLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
  >/dev/null
cmake --build "$asan" -j "$(nproc)"
(cd "$asan" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j 2)
