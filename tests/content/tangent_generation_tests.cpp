#include <gtest/gtest.h>

#include <cmath>

#include "candela/content/normal_generation.h"
#include "candela/content/tangent_generation.h"

namespace candela::content {
namespace {

// Two quads side by side sharing the middle edge; the right one has mirrored U, as artists
// do for symmetric models.
Primitive mirroredPair() {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    p.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 1}, {0, 0}};
    p.normals.assign(6, Float3{0, 0, 1});
    p.indices = {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2};
    return p;
}

TEST(TangentGeneration, FollowsUAndSplitsMirroredSeams) {
    Primitive p = mirroredPair();
    generateTangents(p);
    ASSERT_EQ(p.tangents.size(), p.positions.size());
    EXPECT_EQ(p.positions.size(), 8u) << "vertices 1 and 2 sit on the mirror seam";
    for (std::size_t c = 0; c < p.indices.size(); ++c) {
        const Float4& t = p.tangents[p.indices[c]];
        const bool rightQuad = c >= 6;
        // Tangent follows +u: +X on the left quad, -X on the mirrored right quad.
        EXPECT_NEAR(t[0], rightQuad ? -1.0f : 1.0f, 1e-6f) << c;
        EXPECT_EQ(t[3], rightQuad ? -1.0f : 1.0f) << c;
        // Bitangent w * cross(N, T) points "up" the image, i.e. along -v = +Y here.
        const float bitangentY = t[3] * t[0];  // cross((0,0,1), (tx,0,0)).y = tx
        EXPECT_GT(bitangentY, 0.0f) << c;
    }
}

TEST(TangentGeneration, AngleWeightingMakesTessellationIrrelevant) {
    // A square fan around the centre vertex: 4 triangles or 8 triangles must agree.
    for (int segments : {4, 8}) {
        Primitive p;
        p.positions.push_back({0, 0, 0});
        p.uv0.push_back({0.5f, 0.5f});
        for (int i = 0; i < segments; ++i) {
            const float a =
                2.0f * 3.14159265f * static_cast<float>(i) / static_cast<float>(segments);
            p.positions.push_back({std::cos(a), std::sin(a), 0});
            p.uv0.push_back({0.5f + 0.5f * std::cos(a), 0.5f - 0.5f * std::sin(a)});
        }
        for (int i = 0; i < segments; ++i) {
            p.indices.insert(p.indices.end(), {0u, static_cast<std::uint32_t>(1 + i),
                                               static_cast<std::uint32_t>(1 + (i + 1) % segments)});
        }
        p.normals.assign(p.positions.size(), Float3{0, 0, 1});
        generateTangents(p);
        EXPECT_NEAR(p.tangents[0][0], 1.0f, 1e-5f) << segments;
        EXPECT_NEAR(p.tangents[0][1], 0.0f, 1e-5f) << segments;
    }
}

TEST(TangentGeneration, DegenerateUvsAndMissingUvsStillGiveUnitPerpendicularTangents) {
    Primitive p = mirroredPair();
    for (Float2& uv : p.uv0)
        uv = {0.5f, 0.5f};  // all UVs collapsed
    generateTangents(p);
    Primitive noUv = mirroredPair();
    noUv.uv0.clear();
    generateTangents(noUv);
    for (const Primitive* q : {&p, &noUv}) {
        for (std::size_t v = 0; v < q->positions.size(); ++v) {
            const Float4& t = q->tangents[v];
            EXPECT_NEAR(t[0] * t[0] + t[1] * t[1] + t[2] * t[2], 1.0f, 1e-5f);
            EXPECT_NEAR(t[2], 0.0f, 1e-6f) << "perpendicular to the +Z normal";
            EXPECT_TRUE(std::isfinite(t[0]) && std::isfinite(t[1]));
        }
    }
}

TEST(NormalGeneration, FlatNormalsUnweldAndFaceOutward) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    p.indices = {0, 2, 1, 0, 1, 3, 0, 0, 0};  // last triangle is degenerate
    generateFlatNormals(p);
    ASSERT_EQ(p.positions.size(), 9u);
    EXPECT_EQ(p.normals[0], (Float3{0, 0, -1}));
    EXPECT_EQ(p.normals[3], (Float3{0, -1, 0}));
    EXPECT_EQ(p.normals[6], (Float3{0, 1, 0})) << "degenerate triangles get +Y";
    EXPECT_TRUE(p.normalsGenerated);
}

}  // namespace
}  // namespace candela::content
