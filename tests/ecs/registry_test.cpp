#include <gtest/gtest.h>

#include <candela/ecs/registry.h>

#include <string>
#include <vector>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Frozen;
using test::Health;
using test::Name;
using test::Position;
using test::Velocity;

TEST(Registry, EmplaceGetTryGetHasRemove) {
    Registry registry;
    const Entity e = registry.create();
    EXPECT_FALSE(registry.has<Position>(e));
    Position& p = registry.emplace<Position>(e, 1.0f, 2.0f, 3.0f);
    EXPECT_EQ(p.y, 2.0f);
    registry.emplace<Velocity>(e);
    EXPECT_TRUE((registry.has<Position, Velocity>(e)));
    EXPECT_FALSE((registry.has<Position, Health>(e)));
    EXPECT_EQ(registry.get<Position>(e).z, 3.0f);
    ASSERT_NE(registry.tryGet<Velocity>(e), nullptr);
    EXPECT_EQ(registry.tryGet<Health>(e), nullptr);

    EXPECT_TRUE(registry.remove<Position>(e));
    EXPECT_FALSE(registry.remove<Position>(e));
    EXPECT_FALSE(registry.has<Position>(e));
    EXPECT_TRUE(registry.has<Velocity>(e));
}

TEST(Registry, EmplaceOnExistingReplacesValue) {
    Registry registry;
    const Entity e = registry.create();
    registry.emplace<Health>(e, 10);
    registry.emplace<Health>(e, 20);
    EXPECT_EQ(registry.get<Health>(e).value, 20);
}

TEST(Registry, ComponentsSurviveOtherEntitiesMoving) {
    Registry registry;
    std::vector<Entity> entities;
    for (int i = 0; i < 1000; ++i) {
        const Entity e = registry.create();
        registry.emplace<Health>(e, i);
        registry.emplace<Name>(e, Name{"entity " + std::to_string(i)});
        if (i % 3 == 0) registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
        entities.push_back(e);
    }
    for (int i = 0; i < 1000; i += 2)
        registry.destroy(entities[std::size_t(i)]);
    for (int i = 1; i < 1000; i += 4)
        registry.remove<Health>(entities[std::size_t(i)]);
    for (int i = 1; i < 1000; i += 2) {
        const Entity e = entities[std::size_t(i)];
        ASSERT_TRUE(registry.valid(e));
        EXPECT_EQ(registry.get<Name>(e).text, "entity " + std::to_string(i));
        if (i % 4 == 1) {
            EXPECT_FALSE(registry.has<Health>(e));
        } else {
            EXPECT_EQ(registry.get<Health>(e).value, i);
        }
        EXPECT_EQ(registry.has<Position>(e), i % 3 == 0);
    }
    EXPECT_EQ(registry.aliveCount(), 500u);
}

TEST(Registry, MissingComponentIsAnError) {
    Registry registry;
    const Entity e = registry.create();
#ifdef NDEBUG
    try {
        (void)registry.get<Health>(e);
        FAIL();
    } catch (const EcsError& error) {
        EXPECT_EQ(error.code(), EcsErrorCode::MissingComponent);
    }
#else
    EXPECT_DEATH((void)registry.get<Health>(e), "without T");
#endif
}

// The unchecked storage-level accessor answers what the checked get answers, across pages,
// removals that move elements, group reordering and non-trivial components.
TEST(Registry, StorageGetMatchesCheckedGet) {
    Registry registry;
    registry.group<Position, Velocity>();
    std::vector<Entity> entities;
    for (int i = 0; i < 10000; ++i) {  // more than one 4,096-entry sparse page
        const Entity e = registry.create();
        registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
        registry.emplace<Name>(e, std::to_string(i));
        if (i % 3 == 0) registry.emplace<Velocity>(e);  // group swaps reorder Position
        entities.push_back(e);
    }
    for (int i = 0; i < 10000; i += 7)
        registry.remove<Position>(entities[size_t(i)]);
    const Storage<Position> positions = registry.storage<Position>();
    const Storage<Name> names = registry.storage<Name>();
    EXPECT_EQ(positions.size(), registry.pool<Position>()->size());
    for (int i = 0; i < 10000; ++i) {
        const Entity e = entities[size_t(i)];
        EXPECT_EQ(&names.get(e), &registry.get<Name>(e));
        EXPECT_EQ(names.get(e).text, std::to_string(i));
        EXPECT_EQ(positions.contains(e), i % 7 != 0);
        if (i % 7 != 0) {
            EXPECT_EQ(&positions.get(e), &registry.get<Position>(e));
            EXPECT_EQ(positions.get(e).x, float(i));
        }
    }
    // The handle follows the pool as it grows.
    const Entity late = registry.create();
    registry.emplace<Position>(late, 42.0f, 0.0f, 0.0f);
    EXPECT_EQ(positions.get(late).x, 42.0f);
}

TEST(Registry, StorageOfANeverAddedTypeIsAnError) {
    Registry registry;
#ifdef NDEBUG
    try {
        (void)registry.storage<Health>();
        FAIL();
    } catch (const EcsError& error) {
        EXPECT_EQ(error.code(), EcsErrorCode::MissingComponent);
    }
#else
    EXPECT_DEATH((void)registry.storage<Health>(), "storage");
#endif
}

// Checked access answers stale handles and missing components, including after the slot
// is reused by a new entity (generation mismatch) and past the last slot.
TEST(Registry, CheckedAccessRejectsStaleAndUnknownHandles) {
    Registry registry;
    const Entity old = registry.create();
    registry.emplace<Position>(old);
    ASSERT_TRUE(registry.destroy(old));
    const Entity reused = registry.create();
    ASSERT_EQ(reused.index(), old.index());
    registry.emplace<Position>(reused, 1.0f, 2.0f, 3.0f);
    EXPECT_EQ(registry.tryGet<Position>(old), nullptr);
    EXPECT_EQ(registry.tryGet<Position>(reused)->y, 2.0f);
    EXPECT_EQ(registry.tryGet<Position>(Entity(12345, 0)), nullptr);
    EXPECT_EQ(registry.tryGet<Position>(kNullEntity), nullptr);
    EXPECT_EQ(registry.tryGet<Velocity>(reused), nullptr);  // no pool at all
    EXPECT_FALSE(registry.valid(old));
    EXPECT_TRUE(registry.valid(reused));
    const Entity reserved = registry.reserve();
    EXPECT_FALSE(registry.valid(reserved));
#ifdef NDEBUG
    EXPECT_THROW((void)registry.get<Position>(old), EcsError);
#endif
}

// Unallocated sparse pages share one read-only page of "absent" entries: lookups through it
// miss, and adding a component there allocates a page of the pool's own instead of writing
// into the shared one (which another registry's pool would then see).
TEST(Registry, LookupsThroughUnallocatedSparsePagesMiss) {
    Registry a, b;
    std::vector<Entity> entities;
    for (int i = 0; i < 10000; ++i)
        entities.push_back(a.create());
    for (int i = 0; i < 10000; ++i)
        (void)b.create();
    a.emplace<Position>(entities[0]);
    a.emplace<Position>(entities[9999]);  // pages 0 and 2 exist, page 1 does not
    b.emplace<Position>(Entity(0, 0));
    b.emplace<Position>(Entity(9999, 0));
    EXPECT_EQ(a.tryGet<Position>(entities[5000]), nullptr);
    EXPECT_FALSE(a.has<Position>(entities[5000]));
    a.emplace<Position>(entities[5000], 5.0f, 0.0f, 0.0f);
    EXPECT_EQ(a.get<Position>(entities[5000]).x, 5.0f);
    EXPECT_EQ(a.storage<Position>().get(entities[5000]).x, 5.0f);
    EXPECT_EQ(b.tryGet<Position>(Entity(5000, 0)), nullptr);
    EXPECT_EQ(b.tryGet<Position>(Entity(5001, 0)), nullptr);
    EXPECT_TRUE(a.remove<Position>(entities[5000]));
    EXPECT_EQ(a.tryGet<Position>(entities[5000]), nullptr);
}

TEST(Registry, HooksFireExactlyOnce) {
    Registry registry;
    int added = 0, removed = 0;
    registry.onAdd<Health>([&](Registry&, Entity) { ++added; });
    registry.onRemove<Health>([&](Registry& r, Entity e) {
        EXPECT_TRUE(r.has<Health>(e));  // still readable inside the hook
        ++removed;
    });
    const Entity e = registry.create();
    registry.emplace<Health>(e, 1);
    registry.emplace<Health>(e, 2);  // replace: not an add
    registry.emplace<Position>(e);   // moves the row: neither add nor remove of Health
    registry.remove<Position>(e);
    EXPECT_EQ(added, 1);
    EXPECT_EQ(removed, 0);
    registry.remove<Health>(e);
    registry.remove<Health>(e);  // already gone: no second hook
    EXPECT_EQ(removed, 1);
    registry.emplace<Health>(e);
    registry.destroy(e);
    registry.destroy(e);
    EXPECT_EQ(added, 2);
    EXPECT_EQ(removed, 2);
}

TEST(Registry, DisconnectedHookStopsFiring) {
    Registry registry;
    int added = 0;
    const HookId hook = registry.onAdd<Health>([&](Registry&, Entity) { ++added; });
    registry.emplace<Health>(registry.create());
    registry.disconnect(hook);
    registry.emplace<Health>(registry.create());
    EXPECT_EQ(added, 1);
}

TEST(Registry, StructuralChangeInsideHookIsRejected) {
    Registry registry;
    registry.onAdd<Health>([](Registry& r, Entity e) {
#ifdef NDEBUG
        EXPECT_THROW(r.emplace<Position>(e), EcsError);
        EXPECT_THROW((void)r.create(), EcsError);
#else
        (void)r;
        (void)e;
#endif
    });
    registry.emplace<Health>(registry.create());
}

TEST(Registry, ChangeTicks) {
    Registry registry;
    const Entity e = registry.create();
    registry.emplace<Health>(e);
    const Tick added = registry.changeTick<Health>(e);
    EXPECT_EQ(added, registry.currentTick());
    const Tick seen = registry.advanceTick();
    EXPECT_FALSE(registry.changedSince<Health>(e, seen));
    registry.patch<Health>(e, [](Health& h) { h.value = 5; });
    EXPECT_TRUE(registry.changedSince<Health>(e, seen));
    EXPECT_EQ(registry.get<Health>(e).value, 5);
    const Tick seen2 = registry.advanceTick();
    registry.get<Health>(e).value = 6;  // plain write: not tracked until marked
    EXPECT_FALSE(registry.changedSince<Health>(e, seen2));
    registry.markChanged<Health>(e);
    EXPECT_TRUE(registry.changedSince<Health>(e, seen2));
    EXPECT_EQ(registry.changeTick<Position>(e), kNeverTick);
}

TEST(Registry, ChangeTickSurvivesOtherAddsAndRemoves) {
    Registry registry;
    const Entity e = registry.create();
    registry.emplace<Health>(e);
    const Tick stamped = registry.changeTick<Health>(e);
    registry.advanceTick();
    registry.emplace<Position>(e);
    EXPECT_EQ(registry.changeTick<Health>(e), stamped);
    // Removing e's Health moves the last Health into its place: the tick moves with it.
    const Entity f = registry.create();
    registry.emplace<Health>(f);
    const Tick stampedF = registry.changeTick<Health>(f);
    EXPECT_GT(stampedF, stamped);
    registry.remove<Health>(e);
    EXPECT_EQ(registry.changeTick<Health>(f), stampedF);
}

TEST(Registry, Resources) {
    struct Time {
        double seconds = 0;
    };
    Registry registry;
    EXPECT_FALSE(registry.resources().has<Time>());
    registry.resources().emplace<Time>(Time{1.5});
    EXPECT_EQ(registry.resources().get<Time>().seconds, 1.5);
    registry.resources().getOrEmplace<Time>().seconds = 2.0;
    EXPECT_EQ(registry.resources().tryGet<Time>()->seconds, 2.0);
    EXPECT_TRUE(registry.resources().remove<Time>());
    EXPECT_EQ(registry.resources().tryGet<Time>(), nullptr);
#ifdef NDEBUG
    EXPECT_THROW((void)registry.resources().get<Time>(), EcsError);
#endif
}

TEST(Registry, OneMillionEntitiesCreatedIteratedDestroyed) {
    constexpr std::size_t kCount = 1'000'000;
    Registry registry;
    std::vector<Entity> entities;
    entities.reserve(kCount);
    for (std::size_t i = 0; i < kCount; ++i) {
        const Entity e = registry.create();
        registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
        if (i % 2 == 0) registry.emplace<Velocity>(e, 1.0f, 0.0f, 0.0f);
        entities.push_back(e);
    }
    EXPECT_EQ(registry.aliveCount(), kCount);

    std::size_t moved = 0;
    registry.view<Position, const Velocity>().each([&](Position& p, const Velocity& v) {
        p.x += v.x;
        ++moved;
    });
    EXPECT_EQ(moved, kCount / 2);
    for (std::size_t i = 0; i < kCount; i += 9973) {
        EXPECT_EQ(registry.get<Position>(entities[i]).x, float(i) + (i % 2 == 0 ? 1.0f : 0.0f));
    }

    for (Entity e : entities)
        ASSERT_TRUE(registry.destroy(e));
    EXPECT_EQ(registry.aliveCount(), 0u);
    EXPECT_EQ(registry.view<Position>().size(), 0u);
    for (std::size_t i = 0; i < kCount; i += 9973)
        EXPECT_FALSE(registry.valid(entities[i]));
}

}  // namespace
}  // namespace candela::ecs
