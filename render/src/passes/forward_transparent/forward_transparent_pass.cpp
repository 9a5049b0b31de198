#include "passes/forward_transparent/forward_transparent_pass.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_grid.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "culling/draws_in_view.h"
#include "gbuffer_targets.h"
#include "ibl/environment_descriptors.h"
#include "mesh_vertex_input.h"
#include "passes/forward_transparent/forward_transparent_bindings.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "shaders/forward_transparent.frag.spv.h"
#include "shaders/gbuffer.vert.spv.h"
#include "shaders/msaa_expand.frag.spv.h"
#include "shaders/msaa_expand.vert.spv.h"
#include "shaders/transparent_occupancy.frag.spv.h"
#include "shaders/transparent_occupancy_merge.comp.spv.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

// Both fragment shaders' push block; the vertex stage (gbuffer.vert) reads world only.
struct DrawPush {
    glm::mat4 world;
    uint32_t material;
    uint32_t directionalCount;
    GpuClusterParams grid;
    uint32_t size[2];
    float projectionScale[2];
    float skyIntensity;
    float prefilteredMipCount;
};

static_assert(FORWARD_BINDING_FIRST_TEXTURE + kTextureSlotCount <=
              FORWARD_BINDING_FROXEL_INTEGRATED);

// Specialization constants shared with the lighting pass (shading_models.glsl, lights.glsl,
// forward_transparent.frag).

// The draw's vertices: the mesh's, or a skinned or morphed draw's deformed vertices and last
// frame's (SceneResources::vertexBufferOf, previousVertexBufferOf). firstInstance: the draw's
// index in FrameScene::draws, gbuffer.vert's previous-world index. `lod`: the level of detail.
void drawMesh(VkCommandBuffer cmd, const SceneResources& resources, const DrawItem& draw,
              uint32_t drawIndex, uint8_t lod) {
    const GpuMesh::Lod& level = resources.mesh(draw.mesh).lods[lod];
    bindMeshVertices(cmd, resources.vertexBufferOf(draw), resources.previousVertexBufferOf(draw));
    vkCmdBindIndexBuffer(cmd, resources.mesh(draw.mesh).indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, level.indexCount, 1, level.firstIndex, 0, drawIndex);
}

void setViewport(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
    setViewportAndScissor(cmd, width, height);
}

}  // namespace

ForwardTransparentPass::ForwardTransparentPass(GpuContext& context, VkSampleCountFlagBits samples)
    : context_(context),
      samples_(samples),
      pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}),
      noMedium_(context, VolumetricsPass::kFroxelHeaderBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                MemoryLocation::HostVisible) {
    std::memset(noMedium_.mapped(), 0, VolumetricsPass::kFroxelHeaderBytes);
}

// The occupancy, merge and MSAA-expand pipelines: built on the first frame with blended draws
// (most frames have none, and compiling them would only slow every run's start).
void ForwardTransparentPass::buildFixedPipelines() {
    // Occupancy: no attachments; the fragment shader tests against the G-buffer depth itself,
    // so the depth image stays in the layout the occupancy compute pass read it in.
    GraphicsPipelineDesc occupancy;
    occupancy.vertexSpirv = gbuffer_vert_spv;  // the G-buffer's vertex stage: same transform
    setMeshVertexInput(occupancy);
    occupancy.fragmentSpirv = transparent_occupancy_frag_spv;
    const DescriptorBinding occupancyBindings[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {PREVIOUS_WORLDS_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {TRANSPARENT_OCCUPANCY_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
        {TRANSPARENT_OCCUPANCY_BINDING_DEPTH_RANGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
        {TRANSPARENT_OCCUPANCY_BINDING_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
    };
    occupancy_ = Pipeline::graphics(context_, occupancy, occupancyBindings, sizeof(DrawPush));

    const DescriptorBinding mergeBindings[] = {
        {MERGE_BINDING_TILE_MASKS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {MERGE_BINDING_CLUSTER_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {MERGE_BINDING_TRANSPARENT_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    merge_ = Pipeline::compute(context_, transparent_occupancy_merge_comp_spv, mergeBindings,
                               sizeof(GpuClusterParams));

    if (samples_ != VK_SAMPLE_COUNT_1_BIT) {
        GraphicsPipelineDesc expand;
        expand.vertexSpirv = msaa_expand_vert_spv;
        expand.fragmentSpirv = msaa_expand_frag_spv;
        expand.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT, GBufferTargets::kMotionFormat};
        expand.depthFormat = GBufferTargets::kDepthFormat;
        expand.depthCompare = VK_COMPARE_OP_ALWAYS;  // a copy: every sample takes the depth
        expand.depthWrite = true;
        expand.samples = samples_;
        const DescriptorBinding expandBindings[] = {
            {MSAA_EXPAND_BINDING_HDR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_SHADER_STAGE_FRAGMENT_BIT},
            {MSAA_EXPAND_BINDING_MOTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_SHADER_STAGE_FRAGMENT_BIT},
            {MSAA_EXPAND_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
             VK_SHADER_STAGE_FRAGMENT_BIT},
        };
        expand_ = Pipeline::graphics(context_, expand, expandBindings, 0);
    }
}

ImageDesc ForwardTransparentPass::msaaHdrDesc(uint32_t width, uint32_t height,
                                              VkSampleCountFlagBits samples) {
    ImageDesc desc{VK_FORMAT_R32G32B32A32_SFLOAT,      width, height, 1, false,
                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT};
    desc.samples = samples;
    return desc;
}

ImageDesc ForwardTransparentPass::msaaMotionDesc(uint32_t width, uint32_t height,
                                                 VkSampleCountFlagBits samples) {
    ImageDesc desc{GBufferTargets::kMotionFormat,      width, height, 1, false,
                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT};
    desc.samples = samples;
    return desc;
}

ImageDesc ForwardTransparentPass::msaaDepthDesc(uint32_t width, uint32_t height,
                                                VkSampleCountFlagBits samples) {
    ImageDesc desc{GBufferTargets::kDepthFormat,
                   width,
                   height,
                   1,
                   false,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT};
    desc.samples = samples;
    return desc;
}

ForwardTransparentPass::~ForwardTransparentPass() = default;

void ForwardTransparentPass::buildShadingPipeline() {
    SpecializationConstants constants;
    setShadingConstants(constants, features_);
    // 0 none, 1 split sum, 2 mobile; the reference mode's per-pixel integration is for the
    // deferred pass's measurements: blended surfaces take the split sum under it.
    constants.set(SPEC_IBL_MODE, !features_.ibl ? 0u : *features_.ibl == IblMode::Mobile ? 2u : 1u);
    constants.set(SPEC_SKY_OCCLUSION, features_.skyOcclusion);

    GraphicsPipelineDesc desc;
    desc.vertexSpirv = gbuffer_vert_spv;  // the G-buffer's vertex stage: same transform
    setMeshVertexInput(desc);
    desc.fragmentSpirv = forward_transparent_frag_spv;
    desc.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT,  // the HDR target
                         GBufferTargets::kMotionFormat};
    desc.depthFormat = GBufferTargets::kDepthFormat;
    desc.depthWrite = false;  // blended surfaces neither hide nor sort each other by depth
    desc.alphaBlend = true;
    desc.dynamicCullMode = true;
    desc.samples = samples_;
    desc.specialization = &constants;
    const DescriptorBinding own[] = {
        {PREVIOUS_WORLDS_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {FORWARD_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
        {FORWARD_BINDING_FROXEL_INTEGRATED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
    };
    std::vector<DescriptorBinding> bindings =
        withLitInputBindings(own, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
    for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
        bindings.push_back({FORWARD_BINDING_FIRST_TEXTURE + slot,
                            VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            VK_SHADER_STAGE_FRAGMENT_BIT});
    }
    shading_ = Pipeline::graphics(context_, desc, bindings, sizeof(DrawPush));
    built_ = true;
}

bool ForwardTransparentPass::prepare(const FrameScene& scene, SceneResources& resources,
                                     std::span<const uint8_t> visible,
                                     const LightingFeatures& features,
                                     const GpuBuffer& previousWorlds) {
    previousWorlds_ = &previousWorlds;
    order_.clear();
    sorted_.clear();
    sortedIndex_.clear();
    sortedLod_.clear();
    for (uint32_t i = 0; i < uint32_t(scene.draws.size()); ++i) {
        const DrawItem& draw = scene.draws[i];
        if (visible[i] == kDrawCulled) continue;
        if (resources.material(draw.material).alphaMode != content::AlphaMode::Blend) continue;
        if (resources.mesh(draw.mesh).indexCount == 0) continue;
        glm::vec4 centre = draw.world * glm::vec4(resources.meshSpaceBounds(draw).first, 1.0f);
        float viewDepth = -(scene.camera.view * centre).z;
        order_.emplace_back(viewDepth, i);
    }
    if (order_.empty()) return false;
    // Farthest first; equal depths keep scene order, so the result does not depend on the
    // sort's implementation.
    std::stable_sort(order_.begin(), order_.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [depth, index] : order_) {
        sorted_.push_back(scene.draws[index]);
        sortedIndex_.push_back(index);
        sortedLod_.push_back(visible[index]);
    }
    if (occupancy_.handle() == VK_NULL_HANDLE) buildFixedPipelines();
    if (!built_ || !(features == features_)) {
        features_ = features;
        buildShadingPipeline();
    }
    return true;
}

VkDeviceSize ForwardTransparentPass::boundsBytes(const ClusterGrid& grid) {
    // Min and max xyz per cluster quarter (transparent_occupancy.frag).
    return 2 * VkDeviceSize(grid.clusterCount()) * 4 * 3 * sizeof(uint32_t);
}

void ForwardTransparentPass::recordClearBounds(VkCommandBuffer cmd,
                                               const OccupancyInputs& in) const {
    // Empty boxes: mins at the largest ordered value, maxs at the smallest.
    const VkDeviceSize half = boundsBytes(*in.grid) / 2;
    vkCmdFillBuffer(cmd, in.bounds.handle(), 0, half, 0xffffffffu);
    vkCmdFillBuffer(cmd, in.bounds.handle(), half, half, 0u);
}

void ForwardTransparentPass::recordMarkOccupancy(VkCommandBuffer cmd, SceneResources& resources,
                                                 const OccupancyInputs& in) const {
    const ClusterGrid& grid = *in.grid;
    const uint32_t width = in.depth.desc().width;
    const uint32_t height = in.depth.desc().height;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    vkCmdBeginRendering(cmd, &rendering);
    setViewport(cmd, width, height);
    occupancy_.bind(cmd);
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depthInfo{pointSampler_.handle(), in.depth.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo rangeInfo{in.depthRange->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo boundsInfo{in.bounds.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo previousInfo{previousWorlds_->handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageBufferWrite(PREVIOUS_WORLDS_BINDING, &previousInfo),
        sampledImageWrite(TRANSPARENT_OCCUPANCY_BINDING_DEPTH, &depthInfo),
        storageBufferWrite(TRANSPARENT_OCCUPANCY_BINDING_DEPTH_RANGE, &rangeInfo),
        storageBufferWrite(TRANSPARENT_OCCUPANCY_BINDING_BOUNDS, &boundsInfo)};
    occupancy_.pushDescriptors(cmd, writes);
    DrawPush push{};
    push.grid = toGpu(grid);
    push.size[0] = width;
    push.size[1] = height;
    push.projectionScale[0] = in.projectionScale.x;
    push.projectionScale[1] = in.projectionScale.y;
    for (size_t i = 0; i < sorted_.size(); ++i) {
        const DrawItem& draw = sorted_[i];
        push.world = draw.world;
        push.material = draw.material;
        occupancy_.pushConstants(cmd, &push, sizeof(push));
        drawMesh(cmd, resources, draw, sortedIndex_[i], sortedLod_[i]);
    }
    vkCmdEndRendering(cmd);
}

void ForwardTransparentPass::recordMergeOccupancy(VkCommandBuffer cmd,
                                                  const OccupancyInputs& in) const {
    const ClusterGrid& grid = *in.grid;
    VkDescriptorBufferInfo boundsInfo{in.bounds.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo maskInfo{in.tileMasks->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo clusterInfo{in.clusterBounds->handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet mergeWrites[] = {
        storageBufferWrite(MERGE_BINDING_TILE_MASKS, &maskInfo),
        storageBufferWrite(MERGE_BINDING_CLUSTER_BOUNDS, &clusterInfo),
        storageBufferWrite(MERGE_BINDING_TRANSPARENT_BOUNDS, &boundsInfo)};
    GpuClusterParams params = toGpu(grid);
    merge_.bind(cmd);
    merge_.pushDescriptors(cmd, mergeWrites);
    merge_.pushConstants(cmd, &params, sizeof(params));
    vkCmdDispatch(cmd, grid.tilesX, grid.tilesY, 1);
}

void ForwardTransparentPass::recordShading(VkCommandBuffer cmd, SceneResources& resources,
                                           const ShadingInputs& in) const {
    const uint32_t width = in.hdr.desc().width;
    const uint32_t height = in.hdr.desc().height;
    const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
    std::array<VkRenderingAttachmentInfo, 2> colors{};
    for (size_t i = 0; i < colors.size(); ++i) {
        const ImageRef& single = i == 0 ? in.hdr : in.motion;
        colors[i] = renderingAttachment(single.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_STORE);
        if (msaa) {
            // Plain average of the samples, in linear light: each pixel becomes its coverage-
            // weighted radiance, what a box-filtered supersampled frame holds (the
            // antialiasing reference); motion averages the same way. The multisampled
            // targets are transients nothing reads after the resolve.
            colors[i].imageView = i == 0 ? in.msaaHdr.view() : in.msaaMotion.view();
            colors[i].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            colors[i].resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
            colors[i].resolveImageView = single.view();
            colors[i].resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        }
    }
    const VkRenderingAttachmentInfo depth = renderingAttachment(
        msaa ? in.msaaDepth.view() : in.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
        VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_NONE);
    const VkRenderingInfo rendering = renderingInfo(width, height, colors, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    setViewport(cmd, width, height);
    shading_.bind(cmd);

    const GpuBuffer& materials = resources.materialBuffer();
    VkDescriptorBufferInfo materialInfo{materials.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo previousInfo{previousWorlds_->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo froxelInfo{
        in.froxels ? in.froxelIntegrated.handle() : noMedium_.handle(), 0, VK_WHOLE_SIZE};
    DrawPush push{};
    push.directionalCount = in.lit.clusters->directionalCount();
    push.grid = toGpu(in.lit.clusters->grid());
    push.size[0] = width;
    push.size[1] = height;
    push.skyIntensity = in.lit.skyIntensity;
    push.prefilteredMipCount = in.lit.environment.prefilteredMipCount;
    for (size_t i = 0; i < sorted_.size(); ++i) {
        const DrawItem& draw = sorted_[i];
        const MaterialBinding& binding = resources.materialBinding(draw.material);
        std::array<VkDescriptorImageInfo, kTextureSlotCount> images{};
        std::vector<VkWriteDescriptorSet> own = {
            storageBufferWrite(PREVIOUS_WORLDS_BINDING, &previousInfo),
            storageBufferWrite(FORWARD_BINDING_MATERIALS, &materialInfo),
            storageBufferWrite(FORWARD_BINDING_FROXEL_INTEGRATED, &froxelInfo)};
        for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
            const GpuTexture& t = resources.texture(binding.textures[slot]);
            images[slot] = {t.sampler, t.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            own.push_back(sampledImageWrite(FORWARD_BINDING_FIRST_TEXTURE + slot, &images[slot]));
        }
        const LitDescriptorWrites writes(in.lit, own);
        shading_.pushDescriptors(cmd, writes.writes());
        vkCmdSetCullMode(cmd, resources.material(draw.material).doubleSided
                                  ? VK_CULL_MODE_NONE
                                  : VK_CULL_MODE_BACK_BIT);
        push.world = draw.world;
        push.material = draw.material;
        shading_.pushConstants(cmd, &push, sizeof(push));
        drawMesh(cmd, resources, draw, sortedIndex_[i], sortedLod_[i]);
    }
    vkCmdEndRendering(cmd);
}

void ForwardTransparentPass::recordExpand(VkCommandBuffer cmd, const ShadingInputs& in) const {
    const uint32_t width = in.hdr.desc().width;
    const uint32_t height = in.hdr.desc().height;
    std::array<VkRenderingAttachmentInfo, 2> colors{};
    for (size_t i = 0; i < colors.size(); ++i) {
        // Every sample is written.
        colors[i] =
            renderingAttachment(i == 0 ? in.msaaHdr.view() : in.msaaMotion.view(),
                                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    }
    const VkRenderingAttachmentInfo depth =
        renderingAttachment(in.msaaDepth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    const VkRenderingInfo rendering = renderingInfo(width, height, colors, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    setViewport(cmd, width, height);
    expand_.bind(cmd);
    const VkDescriptorImageInfo hdrInfo{pointSampler_.handle(), in.hdr.view(),
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo motionInfo{pointSampler_.handle(), in.motion.view(),
                                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo depthInfo{pointSampler_.handle(), in.depth.view(),
                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkWriteDescriptorSet writes[] = {
        sampledImageWrite(MSAA_EXPAND_BINDING_HDR, &hdrInfo),
        sampledImageWrite(MSAA_EXPAND_BINDING_MOTION, &motionInfo),
        sampledImageWrite(MSAA_EXPAND_BINDING_DEPTH, &depthInfo)};
    expand_.pushDescriptors(cmd, writes);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
