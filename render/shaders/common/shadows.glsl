// Shadow sampling shared by the deferred lighting pass and the forward (blended) pass
// (render/README.md "Shadows"). Every shadow map is a tile of one depth atlas; a light finds
// its tiles through its entry in the per-light table, indexed like the light buffer, so
// clustered and brute-force lighting read the same maps. The including shader defines
// SHADOW_ATLAS_BINDING, SHADOW_ATLAS_COMPARE_BINDING, SHADOW_VIEWS_BINDING and
// SHADOW_LIGHTS_BINDING first. The constants
// come from render/src/passes/shadows/shadows_bindings.h (an include directory of the shaders).
#ifndef CANDELA_SHADOWS_GLSL
#define CANDELA_SHADOWS_GLSL

#include "common/lights.glsl"
#include "common/specialization_ids.h"
#include "shadows_bindings.h"

// Off in frames where no light casts: the calls below fold to 1 and the image is the
// shadowless one bit for bit.
layout(constant_id = SPEC_SHADOWS_ENABLED) const bool kShadowsEnabled = false;
// Off (the lower quality presets): local lights' maps are filtered as hard shadows.
layout(constant_id = SPEC_SOFT_SHADOWS) const bool kSoftShadows = true;
// Hard shadows' compare taps per axis: 2 (a 3x3-texel tent) or 1 (one bilinear 2x2-texel tap,
// a quarter of the cost, the lower quality presets).
layout(constant_id = SPEC_HARD_SHADOW_TAPS) const int kHardShadowTapsPerAxis = 2;

// One shadow view (render/src/passes/shadows/shadow_views.h, GpuShadowView).
struct ShadowView {
    mat4 worldToClip;
    vec4 tile;    // x, y: first texel in the atlas; z: size in texels
    vec4 params;  // x: texel size in metres (orthographic) or per metre of depth (perspective);
                  // y: SHADOW_KIND_*; z: near; w: far (orthographic)
    vec4 sphere;  // cascades: the bounding sphere (centre, radius) the cascade covers
};

layout(std430, binding = SHADOW_VIEWS_BINDING) readonly buffer ShadowViews {
    ShadowView shadowViews[];
};
// Per light (light buffer index): first view and view count; SHADOW_NO_VIEW: no shadow.
layout(std430, binding = SHADOW_LIGHTS_BINDING) readonly buffer ShadowLights {
    uvec2 shadowLights[];
};
// The atlas twice: raw depths for the blocker search and thickness, and through a comparison
// sampler with linear filtering, where one tap compares the four nearest texels with the
// receiver and weights them bilinearly in the texture unit (the filter's taps below).
layout(binding = SHADOW_ATLAS_BINDING) uniform sampler2D shadowAtlas;
layout(binding = SHADOW_ATLAS_COMPARE_BINDING) uniform sampler2DShadow shadowAtlasCompare;

// Bias (render/README.md "Shadows"), in shadow texels at the receiver: the receiver moves
// along its normal by kShadowNormalOffset x sin(angle to the light) texels, and its depth
// toward the light by kShadowDepthBias + kShadowSlopeBias x tan(angle to the light),
// capped at kShadowMaxSlope.
const float kShadowNormalOffset = 1.0;
const float kShadowDepthBias = 0.5;
const float kShadowSlopeBias = 1.5;
const float kShadowMaxSlope = 10.0;
// Cascades blend into the next over the outer 10% of their sphere.
const float kCascadeBlendBand = 0.1;
// Penumbra search and filter limits, in texels (half widths).
const float kPenumbraMaxSearch = 16.0;
const float kPenumbraMaxFilter = 24.0;

// Work this invocation's lookups did (--stats work; private, so a shader that never reads them
// compiles them out): compare taps of the filter, depth texels of the blocker search.
uint shadowFilterTapCount = 0u;
uint shadowBlockerTapCount = 0u;

// Light-space depth (metres along the view's axis) of a stored depth value.
float shadowLinearDepth(ShadowView v, float stored) {
    if (uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC) {
        return v.params.w - stored * (v.params.w - v.params.z);
    }
    return v.params.z / max(stored, 1e-30);  // 0 (cleared): infinitely far
}

// Size of one texel, in metres, at light-space depth z.
float shadowTexelWorld(ShadowView v, float z) {
    return uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC ? v.params.x : v.params.x * z;
}

// The blocker depth at one atlas texel, clamped into the view's tile.
float shadowBlockerDepth(ShadowView v, ivec2 texel) {
    ivec2 first = ivec2(v.tile.xy);
    texel = clamp(texel, first, first + ivec2(v.tile.z) - 1);
    return shadowLinearDepth(v, texelFetch(shadowAtlas, texel, 0).r);
}

// The value the atlas stores for light-space depth z (the inverse of shadowLinearDepth).
float shadowStoredDepth(ShadowView v, float z) {
    if (uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC) {
        return (v.params.w - z) / (v.params.w - v.params.z);
    }
    return v.params.z / max(z, 1e-30);
}

// Lit fraction at continuous atlas coordinate tc: one comparison-sampler tap (the four
// nearest texels compared with the receiver, bilinearly weighted). The sampler's compare op
// is GREATER_OR_EQUAL on stored depth, which is larger nearer the light, so a texel counts as
// lit when the receiver is no nearer than it. tc is clamped half a texel inside the view's
// tile, so a tap never reads a neighbouring tile (the border texels repeat, as a clamp to
// edge would).
float shadowCompareTap(ShadowView v, vec2 tc, float storedReceiver, vec2 invAtlas) {
    vec2 first = v.tile.xy + 0.5;
    tc = clamp(tc, first, first + v.tile.z - 1.0);
    return textureLod(shadowAtlasCompare, vec3(tc * invAtlas, storedReceiver), 0.0);
}

// Box filter of half width `radius` texels: an n x n grid of bilinear compare taps. n = 2 with
// radius 1 (hard shadows) is four taps half a texel off centre: a 3x3-texel tent.
float shadowFilter(ShadowView v, vec2 tc, float receiver, float radius, int n) {
    vec2 invAtlas = 1.0 / vec2(textureSize(shadowAtlasCompare, 0));
    float storedReceiver = shadowStoredDepth(v, receiver);
    shadowFilterTapCount += uint(n * n);
    float sum = 0.0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            vec2 o = (vec2(x, y) + 0.5) / float(n) * 2.0 - 1.0;
            sum += shadowCompareTap(v, tc + o * radius, storedReceiver, invAtlas);
        }
    }
    return sum / float(n * n);
}

// Blocker search and penumbra (percentage-closer soft shadows): the average depth of the
// blockers in front of the receiver gives the geometric penumbra width
// w = size * (d_receiver - d_blocker) / d_blocker on the receiver, filtered over as many
// texels. Returns the half width in texels, 0 when nothing blocks.
float shadowPenumbraRadius(ShadowView v, vec2 tc, float receiver, float lightSize) {
    float texel = shadowTexelWorld(v, receiver);
    // Blockers up to a quarter of the way to the light are found.
    float nearest = max(v.params.z, 0.25 * receiver);
    float search = clamp(lightSize * (receiver - nearest) / (nearest * texel) * 0.5, 1.0,
                         kPenumbraMaxSearch);
    // 3 x 3 gathers of the raw depths (4 texels each, 36 in all), every gather kept inside
    // the view's tile.
    vec2 invAtlas = 1.0 / vec2(textureSize(shadowAtlas, 0));
    vec2 first = v.tile.xy + 1.0;
    float sum = 0.0;
    float count = 0.0;
    const int n = 3;
    shadowBlockerTapCount += uint(4 * n * n);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            vec2 o = (vec2(x, y) + 0.5) / float(n) * 2.0 - 1.0;
            vec2 at = clamp(tc + o * search, first, first + v.tile.z - 2.0);
            vec4 stored = textureGather(shadowAtlas, at * invAtlas, 0);
            for (int i = 0; i < 4; ++i) {
                float blocker = shadowLinearDepth(v, stored[i]);
                if (blocker < receiver) {
                    sum += blocker;
                    count += 1.0;
                }
            }
        }
    }
    if (count == 0.0) return 0.0;
    float blocker = sum / count;
    float width = lightSize * (receiver - blocker) / max(blocker, 1e-4);
    return clamp(0.5 * width / texel, 1.0, kPenumbraMaxFilter);
}

// The depth view v's map stores for clip position `clip`: linear between its near and far
// planes for an orthographic view, w for a perspective one.
float shadowViewDepth(ShadowView v, vec4 clip) {
    return uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC
               ? v.params.w - clip.z * (v.params.w - v.params.z)
               : clip.w;
}

// Where clip position `clip` falls on the map, 0..1 across it; false behind the view or outside.
bool shadowMapUv(vec4 clip, out vec2 uv) {
    if (clip.w <= 0.0) return false;
    uv = clip.xy / clip.w * 0.5 + 0.5;
    return !(any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))));
}

// Lit fraction of one view at P (normal N, NoL toward the light); lightSize > 0 gives a
// penumbra from the blocker search, 0 hard shadows (2 x 2 compare taps: a 3x3-texel tent).
float sampleShadowView(ShadowView v, vec3 P, vec3 N, float NoL, float lightSize) {
    float depth = shadowViewDepth(v, v.worldToClip * vec4(P, 1.0));
    float texel = shadowTexelWorld(v, max(depth, 1e-4));
    float sinL = sqrt(saturate(1.0 - NoL * NoL));
    vec4 clip = v.worldToClip * vec4(P + N * (kShadowNormalOffset * texel * sinL), 1.0);
    vec2 uv;
    if (!shadowMapUv(clip, uv)) return 1.0;
    float receiver = shadowViewDepth(v, clip);
    float slope = min(sinL / max(NoL, 1e-3), kShadowMaxSlope);
    receiver -= texel * (kShadowDepthBias + kShadowSlopeBias * slope);
    vec2 tc = v.tile.xy + uv * v.tile.z;
    if (lightSize > 0.0) {
        float radius = shadowPenumbraRadius(v, tc, receiver, lightSize);
        if (radius == 0.0) return 1.0;
        // About one tap per texel of half width (bilinear taps overlap up to 2 texels apart),
        // at most 6 x 6.
        return shadowFilter(v, tc, receiver, radius, clamp(int(ceil(radius)), 2, 6));
    }
    return shadowFilter(v, tc, receiver, 1.0, kHardShadowTapsPerAxis);
}

// The view of a light's maps that holds P: its first cascade whose sphere holds P
// (directional), the cube face P lies in (point), or its one view (spot). false: none.
bool shadowViewAt(Light light, uint lightIndex, vec3 P, out ShadowView view) {
    uvec2 entry = shadowLights[lightIndex];
    if (entry.x == SHADOW_NO_VIEW) return false;
    if (light.type == kLightDirectional) {
        for (uint i = 0u; i < entry.y; ++i) {
            view = shadowViews[entry.x + i];
            if (length(P - view.sphere.xyz) < view.sphere.w) return true;
        }
        return false;
    }
    uint index = entry.x;
    if (entry.y == SHADOW_CUBE_FACES) {
        vec3 d = P - light.position;
        vec3 a = abs(d);
        index += a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u)
                 : a.y >= a.z             ? (d.y >= 0.0 ? 2u : 3u)
                                          : (d.z >= 0.0 ? 4u : 5u);
    }
    view = shadowViews[index];
    return true;
}

// One unfiltered lookup of P in a light's map: P's depth from the light (`receiver`, metres) and
// the nearest blocker's at P's texel. False without a map or outside it. The map's view `v`
// comes back for its texel size.
bool shadowMapLookup(Light light, uint lightIndex, vec3 P, out ShadowView v, out float receiver,
                     out float blocker) {
    receiver = 0.0;
    blocker = 0.0;
    if (!shadowViewAt(light, lightIndex, P, v)) return false;
    vec4 clip = v.worldToClip * vec4(P, 1.0);
    vec2 uv;
    if (!shadowMapUv(clip, uv)) return false;
    receiver = shadowViewDepth(v, clip);
    blocker = shadowBlockerDepth(v, ivec2(floor(v.tile.xy + uv * v.tile.z)));
    return true;
}

// Subsurface thickness (Karis 2013, "Real Shading in Unreal Engine 4", subsurface model:
// "samples the shadow map differently"): how far the light travelled inside matter before
// reaching P, the depth of P behind the nearest blocker in the light's map (metres, 0 when
// nothing is in front of P or the light has no map).
// For a surface lit from behind, the blocker is the object's own lit side.
float shadowThickness(Light light, uint lightIndex, vec3 P) {
    if (!kShadowsEnabled) return 0.0;
    ShadowView v;
    float receiver, blocker;
    if (!shadowMapLookup(light, lightIndex, P, v, receiver, blocker)) return 0.0;
    return max(receiver - blocker, 0.0);
}

// Light left after crossing the thickness above: exp(-thickness / kSubsurfaceMeanFreePath),
// 1 without a map (thin panels keep most of it, a 20 cm wax sphere about 2%).
const float kSubsurfaceMeanFreePath = 0.05;
float subsurfaceTransmittance(Light light, uint lightIndex, vec3 P) {
    float thickness = shadowThickness(light, lightIndex, P);
    return thickness > 0.0 ? exp(-thickness / kSubsurfaceMeanFreePath) : 1.0;
}

// A directional light's visibility at P from its cascades (N the surface normal, NoL > 0),
// blended into the next cascade over the outer band of each.
float cascadeShadowVisibility(uvec2 entry, vec3 P, vec3 N, float NoL) {
    // The cascade first, then its lookups: sampling inside the search loop made every lane run
    // the filter once per cascade any lane of its group was still testing (lavapipe runs a
    // loop's body for all lanes until the last one leaves).
    uint cascade = entry.y;
    float band = 1.0;  // 0..1 across the cascade's outer blend band, 1 inside it
    for (uint i = 0u; i < entry.y; ++i) {
        vec4 sphere = shadowViews[entry.x + i].sphere;
        float d = length(P - sphere.xyz);
        if (d < sphere.w) {
            cascade = i;
            band = (sphere.w - d) / (sphere.w * kCascadeBlendBand);
            break;
        }
    }
    if (cascade == entry.y) return 1.0;  // beyond the last cascade
    float visibility = sampleShadowView(shadowViews[entry.x + cascade], P, N, NoL, 0.0);
    if (band < 1.0 && cascade + 1u < entry.y) {
        float next = sampleShadowView(shadowViews[entry.x + cascade + 1u], P, N, NoL, 0.0);
        visibility = mix(next, visibility, band);
    }
    return visibility;
}

// A local light's visibility at P from its cube face (point) or single view (spot), soft by
// its size (sphere lights by their radius, tubes by their length).
float localShadowVisibility(Light light, uvec2 entry, vec3 P, vec3 N, float NoL) {
    float lightSize = kSoftShadows ? max(2.0 * light.sourceRadius, light.sourceLength) : 0.0;
    uint view = entry.x;
    if (entry.y == SHADOW_CUBE_FACES) {
        vec3 d = P - light.position;
        vec3 a = abs(d);
        uint face = a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u)
                    : a.y >= a.z             ? (d.y >= 0.0 ? 2u : 3u)
                                             : (d.z >= 0.0 ? 4u : 5u);
        view += face;
    }
    return sampleShadowView(shadowViews[view], P, N, NoL, lightSize);
}

// Which shadow code a caller compiles in: lavapipe runs every branch of a shader whether or
// not a lane takes it, so a loop that only sees local lights leaves the cascades out, and one
// that only sees directional lights leaves out the penumbra search and the cube faces.
const uint kShadowCodeAny = 0u;
const uint kShadowCodeDirectional = 1u;
const uint kShadowCodeLocal = 2u;

// The light's visibility at P in [0, 1]: its cascades (directional), cube face (point) or
// single view (spot). N is the surface normal. 1 when the light has no shadow. `code` is a
// constant of the call site (above); the light's type must be one it compiles in.
float shadowVisibility(Light light, uint lightIndex, vec3 P, vec3 N, uint code) {
    if (!kShadowsEnabled) return 1.0;
    uvec2 entry = shadowLights[lightIndex];
    if (entry.x == SHADOW_NO_VIEW) return 1.0;
    bool directional = code == kShadowCodeDirectional ||
                       (code == kShadowCodeAny && light.type == kLightDirectional);
    vec3 L = directional ? -light.direction : safeNormalize(light.position - P);
    float NoL = dot(N, L);
    if (NoL <= 0.0) return 1.0;  // facing away: the light adds nothing there anyway
    if (code == kShadowCodeDirectional) return cascadeShadowVisibility(entry, P, N, NoL);
    if (code == kShadowCodeLocal) return localShadowVisibility(light, entry, P, N, NoL);
    return directional ? cascadeShadowVisibility(entry, P, N, NoL)
                       : localShadowVisibility(light, entry, P, N, NoL);
}

float shadowVisibility(Light light, uint lightIndex, vec3 P, vec3 N) {
    return shadowVisibility(light, lightIndex, P, N, kShadowCodeAny);
}

// True when the light has no shadow map this frame (always without shadows).
bool lightUnshadowed(uint lightIndex) {
    return !kShadowsEnabled || shadowLights[lightIndex].x == SHADOW_NO_VIEW;
}

#endif
