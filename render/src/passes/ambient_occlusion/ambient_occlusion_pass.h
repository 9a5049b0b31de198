#pragma once
// Ambient occlusion of the sky's light from the G-buffer (render/README.md "Ambient
// occlusion"): GTAO (horizon search + depth-aware denoise) or the ray-marched reference, each
// writing (world bent normal, visibility) for the lighting pass.
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
    // R16F: the reference's visibility of the specular lobe.
    static ImageDesc specularDesc(uint32_t width, uint32_t height);

    struct Inputs {
        ImageRef depth;             // Sampled
        ImageRef normalRoughMetal;  // Sampled
        const GpuBuffer* camera;
        AmbientOcclusionSettings settings;
    };
    // GTAO into `noisy` (StorageWrite), then the denoise from it (Sampled) into `filtered`.
    void recordGtao(VkCommandBuffer cmd, const Inputs& in, const ImageRef& noisy) const;
    void recordDenoise(VkCommandBuffer cmd, const Inputs& in, const ImageRef& noisy,
                       const ImageRef& filtered) const;
    // The reference into `occlusion` and `specular` (both StorageWrite).
    void recordReference(VkCommandBuffer cmd, const Inputs& in, const ImageRef& occlusion,
                         const ImageRef& specular) const;

private:
    Pipeline gtao_;
    Pipeline denoise_;
    Pipeline reference_;
    Sampler pointSampler_;
};

}  // namespace candela::render
