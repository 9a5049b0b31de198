#include "passes/volumetrics/volumetrics_pass.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <glm/vec4.hpp>
#include <optional>

#include "candela/render/gpu_context.h"
#include "common/specialization_ids.h"
#include "gbuffer_targets.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/light_bins.h"
#include "passes/volumetrics/volumetrics_bindings.h"
#include "shaders/volumetrics_composite.comp.spv.h"
#include "shaders/volumetrics_froxel_integrate.comp.spv.h"
#include "shaders/volumetrics_froxel_light.comp.spv.h"
#include "shaders/volumetrics_reference.comp.spv.h"
#include "shaders/volumetrics_volumes_blur.comp.spv.h"
#include "shaders/volumetrics_volumes_composite.comp.spv.h"
#include "shaders/volumetrics_volumes_march.comp.spv.h"
#include "shaders/volumetrics_volumes_proxy.frag.spv.h"
#include "shaders/volumetrics_volumes_proxy.vert.spv.h"
#include "shaders/volumetrics_volumes_sun.frag.spv.h"
#include "shaders/volumetrics_volumes_sun.vert.spv.h"
#include "vk/memory_barrier.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

// Matches the push block of volumetrics_push.glsl.
struct VolumetricsPush {
    glm::vec4 medium;     // sigma_s, sigma_a, g, height falloff
    glm::vec4 range;      // base height, near, far, composite: 1 adds only (no transmittance)
    glm::uvec4 grid;      // froxels x, y, slices, reference steps
    glm::uvec4 lights;    // count, capacity
    glm::vec4 boundsMin;  // the medium's box (world, m); w: 1 when bounded
    glm::vec4 boundsMax;
};

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

uint32_t groups(uint32_t count, uint32_t size) {
    return (count + size - 1) / size;
}

float nearOf(const VolumetricsPass::Inputs& in) {
    return std::max(in.nearPlane, 1e-4f);
}

float farOf(const VolumetricsPass::Inputs& in) {
    return std::max(in.settings.froxelFar, nearOf(in) * 2.0f);
}

// `steps`: the reference's per pixel, or the per-light volumes' per light and pixel.
VolumetricsPush pushFor(const VolumetricsPass::Inputs& in, uint32_t steps) {
    const float nearPlane = nearOf(in);
    const float farPlane = farOf(in);
    const std::optional<content::FogBounds>& bounds = in.fog.bounds;
    return {
        glm::vec4(in.fog.scattering, in.fog.absorption, in.fog.anisotropy, in.fog.heightFalloff),
        glm::vec4(in.fog.baseHeight, nearPlane, farPlane, 0.0f),
        glm::uvec4(in.grid, std::max(steps, 1u)),
        glm::uvec4(in.lightCount, in.lightCapacity, 0u, 0u),
        bounds ? glm::vec4(bounds->min[0], bounds->min[1], bounds->min[2], 1.0f) : glm::vec4(0.0f),
        bounds ? glm::vec4(bounds->max[0], bounds->max[1], bounds->max[2], 0.0f) : glm::vec4(0.0f)};
}

// The bindings of the shaders that light the medium (reference, froxel lighting).
constexpr DescriptorBinding kLightingBindings[] = {
    {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
    {LIGHT_BUFFER_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {VOLUMETRICS_BINDING_LIGHT_SCALES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {VOLUMETRICS_BINDING_SHADOW_ATLAS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
    {VOLUMETRICS_BINDING_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {VOLUMETRICS_BINDING_SHADOW_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    {VOLUMETRICS_BINDING_SHADOW_ATLAS_COMPARE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
};

// The rasterised per-light volumes' bindings: the lighting passes' (their proxies read the
// lights in the vertex stage too), the scene's depth and the instance list.
constexpr VkShaderStageFlags kRaster = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr DescriptorBinding kProxyBindings[] = {
    {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kRaster},
    {LIGHT_BUFFER_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
    {VOLUMETRICS_BINDING_LIGHT_SCALES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
    {VOLUMETRICS_BINDING_SHADOW_ATLAS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kRaster},
    {VOLUMETRICS_BINDING_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
    {VOLUMETRICS_BINDING_SHADOW_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
    {VOLUMETRICS_BINDING_SHADOW_ATLAS_COMPARE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kRaster},
    {VOLUMETRICS_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kRaster},
    {VOLUMETRICS_BINDING_PROXY_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
};

// A rasterised per-light volumes pipeline: the full-screen pass (`sun`: stores the sun's
// march, the view depth and the depth target) or a proxy pipeline (adds, its depth test and
// culled faces set per draw).
Pipeline volumesRasterPipeline(GpuContext& context, bool sun, SpecializationConstants& constants) {
    GraphicsPipelineDesc desc;
    desc.vertexSpirv = sun ? std::span<const uint32_t>(volumetrics_volumes_sun_vert_spv)
                           : std::span<const uint32_t>(volumetrics_volumes_proxy_vert_spv);
    desc.fragmentSpirv = sun ? std::span<const uint32_t>(volumetrics_volumes_sun_frag_spv)
                             : std::span<const uint32_t>(volumetrics_volumes_proxy_frag_spv);
    desc.colorFormats = {VolumetricsPass::volumesDesc(1, 1).format};
    desc.depthFormat = GBufferTargets::kDepthFormat;
    desc.depthCompare = sun ? VK_COMPARE_OP_ALWAYS : VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse-Z
    desc.depthWrite = sun;
    desc.dynamicCullMode = !sun;
    desc.dynamicDepthTest = !sun;
    desc.additiveBlend = !sun;
    desc.specialization = &constants;
    return Pipeline::graphics(context, desc, kProxyBindings, sizeof(VolumetricsPush));
}

// The lighting passes' bindings (kLightingBindings) followed by a pass's own.
template <size_t N>
std::array<DescriptorBinding, 7 + N> withLightingBindings(
    const std::array<DescriptorBinding, N>& extra) {
    std::array<DescriptorBinding, 7 + N> bindings{};
    std::copy(std::begin(kLightingBindings), std::end(kLightingBindings), bindings.begin());
    std::copy(extra.begin(), extra.end(), bindings.begin() + 7);
    return bindings;
}

// Grows a host-visible storage buffer to at least `bytes`.
void ensureHostBuffer(GpuContext& context, GpuBuffer& buffer, VkDeviceSize bytes) {
    if (buffer.size() >= bytes) return;
    buffer =
        GpuBuffer(context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
}

void upload(GpuContext& context, GpuBuffer& buffer, const std::vector<uint32_t>& words) {
    ensureHostBuffer(context, buffer, words.size() * sizeof(uint32_t));
    std::memcpy(buffer.mapped(), words.data(), words.size() * sizeof(uint32_t));
}

}  // namespace

VolumetricsPass::VolumetricsPass(GpuContext& context)
    : context_(context), pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}) {
    const DescriptorBinding integrate[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {VOLUMETRICS_BINDING_FROXEL_MEDIUM, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
        {VOLUMETRICS_BINDING_FROXEL_INTEGRATED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    };
    froxelIntegrate_ = Pipeline::compute(context, volumetrics_froxel_integrate_comp_spv, integrate,
                                         sizeof(VolumetricsPush));
    const DescriptorBinding composite[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {VOLUMETRICS_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {VOLUMETRICS_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {VOLUMETRICS_BINDING_FROXEL_INTEGRATED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    };
    composite_ = Pipeline::compute(context, volumetrics_composite_comp_spv, composite, 0);
    const DescriptorBinding blur[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {VOLUMETRICS_BINDING_VOLUMES_MARCHED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {VOLUMETRICS_BINDING_VOLUMES_BLURRED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    volumesBlur_ = Pipeline::compute(context, volumetrics_volumes_blur_comp_spv, blur,
                                     sizeof(VolumetricsPush));
    const DescriptorBinding volumesComposite[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {VOLUMETRICS_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {VOLUMETRICS_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {VOLUMETRICS_BINDING_VOLUMES_BLURRED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    volumesComposite_ = Pipeline::compute(context, volumetrics_volumes_composite_comp_spv,
                                          volumesComposite, sizeof(VolumetricsPush));
}

glm::uvec3 VolumetricsPass::froxelGrid(uint32_t width, uint32_t height,
                                       const VolumetricsSettings& settings) {
    // The settings' grid is the one at 1280x720; it scales with the image.
    const uint32_t x = (width * settings.froxelsX + 1279) / 1280;
    const uint32_t y = (height * settings.froxelsY + 719) / 720;
    return {std::max(x, 1u), std::max(y, 1u), std::max(settings.froxelSlices, 1u)};
}

VkDeviceSize VolumetricsPass::froxelBufferBytes(const glm::uvec3& grid) {
    return VkDeviceSize(grid.x) * grid.y * grid.z * sizeof(glm::vec4);
}

VkDeviceSize VolumetricsPass::froxelIntegratedBytes(const glm::uvec3& grid, bool sunChannel) {
    return kFroxelHeaderBytes + froxelBufferBytes(grid) * (sunChannel ? 2 : 1);
}

ImageDesc VolumetricsPass::volumesDesc(uint32_t width, uint32_t height, bool proxies) {
    return {VK_FORMAT_R32G32B32A32_SFLOAT,
            (width + 1) / 2,
            (height + 1) / 2,
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT |
                (proxies ? VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT)
                         : VkImageUsageFlags(0))};
}

ImageDesc VolumetricsPass::volumesDepthDesc(uint32_t width, uint32_t height) {
    return {GBufferTargets::kDepthFormat,
            (width + 1) / 2,
            (height + 1) / 2,
            1,
            false,
            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT};
}

bool VolumetricsPass::sunInMedium(std::span<const LightInstance> lights) {
    return std::any_of(lights.begin(), lights.end(), [](const LightInstance& l) {
        const float s = l.light.volumetric;
        return l.light.type == content::LightType::Directional && s > 0.0f && s <= 1e3f;
    });
}

void VolumetricsPass::prepare(std::span<const LightInstance> lights, bool shadows,
                              const Uses& uses) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(lights.size(), 1) * sizeof(float);
    ensureHostBuffer(context_, lightScales_, bytes);
    auto* scales = static_cast<float*>(lightScales_.mapped());
    for (size_t i = 0; i < lights.size(); ++i) {
        const float s = lights[i].light.volumetric;
        scales[i] = s >= 0.0f && s <= 1e3f ? s : 0.0f;  // NaN and negatives light no medium
    }
    const bool areaLights = std::any_of(lights.begin(), lights.end(), [](const LightInstance& l) {
        return l.light.type == content::LightType::Rect || l.light.type == content::LightType::Disk;
    });
    if (shadows != shadows_ || areaLights != areaLights_) {
        built_ = {};  // every variant changes
        proxyAreaBuilt_ = false;
    }
    shadows_ = shadows;
    areaLights_ = areaLights;
    SpecializationConstants constants;
    constants.set(SPEC_SHADOWS_ENABLED, shadows);
    constants.set(SPEC_MEDIUM_AREA_LIGHTS, areaLights);
    if (uses.reference && !built_.reference) {
        const auto reference = withLightingBindings(
            std::array{DescriptorBinding{VOLUMETRICS_BINDING_DEPTH,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
                       DescriptorBinding{VOLUMETRICS_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                         kCompute}});
        reference_ = Pipeline::compute(context_, volumetrics_reference_comp_spv, reference,
                                       sizeof(VolumetricsPush), &constants);
        built_.reference = true;
    }
    if (uses.froxels && !built_.froxels) {
        const auto light = withLightingBindings(
            std::array{DescriptorBinding{VOLUMETRICS_BINDING_FROXEL_MEDIUM,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
                       DescriptorBinding{VOLUMETRICS_BINDING_LIGHT_BINS,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute}});
        froxelLight_ = Pipeline::compute(context_, volumetrics_froxel_light_comp_spv, light,
                                         sizeof(VolumetricsPush), &constants);
        built_.froxels = true;
    }
    if (uses.volumesMarch && !built_.volumesMarch) {
        const auto march = withLightingBindings(
            std::array{DescriptorBinding{VOLUMETRICS_BINDING_DEPTH,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
                       DescriptorBinding{VOLUMETRICS_BINDING_VOLUMES_MARCHED,
                                         VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
                       DescriptorBinding{VOLUMETRICS_BINDING_LIGHT_BINS,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute}});
        volumesMarch_ = Pipeline::compute(context_, volumetrics_volumes_march_comp_spv, march,
                                          sizeof(VolumetricsPush), &constants);
        built_.volumesMarch = true;
    }
    if (uses.volumesProxies && !built_.volumesProxies) {
        // The full-screen pass marches only the sun, and the point and spot proxies leave the
        // area lights' code out (SPEC_MEDIUM_AREA_LIGHTS): buildProxies adds their variant.
        SpecializationConstants pointLights;
        pointLights.set(SPEC_SHADOWS_ENABLED, shadows);
        pointLights.set(SPEC_MEDIUM_AREA_LIGHTS, false);
        volumesSun_ = volumesRasterPipeline(context_, true, pointLights);
        volumesProxy_ = volumesRasterPipeline(context_, false, pointLights);
        built_.volumesProxies = true;
    }
}

void VolumetricsPass::buildProxies(std::span<const LightInstance> lights, const CameraView& camera,
                                   uint32_t width, uint32_t height) {
    const auto* scales = static_cast<const float*>(lightScales_.mapped());
    proxies_ = buildLightProxies(lights, std::span<const float>(scales, lights.size()), camera,
                                 width, height);
    std::vector<uint32_t> words = proxies_.instances;
    if (words.empty()) words.push_back(0u);  // a buffer to bind
    upload(context_, proxyInstances_, words);
    const bool area = std::any_of(proxies_.draws.begin(), proxies_.draws.end(),
                                  [](const LightProxyDraw& d) { return d.areaLights; });
    if (area && !proxyAreaBuilt_) {
        SpecializationConstants areaLights;
        areaLights.set(SPEC_SHADOWS_ENABLED, shadows_);
        areaLights.set(SPEC_MEDIUM_AREA_LIGHTS, true);
        volumesProxyArea_ = volumesRasterPipeline(context_, false, areaLights);
        proxyAreaBuilt_ = true;
    }
}

void VolumetricsPass::binLights(std::span<const LightInstance> lights, const CameraView& camera,
                                uint32_t width, uint32_t height, const Inputs& in, bool volumes,
                                bool froxels, bool sunMarched) {
    const auto* scales = static_cast<const float*>(lightScales_.mapped());
    const std::span<const float> scaleSpan(scales, lights.size());
    // With the sun marched over the froxels, each list keeps only its own lights (a zero scale
    // leaves a light out of the lists): the march the directional ones, the froxels the rest,
    // or all of them with the sun's channel (the froxel lighting keeps the sun apart there).
    std::vector<float> sunScales, localScales;
    const bool froxelsListTheSun = !sunMarched || in.froxelSunChannel;
    if (sunMarched) {
        sunScales.assign(scaleSpan.begin(), scaleSpan.end());
        localScales = sunScales;
        for (size_t i = 0; i < lights.size(); ++i) {
            const bool sun = lights[i].light.type == content::LightType::Directional;
            (sun ? localScales : sunScales)[i] = 0.0f;
        }
    }
    binnedWork_ = {};
    if (volumes || sunMarched) {
        const LightBinLayout layout = volumeTileLayout(width, height);
        const std::vector<uint32_t> bins = render::binLights(
            lights, sunMarched ? std::span<const float>(sunScales) : scaleSpan, camera, layout);
        binnedWork_.volumeMarchSteps = binnedPairs(bins, layout) * in.settings.volumeSteps;
        upload(context_, volumeBins_, bins);
    }
    if (froxels) {
        const LightBinLayout layout = froxelClusterLayout(in.grid, nearOf(in), farOf(in));
        const std::span<const float> froxelScales =
            froxelsListTheSun ? scaleSpan : std::span<const float>(localScales);
        const std::vector<uint32_t> bins =
            capPlainLights(render::binLights(lights, froxelScales, camera, layout), lights,
                           froxelScales, camera, layout, in.froxelLightCap);
        binnedWork_.froxelLightEvaluations = binnedPairs(bins, layout);
        upload(context_, froxelBins_, bins);
    }
}

// The descriptors both passes that light the medium read (the reference march and the froxel
// lighting): camera, lights, their volumetric scales and the shadow maps. `extra` follows them.
template <size_t N>
std::array<VkWriteDescriptorSet, 7 + N> VolumetricsPass::lightingWrites(
    const Inputs& in, LightingInfos& infos,
    const std::array<VkWriteDescriptorSet, N>& extra) const {
    infos.camera = {in.camera->handle(), 0, VK_WHOLE_SIZE};
    infos.lights = {in.lights->handle(), 0, VK_WHOLE_SIZE};
    infos.scales = {lightScales_.handle(), 0, VK_WHOLE_SIZE};
    std::array<VkWriteDescriptorSet, 7 + N> writes{
        uniformBufferWrite(CAMERA_BINDING, &infos.camera),
        storageBufferWrite(LIGHT_BUFFER_BINDING, &infos.lights),
        storageBufferWrite(VOLUMETRICS_BINDING_LIGHT_SCALES, &infos.scales),
        sampledImageWrite(VOLUMETRICS_BINDING_SHADOW_ATLAS, &in.shadows->atlas),
        storageBufferWrite(VOLUMETRICS_BINDING_SHADOW_VIEWS, &in.shadows->views),
        storageBufferWrite(VOLUMETRICS_BINDING_SHADOW_LIGHTS, &in.shadows->lights),
        sampledImageWrite(VOLUMETRICS_BINDING_SHADOW_ATLAS_COMPARE, &in.shadows->atlasCompare),
    };
    std::copy(extra.begin(), extra.end(), writes.begin() + 7);
    return writes;
}

void VolumetricsPass::recordReference(VkCommandBuffer cmd, const Inputs& in) const {
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdr{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    LightingInfos infos;
    const auto writes =
        lightingWrites(in, infos,
                       std::array{sampledImageWrite(VOLUMETRICS_BINDING_DEPTH, &depth),
                                  storageImageWrite(VOLUMETRICS_BINDING_HDR, &hdr)});
    VolumetricsPush push = pushFor(in, in.settings.referenceSteps);
    reference_.bind(cmd);
    reference_.pushDescriptors(cmd, writes);
    // Lights in batches of at most kReferenceLightSamples / steps, one dispatch each: lavapipe
    // (llvmpipe) ends a shader invocation's loops after 65,535 iterations in all, so one
    // dispatch of 128 steps x 4,096 lights silently marched an eighth of the ray (the
    // reference came out 26 times too dark at 8x8 pixels: docs/speed-vs-error.md).
    constexpr uint32_t kReferenceLightSamples = 32768;
    const uint32_t batch = std::max(kReferenceLightSamples / push.grid.w, 1u);
    for (uint32_t first = 0; first == 0 || first < in.lightCount; first += batch) {
        if (first > 0) {
            // This batch adds to what the previous one stored.
            memoryBarrier(
                cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        push.lights.z = first;
        push.lights.w = batch;
        reference_.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, groups(in.hdr.desc().width, 8), groups(in.hdr.desc().height, 8), 1);
    }
}

void VolumetricsPass::recordFroxelLight(VkCommandBuffer cmd, const Inputs& in,
                                        const BufferRef& medium) const {
    VkDescriptorBufferInfo mediumInfo{medium.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo binsInfo{froxelBins_.handle(), 0, VK_WHOLE_SIZE};
    LightingInfos infos;
    const auto writes = lightingWrites(
        in, infos,
        std::array{storageBufferWrite(VOLUMETRICS_BINDING_FROXEL_MEDIUM, &mediumInfo),
                   storageBufferWrite(VOLUMETRICS_BINDING_LIGHT_BINS, &binsInfo)});
    VolumetricsPush push = pushFor(in, in.settings.referenceSteps);
    push.lights.z = in.froxelSunChannel ? 1u : 0u;
    froxelLight_.bind(cmd);
    froxelLight_.pushDescriptors(cmd, writes);
    froxelLight_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(in.grid.x, 4), groups(in.grid.y, 4), groups(in.grid.z, 4));
}

void VolumetricsPass::recordFroxelIntegrate(VkCommandBuffer cmd, const Inputs& in,
                                            const BufferRef& medium,
                                            const BufferRef& integrated) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo mediumInfo{medium.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo integratedInfo{integrated.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageBufferWrite(VOLUMETRICS_BINDING_FROXEL_MEDIUM, &mediumInfo),
        storageBufferWrite(VOLUMETRICS_BINDING_FROXEL_INTEGRATED, &integratedInfo),
    };
    VolumetricsPush push = pushFor(in, in.settings.referenceSteps);
    push.lights.z = in.froxelSunChannel ? 1u : 0u;
    froxelIntegrate_.bind(cmd);
    froxelIntegrate_.pushDescriptors(cmd, writes);
    froxelIntegrate_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(in.grid.x, 8), groups(in.grid.y, 8), 1);
}

void VolumetricsPass::recordComposite(VkCommandBuffer cmd, const Inputs& in,
                                      const BufferRef& integrated) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdr{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo integratedInfo{integrated.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(VOLUMETRICS_BINDING_DEPTH, &depth),
        storageImageWrite(VOLUMETRICS_BINDING_HDR, &hdr),
        storageBufferWrite(VOLUMETRICS_BINDING_FROXEL_INTEGRATED, &integratedInfo),
    };
    composite_.bind(cmd);
    composite_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, groups(in.hdr.desc().width, 8), groups(in.hdr.desc().height, 8), 1);
}

void VolumetricsPass::recordVolumesMarch(VkCommandBuffer cmd, const Inputs& in,
                                         const ImageRef& marched) const {
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo target{VK_NULL_HANDLE, marched.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo binsInfo{volumeBins_.handle(), 0, VK_WHOLE_SIZE};
    LightingInfos infos;
    const auto writes =
        lightingWrites(in, infos,
                       std::array{sampledImageWrite(VOLUMETRICS_BINDING_DEPTH, &depth),
                                  storageImageWrite(VOLUMETRICS_BINDING_VOLUMES_MARCHED, &target),
                                  storageBufferWrite(VOLUMETRICS_BINDING_LIGHT_BINS, &binsInfo)});
    const VolumetricsPush push = pushFor(in, in.settings.volumeSteps);
    volumesMarch_.bind(cmd);
    volumesMarch_.pushDescriptors(cmd, writes);
    volumesMarch_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(marched.desc().width, 8), groups(marched.desc().height, 8), 1);
}

void VolumetricsPass::recordVolumesProxies(VkCommandBuffer cmd, const Inputs& in,
                                           const ImageRef& marched, const ImageRef& depth) const {
    const uint32_t width = marched.desc().width;
    const uint32_t height = marched.desc().height;
    // The full-screen pass writes every pixel of both targets before any proxy adds.
    const VkRenderingAttachmentInfo color =
        renderingAttachment(marched.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    const VkRenderingAttachmentInfo depthTarget =
        renderingAttachment(depth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    const VkRenderingInfo rendering =
        renderingInfo(width, height, std::span(&color, 1), &depthTarget);
    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);

    VkDescriptorImageInfo sceneDepth{pointSampler_.handle(), in.depth.view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo instances{proxyInstances_.handle(), 0, VK_WHOLE_SIZE};
    LightingInfos infos;
    const auto writes = lightingWrites(
        in, infos,
        std::array{sampledImageWrite(VOLUMETRICS_BINDING_DEPTH, &sceneDepth),
                   storageBufferWrite(VOLUMETRICS_BINDING_PROXY_INSTANCES, &instances)});
    VolumetricsPush push = pushFor(in, in.settings.volumeSteps);
    push.lights.z = proxies_.fullScreen;
    volumesSun_.bind(cmd);
    volumesSun_.pushDescriptors(cmd, writes);
    volumesSun_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDraw(cmd, 3, 1, 0, 0);
    const Pipeline* bound = nullptr;
    for (const LightProxyDraw& draw : proxies_.draws) {
        const Pipeline& pipeline = draw.areaLights ? volumesProxyArea_ : volumesProxy_;
        if (&pipeline != bound) {
            pipeline.bind(cmd);
            pipeline.pushDescriptors(cmd, writes);
            bound = &pipeline;
        }
        // Outside the proxy: its front faces, behind the scene's depth culled by the test; holding
        // the camera (or cut by the near plane): its back faces, every one of them.
        vkCmdSetCullMode(cmd, draw.holdsCamera ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_BACK_BIT);
        vkCmdSetDepthTestEnable(cmd, draw.holdsCamera ? VK_FALSE : VK_TRUE);
        push.lights.z = uint32_t(draw.kind);
        pipeline.pushConstants(cmd, &push, sizeof(push));
        const uint32_t vertices = draw.kind == LightProxyKind::Cone ? kConeProxyVertices
                                  : draw.kind == LightProxyKind::Hemisphere
                                      ? kHemisphereProxyVertices
                                      : kSphereProxyVertices;
        vkCmdDraw(cmd, vertices, draw.instanceCount, 0, draw.firstInstance);
    }
    vkCmdEndRendering(cmd);
}

void VolumetricsPass::recordVolumesBlur(VkCommandBuffer cmd, const Inputs& in,
                                        const ImageRef& marched, const ImageRef& blurred) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo source{VK_NULL_HANDLE, marched.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo target{VK_NULL_HANDLE, blurred.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageImageWrite(VOLUMETRICS_BINDING_VOLUMES_MARCHED, &source),
        storageImageWrite(VOLUMETRICS_BINDING_VOLUMES_BLURRED, &target),
    };
    const VolumetricsPush push = pushFor(in, in.settings.volumeSteps);
    volumesBlur_.bind(cmd);
    volumesBlur_.pushDescriptors(cmd, writes);
    volumesBlur_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(blurred.desc().width, 8), groups(blurred.desc().height, 8), 1);
}

void VolumetricsPass::recordVolumesComposite(VkCommandBuffer cmd, const Inputs& in,
                                             const ImageRef& blurred, bool addOnly) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdr{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo source{VK_NULL_HANDLE, blurred.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(VOLUMETRICS_BINDING_DEPTH, &depth),
        storageImageWrite(VOLUMETRICS_BINDING_HDR, &hdr),
        storageImageWrite(VOLUMETRICS_BINDING_VOLUMES_BLURRED, &source),
    };
    VolumetricsPush push = pushFor(in, in.settings.volumeSteps);
    push.range.w = addOnly ? 1.0f : 0.0f;
    volumesComposite_.bind(cmd);
    volumesComposite_.pushDescriptors(cmd, writes);
    volumesComposite_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(in.hdr.desc().width, 8), groups(in.hdr.desc().height, 8), 1);
}

}  // namespace candela::render
