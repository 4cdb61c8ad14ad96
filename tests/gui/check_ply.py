#!/usr/bin/python3
"""Checks a PLY that MeshLab's GUI exported after "Irregular Vertices: Analyze".

    check_ply.py [--mode irregular|basic] [--vertices N] [--irregular N] mesh.ply

irregular (default): the vertex count is N; the file has vertex colour (red, green, blue) and
  vertex quality; the valence of every vertex, computed here from the faces of the file, equals
  its quality; every colour follows the plugin's legend (README, "Colour legend") for its
  equivalent valence (valence, +2 on a boundary): <=3 purple 150,40,190; 4 cyan 0,175,200;
  5 blue 40,80,230; 6 grey 200,200,200; 7 orange 245,140,20; 8 red 215,30,30;
  >=9 dark red 110,0,20; the number of irregular vertices (equivalent valence != 6) is N.
basic: only the vertex count and that a filter wrote varying colour and quality (used to
  develop the GUI automation with one of MeshLab's own filters).
Pure standard library (runs with /usr/bin/python3). Exit 0 when every check holds.
"""
import argparse
import collections
import struct
import sys

LEGEND = {3: (150, 40, 190), 4: (0, 175, 200), 5: (40, 80, 230), 6: (200, 200, 200),
          7: (245, 140, 20), 8: (215, 30, 30), 9: (110, 0, 20)}
TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
         "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
         "float": "f", "float32": "f", "double": "d", "float64": "d"}


def legend(equiv):
    return LEGEND[min(max(equiv, 3), 9)]


def read_ply(path):
    """Returns (vertex property names, list of vertex tuples, list of faces)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ValueError("not a PLY file")
    body = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt, elements = None, []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append([w[1], int(w[2]), []])
        elif w[0] == "property":
            if w[1] == "list":
                elements[-1][2].append((w[4], "list", TYPES[w[2]], TYPES[w[3]]))
            else:
                elements[-1][2].append((w[2], TYPES[w[1]]))
    if fmt not in ("ascii", "binary_little_endian"):
        raise ValueError("unsupported PLY format %s" % fmt)
    out = {}
    if fmt == "ascii":
        tokens = data[body:].split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    if p[1] == "list":
                        n = int(tokens[pos]); pos += 1
                        row.append(tuple(int(t) for t in tokens[pos:pos + n])); pos += n
                    else:
                        t = tokens[pos]; pos += 1
                        row.append(float(t) if p[1] in "fd" else int(t))
                rows.append(tuple(row))
            out[name] = (props, rows)
    else:
        pos = body
        for name, count, props in elements:
            rows = []
            if all(p[1] != "list" for p in props):
                st = struct.Struct("<" + "".join(p[1] for p in props))
                rows = list(st.iter_unpack(data[pos:pos + st.size * count]))
                pos += st.size * count
            else:
                for _ in range(count):
                    row = []
                    for p in props:
                        if p[1] == "list":
                            cs = struct.calcsize(p[2]); n = struct.unpack_from("<" + p[2], data, pos)[0]; pos += cs
                            isz = struct.calcsize(p[3])
                            row.append(struct.unpack_from("<%d%s" % (n, p[3]), data, pos)); pos += isz * n
                        else:
                            row.append(struct.unpack_from("<" + p[1], data, pos)[0]); pos += struct.calcsize(p[1])
                    rows.append(tuple(row))
            out[name] = (props, rows)
    vprops, verts = out.get("vertex", ([], []))
    fprops, frows = out.get("face", ([], []))
    fi = next((i for i, p in enumerate(fprops) if p[0] in ("vertex_indices", "vertex_index")), None)
    faces = [r[fi] for r in frows] if fi is not None else []
    return [p[0] for p in vprops], verts, faces


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ply")
    ap.add_argument("--mode", choices=("irregular", "basic"), default="irregular")
    ap.add_argument("--vertices", type=int, default=37706)
    ap.add_argument("--irregular", type=int, default=19715)
    a = ap.parse_args()
    fails = []
    try:
        names, verts, faces = read_ply(a.ply)
    except (OSError, ValueError, KeyError, struct.error) as e:
        print("check_ply: FAIL cannot read %s: %s" % (a.ply, e))
        return 1
    print("check_ply: %s: %d vertices, %d faces, vertex properties %s" % (a.ply, len(verts), len(faces), " ".join(names)))
    if len(verts) != a.vertices:
        fails.append("vertex count %d, expected %d" % (len(verts), a.vertices))
    missing = [p for p in ("red", "green", "blue", "quality") if p not in names]
    if missing:
        fails.append("missing vertex properties: %s (colour and quality must be exported)" % ", ".join(missing))
    if not missing:
        ir, ig, ib, iq = (names.index(p) for p in ("red", "green", "blue", "quality"))
        col = [(v[ir], v[ig], v[ib]) for v in verts]
        qual = [v[iq] for v in verts]
        if a.mode == "basic":
            if len(set(col)) < 2:
                fails.append("all vertices have the same colour %s: the filter painted nothing" % (col[0],))
            if len(set(qual)) < 2:
                fails.append("all vertices have the same quality: the filter wrote none")
        else:
            edge_faces = collections.Counter()
            for f in faces:
                if len(f) != 3:
                    fails.append("face %s is not a triangle" % (f,)); break
                for i in range(3):
                    u, w = f[i], f[(i + 1) % 3]
                    edge_faces[(u, w) if u < w else (w, u)] += 1
            valence = [0] * len(verts)
            boundary = [False] * len(verts)
            for (u, w), n in edge_faces.items():
                valence[u] += 1; valence[w] += 1
                if n == 1:
                    boundary[u] = boundary[w] = True
            bad_q = [i for i in range(len(verts)) if abs(qual[i] - valence[i]) > 1e-4]
            if bad_q:
                i = bad_q[0]
                fails.append("quality != valence on %d vertices (e.g. vertex %d: quality %g, valence %d)" % (len(bad_q), i, qual[i], valence[i]))
            equiv = [valence[i] + (2 if boundary[i] else 0) for i in range(len(verts))]
            bad_c = [i for i in range(len(verts)) if col[i] != legend(equiv[i])]
            if bad_c:
                i = bad_c[0]
                fails.append("colour off the legend on %d vertices (e.g. vertex %d: valence %d%s, colour %s, legend %s)" %
                             (len(bad_c), i, valence[i], " boundary" if boundary[i] else "", col[i], legend(equiv[i])))
            by = collections.Counter((equiv[i], boundary[i], col[i]) for i in range(len(verts)))
            for e, label in ((6, "v6 grey"), (5, "v5 blue"), (7, "v7 orange")):
                n_ok = by.get((e, False, legend(e)), 0)
                n_all = sum(n for (ee, b, c), n in by.items() if ee == e and not b)
                print("check_ply: interior %s %s: %d of %d vertices" % (label, legend(e), n_ok, n_all))
                if n_all == 0 and a.vertices == 37706:
                    fails.append("no interior vertex of valence %d" % e)
            hist = collections.Counter(valence)
            print("check_ply: valence histogram %s, boundary vertices %d" %
                  (" ".join("v%d:%d" % kv for kv in sorted(hist.items())), sum(boundary)))
            irregular = sum(1 for e in equiv if e != 6)
            print("check_ply: irregular vertices %d of %d" % (irregular, len(verts)))
            if irregular != a.irregular:
                fails.append("irregular vertices %d, expected %d" % (irregular, a.irregular))
    for f in fails:
        print("check_ply: FAIL " + f)
    if not fails:
        print("check_ply: OK (%s)" % a.mode)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
