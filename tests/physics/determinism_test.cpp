// The same scene, steps and game writes give the same body states, byte for byte.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

// A pile of mixed shapes dropped at angles onto a floor, with game code kicking one body
// every 30 frames (the replay), then every entity's transform and velocities as bytes.
std::vector<unsigned char> runPile() {
    ecs::Registry registry;
    addFloor(registry);
    std::vector<ecs::Entity> bodies;
    for (int i = 0; i < 60; ++i) {
        const auto shape = static_cast<ColliderShape>(i % 4);
        const ecs::Quat tilt = ecs::Quat::fromAxisAngle({1, 0.3f, 0.2f}, 0.1f * float(i));
        bodies.push_back(addCollider(
            registry, {float(i % 4) * 0.3f, 1.0f + 1.1f * float(i / 4), float(i % 3) * 0.25f},
            shapeOf(shape), dynamicBody(1.0f + float(i % 3)), tilt));
    }
    PhysicsWorld physics(registry);
    for (int frame = 0; frame < 240; ++frame) {
        if (frame % 30 == 0) {
            const ecs::Entity kicked = bodies[std::size_t(frame / 30 * 7) % bodies.size()];
            registry.patch<content::RigidBody>(kicked, [](content::RigidBody& b) {
                b.linearVelocity += ecs::Vec3{2.0f, 4.0f, -1.0f};
            });
        }
        physics.update(1.0 / 60.0);
    }
    std::vector<unsigned char> bytes;
    const auto append = [&](const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), p, p + size);
    };
    for (const ecs::Entity e : bodies) {
        const auto& t = registry.get<ecs::LocalTransform>(e);
        const auto& b = registry.get<content::RigidBody>(e);
        append(&t.position, sizeof t.position);
        append(&t.rotation, sizeof t.rotation);
        append(&b.linearVelocity, sizeof b.linearVelocity);
        append(&b.angularVelocity, sizeof b.angularVelocity);
    }
    return bytes;
}

TEST(Determinism, ReplayGivesTheSameBodyStatesByteForByte) {
    const std::vector<unsigned char> first = runPile();
    const std::vector<unsigned char> second = runPile();
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size()), 0);
}

}  // namespace
}  // namespace candela::physics
