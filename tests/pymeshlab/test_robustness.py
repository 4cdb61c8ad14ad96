"""Bad input through every filter, through pymeshlab: defective meshes built with
pymeshlab.Mesh (non-manifold edge or vertex, polygons, duplicated or unreferenced vertices,
zero-area or repeated-vertex faces, a turned-over face), real defective corpus models, absurd
parameters (out of range, negative, NaN, infinite, wrong type or name), no faces, no mesh,
empty selections, boundary vertices. Each is a PyMeshLabException (or pymeshlab's own
exception for what pymeshlab checks itself) with a clear message, the mesh exactly as it was,
and never a crash. Valid but unusual input (boundaries, several components) is handled."""
import os

import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import (AGGREGATE, ANALYZE, ATOMIC, AUTOMATIC, CANCEL_QUADRUPLE, CANCEL_TRIPLE, FILTERS, GENERATE,
                   MOVE_PAIR, REDUCE, RELAX, apply, assert_same_state, corpus, from_arrays, load, raises, refuse,
                   select, state, tri)

PYMESHLAB_ERRORS = (pymeshlab.PyMeshLabException, pymeshlab.InvalidEnumException,
                    pymeshlab.InvalidPercentageException, RuntimeError, TypeError, ValueError)

# Parameters that the plugin checks (filter_catalog.cpp ranges): (filter, parameter, label,
# absurd value, words of the refusal).
RANGE = "must be between %s and %s; got %s"
ABSURD = [
    (ANALYZE, "valence", "Valence to select", -1, RANGE % (0, 1000, -1)),
    (ANALYZE, "valence", "Valence to select", 1001, RANGE % (0, 1000, 1001)),
    (ANALYZE, "valence", "Valence to select", 2 ** 31 - 1, RANGE % (0, 1000, 2 ** 31 - 1)),
    (ATOMIC, "direction", "Direction", -1, RANGE % (0, 63, -1)),
    (ATOMIC, "direction", "Direction", 64, RANGE % (0, 63, 64)),
    (RELAX, "iterations", "Iterations", -3, RANGE % (0, 100000, -3)),
    (RELAX, "iterations", "Iterations", 100001, RANGE % (0, 100000, 100001)),
    (RELAX, "featureAngle", "Feature angle (degrees)", -0.5, RANGE % (0, 180, -0.5)),
    (RELAX, "featureAngle", "Feature angle (degrees)", 180.5, RANGE % (0, 180, 180.5)),
    (RELAX, "featureAngle", "Feature angle (degrees)", float("nan"), "is not a finite number"),
    (RELAX, "featureAngle", "Feature angle (degrees)", float("inf"), "is not a finite number"),
    (MOVE_PAIR, "direction", "Direction", 100, RANGE % (0, 63, 100)),
    (MOVE_PAIR, "steps", "Steps", 0, RANGE % (1, 1000000, 0)),
    (MOVE_PAIR, "steps", "Steps", -1, RANGE % (1, 1000000, -1)),
    (MOVE_PAIR, "steps", "Steps", 1000001, RANGE % (1, 1000000, 1000001)),
    (MOVE_PAIR, "point", "Point", np.array([np.nan, 0, 0]), "is not a finite point"),
    (MOVE_PAIR, "point", "Point", np.array([0, np.inf, 0]), "is not a finite point"),
    (GENERATE, "direction", "Direction", -2, RANGE % (0, 63, -2)),
    (GENERATE, "spacing", "Spacing", -1, RANGE % (0, 100000, -1)),
    (GENERATE, "spacing", "Spacing", 100001, RANGE % (0, 100000, 100001)),
    (AUTOMATIC, "targetCount", "Target irregular count", -1, RANGE % (0, 1000000000, -1)),
    (AUTOMATIC, "hausdorffBudget", "Hausdorff budget (% of diagonal)", -0.1, RANGE % (0, 100, -0.1)),
    (AUTOMATIC, "hausdorffBudget", "Hausdorff budget (% of diagonal)", 100.5, RANGE % (0, 100, 100.5)),
    (AUTOMATIC, "hausdorffBudget", "Hausdorff budget (% of diagonal)", float("nan"), "is not a finite number"),
    (AUTOMATIC, "minAngle", "Minimum angle (degrees)", -1.0, RANGE % (0, 60, -1)),
    (AUTOMATIC, "minAngle", "Minimum angle (degrees)", 61.0, RANGE % (0, 60, 61)),
    (AUTOMATIC, "minAngle", "Minimum angle (degrees)", float("-inf"), "is not a finite number"),
    (AUTOMATIC, "angleAllowance", "Angle allowance (% of triangles)", -0.5, RANGE % (0, 100, -0.5)),
    (AUTOMATIC, "angleAllowance", "Angle allowance (% of triangles)", 101.0, RANGE % (0, 100, 101)),
    (AUTOMATIC, "angleAllowance", "Angle allowance (% of triangles)", float("nan"), "is not a finite number"),
    (AUTOMATIC, "angleFloor", "Angle floor (degrees)", -1.0, RANGE % (0, 60, -1)),
    (AUTOMATIC, "angleFloor", "Angle floor (degrees)", 61.0, RANGE % (0, 60, 61)),
    (AUTOMATIC, "maxTravel", "Pair travel (steps)", 0, RANGE % (1, 100000, 0)),
    (AUTOMATIC, "maxTravel", "Pair travel (steps)", -5, RANGE % (1, 100000, -5)),
    (AUTOMATIC, "maxTravel", "Pair travel (steps)", 100001, RANGE % (1, 100000, 100001)),
    (AUTOMATIC, "timeLimit", "Time limit (seconds)", -1.0, RANGE % (0, 10000000, -1)),
    (AUTOMATIC, "timeLimit", "Time limit (seconds)", float("nan"), "is not a finite number"),
    (AUTOMATIC, "remeshEdgeLength", "Remesh first: target edge length", pymeshlab.PureValue(-1),
     "must be between 0 and the bounding-box diagonal"),
    (AUTOMATIC, "remeshEdgeLength", "Remesh first: target edge length", pymeshlab.PureValue(1e9),
     "must be between 0 and the bounding-box diagonal"),
    (AUTOMATIC, "remeshEdgeLength", "Remesh first: target edge length", pymeshlab.PureValue(float("nan")),
     "is not a finite number"),
]


def knot_with_pair():
    """knot1 with an adjacent 5-7 pair selected: every selection-based filter could act."""
    ms = load("knot1.off")
    select(ms, [206, 2273])
    return ms


@pytest.mark.parametrize("case", ABSURD, ids=lambda c: "%s-%s-%r" % (c[0].split("_", 1)[1], c[1], c[3]))
def test_absurd_parameters_are_refused_with_the_parameter_named(case):
    filter_name, param, label, value, words = case
    ms = knot_with_pair()
    refuse(ms, filter_name, ["Parameter '%s' (%s)" % (param, label), words], **{param.lower(): value})


@pytest.mark.parametrize("filter_name,params", [
    (ANALYZE, lambda: {"select": "Bogus"}),              # not one of the enum's values
    (ATOMIC, lambda: {"operation": "Teleport"}),
    (ANALYZE, lambda: {"valence": 1.5}),                  # wrong types
    (ANALYZE, lambda: {"valence": 2 ** 40}),
    (ANALYZE, lambda: {"colorize": "yes please"}),
    (MOVE_PAIR, lambda: {"point": np.array([1.0, 2.0])}),
    (MOVE_PAIR, lambda: {"point": "here"}),
    (AUTOMATIC, lambda: {"remeshedgelength": pymeshlab.PercentageValue(-5)}),   # percent out of 0..100
    (AUTOMATIC, lambda: {"remeshedgelength": pymeshlab.PercentageValue(250)}),
    (AUTOMATIC, lambda: {"remeshedgelength": 0.3}),      # a bare float for a percentage parameter
    (RELAX, lambda: {"bogus": 3}),                       # no such parameter
    (RELAX, lambda: {"featureAngle": 30}),               # pymeshlab's names are lower case
], ids=["enum", "enum2", "float-for-int", "huge-int", "str-for-bool", "2d-point", "str-point", "percent<0",
        "percent>100", "bare-float-percentage", "unknown", "camel-case"])
def test_what_pymeshlab_itself_rejects_leaves_the_mesh_unchanged(filter_name, params):
    ms = knot_with_pair()
    before = state(ms)
    try:
        kw = params()  # pymeshlab may already refuse to build the value
    except PYMESHLAB_ERRORS as e:
        assert "percentage" in str(e).lower()
        return
    e = raises(ms, PYMESHLAB_ERRORS, filter_name, **kw)
    assert str(e)
    assert_same_state(before, state(ms), "after pymeshlab rejected %s" % kw)


def test_refusal_messages_name_the_parameter_range_exactly():
    """One full message, as a user reads it."""
    ms = knot_with_pair()
    text = refuse(ms, MOVE_PAIR, "", steps=-1)
    assert text.endswith("Details: Parameter 'steps' (Steps) must be between 1 and 1000000; got -1."), text


# ------------------------------------------------------------------ defective meshes
def minimal_params(filter_name):
    return {ATOMIC: {"operation": "5-5-7-7 generation by flip"}, GENERATE: {"kind": "Quadruple from a regular vertex"},
            AUTOMATIC: {"timelimit": 0}}.get(filter_name, {})


@pytest.mark.parametrize("name", list(fo.bad_meshes()))
def test_defective_mesh_is_refused_by_every_filter(name):
    """Every filter refuses, names the MeshLab filter that repairs the defect, and changes
    nothing (vertex 0 selected, so the selection-based filters could act)."""
    vertices, faces, fix = fo.bad_meshes()[name]
    problems = []
    for filter_name in FILTERS:
        ms = from_arrays(vertices, faces)
        select(ms, [0])
        before = state(ms)
        e = raises(ms, PYMESHLAB_ERRORS, filter_name, **minimal_params(filter_name))
        if not isinstance(e, pymeshlab.PyMeshLabException):
            problems.append("%s: %s %s" % (filter_name, type(e).__name__, e))
        elif fix not in str(e):
            problems.append("%s says %r, not %r" % (filter_name, str(e).split("Details: ")[-1], fix))
        assert_same_state(before, state(ms), "%s on %s" % (filter_name, name))
    assert not problems, "\n".join(problems)


def test_the_repair_a_refusal_names_makes_the_mesh_acceptable():
    """Two fans of faces at one vertex (the peer's remeshing of the cow at 20K has one): the
    refusal's repair, with the displacement it asks for, gives a mesh every filter takes; without
    it, the copies at one position are refused as duplicated vertices, and that refusal says
    how to avoid them instead of advising a merge that would undo the repair."""
    # two octahedra touching at a vertex: the second's (-1, 0, 0), moved by (2, 0, 0), is the
    # first's (1, 0, 0)
    o = fo.octahedron()
    v, f = np.asarray(o.vertices, float), np.asarray(o.faces)
    assert tuple(v[0]) == (1, 0, 0) and tuple(v[1]) == (-1, 0, 0)
    second = {0: 6, 1: 0, 2: 7, 3: 8, 4: 9, 5: 10}
    vertices = np.vstack([v, v[[0, 2, 3, 4, 5]] + (2, 0, 0)])
    faces = np.vstack([f, np.vectorize(second.get)(f)])
    ms = from_arrays(vertices, faces)
    refuse(ms, ANALYZE, ["Repair non Manifold Vertices", "Vertex Displacement Ratio above 0"])
    ms.meshing_repair_non_manifold_vertices(vertdispratio=0)
    refuse(ms, ANALYZE, ["duplicated vertices", "Vertex Displacement Ratio above 0"])
    ms = from_arrays(vertices, faces)
    ms.meshing_repair_non_manifold_vertices(vertdispratio=0.05)
    out = apply(ms, ANALYZE)
    assert ms.current_mesh().vertex_number() == len(vertices) + 1  # the shared vertex, split in two
    fo.check_invariants(tri(ms))
    assert out


def test_mesh_without_faces_is_refused():
    for filter_name in FILTERS:
        ms = pymeshlab.MeshSet()
        ms.add_mesh(pymeshlab.Mesh(vertex_matrix=fo.octahedron().vertices))
        before = state(ms)
        e = raises(ms, pymeshlab.PyMeshLabException, filter_name)
        assert "Faces" in str(e) or "no faces" in str(e), str(e)
        assert_same_state(before, state(ms), filter_name)


def test_empty_mesh_set_is_refused():
    for filter_name in FILTERS:
        ms = pymeshlab.MeshSet()
        e = raises(ms, pymeshlab.PyMeshLabException, filter_name)
        assert "requires at least one mesh" in str(e)
        assert ms.mesh_number() == 0


def off_polygons(path):
    """Whether an OFF file has faces of more than three vertices (read here, not by MeshLab:
    MeshLab triangulates them on loading)."""
    with open(path) as f:
        rows = [s for s in (line.split("#")[0].split() for line in f) if s]
    head, body = (rows[0][1:], 1) if len(rows[0]) > 1 else (rows[1], 2)
    nv, nf = int(head[0]), int(head[1])
    return any(int(r[0]) > 3 for r in rows[body + nv:body + nv + nf])


def expected_refusal(path, m):
    """The words of the plugin's refusal for the first defect the oracle finds, in the order
    the plugin checks them, or None for a clean mesh."""
    if path.endswith(".off") and off_polygons(path):
        return "Turn into a Pure-Triangular mesh"
    if not fo.is_edge_manifold(m):
        return "Repair non Manifold Edges"
    if fo.degenerate_face_mask(m).any():
        return "Remove Zero Area Faces"
    if not fo.is_vertex_manifold(m):
        return "Repair non Manifold Vertices"
    if not fo.is_consistently_oriented(m):
        return "Re-Orient all faces coherentely"
    if fo.duplicate_vertex_mask(m).any():
        return "Remove Duplicate Vertices"
    if not fo.referenced_mask(m).all():
        return "Remove Unreferenced Vertices"
    return None


@pytest.mark.parametrize("name", ["elephant-with-holes.off", "tetra_intersected_by_triangle.off", "polygon_mesh.off",
                                  "degtri_sliding.off", "quads_to_stitch.off", "cube_quad.off",
                                  "mesh_with_colors.off", "pig.stl"])
def test_real_defective_models(name):
    """Real models with defects: Analyze, Relax and Reduce refuse exactly when the oracle finds a
    defect, with the repair it needs, and leave the mesh as it was; otherwise they work."""
    path = corpus(name)
    fix = expected_refusal(path, tri(load(name)))
    for filter_name in (ANALYZE, RELAX, REDUCE):
        ms = load(name)
        if fix:
            refuse(ms, filter_name, fix)
            continue
        t0 = tri(ms)
        if filter_name == REDUCE and reduce_refusal(t0):
            refuse(ms, REDUCE, reduce_refusal(t0))
            continue
        apply(ms, filter_name)
        fo.check_invariants(tri(ms))


def reduce_refusal(m):
    """Why Reduce must refuse this clean mesh, or None: no interior vertex of valence other
    than 5, 6 and 7; or (tiny meshes) no regular interior vertex anywhere to collapse into or to
    split toward, so no vertex can be reduced."""
    v, b = fo.valences(m), fo.boundary_mask(m)
    interior = fo.referenced_mask(m) & ~b
    if not ((v < 5) | (v > 7))[interior].any():
        return "no interior vertex of valence other than 5, 6 and 7"
    if not (v[interior] == 6).any():
        return "No vertex could be reduced"
    return None


@pytest.mark.parametrize("name,reduce_says", [
    ("head.off", None), ("blobby_3cc.off", None), ("mesh_with_border.off", None),
    ("tetrahedron.off", "No vertex could be reduced"),  # four v3, no regular vertex to collapse into
    ("triangle.off", "no interior vertex of valence other than 5, 6 and 7"),  # boundary only
    # v4s: every orientation's collapse would touch the boundary or another v4
    ("open_cube.off", "No vertex could be reduced. 3: vertex 3 (v4) cannot be split into v5s in any orientation"),
])
def test_boundaries_and_components_are_handled(name, reduce_says):
    """Valid input with boundaries, several components or almost nothing: Analyze and Relax
    work; Reduce works, or says why it cannot."""
    ms = load(name)
    t0 = tri(ms)
    assert expected_refusal(corpus(name), t0) is None
    out = apply(ms, ANALYZE)
    assert out["irregular"] == fo.irregular_mask(t0).sum() and out["components"] == fo.component_count(t0)
    apply(ms, RELAX, iterations=2)
    assert np.array_equal(tri(ms).faces, t0.faces)
    ms = load(name)
    if reduce_says:
        refuse(ms, REDUCE, reduce_says)
    else:
        out = apply(ms, REDUCE)
        assert out["reduced"] >= 1 and out["irregular_after"] == fo.irregular_mask(tri(ms)).sum()
    fo.check_invariants(tri(ms))


# ------------------------------------------------------------------ selections
@pytest.mark.parametrize("filter_name,words", [
    (ATOMIC, "A 5-7 pair move needs exactly 2 selected vertices (two); 0 are selected."),
    (MOVE_PAIR, "Moving a pair needs exactly 2 selected vertices; 0 are selected."),
    (CANCEL_TRIPLE, "A triple cancellation needs exactly 3 selected vertices; 0 are selected."),
    (CANCEL_QUADRUPLE, "A quadruple cancellation needs exactly 4 selected vertices; 0 are selected."),
    (GENERATE, "Generation needs exactly 1 selected vertices; 0 are selected."),
    (AGGREGATE, "aggregation needs at least two vertices"),
])
def test_empty_selection_is_refused(filter_name, words):
    ms = load("knot1.off")
    select(ms, [])
    refuse(ms, filter_name, words)


@pytest.mark.parametrize("filter_name,params", [(GENERATE, {}), (ATOMIC, {"operation": "5-5-7-7 generation by split"}),
                                                (ATOMIC, {"operation": "v5/v7 move with 5-7 pair generation"})])
def test_boundary_vertex_is_refused(filter_name, params):
    ms = load("mesh_with_border.off")
    t0 = tri(ms)
    b = int(np.nonzero(fo.boundary_mask(t0) & (fo.valences(t0) == 4))[0][0])
    select(ms, [b])
    refuse(ms, filter_name, "lies on the boundary; these operations work on interior vertices", **params)


def test_refusal_after_painting_keeps_colours_quality_and_selection():
    """A refusal on a mesh that has the user's colours, quality and a selection (the state
    compared includes them)."""
    from fi_pm import painted
    ms = painted("knot1.off")
    select(ms, [206])
    refuse(ms, MOVE_PAIR, "Theorem 5.1", colorize=False)
    refuse(ms, ATOMIC, "generated from a regular vertex", operation="5-5-7-7 generation by flip", colorize=False)


def test_corpus_path_is_real():
    assert os.path.isfile(corpus("knot1.off"))
