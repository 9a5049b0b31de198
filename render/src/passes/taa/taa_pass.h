#pragma once
// Temporal antialiasing (taa.comp): resolves this frame's jittered HDR radiance with the
// reprojected, clipped history into the next history image, which is then copied back into
// the HDR target so exposure, bloom, tonemapping and the .exr capture see the resolve.
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class TaaPass {
public:
    explicit TaaPass(GpuContext& context);

    struct Settings {
        float exposure = 1.0f;
        float minimumBlend = 1.0f / 16.0f;
        bool historyValid = false;
        float sharpness = 0.0f;
    };
    // current: StorageRead; motion and history: Sampled; resolved: StorageWrite.
    void recordResolve(VkCommandBuffer cmd, const ImageRef& current, const ImageRef& motion,
                       const ImageRef& history, const ImageRef& resolved,
                       const Settings& settings) const;

    // The i-th offset of the fixed 16-long Halton (2, 3) sequence, in pixels in [-0.5, 0.5).
    static float jitterX(uint32_t frame);
    static float jitterY(uint32_t frame);
    static constexpr uint32_t kJitterPhases = 16;

private:
    Pipeline pipeline_;
    Sampler nearest_;
    Sampler linear_;
};

}  // namespace candela::render
