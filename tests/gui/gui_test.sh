#!/usr/bin/env bash
# GUI test of the plugin in a real MeshLab, 2020.09 (Debian's) or 2025.07 (built from source by
# scripts/build_meshlab2025.sh):
#
#   tests/gui/gui_test.sh <2020|2025> <plugin .so> <out folder>
#
# Starts the GUI under its own Xvfb, opens .deps/data/meshes/bunny00.off, runs Filters >
# Quality Measure and Computations > "Irregular Vertices: Analyze" (Apply in its dialog), exports
# the mesh with File > Export Mesh As... (a .ply, vertex Color and Quality on in the export
# options), quits, and checks the PLY (tests/gui/check_ply.py): 37706 vertices, colours on the
# plugin's legend, quality = valence, 19715 irregular vertices. Screenshots of every step go to
# the out folder; with GUI_TEST_README_PNG=docs/gui_2025_analyze.png (2025) the README picture too.
# Widgets are found by name through Qt's accessibility bus (tests/gui/mlgui.py), input is sent
# with xdotool. Exit status 0 = pass; otherwise a "gui: FAIL ..." or "check_ply: FAIL ..." line
# says what went wrong.
#
# 2020: uses the staged build/stage/bin/meshlab (scripts/build.sh) when its plugins folder holds
#       this very .so, otherwise a private stage in <out>/stage2020 with the given .so.
# 2025: stages the GUI of .deps/meshlab2025-build into build/stage2025 (the binary, links to its
#       libraries, shaders and six plugins, plus a link to the given .so); nothing is written
#       into .deps. A plugin built with double scalars (as for the pymeshlab wheel) gets the
#       double-precision GUI instead (.deps/meshlab2025-build-double, build/stage2025-double),
#       built by scripts/build_meshlab2025.sh double when missing.
# The plugin may be "none" to exercise the automation with one of MeshLab's own filters; then
# set GUI_TEST_MENU / GUI_TEST_FILTER and GUI_TEST_CHECK=basic, e.g.
#   GUI_TEST_MENU="Color Creation and Processing" GUI_TEST_FILTER="Compute curvature principal directions" \
#   GUI_TEST_CHECK=basic tests/gui/gui_test.sh 2025 none out/gui2025-selftest
# Other knobs: GUI_TEST_MESH (default bunny00.off), GUI_TEST_README_PNG (2025 picture path,
# empty = none), GUI_TEST_VERTICES / GUI_TEST_IRREGULAR (expected counts).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
usage() { echo "usage: $0 <2020|2025> <plugin .so|none> <out folder>" >&2; exit 2; }
[ $# -eq 3 ] || usage
gen=$1; plugin=$2; out=$3
case $gen in 2020|2025) ;; *) usage ;; esac
fail() { echo "gui: FAIL $*" >&2; exit 1; }

menu=${GUI_TEST_MENU:-Quality Measure and Computations}
filter=${GUI_TEST_FILTER:-Irregular Vertices: Analyze}
check=${GUI_TEST_CHECK:-irregular}
mesh=${GUI_TEST_MESH:-$here/.deps/data/meshes/bunny00.off}
[ -f "$mesh" ] || fail "mesh $mesh missing (run scripts/setup.sh)"
if [ "$plugin" != none ]; then
  [ -f "$plugin" ] || fail "plugin $plugin not found"
  plugin=$(realpath "$plugin")
fi
mkdir -p "$out"; out=$(realpath "$out")
ply=$out/$(basename "${mesh%.*}")_gui$gen.ply
rm -f "$out"/[0-9][0-9]_*.png "$ply" "$out/meshlab.log" "$out/meshlab_gui_log.txt"   # this test's own files only

# --- tools (Debian bookworm packages, installed when missing) --------------------------------
. "$here/tests/gui/gui_common.sh"
gui_install_tools

# --- the MeshLab to run ------------------------------------------------------------------------
if [ "$gen" = 2020 ]; then
  title="MeshLab 2020.09"
  stage=$here/build/stage
  [ -x "$stage/bin/meshlab" ] || fail "no staged MeshLab 2020.09 in $stage (run scripts/build.sh)"
  pdir=$stage/lib/x86_64-linux-gnu/meshlab/plugins
  if [ "$plugin" != none ] && ! cmp -s "$plugin" "$pdir/$(basename "$plugin")"; then
    # a private stage with the given plugin (same layout as scripts/build.sh makes)
    stage=$out/stage2020; pdir=$stage/lib/x86_64-linux-gnu/meshlab/plugins
    gui_stage_2020 "$stage" "$plugin"
    echo "gui: private 2020 stage $stage with $plugin"
  fi
  bin=$stage/bin/meshlab
  readme=
else
  title="MeshLab 2025.07"
  # MeshLab loads only plugins of its own scalar precision; a plugin built for the pymeshlab
  # 2025.7.post1 wheel uses double.
  scalar=$(gui_scalar_of "$plugin")
  echo "gui: $scalar scalars (GUI_TEST_SCALAR=float|double overrides)"
  if [ "$plugin" = none ]; then gui_stage_2025 "$scalar"; else gui_stage_2025 "$scalar" "$plugin"; fi
  bin=$gui_bin
  readme=${GUI_TEST_README_PNG-}   # e.g. docs/gui_2025_analyze.png to refresh the README picture
  [ "$check" = irregular ] || readme=${GUI_TEST_README_PNG:-}   # no README picture of another filter
fi
echo "gui: MeshLab $gen: $bin; plugins: $(ls "$(dirname "$bin")"/plugins 2>/dev/null | wc -l || true) in stage; filter '$menu > $filter'"

# --- private X server, D-Bus session and settings ------------------------------------------------
gui_start_display "$out"

set +e
/usr/bin/python3 "$here/tests/gui/gui_session.py" --meshlab "$bin" --title "$title" --mesh "$mesh" \
  --out "$out" --ply "$ply" --menu "$menu" --filter "$filter" \
  --readme-png "$readme"
rc=$?
set -e
[ $rc -eq 0 ] || { echo "gui: FAIL the GUI session of MeshLab $gen failed (screenshots and meshlab.log in $out)" >&2; exit 1; }
/usr/bin/python3 "$here/tests/gui/check_ply.py" --mode "$check" \
  --vertices "${GUI_TEST_VERTICES:-37706}" --irregular "${GUI_TEST_IRREGULAR:-19715}" \
  "$ply" || { echo "gui: FAIL wrong content in the exported PLY" >&2; exit 1; }
echo "gui: PASS MeshLab $gen: '$filter' applied, exported and checked (screenshots in $out)"
