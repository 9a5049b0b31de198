#include "passes/scattering/scattering_pass.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "candela/render/gpu_context.h"
#include "common/specialization_ids.h"
#include "passes/scattering/scattering_bindings.h"
#include "passes/shadows/shadow_pass.h"
#include "shaders/scattering_aerial_perspective.comp.spv.h"
#include "shaders/scattering_brute_force.comp.spv.h"
#include "shaders/scattering_coordinates.comp.spv.h"
#include "shaders/scattering_samples.comp.spv.h"
#include "shaders/scattering_tree.comp.spv.h"
#include "shaders/scattering_unwarp.comp.spv.h"
#include "vk/memory_barrier.h"

namespace candela::render {

namespace {

// Matches the push block of scattering_push.glsl.
struct ScatteringPush {
    glm::vec4 rayleigh;    // Rayleigh scattering, Mie g
    glm::vec4 mie;         // Mie scattering, near plane
    glm::vec4 extinction;  // extinction, distance marched for the sky
    glm::vec4 sun;         // sun pixel xy, refinement threshold
    glm::uvec4 epipolar;   // slices, samples per slice, initial step, tree leaves
    glm::uvec4 lights;     // sun index, light capacity, tree levels, shadow maps
    glm::uvec4 batch;      // brute force: steps, first, count; epipolar: phase in y; w: 1,
                           // the in-scattering alone; aerial perspective: first boundary, fog
    glm::uvec4 aerial;     // aerial perspective: columns, rows, slices, steps per slice
};
static_assert(sizeof(ScatteringPush) <= 128, "Vulkan guarantees 128 bytes of push constants");

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr uint32_t kCascadeRows = 4;  // SHADOW_MAX_CASCADES

uint32_t groups(uint32_t count, uint32_t size) {
    return (count + size - 1) / size;
}

// What every light-shaft shader binds (camera, lights, the sun's shadow maps, the counters),
// then a shader's own.
constexpr DescriptorBinding kCommonBindings[] = {
    {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
    {LIGHT_BUFFER_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {SCATTERING_BINDING_SHADOW_ATLAS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
    {SCATTERING_BINDING_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {SCATTERING_BINDING_SHADOW_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {SCATTERING_BINDING_SHADOW_ATLAS_COMPARE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
    {SCATTERING_BINDING_COUNTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
};
constexpr size_t kCommon = std::size(kCommonBindings);

template <size_t N>
std::array<DescriptorBinding, kCommon + N> withCommon(const std::array<DescriptorBinding, N>& own) {
    std::array<DescriptorBinding, kCommon + N> all{};
    std::copy(std::begin(kCommonBindings), std::end(kCommonBindings), all.begin());
    std::copy(own.begin(), own.end(), all.begin() + kCommon);
    return all;
}

struct CommonInfos {
    VkDescriptorBufferInfo camera, lights, counters;
};

template <size_t N>
std::array<VkWriteDescriptorSet, kCommon + N> commonWrites(
    const ScatteringPass::Inputs& in, const GpuBuffer& counters, CommonInfos& infos,
    const std::array<VkWriteDescriptorSet, N>& own) {
    infos.camera = {in.camera->handle(), 0, VK_WHOLE_SIZE};
    infos.lights = {in.lights->handle(), 0, VK_WHOLE_SIZE};
    infos.counters = {counters.handle(), 0, VK_WHOLE_SIZE};
    std::array<VkWriteDescriptorSet, kCommon + N> writes{
        uniformBufferWrite(CAMERA_BINDING, &infos.camera),
        storageBufferWrite(LIGHT_BUFFER_BINDING, &infos.lights),
        sampledImageWrite(SCATTERING_BINDING_SHADOW_ATLAS, &in.shadows->atlas),
        storageBufferWrite(SCATTERING_BINDING_SHADOW_VIEWS, &in.shadows->views),
        storageBufferWrite(SCATTERING_BINDING_SHADOW_LIGHTS, &in.shadows->lights),
        sampledImageWrite(SCATTERING_BINDING_SHADOW_ATLAS_COMPARE, &in.shadows->atlasCompare),
        storageBufferWrite(SCATTERING_BINDING_COUNTERS, &infos.counters),
    };
    std::copy(own.begin(), own.end(), writes.begin() + kCommon);
    return writes;
}

ScatteringPush pushFor(const ScatteringPass::Inputs& in) {
    const ScatteringSettings& s = in.settings;
    const ScatteringPass::Frame& f = in.frame;
    const uint32_t leaves = ScatteringPass::treeLeaves(in.cascadeSize);
    const uint32_t levels = s.minMaxTree ? uint32_t(std::countr_zero(leaves)) : 0u;
    return {glm::vec4(f.rayleigh, f.mieAnisotropy),
            glm::vec4(f.mie, std::max(in.nearPlane, 1e-4f)),
            glm::vec4(f.extinction, s.maxDistance),
            glm::vec4(f.sunPixel, s.refinementThreshold, std::max(s.aerialFar, 1e-3f)),
            glm::uvec4(std::max(in.slices, 1u), std::max(in.samplesPerSlice, 2u),
                       std::max(s.initialStep, 1u), leaves),
            glm::uvec4(uint32_t(std::max(f.sunIndex, 0)), in.lightCapacity, levels,
                       in.shadowMaps ? 1u : 0u),
            glm::uvec4(std::max(s.bruteForceSteps, 1u), 0u, 0u, s.inscatteringOnly ? 1u : 0u),
            glm::uvec4(ScatteringPass::aerialGrid(s), std::max(s.aerialStepsPerSlice, 1u))};
}

}  // namespace

ScatteringPass::ScatteringPass(GpuContext& context)
    : context_(context),
      pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}),
      counters_(context, 2 * sizeof(uint32_t),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                MemoryLocation::HostVisible) {}

ImageDesc ScatteringPass::samplesDesc(uint32_t slices, uint32_t samplesPerSlice) {
    return {VK_FORMAT_R32G32B32A32_SFLOAT,
            std::max(samplesPerSlice, 2u),
            std::max(slices, 1u),
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT};
}

ImageDesc ScatteringPass::treeDesc(uint32_t slices, uint32_t cascadeSize) {
    return {VK_FORMAT_R32G32_SFLOAT,
            2 * treeLeaves(cascadeSize),
            std::max(slices, 1u) * kCascadeRows,
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

VkDeviceSize ScatteringPass::slicesBytes(uint32_t slices) {
    // SliceInfo: end points, flags and a line per cascade (vec4 each).
    return VkDeviceSize(std::max(slices, 1u)) * (2 + kCascadeRows) * sizeof(glm::vec4);
}

glm::uvec3 ScatteringPass::aerialGrid(const ScatteringSettings& settings) {
    return glm::max(glm::uvec3(settings.aerialColumns, settings.aerialRows, settings.aerialSlices),
                    glm::uvec3(1u));
}

VkDeviceSize ScatteringPass::aerialBytes(const ScatteringSettings& settings) {
    const glm::uvec3 grid = aerialGrid(settings);
    return VkDeviceSize(grid.x) * grid.y * grid.z * sizeof(glm::vec4);
}

uint32_t ScatteringPass::treeLeaves(uint32_t cascadeSize) {
    const auto diagonal = uint32_t(std::ceil(std::sqrt(2.0) * double(std::max(cascadeSize, 1u))));
    return std::bit_ceil(diagonal);
}

ScatteringPass::Frame ScatteringPass::frameOf(const FrameScene& scene,
                                              const ScatteringSettings& settings, uint32_t width,
                                              uint32_t height) {
    Frame f;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (scene.lights[i].light.type == content::LightType::Directional) {
            f.sunIndex = int(i);
            break;
        }
    }
    const content::Atmosphere a = scene.atmosphere.value_or(content::Atmosphere{});
    // The air at the camera's altitude: over a scene's few hundred metres its density changes
    // by a few percent at most (Mie's scale height is 1.2 km), so it is taken as uniform.
    const float altitude = std::max(scene.camera.position.y, 0.0f);
    const float rayleighDensity = std::exp(-altitude / a.rayleighScaleHeight);
    const float mieDensity = std::exp(-altitude / a.mieScaleHeight);
    const float scale = settings.densityScale;
    f.rayleigh =
        glm::vec3(a.rayleighScattering[0], a.rayleighScattering[1], a.rayleighScattering[2]) *
        (rayleighDensity * scale);
    f.mie = glm::vec3(a.mieScattering * mieDensity * scale);
    // Ozone is absent below 10 km with Earth's profile; Mie absorbs.
    f.extinction = f.rayleigh + f.mie + glm::vec3(a.mieAbsorption * mieDensity * scale);
    f.mieAnisotropy = a.mieAnisotropy;
    if (f.sunIndex >= 0) {
        const glm::vec3 towardSun = -scene.lights[size_t(f.sunIndex)].direction;
        const glm::vec4 clip =
            scene.camera.projection * scene.camera.view * glm::vec4(towardSun, 0.0f);
        // At w = 0 the sun is at infinity on the screen plane: far away along its direction.
        const float w = std::abs(clip.w) < 1e-6f ? std::copysign(1e-6f, clip.w) : clip.w;
        glm::vec2 ndc = glm::vec2(clip) / w;
        const float far = 1e4f;
        if (glm::length(ndc) > far) ndc *= far / glm::length(ndc);
        f.sunPixel = (ndc * 0.5f + 0.5f) * glm::vec2(float(width), float(height));
    }
    return f;
}

void ScatteringPass::prepare(ScatteringMode mode, bool shadows, bool aerialPerspective) {
    if (shadows != shadows_) {
        epipolarBuilt_ = bruteForceBuilt_ = aerialBuilt_ = false;
        shadows_ = shadows;
    }
    SpecializationConstants constants;
    constants.set(SPEC_SHADOWS_ENABLED, shadows);
    const DescriptorBinding depth{SCATTERING_BINDING_DEPTH,
                                  VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute};
    const DescriptorBinding hdr{SCATTERING_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute};
    const DescriptorBinding slices{SCATTERING_BINDING_SLICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                   kCompute};
    const DescriptorBinding coordinates{SCATTERING_BINDING_COORDINATES,
                                        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute};
    const DescriptorBinding treeStorage{SCATTERING_BINDING_TREE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                        kCompute};
    const DescriptorBinding treeSampled{SCATTERING_BINDING_TREE,
                                        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute};
    const DescriptorBinding inscatter{SCATTERING_BINDING_INSCATTER,
                                      VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute};
    const uint32_t bytes = sizeof(ScatteringPush);
    if (mode == ScatteringMode::Epipolar && !epipolarBuilt_) {
        coordinates_ = Pipeline::compute(context_, scattering_coordinates_comp_spv,
                                         withCommon(std::array{depth, coordinates, slices}), bytes,
                                         &constants);
        tree_ = Pipeline::compute(context_, scattering_tree_comp_spv,
                                  withCommon(std::array{slices, treeStorage}), bytes, &constants);
        samples_ = Pipeline::compute(
            context_, scattering_samples_comp_spv,
            withCommon(std::array{coordinates, slices, treeSampled, inscatter}), bytes, &constants);
        unwarp_ = Pipeline::compute(
            context_, scattering_unwarp_comp_spv,
            withCommon(std::array{depth, hdr, slices, treeSampled, inscatter}), bytes, &constants);
        epipolarBuilt_ = true;
    }
    if (mode == ScatteringMode::BruteForce && !bruteForceBuilt_) {
        bruteForce_ = Pipeline::compute(context_, scattering_brute_force_comp_spv,
                                        withCommon(std::array{depth, hdr}), bytes, &constants);
        bruteForceBuilt_ = true;
    }
    if (aerialPerspective && !aerialBuilt_) {
        const DescriptorBinding target{SCATTERING_BINDING_AERIAL_PERSPECTIVE,
                                       VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute};
        aerial_ = Pipeline::compute(context_, scattering_aerial_perspective_comp_spv,
                                    withCommon(std::array{target}), bytes, &constants);
        aerialBuilt_ = true;
    }
}

void ScatteringPass::recordCoordinates(VkCommandBuffer cmd, const Inputs& in,
                                       const ImageRef& coordinates, const BufferRef& slices) const {
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo coords{VK_NULL_HANDLE, coordinates.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo slicesInfo{slices.handle(), 0, VK_WHOLE_SIZE};
    CommonInfos infos;
    const auto writes =
        commonWrites(in, counters_, infos,
                     std::array{sampledImageWrite(SCATTERING_BINDING_DEPTH, &depth),
                                storageImageWrite(SCATTERING_BINDING_COORDINATES, &coords),
                                storageBufferWrite(SCATTERING_BINDING_SLICES, &slicesInfo)});
    const ScatteringPush push = pushFor(in);
    coordinates_.bind(cmd);
    coordinates_.pushDescriptors(cmd, writes);
    coordinates_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(push.epipolar.y, 64), push.epipolar.x, 1);
}

void ScatteringPass::recordTree(VkCommandBuffer cmd, const Inputs& in, const BufferRef& slices,
                                const ImageRef& tree) const {
    VkDescriptorBufferInfo slicesInfo{slices.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo treeInfo{VK_NULL_HANDLE, tree.view(), VK_IMAGE_LAYOUT_GENERAL};
    CommonInfos infos;
    const auto writes =
        commonWrites(in, counters_, infos,
                     std::array{storageBufferWrite(SCATTERING_BINDING_SLICES, &slicesInfo),
                                storageImageWrite(SCATTERING_BINDING_TREE, &treeInfo)});
    const ScatteringPush push = pushFor(in);
    tree_.bind(cmd);
    tree_.pushDescriptors(cmd, writes);
    tree_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(push.epipolar.x * kCascadeRows, 64), 1, 1);
}

void ScatteringPass::recordSamples(VkCommandBuffer cmd, const Inputs& in, uint32_t phase,
                                   const ImageRef& coordinates, const BufferRef& slices,
                                   const ImageRef& tree, const ImageRef& inscatter) const {
    VkDescriptorImageInfo coords{VK_NULL_HANDLE, coordinates.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo slicesInfo{slices.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo treeInfo{pointSampler_.handle(), tree.view(),
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo inscatterInfo{VK_NULL_HANDLE, inscatter.view(), VK_IMAGE_LAYOUT_GENERAL};
    CommonInfos infos;
    const auto writes =
        commonWrites(in, counters_, infos,
                     std::array{storageImageWrite(SCATTERING_BINDING_COORDINATES, &coords),
                                storageBufferWrite(SCATTERING_BINDING_SLICES, &slicesInfo),
                                sampledImageWrite(SCATTERING_BINDING_TREE, &treeInfo),
                                storageImageWrite(SCATTERING_BINDING_INSCATTER, &inscatterInfo)});
    ScatteringPush push = pushFor(in);
    push.batch.y = phase;
    const uint32_t samples = push.epipolar.y;
    const uint32_t step = push.epipolar.z;
    // Phase 0: every step-th sample and the last (one more invocation).
    const uint32_t invocations = phase == 0 ? (samples - 1) / step + 2 : samples;
    samples_.bind(cmd);
    samples_.pushDescriptors(cmd, writes);
    samples_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(invocations, 64), push.epipolar.x, 1);
}

void ScatteringPass::recordUnwarp(VkCommandBuffer cmd, const Inputs& in, const BufferRef& slices,
                                  const ImageRef& tree, const ImageRef& inscatter) const {
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdr{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo slicesInfo{slices.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo treeInfo{pointSampler_.handle(), tree.view(),
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo inscatterInfo{VK_NULL_HANDLE, inscatter.view(), VK_IMAGE_LAYOUT_GENERAL};
    CommonInfos infos;
    const auto writes =
        commonWrites(in, counters_, infos,
                     std::array{sampledImageWrite(SCATTERING_BINDING_DEPTH, &depth),
                                storageImageWrite(SCATTERING_BINDING_HDR, &hdr),
                                storageBufferWrite(SCATTERING_BINDING_SLICES, &slicesInfo),
                                sampledImageWrite(SCATTERING_BINDING_TREE, &treeInfo),
                                storageImageWrite(SCATTERING_BINDING_INSCATTER, &inscatterInfo)});
    const ScatteringPush push = pushFor(in);
    unwarp_.bind(cmd);
    unwarp_.pushDescriptors(cmd, writes);
    unwarp_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(in.hdr.desc().width, 8), groups(in.hdr.desc().height, 8), 1);
}

void ScatteringPass::recordBruteForce(VkCommandBuffer cmd, const Inputs& in) const {
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdr{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    CommonInfos infos;
    const auto writes = commonWrites(in, counters_, infos,
                                     std::array{sampledImageWrite(SCATTERING_BINDING_DEPTH, &depth),
                                                storageImageWrite(SCATTERING_BINDING_HDR, &hdr)});
    ScatteringPush push = pushFor(in);
    bruteForce_.bind(cmd);
    bruteForce_.pushDescriptors(cmd, writes);
    // Steps in batches: each step's lookup searches up to 4 cascades (a loop), so 8,192 steps
    // stay well under lavapipe's 65,535 loop iterations per invocation.
    constexpr uint32_t kStepsPerBatch = 8192;
    const uint32_t steps = push.batch.x;
    for (uint32_t first = 0; first < steps; first += kStepsPerBatch) {
        if (first > 0) {
            // This batch adds to what the previous one stored.
            memoryBarrier(
                cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        push.batch.y = first;
        push.batch.z = std::min(kStepsPerBatch, steps - first);
        bruteForce_.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, groups(in.hdr.desc().width, 8), groups(in.hdr.desc().height, 8), 1);
    }
}

void ScatteringPass::recordAerialPerspective(VkCommandBuffer cmd, const Inputs& in,
                                             const BufferRef& froxels, uint32_t firstBoundary,
                                             bool fogGrid) const {
    VkDescriptorBufferInfo target{froxels.handle(), 0, VK_WHOLE_SIZE};
    CommonInfos infos;
    const auto writes = commonWrites(
        in, counters_, infos,
        std::array{storageBufferWrite(SCATTERING_BINDING_AERIAL_PERSPECTIVE, &target)});
    ScatteringPush push = pushFor(in);
    push.batch = glm::uvec4(firstBoundary, fogGrid ? 1u : 0u, 0u, 0u);
    aerial_.bind(cmd);
    aerial_.pushDescriptors(cmd, writes);
    aerial_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(push.aerial.x, 8), groups(push.aerial.y, 8), 1);
}

void ScatteringPass::recordClearCounters(VkCommandBuffer cmd) const {
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0u);
}

ScatteringPass::Counts ScatteringPass::readCounters() const {
    const auto* words = static_cast<const uint32_t*>(counters_.mapped());
    return {words[0], words[1]};
}

}  // namespace candela::render
