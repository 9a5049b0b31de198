#pragma once
// Counts non-finite texels (NaN or Inf) of images into a host-visible buffer, one slot per
// image: slot 0 holds the frame's scene radiance before tonemapping (nonfinite_radiance.comp,
// RendererStats::nonFinitePixels), the others the probes of a diagnosis frame
// (nonfinite_count.comp,
// (nonfinite_probes.h). Each slot has a range of its own, so the dispatches that fill them
// need no order among themselves.
#include <cstdint>

#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class NonFinitePass {
public:
    static constexpr uint32_t kSlots = 512;  // slot 0: the frame; the rest: probes
    static constexpr uint32_t kRadianceSlot = 0;
    // The largest minStorageBufferOffsetAlignment Vulkan allows: a slot's range is bindable
    // on any device.
    static constexpr VkDeviceSize kSlotBytes = 256;

    explicit NonFinitePass(GpuContext& context);

    const GpuBuffer& counts() const { return counts_; }
    // Zeroes every slot from the CPU; call before the frame's submission (the buffer is
    // host-coherent and the previous frame has completed).
    void clear() const;
    // radiance: StorageRead, RGBA32F; its rgb pixels count into slot 0.
    void recordRadianceCount(VkCommandBuffer cmd, const ImageRef& radiance) const;
    // image: 2D, one sample, Sampled or (RGBA32F only) StorageRead; every channel counts.
    void recordCount(VkCommandBuffer cmd, const ImageRef& image, uint32_t slot, bool storage) const;
    // Valid once the frame's submission completed.
    uint32_t count(uint32_t slot) const;

private:
    void dispatch(VkCommandBuffer cmd, const Pipeline& pipeline, const VkWriteDescriptorSet& image,
                  uint32_t slot, uint32_t channels, const ImageDesc& desc) const;

    Pipeline sampled_;
    Pipeline radiance_;
    Sampler nearest_;
    GpuBuffer counts_;
};

}  // namespace candela::render
