#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/screen_segment.glsl"
#include "hair_bindings.h"
// The vertex stage writes no storage (the lists are the fragment stage's).
#define HAIR_NO_LISTS
#include "hair_segment.glsl"
// Hair geometry (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): each
// strand segment becomes a camera-facing quad, six vertices per segment and no vertex buffer. Its
// half width is the strand's radius at each end projected at that end's depth (the world-space
// expansion), and the quad reaches a further sqrt(2)/2 px beyond it on screen so that even a strand
// far thinner than a pixel covers every pixel centre whose box it touches: hair_fill.frag turns the
// distance to the centre line into coverage. The shared pieces (clipping, pixels, coverage) are the
// wire pass's (common/screen_segment.glsl).

layout(location = 0) flat out vec4 outEndsPx;       // xy start, zw end (pixels)
layout(location = 1) flat out vec2 outHalfWidthPx;  // the real radius in pixels at each end
layout(location = 2) flat out uint outSegment;
layout(location = 3) flat out float outPixelStep;   // the coverage box's width

const float kScreenExpansionPx = 0.70710678;  // sqrt(2) / 2

void main() {
    const uint segment = uint(gl_VertexIndex) / 6u;
    const vec2 corner = kSegmentQuadCorners[uint(gl_VertexIndex) % 6u];
    const HairSegment s = hairSegment(segment);
    outSegment = segment;
    vec4 c0 = camera.viewProjection * vec4(s.start.xyz, 1.0);
    vec4 c1 = camera.viewProjection * vec4(s.end.xyz, 1.0);
    vec2 range;
    if (!clipSegmentToView(c0, c1, draw.nearPlane, range)) {
        gl_Position = vec4(0.0, 0.0, -1.0, 1.0);
        outEndsPx = vec4(0.0);
        outHalfWidthPx = vec2(0.0);
        outPixelStep = 1.0;
        return;
    }
    vec2 along = clipToPixels(c1, draw.targetSize) - clipToPixels(c0, draw.targetSize);
    along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
    const vec2 across = vec2(-along.y, along.x);
    outPixelStep = segmentPixelStep(along);
    // Both ends' widths in every vertex, so the flat values do not depend on the provoking one.
    vec2 halfWidthPx;
    for (int end = 0; end < 2; ++end) {
        const float radius = mix(s.start.w, s.end.w, range[end]);
        // A pixel's radius in metres at this depth (half the pixel's footprint).
        const float pixelRadius = (end == 0 ? c0.w : c1.w) * draw.pixelRadiusPerDepth;
        halfWidthPx[end] = 0.5 * radius / pixelRadius;
    }
    const int end = corner.x > 0.5 ? 1 : 0;
    vec4 clip = end == 1 ? c1 : c0;
    const float extentPx = halfWidthPx[end] + kScreenExpansionPx;
    clip.xy += across * (corner.y * extentPx) * (2.0 / draw.targetSize) * clip.w;
    gl_Position = clip;
    outEndsPx = vec4(clipToPixels(c0, draw.targetSize), clipToPixels(c1, draw.targetSize));
    outHalfWidthPx = halfWidthPx;
}
