#pragma once
// The ambient occlusion the lighting pass applied to the sky's light, for the passes after it
// that take it out again (SSR's trace): none when the frame has no AO.
#include <cstdint>
#include <optional>

#include "frame_graph/frame_graph.h"

namespace candela::render {

struct AmbientOcclusionFrame {
    std::optional<ResourceHandle> occlusion;  // (bent normal, visibility)
    std::optional<ResourceHandle> specular;   // the reference's specular visibility
    uint32_t mode = 0;                        // lighting.comp's kAoMode
    float intensity = 1.0f;
};

}  // namespace candela::render
