"""'Irregular Vertices: Pattern' with panels through pymeshlab: the panels appear as a new layer
of the MeshSet (FilterContext::NewLayer in the 2025.07 adapter), closed manifold shells with the
counts known for the mesh; the current mesh stays the patterned one; and the recipe of
examples/pattern_circles.py (generate, then pattern) closes circles that a regular torus lacks."""
import importlib.util
import os

import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import EXAMPLES, apply, load, refuse, tri

PATTERN = "compute_color_irregular_pattern"


def layer_measures(ms, mesh_id):
    """pymeshlab's own topological measures of layer mesh_id (the current mesh is restored)."""
    current = ms.current_mesh_id()
    ms.set_current_mesh(mesh_id)
    t = ms.get_topological_measures()
    ms.set_current_mesh(current)
    return t


def icosphere():
    """The corpus's geosphere: an icosahedron subdivided twice, 12 v5 four edges apart, 320 faces."""
    ms = load("geosphere.off")
    assert ms.current_mesh().face_number() == 320
    return ms


def test_star_panels_are_a_new_layer_of_closed_shells():
    ms = icosphere()
    source = ms.current_mesh_id()
    faces = ms.current_mesh().face_matrix().copy()
    out = apply(ms, PATTERN, pattern="Stars", starradius=3, panels=True)
    # radius 3: every v5 is isolated (the next is 4 edges away); the two stars of each of the
    # 30 icosahedron edges meet on the fan of its middle vertex
    assert out["star_seeds"] == 12 and out["isolated_star_seeds"] == 12
    assert out["conflict_regions"] == 30 and out["conflict_faces"] == 180
    assert ms.mesh_number() == 2, "the panels are one new layer"
    assert ms.current_mesh_id() == source, "the patterned mesh stays current"
    assert np.array_equal(ms.current_mesh().face_matrix(), faces), "the pattern does not edit connectivity"
    layer = [i for i in range(4) if ms.mesh_id_exists(i) and i != source][0]
    # 12 stars, 30 conflicts, one background (in 20 pieces, one per icosahedron face)
    assert out["panels"] == 43
    # sides (corners of the outline, region_outline.h): each conflict is the fan of a v6 (6),
    # each star loses those fans at its arms' tips (10), the background's outline has 60
    h = np.asarray(out["panel_sides_histogram"], dtype=np.int64)
    assert h.sum() == 43 and h[6] == 30 and h[10] == 12 and h[60] == 1
    t = layer_measures(ms, layer)
    assert t["boundary_edges"] == 0 and t["non_two_manifold_edges"] == 0 and t["non_two_manifold_vertices"] == 0
    assert t["connected_components_number"] == 12 + 30 + 20
    ms.set_current_mesh(layer)
    panel = ms.current_mesh()
    # top and bottom of each region's faces, two wall triangles per outline edge
    assert panel.face_number() == 1360
    assert panel.has_face_color()
    assert panel.bounding_box().diagonal() > 0, "the layer's bounding box is updated"
    # every shell is closed and consistently oriented: its signed volume is positive
    assert ms.get_geometric_measures()["mesh_volume"] > 0


def test_no_panels_no_layer():
    ms = icosphere()
    apply(ms, PATTERN, pattern="Stars", starradius=3, panels=False)
    assert ms.mesh_number() == 1


def isolated_v5(m, radius):
    """Independent count (the numpy oracle's valences and boundary rule): interior v5 with no
    other irregular vertex within `radius` edges, by breadth-first search on the edge graph."""
    e, _ = fo.unique_edges(m)
    adj = [[] for _ in range(len(m.vertices))]
    for a, b in e:
        adj[a].append(b)
        adj[b].append(a)
    val, irr, bnd = fo.valences(m), fo.irregular_mask(m), fo.boundary_vertex_mask(m)
    seeds = np.nonzero((val == 5) & ~bnd & fo.referenced_mask(m))[0]
    isolated = 0
    for s in seeds:
        seen, frontier, alone = {int(s)}, [int(s)], True
        for _ in range(radius):
            nxt = []
            for v in frontier:
                for w in adj[v]:
                    if w not in seen:
                        seen.add(w)
                        nxt.append(w)
                        alone = alone and not irr[w]
            frontier = nxt
        isolated += alone
    return len(seeds), isolated


@pytest.mark.parametrize("name", ["camel.off", "holes.off", "dino.off"])
def test_star_seeds_and_isolation_match_an_independent_count(name):
    ms = load(name)
    m = tri(ms)
    for radius in (2, 3):
        out = apply(ms, PATTERN, pattern="Stars", starradius=radius, panels=False)
        assert (out["star_seeds"], out["isolated_star_seeds"]) == isolated_v5(m, radius), radius
        # one region id per face in face quality, dense
        region = np.rint(ms.current_mesh().face_scalar_array()).astype(np.int64)
        assert np.array_equal(np.unique(region), np.arange(out["regions"]))


def test_refused_pattern_adds_no_layer():
    """A regular torus has no v5 to seed stars: refused before any panel, the MeshSet unchanged
    (no new layer)."""
    ex = load_example()
    ms = pymeshlab.MeshSet()
    v, f = ex.regular_torus(12, 12)
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    refuse(ms, PATTERN, "no interior v5", pattern="Stars", starradius=3, panels=True)
    assert ms.mesh_number() == 1


def load_example():
    spec = importlib.util.spec_from_file_location("pattern_circles", os.path.join(EXAMPLES, "pattern_circles.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_circles_recipe_generate_then_pattern():
    ex = load_example()
    ms = pymeshlab.MeshSet()
    v, f = ex.regular_torus()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    source = ms.current_mesh_id()
    before, after = ex.run(ms, [10 * 40 + 10, 30 * 40 + 30])
    assert before == 0, "a regular torus has no circle"
    # two quadruples, each two 5-7 pairs 8 steps apart: rings 2 and 4 close around each pair
    # (as in test_circle_pattern.cpp)
    assert after["circles"] == 8
    assert ms.mesh_number() == 2 and ms.current_mesh_id() == source
    layer = [i for i in range(4) if ms.mesh_id_exists(i) and i != source][0]
    assert after["panels"] == after["circles"] + 1, "one panel per circle, and the background"
    t = layer_measures(ms, layer)
    assert t["boundary_edges"] == 0 and t["non_two_manifold_edges"] == 0
    # more generated, spaced irregular vertices: more circles
    ms2 = pymeshlab.MeshSet()
    ms2.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    _, after4 = ex.run(ms2, [10 * 40 + 10, 10 * 40 + 30, 30 * 40 + 10, 30 * 40 + 30])
    assert after4["circles"] == 16


def test_circle_ring_width():
    """ringWidth groups rings into bands: around each 5-7 pair of the recipe's two quadruples,
    width 1 closes rings 2 and 4 (22 and 46 faces), width 2 closes the band of rings 3-4 (80
    faces), which holds ring 4's faces exactly."""
    ex = load_example()
    ms = pymeshlab.MeshSet()
    v, f = ex.regular_torus()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
    ex.run(ms, [10 * 40 + 10, 30 * 40 + 30])
    sizes, members = {}, {}
    for width in (1, 2):
        out = apply(ms, PATTERN, pattern="Circles", ringwidth=width)
        region = ms.current_mesh().face_scalar_array().astype(int)
        counts = np.bincount(region[region >= 0])
        background = int(np.argmax(counts))
        sizes[width] = sorted(int(c) for r, c in enumerate(counts) if r != background)
        members[width] = [set(np.flatnonzero(region == r)) for r in range(len(counts)) if r != background]
        assert out["circles"] == len(sizes[width])
    assert sizes[1] == [22] * 4 + [46] * 4
    assert sizes[2] == [80] * 4
    ring4 = [s for s in members[1] if len(s) == 46]
    for s in ring4:
        assert sum(s <= band for band in members[2]) == 1, "each ring-4 circle lies inside one band of rings 3-4"
