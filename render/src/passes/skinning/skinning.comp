#version 460
#extension GL_GOOGLE_include_directive : require
// Skinning and morphing of one animated instance's primitive (render/README.md "Animation"):
// one invocation per vertex reads the bind-pose vertex, adds the weighted morph deltas, blends
// up to four joint matrices (linear blend skinning), renormalises the normal and tangent and
// writes the whole vertex into the instance's vertex buffer, which the G-buffer, shadow and
// forward passes then draw. The CPU reference is content::deformPrimitive.
#include "skinning_bindings.h"

layout(local_size_x = SKINNING_GROUP_SIZE) in;

struct SkinVertex {
    uvec4 joints;
    vec4 weights;
};

layout(std430, binding = SKINNING_BINDING_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = SKINNING_BINDING_SKIN) readonly buffer Skin { SkinVertex skin[]; };
layout(std430, binding = SKINNING_BINDING_MORPH_DELTAS) readonly buffer Morph { vec4 deltas[]; };
layout(std430, binding = SKINNING_BINDING_JOINTS) readonly buffer Joints { mat4 joints[]; };
layout(std430, binding = SKINNING_BINDING_MORPH_WEIGHTS) readonly buffer Weights {
    float weights[];
};
layout(std430, binding = SKINNING_BINDING_TARGET) writeonly buffer Target { float target[]; };

layout(push_constant) uniform Push {
    uint vertexCount;
    uint firstJoint;
    uint jointCount;  // 0: not skinned
    uint firstMorphWeight;
    uint morphTargetCount;  // 0: not morphed
}
push;

vec3 loadVec3(uint base) {
    return vec3(source[base], source[base + 1], source[base + 2]);
}

void main() {
    const uint v = gl_GlobalInvocationID.x;
    if (v >= push.vertexCount) return;
    const uint base = v * SKINNING_VERTEX_FLOATS;
    vec3 p = loadVec3(base);
    vec3 n = loadVec3(base + SKINNING_NORMAL_OFFSET);
    vec3 t = loadVec3(base + SKINNING_TANGENT_OFFSET);
    const float handedness = source[base + SKINNING_TANGENT_OFFSET + 3];

    for (uint m = 0; m < push.morphTargetCount; ++m) {
        const float w = weights[push.firstMorphWeight + m];
        const uint first = m * SKINNING_MORPH_ATTRIBUTES * push.vertexCount + v;
        p += deltas[first].xyz * w;
        n += deltas[first + push.vertexCount].xyz * w;
        t += deltas[first + 2 * push.vertexCount].xyz * w;
    }

    if (push.jointCount > 0) {
        const SkinVertex s = skin[v];
        vec3 sp = vec3(0.0), sn = vec3(0.0), st = vec3(0.0);
        for (int c = 0; c < 4; ++c) {
            const float w = s.weights[c];
            if (w == 0.0 || s.joints[c] >= push.jointCount) continue;
            const mat4 j = joints[push.firstJoint + s.joints[c]];
            sp += (j * vec4(p, 1.0)).xyz * w;
            sn += mat3(j) * n * w;  // exact for rigid joints; renormalised below
            st += mat3(j) * t * w;
        }
        p = sp;
        n = sn;
        t = st;
    }
    const float normalLength = length(n);
    if (normalLength > 1e-20) n /= normalLength;
    const float tangentLength = length(t);
    if (tangentLength > 1e-20) t /= tangentLength;

    target[base] = p.x;
    target[base + 1] = p.y;
    target[base + 2] = p.z;
    target[base + SKINNING_NORMAL_OFFSET] = n.x;
    target[base + SKINNING_NORMAL_OFFSET + 1] = n.y;
    target[base + SKINNING_NORMAL_OFFSET + 2] = n.z;
    target[base + SKINNING_TANGENT_OFFSET] = t.x;
    target[base + SKINNING_TANGENT_OFFSET + 1] = t.y;
    target[base + SKINNING_TANGENT_OFFSET + 2] = t.z;
    target[base + SKINNING_TANGENT_OFFSET + 3] = handedness;
    for (uint i = SKINNING_TANGENT_OFFSET + 4; i < SKINNING_VERTEX_FLOATS; ++i)
        target[base + i] = source[base + i];
}
