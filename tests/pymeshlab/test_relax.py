"""'Irregular Vertices: Relax' through pymeshlab: every parameter (mode, iterations, region,
reproject, featureAngle); connectivity never changes; which vertices move; moved vertices stay
on the input surface; the returned shape measures against the oracle's angles; the returned
Hausdorff distance against the oracle's exact one (itself cross-checked with pymeshlab's
get_hausdorff_distance); colours, quality and selection untouched."""
import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import RELAX, apply, assert_same_state, load, painted, select, state, tri


def moved_mask(t0, t1):
    assert np.array_equal(t0.faces, t1.faces), "Relax changed the connectivity"
    return np.linalg.norm(t1.vertices - t0.vertices, axis=1) > 0


def assert_shape_values(out, t0, t1):
    """The returned triangle-shape measures equal the oracle's, before and after."""
    for suffix, m in (("_before", t0), ("_after", t1)):
        s = fo.shape_measures(m)
        assert out["min_angle" + suffix] == pytest.approx(s["min_angle"], abs=1e-6)
        assert out["mean_min_angle" + suffix] == pytest.approx(s["mean_min_angle"], abs=1e-6)
        assert out["percent_below_30" + suffix] == pytest.approx(100 * s["share_below_30"], abs=1e-9)


def pymeshlab_hausdorff_percent(t0, t1):
    """MeshLab's own sampled Hausdorff distance (both ways, vertices, edges and faces sampled),
    in percent of the input's diagonal."""
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=t0.vertices, face_matrix=t0.faces.astype(np.int32)))
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=t1.vertices, face_matrix=t1.faces.astype(np.int32)))
    kw = dict(samplevert=True, sampleedge=True, sampleface=True, samplenum=50000)
    a = ms.get_hausdorff_distance(sampledmesh=0, targetmesh=1, **kw)["max"]
    b = ms.get_hausdorff_distance(sampledmesh=1, targetmesh=0, **kw)["max"]
    return 100 * max(a, b) / fo.diagonal(t0)


def test_example_global_relaxation_on_the_bunny():
    """examples/relax.mlx: 3 global rounds on the bunny (README: triangles under 30 degrees
    4.95% -> 0.01%, mean min angle 45.6 -> 49.7 degrees)."""
    ms = load("bunny00.off")
    t0 = tri(ms)
    out = apply(ms, RELAX, mode="Global", iterations=3, region="All", reproject=True, featureangle=60)
    t1 = tri(ms)
    moved = moved_mask(t0, t1)
    assert moved.mean() > 0.9
    assert_shape_values(out, t0, t1)
    assert out["percent_below_30_before"] == pytest.approx(4.95, abs=0.01)
    assert out["percent_below_30_after"] < 0.05
    assert out["mean_min_angle_after"] > out["mean_min_angle_before"] + 3
    assert out["relaxed_vertices"] == len(t0.vertices) and out["moves"] > 0
    assert 0 < out["hausdorff_percent"] < 0.1
    fo.check_invariants(t1)


@pytest.mark.parametrize("name,mode,iterations", [("knot1.off", "Local", 10), ("elephant.off", "Global", 3),
                                                  ("fandisk.off", "Local", 5)])
def test_hausdorff_distance_against_the_oracle(name, mode, iterations):
    """The filter's sampled Hausdorff distance never exceeds the exact one and comes within 20%
    of it; MeshLab's own sampled measure agrees with the oracle the same way (a check of the
    oracle: no sampled distance may exceed its exact maximum)."""
    ms = load(name)
    t0 = tri(ms)
    out = apply(ms, RELAX, mode=mode, iterations=iterations, region="All", reproject=True, featureangle=60)
    t1 = tri(ms)
    exact = fo.hausdorff_percent(t0, t1)
    assert 0 < exact < 1
    assert 0.8 * exact <= out["hausdorff_percent"] <= exact * (1 + 1e-9) + 1e-12
    pm = pymeshlab_hausdorff_percent(t0, t1)
    assert 0.8 * exact <= pm <= exact * (1 + 1e-6) + 1e-9, (pm, exact)
    assert_shape_values(out, t0, t1)


def test_local_relaxation_of_the_selection_moves_only_the_selection():
    ms = load("knot1.off")
    t0 = tri(ms)
    ms.compute_selection_by_condition_per_vertex(condselect="(vi < 500)")
    out = apply(ms, RELAX, mode="Local", iterations=5, region="Selection", reproject=True, featureangle=60)
    moved = moved_mask(t0, tri(ms))
    assert moved[:500].mean() > 0.9 and not moved[500:].any()
    assert out["relaxed_vertices"] == 500


def test_selection_region_with_nothing_selected_relaxes_everything():
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [])
    out = apply(ms, RELAX, mode="Local", iterations=2, region="Selection")
    assert out["relaxed_vertices"] == len(t0.vertices)
    assert moved_mask(t0, tri(ms)).mean() > 0.9


def test_region_around_irregular_vertices_is_their_two_ring():
    ms = load("knot1.off")
    t0 = tri(ms)
    out = apply(ms, RELAX, mode="Local", iterations=3, region="Around irregular vertices", featureangle=0)
    moved = moved_mask(t0, tri(ms))
    d = fo.hop_distances(t0, np.nonzero(fo.irregular_mask(t0))[0])
    ring = (d >= 0) & (d <= 2)
    assert out["relaxed_vertices"] == ring.sum() < len(t0.vertices)
    assert moved.any() and not moved[~ring].any()


@pytest.mark.parametrize("mode", ["Local", "Global"])
def test_reprojection_keeps_vertices_on_the_input_surface(mode):
    ms = load("knot1.off")
    t0 = tri(ms)
    apply(ms, RELAX, mode=mode, iterations=3, region="All", reproject=True)
    t1 = tri(ms)
    moved = moved_mask(t0, t1)
    d = fo.closest_point_distances(t1.vertices[moved], t0)
    assert d.max() <= 1e-7 * fo.diagonal(t0), d.max()
    # without it the tangent-plane moves leave the curved tube
    ms = load("knot1.off")
    apply(ms, RELAX, mode=mode, iterations=3, region="All", reproject=False)
    t2 = tri(ms)
    d = fo.closest_point_distances(t2.vertices[moved_mask(t0, t2)], t0)
    assert d.max() > 1e-4 * fo.diagonal(t0), d.max()


def test_feature_angle_keeps_creases():
    """fandisk's creases (dihedral angle over 60 degrees, measured by the oracle) stay fixed
    with featureAngle 60; with 0 (disabled) they move."""
    ms = load("fandisk.off")
    t0 = tri(ms)
    crease = fo.crease_vertex_mask(t0, 60)
    assert 100 < crease.sum() < 0.5 * len(t0.vertices)
    out = apply(ms, RELAX, mode="Local", iterations=5, region="All", reproject=True, featureangle=60)
    moved = moved_mask(t0, tri(ms))
    assert np.array_equal(moved, ~crease)
    assert out["relaxed_vertices"] == (~crease).sum()
    ms = load("fandisk.off")
    apply(ms, RELAX, mode="Local", iterations=5, region="All", reproject=True, featureangle=0)
    assert moved_mask(t0, tri(ms))[crease].mean() > 0.5


def test_zero_iterations_move_nothing():
    ms = load("knot1.off")
    before = state(ms)
    out = apply(ms, RELAX, mode="Global", iterations=0)
    after = state(ms)
    assert np.array_equal(after["vertices"], before["vertices"])
    assert out["moves"] == 0 and out["hausdorff_percent"] < 1e-4


def test_relax_never_changes_colours_quality_or_selection():
    ms = painted("knot1.off")
    ms.compute_selection_by_condition_per_vertex(condselect="(vi < 100)")
    before = state(ms)
    apply(ms, RELAX, mode="Local", iterations=3, region="Selection")
    after = state(ms)
    for k in ("colours", "quality", "vertex_selection", "faces"):
        assert np.array_equal(after[k], before[k]), k
    assert not np.array_equal(after["vertices"], before["vertices"])


def test_deterministic():
    runs = []
    for _ in range(2):
        ms = load("elephant.off")
        apply(ms, RELAX, mode="Global", iterations=2)
        runs.append(state(ms))
    assert_same_state(runs[0], runs[1], "second run")
