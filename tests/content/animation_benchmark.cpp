// candela-bench-animation: CPU cost of animating 1 to 10,000 Foxes (24 joints each): clip
// sampling + writing local transforms, transform propagation, and joint matrices, against the
// same scene standing still (players paused, nothing changes), in one process. One thread
// (JobSystem with no workers), so ns per joint compares with single-threaded runtimes.
// Then the GPU side: the renderer's skinning pass (SkinningPass::record, one dispatch per Fox
// into its own vertex buffer) timed with timestamps, against the static scene (which declares
// no skinning pass: 0 ms) and against copying the same bytes (a bandwidth floor).
// Usage: candela-bench-animation [--max-foxes N] [--frames F] [--gpu-frames G] [--no-gpu]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench_frame_timing.h"
#include "candela/content/animation_systems.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/ecs/transform_propagation.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "gpu_timer.h"
#include "passes/skinning/skinning_pass.h"

namespace {

using namespace candela;
using bench::framesPerClockPair;
using bench::median;
using bench::threadCpuNs;

// Per stage (three clock pairs per frame) and the whole frame (one pair per `batch` frames,
// as ozz-animation's side-by-side program times its frames): a thread CPU clock read is a
// system call of about 0.5 us here, which each timed interval carries once. A one-Fox frame
// is about that long, so the whole frame is timed over a batch of frames and divided
// (framesPerClockPair), and the stages' sum overstates a one-Fox frame by two reads.
struct FrameTimes {
    double sampleNs = 0, propagateNs = 0, skinNs = 0, frameNs = 0;
};

FrameTimes measure(ecs::Registry& registry, ecs::JobSystem& jobs, int frames, int batch) {
    std::vector<double> sample, propagate, skin, whole;
    for (int f = 0; f < frames; ++f) {
        const double t0 = threadCpuNs();
        for (int b = 0; b < batch; ++b) {
            content::advanceAnimationPlayers(registry, jobs, 1.0f / 60.0f);
            ecs::propagateTransforms(registry);
            content::updateSkins(registry, jobs);
        }
        whole.push_back((threadCpuNs() - t0) / batch);
    }
    for (int f = 0; f < frames; ++f) {
        const double t0 = threadCpuNs();
        content::advanceAnimationPlayers(registry, jobs, 1.0f / 60.0f);
        const double t1 = threadCpuNs();
        ecs::propagateTransforms(registry);
        const double t2 = threadCpuNs();
        content::updateSkins(registry, jobs);
        const double t3 = threadCpuNs();
        sample.push_back(t1 - t0);
        propagate.push_back(t2 - t1);
        skin.push_back(t3 - t2);
    }
    return {median(sample), median(propagate), median(skin), median(whole)};
}

// The skinning pass over every Fox in `registry` (each with its own target buffer), and a
// plain copy of the same vertex bytes into the same buffers: medians over `frames`.
struct GpuTimes {
    double skinningMs = 0, copyMs = 0;
};

GpuTimes measureGpu(render::GpuContext& context, render::SceneResources& resources,
                    render::SkinningPass& pass, uint32_t mesh, ecs::Registry& registry,
                    int frames) {
    std::vector<glm::mat4> joints;
    std::vector<render::DeformJob> jobs;
    registry.view<const content::Skin>().each([&](const content::Skin& skin) {
        render::DeformJob job;
        job.mesh = mesh;
        job.target = resources.deformedVertexBuffers(jobs.size(), mesh, false).current;
        job.firstJoint = static_cast<uint32_t>(joints.size());
        job.jointCount = static_cast<uint32_t>(skin.jointMatrices.size());
        for (const ecs::Mat4& m : skin.jointMatrices) {
            glm::mat4 g;
            std::memcpy(&g[0][0], m.m, sizeof(m.m));
            joints.push_back(g);
        }
        jobs.push_back(job);
    });
    pass.upload(joints, {});
    render::FrameScene scene;
    scene.deforms = jobs;
    test::GpuTimer timer(context);
    const render::GpuMesh& source = resources.mesh(mesh);
    const VkBufferCopy region{0, 0, source.vertices.size()};
    std::vector<double> skinning, copy;
    for (int f = 0; f < frames; ++f) {
        skinning.push_back(
            timer.ms([&](VkCommandBuffer cmd) { pass.record(cmd, scene, resources); }));
        copy.push_back(timer.ms([&](VkCommandBuffer cmd) {
            for (const render::DeformJob& job : jobs)
                vkCmdCopyBuffer(cmd, source.vertices.handle(), job.target, 1, &region);
        }));
    }
    resources.releaseUnusedDeformed();  // twice: the next size asks for its own
    resources.releaseUnusedDeformed();
    return {median(skinning), median(copy)};
}

}  // namespace

int main(int argc, char** argv) {
    int maxFoxes = 10000;
    int frames = 30;
    int gpuFrames = 5;
    bool gpu = true;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--no-gpu") {
            gpu = false;
        } else if (i + 1 < argc && arg == "--max-foxes") {
            maxFoxes = std::atoi(argv[++i]);
        } else if (i + 1 < argc && arg == "--frames") {
            frames = std::atoi(argv[++i]);
        } else if (i + 1 < argc && arg == "--gpu-frames") {
            gpuFrames = std::atoi(argv[++i]);
        } else {
            std::fprintf(stderr, "candela-bench-animation: unknown option '%s'\n", arg.c_str());
            return 2;
        }
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
    std::unique_ptr<render::GpuContext> context;
    std::unique_ptr<render::SceneResources> resources;
    std::unique_ptr<render::SkinningPass> pass;
    uint32_t mesh = 0;
    if (gpu) {
        render::GpuContextOptions options;
        options.validation = render::ValidationMode::Off;  // timing, not checking
        context = std::make_unique<render::GpuContext>(options);
        resources = std::make_unique<render::SceneResources>(*context);
        pass = std::make_unique<render::SkinningPass>(*context);
        for (std::size_t n = 0; n < fox->nodes.size(); ++n) {
            if (fox->nodes[n].skin == 0) {
                const auto& uploaded = resources->addModel(*fox);
                mesh = uploaded.firstPrimitiveOfMesh[static_cast<std::size_t>(fox->nodes[n].mesh)];
            }
        }
        std::printf("GPU: %s, %u vertices per Fox, %d frames per size, timestamps, medians\n",
                    context->deviceName().c_str(), resources->mesh(mesh).vertexCount, gpuFrames);
    }
    std::printf(
        "| foxes | sample+write ms | propagate ms | joint matrices ms | frame ms (one clock "
        "pair per 1,000 / foxes frames) | ns/joint (sample+joint matrices) | static scene ms | "
        "animated / static | GPU "
        "skinning ms | GPU static scene ms | GPU copy of the same bytes ms |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
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
        const int batch = framesPerClockPair(foxes);
        measure(registry, jobs, 3, 1);  // warm: scratch sized, propagation order built
        const FrameTimes animated = measure(registry, jobs, frames, batch);
        // The static scene declares no skinning pass: its GPU skinning cost is 0 by design.
        const GpuTimes gpuTimes =
            gpu ? measureGpu(*context, *resources, *pass, mesh, registry, gpuFrames) : GpuTimes{};
        // The static baseline: the same entities, players removed (no animation at all).
        for (ecs::Entity e : players)
            registry.remove<content::AnimationPlayer>(e);
        measure(registry, jobs, 3, 1);
        const FrameTimes still = measure(registry, jobs, frames, batch);
        const double animatedMs =
            (animated.sampleNs + animated.propagateNs + animated.skinNs) / 1e6;
        const double staticMs = (still.sampleNs + still.propagateNs + still.skinNs) / 1e6;
        const double perJoint = (animated.sampleNs + animated.skinNs) /
                                (static_cast<double>(foxes) * static_cast<double>(joints));
        std::printf("| %d | %.4f | %.4f | %.4f | %.6f | %.1f | %.4f | %.1fx | ", foxes,
                    animated.sampleNs / 1e6, animated.propagateNs / 1e6, animated.skinNs / 1e6,
                    animated.frameNs / 1e6, perJoint, staticMs,
                    staticMs > 0 ? animatedMs / staticMs : 0.0);
        if (gpu)
            std::printf("%.3f | 0 | %.3f |\n", gpuTimes.skinningMs, gpuTimes.copyMs);
        else
            std::printf("- | - | - |\n");
    }
    return 0;
}
