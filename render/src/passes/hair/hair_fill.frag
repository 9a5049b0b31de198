#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/clusters.glsl"
#include "common/screen_segment.glsl"
#include "hair_bindings.h"
#include "hair_segment.glsl"
// The A-buffer fill (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"):
// every strand fragment in front of the scene's depth (tested before this shader runs) is pushed
// onto its pixel's linked list, unsorted and unshaded: its depth, segment and coverage (GPAA: the
// distance to the strand's edge, common/screen_segment.glsl). Colour, order and light come in
// hair_resolve.frag. A full node pool drops the fragment; the counter still counts it, so --stats
// shows how many were lost.
layout(early_fragment_tests) in;

layout(std430, binding = HAIR_BINDING_COUNTERS) buffer Counters {
    uint requested;  // nodes asked for this frame (more than the pool: some were dropped)
} counters;

layout(location = 0) flat in vec4 inEndsPx;
layout(location = 1) flat in vec2 inHalfWidthPx;
layout(location = 2) flat in uint inSegment;
layout(location = 3) flat in float inPixelStep;

void main() {
    const vec2 place = pixelPlaceOnSegment(gl_FragCoord.xy, inEndsPx);
    const float halfWidthPx = mix(inHalfWidthPx.x, inHalfWidthPx.y, place.y);
    const float coverage = segmentCoverage(place.x, halfWidthPx, inPixelStep);
    if (!(coverage > 0.0)) return;
    const uint node = atomicAdd(counters.requested, 1u);
    if (node >= draw.nodeCapacity) return;
    nodes[node].xyz = uvec3(floatBitsToUint(gl_FragCoord.z), inSegment, floatBitsToUint(coverage));
    nodes[node].w = atomicExchange(heads[pixelIndex(gl_FragCoord.xy)], node);
}
