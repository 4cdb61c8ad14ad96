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
need=(xvfb xauth x11-utils xdotool imagemagick dbus dbus-daemon at-spi2-core python3-dbus binutils)
missing=()
for p in "${need[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "gui: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null ||
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; } ||
    fail "could not install ${missing[*]}"
fi

# --- the MeshLab to run ------------------------------------------------------------------------
if [ "$gen" = 2020 ]; then
  title="MeshLab 2020.09"
  stage=$here/build/stage
  [ -x "$stage/bin/meshlab" ] || fail "no staged MeshLab 2020.09 in $stage (run scripts/build.sh)"
  pdir=$stage/lib/x86_64-linux-gnu/meshlab/plugins
  if [ "$plugin" != none ] && ! cmp -s "$plugin" "$pdir/$(basename "$plugin")"; then
    # a private stage with the given plugin (same layout as scripts/build.sh makes)
    stage=$out/stage2020; pdir=$stage/lib/x86_64-linux-gnu/meshlab/plugins
    rm -rf "$stage"; mkdir -p "$stage/bin" "$pdir"
    cp /usr/bin/meshlab "$stage/bin/"
    ln -s /usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so "$stage/lib/x86_64-linux-gnu/meshlab/"
    for f in /usr/lib/x86_64-linux-gnu/meshlab/plugins/*.so; do ln -s "$f" "$pdir/"; done
    ln -sf "$plugin" "$pdir/$(basename "$plugin")"
    echo "gui: private 2020 stage $stage with $plugin"
  fi
  bin=$stage/bin/meshlab
  readme=
else
  title="MeshLab 2025.07"
  # MeshLab loads only plugins of its own scalar precision; a plugin built for the pymeshlab
  # 2025.7.post1 wheel uses double. Detected from the vcg types in the plugin's symbols.
  scalar=${GUI_TEST_SCALAR:-}
  if [ -z "$scalar" ]; then
    scalar=float
    if [ "$plugin" != none ]; then
      nd=$(nm -D -C "$plugin" | grep -c 'vcg::Point3<double>' || true)
      nf=$(nm -D -C "$plugin" | grep -c 'vcg::Point3<float>' || true)
      [ "$nd" -gt "$nf" ] && scalar=double
    fi
  fi
  echo "gui: $scalar scalars (GUI_TEST_SCALAR=float|double overrides)"
  bash "$here/scripts/build_meshlab2025.sh" "$scalar" || fail "building MeshLab 2025.07 ($scalar) failed"
  if [ "$scalar" = double ]; then
    dist=$here/.deps/meshlab2025-build-double/src/distrib; stage=$here/build/stage2025-double
  else
    dist=$here/.deps/meshlab2025-build/src/distrib; stage=$here/build/stage2025
  fi
  mkdir -p "$stage/plugins"
  cp -p -u "$dist/meshlab" "$stage/meshlab"   # a copy: MeshLab finds plugins/ next to its own path
  for l in libmeshlab-common.so libmeshlab-common-gui.so shaders; do ln -sfn "$dist/$l" "$stage/$l"; done
  find "$stage/plugins" -maxdepth 1 -type l -delete
  for f in "$dist"/plugins/*.so; do ln -s "$f" "$stage/plugins/"; done
  [ "$plugin" = none ] || ln -sfn "$plugin" "$stage/plugins/$(basename "$plugin")"
  bin=$stage/meshlab
  readme=${GUI_TEST_README_PNG-}   # e.g. docs/gui_2025_analyze.png to refresh the README picture
  [ "$check" = irregular ] || readme=${GUI_TEST_README_PNG:-}   # no README picture of another filter
fi
echo "gui: MeshLab $gen: $bin; plugins: $(ls "$(dirname "$bin")"/plugins 2>/dev/null | wc -l || true) in stage; filter '$menu > $filter'"

# --- private X server, D-Bus session and settings ------------------------------------------------
tmp=$(mktemp -d /tmp/gui_test.XXXXXX)
xpid=; dpid=
cleanup() {
  [ -n "$dpid" ] && kill "$dpid" 2>/dev/null || true
  [ -n "$xpid" ] && kill "$xpid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
mkdir -p "$tmp/home" "$tmp/config/VCG" "$tmp/run"; chmod 700 "$tmp/run"
# MeshLab's QSettings (organisation VCG, application MeshLab_64bit_fp): the 2025.07 first-start
# question "Send Anonymous Statistics" is asked while informativeShown is unset; the update
# check, the statistics and the "congratulations" mail dialog are switched off; the window size
# is preset (2025.07; 2020.09 is resized with xdotool).
param() { # name type value
  printf 'MeshLab%%3A%%3ASystem%%3A%%3A%s="<!DOCTYPE MeshLabSettings>\\n<Param name=\\"MeshLab::System::%s\\" tooltip=\\"\\" description=\\"\\" type=\\"%s\\" value=\\"%s\\"/>\\n"\n' "$1" "$1" "$2" "$3"
}
{
  echo "[General]"
  echo "informativeShown=true"
  echo "dontRemindMeToSendEmail=true"
  echo "dontRemindMeAboutUpgrade=true"
  param sendAnonymousData RichBool false
  param checkForUpdate RichBool false
  param startupWindowWidth RichInt 1600
  param startupWindowHeight RichInt 1000
} > "$tmp/config/VCG/MeshLab_64bit_fp.conf"
cp "$tmp/config/VCG/MeshLab_64bit_fp.conf" "$tmp/config/VCG/MeshLab_64bit_dp.conf"   # double-scalar builds
export HOME=$tmp/home XDG_CONFIG_HOME=$tmp/config XDG_RUNTIME_DIR=$tmp/run
unset SESSION_MANAGER WAYLAND_DISPLAY QT_QPA_PLATFORM || true

exec 3>"$tmp/display"
Xvfb -displayfd 3 -screen 0 1600x1000x24 +extension GLX -nolisten tcp >"$out/xvfb.log" 2>&1 &
xpid=$!
exec 3>&-
for _ in $(seq 100); do [ -s "$tmp/display" ] && break; kill -0 $xpid 2>/dev/null || break; sleep 0.1; done
[ -s "$tmp/display" ] || fail "Xvfb did not start (see $out/xvfb.log)"
export DISPLAY=:$(head -1 "$tmp/display")
# the D-Bus session (for Qt's accessibility bus) starts after DISPLAY is set
read -r DBUS_SESSION_BUS_ADDRESS dpid < <(dbus-daemon --session --fork --print-address=1 --print-pid=1 | paste -s -d' ')
export DBUS_SESSION_BUS_ADDRESS
[ -n "$dpid" ] || fail "dbus-daemon did not start"
echo "gui: Xvfb $DISPLAY (pid $xpid), D-Bus session (pid $dpid)"

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
