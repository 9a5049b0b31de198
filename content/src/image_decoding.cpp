#include "image_decoding.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

namespace candela::content {

std::string decodeImageRgba8(std::span<const std::uint8_t> bytes, Rgba8Image& image,
                             const ImageDecodeLimits& limits) {
    if (bytes.empty()) return "image data is empty";
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return "image data is over 2 GiB";
    const int length = static_cast<int>(bytes.size());
    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels)) {
        return std::string("not a decodable PNG or JPEG (") + stbi_failure_reason() + ")";
    }
    if (width <= 0 || height <= 0 || static_cast<std::uint32_t>(width) > limits.maxDimension ||
        static_cast<std::uint32_t>(height) > limits.maxDimension ||
        std::uint64_t(width) * std::uint64_t(height) > limits.maxTexels) {
        return "image size " + std::to_string(width) + " x " + std::to_string(height) +
               " is outside the limits";
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 4),
        stbi_image_free);
    if (!pixels) return std::string("image decoding failed (") + stbi_failure_reason() + ")";
    image.width = static_cast<std::uint32_t>(width);
    image.height = static_cast<std::uint32_t>(height);
    image.rgba.assign(pixels.get(), pixels.get() + std::size_t{image.width} * image.height * 4);
    image.isFallback = false;
    return {};
}

}  // namespace candela::content
