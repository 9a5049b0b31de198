#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/camera.glsl"
#include "common/gbaa_edges.glsl"
// GBAA's geometry stage (--aa gbaa only; render/README.md "GBAA"): passes gbuffer.vert's
// outputs through unchanged and gives every fragment of the triangle the triangle's three
// edges as lines in pixel coordinates, so the fragment stage can write how far its pixel is
// from the nearest one (gbaaEdgeOffsets). The device has no fragment-shader barycentrics
// (lavapipe), and the fragment stage alone cannot see the other corners.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec3 inNormal[];
layout(location = 1) in vec4 inTangent[];
layout(location = 2) in vec2 inUv0[];
layout(location = 3) in vec2 inUv1[];
layout(location = 4) in vec4 inColor[];
layout(location = 5) in vec4 inCurrentClip[];
layout(location = 6) in vec4 inPreviousClip[];

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec4 outTangent;
layout(location = 2) out vec2 outUv0;
layout(location = 3) out vec2 outUv1;
layout(location = 4) out vec4 outColor;
layout(location = 5) out vec4 outCurrentClip;
layout(location = 6) out vec4 outPreviousClip;
layout(location = 7) flat out vec3 outEdgeLines[3];

void main() {
    const vec2 targetSize = vec2(camera.frameInfo.xy);
    vec3 lines[3];
    for (int i = 0; i < 3; ++i)
        lines[i] = gbaaEdgeLine(gl_in[i].gl_Position, gl_in[(i + 1) % 3].gl_Position, targetSize);
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        outNormal = inNormal[i];
        outTangent = inTangent[i];
        outUv0 = inUv0[i];
        outUv1 = inUv1[i];
        outColor = inColor[i];
        outCurrentClip = inCurrentClip[i];
        outPreviousClip = inPreviousClip[i];
        outEdgeLines = lines;
        EmitVertex();
    }
    EndPrimitive();
}
