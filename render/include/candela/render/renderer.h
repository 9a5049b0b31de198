#pragma once
// Assembles each frame as a frame graph of only the passes its scene needs and runs it: the lit
// scene's maps and cluster lists, the G-buffer, deferred lighting, the features that own
// themselves (AO, SSR, media, hair, wires, TAA, bloom...), blended surfaces and the output
// stage (tonemap, FXAA, text). The graph orders the passes and places every barrier; the
// frame's full order is in render/README.md, "Frame".
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "candela/render/frame_inputs.h"
#include "candela/render/frame_target_use.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "candela/render/renderer_options.h"

namespace candela::render {

struct DeclaredFrame;
class FeatureList;
class ForwardTransparentPass;
class FrameGraph;
class FrameGraphExecutor;
class FrameSubmitter;
class EnvironmentBrdfLut;
class GBufferPass;
class GpuContext;
class LightingPass;
class LitScene;
class NonFiniteGuard;
class OutputStage;
class SceneResources;
class TrianglePass;
struct ResourceHandle;
struct SceneHandles;  // renderer.cpp
struct WorldBounds;

// A pass recorded after tonemapping by someone outside the renderer (runtime FrameLayers: the
// editor's UI, the stats overlay). The graph orders it after the passes that wrote what it
// uses, places its barriers, and hands `record` the frame's command buffer with each target in
// targetLayout(use).
struct ExtraPass {
    std::string name;
    std::vector<TargetAccess> uses;
    std::function<void(VkCommandBuffer)> record;
};

class Renderer {
public:
    Renderer(GpuContext& context, uint32_t width, uint32_t height,
             const RendererOptions& options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Output size: the targets read after the frame (hdrTarget, ldrTarget, captures, the
    // swapchain blit). The scene renders at renderWidth x renderHeight (options().renderScale).
    void resize(uint32_t width, uint32_t height);
    uint32_t width() const { return targets_.outputWidth; }
    uint32_t height() const { return targets_.outputHeight; }
    uint32_t renderWidth() const { return targets_.width; }
    uint32_t renderHeight() const { return targets_.height; }
    // The size a scene renders at for an output size and scale: each side rounded, at least 1.
    static uint32_t scaledSize(uint32_t outputSize, float scale);
    // Why this device cannot hold a frame of this output size (empty when it can): a side past
    // maxImageDimension2D, an RGBA32F target past the format's maxResourceSize, or the
    // targets every frame needs (kMinimumBytesPerPixel) past the largest device-local heap.
    // Checked before a renderer is made, so a bad --size is refused up front.
    static constexpr uint64_t kMinimumBytesPerPixel = 40;
    static std::string outputSizeProblem(const GpuContext& context, uint32_t width,
                                         uint32_t height);
    const RendererOptions& options() const { return options_; }
    // Whether the next frames count their light evaluations and shadow taps (stats' `work`):
    // the counting variant of the lighting pass costs it a fifth more on lavapipe (runtime's
    // --stats-work last counts a run's last frame only).
    void setCountLightPairs(bool count) { options_.countLightPairs = count; }

    // Records the frame's passes. Clustered lighting with CPU assignment submits the geometry
    // part and waits for it (assignment reads the depth occupancy on the CPU), then begins a
    // new command buffer; device assignment records everything into one. Returns the open command
    // buffer holding the rest of the frame: the caller may append (capture copy, swapchain blit)
    // and submits it. Afterwards both targets are in TRANSFER_SRC_OPTIMAL. `resources` holds what
    // the draws refer to (null: no meshes). `extraPasses` run after tonemapping, in order.
    VkCommandBuffer recordFrame(FrameSubmitter& submitter, const FrameInputs& inputs,
                                SceneResources* resources,
                                std::span<const ExtraPass> extraPasses = {});

    // The layout a target is in while an ExtraPass uses it so.
    static VkImageLayout targetLayout(TargetUse use);

    // A cut: the next frame starts TAA's history and jitter sequence afresh, has no motion from
    // the previous camera, and meters its exposure without adapting from the old one. Call
    // when the scene was replaced or changed at once (an editor's edit).
    void restartTemporalHistory();

    // Reads the GPU-side measurements of the last frame; call once its submission completed.
    const RendererStats& collectStats();

    // The next frame probes every float image each pass writes for NaN and Inf, and its
    // stats name the first pass that wrote one (RendererStats::nonFiniteSource). Call after a
    // frame whose nonFinitePixels was not 0; it costs a pass per probed image.
    void diagnoseNonFiniteNextFrame();

    // RGBA32F scene radiance at the output size (upscaled when the render scale is below 1).
    const GpuImage& hdrTarget() const;
    const GpuImage& ldrTarget() const { return targets_.ldr; }  // RGBA8, sRGB-encoded values
    // With RendererOptions::captureMotionVectors: the last frame's motion vectors, one per pixel
    // row by row (texture-space offset current - previous, motion_vectors.glsl); call once
    // its submission completed. Empty otherwise.
    std::vector<glm::vec2> motionVectors() const;

    // The environment BRDF LUT (eq. 8), built when the first environment was lit; else null.
    const EnvironmentBrdfLut* environmentBrdfLut() const;

    // What this renderer enabled for the last recorded frame, for --stats.
    std::vector<std::string> features() const;

    // The last frame's compiled graph as Graphviz (--frame-graph FILE.dot).
    std::string frameGraphDot() const;

    // Where clustered lists are built for `options` on this device (Auto resolved).
    static LightAssignmentDevice resolveLightAssignment(const RendererOptions& options,
                                                        const GpuContext& context);

private:
    // The frame-persistent targets (renderer_targets.cpp).
    struct Targets {
        uint32_t outputWidth = 0, outputHeight = 0;  // hdrTarget, ldrTarget, captures
        uint32_t width = 0, height = 0;              // the render size: every scene pass's
        GpuImage hdr;                                // at the render size
        GpuImage outputHdr;        // at the output size, when the render size differs (else empty)
        GpuImage ldr;              // at the output size
        GpuBuffer pairCounts;      // uvec2 per lighting workgroup (the counting variant)
        GpuBuffer motionReadback;  // captureMotionVectors: RG16F texels, host-visible
    };
    void createTargets();
    // Declare the frame's passes; return the HDR target's last version.
    uint32_t declareScene(const FrameInputs& inputs, SceneResources& resources, uint32_t hdr);
    // The draws the camera sees, each at its level of detail (kDrawCulled: none).
    std::vector<uint8_t> visibleDraws(const FrameInputs& inputs, const SceneResources& resources,
                                      std::span<const WorldBounds> drawBounds);
    SceneHandles createGBufferTargets(FrameGraph& g, bool extended, uint32_t hdr);
    void declareGBuffer(SceneHandles& h, const FrameInputs& inputs, SceneResources& resources,
                        ResourceHandle deformed);
    void declareLighting(SceneHandles& h, const FrameInputs& inputs, ResourceHandle pairCounts);
    void declareTransparency(SceneHandles& h, SceneResources& resources, ResourceHandle deformed);
    // captureMotionVectors: copies the frame's final motion vectors into motionReadback.
    void declareMotionCapture(ResourceHandle motion);

    GpuContext& context_;
    RendererOptions options_;
    Targets targets_;
    std::unique_ptr<FrameGraph> graph_;
    std::unique_ptr<FrameGraphExecutor> executor_;
    std::unique_ptr<LitScene> lit_;  // camera, lights, clusters, shadows, sky: the lit inputs
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<LightingPass> lightingPass_;
    std::unique_ptr<ForwardTransparentPass> transparentPass_;
    // The techniques that own themselves (features/render_feature.h), in frame order.
    std::unique_ptr<FeatureList> features_;
    std::unique_ptr<OutputStage> output_;  // upscale, tonemap, FXAA, debug text
    std::unique_ptr<TrianglePass> trianglePass_;
    std::unique_ptr<NonFiniteGuard> nonFinite_;  // NaN/Inf count, diagnosis probes
    std::unique_ptr<DeclaredFrame> frame_;       // what the last frame declared and drew
    RendererStats stats_;
};

// Exposure scale for an EV100 (the same formula the shaders use).
float exposureFromEv100(float ev100);

}  // namespace candela::render
