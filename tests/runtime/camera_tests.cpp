// The demo's cameras without a GPU: the path passes through its keys and loops, and the fly
// camera moves by the input it is given.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/content/components/camera.h"
#include "candela/ecs/transform.h"
#include "candela/runtime/camera_path.h"
#include "candela/runtime/fly_camera.h"

using namespace candela;
using namespace candela::runtime;

namespace {

ecs::Vec3 forwardOf(ecs::Quat q) {
    return ecs::rotate(q, {0.0f, 0.0f, -1.0f});
}

void expectNear(ecs::Vec3 a, ecs::Vec3 b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace

TEST(CameraPath, PassesThroughItsKeysLookingAtTheirTargets) {
    CameraPath path({{{0, 1, 5}, {0, 1, 0}}, {{5, 2, 0}, {0, 0, 0}}, {{0, 3, -5}, {1, 0, 0}}},
                    2.0f);
    EXPECT_FLOAT_EQ(path.loopSeconds(), 6.0f);
    CameraPose atSecondKey = path.pose(2.0);
    expectNear(atSecondKey.position, {5, 2, 0});
    ecs::Vec3 toTarget = ecs::Vec3{0, 0, 0} - ecs::Vec3{5, 2, 0};
    expectNear(forwardOf(atSecondKey.rotation), toTarget * (1.0f / ecs::length(toTarget)));
    // The loop closes: one loop later is the same pose; halfway differs from both ends.
    expectNear(path.pose(7.3).position, path.pose(1.3).position);
    CameraPose mid = path.pose(1.0);
    EXPECT_GT(ecs::length(mid.position - ecs::Vec3{0, 1, 5}), 0.5f);
    EXPECT_GT(ecs::length(mid.position - ecs::Vec3{5, 2, 0}), 0.5f);
}

TEST(CameraPath, RejectsTooFewKeysAndBadTiming) {
    EXPECT_THROW(CameraPath({{{0, 0, 0}, {0, 0, -1}}}, 1.0f), std::invalid_argument);
    EXPECT_THROW(CameraPath({{{0, 0, 0}, {0, 0, -1}}, {{1, 0, 0}, {0, 0, -1}}}, 0.0f),
                 std::invalid_argument);
}

TEST(FlyCamera, WMovesForwardAndShiftIsFaster) {
    SceneWorld world;
    ecs::Entity cam = world.registry.create();
    world.registry.emplace<ecs::LocalTransform>(cam);
    world.registry.emplace<ecs::WorldTransform>(cam);
    world.registry.emplace<content::Camera>(cam);
    FlyCamera fly;
    fly.metresPerSecond = 2.0f;
    fly.fastMultiplier = 3.0f;
    world.registry.emplace<FlyCamera>(cam, fly);

    InputState input;
    FrameContext frame;
    frame.input = &input;
    frame.deltaSeconds = 0.5;
    input.setKey(Key::W, true);
    updateFlyCameras(world, frame);  // 0.5 s at 2 m/s along -Z
    expectNear(world.registry.get<ecs::LocalTransform>(cam).position, {0, 0, -1});
    input.setKey(Key::LeftShift, true);
    updateFlyCameras(world, frame);  // 0.5 s at 6 m/s
    expectNear(world.registry.get<ecs::LocalTransform>(cam).position, {0, 0, -4});

    // Mouse look only while a button is held: 100 px right at 0.01 rad/px turns 1 rad right.
    input = InputState{};
    world.registry.get<FlyCamera>(cam).radiansPerPixel = 0.01f;
    input.mouseDeltaX = 100.0f;
    updateFlyCameras(world, frame);
    expectNear(forwardOf(world.registry.get<ecs::LocalTransform>(cam).rotation), {0, 0, -1});
    input.setButton(MouseButton::Right, true);
    input.mouseDeltaX = 100.0f;
    updateFlyCameras(world, frame);
    expectNear(forwardOf(world.registry.get<ecs::LocalTransform>(cam).rotation),
               {std::sin(1.0f), 0.0f, -std::cos(1.0f)});
}
