#include "passes/wires/wire_pass.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "clustered/cluster_grid.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "gbuffer_targets.h"
#include "host_storage_array.h"
#include "ibl/environment_descriptors.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "passes/wires/wire_bindings.h"
#include "shaders/wire.frag.spv.h"
#include "shaders/wire.vert.spv.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

// wire_segment.glsl's WireSegment.
struct WireSegment {
    glm::vec4 start;      // xyz world, w radius
    glm::vec4 end;        // xyz world, w 1: unlit
    glm::vec4 baseColor;  // rgb, a metallic
    glm::vec4 emissive;   // rgb cd/m^2, a roughness
};

// wire_segment.glsl's push block.
struct WirePush {
    GpuClusterParams grid;
    float targetSize[2];
    float pixelRadiusPerDepth;
    float nearPlane;
    uint32_t mode;
    uint32_t directionalCount;
    float skyIntensity;
    float prefilteredMipCount;
};

constexpr VkDeviceSize kInitialSegments = 256;

}  // namespace

WirePass::WirePass(GpuContext& context)
    : context_(context),
      segments_(context, kInitialSegments * sizeof(WireSegment), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                MemoryLocation::HostVisible),
      noMedium_(context, VolumetricsPass::kFroxelHeaderBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                MemoryLocation::HostVisible) {
    std::memset(noMedium_.mapped(), 0, VolumetricsPass::kFroxelHeaderBytes);
}

WirePass::~WirePass() = default;

bool WirePass::prepare(const FrameScene& scene, const LightingFeatures& features, WireMode mode) {
    size_t count = 0;
    for (const WireDraw& draw : scene.wires) {
        if (draw.wire) count += draw.wire->segments.size() / 2;
    }
    segmentCount_ = uint32_t(count);
    if (count == 0) return false;
    WireSegment* out = reserveHostStorageArray<WireSegment>(context_, segments_, count);
    const content::Material defaults;  // the glTF default material
    for (const WireDraw& draw : scene.wires) {
        if (!draw.wire) continue;
        const content::Wire& wire = *draw.wire;
        const content::Material& m = draw.material ? *draw.material : defaults;
        const bool unlit = m.shadingModel == content::ShadingModel::Unlit;
        const glm::vec4 baseColor(m.baseColorFactor[0], m.baseColorFactor[1], m.baseColorFactor[2],
                                  std::clamp(m.metallicFactor, 0.0f, 1.0f));
        const glm::vec4 emissive(
            m.emissiveFactor[0] * m.emissiveStrength, m.emissiveFactor[1] * m.emissiveStrength,
            m.emissiveFactor[2] * m.emissiveStrength, std::clamp(m.roughnessFactor, 0.0f, 1.0f));
        // The radius is a world length: a scaled instance scales it by its mean axis scale.
        const float scale =
            (glm::length(glm::vec3(draw.world[0])) + glm::length(glm::vec3(draw.world[1])) +
             glm::length(glm::vec3(draw.world[2]))) /
            3.0f;
        const float radius = wire.radius * scale;
        for (size_t i = 0; i + 1 < wire.segments.size(); i += 2) {
            const auto& a = wire.positions[wire.segments[i]];
            const auto& b = wire.positions[wire.segments[i + 1]];
            const glm::vec3 p0 = glm::vec3(draw.world * glm::vec4(a[0], a[1], a[2], 1.0f));
            const glm::vec3 p1 = glm::vec3(draw.world * glm::vec4(b[0], b[1], b[2], 1.0f));
            *out++ = {glm::vec4(p0, radius), glm::vec4(p1, unlit ? 1.0f : 0.0f), baseColor,
                      emissive};
        }
    }
    if (!built_ || !(features == features_) || mode != mode_) {
        features_ = features;
        mode_ = mode;
        buildPipeline();
    }
    return true;
}

void WirePass::buildPipeline() {
    SpecializationConstants constants;
    setShadingConstants(constants, features_);
    // The reference mode's per-pixel sky integration is for the deferred pass: wires take the
    // split sum under it, as blended surfaces do.
    constants.set(SPEC_IBL_MODE, !features_.ibl ? 0u : *features_.ibl == IblMode::Mobile ? 2u : 1u);
    GraphicsPipelineDesc desc;
    desc.vertexSpirv = wire_vert_spv;  // no vertex input: six vertices per segment
    desc.fragmentSpirv = wire_frag_spv;
    desc.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT};  // the HDR target
    desc.depthFormat = GBufferTargets::kDepthFormat;
    desc.depthWrite = false;
    desc.alphaBlend = true;
    desc.specialization = &constants;
    constexpr VkShaderStageFlags kRaster =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const DescriptorBinding own[] = {
        {WIRE_BINDING_SEGMENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kRaster},
        {WIRE_BINDING_FROXEL_INTEGRATED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
    };
    const std::vector<DescriptorBinding> bindings = withLitInputBindings(own, kRaster);
    pipeline_ = Pipeline::graphics(context_, desc, bindings, sizeof(WirePush));
    built_ = true;
}

void WirePass::record(VkCommandBuffer cmd, const Inputs& in) const {
    const uint32_t width = in.hdr.desc().width;
    const uint32_t height = in.hdr.desc().height;
    const VkRenderingAttachmentInfo color =
        renderingAttachment(in.hdr.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_STORE);
    const VkRenderingAttachmentInfo depth =
        renderingAttachment(in.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_NONE);
    const VkRenderingInfo rendering = renderingInfo(width, height, std::span(&color, 1), &depth);
    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);
    pipeline_.bind(cmd);

    VkDescriptorBufferInfo segmentInfo{segments_.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo froxelInfo{
        in.froxels ? in.froxelIntegrated.handle() : noMedium_.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet own[] = {
        storageBufferWrite(WIRE_BINDING_SEGMENTS, &segmentInfo),
        storageBufferWrite(WIRE_BINDING_FROXEL_INTEGRATED, &froxelInfo)};
    const LitDescriptorWrites writes(in.lit, own);
    pipeline_.pushDescriptors(cmd, writes.writes());
    WirePush push{};
    push.grid = toGpu(in.lit.clusters->grid());
    push.targetSize[0] = float(width);
    push.targetSize[1] = float(height);
    push.pixelRadiusPerDepth = in.pixelRadiusPerDepth;
    push.nearPlane = in.nearPlane;
    push.mode = mode_ == WireMode::Naive ? WIRE_MODE_NAIVE : WIRE_MODE_COVERAGE;
    push.directionalCount = in.lit.clusters->directionalCount();
    push.skyIntensity = in.lit.skyIntensity;
    push.prefilteredMipCount = in.lit.environment.prefilteredMipCount;
    pipeline_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDraw(cmd, 6 * segmentCount_, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
