#!/usr/bin/env bash
# Installs what filter_irregular needs on Debian bookworm (run as root; idempotent).
#  - Debian's MeshLab 2020.09 (runtime: meshlabserver, meshlab, libmeshlab-common.so)
#  - the MeshLab source package (plugin headers + vcglib), unpacked under .deps/ (git-ignored)
#  - build tools, Qt5/GLEW/Eigen headers, GoogleTest, Google Benchmark
#  - Xvfb (meshlabserver needs an X display), Python 3 test driver deps (Debian's pytest, numpy)
#  - the libcgal-demo corpus of real meshes, unpacked under .deps/data
#  - MeshLab 2025.07's source (plugin headers + its vcglib) from Debian unstable's source
#    package, through a private apt configuration (sid never enters the system's sources and no
#    binary package comes from it), unpacked under .deps/meshlab2025-src
#  - a Python venv (.deps/venv) with pymeshlab 2025.7.post1 from PyPI (MeshLab 2025.07's
#    libmeshlab-common.so and Qt 5.15 come from its wheel), numpy, scipy, pytest
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
deps="$here/.deps"
mkdir -p "$deps"

pkgs=(meshlab libcgal-demo xvfb xauth cmake ninja-build g++ pkg-config dpkg-dev
      qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
      libgtest-dev libbenchmark-dev zlib1g-dev python3-pytest python3-numpy python3-scipy)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# apt-get source needs a deb-src entry: derive it from the existing Debian sources file.
srcfile=/etc/apt/sources.list.d/filter-irregular-src.sources
need_update=0
if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed -e 's/^Types:.*/Types: deb-src/' /etc/apt/sources.list.d/debian.sources > "$srcfile"
  elif [ -f /etc/apt/sources.list ]; then
    grep -E '^deb ' /etc/apt/sources.list | sed -e 's/^deb /deb-src /' > /etc/apt/sources.list.d/filter-irregular-src.list
  fi
  need_update=1
fi
if [ ${#missing[@]} -gt 0 ] || [ $need_update = 1 ] || [ ! -d "$deps/meshlab-src" ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# MeshLab 2020.09 source (headers and the vcglib it was built with).
if [ ! -d "$deps/meshlab-src" ]; then
  tmp=$(mktemp -d "$deps/src.XXXX")
  (cd "$tmp" && apt-get source -qq meshlab >/dev/null 2>&1 || apt-get source meshlab)
  d=$(find "$tmp" -maxdepth 1 -mindepth 1 -type d -name 'meshlab-*' | head -1)
  [ -n "$d" ] || { echo "setup: apt-get source meshlab gave no folder" >&2; exit 1; }
  mv "$d" "$deps/meshlab-src"
  rm -rf "$tmp"
fi

# MeshLab 2025.07 source: Debian sid's meshlab 2025.07~dfsg-4 orig tarball (no .dsc is served
# for it, hence --tar-only), fetched with a private sources list, lists and cache.
if [ ! -d "$deps/meshlab2025-src/src/common" ]; then
  sid="$deps/apt-sid"
  mkdir -p "$sid/lists/partial" "$sid/cache/archives/partial" "$sid/dl"
  mirror=$(grep -hoE '^URIs: *\S+' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -1 | awk '{print $2}')
  [ -n "$mirror" ] || mirror=$(grep -hoE '^deb +\S+' /etc/apt/sources.list 2>/dev/null | head -1 | awk '{print $2}')
  [ -n "$mirror" ] || mirror=http://deb.debian.org/debian
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror sid main" > "$sid/sid.list"
  aptsid=(-o Dir::Etc::sourcelist="$sid/sid.list" -o Dir::Etc::sourceparts=/dev/null
          -o Dir::State::Lists="$sid/lists" -o Dir::Cache="$sid/cache")
  apt-get "${aptsid[@]}" update -qq
  (cd "$sid/dl" && apt-get "${aptsid[@]}" source -qq --tar-only 'meshlab=2025.07~dfsg-4' 2>&1 | grep -v "^W: Download is performed unsandboxed" || true)
  tarball="$sid/dl/meshlab_2025.07~dfsg.orig.tar.xz"
  [ -f "$tarball" ] || { echo "setup: apt-get source --tar-only meshlab=2025.07~dfsg-4 gave no tarball" >&2; exit 1; }
  tmp=$(mktemp -d "$deps/src2025.XXXX")
  tar -xJf "$tarball" -C "$tmp"
  d=$(find "$tmp" -maxdepth 1 -mindepth 1 -type d -name 'meshlab-*' | head -1)
  [ "$(cat "$d/ML_VERSION")" = "2025.07" ] || { echo "setup: the sid tarball is not MeshLab 2025.07" >&2; exit 1; }
  rm -rf "$deps/meshlab2025-src"
  mv "$d" "$deps/meshlab2025-src"
  rm -rf "$tmp"
fi

# Python venv for pymeshlab (never the system Python's site-packages).
venv="$deps/venv"
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import pymeshlab, numpy, scipy, pytest" 2>/dev/null; then
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$here/scripts/requirements.txt"
fi

# Real meshes from Debian's libcgal-demo (never committed).
if [ ! -d "$deps/data/meshes" ]; then
  mkdir -p "$deps/data"
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$deps" data/meshes
fi
echo "setup: ok (deps in $deps)"
