#!/usr/bin/env python3
"""The data side of the edit tool's GUI test (tests/gui/edit_test.sh). Runs with the venv's
python (numpy, pymeshlab, the 2025.07 filter plugin for the reference).

  edit_check.py prepare   --mesh knot1.off --pair 47 3186 --out input.ply
      an ASCII PLY of the mesh whose vertex flags select exactly the pair (MeshLab reads the
      selection from the 'flags' property; the tool picks the pair from it)
  edit_check.py reference --mesh knot1.off --pair 47 3186 --direction 0 --steps 3
                          --plugin libfilter_irregular.so --out ref.npz
      the expected result: the same pair moved by the filter "Irregular Vertices: Move Pair",
      one step at a time (`steps` times direction `direction`: what pressing key direction+1
      `steps` times asks for), with relaxation, as arrays
  edit_check.py check --input input.ply --output exported.ply --reference ref.npz --pair 47 3186
      the exported mesh against the input and the reference (see check())

Exit 0 when every check holds; otherwise an "edit_check: FAIL ..." line says which.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "oracle"))
import fi_oracle as fo  # noqa: E402
from check_ply import read_ply  # noqa: E402


def fail(msg):
    print("edit_check: FAIL " + msg, flush=True)
    sys.exit(1)


def load_ms(path):
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(path)
    return ms


def prepare(a):
    ms = load_ms(a.mesh)
    m = ms.current_mesh()
    v, f = m.vertex_matrix(), m.face_matrix()
    write_ply(a.out, v, f, a.pair)
    print("edit_check: %s: %d vertices, %d faces, vertices %s selected" % (a.out, len(v), len(f), sorted(a.pair)))


def write_ply(path, v, f, selected):
    """An ASCII PLY whose vertex flags select exactly `selected` (MeshLab reads the selection
    from the 'flags' property)."""
    sel = set(selected)
    with open(path, "w") as out:
        out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                  "property int flags\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                  % (len(v), len(f)))
        for i, p in enumerate(v):
            out.write("%.9g %.9g %.9g %d\n" % (p[0], p[1], p[2], 0x20 if i in sel else 0))
        for t in f:
            out.write("3 %d %d %d\n" % tuple(t))


def reference(a):
    import pymeshlab
    pymeshlab.load_plugin(a.plugin)
    ms = load_ms(a.mesh)
    cond = " || ".join("(vi == %d)" % i for i in a.pair)
    ms.compute_selection_by_condition_per_vertex(condselect=cond)
    for s in range(a.steps):
        ms.apply_filter("meshing_irregular_move_pair", lead="Lower valence", direction=a.direction, steps=1,
                        towardpoint=False, point=np.zeros(3), relax=True, colorize=False)
    m = ms.current_mesh()
    pair = np.nonzero(m.vertex_selection_array())[0]
    np.savez(a.out, v=m.vertex_matrix(), f=m.face_matrix(), pair=pair)
    print("edit_check: reference %s: %d steps in direction %d, the pair is now %s" % (a.out, a.steps, a.direction,
                                                                                      pair.tolist()))


def tri_of_ply(path):
    names, verts, faces = read_ply(path)
    xyz = [names.index(c) for c in "xyz"]
    v = np.array([[r[i] for i in xyz] for r in verts], dtype=np.float64)
    f = np.array(faces, dtype=np.int64).reshape(-1, 3)
    return fo.Tri(v, f)


def load_and_compare_counts(a):
    """The input I, the exported mesh E and the reference R (with its npz) of a check: E must
    be a valid mesh (the oracle's invariants) with R's vertex and face counts and R's valence
    histogram (a step or a cancellation may split or collapse: the counts need not be I's)."""
    ti = tri_of_ply(a.input)
    te = tri_of_ply(a.output)
    r = np.load(a.reference)
    tr = fo.Tri(r["v"], r["f"])
    fo.check_invariants(te)
    if len(te.vertices) != len(tr.vertices) or len(te.faces) != len(tr.faces):
        fail("counts differ from the reference: %d/%d vertices, %d/%d faces (exported/reference; input %d/%d)"
             % (len(te.vertices), len(tr.vertices), len(te.faces), len(tr.faces), len(ti.vertices), len(ti.faces)))
    hr = np.bincount(fo.valences(tr), minlength=20)
    he = np.bincount(fo.valences(te), minlength=20)
    if not np.array_equal(hr, he):
        fail("valence histogram differs from the reference's: %s, reference %s" % (he.tolist(), hr.tolist()))
    return ti, te, tr, r


def irregular_set(t):
    val = fo.valences(t)
    mask = fo.irregular_mask(t)
    return t.vertices[mask], val[mask]


def check(a):
    """The exported mesh E against the input I and the reference R (the filter's result):
    1. E is a valid mesh (the oracle's invariants) with R's vertex and face counts and R's
       valence histogram (a step may split or collapse: the counts need not be I's);
    2. the irregular vertices of E other than the moved pair are those of I with the same
       valences, within half a mean edge length of where they were (the relaxation after each
       step may nudge those near the pair; far ones are checked exactly by 3);
    3. every vertex of E far from the pair's path (more than 6 mean edge lengths from both the
       pair's start and the reference's end) is a vertex of I at the same position;
    4. the pair in E is where the reference put it: E's two irregular vertices that are not
       I's lie within half a mean edge length of R's pair, with R's valences (5 and 7).
    The relaxation of the tool and of the filter may place the relaxed ring differently, so
    positions near the pair are compared with a tolerance, connectivity by valence."""
    ti, te, tr, r = load_and_compare_counts(a)
    edge = fo.mean_edge_length(ti)
    tol = 1e-5 * fo.diagonal(ti)

    from scipy.spatial import cKDTree

    def nearest(points, cloud):
        d, j = cKDTree(cloud).query(points)
        return d, j

    pi, vi = irregular_set(ti)
    pe, ve = irregular_set(te)
    start = ti.vertices[list(a.pair)]
    end = tr.vertices[r["pair"]]
    # 2. irregular vertices other than the pair
    others = np.ones(len(pi), bool)
    others[[int(np.nonzero((pi == ti.vertices[p]).all(axis=1))[0][0]) for p in a.pair]] = False
    d, j = nearest(pi[others], pe)
    if (d > 0.5 * edge).any() or (ve[j] != vi[others]).any():
        k = int(np.argmax(d))
        fail("an irregular vertex other than the pair moved or changed valence: %s (distance %.3g)" % (pi[others][k], d[k]))
    # 4. the moved pair
    new = np.ones(len(pe), bool)
    new[j] = False
    if new.sum() != 2:
        fail("%d irregular vertices of the exported mesh are not the input's (expected the moved pair, 2)" % new.sum())
    d_start, _ = nearest(pe[new], start)
    if (d_start < 0.5 * edge).all():
        fail("the pair did not move (it is still at its start)")
    d_end, k_end = nearest(pe[new], end)
    rv = fo.valences(tr)[r["pair"]]
    if (d_end > 0.5 * edge).any():
        fail("the pair is not where Move Pair puts it after the same steps: distances %s mean edge lengths"
             % np.round(d_end / edge, 2).tolist())
    if sorted(ve[new].tolist()) != sorted(rv.tolist()):
        fail("the moved pair has valences %s, the reference %s" % (ve[new].tolist(), rv.tolist()))
    # 3. vertices far from the path
    far_e = (nearest(te.vertices, start)[0] > 6 * edge) & (nearest(te.vertices, end)[0] > 6 * edge)
    d_far, _ = nearest(te.vertices[far_e], ti.vertices) if far_e.any() else (np.zeros(0), None)
    if (d_far > tol).any():
        fail("%d vertices far from the pair moved" % int((d_far > tol).sum()))
    moved = int((nearest(te.vertices, ti.vertices)[0] > tol).sum())
    print("edit_check: PASS the pair moved from %s to %s (reference within %.2f mean edge lengths); %d vertices "
          "moved in all (relaxation near the pair), %d far vertices and %d other irregular vertices unchanged"
          % (np.round(start, 3).tolist(), np.round(pe[new], 3).tolist(), float(d_end.max() / edge), moved,
             int(far_e.sum()), int(others.sum())))


# --- triple / quadruple cancellation (keys T and Q of the tool) --------------------------------------
def adjacent_pairs(t, group):
    """The 5-7 pairs (v5, v7) among `group` whose two vertices share an edge, sorted."""
    val = fo.valences(t)
    return sorted((a, b) for a in group for b in group
                  if val[a] == 5 and val[b] == 7 and fo.adjacent(t, a, b))


def prepare_cancel(a):
    """An icosphere (pymeshlab's create_sphere, `subdiv` levels: 12 v5 far apart, the rest
    regular) in which the filter "Irregular Vertices: Generate" made a 5-5-7 triple (from a v5)
    or a 5-5-7-7 quadruple (from the regular vertex farthest from every v5), its 5-7 pair moved
    2 steps away. The PLY selects one adjacent 5-7 pair of the group (the tool picks it from
    the selection); the JSON names the group, the pair and the expected survivor's valence."""
    import json
    import pymeshlab
    pymeshlab.load_plugin(a.plugin)
    ms = pymeshlab.MeshSet()
    ms.create_sphere(subdiv=a.subdiv)
    m = ms.current_mesh()
    t = fo.Tri(m.vertex_matrix(), m.face_matrix())
    val = fo.valences(t)
    v5s = np.nonzero(val == 5)[0]
    if a.kind == "triple":
        seed, kind = int(v5s[0]), 0
    else:
        from scipy.spatial import cKDTree
        reg = np.nonzero(val == 6)[0]
        d, _ = cKDTree(t.vertices[v5s]).query(t.vertices[reg])
        seed, kind = int(reg[int(np.argmax(d))]), 1
    ms.compute_selection_by_condition_per_vertex(condselect="vi == %d" % seed)
    ms.apply_filter("meshing_irregular_generate", kind=kind, direction=0, spacing=2)
    m = ms.current_mesh()
    group = [int(i) for i in np.nonzero(m.vertex_selection_array())[0]]
    t = fo.Tri(m.vertex_matrix(), m.face_matrix())
    want = [5, 5, 7] if a.kind == "triple" else [5, 5, 7, 7]
    if sorted(fo.valences(t)[group].tolist()) != want:
        fail("Generate made valences %s, not %s" % (sorted(fo.valences(t)[group].tolist()), want))
    pairs = adjacent_pairs(t, group)
    if not pairs:
        fail("no adjacent 5-7 pair in the generated %s %s" % (a.kind, group))
    pair = list(pairs[0])
    write_ply(a.out, m.vertex_matrix().astype(np.float32), m.face_matrix(), pair)
    with open(a.group_out, "w") as f:
        json.dump({"kind": a.kind, "group": group, "pair": pair}, f)
    print("edit_check: %s: icosphere (%d vertices) with the %s %s (valences %s); the pair %s selected"
          % (a.out, len(t.vertices), a.kind, group, fo.valences(t)[group].tolist(), pair))


def reference_cancel(a):
    """The filter "Irregular Vertices: Cancel Triple / Quadruple" on the input PLY with the
    whole group selected: the expected result of key T / Q (same CompositeOperations call)."""
    import json
    import pymeshlab
    g = json.load(open(a.group))
    pymeshlab.load_plugin(a.plugin)
    ms = load_ms(a.input)
    ms.compute_selection_by_condition_per_vertex(condselect=" || ".join("(vi == %d)" % i for i in g["group"]))
    name = "meshing_irregular_cancel_triple" if g["kind"] == "triple" else "meshing_irregular_cancel_quadruple"
    ms.apply_filter(name, relax=True, colorize=False)
    m = ms.current_mesh()
    np.savez(a.out, v=m.vertex_matrix(), f=m.face_matrix())
    print("edit_check: reference %s: %s of %s by the filter: %d vertices, %d faces"
          % (a.out, name, g["group"], len(m.vertex_matrix()), len(m.face_matrix())))


def check_cancel(a):
    """The mesh E exported after key T (Q) against the input I and the reference R (the Cancel
    Triple / Quadruple filter on I):
    1. E is a valid mesh (the oracle's invariants) with R's vertex and face counts and R's
       valence histogram;
    2. the group's vertices are gone: every irregular vertex of I outside the group is in E at
       the same position (exactly) with its valence, and E has exactly one more irregular
       vertex for a triple (the survivor, of R's survivor's valence and within half a mean
       edge of it) and none for a quadruple;
    3. nothing changed beyond the cancellation's region: every vertex of I more than `hops`
       edges from the group is in E at the same position (exactly), and every other vertex of E
       lies within a mean edge length of an input vertex at most `hops` edges from the group;
    4. E and R agree: every vertex of E within `tol` of a vertex of R (the tool and the filter
       run the same cancellation; the vertex order differs: the tool compacts the mesh by
       moving the last vertices into the holes)."""
    import json
    from scipy.spatial import cKDTree
    g = json.load(open(a.group))
    group = g["group"]
    ti, te, tr, _ = load_and_compare_counts(a)
    exact = 1e-6 * fo.diagonal(ti)  # PLY float round trip
    edge = fo.mean_edge_length(ti)
    tree_e = cKDTree(te.vertices)
    # 2. the irregular vertices
    vi, ve, vr = fo.valences(ti), fo.valences(te), fo.valences(tr)
    irr_i = [int(v) for v in np.nonzero(fo.irregular_mask(ti))[0] if v not in group]
    d, j = tree_e.query(ti.vertices[irr_i])
    if (d > exact).any() or (ve[j] != vi[irr_i]).any():
        k = int(np.argmax(d))
        fail("an irregular vertex outside the group moved or changed valence: input vertex %d (distance %.3g)"
             % (irr_i[k], d[k]))
    irr_e = set(np.nonzero(fo.irregular_mask(te))[0].tolist())
    new = sorted(irr_e - set(j.tolist()))
    irr_r = np.nonzero(fo.irregular_mask(tr))[0]
    new_r = [int(v) for v in irr_r if cKDTree(ti.vertices[irr_i]).query(tr.vertices[v])[0] > exact]
    expect = 1 if g["kind"] == "triple" else 0
    if len(new) != expect or len(new_r) != expect:
        fail("%d irregular vertices of the exported mesh (%d of the reference) are not the input's; expected %d "
             "(the group %s cancelled%s)" % (len(new), len(new_r), expect, group,
                                            " to one survivor" if expect else ""))
    for v in new:
        if ve[v] != vr[new_r[0]] or np.linalg.norm(te.vertices[v] - tr.vertices[new_r[0]]) > 0.5 * edge:
            fail("the survivor (valence %d at %s) is not the reference's (valence %d at %s)"
                 % (ve[v], te.vertices[v].tolist(), vr[new_r[0]], tr.vertices[new_r[0]].tolist()))
    # 3. the region
    hops = fo.hop_distances(ti, group)
    far = np.nonzero(hops > a.hops)[0]
    d, j = tree_e.query(ti.vertices[far])
    if (d > exact).any():
        fail("%d input vertices more than %d edges from the group moved" % (int((d > exact).sum()), a.hops))
    rest = np.ones(len(te.vertices), bool)
    rest[j] = False
    near = np.nonzero(hops <= a.hops)[0]
    dg, _ = cKDTree(ti.vertices[near]).query(te.vertices[rest])
    if (dg > edge).any():
        fail("%d exported vertices are new or moved, farther than a mean edge from the input's vertices within %d "
             "edges of the group" % (int((dg > edge).sum()), a.hops))
    # 4. the reference
    dr, _ = cKDTree(tr.vertices).query(te.vertices)
    if dr.max() > a.tol * edge:
        fail("the exported mesh differs from the filter's result: a vertex %.3g mean edge lengths from every "
             "reference vertex" % (dr.max() / edge))
    print("edit_check: PASS the %s %s is cancelled%s; %d vertices more than %d edges away unchanged (%d nearer "
          "may change); the filter's result within %.2g mean edge lengths"
          % (g["kind"], group, " (one v%d left)" % ve[new[0]] if new else "", len(far), a.hops, int(rest.sum()),
             dr.max() / edge))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("prepare")
    p.add_argument("--mesh", required=True)
    p.add_argument("--pair", type=int, nargs=2, required=True)
    p.add_argument("--out", required=True)
    p = sub.add_parser("reference")
    p.add_argument("--mesh", required=True)
    p.add_argument("--pair", type=int, nargs=2, required=True)
    p.add_argument("--direction", type=int, default=0)
    p.add_argument("--steps", type=int, default=3)
    p.add_argument("--plugin", required=True)
    p.add_argument("--out", required=True)
    p = sub.add_parser("check")
    p.add_argument("--input", required=True)
    p.add_argument("--output", required=True)
    p.add_argument("--reference", required=True)
    p.add_argument("--pair", type=int, nargs=2, required=True)
    p = sub.add_parser("prepare-cancel")
    p.add_argument("--kind", choices=["triple", "quadruple"], required=True)
    p.add_argument("--subdiv", type=int, default=4)
    p.add_argument("--plugin", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--group-out", required=True)
    p = sub.add_parser("reference-cancel")
    p.add_argument("--input", required=True)
    p.add_argument("--group", required=True)
    p.add_argument("--plugin", required=True)
    p.add_argument("--out", required=True)
    p = sub.add_parser("check-cancel")
    p.add_argument("--input", required=True)
    p.add_argument("--output", required=True)
    p.add_argument("--reference", required=True)
    p.add_argument("--group", required=True)
    p.add_argument("--hops", type=int, default=8, help="the cancellation's region: edges from the group")
    p.add_argument("--tol", type=float, default=0.05, help="agreement with the filter, in mean edge lengths")
    a = ap.parse_args()
    {"prepare": prepare, "reference": reference, "check": check, "prepare-cancel": prepare_cancel,
     "reference-cancel": reference_cancel, "check-cancel": check_cancel}[a.cmd](a)


if __name__ == "__main__":
    main()
