#!/usr/bin/env python3
"""Writes hair_ball.gltf for the hair golden (issue 19; Martin et al. 2014, GPU Pro 5, "TressFX:
Advanced Real-Time Hair Rendering"): a dark sphere
covered in 800 strands of fur (LINES, root first, 3 segments each, from a fixed random seed)
whose material's extras give `hair` (root and tip radius, colour, the two highlights' shifts
and exponents), on a grey ground under a sun that casts shadows (so the hair shadows itself
through its hair depth map) and an unshadowed sky-blue fill, the runtime's default sun and fill
(which cast none). Standard library only.
Run: python3 hair_ball_gltf.py [STRANDS OUTPUT] (render/README.md's cost figures use 10,000
strands written elsewhere)."""
import math
import random
import sys

from gltf_buffer import GltfBuffer

gltf = GltfBuffer()


RADIUS = 0.5
CENTRE = (0.0, 0.55, 0.0)

# Ground: 20 m square at y = 0, facing up.
ground_positions, ground_normals, ground_indices = gltf.add_ground(10)

# The ball: a UV sphere, 16 x 8.
positions, normals, indices = [], [], []
SEG, RINGS = 16, 8
for r in range(RINGS + 1):
    theta = math.pi * r / RINGS
    for s in range(SEG + 1):
        phi = 2 * math.pi * s / SEG
        n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
        normals += n
        positions += [CENTRE[i] + RADIUS * n[i] for i in range(3)]
for r in range(RINGS):
    for s in range(SEG):
        a, b = r * (SEG + 1) + s, (r + 1) * (SEG + 1) + s
        indices += [a, a + 1, b, a + 1, b + 1, b]
ball_positions = gltf.add_floats(positions, "VEC3", len(positions) // 3)
ball_normals = gltf.add_floats(normals, "VEC3", len(normals) // 3)
ball_indices = gltf.add_indices(indices)

STRANDS = int(sys.argv[1]) if len(sys.argv) > 1 else 800
OUTPUT = sys.argv[2] if len(sys.argv) > 2 else __file__.replace("_gltf.py", ".gltf")

# Fur: 800 strands, 12 cm long, leaning and drooping a little, in 3 segments (LINES pairs).
rng = random.Random(19)
fur, pairs = [], []
for k in range(STRANDS):
    z = rng.uniform(-1.0, 1.0)
    phi = rng.uniform(0.0, 2 * math.pi)
    s = math.sqrt(1 - z * z)
    n = [s * math.cos(phi), z, s * math.sin(phi)]
    lean = [rng.uniform(-0.5, 0.5) for _ in range(3)]
    p = [CENTRE[i] + RADIUS * n[i] for i in range(3)]
    d = list(n)
    first = len(fur) // 3
    fur += p
    for j in range(1, 4):
        d = [d[i] + 0.35 * lean[i] - (0.2 if i == 1 else 0.0) for i in range(3)]
        length = math.sqrt(sum(c * c for c in d))
        p = [p[i] + 0.04 * d[i] / length for i in range(3)]
        fur += p
        pairs += [first + j - 1, first + j]
fur_positions = gltf.add_floats(fur, "VEC3", len(fur) // 3)
fur_indices = gltf.add_indices(pairs)

def aim(direction):
    """The rotation (x, y, z, w) turning a glTF light's -Z onto `direction`."""
    n = math.sqrt(sum(c * c for c in direction))
    d = [c / n for c in direction]
    axis = [d[1], -d[0], 0.0]  # (0, 0, -1) x d
    s = math.sqrt(sum(c * c for c in axis))
    angle = math.acos(max(-1.0, min(1.0, -d[2])))
    if s < 1e-9:
        return [0.0, 0.0, 0.0, 1.0]
    h = math.sin(angle / 2) / s
    return [round(axis[0] * h, 7), round(axis[1] * h, 7), round(axis[2] * h, 7),
            round(math.cos(angle / 2), 7)]


doc = {
    "asset": {"version": "2.0", "generator": "candela tests (hair_ball_gltf.py)"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "name": "sun", "intensity": 100000,
         "color": [1.0, 0.96, 0.9], "extras": {"castShadows": True}},
        {"type": "directional", "name": "fill", "intensity": 25000,
         "color": [0.6, 0.75, 1.0], "extras": {"castShadows": False}}]}},
    "nodes": [
        {"mesh": 0, "name": "ground"},
        {"mesh": 1, "name": "hair ball"},
        {"camera": 0, "name": "camera", "translation": [0, 0.9, 2.2],
         "rotation": [-0.0871557, 0, 0, 0.9961947]},
        {"name": "sun", "rotation": aim([-0.4, -0.8, -0.45]),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "fill", "rotation": aim([0.6, 0.2, -0.5]),
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
    ],
    "meshes": [
        {"name": "ground", "primitives": [
            {"attributes": {"POSITION": ground_positions, "NORMAL": ground_normals},
             "indices": ground_indices, "material": 0}]},
        {"name": "hair ball", "primitives": [
            {"attributes": {"POSITION": ball_positions, "NORMAL": ball_normals},
             "indices": ball_indices, "material": 1},
            {"attributes": {"POSITION": fur_positions}, "indices": fur_indices, "mode": 1,
             "material": 2}]},
    ],
    "materials": [
        {"name": "ground", "pbrMetallicRoughness": {
            "baseColorFactor": [0.3, 0.3, 0.28, 1], "metallicFactor": 0, "roughnessFactor": 0.9}},
        {"name": "skin", "pbrMetallicRoughness": {
            "baseColorFactor": [0.25, 0.15, 0.08, 1], "metallicFactor": 0,
            "roughnessFactor": 0.8}},
        {"name": "fur", "extras": {"hair": {
            "rootRadius": 0.002, "tipRadius": 0.0005, "color": [0.55, 0.33, 0.15],
            "primaryShift": 0.1, "secondaryShift": -0.1, "primaryExponent": 80,
            "secondaryExponent": 20}}},
    ],
    "cameras": [{"type": "perspective",
                 "perspective": {"yfov": 0.8, "znear": 0.05, "aspectRatio": 1.0}}],
}
gltf.write(doc, OUTPUT)
