#include "candela/content/skinning.h"

#include <cmath>

namespace candela::content {

void deformPrimitive(const Primitive& primitive, std::span<const ecs::Mat4> jointMatrices,
                     std::span<const float> morphWeights, DeformedVertices& out) {
    const std::size_t count = primitive.positions.size();
    out.positions.resize(count);
    out.normals.resize(count);
    const bool hasTangents = primitive.tangents.size() == count;
    out.tangents.resize(hasTangents ? count : 0);
    const bool skinned = !jointMatrices.empty() && primitive.joints.size() == count;
    for (std::size_t v = 0; v < count; ++v) {
        ecs::Vec3 p{primitive.positions[v][0], primitive.positions[v][1],
                    primitive.positions[v][2]};
        ecs::Vec3 n{primitive.normals[v][0], primitive.normals[v][1], primitive.normals[v][2]};
        ecs::Vec3 tangent{};
        if (hasTangents)
            tangent = {primitive.tangents[v][0], primitive.tangents[v][1],
                       primitive.tangents[v][2]};
        for (std::size_t t = 0; t < primitive.morphTargets.size() && t < morphWeights.size(); ++t) {
            const MorphTarget& target = primitive.morphTargets[t];
            const float w = morphWeights[t];
            if (!target.positionDeltas.empty())
                p += ecs::Vec3{target.positionDeltas[v][0], target.positionDeltas[v][1],
                               target.positionDeltas[v][2]} *
                     w;
            if (!target.normalDeltas.empty())
                n += ecs::Vec3{target.normalDeltas[v][0], target.normalDeltas[v][1],
                               target.normalDeltas[v][2]} *
                     w;
            if (hasTangents && !target.tangentDeltas.empty())
                tangent += ecs::Vec3{target.tangentDeltas[v][0], target.tangentDeltas[v][1],
                                     target.tangentDeltas[v][2]} *
                           w;
        }
        if (skinned) {
            ecs::Vec3 sp{}, sn{}, st{};
            for (int c = 0; c < 4; ++c) {
                const float w = primitive.weights[v][c];
                if (w == 0) continue;
                if (primitive.joints[v][c] >= jointMatrices.size()) continue;
                const ecs::Mat4& m = jointMatrices[primitive.joints[v][c]];
                sp += m.transformPoint(p) * w;
                sn += m.transformVector(n) * w;  // exact for rigid joints; renormalised below
                st += m.transformVector(tangent) * w;
            }
            p = sp;
            n = sn;
            tangent = st;
        }
        const float length = ecs::length(n);
        if (length > 1e-20f) n *= 1.0f / length;
        out.positions[v] = {p.x, p.y, p.z};
        out.normals[v] = {n.x, n.y, n.z};
        if (hasTangents) {
            const float tangentLength = ecs::length(tangent);
            if (tangentLength > 1e-20f) tangent *= 1.0f / tangentLength;
            out.tangents[v] = {tangent.x, tangent.y, tangent.z, primitive.tangents[v][3]};
        }
    }
}

}  // namespace candela::content
