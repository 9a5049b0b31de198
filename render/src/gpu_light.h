#pragma once
// std430 light record (matches `struct Light` in render/shaders/common/lights.glsl).
#include <cstdint>

#include "candela/render/frame_scene.h"

namespace candela::render {

struct GpuLight {
    float position[3];
    float invAttenuationRadius;
    float intensity[3];  // colour * candela; colour * lux for directional
    float sourceRadius;
    float direction[3];
    float sourceLength;
    float tubeAxis[3];
    uint32_t type;
    float spotScale;
    float spotOffset;
    float shape[2];  // per-type parameters (encodeShape in lights/gpu_light_types.h), else 0
};
static_assert(sizeof(GpuLight) == 80, "std430 layout of struct Light");

// Converts photometric units (lumens -> candela, lux) and cone angles; sanitises values that
// would poison the image (negative or non-finite inputs become a light that adds nothing).
// `textureSlot`: a textured rect's 1 + atlas tile (lights/area_light_textures.h), 0 untextured.
GpuLight packLight(const LightInstance& light, uint32_t textureSlot = 0);

}  // namespace candela::render
