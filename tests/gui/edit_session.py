#!/usr/bin/python3
"""One GUI session of the edit tool "Irregular Vertices: Edit" in a real MeshLab (called by
edit_test.sh, which provides the X server, the D-Bus session and the settings folder):

  start MeshLab on a PLY whose two selected vertices are a 5-7 pair -> (optionally turn and
  zoom the view) -> Edit > Irregular Vertices: Edit (the tool picks the pair from the
  selection: log line "pair picked from the selection") -> a wheel notch over the viewport
  (keyboard focus; the tool ignores the wheel) -> key <key> <n> times (each must log "step
  in direction <key> done") -> Ctrl+Z (must log "undone") -> Ctrl+Y (must log "redone") ->
  a key whose direction is not drawn (not in the logged "accepted next: ..."): must be
  refused -> File > Export Mesh As... <ply> -> arrow key Left (a drawn direction) and Ctrl+Z
  -> a mouse drag (at least one step toward the cursor) and Ctrl+Z as many times (unless
  the tool logs that it compacted the mesh, which clears the undo history) -> a click on
  the mesh (must pick a pair or say why not; screenshot, the README picture) -> File > Exit

With --cancel T (Q), instead of the steps: File > Export Mesh As... <before> -> key T (Q)
(must log "triple cancelled" / "quadruple cancelled") -> export <ply> -> Ctrl+Z (must log
"undone") -> export <undone> -> File > Exit (edit_test.sh checks the three files).

Screenshots of every step go to --out. Exits 1 with a "gui: FAIL ..." line naming the step
that failed.
"""
import argparse
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mlgui import GuiError, log, run, wait_for  # noqa: E402
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
    ap.add_argument("--rotate", type=int, default=0,
                    help="before the tool starts, drag the view this many pixels to the right (trackball), "
                         "so that the pair faces the camera in the screenshot")
    ap.add_argument("--zoom", type=int, default=0, help="then this many wheel notches (zoom in)")
    ap.add_argument("--cancel", choices=["T", "Q"], default="",
                    help="instead of the steps: export --before, key T (Q) must cancel the triple (quadruple) "
                         "the selected pair is part of, export --ply, Ctrl+Z must undo it, export --undone")
    ap.add_argument("--before", default="", help="--cancel: the export before the key press")
    ap.add_argument("--undone", default="", help="--cancel: the export after Ctrl+Z")
    return run_meshlab(ap.parse_args(), session)


def tool_lines(g):
    """The tool's lines in MeshLab's log pane, oldest first."""
    text = g.log_text().replace("\u2028", "\n")
    return [ln.strip() for ln in text.splitlines() if TOOL + ":" in ln]


ARROWS = ": arrows: accepted next: "


def answers(lines):
    """The tool's answers to requests: its lines without the "arrows: accepted next" ones,
    which it logs once the six arrows of a new state are computed (over one or more frames)."""
    return [ln for ln in lines if ARROWS not in ln]


def session(a, a11y, proc):
    g = open_main(a, a11y, proc)
    if a.rotate or a.zoom:
        # the view only (MeshLab's trackball, before the tool takes the mouse): the mesh and
        # the checks are unaffected
        x, y, w, h = g.main_frame().extents()
        cx, cy = x + int(0.3 * w), y + int(0.45 * h)
        run("xdotool", "mousemove", "--sync", str(cx), str(cy))
        if a.rotate:
            run("xdotool", "mousedown", "1")
            for k in range(1, 11):
                run("xdotool", "mousemove", "--sync", str(cx + a.rotate * k // 10), str(cy))
                time.sleep(0.05)
            run("xdotool", "mouseup", "1")
        if a.zoom:
            run("xdotool", "click", "--repeat", str(a.zoom), "--delay", "150", "5")
        time.sleep(1.0)
        g.shot("view")

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

    # 2. keyboard focus: one wheel notch over the viewport (GLArea takes the focus on a wheel
    # event and hands the event to the tool, which ignores it: no pick, no zoom)
    x, y, w, h = g.main_frame().extents()
    run("xdotool", "mousemove", "--sync", str(x + int(0.3 * w)), str(y + int(0.45 * h)))
    run("xdotool", "click", "5")
    time.sleep(0.5)

    def press(keys, what, ok):
        before = len(tool_lines(g))
        g.key(keys)

        def answered():
            g.check_alive(what)
            new = answers(tool_lines(g)[before:])
            if not new:  # the first line after the key press says done or why not
                return None
            if not ok(new[0]):
                raise GuiError("%s: '%s'" % (what, new[0]))
            return new[0]
        line = wait_for("the tool's answer to %s" % what, answered, 20)
        log("%s: %s" % (what, line))
        time.sleep(0.5)

    if a.cancel:
        return cancel_session(a, g, proc, press)

    # 3. the steps: one key press each, each must be logged as done; then Ctrl+Z undoes the
    # last one and Ctrl+Y redoes it (the export must still be "steps" steps from the start)
    done_re = re.compile(r"step in direction %s done" % re.escape(a.key))
    for i in range(a.steps):
        press(a.key, "step %d" % (i + 1), done_re.search)
    press("ctrl+z", "Ctrl+Z (undo the last step)", lambda ln: "undone" in ln)
    press("ctrl+y", "Ctrl+Y (redo it)", lambda ln: "redone: " in ln)
    time.sleep(1.5)  # the repaint with the re-uploaded buffers
    g.shot("after_steps")

    # 4. a direction the tool does not draw (its log lists the accepted ones after each step)
    # must be refused with a reason and change nothing (the export is checked afterwards)
    def arrows_line():
        g.check_alive("the arrows after the redo")
        last = tool_lines(g)[-1]
        return last if ARROWS in last else None
    arrows = wait_for("the line '%s...' after the redo" % ARROWS.strip(), arrows_line, 20)
    m = re.search(r"accepted next: ([0-9 ]+|none)", arrows)
    if not m:
        raise GuiError("the arrows' log line does not list the accepted directions: '%s'" % arrows)
    accepted = m.group(1).split() if m.group(1) != "none" else []
    refused = [k for k in "123456" if k not in accepted]
    log("accepted directions %s, drawn as arrows; trying a refused one: %s" % (accepted, refused[:1]))
    if refused:
        k = refused[0]
        press(k, "step %s (not drawn)" % k,
              lambda ln: ("step in direction %s refused: " % k) in ln)
        time.sleep(1.0)
        g.shot("refused_step")
    with open(os.path.join(a.out, "meshlab_gui_log.txt"), "w") as f:
        f.write(g.log_text().replace("\u2028", "\n") + "\n")

    # 5. export (the state the check compares with the reference)
    export_mesh(g, a.ply, ())

    # 6. an arrow key (mapped to the drawn direction nearest on screen) and a mouse drag (steps
    # toward the cursor), each undone with Ctrl+Z. A step that deletes mesh elements makes the
    # tool compact the mesh for MeshLab's renderer, which clears the undo history (the tool
    # logs it): then Ctrl+Z must answer "nothing to undo". MeshLab must survive all of it.
    any_done = re.compile(r"step in direction ([1-6]) done")
    compacted = "clears the undo history"

    def move_then_undo(what, act):
        before = len(tool_lines(g))
        act()
        time.sleep(1.0)
        g.check_alive(what)
        new = tool_lines(g)[before:]
        for ln in new:
            log("%s: %s" % (what, ln))
            if "picked" in ln:
                raise GuiError("%s picked instead of moving: '%s'" % (what, ln))
        done = [ln for ln in new if any_done.search(ln)]
        if not done:
            raise GuiError("%s moved nothing (log: %s)" % (what, new[-1:] or "nothing"))
        cleared = any(compacted in ln for ln in new)
        undoable = 0 if cleared else len(done)
        for i in range(undoable):
            press("ctrl+z", "Ctrl+Z %d of %d after %s" % (i + 1, undoable, what), lambda ln: "undone" in ln)
        if cleared:
            log("%s deleted elements: the mesh was compacted and the undo history cleared" % what)

    move_then_undo("arrow key Left", lambda: g.key("Left"))

    def drag():
        x, y, w, h = g.main_frame().extents()
        cx, cy = x + int(0.3 * w), y + int(0.45 * h)
        run("xdotool", "mousemove", "--sync", str(cx), str(cy))
        run("xdotool", "mousedown", "1")
        for k in range(1, 13):
            run("xdotool", "mousemove", "--sync", str(cx - 20 * k), str(cy + 10 * k))
            time.sleep(0.25)
        run("xdotool", "mouseup", "1")
    move_then_undo("the mouse drag", drag)
    g.shot("after_arrow_and_drag")

    # a click on the mesh (the viewport's centre area) picks through the depth buffer: the
    # tool answers with a pair, or why there is none near the click; never "nothing under
    # the cursor" (that is the background)
    x, y, w, h = g.main_frame().extents()
    before = len(tool_lines(g))
    g.click_at(x + int(0.3 * w), y + int(0.45 * h))

    def click_answer():
        g.check_alive("the click on the mesh")
        new = answers(tool_lines(g)[before:])
        return new[0] if new else None
    line = wait_for("the tool's answer to a click on the mesh", click_answer, 10)
    log("click on the mesh: %s" % line)
    if not ("pair picked: " in line or "no pair picked: " in line):
        raise GuiError("a click on the mesh did not reach the surface: '%s'" % line)
    time.sleep(1.0)
    shot = g.shot("after_click")
    if a.readme_png:  # the main window, without the status bar: a pair with its arrows
        readme_picture(shot, a.readme_png, "%dx%d+%d+%d" % (w, h - 40, x, y))

    # 7. quit
    quit_meshlab(g, proc)


def cancel_session(a, g, proc, press):
    """Key T (Q) on a pair that is part of a triple (quadruple): export the mesh before, the
    key must log "triple cancelled" ("quadruple cancelled"), export after, Ctrl+Z must log
    "undone", export again (edit_test.sh compares that file with the first, byte for byte),
    quit."""
    what = "triple" if a.cancel == "T" else "quadruple"
    export_mesh(g, a.before, ())
    press(a.cancel.lower(), "key %s (cancel the %s)" % (a.cancel, what),
          lambda ln: (what + " cancelled") in ln and "not cancelled" not in ln)
    time.sleep(1.5)  # the repaint with the re-uploaded buffers
    g.shot("after_%s" % what)
    export_mesh(g, a.ply, ())
    press("ctrl+z", "Ctrl+Z (undo the %s cancellation)" % what, lambda ln: "undone" in ln)
    time.sleep(1.0)
    g.shot("after_undo")
    export_mesh(g, a.undone, ())
    with open(os.path.join(a.out, "meshlab_gui_log.txt"), "w") as f:
        f.write(g.log_text().replace("\u2028", "\n") + "\n")
    quit_meshlab(g, proc)


if __name__ == "__main__":
    sys.exit(main())
