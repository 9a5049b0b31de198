#pragma once
// Per-vertex tangents equivalent to MikkTSpace (the glTF reference tangent space):
//  - per triangle, the direction of the UV gradient dP/du;
//  - projected onto each corner's normal plane and weighted by the corner angle;
//  - summed over the vertices that share position, normal and UV (welded as MikkTSpace does)
//    and the same UV winding, then normalised;
//  - w = +1 where the UV layout is not mirrored, -1 where it is; a vertex used by both
//    windings is split so each side keeps its own tangent.
// Bitangent = w * cross(normal, tangent.xyz), as glTF defines; it points to -dP/dv, "up" in
// the image, because glTF's v runs down the image (normal maps are +Y up). This is what
// MikkTSpace gives when fed (u, 1 - v), as Blender's glTF exporter does.
#include <cstdint>

#include "candela/content/model.h"

namespace candela::content {

// Fills primitive.tangents using uv set `uvSet` (0 or 1). Without that UV set, tangents are
// an arbitrary unit vector perpendicular to the normal with w = 1. Needs normals. May append
// vertices (mirrored-UV seams). Sets tangentsGenerated.
void generateTangents(Primitive& primitive, std::uint32_t uvSet = 0);

}  // namespace candela::content
