#include "culling/draws_in_view.h"

#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"

namespace candela::render {

std::vector<uint8_t> drawsInView(const FrameScene& scene, const SceneResources& resources,
                                 const ViewFrustum& frustum, const LodView& lod) {
    std::vector<uint8_t> levels(scene.draws.size(), kDrawCulled);
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const DrawItem& draw = scene.draws[i];
        const WorldBounds bounds = worldBoundsOf(draw, resources);
        if (!intersects(frustum, bounds)) continue;
        levels[i] = uint8_t(selectLod(resources.mesh(draw.mesh), draw.world, bounds, lod));
    }
    return levels;
}

}  // namespace candela::render
