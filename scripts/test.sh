#!/usr/bin/env bash
# The whole test suite, from a fresh machine: installs what is missing, builds both plugins,
# then runs
#  1. ctest in build/: the GoogleTest unit tests of vcg_ext/ (on MeshLab 2020.09's vcglib), the
#     randomized operation run, the pymeshlab suite (MeshLab 2025.07 plugin in pymeshlab
#     2025.7.post1) and the meshlabserver smoke suite (MeshLab 2020.09);
#  2. one GUI test per MeshLab generation (tests/gui/gui_test.sh), and one of the edit tool
#     (tests/gui/edit_test.sh): Debian's MeshLab 2020.09 and a MeshLab 2025.07 GUI built from
#     Debian sid's source (scripts/build_meshlab2025.sh, once);
#  3. the wheel: built, installed into a fresh venv and smoke-tested (scripts/test_wheel.sh);
#  4. the unit tests (but the 30 labelled corpus_scale) and the randomized run once more under
#     AddressSanitizer and UndefinedBehaviorSanitizer, compiled against MeshLab 2025.07's vcglib
#     (build-asan/).
# Any failure stops it with a non-zero status.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
t0=$SECONDS
stamp() { echo "test.sh: $1 done at $((SECONDS - t0)) s"; }
bash "$here/scripts/build.sh"
stamp build
(cd "$here/build" && ctest --output-on-failure -j 2)
stamp ctest

gui_out="$here/build/gui-test"
rm -rf "$gui_out"
bash "$here/tests/gui/gui_test.sh" 2020 "$here/build/stage/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_irregular.so" \
  "$gui_out/2020"
bash "$here/tests/gui/gui_test.sh" 2025 "$here/build/plugin2025/libfilter_irregular.so" "$gui_out/2025"
# the edit tool "Irregular Vertices: Edit": a pair moved three steps by key presses in each GUI
plugins2020="$here/build/stage/lib/x86_64-linux-gnu/meshlab/plugins"
bash "$here/tests/gui/edit_test.sh" 2020 "$plugins2020/libfilter_irregular.so" "$plugins2020/libedit_irregular.so" \
  "$gui_out/edit2020"
bash "$here/tests/gui/edit_test.sh" 2025 "$here/build/plugin2025/libfilter_irregular.so" \
  "$here/build/plugin2025/libedit_irregular.so" "$gui_out/edit2025"
stamp gui

bash "$here/scripts/test_wheel.sh"
stamp wheel

# Sanitizers: the unit tests but the corpus_scale ones (tests/CMakeLists.txt says which; they ran
# un-instrumented in stage 1), and the randomized run (the plugins run inside un-instrumented
# MeshLab hosts), compiled against MeshLab 2025.07's vcglib, so vcg_ext/ is tested on both
# vcglibs. -g1 (line tables, enough for the sanitizers' stack traces) compiles a third faster
# than -g; asserts stay on (no NDEBUG).
asan="$here/build-asan"
cmake -S "$here" -B "$asan" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DFI_BUILD_PLUGIN=OFF -DFI_BUILD_PLUGIN_2025=OFF \
  -DFI_BUILD_BENCH=OFF -DFI_VCGLIB_DIR="$here/.deps/meshlab2025-src/src/vcglib" \
  -DCMAKE_CXX_FLAGS="-O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
  >/dev/null
cmake --build "$asan" -j "$(nproc)"
(cd "$asan" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j 2 -LE corpus_scale)
stamp sanitizers
echo "test.sh: all passed in $((SECONDS - t0)) s"
