"""The composite filters (sec. 6.3, 7) through pymeshlab: Reduce to Valence 5 and 7, Aggregate,
Move Pair, Cancel Triple, Cancel Quadruple, Generate. Every parameter; where the irregular
vertices end up (graph distances, the neighbour a lead vertex moves to, the vertex nearest a
target point), that nothing else changes (relaxation off: every other irregular vertex keeps
its place and valence), round trips back to the input, returned counts against the oracle,
refusals with an unchanged mesh, and the user's colours with 'Colour by valence' off."""
import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import (AGGREGATE, CANCEL_QUADRUPLE, CANCEL_TRIPLE, GENERATE, MOVE_PAIR, REDUCE, apply, assert_counts,
                   assert_same_state, index_by_position, load, painted, quality, refuse, rgb,
                   select, selected, state, tri)

PAIR = (206, 2273)       # knot1: an adjacent 5-7 pair with no other irregular vertex within 3 edges
EXAMPLE_PAIR = (47, 3186)  # knot1: the pair of examples/move_pair.mlx
REGULAR = [25, 82]       # knot1: regular vertices with no irregular vertex within 3 edges


def hist(m):
    return np.bincount(fo.valences(m)[fo.irregular_mask(m)], minlength=16)


def preserved_irregular(t0, t1):
    """Input irregular vertices found at exactly the same position with the same valence in
    the output, and how many there were."""
    where = index_by_position(t0, t1)
    v0, v1 = fo.valences(t0), fo.valences(t1)
    irr = fo.irregular_mask(t0)
    kept = {int(w) for j, w in enumerate(where) if w >= 0 and irr[w] and v1[j] == v0[w]}
    return len(kept), int(irr.sum())


def mesh_set(t):
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=t.vertices, face_matrix=t.faces.astype(np.int32)))
    return ms


# ------------------------------------------------------------------ Reduce, Aggregate
def test_reduce_everything_on_the_bunny():
    """examples/reduce.mlx: every v3, v4 and v8+ is reduced to v5s and v7s; those left are
    exactly the ones the filter says it could not reduce."""
    ms = load("bunny00.off")
    t0 = tri(ms)
    out = apply(ms, REDUCE, scope="All irregular vertices", relax=True, colorize=True)
    t1 = tri(ms)
    assert_counts(out, t0, "_before")
    assert_counts(out, t1, "_after")
    left = out["v3_after"] + out["v4_after"] + out["v8_after"] + out["v9_after"]
    assert left == out["not_reduced"]
    before = out["v3_before"] + out["v4_before"] + out["v8_before"] + out["v9_before"]
    assert left < 0.1 * before, (before, left)
    assert out["reduced"] > 0.9 * before
    sel = selected(ms)
    assert out["selected"] == len(sel) > 0
    assert np.array_equal(rgb(ms), fo.expected_rgb(t1))
    fo.check_invariants(t1)


def test_reduce_selects_the_irregular_vertices_it_leaves():
    """The filter's help: 'The resulting irregular vertices are selected' (README: composite
    filters 're-select the irregular vertices they leave'): no regular vertex is selected."""
    ms = load("bunny00.off")
    apply(ms, REDUCE, scope="All irregular vertices", relax=True, colorize=True)
    t1 = tri(ms)
    sel = selected(ms)
    regular = sel[~fo.irregular_mask(t1)[sel]]
    assert len(regular) == 0, "%d of %d selected vertices are regular (e.g. %s)" % (
        len(regular), len(sel), regular[:5].tolist())


@pytest.mark.parametrize("vertex,valence,into,dv", [(43, 8, [7, 7], 1), (179, 4, [5, 5], -1)])
def test_reduce_selected_then_aggregate_restores(vertex, valence, into, dv):
    """examples/aggregate.mlx: the bunny's v8 number 43 splits into two v7 (a v4 collapses into
    two v5); Aggregate merges them back: the input's valence histogram, the vertex selected."""
    ms = load("bunny00.off")
    t0 = tri(ms)
    assert fo.valences(t0)[vertex] == valence
    select(ms, [vertex])
    out = apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=True)
    t1 = tri(ms)
    assert (out["reduced"], out["not_reduced"]) == (1, 0)
    assert len(t1.vertices) == len(t0.vertices) + dv
    assert sorted(fo.valences(t1)[selected(ms)].tolist()) == into
    assert out["v%d_after" % valence] == out["v%d_before" % valence] - 1
    # nothing but the reduced vertex's neighbourhood changed
    kept, total = preserved_irregular(t0, t1)
    assert kept >= total - 8, (kept, total)
    out = apply(ms, AGGREGATE, relax=True, colorize=True)
    t2 = tri(ms)
    assert np.array_equal(hist(t2), hist(t0))
    assert len(t2.vertices) == len(t0.vertices)
    assert fo.valences(t2)[selected(ms)].tolist() == [valence]
    assert_counts(out, t2, "_after")
    fo.check_invariants(t2)


def test_reduce_refuses_when_there_is_nothing_to_reduce():
    ms = load("knot1.off")  # only v5 and v7
    refuse(ms, REDUCE, "no interior vertex of valence other than 5, 6 and 7", scope="All irregular vertices")
    select(ms, [3, 4])
    refuse(ms, REDUCE, "no interior vertex of valence other than 5, 6 and 7", scope="Selected vertices")


def test_aggregate_refuses_regular_vertices():
    ms = load("knot1.off")
    val = fo.valences(tri(ms))
    select(ms, [int(i) for i in np.nonzero(val == 6)[0][:2]])
    refuse(ms, AGGREGATE, "aggregation merges only", relax=True, colorize=True)


# ------------------------------------------------------------------ Move Pair
def test_move_pair_example():
    """examples/move_pair.mlx: knot1's pair 47-3186, 5 steps in direction 0."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, list(EXAMPLE_PAIR))
    out = apply(ms, MOVE_PAIR, lead="Lower valence", direction=0, steps=5, towardpoint=False,
                point=np.zeros(3), relax=True, colorize=True)
    t1 = tri(ms)
    assert out["atomic_steps"] == 5
    assert np.array_equal(hist(t1), hist(t0))
    assert sorted(fo.valences(t1)[selected(ms)].tolist()) == [5, 7]
    assert_counts(out, t0, "_before")
    assert_counts(out, t1, "_after")
    fo.check_invariants(t1)


@pytest.mark.parametrize("direction,steps,min_hops", [(1, 30, 24), (0, 30, 10), (1, 10, 8)])
def test_long_move_goes_far_and_touches_nothing_else(direction, steps, min_hops):
    """Without relaxation a pair of `steps` steps ends at least `min_hops` edges from where it
    started (direction 1 glides by flips, almost straight), every other irregular vertex of
    the knot keeps its place and valence, and the pair stays a 5-7 pair."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, list(PAIR))
    out = apply(ms, MOVE_PAIR, direction=direction, steps=steps, relax=False)
    t1 = tri(ms)
    assert out["atomic_steps"] == steps
    assert np.array_equal(hist(t1), hist(t0))
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 7] and fo.adjacent(t1, *sel)
    start = t0.vertices[list(PAIR)].mean(axis=0)
    nearest = int(np.argmin(np.linalg.norm(t1.vertices - start, axis=1)))
    assert fo.hop_distances(t1, [nearest])[sel].min() >= min_hops
    kept, total = preserved_irregular(t0, t1)
    assert kept == total - 2, (kept, total)
    fo.check_invariants(t1)


@pytest.mark.parametrize("hops", [4, 6, 8])
def test_move_toward_point_ends_next_to_it(hops):
    """'Toward point': the pair stops next to the target vertex (at most one edge away)."""
    ms = load("knot1.off")
    t0 = tri(ms)
    target = int(np.nonzero(fo.hop_distances(t0, list(PAIR)) == hops)[0][0])
    select(ms, list(PAIR))
    out = apply(ms, MOVE_PAIR, lead="Lower valence", direction=3, steps=1, towardpoint=True,
                point=t0.vertices[target], relax=True, colorize=True)
    t1 = tri(ms)
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 7]
    near = int(np.argmin(np.linalg.norm(t1.vertices - t0.vertices[target], axis=1)))
    assert fo.hop_distances(t1, [near])[sel].min() <= 1
    assert hops - 1 <= out["atomic_steps"] <= hops + 2  # 'steps' and 'direction' are ignored
    assert np.array_equal(hist(t1), hist(t0))


def quadruple(spacing=3):
    """knot1 with a 5-5-7-7 quadruple generated at the regular vertex 25 (direction 0)."""
    ms = load("knot1.off")
    select(ms, [REGULAR[0]])
    apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=0, spacing=spacing, relax=False)
    return tri(ms)


@pytest.mark.parametrize("lead,direction", [("Lower valence", 0), ("Lower index", 0), ("Higher valence", 2),
                                            ("Higher index", 3)])
def test_non_adjacent_pair_lead_vertex_moves_to_its_neighbour(lead, direction):
    """A non-adjacent 5-7 pair (sec. 7.1.1): the lead (the v5 for 'Lower valence', the v7 for
    'Higher valence'; by index otherwise) moves one step toward its neighbour `direction` -
    a v5 onto that neighbour, a v7 onto the next one counter-clockwise (fig. 7) - and the
    partner follows one step."""
    tq = quadruple()
    v5, v7 = 1897, 2158
    assert fo.valences(tq)[[v5, v7]].tolist() == [5, 7] and not fo.adjacent(tq, v5, v7)
    lead_vertex = {"Lower valence": v5, "Higher valence": v7, "Lower index": min(v5, v7),
                   "Higher index": max(v5, v7)}[lead]
    k = direction
    landing = fo.neighbour_from(tq, lead_vertex, k if lead_vertex == v5 else k + 1)
    ms = mesh_set(tq)
    select(ms, [v5, v7])
    out = apply(ms, MOVE_PAIR, lead=lead, direction=direction, steps=1, relax=False)
    t1 = tri(ms)
    where = index_by_position(tq, t1)
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 7]
    at = np.nonzero(where == landing)[0]
    assert len(at) == 1 and at[0] in sel and fo.valences(t1)[at[0]] == fo.valences(tq)[lead_vertex]
    # the lead left its place: the vertex there is regular now
    left = np.nonzero(where == lead_vertex)[0]
    assert len(left) == 0 or fo.valences(t1)[left[0]] == 6
    assert out["atomic_steps"] >= 2 and np.array_equal(hist(t1), hist(tq))
    fo.check_invariants(t1)


def test_non_adjacent_pair_keeps_its_relative_position_or_refuses():
    """Sec. 7.1.1: the pair translates. Where no cancellation next to the partner moves it by
    the lead's step (the v7 leading toward its neighbour 4 here, with the other pair's
    vertices beside both), the move is refused and the mesh is unchanged."""
    tq = quadruple()
    ms = mesh_set(tq)
    select(ms, [1897, 2158])
    refuse(ms, MOVE_PAIR, "would not keep its relative position", lead="Higher valence", direction=4, steps=1,
           relax=False)


def test_five_five_pair_moves_both():
    """A 5-5 pair (sec. 7.1.2): the lead moves onto its neighbour `direction`, the partner one
    step too, the mirrored one (its step points the other way); where no cancellation gives
    the mirrored step (direction 0 here: 7s next to both), the move is refused, mesh unchanged."""
    tq = quadruple()
    a, b = 24, 1897
    assert fo.valences(tq)[[a, b]].tolist() == [5, 5] and not fo.adjacent(tq, a, b)
    ms = mesh_set(tq)
    select(ms, [a, b])
    refuse(ms, MOVE_PAIR, "mirror image of the lead's step", lead="Lower index", direction=0, steps=1, relax=False)
    apply(ms, MOVE_PAIR, lead="Lower index", direction=1, steps=1, relax=False)
    t1 = tri(ms)
    where = index_by_position(tq, t1)
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 5]
    landing = fo.neighbour_from(tq, a, 1)
    assert landing in where[sel]  # the lead is on its neighbour 1
    assert b not in where[sel]  # the partner moved too
    other = int(next(v for v in sel if where[v] != landing))
    lead_step = tq.vertices[landing] - tq.vertices[a]
    partner_step = t1.vertices[other] - tq.vertices[b]
    assert np.dot(lead_step, partner_step) < 0  # the mirrored step
    assert np.array_equal(hist(t1), hist(tq))


def test_move_pair_refusals():
    ms = load("knot1.off")
    select(ms, [PAIR[0]])
    refuse(ms, MOVE_PAIR, "Theorem 5.1", steps=3)
    select(ms, [PAIR[0], PAIR[1], 5])
    refuse(ms, MOVE_PAIR, "Moving a pair needs exactly 2 selected vertices; 3 are selected")
    select(ms, list(EXAMPLE_PAIR))
    refuse(ms, MOVE_PAIR, ["step 1 of 5", "is in the way"], direction=1, steps=5)


# ------------------------------------------------------------------ Generate, Cancel
@pytest.mark.parametrize("p", REGULAR)
@pytest.mark.parametrize("spacing", [0, 1, 2, 4])
def test_generate_quadruple_spacing(p, spacing):
    """A regular vertex becomes a 5-5-7-7 quadruple; its second 5-7 pair makes `spacing` steps,
    none back toward the first pair (sec. 7.3's greedy placement made monotone): the quadruple
    spans spacing + 2 edges, or spacing + 1 where a step could only go sideways (the knot's
    surface at vertex 25, spacing 4). Exact shapes: test_generate_a_quadruple_of_a_given_shape."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [p])
    out = apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=0, spacing=spacing, relax=False,
                colorize=True)
    t1 = tri(ms)
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 5, 7, 7]
    span = max(fo.hop_distances(t1, [s])[sel].max() for s in sel)
    assert spacing + 1 <= span <= spacing + 2 and (span == spacing + 2 or spacing == 4)
    assert out["atomic_steps"] == spacing + 1
    assert out["v5_after"] == out["v5_before"] + 2 and out["v7_after"] == out["v7_before"] + 2
    assert_counts(out, t1, "_after")
    kept, total = preserved_irregular(t0, t1)
    assert kept == total
    # cancelling the quadruple gives the input's valences back
    out = apply(ms, CANCEL_QUADRUPLE, relax=False, colorize=True)
    t2 = tri(ms)
    assert np.array_equal(np.sort(fo.valences(t2)), np.sort(fo.valences(t0)))
    assert out["irregular_after"] == out["irregular_before"] - 4 and out["selected"] == 0


@pytest.mark.parametrize("p,valence,direction", [(206, 5, 1), (36, 5, 1), (2115, 7, 3)])
@pytest.mark.parametrize("spacing", [0, 2])
def test_generate_triple_then_cancel_triple_restores_the_input(p, valence, direction, spacing):
    """examples/cancel_triple.mlx (knot1 vertex 36): a v5 becomes a 5-5-7 triple (a v7 a 5-7-7
    one), the triple is cancelled: one vertex of the input's valence is left, and without
    relaxation the input's valences and triangles are back."""
    ms = load("knot1.off")
    t0 = tri(ms)
    assert fo.valences(t0)[p] == valence
    select(ms, [p])
    out = apply(ms, GENERATE, kind="Triple from a v5 or v7", direction=direction, spacing=spacing, relax=False)
    t1 = tri(ms)
    assert sorted(fo.valences(t1)[selected(ms)].tolist()) == sorted([5, 7, valence])
    assert out["atomic_steps"] == spacing + 1
    out = apply(ms, CANCEL_TRIPLE, relax=False, colorize=True)
    t2 = tri(ms)
    assert fo.valences(t2)[selected(ms)].tolist() == [valence]
    assert out["irregular_after"] == out["irregular_before"] - 2
    assert np.array_equal(np.sort(fo.valences(t2)), np.sort(fo.valences(t0)))
    assert np.array_equal(hist(t2), hist(t0))
    fo.check_invariants(t2)


@pytest.mark.parametrize("script", ["cancel_triple", "cancel_quadruple"])
def test_examples_generate_then_cancel_with_relaxation(script):
    ms = load("knot1.off")
    t0 = tri(ms)
    if script == "cancel_triple":
        select(ms, [36])
        apply(ms, GENERATE, kind="Triple from a v5 or v7", direction=1, spacing=2, relax=True, colorize=True)
        out = apply(ms, CANCEL_TRIPLE, relax=True, colorize=True)
    else:
        select(ms, [0])
        apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=3, spacing=2, relax=True, colorize=True)
        out = apply(ms, CANCEL_QUADRUPLE, relax=True, colorize=True)
    t1 = tri(ms)
    assert np.array_equal(hist(t1), hist(t0))
    assert_counts(out, t1, "_after")
    fo.check_invariants(t1)


def test_generate_example():
    """examples/generate.mlx: knot1's vertex 0 becomes a quadruple, spacing 2."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [0])
    out = apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=3, spacing=2, relax=True, colorize=True)
    t1 = tri(ms)
    h0, h1 = hist(t0), hist(t1)
    assert h1[5] == h0[5] + 2 and h1[7] == h0[7] + 2
    assert sorted(fo.valences(t1)[selected(ms)].tolist()) == [5, 5, 7, 7]
    assert_counts(out, t1, "_after")
    fo.check_invariants(t1)


@pytest.mark.parametrize("side1direction,side1,side2direction,side2", [(4, 3, 1, 2), (4, 2, 1, 0), (4, 3, 0, 2)])
def test_generate_a_quadruple_of_a_given_shape_then_cancel_it(side1direction, side1, side2direction, side2):
    """Sec. 7.3, fig. 11: the quadruple's second pair is placed by exactly side1 + side2
    atomic steps (atomic_steps = 1 + side1 + side2), the first pair stays where the generating
    flip put it (regular vertex 25's neighbours), and Cancel Quadruple restores the valence
    histogram; a shape that runs into the other pair is refused, mesh unchanged."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [REGULAR[0]])
    out = apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=0, shape="Parallelogram (quadruple)",
                side1direction=side1direction, side1=side1, side2direction=side2direction, side2=side2, relax=False)
    t1 = tri(ms)
    assert out["atomic_steps"] == 1 + side1 + side2
    sel = selected(ms)
    assert sorted(fo.valences(t1)[sel].tolist()) == [5, 5, 7, 7]
    assert 24 in sel.tolist() and 2158 in sel.tolist()  # the pair that stayed
    fo.check_invariants(t1)
    apply(ms, CANCEL_QUADRUPLE, relax=False)
    assert np.array_equal(hist(tri(ms)), hist(t0))
    fo.check_invariants(tri(ms))


def test_generate_shape_that_runs_into_the_other_pair_is_refused():
    ms = load("knot1.off")
    select(ms, [REGULAR[0]])
    refuse(ms, GENERATE, ["placing the generated 5-7 pair", "is in the way"], kind="Quadruple from a regular vertex",
           direction=0, shape="Parallelogram (quadruple)", side1direction=1, side1=3, side2direction=4, side2=2,
           relax=False)


def test_composite_refusals():
    ms = load("knot1.off")
    select(ms, list(PAIR))
    refuse(ms, CANCEL_TRIPLE, "Theorem 5.5", relax=True, colorize=True)
    refuse(ms, CANCEL_QUADRUPLE, "Theorem 5.5", relax=True, colorize=True)
    select(ms, [PAIR[0], PAIR[1], 5, 6, 7])
    refuse(ms, CANCEL_QUADRUPLE, "A quadruple cancellation needs exactly 4 selected vertices; 5 are selected")
    refuse(ms, CANCEL_TRIPLE, "A triple cancellation needs exactly 3 selected vertices; 5 are selected")
    refuse(ms, GENERATE, "Generation needs exactly 1 selected vertices; 5 are selected")
    select(ms, [REGULAR[0]])
    refuse(ms, GENERATE, "vertex 25 has valence 6; this operation moves a v5 or a v7", kind="Triple from a v5 or v7")
    select(ms, [PAIR[0]])
    refuse(ms, GENERATE, "generated from a regular vertex; vertex 206 has valence 5",
           kind="Quadruple from a regular vertex")


def test_cancel_quadruple_of_two_distant_mirror_pairs():
    """Two of knot1's 5-7 pairs that are mirror images: one travels to the other and both
    disappear; every other irregular vertex keeps its place and valence."""
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, list(PAIR) + [400, 2115])
    out = apply(ms, CANCEL_QUADRUPLE, relax=False, colorize=True)
    t1 = tri(ms)
    assert out["irregular_after"] == out["irregular_before"] - 4 and out["atomic_steps"] > 10
    kept, total = preserved_irregular(t0, t1)
    assert kept == total - 4
    fo.check_invariants(t1)


def test_cancel_quadruple_refuses_pairs_that_are_not_mirror_images():
    """Two 5-7 pairs that are not mirror images cannot annihilate (sec. 7.3, fig. 11)."""
    ms = load("knot1.off")
    select(ms, list(PAIR) + [2286, 570])
    refuse(ms, CANCEL_QUADRUPLE, ["do not annihilate", "fig. 11"], relax=True, colorize=True)


# ------------------------------------------------------------------ colours, determinism
def test_users_colours_and_quality_survive_where_no_edit_reaches():
    """'Colour by valence' off, a 20-step pair move with relaxation on a randomly painted
    knot1: every vertex keeps the colour and quality it had, and created vertices take those
    of a vertex of the input (the one they were split from)."""
    ms = painted("knot1.off")
    before = state(ms)
    t0 = tri(ms)
    select(ms, list(EXAMPLE_PAIR))
    apply(ms, MOVE_PAIR, direction=0, steps=20, relax=True, colorize=False)
    t1 = tri(ms)
    where = index_by_position(t0, t1)
    unmoved = where >= 0
    assert unmoved.sum() > 0.3 * len(t0.vertices) and unmoved.sum() < len(t1.vertices)
    colours, q = ms.current_mesh().vertex_color_matrix(), quality(ms)
    assert np.array_equal(colours[unmoved], before["colours"][where[unmoved]])
    assert np.array_equal(q[unmoved], before["quality"][where[unmoved]])
    palette = {tuple(c) + (x,) for c, x in zip(before["colours"].tolist(), before["quality"].tolist())}
    assert all(tuple(c) + (x,) in palette for c, x in zip(colours.tolist(), q.tolist()))
    fo.check_invariants(t1)


def test_composite_filters_are_deterministic():
    runs = []
    for _ in range(2):
        ms = load("knot1.off")
        select(ms, list(EXAMPLE_PAIR))
        apply(ms, MOVE_PAIR, direction=0, steps=8, relax=True)
        select(ms, [0])
        apply(ms, GENERATE, kind="Quadruple from a regular vertex", direction=3, spacing=2, relax=True)
        runs.append(state(ms))
    assert_same_state(runs[0], runs[1], "second run")
