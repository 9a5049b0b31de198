#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/clusters.glsl"
#include "hair_bindings.h"
// The vertex stage writes no storage.
#define HAIR_NO_LISTS
#include "hair_segment.glsl"
#include "common/shadows.glsl"
#include "common/screen_segment.glsl"
// The hair depth map (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering",
// self-shadowing): each strand segment as a quad facing the light, drawn into shadow view
// draw.shadowView's tile of a depth image laid out as the shadow atlas, so the resolve finds a
// point's first hair where it finds its opaque blocker. The quad is the strand's radius wide at
// each end plus sqrt(2)/2 texel, so a strand thinner than a texel still marks every texel it
// touches (the hair fill's expansion, in shadow texels). The depth test keeps the nearest strand
// whatever the order of the segments.

const float kExpansionTexels = 0.70710678;  // sqrt(2) / 2

// Metres from the light along the view's axis of a clip position.
float viewDepth(ShadowView v, vec4 clip) {
    return uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC
               ? v.params.w - clip.z * (v.params.w - v.params.z)
               : clip.w;
}

void main() {
    const uint segment = uint(gl_VertexIndex) / 6u;
    const vec2 corner = kSegmentQuadCorners[uint(gl_VertexIndex) % 6u];
    const HairSegment s = hairSegment(segment);
    const ShadowView v = shadowViews[draw.shadowView];
    const vec4 c0 = v.worldToClip * vec4(s.start.xyz, 1.0);
    const vec4 c1 = v.worldToClip * vec4(s.end.xyz, 1.0);
    // A perspective view (spot, cube face) leaves out a segment reaching behind its near
    // plane: such a segment lies beside the light, in another face or outside the cone.
    if (uint(v.params.y) == SHADOW_KIND_PERSPECTIVE && min(c0.w, c1.w) < v.params.z) {
        gl_Position = vec4(0.0, 0.0, -1.0, 1.0);
        return;
    }
    const float texelsPerNdc = 0.5 * v.tile.z;
    vec2 along = (c1.xy / c1.w - c0.xy / c0.w) * texelsPerNdc;
    along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
    const vec2 across = vec2(-along.y, along.x);
    const bool atEnd = corner.x > 0.5;
    vec4 clip = atEnd ? c1 : c0;
    const float radius = atEnd ? s.end.w : s.start.w;
    const float halfWidthTexels =
        radius / shadowTexelWorld(v, max(viewDepth(v, clip), 1e-4)) + kExpansionTexels;
    clip.xy += across * (corner.y * halfWidthTexels / texelsPerNdc) * clip.w;
    // A cascade's depth range is fitted to the opaque casters: hair beyond it is flattened
    // onto its near or far plane (kept, in its texels) rather than clipped away.
    if (uint(v.params.y) == SHADOW_KIND_ORTHOGRAPHIC) clip.z = clamp(clip.z, 0.0, 1.0);
    gl_Position = clip;
}
