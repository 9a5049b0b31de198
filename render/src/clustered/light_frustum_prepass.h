#pragma once
// Frustum pre-pass of the CPU light assignment: before the per-light walk, four lights at a
// time (SSE) test a bounding sphere of each local light against the near plane and the screen
// edges, so lights outside the view cost a few instructions instead of lightBoundsInView and
// a slice walk. It only rejects what the walk would reject anyway (the bound below is looser
// than every test the walk makes), so the lists are identical with or without it.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"
#include "clustered/cluster_grid.h"

namespace candela::render {

// Scratch kept between calls (one per job): world-space bounding spheres, structure of arrays.
struct LightFrustumScratch {
    std::vector<float> x, y, z, radius;
    std::vector<uint32_t> index;
};

// Appends to `visible`, ascending, the indices in [first, last) of the local (non-directional)
// lights whose bounds may reach a cluster of `grid` seen through `view`.
void lightsInFrustum(const ClusterGrid& grid, std::span<const LightInstance> lights, size_t first,
                     size_t last, const glm::mat4& view, LightFrustumScratch& scratch,
                     std::vector<uint32_t>& visible);

}  // namespace candela::render
