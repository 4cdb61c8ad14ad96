"""Software rendering of a triangle mesh to a PNG with numpy only: orthographic camera, z-buffer,
Lambert headlight, per-vertex colours, optional tiny 5x7 bitmap text and a valence legend.

    img = render(mesh, size=(800, 800))     # (H, W, 3) uint8
    draw_text(img, 10, 10, "BUNNY", scale=2)
    write_png("out.png", img)
"""
import struct
import zlib

import numpy as np

# The plugin's valence legend (vcg_ext/irregular/legend.h): equivalent valence -> colour.
LEGEND = [("3-", (150, 40, 190)), ("4", (0, 175, 200)), ("5", (40, 80, 230)), ("6", (200, 200, 200)),
          ("7", (245, 140, 20)), ("8", (215, 30, 30)), ("9+", (110, 0, 20))]
GREY = (200, 200, 200)


# ------------------------------------------------------------------ PNG
def write_png(path, img):
    """img: (H, W, 3) array, values clipped to 0..255. RGB 8-bit, filter 0 on every row."""
    img = np.clip(np.asarray(img), 0, 255).astype(np.uint8)
    h, w, _ = img.shape
    raw = np.hstack([np.zeros((h, 1), np.uint8), img.reshape(h, w * 3)]).tobytes()

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


# ------------------------------------------------------------------ camera
def rotation(ax_deg=20.0, ay_deg=-30.0):
    """Rotation about x by ax_deg, then about y by ay_deg (degrees)."""
    ax, ay = np.radians(ax_deg), np.radians(ay_deg)
    cx, sx, cy, sy = np.cos(ax), np.sin(ax), np.cos(ay), np.sin(ay)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    return ry @ rx


def look_from(direction, up=(0.0, 1.0, 0.0)):
    """Rotation whose rows are the camera axes for an eye placed along `direction` from the
    object's centre (so the camera looks along -direction); world `up` stays up on screen."""
    z = np.asarray(direction, np.float64)
    z = z / np.linalg.norm(z)
    up = np.asarray(up, np.float64)
    if abs(np.dot(up, z)) > 0.99:  # looking along up: take another up
        up = np.array([0.0, 0.0, 1.0]) if abs(z[2]) < 0.99 else np.array([0.0, 1.0, 0.0])
    x = np.cross(up, z)
    x /= np.linalg.norm(x)
    return np.stack([x, np.cross(z, x), z])


# ------------------------------------------------------------------ rasteriser
def rasterize(p, faces, width, height, eps=1e-7, budget=2_000_000):
    """p: (n, 3) screen points (x right and y down, in pixels; z larger = nearer).
    Returns (face index per pixel, -1 where empty; barycentric weights (H*W, 3)).

    Triangles are grouped by the power-of-two size of the pixel-centre box they cover, and each
    group is tested on all pixels of that box at once. Pixel centres on a shared edge belong to
    both triangles (eps), so there are no cracks; the nearest z wins."""
    n_pix = width * height
    face_of = np.full(n_pix, -1, np.int64)
    bary = np.zeros((n_pix, 3))
    zbuf = np.full(n_pix, -np.inf)
    a, b, c = p[faces[:, 0]], p[faces[:, 1]], p[faces[:, 2]]
    area2 = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    lo = np.minimum(np.minimum(a, b), c)
    hi = np.maximum(np.maximum(a, b), c)
    # Pixel i has its centre at i + 0.5.
    x0 = np.maximum(np.ceil(lo[:, 0] - 0.5), 0).astype(np.int64)
    x1 = np.minimum(np.floor(hi[:, 0] - 0.5), width - 1).astype(np.int64)
    y0 = np.maximum(np.ceil(lo[:, 1] - 0.5), 0).astype(np.int64)
    y1 = np.minimum(np.floor(hi[:, 1] - 0.5), height - 1).astype(np.int64)
    live = (np.abs(area2) > 1e-12) & (x1 >= x0) & (y1 >= y0)
    kx = np.ceil(np.log2(np.maximum(x1 - x0 + 1, 1))).astype(np.int64)
    ky = np.ceil(np.log2(np.maximum(y1 - y0 + 1, 1))).astype(np.int64)
    group = kx * 64 + ky
    for g in np.unique(group[live]):
        gw, gh = 1 << int(g // 64), 1 << int(g % 64)
        ox, oy = (m.ravel() for m in np.meshgrid(np.arange(gw), np.arange(gh)))
        members = np.nonzero(live & (group == g))[0]
        step = max(1, budget // (gw * gh))
        for s in range(0, len(members), step):
            t = members[s:s + step]
            X = x0[t, None] + ox[None]
            Y = y0[t, None] + oy[None]
            cx, cy = X + 0.5, Y + 0.5
            A, B, C, D = a[t], b[t], c[t], area2[t, None]
            w0 = ((B[:, 0, None] - cx) * (C[:, 1, None] - cy) - (B[:, 1, None] - cy) * (C[:, 0, None] - cx)) / D
            w1 = ((C[:, 0, None] - cx) * (A[:, 1, None] - cy) - (C[:, 1, None] - cy) * (A[:, 0, None] - cx)) / D
            w2 = 1.0 - w0 - w1
            inside = (X <= x1[t, None]) & (Y <= y1[t, None]) & (w0 >= -eps) & (w1 >= -eps) & (w2 >= -eps)
            ti, k = np.nonzero(inside)
            if len(ti) == 0:
                continue
            W = np.stack([w0[ti, k], w1[ti, k], w2[ti, k]], axis=1)
            fi = t[ti]
            z = W[:, 0] * a[fi, 2] + W[:, 1] * b[fi, 2] + W[:, 2] * c[fi, 2]
            pix = Y[ti, k] * width + X[ti, k]
            # Within the batch: the nearest fragment of each pixel (sorted last), then the z-test.
            order = np.lexsort((z, pix))
            pix, z, fi, W = pix[order], z[order], fi[order], W[order]
            last = np.r_[pix[1:] != pix[:-1], True]
            near = last.copy()
            near[last] = z[last] > zbuf[pix[last]]
            pix, z, fi, W = pix[near], z[near], fi[near], W[near]
            zbuf[pix], face_of[pix], bary[pix] = z, fi, W
    return face_of, bary


def _triangles(mesh):
    """mesh.faces plus fan triangles of mesh.polygons (OFF input)."""
    extra = [(poly[0], poly[i], poly[i + 1]) for poly in getattr(mesh, "polygons", []) or []
             for i in range(1, len(poly) - 1)]
    if not extra:
        return mesh.faces
    return np.concatenate([mesh.faces, np.array(extra, np.int64).reshape(-1, 3)])


def vertex_colors(mesh):
    """(n, 3) float colours from red/green/blue vertex properties, else light grey."""
    vp = getattr(mesh, "vertex_props", {})
    if all(k in vp for k in ("red", "green", "blue")):
        return np.stack([vp["red"], vp["green"], vp["blue"]], axis=1).astype(np.float64)
    return np.tile(np.array(GREY, np.float64), (len(mesh.vertices), 1))


def face_colors(mesh):
    """(m, 3) float colours from red/green/blue face properties (e.g. the Pattern filter's),
    None without them."""
    fp = getattr(mesh, "face_props", {})
    if all(k in fp for k in ("red", "green", "blue")):
        return np.stack([fp["red"], fp["green"], fp["blue"]], axis=1).astype(np.float64)
    return None


def render(mesh, size=(800, 800), view=None, rotate=(20.0, -30.0), colors=None, flat=False,
           wire=False, margin=0.9, pad_top=0, pad_bottom=0, per_face=None):
    """(H, W, 3) uint8 image of the mesh. size: (width, height). view: eye direction from the
    centre (camera looks along -view); None: rotate=(about x, about y) degrees, camera along -z.
    colors: (n, 3) 0..255 per vertex (default: the mesh's colours or grey). flat: face normals
    instead of interpolated vertex normals. wire: darken triangle edges. pad_top, pad_bottom:
    pixel rows kept free of the mesh (for a title or a legend). per_face: (m, 3) 0..255 per face
    of mesh.faces (e.g. face_colors(mesh)); it replaces the vertex colours, each face one colour."""
    width, height = size
    faces = _triangles(mesh)
    R = look_from(view) if view is not None else rotation(*rotate)
    v = mesh.vertices
    used = np.unique(faces) if len(faces) else np.arange(len(v))
    v = (v - (v[used].max(0) + v[used].min(0)) / 2) @ R.T  # camera space, box centred
    ext = np.ptp(v[used], axis=0) if len(used) else np.ones(3)
    ext_c = (v[used].max(0) + v[used].min(0)) / 2 if len(used) else np.zeros(3)
    free = max(height - pad_top - pad_bottom, 1)
    scale = margin * min(width / max(ext[0], 1e-30), free / max(ext[1], 1e-30))
    screen = np.stack([(v[:, 0] - ext_c[0]) * scale + width / 2,
                       pad_top + free / 2 - (v[:, 1] - ext_c[1]) * scale, v[:, 2]], axis=1)
    face_of, bary = rasterize(screen, faces, width, height)

    # Background: a soft vertical gradient.
    img = np.repeat(np.linspace(240, 205, height)[:, None, None], width, axis=1) * np.ones((1, 1, 3))
    img = img.reshape(-1, 3)
    hit = np.nonzero(face_of >= 0)[0]
    if len(hit) == 0:
        return img.reshape(height, width, 3).astype(np.uint8)
    f = faces[face_of[hit]]
    W = bary[hit]
    fn = np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
    if flat:
        nz = fn[face_of[hit], 2] / (np.linalg.norm(fn[face_of[hit]], axis=1) + 1e-30)
    else:
        vn = np.zeros_like(v)
        for k in range(3):  # area-weighted vertex normals
            np.add.at(vn, faces[:, k], fn)
        vn /= np.linalg.norm(vn, axis=1, keepdims=True) + 1e-30
        n = (W[:, :, None] * vn[f]).sum(1)
        nz = n[:, 2] / (np.linalg.norm(n, axis=1) + 1e-30)
    shade = 0.25 + 0.75 * np.abs(nz)  # headlight, both sides lit
    col = vertex_colors(mesh) if colors is None else np.asarray(colors, np.float64)
    rgb = (W[:, :, None] * col[f]).sum(1) * shade[:, None]
    if per_face is not None:
        fc = np.asarray(per_face, np.float64)
        inside = face_of[hit] < len(fc)  # fan triangles of OFF polygons have no face colour
        rgb[inside] = fc[face_of[hit][inside]] * shade[inside, None]
    if wire:  # distance in pixels to the nearest edge = w_i * height of the triangle over edge i
        P = screen[f][:, :, :2]
        lens = np.linalg.norm(P[:, [1, 2, 0]] - P[:, [2, 0, 1]], axis=2)
        area2 = np.abs(np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]))
        dist = (W * area2[:, None] / (lens + 1e-30)).min(1)
        rgb *= np.where(dist < 0.7, 0.45, 1.0)[:, None]
    img[hit] = rgb
    return np.clip(img, 0, 255).reshape(height, width, 3).astype(np.uint8)


# ------------------------------------------------------------------ 5x7 text and legend
# Rows top to bottom as hex, 5 bits each (bit 4 = leftmost pixel). Lower case prints upper case.
_FONT = {
    "0": "0E11131519110E", "1": "040C040404040E", "2": "0E11010204081F", "3": "1F02040201110E",
    "4": "02060A121F0202", "5": "1F101E0101110E", "6": "0608101E11110E", "7": "1F010204080808",
    "8": "0E11110E11110E", "9": "0E11110F01020C",
    "A": "0E11111F111111", "B": "1E11111E11111E", "C": "0E11101010110E", "D": "1C12111111121C",
    "E": "1F10101E10101F", "F": "1F10101E101010", "G": "0E11101711110F", "H": "1111111F111111",
    "I": "0E04040404040E", "J": "0702020202120C", "K": "11121418141211", "L": "1010101010101F",
    "M": "111B1515111111", "N": "11111915131111", "O": "0E11111111110E", "P": "1E11111E101010",
    "Q": "0E11111115120D", "R": "1E11111E141211", "S": "0F10100E01011E", "T": "1F040404040404",
    "U": "1111111111110E", "V": "11111111110A04", "W": "1111111515150A", "X": "11110A040A1111",
    "Y": "1111110A040404", "Z": "1F01020408101F",
    " ": "00000000000000", ":": "000C0C000C0C00", "-": "0000001F000000", "+": "0004041F040400",
    ".": "00000000000C0C", ",": "000000000C0408", "_": "0000000000001F", "/": "00010204081000",
    "(": "02040808080402", ")": "08040202020408", "=": "00001F001F0000", "<": "02040810080402",
    ">": "08040201020408", "%": "18190204081303", "?": "0E110102040004", "!": "04040404040004",
    "#": "0A0A1F0A1F0A0A", "'": "04040800000000",
}
_GLYPHS = {ch: np.array([[(int(h[2 * r:2 * r + 2], 16) >> (4 - c)) & 1 for c in range(5)] for r in range(7)],
                        dtype=bool)
           for ch, h in _FONT.items()}


def text_size(text, scale=2):
    """(width, height) in pixels of draw_text's output."""
    return (6 * len(text) - 1) * scale, 7 * scale


def draw_text(img, x, y, text, color=(20, 20, 20), scale=2):
    """Draws text with its top-left corner at pixel (x, y); clipped to the image."""
    h, w, _ = img.shape
    for i, ch in enumerate(text.upper()):
        g = np.kron(_GLYPHS.get(ch, _GLYPHS["?"]), np.ones((scale, scale), bool))
        gx, gy = x + i * 6 * scale, y
        ys, xs = np.nonzero(g)
        ys, xs = ys + gy, xs + gx
        ok = (ys >= 0) & (ys < h) & (xs >= 0) & (xs < w)
        img[ys[ok], xs[ok]] = color
    return img


def draw_legend(img, entries=LEGEND, square=24, scale=2):
    """A white box in the bottom-left corner with one coloured square per entry, labelled below."""
    h, w, _ = img.shape
    pitch = square + 12
    box_w, box_h = 12 + pitch * len(entries), 12 + square + 6 + 7 * scale + 10
    bx, by = 12, max(h - box_h - 12, 0)  # slices clip at the right; keep starts >= 0
    img[by:by + box_h, bx:bx + box_w] = (120, 120, 120)  # grey frame around a white box
    img[by + 1:by + box_h - 1, bx + 1:bx + box_w - 1] = (255, 255, 255)
    for i, (label, color) in enumerate(entries):
        x0, y0 = bx + 12 + i * pitch, by + 12
        img[y0:y0 + square, x0:x0 + square] = color
        tw, _ = text_size(label, scale)
        draw_text(img, x0 + (square - tw) // 2, y0 + square + 6, label, scale=scale)
    return img


def title_height(scale=2):
    """Height of draw_title's band (pass as render(..., pad_top=) to keep the mesh clear of it)."""
    return 7 * scale + 16


def draw_title(img, text, scale=2):
    """Text on a white band at the top."""
    img[:title_height(scale)] = (255, 255, 255)
    return draw_text(img, 10, 8, text, scale=scale)


def legend_height(square=24, scale=2):
    """Height of draw_legend's box and its margins (for render(..., pad_bottom=))."""
    return 12 + square + 6 + 7 * scale + 10 + 24
