#!/usr/bin/env python3
"""Writes assets/meshes/mask_card.gltf: the mask-card case's card (meshes/mask_card.obj) as a
glTF 2.0 file with a MASK material, so that a test can hold every family's V on a glTF cut-out
to its V on the same card read from JSON + OBJ + PNG (docs/cut-outs.md). One file, its buffer
and its base colour texture (assets/textures/mask-checker.png, whose alpha is the cut-out's) as
data URIs; baseColorFactor and alphaCutoff as mask-card.json's material. glTF's texture
coordinates run down from the image's top, OBJ's up from its bottom: v_gltf = 1 - v_obj.
Our own data, MIT like the code; plain Python, so that it regenerates anywhere."""
import base64
import json
import struct
import sys

POSITIONS = [(-0.5, 0, 0.5), (0.5, 0, 0.5), (0.5, 0, -0.5), (-0.5, 0, -0.5)]
OBJ_UVS = [(0, 0), (1, 0), (1, 1), (0, 1)]
INDICES = [0, 1, 2, 0, 2, 3]
FLOAT, UNSIGNED_SHORT, ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 5126, 5123, 34962, 34963


def main():
    texture = sys.argv[1] if len(sys.argv) > 1 else "assets/textures/mask-checker.png"
    out = sys.argv[2] if len(sys.argv) > 2 else "assets/meshes/mask_card.gltf"
    positions = b"".join(struct.pack("<3f", *p) for p in POSITIONS)
    normals = struct.pack("<3f", 0, 1, 0) * len(POSITIONS)
    uvs = b"".join(struct.pack("<2f", u, 1 - v) for u, v in OBJ_UVS)
    indices = struct.pack("<6H", *INDICES)
    views, offset = [], 0
    for data, target in ((positions, ARRAY_BUFFER), (normals, ARRAY_BUFFER), (uvs, ARRAY_BUFFER),
                         (indices, ELEMENT_ARRAY_BUFFER)):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data), "target": target})
        offset += len(data)
    buffer = positions + normals + uvs + indices
    with open(texture, "rb") as f:
        png = f.read()
    document = {
        "asset": {"version": "2.0", "generator": "shadowlab scripts/make_mask_card_gltf.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "card", "mesh": 0}],
        "meshes": [{"name": "card", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "materials": [{"name": "mask", "alphaMode": "MASK", "alphaCutoff": 0.6, "doubleSided": True,
                       "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.25, 0.2, 1.0],
                                                "baseColorTexture": {"index": 0},
                                                "metallicFactor": 0.0, "roughnessFactor": 1.0}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}],
        "accessors": [
            {"bufferView": 0, "componentType": FLOAT, "count": 4, "type": "VEC3",
             "min": [-0.5, 0, -0.5], "max": [0.5, 0, 0.5]},
            {"bufferView": 1, "componentType": FLOAT, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": FLOAT, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": UNSIGNED_SHORT, "count": 6, "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
    }
    with open(out, "w") as f:
        json.dump(document, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
