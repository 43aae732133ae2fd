#!/usr/bin/python3
"""Draws StentGraftPlanner.png (128 x 128 RGBA): a bifurcated stent graft, trunk and two legs, with
zigzag stent rings on a shaded fabric tube. Run with Debian's python3 (numpy) to regenerate:

    /usr/bin/python3 make_icon.py OUTPUT.png
"""
import struct
import sys
import zlib

import numpy as np

SIZE, SUPERSAMPLE = 128, 4


def segmentFrame(px, py, a, b):
    """Along-axis position s (px), signed across-axis distance t (px) and clamped fraction of p to segment ab."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    length = np.hypot(*d)
    ux, uy = d / length
    s = (px - a[0]) * ux + (py - a[1]) * uy
    t = -(px - a[0]) * uy + (py - a[1]) * ux
    return np.clip(s, 0, length), s, t, length


def draw():
    n = SIZE * SUPERSAMPLE
    y, x = (np.mgrid[0:n, 0:n] + 0.5) / SUPERSAMPLE
    rgba = np.zeros((n, n, 4))
    best = np.full((n, n), np.inf)
    tubes = (((64, 8), (64, 66), 21.0), ((60, 62), (34, 120), 11.0), ((68, 62), (94, 120), 11.0))
    for a, b, radius in tubes:
        sClamped, s, t, length = segmentFrame(x, y, a, b)
        inside = (s >= 0) & (s <= length) & (np.abs(t) <= radius)
        u = np.clip(t / radius, -1, 1)
        depth = np.abs(u)
        take = inside & (depth < best)
        best = np.where(take, depth, best)
        shade = 0.45 + 0.55 * np.sqrt(1 - u**2)
        fabric = np.stack([0.62 * shade, 0.78 * shade, 0.95 * shade], axis=-1)
        period, amplitude = 11.0, 3.2
        phase = (u * 3.0) % 2.0
        zig = amplitude * np.abs(phase - 1.0)
        ring = np.abs(((s - 2.0) % period) - period / 2 - zig + amplitude / 2) < 1.1
        wire = np.stack([0.10 + 0.25 * shade, 0.20 + 0.3 * shade, 0.35 + 0.35 * shade], axis=-1)
        edge = depth > 0.9
        color = np.where(ring[..., None], wire, fabric)
        color = np.where(edge[..., None], np.array([0.12, 0.22, 0.38]), color)
        rgba[take, :3] = color[take]
        rgba[take, 3] = 1.0
    small = rgba.reshape(SIZE, SUPERSAMPLE, SIZE, SUPERSAMPLE, 4).mean(axis=(1, 3))
    alpha = small[..., 3:4]
    small[..., :3] = np.where(alpha > 0, small[..., :3] / np.maximum(alpha, 1e-9), 0)
    return np.clip(np.round(small * 255), 0, 255).astype(np.uint8)


def writePng(path, image):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    height, width = image.shape[:2]
    raw = b"".join(b"\x00" + image[row].tobytes() for row in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    with open(path, "wb") as png:
        png.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    writePng(sys.argv[1], draw())
