#include <gtest/gtest.h>

#include <candela/ecs/command_buffer.h>
#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Health;
using test::Name;
using test::Position;
using test::Velocity;

struct HookCounts {
    int added = 0;
    int removed = 0;
};

HookCounts& countHealthHooks(Registry& registry) {
    auto& counts = registry.resources().emplace<HookCounts>();
    registry.onAdd<Health>([](Registry& r, Entity) { ++r.resources().get<HookCounts>().added; });
    registry.onRemove<Health>(
        [](Registry& r, Entity) { ++r.resources().get<HookCounts>().removed; });
    return counts;
}

TEST(CommandBuffer, NothingHappensUntilApply) {
    Registry registry;
    const Entity e = registry.create();
    CommandBuffer commands(registry);
    commands.emplace<Health>(e, 5);
    const Entity fresh = commands.create();
    commands.emplace<Position>(fresh, 1.0f, 2.0f, 3.0f);
    EXPECT_FALSE(registry.has<Health>(e));
    EXPECT_FALSE(registry.valid(fresh));
    const auto result = commands.apply();
    EXPECT_EQ(result.applied, 3u);
    EXPECT_EQ(result.skipped, 0u);
    EXPECT_EQ(registry.get<Health>(e).value, 5);
    ASSERT_TRUE(registry.valid(fresh));
    EXPECT_EQ(registry.get<Position>(fresh).y, 2.0f);
    EXPECT_TRUE(commands.empty());
}

TEST(CommandBuffer, AddThenRemoveLeavesNoComponentAndFiresBothHooksOnce) {
    Registry registry;
    HookCounts& hooks = countHealthHooks(registry);
    const Entity e = registry.create();
    CommandBuffer commands(registry);
    commands.emplace<Health>(e, 1);
    commands.remove<Health>(e);
    commands.apply();
    EXPECT_FALSE(registry.has<Health>(e));
    EXPECT_EQ(hooks.added, 1);
    EXPECT_EQ(hooks.removed, 1);
}

TEST(CommandBuffer, RemoveThenAddKeepsTheNewValue) {
    Registry registry;
    HookCounts& hooks = countHealthHooks(registry);
    const Entity e = registry.create();
    registry.emplace<Health>(e, 1);
    CommandBuffer commands(registry);
    commands.remove<Health>(e);
    commands.emplace<Health>(e, 2);
    commands.apply();
    EXPECT_EQ(registry.get<Health>(e).value, 2);
    EXPECT_EQ(hooks.added, 2);  // the original add and the re-add
    EXPECT_EQ(hooks.removed, 1);
}

TEST(CommandBuffer, DestroyThenAddIsSkipped) {
    Registry registry;
    HookCounts& hooks = countHealthHooks(registry);
    const Entity e = registry.create();
    CommandBuffer commands(registry);
    commands.destroy(e);
    commands.emplace<Health>(e, 3);
    commands.remove<Health>(e);
    commands.destroy(e);
    const auto result = commands.apply();
    EXPECT_FALSE(registry.valid(e));
    EXPECT_EQ(result.applied, 1u);
    EXPECT_EQ(result.skipped, 3u);
    EXPECT_EQ(hooks.added, 0);
    EXPECT_EQ(hooks.removed, 0);
    // The slot gets reused by a later entity; the stale commands never touch it.
    const Entity reused = registry.create();
    EXPECT_EQ(reused.index(), e.index());
    EXPECT_FALSE(registry.has<Health>(reused));
}

TEST(CommandBuffer, CreateThenDestroyInOneBuffer) {
    Registry registry;
    CommandBuffer commands(registry);
    const Entity e = commands.create();
    commands.emplace<Name>(e, Name{"short-lived"});
    commands.destroy(e);
    commands.apply();
    EXPECT_FALSE(registry.valid(e));
    EXPECT_EQ(registry.aliveCount(), 0u);
}

TEST(CommandBuffer, StructuralChangesWhileIteratingGoThroughTheBuffer) {
    Registry registry;
    std::vector<Entity> entities;
    for (int i = 0; i < 100; ++i) {
        entities.push_back(registry.create());
        registry.emplace<Health>(entities.back(), i);
    }
    CommandBuffer commands(registry);
    registry.view<Health>().each([&](Entity e, Health& h) {
        if (h.value % 2 == 0) {
            commands.destroy(e);
        } else {
            commands.emplace<Velocity>(e);
            const Entity spawned = commands.create();
            commands.emplace<Health>(spawned, 1000 + h.value);
        }
    });
    commands.apply();
    EXPECT_EQ(registry.view<Health>().size(), 100u);  // 50 survivors + 50 spawned
    EXPECT_EQ((registry.view<Health, Velocity>().size()), 50u);
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(registry.valid(entities[std::size_t(i)]), i % 2 == 1);
    }
}

TEST(CommandBuffer, DeferredCallsRunInOrder) {
    Registry registry;
    const Entity parent = registry.create();
    CommandBuffer commands(registry);
    const Entity child = commands.create();
    commands.defer(
        [=](Registry& r) { EXPECT_EQ(setParent(r, child, parent), ReparentResult::Ok); });
    commands.apply();
    EXPECT_EQ(parentOf(registry, child), parent);
}

TEST(CommandBuffer, DiscardedCreatesAreReleased) {
    Registry registry;
    Entity reserved;
    {
        CommandBuffer commands(registry);
        reserved = commands.create();
        commands.emplace<Name>(reserved, Name{std::string(100, 'x')});
    }  // never applied
    EXPECT_FALSE(registry.valid(reserved));
    EXPECT_FALSE(registry.isReserved(reserved));
    const Entity next = registry.create();
    EXPECT_TRUE(registry.valid(next));
}

TEST(CommandBuffer, ApplyWhileIteratingIsRejectedWithoutConsumingCommands) {
    Registry registry;
    const Entity e = registry.create();
    registry.emplace<Health>(e);
    CommandBuffer commands(registry);
    commands.emplace<Position>(e);
#ifdef NDEBUG
    registry.view<Health>().each([&](Health&) { EXPECT_THROW(commands.apply(), EcsError); });
#endif
    EXPECT_EQ(commands.size(), 1u);
    commands.apply();
    EXPECT_TRUE(registry.has<Position>(e));
}

TEST(CommandBuffer, ReusableAfterApply) {
    Registry registry;
    CommandBuffer commands(registry);
    for (int frame = 0; frame < 3; ++frame) {
        for (int i = 0; i < 1000; ++i) {
            const Entity e = commands.create();
            commands.emplace<Name>(e, Name{"entity"});
        }
        commands.apply();
    }
    EXPECT_EQ(registry.aliveCount(), 3000u);
}

}  // namespace
}  // namespace candela::ecs
