#pragma once
// Energy-conserving bloom on the HDR target (bloom_composite.comp): a pyramid of 2x2 means,
// then `strength` of each pixel's radiance replaced by the pyramid's wide average there.
#include <array>
#include <cstdint>

#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "passes/bloom/bloom_bindings.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class BloomPass {
public:
    explicit BloomPass(GpuContext& context);

    // Levels for a width x height frame: halving until the smaller side would go below 4,
    // at most BLOOM_MAX_LEVELS.
    static uint32_t levelCount(uint32_t width, uint32_t height);
    static ImageDesc levelDesc(uint32_t level, uint32_t width, uint32_t height);

    // source: StorageRead (the HDR target or the level above); target: StorageWrite.
    void recordDownsample(VkCommandBuffer cmd, const ImageRef& source,
                          const ImageRef& target) const;
    // hdr: StorageReadWrite; levels: Sampled (levelCount of them).
    void recordComposite(VkCommandBuffer cmd, const ImageRef& hdr,
                         const std::array<ImageRef, BLOOM_MAX_LEVELS>& levels, uint32_t levelCount,
                         float strength) const;

private:
    Pipeline downsample_;
    Pipeline composite_;
    Sampler linear_;
};

}  // namespace candela::render
