#include "culling/lod_selection.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "candela/render/scene_resources.h"

namespace candela::render {

LodView perspectiveLodView(const glm::vec3& eye, const glm::mat4& projection, float height,
                           float pixelError) {
    LodView v;
    v.eye = eye;
    v.pixelsPerMetre = 0.5f * height * std::abs(projection[1][1]);
    v.perspective = true;
    v.pixelError = pixelError;
    return v;
}

uint32_t selectLod(const GpuMesh& mesh, const glm::mat4& world, const WorldBounds& bounds,
                   const LodView& view) {
    if (mesh.lodCount <= 1 || !(view.pixelError > 0.0f)) return 0;
    // Mesh-space metres to world metres: the longest axis the world matrix stretches.
    const float scale =
        std::max({glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])),
                  glm::length(glm::vec3(world[2]))});
    float pixelsPerMetre = view.pixelsPerMetre;
    if (view.perspective) {
        const glm::vec3 nearest =
            glm::clamp(view.eye, bounds.centre - bounds.extent, bounds.centre + bounds.extent);
        const float distance = glm::length(nearest - view.eye);
        // Inside the box or nearly: the full mesh.
        if (!(distance > 1e-3f)) return 0;
        pixelsPerMetre /= distance;
    }
    uint32_t level = 0;
    for (uint32_t l = 1; l < mesh.lodCount; ++l) {
        if (mesh.lods[l].error * scale * pixelsPerMetre > view.pixelError) break;
        level = l;
    }
    return level;
}

}  // namespace candela::render
