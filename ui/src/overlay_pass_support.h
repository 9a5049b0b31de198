#pragma once
// What the two 2D draw passes of this module (ImGuiRenderer, GameUiRenderer) share: a sampler
// that clamps, a texture uploaded from host memory in a submission of its own, host-visible
// buffers that grow by powers of two, and dynamic rendering onto an existing colour target.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {
class GpuContext;
}

namespace candela::ui {

// Linear filtering, clamped to the edge, one mip level. Throws when Vulkan refuses.
VkSampler makeClampedLinearSampler(render::GpuContext& context);

// Copies `pixels` (the whole image, tightly packed) into `image` and leaves it readable by
// fragment shaders. `fresh`: the image has never been written (its layout is undefined).
void uploadTexture(render::GpuContext& context, render::GpuImage& image, const void* pixels,
                   VkDeviceSize bytes, bool fresh);

// Makes `buffer` at least `bytes` long (host-visible), starting at `minimum` and doubling.
void growHostBuffer(render::GpuContext& context, render::GpuBuffer& buffer, VkDeviceSize bytes,
                    VkBufferUsageFlags usage, VkDeviceSize minimum);

// Begins dynamic rendering onto `target` (COLOR_ATTACHMENT_OPTIMAL, its contents kept) with a
// viewport over the whole of it.
void beginOverlayRendering(VkCommandBuffer cmd, const render::GpuImage& target);

}  // namespace candela::ui
