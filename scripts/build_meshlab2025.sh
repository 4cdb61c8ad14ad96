#!/usr/bin/env bash
# Builds a real MeshLab 2025.07 GUI from the source unpacked by setup.sh
# (.deps/meshlab2025-src) into .deps/meshlab2025-build-double, with the six plugins the GUI tests
# need (io_base, filter_select, filter_meshing, filter_measure, edit_select, decorate_base)
# and no downloads (every MESHLAB_ALLOW_DOWNLOAD_SOURCE_* OFF). The cmake line is the one
# MeshLab's build notes for 2025.07 plus double-precision scalars. Idempotent: does nothing
# when the build's src/distrib/meshlab exists and is newer than every source file.
# Installs the bookworm packages it needs when they are missing. About 4-5 min on 2 cores.
#
#   scripts/build_meshlab2025.sh          # double scalars (as pymeshlab's wheel, -DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=ON):
#                                         # .deps/meshlab2025-build-double; the test command builds this one
#   scripts/build_meshlab2025.sh float    # float scalars (MeshLab's default): .deps/meshlab2025-build
# MeshLab refuses a plugin built with the other precision ("has different floating point
# precision"); the pymeshlab 2025.7.post1 wheel is built with double scalars, so a plugin built
# for the wheel (MESHLAB_SCALAR=double) needs the double GUI.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
scalar=${1:-${MESHLAB2025_SCALAR:-double}}
case $scalar in
  float)  extra=(); suffix= ;;
  double) extra=(-DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=ON); suffix=-double ;;
  *) echo "usage: $0 [float|double]" >&2; exit 2 ;;
esac
src=${MESHLAB2025_SRC:-$here/.deps/meshlab2025-src}
build=${MESHLAB2025_BUILD:-$here/.deps/meshlab2025-build$suffix}
bin=$build/src/distrib/meshlab

[ -f "$src/ML_VERSION" ] || { echo "build_meshlab2025: no MeshLab 2025.07 source in $src (run scripts/setup.sh)" >&2; exit 1; }

# Up to date? The binary must be newer than every file of the source tree.
if [ -x "$bin" ] && [ -z "$(find "$src" -newer "$bin" -type f -print -quit)" ]; then
  echo "build_meshlab2025: up to date ($bin)"
  exit 0
fi

# Bookworm packages (the system's apt sources only; nothing from the private sid list).
need=(cmake ninja-build g++ pkg-config qtbase5-dev libqt5opengl5-dev
      libqt5xmlpatterns5-dev libglew-dev libeigen3-dev libgl-dev libglu1-mesa-dev)
missing=()
for p in "${need[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build_meshlab2025: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null ||
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; }
fi

start=$(date +%s)
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMESHLAB_PLUGINS="meshlabplugins/io_base;meshlabplugins/filter_select;meshlabplugins/filter_meshing;meshlabplugins/edit_select;meshlabplugins/decorate_base;meshlabplugins/filter_measure" \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_BOOST=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_CGAL=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_LIBE57=OFF \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_EMBREE=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_LEVMAR=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_LIB3DS=OFF \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_LIB3MF=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_LIBIGL=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_MUPARSER=OFF \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_NEXUS=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_OPENCTM=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_QHULL=OFF \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_STRUCTURE_SYNTH=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_TINYGLTF=OFF -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_U3D=OFF \
  -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_XERCES=OFF "${extra[@]}"
ninja -C "$build" -j2
[ -x "$bin" ] || { echo "build_meshlab2025: build finished but $bin is missing" >&2; exit 1; }
touch "$bin"   # a no-op relink leaves the old mtime; mark the build as newer than the source
echo "build_meshlab2025: built $bin ($scalar scalars) in $(( $(date +%s) - start )) s"
