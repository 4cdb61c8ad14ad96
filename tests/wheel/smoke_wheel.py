"""Smoke test of an installed pymeshlab-irregular wheel (run by scripts/test_wheel.sh).

    python smoke_wheel.py MESH        (or FI_WHEEL_MESH=MESH python smoke_wheel.py)

MESH is a closed torus-like mesh: .deps/data/meshes/knot1.off. Run it from outside the source
tree, in a venv where only the wheel (and the pymeshlab it pulls) is installed: it checks that
the package imported is the installed one, that its plugin loads into pymeshlab, and that one
analysis, one edit and one refusal work through the real pymeshlab. Exits non-zero on failure.
"""
import importlib.metadata
import os
import subprocess
import sys
import time

import numpy as np
import pymeshlab
import pymeshlab_irregular

EXPECTED_FILTERS = {
    "apply_irregular_relaxation",
    "compute_color_irregular_pattern",
    "compute_irregular_vertex_analysis",
    "meshing_irregular_aggregation",
    "meshing_irregular_atomic_operation",
    "meshing_irregular_automatic_reduction",
    "meshing_irregular_boundary_operation",
    "meshing_irregular_cancel_quadruple",
    "meshing_irregular_cancel_triple",
    "meshing_irregular_generate",
    "meshing_irregular_move_pair",
    "meshing_irregular_reduce_to_valence_5_and_7",
}


def check(cond, what):
    if not cond:
        print("smoke_wheel: FAIL:", what, file=sys.stderr, flush=True)
        sys.exit(1)
    print("smoke_wheel: ok:", what, flush=True)


def irregular_from_faces(faces, n_vertices):
    """Irregular vertices of a closed mesh: valence (= incident faces) other than 6."""
    valence = np.bincount(np.asarray(faces).ravel(), minlength=n_vertices)
    return int(np.count_nonzero(valence != 6))


def main():
    mesh = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("FI_WHEEL_MESH", "")
    if not mesh or not os.path.isfile(mesh):
        print("smoke_wheel: mesh not found: %r (pass it as argument or FI_WHEEL_MESH)" % mesh, file=sys.stderr)
        sys.exit(2)

    # The installed package, not a source checkout on sys.path.
    pkg_dir = os.path.dirname(os.path.abspath(pymeshlab_irregular.__file__))
    check("site-packages" in pkg_dir, "pymeshlab_irregular imported from the venv (%s)" % pkg_dir)
    check(os.environ.get(pymeshlab_irregular.PLUGIN_ENV) is None, "%s unset" % pymeshlab_irregular.PLUGIN_ENV)
    plugin = pymeshlab_irregular.plugin_path()
    check(os.path.dirname(plugin) == pkg_dir, "plugin inside the package: %s" % plugin)
    # The version the project declares (CMakeLists.txt), passed in by scripts/test_wheel.sh.
    expected = os.environ["FI_EXPECTED_VERSION"]
    dist_version = importlib.metadata.version("pymeshlab-irregular")
    check(dist_version == expected and pymeshlab_irregular.__version__ == expected,
          "wheel version %s and __version__ %s == CMakeLists.txt's %s"
          % (dist_version, pymeshlab_irregular.__version__, expected))
    check(importlib.metadata.version("pymeshlab") == "2025.7.post1", "pymeshlab 2025.7.post1")

    # Before load(): the plugin's libraries resolve to pymeshlab's own (RUNPATH), not the system's.
    ldd = subprocess.run(["ldd", plugin], capture_output=True, text=True).stdout
    pm_lib = os.path.join(os.path.dirname(os.path.abspath(pymeshlab.__file__)), "lib")
    resolved = dict((l.split("=>")[0].strip(), os.path.realpath(l.split("=>")[1].split("(")[0].strip()))
                    for l in ldd.splitlines() if "=>" in l and "not found" not in l)
    for lib in ("libmeshlab-common.so", "libQt5Core.so.5", "libQt5Widgets.so.5"):
        check(resolved.get(lib) == os.path.realpath(os.path.join(pm_lib, lib)),
              "ldd: %s -> pymeshlab/lib (%s)" % (lib, resolved.get(lib)))
    check("not found" not in ldd, "ldd: every library found")

    names = pymeshlab_irregular.load()
    check(set(names) == EXPECTED_FILTERS, "load() gives the %d filters: %s" % (len(EXPECTED_FILTERS), sorted(names)))
    maps = open("/proc/self/maps").read()
    loaded_common = {l.split()[-1] for l in maps.splitlines() if l.endswith("libmeshlab-common.so")}
    check(loaded_common == {os.path.realpath(os.path.join(pm_lib, "libmeshlab-common.so"))},
          "one libmeshlab-common.so in the process, pymeshlab's: %s" % sorted(loaded_common))
    check(pymeshlab_irregular.load() == names, "load() twice is harmless")

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(mesh)
    m = ms.current_mesh()
    nv, nf = m.vertex_number(), m.face_number()
    res = ms.compute_irregular_vertex_analysis()
    check(isinstance(res, dict), "analysis returns a dict")
    print("smoke_wheel: analysis:", {k: v for k, v in res.items() if not isinstance(v, np.ndarray)})
    check(res["euler_characteristic"] == 0, "torus: euler_characteristic 0")
    check(res["gauss_bonnet_holds"] is True, "gauss_bonnet_holds")
    check(res["vertices"] == nv and res["faces"] == nf, "vertex and face counts")
    irregular = irregular_from_faces(ms.current_mesh().face_matrix(), nv)
    check(res["irregular"] > 0 and res["irregular"] == irregular,
          "irregular %d == numpy count %d" % (res["irregular"], irregular))

    # A refusal: a triple cancellation with nothing selected.
    ms.set_selection_none()
    verts_before = ms.current_mesh().vertex_matrix().copy()
    faces_before = ms.current_mesh().face_matrix().copy()
    try:
        ms.meshing_irregular_cancel_triple()
        check(False, "cancel_triple with nothing selected raises")
    except pymeshlab.PyMeshLabException as e:
        check("3 selected" in str(e), "refusal raises PyMeshLabException: %s" % " ".join(str(e).split()))
    check(np.array_equal(ms.current_mesh().vertex_matrix(), verts_before)
          and np.array_equal(ms.current_mesh().face_matrix(), faces_before), "mesh unchanged by the refusal")

    # One editing filter, default parameters.
    t = time.perf_counter()
    red = ms.meshing_irregular_automatic_reduction()
    t = time.perf_counter() - t
    before, after = red["irregular_before"], red["irregular_after"]
    check(before == irregular, "reduction: irregular_before %d == analysis" % before)
    check(after < before, "reduction: irregular_after %d < irregular_before %d (%.1f s)" % (after, before, t))
    m = ms.current_mesh()
    check(irregular_from_faces(m.face_matrix(), m.vertex_number()) == after, "irregular_after == numpy count")
    print("smoke_wheel: all passed")


if __name__ == "__main__":
    main()
