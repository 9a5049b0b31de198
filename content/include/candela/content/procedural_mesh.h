#pragma once
// Meshes the engine builds itself (test scenes, the demo level's architecture): the same
// Primitive a glTF loads, with normals, tangents and UVs filled in analytically.
#include <cstdint>

#include "candela/content/model.h"

namespace candela::content {

// A square in the XZ plane facing +Y, centred on the origin, `subdivisions` quads per side.
Primitive makePlane(float halfExtent, uint32_t subdivisions = 1);

// A UV sphere centred on the origin.
Primitive makeSphere(float radius, uint32_t segments = 48, uint32_t rings = 24);

// An axis-aligned box centred on the origin with outward faces.
Primitive makeBox(const Float3& halfExtents);

}  // namespace candela::content
