#include "candela/render/frame_capture.h"

#include <cmath>
#include <cstring>

#include "candela/content/exr_image.h"
#include "candela/content/png_writer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "vk/memory_barrier.h"

namespace candela::render {

namespace {

void copyImage(VkCommandBuffer cmd, const GpuImage& image, const GpuBuffer& staging) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.desc().width, image.desc().height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           staging.handle(), 1, &region);
}

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

size_t CapturedFrame::nonFiniteHdrValues() const {
    size_t count = 0;
    for (float v : hdrRgb)
        count += std::isfinite(v) ? 0 : 1;
    return count;
}

FrameReadback::FrameReadback(GpuContext& context, uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      hdrStaging_(context, VkDeviceSize(width) * height * 4 * sizeof(float),
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::HostVisible),
      ldrStaging_(context, VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryLocation::HostVisible) {}

void FrameReadback::recordCopy(VkCommandBuffer cmd, const Renderer& renderer) const {
    copyImage(cmd, renderer.hdrTarget(), hdrStaging_);
    copyImage(cmd, renderer.ldrTarget(), ldrStaging_);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

CapturedFrame FrameReadback::read() const {
    CapturedFrame frame;
    frame.width = width_;
    frame.height = height_;
    const size_t pixels = size_t(width_) * height_;
    const auto* rgba = static_cast<const float*>(hdrStaging_.mapped());
    frame.hdrRgb.resize(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        std::memcpy(&frame.hdrRgb[i * 3], &rgba[i * 4], 3 * sizeof(float));
    }
    frame.ldrRgba.resize(pixels * 4);
    std::memcpy(frame.ldrRgba.data(), ldrStaging_.mapped(), pixels * 4);
    return frame;
}

std::string writeCapture(const std::filesystem::path& path, const CapturedFrame& frame) {
    const std::string ext = lowercaseExtension(path);
    if (ext == ".exr") {
        // Errors already start with the path (content::writeExrRgbFloat).
        return content::writeExrRgbFloat(path, frame.width, frame.height, frame.hdrRgb.data());
    }
    if (ext == ".png")
        return content::writePng(path, frame.width, frame.height, 4, frame.ldrRgba.data());
    return path.string() + ": unknown capture format '" + ext + "' (use .exr or .png)";
}

}  // namespace candela::render
