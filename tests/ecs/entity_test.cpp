#include <gtest/gtest.h>

#include <candela/ecs/registry.h>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Position;

TEST(Entity, PacksIndexAndGeneration) {
    const Entity e(7, 3);
    EXPECT_EQ(e.index(), 7u);
    EXPECT_EQ(e.generation(), 3u);
    EXPECT_EQ(sizeof(Entity), 8u);
    EXPECT_TRUE(Entity().isNull());
    EXPECT_EQ(Entity(), kNullEntity);
    EXPECT_NE(Entity(7, 3), Entity(7, 4));
}

TEST(Entity, StaleAfterDestroy) {
    Registry registry;
    const Entity e = registry.create();
    EXPECT_TRUE(registry.valid(e));
    EXPECT_TRUE(registry.destroy(e));
    EXPECT_FALSE(registry.valid(e));
    EXPECT_FALSE(registry.destroy(e));  // destroying a stale handle is a no-op
    EXPECT_FALSE(registry.has<Position>(e));
    EXPECT_EQ(registry.tryGet<Position>(e), nullptr);
    EXPECT_FALSE(registry.remove<Position>(e));
}

TEST(Entity, StaleAfterSlotReuse) {
    Registry registry;
    const Entity old = registry.create();
    registry.emplace<Position>(old, 1.0f, 2.0f, 3.0f);
    registry.destroy(old);
    const Entity reused = registry.create();
    ASSERT_EQ(reused.index(), old.index());  // the slot was recycled...
    EXPECT_NE(reused.generation(), old.generation());
    EXPECT_TRUE(registry.valid(reused));
    EXPECT_FALSE(registry.valid(old));  // ...but the old handle does not alias the new entity
    EXPECT_FALSE(registry.has<Position>(reused));
    registry.emplace<Position>(reused);
    EXPECT_FALSE(registry.has<Position>(old));
    EXPECT_EQ(registry.tryGet<Position>(old), nullptr);
}

TEST(Entity, StaleHandleAccessIsAnError) {
    Registry registry;
    const Entity e = registry.create();
    registry.emplace<Position>(e);
    registry.destroy(e);
#ifdef NDEBUG
    try {
        (void)registry.get<Position>(e);
        FAIL() << "get() on a stale handle must throw";
    } catch (const EcsError& error) {
        EXPECT_EQ(error.code(), EcsErrorCode::StaleEntity);
    }
    EXPECT_THROW(registry.emplace<Position>(e), EcsError);
#else
    EXPECT_DEATH((void)registry.get<Position>(e), "stale");
#endif
}

TEST(Entity, SlotWhoseGenerationWouldWrapIsRetired) {
    Registry registry(Registry::Config{.maxGeneration = 3});
    Entity e = registry.create();
    const std::uint32_t index = e.index();
    std::vector<Entity> history{e};
    for (int i = 0; i < 3; ++i) {
        registry.destroy(e);
        e = registry.create();
        ASSERT_EQ(e.index(), index);
        history.push_back(e);
    }
    EXPECT_EQ(e.generation(), 3u);
    registry.destroy(e);  // generation 3 is the last: the slot is retired
    EXPECT_EQ(registry.entityPool().retiredCount(), 1u);
    const Entity fresh = registry.create();
    EXPECT_NE(fresh.index(), index);
    for (Entity old : history)
        EXPECT_FALSE(registry.valid(old));
}

TEST(Entity, RetirementAtFullGenerationRange) {
    Registry registry;
    Entity e = registry.create();
    registry.destroy(e);
    // Jump the free slot to the last generation, as if destroyed 2^32 - 2 more times.
    registry.entityPoolForTesting().setGenerationForTesting(e.index(), EntityPool::kMaxGeneration);
    const Entity last = registry.create();
    EXPECT_EQ(last.index(), e.index());
    EXPECT_EQ(last.generation(), EntityPool::kMaxGeneration);
    registry.destroy(last);
    const Entity next = registry.create();
    EXPECT_NE(next.index(), e.index());
    EXPECT_FALSE(registry.valid(last));
    EXPECT_FALSE(registry.valid(Entity(e.index(), 0)));
}

TEST(Entity, ReservedHandlesBecomeLiveWhenCreated) {
    Registry registry;
    const Entity a = registry.reserve();
    const Entity b = registry.reserve();
    EXPECT_NE(a, b);
    EXPECT_FALSE(registry.valid(a));
    EXPECT_TRUE(registry.isReserved(a));
    const Entity plain = registry.create();  // must not collide with the reservations
    EXPECT_NE(plain.index(), a.index());
    EXPECT_NE(plain.index(), b.index());
    registry.createReserved(a);
    EXPECT_TRUE(registry.valid(a));
    registry.releaseReserved(b);
    EXPECT_FALSE(registry.valid(b));
    EXPECT_FALSE(registry.isReserved(b));
}

}  // namespace
}  // namespace candela::ecs
