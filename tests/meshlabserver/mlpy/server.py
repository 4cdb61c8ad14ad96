"""The staged meshlabserver (MeshLab 2020.09) driven from Python, for the smoke suite and the
scripts: filter scripts (.mlx) written from Python, runs under xvfb-run, the plugin's log lines
(its output values, 'Irregular Vertices: returned: key=value ...', and its refusals).

    Filter("Irregular Vertices: Analyze", select=Enum(1, ["None", "All irregular", "Only valence"]),
           valence=5, colorize=True)
    r = Server().run("bunny00.off", "out.ply", [select_vertices([98]), flt])   # or an .mlx path
    r.ok, r.returncode, r.mesh (read_ply of the output), r.returned (list of dicts), r.refusal

Debian's meshlabserver aborts on a script that leaves out a parameter of a filter, so every
parameter is listed, in the filter's declaration order (the keyword order)."""
import atexit
import os
import re
import shutil
import subprocess
import tempfile
from xml.sax.saxutils import quoteattr

import numpy as np

from .files import HERE, data_path, read_ply

__all__ = ["STAGE", "EXAMPLES", "SOURCE", "Param", "Enum", "AbsPerc", "Point3f", "Filter", "script_text",
           "write_script", "select_vertices", "find_stage", "meshlabserver_path", "have_meshlab", "Result",
           "Server", "run", "parse_returned"]


def _find_upward(start, rel):
    """First ancestor of start (start included) holding rel, else None."""
    d = start
    while True:
        if os.path.exists(os.path.join(d, rel)):
            return os.path.join(d, rel)
        parent = os.path.dirname(d)
        if parent == d:
            return None
        d = parent


def find_stage():
    """$FI_STAGE, else the first build/stage found going up from this file."""
    return os.environ.get("FI_STAGE") or _find_upward(HERE, os.path.join("build", "stage"))


SOURCE = os.environ.get("FI_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "..", "..", ".."))
STAGE = find_stage()
EXAMPLES = os.path.join(SOURCE, "examples")


# ------------------------------------------------------------------ filter scripts
class Param:
    """One <Param>: type (RichInt, RichEnum ...), name, value; extra: {"enum": [names]} for
    RichEnum, {"min": .., "max": ..} for RichAbsPerc. value: bool, int, float, str, or (x, y, z)
    for RichPoint3f."""

    def __init__(self, type, name, value, extra=None):
        self.type, self.name, self.value, self.extra = type, name, value, dict(extra or {})

    def attributes(self):
        """The attributes in writing order, as (name, string) pairs."""
        t, v, extra = self.type, self.value, dict(self.extra)
        attrs = [("type", t), ("name", self.name)]
        if t == "RichPoint3f":
            attrs += [(k, repr(float(c))) for k, c in zip("xyz", v)]
        else:
            attrs.append(("value", _format_value(v)))
        if t == "RichEnum":
            names = extra.pop("enum")
            attrs.append(("enum_cardinality", str(len(names))))
            attrs += [("enum_val%d" % i, n) for i, n in enumerate(names)]
        if t == "RichAbsPerc":
            attrs += [("min", _format_value(float(extra.pop("min")))), ("max", _format_value(float(extra.pop("max"))))]
        attrs += [(k, _format_value(x)) for k, x in extra.items()]
        return attrs

    def xml(self):
        return "<Param %s/>" % " ".join("%s=%s" % (k, quoteattr(s)) for k, s in self.attributes())


def _format_value(v):
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (float, np.floating)):
        return repr(float(v))  # shortest exact round trip
    return str(v)


class Enum:
    def __init__(self, value, names):
        self.value, self.names = int(value), list(names)


class AbsPerc:
    def __init__(self, value, min=0.0, max=1.0):
        self.value, self.min, self.max = float(value), min, max


class Point3f:
    def __init__(self, x, y, z):
        self.value = (x, y, z)


def _keyword_param(name, v):
    if isinstance(v, Param):
        return v
    if isinstance(v, Enum):
        return Param("RichEnum", name, v.value, {"enum": v.names})
    if isinstance(v, AbsPerc):
        return Param("RichAbsPerc", name, v.value, {"min": v.min, "max": v.max})
    if isinstance(v, Point3f):
        return Param("RichPoint3f", name, v.value)
    if isinstance(v, (bool, np.bool_)):  # before int: bool is an int subclass
        return Param("RichBool", name, bool(v))
    if isinstance(v, (int, np.integer)):
        return Param("RichInt", name, int(v))
    if isinstance(v, (float, np.floating)):
        return Param("RichFloat", name, float(v))
    return Param("RichString", name, str(v))


class Filter:
    """A filter call: keyword parameters, in writing order (bool, int, float, str, or the
    wrappers Enum, AbsPerc, Point3f, Param)."""

    def __init__(self, name, **kw):
        self.name = name
        self.params = [_keyword_param(k, v) for k, v in kw.items()]

    def xml(self):
        lines = [" <filter name=%s>" % quoteattr(self.name)]
        lines += ["  " + p.xml() for p in self.params]
        lines.append(" </filter>")
        return "\n".join(lines)


def script_text(filters):
    body = "\n".join(f.xml() for f in filters)
    return "<!DOCTYPE FilterScript>\n<FilterScript>\n%s\n</FilterScript>\n" % body


def write_script(filters, path):
    with open(path, "w") as f:
        f.write(script_text(filters))
    return path


def select_vertices(indices):
    """MeshLab's own 'Conditional Vertex Selection' of the given vertex indices (in 2020.09 its
    only parameter is condSelect; a script with more aborts meshlabserver)."""
    cond = " || ".join("(vi==%d)" % int(i) for i in indices) or "(vi < 0)"
    return Filter("Conditional Vertex Selection", condSelect=cond)


# ------------------------------------------------------------------ the plugin's log lines
_VALUE = re.compile(r"(\w+)=(\[[^\]]*\]|\S+)")


def parse_returned(line):
    """'key=value key=[a b] ...' (the plugin's 'Irregular Vertices: returned:' line) -> dict:
    int, float, bool, or numpy vector."""
    out = {}
    for key, text in _VALUE.findall(line):
        if text.startswith("["):
            out[key] = np.array([float(x) for x in text[1:-1].split()])
        elif text in ("true", "false"):
            out[key] = text == "true"
        elif re.fullmatch(r"-?\d+", text):
            out[key] = int(text)
        else:
            out[key] = float(text)
    return out


# ------------------------------------------------------------------ running meshlabserver
def meshlabserver_path(stage=None):
    stage = stage or STAGE
    return os.path.join(stage, "bin", "meshlabserver") if stage else None


def have_meshlab(stage=None):
    exe = meshlabserver_path(stage)
    return bool(exe and os.path.exists(exe) and shutil.which("xvfb-run"))


class Result:
    """returncode, stdout, stderr, output_path; mesh reads output_path on first use; returned:
    the plugin's output values, one dict per plugin filter run; refusal: the reason of a refusal."""

    def __init__(self, returncode, stdout, stderr, output_path, command=None):
        self.returncode, self.stdout, self.stderr = returncode, stdout, stderr
        self.output_path, self.command = output_path, command
        self._mesh = None

    @property
    def ok(self):
        return self.returncode == 0 and os.path.exists(self.output_path)

    @property
    def log(self):
        return self.stdout + self.stderr

    @property
    def returned(self):
        """meshlabserver prints the log twice (as it happens, 'LOG: <level> ...', and again at
        the end): the first copy, in order."""
        return [parse_returned(m) for m in re.findall(r"^LOG: \d+ Irregular Vertices: returned: (.*)$", self.log, re.M)]

    @property
    def refusal(self):
        m = re.search(r"Irregular Vertices: refused: (.*)$", self.log, re.M)
        return m.group(1) if m else None

    @property
    def mesh(self):
        if self._mesh is None:
            if not os.path.exists(self.output_path):
                raise RuntimeError("meshlabserver wrote no output (exit %d):\n%s" % (self.returncode, self.log))
            self._mesh = read_ply(self.output_path)
        return self._mesh

    def __repr__(self):
        return "Result(returncode=%d, output_path=%r)" % (self.returncode, self.output_path)


class Server:
    """The staged meshlabserver, run under xvfb-run (it needs an X display)."""

    def __init__(self, stage=None, timeout=600):
        self.stage = stage or STAGE
        self.timeout = timeout

    def run(self, input_mesh, output_ply=None, filters=(), mask=("vc", "vq", "vf"), ascii=False, timeout=None):
        """filters: a list of Filter, or the path of an .mlx script. output_ply None: a fresh
        temporary file. Returns a Result; a refusing filter gives exit code 255 and no output."""
        exe = meshlabserver_path(self.stage)
        if not exe or not os.path.exists(exe):
            raise RuntimeError("no staged meshlabserver (set FI_STAGE or build build/stage)")
        work = tempfile.mkdtemp(prefix="mlpy_")
        # The Result's output_path lives here and callers read it after run() returns: the
        # folder goes when the process ends, not before (hundreds of runs must not pile up in /tmp).
        atexit.register(shutil.rmtree, work, True)
        output_ply = os.path.abspath(output_ply or os.path.join(work, "out.ply"))
        if isinstance(filters, (str, os.PathLike)):
            script = str(filters)
        else:
            script = write_script(list(filters), os.path.join(work, "script.mlx"))
        if os.path.exists(output_ply):  # a stale file would hide a refusal
            os.remove(output_ply)
        mask = list(mask) + (["sa"] if ascii and "sa" not in mask else [])
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", exe, "-i", data_path(input_mesh),
               "-o", output_ply, "-m"] + mask + ["-s", script]
        # A private runtime dir keeps Qt from warning about a missing or shared one.
        env = dict(os.environ, XDG_RUNTIME_DIR=tempfile.mkdtemp(prefix="mlpy_xdg_"))
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                           timeout=timeout or self.timeout)
        shutil.rmtree(env["XDG_RUNTIME_DIR"], ignore_errors=True)
        return Result(p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace"),
                      output_ply, cmd)


def run(input_mesh, output_ply=None, filters=(), **kw):
    """Server().run(...) with the default stage."""
    return Server().run(input_mesh, output_ply, filters, **kw)
