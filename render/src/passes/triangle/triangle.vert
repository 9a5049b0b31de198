#version 460
// A single triangle from gl_VertexIndex: the smallest scene that exercises the whole path.
layout(push_constant) uniform Push {
    vec4 radiance;  // flat HDR colour, cd/m^2
} push;

const vec2 kCorners[3] = vec2[](vec2(0.0, -0.6), vec2(0.6, 0.6), vec2(-0.6, 0.6));

void main() {
    gl_Position = vec4(kCorners[gl_VertexIndex], 0.5, 1.0);
}
