#!/usr/bin/env python3
"""Renders a mesh (PLY, e.g. with the plugin's vertex colours, or OFF) to a PNG: z-buffer,
Lambert headlight, per-vertex colours (light grey without). numpy only; see
tests/meshlabserver/mlpy/render.py.

    /usr/bin/python3 scripts/render_png.py IN.ply OUT.png [--size 800x800] [--view x,y,z]
        [--title TEXT] [--legend] [--flat] [--wire] [--face-colors] [--crop x,y,z,r]
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "meshlabserver"))
from mlpy import read_mesh  # noqa: E402
from mlpy.files import Mesh  # noqa: E402
from mlpy.render import draw_legend, draw_title, face_colors, legend_height, render, title_height, write_png  # noqa: E402


def parse_size(s):
    """'800x600' or '800' (square)."""
    w, _, h = s.lower().partition("x")
    return int(w), int(h or w)


def parse_view(s):
    v = [float(x) for x in s.split(",")]
    if len(v) != 3 or not any(v):
        raise argparse.ArgumentTypeError("--view needs three numbers x,y,z, not all 0")
    return v


def parse_crop(s):
    v = [float(x) for x in s.split(",")]
    if len(v) != 4 or v[3] <= 0:
        raise argparse.ArgumentTypeError("--crop needs x,y,z,r with r > 0")
    return v


def crop(mesh, centre, radius):
    """The faces whose centroid lies within radius of centre, with their vertices (and the
    per-vertex and per-face properties of those), renumbered; None if no face is that close."""
    keep = np.linalg.norm(mesh.vertices[mesh.faces].mean(axis=1) - np.asarray(centre), axis=1) < radius
    if not keep.any():
        return None
    used = np.unique(mesh.faces[keep])
    index = np.full(len(mesh.vertices), -1, dtype=np.int64)
    index[used] = np.arange(len(used))
    vprops = {k: v[used] for k, v in mesh.vertex_props.items() if len(v) == len(mesh.vertices)}
    fprops = {k: v[keep] for k, v in mesh.face_props.items() if len(v) == len(mesh.faces)}
    return Mesh(mesh.vertices[used], index[mesh.faces[keep]], vprops, fprops)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("input", help="mesh, .ply or .off")
    ap.add_argument("output", help="PNG to write")
    ap.add_argument("--size", type=parse_size, default=(800, 800), help="WxH or W (default 800x800)")
    ap.add_argument("--view", type=parse_view, default=None,
                    help="eye direction x,y,z from the centre (default: 20 deg about x, -30 about y)")
    ap.add_argument("--title", default="", help="text on a band at the top (5x7 font, upper case)")
    ap.add_argument("--legend", action="store_true", help="valence colour legend (bottom left)")
    ap.add_argument("--flat", action="store_true", help="flat shading (face normals)")
    ap.add_argument("--wire", action="store_true", help="darken triangle edges")
    ap.add_argument("--crop", type=parse_crop, default=None,
                    help="only the faces whose centroid lies within r of the point x,y,z (a close-up)")
    ap.add_argument("--face-colors", action="store_true",
                    help="per-face colours (the PLY's face red/green/blue, e.g. the Pattern filter's) instead of vertex colours")
    a = ap.parse_args(argv)
    t0 = time.time()
    mesh = read_mesh(a.input)
    if a.crop:
        mesh = crop(mesh, a.crop[:3], a.crop[3])
        if mesh is None:
            ap.error("--crop %s: no face of %s has its centroid that close" % (",".join(map(str, a.crop)), a.input))
    per_face = face_colors(mesh) if a.face_colors else None
    if a.face_colors and per_face is None:
        ap.error("%s has no face colours (save with -m fc)" % a.input)
    img = render(mesh, a.size, view=a.view, flat=a.flat, wire=a.wire, per_face=per_face,
                 pad_top=title_height() if a.title else 0, pad_bottom=legend_height() if a.legend else 0)
    if a.title:
        draw_title(img, a.title)
    if a.legend:
        draw_legend(img)
    write_png(a.output, img)
    print("render_png: %s (%d vertices, %d faces%s) -> %s in %.2f s"
          % (a.input, len(mesh.vertices), len(mesh.faces), " in the crop" if a.crop else "", a.output,
             time.time() - t0))


if __name__ == "__main__":
    main()
