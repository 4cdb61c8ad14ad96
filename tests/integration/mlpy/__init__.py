"""mlpy: a tiny pymeshlab-like driver for the staged meshlabserver (filter scripts, runs under
xvfb-run, PLY/OFF reading and writing, topology measured independently with numpy) and a numpy
renderer to PNG (mlpy.render)."""
from .meshlab import *  # noqa: F401,F403
