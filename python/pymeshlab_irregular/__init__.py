"""filter_irregular for pymeshlab 2025.7: editing the irregular vertices of triangle meshes.

    import pymeshlab, pymeshlab_irregular
    pymeshlab_irregular.load()            # loads the MeshLab 2025.07 plugin into pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh("bunny.off")
    print(ms.compute_irregular_vertex_analysis())

load() calls pymeshlab.load_plugin() on the plugin this package carries (or on the file named
by the environment variable FILTER_IRREGULAR_PLUGIN) and, as pymeshlab does for its own
filters at import, binds every filter of the plugin as a method of pymeshlab.MeshSet; the
filters also work through ms.apply_filter(name, **params).
"""
import os

import pymeshlab



def _version():
    """The installed distribution's version (the wheel carries CMakeLists.txt's project
    VERSION); from a source tree, that VERSION itself."""
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version("pymeshlab-irregular")
    except PackageNotFoundError:
        import re
        cmake = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "CMakeLists.txt")
        try:
            with open(cmake) as f:
                return re.search(r"project\(filter_irregular VERSION ([0-9.]+)", f.read()).group(1)
        except (OSError, AttributeError):
            return "unknown"


__version__ = _version()

PLUGIN_ENV = "FILTER_IRREGULAR_PLUGIN"
PLUGIN_FILE = "libfilter_irregular.so"

_loaded = None


def plugin_path():
    """The plugin file load() uses: $FILTER_IRREGULAR_PLUGIN, else the one in this package (the
    wheel), else, from a source checkout (PYTHONPATH=python), the one scripts/build.sh built."""
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.environ.get(PLUGIN_ENV) or os.path.join(here, PLUGIN_FILE)
    built = os.path.join(here, "..", "..", "build", "plugin2025", PLUGIN_FILE)
    if not os.environ.get(PLUGIN_ENV) and not os.path.isfile(path) and os.path.isfile(built):
        path = os.path.normpath(built)
    if not os.path.isfile(path):
        raise FileNotFoundError(
            "filter_irregular plugin not found at %s (build it with scripts/build.sh, or set %s)" % (path, PLUGIN_ENV))
    return path


def load(path=None):
    """Loads the plugin once per process; returns the pymeshlab names of its filters."""
    global _loaded
    if _loaded is not None:
        return list(_loaded)
    before = set(pymeshlab.filter_list())
    # Installed into pymeshlab's own plugin folder (cmake --install --component meshlab2025),
    # pymeshlab loaded it at import and bound its filters already.
    present = sorted(n for n in before if "irregular" in n and hasattr(pymeshlab.MeshSet, n))
    if "compute_irregular_vertex_analysis" in present and path is None:
        _loaded = present
        return list(present)
    pymeshlab.load_plugin(path or plugin_path())
    names = sorted(set(pymeshlab.filter_list()) - before)
    if not names:
        raise RuntimeError("pymeshlab loaded the plugin but it added no filter")
    for name in names:
        setattr(pymeshlab.MeshSet, name, pymeshlab.bind_function(name))
    _loaded = names
    return list(names)
