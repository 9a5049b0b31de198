#include "primitive_vertices.h"

#include <cmath>

namespace candela::content {
namespace {

template <typename T>
void copyElement(std::vector<T>& stream, std::uint32_t index) {
    if (!stream.empty()) stream.push_back(stream[index]);
}

}  // namespace

std::uint32_t appendVertexCopy(Primitive& p, std::uint32_t index) {
    copyElement(p.positions, index);
    copyElement(p.normals, index);
    copyElement(p.tangents, index);
    copyElement(p.uv0, index);
    copyElement(p.uv1, index);
    copyElement(p.colors, index);
    copyElement(p.joints, index);
    copyElement(p.weights, index);
    for (MorphTarget& target : p.morphTargets) {
        copyElement(target.positionDeltas, index);
        copyElement(target.normalDeltas, index);
        copyElement(target.tangentDeltas, index);
    }
    return static_cast<std::uint32_t>(p.positions.size() - 1);
}

Float3 anyPerpendicular(const Float3& n) {
    // Cross with the axis least aligned with n (branch on the smallest component).
    const Float3 axis = std::fabs(n[0]) < 0.577f   ? Float3{1, 0, 0}
                        : std::fabs(n[1]) < 0.577f ? Float3{0, 1, 0}
                                                   : Float3{0, 0, 1};
    Float3 t = {axis[1] * n[2] - axis[2] * n[1], axis[2] * n[0] - axis[0] * n[2],
                axis[0] * n[1] - axis[1] * n[0]};
    const float length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (length < 1e-20f) return {1, 0, 0};
    for (float& c : t)
        c /= length;
    return t;
}

}  // namespace candela::content
