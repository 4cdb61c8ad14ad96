"""PLY and OFF files for the meshlabserver smoke suite and the scripts: ``Mesh`` (numpy
arrays: vertices, faces, per-vertex and per-face properties), ``read_ply`` (ASCII and binary,
any property layout), ``write_ply``, ``read_off`` (OFF/COFF/NOFF, polygons kept apart),
``read_mesh``; ``SELECTED``/``DELETED`` vertex flag bits and ``selected_mask`` as
meshlabserver writes them with ``-m vf``."""
import os

import numpy as np

__all__ = ["Mesh", "read_ply", "write_ply", "read_off", "read_mesh", "selected_mask", "deleted_mask",
           "SELECTED", "DELETED", "DATA", "data_path"]

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("FI_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DATA = os.environ.get("FI_DATA_DIR", os.path.join(SOURCE, ".deps", "data", "meshes"))
SELECTED, DELETED = 0x20, 0x1


def data_path(name):
    """A corpus mesh path (names without a folder are looked up in DATA)."""
    return name if os.path.isabs(name) or os.path.exists(name) else os.path.join(DATA, name)


class Mesh:
    """vertices (n,3) float64, faces (m,3) int64 (triangles), vertex_props / face_props: name ->
    array; polygons: faces that are not triangles (OFF input only; then is_triangle_mesh False)."""

    def __init__(self, vertices, faces, vertex_props=None, face_props=None, polygons=None):
        self.vertices = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
        self.faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
        self.vertex_props = dict(vertex_props or {})
        self.face_props = dict(face_props or {})
        self.polygons = list(polygons or [])
        self.is_triangle_mesh = not self.polygons

    props = property(lambda self: self.vertex_props)  # short alias

    def prop(self, name):
        return self.vertex_props[name]

    def __repr__(self):
        return "Mesh(%d vertices, %d faces)" % (len(self.vertices), len(self.faces))


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}
_NUMPY_TO_PLY = {"i1": "char", "u1": "uchar", "i2": "short", "u2": "ushort", "i4": "int",
                 "u4": "uint", "f4": "float", "f8": "double"}


def _parse_header(data):
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    lines = data[:end].decode("ascii", "replace").splitlines()
    if not lines or lines[0].strip() != "ply":
        raise ValueError("not a PLY file")
    fmt, elements = None, []
    for line in lines[1:]:
        t = line.split()
        if not t or t[0] in ("comment", "obj_info"):
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t[0] == "property" and t[1] == "list":  # (name, count type, item type)
            elements[-1][2].append((t[4], _PLY_TYPES[t[2]], _PLY_TYPES[t[3]]))
        elif t[0] == "property":  # (name, type, None)
            elements[-1][2].append((t[2], _PLY_TYPES[t[1]], None))
    return fmt, elements, end


def _read_element_binary(body, pos, count, props, bo):
    """Returns ({name: array or list of lists}, new pos). Fast path: every list holds 3 items."""
    fields = []
    for name, t, item in props:
        if item is None:
            fields.append((name, bo + t))
        else:
            fields += [(name + "#n", bo + t), (name, bo + item, (3,))]
    dt = np.dtype(fields)
    if pos + dt.itemsize * count <= len(body):
        arr = np.frombuffer(body, dtype=dt, count=count, offset=pos)
        # The first row whose count is not 3 sits where expected, so this check is exact.
        if all((arr[n + "#n"] == 3).all() for n, _, item in props if item is not None):
            return {n: arr[n].copy() for n, _, _ in props}, pos + dt.itemsize * count
    cols = {n: [] for n, _, _ in props}  # slow path: row by row
    for _ in range(count):
        for name, t, item in props:
            if item is None:
                cols[name].append(np.frombuffer(body, bo + t, 1, pos)[0])
                pos += np.dtype(t).itemsize
            else:
                n = int(np.frombuffer(body, bo + t, 1, pos)[0])
                pos += np.dtype(t).itemsize
                cols[name].append(np.frombuffer(body, bo + item, n, pos).tolist())
                pos += n * np.dtype(item).itemsize
    return {n: (c if item is not None else np.array(c, dtype=t))
            for (n, t, item), c in zip(props, cols.values())}, pos


def _read_element_ascii(tokens, pos, count, props):
    width = sum(1 if item is None else 4 for _, _, item in props)
    block = tokens[pos:pos + width * count]
    if len(block) == width * count:
        try:
            arr = np.array(block, dtype=np.float64).reshape(count, width)
        except ValueError:
            arr = None
        if arr is not None:
            out, c, fast = {}, 0, True
            for name, t, item in props:
                if item is None:
                    out[name] = arr[:, c].astype(t); c += 1
                else:
                    fast &= bool((arr[:, c] == 3).all())
                    out[name] = arr[:, c + 1:c + 4].astype(item); c += 4
            if fast:
                return out, pos + width * count
    cols = {n: [] for n, _, _ in props}  # slow path
    for _ in range(count):
        for name, t, item in props:
            if item is None:
                cols[name].append(float(tokens[pos])); pos += 1
            else:
                n = int(tokens[pos])
                cols[name].append([int(x) for x in tokens[pos + 1:pos + 1 + n]]); pos += 1 + n
    return {n: (c if item is not None else np.array(c).astype(t))
            for (n, t, item), c in zip(props, cols.values())}, pos


def read_ply(path):
    """ASCII or binary PLY triangle mesh. Raises ValueError on a face that is not a triangle."""
    with open(path, "rb") as f:
        data = f.read()
    fmt, elements, end = _parse_header(data)
    body = data[end:]
    tokens = body.split() if fmt == "ascii" else None
    bo = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    if fmt != "ascii" and bo is None:
        raise ValueError("unknown PLY format %r" % fmt)
    pos, read = 0, {}
    for name, count, props in elements:
        if fmt == "ascii":
            read[name], pos = _read_element_ascii(tokens, pos, count, props)
        else:
            read[name], pos = _read_element_binary(body, pos, count, props, bo)
    vprops = read.get("vertex", {})
    vertices = np.stack([vprops["x"], vprops["y"], vprops["z"]], axis=1).astype(np.float64)
    faces, fprops = np.zeros((0, 3), np.int64), {}
    if "face" in read:
        fdesc = dict((n, item) for n, _, item in next(e[2] for e in elements if e[0] == "face"))
        lists = [n for n, item in fdesc.items() if item is not None]
        key = "vertex_indices" if "vertex_indices" in lists else "vertex_index" if "vertex_index" in lists else lists[0]
        f = read["face"][key]
        if isinstance(f, list):
            bad = [i for i, x in enumerate(f) if len(x) != 3]
            if bad:
                raise ValueError("%s: face %d has %d vertices, not a triangle" % (path, bad[0], len(f[bad[0]])))
        faces = np.asarray(f, dtype=np.int64).reshape(-1, 3)
        fprops = {n: v for n, v in read["face"].items() if n != key}
    return Mesh(vertices, faces, vprops, fprops)


def write_ply(mesh, path, binary=True, vertex_props=None, face_props=None):
    """Writes x y z, then vertex_props (default: all of mesh.vertex_props but x, y, z) and
    triangles as 'list uchar int vertex_indices' followed by face_props (default: all)."""
    vp = mesh.vertex_props if vertex_props is None else vertex_props
    fp = mesh.face_props if face_props is None else face_props
    vcols = [("x", mesh.vertices[:, 0]), ("y", mesh.vertices[:, 1]), ("z", mesh.vertices[:, 2])]
    vcols = [(n, np.asarray(a, dtype=np.float32)) for n, a in vcols]
    vcols += [(n, np.asarray(a)) for n, a in vp.items() if n not in ("x", "y", "z")]
    fcols = [("vertex_indices#n", np.full(len(mesh.faces), 3, np.uint8)),
             ("vertex_indices", np.asarray(mesh.faces, dtype=np.int32))]
    fcols += [(n, np.asarray(a)) for n, a in fp.items()]

    def ply_type(a):
        return _NUMPY_TO_PLY[a.dtype.str[1:]] if a.dtype.str[1:] in _NUMPY_TO_PLY else "double"

    def fix(a):  # unsupported dtypes (int64, bool ...) are written as int or double
        k = a.dtype.str[1:]
        return a if k in _NUMPY_TO_PLY else a.astype(np.int32 if a.dtype.kind in "iub" else np.float64)

    vcols = [(n, fix(a)) for n, a in vcols]
    fcols = fcols[:2] + [(n, fix(a)) for n, a in fcols[2:]]
    head = ["ply", "format %s 1.0" % ("binary_little_endian" if binary else "ascii"),
            "element vertex %d" % len(mesh.vertices)]
    head += ["property %s %s" % (ply_type(a), n) for n, a in vcols]
    head += ["element face %d" % len(mesh.faces), "property list uchar int vertex_indices"]
    head += ["property %s %s" % (ply_type(a), n) for n, a in fcols[2:]]
    head.append("end_header")
    with open(path, "wb") as f:
        f.write(("\n".join(head) + "\n").encode("ascii"))
        for cols, count in ((vcols, len(mesh.vertices)), (fcols, len(mesh.faces))):
            if binary:
                dt = np.dtype([(n, "<" + a.dtype.str[1:], a.shape[1:]) for n, a in cols])
                rec = np.empty(count, dtype=dt)
                for n, a in cols:
                    rec[n] = a
                f.write(rec.tobytes())
            else:
                parts = [a.reshape(count, -1) for _, a in cols]
                for row in zip(*parts):
                    f.write((" ".join(_ascii(x) for p in row for x in p) + "\n").encode("ascii"))
    return path


def _ascii(x):
    return repr(float(x)) if isinstance(x, np.floating) else str(int(x))


def read_off(path):
    """OFF / COFF / NOFF: optional '#' comments, header, counts, vertices (extra values ignored),
    faces 'n i j k ...' (values after the n indices, e.g. colours, ignored). Faces with more than
    3 vertices go to mesh.polygons (and mesh.is_triangle_mesh is False)."""
    with open(data_path(path)) as f:
        lines = [s for s in (line.split("#")[0].split() for line in f) if s]
    if not lines or not lines[0][0].endswith("OFF"):
        raise ValueError("%s: not an OFF file" % path)
    head = lines[0][1:] or lines[1]  # counts may follow the header on its line
    body = 1 if lines[0][1:] else 2
    nv, nf = int(head[0]), int(head[1])
    vertices = np.array([row[:3] for row in lines[body:body + nv]], dtype=np.float64).reshape(-1, 3)
    tris, polygons = [], []
    for row in lines[body + nv:body + nv + nf]:
        n = int(row[0])
        idx = [int(x) for x in row[1:1 + n]]
        (tris if n == 3 else polygons).append(idx)
    return Mesh(vertices, np.array(tris, dtype=np.int64).reshape(-1, 3), polygons=polygons)


def read_mesh(path):
    """read_ply for .ply, read_off otherwise."""
    return read_ply(path) if path.lower().endswith(".ply") else read_off(path)


def _flags(mesh):
    if "flags" not in mesh.vertex_props:
        raise KeyError("no vertex flags in the mesh (save with -m vf)")
    return mesh.vertex_props["flags"].astype(np.int64)


def selected_mask(mesh):
    return (_flags(mesh) & SELECTED) != 0


def deleted_mask(mesh):
    return (_flags(mesh) & DELETED) != 0
