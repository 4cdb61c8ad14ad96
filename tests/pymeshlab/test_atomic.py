"""'Irregular Vertices: Atomic Operation' through pymeshlab: every operation, every direction of
the 5-7 pair move, predicted vertex by vertex by the oracle from the input's faces (the paper's
sec. 6.1-6.2 rules, neighbours counted counter-clockwise as the plugin documents), then
checked on the output: which vertices end up with which valence, which are selected, that no
other vertex changed valence or moved (relax off), the returned counts; refusals leave the
mesh as it was."""
import numpy as np
import pytest

import fi_oracle as fo
from fi_pm import (ATOMIC, OPERATIONS, apply, assert_counts, assert_same_state, canonical_faces, load, painted,
                   quality, refuse, rgb, select, selected, state, tri)

# knot1: an adjacent 5-7 pair with no other irregular vertex within 3 edges, and a second one.
PAIR = (206, 2273)   # (v5, v7)
PAIR2 = (400, 2115)
# knot1: regular vertices with no irregular vertex within 3 edges.
REGULAR = [25, 82]


def check_edit(t0, t1, expect, created=(), deleted=(), moved=()):
    """The output t1 of an edit without relaxation, with MeshLab's compaction: the input's
    vertices but the `deleted` ones keep their order, created vertices (their valences listed in
    `created`) come last; every kept vertex but those of `moved` (a split vertex) sits exactly
    where it was; the vertices of `expect` (input index -> valence) have that valence and every
    other one kept its own. Returns, for each output vertex, its input index (-1: created)."""
    n0 = len(t0.vertices)
    kept = np.delete(np.arange(n0), list(deleted))
    assert len(t1.vertices) == len(kept) + len(created), "vertex count %d, expected %d" % (
        len(t1.vertices), len(kept) + len(created))
    where = np.concatenate([kept, np.full(len(created), -1)])
    v0, v1 = fo.valences(t0), fo.valences(t1)
    assert sorted(v1[len(kept):].tolist()) == sorted(created), "created vertices"
    still = ~np.isin(kept, list(moved))
    assert np.array_equal(t1.vertices[:len(kept)][still], t0.vertices[kept][still]), "a vertex moved"
    want = v0[kept].copy()
    for i, d in expect.items():
        want[np.nonzero(kept == i)[0]] = d
    wrong = np.nonzero(v1[:len(kept)] != want)[0]
    assert len(wrong) == 0, "valences differ at input vertices %s: %s, expected %s" % (
        kept[wrong][:10].tolist(), v1[:len(kept)][wrong][:10].tolist(), want[wrong][:10].tolist())
    fo.check_invariants(t1)
    return where


def selected_inputs(ms, where):
    """The selected output vertices as input indices (-1 for created vertices), sorted."""
    return sorted(where[selected(ms)].tolist())


def pair_move_prediction(t0, v5, v7, d):
    """The paper's 5-7 pair move (fig. 6) in direction d, counted counter-clockwise around the
    v5 from the v7: (valences after, created, deleted, selected input vertices, moved)."""
    n = lambda k: fo.neighbour_from(t0, v5, k, ref=v7)  # noqa: E731
    m = lambda k: fo.neighbour_from(t0, v7, k, ref=v5)  # noqa: E731
    if d in (1, 4):  # flip (v7, y): the pair moves to (y, z)
        y = n(d)
        z = [o for o in fo.opposite_vertices(t0, v7, y) if o != v5][0]
        return {v5: 6, v7: 6, y: 5, z: 7}, [], [], sorted([y, z]), []
    if d in (2, 3):  # collapse x into the v5: the pair moves to (c, v5)
        x, c = n(1 if d == 2 else 4), n(d)
        return {v5: 7, v7: 6, c: 5}, [], [x], sorted([c, v5]), [v5]
    b = m(4 if d == 0 else 3)  # split the v7 along (v7, v5) and (v7, b): the pair moves to (v7, b)
    return {v7: 5, v5: 6, b: 7}, [6], [], sorted([v7, b]), [v7]


@pytest.mark.parametrize("pair", [PAIR, PAIR2])
@pytest.mark.parametrize("direction", range(6))
def test_pair_move_every_direction_lands_where_the_paper_says(pair, direction):
    v5, v7 = pair
    ms = load("knot1.off")
    t0 = tri(ms)
    assert fo.valences(t0)[[v5, v7]].tolist() == [5, 7] and fo.adjacent(t0, v5, v7)
    expect, created, deleted, sel, moved = pair_move_prediction(t0, v5, v7, direction)
    select(ms, [v7, v5])  # selection order does not matter
    out = apply(ms, ATOMIC, operation="5-7 pair move", direction=direction, relax=False, colorize=True)
    t1 = tri(ms)
    where = check_edit(t0, t1, expect, created, deleted, moved)
    assert selected_inputs(ms, where) == sel
    assert out["changed_vertices"] == 4 and out["relaxed_vertices"] == 0 and out["selected"] == 2
    assert_counts(out, t0, "_before")
    assert_counts(out, t1, "_after")
    assert out["irregular_after"] == out["irregular_before"]
    # the legend and the valence in quality, on the result
    assert np.array_equal(rgb(ms), fo.expected_rgb(t1))
    assert np.array_equal(quality(ms), fo.valences(t1).astype(float))


def test_pair_move_with_relaxation_moves_only_the_two_ring_onto_the_surface():
    v5, v7 = PAIR
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [v5, v7])
    out = apply(ms, ATOMIC, operation="5-7 pair move", direction=1, relax=True)
    t1 = tri(ms)
    expect, _, _, sel, _ = pair_move_prediction(t0, v5, v7, 1)
    assert np.array_equal(t1.faces.shape, t0.faces.shape)
    # a flip keeps indices: valences as predicted, selection as predicted
    v0, v1 = fo.valences(t0), fo.valences(t1)
    want = v0.copy()
    for i, d in expect.items():
        want[i] = d
    assert np.array_equal(v1, want)
    assert sorted(selected(ms).tolist()) == sel
    # the relaxed region is the 2-ring of the four changed vertices, as returned
    ring = fo.hop_distances(t1, list(expect))
    region = (ring >= 0) & (ring <= 2)
    assert out["relaxed_vertices"] == region.sum()
    moved = np.linalg.norm(t1.vertices - t0.vertices, axis=1) > 0
    assert moved.any() and not moved[~region].any()
    # moved vertices are projected back onto the input surface
    d = fo.closest_point_distances(t1.vertices[moved], t0)
    assert d.max() <= 1e-6 * fo.diagonal(t0), d.max()
    fo.check_invariants(t1)


def tangent_angles(t0, p, ref=None):
    """The plugin's directions (directions.h): the angle in degrees, counter-clockwise in p's
    tangent plane (normal: area-weighted face normals), of each neighbour of p (one_ring
    order), measured from the edge to ref or, with ref None, from the world +X axis projected
    into the plane (+Y when the plane faces X)."""
    f, v = t0.faces, t0.vertices.astype(np.float64)
    rows = f[(f == p).any(axis=1)]
    n = np.cross(v[rows[:, 1]] - v[rows[:, 0]], v[rows[:, 2]] - v[rows[:, 0]]).sum(axis=0)
    n /= np.linalg.norm(n)
    axis = (v[ref] - v[p]) if ref is not None else (np.array([0.0, 1, 0]) if abs(n[0]) > 0.9 else np.array([1.0, 0, 0]))
    x = axis - n * axis.dot(n)
    x /= np.linalg.norm(x)
    y = np.cross(n, x)
    ring = fo.one_ring(t0, p)
    d = v[ring] - v[p]
    return ring, np.degrees(np.arctan2(d @ y, d @ x)) % 360.0


def sector_neighbour(t0, p, k, ref=None):
    """The neighbour of p in the 60-degree sector k (centred on 60k degrees) nearest the
    sector's centre, ties to the smaller angle; (index in one_ring order, ring), or (None, ring)."""
    ring, ang = tangent_angles(t0, p, ref)
    best = None
    for i, a in enumerate(ang):
        if int(((a + 30.0) % 360.0) // 60.0) % 6 != k:
            continue
        gap = min(abs(a - 60.0 * k) % 360.0, 360.0 - abs(a - 60.0 * k) % 360.0)
        if best is None or gap < best[0] - 1e-3 or (gap <= best[0] + 1e-3 and a < best[1]):
            best = (gap, a, i)
    return (None if best is None else best[2]), ring


def generation_prediction(t0, p, k, ref=None):
    """The paper's move with 5-7 pair generation (fig. 7) of the v5 or v7 p into sector k by an
    edge flip with the new pair counter-clockwise: valences after, by input vertex, or None
    when no neighbour lies in the sector (a v5's sixth direction goes into a new vertex)."""
    i, ring = sector_neighbour(t0, p, k, ref)
    if i is None:
        return None
    n = lambda j: ring[(i + j) % len(ring)]  # noqa: E731
    if fo.valences(t0)[p] == 5:  # flip the link edge (n_j, n_j+1): n_j is the moved v5, (n_j+1, z) the pair
        z = [o for o in fo.opposite_vertices(t0, n(0), n(1)) if o != p][0]
        return {p: 6, n(0): 5, n(1): 5, z: 7}
    return {p: 6, n(1): 5, n(0): 7, n(2): 7}  # flip (p, n_j+1): n_j is the moved v7, (n_j+1, n_j+2) the pair


@pytest.mark.parametrize("p", list(PAIR))
def test_move_with_pair_generation_then_removal(p):
    """A v5 (v7) moves into each 60-degree sector (from the projected +X axis) whose
    neighbour and flip vertices are regular and leaves a 5-7 pair on the counter-clockwise
    side; the triple cancellation of the three selected vertices (sec. 6.2) puts the mesh
    back exactly as it was."""
    probe = load("knot1.off")
    t0 = tri(probe)
    val = fo.valences(t0)
    ks = []
    for k in range(6):
        e = generation_prediction(t0, p, k)
        if e is not None and all(val[i] == 6 for i in e if i != p):
            ks.append(k)
    assert len(ks) >= 2, ks
    for k in ks:
        ms = load("knot1.off")
        expect = generation_prediction(t0, p, k)
        select(ms, [p])
        out = apply(ms, ATOMIC, operation="v5/v7 move with 5-7 pair generation", direction=k, via="Edge flip",
                    pairside="Counter-clockwise", relax=False, colorize=True)
        t1 = tri(ms)
        check_edit(t0, t1, expect)
        assert sorted(selected(ms).tolist()) == sorted(i for i, d in expect.items() if d != 6), k
        assert out["irregular_after"] == out["irregular_before"] + 2
        assert_counts(out, t1, "_after")
        out = apply(ms, ATOMIC, operation="v5/v7 move with 5-7 pair removal (triple cancellation)", relax=False)
        t2 = tri(ms)
        assert canonical_faces(t2.faces) == canonical_faces(t0.faces), k
        assert np.array_equal(t2.vertices, t0.vertices)
        assert out["irregular_after"] == out["irregular_before"] - 2
        assert fo.valences(t2)[selected(ms)].tolist() == [val[p]]


@pytest.mark.parametrize("p", list(PAIR))
def test_move_with_pair_generation_from_a_selected_reference_edge(p):
    """With the vertex and one neighbour r selected, direction 0 moves toward r (the
    reference edge), whatever the vertex indices: the flip puts the moved vertex on r."""
    t0 = tri(load("knot1.off"))
    val = fo.valences(t0)
    for r in fo.one_ring(t0, p):
        e = generation_prediction(t0, p, 0, ref=r)
        if e is None or not all(val[i] == 6 for i in e if i != p):
            continue
        assert e[r] == val[p]  # the moved vertex is the one on the reference edge
        ms = load("knot1.off")
        select(ms, [p, r])
        apply(ms, ATOMIC, operation="v5/v7 move with 5-7 pair generation", direction=0, via="Edge flip",
              pairside="Counter-clockwise", relax=False)
        check_edit(t0, tri(ms), e)
        return
    pytest.fail("no neighbour of %d allows the move" % p)


def test_move_with_pair_generation_toward_a_point():
    """'Toward point': the sector of the point's direction, the same as naming it."""
    p = PAIR[0]
    t0 = tri(load("knot1.off"))
    val = fo.valences(t0)
    ring, ang = tangent_angles(t0, p)
    for i, r in enumerate(ring):
        k = int(((ang[i] + 30.0) % 360.0) // 60.0) % 6
        e = generation_prediction(t0, p, k)
        if e is None or not all(val[j] == 6 for j in e if j != p):
            continue
        ms = load("knot1.off")
        select(ms, [p])
        target = t0.vertices[p] + 3.0 * (t0.vertices[r] - t0.vertices[p])
        apply(ms, ATOMIC, operation="v5/v7 move with 5-7 pair generation", towardpoint=True,
              point=target, direction=(k + 3) % 6, via="Edge flip", pairside="Counter-clockwise", relax=False)
        check_edit(t0, tri(ms), e)
        return
    pytest.fail("no direction of %d allows the move" % p)


@pytest.mark.parametrize("k", range(6))
def test_quadruple_generation_by_flip_every_direction_and_removal(k):
    p = REGULAR[0]
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [p])
    i, ring = sector_neighbour(t0, p, k)
    if i is None:  # the mesh's angles leave this sector without an edge
        refuse(ms, ATOMIC, "points into direction %d" % k, operation="5-5-7-7 generation by flip", direction=k)
        return
    n = lambda j: ring[(i + j) % 6]  # noqa: E731
    expect = {p: 5, n(0): 5, n(-1): 7, n(1): 7}
    out = apply(ms, ATOMIC, operation="5-5-7-7 generation by flip", direction=k, relax=False, colorize=True)
    t1 = tri(ms)
    check_edit(t0, t1, expect)
    assert sorted(selected(ms).tolist()) == sorted(expect)
    assert out["v5_after"] == out["v5_before"] + 2 and out["v7_after"] == out["v7_before"] + 2
    assert_counts(out, t0, "_before")
    assert_counts(out, t1, "_after")
    out = apply(ms, ATOMIC, operation="5-5-7-7 removal", relax=False)
    t2 = tri(ms)
    assert canonical_faces(t2.faces) == canonical_faces(t0.faces)
    assert np.array_equal(t2.vertices, t0.vertices)
    assert out["irregular_after"] == out["irregular_before"] - 4


def test_example_round_trip_on_the_bunny():
    """examples/atomic.mlx: the bunny's vertex 98 becomes a 5-5-7-7 quadruple (by flip) that
    the removal then cancels; with relaxation on, the valences are the input's again."""
    ms = load("bunny00.off")
    t0 = tri(ms)
    select(ms, [98])
    apply(ms, ATOMIC, operation="5-5-7-7 generation by flip", direction=0, relax=True, colorize=True)
    assert sorted(fo.valences(tri(ms))[selected(ms)].tolist()) == [5, 5, 7, 7]
    out = apply(ms, ATOMIC, operation="5-5-7-7 removal", direction=0, relax=True, colorize=True)
    t2 = tri(ms)
    assert np.array_equal(fo.valences(t2), fo.valences(t0))
    assert out["irregular_after"] == out["irregular_before"] - 4
    fo.check_invariants(t2)


@pytest.mark.parametrize("k", range(6))
def test_quadruple_generation_by_split_adds_one_vertex_where_predicted(k):
    p = REGULAR[1]
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [p])
    i, ring = sector_neighbour(t0, p, k)
    if i is None:  # the mesh's angles leave this sector without an edge
        refuse(ms, ATOMIC, "points into direction %d" % k, operation="5-5-7-7 generation by split", direction=k)
        return
    n = lambda j: ring[(i + j) % 6]  # noqa: E731
    out = apply(ms, ATOMIC, operation="5-5-7-7 generation by split", direction=k, relax=False, colorize=True)
    t1 = tri(ms)
    assert len(t1.vertices) == len(t0.vertices) + 1 and len(t1.faces) == len(t0.faces) + 2
    where = check_edit(t0, t1, {p: 5, n(0): 7, n(3): 7}, created=[5], moved=[p])
    # the split vertex and the new one sit on either side of where p was, within its 1-ring
    reach = np.linalg.norm(t0.vertices[fo.one_ring(t0, p)] - t0.vertices[p], axis=1).max()
    assert np.linalg.norm(t1.vertices[[p, -1]] - t0.vertices[p], axis=1).max() < reach
    assert selected_inputs(ms, where) == sorted([-1, p, n(0), n(3)])
    assert out["v5_after"] == out["v5_before"] + 2 and out["v7_after"] == out["v7_before"] + 2
    assert_counts(out, t1, "_after")
    # the removal collapses it again: the input's connectivity and positions
    apply(ms, ATOMIC, operation="5-5-7-7 removal", relax=False)
    t2 = tri(ms)
    assert len(t2.vertices) == len(t0.vertices)
    assert np.array_equal(np.sort(fo.valences(t2)), np.sort(fo.valences(t0)))
    fo.check_invariants(t2)


@pytest.mark.parametrize("k", range(6))
def test_quadruple_generation_by_collapse_and_split_through_a_v8(k):
    """Fig. 8's two-operation configuration: the neighbour n_k in sector k collapses into p
    (a v8), which splits along its edges to n_k+3 and to q (opposite p across n_k), three
    edges on each side: 5s at n_k-1 and n_k+1, 7s at n_k+3 and q; n_k deleted, one vertex
    created (regular); the removal undoes it."""
    p = REGULAR[1]
    ms = load("knot1.off")
    t0 = tri(ms)
    select(ms, [p])
    i, ring = sector_neighbour(t0, p, k)
    if i is None:  # the mesh's angles leave this sector without an edge
        refuse(ms, ATOMIC, "points into direction %d" % k, operation="5-5-7-7 generation by collapse and split",
               direction=k)
        return
    n = lambda j: ring[(i + j) % 6]  # noqa: E731
    rk = fo.one_ring(t0, n(0))
    q = rk[(rk.index(p) + 3) % 6]
    out = apply(ms, ATOMIC, operation="5-5-7-7 generation by collapse and split", direction=k, relax=False,
                colorize=True)
    t1 = tri(ms)
    where = check_edit(t0, t1, {n(-1): 5, n(1): 5, n(3): 7, q: 7}, created=[6], deleted=[n(0)], moved=[p])
    assert selected_inputs(ms, where) == sorted([n(-1), n(1), n(3), q])
    assert out["v5_after"] == out["v5_before"] + 2 and out["v7_after"] == out["v7_before"] + 2
    apply(ms, ATOMIC, operation="5-5-7-7 removal", relax=False)
    t2 = tri(ms)
    assert len(t2.vertices) == len(t0.vertices)
    assert np.array_equal(np.sort(fo.valences(t2)), np.sort(fo.valences(t0)))
    fo.check_invariants(t2)


def test_edge_flip():
    a, b = REGULAR[0], fo.neighbour_from(tri(load("knot1.off")), REGULAR[0], 2)
    ms = load("knot1.off")
    t0 = tri(ms)
    c, d = fo.opposite_vertices(t0, a, b)
    select(ms, [a, b])
    out = apply(ms, ATOMIC, operation="Edge flip", relax=False)
    t1 = tri(ms)
    check_edit(t0, t1, {a: 5, b: 5, c: 7, d: 7})
    assert fo.adjacent(t1, c, d) and not fo.adjacent(t1, a, b)
    assert out["selected"] == len(selected(ms)) and set(selected(ms).tolist()) <= {a, b, c, d}


def test_edge_collapse_keeps_the_lower_index():
    ms = load("knot1.off")
    t0 = tri(ms)
    a = REGULAR[0]
    b = fo.neighbour_from(t0, a, 1)
    lo, hi = min(a, b), max(a, b)
    c, d = fo.opposite_vertices(t0, a, b)
    select(ms, [a, b])
    out = apply(ms, ATOMIC, operation="Edge collapse", relax=False)
    t1 = tri(ms)
    assert len(t1.vertices) == len(t0.vertices) - 1 and len(t1.faces) == len(t0.faces) - 2
    where = check_edit(t0, t1, {lo: 6 + 6 - 4, c: 5, d: 5}, deleted=[hi], moved=[lo])
    # the survivor sits at the midpoint of the edge
    assert np.allclose(t1.vertices[np.nonzero(where == lo)[0][0]], (t0.vertices[lo] + t0.vertices[hi]) / 2)
    # the irregular vertices it produced are selected: the v8 and the two v5 (README)
    assert selected_inputs(ms, where) == sorted([lo, c, d])
    assert out["changed_vertices"] == 4  # lo, c, d, and hi deleted
    assert out["v8_after"] == out["v8_before"] + 1 and out["v5_after"] == out["v5_before"] + 2


def test_vertex_split_keeps_the_counter_clockwise_side():
    """Split of c along (c, a) and (c, b), selected as three vertices: c keeps the neighbours
    from a to b counter-clockwise (a < b < c by index here, as the selection is read in index
    order), the new vertex the others; a and b gain an edge each."""
    ms = load("knot1.off")
    t0 = tri(ms)
    c = REGULAR[1]
    ring = fo.one_ring(t0, c)
    a, b = ring[0], ring[3]  # opposite neighbours: not adjacent to each other
    sel = sorted([a, b, c])
    i = sel.index(c)
    first, second = sel[(i + 1) % 3], sel[(i + 2) % 3]
    r = fo.one_ring(t0, c)
    j0, j1 = r.index(first), r.index(second)
    between = (j1 - j0) % len(r) - 1  # neighbours strictly between first and second, counter-clockwise
    select(ms, [a, b, c])
    out = apply(ms, ATOMIC, operation="Vertex split", relax=False)
    t1 = tri(ms)
    assert len(t1.vertices) == len(t0.vertices) + 1 and len(t1.faces) == len(t0.faces) + 2
    new_valence = len(r) - 2 - between + 3
    check_edit(t0, t1, {c: between + 3, a: 7, b: 7}, created=[new_valence], moved=[c])
    assert out["selected"] == len(selected(ms))


@pytest.mark.parametrize("operation", ["Edge flip", "Edge collapse", "Vertex split"])
def test_graph_operations_return_the_vertices_whose_valence_changed(operation):
    """README: changed_vertices counts the 'vertices whose valence the operation changed'. On
    a regular patch a flip changes 4 (ends -1, opposite vertices +1), a collapse 4 (the
    survivor, the two opposite vertices, the deleted one), a split 4 (the split vertex, the new
    one, the two neighbours)."""
    ms = load("knot1.off")
    t0 = tri(ms)
    c = REGULAR[1]
    r = fo.one_ring(t0, c)
    select(ms, {"Edge flip": [c, r[0]], "Edge collapse": [c, r[0]], "Vertex split": [c, r[0], r[3]]}[operation])
    out = apply(ms, ATOMIC, operation=operation, relax=False)
    t1 = tri(ms)
    assert len(t1.vertices) == len(t0.vertices) + {"Edge flip": 0, "Edge collapse": -1, "Vertex split": 1}[operation]
    assert out["changed_vertices"] == 4, out["changed_vertices"]


# ------------------------------------------------------------------ refusals
def test_a_single_irregular_vertex_cannot_move_alone():
    ms = load("knot1.off")
    select(ms, [PAIR[0]])
    refuse(ms, ATOMIC, "Theorem 5.1", operation="5-7 pair move", direction=0)


@pytest.mark.parametrize("operation", [2, 5])
def test_a_five_seven_pair_cannot_be_cancelled(operation):
    ms = load("bunny00.off")
    t0 = tri(ms)
    val = fo.valences(t0)
    e, _ = fo.unique_edges(t0)
    a, b = next((a, b) for a, b in e.tolist() if {val[a], val[b]} == {5, 7})
    select(ms, [a, b])
    refuse(ms, ATOMIC, "Theorem 5.5", operation=OPERATIONS[operation])


@pytest.mark.parametrize("operation,count,words", [
    (0, 3, "needs exactly 2 selected vertices (two); 3 are selected"),
    (1, 3, "needs one selected vertex, or that vertex and one of its neighbours"),
    (2, 4, "needs exactly 3 selected vertices (three); 4 are selected"),
    (3, 3, "needs one selected vertex, or that vertex and one of its neighbours"),
    (4, 0, "needs one selected vertex, or that vertex and one of its neighbours"),
    (5, 3, "needs exactly 4 selected vertices (four); 3 are selected"),
    (6, 1, "needs exactly 2 selected vertices (two); 1 are selected"),
    (7, 3, "needs exactly 2 selected vertices (two); 3 are selected"),
    (8, 2, "needs exactly 3 selected vertices (three); 2 are selected"),
])
def test_wrong_selection_count_is_refused(operation, count, words):
    ms = load("knot1.off")
    select(ms, [REGULAR[0] + i for i in range(count)])
    refuse(ms, ATOMIC, words, operation=OPERATIONS[operation], direction=0)


def test_refusals_that_name_the_obstacle():
    ms = load("knot1.off")
    t0 = tri(ms)
    # quadruple generation from an irregular vertex
    select(ms, [PAIR[0]])
    refuse(ms, ATOMIC, "generated from a regular vertex", operation="5-5-7-7 generation by flip")
    # a pair that is not adjacent
    select(ms, [PAIR[0], PAIR2[1]])
    refuse(ms, ATOMIC, "are not adjacent", operation="5-7 pair move")
    # a direction beyond the pair's six (in the parameter's range, refused by the operation)
    select(ms, list(PAIR))
    refuse(ms, ATOMIC, "the direction must be 0..5", operation="5-7 pair move", direction=6)
    # three vertices of a triangle: which one splits is ambiguous
    p = REGULAR[1]
    r = fo.one_ring(t0, p)
    select(ms, [p, r[0], r[1]])
    refuse(ms, ATOMIC, "Ambiguous vertex split", operation="Vertex split")
    # three vertices none of which neighbours the other two
    select(ms, [p, r[0], REGULAR[0]])
    refuse(ms, ATOMIC, "a vertex and two of its neighbours", operation="Vertex split")
    # an irregular vertex in the way of the pair's step
    select(ms, [47, 3186])
    refuse(ms, ATOMIC, "is in the way", operation="5-7 pair move", direction=1)


def test_boundary_vertex_is_refused():
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    b = int(np.nonzero(fo.boundary_mask(t0))[0][0])
    select(ms, [b])
    refuse(ms, ATOMIC, "boundary", operation="5-5-7-7 generation by flip")


def test_colorize_off_keeps_the_users_colours_and_quality():
    """With 'Colour by valence' off, a flip keeps every colour and quality (no vertex is
    created or deleted); with it on, the legend and valences replace them."""
    ms = painted("knot1.off")
    before = state(ms)
    select(ms, list(PAIR))
    apply(ms, ATOMIC, operation="5-7 pair move", direction=1, relax=True, colorize=False)
    after = state(ms)
    assert np.array_equal(after["colours"], before["colours"])
    assert np.array_equal(after["quality"], before["quality"])
    assert not np.array_equal(after["faces"], before["faces"])


def test_deterministic():
    results = []
    for _ in range(2):
        ms = load("knot1.off")
        select(ms, list(PAIR))
        apply(ms, ATOMIC, operation="5-7 pair move", direction=0, relax=True)
        results.append(state(ms))
    assert_same_state(results[0], results[1], "second run")
