// Rows: skinning (issue 20). The Fox's Walk clip at ten times, its 1728 vertices deformed by
// the engine's joint matrices three ways: the GPU skinning pass (fp32 compute), the CPU
// reference content::deformPrimitive (fp32), and linear blend skinning in double with the same
// matrices (the reference both are measured against). Cost: GPU timestamps around one Fox's
// dispatch against the CPU reference's thread time for the same Fox.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "candela/content/animation_sampling.h"
#include "candela/content/animation_systems.h"
#include "candela/content/components/animation.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/skinning.h"
#include "candela/ecs/transform_propagation.h"
#include "candela/render/scene_resources.h"
#include "gpu_timer.h"
#include "median.h"
#include "mesh_vertex.h"
#include "passes/skinning/skinning_pass.h"
#include "report_context.h"

namespace candela::report {

namespace {

double threadMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Largest component difference between sampleAnimation's LINEAR rotations and slerp in double
// (unit keys, shorter arc) at 97 times per key interval, over every clip of `model`.
double largestRotationDifference(const content::Model& model, std::string& where) {
    double worst = 0;
    for (const content::AnimationClip& clip : model.animations) {
        for (const content::AnimationChannel& channel : clip.channels) {
            const content::AnimationSampler& sampler = clip.samplers[size_t(channel.sampler)];
            if (channel.property != content::AnimatedProperty::Rotation ||
                sampler.interpolation != content::Interpolation::Linear)
                continue;
            for (size_t k = 0; k + 1 < sampler.times.size(); ++k) {
                const float* a = &sampler.values[4 * k];
                const float* b = &sampler.values[4 * (k + 1)];
                double dot = 0, la = 0, lb = 0;
                for (int c = 0; c < 4; ++c) {
                    dot += double(a[c]) * b[c];
                    la += double(a[c]) * a[c];
                    lb += double(b[c]) * b[c];
                }
                const double sign = dot < 0 ? -1 : 1;
                const double theta = std::acos(std::min(1.0, std::fabs(dot) / std::sqrt(la * lb)));
                for (int i = 1; i < 98; ++i) {
                    const double t = i / 98.0;
                    const double wa =
                        theta < 1e-9 ? 1 - t : std::sin((1 - t) * theta) / std::sin(theta);
                    const double wb = theta < 1e-9 ? t : std::sin(t * theta) / std::sin(theta);
                    double exact[4], length = 0;
                    for (int c = 0; c < 4; ++c) {
                        exact[c] = wa * a[c] / std::sqrt(la) + sign * wb * b[c] / std::sqrt(lb);
                        length += exact[c] * exact[c];
                    }
                    float sampled[4];
                    content::sampleAnimation(
                        sampler, content::AnimatedProperty::Rotation,
                        float(sampler.times[k] + t * (sampler.times[k + 1] - sampler.times[k])),
                        sampled);
                    for (int c = 0; c < 4; ++c) {
                        const double d = std::fabs(sampled[c] - exact[c] / std::sqrt(length));
                        if (d > worst) {
                            worst = d;
                            char text[120];
                            std::snprintf(text, sizeof(text), "%s, key %zu, t = %.2f, arc %.3f rad",
                                          clip.name.c_str(), k, t, theta);
                            where = text;
                        }
                    }
                }
            }
        }
    }
    return worst;
}

// Thread time per rotation channel sample, the Walk clip's rotation samplers at 2000 times
// (forward, cursors kept), median of 9 repetitions.
double rotationSampleNs(const std::vector<content::AnimationSampler>& samplers, float duration) {
    std::vector<double> ns;
    float sink = 0;
    constexpr int kTimes = 2000;
    for (int r = 0; r < 9; ++r) {
        std::vector<uint32_t> cursors(samplers.size(), 0);
        const double start = threadMs();
        for (int i = 0; i < kTimes; ++i) {
            const float time = duration * float(i) / kTimes;
            for (size_t s = 0; s < samplers.size(); ++s) {
                float q[4];
                content::sampleAnimation(samplers[s], content::AnimatedProperty::Rotation, time, q,
                                         cursors[s]);
                sink += q[3];
            }
        }
        ns.push_back((threadMs() - start) * 1e6 / (double(kTimes) * double(samplers.size())));
    }
    if (sink == 12345.0f) std::printf(" ");  // keeps the samples
    return median(ns);
}

// Rows: LINEAR rotation sampling, the corrected normalised lerp the loader chooses where its
// measured error is within kNlerpErrorTolerance, against exact slerp (the reference mode,
// prepareSlerpAngles with tolerance 0).
void addRotationSamplingRows(ReportContext& context, const content::Model& fox) {
    std::string where;
    const double worst = largestRotationDifference(fox, where);
    float bound = 0;
    std::vector<content::AnimationSampler> fast, exact;
    float duration = 0;
    for (const content::AnimationClip& clip : fox.animations) {
        for (const content::AnimationSampler& sampler : clip.samplers)
            bound = std::max(bound, sampler.rotationErrorBound);
        if (clip.name != "Walk") continue;
        duration = clip.duration;
        for (const content::AnimationChannel& channel : clip.channels) {
            if (channel.property != content::AnimatedProperty::Rotation) continue;
            fast.push_back(clip.samplers[size_t(channel.sampler)]);
            exact.push_back(fast.back());
            content::prepareSlerpAngles(exact.back(), 0.0);
        }
    }
    const double fastNs = rotationSampleNs(fast, duration);
    const double exactNs = rotationSampleNs(exact, duration);
    char metric[220];
    std::snprintf(metric, sizeof(metric),
                  "largest |quaternion component - slerp in double| at 97 times per key "
                  "interval, Fox's 3 clips (60 rotation channels); bound measured at load "
                  "%.2g rad of arc",
                  double(bound));
    context.report.rows.push_back(
        {"LINEAR rotations: corrected nlerp u = t + t(1-t)(2t-1)(k1 + k2 t(1-t)), k fitted per "
         "key interval at load (within kNlerpErrorTolerance = 2e-6 rad, else slerp)",
         "slerp (double)", metric, worst, "abs", where,
         formatCost(fastNs, exactNs, "ns per channel sample") +
             " (exact slerp: cached angle and sine, two sines per sample; one thread)"});
}

}  // namespace

void addAnimationRows(ReportContext& context) {
    render::GpuContext& gpu = context.harness.context();
    content::Diagnostics diagnostics;
    const auto fox = content::loadGltf(
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/Fox/Fox.glb", diagnostics);
    if (!fox) throw std::runtime_error("animation rows: " + diagnostics.toString());
    addRotationSamplingRows(context, *fox);
    ecs::Registry registry;
    ecs::JobSystem jobs(0);
    ecs::Entity playerEntity = ecs::kNullEntity;
    for (ecs::Entity e : content::instantiateModel(registry, *fox))
        if (registry.has<content::AnimationPlayer>(e)) playerEntity = e;
    auto& player = registry.get<content::AnimationPlayer>(playerEntity);
    const int32_t walk = player.findClip("Walk");
    player.play(walk);
    player.playing = false;
    int32_t meshNode = -1;
    for (size_t n = 0; n < fox->nodes.size(); ++n)
        if (fox->nodes[n].skin == 0) meshNode = int32_t(n);
    const int32_t meshIndex = fox->nodes[size_t(meshNode)].mesh;
    const content::Primitive& primitive = fox->meshes[size_t(meshIndex)].primitives[0];

    render::SceneResources resources(gpu);
    const uint32_t mesh = resources.addModel(*fox).firstPrimitiveOfMesh[size_t(meshIndex)];
    const VkBuffer target = resources.deformedVertexBuffers(1, mesh, false).current;
    const render::GpuBuffer& targetBuffer = *resources.deformedBuffer(1);
    render::GpuBuffer readback(gpu, targetBuffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               render::MemoryLocation::HostVisible);
    render::SkinningPass pass(gpu);
    test::GpuTimer timer(gpu);
    const auto& skin = registry.get<content::Skin>(player.nodeEntities[size_t(meshNode)]);

    double worstGpu = 0.0, worstCpu = 0.0;
    float worstGpuTime = 0.0f;
    std::vector<double> gpuMs, cpuMs;
    content::DeformedVertices cpu;
    const int repeats = context.budget.quick ? 1 : 5;
    const float duration = fox->animations[size_t(walk)].duration;
    for (int step = 0; step < 10; ++step) {
        player.time = duration * (0.05f + 0.1f * float(step));
        content::advanceAnimationPlayers(registry, jobs, 0.0f);
        ecs::propagateTransforms(registry);
        content::updateSkins(registry, jobs);
        std::vector<glm::mat4> joints(skin.jointMatrices.size());
        for (size_t j = 0; j < joints.size(); ++j)
            std::memcpy(&joints[j][0][0], skin.jointMatrices[j].m, sizeof(glm::mat4));
        pass.upload(joints, {});
        const render::SkinningPass::Pose pose{
            pass.jointBuffer().handle(), 0, uint32_t(joints.size()), VK_NULL_HANDLE, 0, 0};
        for (int r = 0; r < repeats; ++r) {
            gpuMs.push_back(timer.ms([&](VkCommandBuffer cmd) {
                pass.recordDeform(cmd, resources.mesh(mesh), pose, target);
            }));
            const double t0 = threadMs();
            content::deformPrimitive(primitive, skin.jointMatrices, {}, cpu);
            cpuMs.push_back(threadMs() - t0);
        }
        gpu.submitAndWait([&](VkCommandBuffer cmd) {
            const VkBufferCopy region{0, 0, targetBuffer.size()};
            vkCmdCopyBuffer(cmd, target, readback.handle(), 1, &region);
        });
        const auto* deformed = static_cast<const render::MeshVertex*>(readback.mapped());
        for (size_t v = 0; v < primitive.positions.size(); ++v) {
            double p[3] = {0, 0, 0};
            for (int c = 0; c < 4; ++c) {
                const float* m = skin.jointMatrices[primitive.joints[v][c]].m;
                const double w = primitive.weights[v][c];
                for (int i = 0; i < 3; ++i)
                    p[i] += w * (double(m[i]) * primitive.positions[v][0] +
                                 double(m[4 + i]) * primitive.positions[v][1] +
                                 double(m[8 + i]) * primitive.positions[v][2] + double(m[12 + i]));
            }
            for (int i = 0; i < 3; ++i) {
                const double gpuError = std::fabs(p[i] - double(deformed[v].position[i]));
                if (gpuError > worstGpu) {
                    worstGpu = gpuError;
                    worstGpuTime = player.time;
                }
                worstCpu = std::max(worstCpu, std::fabs(p[i] - double(cpu.positions[v][i])));
            }
        }
    }
    const double gpuMedian = median(gpuMs), cpuMedian = median(cpuMs);
    char metric[200];
    std::snprintf(metric, sizeof(metric),
                  "largest |position - reference| over %zu vertices x 10 times of Fox Walk, "
                  "model units (the Fox is ~150 long)",
                  primitive.positions.size());
    char where[120];
    std::snprintf(where, sizeof(where), "t = %.2f s", double(worstGpuTime));
    context.report.rows.push_back({"GPU skinning pass (fp32 compute, 4 joints per vertex)",
                                   "linear blend skinning in double, same joint matrices", metric,
                                   worstGpu, "abs", where,
                                   formatCost(gpuMedian * 1e3, cpuMedian * 1e3, "us per Fox") +
                                       " (GPU timestamps vs the CPU reference on one thread)"});
    context.report.rows.push_back({"CPU skinning, content::deformPrimitive (fp32)",
                                   "linear blend skinning in double, same joint matrices", metric,
                                   worstCpu, "abs", "-",
                                   formatNumber(cpuMedian * 1e3) + " us per Fox, one thread"});
}

}  // namespace candela::report
