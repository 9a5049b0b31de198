// Thin segments drawn as camera-facing quads (wires, Persson 2014, GPU Pro 5, "Wire Antialiasing";
// hair strands, Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): the
// segment clipped to what the quad may cover, its ends in pixels, and the coverage of a pixel from
// its distance to the centre line (geometric antialiasing).
#ifndef CANDELA_SCREEN_SEGMENT_GLSL
#define CANDELA_SCREEN_SEGMENT_GLSL

// Narrows `range` (parameters along the segment) to where the plane distance, linear from d0
// at the start to d1 at the end, is >= 0.
void clipSegment(float d0, float d1, inout vec2 range) {
    if (d0 < 0.0 && d1 < 0.0) {
        range = vec2(1.0, 0.0);
    } else if (d0 < 0.0) {
        range.x = max(range.x, d0 / (d0 - d1));
    } else if (d1 < 0.0) {
        range.y = min(range.y, d0 / (d0 - d1));
    }
}

// Clip coordinates are linear along the segment: keeps the part in front of the near plane
// (clip.w is the view depth) and within half a screen of the view on each side, so the
// rasteriser never clips a quad itself (lavapipe's clipper returns NaN attributes for these
// slivers) and far-off ends keep their precision. False: nothing is left. `range` receives
// the kept part's parameters along the original segment.
bool clipSegmentToView(inout vec4 c0, inout vec4 c1, float nearPlane, out vec2 range) {
    range = vec2(0.0, 1.0);
    const float kSides = 2.0;  // |x|, |y| <= 2 w: half a screen beyond each edge
    clipSegment(c0.w - nearPlane, c1.w - nearPlane, range);
    clipSegment(kSides * c0.w - c0.x, kSides * c1.w - c1.x, range);
    clipSegment(kSides * c0.w + c0.x, kSides * c1.w + c1.x, range);
    clipSegment(kSides * c0.w - c0.y, kSides * c1.w - c1.y, range);
    clipSegment(kSides * c0.w + c0.y, kSides * c1.w + c1.y, range);
    if (!(range.x < range.y)) return false;
    const vec4 start = mix(c0, c1, range.x);
    c1 = mix(c0, c1, range.y);
    c0 = start;
    return true;
}

vec2 clipToPixels(vec4 clip, vec2 targetSize) {
    return (clip.xy / clip.w * 0.5 + 0.5) * targetSize;
}

// Two triangles: (end, side) of each of a quad's six vertices.
const vec2 kSegmentQuadCorners[6] =
    vec2[](vec2(0, -1), vec2(1, -1), vec2(1, 1), vec2(0, -1), vec2(1, 1), vec2(0, 1));

// The distance across the segment between neighbouring pixel centres along the screen axis
// it runs less along (1 for a horizontal or vertical segment, 1/sqrt(2) at 45 degrees).
float segmentPixelStep(vec2 alongPx) {
    return max(abs(alongPx.x), abs(alongPx.y));
}

// A pixel centre's place relative to a segment given by its ends in pixels: x the distance to
// the centre line, y the parameter along the segment (clamped to [0, 1]). Measured from
// gl_FragCoord itself rather than interpolated values: lavapipe's clipper interpolates
// noperspective values by the ratio of the ends' screen coordinates along the first axis on
// which their clip coordinates differ, 0 / 0 for a quad edge vertical on screen.
vec2 pixelPlaceOnSegment(vec2 pixel, vec4 endsPx) {
    const vec2 fromStart = pixel - endsPx.xy;
    const vec2 line = endsPx.zw - endsPx.xy;
    const float lengthSquared = dot(line, line);
    const vec2 along = lengthSquared > 1e-12 ? line * inversesqrt(lengthSquared) : vec2(1.0, 0.0);
    const float distancePx = abs(dot(fromStart, vec2(-along.y, along.x)));
    const float t =
        lengthSquared > 1e-12 ? clamp(dot(fromStart, line) / lengthSquared, 0.0, 1.0) : 0.0;
    return vec2(distancePx, t);
}

// Coverage (GPAA): the overlap of the width [-h, h] with a box across the segment centred on
// the pixel, as wide as the step b between neighbouring pixel centres across it, over b. The
// boxes of a column (a row, for a segment steeper than 45 degrees) tile the line without gap
// or overlap, so the coverages sum to the cross-section 2h / b wherever it lies.
float segmentCoverage(float distancePx, float halfWidthPx, float b) {
    const float overlap =
        min(distancePx + 0.5 * b, halfWidthPx) - max(distancePx - 0.5 * b, -halfWidthPx);
    return clamp(overlap / b, 0.0, 1.0);
}

#endif
