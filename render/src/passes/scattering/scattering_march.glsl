// What the light-shaft shaders share (render/README.md "Light shafts"; issue 16, Yusov 2014,
// GPU Pro 5, "High Performance Outdoor Light Scattering Using Epipolar Sampling", Yusov 2013
// "Practical Implementation of Light Scattering Effects Using Epipolar Sampling and 1D Min/Max
// Binary Trees"): the sun's single scattering in the air along a view ray, shadowed by its
// cascades, integrated exactly over lit runs; the march through each slice's min/max trees; and the
// view rays of pixels.
//
// The air is homogeneous over a scene: the atmosphere's scattering and extinction at the
// camera's altitude (scaled, ScatteringSettings::densityScale). Along a lit run [t0, t1] of a
// view ray the in-scattered radiance is then exactly
//   S (exp(-sigma_t t0) - exp(-sigma_t t1)) / sigma_t,
//   S = E_sun (sigma_R p_R(theta) + sigma_M p_M(theta)),
// so a march only has to find where the ray is lit.
#ifndef CANDELA_SCATTERING_MARCH_GLSL
#define CANDELA_SCATTERING_MARCH_GLSL

#include "common/atmosphere.glsl"
#include "common/camera.glsl"
#include "common/light_buffer.glsl"
#include "common/math.glsl"
#define SHADOW_ATLAS_BINDING SCATTERING_BINDING_SHADOW_ATLAS
#define SHADOW_ATLAS_COMPARE_BINDING SCATTERING_BINDING_SHADOW_ATLAS_COMPARE
#define SHADOW_VIEWS_BINDING SCATTERING_BINDING_SHADOW_VIEWS
#define SHADOW_LIGHTS_BINDING SCATTERING_BINDING_SHADOW_LIGHTS
#include "common/shadows.glsl"
#include "scattering_push.glsl"

// Per slice: where its epipolar line enters and leaves the screen (pixels; w of `flags` 1
// when the line crosses the screen) and, per cascade, the line the slice's plane cuts from
// the cascade's map: a point (texels in the tile) and a unit direction. Every view ray of the
// slice projects onto it, so its blocker depths are one 1D height map (Yusov 2014).
struct SliceInfo {
    vec4 endpoints;  // entry xy, exit xy
    vec4 flags;      // w: valid
    vec4 lines[SHADOW_MAX_CASCADES];
};

layout(std430, binding = SCATTERING_BINDING_COUNTERS) buffer Counters {
    uint raysMarched;
    uint shadowTests;
}
counters;

const float kNoBlocker = 1e30;

// The view ray through a position in pixels (unit direction) and its length to depth-buffer
// value `depth` (reverse-Z; 0, the sky: the distance marched for the sky).
vec3 pixelRay(vec2 position, out float perDepth) {
    vec2 ndc = position / vec2(camera.frameInfo.xy) * 2.0 - 1.0;
    vec4 nearPoint = camera.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 offset = nearPoint.xyz / nearPoint.w - camera.cameraPosition.xyz;
    perDepth = length(offset) / push.mie.w;
    return offset / length(offset);
}
float rayDistance(float depth, float perDepth) {
    if (depth <= 0.0) return push.extinction.w;
    return min(push.mie.w / depth * perDepth, 1e6);
}

Light sunLight() { return loadLight(push.lights.x, push.lights.y); }

// S above: in-scattered radiance per metre of lit air before extinction, for view direction v.
vec3 sunSource(Light sun, vec3 v) {
    float cosTheta = dot(-sun.direction, v);
    return sun.intensity * (push.rayleigh.rgb * rayleighPhase(cosTheta) +
                            push.mie.rgb * miePhase(push.rayleigh.w, cosTheta));
}

// The in-scattering of the lit run [t0, t1].
vec3 litRun(vec3 source, float t0, float t1) {
    vec3 s = push.extinction.rgb;
    vec3 weight = (exp(-s * t0) - exp(-s * t1)) / max(s, vec3(1e-12));
    return source * mix(weight, vec3(t1 - t0), lessThan(s, vec3(1e-9)));
}

vec3 viewTransmittance(float distance) { return exp(-push.extinction.rgb * distance); }

// Whether the sun lights P: one unfiltered lookup in the cascade that holds P, as the
// volumetric medium's (receiver less the depth bias no deeper than the blocker); lit outside
// every cascade.
bool sunLightsPoint(Light sun, vec3 P) {
    ShadowView v;
    float receiver, blocker;
    if (!shadowMapLookup(sun, push.lights.x, P, v, receiver, blocker)) return true;
    return receiver - kShadowDepthBias * shadowTexelWorld(v, receiver) <= blocker;
}

// P in a cascade: texels in its tile (xy) and depth from the light (z, metres).
vec3 cascadeTexelDepth(ShadowView v, vec3 P) {
    vec4 clip = v.worldToClip * vec4(P, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    return vec3(uv * v.tile.z, v.params.w - clip.z * (v.params.w - v.params.z));
}

// The tree's node (min, max blocker depth) at `level` (0: the leaves, one per texel along the
// line), `node` within it; beyond the line: no blocker. Row layout: level L starts at
// 2M - 2M / 2^L.
vec2 treeNode(sampler2D tree, uint row, int level, int node) {
    int leaves = int(push.epipolar.w);
    if (node < 0 || node >= (leaves >> level)) return vec2(kNoBlocker);
    int offset = 2 * leaves - ((2 * leaves) >> level);
    return texelFetch(tree, ivec2(offset + node, int(row)), 0).rg;
}

// The lit part of [t0, t1] in one leaf whose blocker is at depth `blocker`: the receiver
// depth is linear along the ray, r(t) = r0 + (t - tr) * slope, so the ray crosses the blocker
// once at most and the lit run ends (or starts) there exactly.
vec3 litPartOfLeaf(vec3 source, float t0, float t1, float blocker, float r0, float tr,
                   float slope) {
    if (abs(slope) < 1e-12) return r0 <= blocker ? litRun(source, t0, t1) : vec3(0.0);
    float crossing = tr + (blocker - r0) / slope;
    if (slope > 0.0) return litRun(source, t0, clamp(crossing, t0, t1));
    return litRun(source, clamp(crossing, t0, t1), t1);
}

// The march through one cascade's tree over the ray's run [tA, tB] in it (Yusov 2014,
// Yusov 2013 section 4): a node whose blockers are all deeper than the run's receiver depths
// is lit through (its run integrated at once), one whose blockers are all shallower is in
// shadow (skipped); otherwise the march descends to its children, and at a leaf the run is
// split where the ray crosses the blocker. After a node the march climbs while the next node
// is a left child. `levels` 0: no tree, every leaf in turn (the gain's measurement).
vec3 marchCascade(sampler2D tree, uint row, ShadowView v, vec4 line, vec3 origin, vec3 direction,
                  float tA, float tB, vec3 source, inout uint steps) {
    vec3 a = cascadeTexelDepth(v, origin + direction * tA);
    vec3 b = cascadeTexelDepth(v, origin + direction * tB);
    float bias = kShadowDepthBias * v.params.x;
    float rA = a.z - bias;
    float slope = (b.z - a.z) / (tB - tA);
    float uA = dot(a.xy - line.xy, line.zw);
    float uB = dot(b.xy - line.xy, line.zw);
    vec3 sum = vec3(0.0);
    if (uB - uA < 1e-3) {  // along the light: the run stays in one texel
        steps += 1u;
        float blocker = treeNode(tree, row, 0, int(floor(0.5 * (uA + uB)))).x;
        return litPartOfLeaf(source, tA, tB, blocker, rA, tA, slope);
    }
    float tPerTexel = (tB - tA) / (uB - uA);
    float t = tA;
    if (uA < 0.0) {  // before the line enters the tile: nothing blocks
        float tIn = min(tA - uA * tPerTexel, tB);
        sum += litRun(source, tA, tIn);
        t = tIn;
    }
    int maxLevel = int(push.lights.z);
    int level = 0;
    int node = int(floor(max(uA, 0.0)));
    while (level < maxLevel && (node & 1) == 0 && node > 0) {
        node >>= 1;
        ++level;
    }
    // Lavapipe ends a shader's loops after 65,535 iterations in all; a march is far shorter
    // (2 M leaves per cascade without the tree), the cap only guards against a stuck one.
    for (uint guard = 0u; t < tB && guard < 8192u; ++guard) {
        steps += 1u;
        float tEnd = min(tB, tA + (float((node + 1) << level) - uA) * tPerTexel);
        vec2 range = treeNode(tree, row, level, node);
        float r0 = rA + (t - tA) * slope;
        float r1 = rA + (tEnd - tA) * slope;
        if (max(r0, r1) <= range.x) {
            sum += litRun(source, t, tEnd);
        } else if (min(r0, r1) > range.y) {
            // in shadow
        } else if (level > 0) {
            --level;
            float u = uA + (t - tA) / tPerTexel;
            node = 2 * node + (u >= float((2 * node + 1) << level) ? 1 : 0);
            continue;
        } else {
            sum += litPartOfLeaf(source, t, tEnd, range.x, rA, tA, slope);
        }
        t = max(tEnd, t + 1e-6 * tPerTexel);
        ++node;
        while (level < maxLevel && (node & 1) == 0) {
            node >>= 1;
            ++level;
        }
    }
    return sum;
}

// The in-scattered radiance along a view ray of `slice` (origin the camera, unit direction)
// over [0, distance]: the ray is cut where it passes from one cascade to the next (the first
// whose sphere holds a point holds it, as shadowViewAt), each run marched through its
// cascade's tree; outside every cascade it is lit.
vec3 marchEpipolarRay(sampler2D tree, SliceInfo info, uint slice, vec3 direction, float distance,
                      inout uint steps) {
    Light sun = sunLight();
    vec3 source = sunSource(sun, direction);
    vec3 origin = camera.cameraPosition.xyz;
    uvec2 entry = shadowLights[push.lights.x];
    if (!kShadowsEnabled || push.lights.w == 0u || entry.x == SHADOW_NO_VIEW) {
        steps += 1u;
        return litRun(source, 0.0, distance);
    }
    uint count = min(entry.y, SHADOW_MAX_CASCADES);
    vec2 runs[SHADOW_MAX_CASCADES];
    for (uint c = 0u; c < count; ++c) {
        vec4 sphere = shadowViews[entry.x + c].sphere;
        vec2 run = raySphereSegment(origin, direction, sphere.xyz, sphere.w);
        runs[c] = vec2(max(run.x, 0.0), min(run.y, distance));
    }
    vec3 sum = vec3(0.0);
    float t = 0.0;
    for (uint guard = 0u; t < distance && guard < 2u * SHADOW_MAX_CASCADES + 1u; ++guard) {
        int cascade = -1;
        float end = distance;
        for (uint c = 0u; c < count; ++c) {
            if (runs[c].x >= runs[c].y) continue;
            if (runs[c].x <= t && t < runs[c].y) {
                cascade = int(c);
                end = min(end, runs[c].y);
                break;
            }
            if (runs[c].x > t) end = min(end, runs[c].x);
        }
        if (cascade < 0) {
            steps += 1u;
            sum += litRun(source, t, end);
        } else {
            sum += marchCascade(tree, slice * SHADOW_MAX_CASCADES + uint(cascade),
                                shadowViews[entry.x + uint(cascade)], info.lines[cascade],
                                origin, direction, t, end, source, steps);
        }
        t = end;
    }
    return sum;
}

#endif
