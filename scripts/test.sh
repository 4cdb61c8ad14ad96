#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs ctest (GoogleTest unit tests
# of vcg_ext/ and the meshlabserver integration tests driven by pytest).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/build.sh"
cd "$here/build"
ctest --output-on-failure -j 2
