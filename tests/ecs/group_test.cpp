#include <gtest/gtest.h>

#include <random>
#include <set>

#include <candela/ecs/registry.h>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Frozen;
using test::Health;
using test::Name;
using test::Position;
using test::Velocity;

// The group's members, read back through the aligned (grouped) walk.
std::set<Entity> groupMembers(Registry& registry) {
    std::set<Entity> out;
    registry.view<Position, Velocity>().each(
        [&](Entity e, Position&, Velocity&) { EXPECT_TRUE(out.insert(e).second); });
    return out;
}

TEST(Group, PacksExistingAndNewMembers) {
    Registry registry;
    std::set<Entity> expected;
    for (int i = 0; i < 50; ++i) {
        const Entity e = registry.create();
        registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
        if (i % 3 != 0) {
            registry.emplace<Velocity>(e);
            expected.insert(e);
        }
    }
    registry.group<Position, Velocity>();  // declared after the fact: existing members packed
    EXPECT_EQ(groupMembers(registry), expected);
    EXPECT_EQ((registry.view<Position, Velocity>().size()), expected.size());

    const Entity late = registry.create();
    registry.emplace<Velocity>(late);
    EXPECT_EQ(groupMembers(registry), expected);
    registry.emplace<Position>(late);
    expected.insert(late);
    EXPECT_EQ(groupMembers(registry), expected);
}

TEST(Group, ComponentsStayWithTheirEntities) {
    Registry registry;
    registry.group<Position, Velocity>();
    std::vector<Entity> entities;
    for (int i = 0; i < 20; ++i) {
        const Entity e = registry.create();
        registry.emplace<Velocity>(e, float(i), 0.0f, 0.0f);
        registry.emplace<Position>(e, float(i), 0.0f, 0.0f);
        entities.push_back(e);
    }
    registry.remove<Velocity>(entities[3]);
    registry.destroy(entities[7]);
    registry.remove<Position>(entities[0]);
    registry.view<Position, Velocity>().each([](Position& p, Velocity& v) { EXPECT_EQ(p.x, v.x); });
    for (int i = 0; i < 20; ++i) {
        const Entity e = entities[std::size_t(i)];
        if (const Position* p = registry.tryGet<Position>(e)) {
            EXPECT_EQ(p->x, float(i));
        }
        if (const Velocity* v = registry.tryGet<Velocity>(e)) {
            EXPECT_EQ(v->x, float(i));
        }
    }
}

// Random adds, removes and destroys against a simple model of who should be in the group.
TEST(Group, MatchesAModelUnderRandomChanges) {
    Registry registry;
    registry.group<Position, Velocity>();
    std::mt19937 random(1234);  // fixed seed: reproducible
    std::vector<Entity> entities;
    for (int step = 0; step < 20'000; ++step) {
        const auto action = static_cast<unsigned>(random() % 6);
        if (entities.empty() || action == 0) {
            entities.push_back(registry.create());
            continue;
        }
        const std::size_t pick = random() % entities.size();
        const Entity e = entities[pick];
        switch (action) {
            case 1:
                registry.emplace<Position>(e, float(e.index()), 0.0f, 0.0f);
                break;
            case 2:
                registry.emplace<Velocity>(e, float(e.index()), 0.0f, 0.0f);
                break;
            case 3:
                registry.remove<Position>(e);
                break;
            case 4:
                registry.remove<Velocity>(e);
                break;
            case 5:
                registry.destroy(e);
                entities[pick] = entities.back();
                entities.pop_back();
                break;
        }
    }
    std::set<Entity> expected;
    for (Entity e : entities) {
        if (registry.has<Position, Velocity>(e)) expected.insert(e);
    }
    EXPECT_EQ(groupMembers(registry), expected);
    registry.view<Position, Velocity>().each([](Entity e, Position& p, Velocity& v) {
        EXPECT_EQ(p.x, float(e.index()));
        EXPECT_EQ(v.x, float(e.index()));
    });
}

TEST(Group, NonTrivialComponentsSurviveGroupSwaps) {
    Registry registry;
    registry.group<Name, Health>();
    std::vector<Entity> entities;
    for (int i = 0; i < 100; ++i) {
        const Entity e = registry.create();
        registry.emplace<Name>(e, Name{"entity number " + std::to_string(i)});
        if (i % 2 == 0) registry.emplace<Health>(e, i);
        entities.push_back(e);
    }
    for (int i = 0; i < 100; i += 4)
        registry.remove<Health>(entities[std::size_t(i)]);
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(registry.get<Name>(entities[std::size_t(i)]).text,
                  "entity number " + std::to_string(i));
    }
    EXPECT_EQ((registry.view<Name, Health>().size()), 25u);
}

TEST(Group, OverlappingGroupsAreRejected) {
    Registry registry;
    registry.group<Position, Velocity>();
    registry.group<Position, Velocity>();  // the same group again is fine
#ifdef NDEBUG
    try {
        registry.group<Velocity, Health>();
        FAIL() << "Velocity already belongs to a group";
    } catch (const EcsError& error) {
        EXPECT_EQ(error.code(), EcsErrorCode::GroupConflict);
    }
#endif
}

TEST(Group, ViewsWithExclusionStillWork) {
    Registry registry;
    registry.group<Position, Velocity>();
    const Entity a = registry.create(), b = registry.create();
    for (Entity e : {a, b}) {
        registry.emplace<Position>(e);
        registry.emplace<Velocity>(e);
    }
    registry.emplace<Frozen>(b);
    std::vector<Entity> seen;
    registry.view<Position, Velocity>(exclude<Frozen>).each([&](Entity e, Position&, Velocity&) {
        seen.push_back(e);
    });
    EXPECT_EQ(seen, std::vector<Entity>{a});
}

}  // namespace
}  // namespace candela::ecs
