"""'Irregular Vertices: Boundary Operation' through pymeshlab on corpus meshes with holes: an
interior v5 and an interior v7 next to a hole absorbed into it, a boundary v3 moved along the
boundary, a 5-7 pair generated from the boundary and absorbed again, two boundary 5-7 pairs
generated, one moved along the boundary and back until both cancel, an interior v5 two rings
from a hole moved next to it by the Atomic filter and then absorbed, refusals that change
nothing; every result checked against the oracle (invariants, eq. 2, counts by the boundary
valence rule) and by where the vertices are (positions are kept with relax=False)."""
import numpy as np
import pytest

import fi_oracle as fo
from fi_pm import ANALYZE, ATOMIC, apply, index_by_position, load, refuse, select, selected, tri
from test_atomic import check_edit, generation_prediction

BOUNDARY = "meshing_irregular_boundary_operation"
# corpus meshes with holes and irregular vertices next to them (holes.off and mushroom.off have none)
HOLES = ["mesh_with_border.off", "cylinder_locally_refined.off"]


def interior_next_to_boundary(m, valence):
    """Interior vertices of `valence` with a boundary neighbour, ascending."""
    bnd, val = fo.boundary_mask(m), fo.valences(m)
    nb = fo.adjacency_lists(m)
    return [v for v in np.nonzero(~bnd & (val == valence) & fo.referenced_mask(m))[0].tolist()
            if any(bnd[w] for w in nb[v])]


def check(ms, out, t0):
    """Invariants, eq. 2, the boundary loops kept, and the returned counts equal the oracle's."""
    t = tri(ms)
    fo.check_invariants(t)
    assert fo.boundary_loop_count(t) == fo.boundary_loop_count(t0)
    assert fo.euler_characteristic(t) == fo.euler_characteristic(t0)
    irr = fo.irregular_mask(t)
    assert out["irregular_after"] == irr.sum()
    assert out["boundary_irregular_after"] == (irr & fo.boundary_mask(t)).sum()
    assert out["interior_irregular_after"] == (irr & ~fo.boundary_mask(t)).sum()
    return t


def absorb_first(name, valence):
    """Absorbs the first interior v`valence` next to a hole that the filter accepts."""
    ms = load(name)
    t0 = tri(ms)
    for v in interior_next_to_boundary(t0, valence)[:40]:
        select(ms, [v])
        try:
            out = ms.apply_filter(BOUNDARY, operation="Absorb into the boundary", relax=False)
        except Exception:  # noqa: BLE001 - a refusal: try the next candidate (the mesh is unchanged)
            assert np.array_equal(ms.current_mesh().vertex_matrix(), t0.vertices)
            continue
        return ms, t0, v, out
    pytest.fail("no interior v%d next to a hole of %s could be absorbed" % (valence, name))


@pytest.mark.parametrize("name", HOLES)
def test_v5_next_to_a_hole_is_absorbed(name):
    ms, t0, v, out = absorb_first(name, 5)
    t = check(ms, out, t0)
    # a boundary split: one vertex more; the v5 keeps its index and position and is now a v6
    assert len(t.vertices) == len(t0.vertices) + 1
    assert np.array_equal(t.vertices[v], t0.vertices[v])
    assert fo.valences(t)[v] == 6 and not fo.boundary_mask(t)[v]
    # one interior irregular vertex fewer, and everything away from it is as it was
    assert out["interior_irregular_after"] == out["interior_irregular_before"] - 1
    same = index_by_position(t0, t)
    kept = same >= 0
    ring = set(fo.adjacency_lists(t0)[v]) | {v}
    moved_or_new = [i for i in range(len(t.vertices)) if not kept[i] or same[i] in ring]
    far = [i for i in range(len(t.vertices)) if i not in moved_or_new]
    assert np.array_equal(fo.valences(t)[far], fo.valences(t0)[same[far]])
    # the defect is on the boundary now: the selection is the touched boundary irregular vertices
    sel = selected(ms)
    assert all(fo.boundary_mask(t)[sel]) and all(fo.irregular_mask(t)[sel])


@pytest.mark.parametrize("name", HOLES)
def test_v7_next_to_a_hole_is_absorbed(name):
    ms, t0, v, out = absorb_first(name, 7)
    t = check(ms, out, t0)
    assert len(t.vertices) == len(t0.vertices) - 1  # a boundary-edge collapse
    where = index_by_position(t, fo.Tri(t0.vertices[[v]], np.zeros((0, 3))))[0]
    assert where >= 0, "the v7 does not move"
    assert fo.valences(t)[where] == 6
    assert out["interior_irregular_after"] == out["interior_irregular_before"] - 1


@pytest.mark.parametrize("name", HOLES)
def test_boundary_v3_moves_along_the_boundary(name):
    """A boundary v3 on a smooth stretch (a boundary "v5") moves along the boundary: a collapse
    and a split, the vertex count and every count kept, the v3 elsewhere on the boundary."""
    ms = load(name)
    t0 = tri(ms)
    cand = np.nonzero(fo.boundary_mask(t0) & (fo.valences(t0) == 3) & ~fo.corner_mask(t0))[0].tolist()
    assert cand, "no boundary v3 on a smooth stretch"
    for b in cand[:40]:
        select(ms, [b])
        try:
            out = ms.apply_filter(BOUNDARY, operation="Move along the boundary", side="First boundary neighbour",
                                  relax=False)
        except Exception:  # noqa: BLE001 - refused (mesh unchanged): next candidate
            assert np.array_equal(ms.current_mesh().vertex_matrix(), t0.vertices)
            continue
        break
    else:
        pytest.fail("no boundary v3 of %s could move" % name)
    t1 = check(ms, out, t0)
    assert len(t1.vertices) == len(t0.vertices)  # a collapse and a split
    assert out["irregular_after"] == out["irregular_before"]
    assert out["interior_irregular_after"] == out["interior_irregular_before"]
    # the old v3's position is no longer a vertex; the v3 now is a boundary vertex that moved
    p = t0.vertices[b]
    assert not (t1.vertices == p).all(axis=1).any()
    now = [i for i in selected(ms).tolist() if fo.valences(t1)[i] == 3 and fo.boundary_mask(t1)[i]]
    assert len(now) == 1
    assert index_by_position(t0, fo.Tri(t1.vertices[now], np.zeros((0, 3))))[0] == -1


def test_relaxation_slides_boundary_vertices_along_the_boundary_corners_fixed():
    """With relax on, the boundary vertices of the edited 2-ring move along the boundary as it
    was (on its polyline), and corners (|corner angle - 180| >= 30) stay where they were."""
    ms_plain, t0, v, out = absorb_first("cylinder_locally_refined.off", 5)
    ms = load("cylinder_locally_refined.off")
    select(ms, [v])
    out = apply(ms, BOUNDARY, operation="Absorb into the boundary", relax=True)
    t = check(ms, out, t0)
    assert out["relaxed_vertices"] > 0
    b0 = fo.boundary_mask(t0)
    segs = [(t0.vertices[a], t0.vertices[c]) for a, c in fo.unique_edges(t0)[0][fo.unique_edges(t0)[1] == 1].tolist()]

    def dist_to_boundary(p):
        best = np.inf
        for a, c in segs:
            d = c - a
            s = np.clip(np.dot(p - a, d) / np.dot(d, d), 0, 1)
            best = min(best, np.linalg.norm(a + s * d - p))
        return best

    bnd = fo.boundary_mask(t)
    # the same edit without relaxation (a split: indices line up, the new vertex last)
    t_plain = tri(ms_plain)
    assert len(t_plain.vertices) == len(t.vertices)
    moved = [i for i in np.nonzero(bnd)[0].tolist() if (t.vertices[i] != t_plain.vertices[i]).any()]
    assert moved, "relaxation moved no boundary vertex"
    diag = np.linalg.norm(t0.vertices.max(axis=0) - t0.vertices.min(axis=0))
    for i in moved:
        assert dist_to_boundary(t.vertices[i]) < 1e-5 * diag, "boundary vertex %d left the boundary" % i
    # every corner of the input is still a vertex at the same place
    corners = t0.vertices[fo.corner_mask(t0)]
    for p in corners:
        assert (t.vertices == p).all(axis=1).any()
    assert b0.sum() > 0


def test_generated_pair_is_absorbed_again():
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    bnd, val, nb = fo.boundary_mask(t0), fo.valences(t0), fo.adjacency_lists(t0)
    cand = [b for b in np.nonzero(bnd & (val == 4) & ~fo.corner_mask(t0))[0].tolist()
            if all(val[w] == 6 for w in nb[b] if not bnd[w])]
    for b in cand[:40]:
        select(ms, [b])
        try:
            out = ms.apply_filter(BOUNDARY, operation="Generate a 5-7 pair from the boundary",
                                  side="Second boundary neighbour", relax=False)
        except Exception:  # noqa: BLE001 - refused: next candidate
            continue
        break
    else:
        pytest.fail("no boundary vertex could generate a pair")
    t1 = check(ms, out, t0)
    assert out["interior_irregular_after"] == out["interior_irregular_before"] + 2
    assert len(t1.vertices) == len(t0.vertices)  # a flip
    pair = [i for i in selected(ms).tolist() if not fo.boundary_mask(t1)[i]]
    assert sorted(fo.valences(t1)[pair].tolist()) == [5, 7] and fo.adjacent(t1, *pair)
    select(ms, pair)
    out2 = apply(ms, BOUNDARY, operation="Absorb into the boundary", relax=True, colorize=False)
    t2 = check(ms, out2, t1)
    assert out2["interior_irregular_after"] == out["interior_irregular_before"]
    assert out2["irregular_after"] == out["irregular_before"]


def test_refusals_leave_the_mesh_unchanged():
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    six = [v for v in interior_next_to_boundary(t0, 6)][:1]
    select(ms, six)
    refuse(ms, BOUNDARY, "only an interior v5 or v7", operation="Absorb into the boundary")
    select(ms, [])
    refuse(ms, BOUNDARY, "0 are selected", operation="Absorb into the boundary")
    b = int(np.nonzero(fo.boundary_mask(t0) & (fo.valences(t0) == 4))[0][0])
    select(ms, [b])
    refuse(ms, BOUNDARY, "valence 3", operation="Move along the boundary")
    closed = load("knot1.off")
    select(closed, [0])
    refuse(closed, BOUNDARY, "no boundary", operation="Absorb into the boundary")


def test_analyze_after_boundary_edits_agrees():
    ms, t0, v, out = absorb_first("cylinder_locally_refined.off", 5)
    a = apply(ms, ANALYZE, select="None")
    t = tri(ms)
    assert a["boundary_irregular"] == (fo.irregular_mask(t) & fo.boundary_mask(t)).sum()
    assert a["gauss_bonnet_holds"]


def boundary_neighbours(t, v):
    """The two boundary neighbours of boundary vertex v (its ends of boundary edges)."""
    edges, count = fo.unique_edges(t)
    b = edges[count == 1]
    return sorted(set(b[b[:, 0] == v, 1].tolist()) | set(b[b[:, 1] == v, 0].tolist()))


def boundary_pair_of(t, vertices):
    """Among `vertices`, the boundary pairs: (v3, v5) joined by a boundary edge."""
    val, bnd = fo.valences(t), fo.boundary_mask(t)
    return [(a, b) for a in vertices for b in vertices
            if bnd[a] and bnd[b] and val[a] == 3 and val[b] == 5 and b in boundary_neighbours(t, a)]


@pytest.mark.parametrize("name", HOLES)
def test_boundary_pairs_generated_moved_and_cancelled(name):
    """A regular boundary vertex with regular boundary neighbours on a smooth stretch becomes
    two boundary pairs of opposite sign (two vertices more, the vertex itself inside with valence
    6); one pair moves two steps towards its 5 (two ear splits: the new 3 sits exactly where the
    boundary vertex after the old 5 was), then back towards its 3 until it meets the other pair
    and both cancel: the counts are the input's again and every irregular vertex of the input is
    still there, where it was."""
    ms = load(name)
    t0 = tri(ms)
    bnd, val, corner = fo.boundary_mask(t0), fo.valences(t0), fo.corner_mask(t0)
    smooth4 = lambda v: bnd[v] and val[v] == 4 and not corner[v]  # noqa: E731

    def far_enough(b):  # b and three boundary vertices either way: regular, on a smooth stretch
        for first in boundary_neighbours(t0, b):
            prev, cur = b, first
            for _ in range(3):
                if not smooth4(cur):
                    return False
                prev, cur = cur, [w for w in boundary_neighbours(t0, cur) if w != prev][0]
        return smooth4(b)

    cand = [b for b in np.nonzero(bnd)[0].tolist() if far_enough(b)]
    assert cand, "no regular boundary stretch of 7 vertices in %s" % name
    for b in cand[:20]:
        select(ms, [b])
        try:
            out = ms.apply_filter(BOUNDARY, operation="Generate two boundary 5-7 pairs", relax=False)
        except Exception:  # noqa: BLE001 - refused (a fold): next candidate, the mesh is unchanged
            assert np.array_equal(ms.current_mesh().vertex_matrix(), t0.vertices)
            continue
        break
    else:
        pytest.fail("no boundary vertex of %s could generate boundary pairs" % name)
    t1 = check(ms, out, t0)
    n0 = len(t0.vertices)
    assert len(t1.vertices) == n0 + 2
    assert not fo.boundary_mask(t1)[b] and fo.valences(t1)[b] == 6
    assert out["boundary_irregular_after"] == out["boundary_irregular_before"] + 4
    assert out["interior_irregular_after"] == out["interior_irregular_before"]
    sel = selected(ms).tolist()
    assert sorted(fo.valences(t1)[sel].tolist()) == [3, 3, 5, 5] and all(fo.boundary_mask(t1)[sel])
    assert sorted(set(sel) - {n0, n0 + 1}) == boundary_neighbours(t0, b)  # the new 3s are the new vertices
    pairs = boundary_pair_of(t1, sel)
    assert len(pairs) == 2
    x3, y5 = pairs[0]
    # the boundary vertices after y5 (away from x3): where the pair's 3 will be
    after = [w for w in boundary_neighbours(t1, y5) if w != x3][0]
    after2 = [w for w in boundary_neighbours(t1, after) if w != y5][0]
    select(ms, [x3, y5])
    out2 = apply(ms, BOUNDARY, operation="Move a boundary 5-7 pair along the boundary",
                 pairdirection="Towards its valence-5 vertex", steps=2, relax=False)
    t2 = check(ms, out2, t1)
    assert len(t2.vertices) == len(t1.vertices) + 2
    assert out2["irregular_after"] == out2["irregular_before"]
    # the pair now: a new 3 exactly at `after`'s old place, `after2` (kept index) the 5
    v2, b2 = fo.valences(t2), fo.boundary_mask(t2)
    at_after = np.nonzero((t2.vertices == t1.vertices[after]).all(axis=1))[0]
    new3 = [i for i in at_after.tolist() if i >= len(t1.vertices)]
    assert len(new3) == 1 and v2[new3[0]] == 3 and b2[new3[0]]
    assert v2[after2] == 5 and b2[after2]
    assert not b2[y5] and v2[y5] == 6 and not b2[after] and v2[after] == 6
    assert v2[x3] == 4
    assert sorted(selected(ms).tolist()) == sorted([new3[0], after2])
    # back towards its 3: two steps, then the other pair: both cancel
    select(ms, [new3[0], after2])
    out3 = apply(ms, BOUNDARY, operation="Move a boundary 5-7 pair along the boundary",
                 pairdirection="Towards its valence-3 vertex", steps=10, relax=False)
    t3 = check(ms, out3, t2)
    assert len(t3.vertices) == n0
    assert out3["irregular_after"] == fo.irregular_mask(t0).sum()
    assert out3["boundary_irregular_after"] == (fo.irregular_mask(t0) & bnd).sum()
    assert len(selected(ms)) == 0
    # every irregular vertex of the input is still one, at its place
    where = index_by_position(t3, fo.Tri(t0.vertices[fo.irregular_mask(t0)], np.zeros((0, 3))))
    assert (where >= 0).all() and fo.irregular_mask(t3)[where].all()


@pytest.mark.parametrize("name", HOLES)
def test_interior_v5_two_rings_from_a_hole_is_moved_then_absorbed(name):
    """Editing next to a hole (issue 13): an interior v5 two rings from the boundary moves one
    step onto a vertex next to it with the Atomic filter (fig. 7 by an edge flip, every valence
    as the paper says, nothing moved), then the Boundary filter absorbs it there: the moved v5
    is a regular interior vertex, the generated 5-7 pair is where the atomic move put it, and
    the defect has left through the boundary."""
    ms = load(name)
    t0 = tri(ms)
    bnd, val, nb = fo.boundary_mask(t0), fo.valences(t0), fo.adjacency_lists(t0)
    near = lambda v: any(bnd[w] for w in nb[v])  # noqa: E731
    cands = [p for p in np.nonzero(~bnd & (val == 5) & fo.referenced_mask(t0))[0].tolist()
             if not near(p) and any(near(w) for w in nb[p])]
    assert cands, "no interior v5 two rings from a hole in %s" % name
    tried, reasons = 0, []
    for p in cands:
        for k in range(6):
            e = generation_prediction(t0, p, k)
            if e is None:
                continue
            moved = [v for v, d in e.items() if d == 5 and v != p]
            # the moved v5 is n_j (the first of the two new 5s of generation_prediction)
            mv = list(e)[1]
            if not near(mv) or any(bnd[v] or val[v] != 6 for v in e if v != p):
                continue
            tried += 1
            ms = load(name)
            select(ms, [p])
            try:
                ms.apply_filter(ATOMIC, operation="v5/v7 move with 5-7 pair generation", direction=k,
                                via="Edge flip", pairside="Counter-clockwise", relax=False)
            except Exception as ex:  # noqa: BLE001 - refused: record why, try the next direction
                reasons.append("%d/%d: %s" % (p, k, ex))
                continue
            t1 = tri(ms)
            check_edit(t0, t1, e)
            pair = [v for v in moved if v != mv] + [v for v, d in e.items() if d == 7]
            select(ms, [mv])
            try:
                out = ms.apply_filter(BOUNDARY, operation="Absorb into the boundary", relax=False)
            except Exception as ex:  # noqa: BLE001 - refused (e.g. a fold): record why, next
                reasons.append("absorb %d: %s" % (mv, ex))
                continue
            t2 = check(ms, out, t1)
            v2, b2 = fo.valences(t2), fo.boundary_mask(t2)
            assert v2[mv] == 6 and not b2[mv] and np.array_equal(t2.vertices[mv], t0.vertices[mv])
            assert v2[p] == 6
            assert sorted(v2[pair].tolist()) == [5, 7] and not b2[pair].any()
            assert out["interior_irregular_after"] == out["interior_irregular_before"] - 1
            # interior irregular vertices: the input's, without p, with the generated pair
            i0 = set(np.nonzero(fo.irregular_mask(t0) & ~bnd)[0].tolist())
            i2 = set(np.nonzero(fo.irregular_mask(t2) & ~b2)[0].tolist())
            assert i2 == (i0 - {p}) | set(pair)
            return
    pytest.fail("no interior v5 two rings from a hole of %s was moved and absorbed (%d tries): %s"
                % (name, tried, "; ".join(reasons[:8])))
