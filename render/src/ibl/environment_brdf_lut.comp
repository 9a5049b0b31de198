#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// The environment BRDF LUT of eq. 8 over (NoV, roughness) at texel centres: (scale, bias) with
// Schlick-Smith visibility (eq. 4, the UE4 BRDF) and with height-correlated Smith (the
// energy-conserving BRDF), packed as four 16-bit UNORM values per texel, two uints (copied
// into an R16G16B16A16_UNORM image by the caller).
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = BRDF_LUT_BINDING_TEXELS) writeonly buffer Texels { uint texels[]; };

layout(push_constant) uniform Push {
    uint size;
    uint sampleCount;
} push;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size || id.y >= push.size) return;
    float NoV = (float(id.x) + 0.5) / float(push.size);
    float roughness = (float(id.y) + 0.5) / float(push.size);
    vec2 ab = integrateEnvironmentBrdf(roughness, NoV, push.sampleCount);
    // The height-correlated pair at its own texel positions (correlatedLutTexelParameters).
    vec2 p = correlatedLutTexelParameters(id, push.size);
    vec2 abCorrelated = integrateEnvironmentBrdfCorrelated(p.y, p.x, push.sampleCount);
    uint texel = id.y * push.size + id.x;
    texels[2u * texel] = packUnorm2x16(clamp(ab, 0.0, 1.0));
    texels[2u * texel + 1u] = packUnorm2x16(clamp(abCorrelated, 0.0, 1.0));
}
