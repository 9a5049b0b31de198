#version 460
#extension GL_GOOGLE_include_directive : require
#include "gbaa_bindings.h"
// GBAA's resolve (geometry buffer antialiasing, after Persson 2011; render/README.md "GBAA"):
// each pixel is blended with its neighbours across the edges of its triangle that the
// G-buffer pass found within it (gbuffer.edges, common/gbaa_edges.glsl), each by the fraction
// of the pixel that lies beyond that edge, 0.5 - distance. A silhouette's edge is only in the
// G-buffer on the side its triangle covers: where a pixel's own triangle has no edge within
// half a pixel on one side, the neighbour on that side may have one that reaches into it (a
// distance between 0.5 and 1.5 towards it), covering distance - 0.5 of it. The fractions
// along x and along y combine as a product (a 3x3 tensor of weights), which is the coverage of
// a corner whose sides follow the pixel's axes.
// The blend is in HDR radiance, before exposure and tonemapping: a pixel then holds the
// coverage-weighted radiance of the surfaces in it, what a supersampled frame resolved in
// linear light (and TAA) gives it.
#include "common/gbaa_edges.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = GBAA_BINDING_HDR, rgba32f) uniform readonly image2D hdr;
layout(binding = GBAA_BINDING_EDGES) uniform sampler2D edges;
layout(binding = GBAA_BINDING_RESOLVED, rgba32f) uniform writeonly image2D resolved;

ivec2 size;

// (left, right, up, down) distances; none outside the target.
vec4 edgesAt(ivec2 pixel) {
    if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size)))
        return vec4(GBAA_NO_EDGE);
    return texelFetch(edges, pixel, 0);
}

vec3 radianceAt(ivec2 pixel) {
    return imageLoad(hdr, clamp(pixel, ivec2(0), size - 1)).rgb;
}

// The fraction of this pixel on one side that belongs to the neighbour there: beyond this
// pixel's own edge on that side (`own`, its distance), or else covered by the neighbour's
// triangle reaching in (`neighbours`, the neighbour's distance to its edge on this side).
float beyond(float own, float neighbours) {
    if (own < 0.5) return 0.5 - own;
    return neighbours > 0.5 && neighbours < 1.5 ? neighbours - 0.5 : 0.0;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    size = imageSize(hdr);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 own = edgesAt(pixel);
    // Weights of the columns -1, 0, +1 and of the rows -1, 0, +1.
    vec3 wx = vec3(beyond(own.x, edgesAt(pixel + ivec2(-1, 0)).y), 0.0,
                   beyond(own.y, edgesAt(pixel + ivec2(1, 0)).x));
    vec3 wy = vec3(beyond(own.z, edgesAt(pixel + ivec2(0, -1)).w), 0.0,
                   beyond(own.w, edgesAt(pixel + ivec2(0, 1)).z));
    // Neighbours reaching in from both sides past each other: share the pixel between them.
    wx /= max(wx.x + wx.z, 1.0);
    wy /= max(wy.x + wy.z, 1.0);
    wx.y = 1.0 - wx.x - wx.z;
    wy.y = 1.0 - wy.x - wy.z;
    vec4 centre = imageLoad(hdr, pixel);
    vec3 result = centre.rgb;
    if (wx.y < 1.0 || wy.y < 1.0) {
        result = vec3(0.0);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                float w = wx[dx + 1] * wy[dy + 1];
                if (w > 0.0) result += w * radianceAt(pixel + ivec2(dx, dy));
            }
        }
    }
    imageStore(resolved, pixel, vec4(result, centre.a));
}
