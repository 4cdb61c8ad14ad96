#!/usr/bin/env bash
# GUI test of the edit tool "Irregular Vertices: Edit" in a real MeshLab, 2020.09 (Debian's) or
# 2025.07 (built from source by scripts/build_meshlab2025.sh):
#
#   tests/gui/edit_test.sh <2020|2025> <filter .so> <edit .so> <out folder>
#
# 1. edit_check.py prepare: knot1.off as a PLY whose vertex flags select its 5-7 pair 47-3186
#    (the pair of examples/move_pair.mlx);
# 2. edit_check.py reference: the expected result, from the filter "Irregular Vertices: Move
#    Pair" in pymeshlab (the 2025.07 filter plugin, $EDIT_TEST_REFERENCE_PLUGIN or
#    build/plugin2025/libfilter_irregular.so): 3 single steps in direction 0;
# 3. the GUI under its own Xvfb (tests/gui/edit_session.py): open the PLY, Edit > Irregular
#    Vertices: Edit (the tool picks the pair from the selection), click the empty background
#    (focus), key "1" three times (each step must be logged as done), screenshot, File > Export
#    Mesh As..., File > Exit;
# 4. edit_check.py check: the exported mesh has the pair where Move Pair puts it, the same
#    counts and valence histogram as the reference, every other irregular vertex with its
#    valence, every vertex far from the pair unmoved.
# Before the tool starts the view is turned (a 200-pixel trackball drag, EDIT_TEST_ROTATE) and
# zoomed (3 wheel notches, EDIT_TEST_ZOOM) so that the pair faces the camera in the screenshot;
# after the steps, Ctrl+Z undoes the last one and Ctrl+Y redoes it. With
# EDIT_TEST_README_PNG=docs/gui_edit_<gen>.png the README picture is written too.
# Exit status 0 = pass; otherwise a "gui: FAIL ..." or "edit_check: FAIL ..." line says why.
# 2020 runs a private stage in <out>/stage2020 (Debian's meshlab + system plugins + the two
# given .so); 2025 stages the GUI of the plugins' scalar into build/stage2025[-double].
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
usage() { echo "usage: $0 <2020|2025> <filter .so> <edit .so> <out folder>" >&2; exit 2; }
[ $# -eq 4 ] || usage
gen=$1; filter=$2; edit=$3; out=$4
case $gen in 2020|2025) ;; *) usage ;; esac
fail() { echo "gui: FAIL $*" >&2; exit 1; }

[ -f "$filter" ] || fail "filter plugin $filter not found"
[ -f "$edit" ] || fail "edit plugin $edit not found"
filter=$(realpath "$filter"); edit=$(realpath "$edit")
py=$here/.deps/venv/bin/python
[ -x "$py" ] || fail "no venv python in $py (run scripts/setup.sh)"
refplugin=${EDIT_TEST_REFERENCE_PLUGIN:-$here/build/plugin2025/libfilter_irregular.so}
[ -f "$refplugin" ] || fail "no 2025.07 filter plugin $refplugin for the reference (ninja filter_irregular_2025)"
mesh=$here/.deps/data/meshes/knot1.off
[ -f "$mesh" ] || fail "mesh $mesh missing (run scripts/setup.sh)"
pair=(47 3186)
direction=0   # key "1"
steps=3
mkdir -p "$out"; out=$(realpath "$out")
rm -f "$out"/[0-9][0-9]_*.png "$out"/*.ply "$out/ref.npz" "$out/meshlab.log" "$out/meshlab_gui_log.txt"

# --- input and expected result --------------------------------------------------------------------
input=$out/knot1_pair.ply
"$py" "$here/tests/gui/edit_check.py" prepare --mesh "$mesh" --pair "${pair[@]}" --out "$input" || fail "prepare"
QT_QPA_PLATFORM=offscreen "$py" "$here/tests/gui/edit_check.py" reference --mesh "$mesh" --pair "${pair[@]}" \
  --direction $direction --steps $steps --plugin "$refplugin" --out "$out/ref.npz" || fail "the reference (Move Pair in pymeshlab)"

# --- the MeshLab to run ---------------------------------------------------------------------------
. "$here/tests/gui/gui_common.sh"
gui_install_tools
if [ "$gen" = 2020 ]; then
  title="MeshLab 2020.09"
  gui_stage_2020 "$out/stage2020" "$filter" "$edit"
  bin=$out/stage2020/bin/meshlab
else
  title="MeshLab 2025.07"
  scalar=$(gui_scalar_of "$edit")
  echo "gui: $scalar scalars"
  gui_stage_2025 "$scalar" "$filter" "$edit"
  bin=$gui_bin
fi
echo "gui: MeshLab $gen: $bin with $(basename "$filter") and $(basename "$edit")"

gui_start_display "$out"
ply=$out/knot1_edited_gui$gen.ply
set +e
/usr/bin/python3 "$here/tests/gui/edit_session.py" --meshlab "$bin" --title "$title" --mesh "$input" \
  --out "$out" --ply "$ply" --key $((direction + 1)) --steps $steps --readme-png "${EDIT_TEST_README_PNG:-}" \
  --rotate "${EDIT_TEST_ROTATE:-200}" --zoom "${EDIT_TEST_ZOOM:-3}"
rc=$?
set -e
[ $rc -eq 0 ] || { echo "gui: FAIL the edit tool's GUI session in MeshLab $gen failed (screenshots and meshlab.log in $out)" >&2; exit 1; }
"$py" "$here/tests/gui/edit_check.py" check --input "$input" --output "$ply" --reference "$out/ref.npz" \
  --pair "${pair[@]}" || { echo "gui: FAIL wrong content in the exported PLY" >&2; exit 1; }
echo "gui: PASS MeshLab $gen: the pair moved $steps steps with the edit tool, exported and checked (screenshots in $out)"
