#!/usr/bin/env bash
# The main job on a default input: installs what is missing, builds, and runs the plugin
# through the staged meshlabserver on the bunny of Debian's libcgal-demo corpus.
# Writes out/bunny_irregular.ply (coloured by valence, irregular vertices selected),
# out/bunny_report.txt (the filter's log) and out/bunny_irregular.png (a picture).
#   usage: bash scripts/demo.sh [input mesh] [output folder]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/build.sh"
in=${1:-$here/.deps/data/meshes/bunny00.off}
out=${2:-$here/out}
mkdir -p "$out"
name=$(basename "${in%.*}")
stage="$here/build/stage"
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
xvfb-run -a -s "-screen 0 1024x768x24" "$stage/bin/meshlabserver" -i "$in" -o "$out/${name}_irregular.ply" \
  -m vc vq vf -s "$here/examples/analyze.mlx" > "$out/${name}_meshlabserver.log" 2>&1 || {
  cat "$out/${name}_meshlabserver.log"; echo "demo: meshlabserver failed" >&2; exit 1; }
# The filter's log lines (meshlabserver prints them after the filter), without progress noise.
grep -E "^(Irregular|Valence|Euler|Gauss|Selected)" "$out/${name}_meshlabserver.log" > "$out/${name}_report.txt"
/usr/bin/python3 "$here/scripts/render_png.py" "$out/${name}_irregular.ply" "$out/${name}_irregular.png" --legend \
  --title "$name: irregular vertices"
cat "$out/${name}_report.txt"
echo "demo: wrote $out/${name}_irregular.ply, $out/${name}_report.txt, $out/${name}_irregular.png"
