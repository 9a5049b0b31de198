// screenRay (issue 47): the ray under a pixel, as the renderer projects the scene, and a pick
// through physics' raycast.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/ecs/rotation.h"
#include "candela/ecs/transform.h"
#include "candela/physics/physics_queries.h"
#include "candela/runtime/scene_world.h"
#include "candela/runtime/screen_ray.h"

using namespace candela;
using namespace candela::runtime;

namespace {

ecs::Entity addCamera(SceneWorld& world, ecs::Vec3 at, ecs::Vec3 target, float verticalFov) {
    ecs::LocalTransform t{at, *ecs::lookAtRotation(at, target), {1, 1, 1}};
    const ecs::Entity camera = world.spawn("camera", t);
    content::Camera lens;
    lens.verticalFov = verticalFov;
    world.registry.emplace<content::Camera>(camera, lens);
    world.updateTransforms();
    return camera;
}

TEST(ScreenRay, CentreLooksForwardAndEdgesSpanTheFieldOfView) {
    SceneWorld world;
    const float fov = 1.0f;
    const ecs::Entity camera = addCamera(world, {1, 2, 3}, {1, 2, -7}, fov);
    const auto centre = screenRay(world.registry, camera, 320, 180, 640, 360);
    ASSERT_TRUE(centre.has_value());
    EXPECT_NEAR(centre->direction.z, -1.0f, 1e-6f);
    EXPECT_EQ(centre->origin, (ecs::Vec3{1, 2, 3}));
    // The top edge's middle is half the vertical field of view up; the right edge's middle
    // is atan(aspect tan(fov / 2)) to the right.
    const auto top = screenRay(world.registry, camera, 320, 0, 640, 360);
    EXPECT_NEAR(std::atan2(top->direction.y, -top->direction.z), 0.5f * fov, 1e-5f);
    const auto right = screenRay(world.registry, camera, 640, 180, 640, 360);
    EXPECT_NEAR(std::atan2(right->direction.x, -right->direction.z),
                std::atan(640.0f / 360.0f * std::tan(0.5f * fov)), 1e-5f);
    EXPECT_FALSE(screenRay(world.registry, camera, 0, 0, 0, 360).has_value());
    EXPECT_FALSE(screenRay(world.registry, world.spawn("no camera"), 0, 0, 64, 64).has_value());
}

TEST(ScreenRay, PicksTheBoxUnderThePixelThroughPhysics) {
    SceneWorld world;
    const ecs::Entity camera = addCamera(world, {0, 5, 10}, {0, 0, 0}, 0.8f);
    const ecs::Entity box = world.spawn("box", ecs::LocalTransform{{0, 0.5f, 0}, {}, {1, 1, 1}});
    world.registry.emplace<content::Collider>(box);
    world.stepPhysics(0.0);  // makes and syncs the world
    const auto ray = screenRay(world.registry, camera, 128, 128, 256, 256);
    ASSERT_TRUE(ray.has_value());
    const auto hit = physics::raycast(world.physics(), ray->origin, ray->direction, 100.0f);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->entity, box);
    // A corner of the view misses it.
    const auto corner = screenRay(world.registry, camera, 0, 0, 256, 256);
    EXPECT_FALSE(physics::raycast(world.physics(), corner->origin, corner->direction, 100.0f));
}

}  // namespace
