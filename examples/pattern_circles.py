"""Generate, then pattern (paper sec. 10, Fig. 14): circles made with the triangulation.

A circle of the circle pattern is a ring of faces at a fixed graph distance around a cluster of
irregular vertices that closes as an annulus (vcg_ext/irregular/circle_pattern.h). A regular
lattice has none; generating irregular vertices on purpose, well apart, makes circles close
around each of them, as the paper does on the U-shaped model (from 36 to about 560 irregular
vertices). This script shows it on a regular torus (or on your mesh):

    python3 examples/pattern_circles.py                 # a regular 40 x 40 torus
    python3 examples/pattern_circles.py mesh.ply out    # your mesh: the vertices to generate at
                                                        # are spread over it; writes out.ply and
                                                        # out_panels.ply

It needs pymeshlab 2025.7 and the plugin (pymeshlab_irregular, or FILTER_IRREGULAR_PLUGIN).
run() is what tests/pymeshlab/test_pattern_panels.py checks.
"""
import math
import sys

import numpy as np
import pymeshlab

import pymeshlab_irregular

PATTERN = "compute_color_irregular_pattern"
GENERATE = "meshing_irregular_generate"


def regular_torus(n=40, k=40, R=3.0, r=1.0):
    """A torus whose vertices all have valence 6: an n x k grid of quads cut by one diagonal."""
    v = np.array([[(R + r * math.cos(2 * math.pi * j / k)) * math.cos(2 * math.pi * i / n),
                   (R + r * math.cos(2 * math.pi * j / k)) * math.sin(2 * math.pi * i / n),
                   r * math.sin(2 * math.pi * j / k)] for i in range(n) for j in range(k)])
    f = []
    for i in range(n):
        for j in range(k):
            a, b = i * k + j, ((i + 1) % n) * k + j
            c, d = ((i + 1) % n) * k + (j + 1) % k, i * k + (j + 1) % k
            f += [[a, b, c], [a, c, d]]
    return v, np.array(f)


def circles(ms, panels=False):
    """The circle pattern of the current mesh: the filter's output values."""
    return ms.apply_filter(PATTERN, pattern="Circles", panels=panels)


def generate_at(ms, vertex, spacing):
    """A 5-5-7-7 quadruple generated at a regular vertex, its second 5-7 pair moved `spacing`
    steps away (Irregular Vertices: Generate)."""
    ms.compute_selection_by_condition_per_vertex(condselect="(vi == %d)" % vertex)
    return ms.apply_filter(GENERATE, kind="Quadruple from a regular vertex", direction=0, spacing=spacing)


def run(ms, vertices, spacing=8):
    """Pattern, generate at each vertex, pattern again. Returns (circles before, output values
    of the last pattern, with panels written as a new layer)."""
    mesh_id = ms.current_mesh_id()
    before = circles(ms)["circles"]
    for v in vertices:
        ms.set_current_mesh(mesh_id)
        generate_at(ms, v, spacing)
    ms.set_current_mesh(mesh_id)
    return before, circles(ms, panels=True)


def main(argv):
    pymeshlab_irregular.load()
    ms = pymeshlab.MeshSet()
    if len(argv) > 1:
        ms.load_new_mesh(argv[1])
        n = ms.current_mesh().vertex_number()
        vertices = [n // 5, 2 * n // 5, 3 * n // 5, 4 * n // 5]
    else:
        v, f = regular_torus()
        ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f))
        vertices = [10 * 40 + 10, 10 * 40 + 30, 30 * 40 + 10, 30 * 40 + 30]
    before, after = run(ms, vertices)
    print("circles before generation: %d, after: %d (panels: %d, in layer %d)" % (
        before, after["circles"], after["panels"], ms.mesh_number() - 1))
    if len(argv) > 2:
        ms.set_current_mesh(0)
        ms.save_current_mesh(argv[2] + ".ply")
        ms.set_current_mesh(ms.mesh_number() - 1)
        ms.save_current_mesh(argv[2] + "_panels.ply")


if __name__ == "__main__":
    main(sys.argv)
