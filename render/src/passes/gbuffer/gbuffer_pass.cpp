#include "passes/gbuffer/gbuffer_pass.h"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "common/gbaa_edges.h"
#include "common/specialization_ids.h"
#include "culling/draws_in_view.h"
#include "gbuffer_targets.h"
#include "mesh_vertex_input.h"
#include "passes/gbuffer/gbuffer_bindings.h"
#include "shaders/gbuffer.frag.spv.h"
#include "shaders/gbuffer.vert.spv.h"
#include "shaders/gbuffer_edges.frag.spv.h"
#include "shaders/gbuffer_edges.geom.spv.h"
#include "shaders/gbuffer_edges_only.frag.spv.h"
#include "shaders/gbuffer_extended.frag.spv.h"
#include "shaders/gbuffer_extended_edges.frag.spv.h"
#include "shaders/gbuffer_extended_layered.frag.spv.h"
#include "shaders/gbuffer_extended_layered_edges.frag.spv.h"
#include "shaders/gbuffer_layered.frag.spv.h"
#include "shaders/gbuffer_layered_edges.frag.spv.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

struct DrawPush {
    glm::mat4 world;
    uint32_t material;
};

static_assert(GBUFFER_BINDING_FIRST_TEXTURE + uint32_t(kTextureSlotCount) ==
              GBUFFER_BINDING_FIRST_LAYER_TEXTURE);

// The pipeline description every variant shares; `extended` adds the two extension targets,
// `edges` GBAA's geometry stage and edge target after them.
GraphicsPipelineDesc gbufferDesc(std::span<const uint32_t> fragmentSpirv, bool extended,
                                 bool edges) {
    GraphicsPipelineDesc desc;
    desc.vertexSpirv = gbuffer_vert_spv;
    setMeshVertexInput(desc);
    desc.colorFormats.assign(GBufferTargets::kColorFormats.begin(),
                             GBufferTargets::kColorFormats.end());
    desc.colorFormats.push_back(VK_FORMAT_R32G32B32A32_SFLOAT);  // HDR (emissive)
    desc.colorFormats.push_back(GBufferTargets::kMotionFormat);
    desc.depthFormat = GBufferTargets::kDepthFormat;
    desc.dynamicCullMode = true;  // glTF: back faces of single-sided materials are not drawn
    desc.fragmentSpirv = fragmentSpirv;
    if (extended) {
        desc.colorFormats.push_back(GBufferTargets::kAnisotropyFormat);
        desc.colorFormats.push_back(GBufferTargets::kClearCoatFormat);
    }
    if (edges) {
        desc.geometrySpirv = gbuffer_edges_geom_spv;
        desc.colorFormats.push_back(GBufferTargets::kEdgesFormat);
    }
    return desc;
}

std::vector<DescriptorBinding> gbufferBindings(bool materialLayers, bool edges) {
    // The geometry stage reads the target size from the camera block.
    const VkShaderStageFlags cameraStages =
        VK_SHADER_STAGE_VERTEX_BIT |
        (edges ? VkShaderStageFlags(VK_SHADER_STAGE_GEOMETRY_BIT) : 0u);
    std::vector<DescriptorBinding> bindings = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cameraStages},
        {PREVIOUS_WORLDS_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {GBUFFER_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_FRAGMENT_BIT},
    };
    for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
        bindings.push_back({GBUFFER_BINDING_FIRST_TEXTURE + slot,
                            VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            VK_SHADER_STAGE_FRAGMENT_BIT});
    }
    for (uint32_t slot = 0; materialLayers && slot < kLayerTextureSlotCount; ++slot) {
        bindings.push_back({GBUFFER_BINDING_FIRST_LAYER_TEXTURE + slot,
                            VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            VK_SHADER_STAGE_FRAGMENT_BIT});
    }
    return bindings;
}

// Whether the G-buffer passes draw `draw`: a mesh with triangles whose material is not blended
// (blended surfaces are drawn by the forward transparency pass).
bool drawnInGBuffer(const SceneResources& resources, const DrawItem& draw) {
    return resources.mesh(draw.mesh).indexCount != 0 &&
           resources.material(draw.material).alphaMode != content::AlphaMode::Blend;
}

// One G-buffer draw at level of detail `lod` with `pipeline` bound and its descriptors pushed:
// culled as its material says; firstInstance is the draw's index, which gbuffer.vert reads its
// previous world by.
void recordGBufferDraw(VkCommandBuffer cmd, const Pipeline& pipeline, SceneResources& resources,
                       const DrawItem& draw, uint32_t drawIndex, uint8_t lod) {
    const GpuMesh& mesh = resources.mesh(draw.mesh);
    vkCmdSetCullMode(cmd, resources.material(draw.material).doubleSided ? VK_CULL_MODE_NONE
                                                                        : VK_CULL_MODE_BACK_BIT);
    DrawPush push{draw.world, draw.material};
    pipeline.pushConstants(cmd, &push, sizeof(push));
    bindMeshVertices(cmd, resources.vertexBufferOf(draw), resources.previousVertexBufferOf(draw));
    vkCmdBindIndexBuffer(cmd, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, mesh.lods[lod].indexCount, 1, mesh.lods[lod].firstIndex, 0, drawIndex);
}

}  // namespace

GBufferPass::GBufferPass(GpuContext& context) : context_(context) {}

void GBufferPass::prepare(const FrameScene& scene, const SceneResources& resources,
                          std::span<const uint8_t> visible, bool materialLayers, bool extended,
                          bool edges, std::span<const uint32_t> order) {
    materialLayers_ = materialLayers;
    order_.assign(order.begin(), order.end());
    if (edges && !context_.geometryShaders()) {
        throw std::runtime_error("--aa gbaa needs geometry shaders, which " +
                                 context_.deviceName() + " does not have");
    }
    if (separateEdges(extended, edges)) {
        edges = false;  // the main pass without them, recordEdges after it
        if (edgesOnly_.handle() == VK_NULL_HANDLE) {
            GraphicsPipelineDesc desc;
            desc.vertexSpirv = gbuffer_vert_spv;
            desc.geometrySpirv = gbuffer_edges_geom_spv;
            desc.fragmentSpirv = gbuffer_edges_only_frag_spv;
            setMeshVertexInput(desc);
            desc.colorFormats = {GBufferTargets::kEdgesFormat};
            desc.depthFormat = GBufferTargets::kDepthFormat;
            desc.depthCompare = VK_COMPARE_OP_EQUAL;  // the surface the G-buffer holds
            desc.depthWrite = false;
            desc.dynamicCullMode = true;
            const DescriptorBinding bindings[] = {
                {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                 VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT},
                {PREVIOUS_WORLDS_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                 VK_SHADER_STAGE_VERTEX_BIT}};
            edgesOnly_ = Pipeline::graphics(context_, desc, bindings, sizeof(DrawPush));
        }
    }
    const size_t index = variantIndex(materialLayers, extended, edges);
    const std::span<const uint32_t> fragments[8] = {gbuffer_frag_spv,
                                                    gbuffer_extended_frag_spv,
                                                    gbuffer_layered_frag_spv,
                                                    gbuffer_extended_layered_frag_spv,
                                                    gbuffer_edges_frag_spv,
                                                    gbuffer_extended_edges_frag_spv,
                                                    gbuffer_layered_edges_frag_spv,
                                                    gbuffer_extended_layered_edges_frag_spv};
    drawPipelines_.assign(scene.draws.size(), nullptr);
    drawLods_.assign(visible.begin(), visible.end());
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const DrawItem& draw = scene.draws[i];
        if (visible[i] == kDrawCulled || !drawnInGBuffer(resources, draw)) continue;
        const uint32_t slots = resources.materialTextureSlots(draw.material);
        Pipeline& pipeline = variants_[variantKey(index, slots)];
        if (pipeline.handle() == VK_NULL_HANDLE) {
            SpecializationConstants constants;
            constants.set(SPEC_MATERIAL_TEXTURE_SLOTS, slots);
            GraphicsPipelineDesc desc = gbufferDesc(fragments[index], extended, edges);
            desc.specialization = &constants;
            pipeline = Pipeline::graphics(context_, desc, gbufferBindings(materialLayers, edges),
                                          sizeof(DrawPush));
        }
        drawPipelines_[i] = &pipeline;
    }
}

void GBufferPass::record(VkCommandBuffer cmd, const GBufferTargets& targets, const ImageRef& hdr,
                         const std::array<float, 4>& clearRadiance, const FrameScene& scene,
                         SceneResources& resources, const GpuBuffer& cameraBuffer,
                         const GpuBuffer& previousWorlds) const {
    const uint32_t width = hdr.desc().width;
    const uint32_t height = hdr.desc().height;
    std::array<VkRenderingAttachmentInfo, 9> colors{};
    const uint32_t materialCount = targets.extended ? 8u : 6u;
    const uint32_t colorCount = materialCount + (targets.hasEdges ? 1u : 0u);
    for (size_t i = 0; i < colorCount; ++i) {
        const VkImageView view = i == materialCount ? targets.edges.view()
                                 : i < 4            ? targets.color[i].view()
                                 : i == 4           ? hdr.view()
                                 : i == 5           ? targets.motion.view()
                                 : i == 6           ? targets.anisotropy.view()
                                                    : targets.clearCoat.view();
        colors[i] = renderingAttachment(view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE);
    }
    // No edge where nothing is drawn (the background has no triangle).
    if (targets.hasEdges) {
        colors[materialCount].clearValue.color = {
            {float(GBAA_NO_EDGE), float(GBAA_NO_EDGE), float(GBAA_NO_EDGE), float(GBAA_NO_EDGE)}};
    }
    // Shading model 0 (Unlit) where nothing is drawn; the HDR target starts as the background.
    colors[4].clearValue.color = {{clearRadiance[0], clearRadiance[1], clearRadiance[2], 1.0f}};
    const VkRenderingAttachmentInfo depth = renderingAttachment(
        targets.depth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR,
        VK_ATTACHMENT_STORE_OP_STORE, reverseDepthClear());
    const VkRenderingInfo rendering =
        renderingInfo(width, height, std::span(colors.data(), colorCount), &depth);

    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);
    const Pipeline* bound = nullptr;

    const GpuBuffer& materials = resources.materialBuffer();
    VkDescriptorBufferInfo cameraInfo{cameraBuffer.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo materialInfo{materials.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo previousInfo{previousWorlds.handle(), 0, VK_WHOLE_SIZE};
    for (const uint32_t drawIndex : order_) {
        if (drawIndex >= scene.draws.size()) continue;
        const DrawItem& draw = scene.draws[drawIndex];
        const Pipeline* pipeline = drawPipelines_[drawIndex];
        if (pipeline == nullptr) continue;  // not drawn here (drawnInGBuffer)
        if (pipeline != bound) pipeline->bind(cmd);
        bound = pipeline;
        const MaterialBinding& binding = resources.materialBinding(draw.material);
        std::array<VkDescriptorImageInfo, size_t(kTextureSlotCount) + kLayerTextureSlotCount>
            images{};
        std::vector<VkWriteDescriptorSet> writes = {
            uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
            storageBufferWrite(PREVIOUS_WORLDS_BINDING, &previousInfo),
            storageBufferWrite(GBUFFER_BINDING_MATERIALS, &materialInfo)};
        for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
            const GpuTexture& t = resources.texture(binding.textures[slot]);
            images[slot] = {t.sampler, t.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            writes.push_back(
                sampledImageWrite(GBUFFER_BINDING_FIRST_TEXTURE + slot, &images[slot]));
        }
        for (uint32_t slot = 0; materialLayers_ && slot < kLayerTextureSlotCount; ++slot) {
            const GpuTexture& t = resources.texture(binding.layerTextures[slot]);
            VkDescriptorImageInfo& image = images[kTextureSlotCount + slot];
            image = {t.sampler, t.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            writes.push_back(sampledImageWrite(GBUFFER_BINDING_FIRST_LAYER_TEXTURE + slot, &image));
        }
        pipeline->pushDescriptors(cmd, writes);
        recordGBufferDraw(cmd, *pipeline, resources, draw, drawIndex, drawLods_[drawIndex]);
    }
    vkCmdEndRendering(cmd);
}

void GBufferPass::recordEdges(VkCommandBuffer cmd, const ImageRef& edges, const ImageRef& depth,
                              const FrameScene& scene, SceneResources& resources,
                              const GpuBuffer& cameraBuffer,
                              const GpuBuffer& previousWorlds) const {
    const uint32_t width = edges.desc().width;
    const uint32_t height = edges.desc().height;
    VkClearValue noEdge{};
    noEdge.color = {
        {float(GBAA_NO_EDGE), float(GBAA_NO_EDGE), float(GBAA_NO_EDGE), float(GBAA_NO_EDGE)}};
    const VkRenderingAttachmentInfo color =
        renderingAttachment(edges.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE, noEdge);
    const VkRenderingAttachmentInfo depthInfo =
        renderingAttachment(depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_NONE);
    const VkRenderingInfo rendering =
        renderingInfo(width, height, std::span(&color, 1), &depthInfo);

    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);
    edgesOnly_.bind(cmd);
    VkDescriptorBufferInfo cameraInfo{cameraBuffer.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo previousInfo{previousWorlds.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageBufferWrite(PREVIOUS_WORLDS_BINDING, &previousInfo)};
    edgesOnly_.pushDescriptors(cmd, writes);
    for (uint32_t drawIndex = 0; drawIndex < uint32_t(scene.draws.size()); ++drawIndex) {
        if (drawPipelines_[drawIndex] != nullptr) {
            recordGBufferDraw(cmd, edgesOnly_, resources, scene.draws[drawIndex], drawIndex,
                              drawLods_[drawIndex]);
        }
    }
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
