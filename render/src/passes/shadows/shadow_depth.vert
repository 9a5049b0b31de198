#version 460
// Shadow depth: a caster's positions through one shadow view (light view-projection x world,
// multiplied on the CPU per draw and view). Depth only; the fragment stage writes nothing.
layout(location = 0) in vec3 inPosition;

layout(push_constant) uniform Draw {
    mat4 worldToShadowClip;
} draw;

void main() {
    gl_Position = draw.worldToShadowClip * vec4(inPosition, 1.0);
}
