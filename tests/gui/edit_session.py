#!/usr/bin/python3
"""One GUI session of the edit tool "Irregular Vertices: Edit" in a real MeshLab (called by
edit_test.sh, which provides the X server, the D-Bus session and the settings folder):

  start MeshLab on a PLY whose two selected vertices are a 5-7 pair -> Edit > Irregular
  Vertices: Edit (the tool picks the pair from the selection; log line "pair picked from the
  selection") -> click the empty left margin of the viewport (keyboard focus; a click on no
  surface picks nothing) -> key <key> <n> times (each must log "step in direction <key> done")
  -> screenshot (and the README picture) -> File > Export Mesh As... <ply> -> File > Exit

Screenshots of every step go to --out. Exits 1 with a "gui: FAIL ..." line naming the step
that failed.
"""
import argparse
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mlgui import GuiError, log, wait_for  # noqa: E402
from gui_session import export_mesh, open_main, quit_meshlab, readme_picture, run_meshlab  # noqa: E402

TOOL = "Irregular Vertices: Edit"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--meshlab", required=True)
    ap.add_argument("--title", required=True)
    ap.add_argument("--mesh", required=True, help="a PLY with exactly two selected vertices (a pair)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--ply", required=True, help="where to export the edited mesh")
    ap.add_argument("--key", default="1", help="the direction key (1-6)")
    ap.add_argument("--steps", type=int, default=3)
    ap.add_argument("--readme-png", default="")
    return run_meshlab(ap.parse_args(), session)


def tool_lines(g):
    """The tool's lines in MeshLab's log pane, oldest first."""
    text = g.log_text().replace("\u2028", "\n")
    return [ln.strip() for ln in text.splitlines() if TOOL + ":" in ln]


def session(a, a11y, proc):
    g = open_main(a, a11y, proc)

    # 1. the tool, by name, in the Edit menu
    where = g.locate_in_menu("Edit", TOOL)
    if not where:
        subs = [e.name for e in g.entries(g.popup_of(g.menubar_item("Edit")))]
        raise GuiError("'%s' not in the Edit menu (entries: %s); is the edit plugin loaded? (see meshlab.log)"
                       % (TOOL, "; ".join(subs)))
    g.open_menu_path(where[0], "menu_edit")
    g.check_alive("starting the tool")

    def picked():
        g.check_alive("starting the tool")
        for ln in tool_lines(g):
            if "pair picked from the selection" in ln:
                return ln
            if "the selection is not a pair" in ln or "not implemented" in ln:
                raise GuiError("the tool did not pick the selected pair: '%s'" % ln)
        return None
    line = wait_for("the log line '%s: pair picked from the selection'" % TOOL, picked, 20)
    log("the GUI log says: %s" % line)
    time.sleep(1.0)
    g.shot("tool_started")

    # 2. keyboard focus: a click on the viewport's empty left margin (no surface there: the
    # tool logs "nothing under the cursor" and keeps the pair)
    main = g.main_frame()
    x, y, w, h = main.extents()
    n_lines = len(tool_lines(g))
    g.click_at(x + 15, y + 300)

    def focus_line():
        g.check_alive("the focus click")
        new = tool_lines(g)[n_lines:]
        return new[0] if new else None
    line = wait_for("the tool's answer to the focus click", focus_line, 10)
    if "nothing under the cursor" not in line:
        raise GuiError("the focus click hit the mesh: '%s' (the left margin of the viewport is not empty?)" % line)

    # 3. the steps: one key press each, each must be logged as done
    done_re = re.compile(r"step in direction %s done" % re.escape(a.key))
    for i in range(a.steps):
        before = len(tool_lines(g))
        g.key(a.key)

        def stepped():
            g.check_alive("step %d" % (i + 1))
            new = tool_lines(g)[before:]
            for ln in new:  # the first line after the key press says done or why not
                if done_re.search(ln):
                    return ln
                raise GuiError("step %d not done: '%s'" % (i + 1, ln))
            return None
        line = wait_for("step %d logged as done" % (i + 1), stepped, 20)
        log("step %d: %s" % (i + 1, line))
        time.sleep(0.5)
    time.sleep(1.5)  # the repaint with the re-uploaded buffers
    shot = g.shot("after_steps")
    if a.readme_png:
        readme_picture(shot, a.readme_png)
    with open(os.path.join(a.out, "meshlab_gui_log.txt"), "w") as f:
        f.write(g.log_text().replace("\u2028", "\n") + "\n")

    # 4. export and quit
    export_mesh(g, a.ply, ())
    quit_meshlab(g, proc)


if __name__ == "__main__":
    sys.exit(main())
