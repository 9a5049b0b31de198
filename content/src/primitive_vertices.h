#pragma once
// Helpers that treat all of a Primitive's vertex streams as one vertex.
#include "candela/content/model.h"

namespace candela::content {

// Appends a copy of vertex `index` to every non-empty stream; returns the new index.
std::uint32_t appendVertexCopy(Primitive& primitive, std::uint32_t index);

// Perpendicular unit vector to unit vector n (any one; stable for all n).
Float3 anyPerpendicular(const Float3& n);

}  // namespace candela::content
