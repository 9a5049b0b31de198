// The usage example from ecs/README.md, kept compiling and checked.
#include <gtest/gtest.h>

#include <candela/ecs/command_buffer.h>
#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_propagation.h>

namespace candela::ecs {
namespace {

struct Light {
    float lumens = 800;
};
struct Frozen {};

TEST(ReadmeExample, Runs) {
    Registry registry;
    Entity lamp = registry.create();
    registry.emplace<LocalTransform>(lamp, LocalTransform{{0, 2, 0}, {}, {1, 1, 1}});
    registry.emplace<WorldTransform>(lamp);
    Entity bulb = registry.create();
    registry.emplace<LocalTransform>(bulb, LocalTransform{{0, -0.3f, 0}, {}, {1, 1, 1}});
    registry.emplace<WorldTransform>(bulb);
    registry.emplace<Light>(bulb);
    ASSERT_EQ(setParent(registry, bulb, lamp), ReparentResult::Ok);

    registry.patch<LocalTransform>(lamp, [](LocalTransform& t) { t.position.y = 3; });
    propagateTransforms(registry);

    Tick lastUpload = kNeverTick;
    Tick upTo = registry.advanceTick();
    int uploaded = 0;
    registry.view<const Light, const WorldTransform>().eachChangedSince(
        lastUpload, [&](Entity e, const Light&, const WorldTransform& world) {
            EXPECT_EQ(e, bulb);
            EXPECT_NEAR(world.position().y, 2.7f, 1e-6f);
            ++uploaded;
        });
    lastUpload = upTo;
    EXPECT_EQ(uploaded, 1);

    int freed = 0;
    registry.onRemove<Light>([&](Registry&, Entity) { ++freed; });
    registry.get<Light>(bulb).lumens = 0;
    CommandBuffer commands(registry);
    registry.view<Light>(exclude<Frozen>).each([&](Entity e, Light& light) {
        if (light.lumens <= 0) commands.destroy(e);
    });
    commands.apply();
    EXPECT_EQ(freed, 1);
    EXPECT_FALSE(registry.valid(bulb));
}

}  // namespace
}  // namespace candela::ecs
