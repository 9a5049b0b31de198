#pragma once
// Ambient occlusion of the sky's light from the G-buffer (render/README.md "Ambient
// occlusion"): GTAO (horizon search + depth-aware denoise) or the ray-marched reference, each
// writing (world bent normal, visibility) for the lighting pass.
#include <glm/vec2.hpp>

#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class AmbientOcclusionPass {
public:
    explicit AmbientOcclusionPass(GpuContext& context);

    // RGBA16F (world bent normal, visibility), what every AO pass writes and lighting reads.
    static ImageDesc occlusionDesc(uint32_t width, uint32_t height);
    // R16F: the visibility of the specular lobe (GTAO's horizon slice or the reference's rays).
    static ImageDesc specularDesc(uint32_t width, uint32_t height);
    // RGBA32UI: the temporal history (ao_temporal.comp's packing).
    static ImageDesc historyDesc(uint32_t width, uint32_t height);
    // GTAO's per-frame slice rotation and step offset for temporal accumulation (R2 sequence).
    static glm::vec2 frameRotation(uint32_t frame);

    struct Inputs {
        ImageRef depth;             // Sampled
        ImageRef normalRoughMetal;  // Sampled
        const GpuBuffer* camera;
        AmbientOcclusionSettings settings;
        glm::vec2 frameRotation{0.0f};  // zero without temporal accumulation
    };
    // GTAO into `noisy` and the reflection lobe's visibility into `specular` (StorageWrite),
    // then the denoise from `noisy` (Sampled) into `filtered`.
    void recordGtao(VkCommandBuffer cmd, const Inputs& in, const ImageRef& noisy,
                    const ImageRef& specular) const;
    void recordDenoise(VkCommandBuffer cmd, const Inputs& in, const ImageRef& noisy,
                       const ImageRef& filtered) const;
    // Temporal accumulation (ao_temporal.comp): `current` (the denoise's output), `motion`
    // and last frame's `history` (Sampled) into `accumulated` and this frame's history
    // (StorageWrite).
    struct TemporalInputs {
        ImageRef current;
        ImageRef motion;
        ImageRef history;
        bool historyValid = false;
        uint32_t maxFrames = 16;
    };
    void recordTemporal(VkCommandBuffer cmd, const Inputs& in, const TemporalInputs& temporal,
                        const ImageRef& accumulated, const ImageRef& historyOut) const;
    // The reference into `occlusion` and `specular` (both StorageWrite).
    void recordReference(VkCommandBuffer cmd, const Inputs& in, const ImageRef& occlusion,
                         const ImageRef& specular) const;

private:
    Pipeline gtao_;
    Pipeline denoise_;
    Pipeline temporal_;
    Pipeline reference_;
    Sampler pointSampler_;
};

}  // namespace candela::render
