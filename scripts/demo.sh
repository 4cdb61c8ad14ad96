#!/usr/bin/env bash
# The main job on a default input: installs what is missing, builds, and runs the plugin
# through the staged meshlabserver on the bunny of Debian's libcgal-demo corpus.
# Writes out/bunny00_irregular.ply (coloured by valence, irregular vertices selected),
# out/bunny00_report.txt (the filter's log) and out/bunny00_irregular.png (a picture); then
# runs Automatic Reduction (examples/automatic_reduction.mlx: remesh to about 19K vertices and
# reduce) and writes out/bunny00_reduced.{ply,png} and out/bunny00_reduced_report.txt.
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

# Automatic Reduction: the flagship filter, on the same input. The example script's remeshing
# edge length is the bunny's (about 19K vertices); for another mesh the same script is written
# with the edge length that gives this mesh about 20K vertices.
script="$here/examples/automatic_reduction.mlx"
if [ "$in" != "$here/.deps/data/meshes/bunny00.off" ]; then
  script="$out/${name}_automatic_reduction.mlx"
  /usr/bin/python3 - "$in" "$here/examples/automatic_reduction.mlx" "$script" <<'PY'
import re, sys
sys.path.insert(0, sys.argv[2].rsplit("/examples/", 1)[0] + "/tests/integration")
from mlpy import diagonal, edge_length_for, read_mesh
m = read_mesh(sys.argv[1])
length, diag = edge_length_for(m, 20000), diagonal(m)
text = open(sys.argv[2]).read()
text = re.sub(r'name="remeshEdgeLength" value="[^"]*" min="0" max="[^"]*"',
              'name="remeshEdgeLength" value="%r" min="0" max="%r"' % (float(length), float(diag)), text)
open(sys.argv[3], "w").write(text)
PY
fi
xvfb-run -a -s "-screen 0 1024x768x24" "$stage/bin/meshlabserver" -i "$in" -o "$out/${name}_reduced.ply" \
  -m vc vq vf -s "$script" > "$out/${name}_reduced_meshlabserver.log" 2>&1 || {
  grep -E "refused|Problem" "$out/${name}_reduced_meshlabserver.log"; echo "demo: automatic reduction failed" >&2; exit 1; }
grep -oE "(Isotropic remeshing to|Automatic reduction:|Valences (before|after)|Edits:|Before:|After:|Hausdorff distance|Time:).*" "$out/${name}_reduced_meshlabserver.log" \
  | awk '!seen[$0]++' > "$out/${name}_reduced_report.txt"  # meshlabserver prints its log twice
/usr/bin/python3 "$here/scripts/render_png.py" "$out/${name}_reduced.ply" "$out/${name}_reduced.png" --legend \
  --title "$name: after Automatic Reduction"
cat "$out/${name}_reduced_report.txt"
echo "demo: wrote $out/${name}_reduced.ply, $out/${name}_reduced_report.txt, $out/${name}_reduced.png"
