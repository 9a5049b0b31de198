// Levels of detail (content/mesh_lods.h): fewer triangles level by level over the same
// vertices, an error that grows with the level and bounds how far the coarse surface strays
// from the true one, and no levels where they cannot pay or cannot be trusted.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/content/mesh_lods.h"
#include "candela/content/procedural_mesh.h"

using namespace candela::content;

namespace {

float distanceFromSphere(const Float3& p, float radius) {
    return std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - radius);
}

}  // namespace

TEST(MeshLods, EachLevelHalvesTheTrianglesOverTheSameVertices) {
    const Primitive sphere = makeSphere(1.0f, 96, 48);
    const std::vector<MeshLod> lods = buildMeshLods(sphere);
    ASSERT_GE(lods.size(), 3u);
    EXPECT_LE(lods.size() + 1, kMeshLodMaxLevels);
    size_t previous = sphere.indices.size();
    float previousError = 0.0f;
    for (const MeshLod& lod : lods) {
        EXPECT_EQ(lod.indices.size() % 3, 0u);
        EXPECT_LE(lod.indices.size() * 4, previous * 3);
        EXPECT_GE(lod.indices.size() * 3, previous);  // about half, not a collapse
        for (uint32_t i : lod.indices)
            ASSERT_LT(i, sphere.positions.size());
        EXPECT_GT(lod.error, previousError);
        previous = lod.indices.size();
        previousError = lod.error;
    }
}

TEST(MeshLods, TheErrorBoundsHowFarTheCoarseSurfaceStrays) {
    // A unit sphere: the full mesh's own faceting is the floor (its flat triangles' centres
    // lie inside by 1 - cos of half a segment). Each level's triangle centres and edge
    // midpoints stay within its error of the true sphere, plus that floor.
    const Primitive sphere = makeSphere(1.0f, 96, 48);
    const float faceting = 1.0f - std::cos(3.14159265f / 48.0f);
    for (const MeshLod& lod : buildMeshLods(sphere)) {
        float worst = 0.0f;
        for (size_t t = 0; t < lod.indices.size(); t += 3) {
            const Float3& a = sphere.positions[lod.indices[t]];
            const Float3& b = sphere.positions[lod.indices[t + 1]];
            const Float3& c = sphere.positions[lod.indices[t + 2]];
            Float3 centre, ab;
            for (int k = 0; k < 3; ++k) {
                centre[k] = (a[k] + b[k] + c[k]) / 3.0f;
                ab[k] = 0.5f * (a[k] + b[k]);
            }
            worst =
                std::max({worst, distanceFromSphere(centre, 1.0f), distanceFromSphere(ab, 1.0f)});
        }
        EXPECT_LE(worst, lod.error + faceting) << lod.indices.size() / 3 << " triangles";
        EXPECT_GT(worst, 0.4f * lod.error);  // and is not wildly pessimistic either
    }
}

TEST(MeshLods, SmallOrMorphedPrimitivesGetNone) {
    EXPECT_TRUE(buildMeshLods(makeBox({1.0f, 1.0f, 1.0f})).empty());
    EXPECT_TRUE(buildMeshLods(makeSphere(1.0f, 16, 8)).empty());  // 256 triangles
    Primitive morphed = makeSphere(1.0f, 96, 48);
    morphed.morphTargets.push_back({});
    morphed.morphTargets.back().positionDeltas.assign(morphed.positions.size(), {0, 0.1f, 0});
    EXPECT_TRUE(buildMeshLods(morphed).empty());
    EXPECT_TRUE(buildMeshLods(makeSphere(1.0f, 48, 24)).empty());  // 2,304 triangles
    EXPECT_FALSE(buildMeshLods(makeSphere(1.0f, 96, 48)).empty());
}
