// candela-bench-physics: N dynamic unit boxes dropped in a grid onto a floor, stepped at
// 60 Hz through PhysicsWorld::update, as a game runs it. Prints, per body count, the median
// time per step and its split: Bullet's own step, and what the ECS integration adds (sync
// from components, poses and velocities written back, events). Its side-by-side twin is
// bullet_side_by_side/plain_bullet_boxes.cpp (scripts/bench-physics-vs-bullet).
//   candela-bench-physics [--bodies 1000,10000] [--steps 120]
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

void run(int bodies, int steps) {
    ecs::Registry registry;
    test::addFloor(registry);
    const int columns = std::max(1, int(std::ceil(std::sqrt(bodies / 10.0))));
    for (int i = 0; i < bodies; ++i) {
        test::addCollider(registry, gridPosition(i, columns),
                          test::shapeOf(content::ColliderShape::Box), test::dynamicBody());
    }
    PhysicsWorld physics(registry);
    std::vector<double> total, simulate, integration;
    for (int s = 0; s < steps; ++s) {
        physics.update(1.0 / 60.0);
        const PhysicsTimings t = physics.lastTimings();
        if (s == 0) continue;  // the first update makes every body
        total.push_back(1e3 * (t.simulate + t.integration));
        simulate.push_back(1e3 * t.simulate);
        integration.push_back(1e3 * t.integration);
    }
    const double add = median(integration);
    std::printf("| %d | %.3f | %.3f | %.3f | %.1f | %.1f%% |\n", bodies, median(total),
                median(simulate), add, 1e6 * add / bodies, 100.0 * add / median(simulate));
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts{1000, 10000};
    int steps = 120;
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
