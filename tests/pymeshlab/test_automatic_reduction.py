"""'Irregular Vertices: Automatic Reduction' through pymeshlab. Every measure is taken here,
independently of the filter's own report: topology and angles with the oracle from the
result's arrays, the symmetric Hausdorff distance exactly with numpy/scipy (cross-checked
with pymeshlab's get_hausdorff_distance); MeshLab's isotropic remeshing is the peer. The
filter is slow (bunny00: about 40 s), so it runs on bunny00 once and otherwise on small
inputs (knot1 3200 vertices, elephant 2775, mesh_with_border 548)."""
import re
import time

import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import (AUTOMATIC, apply, assert_counts, assert_same_state, canonical_faces, index_by_position, load,
                   painted, quality, refuse, rgb, select, selected, state, tri)

DEFAULTS = dict(targetcount=0, hausdorffbudget=0.5, minangle=30, maxtravel=12, protect="Nothing",
                relaxation="Local", timelimit=0, aggregate=False, colorize=True)


def reduce(ms, **kw):
    params = dict(DEFAULTS, remeshedgelength=pymeshlab.PureValue(0))
    params.update(kw)
    return apply(ms, AUTOMATIC, **params)


def check_result(out, t0, t1, budget=0.5, remeshed=False):
    """What every run must give: a valid mesh of the input's topology, returned counts equal to
    the oracle's, the budget kept (exact Hausdorff distance), the irregular vertices left
    selected (unless protected) and painted."""
    fo.check_invariants(t1)
    s0, s1 = fo.summary(t0), fo.summary(t1)
    assert (s1["euler_characteristic"], s1["components"], s1["boundary_loops"]) == \
        (s0["euler_characteristic"], s0["components"], s0["boundary_loops"])
    assert_counts(out, t0, "_input")
    assert_counts(out, t1, "_after")
    assert (out["vertices_after"], out["faces_after"]) == (len(t1.vertices), len(t1.faces))
    assert out["remeshed"] == remeshed
    exact = fo.hausdorff_percent(t0, t1)
    assert exact <= budget * (1 + 1e-6), (exact, budget)
    # the filter samples a superset of the oracle's points (quality.h MaxSampleDistance): its own
    # measure of the result is never below the oracle's (float against double: 1e-3, and 1e-4
    # percent, a millionth of the diagonal, for float rounding where nothing moved)
    assert out["hausdorff_percent"] >= exact * (1 - 1e-3) - 1e-4, (out["hausdorff_percent"], exact)
    # Both are maxima over sample points of exact point-to-surface distances, so both are lower
    # bounds of the true distance, and the filter keeps the budget itself. With the edges'
    # midpoints added, the oracle samples the very points the filter does: the two agree up to
    # float rounding (the midpoints alone had put the filter up to 5% above the plain oracle).
    assert out["hausdorff_percent"] <= budget * (1 + 1e-6), (out["hausdorff_percent"], budget)
    same_points = fo.hausdorff_percent(t0, t1, midpoints=True)
    assert out["hausdorff_percent"] == pytest.approx(same_points, rel=1e-3, abs=1e-4), (out["hausdorff_percent"],
                                                                                       same_points)
    sh = fo.shape_measures(t1)
    assert out["min_angle_after"] == pytest.approx(sh["min_angle"], abs=1e-6)
    assert out["percent_below_30_after"] == pytest.approx(100 * sh["share_below_30"], abs=1e-9)
    return exact


def test_bunny_example_meets_the_paper_and_beats_the_peer():
    """examples/automatic_reduction.mlx: bunny00 remeshed to about 19K vertices, then reduced.
    The paper's designers reached 84 irregular vertices by hand on a 40K-triangle bunny; MeshLab's
    own isotropic remeshing to the same edge length leaves thousands."""
    length = 0.01166
    ms = load("bunny00.off")
    t0 = tri(ms)
    out = reduce(ms, remeshedgelength=pymeshlab.PureValue(length))
    t1 = tri(ms)
    exact = check_result(out, t0, t1, remeshed=True)
    irregular = fo.irregular_mask(t1)
    assert 12 <= irregular.sum() <= 84, irregular.sum()
    assert set(np.unique(fo.valences(t1)[irregular]).tolist()) <= {5, 7}
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), irregular)
    assert np.array_equal(rgb(ms), fo.expected_rgb(t1))
    assert fo.shape_measures(t1)["share_below_30"] <= 0.01
    assert out["stop_reason"] == 0 and out["budget_retries"] >= 0
    assert 15000 < out["remeshed_vertices"] < 22000 and out["irregular_before"] > 4000
    assert 0 < out["remesh_hausdorff_percent"] < exact + 1e-9 or out["remesh_hausdorff_percent"] < 0.5
    assert out["type_splits"] + out["local_cancellations"] + out["transports"] + out["glides"] > 0
    assert out["split_absorptions"] > 0 and out["partial_absorptions"] >= 0
    assert 0 <= out["far_meetings_kept"] <= out["far_meetings"]
    assert 0 <= out["near_meetings_kept"] <= out["near_meetings"]
    assert 1 <= out["meeting_rounds"] <= 3
    assert 0 <= out["angle_polished"] <= out["angle_polish_below"]
    assert 0 <= out["angle_flips"] <= out["angle_flips_tried"]
    assert 0 < out["reduction_seconds"] <= out["seconds"]
    # the oracle's distance against MeshLab's own sampled one: both sample the surfaces (neither
    # is the exact maximum), so they agree within a few percent, and MeshLab's keeps the budget
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=t0.vertices, face_matrix=t0.faces.astype(np.int32)))
    kw = dict(samplevert=True, sampleedge=True, sampleface=True, samplenum=100000)
    pm = max(ms.get_hausdorff_distance(sampledmesh=0, targetmesh=1, **kw)["max"],
             ms.get_hausdorff_distance(sampledmesh=1, targetmesh=0, **kw)["max"]) / fo.diagonal(t0) * 100
    assert 0.8 * exact <= pm <= min(1.05 * exact, 0.5), (pm, exact)
    # The irregular vertices left are where the surface needs them: v5 on caps, v7 in saddles
    # (the sign of the input's Gaussian curvature within 4% of the diagonal around them; on
    # random vertices either sign is about as likely). Measured: 90% and 89%.
    k = fo.gaussian_curvature_near(t0, t1.vertices[irregular], 0.04 * fo.diagonal(t0))
    v = fo.valences(t1)[irregular]
    assert (k[v == 5] > 0).mean() >= 0.75, (k[v == 5] > 0).mean()
    assert (k[v == 7] < 0).mean() >= 0.75, (k[v == 7] < 0).mean()
    # the peer: MeshLab's isotropic remeshing to the same edge length
    peer = load("bunny00.off")
    peer.meshing_isotropic_explicit_remeshing(iterations=10, targetlen=pymeshlab.PureValue(length))
    tp = tri(peer)
    assert abs(len(tp.vertices) - out["remeshed_vertices"]) < 0.2 * len(tp.vertices)
    assert fo.irregular_mask(tp).sum() > 40 * irregular.sum()


def test_cow_keeps_its_angles_after_the_angle_polish():
    """The cow as the benchmark remeshes it (MeshLab's isotropic remeshing to about 20K vertices,
    its pinned parameters; the one vertex where that joins two fans repaired first): issue 14
    bounds the share of triangles under 30 degrees at 1%. Transports leave clusters of sheared
    triangles there; the final sweeps overshoot the budget on the cow and are dropped, so without
    the angle polish 1.21% stayed (0.9.11). Measured with it: 0.76%, 57 of 449 relaxed. Since
    0.9.21 the guard refuses fewer transports near the thin parts for no cause (sample
    witnesses), which leaves fewer sheared clusters: 13 relaxed here (native bench on the
    benchmark's cow: 0.53% under 30 degrees without the polish, 0.44% with it, 14 of 196); since
    0.9.22 (witnesses seeded from the input) 8. The bound is the share; the polish must still
    relax some."""
    length = 0.007596064858557005  # the benchmark's edge length for the cow at 20K
    ms = load("cow.off")
    t0 = tri(ms)
    ms.meshing_isotropic_explicit_remeshing(
        targetlen=pymeshlab.PureValue(length), maxsurfdist=pymeshlab.PureValue(length / 10), iterations=10,
        adaptive=False, selectedonly=False, featuredeg=30.0, checksurfdist=False, splitflag=True,
        collapseflag=True, swapflag=True, smoothflag=True, reprojectflag=True)
    if ms.get_topological_measures()["non_two_manifold_vertices"]:
        ms.meshing_repair_non_manifold_vertices(vertdispratio=0.05)
    before = fo.shape_measures(tri(ms))["share_below_30"]
    out = reduce(ms)
    t1 = tri(ms)
    after = fo.shape_measures(t1)["share_below_30"]
    assert after <= 0.01 and after < before, (before, after)
    assert out["percent_below_30_after"] == pytest.approx(100 * after, abs=1e-9)
    assert 0 < out["angle_polished"] <= out["angle_polish_below"], out["angle_polished"]
    assert out["hausdorff_percent"] <= 0.5
    assert fo.irregular_mask(t1).sum() <= 0.03 * len(t1.vertices)


def test_remeshed_knot_keeps_the_budget():
    """knot1 remeshed to about 6000 vertices with a 0.3% budget: a torus can be regular, and
    well under 1% of the vertices stay irregular; remeshing and reduction are deterministic
    (the same run twice gives the same mesh)."""
    runs = []
    for _ in range(2):
        ms = load("knot1.off")
        t0 = tri(ms)
        out = reduce(ms, remeshedgelength=pymeshlab.PureValue(fo.edge_length_for(t0, 6000)), hausdorffbudget=0.3)
        runs.append(state(ms))
    assert_same_state(runs[0], runs[1], "second run")
    t1 = tri(ms)
    check_result(out, t0, t1, budget=0.3, remeshed=True)
    assert fo.genus(t1) == 1
    assert out["remeshed_vertices"] > 4500 and out["remesh_hausdorff_percent"] <= 0.3
    assert fo.irregular_mask(t1).sum() < 0.01 * len(t1.vertices), fo.irregular_mask(t1).sum()
    # every irregular vertex left has one reason; "no route" (tried, no cancellation found) is
    # told apart from "untried"
    reasons = sorted(k for k in out if k.startswith("leftover_") and k != "leftover_on_thin_parts")
    assert reasons == sorted("leftover_" + r for r in (
        "boundary", "protected", "caps", "saddles", "thin", "no_partner", "budget", "no_route", "untried"))
    assert sum(out[k] for k in reasons) == out["irregular_after"] == fo.irregular_mask(t1).sum()
    assert out["stop_reason"] == 0


def test_genus_three_keeps_its_topology_and_stops_at_the_target():
    """elephant (genus 3: at least 24 irregular vertices by Gauss-Bonnet) with targetCount 300."""
    ms = load("elephant.off")
    t0 = tri(ms)
    out = reduce(ms, targetcount=300)
    t1 = tri(ms)
    check_result(out, t0, t1)
    assert fo.genus(t1) == 3 and fo.gauss_bonnet_sum(t1) == -24
    assert out["stop_reason"] == 1
    assert 24 <= out["irregular_after"] <= 300 < out["irregular_input"]


def test_target_count_on_a_mesh_with_boundary():
    """stop_reason 1 says the target was reached: targetCount counts interior irregular vertices
    (boundary irregular vertices do not count); interior_irregular_after is then at
    most targetCount, and irregular_after counts the boundary ones too, as Analyze does."""
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    out = reduce(ms, targetcount=100)
    t1 = tri(ms)
    check_result(out, t0, t1)
    assert out["stop_reason"] == 1
    interior = fo.irregular_mask(t1) & ~fo.boundary_vertex_mask(t1)
    assert interior.sum() == out["interior_irregular_after"] <= 100, out["interior_irregular_after"]
    assert fo.irregular_mask(t1).sum() == out["irregular_after"] > out["interior_irregular_after"]
    # boundary vertices are neither moved nor removed (an interior flip may change the valence
    # of a boundary vertex opposite the flipped edge, so their count is not asserted)
    b0 = t0.vertices[fo.boundary_vertex_mask(t0)]
    b1 = t1.vertices[fo.boundary_vertex_mask(t1)]
    assert np.array_equal(np.unique(b0, axis=0), np.unique(b1, axis=0))


def test_irregular_before_is_the_input_count_without_remeshing():
    """README: irregular_before / valence_histogram_before are what the reduction starts from:
    without remeshing, the input (the oracle's count, as irregular_input)."""
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    out = reduce(ms)
    assert np.array_equal(np.asarray(out["valence_histogram_before"]), fo.counts(t0)["valence_histogram"])
    assert out["irregular_before"] == out["irregular_input"] == fo.irregular_mask(t0).sum(), (
        out["irregular_before"], out["irregular_input"])


def test_deterministic_and_every_parameter_has_its_effect():
    """On mesh_with_border (548 vertices, 297 irregular): the same run twice gives the same
    mesh; maxTravel 1 leaves more irregular vertices than 12; minAngle bounds the result's
    smallest angle (from below, or by the input's) when angleAllowance is 0, and 0 lets thinner
    triangles through; with the allowance (default 0.8%) the share of triangles under minAngle
    stays within it (or the input's) and angleFloor bounds the smallest angle; the global final
    relaxation keeps the budget; a tiny time limit stops early (stop_reason 2)."""
    def run(**kw):
        ms = load("mesh_with_border.off")
        t0 = tri(ms)
        out = reduce(ms, **kw)
        t1 = tri(ms)
        check_result(out, t0, t1, budget=kw.get("hausdorffbudget", 0.5))
        return ms, out, t0, t1

    ms_a, a, t0, _ = run()
    ms_b, b, _, _ = run()
    assert_same_state(state(ms_a), state(ms_b), "second run")
    # bounded effort: regions given up are reported, each around an irregular vertex left
    for key in ("gave_up_regions", "gave_up_vertices"):
        assert a[key] == b[key], key
    assert 0 <= a["gave_up_regions"] <= a["gave_up_vertices"] <= a["interior_irregular_after"]
    input_shape = fo.shape_measures(t0)
    input_min = input_shape["min_angle"]
    # the allowance: under the floor never, under 30 degrees within 0.8% of the triangles
    _, _, _, t_a = run()
    assert a["min_angle_after"] >= min(20, input_min) - 1e-9
    assert fo.shape_measures(t_a)["share_below_30"] <= max(0.008, input_shape["share_below_30"]) + 1e-12
    _, floored, _, _ = run(anglefloor=26)
    assert floored["min_angle_after"] >= min(26, input_min) - 1e-9
    _, kept30, _, _ = run(angleallowance=0)
    assert kept30["min_angle_after"] >= min(30, input_min) - 1e-9
    print("mesh_with_border: smallest angle %.2f (input %.2f), %.2f with angleFloor 26, %.2f with angleAllowance 0; "
          "irregular left %d, %d, %d" % (a["min_angle_after"], input_min, floored["min_angle_after"],
                                         kept30["min_angle_after"], a["irregular_after"], floored["irregular_after"],
                                         kept30["irregular_after"]))
    assert a["min_angle_after"] < kept30["min_angle_after"]  # the allowance was used
    _, short, _, _ = run(maxtravel=1)
    assert short["irregular_after"] > a["irregular_after"]
    _, strict, _, _ = run(minangle=45, angleallowance=0)
    assert strict["min_angle_after"] >= min(45, input_min) - 1e-9
    assert strict["irregular_after"] > a["irregular_after"] and strict["undone"] > a["undone"]
    # the guard's refusals by reason: a stricter angle bound refuses more for the angle
    assert strict["undone_angle"] > a["undone_angle"] and a["undone_frozen"] == 0
    _, loose, _, _ = run(minangle=0)
    assert loose["min_angle_after"] < input_min
    _, glob, _, _ = run(relaxation="Global")
    assert glob["stop_reason"] == 0
    _, timed, _, _ = run(timelimit=0.001)
    assert timed["stop_reason"] == 2 and timed["irregular_after"] > a["irregular_after"]
    _, tight, _, _ = run(hausdorffbudget=0.1)
    assert tight["irregular_after"] > a["irregular_after"]
    assert tight["undone_hausdorff"] > a["undone_hausdorff"]


def test_aggregation_walks_stop_at_their_bound_where_they_do_not_pay():
    """The gathering's walks are tried while they pay their way: fewer than 16 plus 3 per kept
    walk (0.9.33; most walks that fail fail after some hops, each a transport). On the femur
    (raw, 3897 vertices, genus 2) none of its first 16 walks gets there, so the stage stops and
    says so; the aggregations without a walk are still made, and the result is the usual one."""
    ms = load("femur.off")
    t0 = tri(ms)
    out = reduce(ms, aggregate=True)
    t1 = tri(ms)
    check_result(out, t0, t1)
    assert out["gathering_bound_reached"] == True  # noqa: E712
    assert out["gatherings_tried"] == 16 + 3 * out["aggregations_gathered"]
    assert out["aggregated_v4"] + out["aggregated_v8"] > 0


def test_aggregation_merges_leftover_pairs_where_they_were():
    """'Aggregate leftovers into v4/v8' (aggregate, default off) on the elephant (raw, 2775
    vertices): the run is the default one up to its last stage, which merges two leftover v5
    into a v4 and two v7 into a v8 (sec. 6.3) where the guard passes it, after walking a leftover
    toward a partner of its type up to 16 edges away when none stands in the configuration
    (gathering, 0.9.31). Measured: 160 interior irregular vertices left without, 111 with (12 v4
    and 35 v8 of 92 pairs tried, 36 of them gathered in 124 walks, where the walks' bound of
    effort stopped them, 0.9.33; 110 without the bound; 150 before gathering). Each
    new v4 (v8) lies where the default run left two v5 (v7) near each other, and the curvature
    they stand for is kept (genus 3: the sum of 6 - valence stays -24)."""
    runs = {}
    for agg in (False, True):
        ms = load("elephant.off")
        t0 = tri(ms)
        out = reduce(ms, aggregate=agg)
        t1 = tri(ms)
        check_result(out, t0, t1)
        assert fo.genus(t1) == 3 and fo.gauss_bonnet_sum(t1) == -24
        runs[agg] = (out, t1)
    (off, t_off), (on, t_on) = runs[False], runs[True]
    assert off["aggregated_v4"] == off["aggregated_v8"] == off["aggregations_tried"] == 0
    assert on["aggregated_v4"] > 0 and on["aggregated_v8"] > 0, (on["aggregated_v4"], on["aggregated_v8"])
    assert on["aggregated_v4"] + on["aggregated_v8"] <= on["aggregations_tried"]
    mask_off, mask_on = fo.irregular_mask(t_off), fo.irregular_mask(t_on)
    assert on["interior_irregular_after"] == mask_on.sum() < mask_off.sum() == off["interior_irregular_after"]
    assert 0 < on["aggregations_gathered"] <= on["gatherings_tried"]
    assert off["aggregations_gathered"] == off["gatherings_tried"] == 0
    # the walks' bound of effort (16 plus 3 per kept walk, 0.9.33)
    assert on["gatherings_tried"] <= 16 + 3 * on["aggregations_gathered"]
    assert off["gathering_bound_reached"] == False  # noqa: E712
    # where: every v4 (v8) of the aggregated run that the default run does not have has two v5
    # (v7) of the default run near it: within two mean edge lengths where they merged as they
    # stood (the final relaxation moves vertices by a fraction of an edge), within the gathering
    # radius (16 edges, and 2 for the relaxation) where they first walked together
    edge = fo.mean_edge_length(t_off)
    reach, walk = 2 * edge, 18 * edge
    val_off, val_on = fo.valences(t_off), fo.valences(t_on)
    checked = where_they_stood = 0
    for merged, parts in ((4, 5), (8, 7)):
        old = t_off.vertices[mask_off & (val_off == merged)]
        near_parts = t_off.vertices[mask_off & (val_off == parts)]
        for p in t_on.vertices[mask_on & (val_on == merged)]:
            if len(old) and np.linalg.norm(old - p, axis=1).min() < 1e-9 + 0.5 * reach:
                continue  # the default run has this one too
            d = np.linalg.norm(near_parts - p, axis=1)
            assert (d < walk).sum() >= 2, (merged, p, np.sort(d)[:3])
            where_they_stood += (d < reach).sum() >= 2
            checked += 1
    kept = on["aggregated_v4"] + on["aggregated_v8"]
    assert checked >= kept - 2, (checked, kept)
    assert where_they_stood >= kept - on["aggregations_gathered"] - 2, (where_they_stood, kept)


def test_thin_rims_are_not_kept_sharp():
    """The lion (raw, 6.5K vertices) is a shell: its ears are two sheets an edge length or two
    apart, folded over at a sharp rim. The four crease lines around them run straight and sharp
    (over 60 degrees) like a design's crease, but they are a thin part's rims (thin_creases.h):
    the run does not keep them sharp (thin_rim_lines 4), so the irregular vertices next to them
    can be edited. Measured: 315 interior irregular vertices left, 390 with the rims kept
    (native bench, creaseThinEdges=0). Where: of the input's 141 sharp vertices, 106 end farther
    than the crease budget (0.05% of the diagonal) from the result, 52 with the rims kept; every
    one within the Hausdorff budget."""
    ms = load("lion.off")
    t0 = tri(ms)
    out = reduce(ms)
    t1 = tri(ms)
    check_result(out, t0, t1)
    assert out["thin_rim_lines"] == 4
    assert out["interior_irregular_after"] <= 330, out["interior_irregular_after"]
    sharp = fo.crease_vertex_mask(t0, 60)
    assert sharp.sum() == 141
    d = 100 * fo.closest_point_distances(t0.vertices[sharp], t1) / fo.diagonal(t0)
    assert (d > 0.05).sum() >= 80 and d.max() <= 0.5, ((d > 0.05).sum(), d.max())


def test_angle_allowance_lets_more_irregular_vertices_go():
    """The angle allowance (angleAllowance, default 0.8% of the triangles; angleFloor 20): the
    lion remeshed by MeshLab's isotropic remeshing (0.7% of the diagonal, about 17K vertices,
    2.5% of its triangles under 30 degrees). Measured: 95 interior irregular vertices left with
    the allowance, 121 without (angleAllowance 0), where 785 edits were undone for an angle
    instead of 1695; the result's share under 30 degrees 0.52% against 0.30%. Where the
    triangles end: the result keeps under 0.8% of them under 30 degrees, and the allowance adds
    no triangle under the floor (20 degrees) beyond what the run without it leaves."""
    runs = {}
    for allowance in (0.8, 0.0):
        ms = load("lion.off")
        # every parameter named: the remesher keeps some of a previous call's (the cow test's)
        ms.meshing_isotropic_explicit_remeshing(
            targetlen=pymeshlab.PercentageValue(0.7), iterations=5, adaptive=False, selectedonly=False,
            featuredeg=30.0, checksurfdist=True, maxsurfdist=pymeshlab.PercentageValue(1), splitflag=True,
            collapseflag=True, swapflag=True, smoothflag=True, reprojectflag=True)
        t0 = tri(ms)
        out = reduce(ms, angleallowance=allowance)
        t1 = tri(ms)
        check_result(out, t0, t1)
        mn = fo.triangle_angles(t1).min(axis=1)
        runs[allowance] = (out, (mn < 30).mean(), int((mn < 20).sum()))
    (a, share_a, floor_a), (b, share_b, floor_b) = runs[0.8], runs[0.0]
    print("lion remeshed: interior irregular %d with the allowance, %d without; undone for an angle %d, %d; under 30 "
          "degrees %.2f%%, %.2f%%; under 20 degrees %d, %d" % (
              a["interior_irregular_after"], b["interior_irregular_after"], a["undone_angle"], b["undone_angle"],
              100 * share_a, 100 * share_b, floor_a, floor_b))
    assert a["interior_irregular_after"] <= b["interior_irregular_after"] - 10
    assert a["undone_angle"] < b["undone_angle"]
    assert share_a <= 0.008 and share_b <= share_a
    assert floor_a <= floor_b + 2


def test_zero_budget_gives_the_input_back():
    """A 0% budget: every run overshoots, every edit is undone (stop_reason 3): the input's
    vertices and faces, painted."""
    ms = load("mesh_with_border.off")
    before = state(ms)
    out = reduce(ms, hausdorffbudget=0.0)
    after = state(ms)
    assert out["stop_reason"] == 3 and out["irregular_after"] == out["irregular_input"]
    assert np.array_equal(after["faces"], before["faces"])
    assert np.array_equal(after["vertices"], before["vertices"])
    assert np.array_equal(rgb(ms), fo.expected_rgb(tri(ms)))


def test_time_limit_on_a_larger_mesh():
    ms = load("elephant.off")
    t0 = tri(ms)
    out = reduce(ms, timelimit=0.05)
    check_result(out, t0, tri(ms))
    assert out["stop_reason"] == 2 and out["seconds"] < 30


# ------------------------------------------------------------------ protection
def test_protected_region_is_untouched():
    """'Selected region untouched' (elephant, the half x < median selected): the selected
    vertices keep their positions, the faces between them stay as they were, the selection is
    kept."""
    ms = load("elephant.off")
    t0 = tri(ms)
    xs = np.sort(t0.vertices[:, 0])
    cut = float(xs[len(xs) // 2 - 1] + xs[len(xs) // 2]) / 2  # between two vertices, not on one
    ms.compute_selection_by_condition_per_vertex(condselect="(x < %r)" % cut)
    picked = t0.vertices[:, 0] < cut
    assert np.array_equal(ms.current_mesh().vertex_selection_array(), picked)
    out = reduce(ms, protect="Selected region untouched")
    t1 = tri(ms)
    check_result(out, t0, t1)
    where = index_by_position(t0, t1)
    found = np.zeros(len(t0.vertices), bool)
    found[where[where >= 0]] = True
    assert found[picked].all()  # every protected vertex is still where it was
    keep = np.nonzero(picked)[0]

    def faces_among(t, input_index):
        """The faces of t whose corners are all protected, as input indices."""
        f = input_index[t.faces]
        return canonical_faces(f[np.isin(f, keep).all(axis=1)])

    assert faces_among(t1, where) == faces_among(t0, np.arange(len(t0.vertices)))
    assert np.array_equal(np.sort(where[selected(ms)]), keep)  # the selection is kept
    assert out["irregular_after"] < out["irregular_input"]


def test_protected_irregular_vertices_are_kept():
    """'Selected irregular vertices kept': the selected irregular vertices stay where they are
    with their valence (and stay selected); the others are reduced."""
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    irr = np.nonzero(fo.irregular_mask(t0) & ~fo.boundary_mask(t0))[0][:30]
    select(ms, list(irr) + [int(np.nonzero(~fo.irregular_mask(t0))[0][0])])  # and a regular one
    out = reduce(ms, protect="Selected irregular vertices kept")
    t1 = tri(ms)
    check_result(out, t0, t1)
    where = index_by_position(t0, t1)
    v0, v1 = fo.valences(t0), fo.valences(t1)
    for i in irr:
        j = np.nonzero(where == i)[0]
        assert len(j) == 1 and v1[j[0]] == v0[i], i
    assert out["irregular_after"] < out["irregular_input"] - 50


def test_users_colours_and_quality_survive_where_no_edit_reaches():
    """'Colour by valence' off, the half x < 0 of a randomly painted knot1 protected: every
    vertex that did not move keeps its colour and quality, created vertices take those of an
    input vertex, and the painted legend is not applied."""
    ms = painted("knot1.off")
    before = state(ms)
    t0 = tri(ms)
    ms.compute_selection_by_condition_per_vertex(condselect="(x < 0)")
    out = reduce(ms, protect="Selected region untouched", colorize=False)
    t1 = tri(ms)
    check_result(out, t0, t1)
    where = index_by_position(t0, t1)
    unmoved = where >= 0
    assert unmoved.sum() > 0.3 * len(t0.vertices) and unmoved.sum() < len(t1.vertices)
    colours = ms.current_mesh().vertex_color_matrix()
    assert np.array_equal(colours[unmoved], before["colours"][where[unmoved]])
    assert np.array_equal(quality(ms)[unmoved], before["quality"][where[unmoved]])
    palette = {tuple(c) for c in before["colours"].tolist()}
    assert all(tuple(c) in palette for c in colours.tolist())


# ------------------------------------------------------------------ refusals
def test_refusals_leave_the_mesh_unchanged():
    ms = painted("knot1.off")
    select(ms, [])
    refuse(ms, AUTOMATIC, "'Protect the selection' is set but no vertex is selected",
           **dict(DEFAULTS, protect="Selected region untouched"))
    select(ms, [0])
    refuse(ms, AUTOMATIC, ["Remeshing first replaces every vertex", "cannot be protected"],
           **dict(DEFAULTS, protect="Selected irregular vertices kept", remeshedgelength=pymeshlab.PercentageValue(2)))
    # remeshing alone over the budget: the remeshed mesh is replaced by the input, colours,
    # quality and selection included
    refuse(ms, AUTOMATIC, ["alone leaves the input by", "more than the Hausdorff budget (0.01%)"],
           **dict(DEFAULTS, remeshedgelength=pymeshlab.PercentageValue(10), hausdorffbudget=0.01))


def test_a_remeshing_length_that_would_need_billions_of_triangles_is_refused_at_once():
    """remeshEdgeLength 1e-5 on knot1 (diagonal ~ 4.6) would make ~1e11 vertices: refused from
    the area estimate, with the estimate and lengths that work, before any remeshing (the
    filter used to run for hours)."""
    ms = painted("knot1.off")
    t0 = tri(ms)
    area = fo.triangle_areas(t0).sum()
    estimate = 2 * area / (np.sqrt(3) * 1e-5 ** 2)
    assert estimate > 1e10
    start = time.monotonic()
    text = refuse(ms, AUTOMATIC, ["Remeshing to edge length 1e-05 would make about",
                                  "more than this filter accepts (4000000)", "for about 20,000"],
                  **dict(DEFAULTS, remeshedgelength=pymeshlab.PureValue(1e-5)))
    assert time.monotonic() - start < 30  # refused from an estimate, not after remeshing
    # the suggested length for 20,000 vertices is the oracle's
    suggested = float(re.search(r", or ([0-9.e+-]+) for about 20,000", text).group(1))
    assert suggested == pytest.approx(fo.edge_length_for(t0, 20000), rel=1e-3)


def _distance_to_polyline(points, mesh):
    """Distance from each point to the boundary polyline of mesh (its edges with one face)."""
    f = np.asarray(mesh.faces)
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    uniq, count = np.unique(e, axis=0, return_counts=True)
    seg = uniq[count == 1]
    v = np.asarray(mesh.vertices, dtype=np.float64)
    a, b = v[seg[:, 0]], v[seg[:, 1]]
    ab = b - a
    out = np.empty(len(points))
    for i, p in enumerate(np.asarray(points, dtype=np.float64)):
        t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.einsum("ij,ij->i", ab, ab), 0, 1)
        out[i] = np.sqrt((((a + t[:, None] * ab) - p) ** 2).sum(axis=1).min())
    return out


def test_holes_boundary_stays_on_the_input_boundary_and_the_inside_empties():
    """holes.off (chi -5) remeshed by MeshLab's isotropic remeshing to about 10K vertices, then
    reduced: the boundary stage splits and collapses boundary edges, and its relaxation slides
    the boundary vertices along the input's boundary (0.9.13). Where they end up: every boundary
    vertex of the result lies on the input's boundary polyline (a millionth of the diagonal),
    never more boundary irregular vertices than the input had (corner rule), and few interior
    irregular vertices are left (0.5% at 20K in the README's table)."""
    ms = load("holes.off")
    ms.meshing_isotropic_explicit_remeshing(targetlen=pymeshlab.PureValue(0.047), maxsurfdist=pymeshlab.PureValue(0.0047),
                                            iterations=10, adaptive=False, featuredeg=30.0, checksurfdist=False)
    t0 = tri(ms)
    out = reduce(ms)
    t1 = tri(ms)
    check_result(out, t0, t1)
    b0, b1 = fo.boundary_vertex_mask(t0), fo.boundary_vertex_mask(t1)
    assert 7000 < len(t0.vertices) < 13000 and b0.sum() > 300
    d = _distance_to_polyline(t1.vertices[b1], t0)
    assert d.max() <= 1e-6 * fo.diagonal(t0), d.max()
    # the boundary vertices moved along it: many are no longer where the input had one
    moved = (index_by_position(t0, fo.Tri(t1.vertices[b1], np.zeros((0, 3), dtype=np.int64))) < 0).sum()
    assert moved > b1.sum() // 10, (moved, b1.sum())
    irregular0, irregular1 = fo.irregular_mask(t0), fo.irregular_mask(t1)
    assert (irregular1 & b1).sum() == out["boundary_irregular_after"] <= (irregular0 & b0).sum()
    interior = (irregular1 & ~b1).sum()
    assert interior == out["interior_irregular_after"] <= 0.01 * len(t1.vertices), interior
    assert out["boundary_absorbed"] > 0
    print("holes at %d vertices: interior irregular %d -> %d, boundary %d -> %d, %d of %d boundary vertices moved"
          % (len(t0.vertices), (irregular0 & ~b0).sum(), interior, (irregular0 & b0).sum(), (irregular1 & b1).sum(),
             moved, b1.sum()))
