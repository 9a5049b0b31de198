#include "passes/shadows/shadow_pass.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_light_lists.h"
#include "culling/draw_bounds.h"
#include "culling/lod_selection.h"
#include "culling/view_frustum.h"
#include "ibl/environment_cache.h"
#include "lights/gpu_light_types.h"
#include "mesh_vertex.h"
#include "passes/shadows/cascades.h"
#include "passes/shadows/caster_depth_draws.h"
#include "passes/shadows/shadow_atlas.h"
#include "passes/shadows/shadow_render_budget.h"
#include "passes/shadows/shadows_bindings.h"
#include "shaders/shadow_depth.frag.spv.h"
#include "shaders/shadow_depth.vert.spv.h"
#include "vk/depth_placeholder.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

namespace {

constexpr VkFormat kAtlasFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
// Local maps: near plane (metres).
constexpr float kLocalNear = 0.05f;
// Cube faces and spot views reach a little past their edge, so the 3x3 filter at a face's
// border reads texels of that face.
constexpr float kBorderTexels = 2.0f;

// The 6 cube faces: forward and up of each, major-axis order +X, -X, +Y, -Y, +Z, -Z.
const glm::vec3 kFaceForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const glm::vec3 kFaceUp[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

// Reverse-Z, infinite far: clip = (right.d / t, up.d / t, near, forward.d), d = P - origin.
glm::mat4 perspectiveView(const glm::vec3& origin, const glm::vec3& forward, const glm::vec3& up,
                          float tanHalf) {
    const glm::vec3 f = glm::normalize(forward);
    const glm::vec3 r = glm::normalize(glm::cross(up, f));
    const glm::vec3 u = glm::cross(f, r);
    glm::mat4 m(0.0f);
    for (int i = 0; i < 3; ++i) {
        m[i][0] = r[i] / tanHalf;
        m[i][1] = u[i] / tanHalf;
        m[i][3] = f[i];
    }
    m[3][0] = -glm::dot(r, origin) / tanHalf;
    m[3][1] = -glm::dot(u, origin) / tanHalf;
    m[3][2] = kLocalNear;
    m[3][3] = -glm::dot(f, origin);
    return m;
}

glm::vec3 anyPerpendicular(const glm::vec3& v) {
    return std::abs(v.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
}

// A spot light narrow enough for one perspective view (wider ones use cube faces).
bool singleViewSpot(const content::Light& l) {
    return l.type == content::LightType::Spot &&
           l.outerConeAngle <= float(SHADOW_MAX_SPOT_HALF_ANGLE);
}

uint32_t powerOfTwoAtLeast(float v) {
    return std::bit_ceil(uint32_t(std::clamp(v, 1.0f, 65536.0f)));
}

// Casters: every drawn opaque or masked surface (blended ones let light through).
std::vector<uint32_t> shadowCasters(const FrameScene& scene, const SceneResources& resources) {
    std::vector<uint32_t> casters;
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const DrawItem& draw = scene.draws[d];
        const GpuMesh& mesh = resources.mesh(draw.mesh);
        if (mesh.indexCount == 0) continue;
        if (resources.material(draw.material).alphaMode == content::AlphaMode::Blend) continue;
        casters.push_back(d);
    }
    return casters;
}

// A directional light's cascades: fixed size, never shrunk.
ShadowTileRequest cascadeTileRequest(uint32_t cascades, const RendererOptions& options) {
    ShadowTileRequest r;
    r.tiles = cascades;
    r.size = powerOfTwoAtLeast(float(options.shadowCascadeSize));
    r.shrinkable = false;
    return r;
}

// A spot view or cube faces. Projected size: the falloff sphere's diameter in pixels;
// importance: its intensity.
ShadowTileRequest localTileRequest(const LightInstance& instance, const CameraView& camera,
                                   const RendererOptions& options, uint32_t width,
                                   uint32_t height) {
    const content::Light& l = instance.light;
    const float projectionScale = std::abs(camera.projection[1][1]);  // 1 / tan(fov / 2)
    const float reach = std::max(l.attenuationRadius, 1e-3f) + 0.5f * l.sourceLength;
    const float distance = glm::length(instance.position - camera.position);
    const float pixels = distance > reach * 1.05f
                             ? 0.5f * float(height) * projectionScale * reach /
                                   std::sqrt(distance * distance - reach * reach)
                             : 0.5f * float(std::max(width, height)) * projectionScale;
    ShadowTileRequest r;
    r.tiles = singleViewSpot(l) ? 1u : SHADOW_CUBE_FACES;
    r.size = std::min(powerOfTwoAtLeast(2.0f * pixels),
                      powerOfTwoAtLeast(float(options.shadowMaxTileSize)));
    r.size = std::max(r.size, 16u);
    r.priority = pixels * std::sqrt(std::max(l.lumens, 0.0f) + 1.0f);
    return r;
}

// The smallest power-of-two atlas (up to `maxSize`) that holds every map at full size.
uint32_t atlasSizeFor(std::span<const ShadowTileRequest> tiles, uint32_t maxSize) {
    uint64_t wanted = 0;
    for (const ShadowTileRequest& r : tiles)
        wanted += uint64_t(r.size) * r.size * r.tiles;
    uint32_t atlasSize = 256;
    while (atlasSize < maxSize && uint64_t(atlasSize) * atlasSize < wanted)
        atlasSize *= 2;
    return atlasSize;
}

}  // namespace

ShadowPass::ShadowPass(GpuContext& context)
    : context_(context),
      pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}),
      // Stored depth grows toward the light (reverse depth): a texel lets light through when
      // the receiver's stored depth is at least its own. Linear: 2x2 bilinear PCF per tap.
      compareSampler_(
          context,
          SamplerDesc{VK_FILTER_LINEAR, false, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                      VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, true, VK_COMPARE_OP_GREATER_OR_EQUAL}),
      placeholderAtlas_(context, {kAtlasFormat, 1, 1, 1, false,
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}),
      placeholderBuffer_(context, 112,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryLocation::Device) {
    GraphicsPipelineDesc desc;
    desc.vertexSpirv = shadow_depth_vert_spv;
    desc.fragmentSpirv = shadow_depth_frag_spv;
    desc.vertexBindings = {{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)}};
    desc.depthFormat = kAtlasFormat;
    desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse depth, as the camera's
    desc.depthWrite = true;
    desc.cullMode = VK_CULL_MODE_NONE;  // single-sided glTF surfaces cast from both sides
    pipeline_ = Pipeline::graphics(context, desc, {}, sizeof(glm::mat4));
    context.submitAndWait([&](VkCommandBuffer cmd) {
        // Cleared, not left undefined: the variant without shadows still binds it.
        clearDepthPlaceholder(cmd, placeholderAtlas_);
        vkCmdFillBuffer(cmd, placeholderBuffer_.handle(), 0, VK_WHOLE_SIZE, 0);
    });
}

ShadowPass::~ShadowPass() = default;

void ShadowPass::ensureAtlas(uint32_t size) {
    if (atlas_.handle() && atlas_.desc().width == size) return;
    atlas_ = GpuImage(context_,
                      {kAtlasFormat, size, size, 1, false,
                       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    atlasHoldsMaps_ = false;
    previousKeys_.clear();
}

bool ShadowPass::prepare(const FrameScene& scene, const SceneResources& resources,
                         std::span<const WorldBounds> bounds, const RendererOptions& options,
                         uint32_t width, uint32_t height) {
    planned_.clear();
    lightPlans_.clear();
    stats_ = {};
    rendersThisFrame_ = false;
    ++frameCounter_;
    if (!options.shadows) return false;

    const std::vector<uint32_t> casters = shadowCasters(scene, resources);
    std::vector<MapRequest> requests;
    std::vector<ShadowTileRequest> tiles;
    requestMaps(scene, options, width, height, requests, tiles);
    if (requests.empty()) return false;

    const uint32_t atlasSize = atlasSizeFor(tiles, options.shadowAtlasSize);
    ensureAtlas(atlasSize);
    const ShadowAtlasPlan plan = planShadowAtlas(tiles, atlasSize);
    stats_.atlasUsed = double(plan.usedTexels) / (double(atlasSize) * atlasSize);

    std::vector<glm::uvec2> lightTable(std::max<size_t>(scene.lights.size(), 1),
                                       glm::uvec2(SHADOW_NO_VIEW, 0));
    previousKeys_.resize(scene.lights.size(), 0);
    previousViews_.resize(scene.lights.size());
    framesWaiting_.resize(scene.lights.size(), 0);
    std::vector<uint64_t> keys(requests.size(), 0);
    std::vector<ShadowRenderCandidate> candidates(requests.size());
    const ViewInputs viewInputs{scene, resources, bounds, options, casters};
    for (size_t q = 0; q < requests.size(); ++q) {
        const MapRequest& request = requests[q];
        if (plan.tiles[q].size() != request.views) continue;  // never: the atlas floor is 8 px
        const LightPlan lp{request.light, uint32_t(planned_.size()), request.views, true,
                           uint32_t(q)};
        keys[q] = planLightViews(viewInputs, request, plan.tiles[q]);
        candidates[q] = renderCandidate(request, plan.tiles[q], lp.firstView, keys[q],
                                        tiles[q].priority, options);
        lightTable[request.light] = glm::uvec2(lp.firstView, lp.viewCount);
        lightPlans_.push_back(lp);
    }

    const std::vector<ShadowRenderChoice> choices =
        planShadowRenders(candidates, options.shadowCache ? options.shadowRenderBudget : 0);
    applyRenderChoices(choices, keys, scene, resources);
    releaseUnplannedLights(scene.lights.size());
    uploadTables(lightTable);
    return true;
}

void ShadowPass::requestMaps(const FrameScene& scene, const RendererOptions& options,
                             uint32_t width, uint32_t height, std::vector<MapRequest>& requests,
                             std::vector<ShadowTileRequest>& tiles) {
    const uint32_t cascades = std::clamp(options.shadowCascades, 1u, SHADOW_MAX_CASCADES);
    for (uint32_t i = 0; i < scene.lights.size(); ++i) {
        const content::Light& l = scene.lights[i].light;
        if (!l.castShadows) continue;
        if (inEveryCluster(l)) {
            requests.push_back({i, cascades, true});
            tiles.push_back(cascadeTileRequest(cascades, options));
            continue;
        }
        const ShadowTileRequest r =
            localTileRequest(scene.lights[i], scene.camera, options, width, height);
        requests.push_back({i, r.tiles, false});
        tiles.push_back(r);
    }
}

uint64_t ShadowPass::planLightViews(const ViewInputs& in, const MapRequest& request,
                                    std::span<const ShadowTile> tiles) {
    const LightInstance& instance = in.scene.lights[request.light];
    // What the maps are rendered from: views (light placement, tiles) and casters.
    uint64_t key = kFnv1aOffset;
    for (uint32_t v = 0; v < request.views; ++v) {
        const ShadowTile& tile = tiles[v];
        PlannedView pv;
        pv.gpu = {glm::mat4(1.0f), glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f)};
        pv.light = request.light;
        pv.gpu.tile = glm::vec4(float(tile.x), float(tile.y), float(tile.size), 0.0f);
        if (request.cascade) {
            planCascadeView(in, instance, request.views, v, tile, pv);
        } else {
            planLocalView(in, instance, v, tile, pv);
        }
        key = viewKey(pv, in.scene, key);
        planned_.push_back(std::move(pv));
    }
    return key;
}

void ShadowPass::planCascadeView(const ViewInputs& in, const LightInstance& instance,
                                 uint32_t cascades, uint32_t cascade, const ShadowTile& tile,
                                 PlannedView& pv) {
    const CameraView& camera = in.scene.camera;
    const glm::vec3 direction = glm::normalize(instance.direction);
    float casterNear = 0.0f;
    for (uint32_t d : in.casters) {
        casterNear =
            std::min(casterNear, glm::dot(in.bounds[d].centre, direction) - in.bounds[d].radius);
    }
    const float farDistance = std::min(in.options.shadowDistance, camera.farPlane);
    const std::vector<float> splits =
        practicalSplits(camera.nearPlane, farDistance, cascades, kPracticalSplitLambda);
    const CascadeView c =
        fitCascade(camera, splits[cascade], splits[cascade + 1], direction, tile.size, casterNear);
    pv.gpu.worldToClip = c.worldToClip;
    pv.gpu.params =
        glm::vec4(c.texelWorld, float(SHADOW_KIND_ORTHOGRAPHIC), c.nearDepth, c.farDepth);
    pv.gpu.sphere = c.sphere;
    const glm::mat3 basis = lightBasis(direction);
    const glm::vec3 centre = glm::transpose(basis) * glm::vec3(c.sphere);
    // Levels of detail by the cascade's texels (orthographic: one size everywhere).
    LodView lod;
    lod.pixelsPerMetre = 1.0f / std::max(c.texelWorld, 1e-6f);
    lod.perspective = false;
    lod.pixelError = in.options.lodPixelError;
    for (uint32_t d : in.casters) {
        const glm::vec3 p = glm::transpose(basis) * in.bounds[d].centre;
        const float reach = c.sphere.w + in.bounds[d].radius + c.texelWorld;
        if (std::abs(p.x - centre.x) <= reach && std::abs(p.y - centre.y) <= reach &&
            p.z - in.bounds[d].radius <= c.farDepth) {
            pv.casters.push_back(d);
            pv.lods.push_back(uint8_t(selectLod(in.resources.mesh(in.scene.draws[d].mesh),
                                                in.scene.draws[d].world, in.bounds[d], lod)));
        }
    }
}

void ShadowPass::planLocalView(const ViewInputs& in, const LightInstance& instance, uint32_t view,
                               const ShadowTile& tile, PlannedView& pv) {
    const content::Light& l = instance.light;
    const bool spot = singleViewSpot(l);
    const float border = 1.0f + 2.0f * kBorderTexels / float(tile.size);
    const float tanHalf =
        spot ? std::tan(std::clamp(l.outerConeAngle, 0.01f, float(SHADOW_MAX_SPOT_HALF_ANGLE))) *
                   border
             : border;
    const glm::vec3 forward = spot ? glm::normalize(instance.direction) : kFaceForward[view];
    const glm::vec3 up = spot ? anyPerpendicular(forward) : kFaceUp[view];
    pv.gpu.worldToClip = perspectiveView(instance.position, forward, up, tanHalf);
    pv.gpu.params = glm::vec4(2.0f * tanHalf / float(tile.size), float(SHADOW_KIND_PERSPECTIVE),
                              kLocalNear, 0.0f);
    const float reach = std::max(l.attenuationRadius, 0.0f) + 0.5f * l.sourceLength;
    // A caster outside this face's (or the spot's) frustum draws nothing in its tile: each face
    // gets the sixth of the light's casters it sees.
    const ViewFrustum frustum = viewFrustumOf(pv.gpu.worldToClip);
    // Levels of detail by the face's texels: tile.size across 2 tanHalf at 1 m.
    LodView lod;
    lod.eye = instance.position;
    lod.pixelsPerMetre = float(tile.size) / (2.0f * tanHalf);
    lod.pixelError = in.options.lodPixelError;
    for (uint32_t d : in.casters) {
        const WorldBounds& b = in.bounds[d];
        if (glm::length(b.centre - instance.position) > reach + b.radius) continue;
        if (in.options.culling && !intersects(frustum, b)) continue;
        // The light's own fixture (a bulb or tube mesh around it) casts nothing.
        if (glm::all(
                glm::lessThanEqual(glm::abs(instance.position - b.centre), b.extent + 1e-4f))) {
            continue;
        }
        pv.casters.push_back(d);
        pv.lods.push_back(uint8_t(
            selectLod(in.resources.mesh(in.scene.draws[d].mesh), in.scene.draws[d].world, b, lod)));
    }
}

uint64_t ShadowPass::viewKey(const PlannedView& pv, const FrameScene& scene, uint64_t key) const {
    key = fnv1a64(&pv.gpu, sizeof(pv.gpu), key);
    for (size_t c = 0; c < pv.casters.size(); ++c) {
        // Field by field: DrawItem has padding bytes.
        const DrawItem& draw = scene.draws[pv.casters[c]];
        key = fnv1a64(&draw.mesh, sizeof(draw.mesh), key);
        key = fnv1a64(&draw.material, sizeof(draw.material), key);
        key = fnv1a64(&draw.world, sizeof(draw.world), key);
        key = fnv1a64(&pv.lods[c], sizeof(pv.lods[c]), key);
        // An animated caster changes shape under the same draw: never cached.
        if (draw.deformedVertices) key = fnv1a64(&frameCounter_, sizeof(frameCounter_), key);
    }
    return key;
}

ShadowRenderCandidate ShadowPass::renderCandidate(const MapRequest& request,
                                                  std::span<const ShadowTile> tiles,
                                                  uint32_t firstView, uint64_t key, float priority,
                                                  const RendererOptions& options) const {
    ShadowRenderCandidate c;
    const std::vector<GpuShadowView>& previous = previousViews_[request.light];
    c.changed = !options.shadowCache || !atlasHoldsMaps_ || previousKeys_[request.light] != key;
    // Last frame's maps can stand in only where they still are: same tiles (no other light
    // renders into them this frame, as tiles never overlap). Cascades follow the camera and
    // always render.
    c.keepable = options.shadowCache && atlasHoldsMaps_ && !request.cascade &&
                 previous.size() == request.views;
    for (uint32_t v = 0; v < request.views; ++v) {
        const ShadowTile& tile = tiles[v];
        c.texels += uint64_t(tile.size) * tile.size;
        if (c.keepable && previous[v].tile != planned_[firstView + v].gpu.tile) c.keepable = false;
    }
    c.priority = priority;
    c.framesWaiting = framesWaiting_[request.light];
    return c;
}

void ShadowPass::applyRenderChoices(std::span<const ShadowRenderChoice> choices,
                                    std::span<const uint64_t> keys, const FrameScene& scene,
                                    const SceneResources& resources) {
    for (LightPlan& lp : lightPlans_) {
        const uint32_t light = lp.light;
        const ShadowRenderChoice choice = choices[lp.request];
        lp.render = choice == ShadowRenderChoice::Render;
        ++stats_.shadowedLights;
        if (choice == ShadowRenderChoice::Keep) {
            // Sample the maps with the views they were rendered from; the key stays, so the
            // light asks again next frame.
            for (uint32_t v = 0; v < lp.viewCount; ++v)
                planned_[lp.firstView + v].gpu = previousViews_[light][v];
            ++framesWaiting_[light];
            ++stats_.mapsKept;
            continue;
        }
        framesWaiting_[light] = 0;
        if (lp.render) rememberViews(lp, keys[lp.request]);
        rendersThisFrame_ |= lp.render;
        if (lp.render) countCasters(lp, scene, resources);
        (lp.render ? stats_.mapsRendered : stats_.mapsCached) += 1;
    }
}

void ShadowPass::rememberViews(const LightPlan& lp, uint64_t key) {
    previousKeys_[lp.light] = key;
    previousViews_[lp.light].clear();
    for (uint32_t v = 0; v < lp.viewCount; ++v)
        previousViews_[lp.light].push_back(planned_[lp.firstView + v].gpu);
}

void ShadowPass::countCasters(const LightPlan& lp, const FrameScene& scene,
                              const SceneResources& resources) {
    for (uint32_t v = 0; v < lp.viewCount; ++v) {
        const PlannedView& pv = planned_[lp.firstView + v];
        stats_.casterDraws += uint32_t(pv.casters.size());
        for (size_t c = 0; c < pv.casters.size(); ++c) {
            stats_.casterTriangles +=
                resources.mesh(scene.draws[pv.casters[c]].mesh).lods[pv.lods[c]].indexCount / 3;
        }
    }
}

void ShadowPass::releaseUnplannedLights(size_t lightCount) {
    std::vector<bool> requested(lightCount, false);
    for (const LightPlan& lp : lightPlans_)
        requested[lp.light] = true;
    // A light that casts no shadow this frame loses its claim on the atlas: another light may
    // render into its tiles.
    for (size_t i = 0; i < lightCount; ++i) {
        if (requested[i]) continue;
        previousKeys_[i] = 0;
        previousViews_[i].clear();
        framesWaiting_[i] = 0;
    }
}

void ShadowPass::uploadTables(std::span<const glm::uvec2> lightTable) {
    ensureHostBuffer(context_, views_, planned_.size() * sizeof(GpuShadowView));
    auto* out = static_cast<GpuShadowView*>(views_.mapped());
    for (size_t v = 0; v < planned_.size(); ++v)
        out[v] = planned_[v].gpu;
    ensureHostBuffer(context_, lightTable_, lightTable.size() * sizeof(glm::uvec2));
    std::memcpy(lightTable_.mapped(), lightTable.data(), lightTable.size() * sizeof(glm::uvec2));
}

void ShadowPass::record(VkCommandBuffer cmd, const FrameScene& scene,
                        const SceneResources& resources) {
    const uint32_t size = atlas_.desc().width;
    const bool clearAll = !atlasHoldsMaps_;
    const VkRenderingAttachmentInfo depth =
        renderingAttachment(atlas_.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                            clearAll ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                            VK_ATTACHMENT_STORE_OP_STORE, reverseDepthClear());
    const VkRenderingInfo rendering = renderingInfo(size, size, {}, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    pipeline_.bind(cmd);
    for (const LightPlan& lp : lightPlans_) {
        if (!lp.render) continue;
        for (uint32_t v = lp.firstView; v < lp.firstView + lp.viewCount; ++v) {
            const PlannedView& pv = planned_[v];
            const VkRect2D rect{{int32_t(pv.gpu.tile.x), int32_t(pv.gpu.tile.y)},
                                {uint32_t(pv.gpu.tile.z), uint32_t(pv.gpu.tile.z)}};
            if (!clearAll) {
                VkClearAttachment clear{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}};
                clear.clearValue.depthStencil = {0.0f, 0};
                const VkClearRect clearRect{rect, 0, 1};
                vkCmdClearAttachments(cmd, 1, &clear, 1, &clearRect);
            }
            setViewportAndScissor(cmd, rect);
            drawCasterDepths(cmd, pipeline_, scene, resources, pv.casters, pv.gpu.worldToClip,
                             pv.lods);
        }
    }
    vkCmdEndRendering(cmd);
    atlasHoldsMaps_ = true;
}

std::vector<uint8_t> ShadowPass::lightsWithMaps() const {
    std::vector<uint8_t> mapped(previousKeys_.size(), 0);
    for (const LightPlan& lp : lightPlans_) {
        if (lp.light < mapped.size()) mapped[lp.light] = 1;
    }
    return mapped;
}

std::vector<GpuShadowView> ShadowPass::views() const {
    std::vector<GpuShadowView> out;
    out.reserve(planned_.size());
    for (const PlannedView& v : planned_)
        out.push_back(v.gpu);
    return out;
}

ShadowDescriptors ShadowPass::descriptors(bool enabled) const {
    if (!enabled) {
        return {{pointSampler_.handle(), placeholderAtlas_.view(), kRead},
                {compareSampler_.handle(), placeholderAtlas_.view(), kRead},
                {placeholderBuffer_.handle(), 0, VK_WHOLE_SIZE},
                {placeholderBuffer_.handle(), 0, VK_WHOLE_SIZE}};
    }
    return {{pointSampler_.handle(), atlas_.view(), kRead},
            {compareSampler_.handle(), atlas_.view(), kRead},
            {views_.handle(), 0, VK_WHOLE_SIZE},
            {lightTable_.handle(), 0, VK_WHOLE_SIZE}};
}

}  // namespace candela::render
