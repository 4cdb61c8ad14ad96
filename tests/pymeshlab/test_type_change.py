"""Type change (sec. 6.3, fig. 9; vcg_ext/irregular/type_change.h) through pymeshlab: Reduce to
Valence 5 and 7 splits a vk into exactly k-6 v7 (a v4 into two v5) and changes no other
irregular vertex; Aggregate merges them back into the same vertex (same triangles); a v10 and
a v12 are built by Aggregate from v7s and reduced back; refusals say what to do and leave the
mesh unchanged."""
import numpy as np
import pytest

import fi_oracle as fo
from fi_pm import (AGGREGATE, REDUCE, apply, canonical_faces, from_arrays, index_by_position, load, refuse,
                   select, selected, tri)


def cone(k, radius=6):
    """k sectors of the regular triangular lattice glued around vertex 0 (valence k), planar;
    the centre's neighbours counter-clockwise are 1..k (see tests/unit/test_type_change.cpp)."""
    def vid(s, a, b):
        s %= k
        if a == 0 and b == 0:
            return 0
        if a == 0:
            return vid(s + 1, b, 0)
        d = a + b
        return 1 + k * d * (d - 1) // 2 + s * d + b
    n = 1 + k * radius * (radius + 1) // 2
    pts = np.zeros((n, 3))
    for s in range(k):
        for d in range(1, radius + 1):
            for b in range(d):
                a = d - b
                x, y = a + 0.5 * b, b * np.sqrt(3) / 2
                phi = (s + np.arctan2(y, x) / (np.pi / 3)) * 2 * np.pi / k
                pts[vid(s, a, b)] = [np.hypot(x, y) * np.cos(phi), np.hypot(x, y) * np.sin(phi), 0]
    faces = []
    for s in range(k):
        for a in range(radius):
            for b in range(radius - a):
                faces.append([vid(s, a, b), vid(s, a + 1, b), vid(s, a, b + 1)])
                if a + b < radius - 1:
                    faces.append([vid(s, a + 1, b), vid(s, a + 1, b + 1), vid(s, a, b + 1)])
    return from_arrays(pts, np.array(faces))


def neighbours(t, v):
    """The vertices joined to v by an edge, from the face list."""
    f = np.asarray(t.faces)
    return set(f[(f == v).any(axis=1)].ravel().tolist()) - {v}


def test_camel_v10_splits_into_exactly_four_v7_and_aggregates_back():
    """camel's v10 number 144: four v7 on the sides of a chain of regular vertices, every other
    irregular vertex kept (place and valence, relaxation off); Aggregate gives back the v10 at
    vertex 144 with exactly the input's triangles."""
    ms = load("camel.off")
    t0 = tri(ms)
    assert fo.valences(t0)[144] == 10
    select(ms, [144])
    out = apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    t1 = tri(ms)
    assert (out["reduced"], out["not_reduced"]) == (1, 0)
    assert len(t1.vertices) == len(t0.vertices) + 2  # a chain of three vertices
    sel = selected(ms).tolist()
    assert sorted(sel) == [2636, 4628, 4632, 4752]  # neighbours of 144: the sides of the chain
    assert all(fo.valences(t1)[v] == 7 for v in sel)
    assert set(sel) <= neighbours(t0, 144)
    # nothing else: every other input irregular vertex at the same place with the same valence
    where = index_by_position(t0, t1)
    v0, v1 = fo.valences(t0), fo.valences(t1)
    irr0 = set(np.nonzero(fo.irregular_mask(t0))[0].tolist()) - {144}
    kept = {int(w) for j, w in enumerate(where) if w in irr0 and v1[j] == v0[w]}
    assert kept == irr0
    assert int(fo.irregular_mask(t1).sum()) == int(fo.irregular_mask(t0).sum()) - 1 + 4
    out = apply(ms, AGGREGATE, relax=False, colorize=False)
    t2 = tri(ms)
    assert out["atomic_steps"] == 2  # two collapses
    assert selected(ms).tolist() == [144]
    assert fo.valences(t2)[144] == 10
    assert canonical_faces(t2.faces) == canonical_faces(t0.faces)
    fo.check_invariants(t2)


@pytest.mark.parametrize("k", [10, 12])
def test_a_v10_and_a_v12_are_built_by_aggregate_and_reduced_back(k):
    """On a cone patch the vk splits into k-6 v7 in two rows (ids from the chain
    configuration), Aggregate builds the v(6+n) from them at the centre, Reduce splits it
    again into the same v7s."""
    ms = cone(k)
    t0 = tri(ms)
    assert fo.valences(t0)[0] == k
    select(ms, [0])
    apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    # orientation 0: sides r0, r4, then r(4+p), r(k-p): ids 1, 5, 6, 10 (k = 10); 1, 5, 6, 7, 11, 12 (k = 12)
    v7 = sorted(selected(ms).tolist())
    assert v7 == ([1, 5, 6, 10] if k == 10 else [1, 5, 6, 7, 11, 12])
    t1 = tri(ms)
    assert all(fo.valences(t1)[v] == 7 for v in v7)
    out = apply(ms, AGGREGATE, relax=True, colorize=False)
    t2 = tri(ms)
    assert selected(ms).tolist() == [0]
    assert fo.valences(t2)[0] == k
    assert out["atomic_steps"] == (k - 6) // 2
    assert canonical_faces(t2.faces) == canonical_faces(t0.faces)
    fo.check_invariants(t2)
    apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    assert sorted(selected(ms).tolist()) == v7


def test_v9_into_three_v7_and_back():
    """bunny's v9 number 351: the vertex stays the odd v7 at the chain's end, with two v7
    neighbours; Aggregate (three v7: a seed and a facing pair) restores it."""
    ms = load("bunny00.off")
    t0 = tri(ms)
    select(ms, [351])
    apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    assert sorted(selected(ms).tolist()) == [351, 1749, 8061]
    t1 = tri(ms)
    assert sorted(fo.valences(t1)[[351, 1749, 8061]].tolist()) == [7, 7, 7]
    apply(ms, AGGREGATE, relax=False, colorize=False)
    t2 = tri(ms)
    assert selected(ms).tolist() == [351]
    assert canonical_faces(t2.faces) == canonical_faces(t0.faces)


def test_aggregate_refuses_v7s_that_do_not_face_each_other():
    """Two v7 of the same row (adjacent) are not a mergeable pair: the refusal says to move
    them (Move Pair) and the mesh is unchanged."""
    ms = cone(12)
    select(ms, [0])
    apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    select(ms, [5, 6])
    refuse(ms, AGGREGATE, ["cannot", "Move Pair"], relax=False, colorize=False)


def test_aggregate_refuses_adjacent_v5():
    """A v3 splits into three v5 in a triangle; two of them are adjacent and cannot become a
    v4 (sec. 3); the three become the v3 again."""
    ms = cone(3)
    t0 = tri(ms)
    select(ms, [0])
    apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
    # neighbour 1 collapsed into the centre: the centre and neighbours 2, 3 are the v5s, which
    # are 0, 1, 2 once the deleted vertex is compacted away
    assert sorted(selected(ms).tolist()) == [0, 1, 2]
    select(ms, [0, 1])
    refuse(ms, AGGREGATE, "adjacent", relax=False, colorize=False)
    select(ms, [0, 1, 2])
    apply(ms, AGGREGATE, relax=False, colorize=False)
    t2 = tri(ms)
    assert sorted(fo.valences(t2)[selected(ms)].tolist()) == [3]
    assert np.array_equal(np.sort(fo.valences(t2)), np.sort(fo.valences(t0)))
    fo.check_invariants(t2)
