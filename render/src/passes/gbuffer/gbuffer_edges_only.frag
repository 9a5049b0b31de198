#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/gbaa_edges.glsl"
// GBAA's edge target alone (GBufferPass::recordEdges), for frames whose G-buffer already has
// the anisotropy and clear-coat targets: with those, the edge target would be a ninth colour
// attachment, over the eight devices guarantee (lavapipe's maxColorAttachments). The opaque
// draws are drawn again after the G-buffer pass, depth test equal, so each pixel gets the
// edges of the triangle the G-buffer holds there.

layout(location = 7) flat in vec3 inEdgeLines[3];  // gbuffer_edges.geom
layout(location = 0) out vec4 outEdges;            // gbuffer.edges (gbuffer_targets.h)

void main() {
    outEdges = gbaaEdgeDistances(gl_FragCoord.xy, inEdgeLines);
}
