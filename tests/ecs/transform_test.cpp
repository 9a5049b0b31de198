#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_propagation.h>

namespace candela::ecs {
namespace {

void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

Entity spawn(Registry& registry, Vec3 position, Quat rotation = {}, Vec3 scale = {1, 1, 1}) {
    const Entity e = registry.create();
    registry.emplace<LocalTransform>(e, LocalTransform{position, rotation, scale});
    registry.emplace<WorldTransform>(e);
    return e;
}

TEST(TransformMath, LayoutMatchesGlm) {
    // Column-major: translation sits in elements 12..14, as in glm::mat4.
    const Mat4 t = Mat4::translation({1, 2, 3});
    EXPECT_EQ(t.m[12], 1.0f);
    EXPECT_EQ(t.m[13], 2.0f);
    EXPECT_EQ(t.m[14], 3.0f);
    EXPECT_EQ(t(0, 3), 1.0f);
    EXPECT_EQ(offsetof(Quat, w), 12u);
}

TEST(TransformMath, TrsMatchesQuaternionRotation) {
    const Quat q = Quat::fromAxisAngle({0, 1, 0}, std::numbers::pi_v<float> / 2);
    const Mat4 m = Mat4::fromTranslationRotationScale({1, 0, 0}, q, {2, 2, 2});
    // Scale, then rotate +X to -Z (right-handed, +Y up), then translate.
    expectNear(m.transformPoint({1, 0, 0}), {1, 0, -2});
    expectNear(rotate(q, {1, 0, 0}), {0, 0, -1});
    const Mat4 product = Mat4::translation({0, 5, 0}) * m;
    expectNear(product.transformPoint({1, 0, 0}), {1, 5, -2});
    const Mat4 composed = composeWithLocal(Mat4::translation({0, 5, 0}), {1, 0, 0}, q, {2, 2, 2});
    for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(composed.m[i], product.m[i], 1e-6f);
}

TEST(TransformPropagation, ParentMovesChild) {
    Registry registry;
    const Entity parent = spawn(registry, {10, 0, 0});
    const Entity child = spawn(registry, {0, 1, 0});
    ASSERT_EQ(setParent(registry, child, parent), ReparentResult::Ok);
    propagateTransforms(registry);
    expectNear(registry.get<WorldTransform>(child).position(), {10, 1, 0});

    registry.patch<LocalTransform>(parent, [](LocalTransform& t) { t.position = {0, 0, 5}; });
    const auto stats = propagateTransforms(registry);
    EXPECT_EQ(stats.recomputed, 2u);
    expectNear(registry.get<WorldTransform>(child).position(), {0, 1, 5});
}

TEST(TransformPropagation, NothingChangedSkipsTheTree) {
    Registry registry;
    const Entity parent = spawn(registry, {1, 0, 0});
    for (int i = 0; i < 100; ++i) {
        ASSERT_EQ(setParent(registry, spawn(registry, {0, 1, 0}), parent), ReparentResult::Ok);
    }
    EXPECT_TRUE(propagateTransforms(registry).rebuiltOrder);
    const auto stats = propagateTransforms(registry);
    EXPECT_TRUE(stats.skipped);
    EXPECT_FALSE(stats.rebuiltOrder);
    EXPECT_EQ(stats.recomputed, 0u);
}

// The static early exit returns before advancing the tick (issue 22): whatever changes
// after any number of skipped runs is still seen, once, by the next run.
TEST(TransformPropagation, ChangesAfterSkippedRunsAreStillPropagated) {
    Registry registry;
    const Entity parent = spawn(registry, {1, 0, 0});
    const Entity child = spawn(registry, {0, 1, 0});
    propagateTransforms(registry);
    const Tick tick = registry.currentTick();
    EXPECT_TRUE(propagateTransforms(registry).skipped);
    EXPECT_TRUE(propagateTransforms(registry).skipped);
    EXPECT_EQ(registry.currentTick(), tick);  // the skipped runs wrote nothing

    registry.patch<LocalTransform>(parent, [](LocalTransform& t) { t.position.x = 4; });
    auto stats = propagateTransforms(registry);
    EXPECT_FALSE(stats.skipped);
    EXPECT_EQ(stats.recomputed, 1u);
    expectNear(registry.get<WorldTransform>(parent).position(), {4, 0, 0});
    EXPECT_TRUE(propagateTransforms(registry).skipped);

    // A hierarchy change alone (no LocalTransform written) rebuilds the order.
    ASSERT_EQ(setParent(registry, child, parent), ReparentResult::Ok);
    stats = propagateTransforms(registry);
    EXPECT_FALSE(stats.skipped);
    EXPECT_TRUE(stats.rebuiltOrder);
    expectNear(registry.get<WorldTransform>(child).position(), {4, 1, 0});

    // So does a structural change of a transform pool.
    const Entity late = spawn(registry, {0, 0, 7});
    stats = propagateTransforms(registry);
    EXPECT_TRUE(stats.rebuiltOrder);
    expectNear(registry.get<WorldTransform>(late).position(), {0, 0, 7});
    EXPECT_TRUE(propagateTransforms(registry).skipped);
}

TEST(TransformPropagation, OnlyDirtySubtreesAreRecomputed) {
    Registry registry;
    std::vector<Entity> roots;
    for (int r = 0; r < 10; ++r) {
        roots.push_back(spawn(registry, {float(r), 0, 0}));
        for (int c = 0; c < 9; ++c) {
            ASSERT_EQ(setParent(registry, spawn(registry, {0, 1, 0}), roots.back()),
                      ReparentResult::Ok);
        }
    }
    propagateTransforms(registry);
    registry.patch<LocalTransform>(roots[3], [](LocalTransform& t) { t.position.y = 2; });
    const auto stats = propagateTransforms(registry);
    EXPECT_FALSE(stats.rebuiltOrder);
    EXPECT_EQ(stats.recomputed, 10u);  // the root and its 9 children
    for (Entity child : childrenOf(registry, roots[3])) {
        expectNear(registry.get<WorldTransform>(child).position(), {3, 3, 0});
    }
}

TEST(TransformPropagation, WorldChangesAreVisibleToChangeQueries) {
    Registry registry;
    const Entity a = spawn(registry, {1, 0, 0});
    const Entity b = spawn(registry, {2, 0, 0});
    propagateTransforms(registry);
    const Tick uploaded = registry.advanceTick();
    registry.patch<LocalTransform>(b, [](LocalTransform& t) { t.position.x = 3; });
    propagateTransforms(registry);
    std::vector<Entity> changed;
    registry.view<const WorldTransform>().eachChangedSince(
        uploaded, [&](Entity e, const WorldTransform&) { changed.push_back(e); });
    EXPECT_EQ(changed, std::vector<Entity>{b});
    (void)a;
}

// A tree of depth 64 (binary near the top, then a chain): positions add up along the path.
TEST(TransformPropagation, Depth64Hierarchy) {
    Registry registry;
    const Entity root = spawn(registry, {0, 0, 0});
    std::vector<Entity> level{root};
    Entity deepest = root;
    for (int depth = 1; depth <= 64; ++depth) {
        std::vector<Entity> next;
        for (Entity parent : level) {
            const int fanout = depth <= 6 ? 2 : 1;
            for (int i = 0; i < fanout; ++i) {
                const Entity e = spawn(registry, {1, 0, 0});
                ASSERT_EQ(setParent(registry, e, parent), ReparentResult::Ok);
                next.push_back(e);
            }
        }
        level = std::move(next);
        deepest = level.front();
    }
    EXPECT_EQ(depthOf(registry, deepest), 64u);
    propagateTransforms(registry);
    for (Entity leaf : level)
        expectNear(registry.get<WorldTransform>(leaf).position(), {64, 0, 0});

    // Rotate the root 90 degrees about Y: every leaf swings from +X to -Z.
    registry.patch<LocalTransform>(root, [](LocalTransform& t) {
        t.rotation = Quat::fromAxisAngle({0, 1, 0}, std::numbers::pi_v<float> / 2);
    });
    propagateTransforms(registry);
    for (Entity leaf : level) {
        expectNear(registry.get<WorldTransform>(leaf).position(), {0, 0, -64}, 1e-3f);
    }
}

TEST(TransformPropagation, Chain2500Deep) {
    constexpr int kDepth = 2500;
    Registry registry;
    std::vector<Entity> chain{spawn(registry, {0, 0, 0})};
    for (int i = 1; i < kDepth; ++i) {
        chain.push_back(spawn(registry, {0, 1, 0}));
        ASSERT_EQ(setParent(registry, chain.back(), chain[std::size_t(i) - 1]), ReparentResult::Ok);
    }
    EXPECT_EQ(depthOf(registry, chain.back()), kDepth - 1u);
    propagateTransforms(registry);
    for (int i = 0; i < kDepth; i += 97) {
        expectNear(registry.get<WorldTransform>(chain[std::size_t(i)]).position(),
                   {0, float(i), 0});
    }
    expectNear(registry.get<WorldTransform>(chain.back()).position(), {0, kDepth - 1.0f, 0});

    // A cycle through the chain is rejected and the chain stays intact.
    EXPECT_EQ(setParent(registry, chain[0], chain.back()), ReparentResult::WouldCreateCycle);
    registry.patch<LocalTransform>(chain[0], [](LocalTransform& t) { t.position.x = 2; });
    propagateTransforms(registry);
    expectNear(registry.get<WorldTransform>(chain.back()).position(), {2, kDepth - 1.0f, 0});
}

TEST(TransformPropagation, ReparentAndDestroyRebuildTheOrder) {
    Registry registry;
    const Entity a = spawn(registry, {1, 0, 0});
    const Entity b = spawn(registry, {0, 2, 0});
    const Entity c = spawn(registry, {0, 0, 3});
    ASSERT_EQ(setParent(registry, c, b), ReparentResult::Ok);
    propagateTransforms(registry);
    expectNear(registry.get<WorldTransform>(c).position(), {0, 2, 3});
    ASSERT_EQ(setParent(registry, b, a), ReparentResult::Ok);
    propagateTransforms(registry);
    expectNear(registry.get<WorldTransform>(c).position(), {1, 2, 3});
    registry.destroy(a);
    const auto stats = propagateTransforms(registry);
    EXPECT_TRUE(stats.rebuiltOrder);
    expectNear(registry.get<WorldTransform>(c).position(), {0, 2, 3});
}

TEST(TransformPropagation, SortingThePoolsKeepsOtherEntitiesIntact) {
    Registry registry;
    // Entities with only one of the two transforms, interleaved with complete ones.
    std::vector<Entity> partial, complete;
    for (int i = 0; i < 30; ++i) {
        const Entity e = registry.create();
        if (i % 3 == 0) {
            registry.emplace<LocalTransform>(e, LocalTransform{{float(i), 0, 0}, {}, {1, 1, 1}});
            partial.push_back(e);
        } else if (i % 3 == 1) {
            registry.emplace<WorldTransform>(e,
                                             WorldTransform{Mat4::translation({0, float(i), 0})});
            partial.push_back(e);
        } else {
            complete.push_back(spawn(registry, {float(i), 0, 0}));
        }
    }
    for (std::size_t i = 1; i < complete.size(); ++i) {
        ASSERT_EQ(setParent(registry, complete[i], complete[i - 1]), ReparentResult::Ok);
    }
    EXPECT_TRUE(propagateTransforms(registry).rebuiltOrder);
    float x = 0;
    for (Entity e : complete) {
        x += registry.get<LocalTransform>(e).position.x;
        expectNear(registry.get<WorldTransform>(e).position(), {x, 0, 0});
    }
    for (std::size_t i = 0; i < partial.size(); ++i) {
        const Entity e = partial[i];
        if (const LocalTransform* l = registry.tryGet<LocalTransform>(e)) {
            EXPECT_FALSE(registry.has<WorldTransform>(e));
            EXPECT_EQ(std::fmod(l->position.x, 3.0f), 0.0f);
        } else {
            EXPECT_EQ(std::fmod(registry.get<WorldTransform>(e).position().y, 3.0f), 1.0f);
        }
    }
}

}  // namespace
}  // namespace candela::ecs
