// Physics in the application loop (issue 46): a scene file's rigid bodies fall and land
// through Application::update, before transform propagation, with no code of the game's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "candela/content/components/name.h"
#include "candela/ecs/transform.h"
#include "candela/physics/physics_queries.h"
#include "candela/runtime/application.h"

using namespace candela;
using namespace candela::runtime;

namespace {

ecs::Entity named(SceneWorld& world, const std::string& name) {
    ecs::Entity found = ecs::kNullEntity;
    world.registry.view<const content::Name>().each([&](ecs::Entity e, const content::Name& n) {
        if (n.value == name) found = e;
    });
    return found;
}

TEST(PhysicsSystem, SceneFileBodiesFallLandAndPropagate) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "candela_physics_system_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "drop.scene.json";
    std::ofstream(file) << R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "floor", "transform": {"translation": [0, -0.5, 0], "scale": [20, 1, 20]},
         "mesh": {"builtin": "box"}, "collider": {"shape": "box"}},
        {"name": "ball", "transform": {"translation": [0, 3, 0]}, "mesh": {"builtin": "sphere"},
         "rigidBody": {"type": "dynamic", "mass": 1.0, "friction": 0.5, "restitution": 0.0},
         "collider": {"shape": "sphere"}},
        {"name": "coin", "transform": {"translation": [0, 1, 0]},
         "collider": {"shape": "sphere", "radius": 0.3, "trigger": true}}]})";
    ApplicationOptions options;
    options.headless = true;
    Application app(options);
    content::Diagnostics diagnostics;
    ASSERT_TRUE(app.world().loadSceneFile(file, diagnostics)) << diagnostics.toString();
    const ecs::Entity ball = named(app.world(), "ball");
    const ecs::Entity coin = named(app.world(), "coin");
    int coinBegins = 0;
    app.addSystem("collect", ecs::Phase::Update, [&](SceneWorld& world, const FrameContext&) {
        if (!world.hasPhysics()) return;
        for (const physics::TriggerEvent& e : world.physics().events().triggers) {
            if (e.trigger == coin && e.other == ball && e.phase == physics::ContactPhase::Begin)
                ++coinBegins;
        }
    });
    FrameContext frame;
    frame.deltaSeconds = 1.0 / 60.0;
    for (int i = 0; i < 120; ++i)
        app.update(frame);
    // Resting on the floor (sphere of diameter 1), and the world transform followed.
    EXPECT_NEAR(app.world().registry.get<ecs::LocalTransform>(ball).position.y, 0.5f, 0.01f);
    EXPECT_NEAR(app.world().registry.get<ecs::WorldTransform>(ball).position().y, 0.5f, 0.01f);
    EXPECT_EQ(coinBegins, 1);
    // The floor is scaled 20 x 1 x 20: a ray down at x = 9 still hits it at y = 0.
    const auto hit = physics::raycast(app.world().physics(), {9, 5, 0}, {0, -1, 0}, 10);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->entity, named(app.world(), "floor"));
    EXPECT_NEAR(hit->point.y, 0.0f, 1e-4f);
    std::filesystem::remove_all(dir);
}

TEST(PhysicsSystem, AWorldWithoutCollidersMakesNoPhysicsWorld) {
    ApplicationOptions options;
    options.headless = true;
    Application app(options);
    app.world().spawn("lonely");
    app.update(FrameContext{});
    EXPECT_FALSE(app.world().hasPhysics());
}

}  // namespace
