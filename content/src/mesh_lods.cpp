#include "candela/content/mesh_lods.h"

#include <meshoptimizer.h>

#include <cmath>

namespace candela::content {

namespace {
constexpr float kErrorMargin = 2.0f;
}  // namespace

std::vector<MeshLod> buildMeshLods(const Primitive& primitive) {
    std::vector<MeshLod> lods;
    const size_t triangles = primitive.indices.size() / 3;
    if (triangles < kMeshLodMinTriangles || !primitive.morphTargets.empty()) return lods;
    const float* positions = primitive.positions.front().data();
    const size_t vertexCount = primitive.positions.size();
    constexpr size_t kStride = sizeof(Float3);
    // meshoptimizer works in units of the mesh's extent; its errors scale back to metres.
    const float scale = meshopt_simplifyScale(positions, vertexCount, kStride);
    size_t previous = primitive.indices.size();
    for (uint32_t level = 1; level < kMeshLodMaxLevels; ++level) {
        const size_t target = (primitive.indices.size() >> level) / 3 * 3;
        if (target < 3 * 64) break;
        MeshLod lod;
        lod.indices.resize(primitive.indices.size());
        float relativeError = 0.0f;
        // Borders stay where they are: a primitive that is one piece of a larger surface (a
        // glTF mesh split by material) keeps meeting its neighbours.
        const size_t kept =
            meshopt_simplify(lod.indices.data(), primitive.indices.data(), primitive.indices.size(),
                             positions, vertexCount, kStride, target, /*target_error=*/1.0f,
                             meshopt_SimplifyLockBorder, &relativeError);
        if (kept == 0 || kept * 4 > previous * 3 || !std::isfinite(relativeError)) break;
        lod.indices.resize(kept);
        // The quadric error is an estimate, not a bound: on a sphere the coarse surface strays
        // up to 1.6x as far (tests/content/mesh_lod_tests.cpp). Twice it bounds what we
        // measured, so a level's pixel budget holds.
        lod.error = kErrorMargin * relativeError * scale;
        previous = kept;
        lods.push_back(std::move(lod));
    }
    return lods;
}

}  // namespace candela::content
