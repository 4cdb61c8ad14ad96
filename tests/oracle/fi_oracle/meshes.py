"""Small synthetic meshes as (vertices, faces) arrays: regular solids, a grid patch, and the
defective inputs every filter must refuse (each with the MeshLab filter the refusal names)."""
import numpy as np

from .topology import Tri

__all__ = ["icosahedron", "octahedron", "grid", "bad_meshes"]


def icosahedron():
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return Tri(v, f)


def octahedron():
    v = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    f = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return Tri(v, f)


def grid(n, jitter=0.0, seed=0):
    """(n+1) x (n+1) vertices on [0, n]^2 in the z = 0 plane, each square split by a diagonal."""
    ys, xs = np.mgrid[0:n + 1, 0:n + 1]
    v = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1).astype(float)
    if jitter:  # move interior vertices only, so the outline stays the square
        inner = (v[:, 0] > 0) & (v[:, 0] < n) & (v[:, 1] > 0) & (v[:, 1] < n)
        v[inner, :2] += np.random.default_rng(seed).uniform(-jitter, jitter, (inner.sum(), 2))
    i = (ys[:-1, :-1] * (n + 1) + xs[:-1, :-1]).ravel()
    f = np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])
    return Tri(v, f)


def bad_meshes():
    """name -> (vertices (n, 3), faces: an (m, 3) array or, for polygons, a list of index
    lists, the words the refusal must contain)."""
    o = octahedron()
    v, f = o.vertices, o.faces
    out = {}
    # a third face on the edge (0, 2)
    out["non-manifold edge"] = (np.vstack([v, [(0.5, 0.5, 0.5)]]), np.vstack([f, [(0, 2, 6)]]),
                                "Repair non Manifold Edges")
    # two octahedra sharing vertex 0
    v2 = np.vstack([v, v[1:] + (2, 0, 0)])
    f2 = np.vstack([f, np.where(f == 0, 0, f + 5)])
    out["non-manifold vertex"] = (v2, f2, "Repair non Manifold Vertices")
    # a cube of quads
    cube = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], float)
    quads = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    out["polygons"] = (cube, quads, "Turn into a Pure-Triangular mesh")
    # vertex 6 duplicates vertex 0; face (6, 2, 4) uses the copy
    f3 = f.copy()
    f3[0] = (6, 2, 4)
    out["duplicated vertices"] = (np.vstack([v, v[:1]]), f3, "Remove Duplicate Vertices")
    out["unreferenced vertices"] = (np.vstack([v, [(5, 5, 5)]]), f, "Remove Unreferenced Vertices")
    # vertex 4 moved onto the segment (0, 2): face (0, 2, 4) has zero area, the mesh stays a
    # closed manifold
    v5 = v.copy()
    v5[4] = (0.5, 0.5, 0.0)
    out["zero-area face"] = (v5, f, "Remove Zero Area Faces")
    # a face with a repeated vertex
    out["repeated vertex in a face"] = (np.vstack([v, [(0.5, 0.5, 0.5)]]), np.vstack([f, [(0, 6, 6)]]),
                                        "Remove Duplicate Faces")
    # one face turned over
    f7 = f.copy()
    f7[0] = f7[0][::-1]
    out["inconsistent orientation"] = (v, f7, "Re-Orient all faces coherentely")
    return out
