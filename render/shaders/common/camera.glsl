// The per-frame camera block every pass reads (matches render/src/gpu_camera.h).
#ifndef CANDELA_CAMERA_GLSL
#define CANDELA_CAMERA_GLSL

#include "common/shared_bindings.h"

layout(std140, binding = CAMERA_BINDING) uniform CameraBlock {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 cameraPosition;  // xyz, w unused
    uvec4 frameInfo;      // x, y: target size; z: light count; w: unused
    // Motion vectors: this frame's and the previous frame's view-projection without the TAA
    // jitter (viewProjection above has it), so a static pixel has zero motion.
    mat4 unjitteredViewProjection;
    mat4 previousViewProjection;
    vec4 jitter;  // xy: this frame's jitter in pixels, zw: the previous frame's
    // Sky occlusion (common/sky_occlusion.glsl): the maps' sphere (centre, radius) and layout
    // (directions, tiles per row, tile texels, atlas texels); x of the layout 0: off.
    vec4 skyOcclusionSphere;
    uvec4 skyOcclusionLayout;
} camera;

#endif
