// Image-based lighting math of Karis 2013, "Real Shading in Unreal Engine 4", "Image-Based
// Lighting" (eq. 6-8) and Karis 2014, "Physically Based Shading on Mobile", shared by the
// precompute shaders (prefiltered cube, SH irradiance, environment BRDF LUT), the lighting pass
// (split-sum, mobile and reference modes) and the tests.
#ifndef CANDELA_IBL_GLSL
#define CANDELA_IBL_GLSL

#include "common/brdf.glsl"

// --- Sampling -------------------------------------------------------------------------------

float radicalInverseVdC(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10;
}

// Point i of an n-point Hammersley set, shifted by `offset` (Cranley-Patterson rotation) so
// neighbouring pixels of the reference mode see decorrelated sets.
vec2 hammersley(uint i, uint n, vec2 offset) {
    return fract(vec2((float(i) + 0.5) / float(n), radicalInverseVdC(i)) + offset);
}

// GGX half vector around +Z with pdf(H) = D(H) NoH; alpha = roughness^2 (alpha 0: H = +Z).
vec3 importanceSampleGgx(vec2 xi, float alpha) {
    float a2 = alpha * alpha;
    float phi = 2.0 * PI * xi.x;
    float cosTheta = sqrt((1.0 - xi.y) / max(1.0 + (a2 - 1.0) * xi.y, 1e-20));
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Cosine-weighted direction around +Z, pdf = NoL / pi.
vec3 cosineSampleHemisphere(vec2 xi) {
    float r = sqrt(xi.x);
    float phi = 2.0 * PI * xi.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - xi.x, 0.0)));
}

// World direction through (s, t) in [0, 1]^2 of Vulkan cube face `face` (+X,-X,+Y,-Y,+Z,-Z;
// t = 0 is the top row). The inverse of the spec's face selection, as content's
// cubeFaceDirection(), so CPU and GPU agree on every texel.
vec3 cubeFaceDirection(uint face, vec2 st) {
    vec2 uv = st * 2.0 - 1.0;
    vec3 d;
    if (face == 0u) d = vec3(1.0, -uv.y, -uv.x);
    else if (face == 1u) d = vec3(-1.0, -uv.y, uv.x);
    else if (face == 2u) d = vec3(uv.x, 1.0, uv.y);
    else if (face == 3u) d = vec3(uv.x, -1.0, -uv.y);
    else if (face == 4u) d = vec3(uv.x, -uv.y, 1.0);
    else d = vec3(-uv.x, -uv.y, -1.0);
    return normalize(d);
}

// Inverse of cubeFaceDirection (the Vulkan spec's face selection): face and (s, t) in [0, 1]^2.
uint cubeFaceOfDirection(vec3 d, out vec2 st) {
    vec3 a = abs(d);
    uint face;
    vec2 sc;
    float major;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x > 0.0 ? 0u : 1u;
        sc = vec2(d.x > 0.0 ? -d.z : d.z, -d.y);
        major = a.x;
    } else if (a.y >= a.z) {
        face = d.y > 0.0 ? 2u : 3u;
        sc = vec2(d.x, d.y > 0.0 ? d.z : -d.z);
        major = a.y;
    } else {
        face = d.z > 0.0 ? 4u : 5u;
        sc = vec2(d.z > 0.0 ? d.x : -d.x, -d.y);
        major = a.z;
    }
    st = clamp(0.5 * (sc / max(major, 1e-30) + 1.0), 0.0, 1.0);
    return face;
}

// Solid angle of a cube texel of a face with `size` texels per side, at face point uv in
// [-1, 1]^2: dA / (1 + u^2 + v^2)^(3/2) with dA = (2 / size)^2.
float cubeTexelSolidAngle(vec2 uv, float size) {
    float r2 = 1.0 + dot(uv, uv);
    return (4.0 / (size * size)) / (r2 * sqrt(r2));
}

// --- Environment BRDF (eq. 8) -------------------------------------------------------------

// Smith G1 for GGX, exact (the masking the visible-normal distribution is built on).
float smithG1Ggx(float alpha, float NoX) {
    float a2 = alpha * alpha;
    return 2.0 * NoX / (NoX + sqrt(a2 + (1.0 - a2) * NoX * NoX));
}

// Schlick-Smith G1 with k = alpha / 2 (eq. 4): G = G1(V) G1(L).
float smithG1Schlick(float alpha, float NoX) {
    float k = alpha * 0.5;
    return NoX / (NoX * (1.0 - k) + k);
}

// A GGX normal visible from V (tangent space, N = +Z), sampled with pdf
// D(H) G1(V) max(VoH, 0) / NoV (Heitz 2018). Against plain D NoH sampling, the estimator of
// the specular integral becomes F G(V, L) / G1(V): bounded and continuous at the horizon, so
// grazing views converge with a few hundred samples instead of tens of thousands.
// Anisotropic: alpha.x along +X, alpha.y along +Y.
vec3 importanceSampleGgxVisibleAnisotropic(vec2 xi, vec2 alpha, vec3 V) {
    vec3 Vh = normalize(vec3(alpha.x * V.x, alpha.y * V.y, V.z));
    float lengthSquared = Vh.x * Vh.x + Vh.y * Vh.y;
    vec3 T1 = lengthSquared > 0.0 ? vec3(-Vh.y, Vh.x, 0.0) * inversesqrt(lengthSquared)
                                  : vec3(1.0, 0.0, 0.0);
    vec3 T2 = cross(Vh, T1);
    float r = sqrt(xi.x);
    float phi = 2.0 * PI * xi.y;
    float t1 = r * cos(phi);
    float s = 0.5 * (1.0 + Vh.z);
    float t2 = mix(sqrt(max(1.0 - t1 * t1, 0.0)), r * sin(phi), s);
    vec3 Nh = t1 * T1 + t2 * T2 + sqrt(max(1.0 - t1 * t1 - t2 * t2, 0.0)) * Vh;
    return safeNormalize(vec3(alpha.x * Nh.x, alpha.y * Nh.y, max(Nh.z, 1e-7)));
}

vec3 importanceSampleGgxVisible(vec2 xi, float alpha, vec3 V) {
    return importanceSampleGgxVisibleAnisotropic(xi, vec2(alpha), V);
}

// Exact Smith G1 of the anisotropic GGX for a direction in the lobe's frame.
float smithG1GgxAnisotropic(vec2 alpha, vec3 X) {
    return 2.0 * X.z / (X.z + length(vec3(alpha.x * X.x, alpha.y * X.y, X.z)));
}

// Weight of one visible-normal sample in the specular integral, without F:
// f NoL / pdf(L) = F G(V, L) / G1exact(V) for eq. 2 with eq. 3 and eq. 4.
float visibleNormalSampleWeight(float alpha, float NoV, float NoL) {
    return smithG1Schlick(alpha, NoV) * smithG1Schlick(alpha, NoL) / smithG1Ggx(alpha, NoV);
}

// The same weight with exact height-correlated Smith, G2 = 4 NoL NoV Vis: the energy-
// conserving BRDF's visibility.
float visibleNormalSampleWeightCorrelated(float alpha, float NoV, float NoL) {
    return 4.0 * NoL * NoV * visibilitySmithGgxCorrelated(alpha, NoV, NoL) /
           smithG1Ggx(alpha, NoV);
}

// The weight for the visibility term the variant shades with (visibilitySmith).
float visibleNormalSampleWeightShaded(float alpha, float NoV, float NoL) {
    if (kEnergyConserving) return visibleNormalSampleWeightCorrelated(alpha, NoV, NoL);
    return visibleNormalSampleWeight(alpha, NoV, NoL);
}

// The sample loop of eq. 8 both LUT pairs share: (scale, bias) of F0 by sampling visible
// normals, with Schlick-Smith (eq. 4) or, `heightCorrelated`, exact height-correlated Smith in
// the weight.
vec2 integrateVisibleNormals(float alpha, float NoV, uint sampleCount, bool heightCorrelated) {
    vec3 V = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    vec2 ab = vec2(0.0);
    for (uint i = 0u; i < sampleCount; ++i) {
        vec3 H = importanceSampleGgxVisible(hammersley(i, sampleCount, vec2(0.0)), alpha, V);
        float VoH = dot(V, H);
        float NoL = 2.0 * VoH * H.z - V.z;
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        float weight = heightCorrelated ? visibleNormalSampleWeightCorrelated(alpha, NoV, NoL)
                                        : visibleNormalSampleWeight(alpha, NoV, NoL);
        // VoH rounds to just over 1 at some texels, and pow() of a negative base is NaN (one
        // texel of the height-correlated pair came out 0 before the clamp).
        float fc = pow(max(1.0 - VoH, 0.0), 5.0);
        ab += vec2(1.0 - fc, fc) * weight;
    }
    return ab / float(sampleCount);
}

// (scale, bias) of F0 in the integral of the specular BRDF over a white environment (eq. 8):
// the same D, Vis (eq. 4) and pow5 Fresnel split, by sampling visible normals. The LUT
// stores this over (NoV, roughness).
vec2 integrateEnvironmentBrdf(float roughness, float NoV, uint sampleCount) {
    return integrateVisibleNormals(roughness * roughness, max(NoV, 1e-4), sampleCount, false);
}

// integrateEnvironmentBrdf with exact height-correlated Smith visibility: the LUT's second
// pair, for the energy-conserving BRDF. NoV down to 1e-7: near-mirrors' albedo still rises
// between NoV = 1e-4 and 0 (to ~1: only facets facing a grazing view are visible, and they
// reflect upward), and compensating by the value at 1e-4 gave them up to 1.8% more than the
// light at NoV = 0. alpha floored at kMinRoughness^2 as for analytic lights, whose lobe this
// E_ss compensates (below it fp32 visible-normal sampling at grazing views falls apart; the
// albedo there is 1 within 1e-3 either way).
vec2 integrateEnvironmentBrdfCorrelated(float roughness, float NoV, uint sampleCount) {
    return integrateVisibleNormals(alphaFromRoughness(roughness), max(NoV, 1e-7), sampleCount,
                                   true);
}

// The LUT's height-correlated pair (.ba) is laid out on its own grid: texel (x, y) holds
// NoV = (x / (n - 1))^2 and roughness = y / (n - 1), so the first and last texels sit on
// NoV = 0 and 1 and roughness 0 and 1, and sqrt spacing resolves the steep grazing end. At
// texel centres NoV = (x + 0.5) / n (the .rg pair's grid) the directional albedo at
// NoV < 0.004 was extrapolated flat, and compensating by it gave 2% to 11% more than the
// light at grazing angles (tests/render/stability WhiteFurnace).
vec2 correlatedLutTexelParameters(uvec2 texel, uint size) {
    float u = float(texel.x) / float(size - 1u);
    return vec2(u * u, float(texel.y) / float(size - 1u));  // (NoV, roughness)
}

vec2 correlatedLutCoordinates(float roughness, float NoV, vec2 size) {
    vec2 grid = vec2(sqrt(saturate(NoV)), saturate(roughness));
    return (grid * (size - 1.0) + 0.5) / size;
}

// The LUT's (scale, bias) for the variant's visibility term: .rg Schlick-Smith (eq. 4),
// .ba height-correlated Smith.
vec2 environmentBrdfScaleBias(sampler2D lut, float roughness, float NoV) {
    if (kEnergyConserving) {
        vec2 uv = correlatedLutCoordinates(roughness, NoV, vec2(textureSize(lut, 0)));
        return textureLod(lut, uv, 0.0).ba;
    }
    return textureLod(lut, vec2(NoV, roughness), 0.0).rg;
}

// Split-sum specular reflectance (eq. 7's second factor) from the LUT, with the 2% rule of
// eq. 5 on the bias as the direct lighting has it.
vec3 environmentBrdfFromLut(sampler2D lut, vec3 specularColor, float roughness, float NoV) {
    vec2 ab = environmentBrdfScaleBias(lut, roughness, NoV);
    return specularColor * ab.x + saturate(50.0 * specularColor.g) * ab.y;
}

// E_ss: directional albedo of the single-scattering specular lobe for F0 = 1 at (NoV,
// roughness), what multipleScatteringCompensation needs for analytic lights: the LUT's
// height-correlated scale + bias, one read per pixel (not per light), on the mobile path too:
// Karis 2014's fit as E_ss is up to 26% low at NoV = 1 and 2.2x low at grazing angles for this
// lobe, and compensating by it made surfaces reflect up to 2.2x the light (tests/render/
// stability WhiteFurnace). 1 (no compensation) for the UE4 BRDF.
float specularDirectionalAlbedo(sampler2D lut, float roughness, float NoV) {
    if (!kEnergyConserving) return 1.0;
    vec2 ab = environmentBrdfScaleBias(lut, roughness, NoV);
    return ab.x + ab.y;
}

// The mobile path's analytic equivalent for image-based light: Karis 2014's fit of (scale,
// bias) summed, the E_ss of the fit's own single scattering, so the fit's F_ss E_ss plus the
// multiple scattering built on it reflect exactly 1 for a white metal in a white furnace.
float envBrdfApproxDirectionalAlbedo(float roughness, float NoV) {
    vec2 ab = envBrdfApproxScaleBias(roughness, NoV);
    return ab.x + ab.y;
}

// Fdez-Aguera 2019: what an environment adds through multiple scattering, per unit of the
// cosine-weighted mean radiance (irradiance / pi). singleScattering: the split sum's
// F_ss E_ss (F0 A + B); E_ss: its white value (A + B). The 1 - E_ss the first bounce misses
// leaves tinted by the average Fresnel F_avg at each further bounce (a geometric series), and
// leaves nearly diffusely, hence the irradiance rather than the prefiltered lobe. A white
// metal gets E_ss + (1 - E_ss) = 1 in a uniform sky.
vec3 multipleScatteringEnvironmentBrdf(vec3 singleScattering, vec3 specularColor,
                                       float directionalAlbedo) {
    float Ems = 1.0 - saturate(directionalAlbedo);
    vec3 Favg = specularColor + (1.0 - specularColor) * (1.0 / 21.0);
    vec3 Fms = singleScattering * Favg / (1.0 - Ems * Favg);
    return Fms * Ems;
}

// Karis 2014's mobile path: the analytic fit, and its cheaper non-metal form when the material
// is the default non-metal (Specular 0.5, Metallic 0: F0 = 0.04).
vec3 environmentBrdfMobile(vec3 specularColor, float roughness, float NoV, bool defaultNonmetal) {
    if (defaultNonmetal) return vec3(envBrdfApproxNonmetal(roughness, NoV));
    return envBrdfApprox(specularColor, roughness, NoV);
}

// --- Prefiltered radiance (eq. 7's first factor) --------------------------------------------

// The prefiltered cube keeps one roughness per mip, linearly: mip m holds
// roughness m / (mipCount - 1).
float prefilteredMipOfRoughness(float roughness, float mipCount) {
    return saturate(roughness) * (mipCount - 1.0);
}

// --- Anisotropic image-based light ------------------------------------------------------------

// The prefiltered cube and the LUT are isotropic; an anisotropic lobe is approximated by
// bending the normal before reflecting (the "bent reflection vector" of Revie 2011 and
// McAuley 2015). The lobe is stretched along T (alphaT > alphaB): its mirror directions fan
// out in the plane of T and N. Bending N toward the normal, within that plane, that faces V
// most (V without its component along B) moves R the way the stretched highlight moves on a
// brushed surface. The bend grows with the lobe's eccentricity (alphaT - alphaB) /
// (alphaT + alphaB): 0 for an isotropic lobe, 1 for a line. The cube and the LUT are then read
// at the lobe's mean roughness, sqrt((alphaT + alphaB) / 2) (anisotropicAmbientRoughness).
vec3 anisotropicReflection(vec3 N, vec3 V, vec3 T, vec2 alpha) {
    vec3 B = cross(N, T);
    vec3 facing = V - B * dot(V, B);  // in the plane of T and N
    if (dot(facing, facing) < 1e-12) return reflect(-V, N);
    float bend = (alpha.x - alpha.y) / max(alpha.x + alpha.y, 1e-7);
    vec3 bentN = safeNormalize(mix(N, normalize(facing), saturate(bend)));
    return reflect(-V, bentN);
}

float anisotropicAmbientRoughness(vec2 alpha) {
    return sqrt(0.5 * (alpha.x + alpha.y));
}

// --- Diffuse irradiance: order-2 spherical harmonics ----------------------------------------

// Real SH basis Y_lm for l <= 2 at unit direction n.
void shBasis9(vec3 n, out float y[9]) {
    y[0] = 0.282095;
    y[1] = 0.488603 * n.y;
    y[2] = 0.488603 * n.z;
    y[3] = 0.488603 * n.x;
    y[4] = 1.092548 * n.x * n.y;
    y[5] = 1.092548 * n.y * n.z;
    y[6] = 0.315392 * (3.0 * n.z * n.z - 1.0);
    y[7] = 1.092548 * n.x * n.z;
    y[8] = 0.546274 * (n.x * n.x - n.y * n.y);
}

// Irradiance E(n) from coefficients already convolved with the clamped cosine
// (A0 = pi, A1 = 2 pi / 3, A2 = pi / 4, folded in by the projection pass).
vec3 shIrradiance(vec4 coefficients[9], vec3 n) {
    float y[9];
    shBasis9(n, y);
    vec3 e = vec3(0.0);
    for (int i = 0; i < 9; ++i) e += coefficients[i].rgb * y[i];
    return max(e, vec3(0.0));  // order 2 rings slightly negative behind bright suns
}

#endif
