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
# 5. keys T and Q (triple and quadruple cancellation, sec. 7.2-7.3), one MeshLab session each
#    on the same display: edit_check.py prepare-cancel makes an icosphere in which the filter
#    "Irregular Vertices: Generate" made a 5-5-7 triple (a 5-5-7-7 quadruple), with one of its
#    adjacent 5-7 pairs selected; reference-cancel runs "Irregular Vertices: Cancel Triple"
#    ("... Quadruple") in pymeshlab on it with the whole group selected. In the GUI
#    (edit_session.py --cancel): export, key T (Q) must log "triple cancelled", export, Ctrl+Z
#    must log "undone", export. check-cancel: exactly the group's irregular vertices are gone
#    (a triple leaves one survivor where the filter leaves it), every vertex more than 8 edges
#    from the group is unchanged, the result matches the filter's; and the export after Ctrl+Z
#    is byte for byte the export before the key press (cmp).
# EDIT_TEST_PARTS (default "move T Q") chooses the sessions.
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
rm -rf "$out"/[0-9][0-9]_*.png "$out"/*.ply "$out"/*.npz "$out"/*.json "$out/meshlab.log" "$out/meshlab_gui_log.txt" \
  "$out/cancel_T" "$out/cancel_Q"
parts=${EDIT_TEST_PARTS:-move T Q}
has_part() { case " $parts " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

# --- input and expected result --------------------------------------------------------------------
input=$out/knot1_pair.ply
if has_part move; then
  "$py" "$here/tests/gui/edit_check.py" prepare --mesh "$mesh" --pair "${pair[@]}" --out "$input" || fail "prepare"
  QT_QPA_PLATFORM=offscreen "$py" "$here/tests/gui/edit_check.py" reference --mesh "$mesh" --pair "${pair[@]}" \
    --direction $direction --steps $steps --plugin "$refplugin" --out "$out/ref.npz" || fail "the reference (Move Pair in pymeshlab)"
fi
for key in T Q; do
  has_part $key || continue
  kind=$([ $key = T ] && echo triple || echo quadruple)
  QT_QPA_PLATFORM=offscreen "$py" "$here/tests/gui/edit_check.py" prepare-cancel --kind $kind --plugin "$refplugin" \
    --out "$out/${kind}_pair.ply" --group-out "$out/$kind.json" || fail "prepare the $kind"
  QT_QPA_PLATFORM=offscreen "$py" "$here/tests/gui/edit_check.py" reference-cancel --input "$out/${kind}_pair.ply" \
    --group "$out/$kind.json" --plugin "$refplugin" --out "$out/ref_$kind.npz" || fail "the reference (Cancel $kind in pymeshlab)"
done

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
if has_part move; then
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
fi

# --- keys T and Q ---------------------------------------------------------------------------------
for key in T Q; do
  has_part $key || continue
  kind=$([ $key = T ] && echo triple || echo quadruple)
  dir=$out/cancel_$key; mkdir -p "$dir"
  set +e
  /usr/bin/python3 "$here/tests/gui/edit_session.py" --meshlab "$bin" --title "$title" --mesh "$out/${kind}_pair.ply" \
    --out "$dir" --cancel $key --before "$dir/before.ply" --ply "$dir/cancelled.ply" --undone "$dir/undone.ply"
  rc=$?
  set -e
  [ $rc -eq 0 ] || { echo "gui: FAIL key $key in MeshLab $gen failed (screenshots and meshlab.log in $dir)" >&2; exit 1; }
  "$py" "$here/tests/gui/edit_check.py" check-cancel --input "$out/${kind}_pair.ply" --output "$dir/cancelled.ply" \
    --reference "$out/ref_$kind.npz" --group "$out/$kind.json" || { echo "gui: FAIL wrong content after key $key" >&2; exit 1; }
  cmp "$dir/before.ply" "$dir/undone.ply" ||
    { echo "gui: FAIL Ctrl+Z after key $key did not restore the mesh byte for byte ($dir/before.ply, $dir/undone.ply)" >&2; exit 1; }
  echo "gui: PASS MeshLab $gen: key $key cancelled the $kind as the filter does; Ctrl+Z restored the export byte for byte"
done
