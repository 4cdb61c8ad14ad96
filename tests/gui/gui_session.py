#!/usr/bin/python3
"""One GUI session of a real MeshLab (called by gui_test.sh, which provides the X server,
the D-Bus session and the settings folder):

  start MeshLab on the mesh -> Filters > <menu> > <filter> -> Apply -> Close the dialog
  -> File > Export Mesh As... -> type the .ply path -> export options: vertex Color and
  Quality on -> OK -> File > Exit

Screenshots (/usr/bin/import -window root) after every step go to --out. Exits 1 with a
"gui: FAIL ..." line naming the step that failed (window not found, menu entry not found,
dialog not open, file not written, MeshLab died or did not quit).
"""
import argparse
import os
import re
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mlgui import A11y, Gui, GuiError, log, run, wait_for  # noqa: E402


def start_a11y():
    """Starts the AT-SPI bus and registry of this D-Bus session and publishes the bus address
    on the X root window (AT_SPI_BUS), where Qt reads it synchronously at start-up. Without
    the property Qt finds the bus through an asynchronous D-Bus call and, depending on timing,
    never exports its accessible objects."""
    a11y = wait_for("the AT-SPI registry", lambda: _try_a11y(), 30)
    addr = a11y.bus_address
    run("xprop", "-root", "-f", "AT_SPI_BUS", "8s", "-set", "AT_SPI_BUS", addr)
    return a11y


def _try_a11y():
    import dbus
    try:
        a = A11y()
        a.bus_address = str(dbus.SessionBus().get_object("org.a11y.Bus", "/org/a11y/bus")
                            .GetAddress(dbus_interface="org.a11y.Bus"))
        return a
    except dbus.exceptions.DBusException:
        return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--meshlab", required=True)
    ap.add_argument("--title", required=True, help="start of the main window title, e.g. 'MeshLab 2025.07'")
    ap.add_argument("--mesh", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--ply", required=True)
    ap.add_argument("--menu", required=True)
    ap.add_argument("--filter", required=True)
    ap.add_argument("--readme-png", default="", help="also write a cropped picture of the GUI after Apply here")
    return run_meshlab(ap.parse_args(), session)


def run_meshlab(a, session_fn):
    """Starts MeshLab (a.meshlab a.mesh, log in a.out/meshlab.log) with the accessibility bus,
    runs session_fn(a, a11y, proc), and kills MeshLab if it is still there. Returns the exit
    status: 0, or 1 after a "gui: FAIL ..." line and a screenshot of the failure."""
    os.makedirs(a.out, exist_ok=True)
    if os.path.exists(a.ply):
        os.remove(a.ply)

    a11y = start_a11y()
    env = dict(os.environ, QT_LINUX_ACCESSIBILITY_ALWAYS_ON="1")
    mlog = open(os.path.join(a.out, "meshlab.log"), "w")
    proc = subprocess.Popen([a.meshlab, a.mesh], stdout=mlog, stderr=subprocess.STDOUT, env=env,
                            cwd=a.out, start_new_session=True)
    log("started %s (pid %d)" % (a.meshlab, proc.pid))
    try:
        session_fn(a, a11y, proc)
    except Exception as e:
        if not isinstance(e, GuiError):
            import traceback
            traceback.print_exc()
            e = "unexpected error: %s" % str(e).splitlines()[0]
        print("gui: FAIL %s" % e, flush=True)
        try:
            run("/usr/bin/import", "-window", "root", os.path.join(a.out, "99_failure.png"))
            log("screenshot of the failure: %s" % os.path.join(a.out, "99_failure.png"))
        except GuiError:
            pass
        return 1
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        mlog.close()
    return 0


def session(a, a11y, proc):
    g = open_main(a, a11y, proc)
    apply_filter(a, g)
    export_mesh(g, a.ply, ("Color", "Quality"))
    quit_meshlab(g, proc)
    return g


def open_main(a, a11y, proc):
    """Waits for MeshLab's main window (title a.title), places it at 0,0 in 1600x1000 and waits
    for the log to report a.mesh opened. Returns the Gui."""
    # 1. main window, by title (xdotool) and on the accessibility bus
    def window():
        if proc.poll() is not None:
            raise GuiError("MeshLab exited with status %s before showing its window (see meshlab.log)" % proc.returncode)
        # a message box before the main window, e.g. "Error while loading plugins."
        r = subprocess.run(["xdotool", "search", "--onlyvisible", "--pid", str(proc.pid)],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        for w in r.stdout.split():
            name = subprocess.run(["xdotool", "getwindowname", w], stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, text=True).stdout.strip()
            if name and not name.startswith("MeshLab"):
                time.sleep(1)
                subprocess.run(["/usr/bin/import", "-window", "root", os.path.join(a.out, "01_startup_message.png")])
                text = ""
                try:  # its text, from the accessibility bus when it is there already
                    app = a11y.app(pid=proc.pid, timeout=3, need_frame=False)
                    text = " ".join(n.name for f in app.children() if f.role in ("dialog", "alert", "alert message")
                                    for n in f.find(role="label") if n.name)
                    text = " ".join(text.split())
                except Exception as e:
                    log("(text of the message box not readable: %s)" % str(e).splitlines()[0])
                raise GuiError("MeshLab shows a message box '%s' at start-up%s (screenshot 01_startup_message.png)"
                               % (name, (": " + text) if text else ""))
        r = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "^" + re.escape(a.title)],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        return r.stdout.split()[0] if r.stdout.split() else None
    try:
        wid = wait_for("a window titled '%s...'" % a.title, window, 60)
    except GuiError as e:
        if str(e).startswith("timed out"):
            raise GuiError("window not found: %s" % e)
        raise
    log("main window %s" % wid)
    run("xdotool", "windowmove", wid, "0", "0")
    run("xdotool", "windowsize", "--sync", wid, "1600", "1000")
    app = a11y.app(pid=proc.pid, timeout=30)
    g = Gui(app, a.out, proc.pid)
    main = g.main_frame()
    stray = [f for f in g.frames() if f.showing() and f != main]
    if stray:
        raise GuiError("unexpected window at start-up: '%s' (the settings preset did not work?)" % stray[0].name)
    mesh_name = os.path.basename(a.mesh)
    wait_for("the log to report '%s' opened" % mesh_name,
             lambda: "Opened mesh" in g.log_text() and mesh_name in g.log_text(), 60)
    time.sleep(1.0)  # let the first frame render
    g.shot("loaded")
    return g


def apply_filter(a, g):
    """Filters > a.menu > a.filter, Apply, Close; the README picture when asked."""
    # 2. the filter, by name, in its submenu of Filters
    where = g.locate_in_menu("Filters", a.filter)
    wanted = ["Filters", a.menu, a.filter]
    if not where:
        subs = [e.name for e in g.entries(g.popup_of(g.menubar_item("Filters")))]
        raise GuiError("menu entry '%s' not found in any submenu of Filters (submenus: %s); is the plugin loaded? (see meshlab.log)"
                       % (a.filter, "; ".join(subs)))
    log("'%s' is in: %s" % (a.filter, " | ".join(" > ".join(p) for p in where)))
    if wanted not in where:
        log("NOTE: not under '%s'; using %s" % (a.menu, " > ".join(where[0])))
        wanted = where[0]
    g.open_menu_path(wanted, "menu")
    g.check_alive("opening the filter")
    dlg = wait_for("the dialog of '%s'" % a.filter,
                                         lambda: next((f for f in g.frames() if f.name == a.filter and f.showing()), None), 20)
    apply_btn = wait_for("the Apply button of the filter dialog", lambda: g.find_showing("push button", "Apply", within=dlg), 10)
    time.sleep(0.5)
    g.shot("filter_dialog")

    # 3. Apply, then wait for MeshLab's "Applied filter" log line (or an error box)
    applied = re.compile(r"Applied filter:? " + re.escape(a.filter))
    n_before = len(applied.findall(g.log_text()))
    g.click(apply_btn, "Apply")
    def done():
        g.check_alive("applying the filter")
        if len(applied.findall(g.log_text())) > n_before:
            return True
        for f in g.frames():
            if f.role in ("dialog", "alert", "alert message") and f.showing() and f != dlg:
                labels = [n.name for n in f.find(role="label")]
                raise GuiError("the filter failed: '%s': %s" % (f.name, " ".join(labels)))
        return False
    wait_for("the log line 'Applied filter %s'" % a.filter, done, 180)
    time.sleep(1.5)  # repaint with the new colours
    g.shot("applied")
    text = g.log_text().replace("\u2028", "\n")
    with open(os.path.join(a.out, "meshlab_gui_log.txt"), "w") as f:
        f.write(text + "\n")
    m = re.search(r"Irregular vertices: (\d+) of (\d+)", text)
    if m:
        log("the GUI log says: %s" % m.group(0))

    # 4. close the filter dialog (it may cover the menu bar), README picture
    g.click(g.find_showing("push button", "Close", within=dlg), "Close (filter dialog)")
    wait_for("the filter dialog to close", lambda: not dlg.showing(), 10)
    time.sleep(1.5)
    shot = g.shot("applied_dialog_closed")
    if a.readme_png:
        readme_picture(shot, a.readme_png)


def export_mesh(g, ply, vert_options=()):
    """File > Export Mesh As... <ply>, with the export options Vert > <vert_options> checked."""
    # 5. File > Export Mesh As...
    saved_before = g.log_text().count("Saved Mesh")
    g.open_menu_path(["File", "Export Mesh As..."], "menu_export")
    def file_dialog():
        for f in g.frames():
            if f.role == "dialog" and f.showing():
                t = f.find(role="text", name="File name:", showing=True, max_depth=4)
                if t:
                    return f, t[0]
        return None
    fdlg, name_field = wait_for("the export file dialog", file_dialog, 20)
    g.shot("export_dialog")
    g.click(name_field, "the 'File name:' field")
    g.key("ctrl+a")
    g.type(ply)
    time.sleep(0.5)
    g.shot("export_path_typed")
    g.key("Return")

    # 6. export options: vertex Color and Quality must be checked
    def options_dialog():
        g.check_alive("exporting")
        for f in g.frames():
            if f.role == "dialog" and f.showing() and f.find(role="panel", name="Vert", showing=True, max_depth=3):
                return f
        for f in g.frames():
            if f.role in ("dialog", "alert", "alert message") and f.showing() and f != fdlg:
                raise GuiError("unexpected dialog '%s' after typing the path: %s" %
                               (f.name, " ".join(n.name for n in f.find(role="label"))))
        return None
    odlg = wait_for("the export options dialog ('Choose Saving Options')", options_dialog, 20)
    vert = odlg.find(role="panel", name="Vert", showing=True, max_depth=3)[0]
    for label in vert_options:
        boxes = vert.find(role="check box", name=label, showing=True)
        if not boxes:
            raise GuiError("no 'Vert > %s' check box in the export options dialog" % label)
        box = boxes[0]
        if not box.enabled():
            raise GuiError("'Vert > %s' is greyed out in the export options: the mesh has no vertex %s" % (label, label.lower()))
        if not box.checked():
            g.click(box, "Vert > %s (was unchecked)" % label)
            wait_for("'Vert > %s' to be checked" % label, box.checked, 5)
        log("export option Vert > %s: checked" % label)
    g.shot("export_options")
    g.click(g.find_showing("push button", "OK", within=odlg), "OK (export options)")

    # 7. the file: MeshLab logs "Saved Mesh <path>"
    def saved():
        g.check_alive("saving")
        return g.log_text().count("Saved Mesh") > saved_before and os.path.exists(ply)
    try:
        wait_for("'Saved Mesh' in the log and %s on disk" % ply, saved, 60)
    except GuiError as e:
        raise GuiError("file not written: %s" % e)
    size = -1
    while size != os.path.getsize(ply):
        size = os.path.getsize(ply)
        time.sleep(0.5)
    log("exported %s (%d bytes)" % (ply, size))
    g.shot("saved")


def quit_meshlab(g, proc):
    """File > Exit, answering a 'close without saving?' question; MeshLab must quit with 0."""
    # 8. File > Exit; answer a "close without saving?" question if one comes
    g.open_menu_path(["File", "Exit"], "menu_exit")
    end = time.time() + 30
    while proc.poll() is None and time.time() < end:
        try:
            for f in g.frames():
                if f.role in ("dialog", "alert", "alert message") and f.showing():
                    g.shot("exit_question")
                    log("exit question '%s': %s" % (f.name, " ".join(n.name for n in f.find(role="label"))))
                    btn = next((b for name in ("Yes", "Discard", "Close without Saving", "OK")
                                for b in [g.find_showing("push button", name, within=f)] if b), None)
                    if btn:
                        g.click(btn)
        except Exception:  # the application is going away: its accessible objects vanish
            pass
        time.sleep(0.3)
    if proc.poll() is None:
        raise GuiError("MeshLab did not quit within 30 s of File > Exit")
    if proc.returncode != 0:
        raise GuiError("MeshLab quit with status %d (see meshlab.log)" % proc.returncode)
    log("MeshLab quit (status 0)")


def readme_picture(shot, dest, crop="1600x960+0+0"):
    """The main window without the empty bottom rows (or the `crop` geometry), reduced to an
    8-bit palette PNG."""
    os.makedirs(os.path.dirname(os.path.abspath(dest)), exist_ok=True)
    run("/usr/bin/convert", shot, "-crop", crop, "+repage",
        "-dither", "None", "-colors", "256", "-strip", "PNG8:" + dest)
    log("README picture %s (%d KB)" % (dest, os.path.getsize(dest) // 1024))


if __name__ == "__main__":
    sys.exit(main())
