"""Topology of a triangle mesh measured from its face array alone, with numpy: valences,
boundary, Euler characteristic, genus, manifoldness, orientation, irregular vertices, the
discrete Gauss-Bonnet sum, ordered one-rings and graph distances.

Every function takes a mesh in any of these forms (see as_mesh): an object with `vertices`
and `faces` arrays, a (vertices, faces) pair, or a pymeshlab.Mesh (vertex_matrix(),
face_matrix()). Nothing here calls MeshLab or the plugin."""
from collections import deque

import numpy as np

__all__ = [
    "Tri", "as_mesh", "edges", "unique_edges", "referenced_mask", "valences", "boundary_vertex_mask",
    "boundary_mask", "equivalent_valences", "euler_characteristic", "boundary_loop_count", "component_count",
    "genus", "is_edge_manifold", "fan_counts", "is_vertex_manifold", "is_consistently_oriented", "irregular_mask",
    "gauss_bonnet_sum", "check_invariants", "summary", "counts", "histogram", "one_ring", "neighbour_from",
    "adjacent", "hop_distances", "adjacency_lists", "opposite_vertices", "degenerate_face_mask",
    "duplicate_vertex_mask", "corner_angles", "regular_boundary_valence", "regular_valences", "corner_mask",
]


class Tri:
    """A triangle mesh as two arrays: vertices (n, 3) float64, faces (m, 3) int64."""

    def __init__(self, vertices, faces):
        self.vertices = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
        self.faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)

    def __repr__(self):
        return "Tri(%d vertices, %d faces)" % (len(self.vertices), len(self.faces))


def as_mesh(mesh):
    """A Tri from an object with .vertices/.faces, a (vertices, faces) pair, or anything with
    vertex_matrix()/face_matrix() methods (pymeshlab.Mesh)."""
    if isinstance(mesh, Tri):
        return mesh
    if hasattr(mesh, "vertex_matrix") and hasattr(mesh, "face_matrix"):
        return Tri(mesh.vertex_matrix(), mesh.face_matrix())
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return Tri(mesh.vertices, mesh.faces)
    if isinstance(mesh, (tuple, list)) and len(mesh) == 2:
        return Tri(mesh[0], mesh[1])
    raise TypeError("not a mesh: %r" % type(mesh))


def edges(mesh):
    """(3m, 2) sorted vertex pairs, one per face corner (shared edges repeat)."""
    f = as_mesh(mesh).faces
    return np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)


def unique_edges(mesh):
    """(distinct edges (E, 2), number of faces using each)."""
    m = as_mesh(mesh)
    n = max(len(m.vertices), 1)
    e = edges(m)
    keys, counts = np.unique(e[:, 0] * n + e[:, 1], return_counts=True)  # 1-D unique is much faster
    return np.stack([keys // n, keys % n], axis=1), counts


def referenced_mask(mesh):
    m = as_mesh(mesh)
    r = np.zeros(len(m.vertices), dtype=bool)
    r[m.faces.ravel()] = True
    return r


def valences(mesh):
    """Number of distinct edges at each vertex (unreferenced vertices: 0)."""
    m = as_mesh(mesh)
    e, _ = unique_edges(m)
    return np.bincount(e.ravel(), minlength=len(m.vertices))


def boundary_vertex_mask(mesh):
    """Vertices on an edge used by exactly one face."""
    m = as_mesh(mesh)
    e, counts = unique_edges(m)
    b = np.zeros(len(m.vertices), dtype=bool)
    b[e[counts == 1].ravel()] = True
    return b


boundary_mask = boundary_vertex_mask  # short alias


def corner_angles(mesh):
    """Sum of the face angles at every vertex, in degrees (atan2 of |a x b| and a . b)."""
    m = as_mesh(mesh)
    f = m.faces
    out = np.zeros(len(m.vertices))
    if len(f) == 0:
        return out
    p = m.vertices[f]
    for z in range(3):
        a = p[:, (z + 1) % 3] - p[:, z]
        b = p[:, (z + 2) % 3] - p[:, z]
        ang = np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), (a * b).sum(axis=1)))
        np.add.at(out, f[:, z], ang)
    return out


def regular_boundary_valence(angle_deg):
    """The boundary valence rule: round(angle / 60) + 1 (half away from zero), at least 2."""
    a = np.asarray(angle_deg, dtype=np.float64)
    r = np.floor(a / 60.0 + 0.5).astype(np.int64) + 1  # angles are positive: half away from zero
    return np.maximum(r, 2)


def regular_valences(mesh):
    """6 inside; on the boundary the valence rule of the corner angle."""
    m = as_mesh(mesh)
    return np.where(boundary_vertex_mask(m), regular_boundary_valence(corner_angles(m)), 6)


def corner_mask(mesh):
    """Boundary vertices whose regular valence is not 4 (corner angle below 150 or at least 210)."""
    m = as_mesh(mesh)
    return referenced_mask(m) & boundary_vertex_mask(m) & (regular_valences(m) != 4)


def equivalent_valences(mesh):
    """valence + 6 - regular valence: interior valence, boundary valence + 2 on a smooth stretch
    (the plugin's legend and its v3..v9 counts)."""
    m = as_mesh(mesh)
    return valences(m) + 6 - regular_valences(m)


def euler_characteristic(mesh):
    """V - E + F, counting only the vertices that faces reference."""
    m = as_mesh(mesh)
    return int(referenced_mask(m).sum()) - len(unique_edges(m)[0]) + len(m.faces)


def _components(n, pairs):
    """Union-find over n items joined by pairs; returns the root of each item."""
    par = list(range(n))

    def root(a):
        while par[a] != a:
            par[a] = par[par[a]]
            a = par[a]
        return a

    for a, b in np.asarray(pairs).reshape(-1, 2).tolist():
        ra, rb = root(a), root(b)
        if ra != rb:
            par[ra] = rb
    return np.array([root(a) for a in range(n)], dtype=np.int64)


def boundary_loop_count(mesh):
    """Connected components of the boundary edges (one per loop on a manifold mesh)."""
    e, counts = unique_edges(mesh)
    be = e[counts == 1]
    if len(be) == 0:
        return 0
    verts, local = np.unique(be, return_inverse=True)
    return len(np.unique(_components(len(verts), local.reshape(-1, 2))))


def component_count(mesh):
    """Connected components of the faces (through shared vertices)."""
    m = as_mesh(mesh)
    ref = np.nonzero(referenced_mask(m))[0]
    if len(ref) == 0:
        return 0
    local = np.searchsorted(ref, unique_edges(m)[0])
    return len(np.unique(_components(len(ref), local)))


def genus(mesh):
    """g from chi = 2 - 2g - b, for a connected orientable manifold mesh."""
    m = as_mesh(mesh)
    if component_count(m) != 1:
        raise ValueError("genus needs a connected mesh (%d components)" % component_count(m))
    twice = 2 - euler_characteristic(m) - boundary_loop_count(m)
    if twice % 2:
        raise ValueError("odd 2 - chi - b: not an orientable manifold")
    return twice // 2


def is_edge_manifold(mesh):
    """Every edge used by one or two faces."""
    return bool((unique_edges(mesh)[1] <= 2).all())


def fan_counts(mesh):
    """Number of fans of faces around every vertex (faces joined through the edges at the
    vertex): 1 on a manifold mesh, more where separate fans meet at one vertex, 0 unreferenced.
    Graph: one node per (vertex, neighbour) pair; each face corner (v; b, c) joins (v, b) and
    (v, c); the fans of v are the connected components among v's nodes (scipy's csgraph)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    m = as_mesh(mesh)
    n = max(len(m.vertices), 1)
    f = m.faces
    v = f.ravel()
    b = np.roll(f, -1, axis=1).ravel()
    c = np.roll(f, -2, axis=1).ravel()
    keys, inv = np.unique(np.concatenate([v * n + b, v * n + c]), return_inverse=True)
    inv = inv.ravel()
    k = len(v)
    g = coo_matrix((np.ones(k), (inv[:k], inv[k:])), shape=(len(keys), len(keys)))
    _, label = connected_components(g, directed=False)
    owner = keys // n
    pairs = np.unique(np.stack([owner, label], axis=1), axis=0)
    return np.bincount(pairs[:, 0], minlength=len(m.vertices))


def is_vertex_manifold(mesh):
    """Every referenced vertex has one fan of faces."""
    fans = fan_counts(mesh)
    return bool((fans[referenced_mask(mesh)] == 1).all())


def is_consistently_oriented(mesh):
    """Every directed edge appears at most once (two faces on an edge run it opposite ways)."""
    f = as_mesh(mesh).faces
    d = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    return len(np.unique(d, axis=0)) == len(d)


def irregular_mask(mesh):
    """Referenced vertices with valence != 6 (interior) or != the boundary valence rule's
    round(corner angle / 60) + 1 (boundary: 4 on a smooth stretch)."""
    m = as_mesh(mesh)
    return referenced_mask(m) & (valences(m) != regular_valences(m))


def gauss_bonnet_sum(mesh):
    """Sum of (6 - valence) inside and (4 - valence) on the boundary; 6 chi on a manifold mesh."""
    m = as_mesh(mesh)
    deficit = np.where(boundary_vertex_mask(m), 4, 6) - valences(m)
    return int(deficit[referenced_mask(m)].sum())


def degenerate_face_mask(mesh):
    """Faces with a repeated vertex or zero area."""
    m = as_mesh(mesh)
    f = m.faces
    p = m.vertices[f]
    area2 = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    return (f[:, 0] == f[:, 1]) | (f[:, 1] == f[:, 2]) | (f[:, 2] == f[:, 0]) | (area2 == 0)


def duplicate_vertex_mask(mesh):
    """Vertices at exactly the position of another vertex (all copies marked)."""
    v = as_mesh(mesh).vertices
    _, inv, counts = np.unique(v, axis=0, return_inverse=True, return_counts=True)
    return counts[inv.ravel()] > 1


def check_invariants(mesh):
    """Edge manifold, consistently oriented, no degenerate face, interior valence >= 3,
    Gauss-Bonnet holds."""
    m = as_mesh(mesh)
    assert is_edge_manifold(m), "non-manifold edge"
    assert is_consistently_oriented(m), "inconsistent orientation"
    assert not degenerate_face_mask(m).any(), "degenerate face"
    interior = referenced_mask(m) & ~boundary_vertex_mask(m)
    assert (valences(m)[interior] >= 3).all(), "interior valence < 3"
    assert gauss_bonnet_sum(m) == 6 * euler_characteristic(m), "Gauss-Bonnet fails"


def histogram(values):
    """Counts of 0..max(values) as a float vector (as the plugin's valence_histogram)."""
    values = np.asarray(values, dtype=np.int64)
    return np.bincount(values, minlength=1).astype(np.float64) if len(values) else np.zeros(1)


def counts(mesh, suffix=""):
    """The counts the editing filters return with a suffix ("_before", "_after"): irregular,
    boundary_irregular, v3 (equivalent valence 3 or less), v4, v5, v7, v8, v9 (9 or more), valence_histogram
    (interior vertices by valence)."""
    m = as_mesh(mesh)
    ref = referenced_mask(m)
    bnd = boundary_vertex_mask(m)
    val = valences(m)
    eq = equivalent_valences(m)[ref]
    irr = irregular_mask(m)
    out = {"irregular": int(irr.sum()), "boundary_irregular": int((irr & bnd).sum()),
           "v3": int((eq <= 3).sum()), "v4": int((eq == 4).sum()),
           "v5": int((eq == 5).sum()), "v7": int((eq == 7).sum()), "v8": int((eq == 8).sum()),
           "v9": int((eq >= 9).sum()), "valence_histogram": histogram(val[ref & ~bnd])}
    return {k + suffix: v for k, v in out.items()}


def summary(mesh):
    """Everything Analyze returns, measured here: vertices, edges, faces, the counts above,
    irregular_percent, boundary_valence_histogram, euler_characteristic, genus (connected
    meshes only; else absent), boundary_loops, components, gauss_bonnet_sum, gauss_bonnet_holds."""
    m = as_mesh(mesh)
    ref = referenced_mask(m)
    bnd = boundary_vertex_mask(m)
    out = {"vertices": int(ref.sum()), "edges": len(unique_edges(m)[0]), "faces": len(m.faces)}
    out.update(counts(m))
    out["irregular_percent"] = 100.0 * out["irregular"] / max(out["vertices"], 1)
    out["boundary_valence_histogram"] = histogram(valences(m)[ref & bnd])
    out["boundary_corners"] = int(corner_mask(m).sum())
    out["euler_characteristic"] = euler_characteristic(m)
    out["boundary_loops"] = boundary_loop_count(m)
    out["components"] = component_count(m)
    if out["components"] == 1:
        out["genus"] = genus(m)
    out["gauss_bonnet_sum"] = gauss_bonnet_sum(m)
    out["gauss_bonnet_holds"] = out["gauss_bonnet_sum"] == 6 * out["euler_characteristic"]
    return out


# ------------------------------------------------------------------ neighbourhoods
def adjacency_lists(mesh):
    """Neighbours of every vertex (sorted lists)."""
    m = as_mesh(mesh)
    e, _ = unique_edges(m)
    nb = [[] for _ in range(len(m.vertices))]
    for a, b in e.tolist():
        nb[a].append(b)
        nb[b].append(a)
    return [sorted(x) for x in nb]


def adjacent(mesh, a, b):
    e, _ = unique_edges(mesh)
    lo, hi = min(a, b), max(a, b)
    return bool(((e[:, 0] == lo) & (e[:, 1] == hi)).any())


def one_ring(mesh, v):
    """Neighbours of the interior vertex v in counter-clockwise order (the faces' orientation:
    in a face (v, a, b), b follows a), starting at an arbitrary neighbour. Raises on a
    boundary or non-manifold vertex."""
    f = as_mesh(mesh).faces
    nxt = {}
    for row in f[(f == v).any(axis=1)].tolist():
        k = row.index(v)
        a, b = row[(k + 1) % 3], row[(k + 2) % 3]
        if a in nxt:
            raise ValueError("vertex %d is not manifold" % v)
        nxt[a] = b
    if not nxt or set(nxt) != set(nxt.values()):
        raise ValueError("vertex %d is on the boundary" % v)
    start = next(iter(nxt))
    ring = [start]
    while nxt[ring[-1]] != start:
        ring.append(nxt[ring[-1]])
    if len(ring) != len(nxt):
        raise ValueError("vertex %d is not manifold" % v)
    return ring


def neighbour_from(mesh, v, k, ref=None):
    """Neighbour number k of v counting counter-clockwise from ref (None: the neighbour of
    smallest index), as the plugin's 'direction' parameters count."""
    ring = one_ring(mesh, v)
    i0 = ring.index(min(ring) if ref is None else ref)
    return ring[(i0 + k) % len(ring)]


def hop_distances(mesh, sources):
    """Edge-graph distance (number of edges) from the nearest of `sources` to every vertex
    (-1: unreachable)."""
    nb = adjacency_lists(mesh)
    dist = np.full(len(nb), -1, dtype=np.int64)
    q = deque()
    for s in np.atleast_1d(sources).tolist():
        dist[s] = 0
        q.append(s)
    while q:
        a = q.popleft()
        for b in nb[a]:
            if dist[b] < 0:
                dist[b] = dist[a] + 1
                q.append(b)
    return dist


def opposite_vertices(mesh, a, b):
    """The two vertices opposite to the edge (a, b) (the third corners of its two faces)."""
    f = as_mesh(mesh).faces
    rows = f[((f == a).any(axis=1)) & ((f == b).any(axis=1))]
    return sorted(int(x) for r in rows.tolist() for x in r if x not in (a, b))
