"""Drives a real MeshLab GUI (2020.09 or 2025.07) under Xvfb.

Widgets are found by *name* through the accessibility tree that Qt 5 publishes on the AT-SPI
D-Bus (QT_LINUX_ACCESSIBILITY_ALWAYS_ON=1, a private dbus-run-session, see gui_test.sh): menu
entries, buttons, check boxes and the log text are looked up by their label, their on-screen
rectangle is read from AT-SPI, and the real input is sent with xdotool (mouse clicks, key
presses, typing), so MeshLab sees ordinary X events. Nothing depends on fixed pixel
coordinates or on the position of an entry in a menu.

Runs with /usr/bin/python3 (needs python3-dbus, from Debian). Also usable by hand:
    python3 mlgui.py dump [depth]        # print the accessible tree of MeshLab
"""
import os
import subprocess
import sys
import time

import dbus

ACC = "org.a11y.atspi.Accessible"
COMP = "org.a11y.atspi.Component"
TEXT = "org.a11y.atspi.Text"
PROPS = "org.freedesktop.DBus.Properties"
ROOT = ("org.a11y.atspi.Registry", "/org/a11y/atspi/accessible/root")
# AT-SPI state numbers (atspi-constants.h)
ST_CHECKED, ST_ENABLED, ST_FOCUSED, ST_SENSITIVE, ST_SHOWING, ST_VISIBLE = 4, 8, 12, 24, 25, 30


class GuiError(Exception):
    """A step of the GUI session failed; the message says which and why."""


def log(msg):
    print("gui: " + msg, flush=True)


def run(*cmd, check=True):
    r = subprocess.run(list(cmd), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if check and r.returncode != 0:
        raise GuiError("command failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr.strip()))
    return r.stdout.strip()


def wait_for(what, fn, timeout=30.0, step=0.2):
    """Calls fn() until it returns something truthy; raises GuiError after timeout s."""
    end = time.time() + timeout
    last_exc = None
    while True:
        try:
            v = fn()
            if v:
                return v
        except dbus.exceptions.DBusException as e:  # app busy or object gone: retry
            last_exc = e
        if time.time() > end:
            extra = (" (last D-Bus error: %s)" % str(last_exc).splitlines()[0]) if last_exc else ""
            raise GuiError("timed out after %.0f s waiting for %s%s" % (timeout, what, extra))
        time.sleep(step)


class Node:
    """One accessible object (bus name + object path)."""

    def __init__(self, a11y, bus_name, path):
        self.a, self.bus_name, self.path = a11y, str(bus_name), str(path)

    def __eq__(self, other):
        return isinstance(other, Node) and (self.bus_name, self.path) == (other.bus_name, other.path)

    def __hash__(self):
        return hash((self.bus_name, self.path))

    def _o(self):
        return self.a.bus.get_object(self.bus_name, self.path, introspect=False)

    @property
    def name(self):
        return str(self._o().Get(ACC, "Name", dbus_interface=PROPS))

    @property
    def role(self):
        return str(self._o().GetRoleName(dbus_interface=ACC))

    def children(self):
        return [Node(self.a, b, p) for b, p in self._o().GetChildren(dbus_interface=ACC)]

    def states(self):
        words = self._o().GetState(dbus_interface=ACC)
        return {i for i in range(64) if (int(words[i // 32]) >> (i % 32)) & 1}

    def extents(self):
        x, y, w, h = self._o().GetExtents(dbus.UInt32(0), dbus_interface=COMP)
        return int(x), int(y), int(w), int(h)

    def showing(self):
        x, y, w, h = self.extents()
        return w > 0 and h > 0 and ST_SHOWING in self.states()

    def enabled(self):
        s = self.states()
        return ST_ENABLED in s or ST_SENSITIVE in s

    def checked(self):
        return ST_CHECKED in self.states()

    def text(self):
        o = self._o()
        n = int(o.Get(TEXT, "CharacterCount", dbus_interface=PROPS))
        return str(o.GetText(0, n, dbus_interface=TEXT))

    def walk(self, max_depth=60, prune=None):
        """Depth-first generator of (node, depth). prune(node) -> True skips its subtree."""
        stack = [(self, 0)]
        while stack:
            n, d = stack.pop()
            yield n, d
            if d < max_depth and not (prune and prune(n)):
                stack.extend(reversed([(c, d + 1) for c in n.children()]))

    def find(self, role=None, name=None, showing=False, contains=False, max_depth=60, prune=None):
        """Descendants matching role/name. By default the (possibly huge) item lists of list
        and tree views (file dialogs) are not searched; pass prune=lambda n: False to."""
        if prune is None:
            prune = lambda n: n.role in ("list", "tree", "table", "tree table")
        out = []
        for n, _ in self.walk(max_depth, prune):
            try:
                if role is not None and n.role != role:
                    continue
                if name is not None:
                    nn = n.name
                    if (name not in nn) if contains else (nn != name):
                        continue
                if showing and not n.showing():
                    continue
            except dbus.exceptions.DBusException:
                continue
            out.append(n)
        return out

    def center(self):
        x, y, w, h = self.extents()
        return x + w // 2, y + h // 2

    def __repr__(self):
        try:
            return "<%s %r %s>" % (self.role, self.name, self.extents())
        except dbus.exceptions.DBusException:
            return "<gone %s>" % self.path


class A11y:
    """The AT-SPI bus of the current D-Bus session."""

    def __init__(self):
        sb = dbus.SessionBus()
        addr = sb.get_object("org.a11y.Bus", "/org/a11y/bus").GetAddress(dbus_interface="org.a11y.Bus")
        self.bus = dbus.bus.BusConnection(str(addr))
        self.root = Node(self, *ROOT)
        self.root.children()  # starts the registry daemon now, before the application

    def app(self, pid=None, timeout=60, need_frame=True):
        """The accessible application object of MeshLab (the one with a MeshLab frame), of
        process pid if given: from the registry, or straight from the connections of the bus."""
        dbus_daemon = self.bus.get_object("org.freedesktop.DBus", "/org/freedesktop/DBus")
        def look():
            cands = self.root.children()
            me = self.bus.get_unique_name()
            cands += [Node(self, n, ROOT[1]) for n in self.bus.list_names() if str(n).startswith(":") and n != me]
            for a in cands:
                try:
                    if pid is not None and int(dbus_daemon.GetConnectionUnixProcessID(
                            a.bus_name, dbus_interface="org.freedesktop.DBus")) != pid:
                        continue
                    if not need_frame or any(c.role == "frame" and c.name.startswith("MeshLab") for c in a.children()):
                        return a
                except dbus.exceptions.DBusException:
                    pass
            return None
        return wait_for("MeshLab on the accessibility bus", look, timeout)


class Gui:
    """Screenshots, clicks and key presses on a running MeshLab."""

    def __init__(self, app, out_dir, pid):
        self.app, self.out, self.pid = app, out_dir, pid
        self.shot_no = 0

    # --- X input ---------------------------------------------------------------------------
    def click(self, node, what=None):
        x, y = node.center()
        log("click %s at (%d,%d)" % (what or repr(node), x, y))
        run("xdotool", "mousemove", "--sync", str(x), str(y))
        time.sleep(0.15)
        run("xdotool", "click", "1")

    def click_at(self, x, y):
        run("xdotool", "mousemove", "--sync", str(x), str(y))
        time.sleep(0.15)
        run("xdotool", "click", "1")

    def key(self, *keys):
        run("xdotool", "key", "--delay", "80", *keys)

    def type(self, text):
        run("xdotool", "type", "--delay", "30", text)

    def shot(self, label):
        self.shot_no += 1
        path = os.path.join(self.out, "%02d_%s.png" % (self.shot_no, label))
        run("/usr/bin/import", "-window", "root", path)
        log("screenshot %s" % path)
        return path

    def alive(self):
        try:
            os.kill(self.pid, 0)
        except OSError:
            return False
        try:  # a zombie is not alive
            with open("/proc/%d/stat" % self.pid) as f:
                return f.read().split(") ")[-1][0] != "Z"
        except OSError:
            return False

    def check_alive(self, step):
        if not self.alive():
            raise GuiError("MeshLab exited unexpectedly during: %s" % step)

    # --- widgets ---------------------------------------------------------------------------
    def frames(self):
        """Top-level windows of MeshLab (main window, dialogs, floating docks)."""
        return [c for c in self.app.children() if c.role in ("frame", "dialog", "window", "alert", "alert message")]

    def main_frame(self):
        return wait_for("the MeshLab main window", lambda: next(
            (f for f in self.frames() if f.role == "frame" and f.name.startswith("MeshLab")), None), 30)

    def menubar_item(self, name):
        bars = self.main_frame().find(role="menu bar", max_depth=3)
        if not bars:
            raise GuiError("no menu bar in the MeshLab window")
        for it in bars[0].children():
            if it.name.replace("&", "") == name:
                return it
        raise GuiError("menu '%s' not found in the menu bar (menus: %s)" %
                       (name, ", ".join(c.name for c in bars[0].children())))

    @staticmethod
    def popup_of(item):
        kids = [c for c in item.children() if c.role == "popup menu"]
        return kids[0] if kids else None

    @staticmethod
    def entries(popup):
        return [c for c in popup.children() if c.role == "menu item" and c.name]

    def open_menu_path(self, path, shot_prefix="menu"):
        """Opens menu bar > submenu > ... and clicks the last entry. path: list of labels."""
        item = self.menubar_item(path[0])
        self.click(item, "menu '%s'" % path[0])
        for depth, label in enumerate(path[1:], 1):
            popup = wait_for("menu '%s' to open" % path[depth - 1],
                             lambda: (lambda p: p if p is not None and p.showing() else None)(self.popup_of(item)), 10)
            self.shot("%s_%d_%s" % (shot_prefix, depth, _slug(path[depth - 1])))
            matches = [e for e in self.entries(popup) if e.name.replace("&", "") == label]
            if not matches:
                names = [e.name for e in self.entries(popup)]
                raise GuiError("menu entry '%s' not found in '%s' (entries: %s)" %
                               (label, " > ".join(path[:depth]), "; ".join(names)))
            item = matches[0]
            if not item.enabled():
                raise GuiError("menu entry '%s' is disabled" % " > ".join(path[:depth + 1]))
            x, y = self.entry_center(popup, item)
            log("click menu entry '%s' at (%d,%d)" % (" > ".join(path[:depth + 1]), x, y))
            self.click_at(x, y)
        return item

    def entry_center(self, popup, item):
        """Screen centre of a menu entry inside an open popup.

        Qt caches one accessible object per QAction, so an action that MeshLab puts in two
        submenus (a filter of class Quality|Selection, say) reports the rectangle it has in
        whichever menu was first inspected. The entries of a QMenu are stacked in one column,
        so the entry's place is the popup's top plus the heights of the children before it;
        every entry that does report a rectangle inside this popup must agree with that
        layout, otherwise the layout is not understood and the step fails."""
        px, py, pw, ph = popup.extents()
        layout, off = [], 0
        for k in popup.children():
            h = k.extents()[3]
            layout.append((k, off, h))
            off += h
        def inside(k):
            x, y, w, h = k.extents()
            return w > 0 and h > 0 and ST_SHOWING in k.states() and px <= x and x + w <= px + pw and py <= y and y + h <= py + ph
        anchors = [(k, o) for k, o, h in layout if inside(k)]
        if not anchors:
            raise GuiError("menu popup %r shows no entry with a usable rectangle" % popup)
        base = anchors[0][0].extents()[1] - anchors[0][1]
        for k, o in anchors:
            if k.extents()[1] != base + o:
                raise GuiError("menu layout not understood: entry %r is not at y=%d" % (k, base + o))
        for k, o, h in layout:
            if k == item:
                y = base + o + h // 2
                if not (py <= y <= py + ph):
                    raise GuiError("menu entry %r lies outside its popup %r" % (item, popup))
                return px + min(pw, 300) // 2, y
        raise GuiError("entry %r is not a child of popup %r" % (item, popup))

    def locate_in_menu(self, top, label):
        """All submenu paths under menu bar entry `top` holding an entry named label."""
        found = []
        def rec(popup, prefix):
            for e in self.entries(popup):
                sub = self.popup_of(e)
                if sub is not None:
                    rec(sub, prefix + [e.name])
                elif e.name.replace("&", "") == label:
                    found.append(prefix + [label])
        rec(self.popup_of(self.menubar_item(top)), [top])
        return found

    def find_showing(self, role, name, within=None, contains=False):
        roots = [within] if within is not None else self.frames()
        for r in roots:
            m = r.find(role=role, name=name, showing=True, contains=contains)
            if m:
                return m[0]
        return None

    def wait_widget(self, role, name, what, timeout=20, within=None, contains=False):
        return wait_for(what, lambda: self.find_showing(role, name, within, contains), timeout)

    def new_frames(self, before):
        keys = {(f.bus_name, f.path) for f in before}
        return [f for f in self.frames() if (f.bus_name, f.path) not in keys]

    def log_text(self):
        """Text of MeshLab's log pane (the read-only text area holding 'Opened mesh')."""
        for f in self.frames():
            for t in f.find(role="text"):
                try:
                    s = t.text()
                except dbus.exceptions.DBusException:
                    continue
                if "Opened mesh" in s or "opened in" in s:
                    return s
        return ""


def _slug(s):
    return "".join(ch if ch.isalnum() else "_" for ch in s).strip("_")[:40]


def dump(depth=8):
    a = A11y()
    for app in a.root.children():
        print("APP", app.bus_name, app.name)
        for n, d in app.walk(depth):
            try:
                st = n.states()
                flags = "".join(c for c, s in (("S", ST_SHOWING), ("E", ST_ENABLED), ("C", ST_CHECKED),
                                               ("F", ST_FOCUSED)) if s in st)
                print("  " * d, n.role, repr(n.name), n.extents(), flags)
            except dbus.exceptions.DBusException as e:
                print("  " * d, "ERR", str(e).splitlines()[0])


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "dump":
        dump(int(sys.argv[2]) if len(sys.argv) > 2 else 8)
    else:
        print(__doc__)
