"""Integration: 'Irregular Vertices: Relax' through meshlabserver."""
import os

import numpy as np

from mlpy import EXAMPLES, Enum, Filter, check_invariants, read_off, run


def min_angles(m):
    p = m.vertices[m.faces]
    def ang(a, b, c):
        u, v = b - a, c - a
        cos = (u * v).sum(1) / (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1))
        return np.degrees(np.arccos(np.clip(cos, -1, 1)))
    return np.minimum(np.minimum(ang(p[:, 0], p[:, 1], p[:, 2]), ang(p[:, 1], p[:, 2], p[:, 0])),
                      ang(p[:, 2], p[:, 0], p[:, 1]))


def test_example_global_relaxation_improves_and_keeps_connectivity(corpus):
    src = read_off(corpus("bunny00.off"))
    r = run(corpus("bunny00.off"), filters=os.path.join(EXAMPLES, "relax.mlx"))
    assert r.ok, r.log
    assert np.array_equal(r.mesh.faces, src.faces)
    before, after = min_angles(src), min_angles(r.mesh)
    assert (after < 30).mean() < (before < 30).mean()
    assert after.mean() > before.mean()
    assert "Hausdorff distance to the input" in r.log
    check_invariants(r.mesh)


def test_local_relaxation_of_selection_moves_only_selection(corpus):
    src = read_off(corpus("knot1.off"))
    flt = [Filter("Conditional Vertex Selection", condSelect="(vi < 500)"),
           Filter("Irregular Vertices: Relax", mode=Enum(0, ["Local", "Global"]), iterations=5,
                  region=Enum(1, ["All", "Selection", "Around irregular vertices"]), reproject=True,
                  featureAngle=60.0)]
    r = run(corpus("knot1.off"), filters=flt)
    assert r.ok, r.log
    moved = np.linalg.norm(r.mesh.vertices - src.vertices, axis=1) > 1e-7
    assert moved[:500].any()
    assert not moved[500:].any()
