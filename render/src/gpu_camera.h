#pragma once
// std140 camera block (matches render/shaders/common/camera.glsl).
#include <cstdint>
#include <glm/glm.hpp>

namespace candela::render {

struct GpuCamera {
    glm::mat4 viewProjection;
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraPosition;
    glm::uvec4 frameInfo;  // width, height, light count, unused
    glm::mat4 unjitteredViewProjection;
    glm::mat4 previousViewProjection;  // unjittered
    glm::vec4 jitter;                  // xy: this frame's (pixels), zw: the previous frame's
    // Sky occlusion (passes/sky_occlusion): the maps' sphere (centre, radius) and atlas layout
    // (directions, tiles per row, tile texels, atlas texels); directions 0: off.
    glm::vec4 skyOcclusionSphere;
    glm::uvec4 skyOcclusionLayout;
};

}  // namespace candela::render
