#include "culling/draw_bounds.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"

namespace candela::render {

WorldBounds worldBoundsOf(const DrawItem& draw, const SceneResources& resources) {
    const auto [centre, extent] = resources.meshSpaceBounds(draw);
    WorldBounds b;
    b.centre = glm::vec3(draw.world * glm::vec4(centre, 1.0f));
    const glm::mat3 m(draw.world);
    b.extent = glm::abs(m[0]) * extent.x + glm::abs(m[1]) * extent.y + glm::abs(m[2]) * extent.z;
    b.radius = glm::length(b.extent);
    return b;
}

std::vector<WorldBounds> worldBoundsOf(const FrameScene& scene, const SceneResources& resources) {
    std::vector<WorldBounds> bounds;
    bounds.reserve(scene.draws.size());
    for (const DrawItem& draw : scene.draws)
        bounds.push_back(worldBoundsOf(draw, resources));
    return bounds;
}

}  // namespace candela::render
