#version 460
#extension GL_GOOGLE_include_directive : require
#include "lighting_bindings.h"
#include "light_loop_bits.h"
// Deferred lighting: reads the G-buffer and adds the lit radiance to the HDR target, which
// holds emissive already. Clustered: each pixel evaluates its cluster's light list (plus the
// directional lights); brute force: every light at every pixel, the reference. With an
// environment, every lit pixel adds its ambient light (image-based lighting) and background
// pixels show the sky.
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/specialization_ids.h"
#include "common/ambient_lighting.glsl"
#include "common/ambient_occlusion.glsl"
#include "common/ibl.glsl"
#include "common/light_buffer.glsl"
#include "common/shading_models.glsl"
#include "common/shadows.glsl"
#include "common/sky_occlusion.glsl"
#include "common/sky_occluded_ambient.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = SPEC_CLUSTERED) const bool kClustered = true;
// Stats variant: counts evaluated and lit light-pixel pairs per workgroup.
layout(constant_id = SPEC_COUNT_LIGHT_PAIRS) const bool kCountLightPairs = false;
// Image-based lighting: none (no sky), split sum (prefiltered cube x LUT, eq. 7), mobile
// (prefiltered cube x Karis 2014's analytic fit) or reference (eq. 6 by Monte Carlo per pixel).
const uint kIblNone = 0u;
const uint kIblSplitSum = 1u;
const uint kIblMobile = 2u;
const uint kIblReference = 3u;
layout(constant_id = SPEC_IBL_MODE) const uint kIblMode = 0u;
// Ambient occlusion of the sky's light: none, GTAO (specular occlusion from the visibility)
// or the ray-marched reference (specular visibility measured too).
layout(constant_id = SPEC_AMBIENT_OCCLUSION) const uint kAoMode = 0u;
// Sky occlusion (common/sky_occlusion.glsl): off folds every call below to visibility 1.
layout(constant_id = SPEC_SKY_OCCLUSION) const bool kSkyOcclusion = false;
// Which kinds of light cast this frame (with kShadowsEnabled): each loop below compiles in
// only the shadow code of a kind that casts.
layout(constant_id = SPEC_DIRECTIONAL_SHADOWS) const bool kDirectionalShadows = true;
layout(constant_id = SPEC_LOCAL_SHADOWS) const bool kLocalShadows = true;
// The local-light loops the frame's lights reach (light_loops.h, one bit per loop); the others
// are left out, as lavapipe runs a loop's body at least once per pixel.
layout(constant_id = SPEC_LIGHT_LOOPS) const uint kLightLoops = LIGHT_LOOPS_ALL;

layout(binding = LIGHTING_BINDING_GBUFFER_BASE_COLOR) uniform sampler2D gbufferBaseColor;
layout(binding = LIGHTING_BINDING_GBUFFER_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = LIGHTING_BINDING_GBUFFER_SPECULAR_MODEL) uniform sampler2D gbufferSpecularModel;
layout(binding = LIGHTING_BINDING_GBUFFER_CUSTOM_DATA) uniform sampler2D gbufferCustomData;
layout(binding = LIGHTING_BINDING_GBUFFER_DEPTH) uniform sampler2D gbufferDepth;
// Read only by variants with anisotropy / clear coat (gbuffer_targets.h has the packing).
layout(binding = LIGHTING_BINDING_GBUFFER_ANISOTROPY) uniform sampler2D gbufferAnisotropy;
layout(binding = LIGHTING_BINDING_GBUFFER_CLEAR_COAT) uniform sampler2D gbufferClearCoat;
layout(binding = LIGHTING_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;
#include "common/lit_inputs.glsl"
// Per workgroup (LightingPass::kCountsPerWorkgroup): evaluated pairs, lit pairs, evaluations
// of plain, area and shadowed lights, shadow filter taps, blocker-search texels, and one spare
// (each fits 32 bits: 64 pixels x 2^26 lights).
const uint kCounts = 8u;
layout(std430, binding = LIGHTING_BINDING_PAIR_COUNTS) buffer PairCounts {
    uint pairCounts[];
};
#include "common/pixel_lights.glsl"

layout(binding = LIGHTING_BINDING_ENVIRONMENT) uniform samplerCube environmentCube;  // all mips
// Reference mode: luminance importance sampling of environmentCube's mip 0
// (render/src/ibl/environment_sampling_table.h).
layout(std430, binding = LIGHTING_BINDING_SAMPLING_TABLE) readonly buffer EnvironmentSampling {
    uint faceSize;
    uint texelCount;
    uint pad0;
    uint pad1;
    vec2 cdfAndProbability[];
} environmentSampling;
layout(binding = LIGHTING_BINDING_AMBIENT_OCCLUSION) uniform sampler2D ambientOcclusion;
layout(binding = LIGHTING_BINDING_SPECULAR_OCCLUSION) uniform sampler2D specularOcclusion;

layout(push_constant) uniform Push {
    ClusterGridParams grid;
    uint directionalCount;
    float skyIntensity;
    float prefilteredMipCount;
    uint referenceSamples;
    float aoIntensity;
    uint aoMultiBounce;  // 0: visibility as measured (tests of visibility itself)
    // Brute force: this dispatch's lights, [lightFirst, lightEnd). The first dispatch also
    // adds the sky's light and the background; the others add their lights to the radiance
    // before them (lighting_pass.cpp).
    uint lightFirst;
    uint lightEnd;
} push;


Surface decodeSurface(ivec2 pixel, out vec3 N) {
    vec4 gb0 = texelFetch(gbufferBaseColor, pixel, 0);
    vec4 gb1 = texelFetch(gbufferNormalRoughMetal, pixel, 0);
    vec4 gb2 = texelFetch(gbufferSpecularModel, pixel, 0);
    Surface s;
    s.baseColor = gb0.rgb;
    s.roughness = gb1.z;
    s.metallic = gb1.w;
    s.specular = gb2.r;
    s.shadingModel = uint(gb2.g * 255.0 + 0.5);
    s.customData = texelFetch(gbufferCustomData, pixel, 0);
    N = octDecode(gb1.xy);
    clearSurfaceExtensions(s);
    if (kAnisotropyEnabled) {
        vec2 anisotropy = texelFetch(gbufferAnisotropy, pixel, 0).rg;
        s.anisotropy = anisotropy.g;
        float angle = anisotropy.r * PI;  // from tangentFrame(N)'s first axis
        mat3 frame = tangentFrame(N);
        s.anisotropyT = frame[0] * cos(angle) + frame[1] * sin(angle);
    }
    if (kClearCoatEnabled) {
        vec4 coat = texelFetch(gbufferClearCoat, pixel, 0);
        s.clearCoat = coat.r;
        s.clearCoatRoughness = coat.g;
        s.clearCoatN = octDecode(coat.ba);
    }
    return s;
}

struct PixelShading {
    Surface surface;
    vec3 P;
    vec3 N;
    vec3 V;
    vec3 R;
    float alpha;
    // Clear coat (kClearCoatEnabled and a coated pixel): its reflection vector and alpha, and
    // the share of light the layers below keep (clearCoatAttenuation).
    vec3 coatR;
    float coatAlpha;
    float coatAttenuation;
    vec3 radiance;
    // kCountLightPairs: this pixel's share of PairCounts, [0, 4) and [4, 8) (vectors, not an
    // array, which lavapipe would keep in memory).
    uvec4 counts0;
    uvec4 counts1;
};

// One light's share of the pixel's radiance. A coated pixel takes each light twice: the base
// layer, then the coat (coatLayer), which sees the light from its own normal and roughness and
// is shadowed as the base is. Two passes rather than two evaluateLight calls, because compilers
// inline evaluateLight once per call site. `body` (a constant of each call site, kLightBody*)
// says which lights the caller passes, so each loop compiles only their code.
const uint kLightBodyAny = 0u;          // any light, shadowed or not (brute force)
const uint kLightBodyDirectional = 1u;  // directional lights, cascades
const uint kLightBodyPlain = 2u;        // points and spots without a size or a map
const uint kLightBodyUnshadowedPunctual = 3u;  // points, spots, spheres, tubes without a map
const uint kLightBodyUnshadowed = 4u;   // local lights without a map: no shadow code
const uint kLightBodyPunctual = 5u;     // points, spots, spheres, tubes, mapped or not
const uint kLightBodyLocal = 6u;        // local lights, shadowed or not
void addLight(inout PixelShading px, uint lightIndex, bool coatLayer, const uint body) {
    Light light = loadLight(lightIndex, camera.frameInfo.w);
    vec3 N = coatLayer ? px.surface.clearCoatN : px.N;
    vec3 R = coatLayer ? px.coatR : px.R;
    float alpha = coatLayer ? px.coatAlpha : px.alpha;
    bool punctual = body == kLightBodyUnshadowedPunctual || body == kLightBodyPunctual;
    LightIncidence incidence = body == kLightBodyDirectional ? evaluateDirectionalLight(light, N)
                               : body == kLightBodyPlain ? evaluatePlainLocalLight(light, px.P, N)
                               : punctual ? evaluatePunctualLight(light, px.P, N, R, alpha)
                                          : evaluateLight(light, px.P, N, R, alpha);
    float visibility = 1.0;
    bool shadowed = body == kLightBodyDirectional ? kDirectionalShadows
                    : body == kLightBodyLocal || body == kLightBodyPunctual ? kLocalShadows
                    : body == kLightBodyAny ? kShadowsEnabled
                                            : false;
    if (shadowed) {
        uint code = body == kLightBodyDirectional ? kShadowCodeDirectional
                    : body == kLightBodyAny       ? kShadowCodeAny
                                                  : kShadowCodeLocal;
        // Out of the light's range or cone nothing is lit whatever the map says: no sampling.
        visibility = any(greaterThan(incidence.incidentIlluminance, vec3(0.0)))
                         ? shadowVisibility(light, lightIndex, px.P, px.N, code)
                         : 1.0;
    }
    incidence.diffuseIlluminance *= visibility;
    incidence.specularIlluminance *= visibility;
    if (coatLayer) {
        incidence.incidentIlluminance *= visibility;
        px.radiance += clearCoatLobe(px.surface, px.V, incidence);
        return;
    }
    // Without a map the subsurface thickness is 0 and its transmittance 1.
    bool transmits = kSubsurfaceEnabled && shadowed &&
                     px.surface.shadingModel == kShadingSubsurface;
    incidence.incidentIlluminance *=
        transmits ? subsurfaceTransmittance(light, lightIndex, px.P) : visibility;
    vec3 base = shadeSurface(px.surface, px.N, px.V, incidence);
    bool coated = kClearCoatEnabled && px.surface.clearCoat > 0.0;
    px.radiance += coated ? base * px.coatAttenuation : base;
    if (kCountLightPairs) {
        px.counts0.x += 1u;
        px.counts0.y += any(greaterThan(incidence.incidentIlluminance, vec3(0.0))) ? 1u : 0u;
        bool area = light.type == LIGHT_TYPE_RECT || light.type == LIGHT_TYPE_DISK ||
                    (light.type != kLightDirectional &&
                     (light.sourceRadius > 0.0 || light.sourceLength > 0.0));
        bool mapped = shadowed && !lightUnshadowed(lightIndex);
        px.counts0.z += !mapped && !area ? 1u : 0u;
        px.counts0.w += !mapped && area ? 1u : 0u;
        px.counts1.x += mapped ? 1u : 0u;
    }
}

// A per-pixel offset for the reference mode's sample set (deterministic: same image each run).
vec2 pixelHash(ivec2 pixel) {
    uvec2 v = uvec2(pixel) * uvec2(1664525u, 1013904223u);
    v.x += v.y * 1664525u;
    v.y += v.x * 1013904223u;
    v ^= v >> 16u;
    return vec2(v & 0xFFFFu) / 65536.0;
}

// Density over solid angle of sampleEnvironment() at direction d: the texel's probability
// spread uniformly over its face area, dw = dA / (1 + u^2 + v^2)^(3/2).
float environmentPdf(vec3 d) {
    vec2 st;
    uint face = cubeFaceOfDirection(d, st);
    uint size = environmentSampling.faceSize;
    uvec2 texel = min(uvec2(st * float(size)), uvec2(size - 1u));
    uint index = (face * size + texel.y) * size + texel.x;
    vec2 uv = st * 2.0 - 1.0;
    float r2 = 1.0 + dot(uv, uv);
    return environmentSampling.cdfAndProbability[index].y * float(size * size) * 0.25 * r2 *
           sqrt(r2);
}

// One step of the search below: move past `step` texels if all their cumulative
// probabilities are <= x.
#define CANDELA_SEARCH_STEP(step)                                                              \
    if (first + (step) <= count &&                                                             \
        environmentSampling.cdfAndProbability[first + (step) - 1u].x <= x)                    \
        first += (step);

// A direction drawn with probability proportional to the texel's radiance x solid angle.
vec3 sampleEnvironment(vec2 xi, out float pdf) {
    // The first texel whose cumulative probability exceeds xi.x, by a fixed 23-step search
    // (tables up to 8M texels). Written without a loop: llvmpipe (lavapipe) stops a shader's
    // loops after 65,535 iterations in total, and a search loop inside the sample loop
    // silently cut the reference mode's sample count by a quarter.
    uint count = environmentSampling.texelCount;
    float x = xi.x;
    uint first = 0u;
    CANDELA_SEARCH_STEP(4194304u) CANDELA_SEARCH_STEP(2097152u) CANDELA_SEARCH_STEP(1048576u)
    CANDELA_SEARCH_STEP(524288u) CANDELA_SEARCH_STEP(262144u) CANDELA_SEARCH_STEP(131072u)
    CANDELA_SEARCH_STEP(65536u) CANDELA_SEARCH_STEP(32768u) CANDELA_SEARCH_STEP(16384u)
    CANDELA_SEARCH_STEP(8192u) CANDELA_SEARCH_STEP(4096u) CANDELA_SEARCH_STEP(2048u)
    CANDELA_SEARCH_STEP(1024u) CANDELA_SEARCH_STEP(512u) CANDELA_SEARCH_STEP(256u)
    CANDELA_SEARCH_STEP(128u) CANDELA_SEARCH_STEP(64u) CANDELA_SEARCH_STEP(32u)
    CANDELA_SEARCH_STEP(16u) CANDELA_SEARCH_STEP(8u) CANDELA_SEARCH_STEP(4u)
    CANDELA_SEARCH_STEP(2u) CANDELA_SEARCH_STEP(1u)
    uint texel = min(first, count - 1u);
    vec2 entry = environmentSampling.cdfAndProbability[texel];
    // Reuse xi.x's position inside the texel's interval as the first coordinate.
    float u = saturate((x - (entry.x - entry.y)) / max(entry.y, 1e-30));
    uint size = environmentSampling.faceSize;
    uint face = texel / (size * size);
    uint inFace = texel % (size * size);
    vec2 st = (vec2(inFace % size, inFace / size) + vec2(u, xi.y)) / float(size);
    vec3 d = cubeFaceDirection(face, st);
    pdf = environmentPdf(d);
    return d;
}

// Eq. 3 from a tangent-space half vector: 1 - NoH^2 = H.x^2 + H.y^2 exactly, where the usual
// form cancels catastrophically in fp32 for narrow lobes (D of a near-mirror is then off by
// orders of magnitude, and so would be the sample weights below).
float stableGgx(float a2, vec3 tangentH) {
    float d = dot(tangentH.xy, tangentH.xy) + a2 * tangentH.z * tangentH.z;
    return a2 / (PI * d * d);
}

// Eq. 6's specular part for one GGX lobe by Monte Carlo: alpha.x along frame[0], alpha.y along
// frame[1], normal frame[2], reflectance F0. As referenceAmbient's specular lobe (visible
// normals and the sky's luminance, balance heuristic), with the anisotropic D, G1 and
// visibility (which are the isotropic ones when alpha.x == alpha.y, up to rounding). For the
// anisotropic lobe and the clear coat, whose approximations it measures. `albedo`: the lobe's
// own directional albedo from its visible-normal samples, F0 = 1 (x) and with F0 (yzw), what
// the multiple-scattering term needs instead of the isotropic LUT's.
vec3 referenceGgxLobe(mat3 frame, vec2 alpha, vec3 F0, vec3 V, ivec2 pixel, out vec4 albedo) {
    vec3 tangentV = transpose(frame) * V;
    tangentV.z = max(tangentV.z, 1e-4);
    float NoV = tangentV.z;
    vec2 offset = pixelHash(pixel + ivec2(3571, 7793));
    vec2 offsetEnvironment = pixelHash(pixel + ivec2(50021, 1299709));
    float g1V = smithG1GgxAnisotropic(alpha, tangentV);
    vec3 specular = vec3(0.0);
    albedo = vec4(0.0);
    uint n = push.referenceSamples;
    for (uint i = 0u; i < n; ++i) {
        vec3 H = importanceSampleGgxVisibleAnisotropic(hammersley(i, n, offset), alpha, tangentV);
        float VoH = dot(tangentV, H);
        vec3 L = 2.0 * VoH * H - tangentV;
        if (L.z > 0.0 && VoH > 0.0) {
            vec3 Lw = frame * L;
            float D = distributionGgxAnisotropic(alpha.x, alpha.y, H.x, H.y, H.z);
            float pdf = D * g1V / (4.0 * NoV);
            float vis = visibilitySmithGgxCorrelatedAnisotropic(alpha.x, alpha.y, tangentV.x,
                                                                tangentV.y, NoV, L.x, L.y, L.z);
            // f NoL / pdf = F G2 / G1(V), G2 = 4 NoV NoL Vis
            float weight = 4.0 * NoV * L.z * vis / g1V;
            albedo += vec4(weight, fresnelSchlickSg(F0, VoH) * weight);
            specular += textureLod(environmentCube, Lw, 0.0).rgb * fresnelSchlickSg(F0, VoH) *
                        (weight * pdf / (pdf + environmentPdf(Lw)));
        }
        float environmentPdfE;
        vec3 E = sampleEnvironment(hammersley(i, n, offsetEnvironment), environmentPdfE);
        if (environmentPdfE <= 0.0) continue;
        vec3 tangentL = transpose(frame) * E;
        if (tangentL.z <= 0.0) continue;
        vec3 He = safeNormalize(tangentV + tangentL);
        float D = distributionGgxAnisotropic(alpha.x, alpha.y, He.x, He.y, He.z);
        float vis = visibilitySmithGgxCorrelatedAnisotropic(
            alpha.x, alpha.y, tangentV.x, tangentV.y, NoV, tangentL.x, tangentL.y, tangentL.z);
        float brdfPdf = D * g1V / (4.0 * NoV);
        specular += textureLod(environmentCube, E, 0.0).rgb *
                    fresnelSchlickSg(F0, saturate(dot(tangentV, He))) *
                    (D * vis * tangentL.z / (brdfPdf + environmentPdfE));
    }
    albedo /= float(n);
    return specular / float(n);
}

// The clear coat's reflection of the sky by Monte Carlo (reference mode), factor included.
vec3 referenceClearCoat(PixelShading px, ivec2 pixel) {
    float alpha = alphaFromRoughness(px.surface.clearCoatRoughness);
    vec4 albedo;
    return px.surface.clearCoat * referenceGgxLobe(tangentFrame(px.surface.clearCoatN),
                                                   vec2(alpha), vec3(kClearCoatF0), px.V, pixel,
                                                   albedo);
}

// Eq. 6 by Monte Carlo per pixel, for measuring the approximations only. Each iteration
// draws one direction from the BRDF (GGX visible normals for the specular lobe, cosine for
// the diffuse and transmitted parts) and one from the environment's luminance, weighted by
// the balance heuristic, so neither glossy lobes nor a sun clipped to a few 65504 cd/m^2
// texels leave fireflies. Same D, Vis and Fresnel as the direct lighting; radiance is read
// from the unfiltered cube.
vec3 referenceAmbient(AmbientTerms t, PixelShading px, ivec2 pixel) {
    mat3 frame = tangentFrame(px.N);
    vec3 tangentV = transpose(frame) * px.V;
    tangentV.z = max(tangentV.z, 1e-4);
    vec2 offset = pixelHash(pixel);
    vec2 offsetEnvironment = pixelHash(pixel + ivec2(7919, 104729));
    float alpha = px.surface.roughness * px.surface.roughness;
    float a2 = alpha * alpha;
    float NoV = tangentV.z;
    bool transmits = any(greaterThan(t.transmittedColor, vec3(0.0)));
    vec3 specular = vec3(0.0), diffuse = vec3(0.0), transmitted = vec3(0.0);
    // An anisotropic pixel's specular lobe is integrated by referenceGgxLobe instead.
    bool isotropic = !(kAnisotropyEnabled && px.surface.anisotropy > 0.0);
    uint n = push.referenceSamples;
    for (uint i = 0u; i < n; ++i) {
        vec2 xi = hammersley(i, n, offset);

        // BRDF sample of the specular lobe; pdf(L) = D(H) G1(V) / (4 NoV).
        vec3 H = importanceSampleGgxVisible(xi, alpha, tangentV);
        float VoH = dot(tangentV, H);
        vec3 L = 2.0 * VoH * H - tangentV;
        if (isotropic && L.z > 0.0 && VoH > 0.0) {
            vec3 Lw = frame * L;
            float misWeight = 1.0;  // a mirror's lobe is a delta: BRDF sampling only
            if (alpha > 0.0) {
                float pdf = stableGgx(a2, H) * smithG1Ggx(alpha, NoV) / (4.0 * NoV);
                misWeight = pdf / (pdf + environmentPdf(Lw));
            }
            specular += textureLod(environmentCube, Lw, 0.0).rgb *
                        fresnelSchlickSg(t.specularColor, VoH) *
                        (visibleNormalSampleWeightShaded(alpha, NoV, L.z) * misWeight);
        }
        // BRDF sample of the diffuse (and transmitted) lobe; pdf = cos / pi.
        vec3 C = frame * cosineSampleHemisphere(xi);
        float cosPdf = max(dot(C, px.N), 0.0) / PI;
        diffuse += textureLod(environmentCube, C, 0.0).rgb * (cosPdf / (cosPdf + environmentPdf(C)));
        if (transmits) {
            transmitted += textureLod(environmentCube, -C, 0.0).rgb *
                           (cosPdf / (cosPdf + environmentPdf(-C)));
        }

        // Environment sample, shared by all lobes.
        float environmentPdfE;
        vec3 E = sampleEnvironment(hammersley(i, n, offsetEnvironment), environmentPdfE);
        if (environmentPdfE <= 0.0) continue;
        vec3 radiance = textureLod(environmentCube, E, 0.0).rgb;
        float NoL = dot(px.N, E);
        if (NoL > 0.0) {
            float lambertPdf = NoL / PI;
            diffuse += radiance * (NoL / PI) / (lambertPdf + environmentPdfE);
            if (isotropic && alpha > 0.0) {
                vec3 He = safeNormalize(px.V + E);
                float VoHe = saturate(dot(px.V, He));
                float D = stableGgx(a2, transpose(frame) * He);
                float brdfPdf = D * smithG1Ggx(alpha, NoV) / (4.0 * NoV);
                specular += radiance * fresnelSchlickSg(t.specularColor, VoHe) *
                            (D * visibilitySmith(alpha, NoV, NoL) * NoL /
                             (brdfPdf + environmentPdfE));
            }
        } else if (transmits && NoL < 0.0) {
            float lambertPdf = -NoL / PI;
            transmitted += radiance * (-NoL / PI) / (lambertPdf + environmentPdfE);
        }
    }
    vec4 anisotropicAlbedo = vec4(0.0);
    if (!isotropic) {
        vec3 T = px.surface.anisotropyT;
        vec2 anisotropicAlpha = anisotropicAlphas(px.surface.roughness, px.surface.anisotropy);
        specular = referenceGgxLobe(mat3(T, cross(px.N, T), px.N), anisotropicAlpha,
                                    t.specularColor, px.V, pixel, anisotropicAlbedo) *
                   float(n);  // divided by n with the rest below
    }
    vec3 ambient = specular + diffuse * t.diffuseColor + transmitted * t.transmittedColor;
    if (kEnergyConserving) {
        // Multiple scattering as the split sum models it (Fdez-Aguera 2019), on the integrated
        // single scattering of the LUT and this pixel's own cosine-weighted sky (diffuse / n).
        vec3 singleScattering = environmentBrdfFromLut(environmentBrdfLut, t.specularColor,
                                                       px.surface.roughness, NoV);
        float directionalAlbedo = px.surface.directionalAlbedo;
        if (!isotropic) {  // the anisotropic lobe's own albedo, not the isotropic LUT's
            singleScattering = anisotropicAlbedo.yzw;
            directionalAlbedo = anisotropicAlbedo.x;
        }
        ambient += multipleScatteringEnvironmentBrdf(singleScattering, t.specularColor,
                                                     directionalAlbedo) *
                   diffuse;
    }
    return ambient / float(n);
}

// The share of the sky the pixel sees past the scene's static geometry (1 without sky
// occlusion).
SkyVisibility pixelSkyVisibility(PixelShading px) {
    if (!kSkyOcclusion) return SkyVisibility(1.0, 1.0, px.N);
    return skyVisibility(px.P, px.N, px.R, px.surface.roughness);
}

// Ambient light of the environment on the pixel's surface (cd/m^2 before sky intensity).
// Without ambient occlusion, before the material's occlusion (the caller applies it).
vec3 ambientRadiance(PixelShading px, ivec2 pixel) {
    vec3 ambient;
    SkyVisibility sky = pixelSkyVisibility(px);
    if (kIblMode == kIblReference) {
        ambient = referenceAmbient(ambientTermsOf(px.surface), px, pixel);
        if (kSkyOcclusion) ambient *= sky.diffuse;
    } else if (kSkyOcclusion) {
        vec4 sh[9] = irradianceSh;
        ambient = skyOccludedEnvironmentAmbient(px.surface, sky, px.N, px.V, sh,
                                                prefilteredCube, push.prefilteredMipCount,
                                                environmentBrdfLut, kIblMode == kIblMobile);
    } else {
        vec4 sh[9] = irradianceSh;
        ambient = environmentAmbient(px.surface, px.N, px.V, sh, prefilteredCube,
                                     push.prefilteredMipCount, environmentBrdfLut,
                                     kIblMode == kIblMobile);
    }
    if (kClearCoatEnabled && px.surface.clearCoat > 0.0) {
        vec3 coat = kIblMode == kIblReference
                        ? referenceClearCoat(px, pixel)
                        : clearCoatAmbient(px.surface, px.V, prefilteredCube,
                                           push.prefilteredMipCount, environmentBrdfLut,
                                           kIblMode == kIblMobile);
        if (kSkyOcclusion) coat *= sky.specular;
        // The mobile path's coat reflects by Karis 2014's mobile fit: it takes what the fit
        // gives it.
        float attenuation = px.coatAttenuation;
        if (kIblMode == kIblMobile) {
            attenuation = clearCoatAttenuation(
                px.surface, envBrdfApproxScaleBias(px.surface.clearCoatRoughness,
                                                   saturate(dot(px.surface.clearCoatN, px.V))));
        }
        ambient = ambient * attenuation + coat;
    }
    return ambient;
}

// With ambient occlusion, combined with the material's `occlusion` (G-buffer alpha).
vec3 occludedAmbientRadiance(PixelShading px, ivec2 pixel, float occlusion) {
    vec4 ao = texelFetch(ambientOcclusion, pixel, 0);
    float visibility = mix(1.0, saturate(ao.w), push.aoIntensity);
    vec3 bentNormal = safeNormalize(ao.xyz);
    bool horizons = kAoMode == kAoReference || kAoMode == kAoGtaoHorizonSpecular;
    float horizonVisibility = horizons ? texelFetch(specularOcclusion, pixel, 0).r : 1.0;
    // Shared with ssr_trace.comp, which takes out exactly this much of the sky's specular.
    float specularVisibility =
        environmentSpecularVisibility(kAoMode, push.aoIntensity, ao.w, horizonVisibility,
                                      saturate(dot(px.N, px.V)), px.surface.roughness, occlusion);
    if (kSkyOcclusion) {
        // Sky occlusion is the large scale, AO the small: both block, so they multiply, and
        // the sky's blocked directions turn AO's bent normal further.
        SkyVisibility sky = pixelSkyVisibility(px);
        visibility *= sky.diffuse;
        specularVisibility *= sky.specular;
        bentNormal = safeNormalize(bentNormal + sky.bentNormal - px.N);
    }
    visibility = min(visibility, occlusion);
    specularVisibility = min(specularVisibility, occlusion);
    AmbientTerms t = ambientTermsOf(px.surface);
    vec3 diffuseVisibility = push.aoMultiBounce != 0u
                                 ? multiBounceOcclusion(visibility, t.diffuseColor)
                                 : vec3(visibility);
    if (kIblMode == kIblReference) {
        return referenceAmbient(t, px, pixel) * diffuseVisibility;
    }
    vec4 sh[9] = irradianceSh;
    return occludedEnvironmentAmbient(px.surface, px.N, bentNormal, px.V, sh, prefilteredCube,
                                      push.prefilteredMipCount, environmentBrdfLut,
                                      kIblMode == kIblMobile, diffuseVisibility,
                                      specularVisibility);
}

// Whether the loop of `body` takes light `index` (light_loops.cpp's lightLoopTakes, which
// decides the loops a frame compiles in).
bool loopTakes(uint index, const uint body) {
    if (body == kLightBodyLocal || body == kLightBodyAny) return true;
    uint type = loadLightType(index, camera.frameInfo.w);
    bool area = type == LIGHT_TYPE_RECT || type == LIGHT_TYPE_DISK;
    if (body == kLightBodyPunctual) return !area;
    if (!lightUnshadowed(index)) return false;
    if (body == kLightBodyPlain) return isPlainLocalLight(loadLight(index, camera.frameInfo.w));
    return body == kLightBodyUnshadowed || !area;
}

// One loop (`loop`, its LIGHT_LOOP_* bit): the pixel's lights from list position k on, while
// its class takes them; returns where it stopped. The last loop compiled in tests nothing: every
// light that reaches it is one it takes (light_loops.h), and the test costs a light's loads. A
// coated pixel takes each light twice (i odd: the coat).
uint addLightRun(inout PixelShading px, PixelLights lights, uint k, uint layers, const uint body,
                 const uint loop) {
    bool lastLoop = (kLightLoops & ~(loop | (loop - 1u))) == 0u;
    uint count = pixelLightCount(lights);
    for (uint i = k * layers; i < count * layers; ++i) {
        uint index = pixelLightIndexAt(lights, i / layers);
        if (!lastLoop && index != kNoLight && !loopTakes(index, body)) break;
        uint light = pixelLightAt(lights, i / layers);
        if (light != kNoLight) addLight(px, light, i % layers == 1u, body);
        k = (i + 1u) / layers;
    }
    return k;
}

void shadePixel(ivec2 pixel, inout PixelShading px) {
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    bool firstDispatch = push.lightFirst == 0u;
    if (depth <= 0.0) {  // background (reverse-Z: 0 is infinitely far)
        if (kIblMode != kIblNone && firstDispatch) {
            vec4 nearPoint = camera.inverseViewProjection * vec4(ndc, 1.0, 1.0);
            vec3 direction = safeNormalize(nearPoint.xyz / nearPoint.w - camera.cameraPosition.xyz);
            vec3 sky = textureLod(environmentCube, direction, 0.0).rgb * push.skyIntensity;
            imageStore(hdrRadiance, pixel, vec4(sky, 1.0));
        }
        return;
    }
    px.surface = decodeSurface(pixel, px.N);
    if (px.surface.shadingModel == kShadingUnlit) return;

    vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
    px.P = world.xyz / world.w;
    px.V = safeNormalize(camera.cameraPosition.xyz - px.P);
    px.R = reflect(-px.V, px.N);
    px.alpha = alphaFromRoughness(px.surface.roughness);
    px.surface.directionalAlbedo = specularDirectionalAlbedo(
        environmentBrdfLut, px.surface.roughness, saturate(dot(px.N, px.V)));
    if (kClearCoatEnabled && px.surface.clearCoat > 0.0) {
        vec3 coatN = px.surface.clearCoatN;
        px.coatR = reflect(-px.V, coatN);
        px.coatAlpha = alphaFromRoughness(px.surface.clearCoatRoughness);
        px.coatAttenuation = clearCoatAttenuation(
            px.surface, environmentBrdfScaleBias(environmentBrdfLut, px.surface.clearCoatRoughness,
                                                 saturate(dot(coatN, px.V))));
    }

    if (kIblMode != kIblNone && firstDispatch) {
        float occlusion = texelFetch(gbufferBaseColor, pixel, 0).a;
        if (kAoMode == kAoOff) {
            px.radiance += ambientRadiance(px, pixel) * (occlusion * push.skyIntensity);
        } else {
            px.radiance += occludedAmbientRadiance(px, pixel, occlusion) * push.skyIntensity;
        }
    }

    PixelLights lights =
        pixelLights(kClustered, push.directionalCount, push.grid, uvec2(pixel), depth);
    if (!kClustered) lights = pixelLightRange(lights, push.lightFirst, push.lightEnd);
    // Lights by class, each loop with only its class's code: lavapipe runs every branch of a
    // loop's body for every light whether or not a lane takes it, and the shadow code (the
    // penumbra search above all) and the area shapes are most of the body. Lists are in light
    // order and the light table groups its slots the same way (runtime/src/light_table.cpp), so
    // each loop sees only its class; each stops at a light it cannot take, and the loops
    // compiled in (light_loops.h) take every light of any list, whatever the order.
    uint layers = kClearCoatEnabled && px.surface.clearCoat > 0.0 ? 2u : 1u;
    uint k = 0u;
    if (kClustered) {
        for (uint i = 0u; i < lights.directionalCount * layers; ++i) {
            addLight(px, pixelLightAt(lights, i / layers), i % layers == 1u, kLightBodyDirectional);
        }
        k = lights.directionalCount;
    }
    if ((kLightLoops & LIGHT_LOOP_PLAIN) != 0u) {
        k = addLightRun(px, lights, k, layers, kLightBodyPlain, LIGHT_LOOP_PLAIN);
    }
    if ((kLightLoops & LIGHT_LOOP_UNSHADOWED_PUNCTUAL) != 0u) {
        k = addLightRun(px, lights, k, layers, kLightBodyUnshadowedPunctual,
                        LIGHT_LOOP_UNSHADOWED_PUNCTUAL);
    }
    if ((kLightLoops & LIGHT_LOOP_UNSHADOWED) != 0u) {
        k = addLightRun(px, lights, k, layers, kLightBodyUnshadowed, LIGHT_LOOP_UNSHADOWED);
    }
    if ((kLightLoops & LIGHT_LOOP_PUNCTUAL) != 0u) {
        k = addLightRun(px, lights, k, layers, kLightBodyPunctual, LIGHT_LOOP_PUNCTUAL);
    }
    if ((kLightLoops & LIGHT_LOOP_ANY) != 0u) {
        addLightRun(px, lights, k, layers, kClustered ? kLightBodyLocal : kLightBodyAny,
                    LIGHT_LOOP_ANY);
    }
    vec4 previous = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(previous.rgb + px.radiance, 1.0));
}

void main() {
    PixelShading px;
    px.radiance = vec3(0.0);
    px.counts0 = uvec4(0u);
    px.counts1 = uvec4(0u);
    shadePixel(ivec2(gl_GlobalInvocationID.xy), px);

    if (kCountLightPairs) {
        px.counts1.y = shadowFilterTapCount;
        px.counts1.z = shadowBlockerTapCount;
        // Added to the workgroup's slots (cleared by lighting_counts_clear): no barrier, which
        // on lavapipe would run the whole shader as coroutines, and no atomic for a zero.
        uint at = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * kCounts;
        for (uint c = 0u; c < 4u; ++c) {
            if (px.counts0[c] != 0u) atomicAdd(pairCounts[at + c], px.counts0[c]);
            if (px.counts1[c] != 0u) atomicAdd(pairCounts[at + 4u + c], px.counts1[c]);
        }
    }
}
