"""'Irregular Vertices: Pattern' through pymeshlab (issue 15, paper sec. 10, Fig. 1): on corpus
meshes before and after Automatic Reduction, the returned measures against an independent count
from what the filter wrote (face quality = region id, face colour = kind of region): strips,
conflict faces and their connected components (numpy/scipy over the face adjacency), strips
connected, neighbouring strips alternating; the mesh's geometry untouched; refusals leave the
mesh unchanged."""
import numpy as np
import pymeshlab
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

import fi_oracle as fo
from fi_pm import AUTOMATIC, apply, load, refuse, select, state, tri

PATTERN = "compute_color_irregular_pattern"
MAGENTA = (255, 0, 255)


def face_adjacency(faces):
    """Pairs (f, g) of faces sharing an edge (manifold: each interior edge once)."""
    f = np.asarray(faces, dtype=np.int64)
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    owner = np.tile(np.arange(len(f)), 3)
    key = np.sort(e, axis=1)
    order = np.lexsort((key[:, 1], key[:, 0]))
    k, o = key[order], owner[order]
    same = np.all(k[1:] == k[:-1], axis=1)
    return np.stack([o[:-1][same], o[1:][same]], axis=1)


def components(n, pairs, mask):
    """Connected components of the faces in `mask` through `pairs` (both ends in the mask)."""
    idx = np.nonzero(mask)[0]
    if len(idx) == 0:
        return 0
    sub = -np.ones(n, dtype=np.int64)
    sub[idx] = np.arange(len(idx))
    p = pairs[mask[pairs[:, 0]] & mask[pairs[:, 1]]]
    g = coo_matrix((np.ones(len(p)), (sub[p[:, 0]], sub[p[:, 1]])), shape=(len(idx), len(idx)))
    return connected_components(g, directed=False)[0]


def written(ms):
    """(region id per face, kind per face: 'A', 'B', 'conflict' or 'other') from the face
    quality and colour the filter wrote."""
    m = ms.current_mesh()
    q = m.face_scalar_array()
    c = np.rint(m.face_color_matrix()[:, :3] * 255).astype(np.int64)
    region = np.rint(q).astype(np.int64)
    assert np.array_equal(region, q), "face quality must hold integer region ids"
    kind = np.full(len(q), "other", dtype=object)
    kind[np.all(c == MAGENTA, axis=1)] = "conflict"
    blue = (c[:, 2] > c[:, 0]) & ~np.all(c == MAGENTA, axis=1)
    sand = (c[:, 0] > c[:, 2]) & (c[:, 1] > c[:, 2])
    kind[blue] = "A"
    kind[sand] = "B"
    return region, kind


def check_against_written(ms, out, period=2):
    """Every measure the filter returned that the written colours and quality determine."""
    region, kind = written(ms)
    faces = ms.current_mesh().face_matrix()
    n = len(faces)
    pairs = face_adjacency(faces)
    strip = (kind == "A") | (kind == "B")
    strip_ids = np.unique(region[strip])
    assert out["strips"] == len(strip_ids)
    # strips come first, then conflict regions: ids are dense
    assert np.array_equal(strip_ids, np.arange(len(strip_ids)))
    assert out["regions"] == len(np.unique(region))
    # one kind per region, each strip connected
    for r in strip_ids[:200]:
        mask = region == r
        assert len(set(kind[mask])) == 1
        assert components(n, pairs, mask) == 1, "strip %d is not connected" % r
    conflict = kind == "conflict"
    assert out["conflict_faces"] == int(conflict.sum())
    assert out["conflict_regions"] == components(n, pairs, conflict)
    assert out["conflict_regions"] == len(np.unique(region[conflict]))
    hist = np.asarray(out["strip_width_histogram"], dtype=np.int64)
    assert hist.sum() == out["strips"]
    assert out["strip_width_1"] == (hist[1] if len(hist) > 1 else 0)
    assert out["strip_width_2"] == (hist[2] if len(hist) > 2 else 0)
    assert out["strip_width_3_or_more"] == hist[3:].sum()
    cells = np.asarray(out["cell_sides_histogram"], dtype=np.int64)
    assert cells.sum() == out["cells"]
    assert out["non_hexagonal_cells"] == out["cells"] - (cells[6] if len(cells) > 6 else 0)
    # the seed's strip is region 0, an A strip
    if out["strips"]:
        assert kind[out["seed_face"]] == "A" and region[out["seed_face"]] == 0
    # alternation: with period 2 most neighbouring strips differ (odd cycles of strips make a
    # few equal pairs)
    a, b = region[pairs[:, 0]], region[pairs[:, 1]]
    across = strip[pairs[:, 0]] & strip[pairs[:, 1]] & (a != b)
    if period == 2 and across.any():
        differ = kind[pairs[across, 0]] != kind[pairs[across, 1]]
        assert differ.mean() > 0.5
    return region, kind


def pattern(ms, **kw):
    params = dict(pattern="Stripes", direction=0, period=2, panels=False)
    params.update(kw)
    before = ms.current_mesh().vertex_matrix().copy(), ms.current_mesh().face_matrix().copy()
    out = apply(ms, PATTERN, **params)
    m = ms.current_mesh()
    assert np.array_equal(m.vertex_matrix(), before[0]) and np.array_equal(m.face_matrix(), before[1]), \
        "the pattern must not change geometry or connectivity"
    return out


def wide(out):
    return out["strip_width_2"] + out["strip_width_3_or_more"]


REDUCE = dict(targetcount=0, hausdorffbudget=0.5, minangle=30, maxtravel=12, protect="Nothing", relaxation="Local",
              timelimit=0, colorize=True, remeshedgelength=pymeshlab.PureValue(0))


def before_after(ms):
    """Stripes and zebra before and after Automatic Reduction: (stripes, zebra) dicts each."""
    res = []
    for _ in range(2):
        s = pattern(ms)
        check_against_written(ms, s)
        z = pattern(ms, pattern="Zebra")
        check_against_written(ms, z)
        assert z["conflict_faces"] == 0
        res.append((s, z))
        if len(res) == 1:
            apply(ms, AUTOMATIC, **REDUCE)
    return res


def report(name, res):
    def short(h):
        h = np.asarray(h, int)
        return "w1 %d, w2 %d, w3+ %d, widest %d" % (h[1] if len(h) > 1 else 0, h[2] if len(h) > 2 else 0, h[3:].sum(),
                                                    len(h) - 1)
    for when, (s, z) in zip(("before", "after"), res):
        print("%s %s: strips %d (%s) conflict faces %d in %d regions, cells %d non-hex %d | zebra strips %d (%s)"
              % (name, when, s["strips"], short(s["strip_width_histogram"]), s["conflict_faces"],
                 s["conflict_regions"], s["cells"], s["non_hexagonal_cells"], z["strips"],
                 short(z["strip_width_histogram"])))


def test_three_peaks_before_and_after_reduction():
    """Fig. 1's story on the corpus' architecture-like model: after reduction fewer wide strips
    and fewer faces in conflict."""
    ms = load("three_peaks.off")
    res = before_after(ms)
    report("three_peaks", res)
    (s0, _), (s1, _) = res
    assert wide(s1) < wide(s0) and s1["strip_width_2"] < s0["strip_width_2"]
    assert s1["conflict_faces"] < s0["conflict_faces"]
    assert s1["non_hexagonal_cells"] < s0["non_hexagonal_cells"]
    assert s1["strip_width_1"] / s1["strips"] > s0["strip_width_1"] / s0["strips"]


def test_bunny_remeshed_before_and_after_reduction():
    """bunny00 remeshed by MeshLab to about 5000 vertices (for speed), then reduced."""
    ms = load("bunny00.off")
    length = fo.edge_length_for(tri(ms), 5000)
    ms.meshing_isotropic_explicit_remeshing(iterations=10, targetlen=pymeshlab.PureValue(length))
    res = before_after(ms)
    report("bunny", res)
    (s0, _), (s1, _) = res
    assert wide(s1) < wide(s0) and s1["strip_width_2"] < s0["strip_width_2"]
    assert s1["conflict_faces"] < s0["conflict_faces"]
    assert s1["non_hexagonal_cells"] < s0["non_hexagonal_cells"]


@pytest.mark.parametrize("direction", [0, 1, 2])
def test_seed_from_the_selected_vertex_and_the_three_directions(direction):
    """A selected vertex seeds the pattern at one of its faces; the three directions give three
    different strip families on the same mesh."""
    ms = load("three_peaks.off")
    select(ms, [500])
    out = pattern(ms, direction=direction)
    f = ms.current_mesh().face_matrix()
    assert 500 in f[out["seed_face"]]
    region, _ = check_against_written(ms, out)
    other = pattern(ms, direction=(direction + 1) % 3)
    assert not np.array_equal(region, written(ms)[0])
    assert other["seed_face"] == out["seed_face"]


def test_period_three():
    """Period 3: A B B. Strips cut off from the others by conflicts start again at A, so count
    contacts: two B strips side by side exist (never with period 2 without an odd cycle), two A
    strips side by side are rarer than an A beside a B."""
    ms = load("three_peaks.off")
    out = pattern(ms, period=3)
    check_against_written(ms, out, period=3)
    region, kind = written(ms)
    pairs = face_adjacency(ms.current_mesh().face_matrix())
    a, b = pairs[:, 0], pairs[:, 1]
    across = (region[a] != region[b]) & np.isin(kind[a], ["A", "B"]) & np.isin(kind[b], ["A", "B"])
    contacts = {tuple(sorted((kind[x], kind[y]))) for x, y in pairs[across]}
    pair_kinds = [tuple(sorted((kind[x], kind[y]))) for x, y in
                  {tuple(sorted((region[x], region[y]))): (x, y) for x, y in pairs[across]}.values()]
    assert ("B", "B") in contacts
    assert pair_kinds.count(("A", "A")) < pair_kinds.count(("A", "B"))


def test_refusals_leave_the_mesh_unchanged():
    for name, (v, f, words) in fo.bad_meshes().items():
        if name in ("non-manifold edge", "polygons"):
            from fi_pm import from_arrays
            refuse(from_arrays(v, f), PATTERN, words, pattern="Stripes")
    ms = load("three_peaks.off")
    refuse(ms, PATTERN, "'direction'", direction=3)
    refuse(ms, PATTERN, "'period'", period=0)
    refuse(ms, PATTERN, "'panelInset'", panelinset=0.9)


def regular_torus(n, k, R=3.0, r=1.0):
    """test_mesh.h's RegularTorus: vertex (i, j) = i * k + j, faces (a, b, c), (a, c, d)."""
    i, j = np.meshgrid(np.arange(n), np.arange(k), indexing="ij")
    a, b = 2 * np.pi * i / n, 2 * np.pi * j / k
    v = np.stack([(R + r * np.cos(b)) * np.cos(a), (R + r * np.cos(b)) * np.sin(a), r * np.sin(b)], -1).reshape(-1, 3)
    faces = []
    for ii in range(n):
        for jj in range(k):
            A, B = ii * k + jj, ((ii + 1) % n) * k + jj
            C, D = ((ii + 1) % n) * k + (jj + 1) % k, ii * k + (jj + 1) % k
            faces += [(A, B, C), (A, C, D)]
    return v, np.array(faces)


@pytest.mark.parametrize("direction,strips", [(0, 6), (1, 12), (2, 6)])
def test_regular_torus_exact(direction, strips):
    """A regular 12 x 6 torus: every strip a single row of width one (k, n or gcd(n, k) strips
    for the three directions), alternating, 24 hexagonal cells, no conflict; the zebra is the same."""
    from fi_pm import from_arrays
    v, f = regular_torus(12, 6)
    ms = from_arrays(v, f)
    out = pattern(ms, direction=direction)
    region, kind = check_against_written(ms, out)
    assert out["strips"] == strips and out["strip_width_1"] == strips
    assert out["strip_width_2"] == 0 and out["strip_width_3_or_more"] == 0
    assert (out["cells"], out["non_hexagonal_cells"], out["conflict_faces"]) == (24, 0, 0)
    assert np.bincount(region).tolist() == [144 // strips] * strips
    pairs = face_adjacency(f)
    across = region[pairs[:, 0]] != region[pairs[:, 1]]
    assert (kind[pairs[across, 0]] != kind[pairs[across, 1]]).all()
    z = pattern(ms, pattern="Zebra", direction=direction)
    assert np.array_equal(written(ms)[0], region) and z["strips"] == strips


def test_stripe_panels_inset_and_extrusion():
    """Panels of the stripes (a new layer, the mesh itself untouched): one per region; a larger
    inset or extrusion moves the panels' vertices, extrusion 0 keeps them on the surface side."""
    layers = {}
    for inset, extrusion in ((0.1, 0.0), (0.25, 0.0), (0.1, 0.5)):
        ms = load("three_peaks.off")
        source = ms.current_mesh_id()
        out = pattern(ms, panels=True, panelinset=inset, panelextrusion=extrusion)
        assert ms.mesh_number() == 2 and ms.current_mesh_id() == source
        assert out["panels"] == out["regions"]
        assert sum(out["panel_sides_histogram"]) == out["panels"]
        other = [i for i in range(4) if ms.mesh_id_exists(i) and i != source][0]
        layers[(inset, extrusion)] = ms.mesh(other).vertex_matrix().copy()
    a, b, c = layers[(0.1, 0.0)], layers[(0.25, 0.0)], layers[(0.1, 0.5)]
    assert a.shape == b.shape and not np.allclose(a, b)
    assert not (a.shape == c.shape and np.allclose(a, c))
