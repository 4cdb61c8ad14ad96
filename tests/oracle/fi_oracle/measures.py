"""Geometric measures with numpy and scipy, independent of MeshLab and of the plugin:
the exact symmetric Hausdorff distance between two triangle meshes, bounding-box diagonal,
triangle areas and angles, the discrete Gaussian curvature near points."""
import numpy as np

from .topology import as_mesh, referenced_mask, unique_edges

__all__ = ["closest_point_distances", "surface_samples", "hausdorff", "hausdorff_percent", "diagonal",
           "triangle_areas", "edge_length_for", "mean_edge_length", "triangle_angles", "shape_measures",
           "gaussian_curvature_near", "face_normals", "crease_vertex_mask", "vertex_normals", "thin_vertex_mask"]


def closest_point_distances(points, mesh, candidates=12):
    """Distance from each point to the surface of mesh: exact point-triangle distances
    (Ericson, Real-Time Collision Detection, 5.1.5) to the `candidates` triangles whose
    centroids are nearest (scipy's cKDTree). That alone is an upper bound (on uneven meshes the
    closest triangle can have a farther centroid), so the largest values are then made exact:
    the closest triangle of p has its centroid within d + R of p (d: any triangle's distance,
    R: the largest centroid-to-corner distance), and all those are checked, until no point
    left with an upper bound exceeds the largest exact value. The maximum is therefore exact;
    smaller values may stay upper bounds."""
    from scipy.spatial import cKDTree
    m = as_mesh(mesh)
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    tri = m.vertices[m.faces]
    cen = tri.mean(axis=1)
    tree = cKDTree(cen)
    k = min(candidates, len(tri))
    chunk = 50000  # bounded memory: (chunk, k, 3) arrays
    d = np.concatenate([_closest_in(points[i:i + chunk], tri, tree.query(points[i:i + chunk], k=k)[1])
                        for i in range(0, len(points), chunk)])
    reach = float(np.linalg.norm(tri - cen[:, None, :], axis=2).max())
    exact = np.zeros(len(points), bool)
    best = 0.0
    while True:
        todo = np.nonzero(~exact & (d > best))[0]
        if len(todo) == 0:
            return d
        todo = todo[np.argsort(-d[todo])][:256]
        for i in todo:
            near = tree.query_ball_point(points[i], d[i] + reach)
            if near:
                d[i] = min(d[i], _closest_in(points[i:i + 1], tri, np.array([near]))[0])
            exact[i] = True
        best = max(best, float(d[todo].max()))


def _closest_in(points, tri, idx):
    """Distance from each point to the nearest of its candidate triangles idx (n, k)."""
    idx = idx.reshape(len(points), -1)
    k = idx.shape[1]
    p = np.repeat(points[:, None, :], k, axis=1)
    a, b, c = tri[idx, 0], tri[idx, 1], tri[idx, 2]
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
    bp = p - b
    d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
    cp = p - c
    d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        den = va + vb + vc
        v, w = vb / den, vc / den
        q = a + ab * v[..., None] + ac * w[..., None]  # inside the face
        t_ab = d1 / (d1 - d3)
        q = np.where(((vc <= 0) & (d1 >= 0) & (d3 <= 0))[..., None], a + ab * t_ab[..., None], q)
        t_ac = d2 / (d2 - d6)
        q = np.where(((vb <= 0) & (d2 >= 0) & (d6 <= 0))[..., None], a + ac * t_ac[..., None], q)
        t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        q = np.where(((va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0))[..., None], b + (c - b) * t_bc[..., None], q)
    q = np.where(((d1 <= 0) & (d2 <= 0))[..., None], a, q)
    q = np.where(((d3 >= 0) & (d4 <= d3))[..., None], b, q)
    q = np.where(((d6 >= 0) & (d5 <= d6))[..., None], c, q)
    q = np.where(np.isfinite(q), q, a)  # degenerate triangles: their first corner
    return np.linalg.norm(p - q, axis=-1).min(axis=1)


def surface_samples(mesh, per_edge=2, midpoints=False):
    """Vertices, points along every edge and inside every face (where a surface leaves
    another one farthest: corners, creases, face interiors). midpoints: the edges' midpoints
    too (with per_edge 2, the very points the filter's own measure samples: quality.h
    MaxSampleDistance)."""
    m = as_mesh(mesh)
    tri = m.vertices[m.faces]
    pts = [m.vertices[referenced_mask(m)], tri.mean(axis=1)]
    for t in list(np.arange(1, per_edge + 1) / (per_edge + 1)) + ([0.5] if midpoints else []):
        for z in range(3):
            pts.append(tri[:, z] * (1 - t) + tri[:, (z + 1) % 3] * t)
    for u, v in [(0.6, 0.2), (0.2, 0.6), (0.2, 0.2)]:
        pts.append(tri[:, 0] * u + tri[:, 1] * v + tri[:, 2] * (1 - u - v))
    return np.concatenate(pts)


def hausdorff(mesh_a, mesh_b, midpoints=False):
    """Symmetric Hausdorff distance between two triangle meshes, measured with numpy and
    scipy: (max a->b, max b->a), absolute. Each side is the maximum, over fixed sample points
    of one surface (surface_samples: vertices, edge midpoints, face centroids), of the exact
    distance to the other surface: a lower bound of the true Hausdorff distance, so a sampler
    placing its points elsewhere (MeshLab's) may report slightly more. midpoints: sample the
    edges' midpoints too (surface_samples)."""
    a, b = as_mesh(mesh_a), as_mesh(mesh_b)
    return (float(closest_point_distances(surface_samples(a, midpoints=midpoints), b).max()),
            float(closest_point_distances(surface_samples(b, midpoints=midpoints), a).max()))


def hausdorff_percent(original, result, midpoints=False):
    """max(hausdorff(original, result)) in percent of the original's bounding-box diagonal."""
    return 100.0 * max(hausdorff(original, result, midpoints)) / diagonal(original)


def diagonal(mesh):
    """Length of the bounding-box diagonal."""
    v = as_mesh(mesh).vertices
    return float(np.linalg.norm(v.max(axis=0) - v.min(axis=0)))


def triangle_areas(mesh):
    m = as_mesh(mesh)
    p = m.vertices[m.faces]
    return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def edge_length_for(mesh, vertices):
    """Edge length of equilateral triangles that gives this surface about `vertices` vertices
    (each vertex owns two triangles), as vcg_ext's EdgeLengthForVertexCount."""
    return float(np.sqrt(2 * triangle_areas(mesh).sum() / (np.sqrt(3) * vertices)))


def mean_edge_length(mesh):
    m = as_mesh(mesh)
    f = m.faces
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    return float(np.linalg.norm(m.vertices[e[:, 0]] - m.vertices[e[:, 1]], axis=1).mean())


def triangle_angles(mesh):
    """(F, 3) interior angles in degrees."""
    m = as_mesh(mesh)
    p = m.vertices[m.faces]
    out = np.empty(m.faces.shape)
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        c = (u * v).sum(1) / (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1))
        out[:, k] = np.degrees(np.arccos(np.clip(c, -1, 1)))
    return out


def shape_measures(mesh):
    """Smallest angle, mean of the triangles' smallest angles, share of triangles whose
    smallest angle is under 30 degrees."""
    mn = triangle_angles(mesh).min(axis=1)
    return {"min_angle": float(mn.min()), "mean_min_angle": float(mn.mean()),
            "share_below_30": float((mn < 30).mean())}


def gaussian_curvature_near(mesh, points, radius):
    """Discrete Gaussian curvature of mesh (angle defect over vertex area) averaged over the
    vertices within radius of each point: the sign tells a cap (> 0) from a saddle (< 0)."""
    from scipy.spatial import cKDTree
    m = as_mesh(mesh)
    v, f = m.vertices, m.faces
    defect = np.full(len(v), 2 * np.pi)
    np.subtract.at(defect, f.ravel(), np.radians(triangle_angles(m)).ravel())
    vertex_area = np.zeros(len(v))
    np.add.at(vertex_area, f.ravel(), np.repeat(triangle_areas(m) / 3, 3))
    tree = cKDTree(v)
    out = []
    for q in np.atleast_2d(points):
        idx = tree.query_ball_point(q, radius)
        out.append(defect[idx].sum() / max(vertex_area[idx].sum(), 1e-300) if idx else 0.0)
    return np.array(out)


def face_normals(mesh):
    """Unit normals of the faces (orientation from the vertex order)."""
    m = as_mesh(mesh)
    p = m.vertices[m.faces]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)


def crease_vertex_mask(mesh, angle_deg):
    """Vertices on an edge whose two faces' normals differ by more than angle_deg (the
    dihedral angle MeshLab's feature-angle parameters compare)."""
    m = as_mesh(mesh)
    f = m.faces
    n = face_normals(m)
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    owner = np.tile(np.arange(len(f)), 3)
    key = e[:, 0] * len(m.vertices) + e[:, 1]
    order = np.argsort(key, kind="stable")
    key, e, owner = key[order], e[order], owner[order]
    same = np.nonzero(key[1:] == key[:-1])[0]  # consecutive pairs: the two faces of an edge
    cos = (n[owner[same]] * n[owner[same + 1]]).sum(axis=1)
    sharp = np.degrees(np.arccos(np.clip(cos, -1, 1))) > angle_deg
    out = np.zeros(len(m.vertices), dtype=bool)
    out[e[same[sharp]].ravel()] = True
    return out


def vertex_normals(mesh):
    """Unit area-weighted vertex normals, turned outward: if the mesh encloses a negative
    signed volume (faces wound clockwise seen from outside), every normal is flipped."""
    m = as_mesh(mesh)
    p = m.vertices[m.faces]
    fn = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])  # twice the area times the unit normal
    n = np.zeros_like(m.vertices)
    for z in range(3):
        np.add.at(n, m.faces[:, z], fn)
    volume = float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum()) / 6.0
    if volume < 0:
        n = -n
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)


def thin_vertex_mask(mesh, edges=4.0, which=None):
    """Vertices on a part thinner than `edges` edge lengths (issue 14's thin-part exception:
    fingers, toes, thin bones). v is on one if a vertex u of the surface facing the other way
    (n_u . n_v < -0.5) lies behind v ((u - v) . n_v < 0: inside, with outward normals) within
    edges * h_v, h_v being the mean length of v's edges: the opposite side of a tube or a plate
    is that close. which: the vertex indices to test (default all); the others are False."""
    from scipy.spatial import cKDTree
    m = as_mesh(mesh)
    nv = len(m.vertices)
    out = np.zeros(nv, dtype=bool)
    idx = np.arange(nv) if which is None else np.asarray(which, dtype=np.int64).ravel()
    if len(idx) == 0 or len(m.faces) == 0:
        return out
    e, _ = unique_edges(m)
    length = np.linalg.norm(m.vertices[e[:, 0]] - m.vertices[e[:, 1]], axis=1)
    total, count = np.zeros(nv), np.zeros(nv)
    for z in range(2):
        np.add.at(total, e[:, z], length)
        np.add.at(count, e[:, z], 1)
    h = total / np.maximum(count, 1)
    n = vertex_normals(m)
    ref = referenced_mask(m)
    tree = cKDTree(m.vertices)
    for v in idx[ref[idx]]:
        near = np.asarray(tree.query_ball_point(m.vertices[v], edges * h[v]), dtype=np.int64)
        if len(near) == 0:
            continue
        facing = n[near] @ n[v] < -0.5
        behind = (m.vertices[near] - m.vertices[v]) @ n[v] < 0
        out[v] = bool(np.any(facing & behind & ref[near]))
    return out
