// candela-bench-animation: CPU cost of animating 1 to 10,000 Foxes (24 joints each): clip
// sampling + writing local transforms, transform propagation, and joint matrices, against the
// same scene standing still (players paused, nothing changes), in one process. One thread
// (JobSystem with no workers), so ns per joint compares with single-threaded runtimes.
// Usage: candela-bench-animation [--max-foxes N] [--frames F]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "candela/content/animation_systems.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/ecs/transform_propagation.h"

namespace {

using namespace candela;
// Thread CPU time: the development machine is shared, so wall time would count other jobs.
double cpuNow() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct FrameTimes {
    double sampleNs = 0, propagateNs = 0, skinNs = 0;
};

FrameTimes measure(ecs::Registry& registry, ecs::JobSystem& jobs, int frames) {
    std::vector<double> sample, propagate, skin;
    for (int f = 0; f < frames; ++f) {
        const double t0 = cpuNow();
        content::advanceAnimationPlayers(registry, jobs, 1.0f / 60.0f);
        const double t1 = cpuNow();
        ecs::propagateTransforms(registry);
        const double t2 = cpuNow();
        content::updateSkins(registry, jobs);
        const double t3 = cpuNow();
        sample.push_back(t1 - t0);
        propagate.push_back(t2 - t1);
        skin.push_back(t3 - t2);
    }
    return {median(sample), median(propagate), median(skin)};
}

}  // namespace

int main(int argc, char** argv) {
    int maxFoxes = 10000;
    int frames = 30;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string arg = argv[i];
        if (arg == "--max-foxes")
            maxFoxes = std::atoi(argv[i + 1]);
        else if (arg == "--frames")
            frames = std::atoi(argv[i + 1]);
    }
    content::Diagnostics diagnostics;
    const auto fox = content::loadGltf(
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/Fox/Fox.glb", diagnostics);
    if (!fox) {
        std::fprintf(stderr, "%s", diagnostics.toString().c_str());
        return 1;
    }
    const std::size_t joints = fox->skins.at(0).joints.size();
    std::printf(
        "Fox: %zu joints, clip Walk; %d frames per size, medians; one thread, thread CPU time\n",
        joints, frames);
    std::printf(
        "| foxes | sample+write ms | propagate ms | joint matrices ms | ns/joint "
        "(sample+joint matrices) | static scene ms | animated / static |\n"
        "|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int foxes = 1; foxes <= maxFoxes; foxes *= 10) {
        ecs::Registry registry;
        ecs::JobSystem jobs(0);
        std::vector<ecs::Entity> players;
        for (int i = 0; i < foxes; ++i) {
            for (ecs::Entity e : content::instantiateModel(registry, *fox)) {
                if (auto* p = registry.tryGet<content::AnimationPlayer>(e)) {
                    p->play(p->findClip("Walk"));
                    p->time = 0.013f * static_cast<float>(i);  // out of step, as a crowd
                    players.push_back(e);
                }
            }
        }
        measure(registry, jobs, 3);  // warm: scratch sized, propagation order built
        const FrameTimes animated = measure(registry, jobs, frames);
        // The static baseline: the same entities, players removed (no animation at all).
        for (ecs::Entity e : players)
            registry.remove<content::AnimationPlayer>(e);
        measure(registry, jobs, 3);
        const FrameTimes still = measure(registry, jobs, frames);
        const double animatedMs =
            (animated.sampleNs + animated.propagateNs + animated.skinNs) / 1e6;
        const double staticMs = (still.sampleNs + still.propagateNs + still.skinNs) / 1e6;
        const double perJoint = (animated.sampleNs + animated.skinNs) /
                                (static_cast<double>(foxes) * static_cast<double>(joints));
        std::printf("| %d | %.4f | %.4f | %.4f | %.1f | %.4f | %.1fx |\n", foxes,
                    animated.sampleNs / 1e6, animated.propagateNs / 1e6, animated.skinNs / 1e6,
                    perJoint, staticMs, staticMs > 0 ? animatedMs / staticMs : 0.0);
    }
    return 0;
}
