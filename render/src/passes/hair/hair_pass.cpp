#include "passes/hair/hair_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "clustered/cluster_grid.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "culling/view_frustum.h"
#include "gbuffer_targets.h"
#include "host_storage_array.h"
#include "ibl/environment_descriptors.h"
#include "passes/hair/hair_bindings.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "shaders/hair_depth.frag.spv.h"
#include "shaders/hair_fill.frag.spv.h"
#include "shaders/hair_fill.vert.spv.h"
#include "shaders/hair_fullscreen.vert.spv.h"
#include "shaders/hair_resolve.frag.spv.h"
#include "shaders/hair_shadow.vert.spv.h"
#include "shaders/shadow_depth.frag.spv.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

// hair_segment.glsl's HairSegment.
struct HairSegment {
    glm::vec4 start;       // xyz world, w radius
    glm::vec4 end;         // xyz world, w radius
    glm::vec4 color;       // rgb K_d
    glm::vec4 highlights;  // shifts, exponents
};

// hair_segment.glsl's push block.
struct HairPush {
    GpuClusterParams grid;
    float targetSize[2];
    float pixelRadiusPerDepth;
    float nearPlane;
    uint32_t mode;
    uint32_t directionalCount;
    float skyIntensity;
    uint32_t nodeCapacity;
    uint32_t selfShadow;
    uint32_t shadowView;
    uint32_t segmentCount;
    uint32_t pad;
};

constexpr VkDeviceSize kInitialSegments = 1024;
constexpr VkDeviceSize kNodeBytes = 4 * sizeof(uint32_t);  // hair_segment.glsl's uvec4 node

}  // namespace

HairPass::HairPass(GpuContext& context)
    : context_(context),
      segments_(context, kInitialSegments * sizeof(HairSegment), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                MemoryLocation::HostVisible),
      counters_(context, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                MemoryLocation::HostVisible),
      noMedium_(context, VolumetricsPass::kFroxelHeaderBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                MemoryLocation::HostVisible) {
    std::memset(counters_.mapped(), 0, 16);
    std::memset(noMedium_.mapped(), 0, VolumetricsPass::kFroxelHeaderBytes);
}

HairPass::~HairPass() = default;

VkDeviceSize HairPass::headBytes(uint32_t width, uint32_t height) {
    return VkDeviceSize(width) * height * sizeof(uint32_t);
}

size_t HairPass::maxSegments(const GpuContext& context) {
    return 2 * segmentsPerRange(context);
}

size_t HairPass::segmentsPerRange(const GpuContext& context) {
    // Whole 256-byte blocks (four segments): the second range's offset then meets any device's
    // minStorageBufferOffsetAlignment (256 at most).
    return context.properties().limits.maxStorageBufferRange / 256 * (256 / sizeof(HairSegment));
}

std::array<VkDescriptorBufferInfo, 2> HairPass::segmentRanges() const {
    // The first range as far as one binding reaches; the second the rest (or, when there is
    // none, the first segment again: bound, never read).
    const VkDeviceSize perRange = segmentsPerRange(context_) * sizeof(HairSegment);
    const VkDeviceSize used = std::max<VkDeviceSize>(segmentCount_, 1) * sizeof(HairSegment);
    const VkDeviceSize low = std::min(used, perRange);
    if (used <= perRange) {
        return {VkDescriptorBufferInfo{segments_.handle(), 0, low},
                VkDescriptorBufferInfo{segments_.handle(), 0, sizeof(HairSegment)}};
    }
    return {VkDescriptorBufferInfo{segments_.handle(), 0, low},
            VkDescriptorBufferInfo{segments_.handle(), low, used - low}};
}

uint32_t HairPass::maxNodes(const GpuContext& context) {
    return uint32_t(context.properties().limits.maxStorageBufferRange / kNodeBytes);
}

VkDeviceSize HairPass::nodeBytes(uint32_t nodeCapacity) {
    return std::max<VkDeviceSize>(nodeCapacity, 1) * kNodeBytes;
}

uint32_t HairPass::requestedNodes() const {
    return *static_cast<const uint32_t*>(counters_.mapped());
}

bool HairPass::prepare(const FrameScene& scene, const LightingFeatures& features,
                       HairShading shading, HairSelfShadow selfShadow) {
    selfShadow_ = selfShadow;
    size_t count = 0;
    for (const HairDraw& draw : scene.hair) {
        if (draw.hair && draw.style) count += draw.hair->segments.size() / 2;
    }
    // The shaders read the segments through two bindings (hair_segment.glsl), so a frame
    // draws at most what two reach on this device (4,194,304 segments at lavapipe's 128 MiB:
    // a million strands of four); the rest is left out with a warning, never bound past them.
    const size_t bindable = maxSegments(context_);
    if (count > bindable) {
        if (count != segmentsWarnedAbout_) {
            std::fprintf(stderr,
                         "warning: hair: %zu strand segments are more than this device binds "
                         "(two ranges of maxStorageBufferRange %u bytes hold %zu); drawing the "
                         "first %zu\n",
                         count, context_.properties().limits.maxStorageBufferRange, bindable,
                         bindable);
            segmentsWarnedAbout_ = count;
        }
        count = bindable;
    }
    segmentCount_ = uint32_t(count);
    if (count == 0) return false;
    // The strands' world box (radii included): shadow views it misses draw no hair.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    HairSegment* out = reserveHostStorageArray<HairSegment>(context_, segments_, count);
    for (const HairDraw& draw : scene.hair) {
        if (!draw.hair || !draw.style) continue;
        const content::Hair& hair = *draw.hair;
        const content::HairStyle& style = *draw.style;
        const glm::vec4 color(style.color[0], style.color[1], style.color[2], 0.0f);
        const glm::vec4 highlights(style.primaryShift, style.secondaryShift, style.primaryExponent,
                                   style.secondaryExponent);
        // Radii are world lengths: a scaled instance scales them by its mean axis scale.
        const float scale =
            (glm::length(glm::vec3(draw.world[0])) + glm::length(glm::vec3(draw.world[1])) +
             glm::length(glm::vec3(draw.world[2]))) /
            3.0f;
        auto radiusAt = [&](uint32_t index) {
            const float t = index < hair.rootToTip.size() ? hair.rootToTip[index] : 0.0f;
            return scale * (style.rootRadius + t * (style.tipRadius - style.rootRadius));
        };
        for (size_t i = 0; i + 1 < hair.segments.size() && count > 0; i += 2, --count) {
            const uint32_t ia = hair.segments[i], ib = hair.segments[i + 1];
            const auto& a = hair.positions[ia];
            const auto& b = hair.positions[ib];
            const glm::vec3 p0 = glm::vec3(draw.world * glm::vec4(a[0], a[1], a[2], 1.0f));
            const glm::vec3 p1 = glm::vec3(draw.world * glm::vec4(b[0], b[1], b[2], 1.0f));
            *out++ = {glm::vec4(p0, radiusAt(ia)), glm::vec4(p1, radiusAt(ib)), color, highlights};
            const float radius = std::max(radiusAt(ia), radiusAt(ib));
            lo = glm::min(lo, glm::min(p0, p1) - radius);
            hi = glm::max(hi, glm::max(p0, p1) + radius);
        }
    }
    bounds_.centre = 0.5f * (lo + hi);
    bounds_.extent = glm::max(0.5f * (hi - lo), glm::vec3(0.0f));
    bounds_.radius = glm::length(bounds_.extent);
    if (!built_ || !(features == features_) || shading != shading_) {
        features_ = features;
        shading_ = shading;
        buildPipelines();
    }
    return true;
}

void HairPass::buildPipelines() {
    const VkShaderStageFlags raster = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    {
        GraphicsPipelineDesc desc;
        desc.vertexSpirv = hair_fill_vert_spv;  // no vertex input: six vertices per segment
        desc.fragmentSpirv = hair_fill_frag_spv;
        desc.depthFormat = GBufferTargets::kDepthFormat;
        desc.depthWrite = false;
        const DescriptorBinding bindings[] = {
            {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, raster},
            {HAIR_BINDING_SEGMENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, raster},
            {HAIR_BINDING_SEGMENTS_HIGH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, raster},
            {HAIR_BINDING_HEADS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_COUNTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
        };
        fill_ = Pipeline::graphics(context_, desc, bindings, sizeof(HairPush));
    }
    {
        SpecializationConstants constants;
        setShadingConstants(constants, features_);
        constants.set(SPEC_IBL_MODE, features_.ibl ? 1u : 0u);
        GraphicsPipelineDesc desc;
        desc.vertexSpirv = hair_fullscreen_vert_spv;
        desc.fragmentSpirv = hair_resolve_frag_spv;
        desc.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT};  // the HDR target
        desc.alphaBlend = true;
        desc.specialization = &constants;
        const DescriptorBinding own[] = {
            {HAIR_BINDING_SEGMENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_SEGMENTS_HIGH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_HEADS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_HAIR_SHADOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment},
            {HAIR_BINDING_FROXEL_INTEGRATED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
        };
        const std::vector<DescriptorBinding> bindings = withLitInputBindings(own, raster);
        resolve_ = Pipeline::graphics(context_, desc, bindings, sizeof(HairPush));
    }
    {
        GraphicsPipelineDesc desc;
        desc.vertexSpirv = hair_fullscreen_vert_spv;
        desc.fragmentSpirv = hair_depth_frag_spv;
        desc.depthFormat = GBufferTargets::kDepthFormat;
        desc.depthWrite = true;
        desc.depthCompare = VK_COMPARE_OP_ALWAYS;  // the fill already tested every strand
        const DescriptorBinding bindings[] = {
            {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, raster},
            {HAIR_BINDING_SEGMENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_SEGMENTS_HIGH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_HEADS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
            {HAIR_BINDING_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment},
        };
        depth_ = Pipeline::graphics(context_, desc, bindings, sizeof(HairPush));
    }
    built_ = true;
}

void HairPass::pushCommon(VkCommandBuffer cmd, const Pipeline& pipeline, const Inputs& in) const {
    const uint32_t width = in.depth.desc().width;
    const uint32_t height = in.depth.desc().height;
    setViewportAndScissor(cmd, width, height);
    pipeline.bind(cmd);
    HairPush push{};
    push.grid = toGpu(in.lit.clusters->grid());
    push.targetSize[0] = float(width);
    push.targetSize[1] = float(height);
    push.pixelRadiusPerDepth = in.pixelRadiusPerDepth;
    push.nearPlane = in.nearPlane;
    push.mode = shading_ == HairShading::Coverage ? HAIR_MODE_COVERAGE : HAIR_MODE_LIT;
    push.directionalCount = in.lit.clusters->directionalCount();
    push.skyIntensity = in.lit.skyIntensity;
    push.nodeCapacity = in.nodeCapacity;
    push.selfShadow = !in.selfShadow                             ? HAIR_SELF_SHADOW_OFF
                      : selfShadow_ == HairSelfShadow::Reference ? HAIR_SELF_SHADOW_REFERENCE
                                                                 : HAIR_SELF_SHADOW_DEPTH_MAP;
    push.segmentCount = segmentCount_;
    pipeline.pushConstants(cmd, &push, sizeof(push));
}

void HairPass::recordClear(VkCommandBuffer cmd, const Inputs& in) const {
    vkCmdFillBuffer(cmd, in.heads.handle(), 0, VK_WHOLE_SIZE, HAIR_LIST_END);
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0u);
}

namespace {

// Rendering against the scene's depth alone, over the whole target: read (the fill tests its
// fragments against it) or written (the depth pass).
void beginDepthRendering(VkCommandBuffer cmd, const ImageRef& depth, bool write) {
    const VkRenderingAttachmentInfo attachment = renderingAttachment(
        depth.view(),
        write ? VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
        VK_ATTACHMENT_LOAD_OP_LOAD,
        write ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_NONE);
    const VkRenderingInfo rendering =
        renderingInfo(depth.desc().width, depth.desc().height, {}, &attachment);
    vkCmdBeginRendering(cmd, &rendering);
}

}  // namespace

void HairPass::recordFill(VkCommandBuffer cmd, const Inputs& in) const {
    beginDepthRendering(cmd, in.depth, false);
    VkDescriptorBufferInfo cameraInfo{in.lit.camera->handle(), 0, VK_WHOLE_SIZE};
    const std::array<VkDescriptorBufferInfo, 2> segmentInfo = segmentRanges();
    VkDescriptorBufferInfo headInfo{in.heads.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo nodeInfo{in.nodes.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo counterInfo{counters_.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageBufferWrite(HAIR_BINDING_SEGMENTS, &segmentInfo[0]),
        storageBufferWrite(HAIR_BINDING_SEGMENTS_HIGH, &segmentInfo[1]),
        storageBufferWrite(HAIR_BINDING_HEADS, &headInfo),
        storageBufferWrite(HAIR_BINDING_NODES, &nodeInfo),
        storageBufferWrite(HAIR_BINDING_COUNTERS, &counterInfo)};
    pushCommon(cmd, fill_, in);
    fill_.pushDescriptors(cmd, writes);
    vkCmdDraw(cmd, 6 * segmentCount_, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

void HairPass::recordResolve(VkCommandBuffer cmd, const Inputs& in) const {
    const VkRenderingAttachmentInfo color =
        renderingAttachment(in.hdr.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_STORE);
    const VkRenderingInfo rendering =
        renderingInfo(in.hdr.desc().width, in.hdr.desc().height, std::span(&color, 1));
    vkCmdBeginRendering(cmd, &rendering);
    const std::array<VkDescriptorBufferInfo, 2> segmentInfo = segmentRanges();
    VkDescriptorBufferInfo headInfo{in.heads.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo nodeInfo{in.nodes.handle(), 0, VK_WHOLE_SIZE};
    // Without self-shadowing the atlas stands in (bound, never read).
    const ShadowDescriptors& shadows = in.lit.shadows;
    const VkDescriptorImageInfo hairShadowInfo =
        in.selfShadow ? VkDescriptorImageInfo{shadows.atlas.sampler, in.hairShadow.view(),
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}
                      : shadows.atlas;
    VkDescriptorBufferInfo froxelInfo{
        in.froxels ? in.froxelIntegrated.handle() : noMedium_.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet own[] = {
        storageBufferWrite(HAIR_BINDING_SEGMENTS, &segmentInfo[0]),
        storageBufferWrite(HAIR_BINDING_SEGMENTS_HIGH, &segmentInfo[1]),
        storageBufferWrite(HAIR_BINDING_HEADS, &headInfo),
        storageBufferWrite(HAIR_BINDING_NODES, &nodeInfo),
        sampledImageWrite(HAIR_BINDING_HAIR_SHADOW, &hairShadowInfo),
        storageBufferWrite(HAIR_BINDING_FROXEL_INTEGRATED, &froxelInfo)};
    const LitDescriptorWrites writes(in.lit, own);
    pushCommon(cmd, resolve_, in);
    resolve_.pushDescriptors(cmd, writes.writes());
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

void HairPass::recordDepth(VkCommandBuffer cmd, const Inputs& in) const {
    beginDepthRendering(cmd, in.depth, true);
    VkDescriptorBufferInfo cameraInfo{in.lit.camera->handle(), 0, VK_WHOLE_SIZE};
    const std::array<VkDescriptorBufferInfo, 2> segmentInfo = segmentRanges();
    VkDescriptorBufferInfo headInfo{in.heads.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo nodeInfo{in.nodes.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        storageBufferWrite(HAIR_BINDING_SEGMENTS, &segmentInfo[0]),
        storageBufferWrite(HAIR_BINDING_SEGMENTS_HIGH, &segmentInfo[1]),
        storageBufferWrite(HAIR_BINDING_HEADS, &headInfo),
        storageBufferWrite(HAIR_BINDING_NODES, &nodeInfo)};
    pushCommon(cmd, depth_, in);
    depth_.pushDescriptors(cmd, writes);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

ImageDesc HairPass::hairShadowDepthDesc(uint32_t atlasSize) {
    return {GBufferTargets::kDepthFormat,
            atlasSize,
            atlasSize,
            1,
            false,
            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

void HairPass::recordShadowDepth(VkCommandBuffer cmd, const Inputs& in,
                                 std::span<const GpuShadowView> views) {
    if (!shadowDepth_.handle()) {
        GraphicsPipelineDesc desc;
        desc.vertexSpirv = hair_shadow_vert_spv;  // no vertex input: six vertices per segment
        desc.fragmentSpirv = shadow_depth_frag_spv;
        desc.depthFormat = GBufferTargets::kDepthFormat;
        desc.depthWrite = true;
        desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse depth: keep the nearest
        desc.cullMode = VK_CULL_MODE_NONE;
        const DescriptorBinding bindings[] = {
            {HAIR_BINDING_SEGMENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
            {HAIR_BINDING_SEGMENTS_HIGH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
             VK_SHADER_STAGE_VERTEX_BIT},
            {LIT_BINDING_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
             VK_SHADER_STAGE_VERTEX_BIT},
        };
        shadowDepth_ = Pipeline::graphics(context_, desc, bindings, sizeof(HairPush));
    }
    // Drawn into the views whose frustum holds strands (a cube face or cascade beside the hair
    // has none: the resolve never looks a hair fragment up there), cleared and drawn only over
    // their tiles' bounding box (the atlas packs tiles from its corner).
    std::vector<uint32_t> drawn;
    for (uint32_t v = 0; v < views.size(); ++v) {
        if (intersects(viewFrustumOf(views[v].worldToClip), bounds_)) drawn.push_back(v);
    }
    const uint32_t size = in.hairShadow.desc().width;
    uint32_t x0 = size, y0 = size, x1 = 0, y1 = 0;
    for (uint32_t d : drawn) {
        const GpuShadowView& v = views[d];
        x0 = std::min(x0, uint32_t(v.tile.x));
        y0 = std::min(y0, uint32_t(v.tile.y));
        x1 = std::max(x1, std::min(size, uint32_t(v.tile.x + v.tile.z)));
        y1 = std::max(y1, std::min(size, uint32_t(v.tile.y + v.tile.z)));
    }
    if (x1 <= x0 || y1 <= y0) {  // no view: an empty frame of the pass
        x0 = y0 = 0;
        x1 = y1 = 1;
    }
    // Cleared to reverse depth 0: no hair.
    const VkRenderingAttachmentInfo depth = renderingAttachment(
        in.hairShadow.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR,
        VK_ATTACHMENT_STORE_OP_STORE, reverseDepthClear());
    VkRenderingInfo rendering = renderingInfo(x1 - x0, y1 - y0, {}, &depth);
    rendering.renderArea.offset = {int32_t(x0), int32_t(y0)};  // the views' tiles only
    vkCmdBeginRendering(cmd, &rendering);
    const std::array<VkDescriptorBufferInfo, 2> segmentInfo = segmentRanges();
    const VkWriteDescriptorSet writes[] = {
        storageBufferWrite(HAIR_BINDING_SEGMENTS, &segmentInfo[0]),
        storageBufferWrite(HAIR_BINDING_SEGMENTS_HIGH, &segmentInfo[1]),
        storageBufferWrite(LIT_BINDING_SHADOW_VIEWS, &in.lit.shadows.views)};
    shadowDepth_.bind(cmd);
    shadowDepth_.pushDescriptors(cmd, writes);
    HairPush push{};
    for (uint32_t v : drawn) {
        const VkRect2D rect{{int32_t(views[v].tile.x), int32_t(views[v].tile.y)},
                            {uint32_t(views[v].tile.z), uint32_t(views[v].tile.z)}};
        setViewportAndScissor(cmd, rect);
        push.shadowView = v;
        shadowDepth_.pushConstants(cmd, &push, sizeof(push));
        vkCmdDraw(cmd, 6 * segmentCount_, 1, 0, 0);
    }
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
