// The per-frame camera block every pass reads (matches render/src/gpu_camera.h).
#ifndef CANDELA_CAMERA_GLSL
#define CANDELA_CAMERA_GLSL

#include "common/shared_bindings.h"

layout(std140, binding = CAMERA_BINDING) uniform CameraBlock {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 cameraPosition;  // xyz, w unused
    uvec4 frameInfo;      // x, y: target size; z: light count; w: unused
} camera;

#endif
