#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// Resamples a lat-long environment (OpenEXR convention, see content/environment_map.h) into
// mip 0 of the environment cube.
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = IBL_BINDING_SOURCE) uniform sampler2D latLong;  // repeat in u, clamp in v
layout(binding = IBL_BINDING_DESTINATION, rgba16f) uniform writeonly image2DArray cube;

layout(push_constant) uniform Push {
    uint faceSize;
    float maxRadiance;  // fp16 holds 65504; brighter suns are clamped, not turned into Inf
} push;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 d = cubeFaceDirection(id.z, (vec2(id.xy) + 0.5) / float(push.faceSize));
    float longitude = atan(d.x, d.z);
    float latitude = asin(clamp(d.y, -1.0, 1.0));
    vec2 uv = vec2(0.5 - longitude / (2.0 * PI), 0.5 - latitude / PI);
    vec3 radiance = textureLod(latLong, uv, 0.0).rgb;
    imageStore(cube, ivec3(id), vec4(min(radiance, vec3(push.maxRadiance)), 1.0));
}
