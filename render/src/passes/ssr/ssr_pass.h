#pragma once
// Screen-space reflections by Hi-Z tracing (Uludag 2014, GPU Pro 5, "Hi-Z Screen-Space Cone-Traced
// Reflections"; render/README.md "Screen-space reflections"): a Hi-Z pyramid of the G-buffer depth,
// one ray per glossy pixel (Hi-Z or the linear reference march), and a composite that replaces the
// environment's split-sum specular by the reflection in proportion to its confidence.
#include <cstdint>
#include <optional>

#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
struct EnvironmentDescriptors;

class SsrPass {
public:
    explicit SsrPass(GpuContext& context);

    // Levels of the Hi-Z pyramid of a width x height frame: sizes halve rounding up down to 1x1.
    static uint32_t levelCount(uint32_t width, uint32_t height);
    // RGBA32F holding every level (ssr_levels.glsl): level 0 at the origin, the others in a
    // column to its right, each below the one before; nearest depth in r, farthest in g.
    static ImageDesc pyramidDesc(uint32_t width, uint32_t height);
    // R32F pre-integrated visibility of each cell in the same layout.
    static ImageDesc visibilityDesc(uint32_t width, uint32_t height);
    // RGBA16F pre-convolved scene in the same layout.
    static ImageDesc colorDesc(uint32_t width, uint32_t height);
    // RGBA32F: what the trace adds to each pixel (rgb) and its confidence (a).
    static ImageDesc reflectionDesc(uint32_t width, uint32_t height);
    // The temporal filter's history: a reflection image that starts cleared (transfer dst).
    static ImageDesc historyDesc(uint32_t width, uint32_t height);

    // Level `level` of the pyramid from `depth` (level 0) or the level below it.
    void recordHiz(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& depth,
                   const ImageRef& pyramid, uint32_t level, uint32_t width, uint32_t height) const;

    // Level `level` of the pre-convolved scene from `hdr` (level 0) or the level below it.
    void recordColor(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& hdr,
                     const ImageRef& colors, uint32_t level, uint32_t width, uint32_t height) const;

    // Level `level` of the pre-integrated visibility from the pyramid's levels `level` and
    // `level` - 1 and the visibility of the latter (level 0: 100%).
    void recordVisibility(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& pyramid,
                          const ImageRef& visibility, uint32_t level, uint32_t width,
                          uint32_t height) const;

    struct TraceInputs {
        const GpuBuffer* camera;
        ImageRef normalRoughMetal, baseColor, specularModel;  // Sampled
        ImageRef pyramid;                                     // StorageRead
        ImageRef visibility;                                  // StorageRead: pre-integrated
        ImageRef colors;                                      // StorageRead: pre-convolved
        const EnvironmentDescriptors* environment;
        bool hasEnvironment = false;  // take the sky's split-sum specular out where rays hit
        // Weight by the LUT, else by Karis 2014's fit ("Physically Based Shading on Mobile").
        bool hasLut = false;
        // The ambient occlusion the lighting pass applied to the sky's specular (Sampled; unset
        // without it) and its variant (lighting.comp's kAoMode) and intensity.
        std::optional<ImageRef> ambientOcclusion, specularOcclusion;
        uint32_t aoMode = 0;
        float aoIntensity = 1.0f;
        float skyIntensity = 1.0f;
        SsrMode mode = SsrMode::Hiz;
        SsrSettings settings;
        uint32_t width = 0, height = 0;
    };
    void recordTrace(VkCommandBuffer cmd, const TraceInputs& in, const ImageRef& reflection) const;
    // Temporal filtering: `current` (the trace's), `motion` and last frame's `history`
    // (Sampled) into `filtered` (StorageWrite, next frame's history).
    void recordTemporal(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& current,
                        const ImageRef& motion, const ImageRef& history, bool historyValid,
                        float blend, const ImageRef& filtered) const;
    void recordComposite(VkCommandBuffer cmd, const GpuBuffer& camera, const ImageRef& reflection,
                         const ImageRef& hdr) const;

    // Host-visible counters the trace adds to (cleared by recordClearCounters each frame).
    GpuBuffer& counters() { return counters_; }
    void recordClearCounters(VkCommandBuffer cmd) const;
    struct Counts {
        uint64_t steps = 0;
        uint32_t maxSteps = 0;
        uint32_t hits = 0;
        uint32_t rays = 0;
    };
    Counts readCounters() const;

private:
    Pipeline hiz_;
    Pipeline color_;
    Pipeline visibility_;
    Pipeline trace_;
    Pipeline temporal_;
    Pipeline composite_;
    Sampler pointSampler_;
    GpuBuffer counters_;
};

}  // namespace candela::render
