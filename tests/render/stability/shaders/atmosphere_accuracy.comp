#version 460
// The shared atmosphere math (common/atmosphere.glsl) at rays chosen by the CPU: the
// transmittance the table stores per texel (transmittanceToTop with the table's samples), and
// the (r, mu) the table's parameterisation gives back for the texel coordinate of each ray.
#extension GL_GOOGLE_include_directive : require

#include "common/atmosphere.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Rays {
    vec4 rays[];  // x: altitude (km), y: mu
};
layout(std430, binding = 1) writeonly buffer Transmittance {
    vec4 transmittance[];
};
layout(std430, binding = 2) writeonly buffer RoundTrip {
    vec4 roundTrip[];  // x: r - bottom (km), y: mu after uv -> (r, mu)
};

layout(push_constant) uniform Push {
    AtmosphereParameters atmosphere;
    uvec4 info;  // x: ray count, y: samples, z, w: the table's size
} push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.info.x) return;
    AtmosphereParameters a = push.atmosphere;
    float r = atmosphereBottom(a) + rays[i].x;
    float mu = rays[i].y;
    transmittance[i] = vec4(transmittanceToTop(a, r, mu, int(push.info.y)), 0.0);
    vec2 size = vec2(push.info.zw);
    float r2, mu2;
    transmittanceRadiusMu(a, transmittanceUv(a, r, mu, size), size, r2, mu2);
    roundTrip[i] = vec4(r2 - atmosphereBottom(a), mu2, 0.0, 0.0);
}
