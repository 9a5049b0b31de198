#include "culling/draws_in_view.h"

#include "candela/render/frame_scene.h"

namespace candela::render {

std::vector<uint8_t> drawsInView(const FrameScene& scene, const SceneResources& resources,
                                 const ViewFrustum& frustum) {
    std::vector<uint8_t> visible(scene.draws.size(), 0);
    for (size_t i = 0; i < scene.draws.size(); ++i)
        visible[i] = intersects(frustum, worldBoundsOf(scene.draws[i], resources)) ? 1 : 0;
    return visible;
}

}  // namespace candela::render
