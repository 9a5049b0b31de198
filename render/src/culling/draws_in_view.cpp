#include "culling/draws_in_view.h"

#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"

namespace candela::render {

std::vector<uint8_t> drawsInView(const FrameScene& scene, const SceneResources& resources,
                                 std::span<const WorldBounds> bounds, const ViewFrustum& frustum,
                                 const LodView& lod) {
    std::vector<uint8_t> levels(scene.draws.size(), kDrawCulled);
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const DrawItem& draw = scene.draws[i];
        if (!intersects(frustum, bounds[i])) continue;
        levels[i] = uint8_t(selectLod(resources.mesh(draw.mesh), draw.world, bounds[i], lod));
    }
    return levels;
}

}  // namespace candela::render
