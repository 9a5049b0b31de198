#pragma once
// Assembles each frame as a frame graph from the scene's features and runs it:
//   G-buffer (+ emissive) -> depth occupancy -> light assignment (CPU or compute) ->
//   clustered deferred lighting -> forward transparency (blended draws only) -> exposure +
//   tonemap. The graph orders the passes and places every barrier (render/README.md).
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

class ClusterLightLists;
class ForwardTransparentPass;
class AutoExposureFeature;
class FrameBlackboard;
class FrameCamera;
struct FeatureFrame;
enum class FeatureRun : uint8_t;
class RenderFeature;
class EnvironmentBrdfLut;
class FrameGraph;
class FrameGraphExecutor;
struct ResourceHandle;
class FrameSubmitter;
class ShadingTables;
class GBufferPass;
class GpuContext;
class GpuLightBuffer;
class LightingPass;
class AmbientOcclusionPass;
class AtmospherePass;
class SsrPass;
struct EnvironmentDescriptors;
class VolumetricsPass;
class ScatteringPass;
class SceneResources;
class TonemapPass;
class TaaPass;
class FxaaPass;
class UpscalePass;
class GbaaPass;
class BloomPass;
class ExposureHistogramPass;
class ShadowPass;
class SkyOcclusionPass;
class DebugTextPass;
class TrianglePass;
class NonFiniteGuard;

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
    uint32_t width() const { return outputWidth_; }
    uint32_t height() const { return outputHeight_; }
    uint32_t renderWidth() const { return width_; }
    uint32_t renderHeight() const { return height_; }
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
    const GpuImage& hdrTarget() const { return upscalePass_ ? outputHdr_ : hdr_; }
    const GpuImage& ldrTarget() const { return ldr_; }  // RGBA8, sRGB-encoded values
    // With RendererOptions::captureMotionVectors: the last frame's motion vectors, one per pixel
    // row by row (texture-space offset current - previous, motion_vectors.glsl); call once
    // its submission completed. Empty otherwise.
    std::vector<glm::vec2> motionVectors() const;

    // The environment BRDF LUT (eq. 8), built when the first environment was lit; else null.
    const EnvironmentBrdfLut* environmentBrdfLut() const;

    // What this renderer enabled for the last recorded frame, for --stats.
    std::vector<std::string> features() const { return features_; }

    // The last frame's compiled graph as Graphviz (--frame-graph FILE.dot).
    std::string frameGraphDot() const;

    // Where clustered lists are built for `options` on this device (Auto resolved).
    static LightAssignmentDevice resolveLightAssignment(const RendererOptions& options,
                                                        const GpuContext& context);

private:
    void createTargets();
    struct SceneHandles;
    // Declare the frame's passes; return the HDR target's last version.
    uint32_t declareScene(const FrameInputs& inputs, SceneResources& resources, uint32_t hdr);
    // Features are declared in runs (FeatureRun), in the order they were added; in a run the
    // active ones declare their passes, the others restart their history.
    void addFeature(FeatureRun run, std::unique_ptr<RenderFeature> feature);
    void declareRun(FeatureFrame& frame, FeatureRun run);
    void uploadFrameData(const FrameInputs& inputs);
    // captureMotionVectors: copies the frame's final motion vectors into motionReadback_.
    void declareMotionCapture(ResourceHandle motion);

    GpuContext& context_;
    RendererOptions options_;
    uint32_t outputWidth_;
    uint32_t outputHeight_;
    uint32_t width_;  // the render size: every scene pass's
    uint32_t height_;
    LightAssignmentDevice lightAssignment_;  // options_.lightAssignment resolved
    GpuImage hdr_;                           // at the render size
    GpuImage outputHdr_;                     // at the output size, when upscalePass_ (else empty)
    GpuImage ldr_;                           // at the output size
    std::unique_ptr<FrameGraph> graph_;
    std::unique_ptr<FrameGraphExecutor> executor_;
    std::unique_ptr<FrameCamera> camera_;  // the camera block and last frame's matrices
    std::unique_ptr<GpuLightBuffer> lights_;
    std::unique_ptr<ClusterLightLists> clusters_;  // grid, cluster buffers, assignment
    GpuBuffer pairCounts_;                         // uvec2 per lighting workgroup
    // Motion vectors: each draw's previous world matrix, the previous unjittered
    // view-projection and jitter; TAA: the two history images (read one, write the other).
    // GTAO's temporal accumulation (ao_temporal.comp): two RGBA32UI histories like TAA's, made
    // only when the options accumulate, and the frame count that rotates GTAO's slices.
    GpuBuffer motionReadback_;  // captureMotionVectors: RG16F texels, host-visible
    std::unique_ptr<FxaaPass> fxaaPass_;
    std::unique_ptr<UpscalePass> upscalePass_;  // renderScale below 1
    enum class RecordedFrame : uint8_t { None, TestTriangle, Scene };
    RecordedFrame recorded_ = RecordedFrame::None;  // what the last recordFrame drew
    std::unique_ptr<NonFiniteGuard> nonFinite_;     // NaN/Inf count, diagnosis probes
    std::unique_ptr<TrianglePass> trianglePass_;
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<LightingPass> lightingPass_;
    // Work the frame's declaration fixed (froxel and volume pairs, AO samples): collectStats
    // adds the passes' counters to it.
    WorkCounters declaredWork_;
    // SSR's temporal filter: two reflection histories like TAA's (made when the options ask
    // for it), the one written last frame and whether it holds a frame.
    std::unique_ptr<AtmospherePass> atmospherePass_;  // made on the first frame with a sky
    std::unique_ptr<ForwardTransparentPass> transparentPass_;
    // The techniques that own themselves (features/render_feature.h), in frame order, and
    // which of them the last declared frame declared.
    std::vector<std::unique_ptr<RenderFeature>> renderFeatures_;
    std::vector<bool> featureDeclared_;
    std::vector<FeatureRun> featureRuns_;          // each feature's run
    AutoExposureFeature* autoExposure_ = nullptr;  // one of them: the frame's exposure
    std::unique_ptr<FrameBlackboard> board_;
    std::unique_ptr<TonemapPass> tonemapPass_;
    std::unique_ptr<ShadowPass> shadowPass_;
    std::unique_ptr<SkyOcclusionPass> skyOcclusionPass_;
    std::unique_ptr<DebugTextPass> debugTextPass_;  // made on the first frame with text
    std::unique_ptr<ShadingTables>
        shadingTables_;  // LUT, LTC table, rect textures, sky placeholders
    std::vector<std::string> features_;
    RendererStats stats_;
};

// Exposure scale for an EV100 (the same formula the shaders use).
float exposureFromEv100(float ev100);

}  // namespace candela::render
