#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/specialization_ids.h"
#include "hair_bindings.h"
// The A-buffer resolve (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair
// Rendering"): walks the pixel's list to find the HAIR_FULLY_SHADED nearest fragments in order
// (ties broken by segment index, so the result never depends on the order the fill pushed them in),
// shades those fully and blends them front to back; the rest, behind them, blend cheaply as one
// layer: their total opacity 1 - prod(1 - a) with their coverage-weighted mean colour lit as the
// fully shaded ones are on average (their radiance over their colour). Sums and products commute,
// so shuffling the strands changes nothing but rounding. Output straight alpha, blended "over" the
// lit frame.
//
// Shading: Kajiya-Kay with TressFX's two highlights. Diffuse K_d sin(t, l) / pi with t the
// strand's tangent; specular from tangents tilted toward the normal by the style's shifts,
// sin(t', h)^p with its normalisation (p + 2) / (2 pi): the primary coloured by the light only,
// the secondary by the light and the hair. Lit by the clustered lights (with their shadows)
// and the sky's irradiance.
//
// Self-shadowing (Martin et al. 2014: "approximated from a shadow map of the hair's depth, where
// the depth range is the distance of the shaded fragment from the map's depth"; the formula is
// TressFX's): a fragment a depth range Δd behind the first hair in the light's hair
// depth map (hair_shadow.vert) has about n = Δd / (HAIR_FIBRE_SPACING x r) fibres in front of it, r
// its strand's radius, each letting 1 - α through (α = HAIR_SHADOW_OPACITY), so its direct
// light is scaled by (1 - α)^n = exp(-k · density · Δd) with k = -ln(1 - α) and density = 1 /
// (HAIR_FIBRE_SPACING x r) fibres per metre. The reference counts the fibres between the
// fragment and the light exactly instead (every segment the ray to the light passes within
// its radius). Only lights with a shadow map have a hair depth map.
//
// The fog's froxels and the atmosphere's air in front of the hair dim it and add their
// in-scattering (common/froxel_lookup.glsl, as blended surfaces and wires get them), taken at
// the nearest fragment's depth: a pixel's strands lie millimetres to centimetres apart, far less
// than a froxel, so one lookup serves them all.
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/ibl.glsl"
#include "common/light_buffer.glsl"
#include "common/shading_models.glsl"
#include "common/shadows.glsl"
#define FROXEL_INTEGRATED_BINDING HAIR_BINDING_FROXEL_INTEGRATED
#include "common/froxel_lookup.glsl"
#include "hair_segment.glsl"

layout(constant_id = SPEC_CLUSTERED) const bool kClustered = true;
// Image-based lighting: 0 none, else the sky's SH irradiance lights the hair's diffuse.
layout(constant_id = SPEC_IBL_MODE) const uint kIblMode = 0u;

#include "common/lit_inputs.glsl"

layout(binding = HAIR_BINDING_HAIR_SHADOW) uniform sampler2D hairShadowDepth;

layout(location = 0) out vec4 outRadiance;  // cd/m^2, a = the hair's opacity here

const uint kListOverflow = 0xffffffffu;
// The fibre's reflectance at its surface (a dielectric of index ~1.55: keratin).
const float kHairF0 = 0.046;

struct HairPoint {
    vec3 P;
    vec3 T;  // unit tangent, root to tip
    vec3 V;
    vec3 N;  // the normal facing the camera (V without its part along T)
    vec3 color;
    vec4 highlights;
    float radius;  // the strand's radius here (metres)
    vec3 axis;     // the point of the strand's centre line nearest P
};

// sin(t, h)^p with its normalisation: Kajiya-Kay's lobe about the tilted tangent t.
float kajiyaKayLobe(vec3 T, vec3 H, float exponent) {
    const float c = dot(T, H);
    const float s = sqrt(max(1.0 - c * c, 0.0));
    return (exponent + 2.0) / (2.0 * PI) * pow(s, exponent);
}

// Fibres of other strands (segments) that the ray from P toward the light (unit L, up to tMax)
// passes within their radius, beyond tMin: the self-shadow reference.
float fibresCrossed(vec3 P, vec3 L, float tMin, float tMax) {
    float count = 0.0;
    for (uint i = 0u; i < draw.segmentCount; ++i) {
        const HairSegment s = hairSegment(i);
        const vec3 d = s.end.xyz - s.start.xyz;
        const vec3 w = P - s.start.xyz;
        const float b = dot(L, d), c = dot(d, d), e = dot(d, w);
        const float denominator = c - b * b;  // |L| = 1
        const float u = denominator > 1e-12 ? clamp((e - b * dot(L, w)) / denominator, 0.0, 1.0)
                                            : 0.0;
        const vec3 Q = s.start.xyz + u * d;
        const float t = dot(Q - P, L);
        if (t <= tMin || t >= tMax) continue;
        const float radius = mix(s.start.w, s.end.w, u);
        const vec3 off = Q - (P + t * L);
        if (dot(off, off) < radius * radius) count += 1.0;
    }
    return count;
}

// The share of the light's direct light left after the hair between P and the light (1 with
// self-shadowing off or where the light has no shadow map).
float hairSelfShadow(Light light, uint index, HairPoint h) {
    if (!kShadowsEnabled || draw.selfShadow == HAIR_SELF_SHADOW_OFF) return 1.0;
    // From the strand's centre line: the fragment lies on a camera-facing quad up to 0.71 px
    // beyond the strand's edge, which seen from the light may be behind the strand itself.
    ShadowView v;
    if (!shadowViewAt(light, index, h.axis, v)) return 1.0;
    const vec4 clip = v.worldToClip * vec4(h.axis, 1.0);
    vec2 uv;
    if (!shadowMapUv(clip, uv)) return 1.0;
    const bool directional = light.type == kLightDirectional;
    const float receiver = shadowViewDepth(v, clip);
    const vec3 toLight = directional ? -light.direction : light.position - h.axis;
    const vec3 L = safeNormalize(toLight);
    // The strand's own depth spread over a texel of the map (its slope toward the light, as
    // the opaque maps' slope bias), and its own thickness, are not hair in front of it.
    const float cosTL = abs(dot(h.T, L));
    const float slope = min(cosTL / max(sqrt(1.0 - cosTL * cosTL), 1e-3), kShadowMaxSlope);
    const float bias = shadowTexelWorld(v, max(receiver, 1e-4)) * (1.0 + 2.0 * slope) +
                       2.0 * h.radius;
    float fibres;
    if (draw.selfShadow == HAIR_SELF_SHADOW_REFERENCE) {
        fibres = fibresCrossed(h.axis, L, bias, directional ? 1e30 : length(toLight));
    } else {
        const ivec2 texel = ivec2(floor(v.tile.xy + uv * v.tile.z));
        const float first = shadowLinearDepth(v, texelFetch(hairShadowDepth, texel, 0).r);
        const float depthRange = max(receiver - first - bias, 0.0);
        fibres = depthRange / (HAIR_FIBRE_SPACING * max(h.radius, 1e-6));
    }
    return exp(log(1.0 - HAIR_SHADOW_OPACITY) * fibres);
}

vec3 hairLightRadiance(HairPoint h, uint index) {
    Light light = loadLight(index, camera.frameInfo.w);
    LightIncidence incidence = evaluateLight(light, h.P, h.N, reflect(-h.V, h.N), 0.3);
    if (!any(greaterThan(incidence.incidentIlluminance, vec3(0.0)))) return vec3(0.0);
    const vec3 E = incidence.incidentIlluminance * shadowVisibility(light, index, h.P, h.N) *
                   hairSelfShadow(light, index, h);
    const vec3 L = incidence.diffuseL;
    const float TL = dot(h.T, L);
    const float sinTL = sqrt(max(1.0 - TL * TL, 0.0));
    const vec3 H = safeNormalize(L + h.V);
    const vec3 primaryT = safeNormalize(h.T + h.highlights.x * h.N);
    const vec3 secondaryT = safeNormalize(h.T + h.highlights.y * h.N);
    const vec3 diffuse = h.color * (sinTL / PI);
    const vec3 primary = vec3(kHairF0 * kajiyaKayLobe(primaryT, H, h.highlights.z));
    const vec3 secondary = h.color * (kHairF0 * kajiyaKayLobe(secondaryT, H, h.highlights.w));
    return E * (diffuse + primary + secondary);
}

vec3 shadeHair(float depth, uint segment) {
    const HairSegment s = hairSegment(segment);
    if (draw.mode == HAIR_MODE_COVERAGE) return vec3(1.0);
    HairPoint h;
    const vec2 ndc = gl_FragCoord.xy / draw.targetSize * 2.0 - 1.0;
    const vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
    h.P = world.xyz / world.w;
    h.V = safeNormalize(camera.cameraPosition.xyz - h.P);
    h.T = safeNormalize(s.end.xyz - s.start.xyz);
    h.N = safeNormalize(h.V - h.T * dot(h.V, h.T));
    if (dot(h.N, h.N) < 0.5) h.N = h.V;  // looking along the strand
    h.color = s.color.rgb;
    h.highlights = s.highlights;
    h.radius = 0.5 * (s.start.w + s.end.w);
    const vec3 d = s.end.xyz - s.start.xyz;
    h.axis = s.start.xyz + d * clamp(dot(h.P - s.start.xyz, d) / max(dot(d, d), 1e-12), 0.0, 1.0);
    vec3 radiance = vec3(0.0);
    if (kIblMode != 0u) {
        vec4 sh[9] = irradianceSh;
        radiance += h.color * (1.0 / PI) * shIrradiance(sh, h.N) * draw.skyIntensity;
    }
    if (kClustered) {
        for (uint i = 0u; i < draw.directionalCount; ++i)
            radiance += hairLightRadiance(h, lightIndices[i]);
        const uint cluster =
            clusterOfPixel(draw.grid, uvec2(gl_FragCoord.xy), depth,
                           uintBitsToFloat(depthRange[2]), uintBitsToFloat(depthRange[3]));
        const uint first = clusterRanges[2u * cluster];
        const uint count = clusterRanges[2u * cluster + 1u];
        if (count == kListOverflow) {
            for (uint i = 0u; i < camera.frameInfo.z; ++i) {
                if (!lightInEveryCluster(uint(lightData[3u * camera.frameInfo.w + i].w)))
                    radiance += hairLightRadiance(h, i);
            }
        } else {
            const uint quarterBit = quarterBitOfPixel(draw.grid, uvec2(gl_FragCoord.xy));
            for (uint i = 0u; i < count; ++i) {
                const uint light = lightOfEntry(lightIndices[first + i], quarterBit);
                if (light != kNoLight) radiance += hairLightRadiance(h, light);
            }
        }
    } else {
        for (uint i = 0u; i < camera.frameInfo.z; ++i)
            radiance += hairLightRadiance(h, i);
    }
    return radiance;
}

// Whether fragment (depth a, segment sa) is in front of (b, sb): reverse-Z, ties by segment.
bool nearer(float a, uint sa, float b, uint sb) {
    return a > b || (a == b && sa < sb);
}

// Whether fragment (depth b, segment sb) is behind (a, sa): the order's other side.
bool farther(float b, uint sb, float a, uint sa) {
    return nearer(a, sa, b, sb);
}

void main() {
    const uint head = heads[pixelIndex(gl_FragCoord.xy)];
    if (head == HAIR_LIST_END) discard;
    // The HAIR_FULLY_SHADED nearest by selection: walk k finds the nearest fragment behind the
    // one walk k - 1 found. (Depth, segment) orders the fragments strictly (a segment's quad
    // covers a pixel once), so the choice never depends on the list's order. (An insertion
    // sort into local arrays, evicting into the rest, gave order-dependent results on
    // lavapipe.)
    float depth[HAIR_FULLY_SHADED];
    uint segment[HAIR_FULLY_SHADED];
    float coverage[HAIR_FULLY_SHADED];
    uint kept = 0u;
    float previousDepth = 2.0;  // nearer than any fragment (reverse-Z depths are <= 1)
    uint previousSegment = 0u;
    for (uint k = 0u; k < HAIR_FULLY_SHADED; ++k) {
        bool found = false;
        float bestDepth = 0.0;
        uint bestSegment = 0u;
        float bestCoverage = 0.0;
        uint node = head;
        for (uint walked = 0u; node != HAIR_LIST_END && walked < HAIR_MAX_WALK; ++walked) {
            const uvec4 n = nodes[node];
            node = n.w;
            const float d = uintBitsToFloat(n.x);
            if (farther(d, n.y, previousDepth, previousSegment) &&
                (!found || nearer(d, n.y, bestDepth, bestSegment))) {
                found = true;
                bestDepth = d;
                bestSegment = n.y;
                bestCoverage = uintBitsToFloat(n.z);
            }
        }
        if (!found) break;
        depth[k] = bestDepth;
        segment[k] = bestSegment;
        coverage[k] = bestCoverage;
        kept = k + 1u;
        previousDepth = bestDepth;
        previousSegment = bestSegment;
    }
    // The rest (behind the last kept one): their transmittance, coverage-weighted colour sum
    // and coverage sum, all order-independent.
    float tailTransmittance = 1.0;
    vec3 tailColor = vec3(0.0);
    float tailWeight = 0.0;
    if (kept == HAIR_FULLY_SHADED) {
        uint node = head;
        for (uint walked = 0u; node != HAIR_LIST_END && walked < HAIR_MAX_WALK; ++walked) {
            const uvec4 n = nodes[node];
            node = n.w;
            if (!farther(uintBitsToFloat(n.x), n.y, previousDepth, previousSegment)) continue;
            const float a = uintBitsToFloat(n.z);
            tailTransmittance *= 1.0 - a;
            tailColor +=
                a * (draw.mode == HAIR_MODE_COVERAGE ? vec3(1.0) : hairSegment(n.y).color.rgb);
            tailWeight += a;
        }
    }
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0;
    vec3 litSum = vec3(0.0);    // sum of a x shaded radiance of the kept fragments
    vec3 colorSum = vec3(0.0);  // sum of a x colour of the kept fragments
    for (uint i = 0u; i < kept; ++i) {
        const vec3 shaded = shadeHair(depth[i], segment[i]);
        radiance += transmittance * coverage[i] * shaded;
        transmittance *= 1.0 - coverage[i];
        litSum += coverage[i] * shaded;
        colorSum += coverage[i] * (draw.mode == HAIR_MODE_COVERAGE
                                       ? vec3(1.0)
                                       : hairSegment(segment[i]).color.rgb);
    }
    if (tailWeight > 0.0) {
        // Lit per unit of colour as the kept fragments are on average.
        const vec3 lighting = litSum / max(colorSum, vec3(1e-6));
        const vec3 tailRadiance = tailColor / tailWeight * lighting;
        radiance += transmittance * (1.0 - tailTransmittance) * tailRadiance;
        transmittance *= tailTransmittance;
    }
    const float alpha = 1.0 - transmittance;
    if (!(alpha > 0.0)) discard;
    const vec3 hair = radiance / alpha;
    outRadiance = vec4(draw.mode == HAIR_MODE_COVERAGE
                           ? hair
                           : throughMediumAndAir(hair, vec4(gl_FragCoord.xy, depth[0], 1.0)),
                       alpha);
}
