#pragma once
// Which level of detail a view draws a mesh at: the coarsest whose error, projected into the
// view, stays within a budget of pixels (shadow maps: texels). A level's error is a distance
// in mesh space (GpuMesh::Lod::error); the draw's world matrix scales it and the view's
// projection turns metres at the draw's distance into pixels.
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "culling/draw_bounds.h"

namespace candela::render {

struct GpuMesh;

struct LodView {
    glm::vec3 eye{0.0f};
    // Pixels one metre spans: at one metre's distance (perspective), or anywhere
    // (orthographic: a directional light's cascade).
    float pixelsPerMetre = 0.0f;
    bool perspective = true;
    float pixelError = 0.0f;  // the budget; 0: every draw at level 0 (the reference)
};

// The view of a perspective projection (clip w = distance along the view axis) `height`
// pixels tall: pixels per metre at 1 m from its vertical scale, |projection[1][1]|.
LodView perspectiveLodView(const glm::vec3& eye, const glm::mat4& projection, float height,
                           float pixelError);

// The level `view` draws `mesh` at, placed by `world` within `bounds` (its world box). The
// distance is to the box's nearest point, so a level never looks coarser than its budget.
uint32_t selectLod(const GpuMesh& mesh, const glm::mat4& world, const WorldBounds& bounds,
                   const LodView& view);

}  // namespace candela::render
