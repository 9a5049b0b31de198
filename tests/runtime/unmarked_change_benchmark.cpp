// candela-bench-unmarked-changes: one frame's unmarked-change checks (SceneWorld::updateTransforms)
// against the change-driven transform propagation of the same unchanged world, same process.
// Medians of 30 frames at 1,000 / 10,000 / 100,000 entities (every tenth with a Light).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>
#include "candela/content/components/light.h"
#include "candela/ecs/transform.h"
#include "candela/ecs/transform_propagation.h"
#include "unmarked_changes.h"
using namespace candela;
using Clock = std::chrono::steady_clock;
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}
int main() {
    for (int n : {1000, 10000, 100000}) {
        ecs::Registry r;
        for (int i = 0; i < n; ++i) {
            auto e = r.create();
            r.emplace<ecs::LocalTransform>(e);
            r.emplace<ecs::WorldTransform>(e);
            if (i % 10 == 0) r.emplace<content::Light>(e);
        }
        runtime::UnmarkedChangeCheck<content::Light> lights("Light");
        runtime::UnmarkedChangeCheck<ecs::LocalTransform> transforms("LocalTransform");
        std::vector<double> check, propagate;
        for (int f = 0; f < 30; ++f) {
            auto t0 = Clock::now();
            lights.run(r);
            transforms.run(r);
            auto t1 = Clock::now();
            ecs::propagateTransforms(r);
            auto t2 = Clock::now();
            check.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
            propagate.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
        }
        std::printf(
            "%6d entities (%d lights): checks %.3f ms, propagation %.3f ms (medians of 30 "
            "frames)\n",
            n, n / 10, median(check), median(propagate));
    }
}
