#version 460
// White furnace of the specular lobe, evaluated with the real shared terms: for each
// (roughness, NoV) cell, the directional albedo  integral of D * Vis * F * NoL over the
// hemisphere with F0 = 1 (seed 000 eq. 2-5), which energy conservation bounds by 1. Directions
// come from a fixed Hammersley set, importance-sampled by a GGX density written here (not the
// shared D), so the shared D is what gets integrated. The same cell also integrates the
// projected NDF  integral of D * NoH over the hemisphere, which must be exactly 1.
#extension GL_GOOGLE_include_directive : require

#include "common/brdf.glsl"
#include "stability_checks.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 1) readonly buffer Axes {
    float axisValues[];  // roughness values, then NoV values
};
// Per cell: albedo with visibilitySmithSchlick, with visibilitySmithGgxCorrelated,
// integral of D * NoH, and the alpha used.
layout(std430, binding = 2) writeonly buffer Cells {
    vec4 cells[];
};

layout(push_constant) uniform Grid {
    uint roughnessCount;
    uint viewCount;
    uint sampleCount;      // Hammersley points per cell
    uint quadratureCount;  // midpoints of the D * NoH integral
};

const uint kCheckFurnaceSample = 0u;  // every per-sample integrand: finite and >= 0

shared vec3 partialSums[64];

float radicalInverseBase2(uint i) {
    return float(bitfieldReverse(i)) * 2.3283064365386963e-10;  // / 2^32
}

// Projected NDF normalisation: with w = tan^2(theta_h),
// integral D NoH dw = pi * integral D(w) / (1 + w)^2 dw = pi * integral D w / (1 + w)^2 dln(w).
// The midpoint rule in ln(w) around the lobe (w = a2 * e^x, |x| < 18) is exact to ~1e-7.
float projectedNdfTerm(float a2, uint k) {
    const float halfRange = 18.0;
    float step = 2.0 * halfRange / float(quadratureCount);
    float x = -halfRange + (float(k) + 0.5) * step;
    float w = a2 * exp(x);
    float NoH = inversesqrt(1.0 + w);
    return PI * distributionGgx(a2, NoH) * w / ((1.0 + w) * (1.0 + w)) * step;
}

void main() {
    uint cell = gl_WorkGroupID.x;
    uint lane = gl_LocalInvocationID.x;
    uint r = cell / viewCount;
    uint v = cell % viewCount;
    float roughness = axisValues[r];
    float NoV = axisValues[roughnessCount + v];
    float alpha = alphaFromRoughness(roughness);
    float a2 = alpha * alpha;
    vec3 V = vec3(sqrt(max(1.0 - NoV * NoV, 0.0)), 0.0, NoV);

    Tally t = newTally();
    vec3 sums = vec3(0.0);
    for (uint i = lane; i < sampleCount; i += 64u) {
        // GGX half-vector sampling with density D(h) NoH, written from eq. 3 in its
        // tan form so no cancellation near NoH = 1: D = 1 / (pi a2 cos^4 (1 + tan^2 / a2)^2).
        float u = (float(i) + 0.5) / float(sampleCount);
        float phi = 2.0 * PI * radicalInverseBase2(i);
        float tanSq = a2 * u / (1.0 - u);
        float cosTheta = inversesqrt(1.0 + tanSq);
        float sinTheta = sqrt(tanSq) * cosTheta;
        vec3 H = vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
        float cos4 = cosTheta * cosTheta * cosTheta * cosTheta;
        float shape = 1.0 + tanSq / a2;
        float pdfH = cosTheta / (PI * a2 * cos4 * shape * shape);

        float VoH = dot(V, H);
        vec3 L = 2.0 * VoH * H - V;
        float NoL = L.z;
        float contributionSchlick = 0.0;
        float contributionCorrelated = 0.0;
        if (NoL > 0.0 && VoH > 0.0) {
            float pdfL = pdfH / (4.0 * VoH);
            float NoH = saturate(cosTheta);
            float f = fresnelSchlickSg(vec3(1.0), VoH).x;
            float dTimesFNoL = distributionGgx(a2, NoH) * f * NoL;
            contributionSchlick = dTimesFNoL * visibilitySmithSchlick(alpha, NoV, NoL) / pdfL;
            contributionCorrelated =
                dTimesFNoL * visibilitySmithGgxCorrelated(alpha, NoV, NoL) / pdfL;
        }
        uint caseIndex = cell * sampleCount + i;
        tally(t, contributionSchlick, 0.0, kNoUpperBound, caseIndex);
        tally(t, contributionCorrelated, 0.0, kNoUpperBound, caseIndex);
        sums.xy += vec2(contributionSchlick, contributionCorrelated);
    }
    for (uint k = lane; k < quadratureCount; k += 64u) {
        float term = projectedNdfTerm(a2, k);
        tally(t, term, 0.0, kNoUpperBound, cell * sampleCount + k);
        sums.z += term;
    }
    flushTally(kCheckFurnaceSample, t);

    partialSums[lane] = sums;
    barrier();
    for (uint width = 32u; width > 0u; width /= 2u) {
        if (lane < width) partialSums[lane] += partialSums[lane + width];
        barrier();
    }
    if (lane == 0u) {
        vec3 total = partialSums[0];
        cells[cell] = vec4(total.xy / float(sampleCount), total.z, alpha);
    }
}
