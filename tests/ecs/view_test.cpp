#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <candela/ecs/registry.h>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Frozen;
using test::Health;
using test::Position;
using test::Velocity;

struct ViewTest : ::testing::Test {
    Registry registry;
    std::vector<Entity> moving, still, frozen;

    void SetUp() override {
        for (int i = 0; i < 10; ++i) {
            const Entity e = registry.create();
            registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
            registry.emplace<Velocity>(e, 1.0f, 0.0f, 0.0f);
            moving.push_back(e);
        }
        for (int i = 0; i < 5; ++i) {
            const Entity e = registry.create();
            registry.emplace<Position>(e);
            still.push_back(e);
        }
        for (int i = 0; i < 3; ++i) {
            const Entity e = registry.create();
            registry.emplace<Position>(e);
            registry.emplace<Velocity>(e);
            registry.emplace<Frozen>(e);
            frozen.push_back(e);
        }
    }
};

TEST_F(ViewTest, EachVisitsExactlyTheMatchingEntities) {
    std::set<Entity> seen;
    registry.view<Position, Velocity>().each(
        [&](Entity e, Position&, Velocity&) { EXPECT_TRUE(seen.insert(e).second); });
    EXPECT_EQ(seen.size(), moving.size() + frozen.size());
    EXPECT_EQ(registry.view<Position>().size(), 18u);
}

TEST_F(ViewTest, ExcludeSkipsEntities) {
    std::set<Entity> seen;
    registry.view<Position, const Velocity>(exclude<Frozen>)
        .each([&](Entity e, Position& p, const Velocity& v) {
            p.x += v.x;
            seen.insert(e);
        });
    EXPECT_EQ(seen, std::set<Entity>(moving.begin(), moving.end()));
    EXPECT_EQ(registry.get<Position>(moving[3]).x, 4.0f);
    EXPECT_TRUE(registry.view<Position>(exclude<Velocity>).contains(still[0]));
    EXPECT_FALSE(registry.view<Position>(exclude<Velocity>).contains(moving[0]));
}

TEST_F(ViewTest, CallbackWithoutEntity) {
    int count = 0;
    registry.view<const Position>(exclude<Velocity>).each([&](const Position&) { ++count; });
    EXPECT_EQ(count, 5);
}

TEST_F(ViewTest, ConstRegistryGivesReadOnlyViews) {
    const Registry& readOnly = registry;
    float sum = 0;
    readOnly.view<const Position, const Velocity>(exclude<Frozen>)
        .each([&](const Position& p, const Velocity& v) { sum += p.x + v.x; });
    EXPECT_EQ(sum, 45.0f + 10.0f);
}

TEST_F(ViewTest, RangeFor) {
    std::set<Entity> seen;
    for (auto [e, p, v] : registry.view<Position, const Velocity>(exclude<Frozen>)) {
        static_assert(std::is_same_v<decltype(v), const Velocity&>);
        p.y = 7.0f;
        seen.insert(e);
    }
    EXPECT_EQ(seen.size(), moving.size());
    EXPECT_EQ(registry.get<Position>(moving[0]).y, 7.0f);
    EXPECT_EQ(registry.get<Position>(frozen[0]).y, 0.0f);
}

TEST_F(ViewTest, ViewSeesPoolsCreatedLater) {
    auto view = registry.view<Position, Health>();
    EXPECT_EQ(view.size(), 0u);
    registry.emplace<Health>(still[0]);
    registry.emplace<Health>(moving[0]);
    EXPECT_EQ(view.size(), 2u);
}

TEST_F(ViewTest, ChunksCoverEveryRowOnce) {
    auto view = registry.view<Position>();
    std::multiset<Entity> seen;
    for (const ViewChunk& chunk : view.chunks(4)) {
        EXPECT_LE(chunk.end - chunk.begin, 4u);
        view.each(chunk, [&](Entity e, Position&) { seen.insert(e); });
    }
    EXPECT_EQ(seen.size(), 18u);
    EXPECT_EQ(std::set<Entity>(seen.begin(), seen.end()).size(), 18u);
}

TEST_F(ViewTest, EachChangedSinceVisitsOnlyChangedRows) {
    const Tick seen = registry.advanceTick();
    registry.patch<Position>(moving[2], [](Position& p) { p.z = 1.0f; });
    registry.markChanged<Velocity>(frozen[1]);
    std::set<Entity> changed;
    registry.view<Position, Velocity>().eachChangedSince(
        seen, [&](Entity e, Position&, Velocity&) { changed.insert(e); });
    EXPECT_EQ(changed, (std::set<Entity>{moving[2], frozen[1]}));

    changed.clear();
    registry.view<Position, Velocity>().eachChangedSince<Velocity>(
        seen, [&](Entity e, Position&, Velocity&) { changed.insert(e); });
    EXPECT_EQ(changed, (std::set<Entity>{frozen[1]}));

    changed.clear();
    registry.view<Position>().eachChangedSince(registry.advanceTick(),
                                               [&](Entity e, Position&) { changed.insert(e); });
    EXPECT_TRUE(changed.empty());
}

TEST_F(ViewTest, StructuralChangeWhileIteratingIsCaught) {
#ifdef NDEBUG
    int errors = 0;
    registry.view<Position>().each([&](Entity e, Position&) {
        try {
            registry.emplace<Health>(e);
        } catch (const EcsError& error) {
            EXPECT_EQ(error.code(), EcsErrorCode::StructuralChangeWhileLocked);
            ++errors;
        }
        EXPECT_THROW(registry.destroy(e), EcsError);
        EXPECT_THROW((void)registry.create(), EcsError);
        EXPECT_THROW(registry.remove<Position>(e), EcsError);
    });
    EXPECT_EQ(errors, 18);
    for (auto [e, p] : registry.view<Position>()) {
        EXPECT_THROW(registry.remove<Position>(e), EcsError);
    }
    EXPECT_FALSE(registry.structureLocked());
    // Non-structural writes are fine, and nothing was corrupted.
    EXPECT_EQ(registry.view<Position>().size(), 18u);
    registry.emplace<Health>(moving[0]);  // allowed again after the loop
#else
    EXPECT_DEATH(registry.view<Position>().each([&](Entity e, Position&) { registry.destroy(e); }),
                 "structural change");
#endif
}

TEST_F(ViewTest, ReplacingExistingComponentInsideIterationIsAllowed) {
    registry.view<Position>().each([&](Entity e, Position&) {
        if (registry.has<Velocity>(e)) registry.emplace<Velocity>(e, 2.0f, 0.0f, 0.0f);
    });
    EXPECT_EQ(registry.get<Velocity>(moving[0]).x, 2.0f);
}

}  // namespace
}  // namespace candela::ecs
