"""'Irregular Vertices: Analyze' through pymeshlab on corpus meshes: the returned dict, the
colours, the quality and the selection against the oracle's counts from face_matrix(); the
oracle itself cross-checked with pymeshlab's get_topological_measures; every select mode, the
colorize switch, and a save / load round trip of what the filter wrote."""
import numpy as np
import pytest

import fi_oracle as fo
from fi_pm import (ANALYZE, apply, assert_same_state, load, painted, quality, rgb, select, selected, state, tri)

MESHES = [("bunny00.off", 0), ("elephant.off", 3), ("knot1.off", 1), ("mesh_with_border.off", 0),
          ("head.off", 0), ("blobby_3cc.off", None)]


def assert_matches_oracle(out, mesh):
    """Every value Analyze returns equals the oracle's (genus only for connected meshes)."""
    expect = fo.summary(mesh)
    for key, want in expect.items():
        got = out[key]
        if isinstance(want, np.ndarray):
            assert np.array_equal(np.asarray(got, dtype=np.float64), want), (key, got, want)
        elif isinstance(want, float):
            assert got == pytest.approx(want, rel=1e-12), (key, got, want)
        else:
            assert got == want, (key, got, want)


@pytest.mark.parametrize("name,genus", MESHES)
def test_returned_values_colours_quality_selection(name, genus):
    ms = load(name)
    before = state(ms)
    out = apply(ms, ANALYZE, select="All irregular", valence=5, colorize=True)
    m = tri(ms)
    assert_matches_oracle(out, m)
    if genus is not None:
        assert out["genus"] == genus
    assert out["gauss_bonnet_holds"] and out["gauss_bonnet_sum"] == 6 * out["euler_characteristic"]
    # quality holds the valence, colours the legend of the equivalent valence
    assert np.array_equal(quality(ms), fo.valences(m).astype(float))
    assert np.array_equal(rgb(ms), fo.expected_rgb(m))
    # the selection is the irregular vertices, and its size is returned
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), fo.irregular_mask(m))
    assert out["selected"] == fo.irregular_mask(m).sum()
    # geometry and connectivity are untouched
    after = state(ms)
    assert np.array_equal(after["vertices"], before["vertices"]) and np.array_equal(after["faces"], before["faces"])
    fo.check_invariants(m)


@pytest.mark.parametrize("name", [n for n, _ in MESHES])
def test_oracle_agrees_with_pymeshlab_topological_measures(name):
    """The oracle's own topology against MeshLab's independent 'Compute Topological Measures'."""
    ms = load(name)
    pm = ms.get_topological_measures()
    s = fo.summary(tri(ms))
    assert (s["vertices"], s["edges"], s["faces"]) == (pm["vertices_number"], pm["edges_number"], pm["faces_number"])
    assert s["components"] == pm["connected_components_number"]
    assert s["boundary_loops"] == pm["number_holes"]
    assert pm["is_mesh_two_manifold"] and fo.is_edge_manifold(tri(ms)) and fo.is_vertex_manifold(tri(ms))
    if s["components"] == 1:
        assert s["genus"] == pm["genus"]


def test_bunny_numbers():
    """The README's numbers for the bunny."""
    out = apply(load("bunny00.off"), ANALYZE)
    assert (out["irregular"], out["vertices"]) == (19715, 37706)
    assert out["irregular_percent"] == pytest.approx(100 * 19715 / 37706)
    assert out["valence_histogram"].tolist() == [0, 0, 0, 0, 1080, 8951, 17991, 8340, 1276, 65, 3]
    assert (out["euler_characteristic"], out["genus"], out["gauss_bonnet_sum"]) == (2, 0, 12)


@pytest.mark.parametrize("valence", [5, 7])
def test_select_only_valence(valence):
    ms = load("knot1.off")
    out = apply(ms, ANALYZE, select="Only valence", valence=valence)
    m = tri(ms)
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), fo.valences(m) == valence)
    assert out["selected"] == 168


@pytest.mark.parametrize("valence", [4, 5, 7])
def test_only_valence_counts_boundary_vertices_as_valence_plus_two(valence):
    ms = load("mesh_with_border.off")
    out = apply(ms, ANALYZE, select="Only valence", valence=valence)
    m = tri(ms)
    want = fo.equivalent_valences(m) == valence
    assert want.any()
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), want)
    assert out["selected"] == want.sum()


def test_select_only_a_valence_nobody_has():
    ms = load("knot1.off")
    out = apply(ms, ANALYZE, select="Only valence", valence=1000)
    assert out["selected"] == 0 and not ms.current_mesh().vertex_selection_array().any()


def test_boundary_vertices_follow_the_boundary_valence_rule():
    """A boundary vertex is regular at round(corner angle / 60) + 1: 4 on a smooth stretch; the
    selection of 'All irregular' and the grey of the legend follow that rule."""
    ms = load("mesh_with_border.off")
    out = apply(ms, ANALYZE)
    m = tri(ms)
    bnd = fo.boundary_mask(m)
    reg = fo.regular_valences(m)
    sel = ms.current_mesh().vertex_selection_array()
    smooth4 = bnd & ~fo.corner_mask(m) & (fo.valences(m) == 4)
    assert smooth4.any() and not sel[smooth4].any()
    assert np.array_equal(sel[bnd], (fo.valences(m) != reg)[bnd])
    assert (rgb(ms)[bnd & (fo.valences(m) == reg)] == (200, 200, 200)).all()
    assert out["boundary_irregular"] == int((sel & bnd).sum())
    assert out["boundary_corners"] == int(fo.corner_mask(m).sum())


def hex_disc(radius):
    """A planar hexagon of the regular triangular lattice (6 corners of 120 degrees, valence 3)."""
    cells = [(q, r) for q in range(-radius, radius + 1) for r in range(-radius, radius + 1) if abs(q + r) <= radius]
    index = {c: i for i, c in enumerate(cells)}
    v = np.array([[q + 0.5 * r, r * np.sqrt(3) / 2, 0.0] for q, r in cells])
    f = []
    for q, r in cells:
        a, b, d, e = index.get((q, r)), index.get((q + 1, r)), index.get((q, r + 1)), index.get((q - 1, r + 1))
        if b is not None and d is not None:
            f.append([a, b, d])
        if d is not None and e is not None:
            f.append([a, d, e])
    return v, np.array(f)


def test_hexagon_corners_of_120_degrees_are_regular_at_valence_three(tmp_path):
    import pymeshlab
    v, f = hex_disc(4)
    path = tmp_path / "hexagon.off"
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        out.writelines("%r %r %r\n" % tuple(p) for p in v.tolist())
        out.writelines("3 %d %d %d\n" % tuple(t) for t in f.tolist())
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(path))
    out = apply(ms, ANALYZE, select="All irregular")
    m = tri(ms)
    assert_matches_oracle(out, m)
    assert out["irregular"] == 0 and out["boundary_irregular"] == 0 and out["boundary_corners"] == 6
    # eq. 2 still counts the six corners against 4: 6 x (4 - 3) = 6 chi
    assert out["gauss_bonnet_sum"] == 6 and out["gauss_bonnet_holds"]
    assert not ms.current_mesh().vertex_selection_array().any()


@pytest.mark.parametrize("name", ["holes.off", "mushroom.off", "cylinder_locally_refined.off"])
def test_meshes_with_holes_match_the_oracle(name):
    ms = load(name)
    out = apply(ms, ANALYZE, select="All irregular")
    m = tri(ms)
    assert_matches_oracle(out, m)
    assert out["boundary_loops"] >= 1
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), fo.irregular_mask(m))


def test_select_none_keeps_the_users_selection():
    ms = load("knot1.off")
    select(ms, [3, 17, 2000])
    out = apply(ms, ANALYZE, select="None")
    assert selected(ms).tolist() == [3, 17, 2000] and out["selected"] == 3


def test_colorize_off_keeps_colours_and_writes_quality():
    ms = painted("knot1.off")
    before = state(ms)
    out = apply(ms, ANALYZE, select="All irregular", valence=5, colorize=False)
    after = state(ms)
    assert np.array_equal(after["colours"], before["colours"])
    assert np.array_equal(after["quality"], fo.valences(tri(ms)).astype(float))
    assert out["irregular"] == 336


def test_analyze_is_idempotent():
    ms = load("elephant.off")
    a = apply(ms, ANALYZE)
    s = state(ms)
    b = apply(ms, ANALYZE)
    assert_same_state(s, state(ms), "second Analyze")
    assert a.keys() == b.keys()
    for k in a:
        assert np.array_equal(np.asarray(a[k]), np.asarray(b[k])), k


def test_save_and_load_round_trip(tmp_path):
    """pymeshlab writes what the filter painted (PLY with vertex colour and quality) and reads
    it back unchanged."""
    ms = load("elephant.off")
    apply(ms, ANALYZE)
    path = str(tmp_path / "elephant.ply")
    ms.save_current_mesh(path, save_vertex_color=True, save_vertex_quality=True, binary=True)
    back = load_path(path)
    assert np.array_equal(back.current_mesh().face_matrix(), ms.current_mesh().face_matrix())
    assert np.allclose(back.current_mesh().vertex_matrix(), ms.current_mesh().vertex_matrix(), atol=1e-6)
    assert np.array_equal(rgb(back), fo.expected_rgb(tri(ms)))
    assert np.array_equal(quality(back), fo.valences(tri(ms)).astype(float))
    # and Analyze on the reloaded mesh returns the same counts
    assert apply(back, ANALYZE)["irregular"] == apply(ms, ANALYZE)["irregular"]


def load_path(path):
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(path)
    return ms
