#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// Screen-space reflection rays (Uludag 2014, GPU Pro 5, "Hi-Z Screen-Space Cone-Traced
// Reflections", pass 3), one per pixel whose roughness is under the cut-off, in screen space: x, y
// in pixels and z the reverse-Z depth, which is affine along a projected line, so the ray is a
// straight line in (x, y, z).
// - Hi-Z (mode 0): start at level 0; while the ray stays in front of a cell's nearest depth,
//   move to the cell's boundary (plus a small offset, so a ray always enters the next cell)
//   and climb a level; where it reaches the nearest depth inside the cell, move to it and
//   descend; a hit is a level-0 cell whose depth the ray reaches (within the thickness; a ray
//   found further behind a surface ends as a miss). At most maxIterations steps.
// - Reference (mode 1): a linear march in steps of referenceStepPixels against level 0. A
//   mirror traces R; a rougher surface traces referenceRays rays importance-sampled from its
//   GGX lobe and averages what each hits at full resolution (no pre-convolution, no cone):
//   the glossy reflection the cone below approximates.
// Cone tracing (pass 5, coneGather): a cone as wide as the GGX lobe (tan of its half-angle =
// alpha) around the Hi-Z ray is sampled by circles that fill it, from the hit (or a miss's
// last point on screen) back toward the ray's start, each from the pre-convolved level
// (ssr_color.comp) whose texels match its diameter, weighted by how much of the ray's depth
// across the circle lies in the Hi-Z cell's depth range (does the cone meet the cell's
// volume) times the cell's pre-integrated visibility (ssr_visibility.comp, pass 2), until the
// weights reach 100%. A hit takes the weighted mean; a miss also takes the summed weight as
// its confidence (the lobe met something the ray passed by). A cone narrower than a pixel (a
// mirror) reads the hit texel alone.
// Writes confidence x (radiance at the hit x the split sum's specular reflectance - the
// environment's own split-sum specular there, as the lighting pass added it), so the
// composite replaces the environment's specular by the reflection in proportion to the
// confidence instead of adding to it.
#include "common/ambient_occlusion.glsl"
#include "common/ibl.glsl"
#include "ssr_levels.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = SSR_BINDING_BASE_COLOR) uniform sampler2D gbufferBaseColor;
layout(binding = SSR_BINDING_SPECULAR_MODEL) uniform sampler2D gbufferSpecularModel;
layout(binding = SSR_BINDING_HIZ, rgba32f) uniform readonly image2D hiz;
layout(binding = SSR_BINDING_VISIBILITY, r32f) uniform readonly image2D visibility;
layout(binding = SSR_BINDING_COLOR, rgba16f) uniform readonly image2D colorPyramid;
layout(binding = SSR_BINDING_PREFILTERED) uniform samplerCube prefilteredCube;
layout(binding = SSR_BINDING_BRDF_LUT) uniform sampler2D environmentBrdfLut;
layout(binding = SSR_BINDING_AMBIENT_OCCLUSION) uniform sampler2D ambientOcclusion;
layout(binding = SSR_BINDING_SPECULAR_OCCLUSION) uniform sampler2D specularOcclusion;
layout(binding = SSR_BINDING_REFLECTION, rgba32f) uniform writeonly image2D reflection;
layout(std430, binding = SSR_BINDING_COUNTERS) buffer Counters {
    uint stepsLow;
    uint stepsHigh;
    uint stepsMax;
    uint hits;
    uint rays;
} counters;

layout(push_constant) uniform Push {
    uint mode;  // 0: Hi-Z, 1: reference
    uint maxIterations;
    uint levelCount;
    uint flags;  // 1: the frame has a sky (take its specular out), 2: the LUT is bound,
                 // 4: cone tracing (else one pre-convolved read at the hit)
    float roughnessCutoff;
    float thickness;  // metres behind a depth-buffer surface that count as solid
    float referenceStepPixels;
    float skyIntensity;
    float prefilteredMipCount;
    uint coneSamples;    // most circles along a cone
    uint referenceRays;  // lobe rays per rough pixel in the reference mode
    uint aoMode;         // the lighting pass's (kAoOff... in ambient_occlusion.glsl)
    float aoIntensity;
} push;

const uint kShadingUnlit = 0u;  // shading_models.glsl's ID (without its specialisation constants)
const float kCrossingOffset = 0.01;  // pixels past a cell boundary: the ray never stays in a cell

shared uint groupSteps;
shared uint groupMax;
shared uint groupHits;
shared uint groupRays;

struct Ray {
    vec3 origin;     // (pixel x, pixel y, reverse-Z depth)
    vec3 direction;  // per pixel of screen travel
    float extent;    // pixels to the end of the ray (the near plane or far away)
};

struct TraceResult {
    bool hit;
    vec2 position;  // pixels
    uint steps;
};

float levelDepth(uint level, ivec2 cell) {
    SsrLevel l = ssrLevel(level);
    return imageLoad(hiz, l.origin + clamp(cell, ivec2(0), l.size - 1)).r;
}

// (nearest, farthest) depth of a cell.
vec2 levelRange(uint level, ivec2 cell) {
    SsrLevel l = ssrLevel(level);
    return imageLoad(hiz, l.origin + clamp(cell, ivec2(0), l.size - 1)).rg;
}

float levelVisibility(uint level, ivec2 cell) {
    SsrLevel l = ssrLevel(level);
    return imageLoad(visibility, l.origin + clamp(cell, ivec2(0), l.size - 1)).r;
}

bool onScreen(vec2 p) {
    return all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, vec2(camera.frameInfo.xy)));
}

// Whether a ray at depth `rayDepth` that reached a surface of depth `surfaceDepth` is within
// the thickness behind it (and not passing far behind a thin object). near: the near plane.
bool withinThickness(float rayDepth, float surfaceDepth, float near) {
    return near / max(rayDepth, 1e-12) - near / surfaceDepth <= push.thickness;
}

TraceResult traceHiZ(Ray ray, float near) {
    TraceResult r = TraceResult(false, ray.origin.xy, 0u);
    vec2 dirSign = vec2(ray.direction.x >= 0.0 ? 1.0 : 0.0, ray.direction.y >= 0.0 ? 1.0 : 0.0);
    vec2 invDir = 1.0 / max(abs(ray.direction.xy), vec2(1e-12)) * sign(ray.direction.xy + 1e-30);
    // Leave the start pixel first (it holds the surface the ray starts on).
    vec2 startBoundary = floor(ray.origin.xy) + dirSign;
    vec2 tb0 = (startBoundary - ray.origin.xy) * invDir;
    float t = min(tb0.x, tb0.y) + kCrossingOffset;
    int level = 0;
    int top = int(push.levelCount) - 1;
    while (r.steps < push.maxIterations) {
        r.steps += 1u;
        vec3 pos = ray.origin + ray.direction * t;
        if (t > ray.extent || !onScreen(pos.xy) || pos.z <= 0.0) break;
        r.position = pos.xy;  // a miss's last point on screen (where its cone ends)
        float cellSize = float(1 << level);
        vec2 cell = floor(pos.xy / cellSize);
        float nearest = levelDepth(uint(level), ivec2(cell));
        vec2 tb = ((cell + dirSign) * cellSize - pos.xy) * invDir;
        float tCross = min(tb.x, tb.y);
        if (pos.z <= nearest) {  // at or behind the nearest surface of the cell
            if (level > 0) {
                --level;
                continue;
            }
            // Further behind than the thickness: the ray passes behind a surface, where the
            // depth buffer cannot say what it meets. A miss (the sky's light stays), which
            // also bounds the steps: no level-0 march through the shadow of an object.
            r.hit = withinThickness(pos.z, nearest, near);
            r.position = pos.xy;
            return r;
        }
        float tPlane = ray.direction.z < 0.0 ? (nearest - pos.z) / ray.direction.z : 1e30;
        if (tPlane <= tCross) {
            t += tPlane;
            if (level == 0) {
                r.hit = true;
                r.position = (ray.origin + ray.direction * t).xy;
                return r;
            }
            --level;
        } else {
            t += tCross + kCrossingOffset;
            level = min(level + 1, top);
        }
    }
    return r;
}

TraceResult traceLinear(Ray ray, float near) {
    TraceResult r = TraceResult(false, vec2(0.0), 0u);
    float h = push.referenceStepPixels;
    // Start one step out of the start pixel's surface, as the Hi-Z trace does.
    for (float t = h; r.steps < push.maxIterations; t += h) {
        r.steps += 1u;
        vec3 pos = ray.origin + ray.direction * t;
        if (t > ray.extent || !onScreen(pos.xy) || pos.z <= 0.0) break;
        if (all(equal(floor(pos.xy), floor(ray.origin.xy)))) continue;
        float depth = levelDepth(0u, ivec2(floor(pos.xy)));
        if (pos.z <= depth && withinThickness(pos.z, depth, near)) {
            r.hit = true;
            r.position = pos.xy;
            return r;
        }
    }
    return r;
}

// The pre-convolved radiance around `p` (pixels) at a fractional level: bilinear in each of
// the two nearest levels, linear between them; level 0 alone is the hit texel itself.
vec3 levelRadiance(int level, vec2 p) {
    SsrLevel l = ssrLevel(uint(level));
    vec2 q = p / float(1 << level) - 0.5;
    ivec2 i = ivec2(floor(q));
    vec2 f = q - vec2(i);
    ivec2 hi = l.size - 1;
    vec3 c00 = imageLoad(colorPyramid, l.origin + clamp(i, ivec2(0), hi)).rgb;
    vec3 c10 = imageLoad(colorPyramid, l.origin + clamp(i + ivec2(1, 0), ivec2(0), hi)).rgb;
    vec3 c01 = imageLoad(colorPyramid, l.origin + clamp(i + ivec2(0, 1), ivec2(0), hi)).rgb;
    vec3 c11 = imageLoad(colorPyramid, l.origin + clamp(i + 1, ivec2(0), hi)).rgb;
    return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

// One pre-convolved read at a fractional level around `hit`; level 0 is the hit texel.
vec3 preconvolvedRadiance(vec2 hit, ivec2 hitPixel, float level) {
    if (level <= 0.0) return imageLoad(colorPyramid, hitPixel).rgb;
    int below = int(floor(level));
    int above = min(below + 1, int(push.levelCount) - 1);
    vec3 fine = below == 0 ? imageLoad(colorPyramid, hitPixel).rgb : levelRadiance(below, hit);
    return mix(fine, levelRadiance(above, hit), level - float(below));
}

// The level whose texels match a circle of diameter `diameter` pixels.
float levelOfDiameter(float diameter) {
    return clamp(log2(max(diameter, 1e-6)), 0.0, float(push.levelCount - 1u));
}

// Cone tracing (pass 5): what a cone around `ray` gathers back from `travelled` pixels along
// it (the hit, or a miss's last point on screen): circles inscribed in the cone, the first
// centred there, each next one touching the one before on the side of the ray's start (centre
// t, radius t tan: the next centre is t (1 - tan) / (1 + tan)). Each circle's weight: the
// share of the ray's depth across the circle (where it enters and leaves it) inside its Hi-Z
// cell's [farthest, nearest] (the cone meets the cell's volume there: 0 where it passes in
// front of or behind everything) times the cell's pre-integrated visibility, until the weights
// reach 1 (the last is cut to what is left). Returns the weighted mean radiance and the summed
// weight (0: the cone met nothing).
vec4 coneGather(Ray ray, float travelled, float tanHalf) {
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    float t = travelled;
    for (uint i = 0u; i < push.coneSamples && weight < 1.0; ++i) {
        float radius = t * tanHalf;
        if (radius < 0.5) break;  // finer than a pixel: the circles before cover the cone
        float level = levelOfDiameter(2.0 * radius);
        uint cellLevel = uint(ceil(level));  // cells at least as wide as the circle
        vec2 centre = ray.origin.xy + ray.direction.xy * t;
        ivec2 cell = ivec2(floor(centre / float(1 << cellLevel)));
        vec2 range = levelRange(cellLevel, cell);  // (nearest, farthest): reverse-Z, near high
        float enter = ray.origin.z + ray.direction.z * max(t - radius, 0.0);
        float leave = ray.origin.z + ray.direction.z * (t + radius);
        float lo = min(enter, leave), hi = max(enter, leave);
        float inside = max(min(hi, range.x) - max(lo, range.y), 0.0);
        float meets = hi - lo > 1e-12 ? inside / (hi - lo)
                                      : (lo <= range.x && lo >= range.y ? 1.0 : 0.0);
        float w = min(meets * levelVisibility(cellLevel, cell), 1.0 - weight);
        if (w > 0.0) {
            ivec2 centrePixel =
                clamp(ivec2(floor(centre)), ivec2(0), ivec2(camera.frameInfo.xy) - 1);
            sum += w * preconvolvedRadiance(centre, centrePixel, level);
            weight += w;
        }
        t *= (1.0 - tanHalf) / (1.0 + tanHalf);
    }
    return vec4(weight > 0.0 ? sum / weight : vec3(0.0), weight);
}

// The reflected radiance at a hit: the cone's weighted mean, or where the cone is narrower
// than a pixel at the hit (a mirror), cone tracing is off, or the circles met nothing, one
// pre-convolved read at the hit (the hit texel for a mirror).
vec3 coneTrace(Ray ray, vec2 hit, ivec2 hitPixel, float travelled, float roughness) {
    float tanHalf = roughness * roughness;
    if ((push.flags & 4u) != 0u && travelled * tanHalf >= 0.5) {
        vec4 gathered = coneGather(ray, travelled, tanHalf);
        if (gathered.a > 1e-6) return gathered.rgb;
    }
    return preconvolvedRadiance(hit, hitPixel, levelOfDiameter(2.0 * travelled * tanHalf));
}

// Fades the confidence to 0 over the last 4% of the screen, where the rays that would have
// found something just off it leave.
float edgeFade(vec2 p) {
    vec2 size = vec2(camera.frameInfo.xy);
    vec2 margin = max(size * 0.04, vec2(1.0));
    vec2 d = min(p, size - p) / margin;
    return saturate(min(d.x, d.y));
}

void countRay(bool traced, bool hit, uint steps) {
    if (!traced) return;
    atomicAdd(groupSteps, steps);
    atomicMax(groupMax, steps);
    atomicAdd(groupRays, 1u);
    if (hit) atomicAdd(groupHits, 1u);
}

// The screen-space ray from the pixel at `start` (pixel centre, depth) along world direction
// `dir` from P: to far along it, or just short of the near plane when it faces the camera.
// False where the ray has no length on screen or P is at the near plane.
bool screenRay(vec3 P, vec3 dir, vec3 start, vec4 clipP, out Ray ray) {
    float near = clipP.z;  // reverse-Z with an infinite far plane: clip z is the near plane
    float L = 1000.0;
    vec4 clipQ = camera.viewProjection * vec4(P + dir * L, 1.0);
    float wMin = near * 1.5;
    if (clipQ.w < wMin) {
        L *= (clipP.w - wMin) / max(clipP.w - clipQ.w, 1e-12);
        clipQ = camera.viewProjection * vec4(P + dir * L, 1.0);
    }
    vec2 size = vec2(camera.frameInfo.xy);
    vec3 end = vec3((clipQ.xy / clipQ.w * 0.5 + 0.5) * size, clipQ.z / clipQ.w);
    vec3 d = end - start;
    float len = length(d.xy);
    ray = Ray(start, d / max(len, 1e-12), len);
    return clipP.w > wMin && len > 1e-3;
}

// Whether a hit counts, and how much (edge fade x facing): a hit on a surface facing away from
// the ray is one the depth buffer cannot vouch for (its front is hidden).
float hitConfidence(vec2 position, vec3 dir) {
    ivec2 hitPixel = clamp(ivec2(floor(position)), ivec2(0), ivec2(camera.frameInfo.xy) - 1);
    vec3 hitN = octDecode(texelFetch(gbufferNormalRoughMetal, hitPixel, 0).xy);
    return dot(hitN, dir) < 0.0 ? edgeFade(position) : 0.0;
}

// A per-pixel rotation of the reference's Hammersley set (decorrelated neighbours, the same
// every frame).
vec2 pixelOffset(ivec2 pixel) {
    uvec2 h = uvec2(pixel) * uvec2(1597334677u, 3812015801u);
    uint x = (h.x ^ h.y) * 1597334677u;
    return vec2(float(x >> 8u), float((x * 3812015801u) >> 8u)) / 16777216.0;
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupSteps = 0u;
        groupMax = 0u;
        groupHits = 0u;
        groupRays = 0u;
    }
    barrier();

    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    bool inside = all(lessThan(pixel, size));
    vec4 result = vec4(0.0);
    bool traced = false;
    bool anyHit = false;
    uint steps = 0u;
    float depth = inside ? levelDepth(0u, pixel) : 0.0;
    vec4 gb1 = inside ? texelFetch(gbufferNormalRoughMetal, pixel, 0) : vec4(0.0);
    vec4 gb2 = inside ? texelFetch(gbufferSpecularModel, pixel, 0) : vec4(0.0);
    float roughness = gb1.z;
    uint model = uint(gb2.g * 255.0 + 0.5);
    if (inside && depth > 0.0 && model != kShadingUnlit && roughness < push.roughnessCutoff) {
        vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
        vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
        vec3 P = world.xyz / world.w;
        vec3 N = octDecode(gb1.xy);
        vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
        vec3 R = reflect(-V, N);
        float NoV = saturate(dot(N, V));
        vec4 clipP = camera.viewProjection * vec4(P, 1.0);
        float near = clipP.z;
        vec3 start = vec3(vec2(pixel) + 0.5, depth);
        float cutoffFade =
            1.0 - smoothstep(0.75 * push.roughnessCutoff, push.roughnessCutoff, roughness);
        float alpha = roughness * roughness;
        // The reflected radiance (before the split sum's reflectance) and its confidence.
        vec3 radiance = vec3(0.0);
        float confidence = 0.0;
        if (push.mode == 1u && alpha > 1e-4 && push.referenceRays > 1u) {
            // Reference: the lobe's rays, each weighted by NoL as the prefiltered cube's
            // convolution weights them (so a lobe that finds everything matches the split sum).
            mat3 frame = tangentFrame(N);
            vec2 offset = pixelOffset(pixel);
            float total = 0.0;
            for (uint i = 0u; i < push.referenceRays; ++i) {
                vec3 H = frame * importanceSampleGgx(hammersley(i, push.referenceRays, offset),
                                                     alpha);
                vec3 Ldir = reflect(-V, H);
                float NoL = dot(N, Ldir);
                if (NoL <= 0.0) continue;
                total += NoL;
                Ray ray;
                if (!screenRay(P, Ldir, start, clipP, ray)) continue;
                traced = true;
                TraceResult hit = traceLinear(ray, near);
                steps += hit.steps;
                if (!hit.hit) continue;
                float c = hitConfidence(hit.position, Ldir) * NoL;
                ivec2 hitPixel = clamp(ivec2(floor(hit.position)), ivec2(0), size - 1);
                vec3 L = imageLoad(colorPyramid, hitPixel).rgb;
                if (c > 0.0 && all(lessThan(abs(L), vec3(3e38)))) {
                    radiance += c * L;
                    confidence += c;
                }
            }
            if (confidence > 0.0) radiance /= confidence;
            confidence = total > 0.0 ? confidence / total : 0.0;
        } else {
            Ray ray;
            if (screenRay(P, R, start, clipP, ray)) {
                traced = true;
                TraceResult hit = push.mode == 0u ? traceHiZ(ray, near) : traceLinear(ray, near);
                steps = hit.steps;
                if (hit.hit) {
                    confidence = hitConfidence(hit.position, R);
                    ivec2 hitPixel = clamp(ivec2(floor(hit.position)), ivec2(0), size - 1);
                    radiance = coneTrace(ray, hit.position, hitPixel,
                                         length(hit.position - start.xy), roughness);
                } else if (push.mode == 0u && (push.flags & 4u) != 0u) {
                    // A miss: the lobe around it may still meet what the ray passed by (the
                    // glossy spread of a reflection beyond its mirror image). The cone's
                    // summed weight is the confidence; the sky fills the rest.
                    float tanHalf = roughness * roughness;
                    float travelled = length(hit.position - start.xy);
                    if (travelled * tanHalf >= 0.5) {
                        vec4 gathered = coneGather(ray, travelled, tanHalf);
                        radiance = gathered.rgb;
                        confidence = gathered.a * edgeFade(hit.position);
                    }
                }
                if (any(greaterThanEqual(abs(radiance), vec3(3e38))) || any(isnan(radiance))) {
                    confidence = 0.0;  // never carry Inf or NaN on
                }
            }
        }
        confidence *= cutoffFade;
        anyHit = confidence > 0.0;
        if (anyHit) {
            vec4 gb0 = texelFetch(gbufferBaseColor, pixel, 0);
            vec3 F0 = mix(vec3(0.08 * gb2.r), gb0.rgb, gb1.w);
            vec3 weight = (push.flags & 2u) != 0u
                              ? environmentBrdfFromLut(environmentBrdfLut, F0, roughness, NoV)
                              : envBrdfApprox(F0, roughness, NoV);
            vec3 environment = vec3(0.0);
            if ((push.flags & 1u) != 0u) {
                float mip = prefilteredMipOfRoughness(roughness, push.prefilteredMipCount);
                // As the lighting pass occluded it (material and ambient occlusion). Its
                // multiple scattering (energy-conserving BRDF) stays: it is the sky's
                // irradiance over the hemisphere, not the lobe's radiance, which is all the
                // ray knows (render/README.md "Screen-space reflections").
                float horizons = push.aoMode == kAoReference || push.aoMode == kAoGtaoHorizonSpecular
                                     ? texelFetch(specularOcclusion, pixel, 0).r
                                     : 1.0;
                float occlusion = environmentSpecularVisibility(
                    push.aoMode, push.aoIntensity,
                    push.aoMode == kAoOff ? 1.0 : texelFetch(ambientOcclusion, pixel, 0).w,
                    horizons, NoV, roughness, gb0.a);
                environment = textureLod(prefilteredCube, R, mip).rgb * weight *
                              (push.skyIntensity * occlusion);
            }
            result = vec4((radiance * weight - environment) * confidence, confidence);
        }
    }
    if (inside) imageStore(reflection, pixel, result);

    // A hit counts where it gives the reflection (not one on a surface facing away).
    countRay(traced, anyHit, steps);
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupRays > 0u) {
        uint before = atomicAdd(counters.stepsLow, groupSteps);
        if (before > 0xFFFFFFFFu - groupSteps) atomicAdd(counters.stepsHigh, 1u);
        atomicMax(counters.stepsMax, groupMax);
        atomicAdd(counters.hits, groupHits);
        atomicAdd(counters.rays, groupRays);
    }
}
