// GBAA (geometry buffer antialiasing, Persson 2011): where a triangle's edges lie relative to a
// pixel, from the triangle's three clip-space corners. The geometry stage turns the corners
// into the edges' lines in pixel coordinates (gbaaEdgeLine); each fragment then measures how
// far its centre is from each line along the axis that crosses the line more squarely
// (gbaaEdgeOffsets): that is the offset the resolve (passes/gbaa/gbaa.comp) needs, since the
// fraction of a pixel that lies beyond a line is 0.5 - |offset| for any line that crosses both
// of the pixel's sides along the other axis.
#ifndef CANDELA_GBAA_EDGES_GLSL
#define CANDELA_GBAA_EDGES_GLSL

#include "common/gbaa_edges.h"

// The line through two clip-space corners in pixel coordinates (x right, y down, pixel
// centres at +0.5 like gl_FragCoord), as (a, b, c) with a x + b y + c = 0 and (a, b) of unit
// length. Homogeneous, so a corner behind the camera (w < 0) still gives the line its visible
// part lies on; an edge with both corners behind the camera is never visible and gets no line
// (0, 0, 1), which no offset reaches.
vec3 gbaaEdgeLine(vec4 clipA, vec4 clipB, vec2 targetSize) {
    if (clipA.w <= 0.0 && clipB.w <= 0.0) return vec3(0.0, 0.0, 1.0);
    // Pixel position x = (clip.x / clip.w + 1) * width / 2, homogeneous in (x, y, w).
    vec2 halfSize = 0.5 * targetSize;
    vec3 a = vec3((clipA.xy + clipA.w) * halfSize, clipA.w);
    vec3 b = vec3((clipB.xy + clipB.w) * halfSize, clipB.w);
    vec3 line = cross(a, b);
    float len = length(line.xy);
    return len > 0.0 ? line / len : vec3(0.0, 0.0, 1.0);
}

// Distances in pixels from `pixel` to the triangle's nearest edge on each side, each edge
// measured along the axis that crosses it more squarely: (left, right) along the row to the
// nearest lines closer to vertical (|a| >= |b|), (up, down) along the column to those closer
// to horizontal; GBAA_NO_EDGE where none lies within 1.5 pixels. Both sides, not just the
// nearest edge: a face one pixel wide (a pillar's side seen at a grazing angle) has its two
// edges in one pixel. Beyond half a pixel, so that the neighbour an edge reaches into can find
// it there (gbaa.comp).
vec4 gbaaEdgeDistances(vec2 pixel, vec3 lines[3]) {
    vec4 distances = vec4(GBAA_NO_EDGE);
    for (int i = 0; i < 3; ++i) {
        vec3 line = lines[i];
        float value = dot(line, vec3(pixel, 1.0));
        if (abs(line.x) >= abs(line.y)) {
            if (line.x == 0.0) continue;  // no line
            float offset = -value / line.x;
            if (offset < 0.0) distances.x = min(distances.x, -offset);
            else distances.y = min(distances.y, offset);
        } else {
            float offset = -value / line.y;
            if (offset < 0.0) distances.z = min(distances.z, -offset);
            else distances.w = min(distances.w, offset);
        }
    }
    return mix(distances, vec4(GBAA_NO_EDGE), greaterThanEqual(distances, vec4(1.5)));
}

#endif
