#!/usr/bin/env python3
"""Writes assets/textures/leaf.png: the alpha texture of the foliage case's cards,
three leaves on a twig in a 128 x 128 RGBA image (green, alpha 255 on a leaf, 0 elsewhere).
Our own drawing, MIT like the code; plain Python (zlib), so that it regenerates anywhere."""
import math
import struct
import sys
import zlib

SIZE = 128


def inside_leaf(x, y, cx, cy, angle, length, width):
    # A leaf: an ellipse-like blade |across| < width * sin(pi t) along its axis, t in [0, 1].
    dx, dy = x - cx, y - cy
    along = dx * math.cos(angle) + dy * math.sin(angle)
    across = -dx * math.sin(angle) + dy * math.cos(angle)
    t = along / length
    return 0.0 <= t <= 1.0 and abs(across) < width * math.sin(math.pi * t) ** 0.8


def alpha_at(x, y):
    leaves = [(0.5, 0.92, -math.pi / 2, 0.55, 0.16), (0.5, 0.7, -math.pi / 2 - 0.9, 0.4, 0.12),
              (0.5, 0.6, -math.pi / 2 + 0.85, 0.42, 0.13)]
    twig = abs(x - 0.5) < 0.012 and y > 0.55
    return twig or any(inside_leaf(x, y, *leaf) for leaf in leaves)


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"".join(b"\x00" + row for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    rows = []
    for j in range(SIZE):
        row = bytearray()
        for i in range(SIZE):
            a = 255 if alpha_at((i + 0.5) / SIZE, (j + 0.5) / SIZE) else 0
            row += bytes((60, 120, 40, a))
        rows.append(bytes(row))
    out = sys.argv[1] if len(sys.argv) > 1 else "assets/textures/leaf.png"
    with open(out, "wb") as f:
        f.write(png(SIZE, SIZE, rows))


if __name__ == "__main__":
    main()
