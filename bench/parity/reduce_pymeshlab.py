"""One Automatic Reduction of a mesh through pymeshlab 2025.7 (the MeshLab 2025.07 plugin), as
bench/parity/reduce_bunny.mlx does through meshlabserver: load, reduce without remeshing and
without time limit, save PLY with colour and quality. Prints the returned irregular counts.
    .deps/venv/bin/python bench/parity/reduce_pymeshlab.py IN OUT.ply"""
import os
import sys

import pymeshlab

here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(here, "python"))
os.environ.setdefault("FILTER_IRREGULAR_PLUGIN", os.path.join(here, "build", "plugin2025", "libfilter_irregular.so"))
import pymeshlab_irregular  # noqa: E402

pymeshlab_irregular.load()
ms = pymeshlab.MeshSet()
ms.load_new_mesh(sys.argv[1])
r = ms.meshing_irregular_automatic_reduction(remeshedgelength=pymeshlab.PureValue(0), timelimit=0)
ms.save_current_mesh(sys.argv[2], save_vertex_color=True, save_vertex_quality=True)
print("pymeshlab: %d -> %d irregular, Hausdorff %.4f%%, reduction %.2f s"
      % (r["irregular_before"], r["irregular_after"], r["hausdorff_percent"], r["reduction_seconds"]))
