#!/usr/bin/env python3
"""Renders a mesh (PLY with vertex colours, or OFF) to a PNG: z-buffer, Lambert headlight,
per-vertex colours interpolated. numpy only; the PNG is written with zlib.

    /usr/bin/python3 scripts/render_png.py in.ply out.png [--size 900] [--legend] [--title T]
"""
import argparse
import os
import struct
import sys
import zlib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "integration"))
import mlserver  # noqa: E402

LEGEND = [(150, 40, 190), (0, 175, 200), (40, 80, 230), (200, 200, 200), (245, 140, 20), (215, 30, 30), (110, 0, 20)]


def write_png(path, img):
    h, w, _ = img.shape
    raw = b"".join(b"\x00" + img[y].astype(np.uint8).tobytes() for y in range(h))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def rotation(ax, ay):
    cx, sx, cy, sy = np.cos(ax), np.sin(ax), np.cos(ay), np.sin(ay)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    return ry @ rx


def render(mesh, size=900, ax=0.35, ay=-0.5):
    v = mesh.vertices - (mesh.vertices.max(0) + mesh.vertices.min(0)) / 2
    v = v @ rotation(ax, ay).T
    scale = 0.9 * size / max(np.ptp(v[:, 0]), np.ptp(v[:, 1]))
    px = np.stack([v[:, 0] * scale + size / 2, size / 2 - v[:, 1] * scale, v[:, 2]], axis=1)
    if "red" in mesh.props:
        col = np.stack([mesh.props["red"], mesh.props["green"], mesh.props["blue"]], 1).astype(np.float64)
    else:
        col = np.full((len(v), 3), 200.0)
    f = mesh.faces
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-30
    shade = 0.25 + 0.75 * np.abs(n[:, 2])          # headlight along z, both sides lit
    zbuf = np.full(size * size, -np.inf)
    img = np.zeros((size * size, 3))
    p0, p1, p2 = px[f[:, 0]], px[f[:, 1]], px[f[:, 2]]
    lo = np.floor(np.minimum(np.minimum(p0, p1), p2)[:, :2]).astype(int)
    hi = np.ceil(np.maximum(np.maximum(p0, p1), p2)[:, :2]).astype(int)
    ext = (hi - lo).max(1) + 1
    for s in np.unique(np.clip(ext, 1, None)):
        idx = np.nonzero(ext == s)[0]
        for chunk in np.array_split(idx, max(1, len(idx) * s * s // 4_000_000 + 1)):
            if len(chunk) == 0:
                continue
            gx, gy = np.meshgrid(np.arange(s), np.arange(s))
            X = lo[chunk, 0][:, None] + gx.ravel()[None] + 0.5
            Y = lo[chunk, 1][:, None] + gy.ravel()[None] + 0.5
            a, b, c = p0[chunk], p1[chunk], p2[chunk]
            den = (b[:, 1] - c[:, 1]) * (a[:, 0] - c[:, 0]) + (c[:, 0] - b[:, 0]) * (a[:, 1] - c[:, 1])
            den = np.where(np.abs(den) < 1e-12, 1e-12, den)[:, None]
            w0 = ((b[:, 1] - c[:, 1])[:, None] * (X - c[:, 0][:, None]) + (c[:, 0] - b[:, 0])[:, None] * (Y - c[:, 1][:, None])) / den
            w1 = ((c[:, 1] - a[:, 1])[:, None] * (X - c[:, 0][:, None]) + (a[:, 0] - c[:, 0])[:, None] * (Y - c[:, 1][:, None])) / den
            w2 = 1 - w0 - w1
            inside = (w0 >= -1e-6) & (w1 >= -1e-6) & (w2 >= -1e-6) & (X >= 0) & (X < size) & (Y >= 0) & (Y < size)
            ti, pi = np.nonzero(inside)
            if len(ti) == 0:
                continue
            fi = chunk[ti]
            W = np.stack([w0[ti, pi], w1[ti, pi], w2[ti, pi]], 1)
            z = (W * np.stack([p0[fi, 2], p1[fi, 2], p2[fi, 2]], 1)).sum(1)
            pix = (Y[ti, pi].astype(int)) * size + X[ti, pi].astype(int)
            order = np.lexsort((z, pix))            # per pixel, nearest (largest z) last
            pix, z, fi, W = pix[order], z[order], fi[order], W[order]
            last = np.r_[pix[1:] != pix[:-1], True]
            pix, z, fi, W = pix[last], z[last], fi[last], W[last]
            better = z > zbuf[pix]
            pix, z, fi, W = pix[better], z[better], fi[better], W[better]
            zbuf[pix] = z
            c3 = (W[:, :, None] * col[f[fi]]).sum(1)
            img[pix] = c3 * shade[fi][:, None]
    bg = np.linspace(235, 200, size)[:, None, None] * np.ones((1, size, 3))
    img = img.reshape(size, size, 3)
    mask = np.isfinite(zbuf.reshape(size, size))
    return np.where(mask[:, :, None], img, bg)


def draw_legend(img):
    # v3- .. v9+ squares along the bottom left (purple, cyan, blue, grey, orange, red, dark red)
    h = img.shape[0]
    for i, c in enumerate(LEGEND):
        y0, x0 = h - 40, 20 + i * 34
        img[y0:y0 + 24, x0:x0 + 24] = c
    return img


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--size", type=int, default=900)
    ap.add_argument("--legend", action="store_true")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    mesh = mlserver.read_ply(a.input) if a.input.endswith(".ply") else mlserver.read_off(a.input)
    img = render(mesh, a.size)
    if a.legend:
        img = draw_legend(img)
    write_png(a.output, np.clip(img, 0, 255))


if __name__ == "__main__":
    main()
