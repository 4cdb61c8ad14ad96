"""fi_oracle: independent measures for the filter_irregular tests, computed with numpy and
scipy from a mesh's arrays (vertices, faces) and nothing else: topology (valences, boundary,
Euler characteristic, genus, manifoldness, orientation, irregular vertices, Gauss-Bonnet,
ordered one-rings), geometry (exact symmetric Hausdorff distance, angles, areas, Gaussian
curvature), the plugin's colour legend, and small synthetic meshes including the defective
inputs every filter must refuse.

A mesh is anything as_mesh() accepts: an object with `vertices` and `faces`, a (vertices,
faces) pair, or a pymeshlab.Mesh."""
from .legend import *  # noqa: F401,F403
from .measures import *  # noqa: F401,F403
from .meshes import *  # noqa: F401,F403
from .topology import *  # noqa: F401,F403
