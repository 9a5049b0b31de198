#pragma once
// The G-buffer's colour targets in this frame's graph (gbuffer_targets.h order: base colour,
// normal-roughness-metallic, specular-model, custom data), as the G-buffer pass wrote them.
#include <array>
#include <optional>

#include "frame_graph/frame_graph.h"

namespace candela::render {

struct GBufferFrame {
    std::array<ResourceHandle, 4> color;
    std::optional<ResourceHandle> edges;  // GBAA's edge target (--aa gbaa)
};

}  // namespace candela::render
