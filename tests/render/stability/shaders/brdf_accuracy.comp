#version 460
// Evaluates each shared BRDF term at inputs chosen by the CPU, which compares them with its
// double-precision reference (brdf_reference.h).
#extension GL_GOOGLE_include_directive : require

#include "common/brdf.glsl"

layout(local_size_x = 64) in;

// Must match BrdfSample / BrdfValues in brdf_accuracy_tests.cpp.
struct BrdfSample {
    float roughness;
    float NoH;
    float NoV;
    float NoL;
    float VoH;
    float f0;
    float pad0;
    float pad1;
};

struct BrdfValues {
    float alpha;
    float d;
    float visSchlick;
    float visCorrelated;
    float fresnelSg;
    float fresnelPow5;
    float envBrdf;
    float envBrdfNonmetal;
};

layout(std430, binding = 0) readonly buffer Samples {
    BrdfSample samples[];
};
layout(std430, binding = 1) writeonly buffer Values {
    BrdfValues values[];
};

layout(push_constant) uniform Count {
    uint sampleCount;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= sampleCount) return;
    BrdfSample s = samples[i];
    float alpha = alphaFromRoughness(s.roughness);
    BrdfValues o;
    o.alpha = alpha;
    o.d = distributionGgx(alpha * alpha, s.NoH);
    o.visSchlick = visibilitySmithSchlick(alpha, s.NoV, s.NoL);
    o.visCorrelated = visibilitySmithGgxCorrelated(alpha, s.NoV, s.NoL);
    o.fresnelSg = fresnelSchlickSg(vec3(s.f0), s.VoH).x;
    o.fresnelPow5 = fresnelSchlickPow5(vec3(s.f0), s.VoH).x;
    o.envBrdf = envBrdfApprox(vec3(s.f0), s.roughness, s.NoV).x;
    o.envBrdfNonmetal = envBrdfApproxNonmetal(s.roughness, s.NoV);
    values[i] = o;
}
