#include "candela/runtime/fly_camera.h"

#include <algorithm>

#include "candela/ecs/transform.h"
#include "candela/runtime/application.h"

namespace candela::runtime {

ecs::Quat flyCameraRotation(float yaw, float pitch) {
    return ecs::normalize(ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, yaw) *
                          ecs::Quat::fromAxisAngle({1.0f, 0.0f, 0.0f}, pitch));
}

void updateFlyCameras(SceneWorld& world, const FrameContext& frame) {
    const InputState& in = frame.keys();
    const float dt = float(frame.deltaSeconds);
    world.registry.view<ecs::LocalTransform, FlyCamera>().each(
        [&](ecs::Entity e, ecs::LocalTransform& local, FlyCamera& fly) {
            if (in.down(MouseButton::Right) || in.down(MouseButton::Left)) {
                fly.yaw -= in.mouseDeltaX * fly.radiansPerPixel;
                fly.pitch =
                    std::clamp(fly.pitch - in.mouseDeltaY * fly.radiansPerPixel, -1.5f, 1.5f);
            }
            const ecs::Quat rotation = flyCameraRotation(fly.yaw, fly.pitch);
            const ecs::Vec3 forward = ecs::rotate(rotation, {0.0f, 0.0f, -1.0f});
            const ecs::Vec3 right = ecs::rotate(rotation, {1.0f, 0.0f, 0.0f});
            ecs::Vec3 move{};
            if (in.down(Key::W)) move += forward;
            if (in.down(Key::S)) move -= forward;
            if (in.down(Key::D)) move += right;
            if (in.down(Key::A)) move -= right;
            if (in.down(Key::E)) move += ecs::Vec3{0.0f, 1.0f, 0.0f};
            if (in.down(Key::Q)) move -= ecs::Vec3{0.0f, 1.0f, 0.0f};
            float speed = fly.metresPerSecond;
            if (in.down(Key::LeftShift) || in.down(Key::RightShift)) speed *= fly.fastMultiplier;
            if (float len = ecs::length(move); len > 0.0f) move *= speed * dt / len;
            if (!(local.rotation == rotation) || ecs::length(move) > 0.0f) {
                local.rotation = rotation;
                local.position += move;
                world.registry.markChanged<ecs::LocalTransform>(e);
            }
        });
}

void addFlyCameraSystem(Application& app) {
    app.addSystem("fly cameras", ecs::Phase::Update, updateFlyCameras)
        .writes<FlyCamera, ecs::LocalTransform>();
}

}  // namespace candela::runtime
