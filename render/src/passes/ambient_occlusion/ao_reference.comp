#version 460
#extension GL_GOOGLE_include_directive : require
#include "ambient_occlusion_bindings.h"
// Reference ambient occlusion, for measuring GTAO: `slices` cosine-distributed rays per pixel
// (a Hammersley set turned per pixel), each marched in `steps` world steps out to `radius`
// against the G-buffer depth, with surfaces `thickness` metres deep behind it. Visibility is
// the share of rays that escape (so cosine-weighted), the bent normal their mean direction.
// Specular: the same number of rays drawn from the GGX lobe's visible normals around the
// reflection; the share that escape is the lobe's visibility (AO_BINDING_SECOND_OUTPUT).
#include "common/ambient_occlusion.glsl"
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = AO_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = AO_BINDING_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = AO_BINDING_OUTPUT, rgba16f) uniform writeonly image2D aoOutput;
layout(binding = AO_BINDING_SECOND_OUTPUT, r16f) uniform writeonly image2D specularOutput;

layout(push_constant) uniform Push {
    float radius;
    uint slices;
    uint steps;
    float thickness;
} push;

// The depth at a point of the screen, interpolated between the four nearest texels: reverse-Z
// depth is linear in screen space across a plane, so a floor seen at a grazing angle gives its
// exact depth between texel centres. Nearest texel (which rounds a whole texel's depth step,
// and counted half of a glossy lobe's rays on far floor as blocked by the floor itself) only
// where a texel is sky.
float interpolatedDepth(vec2 pixel, vec2 size) {
    vec2 p = clamp(pixel - 0.5, vec2(0.0), size - 1.0);
    ivec2 base = ivec2(floor(p));
    ivec2 far = min(base + 1, ivec2(size) - 1);
    vec2 f = p - vec2(base);
    float d00 = texelFetch(gbufferDepth, base, 0).r;
    float d10 = texelFetch(gbufferDepth, ivec2(far.x, base.y), 0).r;
    float d01 = texelFetch(gbufferDepth, ivec2(base.x, far.y), 0).r;
    float d11 = texelFetch(gbufferDepth, far, 0).r;
    if (min(min(d00, d10), min(d01, d11)) <= 0.0) {
        return texelFetch(gbufferDepth, ivec2(pixel), 0).r;
    }
    return mix(mix(d00, d10, f.x), mix(d01, d11, f.x), f.y);
}

// Whether the ray from P along L hits the depth buffer's surfaces within the radius. Rays
// leaving the screen or passing behind the camera count as escaping: nothing is known there.
bool rayOccluded(vec3 P, vec3 L, float jitter) {
    vec2 size = vec2(camera.frameInfo.xy);
    for (uint k = 0u; k < push.steps; ++k) {
        float t = push.radius * (float(k) + jitter) / float(push.steps);
        vec4 clip = clipOf(P + L * t);
        if (clip.w <= 1e-6) return false;
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * size;
        if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, size))) return false;
        float depth = interpolatedDepth(pixel, size);
        if (depth <= 0.0) continue;
        // Reverse-Z, infinite far: clip.z is the near plane distance, depth = near / distance.
        float surfaceDistance = clip.z / depth;
        float behind = clip.w - surfaceDistance;
        if (behind > 2e-3 * surfaceDistance + 1e-3 && behind < push.thickness) return true;
    }
    return false;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec4 gb = texelFetch(gbufferNormalRoughMetal, pixel, 0);
    vec3 N = octDecode(gb.xy);
    if (depth <= 0.0) {
        imageStore(aoOutput, pixel, vec4(N, 1.0));
        imageStore(specularOutput, pixel, vec4(1.0));
        return;
    }
    vec3 P = aoWorldFromDepth(vec2(pixel) + 0.5, depth);
    vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
    // Off the surface by a little more than its depth precision, so it does not hit itself.
    vec3 origin = P + N * (1e-3 * length(camera.cameraPosition.xyz - P));
    mat3 frame = tangentFrame(N);
    vec3 tangentV = transpose(frame) * V;
    tangentV.z = max(tangentV.z, 1e-4);
    float alpha = max(gb.z * gb.z, 1e-3);
    vec2 offset = aoPixelNoise(pixel);
    uint n = push.slices;
    uint escaped = 0u, lobeRays = 0u, lobeEscaped = 0u;
    vec3 bent = vec3(0.0);
    for (uint i = 0u; i < n; ++i) {
        vec2 xi = hammersley(i, n, offset);
        float jitter = fract(offset.x + float(i) * 0.618034);
        vec3 L = frame * cosineSampleHemisphere(xi);
        if (!rayOccluded(origin, L, jitter)) {
            escaped += 1u;
            bent += L;
        }
        vec3 H = importanceSampleGgxVisible(xi, alpha, tangentV);
        vec3 R = 2.0 * dot(tangentV, H) * H - tangentV;
        if (R.z > 0.0) {
            lobeRays += 1u;
            if (!rayOccluded(origin, frame * R, jitter)) lobeEscaped += 1u;
        }
    }
    bent = escaped > 0u ? normalize(bent) : N;
    imageStore(aoOutput, pixel, vec4(bent, float(escaped) / float(n)));
    imageStore(specularOutput, pixel,
               vec4(lobeRays > 0u ? float(lobeEscaped) / float(lobeRays) : 1.0));
}
