"""Self-checks of mlpy alone (no MeshLab): PLY/OFF reading and writing, filter-script XML,
the plugin's returned-values line, the stage lookup, and the PNG renderer that
scripts/render_png.py uses."""
import os
import struct
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest

import fi_oracle as fo
import mlpy
from mlpy import (AbsPerc, Enum, Filter, Mesh, Param, Point3f, deleted_mask, parse_returned, read_mesh, read_off,
                  read_ply, select_vertices, selected_mask, write_ply, write_script)
from mlpy.render import draw_legend, draw_title, rasterize, render, write_png


def icosahedron():
    return Mesh(fo.icosahedron().vertices, fo.icosahedron().faces)


def grid(n, jitter=0.0, seed=0):
    g = fo.grid(n, jitter, seed)
    return Mesh(g.vertices, g.faces)


# ------------------------------------------------------------------ files
def sample_mesh():
    m = icosahedron()
    n = len(m.vertices)
    m.vertex_props = {
        "flags": np.array([0x20 if i % 3 == 0 else (0x1 if i == 1 else 0) for i in range(n)], np.int32),
        "red": np.arange(n, dtype=np.uint8) * 20, "green": np.full(n, 7, np.uint8),
        "blue": np.full(n, 255, np.uint8), "quality": np.linspace(-1, 2, n).astype(np.float32)}
    m.face_props = {"flags": np.arange(len(m.faces), dtype=np.int32)}
    return m


@pytest.mark.parametrize("binary", [True, False])
def test_ply_round_trip(tmp_path, binary):
    m = sample_mesh()
    path = write_ply(m, str(tmp_path / "m.ply"), binary=binary)
    r = read_ply(path)
    assert np.allclose(r.vertices, m.vertices, atol=1e-6) and np.array_equal(r.faces, m.faces)
    for k, a in m.vertex_props.items():
        assert r.vertex_props[k].dtype == a.dtype and np.array_equal(r.vertex_props[k], a), k
    assert np.array_equal(r.face_props["flags"], m.face_props["flags"])
    assert np.array_equal(np.nonzero(selected_mask(r))[0], np.arange(0, 12, 3))
    assert np.array_equal(np.nonzero(deleted_mask(r))[0], [1])
    assert r.props is r.vertex_props and r.prop("quality").dtype == np.float32


def test_ply_binary_generic_layout(tmp_path):
    """Face properties around the list, another count type, an extra element, variable lists."""
    head = ("ply\nformat binary_little_endian 1.0\ncomment written by hand\n"
            "element vertex 4\nproperty double x\nproperty double y\nproperty double z\nproperty uint16 id\n"
            "element face 2\nproperty int8 tag\nproperty list uint8 uint32 vertex_indices\nproperty float w\n"
            "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n")
    body = b"".join(struct.pack("<dddH", x, y, 0.5, 100 + i) for i, (x, y) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]))
    body += struct.pack("<bB3If", -1, 3, 0, 1, 2, 0.25) + struct.pack("<bB3If", 2, 3, 0, 2, 3, 0.5)
    body += struct.pack("<ii", 0, 2)
    (tmp_path / "g.ply").write_bytes(head.encode() + body)
    r = read_ply(str(tmp_path / "g.ply"))
    assert r.faces.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert r.vertex_props["id"].tolist() == [100, 101, 102, 103] and r.vertices[2].tolist() == [1, 1, 0.5]
    assert r.face_props["tag"].tolist() == [-1, 2] and r.face_props["w"].tolist() == [0.25, 0.5]
    # A quad makes the fast path fail; the row-by-row path must then report it.
    quad = head.replace("element face 2", "element face 1")
    body4 = body[:4 * 26] + struct.pack("<bB4If", 0, 4, 0, 1, 2, 3, 1.0) + struct.pack("<ii", 0, 2)
    (tmp_path / "q.ply").write_bytes(quad.encode() + body4)
    with pytest.raises(ValueError, match="not a triangle"):
        read_ply(str(tmp_path / "q.ply"))


def test_ply_ascii_polygon_raises(tmp_path):
    text = ("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n3 0 1 2\n4 0 1 2 3\n")
    (tmp_path / "p.ply").write_text(text)
    with pytest.raises(ValueError, match="not a triangle"):
        read_ply(str(tmp_path / "p.ply"))


def test_off_comments_colours_polygons(tmp_path):
    text = ("# a comment first\nCOFF\n# counts next\n5 3 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
            "1 1 0 0 0 255 255\n0 1 0 9 9 9 255\n2 2 2 1 1 1 255\n"
            "3 0 1 2 200 10 10\n4 0 1 2 3\n3 2 3 4  # trailing comment\n")
    (tmp_path / "c.off").write_text(text)
    m = read_mesh(str(tmp_path / "c.off"))
    assert m.vertices.shape == (5, 3) and m.vertices[4].tolist() == [2, 2, 2]
    assert m.faces.tolist() == [[0, 1, 2], [2, 3, 4]]
    assert m.polygons == [[0, 1, 2, 3]] and not m.is_triangle_mesh
    (tmp_path / "h.off").write_text("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")  # counts on the header line
    assert read_off(str(tmp_path / "h.off")).faces.tolist() == [[0, 1, 2]]


# ------------------------------------------------------------------ scripts
def test_xml_every_param_type(tmp_path):
    names = ["None", "All irregular", "Only valence"]
    flt = Filter("Irregular Vertices: Analyze", select=Enum(1, names), valence=5, colorize=True, f=0.1,
                 s='a<"b"> & c', ap=AbsPerc(0.01, 0, 1), pt=Point3f(0, 0, 1))
    path = write_script([flt, select_vertices([3, 12])], str(tmp_path / "s.mlx"))
    assert open(path).read().startswith("<!DOCTYPE FilterScript>\n<FilterScript>")
    root = ET.parse(path).getroot()
    assert root.tag == "FilterScript"
    first, second = root.findall("filter")
    assert first.get("name") == "Irregular Vertices: Analyze"
    p = {e.get("name"): e.attrib for e in first.findall("Param")}
    assert [e.get("name") for e in first.findall("Param")] == ["select", "valence", "colorize", "f", "s", "ap", "pt"]
    assert p["select"] == {"type": "RichEnum", "name": "select", "value": "1", "enum_cardinality": "3",
                           "enum_val0": "None", "enum_val1": "All irregular", "enum_val2": "Only valence"}
    assert p["valence"]["type"] == "RichInt" and p["valence"]["value"] == "5"
    assert p["colorize"]["type"] == "RichBool" and p["colorize"]["value"] == "true"
    assert p["f"]["type"] == "RichFloat" and float(p["f"]["value"]) == 0.1
    assert p["s"]["type"] == "RichString" and p["s"]["value"] == 'a<"b"> & c'
    assert (p["ap"]["type"], float(p["ap"]["value"]), float(p["ap"]["min"]), float(p["ap"]["max"])) == \
        ("RichAbsPerc", 0.01, 0, 1)
    assert [float(p["pt"][k]) for k in "xyz"] == [0, 0, 1] and p["pt"]["type"] == "RichPoint3f"
    assert second.get("name") == "Conditional Vertex Selection"
    sp = {e.get("name"): e.attrib for e in second.findall("Param")}
    assert sp["condSelect"]["value"] == "(vi==3) || (vi==12)" and sp["condSelect"]["type"] == "RichString"
    assert set(sp) == {"condSelect"}  # the 2020.09 filter has no other parameter
    assert Param("RichBool", "b", False).xml() == '<Param type="RichBool" name="b" value="false"/>'


def test_every_example_script_parses(tmp_path):
    """The examples are valid XML whose filters list their parameters (meshlabserver aborts on
    a missing one)."""
    for path in sorted(p for p in os.listdir(mlpy.EXAMPLES) if p.endswith(".mlx")):  # not the .py examples
        root = ET.parse(os.path.join(mlpy.EXAMPLES, path)).getroot()
        assert root.tag == "FilterScript" and root.findall("filter"), path
        for f in root.findall("filter"):
            assert f.findall("Param"), (path, f.get("name"))


def test_parse_returned():
    v = parse_returned("vertices=3200 irregular_percent=10.5 valence_histogram=[0 0 5 2864] "
                       "gauss_bonnet_holds=true remeshed=false x=-3 y=1e-05")
    assert v["vertices"] == 3200 and isinstance(v["vertices"], int)
    assert v["irregular_percent"] == 10.5 and v["gauss_bonnet_holds"] is True and v["remeshed"] is False
    assert v["valence_histogram"].tolist() == [0, 0, 5, 2864] and v["x"] == -3 and v["y"] == 1e-05
    log = ("LOG: 2 Irregular Vertices: returned: a=1\nLOG: 2 other\nLOG: 2 Irregular Vertices: returned: a=2\n"
           "Irregular Vertices: returned: a=1\nIrregular Vertices: returned: a=2\n")
    r = mlpy.Result(0, log, "LOG: 4 Irregular Vertices: refused: no.\n", "/nonexistent.ply")
    assert [x["a"] for x in r.returned] == [1, 2] and r.refusal == "no." and not r.ok


def test_stage_from_environment(monkeypatch, tmp_path):
    from mlpy import server
    monkeypatch.setenv("FI_STAGE", str(tmp_path))
    assert server.find_stage() == str(tmp_path)
    assert server.meshlabserver_path(str(tmp_path)) == str(tmp_path / "bin" / "meshlabserver")
    assert not server.have_meshlab(str(tmp_path))
    with pytest.raises(RuntimeError):
        server.Server(stage=str(tmp_path)).run("bunny00.off", str(tmp_path / "o.ply"), [])


def test_scripts_names():
    """What scripts/ import from mlpy (render_png.py, demo.sh, bench_reduction.py) is there,
    with paths accepted where they were."""
    for name in ["DATA", "AbsPerc", "Enum", "Filter", "diagonal", "edge_length_for", "euler_characteristic",
                 "hausdorff", "irregular_mask", "read_mesh", "run", "shape_measures", "valences"]:
        assert hasattr(mlpy, name), name
    m = mlpy.read_mesh(os.path.join(mlpy.DATA, "knot1.off"))
    assert mlpy.diagonal("knot1.off") == pytest.approx(fo.diagonal(m))
    assert max(mlpy.hausdorff("knot1.off", m)) < 1e-12


# ------------------------------------------------------------------ rendering
def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, {}
    while pos < len(data):
        n, tag = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        assert struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0] == zlib.crc32(tag + body) & 0xFFFFFFFF
        chunks[tag] = chunks.get(tag, b"") + body
        pos += 12 + n
    w, h, depth, ctype = struct.unpack(">IIBB", chunks[b"IHDR"][:10])
    assert (depth, ctype) == (8, 2)
    rows = np.frombuffer(zlib.decompress(chunks[b"IDAT"]), np.uint8).reshape(h, 1 + 3 * w)
    assert (rows[:, 0] == 0).all()
    return rows[:, 1:].reshape(h, w, 3)


def test_png_round_trip(tmp_path):
    img = np.random.default_rng(1).integers(0, 256, (7, 5, 3)).astype(np.uint8)
    write_png(str(tmp_path / "a.png"), img)
    assert np.array_equal(read_png(str(tmp_path / "a.png")), img)


def test_rasterizer_has_no_cracks():
    """A jittered grid covering the square [8, 56]^2 covers every pixel centre inside it once."""
    m = grid(12, jitter=0.3)
    p = np.column_stack([m.vertices[:, :2] * 4 + 8, np.zeros(len(m.vertices))])
    face_of, bary = rasterize(p, m.faces, 64, 64)
    img = face_of.reshape(64, 64)
    assert (img[8:56, 8:56] >= 0).all()
    assert (img[:8] < 0).all() and (img[56:] < 0).all() and (img[:, :8] < 0).all() and (img[:, 56:] < 0).all()
    assert np.allclose(bary[face_of >= 0].sum(1), 1)


def test_rasterizer_nearest_wins():
    # Two overlapping triangles: the one with the larger z is in front wherever both cover.
    p = np.array([[0, 0, 0], [32, 0, 0], [0, 32, 0], [0, 0, 1], [32, 0, 1], [0, 32, 1]], float)
    face_of, _ = rasterize(p, np.array([[0, 1, 2], [3, 4, 5]]), 32, 32)
    assert set(face_of[face_of >= 0].tolist()) == {1}
    face_of, _ = rasterize(p, np.array([[3, 4, 5], [0, 1, 2]]), 32, 32)
    assert set(face_of[face_of >= 0].tolist()) == {0}


def test_render_colours(tmp_path):
    m = icosahedron()
    m.vertex_props = {"red": np.full(12, 40, np.uint8), "green": np.full(12, 80, np.uint8),
                      "blue": np.full(12, 230, np.uint8)}
    img = render(m, (120, 100), view=(0, 0, 1))
    draw_title(img, "ICO 5")
    draw_legend(img)
    path = str(tmp_path / "ico.png")
    write_png(path, img)
    back = read_png(path)
    assert back.shape == (100, 120, 3)
    centre = back[50, 60].astype(int)
    assert centre[2] > centre[0] and centre[2] > centre[1]  # shaded blue in the middle


def _render_png_script():
    """scripts/render_png.py as a module (it is a script, not a package)."""
    import importlib.util
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "render_png.py")
    spec = importlib.util.spec_from_file_location("render_png", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_render_png_crop_keeps_the_faces_near_the_point_with_their_colours(tmp_path):
    rp = _render_png_script()
    g = grid(4)  # unit squares on [0, 4]^2, two triangles each
    red = (g.vertices[:, 0] * 10 + g.vertices[:, 1]).astype(np.uint8)  # a colour that names the vertex
    g.vertex_props = {"red": red, "green": red, "blue": red}
    near = rp.crop(g, (2.0, 2.0, 0.0), 1.0)
    # the centroids within 1 of (2, 2): both triangles of the four squares around it, 8 faces on
    # the 3 x 3 vertices of [1, 3]^2
    assert len(near.faces) == 8 and len(near.vertices) == 9
    assert near.vertices[:, :2].min() == 1 and near.vertices[:, :2].max() == 3
    assert (near.props["red"] == (near.vertices[:, 0] * 10 + near.vertices[:, 1]).astype(np.uint8)).all()
    # every face keeps its own corners: the same triangles as the input's, renumbered
    want = {tuple(sorted(map(tuple, g.vertices[f]))) for f in g.faces
            if np.linalg.norm(g.vertices[f].mean(axis=0) - (2, 2, 0)) < 1}
    assert {tuple(sorted(map(tuple, near.vertices[f]))) for f in near.faces} == want
    src = str(tmp_path / "grid.ply")
    write_ply(g, src, vertex_props=g.vertex_props)
    out = str(tmp_path / "close.png")
    rp.main([src, out, "--size", "60x50", "--crop", "2,2,0,1", "--view", "0,0,1"])
    assert read_png(out).shape == (50, 60, 3)
    with pytest.raises(SystemExit) as e:  # nothing that close: an error, no picture
        rp.main([src, str(tmp_path / "none.png"), "--crop", "9,9,9,0.5"])
    assert e.value.code == 2 and not os.path.exists(str(tmp_path / "none.png"))
