import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mlpy  # noqa: E402


def pytest_collection_modifyitems(config, items):
    if not mlpy.have_meshlab():
        skip = pytest.mark.skip(reason="no staged meshlabserver (run scripts/build.sh) or no xvfb-run")
        for item in items:
            item.add_marker(skip)


@pytest.fixture
def corpus():
    def path(name):
        p = os.path.join(mlpy.DATA, name)
        if not os.path.exists(p):
            pytest.skip("corpus mesh %s missing (run scripts/setup.sh)" % name)
        return p
    return path
