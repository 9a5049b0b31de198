#version 460
#extension GL_GOOGLE_include_directive : require
#include "ambient_occlusion_bindings.h"
// Temporal accumulation of GTAO's denoised (bent normal, visibility): last frame's result is
// read where this pixel was (uv - motion), bilinearly from the four history texels that
// still show the same surface, and blended with this frame's at 1 / (frames + 1), at least
// 1 / push.maxFrames. GTAO rotates its slices and step offsets every frame, so a still view
// averages many more slice directions than one frame traces.
//
// A history texel shows the same surface when its view depth matches the depth this pixel's
// point had in the previous view (within 3 %) and its G-buffer normal is within ~25 degrees:
// where a moving object uncovered the floor, or the camera revealed what was behind an edge,
// the taps fail and the pixel starts over from this frame's value (no stale occlusion).
//
// History texel (RGBA32UI): x the bent normal (octahedral, 2 x 16 bits), y the surface normal
// (octahedral, 2 x 8 bits) and the accumulated frame count (8 bits), z the visibility
// (float bits), w the view depth (float bits).
#include "common/ambient_occlusion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = AO_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = AO_BINDING_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = AO_BINDING_INPUT) uniform sampler2D currentOcclusion;
layout(binding = AO_BINDING_MOTION) uniform sampler2D motion;
layout(binding = AO_BINDING_HISTORY) uniform usampler2D history;
layout(binding = AO_BINDING_SECOND_OUTPUT, rgba16f) uniform writeonly image2D aoOutput;
layout(binding = AO_BINDING_HISTORY_OUTPUT, rgba32ui) uniform writeonly uimage2D historyOutput;

layout(push_constant) uniform Push {
    uint historyValid;  // 0: first frame, resize, camera cut: start from this frame's value
    uint maxFrames;
} push;

uvec4 packHistory(vec3 bent, vec3 N, float visibility, float frames, float viewDepth) {
    return uvec4(packUnorm2x16(octEncode(bent)),
                 packUnorm4x8(vec4(octEncode(N), frames / 255.0, 0.0)),
                 floatBitsToUint(visibility), floatBitsToUint(viewDepth));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    vec4 current = texelFetch(currentOcclusion, pixel, 0);
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec3 N = octDecode(texelFetch(gbufferNormalRoughMetal, pixel, 0).xy);
    if (depth <= 0.0) {  // sky: nothing to accumulate
        imageStore(aoOutput, pixel, current);
        imageStore(historyOutput, pixel, packHistory(N, N, 1.0, 0.0, 0.0));
        return;
    }
    vec3 P = aoWorldFromDepth(vec2(pixel) + 0.5, depth);
    float viewDepth = clipOf(P).w;
    // Where this point was seen last frame (the point itself for static geometry; a moving
    // object's motion is sideways at most by the depth tolerance below).
    float previousViewDepth = (camera.previousViewProjection * vec4(P, 1.0)).w;

    float frames = 0.0;
    float visibility = 0.0;
    vec3 bent = vec3(0.0);
    if (push.historyValid != 0u) {
        vec2 uv = (vec2(pixel) + 0.5) / vec2(size) - texelFetch(motion, pixel, 0).xy;
        vec2 texel = uv * vec2(size) - 0.5;
        ivec2 base = ivec2(floor(texel));
        vec2 f = texel - vec2(base);
        float weightSum = 0.0;
        float fewestFrames = 255.0;
        for (int i = 0; i < 4; ++i) {
            ivec2 offset = ivec2(i & 1, i >> 1);
            ivec2 q = base + offset;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            float w = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
            if (w <= 0.0) continue;
            uvec4 h = texelFetch(history, q, 0);
            float hDepth = uintBitsToFloat(h.w);
            vec4 packedNormal = unpackUnorm4x8(h.y);
            if (hDepth <= 0.0) continue;  // sky last frame
            if (abs(hDepth - previousViewDepth) > 0.03 * previousViewDepth) continue;
            if (dot(octDecode(packedNormal.xy), N) < 0.9) continue;
            weightSum += w;
            visibility += w * uintBitsToFloat(h.z);
            bent += w * octDecode(unpackUnorm2x16(h.x));
            fewestFrames = min(fewestFrames, round(packedNormal.z * 255.0));
        }
        // Less than a tenth of the footprint still shows this surface: start over.
        if (weightSum > 0.1) {
            visibility /= weightSum;
            bent /= weightSum;
            frames = fewestFrames;
        }
    }
    float blend = 1.0 / min(frames + 1.0, float(max(push.maxFrames, 1u)));
    visibility = mix(visibility, current.w, blend);
    bent = safeNormalize(mix(bent, current.xyz, blend));
    if (dot(bent, N) < 0.05) bent = N;
    frames = min(frames + 1.0, 255.0);
    imageStore(aoOutput, pixel, vec4(bent, visibility));
    imageStore(historyOutput, pixel, packHistory(bent, N, visibility, frames, viewDepth));
}
