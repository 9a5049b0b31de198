#pragma once
// Which of a frame's draws a view can see: a flag per draw, by its world box against the
// view's frustum. The G-buffer and forward passes skip the rest; on a CPU rasterizer every
// vertex of a draw off screen would still be transformed.
#include <cstdint>
#include <vector>

#include "culling/view_frustum.h"

namespace candela::render {

struct FrameScene;

// 1 for each draw of `scene` whose box meets `frustum`, else 0.
std::vector<uint8_t> drawsInView(const FrameScene& scene, const SceneResources& resources,
                                 const ViewFrustum& frustum);

}  // namespace candela::render
