#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/camera.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
} draw;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec4 outTangent;
layout(location = 2) out vec2 outUv0;
layout(location = 3) out vec2 outUv1;
layout(location = 4) out vec4 outColor;

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
}
