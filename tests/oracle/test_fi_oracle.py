"""Self-checks of the oracle (fi_oracle) alone, no MeshLab: topology on synthetic meshes with
known answers and on corpus meshes of known genus, ordered one-rings, the defective meshes,
the exact Hausdorff distance against brute force, angles, curvature signs."""
import os
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fi_oracle as fo  # noqa: E402

SOURCE = os.environ.get("FI_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "..", ".."))
DATA = os.environ.get("FI_DATA_DIR") or os.path.join(SOURCE, ".deps", "data", "meshes")


def corpus(name):
    """A corpus OFF triangle mesh as a Tri (a missing file fails the test)."""
    path = os.path.join(DATA, name)
    if not os.path.isfile(path):
        pytest.fail("corpus mesh %s missing in %s (run scripts/setup.sh)" % (name, DATA), pytrace=False)
    with open(path) as f:
        rows = [s for s in (line.split("#")[0].split() for line in f) if s]
    assert rows[0][0] == "OFF"
    head, body = (rows[0][1:], 1) if len(rows[0]) > 1 else (rows[1], 2)
    nv, nf = int(head[0]), int(head[1])
    v = np.array([r[:3] for r in rows[body:body + nv]], dtype=np.float64)
    f = np.array([r[1:4] for r in rows[body + nv:body + nv + nf]], dtype=np.int64)
    assert all(r[0] == "3" for r in rows[body + nv:body + nv + nf])
    return fo.Tri(v, f)


def test_bunny():
    m = corpus("bunny00.off")
    assert m.vertices.shape == (37706, 3) and m.faces.shape == (75408, 3)
    assert fo.is_edge_manifold(m) and fo.is_consistently_oriented(m)
    assert fo.euler_characteristic(m) == 2
    assert fo.gauss_bonnet_sum(m) == 6 * fo.euler_characteristic(m) == 12
    assert fo.boundary_loop_count(m) == 0 and fo.component_count(m) == 1 and fo.genus(m) == 0
    assert fo.valences(m).sum() == 2 * len(fo.unique_edges(m)[0])
    s = fo.summary(m)
    # the README's numbers for the bunny
    assert (s["irregular"], s["vertices"]) == (19715, 37706)
    assert s["valence_histogram"].tolist() == [0, 0, 0, 0, 1080, 8951, 17991, 8340, 1276, 65, 3]
    assert (s["v4"], s["v5"], s["v7"], s["v8"], s["v9"]) == (1080, 8951, 8340, 1276, 68)


@pytest.mark.parametrize("name,g", [("knot1.off", 1), ("elephant.off", 3)])
def test_genus_of_corpus_meshes(name, g):
    m = corpus(name)
    assert fo.boundary_loop_count(m) == 0
    assert fo.genus(m) == g
    assert fo.gauss_bonnet_sum(m) == 6 * fo.euler_characteristic(m) == 6 * (2 - 2 * g)


def test_mesh_with_border():
    m = corpus("mesh_with_border.off")
    s = fo.summary(m)
    assert fo.boundary_vertex_mask(m).any() and s["boundary_loops"] >= 1
    assert s["gauss_bonnet_holds"]
    # equivalent valence: valence + 6 - regular valence; boundary valence + 2 on a smooth stretch
    eq = fo.equivalent_valences(m)
    b = fo.boundary_vertex_mask(m)
    smooth = b & ~fo.corner_mask(m)
    assert smooth.any()
    assert np.array_equal(eq[smooth], fo.valences(m)[smooth] + 2) and np.array_equal(eq[~b], fo.valences(m)[~b])
    assert np.array_equal(eq[b], fo.valences(m)[b] + 6 - fo.regular_valences(m)[b])
    # corners are exactly the boundary vertices whose angle is below 150 or at least 210 degrees
    ang = fo.corner_angles(m)
    assert np.array_equal(fo.corner_mask(m)[b], ((ang < 150) | (ang >= 210))[b])
    assert s["boundary_valence_histogram"].sum() == b.sum()
    assert s["valence_histogram"].sum() + b.sum() == len(m.vertices)


def test_icosahedron():
    m = fo.icosahedron()
    assert (fo.valences(m) == 5).all() and fo.irregular_mask(m).all()
    assert fo.euler_characteristic(m) == 2 and fo.gauss_bonnet_sum(m) == 12 and fo.genus(m) == 0
    assert fo.is_edge_manifold(m) and fo.is_vertex_manifold(m) and fo.is_consistently_oriented(m)
    c = fo.counts(m, "_x")
    assert c["v5_x"] == 12 and c["irregular_x"] == 12 and c["valence_histogram_x"].tolist() == [0] * 5 + [12]
    assert (fo.expected_rgb(m) == (40, 80, 230)).all()


def test_grid_patch():
    m = fo.grid(4)
    val, bnd = fo.valences(m), fo.boundary_vertex_mask(m)
    assert bnd.sum() == 16 and fo.boundary_loop_count(m) == 1
    assert fo.euler_characteristic(m) == 1 and fo.gauss_bonnet_sum(m) == 6 and fo.genus(m) == 0
    assert (val[~bnd] == 6).all()
    # The four corners span 90 degrees: regular at round(90 / 60) + 1 = 3 by the boundary
    # valence rule. Corners 0 and 24 (two faces) have valence 3 and are regular; corners 4 and
    # 20 (one face) have valence 2 and are irregular. The sides (180 degrees) are 4: regular.
    corners = [0, 4, 20, 24]
    assert (fo.corner_angles(m)[corners] == 90).all() and (fo.regular_valences(m)[corners] == 3).all()
    assert val[corners].tolist() == [3, 2, 2, 3]
    assert sorted(np.nonzero(fo.irregular_mask(m))[0]) == [4, 20]
    s = fo.summary(m)
    # counted by equivalent valence (valence + 6 - regular): valence 2 at a 90-degree corner -> v5
    assert (s["v3"], s["v4"], s["v5"], s["irregular"]) == (0, 0, 2, 2)
    assert (s["boundary_irregular"], s["boundary_corners"]) == (2, 4)


def test_one_ring_order_and_neighbour_numbering():
    m = fo.grid(4)
    c = 12  # the centre (2, 2): neighbours counter-clockwise seen from +z
    ring = fo.one_ring(m, c)
    angles = [np.arctan2(*(m.vertices[x, 1::-1] - m.vertices[c, 1::-1])) for x in ring]
    steps = np.diff(np.unwrap(angles + angles[:1]))
    assert len(ring) == 6 and (steps > 0).all()  # turning counter-clockwise
    assert fo.neighbour_from(m, c, 0) == min(ring)
    assert fo.neighbour_from(m, c, 1) == ring[(ring.index(min(ring)) + 1) % 6]
    assert fo.neighbour_from(m, c, 6) == min(ring)
    assert fo.neighbour_from(m, c, 2, ref=ring[3]) == ring[5]
    with pytest.raises(ValueError):
        fo.one_ring(m, 0)  # a boundary vertex
    assert fo.opposite_vertices(m, 12, 13) == sorted(set(fo.one_ring(m, 12)) & set(fo.adjacency_lists(m)[13]))
    d = fo.hop_distances(m, [0])
    assert d[0] == 0 and d[24] == 4 and d[6] == 1


def test_unreferenced_vertex_and_components():
    m = fo.icosahedron()
    two = fo.Tri(np.vstack([m.vertices, m.vertices + 10, [[0, 0, 0]]]), np.vstack([m.faces, m.faces + 12]))
    assert fo.valences(two)[-1] == 0 and not fo.irregular_mask(two)[-1]
    assert fo.euler_characteristic(two) == 4 and fo.component_count(two) == 2
    with pytest.raises(ValueError):
        fo.genus(two)
    assert "genus" not in fo.summary(two)


def test_bad_meshes_are_what_they_say():
    bad = fo.bad_meshes()
    tri = {k: fo.Tri(v, f) for k, (v, f, _) in bad.items() if k != "polygons"}
    assert not fo.is_edge_manifold(tri["non-manifold edge"])
    assert fo.is_edge_manifold(tri["non-manifold vertex"]) and not fo.is_vertex_manifold(tri["non-manifold vertex"])
    assert fo.duplicate_vertex_mask(tri["duplicated vertices"]).sum() == 2
    assert not fo.referenced_mask(tri["unreferenced vertices"]).all()
    z = tri["zero-area face"]
    assert fo.degenerate_face_mask(z).tolist() == [True] + [False] * 7
    assert fo.is_edge_manifold(z) and fo.is_vertex_manifold(z) and not fo.duplicate_vertex_mask(z).any()
    assert fo.degenerate_face_mask(tri["repeated vertex in a face"])[-1]
    assert not fo.is_consistently_oriented(tri["inconsistent orientation"])
    assert all(len(p) == 4 for p in bad["polygons"][1])
    with pytest.raises(AssertionError):
        fo.check_invariants(z)


def test_pymeshlab_like_objects():
    class FakeMesh:  # pymeshlab.Mesh's accessors
        def vertex_matrix(self):
            return fo.octahedron().vertices

        def face_matrix(self):
            return fo.octahedron().faces.astype(np.int32)

    assert fo.summary(FakeMesh())["v4"] == 6
    assert fo.summary((fo.octahedron().vertices, fo.octahedron().faces))["euler_characteristic"] == 2


# ------------------------------------------------------------------ geometry
def brute_distance(points, m):
    """Point-to-surface distance by dense sampling of every triangle (an upper bound that
    converges to the true distance)."""
    tri = m.vertices[m.faces]
    u, v = np.meshgrid(np.linspace(0, 1, 41), np.linspace(0, 1, 41))
    keep = u + v <= 1
    u, v = u[keep], v[keep]
    s = tri[:, None, 0] * (1 - u - v)[None, :, None] + tri[:, None, 1] * u[None, :, None] + tri[:, None, 2] * v[None, :, None]
    s = s.reshape(-1, 3)
    return np.array([np.linalg.norm(s - p, axis=1).min() for p in points])


def test_closest_point_distances_against_brute_force():
    m = fo.icosahedron()
    rng = np.random.default_rng(3)
    pts = rng.normal(size=(60, 3)) * 2
    d = fo.closest_point_distances(pts, m, candidates=20)
    b = brute_distance(pts, m)
    assert (d <= b + 1e-9).all() and np.allclose(d, b, atol=0.03)
    # points on the surface are at distance 0
    on = fo.surface_samples(m)
    assert fo.closest_point_distances(on, m).max() < 1e-12


def test_hausdorff_of_known_pairs():
    m = fo.grid(4)
    lifted = fo.Tri(m.vertices + (0, 0, 0.25), m.faces)
    ab, ba = fo.hausdorff(m, lifted)
    assert ab == pytest.approx(0.25) and ba == pytest.approx(0.25)
    assert fo.hausdorff_percent(m, m) < 1e-12
    bump = fo.Tri(m.vertices.copy(), m.faces)
    bump.vertices[12, 2] = 1.0  # one interior vertex raised: the farthest point is the tip
    ab, ba = fo.hausdorff(m, bump)
    assert ba == pytest.approx(1.0) and ab < ba
    assert fo.diagonal(m) == pytest.approx(np.sqrt(32))


def test_angles_areas_edge_length():
    m = fo.grid(2)
    ang = fo.triangle_angles(m)
    assert np.allclose(np.sort(ang, axis=1), [45, 45, 90])
    assert fo.shape_measures(m) == {"min_angle": pytest.approx(45), "mean_min_angle": pytest.approx(45),
                                    "share_below_30": 0.0}
    assert np.allclose(fo.triangle_areas(m), 0.5)
    ico = fo.icosahedron()
    assert np.allclose(fo.triangle_angles(ico), 60)
    assert fo.mean_edge_length(ico) == pytest.approx(2.0)
    # equilateral triangles of edge L: area sqrt(3)/4 L^2, two per vertex
    assert fo.edge_length_for(ico, 10) == pytest.approx(np.sqrt(2 * fo.triangle_areas(ico).sum() / (np.sqrt(3) * 10)))


def test_gaussian_curvature_sign():
    ico = fo.icosahedron()
    assert (fo.gaussian_curvature_near(ico, ico.vertices, 0.1) > 0).all()
    m = fo.grid(6)
    m.vertices[:, 2] = (m.vertices[:, 0] - 3) ** 2 - (m.vertices[:, 1] - 3) ** 2  # a saddle
    assert fo.gaussian_curvature_near(m, [(3, 3, 0)], 1.1)[0] < 0


def test_crease_vertices():
    cube = fo.Tri([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
                  [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5),
                   (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)])
    assert fo.is_consistently_oriented(cube) and fo.gauss_bonnet_sum(cube) == 12
    assert fo.crease_vertex_mask(cube, 60).all()  # every corner is on a 90 degree edge
    assert not fo.crease_vertex_mask(cube, 95).any()
    assert not fo.crease_vertex_mask(fo.grid(3), 1).any()  # flat
    n = fo.face_normals(fo.grid(1))
    assert np.allclose(n, [(0, 0, 1), (0, 0, 1)])


def capped_tube(segments, rings, radius=1.0):
    """A closed tube along z: `rings` rings of `segments` vertices, spaced by the edge length
    around (2 pi radius / segments), each end closed by a fan to a centre vertex."""
    step = 2 * np.pi * radius / segments
    t = 2 * np.pi * np.arange(segments) / segments
    v = [(radius * np.cos(a), radius * np.sin(a), r * step) for r in range(rings) for a in t]
    v += [(0, 0, -step), (0, 0, rings * step)]
    bottom, top = len(v) - 2, len(v) - 1
    f = []
    for r in range(rings - 1):
        for k in range(segments):
            a, b = r * segments + k, r * segments + (k + 1) % segments
            f += [(a, b, b + segments), (a, b + segments, a + segments)]
    for k in range(segments):
        f.append((bottom, (k + 1) % segments, k))
        last = (rings - 1) * segments
        f.append((top, last + k, last + (k + 1) % segments))
    return fo.Tri(np.array(v, float), np.array(f, np.int64))


def test_thin_vertex_mask_finds_the_tube_thinner_than_four_edge_lengths():
    # 12 around: the diameter is 12 / pi = 3.8 edge lengths; 40 around: 12.7
    thin, thick = capped_tube(12, 30), capped_tube(40, 30)
    for m in (thin, thick):
        assert fo.is_consistently_oriented(m) and fo.euler_characteristic(m) == 2
    middle = lambda segments: np.arange(10 * segments, 20 * segments)  # noqa: E731
    assert fo.thin_vertex_mask(thin)[middle(12)].all()
    assert not fo.thin_vertex_mask(thick)[middle(40)].any()
    # the same answer with the faces wound the other way (normals turned outward by volume)
    flipped = fo.Tri(thin.vertices, thin.faces[:, ::-1].copy())
    assert (fo.thin_vertex_mask(flipped) == fo.thin_vertex_mask(thin)).all()
    # a wider bound makes the thick tube thin; `which` tests only those vertices
    assert fo.thin_vertex_mask(thick, edges=14)[middle(40)].all()
    some = fo.thin_vertex_mask(thin, which=[0, 5 * 12 + 3])
    assert some.sum() == 2 and some[0] and some[5 * 12 + 3]
    # the icosahedron is 1.9 edge lengths across: thin at 4, not at 1.5
    assert fo.thin_vertex_mask(fo.icosahedron()).all()
    assert not fo.thin_vertex_mask(fo.icosahedron(), edges=1.5).any()
