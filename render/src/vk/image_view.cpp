#include "vk/image_view.h"

#include <utility>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "vk/vk_check.h"

namespace candela::render {

ImageView::ImageView(GpuContext& context, const GpuImage& image, VkImageViewType type,
                     uint32_t baseMip, uint32_t mipCount)
    : device_(context.device()) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image.handle();
    info.viewType = type;
    info.format = image.desc().format;
    info.subresourceRange = {image.aspect(), baseMip, mipCount, 0, image.layers()};
    CANDELA_VK_CHECK(vkCreateImageView(device_, &info, nullptr, &view_));
}

ImageView::~ImageView() {
    if (view_) vkDestroyImageView(device_, view_, nullptr);
}

ImageView::ImageView(ImageView&& other) noexcept {
    *this = std::move(other);
}

ImageView& ImageView::operator=(ImageView&& other) noexcept {
    if (this != &other) {
        if (view_) vkDestroyImageView(device_, view_, nullptr);
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    }
    return *this;
}

}  // namespace candela::render
