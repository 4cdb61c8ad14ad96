"""Self-checks of the mlpy driver alone (no MeshLab): file reading and writing, the independent
topology measures, script XML, and the PNG renderer."""
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mlpy import (DATA, AbsPerc, Color, DynamicFloat, Enum, Filter, Mesh, Param, Point3f,  # noqa: E402
                  boundary_loop_count, boundary_vertex_mask, component_count, deleted_mask,
                  euler_characteristic, gauss_bonnet_sum, genus, irregular_mask, is_consistently_oriented,
                  is_edge_manifold, read_mesh, read_off, read_ply, select_vertices, selected_mask,
                  valences, write_ply, write_script)
from mlpy import meshlab  # noqa: E402
from mlpy.render import draw_legend, draw_title, rasterize, render, write_png  # noqa: E402


def corpus(name):
    path = os.path.join(DATA, name)
    if not os.path.exists(path):
        pytest.skip("corpus mesh %s missing (run scripts/setup.sh)" % name)
    return path


def icosahedron():
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return Mesh(v, f)


def grid(n, jitter=0.0, seed=0):
    """(n+1) x (n+1) vertices on [0, n]^2 in the z = 0 plane, each square split by a diagonal."""
    ys, xs = np.mgrid[0:n + 1, 0:n + 1]
    v = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1).astype(float)
    if jitter:  # move interior vertices only, so the outline stays the square
        inner = (v[:, 0] > 0) & (v[:, 0] < n) & (v[:, 1] > 0) & (v[:, 1] < n)
        v[inner, :2] += np.random.default_rng(seed).uniform(-jitter, jitter, (inner.sum(), 2))
    i = (ys[:-1, :-1] * (n + 1) + xs[:-1, :-1]).ravel()
    f = np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])
    return Mesh(v, f)


# ------------------------------------------------------------------ topology
def test_bunny_off():
    m = read_off(corpus("bunny00.off"))
    assert m.vertices.shape == (37706, 3) and m.faces.shape == (75408, 3)
    assert m.is_triangle_mesh and m.polygons == []
    assert is_edge_manifold(m) and is_consistently_oriented(m)
    assert euler_characteristic(m) == 2
    assert gauss_bonnet_sum(m) == 6 * euler_characteristic(m) == 12
    assert boundary_loop_count(m) == 0 and component_count(m) == 1 and genus(m) == 0
    assert valences(m).sum() == 2 * len(meshlab.unique_edges(m)[0])


@pytest.mark.parametrize("name,g", [("knot1.off", 1), ("elephant.off", 3)])
def test_genus_of_corpus_meshes(name, g):
    m = read_off(corpus(name))
    assert boundary_loop_count(m) == 0
    assert genus(m) == g
    assert gauss_bonnet_sum(m) == 6 * euler_characteristic(m) == 6 * (2 - 2 * g)


def test_mesh_with_border():
    m = read_off(corpus("mesh_with_border.off"))
    assert boundary_vertex_mask(m).any() and boundary_loop_count(m) >= 1
    assert gauss_bonnet_sum(m) == 6 * euler_characteristic(m)


def test_icosahedron():
    m = icosahedron()
    assert (valences(m) == 5).all() and irregular_mask(m).all()
    assert euler_characteristic(m) == 2 and gauss_bonnet_sum(m) == 12 and genus(m) == 0
    assert is_edge_manifold(m) and is_consistently_oriented(m)


def test_grid_patch():
    m = grid(4)
    val, bnd = valences(m), boundary_vertex_mask(m)
    assert bnd.sum() == 16 and boundary_loop_count(m) == 1
    assert euler_characteristic(m) == 1 and gauss_bonnet_sum(m) == 6 and genus(m) == 0
    assert (val[~bnd] == 6).all()
    # Only the corners are irregular: valence 2 or 3 on the boundary (4 is regular there).
    corners = [0, 4, 20, 24]
    assert sorted(np.nonzero(irregular_mask(m))[0]) == corners
    assert sorted(val[corners]) == [2, 2, 3, 3]


def test_unreferenced_vertex_and_components():
    m = icosahedron()
    two = Mesh(np.vstack([m.vertices, m.vertices + 10, [[0, 0, 0]]]), np.vstack([m.faces, m.faces + 12]))
    assert valences(two)[-1] == 0 and not irregular_mask(two)[-1]
    assert euler_characteristic(two) == 4 and component_count(two) == 2
    with pytest.raises(ValueError):
        genus(two)


def test_non_manifold_edge():
    m = Mesh(np.eye(3).tolist() + [[1, 1, 1], [0, 0, 0]], [(0, 1, 2), (1, 0, 3), (0, 1, 4)])
    assert not is_edge_manifold(m)


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
    tuples = Filter("Irregular Vertices: Analyze", [
        ("RichEnum", "select", 1, {"enum": names}), ("RichInt", "valence", 5), ("RichBool", "colorize", True),
        ("RichFloat", "f", 0.1), ("RichString", "s", 'a<"b"> & c'),
        ("RichAbsPerc", "ap", 0.01, {"min": 0, "max": 1}), ("RichDynamicFloat", "df", 0.3, {"min": 0, "max": 1}),
        ("RichColor", "col", (40, 200, 40)), ("RichPoint3f", "pt", (0, 0, 1))])
    keywords = Filter("Irregular Vertices: Analyze", select=Enum(1, names), valence=5, colorize=True, f=0.1,
                      s='a<"b"> & c', ap=AbsPerc(0.01, 0, 1), df=DynamicFloat(0.3, 0, 1), col=Color(40, 200, 40),
                      pt=Point3f(0, 0, 1))
    assert tuples.xml() == keywords.xml()
    path = write_script([tuples, select_vertices([3, 12])], str(tmp_path / "s.mlx"))
    assert open(path).read().startswith("<!DOCTYPE FilterScript>\n<FilterScript>")
    root = ET.parse(path).getroot()
    assert root.tag == "FilterScript"
    first, second = root.findall("filter")
    assert first.get("name") == "Irregular Vertices: Analyze"
    p = {e.get("name"): e.attrib for e in first.findall("Param")}
    assert [e.get("name") for e in first.findall("Param")] == ["select", "valence", "colorize", "f", "s", "ap",
                                                               "df", "col", "pt"]
    assert p["select"] == {"type": "RichEnum", "name": "select", "value": "1", "enum_cardinality": "3",
                           "enum_val0": "None", "enum_val1": "All irregular", "enum_val2": "Only valence"}
    assert p["valence"]["type"] == "RichInt" and p["valence"]["value"] == "5"
    assert p["colorize"]["type"] == "RichBool" and p["colorize"]["value"] == "true"
    assert p["f"]["type"] == "RichFloat" and float(p["f"]["value"]) == 0.1
    assert p["s"]["type"] == "RichString" and p["s"]["value"] == 'a<"b"> & c'
    assert (p["ap"]["type"], float(p["ap"]["value"]), float(p["ap"]["min"]), float(p["ap"]["max"])) == \
        ("RichAbsPerc", 0.01, 0, 1)
    assert (p["df"]["type"], float(p["df"]["value"]), float(p["df"]["min"]), float(p["df"]["max"])) == \
        ("RichDynamicFloat", 0.3, 0, 1)
    assert [p["col"][k] for k in "rgba"] == ["40", "200", "40", "255"] and "value" not in p["col"]
    assert [float(p["pt"][k]) for k in "xyz"] == [0, 0, 1] and p["pt"]["type"] == "RichPoint3f"
    assert second.get("name") == "Conditional Vertex Selection"
    sp = {e.get("name"): e.attrib for e in second.findall("Param")}
    assert sp["condSelect"]["value"] == "(vi==3) || (vi==12)" and sp["condSelect"]["type"] == "RichString"
    assert set(sp) == {"condSelect"}  # the 2020.09 filter has no other parameter
    assert Param("RichBool", "b", False).xml() == '<Param type="RichBool" name="b" value="false"/>'


def test_stage_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("FI_STAGE", str(tmp_path))
    assert meshlab.find_stage() == str(tmp_path)
    assert meshlab.meshlabserver_path(str(tmp_path)) == str(tmp_path / "bin" / "meshlabserver")
    assert not meshlab.have_meshlab(str(tmp_path))
    with pytest.raises(RuntimeError):
        meshlab.Server(stage=str(tmp_path)).run("bunny00.off", str(tmp_path / "o.ply"), [])


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
