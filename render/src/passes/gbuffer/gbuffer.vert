#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/camera.glsl"
// The vertex stage of every mesh pass (G-buffer, forward transparency and its occupancy).
// Besides the jittered position it passes on where the vertex is in clip space this frame and
// was last frame, both without jitter, for the motion vectors (motion_vectors.glsl).

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
// Last frame's position (mesh_vertex_input.h): an animated draw's previous deformed vertex,
// else the same as inPosition.
layout(location = 6) in vec3 inPreviousPosition;

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
} draw;

// One matrix per draw, indexed by gl_InstanceIndex (= the draw's firstInstance).
layout(std430, binding = PREVIOUS_WORLDS_BINDING) readonly buffer PreviousWorlds {
    mat4 previousWorlds[];
};

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec4 outTangent;
layout(location = 2) out vec2 outUv0;
layout(location = 3) out vec2 outUv1;
layout(location = 4) out vec4 outColor;
layout(location = 5) out vec4 outCurrentClip;
layout(location = 6) out vec4 outPreviousClip;

void main() {
    vec4 worldPosition = draw.world * vec4(inPosition, 1.0);
    // Inverse transpose keeps normals perpendicular under non-uniform scale.
    mat3 normalMatrix = transpose(inverse(mat3(draw.world)));
    outNormal = normalMatrix * inNormal;
    outTangent = vec4(mat3(draw.world) * inTangent.xyz, inTangent.w);
    outUv0 = inUv0;
    outUv1 = inUv1;
    outColor = inColor;
    gl_Position = camera.viewProjection * worldPosition;
    // Skinned and morphed meshes move by their deformation too: last frame's deformed
    // position (render/README.md "Motion vectors"); rigid ones only by their world matrix.
    vec3 previousLocalPosition = inPreviousPosition;
    outCurrentClip = camera.unjitteredViewProjection * worldPosition;
    outPreviousClip = camera.previousViewProjection *
                      (previousWorlds[gl_InstanceIndex] * vec4(previousLocalPosition, 1.0));
}
