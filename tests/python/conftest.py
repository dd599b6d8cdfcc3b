"""What the Python tests share: the command to compare with, a tiny prepared scene, and a PNG
reader (the command's PNGs decoded with zlib alone, so that no imaging package is needed)."""
import os
import struct
import subprocess
import sys
import threading
import time
import zlib

import numpy as np
import pytest

import shadowlab

# Tiny frames: every test here is about the binding, not the techniques.
WIDTH, HEIGHT = 64, 40


def run_command(*args, cwd):
    """Runs $SHADOWLAB_COMMAND (the built command) with args in cwd; its stdout."""
    return subprocess.run([os.environ["SHADOWLAB_COMMAND"], *args], cwd=cwd, check=True,
                          capture_output=True, text=True).stdout


def tiny_scene(name="sphere-box", width=WIDTH, height=HEIGHT):
    scene = shadowlab.load_scene(name)
    scene.apply_overrides(width=width, height=height)
    return scene


@pytest.fixture(scope="module")
def prepared():
    return shadowlab.prepare(tiny_scene())


def read_png(path):
    """An 8-bit RGB or RGBA PNG (non-interlaced) as (H, W, channels) uint8."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows = np.zeros((height, stride), np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        up = rows[y - 1] if y else np.zeros(stride, np.int32)
        if kind in (0, 2):
            rows[y] = (line + (up if kind == 2 else 0)) & 255
            continue
        out = np.zeros(stride, np.int32)   # filters 1, 3, 4 read the pixel to the left
        for x in range(stride):
            left = out[x - channels] if x >= channels else 0
            corner = up[x - channels] if x >= channels else 0
            if kind == 1:
                predictor = left
            elif kind == 3:
                predictor = (left + up[x]) // 2
            else:
                p = left + up[x] - corner
                pa, pb, pc = abs(p - left), abs(p - up[x]), abs(p - corner)
                predictor = left if pa <= pb and pa <= pc else (up[x] if pb <= pc else corner)
            out[x] = (line[x] + predictor) & 255
        rows[y] = out
    return rows.astype(np.uint8).reshape(height, width, channels)


def ticks_while(work):
    """Ticks of this thread while another runs work(): the proof that the library releases the
    GIL, counted, never timed. With a switch interval too long to ever expire, no thread is made
    to give up the GIL: this one waits in start() until the worker releases it, and the worker,
    once done, waits for this one's sleep. Work that held the GIL would run to its end first
    and leave 0 ticks; work that releases it leaves at least 1."""
    done = threading.Event()
    ticks = 0

    def worker():
        work()
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        while not done.is_set():
            ticks += 1
            time.sleep(1e-4)   # hands the GIL to the worker once it is done
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    return ticks
