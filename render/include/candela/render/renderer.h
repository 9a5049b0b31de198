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
class FrameBlackboard;
class RenderFeature;
class EnvironmentBrdfLut;
class EnvironmentPlaceholders;
class EnvironmentSamplingTable;
class FrameGraph;
class FrameGraphExecutor;
struct ResourceHandle;
class FrameSubmitter;
class LtcTableTexture;
class AreaLightTextures;
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
class TemporalHistory;
class FxaaPass;
class UpscalePass;
class GbaaPass;
class BloomPass;
class ExposureHistogramPass;
class ShadowPass;
class SkyOcclusionPass;
class SkinningPass;
class DebugTextPass;
class TrianglePass;
class NonFinitePass;
struct NonFiniteProbe;

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
    void diagnoseNonFiniteNextFrame() { diagnoseNonFinite_ = true; }

    // RGBA32F scene radiance at the output size (upscaled when the render scale is below 1).
    const GpuImage& hdrTarget() const { return upscalePass_ ? outputHdr_ : hdr_; }
    const GpuImage& ldrTarget() const { return ldr_; }  // RGBA8, sRGB-encoded values
    // With RendererOptions::captureMotionVectors: the last frame's motion vectors, one per pixel
    // row by row (texture-space offset current - previous, motion_vectors.glsl); call once
    // its submission completed. Empty otherwise.
    std::vector<glm::vec2> motionVectors() const;

    // The environment BRDF LUT (eq. 8), built when the first environment was lit; else null.
    const EnvironmentBrdfLut* environmentBrdfLut() const { return brdfLut_.get(); }

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
    void uploadFrameData(const FrameInputs& inputs);
    // TAA after the scene's passes: resolve into the history, copy back into the HDR target.
    uint32_t declareTaa(uint32_t hdrId, uint32_t hdrVersion, float exposure);
    // GBAA after the scene's passes (renderer_gbaa.cpp): resolve across the G-buffer's edges
    // into a transient, copy back into the HDR target.
    uint32_t declareGbaa(uint32_t hdrId, uint32_t hdrVersion);
    // Bloom on the HDR target: the pyramid's passes and the composite (in place).
    uint32_t declareBloom(uint32_t hdrId, uint32_t hdrVersion);
    // Auto exposure: meters last frame's histogram, adapts, and returns this frame's EV100.
    float autoExposureEv100(const FrameInputs& inputs);
    void declareHistogram(uint32_t hdrId, uint32_t hdrVersion);
    // Screen-space reflections after lighting: the Hi-Z pyramid, the trace and the composite
    // into the HDR target; returns its version after the composite.
    // The AO the lighting pass applied to the sky's specular (renderer_frame_handles.h).
    struct SsrOcclusion;
    uint32_t declareSsr(const SceneHandles& h, const EnvironmentDescriptors& environment, bool sky,
                        bool mobileIbl, float skyIntensity, const SsrOcclusion& ao);
    // Light shafts (frames whose scene has an atmosphere, options_.scattering not off): the
    // epipolar passes or the brute-force march over h.hdr, which it advances.
    struct ShadowReads;  // shadow atlas, views, per-light table (renderer_frame_handles.h)
    // `aerialFroxels`: the integrated froxel buffer when blended surfaces or wires need the
    // air's grid there (else null), updated to the version the aerial perspective wrote;
    // `fogBoundaries`: the vec4s of the fog's grid in front of it, after the head (0 when the
    // frame has none there).
    void declareScattering(const FrameInputs& inputs, SceneHandles& h, const ShadowReads& shadows,
                           ResourceHandle* aerialFroxels, uint32_t fogBoundaries);
    // captureMotionVectors: copies the frame's final motion vectors into motionReadback_.
    void declareMotionCapture();
    // Non-finite radiance (renderer_nonfinite.cpp): the frame's count over the HDR target
    // before tonemapping, a diagnosis frame's probes, and reading both after the frame.
    void declareNonFiniteCheck(ResourceHandle hdr);
    void addNonFiniteProbes();
    void collectNonFinite();

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
    GpuBuffer cameraBuffer_;
    std::unique_ptr<GpuLightBuffer> lights_;
    std::unique_ptr<ClusterLightLists> clusters_;  // grid, cluster buffers, assignment
    GpuBuffer pairCounts_;                         // uvec2 per lighting workgroup
    // Motion vectors: each draw's previous world matrix, the previous unjittered
    // view-projection and jitter; TAA: the two history images (read one, write the other).
    GpuBuffer previousWorlds_;
    glm::mat4 previousViewProjection_{1.0f};
    glm::vec2 previousJitter_{0.0f};
    bool hasPreviousFrame_ = false;
    uint32_t frameIndex_ = 0;  // scene frames since creation or resize: the jitter phase
    std::unique_ptr<TemporalHistory> taaHistory_;
    // GTAO's temporal accumulation (ao_temporal.comp): two RGBA32UI histories like TAA's, made
    // only when the options accumulate, and the frame count that rotates GTAO's slices.
    bool aoAccumulates() const;
    std::unique_ptr<TemporalHistory> aoHistory_;
    uint32_t aoFrame_ = 0;
    uint32_t motionId_ = UINT32_MAX;  // this frame's gbuffer.motion in the graph
    uint32_t motionVersion_ = 0;
    GpuBuffer motionReadback_;  // captureMotionVectors: RG16F texels, host-visible
    std::unique_ptr<TaaPass> taaPass_;
    std::unique_ptr<FxaaPass> fxaaPass_;
    std::unique_ptr<UpscalePass> upscalePass_;  // renderScale below 1
    std::unique_ptr<GbaaPass> gbaaPass_;
    uint32_t edgesId_ = UINT32_MAX;  // this frame's gbuffer.edges (--aa gbaa) in the graph
    uint32_t edgesVersion_ = 0;
    std::unique_ptr<BloomPass> bloomPass_;
    std::unique_ptr<ExposureHistogramPass> histogramPass_;
    GpuBuffer histogram_;  // host-visible: read back at the start of the next frame
    bool histogramWritten_ = false;
    std::optional<float> adaptedEv100_;  // unset until the first metered frame
    bool frameRecorded_ = false;
    std::unique_ptr<NonFinitePass> nonFinitePass_;  // made on the first checked frame
    bool nonFiniteChecked_ = false;                 // this frame declared the check
    bool diagnoseNonFinite_ = false;                // the next frame probes its passes
    std::vector<NonFiniteProbe> nonFiniteProbes_;   // this frame's probes (diagnosis)
    std::unique_ptr<TrianglePass> trianglePass_;
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<LightingPass> lightingPass_;
    std::unique_ptr<AmbientOcclusionPass> aoPass_;  // made on the first frame with AO
    std::unique_ptr<SsrPass> ssrPass_;              // made on the first frame with a glossy surface
    bool ssrTraced_ = false;  // this frame declared the SSR trace (its counters)
    // Work the frame's declaration fixed (froxel and volume pairs, AO samples): collectStats
    // adds the passes' counters to it.
    WorkCounters declaredWork_;
    // SSR's temporal filter: two reflection histories like TAA's (made when the options ask
    // for it), the one written last frame and whether it holds a frame.
    std::unique_ptr<TemporalHistory> ssrHistory_;
    std::unique_ptr<VolumetricsPass> volumetricsPass_;  // made on the first frame with a medium
    std::unique_ptr<AtmospherePass> atmospherePass_;    // made on the first frame with a sky
    std::unique_ptr<ScatteringPass> scatteringPass_;    // made on the first frame with shafts
    bool scatteringMarched_ = false;  // this frame declared light shafts (their counters)
    std::unique_ptr<ForwardTransparentPass> transparentPass_;
    // The techniques that own themselves (features/render_feature.h), in frame order, and
    // which of them the last declared frame declared.
    std::vector<std::unique_ptr<RenderFeature>> renderFeatures_;
    std::vector<bool> featureDeclared_;
    std::unique_ptr<FrameBlackboard> board_;
    std::unique_ptr<TonemapPass> tonemapPass_;
    std::unique_ptr<ShadowPass> shadowPass_;
    std::unique_ptr<SkyOcclusionPass> skyOcclusionPass_;
    std::unique_ptr<SkinningPass> skinningPass_;    // made on the first frame with animation
    std::unique_ptr<DebugTextPass> debugTextPass_;  // made on the first frame with text
    std::unique_ptr<EnvironmentBrdfLut> brdfLut_;
    std::unique_ptr<EnvironmentPlaceholders> environmentPlaceholders_;
    std::unique_ptr<LtcTableTexture> ltcTable_;  // area lights (lights/ltc_table_texture.h)
    std::unique_ptr<AreaLightTextures> areaLightTextures_;  // textured rects' images
    std::unique_ptr<EnvironmentSamplingTable> samplingTable_;
    std::vector<std::string> features_;
    RendererStats stats_;
};

// Exposure scale for an EV100 (the same formula the shaders use).
float exposureFromEv100(float ev100);

}  // namespace candela::render
