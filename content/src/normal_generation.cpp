#include "candela/content/normal_generation.h"

#include <cmath>

namespace candela::content {
namespace {

template <typename T>
void unweld(std::vector<T>& stream, const std::vector<std::uint32_t>& indices) {
    if (stream.empty()) return;
    std::vector<T> expanded;
    expanded.reserve(indices.size());
    for (std::uint32_t i : indices)
        expanded.push_back(stream[i]);
    stream = std::move(expanded);
}

}  // namespace

void generateFlatNormals(Primitive& p) {
    unweld(p.positions, p.indices);
    unweld(p.tangents, p.indices);
    unweld(p.uv0, p.indices);
    unweld(p.uv1, p.indices);
    unweld(p.colors, p.indices);
    unweld(p.joints, p.indices);
    unweld(p.weights, p.indices);
    for (MorphTarget& target : p.morphTargets) {
        unweld(target.positionDeltas, p.indices);
        unweld(target.normalDeltas, p.indices);
        unweld(target.tangentDeltas, p.indices);
    }
    const std::size_t vertexCount = p.positions.size();
    p.indices.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        p.indices[i] = static_cast<std::uint32_t>(i);

    p.normals.assign(vertexCount, Float3{0, 1, 0});
    for (std::size_t t = 0; t + 2 < vertexCount; t += 3) {
        const Float3& a = p.positions[t];
        const Float3& b = p.positions[t + 1];
        const Float3& c = p.positions[t + 2];
        const Float3 e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const Float3 e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        // Double precision: large coordinates with small triangles cancel badly in float.
        const double nx = double(e1[1]) * e2[2] - double(e1[2]) * e2[1];
        const double ny = double(e1[2]) * e2[0] - double(e1[0]) * e2[2];
        const double nz = double(e1[0]) * e2[1] - double(e1[1]) * e2[0];
        const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 0) || !std::isfinite(length)) continue;  // degenerate: keep +Y
        const Float3 n{float(nx / length), float(ny / length), float(nz / length)};
        p.normals[t] = p.normals[t + 1] = p.normals[t + 2] = n;
    }
    p.normalsGenerated = true;
}

}  // namespace candela::content
