"""Integration: bad input through every filter. Each is refused with a message naming the
problem (and the MeshLab filter that fixes it), meshlabserver exits 255, nothing is written;
valid but unusual input (boundaries, several components) is handled."""
import os

import numpy as np
import pytest

from mlpy import (AbsPerc, Enum, Filter, Mesh, Param, Point3f, check_invariants, read_off, read_ply, run,
                  select_vertices, write_ply)

LEAD = ["Lower valence", "Higher valence", "Lower index", "Higher index"]
OPS = ["5-7 pair move", "v5/v7 move with 5-7 pair generation",
       "v5/v7 move with 5-7 pair removal (triple cancellation)", "5-5-7-7 generation by flip",
       "5-5-7-7 generation by split", "5-5-7-7 removal", "Edge flip", "Edge collapse", "Vertex split"]


def all_filters():
    return {
        "analyze": Filter("Irregular Vertices: Analyze", select=Enum(1, ["None", "All irregular", "Only valence"]),
                          valence=5, colorize=True),
        "atomic": Filter("Irregular Vertices: Atomic Operation", operation=Enum(3, OPS), direction=0, relax=True,
                         colorize=True),
        "relax": Filter("Irregular Vertices: Relax", mode=Enum(0, ["Local", "Global"]), iterations=2,
                        region=Enum(0, ["All", "Selection", "Around irregular vertices"]), reproject=True,
                        featureAngle=60.0),
        "reduce": Filter("Irregular Vertices: Reduce to Valence 5 and 7",
                         scope=Enum(0, ["All irregular vertices", "Selected vertices"]), relax=True, colorize=True),
        "aggregate": Filter("Irregular Vertices: Aggregate", relax=True, colorize=True),
        "move": Filter("Irregular Vertices: Move Pair", lead=Enum(0, LEAD), direction=0, steps=1, towardPoint=False,
                       point=Point3f(0.0, 0.0, 0.0), relax=True, colorize=True),
        "triple": Filter("Irregular Vertices: Cancel Triple", relax=True, colorize=True),
        "quadruple": Filter("Irregular Vertices: Cancel Quadruple", relax=True, colorize=True),
        "generate": Filter("Irregular Vertices: Generate",
                           kind=Enum(1, ["Triple from a v5 or v7", "Quadruple from a regular vertex"]),
                           direction=0, spacing=1, relax=True, colorize=True),
        "automatic": Filter("Irregular Vertices: Automatic Reduction", remeshEdgeLength=AbsPerc(0.0), targetCount=0,
                            hausdorffBudget=0.5, minAngle=30.0, maxTravel=12,
                            protect=Enum(0, ["Nothing", "Selected region untouched", "Selected irregular vertices kept"]),
                            relaxation=Enum(0, ["Local", "Global"]), timeLimit=0.0, colorize=True),
    }


def write_off(path, verts, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%r %r %r\n" % tuple(map(float, v)))
        for t in faces:
            f.write("%d %s\n" % (len(t), " ".join(map(str, t))))


def octahedron():
    v = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    f = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return v, f


def bad_meshes(tmp_path):
    out = {}
    v, f = octahedron()
    # a third face on edge (0, 2)
    out["non-manifold edge"] = (v + [(0.5, 0.5, 0.5)], f + [(0, 2, 6)], "Repair non Manifold Edges")
    # two octahedra sharing vertex 0
    v2 = v + [(2 + x, y, z) for (x, y, z) in v[1:]]
    f2 = f + [tuple(0 if i == 0 else i + 5 for i in t) for t in f]
    out["non-manifold vertex"] = (v2, f2, "Repair non Manifold Vertices")
    out["polygons"] = ([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
                       [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
                       "Turn into a Pure-Triangular mesh")
    # vertex 6 duplicates vertex 0; face (6, 2, 4) uses the copy
    f3 = [(6, 2, 4) if t == (0, 2, 4) else t for t in f]
    out["duplicated vertices"] = (v + [v[0]], f3, "Remove Duplicate Vertices")
    out["unreferenced vertices"] = (v + [(5, 5, 5)], f, "Remove Unreferenced Vertices")
    out["zero-area face"] = (v + [(0.5, 0.5, 0)], f + [(0, 2, 6)], None)  # also non-manifold: any refusal
    paths = {}
    for name, (vv, ff, fix) in out.items():
        p = str(tmp_path / (name.replace(" ", "_") + ".off"))
        write_off(p, vv, ff)
        paths[name] = (p, fix)
    return paths


@pytest.mark.parametrize("filter_key", list(all_filters().keys()))
def test_bad_input_is_refused_by_every_filter(tmp_path, filter_key):
    flt = all_filters()[filter_key]
    for name, (path, fix) in bad_meshes(tmp_path).items():
        r = run(path, filters=[select_vertices([0]), flt])
        assert r.returncode == 255, (name, r.log[-2000:])
        assert "Irregular Vertices: refused" in r.log, (name, r.log[-2000:])
        if fix:
            assert fix in r.log, (name, fix)
        assert not os.path.exists(r.output_path)


@pytest.mark.parametrize("filter_key", ["atomic", "move", "triple", "quadruple", "generate", "aggregate"])
def test_empty_selection_is_refused(corpus, filter_key):
    r = run(corpus("knot1.off"), filters=[Filter("Conditional Vertex Selection", condSelect="(vi < 0)"),
                                  all_filters()[filter_key]])
    assert r.returncode == 255
    assert "Irregular Vertices: refused" in r.log


def test_boundary_vertex_is_refused(corpus):
    # vertex 0 of mesh_with_border lies on the border
    r = run(corpus("mesh_with_border.off"), filters=[select_vertices([0]), all_filters()["generate"]])
    assert r.returncode == 255
    assert "boundary" in r.log


@pytest.mark.parametrize("name", ["head.off", "blobby_3cc.off", "mesh_with_border.off"])
def test_boundaries_and_components_are_handled(corpus, name):
    for key in ["analyze", "relax", "reduce"]:
        r = run(corpus(name), filters=[all_filters()[key]])
        if key == "reduce" and r.returncode == 255:
            assert "nothing to reduce" in r.log or "no interior vertex" in r.log.lower() or "No vertex" in r.log
            continue
        assert r.ok, (key, r.log[-1500:])
        check_invariants(r.mesh)


def test_real_defective_models_do_not_crash(corpus):
    for name in ["elephant-with-holes.off", "tetra_intersected_by_triangle.off", "polygon_mesh.off", "degtri_sliding.off",
                 "quads_to_stitch.off"]:
        try:
            path = corpus(name)
        except BaseException:
            continue
        for key in ["analyze", "relax", "reduce"]:
            r = run(path, filters=[all_filters()[key]])
            assert r.returncode in (0, 255), (name, key, r.returncode, r.log[-1500:])
            if r.returncode == 255:
                assert "Irregular Vertices: refused" in r.log
            else:
                check_invariants(r.mesh)


def _painted_copy(src, path, seed=5):
    """The corpus mesh as a PLY with the user's own vertex colours and quality."""
    m = read_off(src)
    rng = np.random.default_rng(seed)
    rgb = rng.integers(0, 256, size=(len(m.vertices), 3)).astype(np.uint8)
    props = {"red": rgb[:, 0], "green": rgb[:, 1], "blue": rgb[:, 2], "alpha": np.full(len(m.vertices), 255, np.uint8),
             "quality": rng.random(len(m.vertices)).astype(np.float32)}
    write_ply(Mesh(m.vertices, m.faces), path, vertex_props=props)
    return read_ply(path)


def _kept_attributes(before, after):
    """(vertices of `after` found unmoved in `before`, how many of them kept colour and quality)."""
    index = {tuple(p): i for i, p in enumerate(before.vertices.astype(np.float32))}
    found = kept = 0
    for j, p in enumerate(after.vertices.astype(np.float32)):
        i = index.get(tuple(p))
        if i is None:
            continue
        found += 1
        kept += all(before.prop(c)[i] == after.prop(c)[j] for c in ("red", "green", "blue", "quality"))
    return found, kept


@pytest.mark.parametrize("key", ["move", "automatic"])
def test_user_colours_and_quality_survive_where_no_edit_reaches(corpus, tmp_path, key):
    """With 'Colour by valence' off, every vertex an edit did not move keeps the colour and the
    quality the user gave it (new vertices take those of the vertex they were split from)."""
    before = _painted_copy(corpus("knot1.off"), str(tmp_path / "painted.ply"))
    flt = all_filters()[key]
    flt.params[-1] = Param("RichBool", "colorize", False)
    if key == "move":  # a long move, so that many vertices are edited
        pre = [select_vertices([47, 3186])]
        flt.params[2] = Param("RichInt", "steps", 20)
    else:  # the final relaxation moves every free vertex: protect half of the mesh
        pre = [Filter("Conditional Vertex Selection", condSelect="(x < 0)")]
        flt.params[5] = Param("RichEnum", "protect", 1, {"enum": ["Nothing", "Selected region untouched",
                                                                  "Selected irregular vertices kept"]})
    r = run(str(tmp_path / "painted.ply"), filters=pre + [flt], mask=("vc", "vq", "vf"))
    assert r.ok, r.log[-2000:]
    check_invariants(r.mesh)
    found, kept = _kept_attributes(before, r.mesh)
    assert found > 0.3 * len(before.vertices), found  # most of the mesh is untouched
    assert kept == found, (kept, found)
    assert found < len(r.mesh.vertices)  # and some vertices were edited
