#pragma once
// Coarser triangle lists of a primitive for views that see it small: each level keeps about
// half the triangles of the one before, over the same vertices, simplified from the full list
// by edge collapses under the quadric error metric (Garland and Heckbert 1997, "Surface
// Simplification Using Quadric Error Metrics"; meshoptimizer's meshopt_simplify). Each level
// carries the distance its surface may lie from the full one, which the renderer turns into
// pixels to pick a level per view.
#include <cstdint>
#include <vector>

#include "candela/content/model.h"

namespace candela::content {

struct MeshLod {
    std::vector<std::uint32_t> indices;  // a triangle list into the primitive's vertices
    // Metres in mesh space: how far the level's surface may lie from the full one (twice the
    // simplifier's quadric estimate, which alone falls short by up to 1.6x).
    float error = 0.0f;
};

// Levels only pay for primitives of at least this many triangles.
inline constexpr std::uint32_t kMeshLodMinTriangles = 4096;
// Full list included: level 0 and up to 4 coarser ones (down to about 1/16).
inline constexpr std::uint32_t kMeshLodMaxLevels = 5;

// The coarser levels of `primitive` (level 1 first; the full list is not repeated), none for a
// primitive under kMeshLodMinTriangles triangles. A level that keeps more than 3/4 of the
// triangles of the one before (the simplifier could not go further without tearing open
// borders) ends the list. Morphed primitives get none: their targets move vertices the
// error does not account for.
std::vector<MeshLod> buildMeshLods(const Primitive& primitive);

}  // namespace candela::content
