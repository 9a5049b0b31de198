#include "passes/ssr/ssr_pass.h"

#include <algorithm>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "ibl/environment_descriptors.h"
#include "passes/ssr/ssr_bindings.h"
#include "shaders/ssr_color.comp.spv.h"
#include "shaders/ssr_composite.comp.spv.h"
#include "shaders/ssr_hiz.comp.spv.h"
#include "shaders/ssr_temporal.comp.spv.h"
#include "shaders/ssr_trace.comp.spv.h"
#include "shaders/ssr_visibility.comp.spv.h"

namespace candela::render {

namespace {

struct HizPush {
    uint32_t level;
};

struct TemporalPush {
    uint32_t historyValid;
    float blend;
};

struct TracePush {
    uint32_t mode;
    uint32_t maxIterations;
    uint32_t levelCount;
    uint32_t flags;
    float roughnessCutoff;
    float thickness;
    float referenceStepPixels;
    float skyIntensity;
    float prefilteredMipCount;
    uint32_t coneSamples;
    uint32_t referenceRays;
    uint32_t aoMode;
    float aoIntensity;
};

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr uint32_t kCounterWords = 5;

uint32_t groups(uint32_t pixels) {
    return (pixels + 7) / 8;
}

uint32_t halfUp(uint32_t n) {
    return (n + 1) / 2;
}

}  // namespace

SsrPass::SsrPass(GpuContext& context)
    : pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}),
      counters_(context, kCounterWords * sizeof(uint32_t),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                MemoryLocation::HostVisible) {
    const DescriptorBinding hiz[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_HIZ, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    hiz_ = Pipeline::compute(context, ssr_hiz_comp_spv, hiz, sizeof(HizPush));
    const DescriptorBinding color[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_COLOR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    color_ = Pipeline::compute(context, ssr_color_comp_spv, color, sizeof(HizPush));
    const DescriptorBinding visibility[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_HIZ, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_VISIBILITY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    visibility_ = Pipeline::compute(context, ssr_visibility_comp_spv, visibility, sizeof(HizPush));
    const DescriptorBinding temporal[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_REFLECTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_MOTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_HISTORY_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    temporal_ = Pipeline::compute(context, ssr_temporal_comp_spv, temporal, sizeof(TemporalPush));
    const DescriptorBinding trace[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_BASE_COLOR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_SPECULAR_MODEL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_HIZ, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_VISIBILITY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_COLOR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_PREFILTERED, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_BRDF_LUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_AMBIENT_OCCLUSION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_SPECULAR_OCCLUSION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {SSR_BINDING_REFLECTION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_COUNTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompute},
    };
    trace_ = Pipeline::compute(context, ssr_trace_comp_spv, trace, sizeof(TracePush));
    const DescriptorBinding composite[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {SSR_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {SSR_BINDING_REFLECTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
    };
    composite_ = Pipeline::compute(context, ssr_composite_comp_spv, composite, 0);
}

uint32_t SsrPass::levelCount(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    while ((width > 1 || height > 1) && levels < SSR_MAX_LEVELS) {
        width = halfUp(width);
        height = halfUp(height);
        ++levels;
    }
    return levels;
}

ImageDesc SsrPass::pyramidDesc(uint32_t width, uint32_t height) {
    // The column right of level 0 holds levels 1.. stacked: at most the sum of their heights.
    uint32_t column = 0;
    for (uint32_t h = height, l = 1; l < levelCount(width, height); ++l) {
        h = halfUp(h);
        column += h;
    }
    return {
        VK_FORMAT_R32G32B32A32_SFLOAT, width + halfUp(width), std::max(height, column), 1, false,
        VK_IMAGE_USAGE_STORAGE_BIT};
}

ImageDesc SsrPass::visibilityDesc(uint32_t width, uint32_t height) {
    ImageDesc desc = pyramidDesc(width, height);
    desc.format = VK_FORMAT_R32_SFLOAT;
    return desc;
}

ImageDesc SsrPass::colorDesc(uint32_t width, uint32_t height) {
    ImageDesc desc = pyramidDesc(width, height);
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    return desc;
}

ImageDesc SsrPass::historyDesc(uint32_t width, uint32_t height) {
    ImageDesc desc = reflectionDesc(width, height);
    desc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    return desc;
}

ImageDesc SsrPass::reflectionDesc(uint32_t width, uint32_t height) {
    return {VK_FORMAT_R32G32B32A32_SFLOAT,
            width,
            height,
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

void SsrPass::recordHiz(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& depth,
                        const ImageRef& pyramid, uint32_t level, uint32_t width,
                        uint32_t height) const {
    VkDescriptorBufferInfo cameraInfo{camera.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depthInfo{pointSampler_.handle(), depth.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo pyramidInfo{VK_NULL_HANDLE, pyramid.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(SSR_BINDING_DEPTH, &depthInfo),
        storageImageWrite(SSR_BINDING_HIZ, &pyramidInfo),
    };
    for (uint32_t l = 0; l < level; ++l) {
        width = halfUp(width);
        height = halfUp(height);
    }
    const HizPush push{level};
    hiz_.bind(cmd);
    hiz_.pushDescriptors(cmd, writes);
    hiz_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(width), groups(height), 1);
}

void SsrPass::recordColor(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& hdr,
                          const ImageRef& colors, uint32_t level, uint32_t width,
                          uint32_t height) const {
    VkDescriptorBufferInfo cameraInfo{camera.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo colorInfo{VK_NULL_HANDLE, colors.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageImageWrite(SSR_BINDING_HDR, &hdrInfo),
        storageImageWrite(SSR_BINDING_COLOR, &colorInfo),
    };
    for (uint32_t l = 0; l < level; ++l) {
        width = halfUp(width);
        height = halfUp(height);
    }
    const HizPush push{level};
    color_.bind(cmd);
    color_.pushDescriptors(cmd, writes);
    color_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(width), groups(height), 1);
}

void SsrPass::recordVisibility(VkCommandBuffer cmd, const GpuBuffer& camera,
                               const ImageRef& pyramid, const ImageRef& visibility, uint32_t level,
                               uint32_t width, uint32_t height) const {
    VkDescriptorBufferInfo cameraInfo{camera.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo pyramidInfo{VK_NULL_HANDLE, pyramid.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo visibilityInfo{VK_NULL_HANDLE, visibility.view(),
                                         VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageImageWrite(SSR_BINDING_HIZ, &pyramidInfo),
        storageImageWrite(SSR_BINDING_VISIBILITY, &visibilityInfo),
    };
    for (uint32_t l = 0; l < level; ++l) {
        width = halfUp(width);
        height = halfUp(height);
    }
    const HizPush push{level};
    visibility_.bind(cmd);
    visibility_.pushDescriptors(cmd, writes);
    visibility_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(width), groups(height), 1);
}

void SsrPass::recordTemporal(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& current,
                             const ImageRef& motion, const ImageRef& history, bool historyValid,
                             float blend, const ImageRef& filtered) const {
    VkDescriptorBufferInfo cameraInfo{camera.handle(), 0, VK_WHOLE_SIZE};
    auto sampled = [this](const ImageRef& image) {
        return VkDescriptorImageInfo{pointSampler_.handle(), image.view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    };
    const VkDescriptorImageInfo currentInfo = sampled(current);
    const VkDescriptorImageInfo motionInfo = sampled(motion);
    const VkDescriptorImageInfo historyInfo = sampled(history);
    VkDescriptorImageInfo output{VK_NULL_HANDLE, filtered.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(SSR_BINDING_REFLECTION, &currentInfo),
        sampledImageWrite(SSR_BINDING_MOTION, &motionInfo),
        sampledImageWrite(SSR_BINDING_HISTORY, &historyInfo),
        storageImageWrite(SSR_BINDING_HISTORY_OUTPUT, &output),
    };
    const TemporalPush push{historyValid ? 1u : 0u, blend};
    temporal_.bind(cmd);
    temporal_.pushDescriptors(cmd, writes);
    temporal_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(filtered.desc().width), groups(filtered.desc().height), 1);
}

void SsrPass::recordTrace(VkCommandBuffer cmd, const TraceInputs& in,
                          const ImageRef& reflection) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    auto sampled = [this](const ImageRef& image) {
        return VkDescriptorImageInfo{pointSampler_.handle(), image.view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    };
    const VkDescriptorImageInfo normal = sampled(in.normalRoughMetal);
    const VkDescriptorImageInfo baseColor = sampled(in.baseColor);
    const VkDescriptorImageInfo specular = sampled(in.specularModel);
    VkDescriptorImageInfo pyramid{VK_NULL_HANDLE, in.pyramid.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo visibility{VK_NULL_HANDLE, in.visibility.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo colors{VK_NULL_HANDLE, in.colors.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo output{VK_NULL_HANDLE, reflection.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo counterInfo{counters_.handle(), 0, VK_WHOLE_SIZE};
    // Without ambient occlusion the LUT stands in (the shader does not read it then).
    const VkDescriptorImageInfo occlusion =
        in.ambientOcclusion ? sampled(*in.ambientOcclusion) : in.environment->brdfLut;
    const VkDescriptorImageInfo specularOcclusion =
        in.specularOcclusion ? sampled(*in.specularOcclusion) : in.environment->brdfLut;
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(SSR_BINDING_NORMAL, &normal),
        sampledImageWrite(SSR_BINDING_BASE_COLOR, &baseColor),
        sampledImageWrite(SSR_BINDING_SPECULAR_MODEL, &specular),
        storageImageWrite(SSR_BINDING_HIZ, &pyramid),
        storageImageWrite(SSR_BINDING_VISIBILITY, &visibility),
        storageImageWrite(SSR_BINDING_COLOR, &colors),
        sampledImageWrite(SSR_BINDING_PREFILTERED, &in.environment->prefiltered),
        sampledImageWrite(SSR_BINDING_BRDF_LUT, &in.environment->brdfLut),
        sampledImageWrite(SSR_BINDING_AMBIENT_OCCLUSION, &occlusion),
        sampledImageWrite(SSR_BINDING_SPECULAR_OCCLUSION, &specularOcclusion),
        storageImageWrite(SSR_BINDING_REFLECTION, &output),
        storageBufferWrite(SSR_BINDING_COUNTERS, &counterInfo),
    };
    const bool reference = in.mode == SsrMode::Reference;
    const TracePush push{
        reference ? 1u : 0u,
        reference ? in.settings.referenceMaxSteps : in.settings.maxIterations,
        levelCount(in.width, in.height),
        (in.hasEnvironment ? 1u : 0u) | (in.hasLut ? 2u : 0u) | (in.settings.coneTracing ? 4u : 0u),
        in.settings.roughnessCutoff,
        in.settings.thickness,
        in.settings.referenceStepPixels,
        in.skyIntensity,
        in.environment->prefilteredMipCount,
        in.settings.coneSamples,
        reference ? in.settings.referenceRays : 1u,
        in.ambientOcclusion ? in.aoMode : 0u,
        in.aoIntensity};
    trace_.bind(cmd);
    trace_.pushDescriptors(cmd, writes);
    trace_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(in.width), groups(in.height), 1);
}

void SsrPass::recordComposite(VkCommandBuffer cmd, const GpuBuffer& camera,
                              const ImageRef& reflection, const ImageRef& hdr) const {
    VkDescriptorBufferInfo cameraInfo{camera.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo input{pointSampler_.handle(), reflection.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageImageWrite(SSR_BINDING_HDR, &hdrInfo),
        sampledImageWrite(SSR_BINDING_REFLECTION, &input),
    };
    composite_.bind(cmd);
    composite_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, groups(hdr.desc().width), groups(hdr.desc().height), 1);
}

void SsrPass::recordClearCounters(VkCommandBuffer cmd) const {
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0u);
}

SsrPass::Counts SsrPass::readCounters() const {
    const auto* words = static_cast<const uint32_t*>(counters_.mapped());
    Counts c;
    c.steps = uint64_t(words[0]) | (uint64_t(words[1]) << 32);
    c.maxSteps = words[2];
    c.hits = words[3];
    c.rays = words[4];
    return c;
}

}  // namespace candela::render
