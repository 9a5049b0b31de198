#include "passes/sky_occlusion/sky_occlusion_pass.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "culling/draw_bounds.h"
#include "mesh_vertex.h"
#include "passes/shadows/caster_depth_draws.h"
#include "passes/sky_occlusion/sky_occlusion_directions.h"
#include "shaders/shadow_depth.frag.spv.h"
#include "shaders/shadow_depth.vert.spv.h"
#include "vk/depth_placeholder.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

constexpr VkFormat kAtlasFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
// Half-diagonal (m) under which a caster is left out: half GTAO's default 1.5 m radius.
constexpr float kSmallCaster = 0.75f;

uint64_t mix(uint64_t h, const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i)
        h = (h ^ p[i]) * 1099511628211ull;  // FNV-1a
    return h;
}

}  // namespace

uint32_t skyOcclusionDirectionCount(SkyOcclusionMode mode) {
    return mode == SkyOcclusionMode::Reference ? 256u : mode == SkyOcclusionMode::On ? 32u : 0u;
}

uint32_t skyOcclusionTileSize(SkyOcclusionMode) {
    return 256u;
}

SkyOcclusionPass::SkyOcclusionPass(GpuContext& context)
    : context_(context),
      // Stored depth grows toward the sky: a texel lets the sky through when the receiver's
      // stored depth is at least its own (the highest surface of its column).
      compareSampler_(
          context,
          SamplerDesc{VK_FILTER_LINEAR, false, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                      VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, true, VK_COMPARE_OP_GREATER_OR_EQUAL}),
      placeholder_(context, {kAtlasFormat, 1, 1, 1, false,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}) {
    context.submitAndWait([&](VkCommandBuffer cmd) { clearDepthPlaceholder(cmd, placeholder_); });
}

SkyOcclusionPass::~SkyOcclusionPass() = default;

bool SkyOcclusionPass::prepare(const FrameScene& scene, const SceneResources& resources,
                               SkyOcclusionMode mode) {
    rendersThisFrame_ = false;
    casters_.clear();
    if (mode == SkyOcclusionMode::Off) return false;
    // Casters: the static opaque and masked surfaces at least kSmallCaster in size (blended
    // ones let the sky through; skinned or morphed ones move every frame and, like the small
    // ones, are left to screen-space AO).
    struct Box {
        glm::vec3 lo, hi;
    };
    std::vector<Box> boxes;
    glm::vec3 lo(1e30f), hi(-1e30f);
    uint64_t key = 1469598103934665603ull;
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const DrawItem& draw = scene.draws[d];
        const GpuMesh& mesh = resources.mesh(draw.mesh);
        if (mesh.indexCount == 0 || draw.deformedVertices != VK_NULL_HANDLE) continue;
        if (resources.material(draw.material).alphaMode == content::AlphaMode::Blend) continue;
        const WorldBounds world = worldBoundsOf(draw, resources);
        const glm::vec3 c = world.centre, e = world.extent;
        // Small casters (half-diagonal under kSmallCaster) are screen-space AO's scale; drawing
        // them n times would cost more than the sky light they block at the maps' texel size.
        if (world.radius < kSmallCaster) continue;
        boxes.push_back({c - e, c + e});
        lo = glm::min(lo, c - e);
        hi = glm::max(hi, c + e);
        casters_.push_back(d);
        key = mix(key, &draw.mesh, sizeof(draw.mesh));
        key = mix(key, &draw.world, sizeof(draw.world));
    }
    if (casters_.empty()) return false;
    // The sphere: around the casters above the lowest level of the scene. A ground plane
    // (a caster lying at the bottom) blocks no sky for what stands on it, and a wide meadow
    // would spread the maps' texels thin; it is still drawn where it falls in the maps.
    glm::vec3 standingLo(1e30f), standingHi(-1e30f);
    for (const Box& b : boxes) {
        if (b.hi.y <= lo.y + 0.05f * std::max(hi.y - lo.y, 1e-3f)) continue;
        standingLo = glm::min(standingLo, b.lo);
        standingHi = glm::max(standingHi, b.hi);
    }
    if (standingLo.x > standingHi.x) {
        standingLo = lo;
        standingHi = hi;
    }
    const glm::vec3 centre = 0.5f * (standingLo + standingHi);
    const float radius = std::max(0.5f * glm::length(standingHi - standingLo), 1e-2f);
    sphere_ = glm::vec4(centre, radius);

    directions_ = skyOcclusionDirectionCount(mode);
    tileSize_ = skyOcclusionTileSize(mode);
    tilesPerRow_ = uint32_t(std::ceil(std::sqrt(float(directions_))));
    const uint32_t size = tilesPerRow_ * tileSize_;
    if (!atlas_.handle() || atlas_.desc().width != size) {
        atlas_ = GpuImage(
            context_, {kAtlasFormat, size, size, 1, false,
                       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
        atlasHoldsMaps_ = false;
    }
    key = mix(key, &sphere_, sizeof(sphere_));
    key = mix(key, &directions_, sizeof(directions_));
    rendersThisFrame_ = !atlasHoldsMaps_ || key != key_;
    key_ = key;
    return true;
}

void SkyOcclusionPass::record(VkCommandBuffer cmd, const FrameScene& scene,
                              const SceneResources& resources) {
    const uint32_t size = atlas_.desc().width;
    // Cleared to 0: nothing between the texel and the sky.
    const VkRenderingAttachmentInfo depth = renderingAttachment(
        atlas_.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR,
        VK_ATTACHMENT_STORE_OP_STORE, reverseDepthClear());
    const VkRenderingInfo rendering = renderingInfo(size, size, {}, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    if (!pipeline_.handle()) {  // built for the first frame that renders maps
        GraphicsPipelineDesc desc;
        desc.vertexSpirv = shadow_depth_vert_spv;  // the shadow maps' depth-only draw
        desc.fragmentSpirv = shadow_depth_frag_spv;
        desc.vertexBindings = {{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
        desc.vertexAttributes = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)}};
        desc.depthFormat = kAtlasFormat;
        desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;
        desc.depthWrite = true;
        desc.cullMode = VK_CULL_MODE_NONE;  // a roof's single-sided surface blocks from both sides
        pipeline_ = Pipeline::graphics(context_, desc, {}, sizeof(glm::mat4));
    }
    pipeline_.bind(cmd);
    const glm::vec3 centre(sphere_);
    for (uint32_t i = 0; i < directions_; ++i) {
        const glm::mat4 view =
            skyOcclusionView(skyOcclusionDirection(i, directions_), centre, sphere_.w);
        const VkRect2D rect{
            {int32_t((i % tilesPerRow_) * tileSize_), int32_t((i / tilesPerRow_) * tileSize_)},
            {tileSize_, tileSize_}};
        setViewportAndScissor(cmd, rect);
        drawCasterDepths(cmd, pipeline_, scene, resources, casters_, view);
    }
    vkCmdEndRendering(cmd);
    atlasHoldsMaps_ = true;
    ++rebuilds_;
}

VkDescriptorImageInfo SkyOcclusionPass::descriptor(bool enabled) const {
    return {compareSampler_.handle(), enabled ? atlas_.view() : placeholder_.view(), kRead};
}

glm::uvec4 SkyOcclusionPass::layout() const {
    return {directions_, tilesPerRow_, tileSize_, tilesPerRow_ * tileSize_};
}

}  // namespace candela::render
