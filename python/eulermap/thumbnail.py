"""Small pictures of a mapped pair for the batch's summary page, drawn with numpy alone
(no GL context is needed on a worker): flat-shaded triangles in an orthographic view,
with a depth buffer, written as PNG with zlib."""
import math
import struct
import zlib

import numpy as np

SIZE = 160  # pixels of one panel, square


def _view(azimuth=35.0, elevation=20.0):
    a, e = math.radians(azimuth), math.radians(elevation)
    turn = np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])
    tilt = np.array([[1, 0, 0], [0, math.cos(e), -math.sin(e)], [0, math.sin(e), math.cos(e)]])
    return tilt @ turn


def draw(verts, faces, face_colors, size=SIZE):
    """An RGB image (size x size x 3, uint8) of the triangles `faces` (m x 3 indices into
    `verts`, n x 3) with colours `face_colors` (m x 3 in 0..1), white background."""
    image = np.full((size, size, 3), 255, np.uint8)
    if len(faces) == 0:
        return image
    p = (np.asarray(verts, float) - (verts.min(0) + verts.max(0)) / 2) @ _view().T
    scale = 0.9 * size / max(np.ptp(p[:, 0]), np.ptp(p[:, 1]), 1e-12)
    x = p[:, 0] * scale + size / 2
    y = size / 2 - p[:, 1] * scale
    z = p[:, 2]  # towards the viewer
    tri = np.asarray(faces)
    e1, e2 = p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]]
    n = np.cross(e1, e2)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    shade = 0.3 + 0.7 * np.abs(n[:, 2])  # two-sided: a cut surface shows its inside too
    colors = np.clip(np.asarray(face_colors) * shade[:, None] * 255, 0, 255).astype(np.uint8)
    depth = np.full((size, size), -np.inf)
    # Faces within about a pixel (most, on a small picture of a dense mesh) are drawn as
    # their centre's pixel, nearest last; the larger ones are rasterised below.
    cx, cy, cz = x[tri].mean(1), y[tri].mean(1), z[tri].mean(1)
    span = np.maximum(np.ptp(x[tri], 1), np.ptp(y[tri], 1))
    small = np.flatnonzero((span <= 1.5) & (cx >= 0) & (cx < size) & (cy >= 0) & (cy < size))
    order = small[np.argsort(cz[small])]
    px, py = cx[order].astype(int), cy[order].astype(int)
    image[py, px] = colors[order]
    depth[py, px] = cz[order]
    for f in np.flatnonzero(span > 1.5):
        a, b, c = tri[f]
        xs, ys = x[[a, b, c]], y[[a, b, c]]
        x0, x1 = max(int(math.floor(xs.min())), 0), min(int(math.ceil(xs.max())), size - 1)
        y0, y1 = max(int(math.floor(ys.min())), 0), min(int(math.ceil(ys.max())), size - 1)
        if x0 > x1 or y0 > y1:
            continue
        det = (ys[1] - ys[2]) * (xs[0] - xs[2]) + (xs[2] - xs[1]) * (ys[0] - ys[2])
        if abs(det) < 1e-12:
            continue
        px, py = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        w0 = ((ys[1] - ys[2]) * (px - xs[2]) + (xs[2] - xs[1]) * (py - ys[2])) / det
        w1 = ((ys[2] - ys[0]) * (px - xs[2]) + (xs[0] - xs[2]) * (py - ys[2])) / det
        w2 = 1 - w0 - w1
        inside = (w0 >= -1e-9) & (w1 >= -1e-9) & (w2 >= -1e-9)
        if not inside.any():
            continue
        d = w0 * z[a] + w1 * z[b] + w2 * z[c]
        window = depth[y0:y1 + 1, x0:x1 + 1]
        nearer = inside & (d > window)
        window[nearer] = d[nearer]
        image[y0:y1 + 1, x0:x1 + 1][nearer] = colors[f]
    return image


def _distortion_colors(quality):
    """Blue (low) to red (high) over the 5th..95th percentile of a per-face value."""
    lo, hi = np.percentile(quality, [5, 95]) if len(quality) else (0, 1)
    t = np.clip((quality - lo) / max(hi - lo, 1e-12), 0, 1)[:, None]
    return (1 - t) * np.array([0.25, 0.45, 0.9]) + t * np.array([0.9, 0.25, 0.2])


def write_png(path, image):
    """Writes an RGB uint8 image as an 8-bit PNG."""
    h, w, _ = image.shape
    raw = b"".join(b"\x00" + image[row].tobytes() for row in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def render_pair(ms, path, size=SIZE):
    """Writes a picture of a mapped pair: the source (layer 0), the target (layer 1), and
    the mapped source (layer 3) coloured by the cut layer's vertex quality (distortion)."""
    grey = np.array([0.75, 0.75, 0.72])
    panels = []
    for layer in (0, 1):
        m = ms.mesh(layer)
        panels.append(draw(m.vertex_matrix(), m.face_matrix(), np.tile(grey, (m.face_number(), 1)), size))
    cut, mapped = ms.mesh(2), ms.mesh(3)
    faces = mapped.face_matrix()
    quality = cut.vertex_scalar_array()[faces].mean(axis=1) if cut.has_vertex_scalar() else np.zeros(len(faces))
    panels.append(draw(mapped.vertex_matrix(), faces, _distortion_colors(quality), size))
    gap = np.full((size, 4, 3), 255, np.uint8)
    write_png(path, np.concatenate([panels[0], gap, panels[1], gap, panels[2]], axis=1))
