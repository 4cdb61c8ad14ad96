#!/usr/bin/env python3
"""The main job, through pymeshlab 2025.7 and the MeshLab 2025.07 plugin: analyze a mesh
(colours by valence, irregular vertices selected, counts returned), then Automatic Reduction
(remeshed to about 20K vertices first, then reduced); writes PLYs, PNGs and the returned dicts.

    .deps/venv/bin/python scripts/demo.py [mesh] [output folder]

Run by scripts/demo.sh, which installs and builds first.
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
import pymeshlab

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(here, "python"))
os.environ.setdefault("FILTER_IRREGULAR_PLUGIN", os.path.join(here, "build", "plugin2025", "libfilter_irregular.so"))
import pymeshlab_irregular  # noqa: E402


def plain(d):
    """The returned dict with numpy vectors as lists (for JSON)."""
    return {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in d.items()}


def edge_length_for(ms, vertices):
    """Edge length of equilateral triangles giving this surface about `vertices` vertices
    (each vertex owns two triangles)."""
    area = ms.get_geometric_measures()["surface_area"]
    return math.sqrt(2 * area / (math.sqrt(3) * vertices))


def render(ply, png, title):
    subprocess.run([sys.executable, os.path.join(here, "scripts", "render_png.py"), ply, png, "--legend",
                    "--title", title], check=True)


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, ".deps", "data", "meshes", "bunny00.off")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "out")
    os.makedirs(out, exist_ok=True)
    name = os.path.splitext(os.path.basename(src))[0]
    pymeshlab_irregular.load()

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(src)
    analysis = ms.compute_irregular_vertex_analysis()
    ms.save_current_mesh(os.path.join(out, name + "_irregular.ply"), save_vertex_color=True, save_vertex_quality=True)
    with open(os.path.join(out, name + "_analysis.json"), "w") as f:
        json.dump(plain(analysis), f, indent=1)
    print("%s: %d of %d vertices irregular (%.2f%%), chi %d, genus %d, Gauss-Bonnet %s"
          % (name, analysis["irregular"], analysis["vertices"], analysis["irregular_percent"],
             analysis["euler_characteristic"], analysis["genus"], "holds" if analysis["gauss_bonnet_holds"] else "FAILS"))
    render(os.path.join(out, name + "_irregular.ply"), os.path.join(out, name + "_irregular.png"),
           name + ": irregular vertices")

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(src)
    length = edge_length_for(ms, 20000)
    t0 = time.time()
    reduction = ms.meshing_irregular_automatic_reduction(remeshedgelength=pymeshlab.PureValue(length), timelimit=0)
    seconds = time.time() - t0
    ms.save_current_mesh(os.path.join(out, name + "_reduced.ply"), save_vertex_color=True, save_vertex_quality=True)
    with open(os.path.join(out, name + "_reduced.json"), "w") as f:
        json.dump(plain(reduction), f, indent=1)
    print("%s: Automatic Reduction (remeshed to %d vertices, edge length %.5g): %d -> %d irregular vertices, "
          "Hausdorff %.3f%% of the diagonal, min angle %.1f deg, %.1f s"
          % (name, reduction["vertices_after"], length, reduction["irregular_before"], reduction["irregular_after"],
             reduction["hausdorff_percent"], reduction["min_angle_after"], seconds))
    render(os.path.join(out, name + "_reduced.ply"), os.path.join(out, name + "_reduced.png"),
           name + ": after Automatic Reduction")
    print("demo: wrote %s/%s_{irregular,reduced}.{ply,png,json}" % (out, name))


if __name__ == "__main__":
    main()
