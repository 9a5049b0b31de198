#!/usr/bin/env python3
"""Writes layered_sphere.gltf: a UV sphere (radius 1, positions, normals, tangents, UVs) with two
small procedural textures embedded as PNG data URIs, for the material-layers golden
(layered_material.scene.json, issue 21):
  texture 0: the layer mask, 64x64; R = rust blotches (smooth value noise, soft-edged), G = B = 0.
  texture 1: rust grain, 32x32 linear-ish brown variation, tiled at the rust layer's UV scale.
Deterministic (fixed hash), standard library only. Run: python3 layered_sphere_gltf.py"""
import base64
import json
import math
import struct
import zlib


def png(width, height, rgba):
    raw = b"".join(b"\x00" + bytes(rgba[y * width * 4:(y + 1) * width * 4]) for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


def hash01(x, y, seed):
    h = (x * 374761393 + y * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65535.0


def value_noise(u, v, cells, seed):
    """Smooth value noise, tiling with period `cells` in both directions."""
    x, y = u * cells, v * cells
    x0, y0 = int(math.floor(x)), int(math.floor(y))
    fx, fy = x - x0, y - y0
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)

    def corner(i, j):
        return hash01((x0 + i) % cells, (y0 + j) % cells, seed)

    top = corner(0, 0) * (1 - sx) + corner(1, 0) * sx
    bottom = corner(0, 1) * (1 - sx) + corner(1, 1) * sx
    return top * (1 - sy) + bottom * sy


def mask_texture(size=64):
    rgba = []
    for y in range(size):
        for x in range(size):
            u, v = (x + 0.5) / size, (y + 0.5) / size
            n = 0.65 * value_noise(u, v, 4, 1) + 0.35 * value_noise(u, v, 8, 2)
            rust = min(1.0, max(0.0, (n - 0.48) / 0.12))  # soft edge around the threshold
            rgba += [int(round(rust * 255)), 0, 0, 255]
    return png(size, size, rgba)


def grain_texture(size=32):
    rgba = []
    for y in range(size):
        for x in range(size):
            u, v = (x + 0.5) / size, (y + 0.5) / size
            g = 0.6 * value_noise(u, v, 8, 3) + 0.4 * value_noise(u, v, 16, 4)
            shade = 0.55 + 0.45 * g
            rgba += [int(round(255 * shade)), int(round(255 * shade * (0.7 + 0.3 * g))),
                     int(round(255 * shade * 0.6)), 255]
    return png(size, size, rgba)


def sphere(segments=36, rings=18):
    positions, normals, tangents, uvs, indices = [], [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            positions += n
            normals += n
            tangents += [-math.sin(phi), 0.0, -math.cos(phi), 1.0]
            uvs += [s / segments, r / rings]
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, tangents, uvs, indices


def main():
    positions, normals, tangents, uvs, indices = sphere()
    blobs = [struct.pack("<%df" % len(positions), *positions),
             struct.pack("<%df" % len(normals), *normals),
             struct.pack("<%df" % len(tangents), *tangents),
             struct.pack("<%df" % len(uvs), *uvs),
             struct.pack("<%dH" % len(indices), *indices)]
    views, offset = [], 0
    for blob in blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob)})
        offset += len(blob)
    data = b"".join(blobs)
    count = len(positions) // 3
    gltf = {
        "asset": {"version": "2.0",
                  "generator": "candela tests/scenes/layered_sphere_gltf.py (procedural)"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "layered sphere"}],
        "meshes": [{"name": "layered sphere", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3},
            "indices": 4, "material": 0}]}],
        "materials": [{"name": "plain", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [-1, -1, -1], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": count, "type": "VEC4"},
            {"bufferView": 3, "componentType": 5126, "count": count, "type": "VEC2"},
            {"bufferView": 4, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(data).decode()}],
        "images": [{"name": "layer mask", "uri": "data:image/png;base64," +
                    base64.b64encode(mask_texture()).decode()},
                   {"name": "rust grain", "uri": "data:image/png;base64," +
                    base64.b64encode(grain_texture()).decode()}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    }
    with open(__file__.replace("_gltf.py", ".gltf"), "w") as out:
        json.dump(gltf, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
