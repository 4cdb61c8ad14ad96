"""The meshlabserver smoke suite (MeshLab 2020.09): the staged meshlabserver
($FI_STAGE/bin/meshlabserver, else build/stage) under xvfb-run. A missing meshlabserver,
xvfb-run or corpus mesh fails the tests: none is skipped."""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "oracle"))
import mlpy  # noqa: E402


@pytest.fixture
def meshlab():
    """The staged meshlabserver; fails the test when it or xvfb-run is missing."""
    if not mlpy.have_meshlab():
        pytest.fail("no staged meshlabserver at %s or no xvfb-run (run scripts/build.sh; FI_STAGE=%r)" % (
            mlpy.meshlabserver_path(), os.environ.get("FI_STAGE")), pytrace=False)
    return mlpy.Server()


@pytest.fixture
def corpus():
    def path(name):
        p = os.path.join(mlpy.DATA, name)
        if not os.path.isfile(p):
            pytest.fail("corpus mesh %s missing in %s (run scripts/setup.sh)" % (name, mlpy.DATA), pytrace=False)
        return p
    return path
