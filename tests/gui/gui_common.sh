# Sourced by tests/gui/gui_test.sh and tests/gui/edit_test.sh (bash, set -euo pipefail, with
# $here = the source folder and fail() defined): the tools, the staged MeshLabs and a private
# X server + D-Bus session + settings for one GUI run.

# The Debian bookworm packages the GUI tests need, installed when missing.
gui_install_tools() {
  local need=(xvfb xauth x11-utils xdotool imagemagick dbus dbus-daemon at-spi2-core python3-dbus binutils)
  local missing=() p
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
}

# gui_stage_2020 <stage folder> <plugin .so>...: a private copy of Debian's MeshLab 2020.09 GUI
# (the same layout scripts/build.sh makes in build/stage) loading the system plugins plus the
# given ones (links). Prints nothing; the binary is <stage>/bin/meshlab.
gui_stage_2020() {
  local stage=$1; shift
  local pdir=$stage/lib/x86_64-linux-gnu/meshlab/plugins f
  rm -rf "$stage"; mkdir -p "$stage/bin" "$pdir"
  cp /usr/bin/meshlab "$stage/bin/"
  ln -s /usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so "$stage/lib/x86_64-linux-gnu/meshlab/"
  for f in /usr/lib/x86_64-linux-gnu/meshlab/plugins/*.so; do ln -s "$f" "$pdir/"; done
  for f in "$@"; do ln -sf "$f" "$pdir/$(basename "$f")"; done
}

# gui_scalar_of <plugin .so|none>: the MeshLab 2025.07 scalar a plugin was built with (double
# for the pymeshlab wheel's), from the vcg types in its symbols; GUI_TEST_SCALAR overrides.
gui_scalar_of() {
  local scalar=${GUI_TEST_SCALAR:-} nd nf
  if [ -z "$scalar" ]; then
    scalar=float
    if [ "$1" != none ]; then
      nd=$(nm -D -C "$1" | grep -c 'vcg::Point3<double>' || true)
      nf=$(nm -D -C "$1" | grep -c 'vcg::Point3<float>' || true)
      [ "$nd" -gt "$nf" ] && scalar=double
    fi
  fi
  echo "$scalar"
}

# gui_stage_2025 <float|double> <plugin .so>...: stages the MeshLab 2025.07 GUI of that scalar
# (built by scripts/build_meshlab2025.sh when missing) into build/stage2025[-double]: a copy of
# the binary, links to its libraries, shaders and plugins, plus links to the given plugins;
# nothing is written into .deps. Sets gui_bin to the binary.
gui_stage_2025() {
  local scalar=$1; shift
  local dist stage l f
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
  for f in "$@"; do ln -sfn "$f" "$stage/plugins/$(basename "$f")"; done
  gui_bin=$stage/meshlab
}

# gui_start_display <out folder>: a private Xvfb (1600x1000, GLX), a D-Bus session for Qt's
# accessibility bus and MeshLab settings without first-start questions, in a temporary folder
# removed at exit (with the two processes). Exports DISPLAY, DBUS_SESSION_BUS_ADDRESS, HOME,
# XDG_CONFIG_HOME and XDG_RUNTIME_DIR.
gui_start_display() {
  local out=$1
  gui_tmp=$(mktemp -d /tmp/gui_test.XXXXXX)
  gui_xpid=; gui_dpid=
  trap gui_cleanup EXIT
  mkdir -p "$gui_tmp/home" "$gui_tmp/config/VCG" "$gui_tmp/run"; chmod 700 "$gui_tmp/run"
  # MeshLab's QSettings (organisation VCG, application MeshLab_64bit_fp): the 2025.07 first-start
  # question "Send Anonymous Statistics" is asked while informativeShown is unset; the update
  # check, the statistics and the "congratulations" mail dialog are switched off; the window size
  # is preset (2025.07; 2020.09 is resized with xdotool).
  {
    echo "[General]"
    echo "informativeShown=true"
    echo "dontRemindMeToSendEmail=true"
    echo "dontRemindMeAboutUpgrade=true"
    gui_param sendAnonymousData RichBool false
    gui_param checkForUpdate RichBool false
    gui_param startupWindowWidth RichInt 1600
    gui_param startupWindowHeight RichInt 1000
  } > "$gui_tmp/config/VCG/MeshLab_64bit_fp.conf"
  cp "$gui_tmp/config/VCG/MeshLab_64bit_fp.conf" "$gui_tmp/config/VCG/MeshLab_64bit_dp.conf"   # double-scalar builds
  export HOME=$gui_tmp/home XDG_CONFIG_HOME=$gui_tmp/config XDG_RUNTIME_DIR=$gui_tmp/run
  unset SESSION_MANAGER WAYLAND_DISPLAY QT_QPA_PLATFORM || true

  exec 3>"$gui_tmp/display"
  Xvfb -displayfd 3 -screen 0 1600x1000x24 +extension GLX -nolisten tcp >"$out/xvfb.log" 2>&1 &
  gui_xpid=$!
  exec 3>&-
  for _ in $(seq 100); do [ -s "$gui_tmp/display" ] && break; kill -0 $gui_xpid 2>/dev/null || break; sleep 0.1; done
  [ -s "$gui_tmp/display" ] || fail "Xvfb did not start (see $out/xvfb.log)"
  export DISPLAY=:$(head -1 "$gui_tmp/display")
  # the D-Bus session (for Qt's accessibility bus) starts after DISPLAY is set
  read -r DBUS_SESSION_BUS_ADDRESS gui_dpid < <(dbus-daemon --session --fork --print-address=1 --print-pid=1 | paste -s -d' ')
  export DBUS_SESSION_BUS_ADDRESS
  [ -n "$gui_dpid" ] || fail "dbus-daemon did not start"
  echo "gui: Xvfb $DISPLAY (pid $gui_xpid), D-Bus session (pid $gui_dpid)"
}

gui_param() { # name type value: one MeshLab::System setting
  printf 'MeshLab%%3A%%3ASystem%%3A%%3A%s="<!DOCTYPE MeshLabSettings>\\n<Param name=\\"MeshLab::System::%s\\" tooltip=\\"\\" description=\\"\\" type=\\"%s\\" value=\\"%s\\"/>\\n"\n' "$1" "$1" "$2" "$3"
}

gui_cleanup() {
  [ -n "${gui_dpid:-}" ] && kill "$gui_dpid" 2>/dev/null || true
  [ -n "${gui_xpid:-}" ] && kill "$gui_xpid" 2>/dev/null || true
  [ -n "${gui_tmp:-}" ] && rm -rf "$gui_tmp"
  return 0
}
