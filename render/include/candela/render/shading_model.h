#pragma once
// Shading-model IDs as stored in the G-buffer. Must match
// render/shaders/common/shading_models.glsl.
#include <cstdint>

namespace candela::render {

enum class ShadingModelId : uint32_t {
    Unlit = 0,
    DefaultLit = 1,
    Subsurface = 2,
    LegacyDiffuseSpecular = 3,
};

}  // namespace candela::render
