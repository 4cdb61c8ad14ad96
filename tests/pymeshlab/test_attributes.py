"""Attributes through the editing filters (issue 13, item 5), in the real pymeshlab: a mesh with
per-wedge texture coordinates (an affine function of position: a planar parametrisation made
by MeshLab's own filters), face colours and face quality goes through the Atomic Operation
and Move Pair filters (relax off); every corner's texture coordinate must still be the same
affine function of its vertex's position, face colours and qualities must be values the input
had (copied, never averaged), and the saved .ply / .obj must still carry them. A texture seam
is refused with the reason, the mesh unchanged."""
import os

import numpy as np
import pymeshlab

import fi_oracle as fo
from fi_pm import ATOMIC, MOVE_PAIR, apply, corpus, refuse, select, selected, tri

# The parametrisation MeshLab computes per vertex, then copies to the wedges.
U_FN, V_FN = "0.013*x+0.005*y+0.2", "-0.004*x+0.011*y+0.6"
N = 20                      # grid(N): (N+1)^2 vertices on [0, N]^2
CENTRE = (N // 2) * (N + 1) + N // 2


def param(p):
    return np.c_[0.013 * p[:, 0] + 0.005 * p[:, 1] + 0.2, -0.004 * p[:, 0] + 0.011 * p[:, 1] + 0.6]


def face_colours(n):
    i = np.arange(n)
    return np.c_[(i * 37 % 251) / 255.0, (i * 91 % 241) / 255.0, (i % 200) / 255.0, np.ones(n)]


def textured_grid():
    """The planar grid with wedge texture coordinates from MeshLab's filters, a distinct colour
    and quality (its index) per face."""
    g = fo.grid(N)
    ms = pymeshlab.MeshSet()
    nf = len(g.faces)
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=g.vertices, face_matrix=g.faces.astype(np.int32),
                               f_color_matrix=face_colours(nf), f_scalar_array=np.arange(nf, dtype=np.float64)))
    ms.compute_texcoord_by_function_per_vertex(u=U_FN, v=V_FN)
    ms.compute_texcoord_transfer_vertex_to_wedge()
    m = ms.current_mesh()
    assert m.has_wedge_tex_coord() and m.has_face_color() and m.has_face_scalar()
    check_texture(ms)
    return ms


def check_texture(ms, tol=2e-6):
    """Every corner carries the parametrisation of its vertex's position; returns the corners."""
    m = ms.current_mesh()
    assert m.has_wedge_tex_coord(), "the wedge texture coordinates were dropped"
    v, f = m.vertex_matrix(), m.face_matrix()
    wt = m.wedge_tex_coord_matrix()
    assert wt.shape == (3 * len(f), 2)
    want = param(v[f.reshape(-1)])
    err = np.abs(wt - want).max()
    assert err < tol, "texture coordinates off the parametrisation by %g" % err
    return len(wt)


def colour_keys(ms):
    return [tuple(c) for c in np.rint(ms.current_mesh().face_color_matrix() * 255).astype(int).tolist()]


def check_faces_copied(before_colours, before_quality, ms):
    """Every face colour and quality after the edit is one the input had (copied, not mixed)."""
    m = ms.current_mesh()
    assert m.has_face_color() and m.has_face_scalar(), "face colour or quality dropped"
    assert set(colour_keys(ms)) <= set(before_colours)
    assert set(m.face_scalar_array().tolist()) <= set(before_quality)


def pair_away_from_partner():
    """A textured grid with a 5-5-7-7 quadruple generated at the centre, one 5-7 pair moved 3
    steps away from the other: (MeshSet, v5, v7), a pair with regular vertices all round."""
    ms = textured_grid()
    select(ms, [CENTRE])
    apply(ms, ATOMIC, operation=3, direction=0, relax=False, colorize=False)
    check_texture(ms)
    quad = selected(ms)
    val = fo.valences(tri(ms))
    assert sorted(val[quad].tolist()) == [5, 5, 7, 7]
    v5 = int(quad[val[quad] == 5][0])
    v7 = int(quad[val[quad] == 7][0])
    for d in range(6):
        trial = pymeshlab.MeshSet()
        trial.add_mesh(ms.current_mesh())
        select(trial, [v5, v7])
        try:
            trial.apply_filter(MOVE_PAIR, direction=d, steps=3, relax=False, colorize=False)
        except pymeshlab.PyMeshLabException:
            continue
        check_texture(trial)
        pair = selected(trial)
        val = fo.valences(tri(trial))
        if sorted(val[pair].tolist()) != [5, 7]:
            continue
        return trial, int(pair[val[pair] == 5][0]), int(pair[val[pair] == 7][0])
    raise AssertionError("no direction moved the pair 3 steps")


def test_pair_moves_in_six_directions_carry_texture_and_face_colours():
    ms, v5, v7 = pair_away_from_partner()
    colours0, quality0 = colour_keys(ms), ms.current_mesh().face_scalar_array().tolist()
    nv0 = ms.current_mesh().vertex_number()
    kinds = set()
    for d in range(6):
        run = pymeshlab.MeshSet()
        run.add_mesh(ms.current_mesh())
        select(run, [v5, v7])
        apply(run, ATOMIC, operation=0, direction=d, relax=False, colorize=False)
        assert check_texture(run) > 0
        check_faces_copied(colours0, quality0, run)
        kinds.add(run.current_mesh().vertex_number() - nv0)  # flip 0, collapse -1, split +1
        fo.check_invariants(tri(run))
    assert kinds == {-1, 0, 1}, "the six directions are made of flips, collapses and splits"


def test_flip_changes_only_the_two_faces_and_copies_the_larger_ones_colour():
    ms = textured_grid()
    t = tri(ms)
    # two neighbours of the centre: an interior edge, flipped by the Atomic Operation (op 6)
    y = fo.neighbour_from(t, CENTRE, 0)
    colours0 = colour_keys(ms)
    select(ms, [CENTRE, y])
    apply(ms, ATOMIC, operation=6, relax=False, colorize=False)
    check_texture(ms)
    colours1 = colour_keys(ms)
    changed = [i for i in range(len(colours0)) if colours0[i] != colours1[i]]
    # the two faces of a grid edge have equal areas: the tie goes to one of them, so exactly
    # one of the two flipped faces changes colour, to its partner's
    assert len(changed) == 1
    assert colours1[changed[0]] in colours0


def test_saved_ply_and_obj_keep_texture_and_colours(tmp_path):
    ms, v5, v7 = pair_away_from_partner()
    select(ms, [v5, v7])
    apply(ms, MOVE_PAIR, direction=0, steps=2, relax=False, colorize=False)
    check_texture(ms)
    wt = ms.current_mesh().wedge_tex_coord_matrix()
    fc = ms.current_mesh().face_color_matrix()
    ply = str(tmp_path / "edited.ply")
    ms.save_current_mesh(ply, save_wedge_texcoord=True, save_face_color=True, binary=False)
    back = pymeshlab.MeshSet()
    back.load_new_mesh(ply)
    m = back.current_mesh()
    assert m.has_wedge_tex_coord() and m.has_face_color()
    assert np.abs(m.wedge_tex_coord_matrix() - wt).max() < 1e-6
    assert np.abs(m.face_color_matrix() - fc).max() < 1e-6
    check_texture(back)
    obj = str(tmp_path / "edited.obj")
    ms.save_current_mesh(obj, save_wedge_texcoord=True)
    back = pymeshlab.MeshSet()
    back.load_new_mesh(obj)
    assert back.current_mesh().has_wedge_tex_coord()
    check_texture(back, tol=1e-5)  # .obj stores 6 decimals


def test_a_texture_seam_is_refused_and_the_mesh_unchanged():
    ms = textured_grid()
    # every face its own square of the texture: every edge is a seam
    ms.compute_texcoord_parametrization_triangle_trivial_per_wedge()
    wt = ms.current_mesh().wedge_tex_coord_matrix().copy()
    y = fo.neighbour_from(tri(ms), CENTRE, 0)
    select(ms, [CENTRE, y])
    refuse(ms, ATOMIC, ["texture seam"], operation=6, relax=False, colorize=False)
    refuse(ms, ATOMIC, ["texture seam"], operation=7, relax=False, colorize=False)
    assert np.array_equal(ms.current_mesh().wedge_tex_coord_matrix(), wt)


def test_curved_corpus_mesh_keeps_a_continuous_texture():
    """knot1 (curved, closed) textured by a linear function of position: a flip and a collapse
    keep every corner exactly on it (a collapse moves to the edge's midpoint, where linear
    interpolation is exact); a split puts its vertices off the surface's faces, so there the
    texture coordinate is the function at the closest point of the old faces: close, and the
    same at every corner of a vertex (no seam made)."""
    knot_pair = (206, 2273)  # (v5, v7), regular all round (see test_atomic.py)
    for d, exact in [(1, True), (2, True), (0, False), (5, False)]:
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(corpus("knot1.off"))
        ms.compute_texcoord_by_function_per_vertex(u=U_FN, v=V_FN)
        ms.compute_texcoord_transfer_vertex_to_wedge()
        check_texture(ms)
        select(ms, list(knot_pair))
        apply(ms, ATOMIC, operation=0, direction=d, relax=False, colorize=False)
        m = ms.current_mesh()
        v, f, wt = m.vertex_matrix(), m.face_matrix(), m.wedge_tex_coord_matrix()
        per_vertex = {}
        for corner, vi in enumerate(f.reshape(-1)):
            per_vertex.setdefault(int(vi), set()).add(tuple(np.round(wt[corner], 7)))
        assert all(len(s) == 1 for s in per_vertex.values()), "direction %d made a texture seam" % d
        if exact:
            check_texture(ms)
        else:
            edge = np.linalg.norm(v[f[:, 0]] - v[f[:, 1]], axis=1).mean()
            err = np.abs(wt - param(v[f.reshape(-1)])).max()
            assert 0 < err < 0.013 * 0.25 * edge, "split %d: texture off by %g (edge %g)" % (d, err, edge)
