#version 460
// Anisotropic GGX (brdf.glsl distributionGgxAnisotropic, visibilitySmithGgxCorrelatedAnisotropic)
// on the device, one workgroup per (alphaT, alphaB) cell:
//  - the projected microfacet area, integral of D(h) (n.h) dh over the hemisphere, which must be
//    1 for every pair, extreme ratios included. Quadrature in (psi, ln tan^2 theta): the azimuth
//    phi = atan2(aB sin psi, aT cos psi) puts as many points in the narrow azimuths of a 1000:1
//    lobe as in the wide ones (exact Jacobian aT aB / (aT^2 cos^2 psi + aB^2 sin^2 psi)), and
//    per azimuth the midpoint rule in ln(tan^2) covers e^+-18 around that azimuth's alpha^2.
//    Each point is H = (sin cos phi, sin sin phi, cos) built without 1 - cos^2 cancellation.
//  - on cells with aT == aB: the largest distance, in ulps, between the anisotropic D and the
//    isotropic D in its tangent form at the same H (the reduction), the largest relative
//    difference to eq. 3's distributionGgx(a2, NoH) over the lobe's core, and of the
//    anisotropic visibility to visibilitySmithGgxCorrelated.
//  - the directional albedo of D * Vis * NoL (F0 = 1) for nine views, by sampling anisotropic
//    visible normals with a density written here: at most 1 (energy conservation).
#extension GL_GOOGLE_include_directive : require

#include "common/brdf.glsl"
#include "stability_checks.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 1) readonly buffer Alphas {
    float alphaValues[];
};
// Per cell: projected area, max ulps to the tangent-form isotropic D, max relative difference
// to distributionGgx, max relative difference of the visibility; then max albedo, NoV and
// view azimuth of that maximum, alpha pair index.
layout(std430, binding = 2) writeonly buffer Cells {
    vec4 cells[];
};

layout(push_constant) uniform Grid {
    uint alphaCount;
    uint azimuthCount;   // psi midpoints
    uint radialCount;    // ln(tan^2) midpoints per azimuth
    uint sampleCount;    // visible-normal samples per view
};

const uint kCheckIntegrand = 0u;   // D terms of the projected-area quadrature: finite, >= 0
const uint kCheckAlbedo = 1u;      // albedo sample weights: finite, >= 0
const uint kViewCount = 9u;
const float kViewNoV[3] = float[](0.05, 0.5, 1.0);
const float kViewAzimuth[3] = float[](0.0, 0.25 * PI, 0.5 * PI);

shared float partialArea[64];
shared uint partialUlps[64];
shared float partialRelative[64];
shared float partialVisibility[64];
shared float partialAlbedo[kViewCount][64];

float cosFromTanSq(float tanSq) {
    float secant = sqrt(1.0 + tanSq);
    return 1.0 - tanSq / (secant * (secant + 1.0));
}

uint ulpDistance(float a, float b) {
    int ia = floatBitsToInt(a);
    int ib = floatBitsToInt(b);
    return uint(abs(ia - ib));  // both positive floats: integer order is float order
}

float relativeDifference(float a, float b) {
    return abs(a - b) / max(abs(b), 1e-30);
}

// GGX density of the anisotropic visible normals, written independently of brdf.glsl from the
// stretched half vector: D = 1 / (pi aT aB (x^2/aT^2 + y^2/aB^2 + z^2)^2).
float densityD(vec2 alpha, vec3 H) {
    vec3 u = vec3(H.x / alpha.x, H.y / alpha.y, H.z);
    float d = dot(u, u);
    return 1.0 / (PI * alpha.x * alpha.y * d * d);
}

float g1OverNoV(vec2 alpha, vec3 V) {
    float lambdaTerm = length(vec3(alpha.x * V.x, alpha.y * V.y, V.z));
    return 2.0 / (V.z + lambdaTerm);
}

void main() {
    uint cell = gl_WorkGroupID.x;
    uint lane = gl_LocalInvocationID.x;
    float aT = alphaValues[cell / alphaCount];
    float aB = alphaValues[cell % alphaCount];
    bool isotropic = aT == aB;
    float a2 = aT * aB;

    Tally integrandTally = newTally();
    float area = 0.0;
    uint maxUlps = 0u;
    float maxRelative = 0.0;
    float maxVisibility = 0.0;
    const float halfRange = 18.0;
    float radialStep = 2.0 * halfRange / float(radialCount);
    float azimuthStep = 2.0 * PI / float(azimuthCount);
    uint pointCount = azimuthCount * radialCount;
    for (uint k = lane; k < pointCount; k += 64u) {
        float psi = (float(k / radialCount) + 0.5) * azimuthStep;
        float x = -halfRange + (float(k % radialCount) + 0.5) * radialStep;
        float c = cos(psi), s = sin(psi);
        float jacobian = aT * aB / (aT * aT * c * c + aB * aB * s * s);  // dphi / dpsi
        vec2 azimuth = normalize(vec2(aT * c, aB * s));                  // (cos phi, sin phi)
        float alphaSq = 1.0 / (azimuth.x * azimuth.x / (aT * aT) + azimuth.y * azimuth.y / (aB * aB));
        float w = alphaSq * exp(x);  // tan^2 theta
        float NoH = cosFromTanSq(w);
        float sinTheta = sqrt(w) * NoH;
        float ToH = sinTheta * azimuth.x, BoH = sinTheta * azimuth.y;
        float D = distributionGgxAnisotropic(aT, aB, ToH, BoH, NoH);
        // cos sin dtheta = dw / (2 (1 + w)^2), dw = w dx
        float term = D * w / (2.0 * (1.0 + w) * (1.0 + w)) * radialStep * jacobian * azimuthStep;
        tally(integrandTally, term, 0.0, kNoUpperBound, cell * pointCount + k);
        area += term;
        if (isotropic) {
            maxUlps = max(maxUlps, ulpDistance(D, distributionGgxTangent(a2, ToH, BoH, NoH)));
            if (abs(x) < 6.0) {
                maxRelative = max(maxRelative, relativeDifference(D, distributionGgx(a2, NoH)));
            }
        }
    }
    flushTally(kCheckIntegrand, integrandTally);

    // Albedo per view, and the visibility reduction on the same (V, L) pairs.
    Tally albedoTally = newTally();
    vec2 alpha = vec2(aT, aB);
    float albedo[kViewCount];
    for (uint view = 0u; view < kViewCount; ++view) {
        float NoV = kViewNoV[view / 3u];
        float phiV = kViewAzimuth[view % 3u];
        float sinV = sqrt(max(1.0 - NoV * NoV, 0.0));
        vec3 V = vec3(sinV * cos(phiV), sinV * sin(phiV), NoV);
        vec3 Vh = normalize(vec3(aT * V.x, aB * V.y, V.z));
        float lensq = Vh.x * Vh.x + Vh.y * Vh.y;
        vec3 T1 = lensq > 0.0 ? vec3(-Vh.y, Vh.x, 0.0) / sqrt(lensq) : vec3(1.0, 0.0, 0.0);
        vec3 T2 = cross(Vh, T1);
        float sum = 0.0;
        for (uint i = lane; i < sampleCount; i += 64u) {
            float u1 = (float(i) + 0.5) / float(sampleCount);
            float phi = 2.0 * PI * float(bitfieldReverse(i)) * 2.3283064365386963e-10;
            float r = sqrt(u1);
            float t1 = r * cos(phi);
            float t2 = r * sin(phi);
            float h = 0.5 * (1.0 + Vh.z);
            t2 = (1.0 - h) * sqrt(max(1.0 - t1 * t1, 0.0)) + h * t2;
            vec3 Nh = t1 * T1 + t2 * T2 + sqrt(max(1.0 - t1 * t1 - t2 * t2, 0.0)) * Vh;
            float weight = 0.0;
            if (Nh.z > 0.0) {
                vec3 H = normalize(vec3(aT * Nh.x, aB * Nh.y, Nh.z));
                float VoH = dot(V, H);
                vec3 L = 2.0 * VoH * H - V;
                if (L.z > 0.0 && VoH > 0.0) {
                    // pdf(L) = G1(V) D(H) / (4 NoV)
                    float pdf = g1OverNoV(alpha, V) * densityD(alpha, H) * 0.25;
                    float vis = visibilitySmithGgxCorrelatedAnisotropic(aT, aB, V.x, V.y, V.z,
                                                                        L.x, L.y, L.z);
                    weight = distributionGgxAnisotropic(aT, aB, H.x, H.y, H.z) * vis * L.z / pdf;
                    if (isotropic) {
                        maxVisibility = max(maxVisibility,
                                            relativeDifference(
                                                vis, visibilitySmithGgxCorrelated(aT, V.z, L.z)));
                    }
                }
            }
            tally(albedoTally, weight, 0.0, kNoUpperBound, (cell * kViewCount + view) * sampleCount + i);
            sum += weight;
        }
        albedo[view] = sum;
    }
    flushTally(kCheckAlbedo, albedoTally);

    partialArea[lane] = area;
    partialUlps[lane] = maxUlps;
    partialRelative[lane] = maxRelative;
    partialVisibility[lane] = maxVisibility;
    for (uint view = 0u; view < kViewCount; ++view) partialAlbedo[view][lane] = albedo[view];
    barrier();
    for (uint width = 32u; width > 0u; width /= 2u) {
        if (lane < width) {
            partialArea[lane] += partialArea[lane + width];
            partialUlps[lane] = max(partialUlps[lane], partialUlps[lane + width]);
            partialRelative[lane] = max(partialRelative[lane], partialRelative[lane + width]);
            partialVisibility[lane] = max(partialVisibility[lane], partialVisibility[lane + width]);
            for (uint view = 0u; view < kViewCount; ++view) {
                partialAlbedo[view][lane] += partialAlbedo[view][lane + width];
            }
        }
        barrier();
    }
    if (lane == 0u) {
        float maxAlbedo = 0.0;
        uint atView = 0u;
        for (uint view = 0u; view < kViewCount; ++view) {
            float a = partialAlbedo[view][0] / float(sampleCount);
            if (a > maxAlbedo) {
                maxAlbedo = a;
                atView = view;
            }
        }
        cells[2u * cell] = vec4(partialArea[0], float(partialUlps[0]), partialRelative[0],
                                partialVisibility[0]);
        cells[2u * cell + 1u] = vec4(maxAlbedo, kViewNoV[atView / 3u], kViewAzimuth[atView % 3u],
                                     float(cell));
    }
}
