// candela-bench-physics: N dynamic unit boxes dropped in a grid onto a floor, stepped at
// 60 Hz through PhysicsWorld::update, as a game runs it. Prints, per body count, the median
// time per step and its split: Bullet's own step, and what the ECS integration adds (sync
// from components, poses and velocities written back, events). Its side-by-side twin is
// bullet_side_by_side/plain_bullet_boxes.cpp (scripts/bench-physics-vs-bullet).
// --speed-vs-error instead prints docs/physics-speed-vs-error.md's table: solver settings
// against how still stacks stay, how true a bounce is, and the cost of a step.
//   candela-bench-physics [--bodies 1000,10000] [--steps 120] [--speed-vs-error]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

using namespace candela;
using namespace candela::physics;

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// The grid both programs build: columns 1.1 m apart, ten boxes high, 1.1 m apart.
ecs::Vec3 gridPosition(int i, int columns) {
    const int layer = i / (columns * columns);
    const int cell = i % (columns * columns);
    return {1.1f * float(cell % columns - columns / 2), 0.5f + 1.1f * float(layer),
            1.1f * float(cell / columns - columns / 2)};
}

struct Measured {
    double totalMs = 0, simulateMs = 0, integrationMs = 0;
};

Measured dropBoxes(int bodies, int steps, const PhysicsSettings& settings) {
    ecs::Registry registry;
    test::addFloor(registry);
    const int columns = std::max(1, int(std::ceil(std::sqrt(bodies / 10.0))));
    for (int i = 0; i < bodies; ++i) {
        test::addCollider(registry, gridPosition(i, columns),
                          test::shapeOf(content::ColliderShape::Box), test::dynamicBody());
    }
    PhysicsWorld physics(registry, settings);
    std::vector<double> total, simulate, integration;
    for (int s = 0; s < steps; ++s) {
        physics.update(1.0 / 60.0);
        const PhysicsTimings t = physics.lastTimings();
        if (s == 0) continue;  // the first update makes every body
        total.push_back(1e3 * (t.simulate + t.integration));
        simulate.push_back(1e3 * t.simulate);
        integration.push_back(1e3 * t.integration);
    }
    return {median(total), median(simulate), median(integration)};
}

void run(int bodies, int steps) {
    const Measured m = dropBoxes(bodies, steps, {});
    std::printf("| %d | %.3f | %.3f | %.3f | %.1f | %.1f%% |\n", bodies, m.totalMs, m.simulateMs,
                m.integrationMs, 1e6 * m.integrationMs / bodies,
                100.0 * m.integrationMs / m.simulateMs);
}

// The farthest any body of a stack ends from where it was put, after 5 s (metres).
float worstDrift(const std::vector<std::pair<content::Collider, ecs::Vec3>>& bodies, float mass,
                 const PhysicsSettings& settings) {
    ecs::Registry registry;
    test::addFloor(registry);
    std::vector<ecs::Entity> made;
    for (const auto& [collider, at] : bodies)
        made.push_back(test::addCollider(registry, at, collider, test::dynamicBody(mass)));
    PhysicsSettings exact = settings;
    exact.interpolate = false;
    PhysicsWorld physics(registry, exact);
    for (int i = 0; i < 300; ++i)
        physics.update(1.0 / 60.0);
    float worst = 0;
    for (std::size_t i = 0; i < made.size(); ++i) {
        const ecs::Vec3 d = test::positionOf(registry, made[i]) - bodies[i].second;
        worst = std::max(worst, ecs::length(d));
    }
    return worst;
}

std::vector<std::pair<content::Collider, ecs::Vec3>> column(content::ColliderShape shape,
                                                            ecs::Vec3 half, int count) {
    content::Collider collider = test::shapeOf(shape);
    if (shape == content::ColliderShape::Box) {
        collider.halfExtents = half;
    } else {
        collider.radius = half.x;
        collider.height = 2 * half.y;
    }
    std::vector<std::pair<content::Collider, ecs::Vec3>> out;
    for (int i = 0; i < count; ++i)
        out.push_back({collider, {0, half.y * float(2 * i + 1), 0}});
    return out;
}

std::vector<std::pair<content::Collider, ecs::Vec3>> pyramid() {
    content::Collider brick = test::shapeOf(content::ColliderShape::Box);
    brick.halfExtents = ecs::Vec3{0.4f, 0.3f, 0.4f};
    std::vector<std::pair<content::Collider, ecs::Vec3>> out;
    for (int row = 0; row < 5; ++row) {
        for (int i = 0; i < 5 - row; ++i)
            out.push_back(
                {brick, {0.81f * (float(i) - 0.5f * float(4 - row)), 0.3f + 0.6f * float(row), 0}});
    }
    return out;
}

// A restitution-0.5 ball dropped 2 m onto the floor: its first bounce's apex over the 0.5 m
// that restitution allows, minus one.
double bounceError(const PhysicsSettings& settings) {
    ecs::Registry registry;
    test::addFloor(registry);
    content::RigidBody rubber = test::dynamicBody();
    rubber.restitution = 0.5f;
    const ecs::Entity ball = test::addCollider(
        registry, {0, 2.5f, 0}, test::shapeOf(content::ColliderShape::Sphere), rubber);
    PhysicsSettings exact = settings;
    exact.interpolate = false;
    PhysicsWorld physics(registry, exact);
    bool bounced = false;
    float apex = 0;
    for (int i = 0; i < 240; ++i) {
        physics.step();
        const float vy = registry.get<content::RigidBody>(ball).linearVelocity.y;
        bounced = bounced || vy > 0;
        if (bounced) apex = std::max(apex, test::positionOf(registry, ball).y - 0.5f);
        if (bounced && vy < 0) break;
    }
    return apex / 0.5 - 1.0;
}

void speedVsError() {
    struct Row {
        const char* name;
        int iterations;
        float splitDepth;
    };
    const Row rows[] = {
        {"Bullet's defaults: 10 iterations, split impulse past 4 cm", 10, 0.04f},
        {"10 iterations, split impulse past 5 mm", 10, 0.005f},
        {"20 iterations, split impulse past 5 mm", 20, 0.005f},
        {"50 iterations, split impulse past 5 mm (the default)", 50, 0.005f},
        {"100 iterations, split impulse past 5 mm", 100, 0.005f},
    };
    std::printf(
        "| solver (two friction directions per contact) | 10 unit boxes | 12 heavy planks | "
        "10 small boxes | pyramid of 15 (untuned) | 8 cylinders (untuned) | bounce apex "
        "error, 60 Hz | 240 Hz | ms per step, 1,000 boxes |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row& row : rows) {
        PhysicsSettings settings;
        settings.solverIterations = row.iterations;
        settings.splitImpulseDepth = row.splitDepth;
        PhysicsSettings fine = settings;
        fine.stepSeconds = 1.0 / 240.0;
        std::printf(
            "| %s | %.1f cm | %.1f cm | %.1f cm | %.1f cm | %.1f cm | %+.1f%% | %+.1f%% | %.2f |\n",
            row.name,
            100 * worstDrift(column(content::ColliderShape::Box, {0.5f, 0.5f, 0.5f}, 10), 1,
                             settings),
            100 * worstDrift(column(content::ColliderShape::Box, {1.0f, 0.1f, 0.4f}, 12), 8,
                             settings),
            100 * worstDrift(column(content::ColliderShape::Box, {0.1f, 0.1f, 0.1f}, 10), 0.2f,
                             settings),
            100 * worstDrift(pyramid(), 3, settings),
            100 * worstDrift(column(content::ColliderShape::Cylinder, {0.3f, 0.3f, 0.3f}, 8), 1.5f,
                             settings),
            100 * bounceError(settings), 100 * bounceError(fine),
            dropBoxes(1000, 120, settings).totalMs);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts{1000, 10000};
    int steps = 120;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--speed-vs-error") {
            speedVsError();
            return 0;
        }
    }
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--steps") {
            steps = std::max(2, std::atoi(argv[i + 1]));
        } else if (flag == "--bodies") {
            counts.clear();
            for (std::string list = argv[i + 1]; !list.empty();) {
                const auto comma = list.find(',');
                counts.push_back(std::max(1, std::atoi(list.substr(0, comma).c_str())));
                list = comma == std::string::npos ? "" : list.substr(comma + 1);
            }
        }
    }
    std::printf(
        "| bodies | ms per step | Bullet step ms | integration ms | integration ns per body | "
        "integration / Bullet |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|\n");
    for (int bodies : counts)
        run(bodies, steps);
}
