#pragma once
// An extra view of part of a GpuImage (one mip as a 2D array for compute writes, or one mip
// as a cube for sampling), owned and destroyed with this object.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace candela::render {

class GpuContext;
class GpuImage;

class ImageView {
public:
    ImageView() = default;
    ImageView(GpuContext& context, const GpuImage& image, VkImageViewType type, uint32_t baseMip,
              uint32_t mipCount);
    ~ImageView();
    ImageView(ImageView&& other) noexcept;
    ImageView& operator=(ImageView&& other) noexcept;
    ImageView(const ImageView&) = delete;
    ImageView& operator=(const ImageView&) = delete;

    VkImageView handle() const { return view_; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace candela::render
