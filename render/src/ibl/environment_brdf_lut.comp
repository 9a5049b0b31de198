#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// The environment BRDF LUT of eq. 8 over (NoV, roughness) at texel centres, packed as two
// 16-bit UNORM values per texel (copied into an R16G16_UNORM image by the caller).
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
    texels[id.y * push.size + id.x] = packUnorm2x16(clamp(ab, 0.0, 1.0));
}
