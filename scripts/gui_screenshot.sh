#!/usr/bin/env bash
# Checks the plugin in the real MeshLab GUI under Xvfb: opens the bunny in the staged
# meshlab, opens Filters > Quality Measure and Computations, and takes screenshots
# (out/gui_*.png). Needs a build (scripts/build.sh). Installs xdotool and ImageMagick.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$here/out}
mkdir -p "$out"
for p in xdotool imagemagick x11-utils; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$p" >/dev/null
done
disp=:$((50 + RANDOM % 40))
Xvfb $disp -screen 0 1600x1000x24 +extension GLX >/dev/null 2>&1 &
xpid=$!
trap 'kill $mlpid $xpid 2>/dev/null || true' EXIT
sleep 1
export DISPLAY=$disp XDG_RUNTIME_DIR=$(mktemp -d)
"$here/build/stage/bin/meshlab" "$here/.deps/data/meshes/bunny00.off" >"$out/gui.log" 2>&1 &
mlpid=$!
for i in $(seq 1 30); do
  W=$(xdotool search --name "MeshLab 2020.09" 2>/dev/null | head -1 || true)
  [ -n "$W" ] && break
  sleep 1
done
[ -n "$W" ] || { echo "gui: no MeshLab window"; exit 1; }
xdotool windowsize "$W" 1600 1000; xdotool windowmove "$W" 0 0
sleep 3
/usr/bin/import -window root "$out/gui_loaded.png"
xdotool mousemove 121 10 click 1; sleep 1
/usr/bin/import -window root "$out/gui_filters_menu.png"
xdotool mousemove 240 261 click 1; sleep 1   # Quality Measure and Computations
/usr/bin/import -window root "$out/gui_quality_menu.png"
xdotool mousemove 624 536 click 1; sleep 2   # Irregular Vertices: Analyze -> its dialog
/usr/bin/import -window root "$out/gui_dialog.png"
xdotool mousemove 259 412 click 1; sleep 3   # Apply
/usr/bin/import -window root "$out/gui_applied.png"
echo "gui: screenshots in $out"
