"""Helpers of the pymeshlab suite: loading corpus meshes into a pymeshlab.MeshSet, the mesh's
full state (geometry, connectivity, colours, quality, selection) to prove a refusal changed
nothing, selections through MeshLab's own conditional selection, painted copies of meshes,
and the oracle's view (fi_oracle.Tri) of the current mesh."""
import os
import sys

import numpy as np
import pymeshlab
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("FI_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tests", "oracle"))
import fi_oracle as fo  # noqa: E402

DATA = os.environ.get("FI_DATA_DIR") or os.path.join(SOURCE, ".deps", "data", "meshes")
EXAMPLES = os.path.join(SOURCE, "examples")

# The plugin's filters, by pymeshlab name.
ANALYZE = "compute_irregular_vertex_analysis"
ATOMIC = "meshing_irregular_atomic_operation"
RELAX = "apply_irregular_relaxation"
REDUCE = "meshing_irregular_reduce_to_valence_5_and_7"
AGGREGATE = "meshing_irregular_aggregation"
MOVE_PAIR = "meshing_irregular_move_pair"
CANCEL_TRIPLE = "meshing_irregular_cancel_triple"
CANCEL_QUADRUPLE = "meshing_irregular_cancel_quadruple"
GENERATE = "meshing_irregular_generate"
AUTOMATIC = "meshing_irregular_automatic_reduction"
BOUNDARY = "meshing_irregular_boundary_operation"
PATTERN = "compute_color_irregular_pattern"
FILTERS = [ANALYZE, ATOMIC, RELAX, REDUCE, AGGREGATE, MOVE_PAIR, CANCEL_TRIPLE, CANCEL_QUADRUPLE, GENERATE, AUTOMATIC,
           BOUNDARY, PATTERN]
EDITING = [ATOMIC, REDUCE, AGGREGATE, MOVE_PAIR, CANCEL_TRIPLE, CANCEL_QUADRUPLE, GENERATE, AUTOMATIC]

OPERATIONS = ["5-7 pair move", "v5/v7 move with 5-7 pair generation",
              "v5/v7 move with 5-7 pair removal (triple cancellation)", "5-5-7-7 generation by flip",
              "5-5-7-7 generation by split", "5-5-7-7 removal", "Edge flip", "Edge collapse", "Vertex split",
              "5-5-7-7 generation by collapse and split"]


def corpus(name):
    """Path of a corpus mesh; a missing one fails the test (never skips it)."""
    path = os.path.join(DATA, name)
    if not os.path.isfile(path):
        pytest.fail("corpus mesh %s missing in %s (run scripts/setup.sh)" % (name, DATA), pytrace=False)
    return path


def load(name):
    """A fresh MeshSet holding the corpus mesh `name`."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(corpus(name))
    return ms


def from_arrays(vertices, faces, colours=None, quality=None):
    """A fresh MeshSet holding a mesh built from arrays; faces: (m, 3) array or a list of
    polygons (index lists: MeshLab triangulates them with faux edges)."""
    ms = pymeshlab.MeshSet()
    kw = {}
    if colours is not None:
        kw["v_color_matrix"] = np.asarray(colours, dtype=np.float64)
    if quality is not None:
        kw["v_scalar_array"] = np.asarray(quality, dtype=np.float64)
    v = np.asarray(vertices, dtype=np.float64)
    if isinstance(faces, list) and any(len(p) != 3 for p in faces):
        m = pymeshlab.Mesh(vertex_matrix=v, face_list_of_indices=[np.asarray(p, dtype=np.uint32) for p in faces], **kw)
    else:
        m = pymeshlab.Mesh(vertex_matrix=v, face_matrix=np.asarray(faces, dtype=np.int32).reshape(-1, 3), **kw)
    ms.add_mesh(m)
    return ms


def painted(name, seed=5):
    """The corpus mesh with random user colours (multiples of 1/255, as MeshLab stores them)
    and random quality."""
    ms = load(name)  # keep the MeshSet alive while its mesh is read
    v, f = ms.current_mesh().vertex_matrix(), ms.current_mesh().face_matrix()
    rng = np.random.default_rng(seed)
    rgb = rng.integers(0, 256, size=(len(v), 3)) / 255.0
    return from_arrays(v, f, colours=np.c_[rgb, np.ones(len(v))], quality=rng.random(len(v)))


def tri(ms):
    """The oracle's view of the current mesh (copies of its arrays)."""
    m = ms.current_mesh()
    return fo.Tri(m.vertex_matrix(), m.face_matrix())


def rgb(ms):
    """(n, 3) uint8 vertex colours of the current mesh."""
    return np.rint(ms.current_mesh().vertex_color_matrix()[:, :3] * 255).astype(np.int64)


def quality(ms):
    return ms.current_mesh().vertex_scalar_array()


def selected(ms):
    """Indices of the selected vertices of the current mesh."""
    return np.nonzero(ms.current_mesh().vertex_selection_array())[0]


def select(ms, indices):
    """Replaces the vertex selection with `indices`, through MeshLab's own conditional
    selection ('(vi == 3) || ...'; an empty list selects nothing)."""
    cond = " || ".join("(vi == %d)" % int(i) for i in indices) or "(vi < 0)"
    ms.compute_selection_by_condition_per_vertex(condselect=cond)
    got = selected(ms)
    assert sorted(got.tolist()) == sorted(int(i) for i in indices), "the selection filter did not select as asked"


def state(ms):
    """Everything a filter could change: number of meshes, the current mesh's vertices, faces,
    vertex colours, quality, vertex and face selection, and which optional parts it has."""
    m = ms.current_mesh()
    s = {"meshes": ms.mesh_number(), "vertices": m.vertex_matrix().copy(), "faces": m.face_matrix().copy(),
         "vertex_selection": m.vertex_selection_array().copy(), "face_selection": m.face_selection_array().copy(),
         "has_colour": m.has_vertex_color(), "has_quality": m.has_vertex_scalar()}
    if s["has_colour"]:
        s["colours"] = m.vertex_color_matrix().copy()
    if s["has_quality"]:
        s["quality"] = m.vertex_scalar_array().copy()
    return s


def assert_same_state(before, after, what="mesh"):
    assert before.keys() == after.keys(), "%s: optional parts changed: %s -> %s" % (what, sorted(before), sorted(after))
    for k in before:
        a, b = before[k], after[k]
        if isinstance(a, np.ndarray):
            assert a.shape == b.shape and np.array_equal(a, b), "%s: %s changed" % (what, k)
        else:
            assert a == b, "%s: %s changed (%r -> %r)" % (what, k, a, b)


# pymeshlab 2025.7.post1: once a filter has raised, MeshLab's plugins keep a pointer to the log
# of that MeshSet; after the MeshSet is freed, a later load_new_mesh writes to freed memory
# (std::bad_alloc or a segmentation fault a few calls later). Reproduced without this plugin:
# MeshLab's own compute_selection_by_condition_per_vertex(condselect="(vi == ") raising, the
# MeshSet deleted, then two load_new_mesh calls. So every MeshSet that saw an exception is kept
# alive until the end of the session.
_RAISED = []


def raises(ms, exceptions, filter_name, **params):
    """Applies the filter, which must raise one of `exceptions`; returns the exception."""
    try:
        ms.apply_filter(filter_name, **params)
    except exceptions as e:
        _RAISED.append(ms)
        return e
    except BaseException:
        _RAISED.append(ms)
        raise
    pytest.fail("%s(%s) did not raise %s" % (filter_name, params, exceptions), pytrace=False)


def refuse(ms, filter_name, match, **params):
    """Applies the filter, which must refuse with a PyMeshLabException whose text contains
    every string of `match` (a string or a list), and must leave the mesh exactly as it was.
    Returns the exception's text."""
    before = state(ms)
    text = str(raises(ms, pymeshlab.PyMeshLabException, filter_name, **params))
    for words in [match] if isinstance(match, str) else match:
        assert words in text, "refusal of %s does not say %r: %s" % (filter_name, words, text)
    assert_same_state(before, state(ms), "%s after a refusal" % filter_name)
    return text


def apply(ms, filter_name, **params):
    """Applies the filter, which must succeed; returns its dict of output values."""
    try:
        out = ms.apply_filter(filter_name, **params)
    except BaseException:
        _RAISED.append(ms)  # see _RAISED
        raise
    assert isinstance(out, dict) and out, "%s returned no values" % filter_name
    return out


def assert_counts(out, mesh, suffix):
    """The counts a filter returned with `suffix` equal the oracle's counts of `mesh`."""
    expect = fo.counts(mesh, suffix)
    for k, v in expect.items():
        assert k in out, "missing output value %s" % k
        if isinstance(v, np.ndarray):
            got = np.asarray(out[k], dtype=np.float64)
            assert got.shape == v.shape and np.array_equal(got, v), "%s: %s, oracle %s" % (k, got, v)
        else:
            assert out[k] == v, "%s: %s, oracle %s" % (k, out[k], v)


def canonical_faces(faces):
    """Faces as a sorted list of tuples, each rotated to start at its smallest index
    (orientation kept): equal for two meshes with the same triangles in any order."""
    f = np.asarray(faces, dtype=np.int64)
    k = np.argmin(f, axis=1)
    rot = np.stack([f[np.arange(len(f)), (k + i) % 3] for i in range(3)], axis=1)
    return sorted(map(tuple, rot.tolist()))


def index_by_position(reference, mesh, atol=0.0):
    """For each vertex of `mesh`, the index of the vertex of `reference` at exactly the same
    position (-1: none)."""
    ref = np.asarray(reference.vertices)
    index = {tuple(p): i for i, p in enumerate(ref.tolist())}
    return np.array([index.get(tuple(p), -1) for p in np.asarray(mesh.vertices).tolist()], dtype=np.int64)
