"""Integration: 'Irregular Vertices: Analyze' through the staged meshlabserver on corpus meshes,
checked against counts computed here from the written faces alone."""
import os
import re

import numpy as np
import pytest

from mlpy import (EXAMPLES, Enum, Filter, boundary_mask, check_invariants, euler_characteristic,
                      irregular_mask, read_off, referenced_mask, run, selected_mask, valences)

SELECT = ["None", "All irregular", "Only valence"]
LEGEND = {3: (150, 40, 190), 4: (0, 175, 200), 5: (40, 80, 230), 6: (200, 200, 200),
          7: (245, 140, 20), 8: (215, 30, 30), 9: (110, 0, 20)}


def legend(eq):
    return LEGEND[min(max(eq, 3), 9)]


def analyze(select=1, valence=5, colorize=True):
    return Filter("Irregular Vertices: Analyze", select=Enum(select, SELECT), valence=valence, colorize=colorize)


@pytest.mark.parametrize("name,genus,loops", [("bunny00.off", 0, 0), ("elephant.off", 3, 0),
                                              ("knot1.off", 1, 0), ("mesh_with_border.off", None, None)])
def test_example_script_colours_quality_selection(corpus, name, genus, loops):
    r = run(corpus(name), filters=os.path.join(EXAMPLES, "analyze.mlx"))
    assert r.ok, r.log
    m = r.mesh
    val = valences(m)
    ref = referenced_mask(m)
    bnd = boundary_mask(m)
    # vertex quality holds the valence
    assert np.array_equal(m.prop("quality")[ref].astype(int), val[ref])
    # colours follow the legend of the equivalent valence (boundary: valence + 2)
    eq = np.where(bnd, val + 2, val)
    rgb = np.stack([m.prop("red"), m.prop("green"), m.prop("blue")], axis=1)
    expected = np.array([legend(int(e)) for e in eq])
    assert np.array_equal(rgb[ref], expected[ref])
    # selection = irregular vertices
    assert np.array_equal(selected_mask(m), irregular_mask(m))
    # the log reports the same numbers
    chi = euler_characteristic(m)
    n_irr = int(irregular_mask(m).sum())
    assert "Irregular vertices: %d of %d" % (n_irr, int(ref.sum())) in r.log
    assert re.search(r"Euler characteristic %d, genus" % chi, r.log)
    if genus is not None:
        assert "genus %d, boundary loops %d" % (genus, loops) in r.log
    assert "holds" in r.log
    check_invariants(m)
    # the filter does not change the mesh
    src = read_off(corpus(name))
    assert np.allclose(m.vertices, src.vertices, atol=1e-5)
    assert np.array_equal(m.faces, src.faces)


def test_bunny_numbers(corpus):
    r = run(corpus("bunny00.off"), filters=[analyze()])
    assert r.ok, r.log
    assert "Irregular vertices: 19715 of 37706" in r.log
    assert "v4:1080 v5:8951 v6:17991 v7:8340 v8:1276 v9:65 v10:3" in r.log


def test_select_only_valence(corpus):
    r = run(corpus("knot1.off"), filters=[analyze(select=2, valence=7)])
    assert r.ok, r.log
    val = valences(r.mesh)
    assert np.array_equal(selected_mask(r.mesh), val == 7)


def test_boundary_vertices_are_regular_at_valence_four(corpus):
    r = run(corpus("mesh_with_border.off"), filters=[analyze()])
    assert r.ok, r.log
    m = r.mesh
    bnd = boundary_mask(m)
    sel = selected_mask(m)
    assert not sel[bnd & (valences(m) == 4)].any()


def write_off(path, verts, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%g %g %g\n" % tuple(v))
        for t in faces:
            f.write("%d %s\n" % (len(t), " ".join(map(str, t))))


def test_refuses_non_manifold_edge(tmp_path):
    # three triangles sharing the edge (0, 1)
    p = str(tmp_path / "nm.off")
    write_off(p, [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1)], [(0, 1, 2), (1, 0, 3), (0, 1, 4)])
    r = run(p, filters=[analyze()])
    assert r.returncode == 255
    assert "Repair non Manifold Edges" in r.log
    assert not os.path.exists(r.output_path)


def test_refuses_polygonal_mesh(tmp_path):
    p = str(tmp_path / "quad.off")
    write_off(p, [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
              [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)])
    r = run(p, filters=[analyze()])
    assert r.returncode == 255, r.log
    assert "Turn into a Pure-Triangular mesh" in r.log
