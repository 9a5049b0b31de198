#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/screen_segment.glsl"
#include "wire_bindings.h"
#include "wire_segment.glsl"
// Wire antialiasing (Persson 2014, GPU Pro 5, "Wire Antialiasing": his "phone-wire AA"): each
// segment becomes a camera-facing quad, six vertices per segment, no vertex buffer. Its radius is
// clamped to at least one pixel's radius at the wire's depth (so it never falls between pixel
// centres and never flickers) and the alpha is multiplied by real radius / clamped radius (so its
// energy, width x radiance, stays the real wire's). The quad reaches one pixel past the clamped
// edge for the coverage ramp wire.frag computes from the distance to the centre line.

// The segment on screen and its width at each end, all flat: wire.frag measures each pixel's
// distance to the centre line from gl_FragCoord itself rather than from interpolated values,
// because lavapipe's clipper interpolates noperspective values by the ratio of the ends'
// screen coordinates along the first axis on which their clip coordinates differ, 0 / 0 for
// an edge of the quad that is vertical on screen (a wire in the vertical plane of a pitched
// camera: clip x differs with w, x / w does not), which gave NaN coverage.
layout(location = 0) flat out vec4 outEndsPx;       // xy start, zw end (pixels)
layout(location = 1) flat out vec2 outHalfWidthPx;  // the clamped radius in pixels at each end
layout(location = 2) flat out vec2 outFade;         // real / clamped radius at each end
layout(location = 4) flat out uint outSegment;
// The distance across the wire between neighbouring pixel centres along the screen axis the
// wire runs less along (1 for a horizontal or vertical wire, 1/sqrt(2) at 45 degrees):
// wire.frag's box width.
layout(location = 5) flat out float outPixelStep;

void main() {
    const uint segment = uint(gl_VertexIndex) / 6u;
    const vec2 corner = kSegmentQuadCorners[uint(gl_VertexIndex) % 6u];
    const WireSegment s = segments[segment];
    outSegment = segment;
    vec4 c0 = camera.viewProjection * vec4(s.start.xyz, 1.0);
    vec4 c1 = camera.viewProjection * vec4(s.end.xyz, 1.0);
    vec2 range;
    if (!clipSegmentToView(c0, c1, draw.nearPlane, range)) {
        gl_Position = vec4(0.0, 0.0, -1.0, 1.0);
        outEndsPx = vec4(0.0);
        outHalfWidthPx = vec2(0.0);
        outFade = vec2(0.0);
        outPixelStep = 1.0;
        return;
    }

    vec2 along = clipToPixels(c1, draw.targetSize) - clipToPixels(c0, draw.targetSize);
    along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
    const vec2 across = vec2(-along.y, along.x);
    outPixelStep = segmentPixelStep(along);

    // Both ends' widths in every vertex, so the flat values do not depend on the provoking one.
    const float radius = s.start.w;
    vec2 halfWidthPx, fade;
    for (int end = 0; end < 2; ++end) {
        // A pixel's radius in metres at this depth (half the pixel's footprint).
        const float pixelRadius = (end == 0 ? c0.w : c1.w) * draw.pixelRadiusPerDepth;
        float clamped = max(radius, pixelRadius);
        fade[end] = radius / clamped;
        if (draw.mode == WIRE_MODE_NAIVE) {
            clamped = pixelRadius;  // a line one pixel wide whatever the wire's width
            fade[end] = 1.0;
        }
        halfWidthPx[end] = 0.5 * clamped / pixelRadius;
    }
    const int end = corner.x > 0.5 ? 1 : 0;
    vec4 clip = end == 1 ? c1 : c0;
    const float extentPx = draw.mode == WIRE_MODE_NAIVE ? halfWidthPx[end] : halfWidthPx[end] + 1.0;
    clip.xy += across * (corner.y * extentPx) * (2.0 / draw.targetSize) * clip.w;
    gl_Position = clip;
    outEndsPx = vec4(clipToPixels(c0, draw.targetSize), clipToPixels(c1, draw.targetSize));
    outHalfWidthPx = halfWidthPx;
    outFade = fade;
}
