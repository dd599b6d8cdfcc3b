#!/usr/bin/env python3
"""Writes assets/textures/blinds.png: a light cookie (gobo map, RTR 7.2) of venetian
blinds for the spot-cookie case, 128 x 128 grey: eight slats, each 16 rows of which the
lower 6 are closed (0) and the upper 10 open (255), under a closed pelmet 12 rows deep at
the top, so that up and down differ in the image. Our own drawing, MIT like the code;
plain Python (zlib), so that it regenerates anywhere."""
import struct
import sys
import zlib

SIZE = 128
PELMET_ROWS = 12
SLAT_PERIOD, SLAT_CLOSED = 16, 6


def open_at(row):
    return row >= PELMET_ROWS and row % SLAT_PERIOD < SLAT_PERIOD - SLAT_CLOSED


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"".join(b"\x00" + row for row in rows)   # filter type 0 on every row
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


rows = [bytes([255 if open_at(j) else 0]) * SIZE for j in range(SIZE)]
path = sys.argv[1] if len(sys.argv) > 1 else "assets/textures/blinds.png"
with open(path, "wb") as f:
    f.write(png(SIZE, SIZE, rows))
