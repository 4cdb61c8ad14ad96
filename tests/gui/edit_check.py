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
    sel = set(a.pair)
    with open(a.out, "w") as out:
        out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                  "property int flags\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                  % (len(v), len(f)))
        for i, p in enumerate(v):
            out.write("%.9g %.9g %.9g %d\n" % (p[0], p[1], p[2], 0x20 if i in sel else 0))
        for t in f:
            out.write("3 %d %d %d\n" % tuple(t))
    print("edit_check: %s: %d vertices, %d faces, vertices %s selected" % (a.out, len(v), len(f), sorted(sel)))


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
    a = ap.parse_args()
    {"prepare": prepare, "reference": reference, "check": check}[a.cmd](a)


if __name__ == "__main__":
    main()
