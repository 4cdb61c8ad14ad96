"""A small pymeshlab-like driver for the integration tests: writes .mlx filter scripts, runs
the staged meshlabserver under xvfb-run, reads the written PLY, and computes topology from the
face array alone (independently of the plugin) with numpy.

    out = run("bunny00.off", [Filter("Irregular Vertices: Analyze", select=Enum(1, SELECT), ...)])
    mesh = out.mesh            # numpy arrays: vertices, faces, props (quality, flags, red, ...)
"""
import os
import shutil
import struct
import subprocess
import tempfile
from xml.sax.saxutils import quoteattr

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("FI_SOURCE_DIR", os.path.abspath(os.path.join(HERE, "..", "..")))
STAGE = os.environ.get("FI_STAGE", os.path.join(SOURCE, "build", "stage"))
DATA = os.environ.get("FI_DATA_DIR", os.path.join(SOURCE, ".deps", "data", "meshes"))
EXAMPLES = os.path.join(SOURCE, "examples")
SELECTED, DELETED = 0x20, 0x1


# ---------------------------------------------------------------- scripts
class Enum:
    def __init__(self, value, names):
        self.value, self.names = value, names


class Filter:
    """A filter call; keyword parameters in declaration order (Python keeps keyword order).
    Types: bool -> RichBool, int -> RichInt, float -> RichFloat, str -> RichString,
    Enum -> RichEnum."""

    def __init__(self, name, **params):
        self.name, self.params = name, params

    def xml(self):
        lines = [" <filter name=%s>" % quoteattr(self.name)]
        for k, v in self.params.items():
            if isinstance(v, bool):
                p = 'type="RichBool" name=%s value="%s"' % (quoteattr(k), "true" if v else "false")
            elif isinstance(v, Enum):
                vals = " ".join("enum_val%d=%s" % (i, quoteattr(n)) for i, n in enumerate(v.names))
                p = 'type="RichEnum" name=%s value="%d" enum_cardinality="%d" %s' % (
                    quoteattr(k), v.value, len(v.names), vals)
            elif isinstance(v, int):
                p = 'type="RichInt" name=%s value="%d"' % (quoteattr(k), v)
            elif isinstance(v, float):
                p = 'type="RichFloat" name=%s value="%r"' % (quoteattr(k), v)
            else:
                p = 'type="RichString" name=%s value=%s' % (quoteattr(k), quoteattr(str(v)))
            lines.append("  <Param %s/>" % p)
        lines.append(" </filter>")
        return "\n".join(lines)


def write_script(filters, path):
    with open(path, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n")
        f.write("\n".join(flt.xml() for flt in filters))
        f.write("\n</FilterScript>\n")


def select_vertices(indices):
    """MeshLab's own Conditional Vertex Selection of the given vertex indices."""
    cond = " || ".join("(vi == %d)" % i for i in indices)
    return Filter("Conditional Vertex Selection", condSelect=cond)


# ---------------------------------------------------------------- running
class Run:
    def __init__(self, returncode, log, mesh_path):
        self.returncode, self.log, self.path = returncode, log, mesh_path
        self.mesh = read_ply(mesh_path) if returncode == 0 and os.path.exists(mesh_path) else None

    @property
    def ok(self):
        return self.returncode == 0


def run(input_mesh, filters_or_script, out_dir=None, mask=("vc", "vq", "vf"), timeout=600):
    """Runs the staged meshlabserver on input_mesh with a list of Filters or an .mlx path."""
    out_dir = out_dir or tempfile.mkdtemp(prefix="fi_")
    os.makedirs(out_dir, exist_ok=True)
    if not os.path.isabs(input_mesh):
        input_mesh = os.path.join(DATA, input_mesh)
    if isinstance(filters_or_script, str):
        script = filters_or_script
    else:
        script = os.path.join(out_dir, "script.mlx")
        write_script(filters_or_script, script)
    out = os.path.join(out_dir, "out.ply")
    if os.path.exists(out):
        os.remove(out)
    env = dict(os.environ, XDG_RUNTIME_DIR=tempfile.mkdtemp(prefix="xdg_"))
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", os.path.join(STAGE, "bin", "meshlabserver"),
           "-i", input_mesh, "-o", out, "-m"] + list(mask) + ["-s", script]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout, env=env)
    return Run(p.returncode, p.stdout.decode("utf-8", "replace"), out)


def have_meshlab():
    return os.path.exists(os.path.join(STAGE, "bin", "meshlabserver")) and shutil.which("xvfb-run")


# ---------------------------------------------------------------- mesh files
class Mesh:
    def __init__(self, vertices, faces, vprops=None):
        self.vertices = np.asarray(vertices, dtype=np.float64)
        self.faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
        self.props = vprops or {}

    def prop(self, name):
        return self.props[name]


_PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
              "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
              "float": "f", "float32": "f", "double": "d", "float64": "d"}


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt, elements = None, []
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append([t[1], int(t[2]), []])
        elif t[0] == "property":
            if t[1] == "list":
                elements[-1][2].append((t[4], "list", t[2], t[3]))
            else:
                elements[-1][2].append((t[2], t[1]))
    body = data[end:]
    verts, faces, vprops = None, [], {}
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    if p[1] == "list":
                        n = int(tokens[pos]); pos += 1
                        row.append([int(x) for x in tokens[pos:pos + n]]); pos += n
                    else:
                        row.append(float(tokens[pos])); pos += 1
                rows.append(row)
            if name == "vertex":
                for j, p in enumerate(props):
                    vprops[p[0]] = np.array([r[j] for r in rows])
            elif name == "face":
                li = [j for j, p in enumerate(props) if p[1] == "list"][0]
                faces = [r[li] for r in rows]
    else:
        assert fmt == "binary_little_endian", fmt
        pos = 0
        for name, count, props in elements:
            if all(p[1] != "list" for p in props):
                dt = np.dtype([(p[0], "<" + _PLY_TYPES[p[1]]) for p in props])
                arr = np.frombuffer(body, dtype=dt, count=count, offset=pos)
                pos += dt.itemsize * count
                if name == "vertex":
                    for p in props:
                        vprops[p[0]] = arr[p[0]].copy()
                continue
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    if p[1] == "list":
                        cnt_fmt, item_fmt = "<" + _PLY_TYPES[p[2]], _PLY_TYPES[p[3]]
                        n = struct.unpack_from(cnt_fmt, body, pos)[0]; pos += struct.calcsize(cnt_fmt)
                        row.append(list(struct.unpack_from("<%d%s" % (n, item_fmt), body, pos)))
                        pos += struct.calcsize("<%d%s" % (n, item_fmt))
                    else:
                        f = "<" + _PLY_TYPES[p[1]]
                        row.append(struct.unpack_from(f, body, pos)[0]); pos += struct.calcsize(f)
                rows.append(row)
            if name == "face":
                li = [j for j, p in enumerate(props) if p[1] == "list"][0]
                faces = [r[li] for r in rows]
    assert all(len(f) == 3 for f in faces), "not a triangle mesh"
    verts = np.stack([vprops["x"], vprops["y"], vprops["z"]], axis=1)
    return Mesh(verts, faces, vprops)


def read_off(path):
    if not os.path.isabs(path):
        path = os.path.join(DATA, path)
    tokens = [t for line in open(path) for t in line.split("#")[0].split()]
    assert tokens[0].endswith("OFF")
    nv, nf = int(tokens[1]), int(tokens[2])
    v = np.array(tokens[4:4 + 3 * nv], dtype=np.float64).reshape(-1, 3)
    pos, faces = 4 + 3 * nv, []
    for _ in range(nf):
        n = int(tokens[pos])
        faces.append([int(x) for x in tokens[pos + 1:pos + 1 + n]])
        pos += 1 + n
    return Mesh(v, [f for f in faces if len(f) == 3])


# ---------------------------------------------------------------- independent topology
def edges(mesh):
    f = mesh.faces
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    return np.sort(e, axis=1)


def valences(mesh):
    """Number of distinct edges at each vertex (unreferenced vertices: 0)."""
    u = np.unique(edges(mesh), axis=0)
    return np.bincount(u.ravel(), minlength=len(mesh.vertices))


def boundary_mask(mesh):
    e, counts = np.unique(edges(mesh), axis=0, return_counts=True)
    b = np.zeros(len(mesh.vertices), dtype=bool)
    b[e[counts == 1].ravel()] = True
    return b


def referenced_mask(mesh):
    r = np.zeros(len(mesh.vertices), dtype=bool)
    r[mesh.faces.ravel()] = True
    return r


def irregular_mask(mesh):
    val, b, ref = valences(mesh), boundary_mask(mesh), referenced_mask(mesh)
    return ref & (val != np.where(b, 4, 6))


def euler_characteristic(mesh):
    return int(referenced_mask(mesh).sum()) - len(np.unique(edges(mesh), axis=0)) + len(mesh.faces)


def gauss_bonnet_sum(mesh):
    val, b, ref = valences(mesh), boundary_mask(mesh), referenced_mask(mesh)
    return int((np.where(b, 4, 6) - val)[ref].sum())


def is_edge_manifold(mesh):
    _, counts = np.unique(edges(mesh), axis=0, return_counts=True)
    return bool((counts <= 2).all())


def is_consistently_oriented(mesh):
    """Every directed edge appears at most once (two faces on an edge run it opposite ways)."""
    f = mesh.faces
    d = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    return len(np.unique(d, axis=0)) == len(d)


def selected_mask(mesh):
    return (mesh.props["flags"].astype(np.int64) & SELECTED) != 0


def check_invariants(mesh):
    """The DEVELOPERS.md invariants, computed from the written file alone."""
    assert is_edge_manifold(mesh), "non-manifold edge"
    assert is_consistently_oriented(mesh), "inconsistent orientation"
    val = valences(mesh)
    ref = referenced_mask(mesh)
    assert (val[ref & ~boundary_mask(mesh)] >= 3).all(), "valence < 3"
    assert gauss_bonnet_sum(mesh) == 6 * euler_characteristic(mesh), "Gauss-Bonnet fails"
