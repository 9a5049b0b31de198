#!/usr/bin/env python3
"""Writes power_lines.gltf for the wire golden (issue 19; Persson 2014, GPU Pro 5, "Wire
Antialiasing"): a grey ground
quad and, against the default sky, wires from LINE_STRIP / LINES primitives whose materials'
extras give wireRadius: five sagging 1.2 cm cables running away from the camera (from a few
pixels wide near it to a tenth of a pixel far off), a thick 6 cm lit cable across the view
(cylinder shading) and an unlit emissive wire. Standard library only.
Run: python3 power_lines_gltf.py"""
from gltf_buffer import GltfBuffer

gltf = GltfBuffer()


# Ground: 200 m square at y = 0, facing up.
ground_positions, ground_normals, ground_indices = gltf.add_ground(100)

primitives = []
# Five cables from x = -4..4, 4 to 6 m up, running from z = 2 to z = -120 with 20 m spans.
for i in range(5):
    x = -4.0 + 2.0 * i
    top = 4.0 + 0.5 * i
    points = []
    for k in range(0, 61):
        z = 2.0 - 2.0 * k
        u = (k % 10) / 10.0 * 2.0 - 1.0
        points.append((x, top - 0.8 * (1.0 - u * u), z))
    primitives.append({"attributes": {"POSITION": gltf.add_points(points)}, "mode": 3, "material": 1})
# A thick cable across the view, lit (LINES: two segments).
thick = gltf.add_points([(-12, 2.2, -6), (0, 1.6, -6), (0, 1.6, -6), (12, 2.2, -6)])
primitives.append({"attributes": {"POSITION": thick}, "mode": 1, "material": 2})
# An unlit emissive wire, high up.
glow = gltf.add_points([(-30, 9.0, -25), (30, 7.0, -25)])
primitives.append({"attributes": {"POSITION": glow}, "mode": 3, "material": 3})

doc = {
    "asset": {"version": "2.0", "generator": "candela tests (power_lines_gltf.py)"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [
        {"mesh": 0, "name": "ground"},
        {"mesh": 1, "name": "power lines"},
        {"camera": 0, "name": "camera", "translation": [0.5, 1.7, 6],
         "rotation": [0.0871557, 0, 0, 0.9961947]},
    ],
    "meshes": [
        {"name": "ground", "primitives": [
            {"attributes": {"POSITION": ground_positions, "NORMAL": ground_normals},
             "indices": ground_indices, "material": 0}]},
        {"name": "power lines", "primitives": primitives},
    ],
    "materials": [
        {"name": "ground", "pbrMetallicRoughness": {
            "baseColorFactor": [0.3, 0.3, 0.28, 1], "metallicFactor": 0, "roughnessFactor": 0.9}},
        {"name": "aluminium cable", "extras": {"wireRadius": 0.012}, "pbrMetallicRoughness": {
            "baseColorFactor": [0.6, 0.6, 0.62, 1], "metallicFactor": 1, "roughnessFactor": 0.4}},
        {"name": "thick black cable", "extras": {"wireRadius": 0.06}, "pbrMetallicRoughness": {
            "baseColorFactor": [0.05, 0.05, 0.05, 1], "metallicFactor": 0,
            "roughnessFactor": 0.35}},
        {"name": "glowing wire", "extras": {"wireRadius": 0.02, "shadingModel": "unlit"},
         "emissiveFactor": [1, 0.4, 0.1],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 20000}},
         "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}},
    ],
    "extensionsUsed": ["KHR_materials_emissive_strength"],
    "cameras": [{"type": "perspective",
                 "perspective": {"yfov": 1.0, "znear": 0.05, "aspectRatio": 1.0}}],
}
gltf.write(doc, __file__.replace("_gltf.py", ".gltf"))
