#!/usr/bin/env bash
# The Python wheel: builds pymeshlab-irregular (pyproject.toml, scikit-build-core, MeshLab 2025.07
# plugin only) into build/wheel/, installs it into a FRESH venv (build/wheel-venv, made from
# /usr/bin/python3 on every run) and runs tests/wheel/smoke_wheel.py in that venv from a folder
# outside the source tree.
#   scripts/test_wheel.sh [MESH]        MESH: a closed torus mesh; default $FI_WHEEL_MESH, else
#                                       .deps/data/meshes/knot1.off (scripts/setup.sh unpacks it)
# Needs scripts/setup.sh done (the MeshLab sources under .deps/) and PyPI on the first run only:
# the build requirements and pymeshlab (+ numpy) are downloaded once into build/wheel/deps/, and
# every install (the isolated build environment, the test venv) then uses --no-index
# --find-links build/wheel/deps. pip's own HTTP cache is not relied on (responses that carry no
# cache headers, as through some proxies, are never cached). The CMake build folder
# build/wheel/cmake/ is kept, so a rebuild recompiles only what changed.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-${FI_WHEEL_MESH:-$here/.deps/data/meshes/knot1.off}}
[ -f "$mesh" ] || { echo "test_wheel: mesh not found: $mesh" >&2; exit 1; }
mesh=$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")
out="$here/build/wheel"
deps="$out/deps"
venv="$here/build/wheel-venv"
t0=$SECONDS

# A fresh venv from the system Python (nothing is installed into the system Python itself).
rm -rf "$venv"
/usr/bin/python3 -m venv "$venv"
pip=("$venv/bin/pip" --disable-pip-version-check)

# What the build and the wheel need, read from pyproject.toml: build-system.requires and
# project.dependencies. Offline if build/wheel/deps/ already has all of it.
mapfile -t reqs < <("$venv/bin/python" -c '
import sys, tomllib
d = tomllib.load(open(sys.argv[1], "rb"))
print("\n".join(dict.fromkeys(d["build-system"]["requires"] + d["project"]["dependencies"])))' "$here/pyproject.toml")
mkdir -p "$deps"
if ! "${pip[@]}" download -q --no-index --find-links "$deps" -d "$deps" "${reqs[@]}" >/dev/null 2>&1; then
  echo "test_wheel: downloading into $deps: ${reqs[*]}"
  "${pip[@]}" download -q --find-links "$deps" -d "$deps" "${reqs[@]}"
fi
offline=(--no-index --find-links "$deps")

# Build the wheel (build isolation: the build environment gets scikit-build-core and
# pymeshlab==2025.7.post1, whose libmeshlab-common.so the plugin links to).
rm -f "$out"/pymeshlab_irregular-*.whl
log="$out/build.log"
echo "test_wheel: building the wheel (log: $log)"
if ! (cd "$here" && "${pip[@]}" wheel -v --no-deps "${offline[@]}" -w "$out" .) >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "test_wheel: FAIL: wheel build (log: $log)" >&2
  exit 1
fi
wheels=("$out"/pymeshlab_irregular-*.whl)
[ ${#wheels[@]} -eq 1 ] && [ -f "${wheels[0]}" ] || { echo "test_wheel: FAIL: expected one wheel in $out" >&2; exit 1; }
wheel=${wheels[0]}
version=$(sed -nE 's/^project\(filter_irregular VERSION ([0-9.]+).*/\1/p' "$here/CMakeLists.txt")
[ "$(basename "$wheel")" = "pymeshlab_irregular-$version-py3-none-linux_x86_64.whl" ] ||
  { echo "test_wheel: FAIL: wheel name $(basename "$wheel"), expected version $version, py3-none-linux_x86_64" >&2; exit 1; }
# Its contents: the package and the plugin, nothing from the other install rules.
"$venv/bin/python" - "$wheel" <<'EOF'
import sys, zipfile
names = sorted(n for n in zipfile.ZipFile(sys.argv[1]).namelist() if ".dist-info/" not in n)
expected = ["pymeshlab_irregular/__init__.py", "pymeshlab_irregular/libfilter_irregular.so"]
if names != expected:
    sys.exit("test_wheel: FAIL: wheel holds %s, expected %s" % (names, expected))
EOF
echo "test_wheel: built $(basename "$wheel") ($(du -k "$wheel" | cut -f1) KiB) after $((SECONDS - t0)) s"

# Install it (pymeshlab comes with it, as a dependency) and run the smoke test from elsewhere,
# with a clean environment (-I: no PYTHONPATH, no user site, no script folder on sys.path).
"${pip[@]}" install -q "${offline[@]}" "$wheel"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
expected=$(sed -n 's/^project(filter_irregular VERSION \([0-9.]*\).*/\1/p' "$here/CMakeLists.txt")
(cd "$work" && env -u FILTER_IRREGULAR_PLUGIN FI_EXPECTED_VERSION="$expected" \
  "$venv/bin/python" -I "$here/tests/wheel/smoke_wheel.py" "$mesh")
echo "test_wheel: ok in $((SECONDS - t0)) s"
