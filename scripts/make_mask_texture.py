#!/usr/bin/env python3
"""Writes assets/textures/mask-checker.png: the alpha texture of the mask-card case, a cut-out
whose alpha sits at and around its cutoff 0.6 = 153/255, as a glTF MASK material's would
(docs/cut-outs.md). A 64 x 64 RGBA image: a frame 4 texels wide at alpha 154 (1/255 above the
cutoff: solid), inside it a checker of 8 x 8 blocks at 153 (exactly the cutoff: solid, since
alpha >= cutoff is) and 152 (1/255 below: a hole), a hole of radius 10 texels at the centre
(alpha 0) and a dot of radius 4 in it (255). 153 / 255 and the cutoff 0.6 round to the same
float, so a reader that divides bytes by 255 in float meets the cutoff exactly.
Our own drawing, MIT like the code; plain Python (zlib), so that it regenerates anywhere."""
import sys

from make_leaf_texture import png

SIZE = 64


def alpha_at(i, j):
    r2 = (i + 0.5 - SIZE / 2) ** 2 + (j + 0.5 - SIZE / 2) ** 2
    if r2 < 4 ** 2:
        return 255
    if r2 < 10 ** 2:
        return 0
    if min(i, j, SIZE - 1 - i, SIZE - 1 - j) < 4:
        return 154
    return 153 if (i // 8 + j // 8) % 2 == 0 else 152


def main():
    rows = [b"".join(bytes((200, 70, 50, alpha_at(i, j))) for i in range(SIZE)) for j in range(SIZE)]
    out = sys.argv[1] if len(sys.argv) > 1 else "assets/textures/mask-checker.png"
    with open(out, "wb") as f:
        f.write(png(SIZE, SIZE, rows))


if __name__ == "__main__":
    main()
