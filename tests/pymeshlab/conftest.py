"""The pymeshlab suite: the MeshLab 2025.07 plugin loaded into the real pymeshlab
(FILTER_IRREGULAR_PLUGIN names the plugin file; PYTHONPATH must hold python/ for
pymeshlab_irregular). Missing plugin, package or corpus mesh: every test fails, none skips."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

_load_error = None
try:
    import pymeshlab  # noqa: F401
    import pymeshlab_irregular
    import fi_pm
    _names = pymeshlab_irregular.load()
    _missing = sorted(set(fi_pm.FILTERS) - set(_names))
    if _missing:
        _load_error = "the plugin does not provide %s (it has %s)" % (_missing, _names)
except Exception as e:  # reported by every test below
    _load_error = "%s: %s (FILTER_IRREGULAR_PLUGIN=%r, PYTHONPATH=%r)" % (
        type(e).__name__, e, os.environ.get("FILTER_IRREGULAR_PLUGIN"), os.environ.get("PYTHONPATH"))


@pytest.fixture(autouse=True)
def _plugin_loaded():
    if _load_error:
        pytest.fail("filter_irregular plugin not loaded into pymeshlab: " + _load_error, pytrace=False)
