#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/clusters.glsl"
#include "hair_bindings.h"
#include "hair_segment.glsl"
// Hair writes depth after it is drawn (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time
// Hair Rendering"), so later passes (blended surfaces, depth effects) see it: where the pixel's
// strands together are at least half opaque (1 - prod(1 - coverage) >= 1/2, independent of the
// list's order), the nearest strand's depth. Thinner hair leaves the depth as it was. Every strand
// passed the scene's depth test in the fill, so the nearest is never behind what the depth held.

void main() {
    uint node = heads[pixelIndex(gl_FragCoord.xy)];
    float transmittance = 1.0;
    float nearest = 0.0;  // reverse-Z: larger is nearer
    for (uint walked = 0u; node != HAIR_LIST_END && walked < HAIR_MAX_WALK; ++walked) {
        const uvec4 n = nodes[node];
        nearest = max(nearest, uintBitsToFloat(n.x));
        transmittance *= 1.0 - uintBitsToFloat(n.z);
        node = n.w;
    }
    if (transmittance > 0.5) discard;
    gl_FragDepth = nearest;
}
