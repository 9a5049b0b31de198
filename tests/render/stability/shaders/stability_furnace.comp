#version 460
// White furnace of the specular lobe, evaluated with the real shared terms: for each
// (roughness, NoV) cell, the directional albedo  integral of D * Vis * F * NoL over the
// hemisphere with F0 = 1 (Karis 2013, "Real Shading in Unreal Engine 4", eq. 2-5), which energy
// conservation bounds by 1. Directions come from a fixed Hammersley set through visible-normal
// sampling (Heitz 2018) with a GGX density written here, not the shared D, so the shared D is what
// gets integrated; the estimator stays bounded even at NoV = 0. The same cell also integrates the
// projected NDF integral of D * NoH over the hemisphere, which must be exactly 1. For the
// energy-conserving BRDF it also integrates the lobe with height-correlated Smith for a set of F0
// and scales it by multipleScatteringCompensation, with E_ss from the engine's LUT (given per cell
// by the host) and from Karis 2014's ("Physically Based Shading on Mobile") fit (the mobile path):
// what a surface reflects of a white furnace, which must not exceed 1.
#extension GL_GOOGLE_include_directive : require

#include "common/brdf.glsl"
#include "stability_checks.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 1) readonly buffer Axes {
    float axisValues[];  // roughness values, then NoV values, then E_ss from the LUT per cell
};
// Per cell: albedo with visibilitySmithSchlick, with visibilitySmithGgxCorrelated,
// integral of D * NoH, and the alpha used.
layout(std430, binding = 2) writeonly buffer Cells {
    vec4 cells[];
};
// Per cell and F0 of kF0: compensated albedo with E_ss from the LUT, then from the fit.
const uint kF0Count = 6u;
const float kF0[kF0Count] = float[](0.01, 0.02, 0.04, 0.25, 0.5, 1.0);
layout(std430, binding = 3) writeonly buffer Compensated {
    vec2 compensated[];
};

layout(push_constant) uniform Grid {
    uint roughnessCount;
    uint viewCount;
    uint sampleCount;      // Hammersley points per cell
    uint quadratureCount;  // midpoints of the D * NoH integral
};

const uint kCheckFurnaceSample = 0u;  // every per-sample integrand: finite and >= 0

shared vec3 partialSums[64];
shared float partialLobes[kF0Count][64];

float radicalInverseBase2(uint i) {
    return float(bitfieldReverse(i)) * 2.3283064365386963e-10;  // / 2^32
}

// sqrt and division are correctly rounded on the devices we test; inversesqrt() is not, and
// near NoH = 1 one ulp is already a large part of a narrow lobe.
vec3 accurateNormalize(vec3 v) {
    return v / sqrt(dot(v, v));
}

// GGX written from eq. 3 in its tan form, no cancellation near NoH = 1:
// D = (1 + tan^2)^2 / (pi a2 (1 + tan^2 / a2)^2).
float ggxFromTanSq(float a2, float tanSq) {
    float shape = 1.0 + tanSq / a2;
    return (1.0 + tanSq) * (1.0 + tanSq) / (PI * a2 * shape * shape);
}

// cos(theta) from tan^2(theta), correct to an ulp even within 1e-7 of 1: forming 1 + tan^2 in
// fp32 would round away the very part of the lobe near NoH = 1 that a narrow lobe lives in.
float cosFromTanSq(float tanSq) {
    float secant = sqrt(1.0 + tanSq);
    return 1.0 - tanSq / (secant * (secant + 1.0));
}

// Smith G1 of GGX divided by NoV, finite at NoV = 0 (where it is 2 / alpha).
float smithG1OverNoV(float alpha, float NoV) {
    return 2.0 / (NoV + sqrt(alpha * alpha + (1.0 - alpha * alpha) * NoV * NoV));
}

// Projected NDF normalisation: with w = tan^2(theta_h),
// integral D NoH dw = pi * integral D(w) / (1 + w)^2 dw = pi * integral D w / (1 + w)^2 dln(w).
// The midpoint rule in ln(w) around the lobe (w = a2 * e^x, |x| < 18) is exact to ~1e-7.
float projectedNdfTerm(float a2, uint k) {
    const float halfRange = 18.0;
    float step = 2.0 * halfRange / float(quadratureCount);
    float x = -halfRange + (float(k) + 0.5) * step;
    float w = a2 * exp(x);
    float NoH = cosFromTanSq(w);
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
    float lobes[kF0Count];
    for (uint k = 0u; k < kF0Count; ++k) lobes[k] = 0.0;
    for (uint i = lane; i < sampleCount; i += 64u) {
        // Visible-normal sampling (Heitz 2018): stretch V, sample the projected hemisphere
        // disk, unstretch. Density of L: G1(V) D(H) / (4 NoV).
        float u1 = (float(i) + 0.5) / float(sampleCount);
        float phi = 2.0 * PI * radicalInverseBase2(i);
        vec3 Vh = accurateNormalize(vec3(alpha * V.x, alpha * V.y, V.z));
        float lensq = Vh.x * Vh.x + Vh.y * Vh.y;
        vec3 T1 = lensq > 0.0 ? vec3(-Vh.y, Vh.x, 0.0) / sqrt(lensq) : vec3(1.0, 0.0, 0.0);
        vec3 T2 = cross(Vh, T1);
        float radius = sqrt(u1);
        float t1 = radius * cos(phi);
        float t2 = radius * sin(phi);
        float s = 0.5 * (1.0 + Vh.z);
        t2 = (1.0 - s) * sqrt(max(1.0 - t1 * t1, 0.0)) + s * t2;
        vec3 Nh = t1 * T1 + t2 * T2 + sqrt(max(1.0 - t1 * t1 - t2 * t2, 0.0)) * Vh;
        float contributionSchlick = 0.0;
        float contributionCorrelated = 0.0;
        if (Nh.z > 0.0) {
            vec3 H = accurateNormalize(vec3(alpha * Nh.x, alpha * Nh.y, Nh.z));
            float tanSq = a2 * (Nh.x * Nh.x + Nh.y * Nh.y) / (Nh.z * Nh.z);
            float VoH = dot(V, H);
            vec3 L = 2.0 * VoH * H - V;
            float NoL = L.z;
            if (NoL > 0.0 && VoH > 0.0) {
                float pdfL = smithG1OverNoV(alpha, NoV) * ggxFromTanSq(a2, tanSq) / 4.0;
                float f = fresnelSchlickSg(vec3(1.0), VoH).x;
                float NoH = cosFromTanSq(tanSq);
                float dTimesFNoL = distributionGgx(a2, NoH) * f * NoL;
                contributionSchlick = dTimesFNoL * visibilitySmithSchlick(alpha, NoV, NoL) / pdfL;
                contributionCorrelated =
                    dTimesFNoL * visibilitySmithGgxCorrelated(alpha, NoV, NoL) / pdfL;
                float lobe = distributionGgx(a2, NoH) * NoL *
                             visibilitySmithGgxCorrelated(alpha, NoV, NoL) / pdfL;
                for (uint k = 0u; k < kF0Count; ++k) {
                    lobes[k] += lobe * fresnelSchlickSg(vec3(kF0[k]), VoH).x;
                }
            }
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
    for (uint k = 0u; k < kF0Count; ++k) partialLobes[k][lane] = lobes[k];
    barrier();
    for (uint width = 32u; width > 0u; width /= 2u) {
        if (lane < width) {
            partialSums[lane] += partialSums[lane + width];
            for (uint k = 0u; k < kF0Count; ++k) {
                partialLobes[k][lane] += partialLobes[k][lane + width];
            }
        }
        barrier();
    }
    if (lane == 0u) {
        vec3 total = partialSums[0];
        cells[cell] = vec4(total.xy / float(sampleCount), total.z, alpha);
        float albedoLut = axisValues[roughnessCount + viewCount + cell];
        vec2 fit = envBrdfApproxScaleBias(roughness, NoV);
        for (uint k = 0u; k < kF0Count; ++k) {
            float single = partialLobes[k][0] / float(sampleCount);
            vec3 f0 = vec3(kF0[k]);
            compensated[cell * kF0Count + k] =
                single * vec2(multipleScatteringCompensation(f0, albedoLut).x,
                              multipleScatteringCompensation(f0, fit.x + fit.y).x);
        }
    }
}
