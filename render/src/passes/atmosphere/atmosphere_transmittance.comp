#version 460
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_bindings.h"
// The transmittance table (Hillaire 2020 section 5.1): per texel, the (r, mu) of
// transmittanceRadiusMu and exp(-optical depth) to the top of the atmosphere.
#include "atmosphere_push.glsl"

layout(local_size_x = ATMOSPHERE_GROUP_SIZE, local_size_y = ATMOSPHERE_GROUP_SIZE) in;
layout(binding = ATMOSPHERE_BINDING_DESTINATION, rgba16f) uniform writeonly image2D table;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size.x || id.y >= push.size.y) return;
    vec2 size = vec2(push.size.xy);
    float r, mu;
    transmittanceRadiusMu(push.atmosphere, (vec2(id) + 0.5) / size, size, r, mu);
    vec3 transmittance = transmittanceToTop(push.atmosphere, r, mu, int(push.size.z));
    imageStore(table, ivec2(id), vec4(transmittance, 1.0));
}
