"""mlpy: what the meshlabserver smoke suite and the scripts need beyond the oracle: the staged
meshlabserver driven from Python (mlpy.server), PLY/OFF files (mlpy.files), a numpy renderer to
PNG (mlpy.render). The independent measures live in tests/oracle/fi_oracle; they are
re-exported here under their old names for scripts/ (diagonal, hausdorff, ... also accept a
file path, as they did)."""
import os as _os
import sys as _sys

from .files import *  # noqa: F401,F403
from .files import data_path, read_mesh
from .server import *  # noqa: F401,F403

_ORACLE = _os.path.join(_os.path.dirname(_os.path.dirname(_os.path.dirname(_os.path.abspath(__file__)))), "oracle")
if _ORACLE not in _sys.path:
    _sys.path.insert(0, _ORACLE)
import fi_oracle as _fo  # noqa: E402

from fi_oracle import (boundary_loop_count, boundary_mask, boundary_vertex_mask, check_invariants,  # noqa: E402,F401
                       component_count, edge_length_for, euler_characteristic, gauss_bonnet_sum,
                       gaussian_curvature_near, genus, irregular_mask, is_consistently_oriented, is_edge_manifold,
                       referenced_mask, shape_measures, triangle_angles, triangle_areas, unique_edges, valences)


def _mesh(m):
    return read_mesh(data_path(m)) if isinstance(m, str) else m


def diagonal(mesh):
    """Bounding-box diagonal of a mesh or of a mesh file."""
    return _fo.diagonal(_mesh(mesh))


def hausdorff(mesh_a, mesh_b):
    """fi_oracle.hausdorff of two meshes or mesh files: (max a->b, max b->a), absolute."""
    return _fo.hausdorff(_mesh(mesh_a), _mesh(mesh_b))
