#include "lit_scene.h"

#include <cstdio>

#include "candela/render/frame_inputs.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_light_lists.h"
#include "culling/draw_bounds.h"
#include "features/frame_blackboard.h"
#include "frame_camera.h"
#include "frame_graph/frame_graph_executor.h"
#include "gpu_camera.h"
#include "lights/area_light_textures.h"
#include "lights/gpu_light_buffer.h"
#include "lights/gpu_light_types.h"
#include "passes/atmosphere/atmosphere_pass.h"
#include "passes/shadows/shadow_frame.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/sky_occlusion/sky_occlusion_pass.h"
#include "renderer_scene_queries.h"
#include "shading_tables.h"

namespace candela::render {

LitScene::LitScene(GpuContext& context, const RendererOptions& options)
    : context_(context),
      options_(options),
      camera_(std::make_unique<FrameCamera>(context)),
      lights_(std::make_unique<GpuLightBuffer>()),
      clusters_(std::make_unique<ClusterLightLists>(
          context, options, Renderer::resolveLightAssignment(options, context))),
      shadows_(std::make_unique<ShadowPass>(context)),
      skyOcclusion_(std::make_unique<SkyOcclusionPass>(context)),  // pipeline when used
      tables_(std::make_unique<ShadingTables>(context)) {}

LitScene::~LitScene() {
    tables_.reset();  // before the passes whose placeholders it may describe
}

LightingFeatures LitScene::prepare(FrameGraph& g, const FrameInputs& inputs,
                                   SceneResources& resources,
                                   std::span<const WorldBounds> drawBounds, uint32_t width,
                                   uint32_t height, RendererStats& stats) {
    // The atmosphere's tables come first; its sky cube is the environment the frame lights with.
    if (inputs.scene.atmosphere) {
        if (!atmosphere_)
            atmosphere_ = std::make_unique<AtmospherePass>(context_, options_.atmosphere);
        atmosphere_->declareTables(g, AtmospherePass::frameOf(inputs.scene));
        resources.setEnvironment(atmosphere_->environment());
    }
    LightingFeatures features = featuresOf(inputs.scene, resources, options_);
    // The reference samples the sky by a luminance table read back from its cube; the
    // atmosphere's first cube is rendered in this frame, so that frame lights by the split
    // sum and the reference starts with the next one.
    if (features.ibl == IblMode::Reference && atmosphere_ && inputs.scene.atmosphere &&
        !atmosphere_->environmentReadable()) {
        features.ibl = IblMode::SplitSum;
        std::fprintf(stderr,
                     "note: --ibl reference starts on the second frame: the atmosphere's sky "
                     "cube is rendered in the first\n");
    }
    // Shadow maps for the lights that cast; none, and the variant leaves shadows out.
    features.shadows =
        shadows_->prepare(inputs.scene, resources, drawBounds, options_, width, height);
    for (const LightInstance& l : inputs.scene.lights) {
        if (!features.shadows || !l.light.castShadows) continue;
        (inEveryCluster(l.light) ? features.directionalShadows : features.localShadows) = true;
    }
    features.lightLoops =
        lightLoopsFor(inputs.scene.lights, shadows_->lightsWithMaps(), features.clustered);
    // Sky occlusion's maps: rendered when the static casters change, else kept.
    const SkyOcclusionMode skyOcclusion = options_.skyOcclusion == SkyOcclusionMode::Off &&
                                                  options_.skyOcclusionWithAtmosphere &&
                                                  inputs.scene.atmosphere
                                              ? SkyOcclusionMode::On
                                              : options_.skyOcclusion;
    if (skyOcclusion != SkyOcclusionMode::Off && features.ibl) {
        features.skyOcclusion = skyOcclusion_->prepare(inputs.scene, resources, skyOcclusion);
    }
    tables_->prepare(features, resources, stats);
    return features;
}

void LitScene::upload(const FrameInputs& inputs, const LightingFeatures& features, uint32_t width,
                      uint32_t height) {
    const FrameScene& scene = inputs.scene;
    // Textured rects' images first: a changed atlas moves slots, so every light is repacked.
    AreaLightTextures& areaLightTextures = tables_->areaLightTextures();
    const bool texturesMoved = areaLightTextures.update(context_, scene.lights);
    lights_->update(context_, scene.lights, scene.changedLights,
                    scene.lightsRestructured || texturesMoved, &areaLightTextures);
    clusters_->setView(scene.camera, width, height);
    camera_->upload(scene, {width, height, lights_->count(), lights_->capacity(),
                            options_.aa == AntiAliasing::Taa});
    // The camera block carries sky occlusion's sphere and layout.
    GpuCamera* camera = static_cast<GpuCamera*>(camera_->buffer().mapped());
    camera->skyOcclusionSphere = features.skyOcclusion ? skyOcclusion_->sphere() : glm::vec4(0.0f);
    camera->skyOcclusionLayout = features.skyOcclusion ? skyOcclusion_->layout() : glm::uvec4(0u);
    if (!features.clustered) clusters_->usePlaceholders();
}

void LitScene::collectFrameStats(RendererStats& stats, WorkCounters& work) const {
    stats.lights = lights_->count();
    stats.lightsRewritten = lights_->rewrittenLastUpdate();
    stats.lightAssignMs = 0.0;
    stats.shadowedLights = shadows_->stats().shadowedLights;
    stats.shadowMapsRendered = shadows_->stats().mapsRendered;
    stats.shadowMapsCached = shadows_->stats().mapsCached;
    stats.shadowMapsKept = shadows_->stats().mapsKept;
    stats.shadowAtlasUsed = shadows_->stats().atlasUsed;
    stats.shadowCasterDraws = shadows_->stats().casterDraws;
    work.shadowTriangles = shadows_->stats().casterTriangles;
}

LitScene::Buffers LitScene::importBuffers(FrameGraph& g) const {
    return {g.importBuffer("camera", &camera_->buffer()),
            g.importBuffer("lights", &lights_->buffer())};
}

LitScene::Maps LitScene::declareMaps(FrameGraph& g, const FrameInputs& inputs,
                                     SceneResources& resources, const LightingFeatures& features,
                                     ResourceHandle deformed, RendererStats& stats) {
    // Shadows: the atlas keeps its maps between frames (cached tiles), read-only between uses.
    Maps maps;
    if (features.shadows) {
        constexpr ImageState kShadowRead{
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        maps.shadowAtlas =
            g.importImage("shadow_atlas", &shadows_->atlas(),
                          shadows_->atlasHoldsMaps() ? kShadowRead : ImageState{}, kShadowRead);
        maps.shadowViews = g.importBuffer("shadow_views", &shadows_->viewBuffer());
        maps.shadowLights = g.importBuffer("shadow_lights", &shadows_->lightBuffer());
        if (shadows_->rendersThisFrame()) {
            auto p = g.addPass("shadows", PassKind::Device,
                               [this, &inputs, &resources](PassContext& ctx) {
                                   shadows_->record(ctx.cmd(), inputs.scene, resources);
                               });
            if (deformed.valid()) p.read(deformed, Use::VertexInput);
            maps.shadowAtlas = p.write(maps.shadowAtlas, Use::DepthWrite);
        }
    }
    stats.skyOcclusionRebuilt = false;
    if (features.skyOcclusion) {
        constexpr ImageState kSkyRead{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        maps.skyOcclusionAtlas =
            g.importImage("sky_occlusion_atlas", &skyOcclusion_->atlas(),
                          skyOcclusion_->atlasHoldsMaps() ? kSkyRead : ImageState{}, kSkyRead);
        if (skyOcclusion_->rendersThisFrame()) {
            stats.skyOcclusionRebuilt = true;
            auto p = g.addPass("sky_occlusion", PassKind::Device,
                               [this, &inputs, &resources](PassContext& ctx) {
                                   skyOcclusion_->record(ctx.cmd(), inputs.scene, resources);
                               });
            maps.skyOcclusionAtlas = p.write(maps.skyOcclusionAtlas, Use::DepthWrite);
        }
    }
    return maps;
}

void LitScene::declareClusters(FrameGraph& g, const FrameInputs& inputs, SceneResources& resources,
                               const LightingFeatures& features, Buffers buffers, const Maps& maps,
                               ResourceHandle depth, ForwardTransparentPass* blended,
                               ResourceHandle deformed, FrameBlackboard& board,
                               RendererStats& stats) {
    ClusterLightLists::Lists clusters;
    if (features.clustered) {
        clusters = clusters_->declare(
            g,
            {&inputs, depth, buffers.camera, buffers.lights, &camera_->buffer(), &lights_->buffer(),
             lights_->count(), lights_->capacity(), blended, &resources, deformed},
            stats);
    }
    // What every lit pass reads beside its own inputs (the lighting pass in its compute stage,
    // hair, wires and blended surfaces in their fragment stage).
    const LitInputHandles reads{
        buffers.camera,        buffers.lights,        features.clustered, clusters,
        features.shadows,      maps.shadowAtlas,      maps.shadowViews,   maps.shadowLights,
        features.skyOcclusion, maps.skyOcclusionAtlas};
    const LitInputs lit{&camera_->buffer(),
                        &lights_->buffer(),
                        clusters_.get(),
                        tables_->describe(features, resources),
                        inputs.scene.skyIntensity,
                        shadows_->descriptors(features.shadows),
                        skyOcclusion_->descriptor(features.skyOcclusion)};
    if (features.shadows) {
        board.put(
            ShadowFrame{shadows_.get(), maps.shadowAtlas, maps.shadowViews, maps.shadowLights});
    }
    board.put(
        LitFrame{lit, reads, lights_->count(), lights_->capacity(), tables_->brdfLut() != nullptr});
}

ResourceHandle LitScene::declareSky(FrameGraph& g, const FrameInputs& inputs, ResourceHandle camera,
                                    ResourceHandle depth, ResourceHandle hdr,
                                    std::vector<std::string>& features) {
    if (!inputs.scene.atmosphere) return hdr;
    features.push_back("atmosphere");
    return atmosphere_->declareBackground(g, camera, depth, hdr, camera_->buffer());
}

void LitScene::restart() {
    camera_->restart();
}

}  // namespace candela::render
