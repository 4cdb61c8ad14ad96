#!/usr/bin/env bash
# The main job on a default input, through pymeshlab 2025.7 and the MeshLab 2025.07 plugin:
# installs what is missing, builds, then analyzes the bunny of Debian's libcgal-demo corpus and
# runs Automatic Reduction on it (remeshed to about 20K vertices first). Writes
# out/bunny00_irregular.{ply,png,json} (coloured by valence, irregular vertices selected, the
# returned counts) and out/bunny00_reduced.{ply,png,json}.
#   usage: bash scripts/demo.sh [input mesh] [output folder]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/build.sh"
QT_QPA_PLATFORM=offscreen "$here/.deps/venv/bin/python" "$here/scripts/demo.py" "$@"
