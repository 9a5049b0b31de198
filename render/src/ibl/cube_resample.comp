#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// Resamples a cube environment loaded from six faces (any size) into mip 0 of the
// environment cube.
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = IBL_BINDING_SOURCE) uniform samplerCube source;
layout(binding = IBL_BINDING_DESTINATION, rgba16f) uniform writeonly image2DArray cube;

layout(push_constant) uniform Push {
    uint faceSize;
    float maxRadiance;
} push;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 d = cubeFaceDirection(id.z, (vec2(id.xy) + 0.5) / float(push.faceSize));
    vec3 radiance = textureLod(source, d, 0.0).rgb;
    imageStore(cube, ivec3(id), vec4(min(radiance, vec3(push.maxRadiance)), 1.0));
}
