#pragma once
// Shadow maps for every light that casts (render/README.md "Shadows"): plans each frame's
// views (four cascades per directional light, one view per spot, six cube faces per point,
// sphere or tube light), packs them as tiles of one depth atlas sized by each light's
// projected size and importance, renders the tiles whose light or casters changed (the rest
// are cached from earlier frames) and gives the lighting and forward passes what they read:
// the atlas, the views and a per-light table indexed like the light buffer.
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "culling/draw_bounds.h"
#include "passes/shadows/shadow_descriptors.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
class SceneResources;
struct ShadowRenderCandidate;
struct ShadowTile;
struct ShadowTileRequest;
enum class ShadowRenderChoice;

// std430 record of one view (ShadowView in common/shadows.glsl).
struct GpuShadowView {
    glm::mat4 worldToClip;
    glm::vec4 tile;    // first texel x, y in the atlas; size in texels; 0
    glm::vec4 params;  // texel metres (per metre of depth: perspective); SHADOW_KIND_*; near; far
    glm::vec4 sphere;  // cascades: centre and radius of what they cover
};
static_assert(sizeof(GpuShadowView) == 112, "std430 layout of ShadowView");

struct ShadowFrameStats {
    uint32_t shadowedLights = 0;
    uint32_t mapsRendered = 0;     // lights whose maps were rendered this frame
    uint32_t mapsCached = 0;       // lights whose maps were kept from an earlier frame
    uint32_t mapsKept = 0;         // lights that changed but kept stale maps (render budget spent)
    double atlasUsed = 0.0;        // share of the atlas's texels in tiles
    uint32_t casterDraws = 0;      // draws recorded into the maps rendered this frame
    uint64_t casterTriangles = 0;  // their triangles, at their levels of detail
};

class ShadowPass {
public:
    explicit ShadowPass(GpuContext& context);
    ~ShadowPass();
    ShadowPass(const ShadowPass&) = delete;
    ShadowPass& operator=(const ShadowPass&) = delete;

    // Plans the frame's maps and writes the view and per-light tables; false when no light
    // casts (the shading variant without shadows, nothing else to declare). `bounds`: every
    // draw's world box (worldBoundsOf), which casters are fitted and culled by.
    bool prepare(const FrameScene& scene, const SceneResources& resources,
                 std::span<const WorldBounds> bounds, const RendererOptions& options,
                 uint32_t width, uint32_t height);
    // Some tile needs rendering this frame (else the pass is not declared).
    bool rendersThisFrame() const { return rendersThisFrame_; }
    // Frame graph use: the atlas DepthWrite.
    void record(VkCommandBuffer cmd, const FrameScene& scene, const SceneResources& resources);

    const GpuImage& atlas() const { return atlas_; }
    const GpuBuffer& viewBuffer() const { return views_; }
    const GpuBuffer& lightBuffer() const { return lightTable_; }
    // The atlas holds maps from an earlier frame (its import keeps them).
    bool atlasHoldsMaps() const { return atlasHoldsMaps_; }
    ShadowDescriptors descriptors(bool enabled) const;
    const ShadowFrameStats& stats() const { return stats_; }
    // Per light slot of the last prepare(): 1 where the light has a map this frame.
    std::vector<uint8_t> lightsWithMaps() const;
    // This frame's views as viewBuffer() holds them (the hair depth map draws into each).
    std::vector<GpuShadowView> views() const;

private:
    struct PlannedView {
        GpuShadowView gpu;
        uint32_t light;
        std::vector<uint32_t> casters;  // draw indices
        std::vector<uint8_t> lods;      // each caster's level of detail in this view
    };
    struct LightPlan {
        uint32_t light;
        uint32_t firstView;
        uint32_t viewCount;
        bool render;
        uint32_t request;  // index of its MapRequest (and of its render choice and key)
    };

    // One light's maps this frame.
    struct MapRequest {
        uint32_t light;  // slot in the frame's lights
        uint32_t views;
        bool cascade;  // a directional light's cascades (else a spot view or cube faces)
    };
    // What every view of a frame is planned from.
    struct ViewInputs {
        const FrameScene& scene;
        const SceneResources& resources;
        std::span<const WorldBounds> bounds;
        const RendererOptions& options;
        std::span<const uint32_t> casters;  // draw indices that cast
    };

    void ensureAtlas(uint32_t size);

    // prepare()'s steps, in order. Every shadow-casting light's request and its tiles.
    static void requestMaps(const FrameScene& scene, const RendererOptions& options, uint32_t width,
                            uint32_t height, std::vector<MapRequest>& requests,
                            std::vector<ShadowTileRequest>& tiles);
    // Appends the light's views to planned_ and returns the key of what they render.
    uint64_t planLightViews(const ViewInputs& in, const MapRequest& request,
                            std::span<const ShadowTile> tiles);
    // Fill in a view whose tile is set: its projection, casters and their levels of detail
    // (a directional light's cascade; a spot view or cube face).
    static void planCascadeView(const ViewInputs& in, const LightInstance& instance,
                                uint32_t cascades, uint32_t cascade, const ShadowTile& tile,
                                PlannedView& pv);
    static void planLocalView(const ViewInputs& in, const LightInstance& instance, uint32_t view,
                              const ShadowTile& tile, PlannedView& pv);
    // `key` extended by what the view's map is rendered from (its record and casters).
    uint64_t viewKey(const PlannedView& pv, const FrameScene& scene, uint64_t key) const;
    // What the render budget weighs for a light whose views were just planned.
    ShadowRenderCandidate renderCandidate(const MapRequest& request,
                                          std::span<const ShadowTile> tiles, uint32_t firstView,
                                          uint64_t key, float priority,
                                          const RendererOptions& options) const;
    // Per light plan (choices and keys indexed by its request): render, cache or keep stale maps.
    void applyRenderChoices(std::span<const ShadowRenderChoice> choices,
                            std::span<const uint64_t> keys, const FrameScene& scene,
                            const SceneResources& resources);
    // A rendered light's key and views, which later frames compare against and keep.
    void rememberViews(const LightPlan& lp, uint64_t key);
    // Adds a rendered light's caster draws and triangles to stats_.
    void countCasters(const LightPlan& lp, const FrameScene& scene,
                      const SceneResources& resources);
    // Forgets the maps of light slots without a plan this frame.
    void releaseUnplannedLights(size_t lightCount);
    // Writes planned_'s records to views_ and the per-light table to lightTable_.
    void uploadTables(std::span<const glm::uvec2> lightTable);

    GpuContext& context_;
    Pipeline pipeline_;
    Sampler pointSampler_;
    Sampler compareSampler_;
    GpuImage atlas_;
    GpuImage placeholderAtlas_;
    GpuBuffer placeholderBuffer_;
    GpuBuffer views_;
    GpuBuffer lightTable_;
    bool atlasHoldsMaps_ = false;
    bool rendersThisFrame_ = false;
    std::vector<PlannedView> planned_;
    std::vector<LightPlan> lightPlans_;
    std::vector<uint64_t> previousKeys_;  // per light slot: what its maps were rendered from
    std::vector<std::vector<GpuShadowView>> previousViews_;  // per light slot: those views
    std::vector<uint32_t> framesWaiting_;  // per light slot: frames it kept stale maps
    uint64_t frameCounter_ = 0;            // prepare() calls (animated casters' key)
    ShadowFrameStats stats_;
};

}  // namespace candela::render
