#version 460
#extension GL_GOOGLE_include_directive : require
#include "gbaa_bindings.h"
// GBAA's resolve (geometry buffer antialiasing, after Persson 2011; render/README.md "GBAA"):
// each pixel is blended with its neighbour across the triangle edge that the G-buffer pass
// found within it (gbuffer.edges, common/gbaa_edges.glsl), by the fraction of the pixel that
// lies beyond the edge, 0.5 - |offset|. A silhouette's edge is only in the G-buffer on the
// side its triangle covers: a pixel whose own triangle has no edge within half a pixel looks
// at its four neighbours for one whose edge reaches into it (an offset between 0.5 and 1
// towards it). With an edge along x and one along y (a corner) the pixel takes the bilinear
// mix of its 2x2 neighbourhood those two fractions give, which is the coverage of a corner
// whose sides follow the pixel's axes.
// The blend is in HDR radiance, before exposure and tonemapping: a pixel then holds the
// coverage-weighted radiance of the surfaces in it, what a supersampled frame resolved in
// linear light (and TAA) gives it.
#include "common/gbaa_edges.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = GBAA_BINDING_HDR, rgba32f) uniform readonly image2D hdr;
layout(binding = GBAA_BINDING_EDGES) uniform sampler2D edges;
layout(binding = GBAA_BINDING_RESOLVED, rgba32f) uniform writeonly image2D resolved;

ivec2 size;

vec2 edgesAt(ivec2 pixel) {
    return texelFetch(edges, clamp(pixel, ivec2(0), size - 1), 0).xy;
}

vec4 radianceAt(ivec2 pixel) {
    return imageLoad(hdr, clamp(pixel, ivec2(0), size - 1));
}

// The offset of the edge that crosses this pixel along one axis, from the pixel's own
// triangle (`own`) or else from the neighbours before (`before`, at -1) and after (`after`,
// at +1) along that axis; GBAA_NO_EDGE when none does.
float edgeOffset(float own, float before, float after) {
    if (abs(own) < 0.5) return own;
    float offset = GBAA_NO_EDGE;
    // The neighbour before stores +0.5..1 for an edge inside this pixel: -0.5..0 from here.
    if (before >= 0.5 && before < 1.0) offset = before - 1.0;
    if (after <= -0.5 && after > -1.0 && after + 1.0 < abs(offset)) offset = after + 1.0;
    return offset;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    size = imageSize(hdr);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 own = edgesAt(pixel);
    float offsetX = edgeOffset(own.x, edgesAt(pixel + ivec2(-1, 0)).x,
                               edgesAt(pixel + ivec2(1, 0)).x);
    float offsetY = edgeOffset(own.y, edgesAt(pixel + ivec2(0, -1)).y,
                               edgesAt(pixel + ivec2(0, 1)).y);
    // The fraction beyond each edge, and which way the neighbour across it lies.
    float beyondX = abs(offsetX) < 0.5 ? 0.5 - abs(offsetX) : 0.0;
    float beyondY = abs(offsetY) < 0.5 ? 0.5 - abs(offsetY) : 0.0;
    ivec2 step = ivec2(offsetX < 0.0 ? -1 : 1, offsetY < 0.0 ? -1 : 1);
    vec4 centre = radianceAt(pixel);
    vec3 result = centre.rgb;
    if (beyondX > 0.0 || beyondY > 0.0) {
        vec3 acrossX = radianceAt(pixel + ivec2(step.x, 0)).rgb;
        vec3 acrossY = radianceAt(pixel + ivec2(0, step.y)).rgb;
        vec3 diagonal = radianceAt(pixel + step).rgb;
        result = mix(mix(centre.rgb, acrossX, beyondX), mix(acrossY, diagonal, beyondX), beyondY);
    }
    imageStore(resolved, pixel, vec4(result, centre.a));
}
